"""The planner: Fast Downward through unified-planning, and a fast replanner beside it.

The first plan of a task comes from Fast Downward (``engine="fast-downward"``). Replanning after
a situation tries, cheapest first:

1. ``reuse``  — a suffix of the previous plan that is still valid from the corrected state
   (a grasp that failed with the object unchanged leaves the rest of the plan intact);
2. ``cache``  — a plan found before for this exact state and goal;
3. ``search`` — in-process greedy best-first search with the FF heuristic over the grounded task
   (:mod:`vap_bt.domain.search`), grounded once per object set;
4. ``fast-downward`` — when the search runs out of its node budget.

Every plan carries the engine that made it and the time it took, and is checked against the
task's semantics before it is returned: a plan that does not reach the goal is never handed out.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Literal as Lit

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.grounding import GroundedTask, ground
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.search import gbfs
from vap_bt.domain.task import PlanningTask
from vap_bt.errors import UnsolvableError

Engine = Lit["fast-downward", "search", "reuse", "cache"]


@dataclass
class Plan:
    actions: list[GroundAction]
    engine: str
    seconds: float

    def __len__(self) -> int:
        return len(self.actions)

    def __str__(self) -> str:
        return "\n".join(f"{i}: {a}" for i, a in enumerate(self.actions)) or "(empty plan: goal already holds)"

    def to_json(self) -> dict:
        return {"engine": self.engine, "seconds": round(self.seconds, 6), "actions": [str(a) for a in self.actions]}


@dataclass
class Planner:
    task: PlanningTask
    first_engine: str = "fast-downward"  # or "search"
    fd_timeout_s: float = 60.0
    max_expansions: int = 20000
    _grounded: GroundedTask | None = field(default=None, init=False, repr=False)
    _cache: dict = field(default_factory=dict, init=False, repr=False)

    @property
    def grounded(self) -> GroundedTask:
        if self._grounded is None:
            self._grounded = ground(self.task)
        return self._grounded

    def plan(self, state: frozenset[Atom] | None = None, goal: tuple[Literal, ...] | None = None) -> Plan:
        """A first plan from ``state`` (default: the task's initial state)."""
        task = self.task.with_state(state if state is not None else self.task.init, goal)
        t0 = time.perf_counter()
        key = (task.init, task.goal)
        if key in self._cache:
            return Plan(list(self._cache[key]), "cache", time.perf_counter() - t0)
        found = self._fast_downward(task) if self.first_engine == "fast-downward" else self._search_or_fd(task)
        return self._accept(task, *found, t0)

    def replan(self, state: frozenset[Atom], previous: list[GroundAction] | None = None,
               goal: tuple[Literal, ...] | None = None) -> Plan:
        """A plan from a corrected state, trying reuse, the cache and in-process search first."""
        task = self.task.with_state(state, goal)
        t0 = time.perf_counter()
        if previous:
            suffix = self._shortest_valid_suffix(task, previous)
            if suffix is not None:
                return Plan(suffix, "reuse", time.perf_counter() - t0)
        key = (task.init, task.goal)
        if key in self._cache:
            return Plan(list(self._cache[key]), "cache", time.perf_counter() - t0)
        return self._accept(task, *self._search_or_fd(task), t0)

    # -- engines -------------------------------------------------------------------------------

    @staticmethod
    def _shortest_valid_suffix(task: PlanningTask, previous: list[GroundAction]) -> list[GroundAction] | None:
        for i in range(len(previous), -1, -1):
            if task.validate(previous[i:]):
                return list(previous[i:])
        return None

    def _search_or_fd(self, task: PlanningTask) -> tuple[list[GroundAction], str]:
        g = self.grounded
        unknown = [a for a in task.init if a not in g.index and not task.knowledge.is_rigid(a.predicate)]
        if not unknown:
            init = g.ids(task.init)
            pos = [l.atom for l in task.goal if l.positive]
            neg = [l.atom for l in task.goal if not l.positive]
            if all(a in g.index for a in pos):
                res = gbfs(g, init, g.ids(pos), g.ids(neg), self.max_expansions)
                if res.plan is not None:
                    return [g.actions[i] for i in res.plan], "search"
                if res.exhausted:
                    raise UnsolvableError(f"no plan reaches the goal from this state ({task.name})")
            else:
                raise UnsolvableError(f"no action can make {[str(a) for a in pos if a not in g.index]} true")
        return self._fast_downward(task)

    def _fast_downward(self, task: PlanningTask) -> tuple[list[GroundAction], str]:
        from unified_planning.engines import PlanGenerationResultStatus as S
        from unified_planning.shortcuts import OneshotPlanner

        with OneshotPlanner(name="fast-downward") as engine:
            result = engine.solve(task.to_up(), timeout=self.fd_timeout_s)
        if result.status in (S.SOLVED_SATISFICING, S.SOLVED_OPTIMALLY):
            k = task.knowledge
            return [k.ground(ai.action.name, tuple(p.object().name for p in ai.actual_parameters))
                    for ai in result.plan.actions], "fast-downward"
        if result.status in (S.UNSOLVABLE_PROVEN, S.UNSOLVABLE_INCOMPLETELY):
            raise UnsolvableError(f"Fast Downward: no plan reaches the goal of {task.name}")
        raise UnsolvableError(f"Fast Downward found no plan for {task.name}: {result.status.name}")

    def _accept(self, task: PlanningTask, actions: list[GroundAction], engine: str, t0: float) -> Plan:
        if not task.validate(actions):
            raise RuntimeError(f"{engine} returned a plan that does not reach the goal: {[str(a) for a in actions]}")
        self._cache[(task.init, task.goal)] = tuple(actions)
        return Plan(actions, engine, time.perf_counter() - t0)
