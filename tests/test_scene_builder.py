"""The scene-graph builder: an exploration sweep, frames fused into belief, and re-location.

Pixel worlds build by geometry (pybullet: rendered RGB-D, open3d); the symbolic world by voted
relation reports. In both, what the executive believes comes from frames and the task file's
stated prior only — the world's oracle is used here to check the result, never to build it.
"""

from __future__ import annotations

import numpy as np
import pytest

from vap_bt.bt.executive import sweep_order
from vap_bt.domain.atoms import Atom
from vap_bt.robot.frame import Detection, Frame
from vap_bt.robot.site_map import FurnitureInfo, RoomInfo, SiteMap
from vap_bt.app.runner import RunConfig, Session
from vap_bt.robot.labels import label_of
from vap_bt.scene.builder import SceneGraphBuilder
from vap_bt.scene.graph import SceneGraph
from vap_bt.scene.identity import Believed, Identifier, IdentifyingCamera
from vap_bt.taskfile import load

from conftest import ROOT, TREES

A = Atom.parse


def reports_frame(frame_id: str, *detections: tuple[str, tuple[str, ...]]) -> Frame:
    """An identified frame without pixels whose detections carry relation reports as the symbolic
    world's do (the detected thing itself named ``""``), each already named ``n`` by the robot."""
    def report(n: str, a: str):
        atom = A(a)
        return Atom(atom.predicate, tuple("" if x == n else x for x in atom.args))

    return Frame(frame_id, 0.0, tuple(Detection("cup", relations=tuple(report(n, a) for a in rel), name=n)
                                      for n, rel in detections))


def symbolic_builder() -> SceneGraphBuilder:
    task = load(TREES / "collect_cup.yaml").planning
    site = SiteMap((RoomInfo("living_room", "floor_living_room"), RoomInfo("kitchen", "floor_kitchen")),
                   furniture=(FurnitureInfo("coffee_table", "coffee_table", "surface", "living_room"),
                              FurnitureInfo("counter", "counter", "surface", "kitchen")))
    return SceneGraphBuilder(task.knowledge, task.objects, site)


def test_reports_are_voted_across_the_views_that_saw_the_object():
    b = symbolic_builder()
    for i, support in enumerate(("coffee_table", "coffee_table", "counter")):  # one view misreports
        b.integrate(reports_frame(f"f{i}", ("cup", (f"on(cup, {support})", "in_room(cup, living_room)"))))
    assert b.observed("cup") == {A("on(cup, coffee_table)"), A("in_room(cup, living_room)")}
    assert b.placed("cup") and b.evidence["cup"].frames == 3
    b.forget(["cup"])
    assert b.observed("cup") == set() and not b.placed("cup")


def test_a_thing_once_seen_is_never_again_placed_by_the_users_word_alone():
    """Only what no frame has shown may be anywhere (the task file's word can be wrong); a thing
    forgotten to be looked for again was seen, and belief, not the word, places it."""
    b = symbolic_builder()
    graph = SceneGraph.of_facts({A("on(cup, counter)"), A("in_room(cup, kitchen)")})
    assert b.believed(graph, "cup").told
    b.saw(["cup"])  # a check's frame showed it (checks' frames are not integrated)
    b.forget(["cup"])
    assert not b.believed(graph, "cup").told


def test_detections_outside_the_task_vocabulary_are_not_objects_of_the_plan():
    b = symbolic_builder()
    assert b.integrate(reports_frame("f", ("ghost", ("on(ghost, counter)",)))) == set()
    assert "ghost" not in b.evidence


