"""What a behaviour tree's checks and actions leave behind: situations, verifications, what was
left unchecked, what a goal rests on, and which values a later check may reuse.

These are the values behaviours write to the episode's board (:mod:`vap_bt.bt.board`) and the
executive, the report and the live view read: typed records, each saying what it is.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.roles import HOUSEHOLD
from vap_bt.perception.judgement import Basis, Outcome, Phase
from vap_bt.perception.verification import Round

#: what went wrong: a check that settled against belief (of a precondition, an effect, the goal), a
#: skill that failed, a precondition nobody could see; or an action-level question answered "no"
#: (:mod:`vap_bt.bt.action_check`): the action did not succeed, or cannot be done now
SituationKind = Literal["precondition", "effect", "execution", "goal", "unseen", "action_failed",
                        "action_infeasible"]
#: what a situation stems from (paper Sec. II), as the executive diagnoses it (:mod:`vap_bt.bt.diagnosis`)
Diagnosis = Literal["perception_error", "world_change", "execution_failure"]


@dataclass
class Situation:
    """A check that settled against expectation, or a skill that failed: the loop must replan."""

    kind: SituationKind
    action: GroundAction | None
    step: int  # index of the action in the plan being executed
    atom: Atom | None = None
    expected: bool | None = None
    observed: bool | None = None
    detail: str = ""
    #: the thing a failed skill looked for where belief put it and did not see (execution only)
    missing: str | None = None
    #: the precondition a failed skill found false where it looked (execution only)
    unmet: Atom | None = None
    #: a check that settled against belief had views of its own that showed the atom as belief
    #: had it (the model erred about it in this very check, one way or the other)
    split: bool = False
    #: what the executive makes of it, from its own records, and why (None: not diagnosed yet)
    diagnosis: Diagnosis | None = None
    diagnosis_basis: str = ""

    def to_json(self) -> dict:
        return {"kind": self.kind, "action": str(self.action) if self.action else None,
                "predicate": str(self.atom) if self.atom else None,
                "expected": self.expected, "observed": self.observed, "detail": self.detail,
                "missing": self.missing, "unmet": str(self.unmet) if self.unmet else None, "split": self.split, "diagnosis": self.diagnosis, "diagnosis_basis": self.diagnosis_basis}


@dataclass
class Verification:
    """One check of one atom, settled: when and for which action, what was expected and
    believed after, how (the outcome and what it rests on), and the views it took."""

    phase: Phase
    action: str
    atom: Atom
    expected: bool
    value: bool
    outcome: Outcome
    rounds: list[Round]
    basis: Basis
    #: viewpoints moved to after the first view (a direction the robot could not reach is none)
    viewpoints: int = 0
    #: whether the first view decided the check; None where no view was judged (a reused value)
    #: or none elsewhere could help (the hand's checks): the H2 measure's uncertain checks are
    #: those whose first view did not (:mod:`vap_bt.viewpoint_measure`)
    first_settled: bool | None = None

    @property
    def queries(self) -> int:
        """The VLM queries this check asked: each round's answers, its view-sufficiency question
        when the model was asked it, and its viewpoint question when one followed."""
        return sum(len(r.answers) + (r.sufficient_by == "model") + (r.direction is not None) for r in self.rounds)

    @property
    def atoms(self) -> tuple[Atom, ...]:
        """The atoms whose conjunction the check's value is about (the runner scores it so)."""
        return (self.atom,)

    def to_json(self) -> dict:
        return {"phase": self.phase, "action": self.action, "predicate": str(self.atom),
                "expected": self.expected, "value": self.value, "outcome": self.outcome, "basis": self.basis,
                "views": len(self.rounds), "viewpoints": self.viewpoints, "first_settled": self.first_settled,
                "queries": self.queries, "rounds": [r.to_json() for r in self.rounds]}


