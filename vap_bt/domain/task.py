"""A planning task: domain knowledge, objects, an initial state and a goal.

The executive replans from the scene graph many times per episode; each replan is this same
task with another initial state. :meth:`PlanningTask.to_up` rebuilds the unified-planning
problem for that state, so Fast Downward and unified-planning's validator see exactly what the
in-process search sees.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Iterable

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.knowledge import DomainKnowledge, GroundAction


@dataclass(frozen=True)
class PlanningTask:
    """One planning problem over a domain: typed objects, initial state, goal; immutable, so that each
    replan is :meth:`with_state` of the same task."""

    knowledge: DomainKnowledge
    objects: dict[str, str]  # name -> type
    init: frozenset[Atom]
    goal: tuple[Literal, ...]
    name: str = "task"
    source: str = ""
    up_problem: Any = None  # the unified-planning problem this task was read from, if any

    def with_state(self, init: Iterable[Atom], goal: Iterable[Literal] | None = None) -> "PlanningTask":
        """The same task from initial state ``init`` (and ``goal``, if given)."""
        return replace(self, init=frozenset(init), goal=tuple(goal) if goal is not None else self.goal)

    def goal_holds(self, state: frozenset[Atom] | set[Atom]) -> bool:
        """Whether every goal literal holds in ``state``."""
        return all((l.atom in state) == l.positive for l in self.goal)

    def objects_of(self, type_name: str) -> list[str]:
        """The objects of type ``type_name`` or a subtype of it, sorted."""
        k = self.knowledge
        return sorted(o for o, t in self.objects.items() if k.is_subtype(t, type_name))

    def check_atom(self, atom: Atom) -> str | None:
        """Why ``atom`` does not fit the domain (unknown predicate or object, wrong arity, type)."""
        sig = self.knowledge.predicates.get(atom.predicate)
        if sig is None:
            return f"unknown predicate {atom.predicate!r} (the domain has {', '.join(sorted(self.knowledge.predicates))})"
        if len(sig) != len(atom.args):
            return f"{atom.predicate} takes {len(sig)} argument(s), got {len(atom.args)}"
        for a, t in zip(atom.args, sig):
            if a not in self.objects:
                return f"unknown object {a!r} in {atom}"
            if not self.knowledge.is_subtype(self.objects[a], t):
                return f"{a!r} is a {self.objects[a]}, {atom.predicate} expects a {t}"
        return None

    def to_up(self):
        """This task as a unified-planning problem (for Fast Downward and the validator)."""
        from vap_bt.domain.instances import explicit_initial_state

        base = self.up_problem
        if base is None:
            raise ValueError("this task was not read from PDDL; no unified-planning problem to rebuild")
        problem = explicit_initial_state(base.clone())
        problem.clear_goals()
        fluents = {f.name: f for f in problem.fluents}
        objs = {o.name: o for o in problem.all_objects}
        for k in list(problem.explicit_initial_values):
            if k.type.is_bool_type():  # numeric values (action costs) are static: they stay
                problem.set_initial_value(k, False)
        for a in self.init:
            problem.set_initial_value(fluents[a.predicate](*(objs[x] for x in a.args)), True)
        for l in self.goal:
            exp = fluents[l.atom.predicate](*(objs[x] for x in l.atom.args))
            problem.add_goal(exp if l.positive else problem.environment.expression_manager.Not(exp))
        return problem

    def validate(self, plan: list[GroundAction]) -> bool:
        """Check a plan with our own semantics (preconditions hold, goal reached)."""
        state = self.init
        for a in plan:
            if not a.applicable(state):
                return False
            state = a.apply(state)
        return self.goal_holds(state)
