"""What the behaviours of one episode share: belief, senses, hands, settings and the record.

py_trees behaviours are constructed with this context rather than reaching into a global
blackboard: every dependency is explicit and typed, and two executives can run side by side.
Behaviours write what happened (verifications, actions, the pending situation) here; the
executive reads it to decide what to do when a tree fails.
"""

from __future__ import annotations

import time
from concurrent.futures import Executor, Future
from dataclasses import dataclass, field
from typing import Callable, Literal

from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import HOUSEHOLD, Roles
from vap_bt.domain.knowledge import GroundAction
from vap_bt.bt.inflight import InlineExecutor
from vap_bt.perception.evidence import CLAIM_RISK, Calibration, default_calibration
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import Round, VoteSettings
from vap_bt.perception.viewpoints import ViewpointStrategy
from vap_bt.perception.vlm import VLM
from vap_bt.scene.graph import SceneGraph
from vap_bt.robot.camera import Aim, Camera
from vap_bt.skill import SkillClient

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
SituationKind = Literal["precondition", "effect", "execution", "goal", "unseen"]
#: what a precondition check that could not settle does (:class:`ExecutionContext.unseen`):
#: "look" — stop before the action and look for what it is about, then replan (the default: a plan
#: does not go on over a precondition nobody could see); "go_on" — believe it and act; "stop" —
#: end the episode
UnseenPolicy = Literal["look", "go_on", "stop"]


@dataclass(frozen=True)
class VerifyMode:
    pre: bool = True
    eff: bool = True

    @classmethod
    def parse(cls, name: str) -> "VerifyMode":
        return {"both": cls(True, True), "pre": cls(True, False), "eff": cls(False, True),
                "none": cls(False, False)}[name]

    @property
    def name(self) -> str:
        return {(True, True): "both", (True, False): "pre", (False, True): "eff", (False, False): "none"}[
            (self.pre, self.eff)]


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

    def to_json(self) -> dict:
        return {"kind": self.kind, "action": str(self.action) if self.action else None,
                "predicate": str(self.atom) if self.atom else None,
                "expected": self.expected, "observed": self.observed, "detail": self.detail}


@dataclass
class Verification:
    phase: Phase
    action: str
    atom: Atom
    expected: bool
    value: bool
    outcome: Outcome
    rounds: list[Round]
    basis: Basis

    @property
    def queries(self) -> int:
        """The VLM queries this check asked: each round's answers, its view-sufficiency question
        when the model was asked it, and its viewpoint question when one followed."""
        return sum(len(r.answers) + (r.sufficient_by == "model") + (r.direction is not None) for r in self.rounds)

    def to_json(self) -> dict:
        return {"phase": self.phase, "action": self.action, "predicate": str(self.atom),
                "expected": self.expected, "value": self.value, "outcome": self.outcome, "basis": self.basis,
                "views": len(self.rounds), "queries": self.queries, "rounds": [r.to_json() for r in self.rounds]}


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
    rests_on: Literal["looked", "felt", "unchecked"]
    verification: int | None = None
    check: Verification | None = None
    reason: str = ""

    def to_json(self) -> dict:
        out = {"predicate": str(self.atom), "expected": self.expected}
        if self.check is not None:
            out.update(verification=self.verification, value=self.check.value, outcome=self.check.outcome,
                       views=len(self.check.rounds))
        if self.reason:
            out["reason"] = self.reason
        return out


