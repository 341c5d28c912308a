"""The scene graph as rerun shows it: a fact sheet, a node-link graph, and boxes in 3-D.

Belief is a set of ground atoms over named objects (:class:`~vap_bt.scene.graph.SceneGraph`).
Three views of it, each complete on its own:

* **facts** — a markdown document, the atoms grouped by predicate, with the change that led to
  this state (its cause and the atoms added and removed) on top;
* **graph** — objects are nodes; a relation over two or more objects is a small node named for
  its predicate, linked from its first argument to the others (``cup → on → counter``), so the
  predicate survives where a bare edge would lose it; a property of one object is written into
  that object's label; facts about no object (``hand_empty``) label one node of their own;
* **boxes** — objects whose perception gave an axis-aligned box (the pybullet world) as 3-D boxes
  in the world frame, next to the camera.
"""

from __future__ import annotations

from collections import defaultdict

import rerun as rr

from vap_bt.domain.atoms import Atom
from vap_bt.scene.graph import Change, SceneGraph

#: node id of the node that carries facts about no object
STATE_NODE = "(state)"
OBJECT_COLOUR = (70, 130, 200)
RELATION_COLOUR = (200, 200, 200)
STATE_COLOUR = (120, 90, 160)


def facts_markdown(facts: set[Atom] | frozenset[Atom], change: Change | None = None, where: str = "") -> str:
    lines = [f"# Belief: {len(facts)} facts" + (f" ({where})" if where else ""), ""]
    if change is not None:
        lines += [f"**Last change** ({change.cause}):"]
        lines += [f"- ➕ `{a}`" for a in sorted(map(str, change.added))]
        lines += [f"- ➖ `{a}`" for a in sorted(map(str, change.removed))]
        lines.append("")
    by_pred: dict[str, list[Atom]] = defaultdict(list)
    for a in facts:
        by_pred[a.predicate].append(a)
    for pred in sorted(by_pred):
        lines.append(f"## {pred}")
        lines += [f"- `{a}`" for a in sorted(by_pred[pred])]
        lines.append("")
    return "\n".join(lines)


def facts_document(graph: SceneGraph, change: Change | None = None, where: str = "") -> rr.TextDocument:
    return rr.TextDocument(facts_markdown(graph.facts, change, where), media_type=rr.MediaType.MARKDOWN)


def facts_graph(graph: SceneGraph) -> tuple[rr.GraphNodes, rr.GraphEdges]:
    names = set(graph.objects) | {x for a in graph.facts for x in a.args}
    props: dict[str, list[str]] = defaultdict(list)
    nullary: list[str] = []
    rel_ids, rel_labels, edges = [], [], []
    for a in sorted(graph.facts):
        if not a.args:
            nullary.append(a.predicate)
        elif len(a.args) == 1:
            props[a.args[0]].append(a.predicate)
        else:
            rid = str(a)
            rel_ids.append(rid)
            rel_labels.append(a.predicate)
            edges.append((a.args[0], rid))
            edges += [(rid, x) for x in a.args[1:]]
    obj_ids = sorted(names)
    obj_labels = [n + (f"\n[{', '.join(props[n])}]" if props[n] else "") for n in obj_ids]
    ids, labels = obj_ids + rel_ids, obj_labels + rel_labels
    colours = [OBJECT_COLOUR] * len(obj_ids) + [RELATION_COLOUR] * len(rel_ids)
    if nullary:
        ids.append(STATE_NODE)
        labels.append(", ".join(nullary))
        colours.append(STATE_COLOUR)
    return (rr.GraphNodes(ids, labels=labels, colors=colours, show_labels=True),
            rr.GraphEdges(edges, graph_type="directed"))


def object_boxes(graph: SceneGraph) -> rr.Boxes3D | None:
    """Boxes of the objects that have one, or None when perception gave no geometry."""
    boxed = [o for o in graph.objects.values() if o.box is not None]
    if not boxed:
        return None
    return rr.Boxes3D(mins=[o.box[:3] for o in boxed],
                      sizes=[[hi - lo for lo, hi in zip(o.box[:3], o.box[3:])] for o in boxed],
                      labels=[o.name for o in boxed], show_labels=True)
