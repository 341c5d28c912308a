"""Domain knowledge: the action schemas of a PDDL domain and their ground instances.

unified-planning parses the PDDL and grounds it (:mod:`vap_bt.domain.instances`); this module
holds what the rest of the executive works with. A :class:`GroundAction` is one action with its
objects bound: its precondition as ground literals — those every case needs
(:attr:`~GroundAction.preconditions`) and, for disjunctive or existential preconditions, the rest
as a formula (:attr:`~GroundAction.condition`) — and its effects, unconditional
(:attr:`~GroundAction.add`, :attr:`~GroundAction.delete`) and conditional
(:attr:`~GroundAction.conditional`, PDDL's ``when`` and ``forall``).

What an action does depends on the state it is applied in once effects are conditional:
:meth:`GroundAction.diff` is that state difference — the atoms it makes true and the true atoms it
makes false — and it is the one definition of an action's semantics here. The planner's
validation, the scene graph's action-driven update, the symbolic world and the compiler's choice
of what to check after the action all use it (PDDL semantics: every effect whose condition holds
in the state before fires; deletes first, then adds).

:class:`DomainKnowledge` answers questions about the lifted domain: which predicates actions
change (the others are rigid map knowledge), which pairs of predicates are complements
(open/closed), and the ground instance of an action by name and arguments.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Protocol

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.formula import TRUE, Formula, conjunction, holds, literals, support


@dataclass(frozen=True)
class ConditionalEffect:
    """Effects that happen only when ``condition`` holds in the state the action is applied in."""

    condition: Formula
    add: frozenset[Atom] = frozenset()
    delete: frozenset[Atom] = frozenset()


@dataclass(frozen=True)
class StateDiff:
    """What applying an action to a state changes: atoms made true, true atoms made false."""

    added: frozenset[Atom]
    deleted: frozenset[Atom]

    def apply(self, state: frozenset[Atom] | set[Atom]) -> frozenset[Atom]:
        """The state after the difference: ``state`` less the deleted atoms, plus the added ones."""
        return frozenset((set(state) - self.deleted) | self.added)


@dataclass(frozen=True)
class GroundAction:
    """One action with its objects bound; preconditions and effects are ground."""

    name: str
    args: tuple[str, ...]
    #: literals the precondition needs in every case (all of it, for a conjunctive precondition)
    preconditions: tuple[Literal, ...]
    #: unconditional effects
    add: frozenset[Atom]
    delete: frozenset[Atom]
    #: the rest of the precondition (its disjunctions); true for a conjunctive precondition
    condition: Formula = TRUE
    conditional: tuple[ConditionalEffect, ...] = ()
    cost: int = 1

    def __str__(self) -> str:
        return f"{self.name}({', '.join(self.args)})"

    @cached_property
    def pre_pos(self) -> frozenset[Atom]:
        """The atoms the precondition needs true in every case."""
        return frozenset(l.atom for l in self.preconditions if l.positive)

    @cached_property
    def pre_neg(self) -> frozenset[Atom]:
        """The atoms the precondition needs false in every case."""
        return frozenset(l.atom for l in self.preconditions if not l.positive)

    @property
    def precondition(self) -> Formula:
        """The whole precondition as one formula."""
        return conjunction([*self.preconditions, self.condition])

    @cached_property
    def may_add(self) -> frozenset[Atom]:
        """Every atom some effect of this action can add, whatever the state."""
        return self.add.union(*(e.add for e in self.conditional))

    @cached_property
    def may_delete(self) -> frozenset[Atom]:
        """Every atom the action deletes in some state: unconditional deletes and those of any
        conditional effect."""
        return self.delete.union(*(e.delete for e in self.conditional))

    @cached_property
    def mentioned(self) -> frozenset[Atom]:
        """Every atom the action's precondition or effects mention."""
        conds = (l.atom for e in (self.condition, *(c.condition for c in self.conditional)) for l in literals(e))
        return frozenset((*(l.atom for l in self.preconditions), *conds)) | self.may_add | self.may_delete

    def applicable(self, state: frozenset[Atom] | set[Atom]) -> bool:
        """Whether the whole precondition (literals and formula) holds in ``state``."""
        return self.pre_pos <= state and not (self.pre_neg & state) and holds(self.condition, state)

    def support(self, state: frozenset[Atom] | set[Atom]) -> tuple[Literal, ...]:
        """The precondition literals that hold the precondition in ``state`` (for a disjunction,
        the disjunct believed true): what to look at before acting."""
        if self.condition == TRUE:
            return self.preconditions
        return tuple(dict.fromkeys((*self.preconditions, *support(self.condition, state))))

    def diff(self, state: frozenset[Atom] | set[Atom]) -> StateDiff:
        """The state difference of applying this action to ``state`` (PDDL semantics: the effects
        whose conditions hold in ``state`` fire together; an atom both deleted and added stays)."""
        add, delete = set(self.add), set(self.delete)
        for e in self.conditional:
            if holds(e.condition, state):
                add |= e.add
                delete |= e.delete
        return StateDiff(frozenset(a for a in add if a not in state), frozenset(delete.intersection(state) - add))

    def apply(self, state: frozenset[Atom] | set[Atom]) -> frozenset[Atom]:
        """The state after the action in ``state`` (PDDL semantics, :meth:`diff`); applicability is not
        checked."""
        return self.diff(state).apply(state)


