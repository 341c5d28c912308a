"""Domain knowledge: typed STRIPS action schemas, read through unified-planning.

unified-planning parses the PDDL; this module turns its expression trees into a small, flat
form that the rest of the executive works with: types with their parents, objects with their
types, and action schemas whose preconditions are signed literals and whose effects are add and
delete lists over parameters and constants. A :class:`GroundAction` is one schema with objects
bound, exposing its preconditions and effects as ground atoms — exactly what verification asks
the camera about and what the scene graph applies.

Anything outside typed STRIPS with negative preconditions (conditional effects, quantifiers,
numeric fluents, disjunctive preconditions) is refused with a message naming the action.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

from vap_bt.domain.atoms import Atom, Literal

#: a term in a schema is either a parameter ("?x") or a constant object name
Term = str


@dataclass(frozen=True)
class LiteralTemplate:
    predicate: str
    terms: tuple[Term, ...]
    positive: bool = True

    def bind(self, binding: dict[str, str]) -> Literal:
        args = tuple(binding.get(t, t) for t in self.terms)
        return Literal(Atom(self.predicate, args), self.positive)


@dataclass(frozen=True)
class ActionSchema:
    name: str
    parameters: tuple[tuple[str, str], ...]  # (?name, type)
    preconditions: tuple[LiteralTemplate, ...]
    add: tuple[LiteralTemplate, ...]
    delete: tuple[LiteralTemplate, ...]

    def ground(self, args: tuple[str, ...]) -> "GroundAction":
        if len(args) != len(self.parameters):
            raise ValueError(f"{self.name} takes {len(self.parameters)} arguments, got {len(args)}")
        binding = {p: a for (p, _), a in zip(self.parameters, args)}
        return GroundAction(
            name=self.name,
            args=tuple(args),
            preconditions=tuple(t.bind(binding) for t in self.preconditions),
            add=frozenset(t.bind(binding).atom for t in self.add),
            delete=frozenset(t.bind(binding).atom for t in self.delete),
        )


@dataclass(frozen=True)
class GroundAction:
    """One action with its objects bound; preconditions and effects are ground."""

    name: str
    args: tuple[str, ...]
    preconditions: tuple[Literal, ...]
    add: frozenset[Atom]
    delete: frozenset[Atom]

    def __str__(self) -> str:
        return f"{self.name}({', '.join(self.args)})"

    @cached_property
    def pre_pos(self) -> frozenset[Atom]:
        return frozenset(l.atom for l in self.preconditions if l.positive)

    @cached_property
    def pre_neg(self) -> frozenset[Atom]:
        return frozenset(l.atom for l in self.preconditions if not l.positive)

    def applicable(self, state: frozenset[Atom] | set[Atom]) -> bool:
        return self.pre_pos <= state and not (self.pre_neg & state)

    def apply(self, state: frozenset[Atom]) -> frozenset[Atom]:
        # PDDL semantics: deletes first, then adds (an atom both deleted and added stays true)
        return (state - self.delete) | self.add


@dataclass
class DomainKnowledge:
    """Types, predicates and action schemas of one PDDL domain."""

    name: str
    parents: dict[str, str | None]  # type -> parent type
    predicates: dict[str, tuple[str, ...]]  # name -> parameter types
    schemas: dict[str, ActionSchema]
    constants: dict[str, str] = field(default_factory=dict)  # object -> type

    def is_subtype(self, t: str, ancestor: str) -> bool:
        while t is not None:
            if t == ancestor:
                return True
            t = self.parents.get(t)
        return ancestor == "object"

    @cached_property
    def fluent_predicates(self) -> frozenset[str]:
        """Predicates some action changes; the others are rigid (static map knowledge)."""
        return frozenset(t.predicate for s in self.schemas.values() for t in (*s.add, *s.delete))

    @cached_property
    def complements(self) -> dict[str, str]:
        """Pairs like open/closed: every action that adds one over some arguments deletes the
        other over the same arguments, and no action touches either alone. Correcting one of a
        pair to a value implies the other's opposite."""
        pairs: dict[str, str] = {}
        touched: dict[str, set[tuple[str, str] | None]] = {}
        for s in self.schemas.values():
            dels = {(t.predicate, t.terms) for t in s.delete}
            adds = {(t.predicate, t.terms) for t in s.add}
            for t in s.add:
                partner = [p for p, terms in dels if terms == t.terms and p != t.predicate
                           and self.predicates.get(p) == self.predicates.get(t.predicate)]
                touched.setdefault(t.predicate, set()).add(partner[0] if len(partner) == 1 else None)
            for t in s.delete:
                partner = [p for p, terms in adds if terms == t.terms and p != t.predicate
                           and self.predicates.get(p) == self.predicates.get(t.predicate)]
                touched.setdefault(t.predicate, set()).add(partner[0] if len(partner) == 1 else None)
        for p, partners in touched.items():
            if len(partners) == 1 and None not in partners:
                q = next(iter(partners))
                if touched.get(q) == {p}:
                    pairs[p] = q
        return pairs

    def is_rigid(self, predicate: str) -> bool:
        return predicate not in self.fluent_predicates

    def ground(self, name: str, args: tuple[str, ...]) -> GroundAction:
        try:
            schema = self.schemas[name]
        except KeyError:
            raise KeyError(f"unknown action {name!r}; the domain has {sorted(self.schemas)}") from None
        return schema.ground(args)
