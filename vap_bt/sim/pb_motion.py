"""Motion in the simulated world: IK targets become timed joint trajectories tracked by the motors.

Every motion of the robot goes the same way: a Cartesian goal (a pose of the ``tcp`` or of the
camera) is turned into joint values by :mod:`vap_bt.motion.ik` — first with the arm alone from
where the base stands, and only if that fails with the base joints too (so the base moves a little
when the arm cannot reach) — then the joint path is timed by toppra (:mod:`vap_bt.motion.timing`)
or, for base moves, by ruckig (:mod:`vap_bt.motion.tracking`), and each sample becomes the motor
set-point of one simulation step. Between steps the world runs its hooks (scripted disturbances,
injected releases, cancellation): a primitive never sees time pass any other way.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from vap_bt.motion.ik import IKOptions, solve_ik
from vap_bt.motion.kinematics import Kinematics, world_to_base
from vap_bt.motion.limits import Limits, arm_limits, base_limits
from vap_bt.motion.timing import TimingError, time_path
from vap_bt.motion.tracking import point_to_point
from vap_bt.motion.trajectory import Trajectory
from vap_bt.sim.pb_robot import Robot


class Cancelled(Exception):
    """The goal was cancelled while its motion ran."""


def _concat(a: Limits, b: Limits) -> Limits:
    return Limits(a.names + b.names, *(np.concatenate((getattr(a, f), getattr(b, f)))
                                       for f in ("lower", "upper", "velocity", "acceleration", "jerk")))


class Motion:
    def __init__(self, robot: Robot, tick: Callable[[], None], dt: float) -> None:
        self.robot, self.tick, self.dt = robot, tick, dt
        self.kin_arm = Kinematics.arm()
        self.kin_mobile = Kinematics.mobile_arm()
        self.limits = _concat(base_limits(), arm_limits())
        self.base_limits = base_limits()
        self.on_sample: Callable[[float], None] | None = None  # progress 0..1 within one motion

    # ------------------------------------------------------------ executing

    def run(self, traj: Trajectory) -> None:
        n = len(traj.t)
        for i in range(n):
            self.robot.command(traj.q[i], traj.qd[i])
            self.tick()
            if self.on_sample:
                self.on_sample((i + 1) / n)
        self.settle(6)

    def settle(self, steps: int) -> None:
        for _ in range(steps):
            self.robot.command(self.robot.target)
            self.tick()

    def through(self, qs: list[np.ndarray], speed: float = 1.0) -> bool:
        """Move through body-joint waypoints (the first is the current set-point)."""
        pts = np.array([self.robot.target, *qs])
        if np.max(np.abs(pts[-1] - pts[0])) < 1e-4 and len(pts) == 2:
            return True
        try:
            traj = time_path(pts, self.limits.scaled(speed), dt=self.dt)
        except TimingError:
            return False
        self.run(traj)
        return True

    def drive(self, pose: tuple[float, float, float], speed: float = 1.0) -> None:
        """Move the base to ``pose`` (x, y, yaw), arm joints held."""
        start = self.robot.target.copy()
        traj = point_to_point(start[:3], np.array(pose), self.base_limits.scaled(speed), dt=self.dt,
                              angular=(False, False, True))
        q = np.repeat(start[None], len(traj.t), axis=0)
        q[:, :3] = traj.q
        qd = np.zeros_like(q)
        qd[:, :3] = traj.qd
        self.run(Trajectory(traj.t, q, qd, np.zeros_like(q)))

    def fingers(self, opening: float, body: int | None = None, link: int | None = None, force: float | None = None) -> int:
        """Move the fingers to ``opening`` at finger speed; when closing on ``body``, stop as soon as
        both pads touch it. Returns the number of pads touching ``body`` at the end."""
        g = self.robot.cfg.gripper
        start = self.robot.opening
        steps = max(2, int(abs(opening - start) / (2 * g.velocity[0]) / self.dt))
        touching = 0
        for i in range(1, steps + 1):
            self.robot.command_fingers(start + (opening - start) * i / steps, force)
            self.robot.command(self.robot.target)
            self.tick()
            if body is not None:
                touching = self.robot.finger_contacts(body, link)
                if touching == 2:
                    break
        for _ in range(4):
            self.tick()
        return self.robot.finger_contacts(body, link) if body is not None else 0

    # ------------------------------------------------------------ inverse kinematics

    def solve(self, target: np.ndarray, frame: str = "tcp", seed: np.ndarray | None = None,
              allow_base: bool = True) -> np.ndarray | None:
        """Body joints putting ``frame`` at ``target`` (world 4x4): arm alone, else arm and base."""
        seed = self.robot.target if seed is None else seed
        local = world_to_base(target, tuple(seed[:3]))
        r = solve_ik(self.kin_arm, local, frame=frame, q_init=seed[3:],
                     options=IKOptions(max_seeds=6, position_tolerance=2e-3, orientation_tolerance=1e-2))
        if r.success:
            q = seed.copy()
            q[3:] = _nearest_turn(r.q, seed[3:], self.kin_arm.lower, self.kin_arm.upper)
            return q
        if not allow_base:
            return None
        r = solve_ik(self.kin_mobile, target, frame=frame, q_init=seed,
                     options=IKOptions(max_seeds=1, max_iterations=200, position_tolerance=2e-3,
                                       orientation_tolerance=1e-2))
        if not r.success:
            return None
        q = r.q.copy()
        q[2:] = _nearest_turn(q[2:], seed[2:], self.kin_mobile.lower[2:], self.kin_mobile.upper[2:])
        return q

    def line(self, target: np.ndarray, frame: str = "tcp", steps: int = 5, speed: float = 0.4,
             allow_base: bool = False) -> bool:
        """Move ``frame`` along a straight line to ``target`` (orientation interpolated)."""
        start = self.pose(frame)
        qs, seed = [], self.robot.target
        for k in range(1, steps + 1):
            T = _interp(start, target, k / steps)
            q = self.solve(T, frame, seed, allow_base)
            if q is None:
                break
            qs.append(q)
            seed = q
        if not qs:
            return False
        self.through(qs, speed)
        return len(qs) == steps

    def pose(self, frame: str = "tcp") -> np.ndarray:
        """Pose of ``frame`` at the commanded set-point (what IK continues from)."""
        q = self.robot.target
        return self.kin_mobile.fk(q, frame)


def _nearest_turn(q: np.ndarray, ref: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Shift revolute values by whole turns towards ``ref`` (within limits): the short way round."""
    shifted = q - 2 * np.pi * np.round((q - ref) / (2 * np.pi))
    ok = (shifted >= lower) & (shifted <= upper)
    return np.where(ok, shifted, q)


def _interp(a: np.ndarray, b: np.ndarray, s: float) -> np.ndarray:
    from scipy.spatial.transform import Rotation, Slerp

    T = np.eye(4)
    T[:3, 3] = (1 - s) * a[:3, 3] + s * b[:3, 3]
    rots = Rotation.from_matrix(np.stack([a[:3, :3], b[:3, :3]]))
    T[:3, :3] = Slerp([0, 1], rots)(s).as_matrix()
    return T
