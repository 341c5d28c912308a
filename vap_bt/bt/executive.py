"""The closed-loop executive (paper Algorithm 1) on a behaviour tree.

One episode: look round the site and build the scene graph from what the camera sees
(:class:`~vap_bt.scene.builder.SceneGraphBuilder`; the survey, too, is a tree of steps), plan, compile the plan into a tree, and tick
it. When the tree fails, a behaviour has left a :class:`~vap_bt.bt.context.Situation` on the
context; the executive handles it in a recovery tree (:mod:`vap_bt.bt.recovery`: each step a
behaviour whose work is in flight, ticked, drawn in the live view and halted like the plan's) and
then swaps in a new plan's tree:

1. an effect that did not happen (or an action a SuccessVQA question said did not succeed:
   :mod:`vap_bt.bt.action_check`) first undoes the action-driven update, so belief returns to
   what held before the action;
2. the contradicted atom is set to its observed value (observation-driven update);
3. a skill that failed to act (or an action an AffordanceVQA question said cannot be done now)
   makes the robot's placement for it (the in-view role, the household's ``inview``) stale, so that the
   new plan approaches the target again rather than retrying from the same spot; so does a
   precondition the camera could not settle (a situation of kind ``unseen``: the action did not
   run because nobody could see whether it may) drops ``inview`` of the things it is about, so
   the new plan goes to look at them;
4. the objects the action touched are re-located from a fresh frame by the same builder; an
   object that is not where belief puts it, or that belief no longer places anywhere, sends the
   robot to look again: a re-survey of the room it was believed in (the paper's
   UpdateFromObservation), which costs time and is counted in the report;
5. the planner replans from the corrected graph — reusing the old plan's tail when it still
   works — within the replanning budget.

A goal atom the camera could not confirm, back unchanged after looking afresh, stops the episode
as stuck — unless no check ever confirmed it: then belief holds it only because an action was to
bring it about, which may have failed unseen, and it is handed back to the planner once
(:func:`why_redone`); or unless the check that confirmed it after that action still stands
(no action since could change it, no settled view since denied it, and it is a state, not where
a thing rests): then the claim rests on that check, the paper's own standard, and the report
says so (:func:`~vap_bt.bt.goal_check.standing_confirmation`).

Before any of that, an execution failure is asked of the skill client whether the robot still
has a server (``rejoin``, where the client has one: :class:`~vap_bt.transport.client.ZenohSkillClient`).
A goal that failed because its server died is no fact about the world to replan around: the
executive waits, bounded, for the robot to be served again (a restarted ``vap-bt serve``) and
then replans as for any failed action, or the episode ends "transport down" naming the robot.

A goal given in words is read between the survey and the first plan (paper Alg. 1 line 2): the
``goal_parser`` (:mod:`vap_bt.perception.goal_parsing`) is handed the scene graph's objects.

The VLM-planner baseline (``--verify vlm_planner``, :attr:`vap_bt.strategy.Strategy.vlm_plans`) shares the survey
and the skill path and nothing after: no planner, no checks, no situations; the model names each
next action (:mod:`vap_bt.bt.vlm_planner`).

The executive says which :data:`PHASES` it is in (``phase``) and keeps the episode so far readable
at every moment (:meth:`Executive.so_far`), so that a Ctrl-C, which may come anywhere, still leaves
a whole report: before the first plan that is the belief built so far and nothing done.

The executive talks only to protocols — skills (:class:`~vap_bt.skill.SkillClient`), the camera
service and the body (:mod:`vap_bt.robot.camera`), a VLM — and to the task file's words; it never
sees a world or its truth. Its detector reports class labels, not which object each detection is:
every frame it captures is identified first against current belief
(:class:`~vap_bt.scene.identity.IdentifyingCamera`: the map names its furniture and doors, the
gripper what it holds, belief's positions the items, and an object belief places nowhere — one
it is looking for — is taken where it is first seen, but never inside something belief holds
shut, which no camera sees into). Every way an episode ends halts the tree (``root.stop``), so no goal
is left in flight.
"""

from __future__ import annotations

import threading
import time
from collections import Counter
from dataclasses import dataclass, field
from typing import Callable

import py_trees
from py_trees.common import Status

from vap_bt.bt.compiler import compile_plan
from vap_bt.bt.board import Board
from vap_bt.bt.context import ExecutionContext, asking
from vap_bt.bt.diagnosis import Sightings, diagnose, placed, review
from vap_bt.bt.goal_check import confirmed_by_its_action, leans_against, resting_on_earlier, standing_confirmation
from vap_bt.bt.record import Situation, Verification, Verified
from vap_bt.bt.inflight import working
from vap_bt.bt.plan_tree import PlanTree
from vap_bt.bt.recovery import Halting, Step, recovery_tree
from vap_bt.bt.repeats import LOOK_AFRESH, RepeatWatch, contested, describe, seen_together, stuck
from vap_bt.bt.vlm_planner import VlmPlanner
from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.planner import Plan, Planner
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import PlanningTimeout, UnsolvableError
from vap_bt.perception.evidence import Calibration
from vap_bt.perception.profile import PerceptionProfile, resolve
from vap_bt.perception.protocol import Protocol
from vap_bt.perception.viewpoints import ViewpointStrategy
from vap_bt.perception.state_survey import StateAnswer, survey_states
from vap_bt.perception.verification import VoteSettings
from vap_bt.perception.vlm import VLM
from vap_bt.robot.camera import Body, Camera
from vap_bt.scene import belief
from vap_bt.scene.builder import Geometry, SceneGraphBuilder, SweepRecord
from vap_bt.scene.graph import SceneGraph
from vap_bt.scene.identity import Believed, Identifier, IdentifyingCamera
from vap_bt.scene.misses import Misses
from vap_bt.scene.moves import SightingMoves
from vap_bt.scene.trail import lost_on_the_way, trail_spots
from vap_bt.robot.frame import Frame
from vap_bt.robot.labels import label_of
from vap_bt.settings import default as run_default
from vap_bt.skill import SkillClient
from vap_bt.strategy import STRATEGIES, Strategy

#: times an observation that leaves no plan is doubted and looked at again before it stands: a
#: settled check errs now and then (docs/perception.md), two more from new pictures seldom all do
MAX_DOUBTS = 2
#: how often a recovery's tree is ticked while its step is in flight on a thread (it waits on
#: the robot: a drive, a frame), in seconds
RECOVERY_POLL_S = 0.02
#: what an episode is doing, in order (``Executive.phase``): looking round, reading a goal in
#: words, the first plan, ticking a plan's tree, and handling a situation (correcting belief,
#: looking again, replanning)
PHASES = ("survey", "goal parsing", "planning", "acting", "replanning")


@dataclass(frozen=True)
class ExecutiveSettings:
    """What the executive is told of a run's settings (built from them by the runner:
    :func:`vap_bt.app.runner.executive_settings`); the defaults are the run's (:mod:`vap_bt.settings`)."""

    #: which checks the trees make (:mod:`vap_bt.strategy`)
    strategy: Strategy = STRATEGIES[run_default("verify")]
    budget: int = run_default("budget")
    vote: VoteSettings = field(default_factory=VoteSettings)
    max_replans: int = run_default("max_replans")
    #: the episode's budget in wall-clock seconds (the tree is ticked as fast as work completes,
    #: so ticks measure nothing; what the robot may spend is time)
    max_seconds: float = run_default("max_seconds")
    tick_period_s: float = 0.0  # sleep between ticks while a goal runs (0: in-process skills)
    unseen: str = run_default("unseen")  # what an unsettled precondition does (vap_bt.bt.context.UnseenPolicy)
    protocol: Protocol = field(default_factory=lambda: Protocol.parse(run_default("protocol")))
    viewpoints: str = run_default("viewpoints")  # where to look from next: the VLM's suggestion, or the greedy round
    #: a surprise or a goal value needs a second settled view from a new picture (beyond the
    #: paper's Alg. 2, which takes the first: see vap_bt.bt.active_perception)
    second_look: bool = run_default("second_look")
    #: the accepted chance of claiming a goal atom that does not hold (vap_bt.perception.evidence)
    claim_risk: float = run_default("claim_risk")
    #: work in flight on a thread pool (a remote model or robot); False: done at once, in-process
    threads: bool = False
    #: the VLM-planner's budget of steps (it has no plan whose length could bound it)
    max_steps: int = run_default("max_steps")


@dataclass
class Survey:
    """One look round: why, the sweep, and what was asked of the VLM."""

    reason: str  # "initial", "lost <objects>", or the situation that came back unchanged
    sweep: SweepRecord
    states: list[StateAnswer] = field(default_factory=list)
    facts: frozenset[Atom] = frozenset()  # belief right after it
    prior_only: tuple[str, ...] = ()  # items placed only by the task file's prior

    def to_json(self) -> dict:
        return {"reason": self.reason, **self.sweep.to_json(), "states": [s.to_json() for s in self.states],
                "prior_only": list(self.prior_only)}


