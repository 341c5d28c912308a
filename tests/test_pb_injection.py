"""Every Table II row, forced (a one-row SituationModel with probability 1), happens physically
when a scripted sequence of driver calls performs the action: the world is told only which
action the goal is (``begin_action``/``end_action``) and nothing decides the outcome but the
drivers and the physics. The same scripts without injection succeed (first test of each pair)."""

from __future__ import annotations

import numpy as np
import pytest
from driver_scripts import (CLOSED, OPEN, carry, drive, frame, hold, kitchen, line, moved, never, reach,
                            stand_before, world_of)

from vap_bt.domain.atoms import Atom
from vap_bt.sim.pb_rules import FILL_TIME
from vap_bt.sim.situations import SituationModel, SituationSpec

pytestmark = pytest.mark.slow

FURNITURE = {"counter": "type: surface", "kitchen_sink": "type: sink", "microwave": "type: appliance, state: closed",
             "drawer": "type: container, state: {drawer}", "cutting_board": "type: surface"}


def scene(cup="on counter", drawer="closed", knife=False) -> str:
    items = {"cup": f"place: {cup}, fillable: true", "lemon": "place: on cutting_board"}
    if knife:
        items["knife"] = "type: knife, place: held"
    return kitchen({k: v.format(drawer=drawer) for k, v in FURNITURE.items()}, items)


def A(text):
    return Atom.parse(text)



forced = SituationModel.forced


def house(tmp_path, situation=None, **kw):
    return world_of(tmp_path, "kitchen", scene(**kw), situation)


def holds(w, *atoms):
    return all(w.oracle.holds(A(a)) for a in atoms)


def kinds(w):
    return [s.kind for s in w.injected()]


# ------------------------------------------------------------ scripted actions (drivers only)


def grasp(w, action="grasp"):
    """Take the cup from the counter from above, lift it and carry it beside the base."""
    d = w.drivers
    c, box = w.truth.center("cup"), w.truth.aabb("cup")
    w.begin_action(action, ("cup", "counter", "kitchen"))
    assert stand_before(d, c, (0, -1, 0), 0.70).completed
    G = frame((0, 0, -1), (0, 1, 0), (c[0], c[1], box[5] - 0.03))
    assert reach(d, moved(G, (0, 0, 0.12))).completed and d.gripper.move(OPEN, 40, never)
    assert line(d, G, steps=4).completed
    closed = d.gripper.move(CLOSED, 40, never)
    assert line(d, moved(G, (0, 0, 0.12)), steps=3).completed and carry(d).completed
    assert hold(d, 0.8).completed  # whatever fell comes to rest
    w.end_action(action, ("cup", "counter", "kitchen"))
    return closed, c


def place(w, action="placeon"):
    """Put the held cup down on the counter (hand turned as it holds it)."""
    d = w.drivers
    f = w.plan.furniture["counter"]
    spot = np.array([f.x, f.y, f.kind.size[2]])
    grip = w.truth.center("cup") - d.arm.tcp_pose()[:3, 3]  # how the hand holds it (known from the grasp)
    w.begin_action(action, ("cup", "counter", "kitchen"))
    assert stand_before(d, spot, (0, -1, 0), 0.70).completed
    T = d.arm.tcp_pose()
    at = moved(T, spot + (0, 0, 0.05) - (T[:3, 3] + grip))  # the cup's bottom 5 mm above the top
    assert reach(d, moved(at, (0, 0, 0.1))).completed and line(d, at, steps=4).completed
    opened = d.gripper.move(OPEN, 40, never)
    assert line(d, moved(at, (0, 0, 0.12)), steps=3).completed and hold(d, 0.8).completed
    w.end_action(action, ("cup", "counter", "kitchen"))
    return opened


# ------------------------------------------------------------ grasp and takeout


def test_grasp_without_injection_holds_the_cup(tmp_path):
    w = house(tmp_path)
    closed, _ = grasp(w)
    assert closed.holding and holds(w, "holding(cup)") and kinds(w) == []
    w.close()


@pytest.mark.parametrize("action", ["grasp", "takeout"])
def test_grasp_fails_object_unchanged(tmp_path, action):
    w = house(tmp_path, forced(action, "grasp_fails_object_unchanged"))
    closed, before = grasp(w, action)
    assert not closed.holding and closed.width < 0.01  # the fingers closed on nothing
    assert holds(w, "hand_empty", "on(cup, counter)") and not holds(w, "holding(cup)")
    assert np.linalg.norm(w.truth.center("cup") - before) < 0.02  # it stayed where it was
    assert kinds(w) == ["grasp_fails_object_unchanged"]
    w.close()


