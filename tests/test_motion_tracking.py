"""ruckig: point-to-point and online tracking reach their targets within velocity, acceleration
and jerk limits, for the arm and for the base (with yaw unwrapping)."""

from __future__ import annotations

import numpy as np
import pytest

import robots
from vap_bt.motion.limits import arm_limits, base_limits
from vap_bt.motion.timing import time_path
from vap_bt.motion.tracking import base_tracker, point_to_point, track
from vap_bt.motion.trajectory import limit_usage

ARM, BASE = arm_limits(), base_limits()
TOL = 1e-6


@pytest.mark.parametrize("seed", range(4))
def test_arm_point_to_point(seed):
    rng = np.random.default_rng(seed)
    a, b = rng.uniform(-2, 2, 6), rng.uniform(-2, 2, 6)
    traj = point_to_point(a, b, ARM)
    assert np.allclose(traj.q[-1], b, atol=1e-9) and np.allclose(traj.qd[-1], 0, atol=1e-9)
    assert limit_usage(traj, ARM).within(TOL, check_jerk=True)


def test_point_to_point_from_a_moving_start():
    a, b = np.zeros(6), np.full(6, 0.5)
    v0 = np.full(6, -1.0)
    traj = point_to_point(a, b, ARM, start_velocity=v0)
    assert np.allclose(traj.qd[0], v0) and np.allclose(traj.q[-1], b, atol=1e-9)
    assert limit_usage(traj, ARM).within(TOL, check_jerk=True)


def test_base_turns_the_short_way():
    traj = point_to_point([0.0, 0.0, 3.0], [1.0, -0.5, -3.0], BASE, angular=(False, False, True))
    yaw_end = traj.q[-1, 2]
    assert np.isclose(np.cos(yaw_end), np.cos(-3.0)) and np.isclose(np.sin(yaw_end), np.sin(-3.0))
    assert abs(yaw_end - 3.0) < 0.3  # 0.28 rad across +-pi, not 6 rad back
    assert np.allclose(traj.q[-1, :2], [1.0, -0.5])
    assert limit_usage(traj, BASE).within(TOL, check_jerk=True)


def test_online_base_tracker_follows_a_changing_target():
    tracker = base_tracker(dt=0.01)
    tracker.reset([0.0, 0.0, 0.0])
    states = []
    for k in range(2000):
        target = [1.0, 0.5, 0.0] if k < 100 else [-0.5, 1.0, 1.0]  # the goal moves after 1 s
        states.append(tracker.step(target))
        if k > 100 and tracker.finished:
            break
    q = np.array([s[0] for s in states])
    qd = np.array([s[1] for s in states])
    qdd = np.array([s[2] for s in states])
    assert tracker.finished and np.allclose(q[-1], [-0.5, 1.0, 1.0], atol=1e-9)
    assert np.all(np.abs(qd) <= BASE.velocity + TOL) and np.all(np.abs(qdd) <= BASE.acceleration + TOL)
    assert np.all(np.abs(np.diff(qdd, axis=0)) / 0.01 <= BASE.jerk + TOL)


def test_tracking_a_toppra_reference_is_jerk_limited_and_arrives():
    rng = np.random.default_rng(1)
    waypoints = np.array(robots.load_config().arm.home) + np.cumsum(rng.uniform(-0.3, 0.3, (6, 6)), axis=0)
    reference = time_path(waypoints, ARM)
    executed = track(reference, ARM)
    assert np.allclose(executed.q[-1], waypoints[-1], atol=1e-6)
    assert limit_usage(executed, ARM).within(TOL, check_jerk=True)
    assert executed.duration < reference.duration + 2.0
