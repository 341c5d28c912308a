"""In-process heuristic search over a grounded task: greedy best-first with the FF heuristic.

Replanning after a situation must be fast (the robot is standing still meanwhile), and the
problems are small, so a search in this process beats starting a planner process each time. This
is the classic recipe: greedy best-first search, lazy (deferred) evaluation, the FF relaxed-plan
heuristic and its helpful actions in a second, preferred queue. The relaxed planning graph is
built with sparse matrix products, so one heuristic evaluation costs a few layers of mat-vecs.

Conditional effects enter the relaxed graph as the grounding's effect *units* (an effect is
reachable once its action's and its condition's positive literals are); a unit's action is what a
relaxed plan counts. With action costs the heuristic sums the chosen actions' costs plus one (as
LAMA's cost transform does, so zero-cost actions still count) and the queue is ordered by
g + w·h (lazy weighted A*, w = 3, as the Fast Downward configuration the planner uses for costed
tasks): plain greedy search ignores the cost of the path it has already taken.

The search is complete for the grounded task (it falls back to all successors) but bounded by a
node budget; past it the caller falls back to Fast Downward.
"""

from __future__ import annotations

import heapq
import itertools
from dataclasses import dataclass

import numpy as np

from vap_bt.domain.grounding import GroundedTask

INF = np.iinfo(np.int32).max


@dataclass
class SearchResult:
    """A search's outcome and effort."""

    plan: list[int] | None  # action indices
    expanded: int
    evaluated: int
    exhausted: bool  # True when the whole space was searched (unsolvable), False when out of budget


def _relaxed(g: GroundedTask, state: np.ndarray, goal: np.ndarray,
             costs: np.ndarray | None) -> tuple[int, list[int]]:
    """FF heuristic and helpful actions; ``state`` and ``goal`` are boolean atom masks; ``costs``
    per action (None: count actions, with the layered planning graph)."""
    if costs is not None:
        return _relaxed_costs(g, state, goal, costs)
    level = np.where(state, 0, INF).astype(np.int64)
    unit_level = np.full(len(g.unit_action), INF, dtype=np.int64)
    reached = state.copy()
    layer = 0
    while not reached[goal].all():
        count = g.upre @ reached.astype(np.int32)
        enabled = (count == g.upre_len) & (unit_level == INF)
        if not enabled.any():
            return INF, []
        unit_level[enabled] = layer
        new = (g.uadd[enabled].sum(axis=0).A1 > 0) & ~reached
        if not new.any():
            return INF, []
        layer += 1
        level[new] = layer
        reached |= new
    # extract a relaxed plan backwards, choosing for each open goal its easiest achiever
    chosen: set[int] = set()
    marked = state.copy()
    heap = sorted((int(level[p]), p) for p in np.flatnonzero(goal) if not state[p])
    heapq.heapify(heap)
    pre_indptr, pre_idx = g.upre.indptr, g.upre.indices
    while heap:
        lv, p = heapq.heappop(heap)
        if marked[p]:
            continue
        best, best_cost = -1, None
        for u in g.add_of[p]:
            if unit_level[u] < lv:
                pres = pre_idx[pre_indptr[u]:pre_indptr[u + 1]]
                cost = int(level[pres].sum()) if len(pres) else 0
                if best_cost is None or cost < best_cost:
                    best, best_cost = u, cost
        chosen.add(best)
        marked[g.unit_adds[best]] = True
        for q in pre_idx[pre_indptr[best]:pre_indptr[best + 1]]:
            if not marked[q]:
                heapq.heappush(heap, (int(level[q]), int(q)))
    acts = {int(g.unit_action[u]) for u in chosen}
    helpful = sorted({int(g.unit_action[u]) for u in chosen if unit_level[u] == 0})
    h = len(acts) if costs is None else int(sum(costs[a] for a in acts))
    return h, helpful


