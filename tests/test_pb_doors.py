"""Doors, drawers and appliance doors in the physics: the skills open and close each articulated
piece within its joint's limits, with a full hand too, and the skills' scene model takes a leaf as
every frame shows it; a door the Table II situations leave shut or half open stays so, and a
half-open one blocks the way. Real physics, no mocks (see :mod:`test_pb_skills`)."""

import pytest
from skill_runs import act, forced, holds, run, skills_fail

from vap_bt.skill import GoalState

pytestmark = pytest.mark.slow


def test_open_with_full_hand_sets_down_and_regrasps(worlds):
    w = worlds("boil_water")
    run(w, "find(floor_kitchen, cabinet, kitchen)", "open(cabinet)", "takeout(cup, cabinet, kitchen)",
        "find(cabinet, kitchen_sink, kitchen)", "fill(cup, kitchen_sink)", "find(kitchen_sink, microwave, kitchen)",
        "open(microwave)")
    assert holds(w, "open(microwave)", "holding(cup)")


def test_an_oven_opened_with_the_pie_in_hand_is_pulled_again_until_its_door_lies_open(worlds):
    """With the pie set down on the counter for it, the arm could not follow the oven's drop-down
    door past 0.39 of its travel (heat_pie seeds 4, 9, 10): "open" succeeded, and every placein
    after it found no arm pose past the half-raised door. The skill pulls again from where the
    door stopped."""
    w = worlds("heat_pie", seed=4)
    run(w, "find(floor_kitchen, fridge, kitchen)", "open(fridge)", "takeout(apple_pie, fridge, kitchen)",
        "find(fridge, oven, kitchen)", "open(oven)")
    assert w.truth.joint_fraction(w.scene.things["oven"]) > 0.9 and holds(w, "open(oven)", "holding(apple_pie)")
    run(w, "placein(apple_pie, oven, kitchen)")
    assert holds(w, "inside(apple_pie, oven)")


def test_a_view_closer_to_an_open_door_does_not_drive_the_held_item_into_its_leaf(worlds):
    """A view move is a careful trip: it must not take the arm, held out where the last look left
    it, to a room door's open leaf. retrieve_bottles seed 2: with bottle2 in the hand, a look
    "closer" at the open door_kg from the garden drove the bottle over the leaf's top edge and
    pushed the leaf to its stop; the next drive dragged the bottle along the leaf, a finger pad
    sank into it, and when open(door_kg) set it down on the bench the fingers flung it off onto
    the floor by the wall, where no grasp reached it (the replanning budget ran out)."""
    import math

    from skill_runs import camera, lay
    from vap_bt.robot.camera import Viewpoint

    w = worlds("retrieve_bottles", seed=2)
    lay(w, "bottle2", (4.716, 3.106), 0.03, (math.pi / 2, 0.0, 0.0))  # where the episode's bottle lay
    run(w, "find(floor_garden, bottle2, garden)", "grasp(bottle2, floor_garden, garden)",
        "find(floor_garden, door_kg, garden)")
    door = w.aim_at(("door_kg",))
    view = camera(w)
    assert view.goto_view(Viewpoint("garden", door, (6.9, 2.2, math.pi / 2)))  # the survey's stance there
    q = w.truth.joint_value("door_kg")
    view.move_view(door, "closer")
    assert abs(w.truth.joint_value("door_kg") - q) < 0.01, "the leaf was pushed"
    assert holds(w, "holding(bottle2)", "open(door_kg)")


# turning every waypoint near a wrist's limit by a whole turn let the fridge and the cabinet close, but
# swept the wrist round mid-path elsewhere (boil_water seed 0's cup then not found in the cabinet): not
# done. The cabinet's close stopped before that, its handle out of reach from where the open left it,
# until stop 60's look at the handle (the arm back where the leaf's look left it): refused there too
NOT_CLOSED = skills_fail("close is refused: the timed path through the handle's waypoints leaves a wrist's joint limits",
                         "refused: a sample leaves the joint limits")