def test_the_floor_round_a_spot_is_looked_at_from_all_round_it_within_its_room():
    """Where something slipped from the hand: the floor round the spot the robot stands on (and
    under its own base), seen from stands round it in two rings (the nearer turned by half a
    step: new pictures, the item larger in them), each facing it; none beyond the room's walls."""
    from vap_bt.scene.builder import SPOT_LOOK_RINGS

    task = load(TREES / "collect_cup.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 4.0, 3.0)),))
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    views = b.spot_views("kitchen", (1.0, 1.5))
    # the stand through the wall at x = 0 is not offered: one of the six 1.1 m away
    assert len(views) == 11 and len({v.label for v in views}) == 11
    distances = []
    for v in views:
        x, y, yaw = v.base_pose
        assert 0.0 < x < 4.0 and 0.0 < y < 3.0
        assert v.aim.point == (1.0, 1.5, 0.0) and v.aim.names == ("floor_kitchen",)
        d = float(np.hypot(x - 1.0, y - 1.5))
        distances.append(round(d, 6))
        assert np.cos(yaw) * (1.0 - x) + np.sin(yaw) * (1.5 - y) == pytest.approx(d)  # facing the spot
    assert sorted(set(distances)) == sorted(round(d, 6) for d, _ in SPOT_LOOK_RINGS)
    assert distances == sorted(distances, reverse=True)  # the far ring first: it sees more floor


def test_the_floor_along_every_wall_is_looked_at_from_inside_the_room_facing_the_wall():
    """The last look for a lost item: the look round the floor from the room's middle leaves the
    feet of the walls out, and a dropped bottle rolls to one. Every point of the floor by a wall,
    corners included, is within half a frame of some look's aim."""
    from vap_bt.scene.builder import WALL_LOOK_DISTANCE, WALL_LOOK_INSET, WALL_LOOK_SPACING

    task = load(TREES / "collect_cup.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 4.0, 3.0)),))
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    views = b.wall_views("kitchen")
    assert len(views) == 2 * 4 + 2 * 3  # 4 m walls in four looks, 3 m ones in three
    for v in views:
        (px, py, _), (x, y, yaw) = v.aim.point, v.base_pose
        assert 0.0 < x < 4.0 and 0.0 < y < 3.0 and v.aim.names == ("floor_kitchen",)
        assert min(px, 4.0 - px, py, 3.0 - py) == pytest.approx(WALL_LOOK_INSET)  # by a wall
        assert np.hypot(x - px, y - py) == pytest.approx(WALL_LOOK_DISTANCE)
        assert np.cos(yaw) * (px - x) + np.sin(yaw) * (py - y) == pytest.approx(WALL_LOOK_DISTANCE)  # facing it
    aims = np.array([v.aim.point[:2] for v in views])
    foot = [(t, 0.0) for t in np.linspace(0, 4, 41)] + [(4.0, t) for t in np.linspace(0, 3, 31)]
    foot += [(t, 3.0) for t in np.linspace(0, 4, 41)] + [(0.0, t) for t in np.linspace(0, 3, 31)]
    reach = np.hypot(WALL_LOOK_SPACING / 2, WALL_LOOK_INSET) + 1e-9
    assert all(np.min(np.hypot(*(aims - p).T)) <= reach for p in foot)
    assert b.wall_views("nowhere") == []


def in_frame(view, points: np.ndarray, z: float = 0.0) -> np.ndarray:
    """Which ``points`` (x, y; at height ``z``: the floor's by default) a view's frame shows: the
    wrist camera (robots/mobile_ur5e.yaml's intrinsics) at the skills' eye over the stand
    (``skills.eyes.CAMERA_EYE``), aimed at the view's point — a pinhole with nothing in the way."""
    from robots.config import RobotConfig
    from skills.eyes import CAMERA_EYE
    from vap_bt.motion.se3 import look_pose

    cam = RobotConfig.from_yaml(ROOT / "robots" / "mobile_ur5e.yaml").camera
    x, y, yaw = view.base_pose
    eye = (x + CAMERA_EYE[0] * np.cos(yaw), y + CAMERA_EYE[0] * np.sin(yaw), CAMERA_EYE[2])
    T = look_pose(eye, view.aim.point)
    u, v, depth = ((np.c_[points, np.full(len(points), z)] - T[:3, 3]) @ T[:3, :3]).T  # optical: x right, y down
    return (depth > 0) & (np.abs(u) <= depth * cam.width / (2 * cam.fx)) & (np.abs(v) <= depth * cam.height / (2 * cam.fy))


def test_the_floor_between_the_walls_and_the_middle_of_a_wide_room_is_looked_at_too():
    """In a room 4.4 m across (boil_water's kitchen) the walls' looks show the floor to about 0.8 m
    off each wall, and the middle's (with the sweep's look round from the middle) not as far as
    1.3 m off it: boil_water seed 129's cup lay there, in no frame of three searches. With the
    inner ring's looks every point of the floor is in some frame."""
    from vap_bt.scene.builder import INNER_LOOK_INSET, WALL_LOOK_DISTANCE

    task = load(TREES / "collect_cup.yaml").planning
    w, d = 6.15, 4.4
    b = SceneGraphBuilder(task.knowledge, task.objects, SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, w, d)),)))
    inner = b.inner_views("kitchen")
    assert len(inner) == 2 * 4 + 2 * 2  # 3.75 m between the corners' points in four looks, 2.0 m in two
    for v in inner:
        (px, py, _), (x, y, yaw) = v.aim.point, v.base_pose
        assert 0.0 < x < w and 0.0 < y < d
        assert min(px, w - px, py, d - py) == pytest.approx(INNER_LOOK_INSET)
        assert np.cos(yaw) * (px - x) + np.sin(yaw) * (py - y) == pytest.approx(WALL_LOOK_DISTANCE)  # facing it
    floor = np.array([(x, y) for x in np.linspace(0.05, w - 0.05, 60) for y in np.linspace(0.05, d - 0.05, 43)])

    def unseen(views) -> np.ndarray:
        return floor[~np.any([in_frame(v, floor) for v in views], axis=0)]

    outer = b.wall_views("kitchen") + b.middle_views("kitchen") + b.floor_views("kitchen")
    missed = unseen(outer)
    assert len(missed) and np.min(np.hypot(*(missed - (4.25, 1.29)).T)) < 0.15  # the cup's spot among them
    assert len(unseen(outer + inner)) == 0
    assert b.inner_views("nowhere") == []
    narrow = SceneGraphBuilder(task.knowledge, task.objects, SiteMap((RoomInfo("hall", "floor_hall", (0.0, 0.0, 6.0, 2.0)),)))
    assert narrow.inner_views("hall") == []  # 2 m across: the walls' looks meet the middle's


