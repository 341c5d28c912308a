"""Each built-in skill achieves its domain effect in the physics, moving the robot through its
drivers only; the camera service turns the camera; the world is told nothing but which action a
goal is, and the oracle is asked afterwards. Real physics, no mocks. The Table II rows are forced
at the drivers by :mod:`test_pb_injection`; the ones here show the skills meet them unchanged.
Doors and drawers are :mod:`test_pb_doors`'s; items taken off the floor, :mod:`test_pb_floor_grasps`'s."""

import math
from pathlib import Path

import pytest
from skill_runs import (TREES, act, forced, holds, lay, move_view, on_both_sensors, pybullet, run,
                        seen, settle, skills_fail, truths)

from skills.kit import kit_for

from vap_bt.skill import GoalState

pytestmark = pytest.mark.slow

CUT_SCENE = """
name: cut_test
domain: {domain}
goal: ["sliced(lemon)"]
scene:
  rooms: [kitchen]
  robot: {{room: kitchen}}
  furniture:
    cutting_board: {{type: surface, room: kitchen}}
  items:
    lemon: {{place: on cutting_board}}
    knife: {{type: knife, place: held}}
"""


@pytest.fixture
def cut_task(tmp_path) -> Path:
    p = tmp_path / "cut.yaml"
    p.write_text(CUT_SCENE.format(domain=(TREES.parent / "domains" / "household.pddl").as_posix()))
    return p


# ------------------------------------------------------------ effects without situations


@on_both_sensors()
def test_grasp_navigate_place(worlds, sensors):
    w = worlds("collect_cup", sensors=sensors)
    run(w, "find(floor_living_room, cup, living_room)", "grasp(cup, coffee_table, living_room)")
    assert holds(w, "holding(cup)") and not holds(w, "hand_empty") and not holds(w, "on(cup, coffee_table)")
    run(w, "navigate(living_room, kitchen, door_lk, cup)")
    assert holds(w, "robot_in(kitchen)", "holding(cup)")
    run(w, "find(door_lk, counter, kitchen)")
    assert holds(w, "robot_at(counter)", "inview(counter)")
    run(w, "placeon(cup, counter, kitchen)")
    assert holds(w, "on(cup, counter)", "hand_empty", "in_room(cup, kitchen)")


@on_both_sensors(("fill(cup, kitchen_sink) finds the tap out of reach", "kitchen_sink: tap out of reach"))
def test_open_takeout_fill_turnon(worlds, sensors):
    w = worlds("boil_water", sensors=sensors)
    run(w, "find(floor_kitchen, cabinet, kitchen)", "open(cabinet)")
    assert holds(w, "open(cabinet)") and not holds(w, "closed(cabinet)")
    run(w, "takeout(cup, cabinet, kitchen)")
    assert holds(w, "holding(cup)") and not holds(w, "inside(cup, cabinet)")
    run(w, "find(cabinet, kitchen_sink, kitchen)", "fill(cup, kitchen_sink)")
    assert holds(w, "filled(cup)")
    run(w, "find(kitchen_sink, microwave, kitchen)", "turnon(microwave, cup)")
    assert holds(w, "turned_on(microwave)") and not holds(w, "heated(cup)")  # the cup is not inside


@pytest.mark.slow(seconds=40)
def test_the_cup_goes_in_under_the_tap_below_its_arm():
    # boil_water seed 0 (the pilot's episode, the demo): the arm swung the cup straight to its
    # pose under the tap from above; the cup caught on the tap's arm and was dragged up out of
    # the fingers' hold (filled never held), or the arm stopped against the tap (blocked)
    w = pybullet("boil_water", image_size=(320, 240))  # as an episode sees
    try:
        run(w, "find(floor_kitchen, cabinet, kitchen)", "open(cabinet)", "takeout(cup, cabinet, kitchen)",
            "find(cabinet, kitchen_sink, kitchen)", "fill(cup, kitchen_sink)")
        assert holds(w, "filled(cup)", "holding(cup)")
    finally:
        w.close()


