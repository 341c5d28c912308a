"""Rigid transforms as plain 4x4 numpy arrays.

Motion code passes poses across module boundaries as homogeneous matrices (``T[:3, :3]`` rotation,
``T[:3, 3]`` translation) so that callers need neither pinocchio nor pybullet types. These helpers
build them and measure how far apart two of them are.
"""

from __future__ import annotations

import math

import numpy as np


def rpy_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """Rotation for URDF roll-pitch-yaw (fixed axes x, then y, then z)."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def make_pose(position=(0.0, 0.0, 0.0), rotation: np.ndarray | None = None) -> np.ndarray:
    """A 4x4 transform from a translation and a 3x3 rotation (None: identity)."""
    T = np.eye(4)
    if rotation is not None:
        T[:3, :3] = rotation
    T[:3, 3] = position
    return T


def approach_pose(z, x, position) -> np.ndarray:
    """A tool pose approaching along ``z``, its x axis the part of ``x`` across ``z`` (for a
    parallel gripper the fingers then close along the y axis, ``z`` x ``x``), at ``position``."""
    z = np.asarray(z, float) / np.linalg.norm(z)
    x = np.asarray(x, float) - np.dot(x, z) * z
    x /= np.linalg.norm(x)
    return make_pose(position, np.column_stack([x, np.cross(z, x), z]))


def planar_pose(x: float, y: float, yaw: float) -> np.ndarray:
    """Pose of a mobile base on the floor: the frame of its virtual x, y, yaw joints."""
    return make_pose((x, y, 0.0), rpy_matrix(0.0, 0.0, yaw))


def inverse(T: np.ndarray) -> np.ndarray:
    """The inverse of the rigid transform ``T`` (transpose the rotation: cheaper and exact, unlike a
    general matrix inverse)."""
    R, p = T[:3, :3], T[:3, 3]
    out = np.eye(4)
    out[:3, :3] = R.T
    out[:3, 3] = -R.T @ p
    return out


def rotation_angle(R: np.ndarray) -> float:
    """Angle of a rotation matrix, robust near 0 and pi."""
    c = (np.trace(R) - 1.0) / 2.0
    s = np.linalg.norm([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / 2.0
    return float(math.atan2(s, c))


def pose_error(a: np.ndarray, b: np.ndarray) -> tuple[float, float]:
    """(position distance in m, rotation angle in rad) between two poses."""
    return float(np.linalg.norm(a[:3, 3] - b[:3, 3])), rotation_angle(a[:3, :3].T @ b[:3, :3])


def wrap_angle(a):
    """Angle(s) mapped to [-pi, pi)."""
    return (np.asarray(a) + np.pi) % (2.0 * np.pi) - np.pi


def interpolate(a: np.ndarray, b: np.ndarray, s: float) -> np.ndarray:
    """The pose a share ``s`` of the way from ``a`` to ``b``: position linear, rotation slerped."""
    from scipy.spatial.transform import Rotation, Slerp

    T = np.eye(4)
    T[:3, 3] = (1 - s) * a[:3, 3] + s * b[:3, 3]
    rots = Rotation.from_matrix(np.stack([a[:3, :3], b[:3, :3]]))
    T[:3, :3] = Slerp([0, 1], rots)(s).as_matrix()
    return T


def frame_zx(z, x, p) -> np.ndarray:
    """The pose at ``p`` whose z axis is ``z`` and whose x axis is ``x`` made orthogonal to it (a
    hand approaching along z with its fingers closing across y)."""
    z = np.asarray(z, float) / np.linalg.norm(z)
    x = np.asarray(x, float) - np.dot(x, z) * z
    x /= np.linalg.norm(x)
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2], T[:3, 3] = x, np.cross(z, x), z, p
    return T


def axis_angle(axis, angle: float) -> np.ndarray:
    """Rotation matrix about a unit axis (Rodrigues)."""
    axis = np.asarray(axis, float)
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * (k @ k)


def look_pose(eye, target) -> np.ndarray:
    """Camera optical-frame pose at ``eye`` looking at ``target`` (z forward, x right, y down),
    the image upright."""
    z = np.asarray(target, float) - np.asarray(eye, float)
    z /= np.linalg.norm(z)
    x = np.cross(z, (0.0, 0.0, 1.0))
    if np.linalg.norm(x) < 1e-6:  # looking straight down: any right vector
        x = np.array([1.0, 0.0, 0.0])
    x /= np.linalg.norm(x)
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2], T[:3, 3] = x, np.cross(z, x), z, eye
    return T