@dataclass(frozen=True)
class GoalEvidence:
    """What the goal check of a tree rested on, per goal literal (the report's ``goal_evidence``):
    ``looked`` — a VLM verdict on views its goal check took; ``felt`` — the body's word (the
    gripper settled the check, or the domain leaves the predicate to proprioception);
    ``unchecked`` — belief alone (map knowledge, a predicate never checked, goal checks off, or a
    look that could not settle it)."""

    atoms: tuple[GoalAtomEvidence, ...]

    def to_json(self) -> dict:
        return {kind: [a.to_json() for a in self.atoms if a.rests_on == kind]
                for kind in ("looked", "felt", "unchecked")}


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
    the microwave, where no view shows its inside."""

    def __init__(self, enabled: bool = False, hand: frozenset[str] = HOUSEHOLD.hand) -> None:
        self.enabled = enabled
        #: the hand's predicates (the profile's roles ``held`` and ``hand_empty``)
        self.hand = hand
        self._values: dict[Atom, bool] = {}
        self._rounds: dict[Atom, list[Round]] = {}

    def get(self, atom: Atom) -> bool | None:
        return self._values.get(atom) if self.enabled else None

    def remember(self, atom: Atom, value: bool) -> None:
        if self.enabled:
            self._values[atom] = value

    def saw(self, atom: Atom, rounds) -> None:
        """``atom`` was judged on ``rounds`` (one per frame) by one check."""
        known = self._rounds.setdefault(atom, [])
        known += [r for r in rounds if not any(r is k for k in known)]

    def views(self, atom: Atom) -> list[Round]:
        """The rounds ``atom`` was judged on since the last action that could have changed it."""
        return list(self._rounds.get(atom, ()))

    def distrust(self, atoms) -> None:
        """Forget the values and views ``atoms`` were judged on: something since casts doubt on
        them (the action meant to bring them about lost its tool)."""
        self._values = {a: v for a, v in self._values.items() if a not in atoms}
        self._rounds = {a: r for a, r in self._rounds.items() if a not in atoms}

    def executed(self, action: GroundAction) -> None:
        """``action`` ran (or tried to): forget what it could have changed."""
        args, changed = set(action.args), action.may_add | action.may_delete

        def changeable(a: Atom) -> bool:
            return a in changed or a.predicate in self.hand or not a.args

        self._values = {a: v for a, v in self._values.items() if not (args & set(a.args) or changeable(a))}
        self._rounds = {a: r for a, r in self._rounds.items() if not changeable(a)}


@dataclass
class ExecutionContext:
    graph: SceneGraph
    vlm: VLM | None
    camera: Camera
    skills: SkillClient
    mode: VerifyMode = field(default_factory=VerifyMode)
    budget: int = 3  # K: viewpoint moves per verification
    vote: VoteSettings = field(default_factory=VoteSettings)
    progress: Callable[[str], None] = lambda msg: None
    situation: Situation | None = None
    verifications: list[Verification] = field(default_factory=list)
    #: goal atoms the final look could not settle: success is not claimed over them (the
    #: executive looks again, and clears this for the next tree)
    unconfirmed_goal: list[Atom] = field(default_factory=list)
    #: what the goal check of the tree last ticked through to it rested on (None: no tree since
    #: the last plan got there); recorded by :class:`~vap_bt.bt.goal_check.GoalCheck`
    goal_evidence: GoalEvidence | None = None
    actions: list[dict] = field(default_factory=list)
    unseen: UnseenPolicy = "look"
    #: what the body itself says of an atom the camera could not settle (the gripper of
    #: ``holding``/``hand_empty``), or None: proprioception decides where looking could not
    felt: Callable[[SceneGraph, Atom], bool | None] = lambda graph, atom: None
    #: whether the body may say anything of an atom at all (asking it is a query to the robot's
    #: state service: behaviours ask it in flight, and only where it may answer)
    feels: Callable[[Atom], bool] = lambda atom: True
    #: where to point the camera for some objects, from belief (the scene-graph builder's ``aim``)
    aim: Callable[[SceneGraph, tuple[str, ...]], Aim] = lambda graph, names: Aim(tuple(names))
    #: names no detector ever finds (the map's rooms and floors): never "missing" from a view
    undetectable: frozenset = frozenset()
    #: what belief says about a goal's objects, sent with it (the scene-graph builder's ``hints``)
    hints: Callable[[SceneGraph, tuple[str, ...]], tuple] = lambda graph, names: ()
    protocol: Protocol = field(default_factory=lambda: Protocol("paper"))
    viewpoints: ViewpointStrategy = field(default_factory=ViewpointStrategy)
    #: a surprise or a goal value needs a second agreeing view from another picture (beyond the paper)
    second_look: bool = True
    #: what each kind of view weighs (the backend's calibration) and the accepted chance of
    #: claiming a goal atom that does not hold (:mod:`vap_bt.perception.evidence`)
    calibration: Calibration = field(default_factory=default_calibration)
    claim_risk: float = CLAIM_RISK
    #: preconditions the camera could not make out however often the robot looked again: it acts on
    #: belief there (the action's effects are checked), as the ``go_on`` policy does everywhere
    on_belief: set[Atom] = field(default_factory=set)
    #: preconditions of an action that failed when it ran (a failure is evidence against what the
    #: action presumed): a view that confirms one is a second opinion only with another view from
    #: a new picture that agrees (as for a surprise); cleared when a check settles it
    doubted: set[Atom] = field(default_factory=set)
    #: preconditions the camera denied, that no action can make true, after every doubt: the
    #: action itself is their test (its skill fails if the camera was right), so a check that
    #: contradicts one again lets the action run (the verification still says contradicted)
    on_trial: set[Atom] = field(default_factory=set)
    verified: Verified = field(default_factory=Verified)
    #: where work in flight runs (a thread pool against a remote model; inline in-process)
    executor: Executor = field(default_factory=InlineExecutor)
    #: the runner's record of each verification (scored against the world there; returns nothing)
    record: Callable[["Verification"], None] = lambda v: None
    #: atoms the compiled trees leave unchecked, keyed by (phase, action, atom), in compile order
    unchecked: dict[tuple, Unchecked] = field(default_factory=dict)
    #: which predicates are asked of the VLM, and with which questions (None: the compiler reads
    #: the domain's own, :func:`vap_bt.perception.profile.resolve`)
    profile: PerceptionProfile | None = None
    t0: float = field(default_factory=time.perf_counter)

    @property
    def roles(self) -> Roles:
        """Which predicate plays each role (the profile's; the household's before there is one)."""
        return self.profile.roles if self.profile is not None else HOUSEHOLD

    def submit(self, fn, *args) -> Future:
        return self.executor.submit(fn, *args)

    def now(self) -> float:
        return round(time.perf_counter() - self.t0, 6)
