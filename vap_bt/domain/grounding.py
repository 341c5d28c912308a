"""Grounding for the search: every action instance the rigid facts allow, as sparse matrices.

Replanning happens over and over with the same objects and a different initial state, so the
grounded task is built once per object set and reused — unless the rigid facts leave more than
:data:`INSTANCE_LIMIT` instances, when replanning is Fast Downward's alone. Instances come from
:mod:`vap_bt.domain.instances` (which prunes parameters by the rigid facts); the rigid
facts — atoms of predicates no action changes — are then substituted into each precondition and
effect condition (:func:`~vap_bt.domain.formula.assume`), which drops the instances they rule out.
Fluent facts of the initial state are never used: the executive replans from corrected belief.

The search wants literal sets, so each precondition is put in disjunctive normal form: one *row*
per disjunct (most actions have exactly one), with its positive and negative literals as CSR
matrices over atom ids, for a vectorised applicability test. This is done here, on ground
formulas after the rigid facts are in, rather than with unified-planning's disjunctive-conditions
remover, which works on lifted actions before any fact is known: a fridge-like
``(forall (?s - screw) (imply (holds ?s ?b) (not (fastened ?s))))`` would become one action copy
per subset of screws, where the static ``holds`` facts leave a single conjunction (the remover
also turns disjunctive goals into extra actions and fluents the executive would have to hide).
Conditional effects are kept as they are, for the same reason — unified-planning's
conditional-effects remover makes an action per combination of effect conditions, 2^n for a
briefcase holding n things — and enter the relaxed planning graph as *units*: one per row and
effect (unconditional, or one disjunct of a condition), whose precondition is the row's plus the
condition's positive literals.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from vap_bt.domain.atoms import Atom, Literal
from vap_bt.domain.formula import FALSE, TRUE, Formula, FormulaTooLarge, assume, dnf
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.task import PlanningTask

if TYPE_CHECKING:
    from scipy import sparse

#: at most this many disjuncts per precondition or effect condition (beyond: Fast Downward only)
DNF_LIMIT = 4096
#: at most this many action instances (beyond: Fast Downward only). The in-process search grounds
#: every instance the rigid facts allow, where Fast Downward's translator grounds only what is
#: reachable: caldera-sat18's smb_copy, whose preconditions are all fluents, has 13.7 million
#: candidates, enumerating which took 32 s before the first action; a household task has a few
#: hundred, the largest IPC domain that ran in the sweep about a thousand. A count, not a time, so
#: that one seed always plans the same way on any machine
INSTANCE_LIMIT = 20_000

IdSet = frozenset[int]


@dataclass(frozen=True)
class _Effects:
    """An action's effects over atom ids; ``conditional`` holds (condition disjuncts as
    (positive, negative) id sets, added ids, deleted ids)."""

    add: IdSet
    delete: IdSet  # unconditional deletes that are not also added
    conditional: tuple[tuple[tuple[tuple[IdSet, IdSet], ...], IdSet, IdSet], ...]


@dataclass
class GroundedTask:
    """The task as the search sees it: instances, atom ids, precondition rows, relaxed units."""

    actions: list[GroundAction]
    atoms: list[Atom]
    index: dict[Atom, int]
    rigid: frozenset[Atom]  # the rigid facts this grounding assumed
    row_action: np.ndarray  # precondition disjunct -> action
    pre: sparse.csr_matrix  # rows x atoms, positive literals
    neg: sparse.csr_matrix  # rows x atoms, negative literals
    pre_len: np.ndarray
    unit_action: np.ndarray  # relaxed effect unit -> action
    upre: sparse.csr_matrix  # units x atoms
    upre_len: np.ndarray
    uadd: sparse.csr_matrix  # units x atoms
    add_of: list[list[int]]  # atom -> units adding it
    unit_adds: list[np.ndarray]
    cost: np.ndarray  # per action
    effects: list[_Effects]

    def ids(self, atoms) -> frozenset[int]:
        """The ids of those of ``atoms`` the grounded task knows (an atom no instance mentions has none
        and is dropped)."""
        return frozenset(self.index[a] for a in atoms if a in self.index)

    def successor(self, state: IdSet, a: int) -> IdSet:
        """The state after action ``a`` (PDDL semantics, as :meth:`GroundAction.diff`)."""
        e = self.effects[a]
        if not e.conditional:
            return (state - e.delete) | e.add
        add, delete = set(e.add), set(e.delete)
        for disjuncts, cadd, cdel in e.conditional:
            if any(pos <= state and not (neg & state) for pos, neg in disjuncts):
                add |= cadd
                delete |= cdel
        return frozenset((state - (delete - add)) | add)


class TooManyInstances(FormulaTooLarge):
    """More action instances than the in-process search takes (:data:`INSTANCE_LIMIT`)."""


def ground(task: PlanningTask, limit: int = DNF_LIMIT, instance_limit: int = INSTANCE_LIMIT) -> GroundedTask:
    """Raises :class:`~vap_bt.domain.formula.FormulaTooLarge` when a precondition has more than
    ``limit`` disjuncts after the rigid facts are substituted, :class:`TooManyInstances` (one of
    them) when the rigid facts leave more than ``instance_limit`` action instances."""
    k = task.knowledge
    rigid = frozenset(a for a in task.init if k.is_rigid(a.predicate))

    def known(atom: Atom) -> bool | None:
        return (atom in rigid) if k.is_rigid(atom.predicate) else None

    left = instance_limit
    candidates: dict[str, list[tuple[str, ...]]] = {}
    for name in k.schemas:
        candidates[name] = k.instances.candidates(name, limit=left)
        left -= len(candidates[name])
        if left < 0:
            raise TooManyInstances(f"more than {instance_limit} action instances ({name} alone: "
                                   f"{len(candidates[name])}+)")
    actions: list[GroundAction] = []
    rows: list[tuple[int, tuple[Literal, ...]]] = []
    effects: list[tuple[frozenset[Atom], frozenset[Atom], list]] = []
    for name in k.schemas:
        for args in sorted(candidates[name]):
            a = k.ground(name, args)
            disjuncts = _dnf(a.precondition, known, limit)
            if not disjuncts:
                continue  # the rigid facts rule it out
            eff = _effects(a, known, limit)
            actions.append(a)
            effects.append(eff)
            rows += [(len(actions) - 1, d) for d in disjuncts]
    atoms_set = set(task.init) | {l.atom for l in task.goal}
    atoms_set |= {l.atom for _, d in rows for l in d}
    for add, delete, cond in effects:
        atoms_set |= add | delete
        for ds, cadd, cdel in cond:
            atoms_set |= cadd | cdel | {l.atom for d in ds for l in d}
    atoms = sorted(atoms_set)
    index = {a: i for i, a in enumerate(atoms)}

    def ids(xs) -> frozenset[int]:
        return frozenset(index[x] for x in xs)

    def pos(d: tuple[Literal, ...]) -> list[int]:
        return [index[l.atom] for l in d if l.positive]

    # relaxed units: each row with its unconditional adds, and with each disjunct of a conditional effect
    units: list[tuple[int, list[int], list[int]]] = []
    for ai, d in rows:
        add, _, cond = effects[ai]
        if add:
            units.append((ai, pos(d), sorted(ids(add))))
        for ds, cadd, _ in cond:
            if cadd:
                units += [(ai, sorted(set(pos(d)) | set(pos(c))), sorted(ids(cadd))) for c in ds]
    add_of: list[list[int]] = [[] for _ in atoms]
    for u, (_, _, adds) in enumerate(units):
        for p in adds:
            add_of[p].append(u)
    return GroundedTask(
        actions=actions, atoms=atoms, index=index, rigid=rigid,
        row_action=np.array([ai for ai, _ in rows], dtype=np.int64),
        pre=_matrix([pos(d) for _, d in rows], len(atoms)),
        neg=_matrix([[index[l.atom] for l in d if not l.positive] for _, d in rows], len(atoms)),
        pre_len=np.array([len(pos(d)) for _, d in rows], dtype=np.int32),
        unit_action=np.array([ai for ai, _, _ in units], dtype=np.int64),
        upre=_matrix([p for _, p, _ in units], len(atoms)),
        upre_len=np.array([len(p) for _, p, _ in units], dtype=np.int32),
        uadd=_matrix([a for _, _, a in units], len(atoms)),
        add_of=add_of, unit_adds=[np.array(a, dtype=np.int64) for _, _, a in units],
        cost=np.array([a.cost for a in actions], dtype=np.int64),
        effects=[_Effects(ids(add), ids(delete - add), tuple(
            (tuple((ids(l.atom for l in c if l.positive), ids(l.atom for l in c if not l.positive)) for c in ds),
             ids(cadd), ids(cdel)) for ds, cadd, cdel in cond)) for add, delete, cond in effects],
    )


def _dnf(f: Formula, known, limit: int) -> list[tuple[Literal, ...]]:
    f = assume(f, known)
    return [] if f == FALSE else dnf(f, limit)


def _effects(a: GroundAction, known, limit: int):
    """Unconditional add/delete and the conditional effects that the rigid facts leave open."""
    add, delete, cond = set(a.add), set(a.delete), []
    for e in a.conditional:
        c = assume(e.condition, known)
        if c == TRUE:
            add |= e.add
            delete |= e.delete
        elif c != FALSE:
            cond.append((dnf(c, limit), e.add, e.delete))
    return frozenset(add), frozenset(delete), cond


def _matrix(rows: list[list[int]], width: int) -> sparse.csr_matrix:
    from scipy import sparse  # on first grounding: a command that only asks Fast Downward never pays for scipy

    indptr = np.cumsum([0] + [len(r) for r in rows])
    data = np.ones(int(indptr[-1]), dtype=np.int32)
    cols = np.fromiter((c for r in rows for c in r), dtype=np.int64, count=int(indptr[-1]))
    return sparse.csr_matrix((data, cols, indptr), shape=(len(rows), width))


__all__ = ["DNF_LIMIT", "GroundedTask", "ground"]