def cup_on_the_counter(at):
    """Test setup: boil_water's world with the cup standing on the counter at ``at`` (x, y)."""
    w = pybullet("boil_water", image_size=(320, 240))  # as an episode sees
    lay(w, "cup", at, 0.946, (0.0, 0.0, 0.0))
    return w


@pytest.mark.slow(seconds=40)
@pytest.mark.parametrize("at", [
    # boil_water seeds 5 and 6 at 0b833f6: the cup, dropped by a takeout, was taken off the floor
    # from above; with the hand over its opening the wrist met the tap's arm before the cup was
    # under the outlet (blocked, 0.30 rad behind), or the cup stood under the tap hand and all and
    # stayed empty. Taken from above off the counter here, as a grasp off any surface is
    pytest.param((4.2, 3.95), id="by_its_side"),
    # taken again by its side that low, the arm reached the pose 15 cm in front of the tap only
    # on branches that met the tap (boil_water seed 7 at bf96344: "tap out of reach")
    pytest.param((4.6, 3.95), id="nearer_the_tap"),
])
def test_a_cup_taken_from_above_is_taken_by_its_side_to_be_filled(at):
    w = cup_on_the_counter(at)
    try:
        run(w, "find(floor_kitchen, counter, kitchen)", "grasp(cup, counter, kitchen)",
            "find(counter, kitchen_sink, kitchen)", "fill(cup, kitchen_sink)")
        assert holds(w, "filled(cup)", "holding(cup)")
    finally:
        w.close()


@pytest.mark.slow(seconds=40)
def test_a_cup_set_down_at_the_counters_end_is_looked_for_where_it_was_let_go():
    # boil_water seed 6: the robot came from the sink's side, the fill set the cup down at the
    # counter's near end to take it by its side, and the look for it went to the counter's middle
    # from its standoff, which does not show that end: "not taken again", three times
    w = cup_on_the_counter((3.98, 3.95))
    try:
        run(w, "find(floor_kitchen, counter, kitchen)", "grasp(cup, counter, kitchen)",
            "find(counter, cabinet, kitchen)", "find(cabinet, kitchen_sink, kitchen)", "fill(cup, kitchen_sink)")
        assert holds(w, "filled(cup)", "holding(cup)")
    finally:
        w.close()


@pytest.mark.slow(seconds=40)
def test_a_cup_taken_off_the_floor_leaves_no_ghost_where_it_lay():
    # boil_water seed 7: the cup fell in front of the sink, where the fill's work pose is; looks
    # that did not name it left it remembered as '?cup#0', '?bottle#0' and '?mug#0' on the floor
    # there, the grasp took it, and the fill's drive to the tap found "no clear way", thrice
    from skills.kit import kit_for
    from vap_bt.motion.footprint import Obb

    w = pybullet("boil_water", image_size=(320, 240))
    try:
        lay(w, "cup", (2.378, 3.313), 0.033, (1.5708, 0.0, 0.0))
        run(w, "find(floor_kitchen, cup, kitchen)")
        kit = kit_for(w)
        kit.scene.floor_items["?bottle#0"] = Obb.aabb((2.34, 3.27, 0.0), (2.42, 3.36, 0.07))  # as a look leaves it
        kit.scene.floor_items["?pan#0"] = Obb.aabb((3.0, 2.5, 0.0), (3.1, 2.6, 0.05))  # something else, elsewhere
        run(w, "grasp(cup, floor_kitchen, kitchen)", "find(cup, kitchen_sink, kitchen)")
        assert holds(w, "holding(cup)")
        assert set(kit.scene.floor_items) == {"?pan#0"}
        assert kit.nav.base_path((2.38, 3.35, math.pi / 2), True) is not None  # the fill's work pose
    finally:
        w.close()