def test_the_floor_at_the_middle_of_a_room_is_looked_at_from_all_round_it():
    """The sweep looks round the floor from a room's middle, and the floor at its feet is in no
    frame (gather_kindling seed 1: the lost stick 0.5 m from the middle): a search's later look
    aims at the middle from stands round it, all in the room."""
    from vap_bt.scene.builder import FLOOR_LOOK_DISTANCE

    task = load(TREES / "collect_cup.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 4.0, 3.0)), RoomInfo("hall", "floor_hall")))
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    views = b.middle_views("kitchen")
    assert len(views) >= 6 and all(v.aim.point[:2] == (2.0, 1.5) for v in views)
    stands = np.array([v.base_pose[:2] for v in views])
    assert np.all((stands > 0) & (stands < (4.0, 3.0)))
    assert np.all(np.hypot(*(stands - (2.0, 1.5)).T) < FLOOR_LOOK_DISTANCE)  # nearer than the sweep's aim
    assert b.middle_views("hall") == []  # no outline


def test_an_item_is_looked_at_from_close_by_on_its_support_or_round_it_on_the_floor():
    """A check that could not make an item out goes to look from close by where belief puts it:
    the top of the piece it rests on from two stands in front of it, nearer each, facing it; an
    item on the floor from stands all round it."""
    from vap_bt.scene.builder import SEARCH_TOP_STANDOFF, TOP_VIEW_STANDOFF

    task = load(TREES / "collect_cup.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 4.0, 3.0)),),
                   furniture=(FurnitureInfo("counter", "counter", "surface", "kitchen", (2.0, 2.5, -np.pi / 2), (1.0, 0.6)),))
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    on_counter = SceneGraph.of_facts({A("on(cup, counter)"), A("in_room(cup, kitchen)")})
    views = b.near_views(on_counter, "cup")
    assert [v.aim.names for v in views] == [("counter",), ("counter",)]
    assert [round(2.5 - v.base_pose[1], 3) for v in views] == [0.3 + TOP_VIEW_STANDOFF, 0.3 + SEARCH_TOP_STANDOFF]
    assert all(v.base_pose[0] == pytest.approx(2.0) and v.base_pose[2] == pytest.approx(np.pi / 2) for v in views)
    on_floor = SceneGraph.of_facts({A("on(cup, floor_kitchen)"), A("in_room(cup, kitchen)")})
    round_it = b.near_views(on_floor, "cup")
    assert len(round_it) >= 3 and all(v.aim.names == ("floor_kitchen",) for v in round_it)
    assert len({v.base_pose for v in round_it}) == len(round_it)  # each from its own stand
    held = SceneGraph.of_facts({A("holding(cup)")})
    assert b.near_views(held, "cup") == []


def test_what_is_in_a_basket_is_looked_at_from_above():
    """store_firewood seed 4: three views of the basket's front judged the log in it outside; its
    top from close by shows the inside. A piece named for itself (the check relates an item belief
    no longer places to it) is looked at the same way."""
    from vap_bt.robot.site_map import Cavity
    from vap_bt.scene.builder import TOP_LOOKS

    task = load(TREES / "store_firewood.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 6.0, 4.0)),), furniture=(
        FurnitureInfo("basket", "basket", "container", "kitchen", (2.0, 3.5, -np.pi / 2), (0.5, 0.4), 0.3,
                      Cavity((0.02, 0.3), 0.02, "top")),
        FurnitureInfo("fridge", "fridge", "container", "kitchen", (4.0, 3.5, -np.pi / 2), (0.7, 0.7), 1.7,
                      Cavity((0.1, 1.6), 0.04, "front"))))
    b = SceneGraphBuilder(task.knowledge, {**task.objects, "fridge": "container"}, site)
    in_basket = SceneGraph.of_facts({A("inside(wood1, basket)")})
    for name in ("wood1", "basket"):
        assert [v.label for v in b.near_views(in_basket, name)] == [f"basket {label}" for label in TOP_LOOKS.values()]
    assert b.opens_on_top("basket") and not b.opens_on_top("fridge") and not b.opens_on_top("wood1")


