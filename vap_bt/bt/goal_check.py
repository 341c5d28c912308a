"""GoalCheck: the last node of every compiled plan — does the belief now satisfy the goal?

Effects were verified along the way, so the belief is grounded; this node only fails when it is
not (a plan compiled for a goal the belief does not reach is a bug or a stale tree), and its
failure is a situation of kind ``goal``.

It also records what the goal rests on (the board's ``goal_evidence``, the report's):
success is claimed right after it, so a claim can be read off against its evidence — which goal
atoms the goal's own checks looked at (the VLM's verdict; never a value reused from earlier,
under any protocol), which rest on the robot's body (the gripper settled the check, or the
domain's profile leaves the predicate to proprioception), and which on belief alone (map
knowledge, never checked, goal checks off, or a look that could not settle them).
"""

from __future__ import annotations

from typing import ClassVar, Sequence

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.record import GoalAtomEvidence, GoalEvidence, Situation, Verification
from vap_bt.domain.atoms import Literal
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.strategy import Strategy


class GoalCheck(py_trees.behaviour.Behaviour):
    """Whether belief satisfies the goal once the plan is through, and what the goal rests on."""

    KEYS: ClassVar[dict[str, Access]] = {"verifications": Access.READ, "goal_evidence": Access.WRITE,
                                         "situation": Access.WRITE}

    def __init__(self, ctx: ExecutionContext, goal: tuple[Literal, ...], step: int,
                 profile: PerceptionProfile) -> None:
        super().__init__(name="goal check")
        self.ctx, self.goal, self.step, self.profile = ctx, goal, step, profile
        self.board = ctx.board.client(type(self).__name__, self.KEYS)

    def update(self) -> Status:
        self.board.goal_evidence = goal_evidence(self.board.verifications, self.ctx.strategy, self.goal, self.profile)
        missing = [l for l in self.goal if self.ctx.graph.holds(l.atom) != l.positive]
        if not missing:
            return Status.SUCCESS
        l = missing[0]
        self.board.situation = Situation("goal", None, self.step, l.atom, l.positive, not l.positive,
                                         detail="belief does not satisfy the goal")
        return Status.FAILURE


def goal_evidence(verifications: Sequence[Verification], strategy: Strategy, goal: tuple[Literal, ...],
                  profile: PerceptionProfile) -> GoalEvidence:
    """What each goal literal rests on now, just after the tree's goal checks (``verifications``:
    the episode's so far; ``strategy``: which phases are verified). The latest goal check of an atom
    is this tree's: every tree checks every goal atom the camera is asked about (when effects are
    verified at all), right before this node."""
    last = {v.atom: i for i, v in enumerate(verifications) if v.phase == "goal"}
    return GoalEvidence(tuple(_atom_evidence(verifications, strategy, l, last.get(l.atom), profile) for l in goal))


def _atom_evidence(verifications: Sequence[Verification], strategy: Strategy, l: Literal, index: int | None,
                   profile: PerceptionProfile) -> GoalAtomEvidence:
    if index is None:  # no goal check asked about it: the profile's source, or the strategy, says why
        reason = profile.unchecked_reason(l.atom) \
            or f"not looked at: verification strategy {strategy.name!r} checks no goal"
        felt = profile.source(l.atom.predicate, len(l.atom.args)) == "proprioception"
        return GoalAtomEvidence(l.atom, l.positive, "felt" if felt else "unchecked", reason=reason)
    v = verifications[index]
    if v.basis == "vlm":
        return GoalAtomEvidence(l.atom, l.positive, "looked", index, v)
    if v.basis == "proprioception":
        return GoalAtomEvidence(l.atom, l.positive, "felt", index, v, "the gripper settled it")
    why = {"belief": "its goal check could not settle it: belief stands",
           "reused": "an earlier check's value, reused"}[v.basis]  # reuse never settles a goal check, said should it
    return GoalAtomEvidence(l.atom, l.positive, "unchecked", index, v, why)
