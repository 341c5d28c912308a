"""The mobile manipulator inside pybullet: joints, links, motors, fingers, grasp constraints.

The robot is loaded from ``robots/`` with a fixed root; the base moves through its x, y, yaw
joints like every other joint — by position motors that track commanded set-points each
simulation step, never by teleporting. The ``body`` joint vector is the one
:meth:`vap_bt.motion.kinematics.Kinematics.mobile_arm` uses: base x, y, yaw, then the six arm
joints. The fingers are commanded separately as an opening width.

A grasp is a fixed constraint between the ``tcp`` link and the object, created only after the
fingers have closed on it (contact); an opened hand removes it. Holding is that constraint.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import robots
from vap_bt.sim.pb import pb


@dataclass
class Grip:
    """A constraint tying the hand to a body (a held item, or a door handle being pulled)."""

    constraint: int
    body: int
    link: int
    name: str


class Robot:
    """The robot's body in a pybullet client: joint and link indices by name, its position motors'
    set-points (``target``, ``opening``), and the grasp it holds (``grip``)."""

    def __init__(self, cid: int, name: str = robots.DEFAULT_ROBOT) -> None:
        self.cid = cid
        self.cfg = robots.load_config(name)
        self.id = pb.loadURDF(str(robots.urdf_path(name)), useFixedBase=True, physicsClientId=cid)
        self.joint: dict[str, int] = {}
        self.link: dict[str, int] = {}
        for i in range(pb.getNumJoints(self.id, physicsClientId=cid)):
            info = pb.getJointInfo(self.id, i, physicsClientId=cid)
            self.joint[info[1].decode()] = i
            self.link[info[12].decode()] = i
        self.body_joints = [self.joint[j] for j in self.cfg.base.joints + self.cfg.arm.joints]
        self.finger_joints = [self.joint[j] for j in self.cfg.gripper.joints]
        self.forces = list(self.cfg.base.effort + self.cfg.arm.effort)
        self.grip: Grip | None = None
        self.target = self.q()
        self._unsent = False  # set-points not yet sent to the motors (:meth:`set_target`)
        self.opening = self.cfg.gripper.stroke
        #: the fingers' force set by the gripper driver (None: the motors' full effort)
        self.grip_force: float | None = None

    # ------------------------------------------------------------ state

    def q(self) -> np.ndarray:
        """Measured body joints (base x, y, yaw, six arm joints)."""
        return np.array([s[0] for s in pb.getJointStates(self.id, self.body_joints, physicsClientId=self.cid)])

    @property
    def base_pose(self) -> tuple[float, float, float]:
        """The base joints now (x, y, yaw): the true pose, which only the simulation may read."""
        x, y, yaw = self.q()[:3]
        return float(x), float(y), float(yaw)

    def finger_q(self) -> np.ndarray:
        """The finger joints now (m)."""
        return np.array([s[0] for s in pb.getJointStates(self.id, self.finger_joints, physicsClientId=self.cid)])

    def link_pose(self, link: str) -> np.ndarray:
        """The URDF link ``link``'s pose in the world (4x4), from forward kinematics."""
        s = pb.getLinkState(self.id, self.link[link], computeForwardKinematics=True, physicsClientId=self.cid)
        T = np.eye(4)
        T[:3, :3] = np.array(pb.getMatrixFromQuaternion(s[5])).reshape(3, 3)
        T[:3, 3] = s[4]
        return T

    def reset(self, body_q, opening: float | None = None) -> None:
        """Place the joints (only when a world is (re)built, before any motion)."""
        for j, v in zip(self.body_joints, body_q):
            pb.resetJointState(self.id, j, float(v), physicsClientId=self.cid)
        self.opening = self.cfg.gripper.stroke if opening is None else opening
        for j, v in zip(self.finger_joints, self.cfg.gripper.finger_positions(self.opening)):
            pb.resetJointState(self.id, j, v, physicsClientId=self.cid)
        self.target = np.array(body_q, float)
        self.command(self.target)

    # ------------------------------------------------------------ motors

    def command(self, q, qd=None) -> None:
        """Position set-points (with velocity feed-forward) for the body joints and the fingers."""
        self.target = np.asarray(q, float)
        self._unsent = False
        qd = np.zeros(len(q)) if qd is None else qd
        pb.setJointMotorControlArray(self.id, self.body_joints, pb.POSITION_CONTROL, targetPositions=list(q),
                                     targetVelocities=list(qd), forces=self.forces,
                                     positionGains=[0.6] * len(q), velocityGains=[1.0] * len(q),
                                     physicsClientId=self.cid)
        self.command_fingers(self.opening, self.grip_force)

    def set_target(self, q) -> None:
        """The body's set-points are ``q``, where the joints were just set (a kinematic base,
        :mod:`pb_glide`): the motors are told only before the physics steps again (:meth:`sync`)."""
        self.target = np.asarray(q, float)
        self._unsent = True

    def sync(self) -> None:
        """Tell the motors the set-points :meth:`set_target` left unsent (to hold, at rest)."""
        if self._unsent:
            self.command(self.target)

    def command_fingers(self, opening: float, force: float | None = None) -> None:
        """Set the fingers' motors towards ``opening`` (m between the pads) with at most ``force`` N
        (None: their full effort); they move as the simulation steps."""
        self.opening = opening
        f = force if force is not None else self.cfg.gripper.effort[0]
        pb.setJointMotorControlArray(self.id, self.finger_joints, pb.POSITION_CONTROL,
                                     targetPositions=list(self.cfg.gripper.finger_positions(opening)),
                                     forces=[f, f], positionGains=[0.3, 0.3], physicsClientId=self.cid)

    # ------------------------------------------------------------ contact and grip

    def finger_contacts(self, body: int, link: int | None = None) -> int:
        """How many of the two finger pads touch ``body`` (optionally one of its links)."""
        n = 0
        for j in self.finger_joints:
            pts = pb.getContactPoints(self.id, body, linkIndexA=j, physicsClientId=self.cid)
            if link is not None:
                pts = [p for p in pts if p[4] == link]
            n += bool(pts)
        return n

    def attach(self, body: int, name: str, link: int = -1, point: bool = False) -> Grip:
        """Tie ``body`` to the tcp where it is now (fixed, or a ball joint for a handle)."""
        tcp = self.link_pose("tcp")
        if link == -1:
            pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=self.cid)
        else:
            s = pb.getLinkState(body, link, physicsClientId=self.cid)
            pos, orn = s[4], s[5]
        inv_p, inv_o = pb.invertTransform(tuple(tcp[:3, 3]), _quat(tcp[:3, :3]))
        rel_p, rel_o = pb.multiplyTransforms(inv_p, inv_o, pos, orn)
        if point:  # pivot at the tcp, expressed in both frames
            inv_pos, inv_orn = pb.invertTransform(pos, orn)
            child_p, _ = pb.multiplyTransforms(inv_pos, inv_orn, tuple(tcp[:3, 3]), (0, 0, 0, 1))
            c = pb.createConstraint(self.id, self.link["tcp"], body, link, pb.JOINT_POINT2POINT, (0, 0, 0),
                                    (0, 0, 0), child_p, physicsClientId=self.cid)
        else:
            c = pb.createConstraint(self.id, self.link["tcp"], body, link, pb.JOINT_FIXED, (0, 0, 0), rel_p,
                                    (0, 0, 0), parentFrameOrientation=rel_o, physicsClientId=self.cid)
        pb.changeConstraint(c, maxForce=1000.0 if point else 400.0, physicsClientId=self.cid)
        self.grip = Grip(c, body, link, name)
        return self.grip

    def detach(self) -> Grip | None:
        """Remove the grasp constraint, if any, and return it (the hand lets go of what it held)."""
        g, self.grip = self.grip, None
        if g is not None:
            pb.removeConstraint(g.constraint, physicsClientId=self.cid)
        return g


def _quat(R: np.ndarray) -> tuple[float, float, float, float]:
    """Quaternion (x, y, z, w) of a rotation matrix."""
    m = R
    t = np.trace(m)
    if t > 0:
        s = np.sqrt(t + 1.0) * 2
        return ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s)
    i = int(np.argmax(np.diag(m)))
    j, k = (i + 1) % 3, (i + 2) % 3
    s = np.sqrt(1.0 + m[i, i] - m[j, j] - m[k, k]) * 2
    q = [0.0, 0.0, 0.0, 0.0]
    q[i] = 0.25 * s
    q[j] = (m[j, i] + m[i, j]) / s
    q[k] = (m[k, i] + m[i, k]) / s
    q[3] = (m[k, j] - m[j, k]) / s
    return tuple(q)  # type: ignore[return-value]


quat_of = _quat
