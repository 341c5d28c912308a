"""The kinematic base: a base drive's set-point taken by setting the base there, not by motors.

A base that follows its profile through free space tracks it to a millimetre, and stepping the
physics for it (85 % of an episode's physics steps are base drives) computes nothing a set pose
would not give. So while nothing but the base would move, a set-point of
:meth:`~vap_bt.sim.pb_drivers.PybulletBase.follow` is taken kinematically (:meth:`Glide.place`):
the base's joints are set to the set-point (with its velocity), a held item is carried along
with the hand, and a collision check at the new pose decides whether that was honest. If the
robot or what it holds would come within :data:`CONTACT_MARGIN` of anything else — furniture, a
wall, a door leaf, an item on the floor — the pose is undone and that set-point is driven the
physical way (motors and a physics step), as every step was before, so touching, pushing an item
or a leaf, and being blocked (the base falling behind) stay the physics'. The same holds while
anything else is in motion (a falling or rolling item, a swinging leaf, the arm or the fingers
still moving, a grip just made or lost, a handle in the hand), and until a physically driven
base has caught up with its set-points again (:data:`CATCH_UP`).

What a real base does that this does not: in free space it lags its set-points a little and
sways the arm as it accelerates; here the arm stays exactly still and the base is exactly on its
profile. Things moving slower than :data:`REST_SPEED` / :data:`REST_SPIN` count as at rest and
stay where they are while the base glides (the physics would let them creep).
"""

from __future__ import annotations

import math

import numpy as np

from vap_bt.sim.pb import pb
from vap_bt.sim.pb_robot import Robot, quat_of
from vap_bt.sim.pb_scene import Scene

#: m between the robot (or what it holds) and anything else at which a set-point is driven by
#: physics: contact forces start at 0 m; the margin covers the next step's approach
CONTACT_MARGIN = 0.005
#: m (and rad of yaw) between the measured base and its last set-point within which the base may
#: glide on: a physically driven base that lags further catches up by its motors first
CATCH_UP = 0.005
#: m/s of a loose item, and of the fingers, below which it counts as at rest
REST_SPEED = 0.01
#: rad/s of an item's spin, a leaf's or an arm joint's velocity below which it counts as at rest
REST_SPIN = 0.05