def test_a_drawn_failure_the_action_never_reached_is_not_in_the_worlds_record(tmp_path):
    # a grasp whose skill does not find the item where belief put it (it lies elsewhere) closes no
    # fingers; its drawn row was recorded all the same, and the runner scored the executive's
    # reading of the situation (belief was wrong: a perception error) against a grasp failure
    # that never happened
    w = house(tmp_path, forced("grasp", "grasp_fails_object_unchanged"))
    d = w.drivers
    w.begin_action("grasp", ("cup", "counter", "kitchen"))
    assert w.injection.active.spec.kind == "grasp_fails_object_unchanged"  # drawn ...
    assert not d.gripper.move(CLOSED, 40, never).holding  # ... the fingers close in the air
    w.end_action()
    assert "grasp_fails_object_unchanged" not in kinds(w) and holds(w, "on(cup, counter)")
    w.close()


@pytest.mark.parametrize("action", ["grasp", "takeout"])
def test_grasp_fails_object_drops_nearby(tmp_path, action):
    w = house(tmp_path, forced(action, "grasp_fails_object_drops_nearby"))
    closed, _ = grasp(w, action)
    assert closed.holding  # the grip formed ...
    assert holds(w, "hand_empty", "on(cup, floor_kitchen)") and not w.drivers.gripper.state().holding  # ... and was lost
    assert kinds(w) == ["grasp_fails_object_drops_nearby"]
    w.close()


def test_a_drop_never_carried_over_the_floor_happens_when_the_goal_ends(tmp_path):
    w = house(tmp_path, forced("grasp", "grasp_fails_object_drops_nearby"))
    d = w.drivers
    c, box = w.truth.center("cup"), w.truth.aabb("cup")
    w.begin_action("grasp", ("cup", "counter", "kitchen"))
    assert stand_before(d, c, (0, -1, 0), 0.70).completed
    G = frame((0, 0, -1), (0, 1, 0), (c[0], c[1], box[5] - 0.03))
    assert reach(d, moved(G, (0, 0, 0.12))).completed and line(d, G, steps=4).completed
    assert d.gripper.move(CLOSED, 40, never).holding
    assert line(d, moved(G, (0, 0, 0.06)), steps=3).completed  # lifted, still over the counter
    assert holds(w, "holding(cup)")
    w.end_action("grasp", ("cup", "counter", "kitchen"))
    assert holds(w, "hand_empty") and hold(d, 1.0).completed and holds(w, "on(cup, counter)")
    w.close()


# ------------------------------------------------------------ placeon and placein


def test_place_without_injection_puts_the_cup_down(tmp_path):
    w = house(tmp_path, cup="held")
    assert not place(w).holding and holds(w, "on(cup, counter)", "hand_empty")
    w.close()


@pytest.mark.parametrize("action", ["placeon", "placein"])
def test_place_fails_object_in_hand(tmp_path, action):
    w = house(tmp_path, forced(action, "place_fails_object_in_hand"), cup="held")
    opened = place(w, action)
    assert opened.holding and opened.width < 0.07  # the gripper did not open
    assert holds(w, "holding(cup)") and not holds(w, "on(cup, counter)")
    # once the goal is over the gripper works again
    assert not w.drivers.gripper.move(OPEN, 40, never).holding
    w.close()


@pytest.mark.parametrize("action", ["placeon", "placein"])
def test_place_fails_object_drops_nearby(tmp_path, action):
    w = house(tmp_path, forced(action, "place_fails_object_drops_nearby"), cup="held")
    place(w, action)
    assert holds(w, "hand_empty", "on(cup, floor_kitchen)") and not holds(w, "on(cup, counter)")
    assert kinds(w) == ["place_fails_object_drops_nearby"]
    w.close()


# ------------------------------------------------------------ navigation


@pytest.mark.parametrize("action", ["find", "navigate"])
def test_held_object_drops_during_navigation(tmp_path, action):
    w = house(tmp_path, forced(action, "held_object_drops_during_navigation"), cup="held")
    d = w.drivers
    x, y, yaw = d.base.pose()
    goal = (x - 1.2, y, yaw)
    w.begin_action(action, ("floor_kitchen", "counter", "kitchen"))
    assert d.base.follow([(x - 0.3, y, yaw), goal], 0.8, never).completed  # it still arrives
    assert hold(d, 0.5).completed
    w.end_action()
    assert abs(d.base.pose()[0] - goal[0]) < 0.02
    assert holds(w, "hand_empty", "on(cup, floor_kitchen)")
    cup = w.truth.center("cup")
    assert abs(cup[0] - (x - 0.6)) < 0.35  # it fell half way, not at the start or the end
    assert kinds(w) == ["held_object_drops_during_navigation"]
    assert w.injected()[0].affected == ("cup",)  # what fell, not the place the robot went to
    w.close()