def _relaxed_costs(g: GroundedTask, state: np.ndarray, goal: np.ndarray,
                   costs: np.ndarray) -> tuple[int, list[int]]:
    """FF over action costs: best supporters by h_add (the cheapest unit that adds an atom, its
    cost being its action's plus its preconditions'), propagated to a fixpoint; the relaxed plan
    follows best supporters back from the goal. Costs are at least 1, so supporters form no cycle."""
    atom = np.where(state, 0, INF).astype(np.int64)
    unit_cost = costs[g.unit_action].astype(np.int64)
    add_cols = g.uadd.indices
    add_rows = np.repeat(np.arange(len(g.unit_action)), np.diff(g.uadd.indptr))
    while True:
        finite = atom < INF
        ok = (g.upre @ finite.astype(np.int32)) == g.upre_len
        ucost = np.where(ok, g.upre @ np.where(finite, atom, 0) + unit_cost, INF)
        new = atom.copy()
        np.minimum.at(new, add_cols, ucost[add_rows])
        if (new == atom).all():
            break
        atom = new
    if (atom[goal] >= INF).any():
        return INF, []
    chosen: set[int] = set()
    marked = state.copy()
    agenda = [int(p) for p in np.flatnonzero(goal) if not state[p]]
    pre_indptr, pre_idx = g.upre.indptr, g.upre.indices
    while agenda:
        p = agenda.pop()
        if marked[p]:
            continue
        best = min(g.add_of[p], key=lambda u: ucost[u])
        chosen.add(best)
        marked[g.unit_adds[best]] = True
        agenda += [int(q) for q in pre_idx[pre_indptr[best]:pre_indptr[best + 1]] if not marked[q]]
    acts = {int(g.unit_action[u]) for u in chosen}
    helpful = sorted({int(g.unit_action[u]) for u in chosen
                      if all(state[q] for q in pre_idx[pre_indptr[u]:pre_indptr[u + 1]])})
    return int(sum(costs[a] for a in acts)), helpful


def _applicable(g: GroundedTask, state: np.ndarray) -> np.ndarray:
    """Actions applicable in ``state``: those with a precondition disjunct that holds."""
    s = state.astype(np.int32)
    ok = (g.pre @ s) == g.pre_len
    if g.neg.nnz:
        ok &= (g.neg @ s) == 0
    return np.unique(g.row_action[ok])


#: weight of the heuristic in the weighted A* used for tasks with action costs
COST_WEIGHT = 3


def gbfs(g: GroundedTask, init: frozenset[int], goal_pos: frozenset[int], goal_neg: frozenset[int] = frozenset(),
         max_expansions: int = 5000, use_costs: bool = False) -> SearchResult:
    """Greedy best-first search (``use_costs``: weighted A* over the actions' costs)."""
    n = len(g.atoms)
    goal = np.zeros(n, dtype=bool)
    goal[list(goal_pos)] = True
    gneg = list(goal_neg)
    costs = g.cost + 1 if use_costs else None  # plus one: zero-cost actions still cost search effort

    def mask(s: frozenset[int]) -> np.ndarray:
        m = np.zeros(n, dtype=bool)
        m[list(s)] = True
        return m

    def is_goal(m: np.ndarray) -> bool:
        return bool(m[goal].all()) and not m[gneg].any()

    tie = itertools.count()
    parents: dict[frozenset[int], tuple[frozenset[int] | None, int]] = {init: (None, -1)}
    path_cost: dict[frozenset[int], int] = {init: 0}
    m0 = mask(init)
    h0, helpful0 = _relaxed(g, m0, goal, costs)
    if is_goal(m0):
        return SearchResult([], 0, 1, False)
    if h0 >= INF and not gneg:
        return SearchResult(None, 0, 1, True)
    # lazy search: queue entries carry (parent state, action); the child is evaluated when popped,
    # ranked by the parent's h (greedy) or by the child's g plus w times the parent's h (costs)
    open_pref: list = []
    open_all: list = []

    def push_successors(s: frozenset[int], m: np.ndarray, h: int, helpful: list[int]) -> None:
        hs = set(helpful)
        for a in _applicable(g, m):
            rank = h if costs is None else path_cost[s] + int(costs[a]) + COST_WEIGHT * h
            entry = (rank, next(tie), s, int(a))
            heapq.heappush(open_all, entry)
            if a in hs:
                heapq.heappush(open_pref, entry)

    push_successors(init, m0, h0, helpful0)
    expanded, evaluated, turn = 0, 1, 0
    while open_pref or open_all:
        # alternate queues, favouring helpful actions (as FF and Fast Downward's lazy search do)
        turn += 1
        q = open_pref if (open_pref and (turn % 4 != 0 or not open_all)) else open_all
        _, _, s, a = heapq.heappop(q)
        child = g.successor(s, a)
        if child in parents:
            continue
        parents[child] = (s, a)
        path_cost[child] = path_cost[s] + (int(costs[a]) if costs is not None else 1)
        m = mask(child)
        if is_goal(m):
            return SearchResult(_trace(parents, child), expanded, evaluated, False)
        h, helpful = _relaxed(g, m, goal, costs)
        evaluated += 1
        if h >= INF:
            continue
        expanded += 1
        if expanded > max_expansions:
            return SearchResult(None, expanded, evaluated, False)
        push_successors(child, m, h, helpful)
    return SearchResult(None, expanded, evaluated, True)


def _trace(parents, s) -> list[int]:
    plan = []
    while True:
        prev, a = parents[s]
        if prev is None:
            return plan[::-1]
        plan.append(a)
        s = prev
