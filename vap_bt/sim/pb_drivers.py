"""The robot's drivers in pybullet: arm, gripper, base and wrist camera, as a real robot offers them.

These implement :mod:`vap_bt.robot.drivers` on the simulated mobile UR5e. They decide nothing
about how to move — skills plan (with :mod:`vap_bt.motion`) and command — and they read nothing
a real driver could not measure: joint encoders, the fingers' opening and whether they stopped on
something, the base's localization, the camera's frame. Every call that moves the robot steps the
physics one step at a time (:meth:`PybulletWorld.step`, which also evaluates the physics rules
and Table II injection), checks ``cancelled()`` and ``stop()`` before every step and ends with a
:class:`Outcome` saying why it ended:

* :class:`PybulletArm` — ``follow`` tracks a timed trajectory of the six arm joints: each
  physics step the set-point is the trajectory linearly interpolated at that step's time (with
  its velocity as feed-forward), as a UR controller's ``servoJ`` stream; refused when the joints
  are not the arm's, the times do not grow, a sample leaves the joint limits, or the first sample
  is more than ``START_TOLERANCE`` from where the arm is; ended ``blocked`` when the measured
  joints fall ``TRACKING_LIMIT`` behind the set-point (the arm pushes against something), the
  way a UR stops on a protective stop.
* :class:`PybulletGripper` — ``move`` sweeps the fingers at their speed; closing, it stops as
  soon as both pads touch one graspable thing and holds it with the given force: an item is tied
  to the hand by a fixed constraint (:meth:`Robot.attach`), a door's or drawer's handle bar
  (both pads on the leaf's link with the tcp within ``BAR_REACH`` of the bar) by a ball joint at
  the tcp, so that the bar may turn in the hand and the arm drags the leaf along its arc against
  the joint's friction; released, the friction keeps the leaf where it was pulled. Opening lets
  an item go once the fingers are ``ITEM_RELEASE`` wider than they held it (or fully open), a handle once they
  are ``HANDLE_CAPTURE`` apart (a loosely closed hand still traps the bar). ``holding`` is a grip
  in force — on an item or a handle. A cancelled ``move`` returns the state where the fingers
  stopped (the protocol's ``move`` answers with the gripper's state, not a Outcome).
* :class:`PybulletBase` — ``follow`` drives through the poses one after the other, each leg a
  time-optimal jerk-limited rest-to-rest move (ruckig) at ``speed`` of the base's limits (a base
  controller's own profile, not a plan); ends ``blocked`` when the base falls ``BASE_TRACKING_LIMIT`` behind.
  Through free space, while nothing else moves, a set-point is set rather than driven to
  (:mod:`~vap_bt.sim.pb_glide`: the base glides, a held item with the hand); wherever the robot
  would come near anything, the step is the physics' as above, so contact and blocking are too.

Poses in the map frame — the base's ``pose()``, a path to follow, the tcp's pose, the base's
joints in a whole-body trajectory — are in the frame the robot believes it is in
(:mod:`~vap_bt.sim.localization`): reported through the localiser's error, and commanded through
it, so a path lands the true base at the commanded pose less the error. When a motion of the base
ends, the localiser may update (a new error once the base has moved far enough).
* :class:`PybulletWristCamera` — ``capture`` is the frame of what the wrist camera sees now:
  the detector model's class-labelled detections and masks (:mod:`vap_bt.sim.detector`), metric depth,
  intrinsics, the camera pose, and the capture record the simulated VLM answers from
  (:meth:`PybulletWorld.capture` without an aim).

All four take the world (:class:`Simulation`) and look its robot and scene up on every call, so
they stay valid across :meth:`PybulletWorld.reset`; each call holds the world's lock, so a camera
query from another thread waits for the step in progress, and ``stop`` (lock-free) ends a motion
running on another thread at its next step.
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass
from collections.abc import Callable, Iterator
from typing import Protocol

import numpy as np

from vap_bt.motion.limits import base_limits
from vap_bt.motion.tracking import point_to_point
from vap_bt.robot.drivers import Cancelled, GripperState, JointState, JointTrajectory
from vap_bt.outcome import Outcome
from vap_bt.robot.frame import Frame
from vap_bt.sim.localization import Localization
from vap_bt.sim.pb import pb
from vap_bt.sim.pb_injection import Injection
from vap_bt.sim.pb_robot import Robot
from vap_bt.sim.pb_scene import Hinge, Scene, Thing

#: rad between the arm's position and a trajectory's first sample that a driver still accepts
#: (encoder noise and the motors' static error are hundredths; more is a plan from a stale state)
START_TOLERANCE = 0.05
#: rad of any joint between set-point and measurement at which the arm stops as blocked (tracking
#: a feasible trajectory stays within a few hundredths)
TRACKING_LIMIT = 0.3
#: m between the base's set-point and its position at which it stops as blocked
BASE_TRACKING_LIMIT = 0.15
#: physics steps a motion holds its last set-point after the last sample, to come to rest
SETTLE_STEPS = 6
#: the gripper's force range (N per finger; the motors' effort caps it from above)
MIN_FORCE = 5.0
#: m the fingers press on past where they stopped on an object (a gentle squeeze, no sinking in)
SQUEEZE = 0.004
#: m the fingers open past the width they held an item at before it falls out
ITEM_RELEASE = 0.006
#: m short of the stroke at which the fingers count as fully open (an item held near the stroke
#: cannot be opened on by ITEM_RELEASE, yet fully open fingers hold nothing)
FULLY_OPEN = 0.002
#: m of opening above which a handle bar (0.024 m thick, 0.034 m across its diagonal) can slip out
HANDLE_CAPTURE = 0.06
#: m from the tcp to a handle bar's axis for two pads on a leaf to be a hand on its handle
BAR_REACH = 0.03


class Simulation(Protocol):
    """What the drivers need of the world (:class:`~vap_bt.sim.pybullet_world.PybulletWorld`)."""

    lock: threading.RLock
    robot: Robot
    scene: Scene
    injection: Injection
    localization: Localization
    dt: float

    def step(self) -> None:
        """One physics step, with the rules and the injection evaluated after it."""

    def glide(self, body: np.ndarray, vel: np.ndarray) -> bool:
        """One step with the base set at its set-point instead, if the physics would do no more
        (:mod:`~vap_bt.sim.pb_glide`); False, and nothing done, when the step is the physics'."""

    def capture(self, aim=None) -> Frame:
        """A wrist-camera frame of the world now, with its capture record
        (:meth:`PybulletWorld.capture`)."""


