"""How well the robot's scene graph matches the world: precision and recall against the oracle.

Scored when a graph is built (the initial survey) and after every re-survey, at that moment, by
the runner (which holds the oracle); the executive never sees the score.

* **relations** — ``on``, ``inside`` and ``in_room`` atoms whose first argument is an item (the
  things that move; furniture's rooms are the map's and would only flatter the figure), over every
  typed candidate: true positives are believed atoms that hold. Reported over all items, and
  over the items the camera actually saw (``perceived``), so that what the task file's prior
  supplied is not counted as perception;
* **detections** — the objects perception reported (items, furniture, doors) against the objects
  the scene has; recall says how much the sweep found (what is shut in a closed container cannot
  be found); precision is 1 unless a detector reports a thing the scene does not have;
* **by predicate** — the same per relation, over all items and over the perceived ones, and
  beside them the items' ``blocking``/``reachable`` (geometry too, though not location: they are
  not in the headline figure, which stays comparable with earlier measurements).

The detector gives the robot class labels, and the robot names what it sees itself
(:mod:`vap_bt.scene.identity`): two bottles the task file does not tell apart (no ``belief:``
atom names either) may be bottle1 and bottle2 the other way round from the world's names, and
both are right. Such items — of one class, not named by the task's prior — are scored under the
best matching of the robot's names to the world's instances (:func:`match_instances`: the
assignment minimising the distance from each graph node's believed centroid to the instance's
true centre; in a world without geometry, the one agreeing with the most believed relations),
and the swaps it made are reported (``swaps``).
"""

from __future__ import annotations

from itertools import product
from typing import Mapping

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.domain.task import PlanningTask
from vap_bt.robot.labels import class_of
from vap_bt.sim.oracle import Oracle

RELATIONS = ("on", "inside", "in_room")
#: relations between items the graph also derives by geometry, scored apart
AFFORDANCES = ("blocking", "reachable")


def _pr(believed: set[Atom], true: set[Atom]) -> dict:
    tp = len(believed & true)
    return {"precision": round(tp / len(believed), 4) if believed else 1.0,
            "recall": round(tp / len(true), 4) if true else 1.0,
            "tp": tp, "fp": len(believed - true), "fn": len(true - believed)}


def candidates(task: PlanningTask, items: list[str], predicates=RELATIONS) -> set[Atom]:
    """Every typed atom of ``predicates`` (unary or binary) whose first argument is an item."""
    k = task.knowledge
    out = set()
    for p in predicates:
        sig = k.predicates.get(p)
        if sig is None or len(sig) not in (1, 2):
            continue
        if len(sig) == 1:
            out |= {Atom(p, (o,)) for o in items if k.is_subtype(task.objects[o], sig[0])}
            continue
        for o, x in product(items, task.objects):
            if k.is_subtype(task.objects[o], sig[0]) and k.is_subtype(task.objects[x], sig[1]) and o != x:
                out.add(Atom(p, (o, x)))
    return out


def match_instances(oracle: Oracle, items: list[str], told: set[str], centroids: Mapping[str, tuple | None],
                    believed: set[Atom], true: set[Atom]) -> dict[str, str]:
    """The robot's name -> the world's instance, for items of one class the task does not tell
    apart (see the module docstring); identity elsewhere."""
    out = {o: o for o in items}
    position = getattr(oracle, "position", lambda name: None)  # a world elsewhere may not say
    groups: dict[str, list[str]] = {}
    for o in items:
        if o not in told:
            groups.setdefault(class_of(o), []).append(o)
    for group in groups.values():
        if len(group) < 2:
            continue
        cost = np.zeros((len(group), len(group)))
        for i, n in enumerate(group):
            for j, m in enumerate(group):
                c, p = centroids.get(n), position(m)
                if c is not None and p is not None:
                    cost[i, j] = float(np.linalg.norm(np.subtract(c, p)))
                else:  # no geometry: the matching that makes the most believed relations true
                    cost[i, j] = -sum(_renamed(a, {n: m}) in true for a in believed if a.args and a.args[0] == n)
        from scipy.optimize import linear_sum_assignment  # on first use: scipy.optimize costs 0.6 s at start-up

        rows, cols = linear_sum_assignment(cost)
        out.update({group[i]: group[j] for i, j in zip(rows, cols)})
    return out


def _renamed(atom: Atom, names: Mapping[str, str]) -> Atom:
    return Atom(atom.predicate, tuple(names.get(a, a) for a in atom.args))


def score_graph(oracle: Oracle, task: PlanningTask, facts: frozenset[Atom], perceived: set[str],
                detectable: set[str], told: set[str] | None = None,
                centroids: Mapping[str, tuple | None] | None = None) -> dict:
    """The figures described in the module docstring, for one graph at the moment it was built.
    ``detectable`` are the scene's objects a detector could report (items, furniture, doors);
    ``told``: the objects the task's prior names (the rest of a class may be matched to the
    world's instances either way round); ``centroids``: the graph's believed centroid per object."""
    k = task.knowledge
    items = sorted(o for o, t in task.objects.items() if "item" in k.parents and k.is_subtype(t, "item"))
    cands = candidates(task, items)
    true = set(oracle.true_atoms(cands))
    believed = {a for a in facts if a in cands}
    match = match_instances(oracle, items, set(items) if told is None else told, centroids or {}, believed, true)
    swaps = {n: m for n, m in match.items() if n != m}
    believed = {_renamed(a, swaps) for a in believed}
    perceived = {swaps.get(o, o) for o in perceived}
    seen = set(items) & perceived
    out = {"relations": _pr(believed, true),
           "relations_perceived": _pr({a for a in believed if a.args[0] in seen}, {a for a in true if a.args[0] in seen}),
           "detections": {**_pr(set(perceived), set(detectable)), "missed": sorted(set(detectable) - perceived)},
           "by_predicate": {p: _pr({a for a in believed if a.predicate == p}, {a for a in true if a.predicate == p})
                            for p in RELATIONS if any(a.predicate == p for a in cands)}}
    out["by_predicate_perceived"] = {p: _pr({a for a in believed if a.predicate == p and a.args[0] in seen},
                                            {a for a in true if a.predicate == p and a.args[0] in seen})
                                     for p in out["by_predicate"]}
    extra = candidates(task, items, AFFORDANCES)
    if extra:
        # blocking(b, o) is about two items: perceived when the camera saw both
        both = {a for a in extra if set(a.args) <= seen}
        true_x = set(oracle.true_atoms(both))
        held = {_renamed(a, swaps) for a in facts} & both
        out["affordances_perceived"] = {p: _pr({a for a in held if a.predicate == p}, {a for a in true_x if a.predicate == p})
                                        for p in AFFORDANCES if any(a.predicate == p for a in both)}
    if swaps:
        out["swaps"] = dict(sorted(swaps.items()))
    if believed - true:
        out["wrong"] = sorted(map(str, believed - true))
    if true - believed:
        out["missing"] = sorted(map(str, true - believed))
    return out
