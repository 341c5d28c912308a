"""Action instances through unified-planning: quantifiers compiled away, then ground one by one.

The parsed problem is compiled once with unified-planning's quantifiers remover: ``forall`` and
``exists`` over typed variables become conjunctions and disjunctions over the problem's objects,
and ``forall`` effects become one conditional effect per object. Each action instance is then
ground by unified-planning's grounder (``GrounderHelper``: parameters substituted, the expression
simplified, so that ``(= ?from ?to)`` is decided) and translated into a
:class:`~vap_bt.domain.knowledge.GroundAction`.

Two grounders are kept, for two different questions:

* :meth:`UPInstances.ground` answers "what does this action do" for any state, so it uses no
  facts of the initial state at all (the executive applies it to a belief the camera corrected);
* :meth:`UPInstances.candidates` enumerates the parameter tuples worth grounding for the search,
  with unified-planning's pruning by static fluents — rigid facts, never the fluent ones.

Action costs come from the problem's action-cost metric (PDDL ``:action-costs``), evaluated with
the static numeric fluents of the initial state (road lengths); without a metric every action
costs 1.
"""

from __future__ import annotations

import threading

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.formula import FALSE, TRUE, And, Formula, conjunction, from_up
from vap_bt.domain.knowledge import ConditionalEffect, GroundAction


class UPInstances:
    """Ground instances of one unified-planning problem's actions."""

    def __init__(self, problem, has_quantifiers: bool = True) -> None:
        from unified_planning.engines import CompilationKind
        from unified_planning.engines.compilers import GrounderHelper, QuantifiersRemover
        from unified_planning.model.walkers import Simplifier

        if has_quantifiers:
            problem = QuantifiersRemover().compile(problem, CompilationKind.QUANTIFIERS_REMOVING).problem
        self.problem = problem
        self._actions = {a.name: a for a in problem.actions}
        self._objects = {o.name: o for o in problem.all_objects}
        self._exact = GrounderHelper(problem, prune_actions=False)
        self._static = GrounderHelper(problem, prune_actions=True)
        self._metric = next((m for m in problem.quality_metrics if m.is_minimize_action_costs()), None)
        self._statics = Simplifier(problem.environment, problem)
        # unified-planning's expression manager is not thread-safe, and the symbolic world's
        # skill servers ground actions on their own threads while the executive plans
        self._lock = threading.Lock()

    @property
    def has_costs(self) -> bool:
        return self._metric is not None

    def goal(self) -> Formula:
        """The problem's goal, quantifiers removed."""
        return conjunction([from_up(g) for g in self.problem.goals])

    def candidates(self, name: str) -> list[tuple[str, ...]]:
        """Parameter tuples of action ``name`` that the static (rigid) facts do not rule out."""
        with self._lock:
            return [tuple(p.object().name for p in params)
                    for params in self._static.get_possible_parameters(self._actions[name])]

    def ground(self, name: str, args: tuple[str, ...]) -> GroundAction:
        with self._lock:
            return self._ground(name, args)

    def _ground(self, name: str, args: tuple[str, ...]) -> GroundAction:
        action = self._actions[name]
        params = []
        for p, a in zip(action.parameters, args):
            obj = self._objects.get(a)
            if obj is None:
                raise ValueError(f"{name}: unknown object {a!r}")
            if not p.type.is_compatible(obj.type):
                raise ValueError(f"{name}: {a!r} is a {obj.type}, parameter {p.name} expects a {p.type}")
            params.append(self.problem.environment.expression_manager.ObjectExp(obj))
        ground = self._exact.ground_action(action, tuple(params))
        cost = self._cost(action, tuple(params))
        if ground is None or cost is None:
            # unified-planning's grounder drops an instance whose precondition is contradictory
            # (``(not (= ?x ?y))`` with x = y) or whose effects conflict; an instance whose cost is
            # undefined in the initial state is inapplicable (PDDL 2.1). Either way it never applies
            return GroundAction(name, tuple(args), (), frozenset(), frozenset(), condition=FALSE, cost=cost or 0)
        pre = conjunction([from_up(p) for p in ground.preconditions])
        required, rest = _split(pre)
        add, delete, conditional = _effects(ground.effects)
        return GroundAction(name, tuple(args), required, add, delete, condition=rest, conditional=conditional,
                            cost=cost)

    def _cost(self, action, params) -> int | None:
        """The instance's cost; None where it is undefined (a cost fluent without a value)."""
        if self._metric is None:
            return 1
        expr = self._metric.get_action_cost(action)
        if expr is None:
            return 0
        value = self._statics.simplify(expr.substitute(dict(zip(action.parameters, params))))
        return int(value.constant_value()) if value.is_constant() else None


def _split(pre: Formula) -> tuple[tuple[Literal, ...], Formula]:
    """A precondition as (the literals every case needs, the rest)."""
    if isinstance(pre, Literal):
        return (pre,), TRUE
    if isinstance(pre, And):
        lits = tuple(p for p in pre.parts if isinstance(p, Literal))
        return lits, conjunction([p for p in pre.parts if not isinstance(p, Literal)])
    return (), pre


def _effects(effects) -> tuple[frozenset[Atom], frozenset[Atom], tuple[ConditionalEffect, ...]]:
    add: set[Atom] = set()
    delete: set[Atom] = set()
    conditional: dict[Formula, tuple[set[Atom], set[Atom]]] = {}
    for e in effects:
        if not e.value.is_bool_constant():
            raise ValueError(f"unsupported effect {e}")
        atom = Atom(e.fluent.fluent().name, tuple(a.object().name for a in e.fluent.args))
        cond = from_up(e.condition) if e.is_conditional() else TRUE
        if cond == FALSE:
            continue
        adds, dels = (add, delete) if cond == TRUE else conditional.setdefault(cond, (set(), set()))
        (adds if e.value.bool_constant_value() else dels).add(atom)
    return frozenset(add), frozenset(delete), tuple(
        ConditionalEffect(c, frozenset(a), frozenset(d)) for c, (a, d) in conditional.items())


__all__ = ["UPInstances"]
