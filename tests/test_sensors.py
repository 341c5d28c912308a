"""The simulated sensors err as a real robot's do: D435i-like depth and a few centimetres of
localisation error, on the world's side (:mod:`vap_bt.sim.depth_noise`,
:mod:`vap_bt.sim.localization`)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from skill_runs import pybullet

from vap_bt.sim.depth_noise import DepthNoiseModel
from vap_bt.sim.localization import Localization, LocalizationModel

NOISE = DepthNoiseModel()
FX = 307.5  # the simulated 320 x 240 image's focal length


def wall(z: float, h: int = 120, w: int = 160) -> np.ndarray:
    """Depth of a flat wall facing the camera ``z`` away."""
    return np.full((h, w), z, np.float32)


def errors(z: float, frames: int = 12) -> np.ndarray:
    """The depth errors of the valid pixels of ``frames`` pictures of a wall ``z`` away."""
    out = []
    for k in range(frames):
        d = NOISE.apply(wall(z), FX, 5.0, (0, 1000 + k))
        out.append(d[d > 0] - z)
    return np.concatenate(out)


# ------------------------------------------------------------ depth


def test_depth_noise_grows_with_the_square_of_the_range():
    near, far = errors(1.0), errors(2.0)
    s1, s2 = float(near.std()), float(far.std())
    # Intel's formula times the household factor: 9.4 mm at 1 m, 37.7 mm at 2 m
    assert 0.75 * NOISE.sigma(1.0) < s1 < 1.25 * NOISE.sigma(1.0)
    assert 0.75 * NOISE.sigma(2.0) < s2 < 1.25 * NOISE.sigma(2.0)
    assert 3.0 < s2 / s1 < 5.0  # twice as far, four times the error
    assert abs(float(near.mean())) < 0.004 and abs(float(far.mean())) < 0.015  # no bias


def test_depth_noise_comes_in_patches():
    """Stereo noise is spatially correlated: neighbouring pixels err alike, unlike white noise."""
    d = NOISE.apply(wall(2.0), FX, 5.0, (0, 7)).astype(np.float64)
    e = np.where(d > 0, d - 2.0, np.nan)
    a, b = e[:, :-1].ravel(), e[:, 1:].ravel()
    ok = ~np.isnan(a) & ~np.isnan(b)
    assert np.corrcoef(a[ok], b[ok])[0, 1] > 0.5
    far = e[:, :-20].ravel(), e[:, 20:].ravel()  # twenty pixels apart: nearly independent
    ok = ~np.isnan(far[0]) & ~np.isnan(far[1])
    assert abs(np.corrcoef(far[0][ok], far[1][ok])[0, 1]) < 0.3


def test_holes_appear_at_edges_and_in_the_stereo_shadow():
    z = wall(2.0)
    z[40:80, 80:120] = 1.0  # a box 1 m nearer
    holes = np.mean([NOISE.apply(z, FX, 5.0, (0, k)) == 0 for k in range(10)], axis=0)
    # the band the right imager cannot see, left of the box: f·B·(1/1 - 1/2) = 7.7 px wide
    assert holes[45:75, 73:79].mean() > 0.95
    assert holes[45:75, 60:70].mean() < 0.05
    # the box's own outline: about half its pixels have no return
    assert 0.3 < holes[45:75, 119].mean() < 0.8 and 0.3 < holes[80, 85:115].mean() < 0.8
    # elsewhere: the share of pixels with no return at all
    assert holes[90:, :60].mean() < 0.03 and holes[50:70, 90:110].mean() < 0.03


def test_no_depth_outside_the_working_range():
    z = wall(2.0)
    z[:, :40] = 0.12  # the fingers, or what they hold, right in front of the lens
    z[:, 120:] = 5.0  # nothing before the renderer's far plane
    d = NOISE.apply(z, FX, 5.0, (0, 3))
    assert (d[:, :40] == 0).all() and (d[:, 120:] == 0).all()
    valid = d[d > 0]
    assert valid.min() >= NOISE.min_range and 0.16 < NOISE.min_range < 0.18  # Intel: f·B/126 = 0.168 m


def test_the_same_picture_gives_the_same_depth():
    """Keyed by the world's seed and the picture: an unchanged view returns the same pattern."""
    w = pybullet("pick_plate", sensors="real")
    try:
        a, b = w.capture(), w.capture()
        assert np.array_equal(a.rgb, b.rgb) and np.array_equal(a.depth, b.depth)
        assert not np.array_equal(a.depth, w.wrist_view().depth)  # and it is not the rendered one
        other = pybullet("pick_plate", depth_noise=DepthNoiseModel())
        other.reset(1)  # another episode: the same picture, other draws
        if np.array_equal(other.capture().rgb, a.rgb):
            assert not np.array_equal(other.capture().depth, a.depth)
        other.close()
    finally:
        w.close()


