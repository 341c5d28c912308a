"""toppra timing: rest to rest, through the waypoints, within the UR5e limits at every sample."""

from __future__ import annotations

import numpy as np
import pytest

from vap_bt.motion.limits import arm_limits
from vap_bt.motion.timing import time_path
from vap_bt.motion.trajectory import limit_usage

LIMITS = arm_limits()


def random_path(rng, n=10, step=0.4):
    """A random walk kept inside the joint limits (the elbow has only +-pi)."""
    walk = np.array([0.0, -1.5, 1.5, -1.5, -1.5, 0.0]) + np.cumsum(rng.uniform(-step, step, (n, 6)), axis=0)
    return np.clip(walk, LIMITS.lower + 0.3, LIMITS.upper - 0.3)


@pytest.mark.parametrize("seed", range(6))
def test_limits_hold_at_every_sample(seed):
    rng = np.random.default_rng(seed)
    waypoints = random_path(rng)
    traj = time_path(waypoints, LIMITS, dt=0.005)
    usage = limit_usage(traj, LIMITS)
    assert usage.within(1e-9)
    # Time-optimal: some joint actually works at a limit.
    assert max(usage.velocity, usage.acceleration) > 0.9
    assert np.allclose(traj.q[0], waypoints[0]) and np.allclose(traj.q[-1], waypoints[-1])
    assert np.allclose(traj.qd[[0, -1]], 0.0, atol=1e-6)
    # The path passes through every waypoint (to within one sample's travel).
    reach = np.max(LIMITS.velocity) * 0.005
    for w in waypoints:
        assert np.min(np.linalg.norm(traj.q - w, axis=1)) <= reach * np.sqrt(6)


def test_straight_move_duration_matches_bang_bang():
    # One joint, 1 rad: accelerate at 3 rad/s^2 to the midpoint: t = 2 sqrt(d/a) (never hits pi rad/s).
    a, b = np.zeros(6), np.zeros(6)
    b[0] = 1.0
    traj = time_path(np.array([a, b]), LIMITS)
    assert traj.duration == pytest.approx(2 * np.sqrt(1.0 / 3.0), rel=0.03)


def test_degenerate_paths():
    q = np.ones(6)
    assert time_path(np.array([q, q]), LIMITS).duration == 0.0
    traj = time_path(np.array([q, q, q + 0.1]), LIMITS)
    assert np.allclose(traj.q[-1], q + 0.1)


@pytest.mark.parametrize("length", [1e-7, 1e-5, 5e-5, 3e-4])
def test_a_move_too_short_for_toppra_still_ends_where_asked(length):
    # a settled arm asked for the pose it holds, up to the physics' last micro-radians: toppra
    # finds no parametrization below about 2e-5 rad (the injection test's press did, once)
    a = np.array([-0.475106, -1.235834, 2.497252, -4.403009, -1.095675, 1.570796])
    b = a + length * np.array([0.6, -0.8, 0.0, 0.0, 0.0, 0.0])
    traj = time_path(np.array([a, b]), LIMITS.scaled(0.5), dt=0.01)
    assert np.allclose(traj.q[0], a, atol=1e-12) and np.allclose(traj.q[-1], b, atol=1e-12)
    assert limit_usage(traj, LIMITS).within(1e-9)


@pytest.mark.parametrize("seed", range(4))
def test_samples_are_toppras_own_bit_for_bit(seed):
    # time_path probes toppra's trajectory a whole array at a time (timing._Samples) instead of
    # through toppra's per-sample loop: every number must be the one toppra's call gives, or an
    # episode's motions (and everything after them) would change
    from vap_bt.motion.timing import _Samples, _parametrize, _sample_times

    rng = np.random.default_rng(seed)
    timed = _parametrize(random_path(rng, n=4 + seed), LIMITS.scaled(0.8))
    native = float(timed.duration)
    for tau in (np.linspace(0.0, native, 4000), np.minimum(_sample_times(native, 1.01, 1 / 60) / 1.01, native)):
        probe = _Samples(timed, tau)
        for ours, order in ((probe.q(), 0), (probe.qd, 1), (probe.qdd, 2)):
            assert np.array_equal(ours, timed(tau, order)), f"order {order} differs"
