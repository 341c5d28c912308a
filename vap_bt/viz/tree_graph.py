"""A behaviour tree drawn for a person: the plan as a column, the open action spread out beside it.

A compiled tree has a dozen nodes per action; drawn whole, a 7-action plan is a strip of 60
boxes too small to read. This view shows what someone watching needs, at positions computed
here (rerun lays out no trees, and its graph view fits the whole drawing into the panel, never
zooming in past 1:1 — so the drawing's size decides whether its text can be read):

* the root (``plan``) at the top and its children — the plan's actions, the goal's checks, the
  goal check — as one column below it, each *folded* to one node that says how it ended:
  ``✓ a0: find(…)``, ``✗ a1: grasp(…) — eff: holding(cup)``, ``· a2: navigate(…)`` (not yet);
* the *open* child — the one running or, once the tree has failed, the one that failed —
  spread out in a row to its right: ``pre``, ``execute grasp``, ``apply effects``, ``eff``, each
  phase's checks hanging in a column under it; an ``ActivePerception`` and the
  ``VerifyPredicate`` it decorates are one node, named by the atom;
* status as the label's colour and a mark (✓ success, ✗ failure, ▶ running, · not run); a
  running node adds a second line — the skill's progress, or the check's view and answers
  (``view 2: yyyny→yes``) — no wider than its first, so nothing moves when it appears. rerun
  colours a node's text only — it has no node size or fill for labelled nodes and cannot colour
  edges — so the active path is the orange ▶ chain from the root to the running leaf, the only
  two-line labels in the drawing.

Edges are all vertical or horizontal: a parent's children sit on one line through its centre.
rerun draws an edge as a straight line between node centres, behind the (opaque) labels, so
the lines to later children pass behind the earlier ones and read as the sequence's order,
``plan ↓ a0 ↓ a1 …``, instead of a fan of diagonals across the labels.

Nodes are identified by their *path* of child indices from the root (``"0"``, ``"0.2"``,
``"0.2.1"``), which stays the same for the life of one tree; a folded node keeps the id of the
behaviour it stands for. :meth:`TreeGraph.signature` is what the view depends on (statuses,
feedback, views taken), so the recorder computes and logs a view only when it changed.
:meth:`TreeGraph.extent` bounds every drawing of one tree, whichever child is open: the
recorder makes it the graph view's visible area, because the view otherwise keeps the zoom at
which it fitted the first drawing and cuts off a later, wider one.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import py_trees
import rerun as rr
from py_trees.common import Status

from vap_bt.bt.active_perception import ActivePerception
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.recovery import RecoveryRoot

#: text colours, readable on the viewer's light and dark themes alike
STATUS_COLOURS: dict[Status, tuple[int, int, int]] = {
    Status.SUCCESS: (0, 150, 60),
    Status.FAILURE: (215, 40, 40),
    Status.RUNNING: (235, 130, 0),
    Status.INVALID: (130, 130, 130),
}
MARKS: dict[Status, str] = {Status.SUCCESS: "✓", Status.FAILURE: "✗", Status.RUNNING: "▶", Status.INVALID: "·"}

# Geometry in graph-view units, which are screen pixels at zoom 1. Measured on rerun 0.41's web
# viewer: labels are 12 px Inter, 5.64 px per character of our names, in a frame with a 6x4 px
# margin and a 1 px stroke (about 24 px tall for one line); the estimates err a little wide.
CHAR_W, PAD_W = 5.9, 16.0
LINE_H, PAD_H = 15.0, 10.0
#: space between neighbouring labels: wider than an arrowhead (10 px), so each arrow shows
GAP_X, GAP_Y = 28.0, 12.0
#: a running node's second line is cut to its first line's length, but may have this many characters
FEEDBACK_MIN_CHARS = 12


def size_of(label: str) -> tuple[float, float]:
    """The estimated (width, height) of a node with this label."""
    lines = label.split("\n")
    return max(len(l) for l in lines) * CHAR_W + PAD_W, len(lines) * LINE_H + PAD_H


@dataclass(frozen=True)
class TreeView:
    """The visible nodes of a tree at one tick: ids, labels, centres, statuses and edges."""

    ids: tuple[str, ...]
    labels: tuple[str, ...]
    positions: tuple[tuple[float, float], ...]
    statuses: tuple[Status, ...]
    edges: tuple[tuple[str, str], ...]

    def nodes(self) -> rr.GraphNodes:
        """The drawing's nodes as rerun logs them: labels at their positions, coloured by status."""
        return rr.GraphNodes(list(self.ids), labels=list(self.labels), positions=list(self.positions),
                             colors=[STATUS_COLOURS[s] for s in self.statuses], show_labels=True)

    def links(self) -> rr.GraphEdges:
        """The drawing's edges as rerun logs them."""
        return rr.GraphEdges(list(self.edges), graph_type="directed")

    def bounds(self) -> tuple[float, float, float, float]:
        """(min x, min y, max x, max y) of the labels: what the graph view fits into its panel."""
        boxes = [(x, y, *size_of(l)) for (x, y), l in zip(self.positions, self.labels)]
        return (min(x - w / 2 for x, _, w, _ in boxes), min(y - h / 2 for _, y, _, h in boxes),
                max(x + w / 2 for x, _, w, _ in boxes), max(y + h / 2 for _, y, _, h in boxes))


