"""The tree as drawn for rerun (vap_bt/viz/tree_graph.py) and in words (tree_text.py).

Compiled trees are given statuses by hand (as ticking would leave them) and the drawing is
checked for what a person needs: the root on top, the actions in one column, the open action
spread out with its checks, the rest folded to their outcome, axis-aligned edges, labels that do
not overlap, and a 20-action plan that fits the tree panel of the default layout at a zoom where
12 px text stays readable.
"""

from __future__ import annotations

import functools
import itertools

import pytest
from py_trees.common import Status

pytest.importorskip("rerun")

from vap_bt.viz.tree_graph import MARKS, STATUS_COLOURS, TreeGraph, label_of, size_of  # noqa: E402
from vap_bt.viz.tree_text import tree_text  # noqa: E402

from conftest import TREES, tree_for  # noqa: E402

#: the behaviour-tree panel of the default blueprint in a 1920x1080 browser window, measured on the
#: screenshots of tests/test_live_view.py: 9/20 of the width, 4/5 of the height between the top bar
#: and the time panel, less the view's title bar
PANEL_W, PANEL_H = 860.0, 780.0
#: the zoom below which 12 px labels are no longer comfortably readable (about 10 px)
MIN_ZOOM = 0.85


@functools.cache
def plan_of(task_file: str):
    from vap_bt.domain.planner import Planner
    from vap_bt.taskfile import load

    planning = load(TREES / task_file).planning
    return planning, tuple(Planner(planning).plan().actions)


def compiled(task_file: str = "collect_cup.yaml", actions=None):
    planning, plan = plan_of(task_file)
    return tree_for(planning, list(actions or plan), "both")


def mark(node, status: Status) -> None:
    node.status = status
    for c in node.children:
        mark(c, status)


def running_at(root, k: int, checks_done: int = 1) -> None:
    """Statuses as ticking leaves them while action ``k`` runs its precondition checks."""
    mark(root, Status.INVALID)
    root.status = Status.RUNNING
    for child in root.children[:k]:
        mark(child, Status.SUCCESS)
    action = root.children[k]
    action.status = Status.RUNNING
    phase = action.children[0]
    phase.status = Status.RUNNING
    for i, check in enumerate(phase.children):
        if i < checks_done:
            mark(check, Status.SUCCESS)
        elif i == checks_done:
            mark(check, Status.RUNNING)


def boxes(view):
    return [(x - w / 2, y - h / 2, x + w / 2, y + h / 2)
            for (x, y), (w, h) in zip(view.positions, map(size_of, view.labels))]


def overlapping(view) -> list[tuple[str, str]]:
    out = []
    for (i, a), (j, b) in itertools.combinations(enumerate(boxes(view)), 2):
        if a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]:
            out.append((view.labels[i], view.labels[j]))
    return out


def test_before_the_first_tick_the_plan_is_one_column_under_the_root():
    root = compiled()
    view = TreeGraph.of(root).view()
    assert view.ids == ("0", *[f"0.{i}" for i in range(len(root.children))])
    assert view.positions[0] == (0.0, 0.0) and view.labels[0].startswith("· plan")
    ys = [y for _, y in view.positions]
    assert all(x == 0.0 for x, _ in view.positions) and ys == sorted(ys) and len(set(ys)) == len(ys)
    assert [l.split(" ", 1)[1] for l in view.labels[1:]] == [c.name for c in root.children]
    assert set(view.edges) == {("0", f"0.{i}") for i in range(len(root.children))}
    assert set(view.statuses) == {Status.INVALID}


def test_the_running_action_is_spread_out_and_the_others_folded():
    root = compiled()
    k = next(i for i, c in enumerate(root.children) if c.name.startswith("a1: grasp"))
    running_at(root, k)
    view = TreeGraph.of(root).view()
    at = dict(zip(view.ids, zip(view.labels, view.positions, view.statuses)))
    action = f"0.{k}"
    # the open action's children in a row to its right, on its line; the checks hang under "pre"
    row = [f"{action}.{i}" for i in range(4)]
    assert [at[i][0].split("\n")[0] for i in row] == ["▶ pre", "· execute grasp", "· apply effects", "· eff"]
    xs = [at[i][1][0] for i in row]
    assert all(at[i][1][1] == at[action][1][1] for i in row) and xs == sorted(xs) and xs[0] > 0
    pre_checks = [i for i in view.ids if i.startswith(f"{action}.0.")]
    assert [at[i][0].split("\n")[0] for i in pre_checks] == [
        "✓ inview(cup)", "▶ hand_empty", "· reachable(cup)", "· on(cup, coffee_table)"]
    assert all(at[i][1][0] == xs[0] for i in pre_checks)
    # finished and future actions are one node each, with their outcome
    assert at["0.0"][0] == f"✓ {root.children[0].name}" and not any(i.startswith("0.0.") for i in view.ids)
    assert at[f"0.{k + 1}"][0] == f"· {root.children[k + 1].name}"
    # the active path: orange from the root to the running check, and nothing else running
    running = [i for i, s in zip(view.ids, view.statuses) if s == Status.RUNNING]
    assert running == ["0", action, f"{action}.0", f"{action}.0.1"]
    assert STATUS_COLOURS[Status.RUNNING] not in [STATUS_COLOURS[s] for s in view.statuses if s != Status.RUNNING]
    # a tree drawn with axis-aligned edges, one parent per node, and no label over another
    parents = {b: a for a, b in view.edges}
    assert set(parents) == set(view.ids) - {"0"} and all(b.rsplit(".", 1)[0] == a for b, a in parents.items())
    pos = dict(zip(view.ids, view.positions))
    assert all(pos[a][0] == pos[b][0] or pos[a][1] == pos[b][1] for a, b in view.edges)
    assert overlapping(view) == []


