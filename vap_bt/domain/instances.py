"""Action instances: each action read once as a lifted template, then ground by substitution.

The parsed problem is compiled once with unified-planning's quantifiers remover: ``forall`` and
``exists`` over typed variables become conjunctions and disjunctions over the problem's objects,
and ``forall`` effects become one conditional effect per object. Each action is then translated
once into a *template* — its precondition and effect conditions as :mod:`~vap_bt.domain.formula`
formulas whose atoms may name parameters (``?x``), equality kept as a ``=`` literal — and an
instance is the template with its arguments substituted, equalities decided, simplified. This is
what unified-planning's ``GrounderHelper`` does per instance; doing it on our own formulas makes
an instance cost microseconds instead of milliseconds (pegsol's 2,271 instances took 40 s through
the helper), and keeps the helper's parameter enumeration out of the way: it ends in a
``ValueError`` inside unified-planning on driverlog and elevators (``tests/domains/up-grounder-*``
reproduce it).

Two questions are asked of the instances:

* :meth:`UPInstances.ground` answers "what does this action do" for any state, so it uses no
  facts of the initial state at all (the executive applies it to a belief the camera corrected);
* :meth:`UPInstances.candidates` enumerates the argument tuples worth grounding for the search:
  typed objects, pruned by the precondition's positive literals over *rigid* predicates (those no
  action changes), which the initial state fixes for good — never by the fluent ones.

Action costs come from the problem's action-cost metric (PDDL ``:action-costs``), evaluated with
the static numeric fluents of the initial state (road lengths); without a metric every action
costs 1.
"""

from __future__ import annotations

import itertools
import threading
from dataclasses import dataclass
from typing import Iterator

from vap_bt.domain import up_engines
from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.formula import FALSE, TRUE, And, Formula, bind, conjunction, from_up
from vap_bt.domain.knowledge import ConditionalEffect, GroundAction


@dataclass(frozen=True)
class _Effect:
    """One lifted effect: the atom it sets, to which value, under which condition."""

    atom: Atom
    value: bool
    condition: Formula


@dataclass(frozen=True)
class _Template:
    """One lifted action: parameters, precondition and effects over ``?x`` terms."""

    params: tuple[str, ...]
    precondition: Formula
    effects: tuple[_Effect, ...]


class UPInstances:
    """Ground instances of one unified-planning problem's actions."""

    def __init__(self, problem, has_quantifiers: bool = True) -> None:
        up_engines.load()
        from unified_planning.engines import CompilationKind
        from unified_planning.engines.compilers import QuantifiersRemover
        from unified_planning.model.walkers import Simplifier

        if has_quantifiers:
            problem = QuantifiersRemover().compile(explicit_initial_state(problem.clone()),
                                                   CompilationKind.QUANTIFIERS_REMOVING).problem
        self.problem = problem
        self._actions = {a.name: a for a in problem.actions}
        self._templates = {a.name: _template(a) for a in problem.actions}
        self._allowed = {a.name: tuple(frozenset(o.name for o in problem.objects(p.type)) for p in a.parameters)
                         for a in problem.actions}
        self._objects = {o.name: o for o in problem.all_objects}
        changed = {e.atom.predicate for t in self._templates.values() for e in t.effects}
        self._rigid = {f.name for f in problem.fluents if f.type.is_bool_type()} - changed
        self.init = initial_atoms(problem)
        self._rigid_facts = frozenset(a for a in self.init if a.predicate in self._rigid)
        self._metric = next((m for m in problem.quality_metrics if m.is_minimize_action_costs()), None)
        self._statics = Simplifier(problem.environment, problem)
        # unified-planning's expression manager is not thread-safe, and the symbolic world's
        # skill servers ground actions on their own threads while the executive plans
        self._lock = threading.Lock()

    @property
    def has_costs(self) -> bool:
        """Whether the problem has an action-cost metric (without one every action costs 1)."""
        return self._metric is not None

    def goal(self) -> Formula:
        """The problem's goal, quantifiers removed."""
        return conjunction([from_up(g) for g in self.problem.goals])

    def candidates(self, name: str, limit: int | None = None) -> list[tuple[str, ...]]:
        """Argument tuples of action ``name`` that the rigid facts do not rule out; with ``limit``,
        at most ``limit + 1`` of them (enough to tell that there are more than ``limit``)."""
        t = self._templates[name]
        required = [l.atom for l in _split(t.precondition)[0]
                    if l.positive and l.atom.predicate in self._rigid]
        found = _join(t.params, [sorted(s) for s in self._allowed[name]], required, self._rigid_facts)
        return list(found if limit is None else itertools.islice(found, limit + 1))

    def ground(self, name: str, args: tuple[str, ...]) -> GroundAction:
        action, allowed = self._actions[name], self._allowed[name]
        for p, a, ok in zip(action.parameters, args, allowed):
            if a not in ok:
                if a not in self._objects:
                    raise ValueError(f"{name}: unknown object {a!r}")
                raise ValueError(f"{name}: {a!r} is a {self._objects[a].type}, parameter {p.name} expects a {p.type}")
        t = self._templates[name]
        binding = dict(zip(t.params, args))
        cost = self._cost(action, args)
        pre = bind(t.precondition, binding)
        if pre == FALSE or cost is None:
            # a contradictory precondition (``(not (= ?x ?y))`` with x = y) never holds; an
            # instance whose cost is undefined in the initial state is inapplicable (PDDL 2.1)
            return GroundAction(name, tuple(args), (), frozenset(), frozenset(), condition=FALSE, cost=cost or 0)
        required, rest = _split(pre)
        add, delete, conditional = _effects(t.effects, binding)
        return GroundAction(name, tuple(args), required, add, delete, condition=rest, conditional=conditional,
                            cost=cost)

    def _cost(self, action, args: tuple[str, ...]) -> int | None:
        """The instance's cost; None where it is undefined (a cost fluent without a value)."""
        if self._metric is None:
            return 1
        expr = self._metric.get_action_cost(action)
        if expr is None:
            return 0
        if expr.is_constant():
            return int(expr.constant_value())
        em = self.problem.environment.expression_manager
        subs = {p: em.ObjectExp(self._objects[a]) for p, a in zip(action.parameters, args)}
        with self._lock:
            value = self._statics.simplify(expr.substitute(subs))
        return int(value.constant_value()) if value.is_constant() else None


