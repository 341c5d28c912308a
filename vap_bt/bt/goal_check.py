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

A goal atom whose goal checks could not settle it, after the robot went back to look and checked
again until the executive calls it stuck, may still rest on an earlier check: the effect check
that confirmed it right after the action that brought it about, with no action since that could
change it and no settled view since that denied it (:func:`standing_confirmation`). That is the
paper's standard for the whole goal (Alg. 1 claims once the plan's effects are verified); the
goal check's stricter bound (a second picture and odds that reach the claim's risk) stays the
rule, and this is the fallback where the model reads the relation too poorly to ever reach it
(vlm-2 on ``heated``: boil_water seed 2 in pybullet, the cup heated and confirmed so at the
microwave, three goal checks split between "yes" and "no", the episode given up). Where a thing
rests (``on``, ``inside``) is not a state that persists unseen: a slip or a nudge moves it without
any action of the plan (see :func:`vap_bt.perception.judgement.evidence`), so those atoms never
fall back.
"""

from __future__ import annotations

from typing import ClassVar, Sequence

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.record import GoalAtomEvidence, GoalEvidence, Situation, Verification
from vap_bt.domain.atoms import Atom, Literal
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import Round
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


def standing_confirmation(atom: Atom, expected: bool, verifications: Sequence[Verification],
                          views: Sequence[Round]) -> int | None:
    """The index in ``verifications`` of the check whose settled verdict ``atom`` still rests on
    at ``expected``, or None. ``views`` are the rounds the atom was judged on since the last
    action that could change it (:meth:`vap_bt.bt.record.Verified.views`): the check must be
    among them, and the last check of the atom that settled (confirmed, denied or felt) since; a
    goal check that could not settle it neither confirms nor denies."""
    since = [i for i, v in enumerate(verifications) if v.atom == atom and v.rounds
             and all(any(r is w for w in views) for r in v.rounds)]
    settled = [i for i in since if verifications[i].outcome in ("confirmed", "contradicted", "felt")]
    if not settled or verifications[settled[-1]].value != expected:
        return None
    return settled[-1]


def resting_on_earlier(evidence: GoalEvidence, earlier: dict[Atom, int],
                       verifications: Sequence[Verification]) -> GoalEvidence:
    """``evidence`` with each atom in ``earlier`` resting on the check it names (an index in
    ``verifications``: :func:`standing_confirmation`)."""
    def rest(a: GoalAtomEvidence) -> GoalAtomEvidence:
        i = earlier.get(a.atom)
        if i is None:
            return a
        v = verifications[i]
        return GoalAtomEvidence(a.atom, a.expected, "earlier", i, v,
                                f"its goal checks could not settle it; its {v.phase} check after "
                                f"{v.action} did, and nothing since could change it")
    return GoalEvidence(tuple(rest(a) for a in evidence.atoms))