@on_both_sensors()
def test_placein_puts_the_held_item_into_the_container(worlds, sensors):
    w = worlds("store_firewood", sensors=sensors)
    run(w, "find(floor_living_room, wood1, living_room)", "grasp(wood1, hearth, living_room)",
        "navigate(living_room, storage_room, door_ls, wood1)", "find(door_ls, basket, storage_room)")
    assert holds(w, "holding(wood1)", "inview(basket)")
    run(w, "placein(wood1, basket, storage_room)")
    assert holds(w, "inside(wood1, basket)", "hand_empty", "in_room(wood1, storage_room)")
    # placing folded the arm: a look re-aims the camera and, from where the robot stands, sees
    # down into the open top; looking from above needs no base room
    assert seen(w, ("wood1", "basket"))["wood1"] >= 0.5
    eye = w.robot.link_pose("camera_optical")[:3, 3]
    assert move_view(w, ("wood1",), "above")
    assert w.robot.link_pose("camera_optical")[2, 3] > eye[2] + 0.1  # higher than the eye was
    assert seen(w, ("wood1", "basket"))["wood1"] >= 0.5


@pytest.mark.slow(seconds=20)
def test_an_item_held_from_above_goes_into_the_oven_leaned():
    """The oven's opening is 0.3 m high: a pie taken from above cannot go in upright (the wrist
    rides over the hand and strikes the face above the opening). heat_pie's seed 4 takes the pie
    off the counter from above; upright, every placein stopped on the blocked arm and the episode
    ended stuck. Leaned in, the pie is let go tilted and settles inside.

    The episode stops at the first placein into the oven that fails (as a Ctrl-C would: the report
    so far): every placein must succeed, so the test is decided there, and the rest of the episode
    (a re-survey, the oven opened, more placeins: 25 of its 45 s on CI) could not change that.

    In world pb-1 it failed (a strict xfail): seed 4's survey believed the shut oven open (the
    VLM's error) and no placein found an arm pose. In pb-2 (the gliding base) it is decided by the
    pictures' draws too: it failed so with the skills that looked again from the same views, and
    succeeds with those that look again from new ones. A placein that finds the oven shut (the
    survey's belief, wrong again on the pictures the handle's look of stop 60 led to) is the
    executive's to correct (it opens the oven, stop 59), not the leaning's: it does not count."""
    SHUT = "oven is shut"
    from vap_bt.app.runner import EpisodeInterrupted, RunConfig, Session
    from vap_bt.taskfile import load

    def stop_at_a_failed_placein(line: str) -> None:
        if line.lstrip().startswith("situation: execution of placein(apple_pie, oven") and SHUT not in line:
            raise KeyboardInterrupt

    task = load(TREES / "heat_pie.yaml")
    session = Session(task, RunConfig.from_task(task, world="pybullet", seed=4, injection=False, transport="inproc"),
                      progress=stop_at_a_failed_placein)
    try:
        r = session.episode()
    except EpisodeInterrupted as stopped:
        r = stopped.report
    finally:
        session.close()
    placed = [a for a in r["actions_executed"] if a["action"].startswith("placein(apple_pie, oven")
              and SHUT not in a.get("message", "")]
    assert placed and all(a["state"] == "succeeded" for a in placed), placed
    assert r["success"] and r["goal_satisfied"], r["reason"]


def test_a_held_item_does_not_hide_what_the_camera_looks_at(worlds):
    # the knife, rigid in the wrist camera's view, lay across the egg: the aim turns past it
    w = worlds("halve_egg")
    run(w, "open(drawer)", "takeout(knife, drawer, kitchen)", "find(floor_kitchen, egg, kitchen)")
    assert holds(w, "holding(knife)")
    egg = seen(w, ("egg",))["egg"]
    assert egg >= 0.5, f"the egg {egg:.0%} seen after find(egg)"
    assert move_view(w, ("egg",), "closer") and seen(w, ("egg",))["egg"] >= 0.5


def test_a_closed_room_door_is_seen_whole_and_view_moves_stay_in_the_room(worlds):
    w = worlds("gather_kindling")
    run(w, "find(floor_living_room, door_lg, living_room)")
    assert seen(w, ("door_lg",))["door_lg"] >= 0.5
    # "behind" the door is the other room: a view move does not drive through the closed leaf
    assert not move_view(w, ("door_lg",), "behind")
    assert holds(w, "robot_in(living_room)", "closed(door_lg)")


