"""Time-optimal timing of a joint path through waypoints, with toppra.

The waypoints are joined by a cubic spline in a path parameter ``s`` that grows with the
distance between successive waypoints (so that long and short segments are traversed at
comparable path speeds and the spline does not overshoot on short ones). TOPP-RA then finds the
fastest traversal of that fixed geometric path under per-joint velocity and acceleration bounds,
starting and ending at rest.

TOPP-RA enforces the bounds at its grid points only; between them the constant-acceleration
parametrization overshoots them by a few per cent (the path's curvature changes within a grid
interval). Rather than guess a safety factor, we measure the peaks on a fine grid and slow the
whole trajectory down uniformly by the factor that brings them back (velocity scales with 1/k,
acceleration with 1/k^2), so every sample respects the true limits — the tests check this.
"""

from __future__ import annotations

import logging

import numpy as np
import toppra as ta
import toppra.algorithm as algo
import toppra.constraint as constraint

from vap_bt.motion.limits import Limits
from vap_bt.motion.trajectory import Trajectory

# A path toppra cannot time is an answer, not an alarm: time_path raises TimingError and the
# caller plans another way. toppra's own warnings for it would flood every run's log.
logging.getLogger("toppra").setLevel(logging.ERROR)


class TimingError(RuntimeError):
    """toppra found no feasible parametrization (e.g. the path leaves the joint limits)."""


def _path_parameter(waypoints: np.ndarray) -> np.ndarray:
    """Cumulative chord length, normalised to [0, 1]."""
    steps = np.linalg.norm(np.diff(waypoints, axis=0), axis=1)
    s = np.concatenate(([0.0], np.cumsum(steps)))
    return s / s[-1]


def _dedupe(waypoints: np.ndarray, eps: float = 1e-9) -> np.ndarray:
    """Drop waypoints equal to their predecessor: the spline needs a strictly growing s."""
    keep = np.concatenate(([True], np.linalg.norm(np.diff(waypoints, axis=0), axis=1) > eps))
    return waypoints[keep]


def _at_rest(q: np.ndarray) -> Trajectory:
    q = q.reshape(1, -1)
    zero = np.zeros_like(q)
    return Trajectory(np.zeros(1), q, zero, zero)


def _slowdown(timed, tau: np.ndarray, limits: Limits) -> float:
    """Smallest k >= 1 such that q(t / k), probed at path times ``tau``, is within the limits."""
    v = np.max(np.abs(timed(tau, 1)) / limits.velocity)
    a = np.max(np.abs(timed(tau, 2)) / limits.acceleration)
    return max(1.0, float(v), float(np.sqrt(a)))


def _sample_times(native: float, k: float, dt: float) -> np.ndarray:
    return np.append(np.arange(0.0, native * k, dt), native * k)


def time_path(
    waypoints: np.ndarray,
    limits: Limits,
    *,
    dt: float = 0.01,
    gridpoints: int | None = None,
) -> Trajectory:
    """Fastest rest-to-rest trajectory through ``waypoints`` (K, dof), sampled every ``dt`` s."""
    path_q = _dedupe(np.asarray(waypoints, dtype=float))
    if len(path_q) < 2:
        return _at_rest(path_q[0])
    path = ta.SplineInterpolator(_path_parameter(path_q), path_q)
    v, a = limits.velocity, limits.acceleration
    constraints = [
        constraint.JointVelocityConstraint(np.stack([-v, v], axis=1)),
        constraint.JointAccelerationConstraint(np.stack([-a, a], axis=1)),
    ]
    n_grid = gridpoints or max(100, 10 * len(path_q))
    grid = np.linspace(0.0, 1.0, n_grid)
    instance = algo.TOPPRA(constraints, path, gridpoints=grid, parametrizer="ParametrizeConstAccel")
    timed = instance.compute_trajectory(0.0, 0.0)
    if timed is None:
        raise TimingError("toppra: no feasible time parametrization")
    native = float(timed.duration)
    # Peaks sit at grid points, where acceleration jumps: probe finely, then probe the actual
    # samples of the slowed trajectory and stretch again if one still pokes out (rarely twice).
    k = _slowdown(timed, np.linspace(0.0, native, 4000), limits)
    for _ in range(4):
        tau = np.minimum(_sample_times(native, k, dt) / k, native)
        extra = _slowdown(timed, tau, limits) / k  # peak usage of the slowed samples
        if extra <= 1.0:
            break
        k *= extra * (1.0 + 1e-9)
    t = _sample_times(native, k, dt)
    tau = np.minimum(t / k, native)
    return Trajectory(t, timed(tau), timed(tau, 1) / k, timed(tau, 2) / (k * k))