def test_what_is_in_a_front_opening_cavity_is_looked_at_through_its_front():
    """boil_water seed 6 in pybullet: the goal check could not settle heated(cup) with the cup in
    the microwave, and the looks again went to the microwave's top, from where the cup was in none
    of the frames. An item inside a piece that opens at the front is looked at from the same close
    stands, aimed at the middle of the cavity; the piece itself, and an item on a top, as before."""
    from vap_bt.robot.site_map import Cavity
    from vap_bt.scene.builder import INSIDE_LOOKS, TOP_LOOKS

    task = load(TREES / "boil_water.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 6.0, 4.0)),), furniture=(
        FurnitureInfo("microwave", "microwave", "appliance", "kitchen", (4.0, 3.5, -np.pi / 2), (0.5, 0.4), 1.25,
                      Cavity((0.95, 1.2), 0.02, "front")),))
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    inside = SceneGraph.of_facts({A("inside(cup, microwave)"), A("in_room(cup, kitchen)")})
    views = b.near_views(inside, "cup")
    assert [v.label for v in views] == [f"microwave {label}" for label in INSIDE_LOOKS.values()]
    assert all(v.aim.point[2] == pytest.approx(1.075) and v.base_pose[1] < 3.5 for v in views)
    assert [v.label for v in b.near_views(inside, "microwave")] == [f"microwave {label}" for label in TOP_LOOKS.values()]


def test_a_hidden_item_is_placed_by_the_prior_and_a_seen_one_by_perception():
    """boil_water: the cup is in the closed cabinet, which no view shows into; the task file says
    so, and the belief says which source placed it."""
    task = load(TREES / "boil_water.yaml")
    s = Session(task, RunConfig.from_task(task, world="symbolic", injection=False, vlm_noise=0.0, miss_rate=0.0,
                                              relation_noise=0.0))
    r = s.episode(0)
    initial = r["perception"]["surveys"][0]
    assert initial["prior_only"] == ["cup"] and "cup" not in initial["detected"]
    assert {"cabinet", "microwave", "counter", "kitchen_sink"} <= set(initial["detected"])
    graph = r["perception"]["graph"]["initial"]
    assert graph["relations"]["recall"] == 1.0 and graph["detections"]["missed"] == ["cup"]
    assert r["success"] and r["goal_satisfied"]