@dataclass
class ActionCheck:
    """One action-level question (SuccessVQA after an action, AffordanceVQA before it), answered:
    the question, the atoms it implies (whose conjunction the simulated model judges, and the
    runner scores it by), the answer and what became of it. ``value`` is the answer (None: the
    model gave none, and belief stands)."""

    phase: Phase  # "pre": affordance, "eff": success
    action: str
    question: str
    implied: tuple[Atom, ...]
    value: bool | None
    outcome: Outcome  # confirmed (yes), contradicted (no), unsettled (no answer)
    round: Round

    @property
    def atoms(self) -> tuple[Atom, ...]:
        """The atoms whose conjunction the question is about."""
        return self.implied

    @property
    def rounds(self) -> list[Round]:
        """The check's one view (as a :class:`Verification`'s rounds)."""
        return [self.round]

    @property
    def basis(self) -> Basis:
        """The VLM's answer, or belief where it gave none."""
        return "belief" if self.value is None else "vlm"

    @property
    def queries(self) -> int:
        """The VLM queries the check asked: one."""
        return len(self.round.answers)

    def to_json(self) -> dict:
        return {"phase": self.phase, "action": self.action, "question": self.question,
                "implies": [str(a) for a in self.implied], "value": self.value, "outcome": self.outcome,
                "basis": self.basis, "views": 1, "queries": self.queries, "round": self.round.to_json()}


@dataclass(frozen=True)
class Unchecked:
    """An atom a compiled tree does not look at, and why (the report lists them)."""

    phase: Phase
    action: str
    atom: Atom
    expected: bool
    reason: str

    def to_json(self) -> dict:
        return {"phase": self.phase, "action": self.action, "predicate": str(self.atom),
                "name": self.atom.predicate, "expected": self.expected, "reason": self.reason}


@dataclass(frozen=True)
class GoalAtomEvidence:
    """What one goal atom rests on when the goal is checked: the last goal check of it
    (``verification``: its index in the context's, and the report's, verifications), or, where
    none looked, why not."""

    atom: Atom
    expected: bool
    rests_on: Literal["looked", "earlier", "felt", "unchecked"]
    verification: int | None = None
    check: Verification | None = None
    reason: str = ""

    def to_json(self) -> dict:
        out = {"predicate": str(self.atom), "expected": self.expected}
        if self.check is not None:
            out.update(verification=self.verification, value=self.check.value, outcome=self.check.outcome,
                       views=len(self.check.rounds))
            if self.check.atom != self.atom:  # it rests on another effect of the action that made it
                out["checked"] = str(self.check.atom)
        if self.reason:
            out["reason"] = self.reason
        return out


@dataclass(frozen=True)
class GoalEvidence:
    """What the goal check of a tree rested on, per goal literal (the report's ``goal_evidence``):
    ``looked`` — a VLM verdict on views its goal check took; ``earlier`` — an earlier check's
    settled verdict, no action since could undo it, and the goal's own checks could not settle it
    (:func:`~vap_bt.bt.goal_check.standing_confirmation`), or, where no check ever settled it, the
    check that saw another effect of the action that made it (``checked`` names that atom:
    :func:`~vap_bt.bt.goal_check.confirmed_by_its_action`); ``felt`` — the body's word (the
    gripper settled the check, or the domain leaves the predicate to proprioception);
    ``unchecked`` — belief alone (map knowledge, a predicate never checked, goal checks off, or a
    look that could not settle it)."""

    atoms: tuple[GoalAtomEvidence, ...]

    def to_json(self) -> dict:
        return {kind: [a.to_json() for a in self.atoms if a.rests_on == kind]
                for kind in ("looked", "earlier", "felt", "unchecked")}


