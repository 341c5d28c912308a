"""The scene graph: action-driven and observation-driven updates."""

from __future__ import annotations

from vap_bt.domain.atoms import Atom
from vap_bt.scene.graph import SceneGraph
from vap_bt.taskfile import load

from conftest import TREES

A = Atom.parse


def graph_for(name: str) -> tuple[SceneGraph, object]:
    task = load(TREES / name).planning
    return SceneGraph.of_facts(task.init, tracks_hand=True), task


def test_apply_then_undo_restores_belief():
    g, task = graph_for("collect_cup.yaml")
    before = g.state()
    grasp = task.knowledge.ground("grasp", ("cup", "coffee_table", "living_room"))
    g.apply(grasp)
    assert g.holds(A("holding(cup)")) and not g.holds(A("on(cup, coffee_table)")) and not g.holds(A("hand_empty"))
    assert g.undo(grasp)
    assert g.state() == before
    assert not g.undo(grasp), "undo of an action that is no longer the last applied must refuse"


def test_correct_sets_the_complement_only_where_it_applies():
    g, _ = graph_for("boil_water.yaml")
    assert g.holds(A("closed(cabinet)"))
    g.correct(A("closed(cabinet)"), False, complement="open")
    assert g.holds(A("open(cabinet)")) and not g.holds(A("closed(cabinet)"))
    # the counter is neither open nor closed in belief: no complement is invented for it
    g.correct(A("open(counter)"), False, complement="closed")
    assert not g.holds(A("closed(counter)"))


def test_relocate_replaces_the_location_and_keeps_the_hand_consistent():
    g, task = graph_for("collect_cup.yaml")
    g.apply(task.knowledge.ground("grasp", ("cup", "coffee_table", "living_room")))
    seen = {A("on(cup, floor_living_room)"), A("in_room(cup, living_room)")}
    g.relocate("cup", seen)
    assert g.location("cup") == seen
    assert g.holds(A("hand_empty")), "nothing is held any more, so the hand must be believed empty"
    assert [c.cause for c in g.history][-2:] == ["relocate", "relocate"]


def test_relocate_believes_what_the_frames_show_in_the_way_and_leaves_reachability_to_the_checks():
    # pick_plate: a check found the plate out of reach; the frame then shows the bowl in front of
    # it. Without the blocker in belief no plan could push it away.
    g, _ = graph_for("pick_plate.yaml")
    g.correct(A("reachable(plate)"), False)
    where = {A("on(plate, dining_table)"), A("in_room(plate, kitchen)")}
    mug = g.holds(A("reachable(mug)"))
    g.relocate("plate", where | {A("blocking(bowl, plate)"), A("reachable(mug)"), A("reachable(plate)")})
    assert g.holds(A("blocking(bowl, plate)")) and not g.holds(A("reachable(plate)"))
    assert g.holds(A("reachable(mug)")) == mug  # only the plate's place and what stands in its way
    g.relocate("plate", where)  # a later frame shows nothing in its way
    assert not g.holds(A("blocking(bowl, plate)")) and not g.holds(A("reachable(plate)"))


def test_same_class_items_the_task_does_not_tell_apart_are_scored_under_the_best_matching():
    """retrieve_bottles: the robot named the bench's bottle bottle2 and the floor's bottle1 (the
    task file tells them apart nowhere). Scored under the matching of its graph's centroids to the
    bottles' true centres, its belief is right, and the swap is reported; a task that names them
    (``told``) gets no such matching."""
    from vap_bt.sim.graph_score import score_graph
    from vap_bt.sim.oracle import FunctionOracle

    task = load(TREES / "retrieve_bottles.yaml").planning
    truth = {A("on(bottle1, garden_bench)"), A("on(bottle2, floor_garden)"), A("in_room(bottle1, garden)"),
             A("in_room(bottle2, garden)")}
    where = {"bottle1": (7.0, 4.1, 0.5), "bottle2": (7.5, 1.0, 0.1)}
    oracle = FunctionOracle(lambda a: a in truth, lambda: [], where.get)
    believed = frozenset({A("on(bottle2, garden_bench)"), A("on(bottle1, floor_garden)"), A("in_room(bottle1, garden)"),
                          A("in_room(bottle2, garden)")})
    centroids = {"bottle2": (7.02, 4.08, 0.52), "bottle1": (7.48, 1.03, 0.09)}
    s = score_graph(oracle, task, believed, {"bottle1", "bottle2"}, {"bottle1", "bottle2"}, set(), centroids)
    assert s["relations"]["precision"] == 1.0 and s["relations"]["recall"] == 1.0
    assert s["swaps"] == {"bottle1": "bottle2", "bottle2": "bottle1"}
    told = score_graph(oracle, task, believed, {"bottle1", "bottle2"}, {"bottle1", "bottle2"}, {"bottle1"}, centroids)
    assert "swaps" not in told and told["relations"]["precision"] == 0.5
    # without geometry, the matching that makes the most believed relations true
    blind = FunctionOracle(lambda a: a in truth, lambda: [])
    s = score_graph(blind, task, believed, {"bottle1", "bottle2"}, {"bottle1", "bottle2"}, set(), {})
    assert s["relations"]["precision"] == 1.0 and s["swaps"] == {"bottle1": "bottle2", "bottle2": "bottle1"}
