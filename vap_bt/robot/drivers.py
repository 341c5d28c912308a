"""The drivers of a mobile manipulator: arm, gripper, base and wrist camera, as a robot offers them.

These are the interfaces skills move the robot through (``skills/``): nothing above them knows
whether a simulator or a real robot answers. Each call that moves the robot blocks until the
motion ends — completed, stopped by ``cancelled()`` turning true (checked every control cycle),
or refused — and says which, the way a real driver's action server does. How a real robot maps
onto them:

* **arm** — a UR5e over RTDE: ``joint_state`` is ``actual_q``/``actual_qd``;
  ``follow(trajectory)`` streams the samples with ``servoJ`` at 500 Hz (or uploads a URScript
  ``movej`` path), polling ``cancelled`` between samples and ending with ``stopJ`` when it turns
  true; ``stop`` is ``stopJ``. The TCP pose comes from ``actual_TCP_pose``.
* **gripper** — a Robotiq 2F-85 over its Modbus registers: ``move(width, force)`` writes the
  position and force requests and polls ``gOBJ`` (object detected while opening/closing) and
  the reached position; ``holding`` is ``gOBJ`` = 2 (stopped on an object while closing).
* **base** — a differential or holonomic base's driver (ROS ``nav_msgs/Path`` following, or
  velocity commands on ``cmd_vel`` with localization feedback): ``follow(path)`` drives through
  the poses, ``pose`` is localization's, ``stop`` zeroes the command.
* **camera** — a wrist RGB-D camera (RealSense D435) with an instance-segmentation model:
  ``capture`` is one aligned colour + depth frame with the detector's masks, in the map frame
  through the arm's forward kinematics and the base's localization.

Everything here is plain data, so that the interfaces can be served over Zenoh
(:mod:`vap_bt.transport`) to skill servers in other processes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Protocol

import numpy as np

from vap_bt.outcome import Outcome
from vap_bt.robot.frame import Frame

Cancelled = Callable[[], bool]


@dataclass(frozen=True)
class JointTrajectory:
    """Joint positions (and velocities) at sample times from 0, for the named joints."""

    joints: tuple[str, ...]
    times: np.ndarray  # (N,) seconds, times[0] == 0
    positions: np.ndarray  # (N, dof)
    velocities: np.ndarray | None = None  # (N, dof)

    @property
    def duration(self) -> float:
        """Seconds from the first sample to the last."""
        return float(self.times[-1])


@dataclass(frozen=True)
class JointState:
    """Measured joint positions and velocities."""

    joints: tuple[str, ...]
    positions: tuple[float, ...]
    velocities: tuple[float, ...] = ()


@dataclass(frozen=True)
class GripperState:
    """The fingers' opening (m) and whether they stopped on something while closing."""

    width: float
    holding: bool


class Arm(Protocol):
    """A joint-space arm controller."""

    def joint_state(self) -> JointState:
        """The measured joint positions (rad) and velocities (rad/s)."""

    def tcp_pose(self) -> np.ndarray:
        """The tool centre point's pose in the map frame (4x4)."""

    def follow(self, trajectory: JointTrajectory, cancelled: Cancelled) -> Outcome:
        """Track ``trajectory`` from the current joint positions; blocks until it is done, stopped by
        ``cancelled()`` or refused, and says which."""

    def stop(self) -> None:
        """Stop the arm's motion where it is now (a UR's ``stopJ``)."""


class Gripper(Protocol):
    """A parallel gripper with object detection."""

    def state(self) -> GripperState: ...

    def move(self, width: float, force: float, cancelled: Cancelled) -> GripperState:
        """Open or close to ``width`` with at most ``force`` newtons; stops early on an object."""


class Base(Protocol):
    """A mobile base that follows a path of poses in the map frame."""

    def pose(self) -> tuple[float, float, float]:
        """Where the localiser puts the base in the map (x, y, yaw): good to a few centimetres,
        and it jumps when the localiser updates."""

    def odometry(self) -> tuple[float, float, float]:
        """Where the wheels say the base is (x, y, yaw) in a frame fixed where it started: it
        never jumps and is exact over a short way (odometry drifts over a long one), so the
        motion between two readings is what the base did."""

    def follow(self, path: list[tuple[float, float, float]], speed: float, cancelled: Cancelled) -> Outcome:
        """Drive through ``path`` (x, y, yaw) at ``speed`` (share of the base's limits)."""

    def stop(self) -> None:
        """Stop the base where it is now (zero velocity command)."""


class WristCamera(Protocol):
    """The wrist RGB-D camera with its instance detector: one frame of what it sees now."""

    def capture(self) -> Frame:
        """One aligned colour + depth frame with the detector's masks, in the map frame; it moves
        nothing."""


#: the driver interfaces motion skills move a robot through (attributes of its ``drivers``)
REQUIRED = ("arm", "gripper", "base", "camera")


def has_drivers(robot: object) -> bool:
    """Whether ``robot`` offers the driver interfaces motion skills move it through (its
    ``drivers``: arm, gripper, base and wrist camera)."""
    drivers = getattr(robot, "drivers", None)
    return drivers is not None and all(getattr(drivers, name, None) is not None for name in REQUIRED)
