"""Following a handle with the whole robot: where to stand and how to move while a door turns.

A door leaf or drawer moves only because the hand holding its handle moves (see
:mod:`pb_primitives`). The handle's path is known from the :class:`~vap_bt.sim.pb_scene.Hinge`;
what is not known is where the base must be at each point of it. A side-hinged leaf swings
through the space in front of its cabinet and turns its handle by up to 100 degrees, a room door
carries its handle into the next room: no single base pose reaches the whole arc, and a base
that stays put is soon in the leaf's way.

:class:`HandleFollower` therefore plans base and arm together, one waypoint of the handle path at
a time (every few degrees or centimetres), and checks every candidate before any joint moves:

* the base's footprint keeps a margin from walls, furniture and the leaf in its pose at that
  waypoint (convex polygons, separating-axis test);
* the arm reaches the handle from that base (:func:`vap_bt.motion.ik.solve_ik`, arm alone),
  staying near the previous joint values, and no collision shape of the robot (fingers at the
  grip's opening) comes near the leaf's panel (the leaf without its handle) or itself
  (:class:`vap_bt.motion.collision.CollisionChecker` with the panel as an oriented box);
* the hand may lag the leaf's rotation by up to ``MAX_LAG`` about the bar (the grip is a ball
  joint: a loosely closed hand lets the bar turn in it), which keeps the wrist comfortable and
  lets the hand take the handle of a leaf lying open from the side rather than from below.

The first waypoint (the grasp) is searched globally on a ring of base poses around the handle;
for each of the best few the whole path is planned and the first that gets through wins (else
the one that gets furthest). Later waypoints search locally around the previous base pose and
lag, preferring the pose in which the handle sits comfortably in front of the robot — so the base
walks along with the door. The result is a list of body-joint waypoints that
:meth:`~vap_bt.sim.pb_motion.Motion.through` times and the motors track.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
import pinocchio as pin
import pybullet as pb

from vap_bt.motion.collision import CollisionChecker, SceneBoxes
from vap_bt.motion.kinematics import Kinematics
from vap_bt.sim.pb_motion import Motion
from vap_bt.sim.pb_scene import Hinge, Scene, _axis_angle

FOOTPRINT = (0.31, 0.26)  # half length and half width of the base box
#: the folded arm (home pose) seen from above, in the base frame: it reaches past the base's front
FOLDED_ARM = ((0.31, -0.06), (0.72, -0.06), (0.72, 0.2), (0.31, 0.2))
BASE_MARGIN = 0.04  # footprint to obstacles while the leaf moves with the hand (the grip is springy)
PARKED_MARGIN = 0.015  # footprint to obstacles when the leaf stands still
ARM_MARGIN = 0.04  # arm and base shapes to the leaf's panel
HAND_MARGIN = 0.006  # gripper and finger shapes to the panel (they hold a bar 0.045 m in front of it)
HAND_LINKS = ("gripper_base_link", "left_finger_link", "right_finger_link")
COMFORT = 0.66  # handle distance in front of the base centre that the arm reaches best
ANGLE_STEP = 0.07  # rad between revolute waypoints
SLIDE_STEP = 0.025  # m between prismatic waypoints
MAX_LAG = 1.4  # rad the hand may trail (or lead) the leaf's rotation about the bar
MAX_JOINT_JUMP = 0.45  # rad of any arm joint between consecutive waypoints
GRASP_LAGS = (0.0, 0.4, -0.4, 0.8, -0.8, 1.2, -1.2)
LOCAL_STEPS = ((-0.08, 0.0, 0.08), (-0.08, 0.0, 0.08), (-0.12, 0.0, 0.12))  # base forward, left, yaw
LAG_STEPS = (-0.15, 0.0, 0.15)
RING = dict(distance=(0.58, 0.66, 0.74, 0.84), bearing=(0.0, -0.35, 0.35, -0.7, 0.7, -1.0, 1.0), yaw=(0.0, -0.3, 0.3))
GLOBAL_TRIES = 6  # initial poses whose whole path is planned before settling for the furthest


@dataclass(frozen=True)
class Obb:
    """An oriented box: centre, rotation (columns are its axes), half extents."""

    center: np.ndarray
    R: np.ndarray
    half: np.ndarray

    @classmethod
    def aabb(cls, lo, hi) -> Obb:
        lo, hi = np.asarray(lo, float), np.asarray(hi, float)
        return cls((lo + hi) / 2, np.eye(3), (hi - lo) / 2)

    def polygon(self) -> np.ndarray:
        """Its outline seen from above (convex polygon, counter-clockwise)."""
        signs = np.array(list(itertools.product((-1, 1), repeat=3)), float)
        corners = self.center + (signs * self.half) @ self.R.T
        return _hull(corners[:, :2])

    def contains(self, pts: np.ndarray, margin: float) -> bool:
        local = np.abs((pts - self.center) @ self.R)
        return bool(np.any(np.all(local <= self.half + margin, axis=1)))


@dataclass
class Waypoint:
    q: np.ndarray  # body joints (base x, y, yaw, arm)
    T: np.ndarray  # tcp pose
    lag: float  # rad the hand trails the leaf


@dataclass
class Path:
    waypoints: list[Waypoint]  # the first is the grasp
    joint_values: list[float]  # leaf joint value at each waypoint
    complete: bool
    pre: Waypoint | None = None  # the hand backed off the handle along its approach axis


def _hull(pts: np.ndarray) -> np.ndarray:
    """Convex hull of 2-D points (monotone chain), counter-clockwise."""
    P = sorted(map(tuple, np.round(pts, 9)))
    if len(P) <= 2:
        return np.array(P)

    def half(seq):
        out: list = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out

    lower, upper = half(P), half(reversed(P))
    return np.array(lower[:-1] + upper[:-1])


def _apart(a: np.ndarray, b: np.ndarray, margin: float) -> bool:
    """True when two convex polygons are separated by more than ``margin`` along some edge normal."""
    for poly in (a, b):
        edges = np.roll(poly, -1, axis=0) - poly
        normals = np.stack([edges[:, 1], -edges[:, 0]], axis=1)
        lengths = np.linalg.norm(normals, axis=1)
        for n in normals[lengths > 1e-9] / lengths[lengths > 1e-9, None]:
            pa, pb_ = a @ n, b @ n
            if pa.min() > pb_.max() + margin or pb_.min() > pa.max() + margin:
                return True
    return False


def _placed(local, pose) -> np.ndarray:
    """A polygon given in the base frame, in the world for base ``pose``."""
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    return np.asarray(local, float) @ np.array([[c, s], [-s, c]]) + (x, y)


def footprint(pose) -> np.ndarray:
    L, W = FOOTPRINT
    return _placed([(L, W), (-L, W), (-L, -W), (L, -W)], pose)


class HandleFollower:
    def __init__(self, scene: Scene, motion: Motion) -> None:
        self.scene, self.motion = scene, motion
        self.cid = scene.client
        self.opening = 0.0  # of the fingers round the bar, for the clearance checks
        self._kin: Kinematics | None = None
        self._checker: CollisionChecker | None = None

    # ------------------------------------------------------------ obstacles

    def obstacles(self, moving: Hinge | None = None) -> list[np.ndarray]:
        """Outlines of everything the base must keep off (walls, furniture, door leaves as they
        stand), except ``moving``'s own leaf."""
        polys = []
        for w in self.scene.walls:
            polys.append(Obb.aabb(*pb.getAABB(w, -1, physicsClientId=self.cid)).polygon())
        for t in self.scene.things.values():
            if t.furniture is None and t.door is None:
                continue
            for link in range(-1, pb.getNumJoints(t.body, physicsClientId=self.cid)):
                if moving is not None and t.hinge is moving and link == moving.joint:
                    continue
                lo, hi = pb.getAABB(t.body, link, physicsClientId=self.cid)
                if lo[0] <= hi[0] and hi[2] - lo[2] > 1e-3:
                    polys.append(Obb.aabb(lo, hi).polygon())
        return polys

    def base_free(self, pose, static: list[np.ndarray], leaf: Obb | None = None, folded: bool = False,
                  margin: float = BASE_MARGIN) -> bool:
        """The base (and the folded arm ahead of it, if ``folded``) keeps off every obstacle."""
        shapes = [footprint(pose)] + ([_placed(FOLDED_ARM, pose)] if folded else [])
        obstacles = static + ([leaf.polygon()] if leaf is not None else [])
        return all(_apart(s, o, margin) for s in shapes for o in obstacles)

    def use_panel(self, h: Hinge, opening: float) -> None:
        """Set up the arm's collision check against ``h``'s panel, fingers ``opening`` apart."""
        if self._kin is None or self.opening != opening:
            cfg = self.motion.robot.cfg
            fingers = dict(zip(cfg.gripper.joints, cfg.gripper.finger_positions(opening)))
            self._kin = Kinematics(joints=cfg.base.joints + cfg.arm.joints, locked=fingers)
            self.opening = opening
        _, _, half = h.plate(0.0)
        checker = CollisionChecker(self._kin, SceneBoxes(np.eye(4)[None], 2 * half[None]), margin=HAND_MARGIN)
        objs = checker.geometry.geometryObjects
        panel = checker.geometry.ngeoms - 1
        for pair, request in zip(checker.geometry.collisionPairs, checker.data.collisionRequests):
            if pair.second == panel and objs[pair.first].name.rsplit("_", 1)[0] not in HAND_LINKS:
                request.security_margin = ARM_MARGIN
        self._checker = checker

    def arm_clear(self, q: np.ndarray, plate: Obb) -> bool:
        """The robot (base, arm, gripper, fingers round the bar) keeps off the panel and itself."""
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = plate.R, plate.center
        self._checker.geometry.geometryObjects[self._checker.geometry.ngeoms - 1].placement = pin.SE3(T)
        return not self._checker.in_collision(q)

    # ------------------------------------------------------------ the handle's path

    def hand_pose(self, h: Hinge, side: float, q: float, q0: float, G0: np.ndarray, lag: float) -> np.ndarray:
        """tcp pose holding the handle at joint value ``q``, the hand turned ``lag`` back from the
        leaf's rotation about the hinge axis (signed like the joint)."""
        p, _, _ = h.handle_at(q, side)
        T = np.eye(4)
        T[:3, 3] = p
        if h.prismatic:
            T[:3, :3] = G0[:3, :3]
        else:
            T[:3, :3] = _axis_angle(h.axis, (q - q0) - lag) @ G0[:3, :3]
        return T

    def _solve(self, T: np.ndarray, base, seed: np.ndarray, plate: Obb, prev: np.ndarray | None) -> np.ndarray | None:
        s = seed.copy()
        s[:3] = base
        q = self.motion.solve(T, seed=s, allow_base=False)
        if q is None:
            return None
        if prev is not None and np.max(np.abs(q[3:] - prev[3:])) > MAX_JOINT_JUMP:
            return None
        return q if self.arm_clear(q, plate) else None

    @staticmethod
    def comfort(base, T: np.ndarray) -> float:
        """How awkward it is to hold ``T`` from ``base``: handle off the comfortable spot in front,
        hand turned away from the base's forward direction."""
        x, y, yaw = base
        c, s = math.cos(yaw), math.sin(yaw)
        d = T[:2, 3] - (x, y)
        fwd, left = c * d[0] + s * d[1], -s * d[0] + c * d[1]
        a = T[:2, 2]
        a_fwd = (c * a[0] + s * a[1]) / max(np.linalg.norm(a), 1e-6)
        return (fwd - COMFORT) ** 2 + left ** 2 + 0.03 * (1.0 - a_fwd)

    # ------------------------------------------------------------ planning

    def plan(self, h: Hinge, side: float, q0: float, goal: float, G0: np.ndarray, here, opening: float,
             approach: float) -> Path:
        """Body-joint waypoints that carry the handle from ``q0`` to ``goal`` with the fingers
        ``opening`` apart round it; the grasp is preceded by a pre-grasp ``approach`` metres back
        along the hand's axis. ``G0``: the hand square to the leaf's face at ``q0``; ``here``: the
        base pose now."""
        self.use_panel(h, opening)
        step = SLIDE_STEP if h.prismatic else ANGLE_STEP
        n = max(1, int(math.ceil(abs(goal - q0) / step)))
        values = [q0 + (goal - q0) * k / n for k in range(n + 1)]
        static = self.obstacles(h)
        best: Path | None = None
        for pre, wp in self._grasp_poses(h, side, q0, G0, static, here, approach):
            path = self._follow(h, side, values, G0, wp, static)
            path.pre = pre
            if best is None or len(path.waypoints) > len(best.waypoints):
                best = path
            if path.complete:
                break
        return best or Path([], [], False)

    def _grasp_poses(self, h: Hinge, side: float, q0: float, G0: np.ndarray, static, here, approach: float):
        """Feasible (pre-grasp, grasp) pairs, best first: base poses on a ring around the handle,
        the hand square to the leaf or turned about the bar."""
        p = G0[:3, 3]
        leaf, plate = Obb(*h.leaf(q0)), Obb(*h.plate(q0))
        cands = []
        for lag in ((0.0,) if h.prismatic else GRASP_LAGS):
            T = self.hand_pose(h, side, q0, q0, G0, lag)
            out = -T[:3, 2]
            if np.hypot(out[0], out[1]) < 0.3:  # a hand from below or above: no base pose faces it
                continue
            bearing0 = math.atan2(out[1], out[0])
            for d, b, dyaw in itertools.product(RING["distance"], RING["bearing"], RING["yaw"]):
                x, y = p[0] + d * math.cos(bearing0 + b), p[1] + d * math.sin(bearing0 + b)
                pose = (x, y, math.atan2(p[1] - y, p[0] - x) + dyaw)
                cost = self.comfort(pose, T) + 0.05 * math.hypot(x - here[0], y - here[1]) + 0.02 * lag * lag
                cands.append((cost, pose, T, lag))
        tries = 0
        seed = self.motion.robot.target
        for _, pose, T, lag in sorted(cands, key=lambda c: c[0]):
            if not self.base_free(pose, static, leaf):
                continue
            pose = np.array(pose)
            pose[2] = here[2] + math.remainder(pose[2] - here[2], 2 * math.pi)
            q = self._solve(T, pose, seed, plate, None)
            if q is None:
                continue
            P = T.copy()
            P[:3, 3] -= T[:3, 2] * approach
            q_pre = self._solve(P, pose, q, plate, q)
            if q_pre is not None:
                yield Waypoint(q_pre, P, lag), Waypoint(q, T, lag)
                tries += 1
                if tries >= GLOBAL_TRIES:
                    return

    def _follow(self, h: Hinge, side: float, values: list[float], G0: np.ndarray, first: Waypoint, static) -> Path:
        wps = [first]
        for q in values[1:]:
            prev = wps[-1]
            leaf, plate = Obb(*h.leaf(q)), Obb(*h.plate(q))
            x, y, yaw = prev.q[:3]
            c, s = math.cos(yaw), math.sin(yaw)
            lags = (0.0,) if h.prismatic else tuple({min(MAX_LAG, max(-MAX_LAG, prev.lag + d)) for d in LAG_STEPS})
            cands = []
            for (df, dl, dyaw), lag in itertools.product(itertools.product(*LOCAL_STEPS), lags):
                base = (x + c * df - s * dl, y + s * df + c * dl, yaw + dyaw)
                T = self.hand_pose(h, side, q, values[0], G0, lag)
                moved = df * df + dl * dl + 0.1 * dyaw * dyaw
                cands.append((self.comfort(base, T) + 0.3 * moved + 0.01 * lag * lag, base, T, lag))
            found = None
            for _, base, T, lag in sorted(cands, key=lambda c: c[0]):
                if not self.base_free(base, static, leaf):
                    continue
                sol = self._solve(T, base, prev.q, plate, prev.q)
                if sol is not None:
                    found = Waypoint(sol, T, lag)
                    break
            if found is None:
                return Path(wps, values[:len(wps)], False)
            wps.append(found)
        return Path(wps, values, True)
