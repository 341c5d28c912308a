"""Collision checking of a kinematic chain against itself and against boxes in the scene (coal).

The robot's collision shapes come from the URDF through pinocchio's GeometryModel. Self pairs
are all pairs of shapes except those that cannot meaningfully collide: shapes moved by the same
joint, shapes on adjacent joints (a parent joint and its child: they touch at the motor by
construction), and the link pairs the robot's YAML lists as allowed (the two finger pads).

Scene obstacles are boxes given as arrays, in the chain's world frame (for the arm chain: the base
footprint frame; :meth:`SceneBoxes.transformed` moves world boxes there). They are checked against
every robot shape except those fixed to the chain's root (for the arm chain that is the base body,
which the navigation layer keeps clear, not IK). ``scene_margins`` keeps named links further
off the scene than the hand, which must come close to what it works on.

What the hand holds rides along as one more box (:class:`Attached`, fixed in a frame of the
chain, the tool's): it is kept off the scene like a link, and off the arm's own links except those
moved by its joint and the joint before it (the hand and the wrist round the item).
"""

from __future__ import annotations

from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from vap_bt.motion.kinematics import Kinematics


@dataclass(frozen=True)
class SceneBoxes:
    """N boxes: ``poses`` (N, 4, 4) of their centres, ``sizes`` (N, 3) full edge lengths."""

    poses: np.ndarray
    sizes: np.ndarray
    names: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if self.poses.shape[1:] != (4, 4) or self.sizes.shape != (len(self.poses), 3):
            raise ValueError("poses must be (N, 4, 4) and sizes (N, 3)")

    def __len__(self) -> int:
        return len(self.sizes)

    @classmethod
    def empty(cls) -> SceneBoxes:
        """No obstacles: what a chain is checked against when only its own links matter."""
        return cls(np.zeros((0, 4, 4)), np.zeros((0, 3)))

    @classmethod
    def from_aabbs(cls, aabbs: np.ndarray, names: tuple[str, ...] = ()) -> SceneBoxes:
        """From rows (xmin, ymin, zmin, xmax, ymax, zmax), as :class:`vap_bt.world.ObjectInfo` boxes."""
        a = np.asarray(aabbs, dtype=float).reshape(-1, 6)
        poses = np.repeat(np.eye(4)[None], len(a), axis=0)
        poses[:, :3, 3] = (a[:, :3] + a[:, 3:]) / 2.0
        return cls(poses, a[:, 3:] - a[:, :3], names)

    def transformed(self, T: np.ndarray) -> SceneBoxes:
        """The same boxes with every pose premultiplied by ``T`` (a change of frame)."""
        return SceneBoxes(T @ self.poses, self.sizes, self.names)


@dataclass(frozen=True)
class Attached:
    """A box carried by the chain: ``pose`` (4x4) of its centre in ``frame``, ``size`` its full
    edge lengths."""

    frame: str
    pose: np.ndarray
    size: np.ndarray


def _link_of(obj: pin.GeometryObject) -> str:
    # pinocchio names URDF collision shapes "<link>_<index>".
    return obj.name.rsplit("_", 1)[0]


class CollisionChecker:
    """Answers "is this configuration in collision?" for one chain and one set of scene boxes."""

    def __init__(self, kin: Kinematics, boxes: SceneBoxes | None = None, margin: float = 0.0,
                 scene_margins: dict[str, float] | None = None, attached: Attached | None = None) -> None:
        self.kin = kin
        self.boxes = boxes if boxes is not None else SceneBoxes.empty()
        self.scene_margins = dict(scene_margins or {})
        self.attached = attached
        self.geometry = kin.collision_model.copy()
        if attached is not None:
            frame = kin.model.frames[kin.model.getFrameId(attached.frame)]
            self.geometry.addGeometryObject(pin.GeometryObject(
                "held_0", frame.parentJoint, frame.placement * pin.SE3(np.asarray(attached.pose, float)),
                coal.Box(*np.asarray(attached.size, float))))
        n_robot = self.geometry.ngeoms
        self._add_boxes(margin)
        self._add_self_pairs(n_robot)
        self._add_scene_pairs(n_robot)
        self.data = pin.GeometryData(self.geometry)
        objs = self.geometry.geometryObjects
        for request, pair in zip(self.data.collisionRequests, self.geometry.collisionPairs):
            extra = self.scene_margins.get(_link_of(objs[pair.first]), 0.0) if pair.second >= n_robot else 0.0
            request.security_margin = margin + extra

    def _add_boxes(self, margin: float) -> None:
        for i in range(len(self.boxes)):
            name = self.boxes.names[i] if i < len(self.boxes.names) else f"box{i}"
            placement = pin.SE3(self.boxes.poses[i])
            shape = coal.Box(*self.boxes.sizes[i])
            self.geometry.addGeometryObject(pin.GeometryObject(f"scene:{name}", 0, placement, shape))

    def _adjacent(self, a: int, b: int) -> bool:
        parents = self.kin.model.parents
        return a == b or parents[a] == b or parents[b] == a

    def _add_self_pairs(self, n_robot: int) -> None:
        allowed = {frozenset(p) for p in self.kin.config.allowed_collisions}
        objs = self.geometry.geometryObjects
        for i in range(n_robot):
            for j in range(i + 1, n_robot):
                if self._adjacent(objs[i].parentJoint, objs[j].parentJoint):
                    continue
                if frozenset((_link_of(objs[i]), _link_of(objs[j]))) in allowed:
                    continue
                self.geometry.addCollisionPair(pin.CollisionPair(i, j))
        self.n_self_pairs = len(self.geometry.collisionPairs)

    def _add_scene_pairs(self, n_robot: int) -> None:
        objs = self.geometry.geometryObjects
        for b in range(n_robot, self.geometry.ngeoms):
            for i in range(n_robot):
                if objs[i].parentJoint != 0:
                    self.geometry.addCollisionPair(pin.CollisionPair(i, b))

    def place_boxes(self, poses: np.ndarray) -> None:
        """Move the scene's boxes (same boxes, new poses in the chain's world frame): cheaper than a
        new checker when only the chain's root moved (a base that drove somewhere else)."""
        objs, first = self.geometry.geometryObjects, self.geometry.ngeoms - len(self.boxes)
        for i, T in enumerate(np.asarray(poses)):
            objs[first + i].placement = pin.SE3(T)
        self.boxes = SceneBoxes(np.asarray(poses), self.boxes.sizes, self.boxes.names)

    def with_boxes(self, boxes: SceneBoxes, margin: float = 0.0) -> CollisionChecker:
        """A checker for the same chain in another scene."""
        return CollisionChecker(self.kin, boxes, margin, self.scene_margins, self.attached)

    def in_collision(self, q: np.ndarray) -> bool:
        """Whether the chain at joint values ``q`` touches itself, the scene boxes or the held item
        (stops at the first contact)."""
        return bool(
            pin.computeCollisions(
                self.kin.model, self.kin.data, self.geometry, self.data, np.asarray(q, dtype=float), True
            )
        )

    def colliding_pairs(self, q: np.ndarray) -> list[tuple[str, str]]:
        """Names of every colliding pair (for diagnostics; slower than :meth:`in_collision`)."""
        pin.computeCollisions(self.kin.model, self.kin.data, self.geometry, self.data, np.asarray(q, dtype=float), False)
        objs = self.geometry.geometryObjects
        out = []
        for k, pair in enumerate(self.geometry.collisionPairs):
            if self.data.collisionResults[k].isCollision():
                out.append((objs[pair.first].name, objs[pair.second].name))
        return out
