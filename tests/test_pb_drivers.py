"""The pybullet drivers move the robot as commanded and stop when told: real physics, scripted
motions through the drivers only (:mod:`driver_scripts`), no primitive involved."""

from __future__ import annotations

import math
import threading

import numpy as np
import pytest
from driver_scripts import (CLOSED, OPEN, arc_joints, drive, frame, hold, kitchen, line, moved, never, reach,
                            stand_before, through, world_of)

from vap_bt.domain.atoms import Atom
from vap_bt.motion.kinematics import Kinematics
from vap_bt.robot.drivers import JointTrajectory
from vap_bt.robot.labels import partners

pytestmark = pytest.mark.slow

COUNTER = kitchen({"counter": "type: surface"}, {"cup": "place: on counter"})
CABINET = kitchen({"cabinet": "type: container, state: closed", "drawer": "type: container, state: closed"})


def A(text):
    return Atom.parse(text)



class After:
    """A ``cancelled`` that turns true on its ``n``-th call, counting the physics steps before."""

    def __init__(self, world, n):
        self.world, self.n, self.calls, self.ticks = world, n, 0, None

    def __call__(self):
        self.calls += 1
        if self.calls >= self.n and self.ticks is None:
            self.ticks = self.world.ticks
        return self.calls >= self.n


@pytest.fixture(scope="module")
def counter(tmp_path_factory):
    w = world_of(tmp_path_factory.mktemp("counter"), "counter", COUNTER)
    yield w
    w.close()


def wave(d, dq, seconds=1.5):
    q0 = np.array(d.arm.joint_state().positions)
    t = np.linspace(0.0, seconds, 151)
    s = 0.5 - 0.5 * np.cos(np.pi * t / seconds)
    return JointTrajectory(d.arm.joints, t, q0 + np.outer(s, dq))


# ------------------------------------------------------------ arm and base


def test_the_arm_follows_a_trajectory_and_reports_where_it_is(counter):
    d = counter.drivers
    tr = wave(d, np.array([0.3, 0.1, -0.2, 0.0, 0.2, 0.5]))
    t0 = counter.ticks
    assert d.arm.follow(tr, never).completed
    assert counter.ticks - t0 >= math.ceil(tr.duration / counter.dt)  # it took the trajectory's time
    q = np.array(d.arm.joint_state().positions)
    assert np.max(np.abs(q - tr.positions[-1])) < 0.01
    x, y, yaw = d.base.pose()
    fk = Kinematics.mobile_arm().fk(np.array([x, y, yaw, *q]), "tcp")
    assert np.linalg.norm(d.arm.tcp_pose()[:3, 3] - fk[:3, 3]) < 0.005
    assert d.arm.follow(wave(d, -np.array([0.3, 0.1, -0.2, 0.0, 0.2, 0.5])), never).completed


def test_the_arm_refuses_what_it_cannot_follow(counter):
    d = counter.drivers
    here = np.array(d.arm.joint_state().positions)
    t = np.array([0.0, 1.0])
    t0 = counter.ticks
    wrong = JointTrajectory(("a", "b", "c", "d", "e", "f"), t, np.array([here, here]))
    far = JointTrajectory(d.arm.joints, t, np.array([here + 0.3, here + 0.3]))
    beyond = JointTrajectory(d.arm.joints, t, np.array([here, here + np.array([0, 0, 4.0, 0, 0, 0])]))
    backwards = JointTrajectory(d.arm.joints, np.array([0.0, -1.0]), np.array([here, here]))
    for tr, why in ((wrong, "joints"), (far, "starts"), (beyond, "limits"), (backwards, "grow")):
        out = d.arm.follow(tr, never)
        assert not out.completed and out.message.startswith("refused") and why in out.message
    assert counter.ticks == t0  # nothing moved
    # the joints may come in any order: they are matched by name
    order = tuple(reversed(d.arm.joints))
    assert d.arm.follow(JointTrajectory(order, t, np.array([here[::-1], here[::-1]])), never).completed


