"""IK round-trips on random reachable poses, is deterministic, and rejects colliding solutions."""

from __future__ import annotations

import numpy as np
import pytest

import robots
from vap_bt.motion import se3
from vap_bt.motion.collision import Attached, CollisionChecker, SceneBoxes
from vap_bt.motion.ik import IKOptions, solve_ik
from vap_bt.motion.kinematics import Kinematics, world_to_base

CFG = robots.load_config()


@pytest.fixture(scope="module")
def kin():
    return Kinematics.arm()


@pytest.fixture(scope="module")
def checker(kin):
    return CollisionChecker(kin)


def reachable_targets(kin, checker, n, seed):
    """FK of random collision-free configurations: every target has at least one solution."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        q = kin.random_configuration(rng)
        if not checker.in_collision(q):
            out.append((q, kin.fk(q)))
    return out


def test_home_and_zero_are_collision_free(kin, checker):
    assert not checker.in_collision(np.array(CFG.arm.home))
    assert not checker.in_collision(np.zeros(6))
    assert checker.n_self_pairs > 50


def test_folded_arm_collides_with_itself(kin, checker):
    q = np.array(CFG.arm.home)
    q[2] = np.pi  # elbow fully folded: forearm inside the upper arm
    assert checker.in_collision(q)


def test_a_held_box_collides_with_the_arm_not_with_the_hand_holding_it(kin):
    """What the hand holds rides at the tcp: checked against the arm, not the gripper round it."""
    q = np.array(CFG.arm.home)
    small = CollisionChecker(kin, attached=Attached("tcp", np.eye(4), np.array([0.06, 0.06, 0.08])))  # a cup
    assert not small.in_collision(q)
    # a pole through the hand, as long as the arm: it meets the arm whichever way it points
    long = [CollisionChecker(kin, attached=Attached("tcp", T, np.array([1.6, 0.04, 0.04])))
            for T in (np.eye(4), se3.make_pose(rotation=se3.axis_angle((0.0, 0.0, 1.0), np.pi / 2)))]
    assert any(c.in_collision(q) for c in long)


def test_round_trip_success_rate(kin, checker):
    opt = IKOptions(seed=11)
    targets = reachable_targets(kin, checker, 400, seed=5)
    results = [solve_ik(kin, T, collision=checker, options=opt) for _, T in targets]
    rate = np.mean([r.success for r in results])
    print(f"IK round-trip success {rate:.1%} over {len(targets)} targets")
    assert rate >= 0.995
    for (q_true, T), r in zip(targets, results):
        if r.success:
            pos, rot = se3.pose_error(kin.fk(r.q), T)
            assert pos <= opt.position_tolerance and rot <= opt.orientation_tolerance
            assert np.all(r.q >= kin.lower) and np.all(r.q <= kin.upper)
            assert not checker.in_collision(r.q)


def test_deterministic_given_seed(kin, checker):
    (_, T), = reachable_targets(kin, checker, 1, seed=9)
    a = solve_ik(kin, T, options=IKOptions(seed=3))
    b = solve_ik(kin, T, options=IKOptions(seed=3))
    assert a.success and np.array_equal(a.q, b.q) and a.iterations == b.iterations


def test_initial_guess_near_solution_converges_at_once(kin):
    q = np.array(CFG.arm.home)
    r = solve_ik(kin, kin.fk(q), q_init=q + 0.01)
    assert r.success and r.seeds == 1 and r.iterations <= 5
    assert np.allclose(r.q, q, atol=1e-3)


def test_solution_in_collision_is_rejected(kin, checker):
    target = kin.fk(np.array(CFG.arm.home))
    # A box around the TCP: any configuration reaching the pose has its fingers inside it.
    centre = target[:3, 3]
    box = SceneBoxes.from_aabbs(np.concatenate([centre - 0.05, centre + 0.05])[None], ("block",))
    blocked = checker.with_boxes(box)
    assert blocked.in_collision(np.array(CFG.arm.home))
    r = solve_ik(kin, target, collision=blocked, options=IKOptions(max_seeds=4))
    assert not r.success and r.reason == "collision"
    assert solve_ik(kin, target, collision=checker, options=IKOptions(max_seeds=4)).success


def test_unreachable_target_fails_cleanly(kin):
    far = se3.make_pose((3.0, 0.0, 0.5))
    r = solve_ik(kin, far, options=IKOptions(max_seeds=3))
    assert not r.success and r.reason == "unreachable" and r.position_error > 1.0
    # no closed-form branch: out of reach, and random restarts would not change that
    assert r.seeds == 0
    guess = solve_ik(kin, far, q_init=np.array(CFG.arm.home), options=IKOptions(max_seeds=3))
    assert not guess.success and guess.seeds == 1  # the caller's guess is still polished
    # pure DLS has no branches to go by: it spends its seeds
    assert solve_ik(kin, far, options=IKOptions(max_seeds=3, analytic_seeds=False)).seeds == 3


def test_when_every_branch_is_turned_down_random_seeds_are_not_tried(kin):
    """Every closed-form branch converges and is refused: random seeds would only find them again."""
    from vap_bt.motion import ur_analytic

    q = np.array(CFG.arm.home)
    target = kin.fk(q)
    branches = len(ur_analytic.solve(*_flange_problem(kin, target)))
    r = solve_ik(kin, target, q_init=q, options=IKOptions(max_seeds=20), accept=lambda s: False)
    assert not r.success and r.reason == "collision" and r.seeds == branches + 1 < 20


def _flange_problem(kin, target):
    wab, flange = kin.flange_offsets("tcp")
    return se3.inverse(wab) @ target @ se3.inverse(flange), kin.config.arm.dh


def test_world_target_with_the_base_elsewhere(kin):
    base = (2.0, 1.0, np.pi / 2)
    q = np.array(CFG.arm.home)
    target_world = se3.planar_pose(*base) @ kin.fk(q)
    r = solve_ik(kin, world_to_base(target_world, base), q_init=q)
    assert r.success


def test_mobile_chain_reaches_a_far_target_by_moving_the_base():
    mobile = Kinematics.mobile_arm()
    home = np.concatenate([[0.0, 0.0, 0.0], CFG.arm.home])
    target = se3.planar_pose(3.0, -2.0, 0.8) @ Kinematics.arm().fk(np.array(CFG.arm.home))
    r = solve_ik(mobile, target, q_init=home)
    assert r.success
    assert np.linalg.norm(r.q[:2] - [3.0, -2.0]) < 1.5


def test_closed_form_solutions_are_exact():
    from vap_bt.motion import ur_analytic

    dh = CFG.arm.dh
    rng = np.random.default_rng(4)
    for _ in range(50):
        T = ur_analytic.dh_fk(rng.uniform(-np.pi, np.pi, 6), dh)
        solutions = ur_analytic.solve(T, dh)
        assert 2 <= len(solutions) <= 8
        for q in solutions:
            pos, rot = se3.pose_error(ur_analytic.dh_fk(q, dh), T)
            assert pos < 1e-9 and rot < 1e-9


def test_pure_dls_without_closed_form_seeds(kin, checker):
    opt = IKOptions(seed=2, analytic_seeds=False)
    targets = reachable_targets(kin, checker, 60, seed=8)
    rate = np.mean([solve_ik(kin, T, options=opt).success for _, T in targets])
    print(f"pure DLS success {rate:.1%}")
    assert rate >= 0.98


def test_a_held_box_is_kept_off_the_scene_and_the_arm(kin, checker):
    """What the hand holds rides at the tcp as one more shape: a log held across the hand reaches
    a box beside the fingers that the hand alone misses, and may not pass through the forearm."""
    q = np.array(CFG.arm.home)
    tcp = kin.fk(q)
    log = np.eye(4)
    held = Attached("tcp", log, np.array([0.5, 0.03, 0.03]))  # 0.5 m along the tcp's x, centred on it
    side = tcp[:3, 3] + tcp[:3, 0] * 0.2  # 0.2 m along the log from the tcp
    box = SceneBoxes.from_aabbs(np.concatenate([side - 0.03, side + 0.03])[None], ("post",))
    assert not checker.with_boxes(box).in_collision(q)
    carrying = CollisionChecker(kin, box, attached=held)
    assert carrying.in_collision(q) and ("held_0", "scene:post") in carrying.colliding_pairs(q)
    # a scene box's checker made from a carrying one carries too; with no scene the log alone at
    # home does not touch the arm (its own wrist and hand are allowed round it)
    assert carrying.with_boxes(SceneBoxes.empty()).attached == held
    assert not CollisionChecker(kin, attached=held).in_collision(q)
    through_forearm = Attached("tcp", np.linalg.inv(tcp) @ kin.fk(q, "forearm_link"), np.array([0.05, 0.05, 0.05]))
    assert CollisionChecker(kin, attached=through_forearm).in_collision(q)


def test_a_solution_turned_down_gives_way_to_another_branch(kin, checker):
    q = np.array(CFG.arm.home)
    target = kin.fk(q)
    first = solve_ik(kin, target, q_init=q, collision=checker, options=IKOptions(max_seeds=10))
    assert first.success and np.allclose(first.q, q, atol=1e-3)
    other = solve_ik(kin, target, q_init=q, collision=checker, options=IKOptions(max_seeds=10),
                     accept=lambda s: not np.allclose(s, q, atol=1e-2))
    assert other.success and not np.allclose(other.q, q, atol=1e-2)
    assert np.allclose(kin.fk(other.q)[:3, 3], target[:3, 3], atol=1e-3)
    none = solve_ik(kin, target, q_init=q, options=IKOptions(max_seeds=10), accept=lambda s: False)
    assert not none.success and none.reason == "collision"
