"""A behaviour tree drawn as a graph: stable node ids, a tidy top-down layout, status colours.

A compiled tree is a few dozen py_trees behaviours whose names repeat ("pre", "eff",
"look(K=3)"), so a node is identified by its *path* of child indices from the root ("0",
"0.2", "0.2.1"), which stays the same for the life of one tree. The layout is fixed rather than
left to rerun's force simulation: leaves sit side by side in tree order, each parent centred over
its children, one row per depth — it reads like the diagrams in DESIGN.md and does not jitter
while statuses change.

:func:`status_nodes` is what changes per tick: the same ids with a colour per status
(SUCCESS green, FAILURE red, RUNNING amber, INVALID grey). The recorder compares
:func:`statuses` between ticks and logs only when something moved.
"""

from __future__ import annotations

from dataclasses import dataclass

import py_trees
import rerun as rr
from py_trees.common import Status

STATUS_COLOURS: dict[Status, tuple[int, int, int]] = {
    Status.SUCCESS: (46, 160, 67),
    Status.FAILURE: (215, 48, 39),
    Status.RUNNING: (240, 180, 0),
    Status.INVALID: (150, 150, 150),
}
#: layout spacing in graph-view units: between neighbouring leaves, and between depths
DX, DY = 170.0, 90.0


@dataclass(frozen=True)
class TreeGraph:
    """The structure of one tree: what does not change while it is ticked."""

    ids: tuple[str, ...]
    labels: tuple[str, ...]
    positions: tuple[tuple[float, float], ...]
    edges: tuple[tuple[str, str], ...]
    behaviours: tuple[py_trees.behaviour.Behaviour, ...]

    @classmethod
    def of(cls, root: py_trees.behaviour.Behaviour) -> "TreeGraph":
        ids, labels, edges, behaviours, depth, leaf_x = [], [], [], [], {}, {}
        next_leaf = [0]

        def visit(node, node_id: str, d: int) -> float:
            ids.append(node_id)
            labels.append(node.name)
            behaviours.append(node)
            depth[node_id] = d
            kids = list(node.children)
            if not kids:
                leaf_x[node_id] = next_leaf[0] * DX
                next_leaf[0] += 1
                return leaf_x[node_id]
            xs = []
            for i, child in enumerate(kids):
                child_id = f"{node_id}.{i}"
                edges.append((node_id, child_id))
                xs.append(visit(child, child_id, d + 1))
            leaf_x[node_id] = (xs[0] + xs[-1]) / 2
            return leaf_x[node_id]

        visit(root, "0", 0)
        positions = tuple((leaf_x[i], depth[i] * DY) for i in ids)
        return cls(tuple(ids), tuple(labels), positions, tuple(edges), tuple(behaviours))

    def statuses(self) -> tuple[Status, ...]:
        return tuple(b.status for b in self.behaviours)

    def structure(self) -> rr.GraphEdges:
        return rr.GraphEdges(list(self.edges), graph_type="directed")

    def status_nodes(self, statuses: tuple[Status, ...] | None = None) -> rr.GraphNodes:
        statuses = statuses or self.statuses()
        return rr.GraphNodes(list(self.ids), labels=list(self.labels), positions=list(self.positions),
                             colors=[STATUS_COLOURS[s] for s in statuses], show_labels=True)


def status_of_colour(rgb: tuple[int, int, int]) -> Status:
    """The inverse of :data:`STATUS_COLOURS` (for reading a recording back)."""
    return {v: k for k, v in STATUS_COLOURS.items()}[tuple(rgb[:3])]