@dataclass
class EpisodeOutcome:
    """How an episode ended: the executive's claim, why, and what it did on the way."""

    #: the executive's own claim: its tree reached GoalCheck and it held (the VLM-planner's: the model said done)
    success: bool
    reason: str
    plans: list[Plan]
    situations: list[Situation]
    replans: int
    replan_seconds: list[float]
    surveys: list[Survey]
    ticks: int
    graph: SceneGraph
    context: ExecutionContext
    #: why there was no first plan: "unsolvable" (none exists from what the survey saw) or
    #: "timeout" (the planner gave up); empty when there was one. The CLI's exit codes 3 and 5
    no_initial_plan: str = ""
    #: the VLM-planner's steps (vap_bt.perception.action_proposal.Proposal); empty for the planner's
    proposals: list = field(default_factory=list)

    @classmethod
    def nothing_yet(cls, graph: SceneGraph) -> "EpisodeOutcome":
        """An episode stopped before its first plan: no plan, survey, action or situation; ``graph``
        is belief as far as it got."""
        return cls(False, "", [], [], 0, [], [], 0, graph, ExecutionContext(graph, None, None, None))


class Executive:
    """Runs one task to its end: perceive, plan, tick, handle situations, replan."""

    def __init__(self, task: PlanningTask, planner: Planner, skills: SkillClient, camera: Camera, body: Body,
                 vlm: VLM | None, settings: ExecutiveSettings | None = None,
                 progress: Callable[[str], None] = lambda m: None,
                 on_tree: Callable[[py_trees.trees.BehaviourTree, int], None] | None = None,
                 prior: frozenset[Atom] = frozenset(),
                 geometry: Callable[..., Geometry] | None = None,
                 on_survey: Callable[[Survey, SceneGraph], None] | None = None,
                 on_verification: Callable[[Verification], None] | None = None,
                 on_situation: Callable[[Situation], None] | None = None,
                 goal_parser: Callable[[list[str]], tuple[Literal, ...]] | None = None,
                 profile: PerceptionProfile | None = None, instruction: str = "") -> None:
        self.task, self.planner, self.skills, self.body, self.vlm = task, planner, skills, body, vlm
        #: raised by a halted recovery step: its routine stops at its next camera call
        self._halt = threading.Event()
        #: every frame is identified against belief before anything reads it (see the module docstring)
        self.camera = IdentifyingCamera(Halting(camera, self._halt), self._identify)
        self.graph: SceneGraph | None = None  # belief, once the first survey has built it
        self._searching: set[str] = set()  # objects being looked for: placed nowhere
        #: how often the robot went to look from close by at each set of items (a new stand each time)
        self._near_looks: Counter[tuple[str, ...]] = Counter()
        #: where the base stood when the gripper last said it held each thing, and, while a search
        #: looks for what the hand lost on the way, where belief puts it (:mod:`vap_bt.scene.trail`)
        self._held_at: dict[str, tuple[float, float]] = {}
        self._lost_ways: dict[str, Believed] = {}
        #: where checks did not find items a measurement had put there (a false positive's spot)
        self.misses = Misses()
        self.moves = SightingMoves()  # where a sighting moved an item from: taken back if it proves wrong
        self.s = settings or ExecutiveSettings()
        self.progress = progress
        self.on_tree = on_tree or (lambda tree, tick: None)
        self.on_survey = on_survey or (lambda survey, graph: None)
        self.on_verification = on_verification or (lambda v: None)
        #: told of each situation as the executive takes it up (the runner scores its diagnosis)
        self.on_situation = on_situation or (lambda s: None)
        self.prior = frozenset(prior)
        self.geometry = geometry
        #: ParseGoal (vap_bt.perception.goal_parsing): the goal from words, over the graph's objects
        self.goal_parser = goal_parser
        #: the task's words, for the prompts that show them (the VLM-planner's)
        self.instruction = instruction
        #: which predicates are asked of the VLM and how (default: the domain's own profile)
        self.profile = profile if profile is not None else resolve(task.knowledge)
        #: which predicate plays each role the executive acts on (the profile's): the one that says
        #: the robot is placed to act on a thing (a skill that failed to act from where the robot
        #: stands makes it stale, so the new plan re-approaches), the hand's, where things are
        self.roles = self.profile.roles
        self._prior_graph = SceneGraph.of_facts(prior, roles=self.roles)  # what the task file says, until then
        #: what the senses last showed of each atom, for a situation's diagnosis (vap_bt.bt.diagnosis)
        self.sightings = Sightings(self.roles.hand)
        self._seen_again: set[str] = set()  # the items the recovery under way re-located from a fresh frame
        self._missed: set[str] = set()  # the items its look aimed at belief's place for them did not show
        #: the episode once it has a belief to plan from (before that, :meth:`so_far`)
        self.outcome: EpisodeOutcome | None = None
        self.phase = PHASES[0]  # which of PHASES the episode is in
        if vlm is None and self.s.strategy.asks:
            raise ValueError("verification needs a VLM; use the verification strategy 'none' to run without one")
        if self.s.strategy.vlm_plans and not callable(getattr(vlm, "complete", None)):
            raise ValueError("the VLM-planner needs a VLM that writes text (a real backend)")

    # -- the loop ----------------------------------------------------------------------------

    def so_far(self) -> EpisodeOutcome:
        """The episode up to now, readable at any moment (after a Ctrl-C, for the report)."""
        if self.outcome is not None:
            return self.outcome
        return EpisodeOutcome.nothing_yet(self.graph if self.graph is not None else self._prior_graph)

    def run(self) -> EpisodeOutcome:
        """Run the episode to its end — survey, plan, tick, handle situations, replan — and return how it
        ended. Blocks until then; ``phase`` says meanwhile where it is."""
        self.phase = "survey"
        #: where work in flight runs: the checks' captures and questions, the recovery steps
        with working(self.s.threads) as executor:
            self.executor = executor
            return self._run(executor)

    def _run(self, executor) -> EpisodeOutcome:
        graph, survey = self._survey_in_tree()
        ctx = ExecutionContext(graph=graph, vlm=self.vlm, camera=self.camera, skills=self.skills,
                               strategy=self.s.strategy, budget=self.s.budget, vote=self.s.vote, progress=self.progress,
                               aim=self.builder.aim, approach=self._look_at, hints=self.builder.hints, undetectable=self.builder.undetectable(), unseen=self.s.unseen, felt=self._felt, feels=self._feels,
                               protocol=self.s.protocol, viewpoints=ViewpointStrategy(self.s.viewpoints),
                               second_look=self.s.second_look, claim_risk=self.s.claim_risk,
                               board=Board(verified=Verified(self.s.protocol.reuse, self.roles.hand),
                                           sightings=self.sightings), executor=executor,
                               record=self.on_verification, profile=self.profile)
        out = self.outcome = EpisodeOutcome(False, "", [], [], 0, [], [survey], 0, graph, ctx)
        if self.goal_parser is not None:  # Alg. 1 line 2: ParseGoal comes after BuildSceneGraph
            self.phase = "goal parsing"
            self.task = self.task.with_state(self.task.init, self.goal_parser(sorted(graph.objects)))
            self.progress(f"goal from words: {', '.join(map(str, self.task.goal))}")
        if self.s.strategy.vlm_plans:
            return self._run_vlm_planner(ctx, out)
        self.phase = "planning"
        try:
            plan = self.planner.plan(graph.state(), self.task.goal)
        except (UnsolvableError, PlanningTimeout) as exc:
            out.reason = f"no initial plan: {exc}"
            out.no_initial_plan = "timeout" if isinstance(exc, PlanningTimeout) else "unsolvable"
            return out
        out.plans.append(plan)
        self.progress(f"plan ({plan.engine}, {plan.seconds * 1000:.0f} ms): {len(plan)} actions")
        tree = self._tree(ctx, plan)
        self.phase = "acting"
        try:
            return self._tick_until_done(tree, ctx, plan, out, time.monotonic() + self.s.max_seconds)
        finally:
            self.halt(tree)
            ctx.close()  # the body's worker, if a check asked the gripper

    def _run_vlm_planner(self, ctx: ExecutionContext, out: EpisodeOutcome) -> EpisodeOutcome:
        """The VLM-planner baseline instead of plan, compile and tick (:mod:`vap_bt.bt.vlm_planner`):
        the model names each action, the skills execute it, nothing is checked."""
        self.phase = "acting"
        loop = VlmPlanner(ctx, self.vlm, self.task, self.instruction, self.s.max_steps,
                          drive=lambda tree, deadline: self._drive(tree, deadline, out), rejoin=self._rejoin)
        out.proposals = loop.record.proposals  # readable as it fills (a Ctrl-C's report)
        try:
            run = loop.run(time.monotonic() + self.s.max_seconds)
        finally:
            ctx.close()
        out.success, out.reason = run.success, run.reason
        return out

    def _tick_until_done(self, tree, ctx: ExecutionContext, plan: Plan, out: EpisodeOutcome,
                         deadline: float) -> EpisodeOutcome:
        # the tree ticked last is halted however this ends (a replan replaces the one run() built,
        # and a time budget or Ctrl-C may come while the replanned tree has a goal in flight)
        try:
            graph, board = out.graph, ctx.board
            repeats = RepeatWatch()
            doubted: Counter[Atom] = Counter()  # observations doubted because they left no plan
            redone: set[Atom] = set()  # goal atoms no view confirmed, handed back to the planner once
            while time.monotonic() < deadline:
                tree.tick()
                out.ticks += 1
                if board.situation is not None:  # diagnosed before the live view shows it
                    self._diagnose(board.situation)
                self.on_tree(tree, out.ticks)
                status = tree.root.status
                if status == Status.SUCCESS and not board.unconfirmed_goal:
                    out.success, out.reason = True, "goal reached"
                    return out
                if status == Status.RUNNING:
                    if self.s.tick_period_s:
                        time.sleep(self.s.tick_period_s)
                    continue
                unconfirmed = list(board.unconfirmed_goal)
                if status == Status.SUCCESS:  # the tree got through, but the camera could not confirm the goal
                    situation = self._diagnose(unconfirmed_goal(unconfirmed, len(plan.actions)))
                    board.unconfirmed_goal.clear()
                else:
                    situation, board.situation = board.situation, None
                if situation is None:
                    out.reason = "the tree failed without a situation"
                    return out
                self.phase = "replanning"
                out.situations.append(situation)
                self.on_situation(situation)
                before = placed(situation, graph, self.sightings)  # for the diagnosis' review once it is handled
                if situation.kind == "execution" and situation.action is not None:
                    self._rejoin(situation.action.name)  # raises TransportError: nobody drives it
                if situation.kind == "unseen" and self.s.unseen == "stop":
                    out.reason = f"stopped: {situation.detail}"
                    return out
                times = repeats.count(situation, graph.state())
                if stuck(situation, times) and situation.kind == "unseen" and situation.action is not None \
                        and situation.atom not in board.on_belief:
                    # looked again and again, and no view shows it well enough: act on belief
                    # (the action's effects are checked) rather than give the episode up — on the
                    # action's other preconditions about the same thing too, which the same views
                    # show no better (retrieve_bottles seed 0: inview, reachable and on of a bottle
                    # the views never showed, each looked at three times, nine replans)
                    board.on_belief |= seen_together(situation.atom, situation.action)
                    self.progress(f"    could not see {situation.atom} after {times} looks: acting on belief")
                elif stuck(situation, times) and situation.kind == "action_infeasible" \
                        and str(situation.action) not in board.actions_on_trial:
                    # looking afresh brought the robot back to the same "no": the skill is the test
                    board.actions_on_trial.add(str(situation.action))
                    self.progress(f"    {situation.action} said impossible {times} times: trying it against that")
                elif contested(situation, times) and situation.atom not in board.on_trial:
                    # denied again and again from the same belief, which looking afresh restores
                    # each time: the same pictures will say the same, so the skill is the test
                    board.on_trial.add(situation.atom)
                    self.progress(f"    {situation.atom} denied {times} times from the same belief: "
                                  f"trying {situation.action} against it")
                elif stuck(situation, times) and situation.atom not in redone \
                        and (how := why_redone(situation, board, ctx.calibration)):
                    # the action may have failed unseen (halve_egg seed 3: a cut that did not cut,
                    # its effect unsettled, three goal checks unsettled): do it again, once
                    redone.add(situation.atom)
                    # the goal checks after the redo see what it did: their count starts anew
                    # (boil_water seed 128: filled(cup) unseen three times, the cup refilled, and
                    # the first goal check after it, unsettled, made the fourth: stuck)
                    repeats.forget(situation.atom)
                    graph.correct(situation.atom, not situation.expected,
                                  self.task.knowledge.complements.get(situation.atom.predicate), cause="unconfirmed")
                    self.progress(f"    {situation.atom} {how} after {times} looks: doing it again")
                elif stuck(situation, times) and status == Status.SUCCESS \
                        and (earlier := self._standing(unconfirmed, board, ctx.calibration)):
                    # no goal check could settle it, however often the robot went back to look; the
                    # check that confirmed it after the action that brought it about still stands
                    board.goal_evidence = resting_on_earlier(board.goal_evidence, earlier, board.verifications)
                    out.success = True
                    out.reason = ("goal reached: " + ", ".join(map(str, earlier))
                                  + f" on the check that confirmed it (its goal checks could not settle it, {times} times)")
                    return out
                elif stuck(situation, times):
                    out.reason = (f"stuck: {describe(situation)}, {times} times from the same belief "
                                  "(looking afresh changed nothing)")
                    return out
                if out.replans >= self.s.max_replans:
                    out.reason = f"replanning budget ({self.s.max_replans}) exhausted"
                    return out
                t0 = time.perf_counter()
                if situation.kind == "execution" and situation.action is not None:
                    board.doubted |= {lit.atom for lit in situation.action.preconditions
                                      if lit.positive and lit.atom.predicate != self.roles.in_view}
                recovered, survey = self._recover(graph, situation, times, out, deadline,
                                                  shown_by_check(situation, board.verifications, frozenset(self.roles.support)))
                review(situation, before, self._seen_again, graph, self._missed)
                if not recovered:
                    break  # the time budget ran out while the robot was looking
                if survey is not None:
                    out.surveys.append(survey)
                try:
                    plan = self._replan(graph, situation, plan, doubted, board.on_trial,
                                        lambda look: self._drive(look, deadline, out))
                except (UnsolvableError, PlanningTimeout) as exc:
                    out.reason = f"no plan after {situation.kind} situation: {exc}"
                    return out
                self.halt(tree)
                tree = self._tree(ctx, plan)
                out.replan_seconds.append(time.perf_counter() - t0)
                out.replans += 1
                out.plans.append(plan)
                self.progress(f"replan #{out.replans} ({replan_timing(plan, out.replan_seconds[-1])}): "
                              f"{len(plan)} actions")
                self.phase = "acting"
            out.reason = f"time budget ({self.s.max_seconds:g} s) exhausted"
            return out
        finally:
            self.halt(tree)

    def _standing(self, atoms: list[Atom], board: Board, calibration: Calibration) -> dict[Atom, int]:
        """Each goal atom in ``atoms`` (no goal check could settle them) with the earlier check it
        still rests on (:func:`~vap_bt.bt.goal_check.standing_confirmation`), or nothing unless
        every one has one; never where a thing rests, which a slip or a nudge moves with no action
        of the plan, nor where the views since weigh against it (:func:`~vap_bt.bt.goal_check.leans_against`)."""
        expected = {l.atom: l.positive for l in self.task.goal}
        verified, checks = board.verified, board.verifications

        def rests_on(a: Atom) -> int | None:
            value = expected.get(a, True)
            if leans_against(a, value, verified.views(a), calibration):
                return None
            # among the views since the last action that could change it, else the last check that
            # settled it, while no action since could undo that value (:meth:`Verified.standing`)
            for views in (verified.views(a), verified.standing(a)):
                if (i := standing_confirmation(a, value, checks, views)) is not None:
                    return i
            # no check settled it: the action that made it, seen to have happened
            return confirmed_by_its_action(a, value, checks, verified.ran, verified.hand)

        earlier = {a: rests_on(a) for a in atoms if not self.roles.supports(a)}
        return earlier if atoms and len(earlier) == len(atoms) and None not in earlier.values() else {}

    def _diagnose(self, s: Situation) -> Situation:
        """``s`` with the executive's diagnosis of it (:mod:`vap_bt.bt.diagnosis`), made once: from
        what the senses had shown before it."""
        if s.diagnosis is None:
            s.diagnosis, s.diagnosis_basis = diagnose(s, self.sightings, self.graph)
            self.sightings.watch(s)  # a later look may show the view that raised it erred
        return s

    def _rejoin(self, action: str) -> None:
        """Wait for ``action``'s robot to have a skill server again, if the client can tell
        (:meth:`~vap_bt.transport.client.ZenohSkillClient.rejoin`); in-process skills always do."""
        rejoin = getattr(self.skills, "rejoin", None)
        if rejoin is None:
            return
        robot = self.skills.routes.get(action)
        if robot is not None and not self.skills.servers(robot):
            self.progress(f"    no skill server of robot {robot!r} is up: waiting for one")
        back = rejoin(action)
        if back is not None:
            self.progress(f"    {back}")

    def _replan(self, graph: SceneGraph, s: Situation, plan: Plan, doubted: Counter, on_trial: set[Atom],
                drive: Callable[[py_trees.trees.BehaviourTree], bool]) -> Plan:
        """A plan from the corrected belief. When the correction leaves none, the observation
        behind it is doubted: a camera that errs (as every real one does, and the more so about a
        relation it saw poorly) can report a fact that shuts every way to the goal — the cup "not
        reachable" with nothing in front of it. Belief goes back to what it held, the robot
        re-approaches what the atom is about (a new picture, not the one that misled it: a model
        answers one picture the same way every time), and the next plan checks the atom again. An
        observation is doubted at most :data:`MAX_DOUBTS` times; an effect observed missing never
        is (belief already went back to what it held). A denied *precondition* that
        still leaves no plan is then put on trial (``on_trial``): the action is tried against it —
        its skill fails if the camera was right, and that failure is the situation that stands.
        A check that could not see its atom, after whose look belief no longer holds what the plan
        presumed, leaves belief as it was (no view denied it). The look a doubt takes is a
        recovery tree, ``drive``-n like the situation's own."""
        try:
            return self.planner.replan(graph.state(), plan.actions[s.step:], self.task.goal)
        except UnsolvableError:
            recourse = self._recourse(graph, s, doubted)
            if recourse is None:
                raise
        # belief back to what the plan presumed: what it held before an unseen check, the
        # opposite of what a doubted or tried observation said
        value = s.expected if recourse == "belief" else not s.observed
        graph.correct(s.atom, value, self.task.knowledge.complements.get(s.atom.predicate), cause=recourse)
        if recourse == "belief":
            self.progress(f"    {s.atom} is what every plan needs, and no view denied it: believing it again")
        elif recourse == "trial":
            on_trial.add(s.atom)
            self.progress(f"    {s.atom} = {s.observed} still leaves no plan: the action will be tried against it")
        else:
            doubted[s.atom] += 1
            self.progress(f"    {s.atom} = {s.observed} leaves no plan: doubting it, looking again")
            look = Step(f"look at {', '.join(s.atom.args)}", lambda: self._look_at(graph, s.atom.args),
                        self.executor, self._halt)
            drive(recovery_tree(f"doubting {s.atom}", [look]))
        return self.planner.replan(graph.state(), plan.actions[s.step:], self.task.goal)

    @staticmethod
    def _recourse(graph: SceneGraph, s: Situation, doubted: Counter) -> str | None:
        """What to do when the corrected belief leaves no plan (:meth:`_replan`): "belief" (an
        unseen atom the look dropped is held again), "doubt", "trial", or None (the situation
        stands). An effect observed missing is the check doing its work: belief already went
        back to what it held before the action, and doubting it would believe the action worked
        (cut_lemon seed 0 with injection: a failed cut, the knife lost, "sliced" doubted into
        belief and then claimed)."""
        if s.atom is None or s.kind == "effect":
            return None
        spent = doubted[s.atom] >= MAX_DOUBTS
        if s.observed is None:
            # no view could tell, and the look that followed dropped what the plan presumed (a
            # re-survey's geometry does not see a bowl blocking a plate it cannot see)
            return "belief" if s.kind == "unseen" and (s.atom in graph.facts) != s.expected and not spent else None
        if not spent:
            return "doubt"
        # (already on trial when it was denied from the same belief once too often: belief goes back all the same)
        return "trial" if s.kind == "precondition" else None

    @staticmethod
    def halt(tree: py_trees.trees.BehaviourTree) -> None:
        """Stop every running behaviour (each cancels what it has in flight in ``terminate``)."""
        if tree.root.status == Status.RUNNING:
            tree.root.stop(Status.INVALID)

    def _tree(self, ctx: ExecutionContext, plan: Plan) -> py_trees.trees.BehaviourTree:
        ctx.board.goal_evidence = None  # a claim rests on the new tree's own goal checks
        return PlanTree(compile_plan(ctx, plan.actions, self.task.goal, self.task.knowledge))

    # -- perception ----------------------------------------------------------------------------

    def perceive(self) -> tuple[SceneGraph, Survey]:
        """BuildSceneGraph: sweep every room the robot can reach, then assemble the belief (at
        once, outside any tree: the benchmarks of the survey alone call this)."""
        graph, sweep, prior_only = self._sweep_site()
        return self._finish_survey(graph, sweep, prior_only, self._ask_states(graph))

    def _survey_in_tree(self) -> tuple[SceneGraph, Survey]:
        """BuildSceneGraph as a tree the executive ticks: the sweep of every room, then the VLM
        asked which doors and drawers are open; each step in flight, halted like any other."""
        swept = Step("survey: sweep the rooms", self._sweep_site, self.executor, self._halt)
        asked = Step("survey: ask what is open", lambda: self._ask_states(self.graph), self.executor, self._halt)
        self._drive(recovery_tree("the first survey", [swept, asked]), None)
        return self._finish_survey(*swept.result, asked.result)

    def _sweep_site(self) -> tuple[SceneGraph, SweepRecord, set[str]]:
        """The survey's sweep and the belief assembled from it (``self.graph`` from then on),
        with the items only the task file places."""
        k = self.task.knowledge
        site_map = self.body.site_map()
        self.builder = SceneGraphBuilder(k, self.task.objects, site_map, self.geometry, self.roles)
        self.identifier = Identifier({n: label_of(n, site_map) for n in self.task.objects}, site_map,
                                     roles=self.roles)
        start = self.body.state().room
        rooms = sweep_order(site_map, start)
        self.progress(f"survey: {len(rooms)} room(s) {', '.join(rooms) or '(no map rooms)'}")
        sweep = self.builder.sweep(self.camera, rooms)
        items = [o for o in self.task.objects if self._portable(o)]
        def unplaced() -> list[str]:
            return [o for o in items if not self.builder.placed(o) and not self._said_where(o)]

        if unplaced():  # a detector misses things now and then: look round once more before giving up
            self.progress(f"survey: {', '.join(unplaced())} not seen; looking again")
            sweep = self.builder.sweep(self.camera, rooms).after(sweep)
        if unplaced():
            sweep = self._closer_looks(sweep, rooms, unplaced,
                                       lambda: f"survey: {', '.join(unplaced())} still not seen;")
        state = self.body.state()
        located, prior_only = belief.item_facts(self.builder, items, self.prior)
        facts = belief.map_facts(site_map, self.roles) | belief.robot_facts(state, sweep, site_map, self.roles) \
            | belief.hand_facts(state, self.builder)
        facts |= located
        # the prior's other statements (states, and anything of a domain without a site map)
        surveyed = bool(site_map.rooms)  # without a site to look round, the prior is all there is
        facts |= {a for a in self.prior if not surveyed or a.predicate not in self.builder.geometric
                  | self.roles.robot | self.roles.hand}
        graph = SceneGraph({n: self.builder.node(n) for n in self.task.objects},
                           belief.typed(facts, k, self.task.objects),
                           tracks_hand=self.roles.tracks_hand, roles=self.roles)
        for n, obj in graph.objects.items():
            if obj.centroid is not None and n not in prior_only:  # the prior's place is not where it was seen
                graph.objects[n] = obj.seen(located=frozenset(graph.location(n)))
        for o in items:  # what the frames showed of each item (nothing of one only the prior places)
            self.sightings.saw(self.builder.observed(o), True, "survey")
            if o not in prior_only:  # the survey moved it from the task file's place: taken back if it proves wrong
                self.moves.note(o, self._told_place(o), graph.location(o))
        self.sightings.saw(belief.robot_facts(state, sweep, site_map, self.roles), True, "survey")
        self.sightings.saw(belief.hand_facts(state, self.builder), True, "gripper")
        self.graph = graph
        return graph, sweep, prior_only

    def _told_place(self, o: str) -> set[Atom]:
        """Where the task file's prior puts item ``o`` (none: it says nothing of it), with the room
        of the piece it is on or in where the prior names no room (boil_water: "inside(cup,
        cabinet)" alone; boil_water seed 20 in pybullet: the survey put the cup on the counter,
        three grasps there did not see it, and belief kept it there until stuck)."""
        told = {a for a in self.prior if a.predicate in self.roles.location and a.args and a.args[0] == o}
        if not any(map(self.roles.supports, told)):
            return set()
        if self.roles.in_room is not None and not any(a.predicate == self.roles.in_room for a in told):
            told |= {Atom(self.roles.in_room, (o, piece.room)) for a in told if self.roles.supports(a)
                     and (piece := self.builder.site_map.piece(a.args[1])) is not None}
        return told

    def _finish_survey(self, graph: SceneGraph, sweep: SweepRecord, prior_only, states: list[StateAnswer]
                       ) -> tuple[SceneGraph, Survey]:
        """Belief completed after the survey's questions: the closed world's defaults, the record."""
        site_map, k = self.builder.site_map, self.task.knowledge
        graph.facts |= belief.typed(belief.closed_world_defaults(graph.facts, site_map, self.task.objects, k,
                                                                 self.roles), k, self.task.objects)
        survey = Survey("initial", sweep, states, graph.state(), tuple(sorted(prior_only)))
        self.progress(f"survey: {sweep.frames} frames from {sweep.reached}/{sweep.views} views in "
                      f"{sweep.seconds:.2f} s; {len(sweep.detected)} objects seen"
                      + (f"; placed by the task file only: {', '.join(sorted(prior_only))}" if prior_only else ""))
        self.on_survey(survey, graph)
        return graph, survey

    def _identify(self, frame: Frame) -> Frame:
        """Name the frame's detections (:mod:`vap_bt.scene.identity`) against belief now: the
        scene graph (during the first sweep, what its frames showed so far, then the task file),
        the gripper and what belief has in it, the tool point and the room localization gives.
        What the robot is looking for is placed nowhere, so that it is taken where it is seen."""
        graph = self.graph if self.graph is not None else self._prior_graph
        state = self.body.state()
        held = next((a.args[0] for a in sorted(graph.facts) if self.roles.is_held(a)), None)
        if state.gripper_holding is False:
            held = None  # an empty gripper holds nothing, whatever belief says
        # a thing looked for is placed nowhere until this search has seen it, and then where it
        # did; so is, with depth, any item whose sightings place it on or in nothing: a false
        # positive of its class against a wall or 0.9 m up in the wrong room, taken for it, would
        # otherwise pin it there, and the real one would never be taken (without pixels, a
        # detection's reports place it)
        unplaced = {n for n in self._searching if not self.builder.detected(n)}
        if self.geometry is not None:
            in_hand = (held,) if held else ()
            unplaced |= {n for n in self.task.objects if self._portable(n) and n not in in_hand
                         and self.builder.detected(n) and not self._placed_anew(n, in_hand)}
        belief = {}
        for n in self.task.objects:
            if n in unplaced:
                if n in self._lost_ways:  # the hand lost it on the way: it lies near the way
                    belief[n] = self._lost_ways[n]
                continue
            b = self.builder.believed(graph, n, seen_first=self.graph is None or n in self._searching)
            if b is not None:
                belief[n] = b
        hand = tuple(state.tcp_pose[:3]) if state.tcp_pose is not None else None
        named = self.identifier.identify(frame, belief, held, hand, state.room)
        seen = {d.name for d in named.detections if d.name}
        self.builder.forget(seen & unplaced)  # this sighting replaces one that placed it nowhere
        self.builder.saw(seen)
        return named

    def _said_where(self, obj: str) -> bool:
        return any(a.predicate in self.roles.location and a.args and a.args[0] == obj for a in self.prior)

    def _ask_states(self, graph: SceneGraph) -> list[StateAnswer]:
        """Ask the VLM whether each openable thing seen (a door, a drawer, a fridge) is open;
        believe what settles. What the map says cannot be opened or shut (a basket) is not asked:
        its state is rigid, and a view that judged a basket "not open" left no plan to put logs in
        it (store_firewood seeds 7 and 10). Without ``openable`` in the domain, every container."""
        opened, container = self.roles.open, self.roles.container
        if self.vlm is None or opened is None or not self.profile.asks(opened, 1):
            return []
        k = self.task.knowledge
        sig = k.predicates[opened][0]
        if self.roles.openable is not None:
            askable = {a.args[0] for a in self.builder.site_map.facts if a.predicate == self.roles.openable}
        else:
            askable = {f.name for f in self.builder.site_map.furniture if container is not None
                       and k.is_subtype(f.type, container)}
        candidates = [n for n in sorted(self.builder.evidence) if n in askable and k.is_subtype(self.task.objects[n], sig)]
        with working(self.s.threads) as executor:
            vote, protocol = asking(self.s.strategy, self.s.vote, self.s.protocol)
            answers = survey_states(self.vlm, self.builder.best_frames(), candidates, vote, self.profile,
                                    predicates=(opened,), protocol=protocol, undetectable=self.builder.undetectable(),
                                    executor=executor)
        complement = k.complements.get(opened)
        for a in answers:
            if a.value is not None:
                graph.correct(a.atom, a.value)
                self.sightings.saw((a.atom,), a.value, "survey")
                if complement:  # open and closed are exclusive: the answer settles both
                    graph.correct(Atom(complement, a.atom.args), not a.value)
        return answers

    def _recover(self, graph: SceneGraph, s: Situation, times: int, out: EpisodeOutcome,
                 deadline: float, shown: bool = False) -> tuple[bool, Survey | None]:
        """Handle situation ``s`` in a recovery tree (:mod:`vap_bt.bt.recovery`) the executive
        ticks — and the live view draws — until its steps are done: belief corrected from what was
        observed, a look at what a check could not make out, the gripper asked, the items involved
        re-located and, when lost, looked for; and when the same situation came back from the same
        belief (``times``), a look round before the same plan — after which a thing a check could
        not make out is looked at again, so that the next check starts from a view of it. Returns whether it finished before
        the time budget ran out, and the re-survey it took, if any."""
        executor, halt = self.executor, self._halt
        self._seen_again, self._missed = set(), set()
        steps = [Step("correct belief", lambda: self._correct_belief(graph, s, shown), executor, halt)]
        if s.kind == "unseen" and s.atom is not None:
            steps.append(Step(f"look at {', '.join(s.atom.args)}", lambda: self._look_at(graph, s.atom.args),
                              executor, halt))
        # each step reads what the one before it found from that step's result
        feel = Step("feel the hand", lambda: self._feel_hand(graph, s), executor, halt)
        relocate = Step("re-locate what it is about", lambda: self._relocate_involved(graph, s, feel.result),
                        executor, halt)

        def look_for() -> Survey | None:
            if relocate.result:
                return self._resurvey(graph, relocate.result, worked=self._worked(s), carried=carried(feel.result))
            if times >= LOOK_AFRESH:  # the same failure again: look round before the same plan
                return self._look_afresh(graph, s)
            return None

        def carried(dropped: list[str]) -> tuple[str, ...]:  # what left the hand: belief's, or the check's
            held = s.atom is not None and self.roles.is_held(s.atom) and s.observed is False
            return tuple(dict.fromkeys([*dropped, *((s.atom.args[0],) if held else ())]))

        search = Step("look for what is lost", look_for, executor, halt)
        steps += [feel, relocate, search]
        if s.kind == "unseen" and s.atom is not None:
            # a search walks the robot round rooms and leaves it where its last view stood, and the
            # check that follows starts from there, not from the look above (boil_water seed 211 in
            # pybullet: each look at the cup in the microwave, from its front, was followed by a
            # re-survey for it, and every goal check began at the survey's last stand, beside the
            # microwave, whose side hid the cup: the same four pictures, three times, then "stuck")
            steps.append(Step(f"look at {', '.join(s.atom.args)} again",
                              lambda: search.result is not None and self._look_at(graph, s.atom.args), executor, halt))
        done = self._drive(recovery_tree(describe(s), steps), deadline, out)
        return done, search.result

    def _drive(self, tree: py_trees.trees.BehaviourTree, deadline: float | None,
               out: EpisodeOutcome | None = None) -> bool:
        """Tick a recovery's tree until its steps are done (drawn for the live view when ``out``
        counts the episode's ticks); False when the time budget ran out first. Halted however it
        ends, so no step is left in flight."""
        if out is not None:  # drawn before its first tick, at a tick of its own on the live view's
            out.ticks += 1  # timeline: what it is about comes before what it does
            self.on_tree(tree, out.ticks)
        try:
            while True:
                tree.tick()
                if out is not None:
                    out.ticks += 1
                    self.on_tree(tree, out.ticks)
                if tree.root.status != Status.RUNNING:
                    return True
                if deadline is not None and time.monotonic() >= deadline:
                    return False
                time.sleep(RECOVERY_POLL_S)
        finally:
            self.halt(tree)

    def _correct_belief(self, graph: SceneGraph, s: Situation, shown: bool = False) -> None:
        """Bring belief in line with what was observed (steps 1–3 of the module docstring);
        ``shown``: the check's views showed the thing it is about (:func:`shown_by_check`)."""
        if not shown:
            self._note_miss(graph, s)
        if s.kind in ("effect", "action_failed") and s.action is not None:
            graph.undo(s.action)
        if s.atom is not None and s.observed is not None:
            graph.correct(s.atom, s.observed, self.task.knowledge.complements.get(s.atom.predicate))
            self.sightings.saw((s.atom,), s.observed, "check")  # what the situation's check showed
        if s.kind in ("execution", "action_infeasible") and s.action is not None:
            for lit in s.action.preconditions:
                if lit.positive and lit.atom.predicate == self.roles.in_view:
                    graph.correct(lit.atom, False)
        if s.unmet is not None:  # the skill's camera found a precondition false (a fridge shut)
            graph.correct(s.unmet, False, self.task.knowledge.complements.get(s.unmet.predicate))
            self.sightings.saw((s.unmet,), False, "skill")

    def _relocate_involved(self, graph: SceneGraph, s: Situation, dropped: list[str]) -> list[str]:
        """Re-locate the portable things the situation is about (and what the hand dropped) from
        a fresh frame; returns those that are lost."""
        involved = tuple(dict.fromkeys((*(s.action.args if s.action else ()), *(s.atom.args if s.atom else ()),
                                        *dropped)))
        portable = [o for o in involved if self._portable(o)]
        if not portable:
            return []
        lost = self._relocate(graph, portable)
        return lost + [o for o in portable if o not in lost
                       and not any(self.roles.supports(a) or self.roles.is_held(a) for a in graph.location(o))]

    def _look_afresh(self, graph: SceneGraph, s: Situation) -> Survey:
        """A situation came back unchanged: re-survey for the items it is about (or round the
        robot's room when it is about none), so the next plan starts from fresh frames rather
        than from the belief that led to the same failure."""
        names = (*(s.action.args if s.action else ()), *(s.atom.args if s.atom else ()))
        items = list(dict.fromkeys(o for o in names if self._portable(o)))
        return self._resurvey(graph, items, f"{describe(s)} again", self._worked(s))

    def _look_at(self, graph: SceneGraph, names: tuple[str, ...]) -> bool:
        """Go and look at what a check could not make out: the sweep's own view of a piece of
        furniture or a door; about an item in or on a container open at the top, the container's
        top from close by (a log in a basket shows from above: three views of the basket's front
        judged it outside, store_firewood seed 4); about items only, a view from close by of where
        belief puts them. From close by, another stand each time (the same stand would show the
        same picture, which a model answers the same way). What could not be made out is not in
        view: the new plan re-approaches it. Returns whether the robot reached a view (belief's
        robot facts are then those of where it stands)."""
        for a in names:
            if Atom(self.roles.in_view, (a,)) in graph.facts:
                graph.correct(Atom(self.roles.in_view, (a,)), False)
        # an item and a container open at the top: the container's top from close by
        tops = [n for n in names if self.builder.opens_on_top(n)] if any(map(self._portable, names)) else []
        view = next((v for n in names if not tops and not self._portable(n) and (v := self.builder.view_of(graph, n))), None)
        near = [] if view else next((vs for n in (tops or names) if (vs := self.builder.near_views(graph, n))), [])
        if near:
            self._near_looks[names] += 1
            turn = self._near_looks[names] % len(near)  # round the stands, a new one each time
            view = next((v for v in near[turn:] + near[:turn] if self.camera.goto_view(v)), None)
        elif view is not None and not self.camera.goto_view(view):
            view = None
        if view is not None:
            self.progress(f"    looking again: {view.label}")
            sweep = SweepRecord((view.room,), 1, 1, 0, last_view=view, last_frame=self.camera.capture(view.aim))
            self.builder.integrate(sweep.last_frame)
            graph.replace_predicates(self.roles.robot - {self.roles.in_view},
                                     belief.robot_facts(self.body.state(), sweep, self.builder.site_map, self.roles),
                                     "look")
        return view is not None

    def _feel_hand(self, graph: SceneGraph, s: Situation) -> list[str]:
        """An empty gripper holds nothing, whatever belief says (proprioception). Returns what
        belief had in the hand: it is somewhere else now, and must be looked for. A gripper that
        holds something belief does not: see :meth:`_held_after_all`."""
        felt = self.body.state().gripper_holding
        if felt and not any(self.roles.is_held(a) for a in graph.facts):
            self._held_after_all(graph, s)
            # what belief now has in the hand, the fingers hold: a look that judged it not taken erred
            self.sightings.saw([a for a in graph.facts if self.roles.is_held(a)], True, "gripper")
            return []
        if felt is not False:
            return []
        held = sorted(a for a in graph.facts if self.roles.is_held(a))
        for a in held:
            graph.correct(a, False, cause="gripper")
            self._let_go(graph, s, a.args[0])
        self.sightings.saw(held, False, "gripper")
        empty = self.roles.hand_empty
        if empty is not None and Atom(empty) not in graph.facts:
            graph.correct(Atom(empty), True, cause="gripper")
        return [a.args[0] for a in held]

    def _let_go(self, graph: SceneGraph, s: Situation, name: str) -> None:
        """The hand let ``name`` go in ``s``'s action, which was to put it somewhere (a placing
        whose effect a check denied): where it was to go is the place to go back to if the search
        finds it nowhere (:mod:`vap_bt.scene.moves`). heat_pie seed 29 in pybullet: the pie set
        into the oven, a look judged it not inside, the sweeps do not see into the oven, and the
        episode ended with no plan for a pie placed nowhere."""
        put = {a for a in (s.action.may_add if s.action is not None else ())
               if a.predicate in self.roles.location and a.args[0] == name and not self.roles.is_held(a)}
        if any(map(self.roles.supports, put)):
            self.moves.note(name, put, graph.location(name))

    @staticmethod
    def _held_after_all(graph: SceneGraph, s: Situation) -> None:
        """The gripper holds something belief does not: what. After an action that was to take
        one thing into the hand, that thing — the action stopped after the fingers closed (a lift
        or a withdrawal blocked), or a look judged the hand empty, or a SuccessVQA question said
        the action failed: one view against the fingers' word — and the action's effects are
        believed as if it had succeeded. After a check that
        the hand holds an item, or that it is empty, said no: the item, or the last one a check
        took out of the hand (store_firewood seed 4: a view judged the log not held, and the robot
        searched two rooms for the log in its own hand until the replanning budget ran out)."""
        if s.action is not None and s.kind in ("execution", "effect", "action_failed"):
            took = [a for a in s.action.diff(graph.state()).added if graph.roles.is_held(a)]
            if len(took) == 1 and (s.kind != "effect" or s.atom in took):
                graph.apply(s.action)
                return
        if s.atom is None or s.observed is not False:
            return
        item = s.atom.args[0] if graph.roles.is_held(s.atom) else None
        if s.atom.predicate == graph.roles.hand_empty:
            item = last_taken_from_hand(graph)
        if item is not None:
            graph.relocate(item, {graph.roles.holding(item)})

    def _relocate(self, graph: SceneGraph, portable: list[str]) -> list[str]:
        """Look where belief puts ``portable``; re-locate what the frame shows. Returns the objects
        that should have been in sight and were not."""
        aim = self.builder.aim(graph, tuple(portable))
        self.builder.forget(portable)
        frame = self.camera.capture(aim)
        seen = self.builder.integrate(frame)
        lost = []
        in_hand = self._in_hand(graph)
        for o in portable:
            if o in in_hand:
                continue  # belief holds it and the gripper feels something: it is in the hand
            observed = self.builder.observed(o, in_hand) if o in seen else set()
            if self._placed_anew(o, in_hand):
                self._relocated(graph, o, observed)
            elif self._at_miss(o) or self._expected_in_sight(graph, o):
                lost.append(o)  # the camera turned toward where belief puts it, and it is not there
                if o not in seen:  # not seen at all (not only where a check found it missing)
                    self._missed.add(o)
        return lost

    def _relocated(self, graph: SceneGraph, o: str, observed: set[Atom]) -> None:
        """Believe ``o`` where a frame shows it now (``observed``), and that it was seen there."""
        before = graph.location(o)
        change = graph.relocate(o, observed)
        if any(self.roles.supports(a) for a in before):  # only a place to go back to: not a room alone
            self.moves.note(o, before, graph.location(o))
        graph.objects[o] = self.builder.node(o).seen(located=frozenset(graph.location(o)))
        self.sightings.saw(graph.location(o), True, "re-location")
        self._seen_again.add(o)
        self.sightings.saw(change.removed - graph.facts, False, "re-location")

    def _worked(self, s: Situation) -> tuple[str, ...]:
        """The pieces of furniture the situation's action worked at (a fridge a pie was taken
        from): what slips from the hand there falls on the floor at their front."""
        return tuple(n for n in (s.action.args if s.action else ()) if self.builder.site_map.piece(n) is not None)

    def _resurvey(self, graph: SceneGraph, lost: list[str], why: str | None = None,
                  worked: tuple[str, ...] = (), carried: tuple[str, ...] = ()) -> Survey:
        """Sweep the rooms belief put the lost objects in and the robot's own; if that does not
        find them, the rest of the house; then the floor along every wall of those rooms, until
        they are found. Every item the sweep saw is re-located. ``why``: the
        reason to look, when it is not that ``lost`` are lost; ``carried``: what the hand lost in
        the situation, believed near the way it was carried while it is looked for."""
        state = self.body.state()
        here = state.room
        near = sorted({a.args[1] for o in lost for a in graph.facts if a.predicate == self.roles.in_room and a.args[0] == o}
                      - {here}) + ([here] if here else [])
        self.progress(f"    {why or 'lost track of ' + ', '.join(lost)}: re-surveying {', '.join(near)}")
        items = [o for o in self.task.objects if self._portable(o)]
        self.builder.forget(items)
        self._searching = set(lost)  # placed nowhere while looked for: taken wherever first seen
        self._lost_ways = self._ways(lost, carried, state.base_pose)  # but what the hand lost: near its way
        try:
            return self._search(graph, lost, why, near, items, worked)
        finally:
            self._searching, self._lost_ways = set(), {}

    def _ways(self, lost: list[str], carried: tuple[str, ...], here) -> dict[str, Believed]:
        """Where belief puts each of ``lost`` the hand lost while the base drove: near the way from
        where the gripper last held it to where the base is (``here``; :mod:`vap_bt.scene.trail`)."""
        if here is None:
            return {}
        return {o: lost_on_the_way(self._held_at[o], here[:2]) for o in carried if o in lost and o in self._held_at}

    def _search(self, graph: SceneGraph, lost: list[str], why: str | None, near: list[str], items: list[str],
                worked: tuple[str, ...] = ()) -> Survey:
        """The sweeps of a re-survey (:meth:`_resurvey`)."""
        here = self.body.state().room
        # an item that slipped from the hand lies on the floor near the robot (or under its base,
        # if it drove on), or at the front of the piece the hand worked at (a pie the hand lost on
        # its way out of the fridge, a metre from the base): look at the floor round those first
        state = self.body.state()
        spots = [state.base_pose[:2]] if here and state.base_pose else []
        spots += [p for n in worked if (p := self.builder.front_spot(n)) is not None] if here else []
        around = tuple(v for p in spots for v in self.builder.spot_views(here, p))
        in_hand = self._in_hand(graph)

        def unfound() -> list[str]:  # a sighting where a check found it missing is not (yet) taken
            return [o for o in lost if o not in in_hand and not self._placed_anew(o, in_hand)]

        def found() -> bool:
            return not unfound()

        sweep = self.builder.sweep(self.camera, near, first=around)
        trail = self._trail(state)
        if trail and not found():
            self.progress(f"    not there: looking along the way {', '.join(self._lost_ways)} was carried")
            sweep = self.builder.look_round(self.camera, trail, until=found).after(sweep)
        rest = [r for r in sweep_order(self.builder.site_map, self.body.state().room) if r not in near]

        if rest and not found():
            self.progress(f"    not there: searching {', '.join(rest)}")
            sweep = self.builder.sweep(self.camera, rest).after(sweep)
        if not found():
            sweep = self._closer_looks(sweep, [*near, *rest], unfound, lambda: "    still not found:")
        for o in items:
            if o in lost and self._taken_back(graph, o, in_hand):
                continue
            observed = self.builder.observed(o, in_hand)
            if o not in in_hand and self.builder.placed(o, in_hand):
                self._relocated(graph, o, observed)
        graph.replace_predicates(self.roles.robot, belief.robot_facts(self.body.state(), sweep, self.builder.site_map,
                                                                      self.roles), "survey")
        survey = Survey(why or f"lost {', '.join(lost)}", sweep, facts=graph.state())
        self.on_survey(survey, graph)
        return survey

    def _taken_back(self, graph: SceneGraph, o: str, in_hand: set[str]) -> bool:
        """A check found lost ``o`` missing where belief puts it, and the search found it nowhere
        else: where belief had it before the sighting that put it there, if nothing moved it since
        (:mod:`vap_bt.scene.moves`). Keeping it at the place the check failed at would make the
        same plan, and the same check fail, again. Or belief places ``o`` nowhere since the hand
        let it go in a placing a check denied, and the search found it nowhere: where it was put."""
        node = graph.objects.get(o)
        if o in in_hand or self._placed_anew(o, in_hand):
            return False
        placed = any(self.roles.supports(a) for a in graph.location(o))
        if placed and (node is None or not self.misses.at(o, node.centroid)):
            return False  # belief places it, and no check found it missing there
        place = self.moves.taken_back(o, graph.location(o))
        if place is None:
            return False
        self.progress(f"    {o} not found: believed where it was before "
                      f"{'a sighting moved it' if placed else 'the hand let it go'} ({', '.join(sorted(map(str, place)))})")
        graph.relocate(o, set(place))
        return True

    def _trail(self, state) -> list[tuple[str, list]]:
        """Looks round the floor along the way from where the gripper last held each thing the hand
        lost on the way to where the base stood when it was found gone (:func:`trail_spots`)."""
        if state.base_pose is None:
            return []
        spots = [spot for o in self._lost_ways
                 for spot in trail_spots(self.builder.site_map, self._held_at[o], state.base_pose[:2])]
        return [(room, self.builder.spot_views(room, p)) for room, p in spots]

    def _closer_looks(self, sweep: SweepRecord, rooms: list[str], sought: Callable[[], list[str]],
                      lead: Callable[[], str]) -> SweepRecord:
        """The last looks of a survey or a search for ``sought()``, each until nothing is sought:
        first the floor along every wall (the sweep's views leave the feet of the walls out, and
        what rolled away lies there), then round the middle of each room's floor (the look round
        from there leaves the floor at its feet out), then the floor between those two (in a wide
        room neither reaches it), then the tops of the rooms' pieces that
        things are put on, from nearer than the sweep's (a small thing on a counter every sweep
        view missed: a detector's miss belongs to the picture, a new one draws anew); before and
        after each, the floor round where a view glimpsed a sought thing (:meth:`_glimpses`).
        ``lead()`` opens each progress line; the looks are added to ``sweep``."""
        looked: set[tuple[float, float]] = set()
        sweep = self._glimpses(sweep, sought, looked, lead)
        for what, views in (("along the walls of", self.builder.wall_views),
                            ("round the middle of the floor of", self.builder.middle_views),
                            ("over the floor between the walls and the middle of", self.builder.inner_views),
                            ("nearer at the tops in", self.builder.near_top_views)):
            looks = [(r, views(r)) for r in rooms]
            if not sought() or not any(v for _, v in looks):
                continue
            self.progress(f"{lead()} looking {what} {', '.join(rooms)}")
            sweep = self.builder.look_round(self.camera, looks, until=lambda: not sought()).after(sweep)
            sweep = self._glimpses(sweep, sought, looked, lead)
        return sweep

    def _glimpses(self, sweep: SweepRecord, sought: Callable[[], list[str]], looked: set[tuple[float, float]],
                  lead: Callable[[], str]) -> SweepRecord:
        """A look at the floor round each spot where a view showed a sought thing too little to
        measure it (:meth:`SceneGraphBuilder.glimpsed`), from the stands round it, until nothing
        is sought; spots in ``looked`` are not looked at again. A real search goes to look closer
        at what it half saw: retrieve_bottles seed 49 in pybullet glimpsed the bottle the hand
        lost, five pixels past the doorway from the garden's sweep, could not place it, and ended
        with no plan, the walls' views having missed it in full sight."""
        spots = {o: p for o in sought() if (p := self.builder.glimpsed(o)) is not None and p not in looked}
        looked.update(spots.values())
        looks = [(room, self.builder.spot_views(room, p)) for p in spots.values()
                 if (room := self.builder.site_map.room_at(*p)) is not None]
        if not any(v for _, v in looks):
            return sweep
        self.progress(f"{lead()} {', '.join(spots)} glimpsed: looking closer")
        return self.builder.look_round(self.camera, looks, until=lambda: not sought()).after(sweep)

    def _note_miss(self, graph: SceneGraph, s: Situation) -> None:
        """An item not found where belief had it, by a check before an action (about its place or
        whether it is in view) or by the skill of the action that went to take it (``missing``):
        the place is doubted (:mod:`vap_bt.scene.moves`) and, if frames had measured it there,
        the spot is noted (:mod:`vap_bt.scene.misses`). Items the hand holds are not missing
        anywhere."""
        for a in graph.facts:
            if self.roles.is_held(a):
                self.misses.clear(a.args[0])
                self.moves.clear(a.args[0])
        a = s.atom
        if s.kind == "execution" and s.missing:
            # the skill's own looks at the place are a check's (boil_water seed 23: a phantom cup
            # in the empty cabinet was taken again by every search, and three take-outs found it
            # not there; heat_pie seed 29: every search sent the pie back into the fridge three
            # take-outs had looked into, while it lay on the floor where a sighting had put it)
            name, places = s.missing, [p for p in graph.location(s.missing) if self.roles.supports(p)]
        elif s.kind in ("unseen", "precondition") and a is not None and s.observed is not True and a.args \
                and a.predicate in (self.roles.in_view, *self.roles.support):
            name, places = a.args[0], [a] if a.predicate in self.roles.support else []
        else:
            return  # an effect or a goal is about what the robot just did there: no phantom put it
        for place in places:  # not a place to go back to should a sighting move it from there
            self.moves.doubt(place, firm=s.kind != "unseen")  # "could not make it out": the weaker doubt
        obj = graph.objects.get(name)
        if obj is not None and self._portable(obj.name) and obj.centroid is not None \
                and obj.located == frozenset(graph.location(obj.name)):
            self.misses.note(obj.name, obj.centroid)

    def _placed_anew(self, name: str, held=()) -> bool:
        """Whether the frames put ``name`` on or in something (or in the hand) somewhere a check
        did not find it missing: a sighting the executive takes as where the item is."""
        return self.builder.placed(name, held) and not self._at_miss(name) and not self._behind_shut_door(name, held)

    def _behind_shut_door(self, name: str, held=()) -> bool:
        """Whether the frames put ``name`` inside something belief holds shut: no camera sees into
        a shut oven, so what a frame shows there is a detector's false positive of its class
        (heat_pie seed 2 in pybullet: the pie, lost after a failed take-out, was "found" inside
        the oven nobody had opened, the oven was turned on, and no goal check could see a pie
        that stood in the fridge)."""
        closed = self.roles.closed
        return closed is not None and self.graph is not None and any(
            a.predicate == self.roles.inside and Atom(closed, a.args[1:]) in self.graph.facts
            for a in self.builder.observed(name, held) if a.args[0] == name)

    def _at_miss(self, name: str) -> bool:
        """Whether the frames' track of ``name`` puts it where a check found it missing."""
        g = self.builder.geometry
        return g is not None and self.misses.at(name, g.centroid(name))

    def _feels(self, atom: Atom) -> bool:
        """Whether the gripper can say anything of ``atom``: ``holding(x)`` and ``hand_empty``."""
        return self.roles.is_held(atom) or (atom.predicate == self.roles.hand_empty and not atom.args)

    def _felt(self, graph: SceneGraph, atom: Atom) -> bool | None:
        """Proprioception's word on ``holding(x)`` and ``hand_empty``: the gripper reports whether
        its fingers closed on something; which thing it is, is belief's. A query to the robot's
        state service: behaviours ask it in flight (``ctx.submit``), never from ``update()``."""
        if not self._feels(atom):
            return None
        state = self.body.state()
        holding = state.gripper_holding
        if holding is None:
            return None
        if holding and self.roles.is_held(atom) and atom in graph.facts and state.base_pose is not None:
            self._held_at[atom.args[0]] = state.base_pose[:2]
        return (not holding) if atom.predicate == self.roles.hand_empty else (holding and atom in graph.facts)

    def _in_hand(self, graph: SceneGraph) -> set[str]:
        """What belief holds, while the gripper feels something between its fingers."""
        if self.body.state().gripper_holding is False:
            return set()
        return {a.args[0] for a in graph.facts if self.roles.is_held(a)}

    @staticmethod
    def _expected_in_sight(graph: SceneGraph, obj: str) -> bool:
        """Belief says the camera should see ``obj``: it is held, or it is in the robot's room and
        not inside something (a container's interior shows only to a view into it, and a detector
        misses most of what stands inside: a frame without the thing is no sign it moved)."""
        loc, r = graph.location(obj), graph.roles
        if any(r.is_held(a) for a in loc):
            return True
        if any(a.predicate == r.inside for a in loc):
            return False
        rooms = {a.args[0] for a in graph.facts if a.predicate == r.robot_in}
        return any(a.predicate == r.in_room and a.args[1] in rooms for a in loc)

    def _situated(self) -> bool:
        return bool(self.roles.location & set(self.task.knowledge.predicates))

    def _portable(self, obj: str) -> bool:
        t = self.task.objects.get(obj)
        return t is not None and any(self.task.knowledge.is_subtype(t, p) for p in self.roles.portable) \
            and self._situated()