def test_the_base_drives_through_its_path(counter):
    d = counter.drivers
    x, y, yaw = d.base.pose()
    seen = []
    path = [(x + 0.6, y, yaw), (x + 0.6, y - 0.5, yaw + 0.8)]

    def watch():
        seen.append(d.base.pose())
        return False

    out = d.base.follow(path, 0.8, watch)
    assert out.completed
    end = d.base.pose()
    assert math.hypot(end[0] - path[-1][0], end[1] - path[-1][1]) < 0.01 and abs(end[2] - path[-1][2]) < 0.02
    assert min(math.hypot(p[0] - path[0][0], p[1] - path[0][1]) for p in seen) < 0.02  # through the first pose
    assert drive(d, (x, y, yaw)).completed
    assert not d.base.follow(path, 0.0, never).completed  # a speed is a share of the limits


def test_the_base_glides_through_free_space_and_is_driven_where_it_would_touch(tmp_path):
    # pb-2 (pb_glide): a set-point in free space is set, not stepped through the physics, and the
    # held cup goes along in the hand; towards the counter the physics drives and blocks as before
    import pybullet as pb

    w = world_of(tmp_path, "glide", kitchen({"counter": "type: surface"}, {"cup": "place: held"}))
    d, physics, step = w.drivers, [0], w.step

    def counted() -> None:
        physics[0] += 1
        step()

    assert hold(d, 0.5).completed  # the cup comes to rest in the hand
    w.step = counted  # the drivers step the world through it
    x, y, yaw = d.base.pose()
    cup = np.linalg.inv(w.robot.link_pose("tcp")) @ _pose_of(pb, w, "cup")
    t0 = w.ticks
    assert drive(d, (x, y - 0.8, yaw), (x + 0.3, y - 0.8, yaw - 1.0)).completed
    assert w.ticks - t0 > 100 and physics[0] <= 3  # the time passed; the physics hardly stepped
    assert d.gripper.state().holding
    now = np.linalg.inv(w.robot.link_pose("tcp")) @ _pose_of(pb, w, "cup")
    assert np.linalg.norm(now[:3, 3] - cup[:3, 3]) < 0.002  # where the hand held it
    cx, cy, _ = w.site_map().piece("counter").pose
    physics[0] = 0
    out = drive(d, (cx, cy, math.pi / 2))
    assert not out.completed and out.message.startswith("blocked") and physics[0] > 0
    counter = w.scene.things["counter"].body
    robot_and_cup = (w.robot.id, w.scene.things["cup"].body)
    assert min(p[8] for b in robot_and_cup for p in pb.getClosestPoints(b, counter, 0.05, physicsClientId=w.cid)) > -0.02
    w.close()


def test_an_item_in_the_gliding_base_s_way_is_pushed_by_the_physics(tmp_path):
    # a kinematic base set pose by pose would pass through it and leave it where it stood
    import pybullet as pb

    w = world_of(tmp_path, "sweep", kitchen({"counter": "type: surface"}, {"cup": "place: on floor_kitchen"}))
    d = w.drivers
    x, y, yaw = d.base.pose()
    cup = w.scene.things["cup"].body
    pb.resetBasePositionAndOrientation(cup, (x, y - 0.75, 0.06), (0, 0, 0, 1), physicsClientId=w.cid)
    assert hold(d, 0.5).completed  # it stands on the floor
    before = np.array(w.truth.center("cup"))
    drive(d, (x, y - 1.4, yaw))  # into it, backwards: pushed along, or blocked by it
    after = np.array(w.truth.center("cup"))
    assert np.linalg.norm(after[:2] - before[:2]) > 0.1
    assert min([p[8] for p in pb.getClosestPoints(w.robot.id, cup, 0.05, physicsClientId=w.cid)] + [1.0]) > -0.01
    w.close()


def _pose_of(pb, w, name) -> np.ndarray:
    p, o = pb.getBasePositionAndOrientation(w.scene.things[name].body, physicsClientId=w.cid)
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = np.array(pb.getMatrixFromQuaternion(o)).reshape(3, 3), p
    return T


@pytest.mark.parametrize("n", [1, 5])
def test_cancel_stops_every_driver_within_one_step(counter, n):
    d = counter.drivers
    for move in (lambda c: d.arm.follow(wave(d, np.full(6, 0.4)), c),
                 lambda c: d.base.follow([(d.base.pose()[0] + 1.0, *d.base.pose()[1:])], 1.0, c),
                 lambda c: d.gripper.move(CLOSED if d.gripper.state().width > 0.04 else OPEN, 50, c)):
        c = After(counter, n)
        out = move(c)
        assert counter.ticks - c.ticks <= 1  # at most the step in progress
        if hasattr(out, "completed"):
            assert not out.completed and out.message == "cancelled"
        q = counter.robot.q()
        hold(d, 0.3)  # the stop holds where the joints were, it does not finish the motion
        assert np.max(np.abs(counter.robot.q() - q)) < 0.02