def test_a_navigation_drop_drawn_while_the_hand_is_empty_is_no_situation(tmp_path):
    """The fault campaign counted such draws as faults — affecting ``floor_kitchen``, the find's
    first argument — and scored whether the executive "detected" them: nothing happened to detect."""
    w = house(tmp_path, forced("find", "held_object_drops_during_navigation"))
    d = w.drivers
    x, y, yaw = d.base.pose()
    w.begin_action("find", ("floor_kitchen", "counter", "kitchen"))
    assert d.base.follow([(x - 0.3, y, yaw), (x - 1.2, y, yaw)], 0.8, never).completed
    w.end_action()
    assert w.injected() == [] and holds(w, "hand_empty", "on(cup, counter)")
    w.close()


# ------------------------------------------------------------ open and close


def pull_drawer(w, action, out: float):
    """Take the drawer's handle and move it ``out`` metres along its slide: pulled by the arm,
    or (negative) pushed in by the base driving on with the arm still."""
    d = w.drivers
    art = w.site_map().piece("drawer").articulation
    n = np.array(art.normal)
    q = w.truth.joint_value("drawer")  # where the drawer is: the test stages its start
    handle = np.array(art.handle) + np.array(art.axis) * q
    G = frame(-n, art.bar, handle)
    w.begin_action(action, ("drawer",))
    assert stand_before(d, handle, n, 0.92 if out > 0 else 0.75).completed
    assert reach(d, moved(G, n * 0.12)).completed and line(d, G, steps=4).completed
    took = d.gripper.move(CLOSED, 80, never)
    if out > 0:
        assert line(d, moved(G, n * out), steps=8, speed=0.2).completed
    else:
        x, y, yaw = d.base.pose()
        assert drive(d, (x + n[0] * out, y + n[1] * out, yaw), speed=0.3).completed
    d.gripper.move(OPEN, 60, never)
    x, y, yaw = d.base.pose()
    assert drive(d, (x + n[0] * 0.15, y + n[1] * 0.15, yaw)).completed and hold(d, 0.5).completed
    w.end_action(action, ("drawer",))
    return took


def test_open_and_close_without_injection(tmp_path):
    w = house(tmp_path)
    pull_drawer(w, "open", 0.30)
    assert holds(w, "open(drawer)")
    pull_drawer(w, "close", -0.34)
    assert holds(w, "closed(drawer)")
    w.close()


def test_open_fails_object_closed(tmp_path):
    w = house(tmp_path, forced("open", "open_fails_object_closed"))
    assert pull_drawer(w, "open", 0.30).holding  # the hand took the handle ...
    assert holds(w, "closed(drawer)") and not holds(w, "open(drawer)")  # ... and slipped off early
    assert kinds(w) == ["open_fails_object_closed"]
    w.close()


def test_close_fails_object_open(tmp_path):
    w = house(tmp_path, forced("close", "close_fails_object_open"), drawer="open")
    assert holds(w, "open(drawer)")
    assert pull_drawer(w, "close", -0.34).holding
    assert holds(w, "open(drawer)") and not holds(w, "closed(drawer)")
    assert kinds(w) == ["close_fails_object_open"]
    w.close()


# ------------------------------------------------------------ turnon


def press_switch(w, announce=True):
    d = w.drivers
    m = w.site_map().piece("microwave")
    n = np.array([*m.front, 0.0])
    if announce:
        w.begin_action("turnon", ("microwave", "cup"))
    assert stand_before(d, m.switch, n, 0.85).completed
    d.gripper.move(CLOSED, 60, never)
    G = frame(-n, (0, 0, -1), np.asarray(m.switch) + n * 0.014)
    assert reach(d, moved(G, n * 0.1)).completed and line(d, G, steps=4, speed=0.2).completed
    assert line(d, moved(G, n * 0.1), steps=2).completed
    w.end_action()


def test_turnon_without_and_with_injection(tmp_path):
    w = house(tmp_path)
    press_switch(w)
    assert holds(w, "turned_on(microwave)")
    w.close()
    w = house(tmp_path, forced("turnon", "turnon_fails_object_off"))
    press_switch(w)
    assert not holds(w, "turned_on(microwave)") and kinds(w) == ["turnon_fails_object_off"]
    # a press outside the failing goal registers
    press_switch(w, announce=False)
    assert holds(w, "turned_on(microwave)") and kinds(w) == ["turnon_fails_object_off"]
    w.close()


# ------------------------------------------------------------ cut