class Verified:
    """Atoms verified earlier and not changeable since (the lean protocol's reuse, mid-plan only:
    the goal's check before success is claimed always looks).

    An entry lives until an executed action could have changed its atom: one whose arguments
    include one of the atom's objects, or one of whose effects (conditional ones included) could
    add or delete that atom; the hand's atoms (no arguments, or ``holding``) go after every
    action, as the hand can lose things on any move. Disabled (always empty) unless the protocol
    reuses.

    It also keeps the views each atom was judged on (:meth:`saw`), for the goal's second opinion
    (:class:`~vap_bt.bt.active_perception.ActivePerception`): those live, whatever the protocol,
    until an executed action's effects could change the atom (the planner's own frame assumption;
    the hand's atoms after every action) — a cup confirmed filled at the sink is still filled in
    the microwave, where no view shows its inside.

    And it keeps the last check that settled each atom (:meth:`settle`, :meth:`standing`) for as
    long as no executed action could undo *its value*: an action that can only add an atom does
    not make a seen-true one false (a second press of the oven's switch does not un-heat the pie
    a view saw heated after the first), nor one that can only delete it a seen-false one true —
    the same frame assumption, read per value. The actions that ran are kept in order (``ran``),
    for a goal to rest on the action seen to have made it
    (:func:`~vap_bt.bt.goal_check.confirmed_by_its_action`)."""

    def __init__(self, enabled: bool = False, hand: frozenset[str] = HOUSEHOLD.hand) -> None:
        self.enabled = enabled
        #: the hand's predicates (the profile's roles ``held`` and ``hand_empty``)
        self.hand = hand
        self._values: dict[Atom, bool] = {}
        self._rounds: dict[Atom, list[Round]] = {}
        self._settled: dict[Atom, tuple[bool, list[Round]]] = {}
        #: every action that ran (or tried to), in order: the action, how many checks the episode
        #: had recorded when it ended, and whether its skill reported success
        self.ran: list[tuple[GroundAction, int, bool]] = []

    def get(self, atom: Atom) -> bool | None:
        """The value remembered for ``atom``, or None: never verified, forgotten since, or reuse disabled."""
        return self._values.get(atom) if self.enabled else None

    def remember(self, atom: Atom, value: bool) -> None:
        """Keep ``atom``'s verified value for later checks to reuse (nothing, while reuse is disabled)."""
        if self.enabled:
            self._values[atom] = value

    def saw(self, atom: Atom, rounds) -> None:
        """``atom`` was judged on ``rounds`` (one per frame) by one check."""
        known = self._rounds.setdefault(atom, [])
        known += [r for r in rounds if not any(r is k for k in known)]

    def views(self, atom: Atom) -> list[Round]:
        """The rounds ``atom`` was judged on since the last action that could have changed it."""
        return list(self._rounds.get(atom, ()))

    def settle(self, atom: Atom, value: bool, rounds) -> None:
        """A check settled ``atom`` at ``value`` on ``rounds`` (a view's verdict or the body's):
        it replaces whatever settled the atom before."""
        self._settled[atom] = (value, list(rounds))

    def standing(self, atom: Atom) -> list[Round]:
        """The rounds of the last check that settled ``atom``, while no action since could have
        undone the value it settled (none when nothing settled it, or something since could)."""
        return list(self._settled.get(atom, (None, []))[1])

    def distrust(self, atoms) -> None:
        """Forget the values and views ``atoms`` were judged on: something since casts doubt on
        them (the action meant to bring them about lost its tool)."""
        self._values = {a: v for a, v in self._values.items() if a not in atoms}
        self._rounds = {a: r for a, r in self._rounds.items() if a not in atoms}
        self._settled = {a: s for a, s in self._settled.items() if a not in atoms}

    def executed(self, action: GroundAction, checks: int = 0, succeeded: bool = False) -> None:
        """``action`` ran (or tried to; ``succeeded``: its skill said it did), ``checks`` checks
        into the episode: forget what it could have changed."""
        self.ran.append((action, checks, succeeded))
        self._values = {a: v for a, v in self._values.items() if not acted_on(action, a, self.hand)}
        self._rounds = {a: r for a, r in self._rounds.items() if not may_change(action, a, self.hand)}
        self._settled = {a: (v, r) for a, (v, r) in self._settled.items()
                         if not may_change(action, a, self.hand, v)}


def may_change(action: GroundAction, atom: Atom, hand: frozenset[str], value: bool | None = None) -> bool:
    """Whether ``action``'s effects (conditional ones included) could add or delete ``atom`` —
    given its ``value``, only those that could make it otherwise: delete a true one, add a false
    one — or ``atom`` is the hand's (one of the ``hand`` predicates, or without arguments): the
    hand can lose things on any move."""
    if atom.predicate in hand or not atom.args:
        return True
    adds, deletes = atom in action.may_add, atom in action.may_delete
    return deletes if value is True else adds if value is False else adds or deletes


def acted_on(action: GroundAction, atom: Atom, hand: frozenset[str]) -> bool:
    """Whether ``action`` could have changed ``atom`` in any way: it names one of the atom's
    objects, or :func:`may_change` says so."""
    return not set(action.args).isdisjoint(atom.args) or may_change(action, atom, hand)