def test_stop_ends_a_motion_running_on_another_thread(counter):
    d = counter.drivers
    out, moving = [], threading.Event()

    def polled() -> bool:  # the driver asks every step whether to go on: the motion is under way
        moving.set()
        return False

    run = threading.Thread(target=lambda: out.append(d.arm.follow(wave(d, np.full(6, 0.5), 200.0), polled)))
    run.start()
    # a stop before the motion has begun stops nothing (the world's clock may step the physics
    # before the thread starts; waiting on its ticks alone left the test to the threads' timing)
    assert moving.wait(10)
    d.arm.stop()
    run.join(timeout=10)
    assert out and not out[0].completed and out[0].message == "stopped"
    assert through(d, [np.array(d.arm.joint_state().positions)], 0.5).completed  # and it moves again


# ------------------------------------------------------------ gripper


def test_a_gripper_closing_on_an_item_holds_it_and_on_nothing_holds_nothing(tmp_path):
    w = world_of(tmp_path, "grip", COUNTER)
    d = w.drivers
    assert d.gripper.move(CLOSED, 40, never) == d.gripper.state() and not d.gripper.state().holding
    assert d.gripper.state().width < 0.005  # closed on nothing
    assert d.gripper.move(OPEN, 40, never).width > 0.08
    c, box = w.truth.center("cup"), w.truth.aabb("cup")
    assert stand_before(d, c, (0, -1, 0), 0.70).completed
    G = frame((0, 0, -1), (0, 1, 0), (c[0], c[1], box[5] - 0.03))
    assert reach(d, moved(G, (0, 0, 0.12))).completed and line(d, G, steps=4).completed
    s = d.gripper.move(CLOSED, 40, never)
    assert s.holding and 0.055 < s.width < 0.066  # stopped on the cup (0.066 m across)
    assert w.oracle.holds(A("holding(cup)"))
    assert line(d, moved(G, (0, 0, 0.15)), steps=3).completed
    assert w.truth.center("cup")[2] > c[2] + 0.12  # it came along
    # opening over the counter lets it go; it lands there
    assert line(d, moved(G, (0, 0, 0.005)), steps=3).completed
    s = d.gripper.move(OPEN, 40, never)
    assert not s.holding and w.oracle.holds(A("hand_empty"))
    assert line(d, moved(G, (0, 0, 0.15)), steps=3).completed and hold(d, 0.5).completed
    assert w.oracle.holds(A("on(cup, counter)"))
    w.close()


# ------------------------------------------------------------ doors and drawers


@pytest.fixture
def cabinet(tmp_path):
    w = world_of(tmp_path, "cabinet", CABINET)
    yield w
    w.close()


def test_a_drawer_pulled_by_its_handle_opens_and_stays_open(cabinet):
    w, d = cabinet, cabinet.drivers
    art = w.site_map().piece("drawer").articulation
    n = np.array(art.normal)
    G = frame(-n, art.bar, art.handle)
    assert stand_before(d, art.handle, n, 0.92).completed
    assert reach(d, moved(G, n * 0.12)).completed and line(d, G, steps=4).completed
    s = d.gripper.move(CLOSED, 80, never)
    assert s.holding and w.truth.joint_value("drawer") == pytest.approx(0.0, abs=0.01)
    assert line(d, moved(G, n * 0.30), steps=8, speed=0.2).completed
    assert w.truth.joint_value("drawer") == pytest.approx(0.30, abs=0.02)
    assert not d.gripper.move(OPEN, 60, never).holding
    x, y, yaw = d.base.pose()
    assert drive(d, (x + n[0] * 0.15, y + n[1] * 0.15, yaw)).completed and hold(d, 1.0).completed
    assert w.truth.joint_value("drawer") == pytest.approx(0.30, abs=0.02)  # released, it stays
    assert w.oracle.holds(A("open(drawer)"))


