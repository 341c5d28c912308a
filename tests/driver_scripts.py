"""Scripted motions for the driver tests: small explicit moves, through the drivers only.

A test says where the hand goes (a tcp pose in the map frame) or where the base stands; these
helpers turn that into joint trajectories with :mod:`vap_bt.motion` — IK of the arm from the base
pose the base driver reports, toppra timing under the arm's limits — and hand them to the arm
driver, the way a skill does. They plan nothing clever (no collision checks, no search): each test
stages its scene so that straight moves are clear. They read the world's truth only to know where
to put the hand, never to move anything.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation, Slerp

from vap_bt.motion.ik import IKOptions, solve_ik
from vap_bt.motion.kinematics import Kinematics, world_to_base
from vap_bt.motion.limits import arm_limits
from vap_bt.motion.se3 import approach_pose as frame  # noqa: F401  (the tests' name for it)
from vap_bt.motion.timing import time_path
from vap_bt.robot.drivers import JointTrajectory
from vap_bt.outcome import Outcome

ARM = Kinematics.arm()
LIMITS = arm_limits()
IK = IKOptions(max_seeds=8, position_tolerance=1e-3, orientation_tolerance=5e-3)
OPEN, CLOSED = 0.085, 0.0


def never() -> bool:
    return False


def ik(d, T: np.ndarray, seed: np.ndarray | None = None) -> np.ndarray:
    """Arm joints putting the tcp at ``T`` from where the base stands (nearest turn to ``seed``)."""
    q0 = np.array(d.arm.joint_state().positions) if seed is None else seed
    r = solve_ik(ARM, world_to_base(T, d.base.pose()), q_init=q0, options=IK)
    assert r.success, f"no arm pose reaches {T[:3, 3].round(3)}"
    q = r.q - 2 * np.pi * np.round((r.q - q0) / (2 * np.pi))
    return np.where((q >= ARM.lower) & (q <= ARM.upper), q, r.q)


def trajectory(d, qs: list[np.ndarray], speed: float) -> JointTrajectory:
    here = np.array(d.arm.joint_state().positions)
    timed = time_path(np.array([here, *qs]), LIMITS.scaled(speed), dt=0.01)
    return JointTrajectory(d.arm.joints, timed.t, timed.q, timed.qd)


def through(d, qs: list[np.ndarray], speed: float = 0.5, cancelled: Callable[[], bool] = never) -> Outcome:
    return d.arm.follow(trajectory(d, qs, speed), cancelled)


def reach(d, T: np.ndarray, speed: float = 0.5) -> Outcome:
    """A joint-space move to the tcp pose ``T``."""
    return through(d, [ik(d, T)], speed)


def line(d, T: np.ndarray, steps: int = 6, speed: float = 0.3) -> Outcome:
    """The tcp along a straight line to ``T`` (orientation slerped)."""
    A = d.arm.tcp_pose()
    slerp = Slerp([0, 1], Rotation.from_matrix(np.stack([A[:3, :3], T[:3, :3]])))
    qs, seed = [], np.array(d.arm.joint_state().positions)
    for k in range(1, steps + 1):
        s = k / steps
        P = np.eye(4)
        P[:3, :3], P[:3, 3] = slerp(s).as_matrix(), (1 - s) * A[:3, 3] + s * T[:3, 3]
        seed = ik(d, P, seed)
        qs.append(seed)
    return through(d, qs, speed)


def moved(T: np.ndarray, dp) -> np.ndarray:
    out = T.copy()
    out[:3, 3] += dp
    return out


def hold(d, seconds: float) -> Outcome:
    """Keep the arm still for ``seconds`` (time passes only while something moves)."""
    q = np.array(d.arm.joint_state().positions)
    return d.arm.follow(JointTrajectory(d.arm.joints, np.array([0.0, seconds]), np.array([q, q])), never)


def drive(d, *poses, speed: float = 0.8) -> Outcome:
    return d.base.follow([tuple(map(float, p)) for p in poses], speed, never)


def face(x: float, y: float, toward_y: float) -> tuple[float, float, float]:
    """A base pose at (x, y) facing along +y or -y towards ``toward_y``."""
    return (x, y, math.pi / 2 if toward_y > y else -math.pi / 2)


def in_base(d, fwd: float, left: float, z: float) -> np.ndarray:
    """A point given in the base frame (forward, left, up), in the map frame."""
    x, y, yaw = d.base.pose()
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([x + c * fwd - s * left, y + s * fwd + c * left, z])


def carry(d, T: np.ndarray | None = None) -> Outcome:
    """The held item beside the base, over the floor (hand orientation kept)."""
    T = d.arm.tcp_pose() if T is None else T
    return line(d, moved(T, in_base(d, 0.35, 0.42, 0.95) - T[:3, 3]), steps=8)


def rotation(axis, angle: float) -> np.ndarray:
    return Rotation.from_rotvec(np.asarray(axis, float) / np.linalg.norm(axis) * angle).as_matrix()


def handle_pose(art, q: float, grasp: np.ndarray) -> np.ndarray:
    """The tcp holding the handle of the leaf ``art`` (the map's Articulation) at joint value
    ``q``, turned with the leaf from ``grasp`` (its pose at q = 0)."""
    T = grasp.copy()
    if art.prismatic:
        T[:3, 3] += np.asarray(art.axis) * q
        return T
    R = rotation(art.axis, q)
    T[:3, :3] = R @ grasp[:3, :3]
    T[:3, 3] = np.asarray(art.origin) + R @ (grasp[:3, 3] - np.asarray(art.origin))
    return T


def arc_joints(d, art, grasp: np.ndarray, values) -> list[np.ndarray] | None:
    """Arm joints along the handle's path from where the base stands, or None where it leaves
    the arm's reach (or a joint would jump)."""
    qs, seed = [], np.array(d.arm.joint_state().positions)
    for q in values:
        r = solve_ik(ARM, world_to_base(handle_pose(art, q, grasp), d.base.pose()), q_init=seed, options=IK)
        if not r.success:
            return None
        sol = r.q - 2 * np.pi * np.round((r.q - seed) / (2 * np.pi))
        if np.max(np.abs(sol - seed)) > 0.5 and qs:
            return None
        qs.append(sol)
        seed = sol
    return qs


def kitchen(furniture: dict[str, str], items: dict[str, str] | None = None) -> str:
    """The ``scene:`` of a task file: one kitchen with the robot in it, ``furniture`` and ``items``
    given as their task-file fields (``{"counter": "type: surface"}``)."""
    lines = ["  rooms: [kitchen]", "  robot: {room: kitchen}", "  furniture:"]
    lines += [f"    {name}: {{{spec}, room: kitchen}}" for name, spec in furniture.items()]
    if items:
        lines += ["  items:", *(f"    {name}: {{{spec}}}" for name, spec in items.items())]
    return "\n".join(lines) + "\n"


def world_of(tmp_path, name: str, scene: str, situations=None, **kw):
    """A pybullet world for a task file with ``scene`` (YAML under ``scene:``) and a trivial goal.

    Its base is perfectly localised: the scripts put the hand where the truth says a thing is, in
    the true frame, to test the drivers' physics (a robot's localisation error is the skills' to
    cope with, and their tests keep it)."""
    from vap_bt.sim.localization import LocalizationModel
    from vap_bt.sim.pybullet_world import PybulletWorld
    from vap_bt.taskfile import load

    kw.setdefault("localization", LocalizationModel.perfect())

    domain = (Path(__file__).resolve().parents[1] / "domains" / "household.pddl").as_posix()
    path = tmp_path / f"{name}.yaml"
    path.write_text(f"name: {name}\ndomain: {domain}\ngoal: [\"hand_empty\"]\nscene:\n{scene}")
    return PybulletWorld(load(path), seed=0, injection=situations is not None, situations=situations,
                         image_size=(160, 120), **kw)


def stand_before(d, point, normal, distance: float, side=(0.0, 0.0, 0.0)) -> Outcome:
    """Drive (sideways along the room's middle, then straight in) to stand ``distance`` in front
    of ``point`` along ``normal`` (horizontal), shifted by ``side``, facing it."""
    n = np.array([normal[0], normal[1], 0.0]) / np.hypot(normal[0], normal[1])
    p = np.asarray(point, float) + n * distance + np.asarray(side, float)
    yaw = math.atan2(-n[1], -n[0])
    x, y, _ = d.base.pose()
    return drive(d, (p[0], y, yaw), (p[0], p[1], yaw))