def _hold(robot: Robot, arm: bool = True, base: bool = True) -> None:
    """Set-points to where the joints are now: a stop, not a return to the last set-point."""
    target = robot.target.copy()
    q = robot.q()
    if base:
        target[:3] = q[:3]
    if arm:
        target[3:] = q[3:]
    robot.command(target)


def sampled(times: np.ndarray, q: np.ndarray, qd: np.ndarray, dt: float,
            steps: int) -> tuple[np.ndarray, np.ndarray]:
    """A timed trajectory's positions and velocities (rows ``steps``, one column a joint) linearly
    interpolated at the times of physics steps 1..``steps`` (``k * dt``, the last time at most).
    One ``np.interp`` per joint over all the steps' times, rather than one per joint per step: it
    interpolates each time alone with the same arithmetic, so the set-points are the same to the
    bit (tests/test_pb_drivers.py holds it), in a tenth of the time of an arm motion's Python."""
    t = np.minimum(np.arange(1, steps + 1) * dt, times[-1])
    q_at = np.stack([np.interp(t, times, q[:, j]) for j in range(q.shape[1])], axis=1)
    qd_at = np.stack([np.interp(t, times, qd[:, j]) for j in range(qd.shape[1])], axis=1)
    return q_at, qd_at


class _Stoppable:
    def __init__(self, sim: Simulation) -> None:
        self.sim = sim
        self._stop = threading.Event()

    def _halted(self, cancelled: Cancelled) -> str | None:
        if cancelled():
            return "cancelled"
        if self._stop.is_set():
            return "stopped"
        return None

    def _track(self, setpoints: Iterator[tuple[np.ndarray, np.ndarray]], cancelled: Cancelled,
               lag: Callable[[np.ndarray], float], limit: float, blocked: str, glide: bool = False) -> Outcome:
        """Command each (body joints, velocities) set-point for one physics step, then settle;
        halts (holding where the joints are) on cancel, stop, or a lag beyond ``limit``. With
        ``glide`` a set-point the physics would only track is set instead (:meth:`Simulation.glide`)."""
        r = self.sim.robot
        for body, vel in setpoints:
            if (why := self._halted(cancelled)) is not None:
                self._hold_now()
                return Outcome(False, why)
            # a set base is where its set-point is: only a driven one can fall behind
            if not self._step_to(body, vel, glide) and (off := lag(body)) > limit:
                self._hold_now()
                return Outcome(False, f"blocked: {blocked.format(off)}")
        for _ in range(SETTLE_STEPS):
            if (why := self._halted(cancelled)) is not None:
                self._hold_now()
                return Outcome(False, why)
            self._step_to(r.target, np.zeros(len(r.target)), glide)
        return Outcome(True)

    def _step_to(self, body: np.ndarray, vel: np.ndarray, glide: bool) -> bool:
        """One step towards the set-point: set there (gliding: True), or by the motors and the physics."""
        if glide and self.sim.glide(body, vel):
            return True
        self.sim.robot.command(body, vel)
        self.sim.step()
        return False

    def stop(self) -> None:
        """End the motion in progress at its next step; idle, hold where the joints are."""
        self._stop.set()
        if self.sim.lock.acquire(blocking=False):
            try:
                self._hold_now()
            finally:
                self.sim.lock.release()

    def _hold_now(self) -> None: ...


