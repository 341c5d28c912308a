"""Jerk-limited motion with ruckig: point-to-point moves and online tracking of a moving target.

Ruckig computes, from the current position/velocity/acceleration, the time-optimal motion to a
target state under velocity, acceleration and jerk bounds. We use it two ways:

* :func:`point_to_point` — one rest-to-rest (or state-to-state) move, computed once and sampled;
  for the arm between two configurations and for the base between two poses (x, y, yaw).
* :class:`OnlineTracker` — one control cycle at a time, towards a target that may change every
  cycle (a person moved the object; a new toppra reference sample). :func:`track` runs it along a
  toppra trajectory so that the executed motion is jerk-limited too (toppra's acceleration jumps
  at grid points; the tracker smooths them at the cost of a short lag).

Angular coordinates (the base yaw) are unwrapped: the target is moved by multiples of 2 pi to
the nearest equivalent of the current angle, so the base never turns the long way round.
Ruckig's intermediate waypoints are *not* used: in the Python package they are computed by a
cloud service, which fails offline. Paths through waypoints go through :mod:`timing` instead.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import ruckig

import robots
from vap_bt.motion.limits import Limits, arm_limits, base_limits
from vap_bt.motion.se3 import wrap_angle
from vap_bt.motion.trajectory import Trajectory


class TrackingError(RuntimeError):
    """Ruckig rejected the input (e.g. a target velocity beyond the limits)."""


def _unwrap(current: np.ndarray, target: np.ndarray, angular: np.ndarray) -> np.ndarray:
    out = np.array(target, dtype=float)
    out[angular] = current[angular] + wrap_angle(out[angular] - current[angular])
    return out


def _input(limits: Limits, position, velocity, acceleration) -> ruckig.InputParameter:
    inp = ruckig.InputParameter(limits.dof)
    inp.current_position = list(map(float, position))
    inp.current_velocity = list(map(float, velocity))
    inp.current_acceleration = list(map(float, acceleration))
    inp.max_velocity = limits.velocity.tolist()
    inp.max_acceleration = limits.acceleration.tolist()
    inp.max_jerk = limits.jerk.tolist()
    return inp


def _set_target(inp: ruckig.InputParameter, position, velocity=None, acceleration=None) -> None:
    n = len(position)
    inp.target_position = list(map(float, position))
    inp.target_velocity = [0.0] * n if velocity is None else list(map(float, velocity))
    inp.target_acceleration = [0.0] * n if acceleration is None else list(map(float, acceleration))


def _angular_mask(limits: Limits, angular: Sequence[bool] | None) -> np.ndarray:
    return np.zeros(limits.dof, bool) if angular is None else np.asarray(angular, bool)


def point_to_point(
    start: np.ndarray,
    goal: np.ndarray,
    limits: Limits,
    *,
    dt: float = 0.01,
    start_velocity: np.ndarray | None = None,
    start_acceleration: np.ndarray | None = None,
    angular: Sequence[bool] | None = None,
) -> Trajectory:
    """Time-optimal jerk-limited move from ``start`` (at rest unless told) to ``goal`` at rest."""
    start = np.asarray(start, dtype=float)
    zero = np.zeros(limits.dof)
    goal = _unwrap(start, np.asarray(goal, dtype=float), _angular_mask(limits, angular))
    inp = _input(
        limits,
        start,
        zero if start_velocity is None else start_velocity,
        zero if start_acceleration is None else start_acceleration,
    )
    _set_target(inp, goal)
    traj = ruckig.Trajectory(limits.dof)
    result = ruckig.Ruckig(limits.dof).calculate(inp, traj)
    if result not in (ruckig.Result.Working, ruckig.Result.Finished):
        raise TrackingError(f"ruckig: {result}")
    duration = traj.duration
    t = np.append(np.arange(0.0, duration, dt), duration)
    samples = [traj.at_time(float(ti)) for ti in t]
    q, qd, qdd = (np.array([s[k] for s in samples]) for k in range(3))
    return Trajectory(t, q, qd, qdd)


class OnlineTracker:
    """Steps a jerk-limited state towards a target, one control cycle of ``dt`` per call."""

    def __init__(self, limits: Limits, dt: float = 0.01, angular: Sequence[bool] | None = None) -> None:
        self.limits = limits
        self.dt = dt
        self.angular = _angular_mask(limits, angular)
        self._otg = ruckig.Ruckig(limits.dof, dt)
        self._out = ruckig.OutputParameter(limits.dof)
        self._inp: ruckig.InputParameter | None = None
        self.finished = True

    def reset(self, position, velocity=None, acceleration=None) -> None:
        """Start again from ``position`` (moving at ``velocity`` and ``acceleration``, zero unless given)
        and hold it there (``finished`` until :meth:`step` is given another target)."""
        zero = np.zeros(self.limits.dof)
        self._inp = _input(
            self.limits,
            position,
            zero if velocity is None else velocity,
            zero if acceleration is None else acceleration,
        )
        _set_target(self._inp, position)
        self.finished = True

    @property
    def state(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Current (position, velocity, acceleration)."""
        if self._inp is None:
            raise RuntimeError("call reset() first")
        return (
            np.array(self._inp.current_position),
            np.array(self._inp.current_velocity),
            np.array(self._inp.current_acceleration),
        )

    def step(self, target_position, target_velocity=None, target_acceleration=None):
        """Advance one cycle towards the (possibly new) target; returns the new state."""
        if self._inp is None:
            raise RuntimeError("call reset() first")
        current = np.array(self._inp.current_position)
        goal = _unwrap(current, np.asarray(target_position, dtype=float), self.angular)
        _set_target(self._inp, goal, target_velocity, target_acceleration)
        result = self._otg.update(self._inp, self._out)
        if result not in (ruckig.Result.Working, ruckig.Result.Finished):
            raise TrackingError(f"ruckig: {result}")
        self._out.pass_to_input(self._inp)
        self.finished = result == ruckig.Result.Finished
        return self.state