class Glide:
    """Sets the base at a drive's set-point when the physics would do no more than that."""

    def __init__(self, robot: Robot, scene: Scene, dt: float) -> None:
        self.robot, self.scene, self.dt = robot, scene, dt
        self.cid = robot.cid
        self._grip = robot.grip  # the grip at the last glide: a change is a step for the physics
        self._quiet = False  # all at rest and the base on its profile, seen since the physics last stepped
        self._hinges = [t.hinge for t in scene.things.values() if t.hinge is not None]
        self._moving_joints = list(robot.body_joints[3:]) + list(robot.finger_joints)

    def place(self, body: np.ndarray, vel: np.ndarray) -> bool:
        """Set the base at ``body[:3]`` moving at ``vel[:3]`` (the arm's set-points as given), if
        nothing else moves and the new pose touches nothing; False (nothing changed) when this
        set-point is the physics' to drive."""
        r = self.robot
        grip, self._grip = self._grip, r.grip
        if r.grip is not grip:
            return False
        held = r.grip.body if r.grip is not None else None
        before = self._pose(held)
        if not self._settled(before[0]):
            return False
        self._set(body[:3], vel[:3], held, before)
        if self._touches(held):
            self._undo(before, held)
            return False
        r.set_target(body)
        return True

    def stepped(self) -> None:
        """The physics stepped: whether all rests is to be seen afresh (with no step, nothing but
        the glides moves, and what rested still rests)."""
        self._quiet = False

    def _settled(self, base: list[float]) -> bool:
        if not self._quiet:
            self._quiet = self._at_rest() and self._on_profile(base)
        return self._quiet

    # ------------------------------------------------------------ when the physics is needed

    def _at_rest(self) -> bool:
        """Nothing but the base would move: no loose item, leaf, arm joint or finger in motion,
        no handle in the hand (the arm drags a leaf through it)."""
        r = self.robot
        if r.grip is not None and r.grip.link != -1:
            return False
        states = pb.getJointStates(r.id, self._moving_joints, physicsClientId=self.cid)
        arm, fingers = states[:len(r.body_joints) - 3], states[len(r.body_joints) - 3:]
        if any(abs(s[1]) > REST_SPIN for s in arm) or any(abs(s[1]) > REST_SPEED for s in fingers):
            return False
        held = r.grip.body if r.grip is not None else None
        for b in (b for t in self.scene.items() for b in t.bodies):  # a cut item is two bodies
            if b != held:
                v, w = pb.getBaseVelocity(b, physicsClientId=self.cid)
                if math.hypot(*v) > REST_SPEED or math.hypot(*w) > REST_SPIN:
                    return False
        return all(abs(pb.getJointState(h.body, h.joint, physicsClientId=self.cid)[1]) <= REST_SPIN
                   for h in self._hinges)

    def _on_profile(self, base: list[float]) -> bool:
        """The measured ``base`` is where its last set-point put it (it is not catching up)."""
        return all(abs(q - t) <= CATCH_UP for q, t in zip(base, self.robot.target[:3]))

    def _touches(self, held: int | None) -> bool:
        """The robot or its held item is within :data:`CONTACT_MARGIN` of anything else (the
        collision filters apply: a body the hand slipped off is passed through, as in a step)."""
        pb.performCollisionDetection(physicsClientId=self.cid)
        ours = {self.robot.id, held}
        for a in ours - {None}:
            for p in pb.getContactPoints(bodyA=a, physicsClientId=self.cid):
                if p[2] not in ours and p[8] < CONTACT_MARGIN:
                    return True
        return False

    # ------------------------------------------------------------ setting poses

    def _pose(self, held: int | None):
        """The base joints' positions and velocities, and the held item's pose and velocity."""
        r = self.robot
        base = pb.getJointStates(r.id, r.body_joints[:3], physicsClientId=self.cid)
        item = None
        if held is not None:
            item = (pb.getBasePositionAndOrientation(held, physicsClientId=self.cid),
                    pb.getBaseVelocity(held, physicsClientId=self.cid))
        return [s[0] for s in base], [s[1] for s in base], item

    def _set(self, q, qd, held: int | None, before) -> None:
        """The base at ``q`` (velocity ``qd``); a held item keeps its pose in the hand and moves
        with it (the grip's constraint then holds it there with no force)."""
        r = self.robot
        hand = _inverse(r.link_pose("tcp")) if held is not None else None
        _reset_base(r, q, qd)
        if held is None:
            return
        (p0, o0), _ = before[2]
        rel_p, rel_o = pb.multiplyTransforms(*hand, p0, o0)
        T = r.link_pose("tcp")
        p, o = pb.multiplyTransforms(tuple(T[:3, 3]), _quat(T), rel_p, rel_o)
        pb.resetBasePositionAndOrientation(held, p, o, physicsClientId=self.cid)
        # the hand's velocity: an item let go from a gliding base flies on as it would from a driven one
        pb.resetBaseVelocity(held, tuple((np.array(p) - np.array(p0)) / self.dt), (0.0, 0.0, float(qd[2])),
                             physicsClientId=self.cid)

    def _undo(self, before, held: int | None) -> None:
        r = self.robot
        q, qd, item = before
        _reset_base(r, q, qd)
        if held is not None:
            (p, o), (v, w) = item
            pb.resetBasePositionAndOrientation(held, p, o, physicsClientId=self.cid)
            pb.resetBaseVelocity(held, v, w, physicsClientId=self.cid)


def _reset_base(r: Robot, q, qd) -> None:
    """The base's joints set to ``q`` moving at ``qd`` (one call: each call costs as much as three)."""
    pb.resetJointStatesMultiDof(r.id, r.body_joints[:3], [[float(v)] for v in q], [[float(w)] for w in qd],
                                physicsClientId=r.cid)


def _quat(T: np.ndarray):
    return quat_of(T[:3, :3])


def _inverse(T: np.ndarray):
    """pybullet's (position, orientation) of the inverse of the pose ``T``."""
    return pb.invertTransform(tuple(T[:3, 3]), _quat(T))