class PybulletArm(_Stoppable):
    """The UR5e's joint-space controller."""

    def __init__(self, sim: Simulation) -> None:
        super().__init__(sim)
        cfg = sim.robot.cfg
        self.joints: tuple[str, ...] = tuple(cfg.arm.joints)
        #: a whole-body trajectory (following a door's handle) names the base's joints too
        self.body_joints: tuple[str, ...] = tuple(cfg.base.joints) + self.joints
        self.lower, self.upper = np.array(cfg.arm.lower), np.array(cfg.arm.upper)
        self.body_lower = np.concatenate((cfg.base.lower, cfg.arm.lower))
        self.body_upper = np.concatenate((cfg.base.upper, cfg.arm.upper))

    def joint_state(self) -> JointState:
        with self.sim.lock:
            r = self.sim.robot
            states = pb.getJointStates(r.id, r.body_joints[3:], physicsClientId=r.cid)
            return JointState(self.joints, tuple(float(s[0]) for s in states), tuple(float(s[1]) for s in states))

    def tcp_pose(self) -> np.ndarray:
        with self.sim.lock:
            return self.sim.localization.believed_T(self.sim.robot.link_pose("tcp"))

    def _hold_now(self) -> None:
        _hold(self.sim.robot, base=False)

    def follow(self, trajectory: JointTrajectory, cancelled: Cancelled) -> Outcome:
        with self.sim.lock:
            r = self.sim.robot
            checked = self._check(trajectory, r.q()[3:])
            if isinstance(checked, str):
                return Outcome(False, f"refused: {checked}")
            times, q, qd = checked
            first = len(r.target) - q.shape[1]  # 3: the arm alone; 0: base and arm together
            if first == 0:  # the base's joints are commanded in the believed map frame
                q, qd = self._true_base(q, qd)
            self._stop.clear()
            dt = self.sim.dt
            steps = max(1, math.ceil(times[-1] / dt - 1e-9))
            q_at, qd_at = sampled(times, q, qd, dt, steps)

            def setpoints():
                for k in range(steps):
                    body, vel = r.target.copy(), np.zeros(len(r.target))
                    body[first:], vel[first:] = q_at[k], qd_at[k]
                    yield body, vel

            out = self._track(setpoints(), cancelled, lambda body: float(np.max(np.abs(r.q()[3:] - body[3:]))),
                              TRACKING_LIMIT, "the arm is {:.2f} rad behind its set-point")
            if first == 0:
                self.sim.localization.settle(r.base_pose)
            return out

    def _true_base(self, q: np.ndarray, qd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A whole-body trajectory's base columns (believed frame) as the true base follows them."""
        loc = self.sim.localization
        q, qd = q.copy(), qd.copy()
        q[:, :3] = [loc.true(row) for row in q[:, :3]]
        c, s = math.cos(loc.offset[2]), math.sin(loc.offset[2])
        qd[:, :2] = qd[:, :2] @ np.array([[c, -s], [s, c]])  # velocities turned back by the heading error
        return q, qd

    def _check(self, tr: JointTrajectory, here: np.ndarray):
        """(times, positions, velocities) in the arm's joint order, or why the trajectory is refused."""
        whole = sorted(tr.joints) == sorted(self.body_joints)
        if sorted(tr.joints) != sorted(self.joints) and not whole:
            return (f"the trajectory moves {list(tr.joints)}, the arm's joints are {list(self.joints)} "
                    f"(with the base's: {list(self.body_joints)})")
        names, lower, upper = (self.body_joints, self.body_lower, self.body_upper) if whole else \
            (self.joints, self.lower, self.upper)
        if whole:  # where the robot believes its base is
            here = self.sim.robot.q()
            here[:3] = self.sim.localization.believed(here[:3])
        order = [tr.joints.index(j) for j in names]
        times = np.asarray(tr.times, float)
        q = np.asarray(tr.positions, float)
        if times.ndim != 1 or q.ndim != 2 or q.shape[0] != len(times) or len(times) == 0:
            return f"times {times.shape} and positions {q.shape} do not match"
        if abs(times[0]) > 1e-9 or np.any(np.diff(times) <= 0) or not np.all(np.isfinite(q)):
            return "times must start at 0 and grow, positions must be finite"
        if q.shape[1] != len(names):
            return f"positions have {q.shape[1]} columns for {len(names)} joints"
        q = q[:, order]
        if np.any(q < lower - 1e-9) or np.any(q > upper + 1e-9):
            return "a sample leaves the joint limits"
        off = float(np.max(np.abs(q[0] - here)))
        if off > START_TOLERANCE:
            return f"the trajectory starts {off:.3f} rad from the arm's position"
        if tr.velocities is not None:
            qd = np.asarray(tr.velocities, float)[:, order]
        elif len(times) > 1:
            qd = np.gradient(q, times, axis=0)
        else:
            qd = np.zeros_like(q)
        if len(times) == 1:  # a single sample: hold it for one step
            times, q, qd = np.array([0.0, self.sim.dt]), np.repeat(q, 2, axis=0), np.zeros((2, q.shape[1]))
        return times, q, qd


class PybulletGripper:
    """The parallel gripper with object detection (a Robotiq 2F-85's behaviour)."""

    def __init__(self, sim: Simulation) -> None:
        self.sim = sim
        self.requested: float | None = None  # the width last asked for

    def state(self) -> GripperState:
        with self.sim.lock:
            r = self.sim.robot
            return GripperState(float(np.sum(r.finger_q())), r.grip is not None)

    def lost_grip(self) -> None:
        """The object slipped out: the fingers go on to the width they were asked for."""
        r = self.sim.robot
        r.command_fingers(r.opening if self.requested is None else self.requested, r.grip_force)

    def move(self, width: float, force: float, cancelled: Cancelled) -> GripperState:
        with self.sim.lock:
            r, sim = self.sim.robot, self.sim
            g = r.cfg.gripper
            target = float(min(max(width, 0.0), g.stroke))
            r.grip_force = float(min(max(force, MIN_FORCE), g.effort[0]))
            self.requested = target
            now = float(np.sum(r.finger_q()))
            opening = target > now
            start = r.opening
            steps = max(2, math.ceil(abs(target - start) / (2 * g.velocity[0]) / sim.dt))
            stuck = opening and sim.injection.gripper_stuck()
            if stuck:
                start = target = r.opening  # the fingers do not move; the time passes
            # fingers that do not open let nothing go (the pads jitter on a held item: the width
            # measured may wander past the release margin without the fingers having moved)
            opening = opening and not stuck
            for i in range(1, steps + 1):
                if cancelled():
                    return self.state()
                r.command_fingers(start + (target - start) * i / steps, r.grip_force)
                r.command(r.target)
                sim.step()
                if opening:
                    self._release_if_open(now)
                elif r.grip is None and self._close_on(self._caught()):
                    break
            for _ in range(SETTLE_STEPS):
                if cancelled():
                    break
                r.command(r.target)
                sim.step()
                if opening:
                    self._release_if_open(now)
            return self.state()

    # ------------------------------------------------------------ grip

    def _close_on(self, caught: tuple[Thing, int, int] | None) -> bool:
        """Both pads are on ``caught`` (thing, body, link): grip it, or slip off it if injection
        says so. Returns whether the fingers stop here."""
        if caught is None:
            return False
        r, inj = self.sim.robot, self.sim.injection
        thing, body, link = caught
        if link == -1 and inj.refuses_grip():
            inj.slip(body=body)  # the fingers close on through it, on nothing
            return False
        grip = r.attach(body, thing.name, link, point=link != -1)
        r.command_fingers(max(0.0, float(np.sum(r.finger_q())) - SQUEEZE), r.grip_force)
        inj.on_grip(grip, thing)
        return True

    def _caught(self) -> tuple[Thing, int, int] | None:
        """A graspable thing both finger pads touch: an item, or a leaf's link at its handle bar."""
        r, scene = self.sim.robot, self.sim.scene
        touched = [{(p[2], p[4]) for p in pb.getContactPoints(r.id, linkIndexA=j, physicsClientId=r.cid)}
                   for j in r.finger_joints]
        owner = scene.by_body()
        for body, link in sorted(touched[0] & touched[1]):
            t = scene.things.get(owner.get(body, ""))
            if t is None:
                continue
            if t.item is not None and link == -1:
                return t, body, -1
            if t.hinge is not None and link == t.hinge.joint and self._on_bar(t.hinge):
                return t, body, link
        return None

    def _on_bar(self, h: Hinge) -> bool:
        r = self.sim.robot
        tcp = r.link_pose("tcp")[:3, 3]
        q = pb.getJointState(h.body, h.joint, physicsClientId=r.cid)[0]
        for side in ((1.0, -1.0) if h.other_side is not None else (1.0,)):
            p, _, bar = h.handle_at(q, side)
            v = tcp - p
            along = float(np.clip(v @ bar, -h.bar_half, h.bar_half))
            if np.linalg.norm(v - along * bar) <= BAR_REACH:
                return True
        return False

    def _release_if_open(self, held_at: float) -> None:
        r = self.sim.robot
        if r.grip is None:
            return
        # the opening commanded counts too: pybullet's finger pads can sink into a held item's
        # shape while the base drives (its constraint and the pad contacts fight), and the measured
        # width then lags an opening that on a real gripper would already have let go
        width = max(float(np.sum(r.finger_q())), r.opening)
        # fingers open as wide as they go have let go of whatever they held near their stroke
        loose = min(held_at + ITEM_RELEASE, r.cfg.gripper.stroke - FULLY_OPEN)
        if (r.grip.link == -1 and width > loose) or (r.grip.link != -1 and width > HANDLE_CAPTURE):
            r.detach()


class PybulletBase(_Stoppable):
    """The mobile base's path follower (holonomic: x, y, yaw)."""

    def pose(self) -> tuple[float, float, float]:
        """The localiser's pose of the base (the believed map frame)."""
        with self.sim.lock:
            return self.sim.localization.believed(self.sim.robot.base_pose)

    def odometry(self) -> tuple[float, float, float]:
        """The wheels' pose of the base: its motion since the episode began, in a frame fixed at
        where it began (drift-free: a simulated base's wheels do not slip)."""
        with self.sim.lock:
            return self.sim.localization.odometry(self.sim.robot.base_pose)

    def _hold_now(self) -> None:
        _hold(self.sim.robot, arm=False)

    def follow(self, path: list[tuple[float, float, float]], speed: float, cancelled: Cancelled) -> Outcome:
        with self.sim.lock:
            r, sim = self.sim.robot, self.sim
            poses = [tuple(map(float, p)) for p in path]
            if any(len(p) != 3 or not all(map(math.isfinite, p)) for p in poses):
                return Outcome(False, "refused: a path is a list of finite (x, y, yaw) poses")
            if not 0.0 < speed <= 1.0:
                return Outcome(False, f"refused: speed {speed} is not a share of the limits in (0, 1]")
            self._stop.clear()
            limits = base_limits().scaled(speed)
            legs, here = [], r.target[:3].copy()
            # the controller drives until the localiser says it is there
            for p in (sim.localization.true(p) for p in poses):
                leg = point_to_point(here, np.array(p), limits, dt=sim.dt, angular=(False, False, True))
                legs.append(leg)
                here = leg.q[-1]
            hops = np.concatenate([np.linalg.norm(np.diff(leg.q[:, :2], axis=0), axis=1) for leg in legs])
            length = float(hops.sum())
            sim.injection.base_path_started(length)

            def setpoints():
                share = iter((np.cumsum(hops) / length).tolist() if length > 0 else [1.0] * len(hops))
                for leg in legs:
                    for i in range(1, len(leg.t)):
                        body, vel = r.target.copy(), np.zeros(len(r.target))
                        body[:3], vel[:3] = leg.q[i], leg.qd[i]
                        yield body, vel  # resumed after the step: the base has come this far
                        sim.injection.base_progress(next(share), length)

            out = self._track(setpoints(), cancelled, lambda body: float(np.linalg.norm(r.q()[:2] - body[:2])),
                              BASE_TRACKING_LIMIT, "the base is {:.2f} m behind its set-point", glide=True)
            sim.localization.settle(r.base_pose)  # at rest: the localiser may update
            return out


class PybulletWristCamera:
    """The wrist RGB-D camera and its instance detector."""

    def __init__(self, sim: Simulation) -> None:
        self.sim = sim

    def capture(self) -> Frame:
        return self.sim.capture(None)


@dataclass(frozen=True)
class Drivers:
    """The four drivers of one simulated robot."""

    arm: PybulletArm
    gripper: PybulletGripper
    base: PybulletBase
    camera: PybulletWristCamera

    @classmethod
    def of(cls, sim: Simulation) -> Drivers:
        """The four drivers over one simulation."""
        return cls(PybulletArm(sim), PybulletGripper(sim), PybulletBase(sim), PybulletWristCamera(sim))