def cut_lemon(w):
    import pybullet as pb

    d = w.drivers
    c, top = w.truth.center("lemon"), w.truth.aabb("lemon")[5]
    pos, orn = pb.getBasePositionAndOrientation(w.scene.things["knife"].body, physicsClientId=w.cid)
    R = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
    # the blade's edge 0.08 m from its middle, clear of the fingers, as the hand holds it
    blade = np.asarray(pos) + R[:, 0] * 0.08 - R[:, 2] * 0.009 - d.arm.tcp_pose()[:3, 3]
    w.begin_action("cut", ("lemon", "knife"))
    assert stand_before(d, c, (0, -1, 0), 0.62).completed
    T = d.arm.tcp_pose()
    above = moved(T, np.array([c[0], c[1], top + 0.03]) - (T[:3, 3] + blade))
    assert reach(d, above).completed
    assert line(d, moved(above, (0, 0, c[2] - top - 0.03)), steps=6, speed=0.15).completed
    assert line(d, above, steps=2).completed and hold(d, 0.5).completed
    w.end_action()


def test_cut_without_injection_halves_the_lemon(tmp_path):
    w = house(tmp_path, knife=True)
    cut_lemon(w)
    assert holds(w, "sliced(lemon)", "holding(knife)")
    w.close()


def test_cut_fails_knife_in_hand(tmp_path):
    w = house(tmp_path, forced("cut", "cut_fails_knife_in_hand"), knife=True)
    cut_lemon(w)
    assert holds(w, "holding(knife)") and not holds(w, "sliced(lemon)")
    assert len(w.scene.things["lemon"].bodies) == 1
    w.close()


def test_cut_fails_knife_drops_nearby(tmp_path):
    w = house(tmp_path, forced("cut", "cut_fails_knife_drops_nearby"), knife=True)
    cut_lemon(w)
    assert holds(w, "hand_empty", "on(knife, floor_kitchen)") and not holds(w, "sliced(lemon)")
    w.close()


# ------------------------------------------------------------ fill


def fill_cup(w):
    d = w.drivers
    tap = np.array(w.site_map().piece("kitchen_sink").tap)
    grip = w.truth.center("cup") - d.arm.tcp_pose()[:3, 3]  # how the hand holds it
    w.begin_action("fill", ("cup", "kitchen_sink"))
    assert stand_before(d, tap, (0, -1, 0), 0.75).completed
    T = d.arm.tcp_pose()
    under = moved(T, tap - (0, 0, 0.18) - (T[:3, 3] + grip))
    assert reach(d, moved(under, (0.15, 0, 0))).completed and line(d, under, steps=3).completed
    assert hold(d, 1.3 * FILL_TIME).completed
    assert carry(d).completed and hold(d, 0.5).completed
    w.end_action()


def test_fill_without_injection_fills_the_cup(tmp_path):
    w = house(tmp_path, cup="held")
    fill_cup(w)
    assert holds(w, "filled(cup)", "holding(cup)")
    w.close()


def test_container_not_fully_filled(tmp_path):
    w = house(tmp_path, forced("fill", "container_not_fully_filled"), cup="held")
    fill_cup(w)
    assert holds(w, "holding(cup)") and not holds(w, "filled(cup)")
    assert 0.0 < w.scene.things["cup"].states["filled"] < 0.95  # some water, not a full cup
    w.close()


def test_container_drops_nearby(tmp_path):
    w = house(tmp_path, forced("fill", "container_drops_nearby"), cup="held")
    fill_cup(w)
    assert holds(w, "hand_empty", "on(cup, floor_kitchen)") and not holds(w, "filled(cup)")
    w.close()


# ------------------------------------------------------------ the hooks themselves


def test_one_draw_per_announced_action_and_late_ends_are_ignored(tmp_path):
    model = SituationModel(table=(SituationSpec("grasp", "grasp_fails_object_unchanged", 0.5, effect=False),), seed=3)
    w = house(tmp_path, model)
    draws = []
    for i in range(6):
        w.begin_action("grasp", ("cup", "counter", "kitchen"))
        draws.append(w.injection.active.spec is not None)
        w.end_action("placeon", ("cup", "counter", "kitchen"))  # not the open action: ignored
        assert w.injection.active is not None
        w.end_action()
    assert w.injection.active is None
    w.begin_action("navigate", ("kitchen", "hall", "door"))  # not in the table: no draw
    assert w.injection.active.spec is None
    w.end_action()
    reference = SituationModel(table=model.table, seed=w.seed)  # a world reseeds its model
    expected = [reference.draw("grasp") is not None for _ in range(6)]
    assert draws == expected and 0 < sum(expected) < 6
    assert w.injected() == []  # no fingers closed on the cup: no drawn row happened
    w.close()


def test_scripted_disturbances_still_apply_to_announced_actions(tmp_path):
    w = world_of(tmp_path, "moved", scene(),
                 disturbances=[{"at": 1, "move": "cup", "to": "cutting_board"}])
    w.begin_action("find", ("floor_kitchen", "counter", "kitchen"))
    w.end_action()
    assert holds(w, "on(cup, counter)")
    w.begin_action("grasp", ("cup", "counter", "kitchen"))
    assert holds(w, "on(cup, cutting_board)") and kinds(w) == ["object_moved_by_person"]
    w.end_action()
    w.close()