def sweep_order(site_map, start: str | None) -> list[str]:
    """Rooms in the order the sweep visits them: farthest first (by doors), so that it ends back
    in the room where the robot started."""
    if not site_map.rooms:
        return []
    nbrs: dict[str, set[str]] = {r.name: set() for r in site_map.rooms}
    for d in site_map.doors:
        a, b = d.rooms
        nbrs[a].add(b)
        nbrs[b].add(a)
    first = start if start in nbrs else site_map.rooms[0].name
    order, todo = [], [first]
    while todo:
        r = todo.pop(0)
        if r not in order:
            order.append(r)
            todo += sorted(nbrs[r] - set(order))
    order += [r.name for r in site_map.rooms if r.name not in order]
    return order[::-1]


def last_taken_from_hand(graph: SceneGraph) -> str | None:
    """The item a check last took out of the hand in belief (a view that judged it not held, or a
    grasp not done), unless something else touched what the hand holds since (an action put it
    down, the gripper felt it gone)."""
    for ch in reversed(graph.history):
        touched = [a for a in ch.added | ch.removed if graph.roles.is_held(a)]
        if touched:
            # "correct": a check said it is not held; "undo": a check said the grasp did not take
            return touched[0].args[0] if ch.cause in ("correct", "undo") and touched[0] in ch.removed else None
    return None