@dataclass(frozen=True)
class EffectTemplate:
    """One lifted effect: a predicate over parameters (``?x``) and constants, its sign, and the
    condition it fires under (``""`` when unconditional)."""

    predicate: str
    terms: tuple[str, ...]
    positive: bool
    condition: str = ""


@dataclass(frozen=True)
class ActionSchema:
    """A lifted action: its typed parameters and what its effects touch."""

    name: str
    parameters: tuple[tuple[str, str], ...]  # (?name, type)
    effects: tuple[EffectTemplate, ...] = ()


class Instantiator(Protocol):
    """Grounds action instances (see :mod:`vap_bt.domain.instances`)."""

    def ground(self, name: str, args: tuple[str, ...]) -> GroundAction:
        """The action ``name`` with its parameters bound to ``args``, valid in any state."""

    def candidates(self, name: str, limit: int | None = None) -> list[tuple[str, ...]]:
        """Argument tuples of ``name`` worth grounding (rigid facts rule the others out); with
        ``limit``, at most ``limit + 1`` of them."""


@dataclass
class DomainKnowledge:
    """Types, predicates and action schemas of one PDDL domain (over one problem's objects)."""

    name: str
    parents: dict[str, str | None]  # type -> parent type
    predicates: dict[str, tuple[str, ...]]  # name -> parameter types
    schemas: dict[str, ActionSchema]
    constants: dict[str, str] = field(default_factory=dict)  # object -> type
    instances: Instantiator | None = field(default=None, repr=False)
    #: the task has an action-cost metric (PDDL :action-costs); otherwise every action costs 1
    has_costs: bool = False
    #: the PDDL file the domain was read from (its perception profile lies beside it), if any
    domain_file: Path | None = None
    _ground: dict[tuple[str, tuple[str, ...]], GroundAction] = field(default_factory=dict, repr=False)

    def is_subtype(self, t: str, ancestor: str) -> bool:
        """Whether type ``t`` is ``ancestor`` or descends from it (every type descends from ``object``)."""
        while t is not None:
            if t == ancestor:
                return True
            t = self.parents.get(t)
        return ancestor == "object"

    @cached_property
    def fluent_predicates(self) -> frozenset[str]:
        """Predicates some action changes; the others are rigid (static map knowledge)."""
        return frozenset(e.predicate for s in self.schemas.values() for e in s.effects)

    @cached_property
    def complements(self) -> dict[str, str]:
        """Pairs like open/closed: every action that adds one over some arguments deletes the
        other over the same arguments (under the same condition), and no action touches either
        alone. Correcting one of a pair to a value implies the other's opposite."""
        touched: dict[str, set[str | None]] = {}
        for s in self.schemas.values():
            for e in s.effects:
                partner = [o.predicate for o in s.effects
                           if o.positive != e.positive and o.terms == e.terms and o.condition == e.condition
                           and o.predicate != e.predicate
                           and self.predicates.get(o.predicate) == self.predicates.get(e.predicate)]
                touched.setdefault(e.predicate, set()).add(partner[0] if len(partner) == 1 else None)
        pairs: dict[str, str] = {}
        for p, partners in touched.items():
            if len(partners) == 1 and None not in partners:
                q = next(iter(partners))
                if touched.get(q) == {p}:
                    pairs[p] = q
        return pairs

    def is_rigid(self, predicate: str) -> bool:
        """Whether no action changes ``predicate``: its atoms are map knowledge, fixed by the initial
        state."""
        return predicate not in self.fluent_predicates

    def ground(self, name: str, args: tuple[str, ...]) -> GroundAction:
        """The instance of action ``name`` over ``args`` (grounded once, then remembered)."""
        key = (name, tuple(args))
        found = self._ground.get(key)
        if found is None:
            schema = self.schemas.get(name)
            if schema is None:
                raise KeyError(f"unknown action {name!r}; the domain has {sorted(self.schemas)}")
            if len(args) != len(schema.parameters):
                raise ValueError(f"{name} takes {len(schema.parameters)} arguments, got {len(args)}")
            if self.instances is None:
                raise ValueError(f"domain {self.name!r} was not read through unified-planning: cannot ground {name}")
            found = self._ground[key] = self.instances.ground(name, tuple(args))
        return found
