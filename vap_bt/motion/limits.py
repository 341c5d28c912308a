"""Joint limits as numpy arrays, taken from a robot's YAML configuration.

Every motion routine (IK, toppra timing, ruckig tracking) needs the same five vectors; they are
read once from :mod:`robots` so that no module hard-codes a number.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import robots


@dataclass(frozen=True)
class Limits:
    """Per-joint position range and derivative bounds (symmetric), SI units."""

    names: tuple[str, ...]
    lower: np.ndarray
    upper: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    jerk: np.ndarray

    @property
    def dof(self) -> int:
        return len(self.names)

    @classmethod
    def of(cls, group: robots.JointGroup) -> Limits:
        """The limits of a joint group of a robot's configuration, as arrays."""
        return cls(
            names=group.joints,
            lower=np.array(group.lower),
            upper=np.array(group.upper),
            velocity=np.array(group.velocity),
            acceleration=np.array(group.acceleration),
            jerk=np.array(group.jerk),
        )

    def scaled(self, speed: float = 1.0, accel: float | None = None) -> Limits:
        """Slower limits: velocity x speed, acceleration x accel (default speed), jerk alike."""
        a = speed if accel is None else accel
        return Limits(self.names, self.lower, self.upper, self.velocity * speed, self.acceleration * a, self.jerk * a)


def arm_limits(robot: str = robots.DEFAULT_ROBOT) -> Limits:
    """The arm's joint limits from ``robot``'s YAML configuration."""
    return Limits.of(robots.load_config(robot).arm)


def base_limits(robot: str = robots.DEFAULT_ROBOT) -> Limits:
    """The base's limits on (x, y, yaw) from ``robot``'s YAML configuration."""
    return Limits.of(robots.load_config(robot).base)
