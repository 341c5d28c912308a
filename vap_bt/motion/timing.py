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


#: rad (joint-space norm): a waypoint this near the one kept before it is the same pose. TOPP-RA
#: finds no parametrization for a path shorter than about 2e-5 rad (a settled arm asked to go
#: where it already is, up to the physics' last micro-radians), and a UR5e's repeatability
#: (±0.03 mm at its 0.85 m reach, about 4e-5 rad) does not tell such poses apart
SAME_POSE = 1e-4


def _dedupe(waypoints: np.ndarray, eps: float = SAME_POSE) -> np.ndarray:
    """Drop waypoints within ``eps`` of the one kept before them (the spline needs a strictly
    growing s); the last waypoint stands in for a kept one it is that near to: the path still
    ends where it was asked to."""
    kept = [waypoints[0]]
    for q in waypoints[1:]:
        if np.linalg.norm(q - kept[-1]) > eps:
            kept.append(q)
    if len(kept) > 1:
        kept[-1] = waypoints[-1]
    return np.array(kept)


def _at_rest(q: np.ndarray) -> Trajectory:
    q = q.reshape(1, -1)
    zero = np.zeros_like(q)
    return Trajectory(np.zeros(1), q, zero, zero)


def _step(a: np.ndarray, b: np.ndarray, dt: float) -> Trajectory:
    """From ``a`` to ``b``, no further apart than :data:`SAME_POSE`, in one sample."""
    q = np.stack([a, b])
    zero = np.zeros_like(q)
    return Trajectory(np.array([0.0, dt]), q, zero, zero)


class _Samples:
    """A toppra trajectory (``ParametrizeConstAccel``) probed at path times ``tau``: its
    positions, velocities and accelerations, exactly as ``timed(tau, order)`` gives them.

    toppra evaluates its time parametrization in a Python loop, one sample at a time, and again
    for every order asked: timing a path probes 4000 samples for velocity and acceleration
    and then the samples it keeps, and the loop was 9 % of a pybullet episode's CPU. Here the
    same arithmetic runs on whole arrays, once per ``tau`` for every order, the same operations
    in the same order, so every number is the one toppra's own call gives (the tests compare
    them bit for bit). One operation differs in kind: toppra squares a numpy scalar, which is
    the C library's ``pow``, where ``array ** 2`` multiplies (``x * x``, one rounding away
    in about one sample of a thousand): ``np.float_power`` calls ``pow`` as the scalar does."""

    def __init__(self, timed, tau: np.ndarray) -> None:
        self.tau = tau
        self._path = timed._path
        # toppra's ParametrizeConstAccel._eval_params, a whole array at a time
        idx = np.searchsorted(timed._ts, tau, side="right") - 1
        idx[idx == len(timed._us)] -= 1  # the last instant lies in the last interval
        dt = tau - timed._ts[idx]
        u, v = timed._us[idx], timed._velocities[idx]
        self.ss = timed._ss[idx] + dt * v + 0.5 * np.float_power(dt, 2) * u
        vs, us = (v + dt * u)[:, np.newaxis], u[:, np.newaxis]
        # toppra's __call__ for orders 1 and 2 (the path's first derivative serves both)
        d1 = self._path(self.ss, 1)
        self.qd = np.multiply(d1, vs)
        self.qdd = np.multiply(self._path(self.ss, 2), vs ** 2) + np.multiply(d1, us)

    def q(self) -> np.ndarray:
        """The positions (order 0)."""
        return self._path(self.ss)


def _slowdown(probe: _Samples, limits: Limits) -> float:
    """Smallest k >= 1 such that q(t / k), probed at the path times of ``probe``, is within the limits."""
    v = np.max(np.abs(probe.qd) / limits.velocity)
    a = np.max(np.abs(probe.qdd) / limits.acceleration)
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
    waypoints = np.asarray(waypoints, dtype=float)
    path_q = _dedupe(waypoints)
    if len(path_q) < 2:
        return _at_rest(path_q[0]) if np.array_equal(waypoints[-1], path_q[0]) else _step(path_q[0], waypoints[-1], dt)
    timed = _parametrize(path_q, limits, gridpoints)
    native = float(timed.duration)
    # Peaks sit at grid points, where acceleration jumps: probe finely, then probe the actual
    # samples of the slowed trajectory and stretch again if one still pokes out (rarely twice).
    k = _slowdown(_Samples(timed, np.linspace(0.0, native, 4000)), limits)
    probe = None
    for _ in range(4):
        probe = _Samples(timed, np.minimum(_sample_times(native, k, dt) / k, native))
        extra = _slowdown(probe, limits) / k  # peak usage of the slowed samples
        if extra <= 1.0:
            break
        k *= extra * (1.0 + 1e-9)
        probe = None  # stretched again: the samples are others
    t = _sample_times(native, k, dt)
    if probe is None:
        probe = _Samples(timed, np.minimum(t / k, native))
    return Trajectory(t, probe.q(), probe.qd / k, probe.qdd / (k * k))


def _parametrize(path_q: np.ndarray, limits: Limits, gridpoints: int | None = None):
    """toppra's fastest traversal of the spline through ``path_q`` (at least two distinct
    waypoints), at its own pace: a ``ParametrizeConstAccel`` trajectory; TimingError if none."""
    import toppra as ta  # on first use: its 2 s (matplotlib with it) are no cost to a run that moves no arm
    import toppra.algorithm as algo
    import toppra.constraint as constraint

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
    return timed