ARTICULATED = [  # (task scene, the thing, where the robot stands first)
    pytest.param("boil_water", "cabinet", "find(floor_kitchen, cabinet, kitchen)", marks=NOT_CLOSED, id="cabinet"),
    pytest.param("boil_water", "microwave", "find(floor_kitchen, microwave, kitchen)", id="microwave"),
    pytest.param("heat_pie", "fridge", "find(floor_kitchen, fridge, kitchen)", marks=NOT_CLOSED, id="fridge"),
    pytest.param("heat_pie", "oven", "find(floor_kitchen, oven, kitchen)", id="oven",
                 marks=skills_fail("close(oven): from the stance by the dropped door no pre-pose over "
                                   "its handle has a clear way (handle out of reach)", "oven: handle out of reach")),
    pytest.param("halve_egg", "drawer", "find(floor_kitchen, drawer, kitchen)", id="drawer"),
    pytest.param("gather_kindling", "door_lg", "find(floor_living_room, table, living_room)", id="door_lg"),
]


def within_limits(w, name):
    h = w.scene.things[name].hinge
    q = w.truth.joint_value(name)
    return h.lower - 1e-3 <= q <= h.upper + 1e-3


@pytest.mark.parametrize("task, thing, start", ARTICULATED)
def test_open_then_close(worlds, task, thing, start):
    w = worlds(task)
    run(w, start)
    assert holds(w, f"closed({thing})")
    run(w, f"open({thing})")
    assert holds(w, f"open({thing})") and not holds(w, f"closed({thing})") and within_limits(w, thing)
    run(w, f"close({thing})")
    assert holds(w, f"closed({thing})") and not holds(w, f"open({thing})") and within_limits(w, thing)


@pytest.mark.parametrize("seed, find", [(0, "find(floor_kitchen, fridge)"), (4, "find(floor_kitchen, fridge, kitchen)")])
def test_on_real_sensors_a_fridge_opens_its_handle_placed_where_a_look_shows_the_bar(worlds, seed, find):
    """The fingers closed 5 to 16 cm beside the fridge's handle ("the handle slipped"): seed 0's map,
    registered to the fridge, slid 5 cm along its front (the door, which fills it, is left out of
    the fit); seed 4's localiser frame moved 14 cm as the base came to rest at the grasp stance,
    after the path was planned. A look at the handle from the stance places its bar, carried by the
    wheels to where the base then stands, and the path is planned again in the frame believed there."""
    w = worlds("heat_pie", seed=seed, sensors="real")
    run(w, find, "open(fridge)")
    assert holds(w, "open(fridge)")


def test_open_fails_door_stays_closed(worlds):
    w = worlds("gather_kindling", forced("open", "open_fails_object_closed"))
    run(w, "find(floor_living_room, table, living_room)", "open(door_lg)")
    assert holds(w, "closed(door_lg)") and not holds(w, "open(door_lg)")


def test_door_left_half_open_blocks_navigation(worlds):
    w = worlds("gather_kindling", disturbances=[{"at": 0, "door": "door_lg", "open": 0.4}])
    run(w, "find(floor_living_room, table, living_room)")
    assert not holds(w, "open(door_lg)") and not holds(w, "closed(door_lg)")
    assert [s.kind for s in w.injected()] == ["door_left_half_open"]
    goal = act(w, "navigate(living_room, garden, door_lg, table)")
    assert goal.state() is GoalState.ABORTED and "door_lg" in goal.result().message
    assert holds(w, "robot_in(living_room)") and not holds(w, "robot_in(garden)")


def test_a_door_shut_behind_the_robots_back_is_seen_shut_in_the_next_frame(worlds):
    """The skills' scene model takes a piece's leaf as every frame shows it, not as the last
    action left it: a fridge door that swung shut after a takeout was believed open, and the arm
    went through it on its way to the floor in front of it."""
    import pybullet as pb

    from skill_runs import camera
    from skills.kit import kit_for

    w = worlds("heat_pie")
    run(w, "find(floor_kitchen, fridge, kitchen)", "open(fridge)")
    scene = kit_for(w).scene
    opened = scene.joint["fridge"]
    assert abs(opened) > 0.5, opened
    hinge = w.scene.things["fridge"].hinge
    pb.resetJointState(hinge.body, hinge.joint, 0.0, physicsClientId=w.cid)  # someone shuts it
    for _ in range(30):
        w.step()
    camera(w).capture(w.aim_at(("fridge",)))
    assert abs(scene.joint["fridge"]) < 0.1, scene.joint["fridge"]
