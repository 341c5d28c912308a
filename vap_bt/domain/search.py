"""In-process heuristic search over a grounded task: greedy best-first with the FF heuristic.

Replanning after a situation must be fast (the robot is standing still meanwhile), and the
problems are small, so a search in this process beats starting a planner process each time. This
is the classic recipe: greedy best-first search, lazy (deferred) evaluation, the FF relaxed-plan
heuristic and its helpful actions in a second, preferred queue. The relaxed planning graph is
built with sparse matrix products, so one heuristic evaluation costs a few layers of mat-vecs.

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
    plan: list[int] | None  # action indices
    expanded: int
    evaluated: int
    exhausted: bool  # True when the whole space was searched (unsolvable), False when out of budget


def _relaxed(g: GroundedTask, state: np.ndarray, goal: np.ndarray) -> tuple[int, list[int]]:
    """FF heuristic and helpful actions; ``state`` and ``goal`` are boolean atom masks."""
    level = np.where(state, 0, INF).astype(np.int64)
    act_level = np.full(len(g.actions), INF, dtype=np.int64)
    reached = state.copy()
    layer = 0
    while not reached[goal].all():
        count = g.pre @ reached.astype(np.int32)
        enabled = (count == g.pre_len) & (act_level == INF)
        if not enabled.any():
            return INF, []
        act_level[enabled] = layer
        new = (g.add[enabled].sum(axis=0).A1 > 0) & ~reached
        if not new.any():
            return INF, []
        layer += 1
        level[new] = layer
        reached |= new
    # extract a relaxed plan backwards, choosing for each open goal its easiest achiever
    chosen: set[int] = set()
    marked = state.copy()
    agenda = sorted((int(level[p]), p) for p in np.flatnonzero(goal) if not state[p])
    heap = list(agenda)
    heapq.heapify(heap)
    pre_indptr, pre_idx = g.pre.indptr, g.pre.indices
    while heap:
        lv, p = heapq.heappop(heap)
        if marked[p]:
            continue
        best, best_cost = -1, None
        for a in g.add_of[p]:
            if act_level[a] < lv:
                pres = pre_idx[pre_indptr[a]:pre_indptr[a + 1]]
                cost = int(level[pres].sum()) if len(pres) else 0
                if best_cost is None or cost < best_cost:
                    best, best_cost = a, cost
        chosen.add(best)
        marked[g.add_ids[best]] = True
        for q in pre_idx[pre_indptr[best]:pre_indptr[best + 1]]:
            if not marked[q]:
                heapq.heappush(heap, (int(level[q]), int(q)))
    helpful = [a for a in chosen if act_level[a] == 0]
    return len(chosen), helpful


def _applicable(g: GroundedTask, state: np.ndarray) -> np.ndarray:
    s = state.astype(np.int32)
    ok = (g.pre @ s) == g.pre_len
    if g.neg.nnz:
        ok &= (g.neg @ s) == 0
    return np.flatnonzero(ok)


def gbfs(g: GroundedTask, init: frozenset[int], goal_pos: frozenset[int], goal_neg: frozenset[int] = frozenset(),
         max_expansions: int = 5000) -> SearchResult:
    n = len(g.atoms)
    goal = np.zeros(n, dtype=bool)
    goal[list(goal_pos)] = True
    gneg = list(goal_neg)

    def mask(s: frozenset[int]) -> np.ndarray:
        m = np.zeros(n, dtype=bool)
        m[list(s)] = True
        return m

    def is_goal(m: np.ndarray) -> bool:
        return bool(m[goal].all()) and not m[gneg].any()

    tie = itertools.count()
    parents: dict[frozenset[int], tuple[frozenset[int] | None, int]] = {init: (None, -1)}
    m0 = mask(init)
    h0, helpful0 = _relaxed(g, m0, goal)
    if is_goal(m0):
        return SearchResult([], 0, 1, False)
    if h0 >= INF and not gneg:
        return SearchResult(None, 0, 1, True)
    # lazy search: queue entries carry (parent state, action, parent's h); the child is evaluated when popped
    open_pref: list = []
    open_all: list = []

    def push_successors(s: frozenset[int], m: np.ndarray, h: int, helpful: list[int]) -> None:
        hs = set(helpful)
        for a in _applicable(g, m):
            entry = (h, next(tie), s, int(a))
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
        child = (s - frozenset(g.del_ids[a].tolist())) | frozenset(g.add_ids[a].tolist())
        if child in parents:
            continue
        parents[child] = (s, a)
        m = mask(child)
        if is_goal(m):
            return SearchResult(_trace(parents, child), expanded, evaluated, False)
        h, helpful = _relaxed(g, m, goal)
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