def unconfirmed_goal(atoms: list[Atom], step: int) -> Situation:
    """The goal the tree got through to but the camera could not confirm, as an ``unseen``
    situation after the plan's last step: the robot goes to look at what the first unconfirmed
    atom is about and checks the goal again from there, as it does for a precondition it could
    not see. Ending the episode there gave up on goals the world showed reached (10 of 180
    episodes with injection), and claiming them would be claiming what nobody saw."""
    detail = "goal reached in belief but not confirmed by looking: " + ", ".join(map(str, atoms))
    return Situation("unseen", None, step, atoms[0], True, None, detail=detail)


def shown_by_check(s: Situation, verifications: list[Verification], support: frozenset[str] = frozenset()) -> bool:
    """Whether the thing ``s``'s atom is about was where belief put it, by the views of the check
    that raised ``s``: then no miss is noted there (:meth:`Executive._note_miss`). A noted miss
    vetoes every later sighting at that spot, and the true one with it (heat_pie seed 30 in
    pybullet: the pie stood in the fridge all episode, seen there by the check whose "inside"
    stayed unsettled; the re-survey's sighting of it in the fridge was refused, a false positive on
    the floor took it, and three grasps on the floor found nothing). Two cases:

    * a check that could not settle its atom (``unseen``) though the detector found the thing in a
      frame of it, where the camera was turned to belief's place for it: the model could not make
      the relation out;
    * a check that settled against where the thing rests (a ``support`` predicate: on, inside)
      whose frames showed the thing from two stands or more: a detector's false positive belongs
      to one picture (the same view shows it again, another draws anew), so a thing found at its
      spot from two stands is there, and the model's "no" is about what it rests on, not whether
      it is there (gather_kindling seed 89 in pybullet: the stick lay on the garden floor, found
      there from two stands, and vlm-2 said "not on the floor"; the miss noted at the spot refused
      every later sighting of it there, a false positive across the garden took it, and three
      grasps there found nothing). One picture's sighting proves nothing against a phantom (a
      "cup" in the empty cabinet, boil_water seed 23)."""
    if s.atom is None or not s.atom.args:
        return False
    v = next((v for v in reversed(verifications) if v.atom == s.atom), None)
    if v is None:
        return False
    thing = s.atom.args[0]
    if s.kind == "unseen":
        return any(thing in r.identified for r in v.rounds)
    if s.kind == "precondition" and s.observed is False and s.atom.predicate in support:
        return len({r.stand for r in v.rounds if thing in r.identified and r.stand is not None}) >= 2
    return False


