"""The closed-loop executive (paper Algorithm 1) on a behaviour tree.

One episode: survey the scene into a scene graph, plan, compile the plan into a tree, and tick it.
When the tree fails, a behaviour has left a :class:`~vap_bt.bt.context.Situation` on the
context; the executive handles it and swaps in a new tree:

1. an effect that did not happen first undoes the action-driven update, so belief returns to
   what held before the action;
2. the contradicted atom is set to its observed value (observation-driven update);
3. a skill that failed to act makes the robot's placement for it (``inview``) stale, so that the
   new plan approaches the target again rather than retrying from the same spot;
4. the objects the action touched are re-located from what the camera sees now; an object that
   belief no longer places anywhere triggers a fresh survey (the paper's UpdateFromObservation);
5. the planner replans from the corrected graph — reusing the old plan's tail when it still
   works — within the replanning budget.

The executive talks only to protocols (SkillClient, Camera, VLM): it never sees a world.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable

import py_trees
from py_trees.common import Status

from vap_bt.bt.compiler import compile_plan
from vap_bt.bt.context import ExecutionContext, Situation, VerifyMode
from vap_bt.domain.planner import Plan, Planner
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import UnsolvableError
from vap_bt.perception.verification import VoteSettings
from vap_bt.perception.vlm import VLM
from vap_bt.scene.graph import LOCATION_PREDICATES, SceneGraph
from vap_bt.skill import Camera, SkillClient

#: PDDL types whose objects are placed somewhere (and so can be lost track of)
PORTABLE_TYPES = ("item",)
#: the perception predicate that says the robot is placed to act on a thing; a skill that failed
#: to act from where the robot stands makes these beliefs stale, so the new plan re-approaches
VIEW_PREDICATE = "inview"


@dataclass
class ExecutiveSettings:
    mode: VerifyMode = field(default_factory=VerifyMode)
    budget: int = 3
    vote: VoteSettings = field(default_factory=VoteSettings)
    max_replans: int = 10
    max_ticks: int = 2000
    tick_period_s: float = 0.0  # sleep between ticks while a goal runs (0: in-process skills)


@dataclass
class EpisodeOutcome:
    success: bool  # the executive's own claim: its tree reached GoalCheck and it held
    reason: str
    plans: list[Plan]
    situations: list[Situation]
    replans: int
    replan_seconds: list[float]
    surveys: int
    ticks: int
    graph: SceneGraph
    context: ExecutionContext


class Executive:
    def __init__(self, task: PlanningTask, planner: Planner, skills: SkillClient, camera: Camera,
                 vlm: VLM | None, settings: ExecutiveSettings | None = None,
                 progress: Callable[[str], None] = lambda m: None,
                 on_tree: Callable[[py_trees.trees.BehaviourTree, int], None] | None = None) -> None:
        self.task, self.planner, self.skills, self.camera, self.vlm = task, planner, skills, camera, vlm
        self.s = settings or ExecutiveSettings()
        self.progress = progress
        self.on_tree = on_tree or (lambda tree, tick: None)
        #: the episode so far; readable after an interruption (Ctrl-C) for a partial report
        self.outcome: EpisodeOutcome | None = None
        if vlm is None and (self.s.mode.pre or self.s.mode.eff):
            raise ValueError("verification needs a VLM; use verify mode 'none' to run without one")

    def run(self) -> EpisodeOutcome:
        k = self.task.knowledge
        graph = SceneGraph.from_snapshot(self.camera.survey(),
                                         tracks_hand={"holding", "hand_empty"} <= set(k.predicates))
        ctx = ExecutionContext(graph=graph, vlm=self.vlm, camera=self.camera, skills=self.skills,
                               mode=self.s.mode, budget=self.s.budget, vote=self.s.vote, progress=self.progress)
        out = self.outcome = EpisodeOutcome(False, "", [], [], 0, [], 1, 0, graph, ctx)
        try:
            plan = self.planner.plan(graph.state(), self.task.goal)
        except UnsolvableError as exc:
            out.reason = f"no initial plan: {exc}"
            return out
        out.plans.append(plan)
        self.progress(f"plan ({plan.engine}, {plan.seconds * 1000:.0f} ms): {len(plan)} actions")
        tree = self._tree(ctx, plan)
        while out.ticks < self.s.max_ticks:
            tree.tick()
            out.ticks += 1
            self.on_tree(tree, out.ticks)
            status = tree.root.status
            if status == Status.SUCCESS:
                if ctx.unconfirmed_goal:  # the tree got through, but the camera could not confirm it
                    out.reason = "goal reached in belief but not confirmed by looking: " + ", ".join(
                        map(str, ctx.unconfirmed_goal))
                    return out
                out.success, out.reason = True, "goal reached"
                return out
            if status == Status.RUNNING:
                if self.s.tick_period_s:
                    time.sleep(self.s.tick_period_s)
                continue
            situation, ctx.situation = ctx.situation, None
            if situation is None:
                out.reason = "the tree failed without a situation"
                return out
            out.situations.append(situation)
            if out.replans >= self.s.max_replans:
                out.reason = f"replanning budget ({self.s.max_replans}) exhausted"
                return out
            t0 = time.perf_counter()
            out.surveys += self._correct(graph, situation)
            try:
                plan = self.planner.replan(graph.state(), plan.actions[situation.step:], self.task.goal)
            except UnsolvableError as exc:
                out.reason = f"no plan after {situation.kind} situation: {exc}"
                return out
            tree.interrupt()
            tree = self._tree(ctx, plan)
            out.replan_seconds.append(time.perf_counter() - t0)
            out.replans += 1
            out.plans.append(plan)
            self.progress(f"replan #{out.replans} ({plan.engine}, {out.replan_seconds[-1] * 1000:.1f} ms): "
                          f"{len(plan)} actions")
        out.reason = f"tick budget ({self.s.max_ticks}) exhausted"
        return out

    def _tree(self, ctx: ExecutionContext, plan: Plan) -> py_trees.trees.BehaviourTree:
        return py_trees.trees.BehaviourTree(compile_plan(ctx, plan.actions, self.task.goal, self.task.knowledge))

    def _correct(self, graph: SceneGraph, s: Situation) -> int:
        """Bring belief in line with what was observed; returns how many surveys it took."""
        if s.kind == "effect" and s.action is not None:
            graph.undo(s.action)
        if s.atom is not None and s.observed is not None:
            graph.correct(s.atom, s.observed, self.task.knowledge.complements.get(s.atom.predicate))
        if s.kind == "execution" and s.action is not None:
            for lit in s.action.preconditions:
                if lit.positive and lit.atom.predicate == VIEW_PREDICATE:
                    graph.correct(lit.atom, False)
        involved = tuple(dict.fromkeys((*(s.action.args if s.action else ()), *(s.atom.args if s.atom else ()))))
        portable = [o for o in involved if self._portable(o)]
        if not portable:
            return 0
        obs = self.camera.observe(tuple(portable))
        lost = []
        for o in portable:
            if obs.visibility.get(o, 0.0) > 0.0:
                seen = {a for a in obs.relations if a.args and a.args[0] == o}
                if seen:
                    graph.relocate(o, seen)
            elif self._expected_in_sight(graph, o):
                lost.append(o)  # the camera turned toward where belief puts it, and it is not there
        lost += [o for o in portable if o not in lost
                 and not any(a.predicate in ("on", "inside", "holding") for a in graph.location(o))]
        if lost:
            graph.merge_survey(self.camera.survey())
            return 1
        return 0

    @staticmethod
    def _expected_in_sight(graph: SceneGraph, obj: str) -> bool:
        """Belief says the camera should see ``obj``: it is held, or it is in the robot's room."""
        loc = graph.location(obj)
        if any(a.predicate == "holding" for a in loc):
            return True
        rooms = {a.args[0] for a in graph.facts if a.predicate == "robot_in"}
        return any(a.predicate == "in_room" and a.args[1] in rooms for a in loc)

    def _portable(self, obj: str) -> bool:
        t = self.task.objects.get(obj)
        return t is not None and any(self.task.knowledge.is_subtype(t, p) for p in PORTABLE_TYPES) \
            and bool(LOCATION_PREDICATES & set(self.task.knowledge.predicates))