def test_a_lost_object_is_searched_for_room_by_room():
    """collect_cup, symbolic: the cup falls while carried between rooms (Table II); the gripper
    feels it gone, the camera does not show it where it was carried to, and the re-survey finds
    it in the other room."""
    task = load(TREES / "collect_cup.yaml")
    s = Session(task, RunConfig.from_task(task, world="symbolic", vlm_noise=0.0, miss_rate=0.0, relation_noise=0.0,
                                              planner="search"))
    r = next(r for r in map(s.episode, range(60))
             if any(i["kind"] == "held_object_drops_during_navigation" and i["action"] == "navigate"
                    for i in r["injected"]))
    resurveys = r["perception"]["surveys"][1:]
    assert resurveys and any("cup" in x["detected"] for x in resurveys)
    assert r["perception"]["graph"]["resurveys"] and r["success"] and r["goal_satisfied"]
    assert all(x["views"] > 0 and x["seconds"] >= 0 for x in resurveys)


# -- pybullet: geometry from rendered depth ------------------------------------------------------


@pytest.mark.slow
def test_the_sweep_finds_what_the_first_view_does_not_show():
    """collect_cup in pybullet: from where the robot starts the cup on the coffee table is out of
    view; the sweep (through the skills' camera service, which drives and aims) finds it, and the
    fused point cloud puts it on the coffee table, within 3 cm of where it is from noisy depth (the
    base perfectly localised: with a localisation error the belief is in the believed frame, a
    few centimetres off the truth by design — tests/test_sensors.py)."""
    from skill_runs import camera

    from vap_bt.scene.geometry import PointCloudGeometry
    from vap_bt.sim.localization import LocalizationModel
    from vap_bt.sim.pybullet_world import PybulletWorld

    task = load(TREES / "collect_cup.yaml")
    world = PybulletWorld(task, seed=0, injection=False, localization=LocalizationModel.perfect())
    try:
        site, objects = world.site_map(), task.planning.objects
        b = SceneGraphBuilder(task.planning.knowledge, objects, site, PointCloudGeometry)
        # frames named against what the sweep has seen so far (the executive's own wiring)
        ident = Identifier({n: label_of(n, site) for n in objects}, site)
        view = IdentifyingCamera(camera(world), lambda f: ident.identify(
            f, {n: Believed(c) for n in objects if (c := b.geometry.centroid(n)) is not None}))
        first = view.capture()
        assert "cup" not in first.detected()
        b.integrate(first)
        record = b.sweep(view, sweep_order(world.site_map(), world.state().room))
        assert "cup" in record.detected and record.frames == record.reached > 5
        assert {A("on(cup, coffee_table)"), A("in_room(cup, living_room)")} <= b.observed("cup")
        assert world.oracle.holds(A("on(cup, coffee_table)"))  # the check, not the source
        c = np.array(b.geometry.centroid("cup"))
        # a few cm: views of one side only (2.3 cm off with the renderer's exact masks), masks a
        # pixel or two off the boundary, and the views the detector missed the cup in not fused
        assert np.linalg.norm(c - world.truth.center("cup")) < 0.04
    finally:
        world.close()


@pytest.mark.slow
def test_an_object_moved_by_a_person_is_noticed_and_relocated_from_the_frame():
    """After the robot went to the cup, a person puts it on the floor. The grasp's precondition
    check no longer finds it, and the cup is re-located from what the camera shows — the oracle
    is only asked afterwards, to check."""
    task = load(TREES / "collect_cup.yaml")
    s = Session(task, RunConfig.from_task(task, world="pybullet", injection=False, vlm_noise=0.0))
    try:
        s.world.disturbances = [{"after": 0, "move": "cup", "to": "floor_living_room"}]
        r = s.episode(0)
        graph = s.last_outcome.graph
        assert any(i["kind"] == "object_moved_by_person" for i in r["injected"])
        # noticed before the grasp: a precondition about the cup that no longer holds, or that the
        # camera, turned to where belief puts the cup, can no longer see
        first = r["situations"][0]
        assert first["kind"] in ("precondition", "unseen") and "cup" in first["predicate"], first
        assert first["action"].startswith("grasp(cup, coffee_table")
        moved = [c for c in r["belief_changes"] if c["cause"] in ("relocate", "survey")
                 and "on(cup, floor_living_room)" in c["added"]]
        assert moved, r["belief_changes"]
        assert graph.objects["cup"].source == "perceived" and graph.objects["cup"].frames > 0
        assert r["success"] and r["goal_satisfied"], r["reason"]
    finally:
        s.close()


