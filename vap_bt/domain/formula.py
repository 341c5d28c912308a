"""Ground formulas: what a precondition or an effect's condition asks of a state.

A typed STRIPS precondition is a conjunction of literals; PDDL as Fast Downward reads it also
has disjunctions, implications, equality and quantifiers. Once an action is grounded (its
parameters bound to objects), quantifiers have become finite conjunctions and disjunctions over
the objects (unified-planning's quantifiers remover) and equalities between objects have become
true or false, so what remains is a negation normal form over ground literals: :class:`And` (a
conjunction), :class:`Or` (a disjunction) and :class:`~vap_bt.domain.atoms.Literal`.

Three questions are asked of such a formula:

* does it hold in a state (:func:`holds`)?
* which of its literals make it hold there (:func:`support`)? These are what the camera is asked
  about before the action: for ``(or (holding ?x) (on ?x ?table))`` it is the disjunct that is
  believed true, not both;
* what is it as a disjunction of conjunctions (:func:`dnf`)? The in-process search wants plain
  literal sets; rigid facts are substituted first (:func:`assume`), which usually collapses the
  disjunctions that quantifiers over static facts produce.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Callable, Iterator, Union

from vap_bt.domain.atoms import Atom, Literal


@dataclass(frozen=True)
class And:
    """A conjunction; ``And(())`` is true."""

    parts: tuple["Formula", ...]

    def __str__(self) -> str:
        return "true" if not self.parts else "(" + " and ".join(map(str, self.parts)) + ")"


@dataclass(frozen=True)
class Or:
    """A disjunction; ``Or(())`` is false."""

    parts: tuple["Formula", ...]

    def __str__(self) -> str:
        return "false" if not self.parts else "(" + " or ".join(map(str, self.parts)) + ")"


Formula = Union[Literal, And, Or]
TRUE: Formula = And(())
FALSE: Formula = Or(())
#: the predicate of a lifted equality literal (no PDDL predicate can be named ``=``)
EQUALS = "="


class FormulaTooLarge(ValueError):
    """A formula whose disjunctive normal form has more disjuncts than the caller allows."""


def conjunction(parts) -> Formula:
    """``parts`` joined by *and*, flattened and simplified (a false part makes it false)."""
    return _join(And, parts, FALSE)


def disjunction(parts) -> Formula:
    """``parts`` joined by *or*, flattened and simplified (a true part makes it true)."""
    return _join(Or, parts, TRUE)


def _join(kind: type, parts, absorbing: Formula) -> Formula:
    out: list[Formula] = []
    for p in parts:
        if p == absorbing:
            return absorbing
        out.extend(p.parts if isinstance(p, kind) else (p,))  # the neutral element has no parts
    return out[0] if len(out) == 1 else kind(tuple(out))


def holds(f: Formula, state: frozenset[Atom] | set[Atom]) -> bool:
    """Whether ground formula ``f`` is true in ``state`` (closed world: an atom not in the state is
    false)."""
    if isinstance(f, Literal):
        return (f.atom in state) == f.positive
    if isinstance(f, And):
        return all(holds(p, state) for p in f.parts)
    return any(holds(p, state) for p in f.parts)


def support(f: Formula, state: frozenset[Atom] | set[Atom]) -> tuple[Literal, ...]:
    """The literals that make ``f`` hold in ``state``: every part of a conjunction, the first
    disjunct that holds of a disjunction. Where ``f`` does not hold, the first disjunct stands in
    (what a plan that expected it to hold relied on)."""
    if isinstance(f, Literal):
        return (f,)
    if isinstance(f, And):
        return tuple(dict.fromkeys(lit for p in f.parts for lit in support(p, state)))
    if not f.parts:
        return ()
    chosen = next((p for p in f.parts if holds(p, state)), f.parts[0])
    return support(chosen, state)


def literals(f: Formula) -> Iterator[Literal]:
    """Every literal that occurs in ``f``."""
    if isinstance(f, Literal):
        yield f
    else:
        for p in f.parts:
            yield from literals(p)


def assume(f: Formula, known: Callable[[Atom], bool | None]) -> Formula:
    """``f`` with the atoms ``known`` decides replaced by their truth value, simplified."""
    if isinstance(f, Literal):
        value = known(f.atom)
        if value is None:
            return f
        return TRUE if value == f.positive else FALSE
    parts = [assume(p, known) for p in f.parts]
    return conjunction(parts) if isinstance(f, And) else disjunction(parts)


def dnf(f: Formula, limit: int = 4096) -> list[tuple[Literal, ...]]:
    """``f`` as a list of consistent literal conjunctions (an empty list: ``f`` is false)."""
    if isinstance(f, Literal):
        return [(f,)]
    if isinstance(f, Or):
        out = [c for p in f.parts for c in dnf(p, limit)]
    else:
        out = [()]
        for p in f.parts:
            out = [_merge(a, b) for a, b in itertools.product(out, dnf(p, limit))]
            out = [c for c in out if c is not None]
            if len(out) > limit:
                raise FormulaTooLarge(f"more than {limit} disjuncts")
    if len(out) > limit:
        raise FormulaTooLarge(f"more than {limit} disjuncts")
    return list(dict.fromkeys(out))


def _merge(a: tuple[Literal, ...], b: tuple[Literal, ...]) -> tuple[Literal, ...] | None:
    merged = tuple(dict.fromkeys((*a, *b)))
    signs: dict[Atom, bool] = {}
    for lit in merged:
        if signs.setdefault(lit.atom, lit.positive) != lit.positive:
            return None  # p and not p: this conjunction never holds
    return merged


def from_up(node, lifted: bool = False) -> Formula:
    """A unified-planning boolean expression (quantifiers already removed) in negation normal
    form. Ground, unless ``lifted``: then an action's parameters may stand in atoms as ``?x``
    and an equality over them as an :data:`EQUALS` literal, for :func:`bind` to decide. Raises
    ``ValueError`` on anything else (a numeric comparison, a quantifier)."""
    return _nnf(node, True, lifted)


def _nnf(node, positive: bool, lifted: bool) -> Formula:
    if node.is_bool_constant():
        return TRUE if node.bool_constant_value() == positive else FALSE
    if node.is_fluent_exp():
        return Literal(Atom(node.fluent().name, tuple(_term(a, lifted) for a in node.args)), positive)
    if node.is_not():
        return _nnf(node.arg(0), not positive, lifted)
    if node.is_and() or node.is_or():
        parts = [_nnf(a, positive, lifted) for a in node.args]
        return conjunction(parts) if node.is_and() == positive else disjunction(parts)
    if node.is_implies():  # a -> b  ==  not a or b
        parts = [_nnf(node.arg(0), not positive, lifted), _nnf(node.arg(1), positive, lifted)]
        return disjunction(parts) if positive else conjunction(parts)
    if node.is_iff():
        a, b = node.arg(0), node.arg(1)
        same = (conjunction([_nnf(a, True, lifted), _nnf(b, True, lifted)]),
                conjunction([_nnf(a, False, lifted), _nnf(b, False, lifted)]))
        differ = (conjunction([_nnf(a, True, lifted), _nnf(b, False, lifted)]),
                  conjunction([_nnf(a, False, lifted), _nnf(b, True, lifted)]))
        return disjunction(same if positive else differ)
    if node.is_equals() and all(a.is_object_exp() for a in node.args):
        return TRUE if (node.arg(0) == node.arg(1)) == positive else FALSE
    if node.is_equals() and lifted:
        return Literal(Atom(EQUALS, tuple(_term(a, lifted) for a in node.args)), positive)
    raise ValueError(f"unsupported expression {node}")


def _term(node, lifted: bool) -> str:
    if lifted and node.is_parameter_exp():
        return f"?{node.parameter().name}"
    if not node.is_object_exp():
        raise ValueError(f"not a ground argument: {node}")
    return node.object().name


def bind(f: Formula, binding: dict[str, str]) -> Formula:
    """A lifted formula with its parameters replaced by objects (``binding``: ``?x`` -> object)
    and its equalities decided, simplified."""
    if isinstance(f, Literal):
        args = tuple(binding.get(a, a) for a in f.atom.args)
        if f.atom.predicate == EQUALS:
            return TRUE if (args[0] == args[1]) == f.positive else FALSE
        return Literal(Atom(f.atom.predicate, args), f.positive)
    parts = [bind(p, binding) for p in f.parts]
    return conjunction(parts) if isinstance(f, And) else disjunction(parts)


__all__ = ["And", "EQUALS", "Or", "FALSE", "Formula", "FormulaTooLarge", "TRUE", "assume", "conjunction", "disjunction",
           "bind", "dnf", "from_up", "holds", "literals", "support"]
