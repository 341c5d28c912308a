"""The UR5e in the URDF is the published UR5e: pinocchio's FK equals an independent DH FK."""

from __future__ import annotations

import numpy as np

import robots
from vap_bt.motion import se3
from vap_bt.motion.kinematics import Kinematics, world_to_base

CFG = robots.load_config()


def dh_fk(q: np.ndarray) -> np.ndarray:
    """Standard DH: T_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i), straight from the table."""
    T = np.eye(4)
    for theta, d, a, alpha in zip(q, CFG.arm.dh.d, CFG.arm.dh.a, CFG.arm.dh.alpha, strict=True):
        ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha)
        T = T @ np.array([[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, d], [0, 0, 0, 1]])
    return T


def test_published_dh_table_is_the_one_configured():
    assert CFG.arm.dh.d == (0.1625, 0.0, 0.0, 0.1333, 0.0997, 0.0996)
    assert CFG.arm.dh.a == (0.0, -0.425, -0.3922, 0.0, 0.0, 0.0)


def test_fk_matches_dh_on_random_configurations():
    kin = Kinematics.arm()
    rng = np.random.default_rng(0)
    worst_pos = worst_rot = 0.0
    for _ in range(200):
        q = rng.uniform(kin.lower, kin.upper)
        frames = kin.fk_all(q)
        flange_in_arm_base = se3.inverse(frames["arm_base_link"]) @ frames["flange"]
        pos, rot = se3.pose_error(flange_in_arm_base, dh_fk(q))
        worst_pos, worst_rot = max(worst_pos, pos), max(worst_rot, rot)
    assert worst_pos <= 1e-6 and worst_rot <= 1e-6


def test_mobile_chain_moves_the_arm_with_the_base():
    arm, mobile = Kinematics.arm(), Kinematics.mobile_arm()
    q = np.array(CFG.arm.home)
    base = (1.5, -0.7, 2.0)
    in_world = mobile.fk(np.concatenate([base, q]))
    assert np.allclose(world_to_base(in_world, base), arm.fk(q), atol=1e-9)


def test_clamp_shifts_full_turn_joints_and_clips_the_rest():
    kin = Kinematics.mobile_arm()
    q = np.zeros(kin.dof)
    q[0] = 80.0  # base x beyond +-50 m: clipped
    q[3] = 7.0  # shoulder pan beyond 2 pi: shifted by a turn
    out = kin.clamp(q)
    assert out[0] == 50.0 and np.isclose(out[3], 7.0 - 2 * np.pi)
