"""The scene graph as rerun shows it: a fact sheet, a node-link graph, and boxes in 3-D.

Belief is a set of ground atoms over named objects (:class:`~vap_bt.scene.graph.SceneGraph`).
Three views of it, each complete on its own:

* **facts** — a markdown document, the atoms grouped by predicate, with the change that led to
  this state (its cause and the atoms added and removed) on top;
* **graph** — laid out by :mod:`~vap_bt.viz.scene_graph`: rooms with what they hold, each thing
  under what it rests on or in, relations as labelled edges, properties in the labels;
* **boxes** — objects whose perception gave an axis-aligned box (the pybullet world) as 3-D boxes
  in the world frame, next to the camera.
"""

from __future__ import annotations

from collections import defaultdict

import rerun as rr

from vap_bt.domain.atoms import Atom
from vap_bt.scene.graph import Change, SceneGraph



def facts_markdown(facts: set[Atom] | frozenset[Atom], change: Change | None = None, where: str = "") -> str:
    """The fact sheet: every atom of ``facts`` grouped by predicate under a count, with ``change`` (its
    cause, atoms added and removed) on top; ``where`` names the moment."""
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
    """The fact sheet of ``graph`` as a rerun markdown document."""
    return rr.TextDocument(facts_markdown(graph.facts, change, where), media_type=rr.MediaType.MARKDOWN)


def object_boxes(graph: SceneGraph) -> rr.Boxes3D | None:
    """Boxes of the objects that have one, or None when perception gave no geometry."""
    boxed = [o for o in graph.objects.values() if o.box is not None]
    if not boxed:
        return None
    return rr.Boxes3D(mins=[o.box[:3] for o in boxed],
                      sizes=[[hi - lo for lo, hi in zip(o.box[:3], o.box[3:])] for o in boxed],
                      labels=[o.name for o in boxed], show_labels=True)