# ------------------------------------------------------------ localisation


def test_localisation_error_stays_within_its_bounds():
    m = LocalizationModel()
    loc = Localization(m, seed=3)
    drawn = []
    for k in range(400):
        loc.settle((k * 1.0, 0.0, 0.0))  # a metre further each time: a new error every time
        drawn.append(loc.offset.copy())
    e = np.array(drawn)
    assert loc.draws == 400
    assert np.all(np.abs(e[:, :2]) <= m.max_xy + 1e-12) and np.all(np.abs(e[:, 2]) <= m.max_yaw + 1e-12)
    assert 0.8 * m.sigma_xy < e[:, 0].std() < 1.2 * m.sigma_xy
    assert 0.8 * m.sigma_yaw < e[:, 2].std() < 1.2 * m.sigma_yaw
    assert m.max_xy == pytest.approx(0.125) and math.degrees(m.max_yaw) == pytest.approx(5.0)


def test_localisation_maps_poses_both_ways():
    loc = Localization(LocalizationModel(), seed=1)
    loc.reset((2.0, 1.0, 0.3))
    b = loc.believed((2.0, 1.0, 0.3))
    assert np.allclose(np.subtract(b, (2.0, 1.0, 0.3)), loc.offset)  # the base itself: off by the error
    p = (3.1, -0.4, 1.2)
    assert np.allclose(loc.true(loc.believed(p)), p)
    T = np.eye(4)
    T[:3, 3] = (1.0, 2.0, 0.8)
    assert np.allclose(loc.true_T(loc.believed_T(T)), T) and loc.believed_T(T)[2, 3] == pytest.approx(0.8)


def test_the_robot_reports_and_is_commanded_in_its_believed_frame():
    w = pybullet("collect_cup", sensors="real")
    try:
        d, loc = w.drivers, w.localization
        true0 = w.robot.base_pose
        believed0 = d.base.pose()
        assert 0.0 < math.hypot(believed0[0] - true0[0], believed0[1] - true0[1]) <= loc.model.max_xy * math.sqrt(2)
        assert np.allclose(w.state().base_pose, believed0)
        frame = w.capture()
        assert np.allclose(frame.camera_pose, loc.believed_T(w.robot.link_pose("camera_optical")))
        assert np.allclose(d.arm.tcp_pose(), loc.believed_T(w.robot.link_pose("tcp")))
        # held while the base stands still, and over a short move (the localiser does not update)
        offset = loc.offset.copy()
        w.step()
        assert np.allclose(d.base.pose(), believed0, atol=1e-4) and np.allclose(loc.offset, offset)
        x, y, yaw = believed0
        target = (x + 0.1 * math.cos(yaw), y + 0.1 * math.sin(yaw), yaw)
        assert d.base.follow([target], 0.8, lambda: False).completed
        assert np.allclose(loc.offset, offset) and np.allclose(d.base.pose(), target, atol=0.01)
        # a longer drive lands the true base at the command less the error, then the localiser updates
        target = (x + 0.6 * math.cos(yaw), y + 0.6 * math.sin(yaw), yaw)
        expected = loc.true(target)
        assert d.base.follow([target], 0.8, lambda: False).completed
        assert np.allclose(w.robot.base_pose[:2], expected[:2], atol=0.01)
        assert not np.allclose(loc.offset, offset) and loc.draws == 2
        assert not np.allclose(d.base.pose(), target, atol=0.002)  # the belief moved with the update
    finally:
        w.close()


# ------------------------------------------------------------ which sensors a run has


def test_a_run_has_exact_sensors_unless_it_asks_for_the_real_ones():
    """``RunConfig.sensors`` (``vap-bt run --sensors``) builds the pybullet world with the models
    on or off; every report prints them (``world.depth_noise``, ``world.localization``)."""
    from vap_bt.app.runner import RunConfig, make_world
    from vap_bt.taskfile import load
    from skill_runs import TREES

    task = load(TREES / "collect_cup.yaml")
    for sensors, on in (("exact", False), ("real", True)):
        w = make_world(task, RunConfig.from_task(task, world="pybullet", sensors=sensors, injection=False))
        try:
            assert w.depth_noise.enabled is on and (w.localization_model.sigma_xy > 0) is on
            d = w.drivers.base.pose()
            assert np.allclose(d, w.robot.base_pose) is not on  # the believed pose is the true one only when exact
        finally:
            w.close()


def test_real_sensors_on_a_world_without_them_is_one_clear_error(cli):
    from skill_runs import TREES

    code, _, err = cli("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--sensors", "real")
    assert code == 2 and "--sensors" in err and "Traceback" not in err
