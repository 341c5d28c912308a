"""The planner: Fast Downward through unified-planning, and a fast replanner beside it.

The first plan of a task comes from Fast Downward (``engine="fast-downward"``). Replanning after
a situation tries, cheapest first:

1. ``reuse``  — a suffix of the previous plan that is still valid from the corrected state
   (a grasp that failed with the object unchanged leaves the rest of the plan intact);
2. ``cache``  — a plan found before for this exact state and goal;
3. ``search`` — in-process greedy best-first search with the FF heuristic over the grounded task
   (:mod:`vap_bt.domain.search`), grounded once per object set (with the first plan, for an
   executive's planner: ``ground_eagerly``);
4. ``fast-downward`` — when the search runs out of its node budget, when the belief holds atoms
   or rigid facts the grounding did not assume, or when a precondition is too large for it.

Every plan carries the engine that made it, the time it took and its cost (the sum of its
actions' costs: PDDL ``:action-costs``, or 1 per action). A plan a planner produced is checked
twice before it is returned — with our semantics and with unified-planning's ``PlanValidator``
(:mod:`vap_bt.domain.validation`) — so a plan that does not reach the goal is never handed out. A
reused tail is re-checked from the corrected state with our semantics only: it is a suffix of a
plan the validator accepted, our semantics are tested against unified-planning's simulator, and
the validator's 20–70 ms per call, times every tail tried, would dominate replanning
(docs/BENCHMARKS.md).

Tasks with action costs are planned with them: Fast Downward runs LAMA's cost-aware greedy
search (:data:`FD_COST_CONFIG`; its default, ``lama-first``, ignores costs) — for a third of its
time limit, then ``lama-first`` for the rest — and the in-process search orders its queue by
g + w·h over the costs.

Fast Downward's driver writes its translated task (``output.sas``) to the working directory
unless told otherwise; two planners running at once from one folder (two runs, or a benchmark's
workers) then search each other's task. Ours keeps it beside the plan file, in the engine's own
temporary folder (:func:`private_fast_downward`).
"""

from __future__ import annotations

import os
import time
import warnings
from dataclasses import dataclass, field
from typing import Literal as Lit

from vap_bt.domain import up_engines, validation
from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.formula import FormulaTooLarge
from vap_bt.domain.grounding import GroundedTask, ground
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.search import gbfs
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import PlanningTimeout, UnsolvableError

Engine = Lit["fast-downward", "search", "reuse", "cache"]

#: Fast Downward for tasks with action costs: the cost-aware greedy iteration of LAMA (its
#: second): FF and landmark heuristics over the costs (plus one, so that zero-cost actions still
#: count), preferred operators, no reopening. ``lama-first`` ignores costs; the weighted A* used
#: before (w=3, FF alone) found barman's and elevators' plans only after Fast Downward's time
#: limit, where this finds them in a second (tools/bench/pddl_sweep.py)
FD_COST_CONFIG = ("let(hlm,eval_modify_costs(landmark_sum(lm_reasonable_orders_hps(lm_rhw()),pref=false),"
                  "cost_type=plusone),let(hff,eval_modify_costs(ff(),cost_type=plusone),"
                  "lazy_greedy([hff,hlm],preferred=[hff,hlm],reopen_closed=false)))")
#: the share of Fast Downward's time limit the cost-aware search has before ``lama-first`` takes over
COST_AWARE_SHARE = 1 / 3


@dataclass
class Plan:
    """A sequence of ground actions, with the engine that made it and how long that took."""

    actions: list[GroundAction]
    engine: str
    seconds: float

    def __len__(self) -> int:
        return len(self.actions)

    @property
    def cost(self) -> int:
        """The plan's cost: the sum of its actions' costs (its length without action costs)."""
        return sum(a.cost for a in self.actions)

    def __str__(self) -> str:
        return "\n".join(f"{i}: {a}" for i, a in enumerate(self.actions)) or "(empty plan: goal already holds)"

    def to_json(self) -> dict:
        return {"engine": self.engine, "seconds": round(self.seconds, 6), "cost": self.cost,
                "actions": [str(a) for a in self.actions]}