def _template(action) -> _Template:
    pre = conjunction([from_up(p, lifted=True) for p in action.preconditions])
    effects = []
    for e in action.effects:
        if not e.fluent.type.is_bool_type():
            continue  # numeric effects are the action costs, read from the metric
        if not e.value.is_bool_constant():
            raise ValueError(f"unsupported effect {e}")
        atom = from_up(e.fluent, lifted=True).atom
        cond = from_up(e.condition, lifted=True) if e.is_conditional() else TRUE
        effects.append(_Effect(atom, e.value.bool_constant_value(), cond))
    return _Template(tuple(f"?{p.name}" for p in action.parameters), pre, tuple(effects))


def _join(params: tuple[str, ...], domains: list[list[str]], required: list[Atom],
          facts: frozenset[Atom]) -> Iterator[tuple[str, ...]]:
    """Every typed argument tuple under which each ``required`` atom is among ``facts``: a
    backtracking join that checks an atom as soon as its last parameter is bound."""
    position = {p: i for i, p in enumerate(params)}

    def last(atom: Atom) -> int:
        return max((position[a] for a in atom.args if a in position), default=-1)

    checks: list[list[Atom]] = [[] for _ in params]
    for atom in required:
        if last(atom) < 0:
            if atom not in facts:
                return  # a ground rigid precondition that is false: no instance applies
        else:
            checks[last(atom)].append(atom)
    binding: dict[str, str] = {}

    def extend(i: int) -> Iterator[tuple[str, ...]]:
        if i == len(params):
            yield tuple(binding[p] for p in params)
            return
        for obj in domains[i]:
            binding[params[i]] = obj
            if all(Atom(a.predicate, tuple(binding.get(x, x) for x in a.args)) in facts for a in checks[i]):
                yield from extend(i + 1)
        binding.pop(params[i], None)

    yield from extend(0)


def explicit_initial_state(problem):
    """``problem`` itself, made to report only its explicit initial values as ``initial_values``.

    unified-planning's ``initial_values`` builds the value of every ground fluent, false ones
    included — tens of thousands of expressions on an IPC problem (7 s on maintenance-sat14's
    smallest, each time its quantifiers remover copies a problem and each time its PDDL writer
    writes one for Fast Downward) — and stores them among the explicit values as it goes. Both
    callers need no false atom: every predicate of a parsed problem defaults to false, and the
    writer prints only true atoms and numbers. Numeric fluents keep their defaults (few: costs)."""
    base = type(problem)
    if base not in _EXPLICIT:
        # a subclass with no fields of its own, so that the problem's class can be swapped for it
        _EXPLICIT[base] = type(f"Explicit{base.__name__}", (base,),
                               {"__slots__": (), "initial_values": property(_explicit_values)})
    problem.__class__ = _EXPLICIT[base]
    return problem


_EXPLICIT: dict[type, type] = {}


def _explicit_values(problem) -> dict:
    from unified_planning.model.fluent import get_all_fluent_exp

    values = dict(problem.explicit_initial_values)
    for f in problem.fluents:
        if not f.type.is_bool_type():
            for exp in get_all_fluent_exp(problem, f):
                if exp not in values and (v := problem.initial_value(exp)) is not None:
                    values[exp] = v
    return values


def initial_atoms(problem) -> frozenset[Atom]:
    """The atoms true in ``problem``'s initial state. From the explicit values: ``initial_values``
    would also build every false ground atom (11 s on nomystery's smallest problem)."""
    return frozenset(Atom(k.fluent().name, tuple(a.object().name for a in k.args))
                     for k, v in problem.explicit_initial_values.items() if k.type.is_bool_type() and v.is_true())


def _split(pre: Formula) -> tuple[tuple[Literal, ...], Formula]:
    """A precondition as (the literals every case needs, the rest)."""
    if isinstance(pre, Literal):
        return (pre,), TRUE
    if isinstance(pre, And):
        lits = tuple(p for p in pre.parts if isinstance(p, Literal))
        return lits, conjunction([p for p in pre.parts if not isinstance(p, Literal)])
    return (), pre


def _effects(effects: tuple[_Effect, ...], binding: dict[str, str]
             ) -> tuple[frozenset[Atom], frozenset[Atom], tuple[ConditionalEffect, ...]]:
    add: set[Atom] = set()
    delete: set[Atom] = set()
    conditional: dict[Formula, tuple[set[Atom], set[Atom]]] = {}
    for e in effects:
        cond = bind(e.condition, binding)
        if cond == FALSE:
            continue
        atom = Atom(e.atom.predicate, tuple(binding.get(a, a) for a in e.atom.args))
        adds, dels = (add, delete) if cond == TRUE else conditional.setdefault(cond, (set(), set()))
        (adds if e.value else dels).add(atom)
    return frozenset(add), frozenset(delete), tuple(
        ConditionalEffect(c, frozenset(a), frozenset(d)) for c, (a, d) in conditional.items())


__all__ = ["UPInstances", "initial_atoms"]
