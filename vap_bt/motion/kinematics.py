"""Forward kinematics of a chosen joint chain of the robot, with pinocchio.

The URDF describes the whole robot (base joints, arm, fingers). Planning usually moves only some
of those joints, so a :class:`Kinematics` is the robot's model *reduced* to a chain: the other
joints are locked at given values (base at the origin, fingers open, unless told otherwise). The
arm chain's world is therefore the base footprint frame ``base_link``; use
:func:`world_to_base` to bring world-frame targets into it. The chain with the base joints
(``Kinematics.mobile_arm``) moves in the world frame itself.

The collision shapes of the URDF are reduced with the model, so :mod:`vap_bt.motion.collision`
checks exactly the chain that IK moves.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from functools import cached_property

import numpy as np
import pinocchio as pin

import robots
from vap_bt.motion import se3

LOCAL = pin.ReferenceFrame.LOCAL


class Kinematics:
    """Pinocchio model + data of a joint chain; ``q`` always lists ``joint_names`` in order."""

    def __init__(
        self,
        robot: str = robots.DEFAULT_ROBOT,
        joints: Sequence[str] | None = None,
        locked: Mapping[str, float] | None = None,
    ) -> None:
        self.config = robots.load_config(robot)
        urdf = str(robots.urdf_path(robot))
        full = pin.buildModelFromUrdf(urdf)
        geometry = pin.buildGeomFromUrdf(full, urdf, pin.COLLISION)
        keep = tuple(joints) if joints is not None else self.config.arm.joints
        reference = self._reference_configuration(full, locked or {})
        lock_ids = [i for i in range(1, full.njoints) if full.names[i] not in keep]
        self.model, self.collision_model = pin.buildReducedModel(full, geometry, lock_ids, reference)
        self.data = self.model.createData()
        names = tuple(self.model.names[1:])
        if set(names) != set(keep):
            raise ValueError(f"unknown joints: {sorted(set(keep) - set(names))}")
        if names != keep:
            # Reduced models keep URDF order; asking for another order would silently permute q.
            raise ValueError(f"list the joints in URDF order: {names}")
        if self.model.nq != self.model.nv:
            raise ValueError("only 1-dof joints are supported")
        self.joint_names: tuple[str, ...] = names
        self.lower = self.model.lowerPositionLimit.copy()
        self.upper = self.model.upperPositionLimit.copy()
        # Python copies for scalar loops (IK), where numpy's per-call cost dominates.
        self.lower_list: list[float] = self.lower.tolist()
        self.upper_list: list[float] = self.upper.tolist()
        self._offsets: dict[str, tuple[np.ndarray, np.ndarray]] = {}

    def _reference_configuration(self, full: pin.Model, locked: Mapping[str, float]) -> np.ndarray:
        """Values of the locked joints: fingers open, everything else at zero, then overrides."""
        values = dict.fromkeys(self.config.gripper.joints, self.config.gripper.stroke / 2.0)
        values.update(locked)
        q = pin.neutral(full)
        for name, value in values.items():
            q[full.joints[full.getJointId(name)].idx_q] = value
        return q

    @classmethod
    def arm(cls, robot: str = robots.DEFAULT_ROBOT, finger_opening: float | None = None) -> Kinematics:
        """The six UR5e joints; base at the origin, fingers at ``finger_opening`` (default open)."""
        cfg = robots.load_config(robot)
        opening = cfg.gripper.stroke if finger_opening is None else finger_opening
        locked = dict(zip(cfg.gripper.joints, cfg.gripper.finger_positions(opening), strict=True))
        return cls(robot, cfg.arm.joints, locked)

    @classmethod
    def mobile_arm(cls, robot: str = robots.DEFAULT_ROBOT) -> Kinematics:
        """Base x, y, yaw followed by the six arm joints, in the world frame."""
        cfg = robots.load_config(robot)
        return cls(robot, cfg.base.joints + cfg.arm.joints)

    @property
    def dof(self) -> int:
        return self.model.nq

    @cached_property
    def wraps(self) -> np.ndarray:
        """Joints whose range spans a full turn: a value outside it can be shifted by 2 pi."""
        # pinocchio names revolute joints JointModelR* (RX, RY, RZ, RevoluteUnaligned).
        revolute = np.array([j.shortname().startswith("JointModelR") for j in self.model.joints[1:]])
        return revolute & (self.upper - self.lower >= 2.0 * np.pi - 1e-9)

    def frame_id(self, frame: str) -> int:
        """Pinocchio's index of the URDF frame (link or joint) named ``frame``; KeyError when the model
        has none."""
        fid = self.model.getFrameId(frame)
        if fid >= self.model.nframes:
            raise KeyError(f"no frame {frame!r} in the model")
        return fid

    def fk(self, q: np.ndarray, frame: str = "tcp") -> np.ndarray:
        """Pose (4x4) of ``frame`` in the chain's world for joint values ``q``."""
        fid = self.frame_id(frame)
        pin.forwardKinematics(self.model, self.data, np.asarray(q, dtype=float))
        return pin.updateFramePlacement(self.model, self.data, fid).homogeneous

    def fk_all(self, q: np.ndarray) -> dict[str, np.ndarray]:
        """Poses of every frame (for drawing or for tests)."""
        pin.framesForwardKinematics(self.model, self.data, np.asarray(q, dtype=float))
        return {f.name: self.data.oMf[i].homogeneous for i, f in enumerate(self.model.frames)}

    def flange_offsets(self, frame: str) -> tuple[np.ndarray, np.ndarray] | None:
        """For the UR arm chain: (arm base in the chain's world, ``frame`` in the flange frame),
        both constant; None when the chain is not exactly the arm or ``frame`` does not ride on
        the flange. This is what the closed-form UR solution needs to seed IK."""
        if self.joint_names != self.config.arm.joints:
            return None
        fid = self.frame_id(frame)
        if self.model.frames[fid].parentJoint != self.model.njoints - 1:
            return None
        if frame not in self._offsets:
            frames = self.fk_all(np.zeros(self.dof))
            self._offsets[frame] = (
                frames[self.config.arm.base_link],
                se3.inverse(frames[self.config.arm.flange]) @ frames[frame],
            )
        return self._offsets[frame]

    def pose_and_jacobian(self, q: np.ndarray, fid: int) -> tuple[pin.SE3, np.ndarray]:
        """Frame placement and its 6 x dof Jacobian in the frame's own (local) axes."""
        # computeJointJacobians also runs forward kinematics (pin.computeFrameJacobian does not
        # leave data.oMi consistent with q, so it cannot give the placement as well).
        pin.computeJointJacobians(self.model, self.data, q)
        placement = pin.updateFramePlacement(self.model, self.data, fid)
        return placement, pin.getFrameJacobian(self.model, self.data, fid, LOCAL)

    def clamp(self, q: np.ndarray) -> np.ndarray:
        """Bring ``q`` into the limits: shift full-turn joints by 2 pi, clip the others."""
        q = np.array(q, dtype=float)
        if ((q >= self.lower) & (q <= self.upper)).all():  # the common case, kept cheap for IK
            return q
        w = self.wraps
        span = 2.0 * np.pi
        below = w & (q < self.lower)
        above = w & (q > self.upper)
        q[below] += span * np.ceil((self.lower[below] - q[below]) / span)
        q[above] -= span * np.ceil((q[above] - self.upper[above]) / span)
        return np.clip(q, self.lower, self.upper)

    def random_configuration(self, rng: np.random.Generator) -> np.ndarray:
        """Uniform within the limits, full-turn joints within one turn around zero."""
        lo, hi = self._sampling_range
        return rng.uniform(lo, hi)

    @cached_property
    def _sampling_range(self) -> tuple[np.ndarray, np.ndarray]:
        lo = np.where(self.wraps, np.maximum(self.lower, -np.pi), self.lower)
        hi = np.where(self.wraps, np.minimum(self.upper, np.pi), self.upper)
        return lo, hi


def world_to_base(target_world: np.ndarray, base_pose: tuple[float, float, float]) -> np.ndarray:
    """Express a world-frame pose in the base footprint frame (the arm chain's world)."""
    return se3.inverse(se3.planar_pose(*base_pose)) @ target_world