@dataclass
class Planner:
    """Plans and replans one task (see the module docstring for the engines it tries)."""

    task: PlanningTask
    first_engine: str = "fast-downward"  # or "search"
    fd_timeout_s: float = 60.0
    max_expansions: int = 20000
    #: ground the task for the in-process search along with the first plan, so that the first
    #: situation does not wait for grounding (an executive wants this; a one-off plan does not)
    ground_eagerly: bool = False
    _grounded: GroundedTask | None = field(default=None, init=False, repr=False)
    _too_large: bool = field(default=False, init=False, repr=False)
    #: plans found, keyed by the engine path (Fast Downward alone, or the in-process search first),
    #: the state and the goal: a cached plan is the one a fresh planner would find there, so an
    #: episode's plans do not depend on which episodes a warm session ran before it
    _cache: dict = field(default_factory=dict, init=False, repr=False)

    @property
    def grounded(self) -> GroundedTask | None:
        """The grounded task for the in-process search; None when it is too large for it (a
        precondition with thousands of disjuncts), which leaves Fast Downward."""
        if self._grounded is None and not self._too_large:
            try:
                self._grounded = ground(self.task)
            except FormulaTooLarge:
                self._too_large = True
        return self._grounded

    def plan(self, state: frozenset[Atom] | None = None, goal: tuple[Literal, ...] | None = None) -> Plan:
        """A first plan from ``state`` (default: the task's initial state)."""
        task = self.task.with_state(state if state is not None else self.task.init, goal)
        t0 = time.perf_counter()
        fd_only = self.first_engine == "fast-downward"
        key = ("fast-downward" if fd_only else "search", task.init, task.goal)
        if key in self._cache:
            return Plan(list(self._cache[key]), "cache", time.perf_counter() - t0)
        found = self._fast_downward(task) if fd_only else self._search_or_fd(task)
        plan = self._accept(key, task, *found, t0)
        if self.ground_eagerly:
            _ = self.grounded
        return plan

    def replan(self, state: frozenset[Atom], previous: list[GroundAction] | None = None,
               goal: tuple[Literal, ...] | None = None) -> Plan:
        """A plan from a corrected state, trying reuse, the cache and in-process search first."""
        task = self.task.with_state(state, goal)
        t0 = time.perf_counter()
        # an empty ``previous`` is a plan run to its end (the goal left unconfirmed): its empty
        # tail is the answer when the goal holds in belief, without a search and its validation
        if previous is not None:
            suffix = self._shortest_valid_suffix(task, previous)
            if suffix is not None:
                return Plan(suffix, "reuse", time.perf_counter() - t0)
        key = ("search", task.init, task.goal)
        if key in self._cache:
            return Plan(list(self._cache[key]), "cache", time.perf_counter() - t0)
        return self._accept(key, task, *self._search_or_fd(task), t0)

    # -- engines -------------------------------------------------------------------------------

    @staticmethod
    def _shortest_valid_suffix(task: PlanningTask, previous: list[GroundAction]) -> list[GroundAction] | None:
        for i in range(len(previous), -1, -1):
            if task.validate(previous[i:]):
                return list(previous[i:])
        return None

    def _search_or_fd(self, task: PlanningTask) -> tuple[list[GroundAction], str]:
        g = self.grounded
        k = task.knowledge
        # the grounding assumed the task's rigid facts and knows the atoms actions can reach; a
        # belief outside that (a rigid fact corrected, an unknown atom) is Fast Downward's to plan
        if g is not None and g.rigid == frozenset(a for a in task.init if k.is_rigid(a.predicate)) and all(
                a in g.index for a in task.init if not k.is_rigid(a.predicate)):
            rigid_goal = [l for l in task.goal if k.is_rigid(l.atom.predicate)]
            if any((l.atom in task.init) != l.positive for l in rigid_goal):
                raise UnsolvableError(f"no action changes {[str(l) for l in rigid_goal]}: the goal cannot hold")
            fluent_goal = [l for l in task.goal if not k.is_rigid(l.atom.predicate)]
            pos = [l.atom for l in fluent_goal if l.positive]
            neg = [l.atom for l in fluent_goal if not l.positive]
            if not all(a in g.index for a in pos):
                raise UnsolvableError(f"no action can make {[str(a) for a in pos if a not in g.index]} true")
            res = gbfs(g, g.ids(task.init), g.ids(pos), g.ids(neg), self.max_expansions, use_costs=k.has_costs)
            if res.plan is not None:
                return [g.actions[i] for i in res.plan], "search"
            if res.exhausted:
                raise UnsolvableError(f"no plan reaches the goal from this state ({task.name})")
        return self._fast_downward(task)

    def _fast_downward(self, task: PlanningTask) -> tuple[list[GroundAction], str]:
        """Fast Downward's plan; for a task with action costs, the cost-aware search first, for
        :data:`COST_AWARE_SHARE` of the time limit, then ``lama-first``, which ignores the costs
        (LAMA's own order: its first iteration is cost-blind), for the rest — data-network-sat18,
        which lama-first solves in a second, ran the cost-aware search out of its 60 s."""
        if not task.knowledge.has_costs:
            return self._fast_downward_with(task, {}, self.fd_timeout_s)
        try:
            return self._fast_downward_with(task, {"fast_downward_search_config": FD_COST_CONFIG},
                                            self.fd_timeout_s * COST_AWARE_SHARE)
        except PlanningTimeout:
            return self._fast_downward_with(task, {}, self.fd_timeout_s * (1 - COST_AWARE_SHARE))

    def _fast_downward_with(self, task: PlanningTask, params: dict, timeout: float) -> tuple[list[GroundAction], str]:
        up_engines.load()
        from unified_planning.engines import PlanGenerationResultStatus as S

        with warnings.catch_warnings():
            # integral PDDL ``number`` costs are reals to unified-planning, which then cannot tell
            # whether Fast Downward takes them (it does; requirements.check_costs saw they are integers)
            warnings.simplefilter("ignore")
            with private_fast_downward(**params) as engine:
                result = engine.solve(task.to_up(), timeout=timeout)
        if result.status in (S.SOLVED_SATISFICING, S.SOLVED_OPTIMALLY):
            k = task.knowledge
            return [k.ground(ai.action.name, tuple(p.object().name for p in ai.actual_parameters))
                    for ai in result.plan.actions], "fast-downward"
        if result.status in (S.UNSOLVABLE_PROVEN, S.UNSOLVABLE_INCOMPLETELY):
            raise UnsolvableError(f"Fast Downward: no plan reaches the goal of {task.name}")
        if result.status == S.TIMEOUT:
            raise PlanningTimeout(f"Fast Downward found no plan for {task.name} within {self.fd_timeout_s:g} s")
        raise UnsolvableError(f"Fast Downward found no plan for {task.name}: {result.status.name}")

    def _accept(self, key: tuple, task: PlanningTask, actions: list[GroundAction], engine: str, t0: float) -> Plan:
        if not task.validate(actions):
            raise RuntimeError(f"{engine} returned a plan that does not reach the goal: {[str(a) for a in actions]}")
        verdict = validation.validate(task, actions)
        if not verdict.valid:
            raise RuntimeError(f"unified-planning's validator rejects the {engine} plan "
                               f"{[str(a) for a in actions]}: {verdict.reason}")
        if verdict.cost is not None and verdict.cost != sum(a.cost for a in actions):
            raise RuntimeError(f"unified-planning costs the {engine} plan {verdict.cost}, "
                               f"our grounding {sum(a.cost for a in actions)}")
        self._cache[key] = tuple(actions)
        return Plan(actions, engine, time.perf_counter() - t0)


def private_fast_downward(**params):
    """unified-planning's Fast Downward engine with the translator's output in the engine's own
    temporary folder, beside its plan file, instead of the working directory (see the module's
    docstring)."""
    up_engines.load()
    from up_fast_downward import FastDownwardPDDLPlanner

    class PrivateFastDownward(FastDownwardPDDLPlanner):
        def _base_cmd(self, plan_filename: str) -> list[str]:
            python, driver, *rest = super()._base_cmd(plan_filename)
            return [python, driver, "--sas-file", os.path.join(os.path.dirname(plan_filename), "output.sas"), *rest]

    engine = PrivateFastDownward(**params)
    engine.error_on_failed_checks = False  # as OneshotPlanner(name=...) makes it: see _fast_downward
    return engine
