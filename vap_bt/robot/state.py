"""Proprioception and localization: what the robot knows about its own body.

A real base publishes its pose from localization against the site map (and the localizer says
which room that pose is in); a UR5e over RTDE reports joint positions and the TCP pose; a
Robotiq-style gripper reports its opening and whether its fingers stopped on an object. The
symbolic world has no poses: it reports the room and the gripper only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class RobotState:
    """The robot's own state at one instant."""

    stamp: float
    room: str | None  # the localizer's room for the base pose
    base_pose: tuple[float, float, float] | None = None  # x, y, yaw in the map frame
    joints: tuple[float, ...] = ()  # arm joint positions, rad
    tcp_pose: tuple[float, ...] | None = None  # x, y, z, qx, qy, qz, qw in the map frame
    gripper_width: float | None = None  # metres between the fingers
    #: the fingers closed on something and stopped before closing fully (object detected)
    gripper_holding: bool | None = None


def quat_xyzw(R) -> tuple[float, float, float, float]:
    """Unit quaternion (x, y, z, w) of a rotation matrix (for poses in messages and views)."""
    R = np.asarray(R, dtype=float)
    w = np.sqrt(max(0.0, 1.0 + R[0, 0] + R[1, 1] + R[2, 2])) / 2
    x = np.sqrt(max(0.0, 1.0 + R[0, 0] - R[1, 1] - R[2, 2])) / 2
    y = np.sqrt(max(0.0, 1.0 - R[0, 0] + R[1, 1] - R[2, 2])) / 2
    z = np.sqrt(max(0.0, 1.0 - R[0, 0] - R[1, 1] + R[2, 2])) / 2
    x = np.copysign(x, R[2, 1] - R[1, 2])
    y = np.copysign(y, R[0, 2] - R[2, 0])
    z = np.copysign(z, R[1, 0] - R[0, 1])
    return (float(x), float(y), float(z), float(w))