def test_the_plate_on_the_tall_shelf_is_seen_from_the_front(worlds):
    w = worlds("pick_plate")
    run(w, "find(floor_kitchen, plate, kitchen)", "push(bowl, plate)", "grasp(plate, dining_table, kitchen)",
        "placeon(plate, shelf, kitchen)")
    assert holds(w, "on(plate, shelf)")
    assert move_view(w, ("plate",), "front")
    vis = seen(w, ("plate", "shelf"))
    assert min(vis["plate"], vis["shelf"]) >= 0.5


@on_both_sensors(real_fails=("the grasp closes on nothing and the pie stays in the fridge (the takeout completes)",
                             "holding(apple_pie)=False"))
def test_takeout_from_fridge_round_its_open_door(worlds, sensors):
    # straight from where opening left the robot: the base drives round the open leaf (a straight
    # drive would push it shut) and the low pie is taken with the hand pitched down
    w = worlds("heat_pie", sensors=sensors)
    run(w, "open(fridge)", "takeout(apple_pie, fridge, kitchen)")
    taken = ("holding(apple_pie)", "open(fridge)", "inside(apple_pie, fridge)")
    assert holds(w, *taken[:2]) and not holds(w, taken[2]), truths(w, *taken)


@on_both_sensors()
def test_a_takeout_from_a_shut_fridge_says_the_fridge_is_not_open(worlds, sensors):
    # heat_pie seed 141: the fridge's opening failed unseen, and three takeouts saw only its door
    # ("apple_pie is not where it was believed to be"): a look finds the door shut, and the skill
    # says its precondition open(fridge) was what failed, not where the pie is
    w = worlds("heat_pie", sensors=sensors)
    run(w, "find(floor_kitchen, fridge, kitchen)")
    goal = act(w, "takeout(apple_pie, fridge, kitchen)")
    result = goal.result()
    assert goal.state() is GoalState.ABORTED and result.unmet == "open(fridge)", result
    assert result.missing is None and holds(w, "inside(apple_pie, fridge)", "closed(fridge)")


def test_a_takeout_from_an_open_fridge_the_pie_is_gone_from_says_the_pie_is_missing(worlds):
    # the look finds the door open: where the pie is was what failed
    w = worlds("heat_pie")
    run(w, "find(floor_kitchen, fridge, kitchen)", "open(fridge)")
    lay(w, "apple_pie", (3.5, 2.0), 0.03, (0.0, 0.0, 0.0))
    result = act(w, "takeout(apple_pie, fridge, kitchen)").result()
    assert holds(w, "open(fridge)") and result.missing == "apple_pie" and result.unmet is None, result


@on_both_sensors()
def test_takeout_from_drawer_then_cut_after_view_moves(worlds, sensors):
    w = worlds("halve_egg", sensors=sensors)
    run(w, "open(drawer)", "takeout(knife, drawer, kitchen)")
    assert holds(w, "holding(knife)", "open(drawer)")
    run(w, "find(floor_kitchen, egg, kitchen)")
    for _ in range(2):  # the wrist camera turns the hand and the knife with it
        move_view(w, ("egg",), "closer")
    run(w, "cut(egg, knife)")
    assert holds(w, "sliced(egg)", "holding(knife)"), truths(w, "sliced(egg)", "holding(knife)")


def test_an_egg_at_the_back_of_the_board_is_cut_with_the_blade_further_out(worlds):
    # halve_egg seed 142 in pybullet: the egg lay 2 cm in from the board's back edge (as laid out);
    # no stand in front of the board put the blade's middle over it, and the cut ended "egg: out of
    # reach" three times from the same belief. Seed 155's egg, pushed there by an earlier cut, is
    # still out of reach: its knife was held by its middle, with less blade beyond the hand
    w = worlds("halve_egg", image_size=(320, 240))
    lay(w, "egg", (3.846, 4.334), 0.93, (0.0, 0.0, 0.0))
    run(w, "open(drawer)", "takeout(knife, drawer, kitchen)", "find(floor_kitchen, egg, kitchen)", "cut(egg, knife)")
    assert holds(w, "sliced(egg)", "holding(knife)"), truths(w, "sliced(egg)", "holding(knife)")