def track(reference: Trajectory, limits: Limits, *, lookahead: float = 0.05, max_overrun: float = 5.0) -> Trajectory:
    """Execute ``reference`` through an :class:`OnlineTracker` stepping at the reference's own
    period; the target each cycle is the reference state ``lookahead`` s ahead (the tracker's
    lag), and the run ends once the tracker rests at the final point."""
    dt = float(reference.t[1] - reference.t[0]) if len(reference.t) > 1 else 0.01
    tracker = OnlineTracker(limits, dt)
    tracker.reset(reference.q[0], reference.qd[0], np.clip(reference.qdd[0], -limits.acceleration, limits.acceleration))
    rows = [tracker.state]
    end = reference.duration
    n_max = int((end + max_overrun) / dt)
    for k in range(1, n_max + 1):
        ahead = min(k * dt + lookahead, end)
        i = int(np.searchsorted(reference.t, ahead))
        i = min(i, len(reference.t) - 1)
        # Target velocity must itself be reachable: the reference respects the same velocity limits.
        rows.append(tracker.step(reference.q[i], reference.qd[i]))
        if k * dt >= end and tracker.finished:
            break
    q, qd, qdd = (np.array([r[j] for r in rows]) for j in range(3))
    return Trajectory(np.arange(len(rows)) * dt, q, qd, qdd)


def arm_tracker(dt: float = 0.01, robot: str = robots.DEFAULT_ROBOT) -> OnlineTracker:
    """An :class:`OnlineTracker` under ``robot``'s arm limits, stepped every ``dt`` seconds."""
    return OnlineTracker(arm_limits(robot), dt)


def base_tracker(dt: float = 0.01, robot: str = robots.DEFAULT_ROBOT) -> OnlineTracker:
    """Base (x, y, yaw): yaw is angular, so targets are unwrapped to the nearest turn."""
    return OnlineTracker(base_limits(robot), dt, angular=(False, False, True))
