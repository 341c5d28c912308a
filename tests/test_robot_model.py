"""The shipped robot description: loads offline in pinocchio and pybullet, agrees with its YAML,
and both engines agree on where every frame is."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

import robots
from robots.build_urdf import urdf_text

CFG = robots.load_config()


@pytest.fixture(scope="module")
def pin_model():
    return pin.buildModelFromUrdf(str(robots.urdf_path()))


@pytest.fixture(scope="module")
def bullet():
    p = pytest.importorskip("pybullet")
    cid = p.connect(p.DIRECT)
    body = p.loadURDF(str(robots.urdf_path()), useFixedBase=True, physicsClientId=cid)
    yield p, cid, body
    p.disconnect(cid)


def test_installed_files_and_config():
    assert robots.DEFAULT_ROBOT in robots.available()
    assert robots.urdf_path().is_file() and robots.urdf_path().is_absolute()
    assert CFG.urdf == robots.urdf_path()
    assert CFG.arm.dof == 6 and CFG.base.dof == 3 and CFG.gripper.dof == 2
    assert np.allclose(CFG.arm.velocity, np.pi)
    assert CFG.arm.lower[2] == pytest.approx(-np.pi) and CFG.arm.upper[0] == pytest.approx(2 * np.pi)
    assert 0.5 <= CFG.arm.mount.xyz[2] <= 0.7


def test_shipped_urdf_is_generated_from_yaml():
    assert robots.urdf_path().read_text() == urdf_text(CFG), "run `python -m robots.build_urdf`"


def test_pinocchio_model_has_groups_and_frames(pin_model):
    names = list(pin_model.names[1:])
    assert names == list(CFG.base.joints + CFG.arm.joints + CFG.gripper.joints)
    assert pin_model.nq == pin_model.nv == 11
    for frame in ("world", "base_link", "arm_base_link", "flange", "tcp", "camera_link", "camera_optical"):
        assert pin_model.existFrame(frame), frame
    lo, hi = pin_model.lowerPositionLimit, pin_model.upperPositionLimit
    assert np.allclose(lo[3:9], CFG.arm.lower) and np.allclose(hi[9:], CFG.gripper.upper)
    assert np.allclose(pin_model.velocityLimit[3:9], CFG.arm.velocity)


def _bullet_indices(p, body, cid):
    info = [p.getJointInfo(body, i, physicsClientId=cid) for i in range(p.getNumJoints(body, physicsClientId=cid))]
    joints = {i[1].decode(): i[0] for i in info}
    links = {i[12].decode(): i[0] for i in info}
    return joints, links


def test_pybullet_and_pinocchio_agree_on_frames(pin_model, bullet):
    p, cid, body = bullet
    joints, links = _bullet_indices(p, body, cid)
    data = pin_model.createData()
    rng = np.random.default_rng(3)
    for _ in range(5):
        q = rng.uniform(np.maximum(pin_model.lowerPositionLimit, -3), np.minimum(pin_model.upperPositionLimit, 3))
        for j in range(1, pin_model.njoints):
            p.resetJointState(body, joints[pin_model.names[j]], q[j - 1], physicsClientId=cid)
        pin.framesForwardKinematics(pin_model, data, q)
        for frame in ("tcp", "camera_optical", "left_finger_link"):
            state = p.getLinkState(body, links[frame], computeForwardKinematics=True, physicsClientId=cid)
            M = data.oMf[pin_model.getFrameId(frame)]
            R = np.array(p.getMatrixFromQuaternion(state[5])).reshape(3, 3)
            assert np.allclose(state[4], M.translation, atol=1e-6)
            assert np.allclose(R, M.rotation, atol=1e-6)


def test_tcp_and_camera_geometry(pin_model):
    data = pin_model.createData()
    q = pin.neutral(pin_model)
    q[3:9] = CFG.arm.home
    pin.framesForwardKinematics(pin_model, data, q)
    flange = data.oMf[pin_model.getFrameId("flange")]
    tcp = data.oMf[pin_model.getFrameId("tcp")]
    cam = data.oMf[pin_model.getFrameId("camera_optical")]
    assert np.allclose(flange.actInv(tcp).translation, [0, 0, CFG.gripper.tcp_offset])
    # Camera looks along the approach axis, ahead and down at home, with the image upright.
    assert np.allclose(cam.rotation[:, 2], tcp.rotation[:, 2])
    assert cam.rotation[0, 2] > 0.5 and cam.rotation[2, 2] < -0.5
    assert cam.rotation[2, 1] < 0  # image "down" has a downward world component


def test_camera_intrinsics_and_gripper_helpers():
    cam = CFG.camera
    assert (cam.width, cam.height, cam.fx, cam.near, cam.far) == (640, 480, 615.0, 0.1, 5.0)
    small = cam.for_sim()
    assert small.width == 320 and small.fx == pytest.approx(307.5) and small.cx == pytest.approx(160.0)
    assert small.vertical_fov_deg == pytest.approx(cam.vertical_fov_deg)
    assert CFG.gripper.finger_positions(0.085) == (0.0425, 0.0425)
    assert CFG.gripper.finger_positions(1.0) == (0.0425, 0.0425)
