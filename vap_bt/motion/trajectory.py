"""A joint trajectory sampled at fixed times, and how close it comes to a set of limits.

Both timing (toppra) and tracking (ruckig) hand their result over in this one form, so that the
world, a real controller, the tests and the benchmark read every motion the same way.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from vap_bt.motion.limits import Limits


@dataclass(frozen=True)
class Trajectory:
    """``t`` (N,), ``q``, ``qd``, ``qdd`` (N, dof); ``t[0] == 0``, ``t[-1]`` is the duration."""

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray

    @property
    def duration(self) -> float:
        """Seconds from the first sample to the last."""
        return float(self.t[-1])

    @property
    def dof(self) -> int:
        return self.q.shape[1]

    def jerk(self) -> np.ndarray:
        """Finite-difference jerk (N-1, dof); an estimate, exact only for piecewise-linear qdd."""
        return np.diff(self.qdd, axis=0) / np.diff(self.t)[:, None]

    def position_at(self, time: float) -> np.ndarray:
        """Joint values at any time, linearly interpolated between samples (clamped to the ends)."""
        return np.array([np.interp(time, self.t, self.q[:, j]) for j in range(self.dof)])


@dataclass(frozen=True)
class LimitUsage:
    """Peak |value| / limit over the trajectory, per quantity (1.0 = exactly at the limit)."""

    velocity: float
    acceleration: float
    jerk: float
    position: float  # > 0 means outside [lower, upper] by that much (m or rad); <= 0 inside

    def within(self, tolerance: float = 1e-6, check_jerk: bool = False) -> bool:
        """Whether velocity and acceleration (and jerk, if ``check_jerk``) stay within their limits and
        the positions within their range, up to ``tolerance``."""
        ok = self.velocity <= 1 + tolerance and self.acceleration <= 1 + tolerance and self.position <= tolerance
        return ok and (not check_jerk or self.jerk <= 1 + tolerance)


def limit_usage(traj: Trajectory, limits: Limits) -> LimitUsage:
    """How close ``traj`` comes to ``limits``: per quantity, the peak over every joint and sample of
    |value| / limit."""
    jerk = traj.jerk()
    return LimitUsage(
        velocity=float(np.max(np.abs(traj.qd) / limits.velocity)),
        acceleration=float(np.max(np.abs(traj.qdd) / limits.acceleration)),
        jerk=float(np.max(np.abs(jerk) / limits.jerk)) if len(jerk) else 0.0,
        position=float(max(np.max(limits.lower - traj.q), np.max(traj.q - limits.upper))),
    )