@pytest.mark.slow
def test_a_false_positive_taken_at_a_first_sighting_does_not_pin_the_item():
    """store_firewood seed 2: the sweep's first frame with a "wood" in it is a detector's false
    positive 0.9 m up in the storage room, which a first sighting takes for wood2 (placed on or
    in nothing); the real log lies on the living-room floor. A sighting that places an item
    nowhere does not pin it: the next one, on the floor, takes it, and the survey believes the
    log where the world has it (before, the survey kept the false positive and no plan existed)."""
    task = load(TREES / "store_firewood.yaml")
    s = Session(task, RunConfig.from_task(task, world="pybullet", injection=False, max_replans=0))
    try:
        r = s.episode(2)
        initial = r["perception"]["graph"]["initial"]
        assert "wood2" in r["perception"]["surveys"][0]["detected"]
        assert not [a for a in initial.get("wrong", []) + initial.get("missing", []) if "wood2" in a], initial
        assert r["plans"], r["reason"]  # a plan exists from what the robot perceived
    finally:
        s.close()


def test_what_slips_from_a_hand_working_at_a_piece_is_looked_for_at_the_piece_s_front():
    """heat_pie seed 0 with injection: the pie slipped from the hand on its way out of the fridge
    and lay on the floor 4 cm from the fridge's front, a metre from the base; the floor round the
    base never showed it."""
    from vap_bt.scene.builder import FRONT_SPOT

    task = load(TREES / "heat_pie.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 6.0, 4.5)),), furniture=(
        FurnitureInfo("fridge", "fridge", "container", "kitchen", (1.5, 4.05, -np.pi / 2), (0.7, 0.6), 1.6),))
    b = SceneGraphBuilder(task.knowledge, task.objects, site)
    x, y = b.front_spot("fridge")
    assert x == pytest.approx(1.5) and y == pytest.approx(4.05 - 0.3 - FRONT_SPOT)
    assert b.front_spot("apple_pie") is None  # an item is no piece the map places


def _cup_frame(fid: str, side: int) -> Frame:
    """test_identity's downward frame, its one detection the cup (named), ``side`` pixels wide,
    10 cm above the floor at (0.4, 0.3)."""
    from dataclasses import replace

    from test_identity import pixel_frame

    frame = pixel_frame(("cup", (0.4, 0.3, 0.1), side), fid=fid)
    return replace(frame, detections=(replace(frame.detections[0], name="cup"),))


def test_a_thing_seen_too_little_to_measure_is_glimpsed_where_its_pixels_lie():
    """retrieve_bottles seed 49: five pixels of the lost bottle past a doorway named it, too few
    points for a centroid; where they lie is where to look closer. Once a frame measures it, it is
    placed, not glimpsed."""
    from vap_bt.scene.geometry import PointCloudGeometry

    task = load(TREES / "collect_cup.yaml").planning
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (-2.0, -2.0, 2.0, 2.0)),))
    b = SceneGraphBuilder(task.knowledge, task.objects, site, PointCloudGeometry)
    assert b.glimpsed("cup") is None  # never seen
    b.integrate(_cup_frame("far", 1))
    assert b.detected("cup") and b.geometry.centroid("cup") is None
    x, y = b.glimpsed("cup")
    assert abs(x - 0.4) < 0.05 and abs(y - 0.3) < 0.05
    b.integrate(_cup_frame("near", 20))
    assert b.geometry.centroid("cup") is not None and b.glimpsed("cup") is None
