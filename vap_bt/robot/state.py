"""Proprioception and localization: what the robot knows about its own body.

A real base publishes its pose from localization against the site map (and the localizer says
which room that pose is in); a UR5e over RTDE reports joint positions and the TCP pose; a
Robotiq-style gripper reports its opening and whether its fingers stopped on an object. The
symbolic world has no poses: it reports the room and the gripper only.
"""

from __future__ import annotations

from dataclasses import dataclass


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
