"""What the behaviours of one episode are given: services, the checks' settings, and the board.

py_trees behaviours are constructed with this context rather than reaching into a global
blackboard: every dependency is explicit and typed, and two executives can run side by side. The
context holds what behaviours *use* — belief (the scene graph), the camera, the VLM, the skills,
the body's word, the clock, where work in flight runs — and the settings of the checks. What they
*leave* (the situation, the verifications, the actions, the goal's evidence) and what they read
of one another's leaving goes on the episode's :class:`~vap_bt.bt.board.Board`, through keys
each behaviour class declares (:mod:`vap_bt.bt.board`); the executive reads it when a tree fails.
"""

from __future__ import annotations

import time
from concurrent.futures import Executor, Future
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Literal

from vap_bt.bt.board import Board
from vap_bt.bt.inflight import InlineExecutor, body_executor
from vap_bt.bt.record import (ActionCheck, GoalAtomEvidence, GoalEvidence, Situation, SituationKind,  # noqa: F401
                              Unchecked, Verification, Verified)
from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import HOUSEHOLD, Roles
from vap_bt.perception.evidence import CLAIM_RISK, Calibration, default_calibration
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.judgement import BASIS, Basis, JudgementRules, Outcome, Phase  # noqa: F401
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import VoteSettings
from vap_bt.perception.viewpoints import ViewpointStrategy
from vap_bt.perception.vlm import VLM
from vap_bt.scene.graph import SceneGraph
from vap_bt.robot.camera import Aim, Camera
from vap_bt.skill import SkillClient
from vap_bt.strategy import STRATEGIES, Strategy

#: what a precondition check that could not settle does (:class:`ExecutionContext.unseen`):
#: "look" — stop before the action and look for what it is about, then replan (the default: a plan
#: does not go on over a precondition nobody could see); "go_on" — believe it and act; "stop" —
#: end the episode
UnseenPolicy = Literal["look", "go_on", "stop"]
#: how a strategy that asks once (OK-Robot's, :attr:`Strategy.single`) votes: one question, the
#: first paraphrase, settled by its answer alone
ONE_QUESTION = VoteSettings(paraphrases=1, agreement=1.0)


def asking(strategy: Strategy, vote: VoteSettings, protocol: Protocol) -> tuple[VoteSettings, Protocol]:
    """The vote and the protocol ``strategy``'s predicate questions are asked with: the run's,
    or — for a strategy that asks once — one question and no view-sufficiency question."""
    if not strategy.single:
        return vote, protocol
    return ONE_QUESTION, replace(protocol, sufficiency=False)


@dataclass
class ExecutionContext:
    """The services and settings the behaviours of one episode are built with, and its board. A
    strategy that asks once (:attr:`Strategy.single`) sets the checks' settings its way: no
    budget, no second look, one question, no view-sufficiency question."""

    graph: SceneGraph  # belief: read by the checks, changed by ApplyEffects (and the executive)
    vlm: VLM | None
    camera: Camera
    skills: SkillClient
    #: which checks the compiled trees make (:mod:`vap_bt.strategy`)
    strategy: Strategy = STRATEGIES["both"]
    budget: int = 3  # K: viewpoint moves per verification
    vote: VoteSettings = field(default_factory=VoteSettings)
    progress: Callable[[str], None] = lambda msg: None
    unseen: UnseenPolicy = "look"
    #: what the body itself says of an atom the camera could not settle (the gripper of
    #: ``holding``/``hand_empty``), or None: proprioception decides where looking could not. A query
    #: to the robot's state service, which may be slow: asked through :meth:`ask_body` only
    felt: Callable[[SceneGraph, Atom], bool | None] = lambda graph, atom: None
    #: whether the body may say anything of an atom at all (behaviours ask it only where it may answer)
    feels: Callable[[Atom], bool] = lambda atom: True
    #: where to point the camera for some objects, from belief (the scene-graph builder's ``aim``)
    aim: Callable[[SceneGraph, tuple[str, ...]], Aim] = lambda graph, names: Aim(tuple(names))
    #: go to a view of where belief puts some objects, from wherever the robot stands (another
    #: room, after a search), and say whether it got there (the executive's look at them)
    approach: Callable[[SceneGraph, tuple[str, ...]], bool] = lambda graph, names: False
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
    #: where work in flight runs (a thread pool against a remote model; inline in-process)
    executor: Executor = field(default_factory=InlineExecutor)
    #: the runner's record of each verification and action-level check (scored against the world
    #: there; returns nothing)
    record: Callable[["Verification | ActionCheck"], None] = lambda v: None
    #: which predicates are asked of the VLM, and with which questions (None: the compiler reads
    #: the domain's own, :func:`vap_bt.perception.profile.resolve`)
    profile: PerceptionProfile | None = None
    #: what the behaviours leave for one another and for the executive (:mod:`vap_bt.bt.board`)
    board: Board = field(default_factory=Board)
    t0: float = field(default_factory=time.perf_counter)
    #: where the body's word is asked (:meth:`ask_body`): made on first use, closed with :meth:`close`
    _body: Executor | None = field(default=None, init=False, repr=False)

    def __post_init__(self) -> None:
        # a strategy that asks once looks once: no viewpoint move, no second look, one question
        if self.strategy.single:
            self.budget, self.second_look = 0, False
            self.vote, self.protocol = asking(self.strategy, self.vote, self.protocol)

    @property
    def roles(self) -> Roles:
        """Which predicate plays each role (the profile's; the household's before there is one)."""
        return self.profile.roles if self.profile is not None else HOUSEHOLD

    def submit(self, fn, *args) -> Future:
        """Start ``fn(*args)`` where the episode's work in flight runs; the caller polls the future
        (:mod:`vap_bt.bt.inflight`)."""
        return self.executor.submit(fn, *args)

    def ask_body(self, fn: Callable[..., Any], *args) -> Future:
        """Ask the robot's state service in flight, always off the ticking thread: however the
        context's other work runs (inline, in-process), the body is another process's to answer,
        and a slow or silent one must not hold a tick (:func:`~vap_bt.bt.inflight.body_executor`)."""
        if self._body is None:
            self._body = body_executor(self.executor)
        return self._body.submit(fn, *args)

    def close(self) -> None:
        """Let go of the body's worker (a query in flight finishes unheard)."""
        if self._body is not None and self._body is not self.executor:
            self._body.shutdown(wait=False, cancel_futures=True)
        self._body = None

    @property
    def rules(self) -> JudgementRules:
        """How sure a check must be (:mod:`vap_bt.perception.judgement`)."""
        return JudgementRules(self.second_look, self.calibration, self.claim_risk)

    def now(self) -> float:
        """Seconds since the context was made (the episode's clock for records), to the microsecond."""
        return round(time.perf_counter() - self.t0, 6)