class _Drawing:
    """Collects the visible nodes while the layout places them."""

    def __init__(self) -> None:
        self.ids, self.labels, self.positions, self.statuses, self.edges = [], [], [], [], []

    def node(self, node_id: str, label: str, status: Status, x: float, y: float, parent: str | None) -> None:
        self.ids.append(node_id)
        self.labels.append(label)
        self.positions.append((x, y))
        self.statuses.append(status)
        if parent is not None:
            self.edges.append((parent, node_id))

    def view(self) -> TreeView:
        return TreeView(tuple(self.ids), tuple(self.labels), tuple(self.positions), tuple(self.statuses),
                        tuple(self.edges))


def short_name(node: py_trees.behaviour.Behaviour) -> str:
    """The name a node goes by in the drawing (the action's arguments are on the action already)."""
    if isinstance(node, ActivePerception):
        return node.verify.name
    if isinstance(node, ExecuteSkill):
        return f"execute {node.action.name}"
    return node.name


def failed_at(node: py_trees.behaviour.Behaviour) -> str:
    """Where inside ``node`` the failure happened: ``"eff: holding(cup)"``, ``"execute grasp"``."""
    names = []
    while node.children:
        failed = [c for c in node.children if c.status == Status.FAILURE]
        if not failed:
            break
        node = failed[0]
        names.append(short_name(node))
        if isinstance(node, ActivePerception):
            break
    return ": ".join(names)


def label_of(node: py_trees.behaviour.Behaviour, folded: bool = False) -> str:
    """Mark and name; a folded failure adds where it failed, a running node its feedback."""
    text = f"{MARKS[node.status]} {short_name(node)}"
    if folded and node.status == Status.FAILURE and node.children and not isinstance(node, ActivePerception):
        where = failed_at(node)
        text += f" — {where}" if where else ""
    feedback = _round_summary(node) if isinstance(node, ActivePerception) else node.feedback_message
    if node.status == Status.RUNNING and feedback:
        room = max(len(text), FEEDBACK_MIN_CHARS)
        text += "\n" + (feedback if len(feedback) <= room else feedback[:room - 1] + "…")
    return text


def _round_summary(check: ActivePerception) -> str:
    """The check's view count and last round in a few characters: ``view 2: yyyny→yes``."""
    r = check.verify.round
    if r is None:
        return ""
    answers = "".join("?" if a is None else ("y" if a else "n") for a in r.answers)
    vote = "?" if r.vote is None else ("yes" if r.vote else "no")
    return f"view {max(len(check.rounds), 1)}: {answers}→{vote}"


def _is_leaf_for_view(node: py_trees.behaviour.Behaviour) -> bool:
    return not node.children or isinstance(node, ActivePerception)