def test_a_grasp_whose_approach_meets_something_closes_where_the_hand_stopped(worlds, monkeypatch):
    """A guarded approach: the last stretch into a grasp that stops on contact (the driver's
    ``blocked``: a drawer's floor a little higher than the map has it, the fingertips on it beside
    the knife) closes the fingers there, and the item is taken, rather than the skill ending
    "blocked" three times from the same belief (halve_egg seeds 63 and 117 in pybullet)."""
    from skills.body import Body, Struck

    line, met = Body.line, []

    def touches_at_the_end(self, target, frame="tcp", steps=5, speed=0.4, collide=False):
        done = line(self, target, frame, steps, speed, collide)
        if (steps, speed) == (4, 0.3) and not met:  # the approach into the grasp
            met.append(target)
            raise Struck("blocked: the arm is 0.31 rad behind its set-point")
        return done

    w = worlds("halve_egg")
    run(w, "open(drawer)")
    monkeypatch.setattr(Body, "line", touches_at_the_end)
    run(w, "takeout(knife, drawer, kitchen)")
    assert met and holds(w, "holding(knife)", "open(drawer)"), truths(w, "holding(knife)")


@on_both_sensors()
def test_push_clears_the_blocker(worlds, sensors):
    w = worlds("pick_plate", sensors=sensors)
    assert holds(w, "blocking(bowl, plate)") and not holds(w, "reachable(plate)")
    run(w, "find(floor_kitchen, plate, kitchen)", "push(bowl, plate)")
    assert not holds(w, "blocking(bowl, plate)") and holds(w, "reachable(plate)", "on(bowl, dining_table)")


@skills_fail("the knife in the hand from the start is never measured: after find(lemon) the wrist camera "
             "shows 12 % of it, behind the fingers, and the detector misses it (so from the carry pose and "
             "home): the cut aborts 'not holding knife'", "cut(lemon, knife): aborted not holding knife")
def test_cut_splits_the_object(worlds, cut_task):
    w = worlds(cut_task)
    run(w, "find(floor_kitchen, lemon, kitchen)", "cut(lemon, knife)")
    assert holds(w, "sliced(lemon)", "holding(knife)") and len(w.scene.things["lemon"].bodies) == 2


def test_scripted_disturbance_moves_an_object(worlds):
    w = worlds("pick_plate", disturbances=[{"at": 0, "move": "mug", "to": "shelf"}])
    run(w, "find(floor_kitchen, shelf, kitchen)")
    assert holds(w, "on(mug, shelf)") and not holds(w, "on(mug, dining_table)")
    assert [s.kind for s in w.injected()] == ["object_moved_by_person"]


# ------------------------------------------------------------ Table II rows, met by the skills


@pytest.mark.parametrize("kind, expect", [
    ("grasp_fails_object_unchanged", ["hand_empty", "on(cup, coffee_table)"]),
    ("grasp_fails_object_drops_nearby", ["hand_empty", "on(cup, floor_living_room)"]),
])
def test_grasp_situations(worlds, kind, expect):
    w = worlds("collect_cup", forced("grasp", kind))
    goal = act(w, "grasp(cup, coffee_table, living_room)")
    assert goal.state() is GoalState.SUCCEEDED  # the motion completed: the failure is for perception
    settle(w)
    assert holds(w, *expect) and not holds(w, "holding(cup)")
    assert [s.kind for s in w.injected()] == [kind]