def test_a_running_skill_shows_its_feedback_and_a_folded_failure_where_it_failed():
    root = compiled()
    k = next(i for i, c in enumerate(root.children) if c.name.startswith("a1: grasp"))
    action = root.children[k]
    running_at(root, k, checks_done=4)
    mark(action.children[0], Status.SUCCESS)
    skill = action.children[1]
    skill.status, skill.feedback_message = Status.RUNNING, "40% closing the gripper"
    assert label_of(skill) == "▶ execute grasp\n40% closing th…"  # cut to the name's width
    skill.feedback_message = "x" * 80
    first, second = label_of(skill).split("\n")
    assert len(second) == len(first), "long feedback is cut, so a running node is no wider than its name"
    # the effect check failed: the action fails; folded, it says where
    mark(action, Status.SUCCESS)
    action.status, action.children[3].status = Status.FAILURE, Status.FAILURE
    mark(action.children[3].children[0], Status.FAILURE)
    assert label_of(action, folded=True) == f"✗ {action.name} — eff: holding(cup)"
    root.status = Status.FAILURE
    graph = TreeGraph.of(root)
    assert graph.open_child() == k, "once the tree has failed, the failed action stays open"


@pytest.mark.parametrize("n_actions", [20])
def test_a_long_plan_fits_the_tree_panel_at_a_readable_zoom(n_actions):
    """Whatever action is open, the drawing of a 20-action plan fits the default layout's tree panel
    at a zoom of at least MIN_ZOOM (the graph view fits the drawing to the panel, never above 1:1)."""
    _, a = plan_of("gather_kindling.yaml")
    _, b = plan_of("retrieve_bottles.yaml")
    actions = (list(a) + list(b))[:n_actions]
    assert len(actions) == n_actions
    root = compiled(actions=actions)
    x0, y0, x1, y1 = TreeGraph.of(root).extent()  # the tree view's visible area, as the recorder sets it
    zoom = min(PANEL_W / (x1 - x0), PANEL_H / (y1 - y0))
    assert zoom >= MIN_ZOOM, f"a {n_actions}-action plan is drawn at {zoom:.2f}x: labels too small to read"
    for k in range(n_actions):  # and every drawing of it, whatever runs, lies inside that area
        running_at(root, k)
        view = TreeGraph.of(root).view()
        assert overlapping(view) == [], k
        bx0, by0, bx1, by1 = view.bounds()
        assert x0 <= bx0 and y0 <= by0 and bx1 <= x1 and by1 <= y1, (k, view.bounds(), (x0, y0, x1, y1))


def test_signature_follows_what_is_drawn():
    root = compiled()
    graph = TreeGraph.of(root)
    before = graph.signature()
    assert graph.signature() == before
    root.children[0].children[0].feedback_message = "10% moving"
    assert graph.signature() != before
    root.children[0].children[0].feedback_message = ""
    assert graph.signature() == before
    root.children[0].status = Status.RUNNING
    assert graph.signature() != before


def test_the_text_is_py_trees_unicode_tree_with_every_status_mark():
    import py_trees

    root = compiled()
    k = 1
    running_at(root, k)
    text = tree_text(root)
    assert "\x1b" not in text
    lines = text.splitlines()
    # py_trees' own lines, node for node (its colour codes, when stdout is a terminal, removed)
    assert [l.split(" [")[0] for l in lines] == [
        l.split(" [")[0] for l in py_trees.display.unicode_tree(root, show_status=True).splitlines()]
    assert len(lines) == sum(1 for _ in root.iterate())
    assert lines[0] == "{-} plan [*]" and lines[1].strip() == f"{{-}} {root.children[0].name} [✓]"
    assert sum("[-]" in l for l in lines) > 0 and sum("[*]" in l for l in lines) == 5
    assert MARKS[Status.SUCCESS] in TreeGraph.of(root).view().labels[1]
