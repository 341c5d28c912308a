"""Grounding: every action schema instantiated over the task's objects, as sparse matrices.

Replanning happens over and over with the same objects and a different initial state, so the
grounded task is built once per object set and reused. Bindings are pruned as soon as a rigid
precondition (one no action changes) is fully bound and false in the initial state; type
constraints prune the rest. The result keeps each action's preconditions and add/delete lists
both as ground atoms (for the executive) and as CSR matrices over atom ids (for the search's
vectorised applicability test and relaxed planning graph).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import sparse

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import ActionSchema, GroundAction
from vap_bt.domain.task import PlanningTask


@dataclass
class GroundedTask:
    actions: list[GroundAction]
    atoms: list[Atom]
    index: dict[Atom, int]
    pre: sparse.csr_matrix  # actions x atoms, positive preconditions
    neg: sparse.csr_matrix  # actions x atoms, negative preconditions
    add: sparse.csr_matrix  # actions x atoms
    pre_len: np.ndarray
    add_of: list[list[int]]  # atom -> actions adding it
    add_ids: list[np.ndarray]
    del_ids: list[np.ndarray]

    def ids(self, atoms) -> frozenset[int]:
        return frozenset(self.index[a] for a in atoms if a in self.index)


def ground(task: PlanningTask) -> GroundedTask:
    k = task.knowledge
    rigid_true = {a for a in task.init if k.is_rigid(a.predicate)}
    actions: list[GroundAction] = []
    for schema in k.schemas.values():
        actions.extend(_ground_schema(task, schema, rigid_true))
    atoms_set = set(task.init) | {l.atom for l in task.goal}
    for a in actions:
        atoms_set |= a.pre_pos | a.pre_neg | a.add | a.delete
    atoms = sorted(atoms_set)
    index = {a: i for i, a in enumerate(atoms)}

    def matrix(rows: list[list[int]]) -> sparse.csr_matrix:
        indptr = np.cumsum([0] + [len(r) for r in rows])
        data = np.ones(int(indptr[-1]), dtype=np.int32)
        cols = np.fromiter((c for r in rows for c in r), dtype=np.int64, count=int(indptr[-1]))
        return sparse.csr_matrix((data, cols, indptr), shape=(len(rows), len(atoms)))

    pre_rows = [[index[x] for x in a.pre_pos] for a in actions]
    add_rows = [[index[x] for x in a.add] for a in actions]
    add_of: list[list[int]] = [[] for _ in atoms]
    for i, row in enumerate(add_rows):
        for p in row:
            add_of[p].append(i)
    return GroundedTask(
        actions=actions, atoms=atoms, index=index,
        pre=matrix(pre_rows), neg=matrix([[index[x] for x in a.pre_neg] for a in actions]),
        add=matrix(add_rows), pre_len=np.array([len(r) for r in pre_rows], dtype=np.int32),
        add_of=add_of,
        add_ids=[np.array(r, dtype=np.int64) for r in add_rows],
        del_ids=[np.array([index[x] for x in a.delete], dtype=np.int64) for a in actions],
    )


def _ground_schema(task: PlanningTask, schema: ActionSchema, rigid_true: set[Atom]):
    k = task.knowledge
    params = [p for p, _ in schema.parameters]
    domains = [task.objects_of(t) for _, t in schema.parameters]
    # a rigid precondition is checked at the first parameter position where all its terms are bound
    rigid = [t for t in schema.preconditions if k.is_rigid(t.predicate)]
    checks: list[list] = [[] for _ in params]
    for t in rigid:
        last = max((params.index(x) for x in t.terms if x in params), default=-1)
        if last >= 0:
            checks[last].append(t)
        elif (Atom(t.predicate, t.terms) in rigid_true) != t.positive:
            return []  # a rigid precondition over constants only, and it is false: never applicable

    out: list[GroundAction] = []

    def extend(i: int, binding: dict[str, str]) -> None:
        if i == len(params):
            out.append(schema.ground(tuple(binding[p] for p in params)))
            return
        for obj in domains[i]:
            binding[params[i]] = obj
            if all((t.bind(binding).atom in rigid_true) == t.positive for t in checks[i]):
                extend(i + 1, binding)
        binding.pop(params[i], None)

    if not params:
        return [schema.ground(())]
    extend(0, {})
    return out


__all__ = ["GroundedTask", "ground"]
