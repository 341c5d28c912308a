"""The scene graph drawn for a person: rooms as columns of what they hold, relations as labelled edges.

Belief is a set of ground atoms. Left to rerun's force layout, a household's 40 facts become a
pile of overlapping ``in_room`` and ``on`` boxes; this module computes where everything goes,
as :mod:`~vap_bt.viz.tree_graph` does for the behaviour tree, so that nothing overlaps:

* **where things are** is a forest. Each object hangs from what holds it: the thing it is on or
  in (the support roles, :attr:`~vap_bt.domain.roles.Roles.support`: the household's ``on``,
  ``inside``), the robot when a one-argument location atom says the hand has it (``holding(cup)``),
  else its room (``in_room``). Rooms are the roots, drawn top to bottom; the robot hangs in the
  room belief puts it in (``robot_in``). Which predicate plays each part is the graph's
  :class:`~vap_bt.domain.roles.Roles` (the domain's perception profile says).
* the forest is laid out **sideways**: a node sits on the row of its first child, its children
  stacked below in the next column; every leaf has a row of its own (as tall as the row's
  tallest label), so no two labels share one. Between a node's column and its children's, a small grey node carries the relation's
  name — rerun cannot label an edge, so the edge is split at a label: ``cabinet — inside — cup``.
  Belonging to a room needs no label: the grouping says it.
* **properties** (one-argument facts) are written into their object's label, under its name —
  ``cabinet`` / ``[closed, openable]`` — and facts about nothing (``hand_empty``) into the robot's;
  the lines are kept short, since one long label widens a column and shrinks the whole drawing.
* every other relation (a door ``in_room`` of a second room, ``connected(a, b)``) is a grey
  node in a last column on its first argument's row, linked to each of its arguments.

Colours: objects blue, rooms dark, the robot purple, relation names grey. Pure layout: the
recorder logs :meth:`SceneDrawing.nodes` and :meth:`SceneDrawing.links`, and fits the view to
:meth:`SceneDrawing.bounds` as it does the tree's.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

import rerun as rr

from vap_bt.domain.atoms import Atom
from vap_bt.scene.graph import SceneGraph
from vap_bt.viz.tree_graph import GAP_X, GAP_Y, size_of

ROBOT = "(robot)"
OBJECT_COLOUR = (70, 130, 200)
ROOM_COLOUR = (40, 60, 110)
ROBOT_COLOUR = (120, 90, 160)
RELATION_COLOUR = (150, 150, 150)
#: properties are wrapped under an object's name to lines of this many characters (or the name's)
PROPERTY_CHARS = 18


@dataclass(frozen=True)
class SceneDrawing:
    """The nodes of a drawn scene graph (objects, the robot, relation labels) and its edges."""

    ids: tuple[str, ...]
    labels: tuple[str, ...]
    positions: tuple[tuple[float, float], ...]
    colours: tuple[tuple[int, int, int], ...]
    edges: tuple[tuple[str, str], ...]

    def nodes(self) -> rr.GraphNodes:
        """Every node (the objects, the robot, the relations' labels) as rerun graph nodes, each at its
        computed place with its label and colour."""
        return rr.GraphNodes(list(self.ids), labels=list(self.labels), positions=list(self.positions),
                             colors=list(self.colours), show_labels=True)

    def links(self) -> rr.GraphEdges:
        """The edges as rerun graph edges (undirected)."""
        # undirected: an edge reads both ways (``counter — on — cup``), and arrowheads would
        # point at the labels of the relations
        return rr.GraphEdges(list(self.edges), graph_type="undirected")

    def bounds(self, margin: float = 16.0) -> tuple[float, float, float, float]:
        """(min x, min y, max x, max y) of the labels, plus ``margin``."""
        boxes = [(x, y, *size_of(l)) for (x, y), l in zip(self.positions, self.labels)] or [(0.0, 0.0, 0.0, 0.0)]
        return (min(x - w / 2 for x, _, w, _ in boxes) - margin, min(y - h / 2 for _, y, _, h in boxes) - margin,
                max(x + w / 2 for x, _, w, _ in boxes) + margin, max(y + h / 2 for _, y, _, h in boxes) + margin)


@dataclass
class _Node:
    id: str
    label: str
    colour: tuple[int, int, int]
    relation: str | None = None  # the name on the edge from its parent (None: no label)
    atom: str | None = None  # the fact that edge stands for: the id of its label's node
    children: list["_Node"] | None = None

    def __post_init__(self) -> None:
        self.children = self.children or []


def draw(graph: SceneGraph) -> SceneDrawing:
    """The drawing of ``graph``'s facts (see the module docstring)."""
    facts, roles = sorted(graph.facts), graph.roles
    supports = roles.supports
    rooms = {o for o, obj in graph.objects.items() if roles.room is not None and obj.label == roles.room} | {
        a.args[1] for a in facts if a.predicate == roles.in_room and len(a.args) == 2}
    names = (set(graph.objects) | {x for a in facts for x in a.args}) - rooms
    props: dict[str, list[str]] = defaultdict(list)
    parent: dict[str, tuple[str, Atom | None]] = {}  # object -> (parent id, the fact that puts it there)
    robot_props: list[str] = [a.predicate for a in facts if not a.args]
    others: list[Atom] = []
    for a in facts:
        if len(a.args) == 1:
            x = a.args[0]
            if x in rooms and a.predicate in roles.robot:  # robot_in(kitchen): where the robot is
                parent.setdefault(ROBOT, (x, a))
            elif a.predicate in roles.location and not supports(a):  # holding(cup)
                parent[x] = (ROBOT, a)
            else:
                props[x].append(a.predicate)
    for a in facts:  # supports win over rooms, the hand over both (set above)
        if supports(a) and a.args[0] not in parent:
            parent[a.args[0]] = (a.args[1], a)
    for a in facts:
        if a.predicate == roles.in_room and len(a.args) == 2 and a.args[1] in rooms and a.args[0] not in parent:
            parent[a.args[0]] = (a.args[1], None)
    for a in facts:
        if len(a.args) < 2 or supports(a):
            continue
        # in_room(cup, kitchen) with the cup in a cabinet in the kitchen: the drawing says it already
        if not (a.predicate == roles.in_room and a.args[1] in _ancestors(parent, a.args[0])):
            others.append(a)
    nodes = {r: _Node(r, r, ROOM_COLOUR) for r in rooms}
    for n in names:
        nodes[n] = _Node(n, labelled(n, props[n]), OBJECT_COLOUR)
    if ROBOT in parent or any(p == ROBOT for p, _ in parent.values()) or robot_props:
        nodes[ROBOT] = _Node(ROBOT, labelled("robot", robot_props), ROBOT_COLOUR)
    roots = []
    for n in sorted(nodes, key=lambda k: (k not in rooms, k)):
        p, fact = parent.get(n, (None, None))
        if p in nodes and not _descends(parent, p, n):
            if fact is not None:
                nodes[n].relation, nodes[n].atom = fact.predicate, str(fact)
            nodes[p].children.append(nodes[n])
        else:
            roots.append(nodes[n])
    return _layout(roots, others)


def labelled(name: str, properties: list[str]) -> str:
    """The name, then its properties in brackets on lines no wider than the name (or
    :data:`PROPERTY_CHARS`): the panel is narrow, and a long line would shrink the whole drawing."""
    if not properties:
        return name
    width, lines = max(len(name), PROPERTY_CHARS), [""]
    for p in properties:
        word = p + ","
        if lines[-1] and len(lines[-1]) + 1 + len(word) + (len(lines) == 1) > width:  # the first line has "["
            lines.append("")
        lines[-1] = f"{lines[-1]} {word}".strip()
    lines[0] = "[" + lines[0]
    lines[-1] = lines[-1][:-1] + "]"
    return "\n".join([name, *lines])


def _ancestors(parent: dict, node: str) -> list[str]:
    """What ``node`` hangs from, nearest first. Belief can hold a cycle (a on b, b on a, after a
    wrong correction): the walk stops where it would come round again."""
    out: list[str] = []
    while node in parent and parent[node][0] not in out:
        node = parent[node][0]
        out.append(node)
    return out


def _descends(parent: dict, start: str, node: str) -> bool:
    """Whether ``start`` hangs (transitively) from ``node``: the drawing breaks a cycle of
    belief there instead of following it."""
    return start == node or node in _ancestors(parent, start)


def _layout(roots: list[_Node], others: list[Atom]) -> SceneDrawing:
    """Columns by depth (objects, then the labels of the edges to their children), rows by a
    walk of the forest: a node on its first child's row, a leaf on a row of its own, each row as
    tall as its tallest label."""
    order: list[tuple[_Node, int, int, str | None]] = []  # (node, depth, row, parent id) in walk order
    rows = 0

    def walk(node: _Node, depth: int, up: str | None) -> None:
        nonlocal rows
        order.append((node, depth, rows, up))
        if not node.children:
            rows += 1
        for c in node.children:
            walk(c, depth + 1, node.id)

    for r in roots:
        walk(r, 0, None)
    depths = {d for _, d, _, _ in order}
    widths = {d: max(size_of(n.label)[0] for n, nd, _, _ in order if nd == d) for d in depths}
    rel_w = {d: max((size_of(n.relation)[0] for n, nd, _, _ in order if nd == d + 1 and n.relation), default=0.0)
             for d in depths}
    x_obj, x_rel, x = {}, {}, 0.0
    for d in sorted(depths):
        x_obj[d] = x + widths[d] / 2
        x += widths[d] + GAP_X
        x_rel[d] = x + rel_w[d] / 2
        x += (rel_w[d] + GAP_X) if rel_w[d] else 0.0
    heights = [size_of("x")[1]] * max(rows, 1)
    for n, _, row, _ in order:
        heights[row] = max(heights[row], size_of(n.label)[1])
    tops = [sum(heights[:k]) + k * GAP_Y for k in range(len(heights))]
    y_row = [t + h / 2 for t, h in zip(tops, heights)]
    ids, labels, positions, colours, edges = [], [], [], [], []
    y_of: dict[str, float] = {}
    for node, d, row, up in order:
        ids.append(node.id), labels.append(node.label), positions.append((x_obj[d], y_row[row]))
        colours.append(node.colour)
        y_of[node.id] = y_row[row]
        if up is not None and node.relation:  # the edge's label: a node of its own between the columns
            ids.append(node.atom), labels.append(node.relation), colours.append(RELATION_COLOUR)
            positions.append((x_rel[d - 1], y_row[row]))
            edges += [(up, node.atom), (node.atom, node.id)]
        elif up is not None:
            edges.append((up, node.id))
    x_last, below = x + GAP_X, (tops[-1] + heights[-1] + GAP_Y if order else 0.0)
    for a in others:  # everything else: a grey node on its first argument's row, linked to each
        ids.append(str(a)), labels.append(a.predicate), colours.append(RELATION_COLOUR)
        y = y_of.get(a.args[0])
        if y is None:
            y, below = below + size_of("x")[1] / 2, below + size_of("x")[1] + GAP_Y
        positions.append((x_last + size_of(a.predicate)[0] / 2, y))
        edges.append((a.args[0], str(a)))
        edges += [(str(a), arg) for arg in a.args[1:]]
    return SceneDrawing(tuple(ids), tuple(labels), tuple(positions), tuple(colours), tuple(edges))