@dataclass(frozen=True)
class TreeGraph:
    """The structure of one tree (what does not change while it is ticked) and its views."""

    ids: tuple[str, ...]
    behaviours: tuple[py_trees.behaviour.Behaviour, ...]

    @classmethod
    def of(cls, root: py_trees.behaviour.Behaviour) -> "TreeGraph":
        """The tree under ``root``, each behaviour with its path id (``0``, ``0.2``, ``0.2.1``), depth
        first."""
        ids, behaviours = [], []

        def visit(node, node_id: str) -> None:
            ids.append(node_id)
            behaviours.append(node)
            for i, child in enumerate(node.children):
                visit(child, f"{node_id}.{i}")

        visit(root, "0")
        return cls(tuple(ids), tuple(behaviours))

    @property
    def root(self) -> py_trees.behaviour.Behaviour:
        return self.behaviours[0]

    def statuses(self) -> tuple[Status, ...]:
        """Every behaviour's status now, in :attr:`ids` order."""
        return tuple(b.status for b in self.behaviours)

    def signature(self) -> tuple:
        """Everything the view and the text depend on; equal signatures draw the same."""
        return tuple((b.status, b.feedback_message, len(b.rounds) if isinstance(b, ActivePerception) else 0)
                     for b in self.behaviours)

    @cached_property
    def actions(self) -> tuple[ExecuteSkill, ...]:
        """The plan's actions, in order (the root's other children are the goal's checks): the
        count the command line prints. The structure never changes, so it is counted once."""
        return tuple(b for b in self.behaviours if isinstance(b, ExecuteSkill))

    def open_child(self) -> int | None:
        """Index of the root's child that is spread out: the running one, else the failed one."""
        kids = self.root.children
        for wanted in (Status.RUNNING, Status.FAILURE):
            for i, c in enumerate(kids):
                if c.status == wanted and c.children:
                    return i
        return None

    def view(self, opened: int | None | str = "auto") -> TreeView:
        """The drawing at the current statuses, with the :meth:`open_child` (or child ``opened``)
        spread out."""
        root, d = self.root, _Drawing()
        opened = self.open_child() if opened == "auto" else opened
        kids = list(root.children)
        labels = [label_of(c, folded=i != opened) for i, c in enumerate(kids)]
        column_w = max((size_of(l)[0] for l in labels), default=0.0)
        root_label = label_of(root)
        if not isinstance(root, RecoveryRoot):  # a recovery's steps are no plan's actions
            root_label += f" · {plural(len(self.actions), 'action')}"
        d.node("0", root_label, root.status, 0.0, 0.0, None)
        y, h_prev = 0.0, size_of(root_label)[1]
        for i, (child, label) in enumerate(zip(kids, labels)):
            h = size_of(label)[1]
            y += h_prev / 2 + GAP_Y + h / 2
            child_id = f"0.{i}"
            d.node(child_id, label, child.status, 0.0, y, "0")
            if i == opened:
                self._spread(d, child, child_id, column_w / 2 + GAP_X, y)
            h_prev = h
        return d.view()

    def extent(self, margin: float = 16.0) -> tuple[float, float, float, float]:
        """Bounds that hold the drawing whichever child is open, plus ``margin`` and, below, room
        for the second lines of a running path: the graph view's visual area for this tree, so the
        zoom stays put while the tree runs and a spread-out action is never cut off."""
        views = [self.view(opened=k) for k in [None, *range(len(self.root.children))]]
        corners = [v.bounds() for v in views]
        running_line = LINE_H  # composites have no feedback: only the running leaf grows a line
        return (min(c[0] for c in corners) - margin, min(c[1] for c in corners) - margin,
                max(c[2] for c in corners) + margin, max(c[3] for c in corners) + margin + running_line)

    def _spread(self, d: _Drawing, node, node_id: str, x_left: float, y: float) -> None:
        """``node``'s children in a row from ``x_left`` at height ``y``; their children hang below."""
        for i, child in enumerate(node.children):
            child_id = f"{node_id}.{i}"
            label = label_of(child)
            hanging = [] if _is_leaf_for_view(child) else list(child.children)
            hanging_labels = [label_of(g, folded=True) for g in hanging]
            width = max(size_of(l)[0] for l in [label, *hanging_labels])
            x = x_left + width / 2
            d.node(child_id, label, child.status, x, y, node_id)
            gy, h_prev = y, size_of(label)[1]
            for j, (g, g_label) in enumerate(zip(hanging, hanging_labels)):
                h = size_of(g_label)[1]
                gy += h_prev / 2 + GAP_Y + h / 2
                d.node(f"{child_id}.{j}", g_label, g.status, x, gy, child_id)
                h_prev = h
            x_left += width + GAP_X


def plural(n: int, word: str) -> str:
    """``n`` and ``word``, with an s unless ``n`` is 1 (``3 answers``, ``1 view``)."""
    return f"{n} {word}{'s' * (n != 1)}"


def status_of_colour(rgb: tuple[int, int, int]) -> Status:
    """The inverse of :data:`STATUS_COLOURS` (for reading a recording back)."""
    return {v: k for k, v in STATUS_COLOURS.items()}[tuple(rgb[:3])]