def why_redone(s: Situation, board: Board, calibration: Calibration) -> str | None:
    """Why the action that was to bring about ``s``, a goal atom the camera could not confirm
    (:func:`unconfirmed_goal`), is to be done again before anything is claimed; None if not.

    * "never confirmed": belief holds it only because a plan's action was to bring it about — no
      check of the episode settled it at the goal's value, by a view or by the body. The action may
      have failed where no view could tell (an injected cut that does not cut: vlm-2 reads
      ``sliced`` poorly, and its effect check stayed unsettled);
    * "weighed against by its views": a check did confirm it, but the views since the last action
      that could change it weigh against it (:func:`~vap_bt.bt.goal_check.leans_against`), so no
      claim may rest on that check (symbolic halve_egg seed 159: "sliced" on one such check, and
      the egg was whole)."""
    if s.kind != "unseen" or s.action is not None or s.atom is None:
        return None
    if not any(v.atom == s.atom and v.value == s.expected and v.outcome in ("confirmed", "felt")
               for v in board.verifications):
        return "never confirmed"
    if s.expected is not None and leans_against(s.atom, s.expected, board.verified.views(s.atom), calibration):
        return "weighed against by its views"
    return None


def replan_timing(plan: Plan, seconds: float) -> str:
    """How a replan's progress line times it: the engine and what the planner itself took, then,
    when it is most of the wait, the whole of it from the situation. A replan's time runs from the
    situation to the new tree, and takes in the recovery's looks (a re-survey of a room: tens of
    seconds in pybullet); printed as one number beside the engine, that read as a search of
    seconds for a plan the planner found in milliseconds."""
    timing = f"{plan.engine}, {plan.seconds * 1000:.1f} ms"
    if seconds >= 1.0 and seconds > 2 * plan.seconds:
        timing += f"; {seconds:.1f} s from the situation, with the recovery"
    return timing
