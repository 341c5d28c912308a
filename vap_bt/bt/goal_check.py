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
undo it and no settled view since that denied it (:func:`standing_confirmation`; an action that
can only add the atom, the same press of a switch again, does not undo a view that saw it true:
:meth:`vap_bt.bt.record.Verified.standing`). That is the
paper's standard for the whole goal (Alg. 1 claims once the plan's effects are verified); the
goal check's stricter bound (a second picture and odds that reach the claim's risk) stays the
rule, and this is the fallback where the model reads the relation too poorly to ever reach it
(vlm-2 on ``heated``: boil_water seed 2 in pybullet, the cup heated and confirmed so at the
microwave, three goal checks split between "yes" and "no", the episode given up). Where a thing
rests (``on``, ``inside``) is not a state that persists unseen: a slip or a nudge moves it without
any action of the plan (see :func:`vap_bt.perception.judgement.evidence`), so those atoms never
fall back.

Where no check ever settled the atom, it may rest on the domain's model of the action that made it
(:func:`confirmed_by_its_action`): the action's preconditions about the atom's things confirmed
by views right before it ran, its skill said it succeeded, and a view right after it confirmed
another of its effects — the action happened, and an action's effects come together (the oven's
"on" seen after the press, the pie seen inside it before: the pie is heated, though vlm-2 reads
"heated" of a pie small in the oven's mouth too poorly to say; heat_pie seed 93 in pybullet).
A pie dropped beside the oven leaves "inside" unconfirmed before the press, and no claim rests
on the press then.

Neither fallback holds where the views of the atom since the action that could change it —
the confirming check's and every goal check's — weigh against it (:func:`leans_against`: their
log odds by the backend's calibration fall below even). There the executive does the action again
once (as for a goal no check ever confirmed) and claims nothing the views lean against: symbolic
halve_egg seed 159 and boil_water seed 146 claimed "sliced" and "heated" on such a check, and the
world denied both; cut and heated again, both goals were then seen reached (pybullet halve_egg seed
228 too). Views that do not weigh against it leave the claim on the check: pybullet halve_egg
seeds 214 and 218 are claimed so and denied, as before.
"""

from __future__ import annotations

from typing import ClassVar, Sequence

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.record import GoalAtomEvidence, GoalEvidence, Situation, Verification, may_change
from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.knowledge import GroundAction
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.evidence import Calibration
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


def leans_against(atom: Atom, value: bool, views: Sequence[Round], calibration: Calibration) -> bool:
    """Whether ``views`` of ``atom`` (those since the last action that could change it) weigh
    against ``value``: their log odds (:meth:`~vap_bt.perception.evidence.Calibration.log_odds`)
    below even, for it."""
    return calibration.odds_for(atom.predicate, views, value) < 0.0


def confirmed_by_its_action(atom: Atom, expected: bool, verifications: Sequence[Verification],
                            ran: Sequence[tuple[GroundAction, int, bool]], hand: frozenset[str]) -> int | None:
    """The index in ``verifications`` of the check ``atom`` rests on by the model of the action that
    brought it to ``expected`` (see the module docstring), or None. ``ran``: the actions that ran,
    in order, each with how many checks had been recorded when it ended and whether its skill
    succeeded (:attr:`vap_bt.bt.record.Verified.ran`); ``hand``: the hand's predicates, which any
    action may change. The latest run of such an action that shows it, since the last action that
    could undo the atom, counts, and no settled check of the atom since it may have said otherwise."""
    for k in range(len(ran) - 1, -1, -1):
        action, at, ok = ran[k]
        if ok and atom in (action.add if expected else action.delete):
            before = ran[k - 1][1] if k else 0
            after = ran[k + 1][1] if k + 1 < len(ran) else len(verifications)
            i = _co_effect_check(atom, action, verifications, before, at, after)
            if i is None:
                continue  # this run shows nothing; an earlier one may, and this one undid nothing
            denied = any(v.atom == atom and v.value != expected and v.outcome in ("confirmed", "contradicted", "felt")
                         for v in verifications[at:])
            return None if denied else i
        if may_change(action, atom, hand, expected):
            return None  # something since could have undone it
    return None


def _co_effect_check(atom: Atom, action: GroundAction, verifications: Sequence[Verification],
                     before: int, at: int, after: int) -> int | None:
    """The check, among the effect checks of ``action``'s run (``verifications[at:after]``), that
    confirmed another of its effects by a view — if every precondition of it about ``atom``'s
    things was confirmed (by a view or the body) by its checks since the run before
    (``verifications[before:at]``); None otherwise."""
    name, things = str(action), set(atom.args)
    pre = {v.atom: v for v in verifications[before:at] if v.phase == "pre" and v.action == name}
    about = [a for a in action.pre_pos if things & set(a.args)]
    if not about or any(a not in pre or pre[a].outcome not in ("confirmed", "felt") or pre[a].value is not True
                        for a in about):
        return None
    made = action.add | action.delete
    return next((i for i in range(at, after) if (v := verifications[i]).phase == "eff" and v.action == name
                 and v.atom != atom and v.atom in made and v.outcome == "confirmed" and v.value == v.expected), None)


def resting_on_earlier(evidence: GoalEvidence, earlier: dict[Atom, int],
                       verifications: Sequence[Verification]) -> GoalEvidence:
    """``evidence`` with each atom in ``earlier`` resting on the check it names (an index in
    ``verifications``: :func:`standing_confirmation`, or :func:`confirmed_by_its_action` when the
    check is of another atom)."""
    def rest(a: GoalAtomEvidence) -> GoalAtomEvidence:
        i = earlier.get(a.atom)
        if i is None:
            return a
        v = verifications[i]
        if v.atom != a.atom:
            return GoalAtomEvidence(a.atom, a.expected, "earlier", i, v,
                                    f"its goal checks could not settle it; {v.action} brings it about, ran "
                                    f"with its preconditions about it confirmed, and its eff check confirmed "
                                    f"{v.atom}; nothing since could undo it")
        return GoalAtomEvidence(a.atom, a.expected, "earlier", i, v,
                                f"its goal checks could not settle it; its {v.phase} check after "
                                f"{v.action} did, and nothing since could undo it")
    return GoalEvidence(tuple(rest(a) for a in evidence.atoms))
