"""How one check of an atom is judged: from the views it took to a value, an outcome and a basis.

A check (paper Alg. 2) looks at an atom from one view, then another, until its views decide.
:func:`~vap_bt.perception.verification.verdict` weighs the views (the vote, view sufficiency,
what a spent budget may still settle); this module adds the rules that make a verdict a check's
outcome, whatever runs the check (the behaviour tree's
:class:`~vap_bt.bt.active_perception.ActivePerception` today):

* **a second look** (:func:`needs_second_look`, beyond the paper, on by default): a *surprise* —
  a value against the plan's expectation, or about an atom in doubt — and a *goal* value need a
  second view from a different picture that agrees, since a model's errors are shared by every
  question about one picture; a goal atom found as the goal wants it must also reach the claim's
  bound in log odds (:mod:`vap_bt.perception.evidence`). :func:`judge` keeps looking while the
  budget allows one, and a goal value the spent budget leaves short of it is unsettled;
* **the evidence** (:func:`evidence`): a goal check weighs, besides its own views, those earlier
  checks judged the atom on since the last action that could change it (a cup confirmed filled
  at the sink, whose inside no view into the microwave shows, is still filled);
* **the body's word** (:func:`conclude`): where the camera could not tell, the gripper's answer
  settles; where the gripper is surer than a camera — fingers that closed on nothing hold nothing,
  and whether the hand is empty at all is theirs to say — it overrules the views.

Each check ends in a :class:`Settlement`: the value believed, the outcome (confirmed,
contradicted, unsettled, felt, reused) and the basis it rests on (:data:`BASIS`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from vap_bt.domain.atoms import Atom
from vap_bt.perception.evidence import CLAIM_RISK, Calibration, claim_threshold, default_calibration
from vap_bt.perception.verification import Round, Verdict, distinct, verdict, votes
from vap_bt.robot.frame import Frame

Phase = Literal["pre", "eff", "goal"]
Outcome = Literal["confirmed", "contradicted", "unsettled", "felt", "reused"]
#: what a check's value rests on: the VLM's verdict on views this check took ("vlm"), the
#: gripper's feel ("proprioception"), an earlier check's value that no action since could have
#: changed ("reused": the lean protocol's, nothing was looked at), or nothing — belief stands
#: ("belief": unsettled). Only a value a sense gave at the time is scored as verified
#: (:func:`vap_bt.report.verification_counts`)
Basis = Literal["vlm", "proprioception", "reused", "belief"]
#: the basis of each outcome where the outcome alone says it (the gripper can contradict too)
BASIS: dict[Outcome, Basis] = {"confirmed": "vlm", "contradicted": "vlm", "felt": "proprioception",
                               "reused": "reused", "unsettled": "belief"}


@dataclass(frozen=True)
class Subject:
    """What one check is about: an atom, the value the plan expects of it, and when it is asked."""

    atom: Atom
    expected: bool
    phase: Phase


@dataclass(frozen=True)
class Look:
    """What one run of a check produced: the round of questions and the frame it asked them of
    (a viewpoint question, when one follows, is asked of the same frame)."""

    round: Round
    frame: Frame


@dataclass(frozen=True)
class JudgementRules:
    """How sure a check must be: second looks on or off, the backend's calibration, and the
    accepted chance of claiming a goal atom that does not hold."""

    second_look: bool = True
    calibration: Calibration = field(default_factory=default_calibration)
    claim_risk: float = CLAIM_RISK


@dataclass(frozen=True)
class Settlement:
    """How a check ended: the value believed, the outcome, and what the value rests on."""

    value: bool
    outcome: Outcome
    basis: Basis


def evidence(subject: Subject, own: list[Round], earlier: list[Round], whereabouts: bool = False) -> list[Round]:
    """The views a check weighs: its own; for a goal atom also ``earlier`` ones (views other
    checks judged it on since the last action that could change it), each once — but for where
    a thing rests (``whereabouts``: ``on``, ``inside``) only once one of its own views showed the
    thing. A state persists where no view shows it (a cup filled at the sink is still filled in
    the microwave), but a thing's place is what a slip, a nudge or the hand taking the other
    bottle for it changes without any action of the plan touching the atom: retrieve_bottles
    seed 0 claimed on(bottle2, counter) from the views of its place check while the goal check's
    own view of the counter showed one bottle, taken for bottle1, and bottle2 lay on the floor."""
    if subject.phase != "goal" or whereabouts and all(r.unshown for r in own):
        return own
    return [*(r for r in earlier if not any(r is o for o in own)), *own]


def needs_second_look(subject: Subject, value: bool, views: list[Round], rules: JudgementRules,
                      doubted: bool = False) -> bool:
    """Whether ``value``, which the views gave, still needs another view from a new picture: a
    surprise (it would correct belief and make the robot replan), an atom in ``doubted`` (a
    precondition of an action that failed when it last ran: the failure is evidence against it,
    even when confirmed) or a goal value (success would be claimed on it), when the rules ask for
    second looks. Enough is two views of different pictures whose answers agreed on the value —
    and, for a goal atom found as the goal wants it, log odds of every view (views against
    included) that reach the claim's bound."""
    surprise = value != subject.expected or doubted
    if not rules.second_look or not (surprise or subject.phase == "goal"):
        return False
    pictures = distinct(views)
    agreeing = votes(pictures).count(value)
    if subject.phase == "goal" and value == subject.expected:  # success is claimed on it
        return agreeing < 2 or rules.calibration.odds_for(subject.atom.predicate, pictures, value) \
            < claim_threshold(rules.claim_risk)
    return agreeing < 2


def judge(subject: Subject, views: list[Round], rules: JudgementRules, exhausted: bool,
          doubted: bool = False) -> Verdict | None:
    """The views' verdict on the check (None: look again). While the budget allows a move
    (``exhausted`` False) a value that needs a second look is not yet believed; once spent, a
    goal value short of the claim's bound is unsettled (a surprise stands on what it has, as
    :func:`~vap_bt.perception.verification.verdict` allowed it)."""
    v = verdict(views, exhausted)
    if v is None or v.outcome == "unsettled" or not needs_second_look(subject, v.value, views, rules, doubted):
        return v
    if not exhausted:
        return None  # one picture is one draw of the model's errors: another view before believing it
    if subject.phase == "goal" and v.value == subject.expected:
        return Verdict(v.value, "unsettled")  # success is never claimed on views short of the bound
    return v


def conclude(subject: Subject, v: Verdict, felt: bool | None) -> Settlement:
    """The check's settlement from the views' verdict and the body's word on the atom (None: the
    body has none)."""
    if v.outcome == "unsettled":
        if felt is not None:  # the camera could not tell; the gripper can
            return by_feel(subject, felt)
        return Settlement(subject.expected, "unsettled", BASIS["unsettled"])
    if felt is not None and felt != v.value and (felt is False or not subject.atom.args):
        # fingers that closed on nothing hold nothing, and whether the hand is empty is theirs to say
        return by_feel(subject, felt)
    outcome: Outcome = "confirmed" if v.value == subject.expected else "contradicted"
    return Settlement(v.value, outcome, BASIS[outcome])


def by_feel(subject: Subject, felt: bool) -> Settlement:
    """A settlement on the gripper's word (it can contradict the plan as well as confirm it)."""
    return Settlement(felt, "felt" if felt == subject.expected else "contradicted", "proprioception")


def reused(value: bool) -> Settlement:
    """A settlement on an earlier check's value that nothing since could have changed."""
    return Settlement(value, "reused", BASIS["reused"])