def test_a_look_again_from_where_the_last_one_stood_takes_views_not_taken_yet(worlds):
    # world pb-2: the base stands still, so a camera pose taken again is the same picture, its
    # detections and misses the same (heat_pie: the grasp looked at the pie at the fridge's foot
    # from one view, another, and the first again, and missed it in every one). Looked for twice
    # from one stand where it is not, the item is looked at from a new view every time
    import hashlib

    from skills.eyes import VIEWS_PER_MEASURE, same_view
    from skills.kit import kit_for

    w = worlds("heat_pie", image_size=(320, 240))
    kit = kit_for(w)
    frames, take = [], kit.eyes.frame
    kit.eyes.frame = lambda *a, **k: frames.append(take(*a, **k)) or frames[-1]
    point = kit.body.in_base((1.0, 0.0, 0.0))  # the floor in front: the pie is in the shut fridge
    for _ in range(2):
        assert kit.eyes.measure("apple_pie", point) is None
    poses = [f.camera_pose for f in frames]
    assert len(poses) == 2 * VIEWS_PER_MEASURE
    assert not any(same_view(a, b) for i, a in enumerate(poses) for b in poses[i + 1:])
    assert len({hashlib.sha1(f.rgb.tobytes()).hexdigest() for f in frames}) == len(frames)


def test_held_object_drops_during_navigation(worlds):
    # the gripper feels the cup go: the trip stops once the cup has had the time to fall, beside
    # it (driving on would leave it behind, in a room nobody looks in for it), and says so; that
    # the robot is not where the action takes it is for the checks to see
    w = worlds("collect_cup", forced("navigate", "held_object_drops_during_navigation"))
    run(w, "grasp(cup, coffee_table, living_room)")
    goal = act(w, "navigate(living_room, kitchen, door_lk, cup)")
    assert goal.state() is GoalState.SUCCEEDED and "cup slipped from the gripper" in goal.result().message
    assert holds(w, "robot_in(living_room)")
    assert holds(w, "hand_empty")
    settle(w)
    assert holds(w, "on(cup, floor_living_room)") or holds(w, "on(cup, floor_kitchen)")
    x, y, _ = w.robot.base_pose
    cx, cy, _ = w.truth.center("cup")
    assert math.hypot(cx - x, cy - y) < 1.0


@pytest.mark.slow(seconds=30)
def test_a_spot_the_hand_set_an_item_on_is_not_free_when_a_look_misses_the_item(worlds):
    # retrieve_bottles seed 2 (pb-2): the look at the counter's top showed no bottle on it (the
    # detector missed the one set down there before), the second bottle was let go where the first
    # stood and knocked it to the floor, and the executive took that one for the second and spent
    # its replans on it. The first bottle is taken out of every view here: the look misses it
    w = worlds("retrieve_bottles")
    lay(w, "bottle1", (2.75, 4.05), 0.99, (0.0, 0.0, 0.0))
    run(w, "find(floor_kitchen, counter, kitchen)", "grasp(bottle1, counter, kitchen)",
        "placeon(bottle1, counter, kitchen)")
    put = w.oracle.position("bottle1")
    assert holds(w, "on(bottle1, counter)")
    lay(w, "bottle1", (6.0, 2.0), 0.09, (0.0, 0.0, 0.0))
    spot = kit_for(w).hands.free_spot("counter", "bottle2")
    assert math.dist(spot[:2], put[:2]) > 0.15, (spot, put)


@pytest.mark.slow(seconds=40)
def test_a_bottle_is_set_on_the_counter_where_a_bottle_on_the_floor_does_not_block_the_stand(worlds):
    # retrieve_bottles seed 5 (pb-2): an injected place failure dropped the first bottle at the
    # counter's foot, where the base stands to set a bottle down at the counter's middle; the
    # place chose that middle spot three times, and three times the base would have run into the
    # bottle on the floor ("no clear way to (2.30, 3.35)"): the episode stopped stuck
    w = worlds("retrieve_bottles", sensors="real", image_size=(320, 240))
    lay(w, "bottle1", (2.47, 3.18), 0.03, (math.pi / 2, 0.0, 0.3))
    lay(w, "bottle2", (2.15, 3.27), 0.03, (math.pi / 2, 0.0, 1.2))
    run(w, "find(floor_kitchen, bottle2, kitchen)", "grasp(bottle2, floor_kitchen, kitchen)",
        "find(bottle2, counter, kitchen)", "placeon(bottle2, counter, kitchen)")
    settle(w)
    assert holds(w, "on(bottle2, counter)")