def test_a_cabinet_door_dragged_along_its_arc_opens_and_stays(cabinet):
    w, d = cabinet, cabinet.drivers
    art = w.site_map().piece("cabinet").articulation
    n, o, hp = np.array(art.normal), np.array(art.origin), np.array(art.handle)
    away = (hp - o) * (1, 1, 0)
    away /= np.linalg.norm(away)  # along the face, from the hinge towards the handle
    G = frame(-n, -np.array(art.bar), hp)
    goal = 0.75 * art.opened
    assert stand_before(d, hp, n, 0.75, side=away * 0.1).completed
    assert reach(d, moved(G, n * 0.12)).completed and line(d, G, steps=4).completed
    assert d.gripper.move(CLOSED, 80, never).holding
    arc = arc_joints(d, art, G, np.linspace(0.0, goal, 16))
    assert arc is not None, "the arc leaves the arm's reach from this base pose"
    assert through(d, arc[1:], speed=0.3).completed
    assert w.truth.joint_value("cabinet") == pytest.approx(goal, abs=0.05)
    assert not d.gripper.move(OPEN, 60, never).holding
    x, y, yaw = d.base.pose()
    assert drive(d, (x + n[0] * 0.2, y + n[1] * 0.2, yaw)).completed and hold(d, 1.0).completed
    assert w.truth.joint_value("cabinet") == pytest.approx(goal, abs=0.05)  # released, it stays
    assert w.oracle.holds(A("open(cabinet)")) and not w.oracle.holds(A("closed(cabinet)"))


# ------------------------------------------------------------ camera


def test_the_wrist_camera_frame_is_what_it_sees_now(counter):
    d = counter.drivers
    # the module's other tests leave the arm where they stopped it (the stop test: anywhere along
    # its wave, as the threads' timing goes), and where the camera looks depends on it
    assert through(d, [np.array(counter.robot.cfg.arm.home)], 0.8).completed
    c = counter.truth.center("cup")
    assert stand_before(d, c, (0, -1, 0), 0.85).completed
    frame_ = d.camera.capture()
    shown = counter.captures.get(frame_.frame_id).visibility  # the world's record: the detector says "cup", not which
    assert shown.get("cup", 0.0) > 0.0 and shown.get("counter", 0.0) > 0.0
    # labels are classes of the scene's things (a false positive takes one of them too), or the
    # classes a detector confuses them with now and then
    classes = {c for k in counter._classes for c in (k, *partners(k))}
    assert all(not x.name for x in frame_.detections) and {x.label for x in frame_.detections} <= classes
    assert frame_.rgb.shape == (120, 160, 3) and frame_.depth.shape == (120, 160) and frame_.masks is not None
    assert frame_.intrinsics is not None and np.allclose(frame_.camera_pose, counter.robot.link_pose("camera_optical"))
    assert counter.captures.get(frame_.frame_id) is not None  # the simulated VLM answers about it
    # the frame is the camera's view now: turn the camera away and the cup is gone
    assert d.arm.follow(wave(d, np.array([1.5, 0, 0, 0, 0, 0])), never).completed
    assert counter.captures.get(d.camera.capture().frame_id).visibility.get("cup", 0.0) == 0.0
    assert d.arm.follow(wave(d, np.array([-1.5, 0, 0, 0, 0, 0])), never).completed


@pytest.mark.parametrize("seed", range(4))
def test_an_arm_trajectory_s_set_points_are_the_per_step_interpolation_bit_for_bit(seed):
    # follow() samples the whole trajectory at once (pb_drivers.sampled) rather than calling
    # np.interp once per joint per physics step as it did: the set-points must be those exactly
    from vap_bt.sim.pb_drivers import sampled
    from vap_bt.sim.pybullet_world import DT

    rng = np.random.default_rng(seed)
    for _ in range(50):
        n = int(rng.integers(2, 40))
        times = np.concatenate(([0.0], np.cumsum(rng.uniform(1e-4, 0.3, n - 1))))
        q = np.cumsum(rng.normal(0.0, 0.2, (n, 6)), axis=0)
        qd = rng.normal(0.0, 1.0, (n, 6))
        steps = max(1, math.ceil(times[-1] / DT - 1e-9))
        q_at, qd_at = sampled(times, q, qd, DT, steps)
        assert q_at.shape == qd_at.shape == (steps, 6)
        for k in range(1, steps + 1):
            t = min(k * DT, times[-1])
            want_q = np.array([np.interp(t, times, q[:, j]) for j in range(6)])
            want_qd = np.array([np.interp(t, times, qd[:, j]) for j in range(6)])
            assert q_at[k - 1].tobytes() == want_q.tobytes()
            assert qd_at[k - 1].tobytes() == want_qd.tobytes()
