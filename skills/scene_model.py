"""What skills know of the scene: the map's furniture and walls, and what the camera shows now.

Skills plan motions against two kinds of knowledge, neither of which is the simulator's state:

* **the site map** (:mod:`vap_bt.robot.site_map`) — room outlines (their walls, with gaps where
  the doorways are), each piece of furniture's footprint, height, cavity and articulation (how
  its door or drawer moves, where its handle, switch or tap is). From it come the furniture's
  frame (x along its front, y out of it, z up), the obstacles a base must keep off (as polygons
  seen from above) and the solid boxes IK must keep the arm clear of — a container's box has its
  cavity carved out, so a hand can reach in;
* **what the camera shows** — where an item is, how big, which way it lies: the skill looks where
  the executive believes the item is (the goal's hint), takes a frame, takes the detection of
  the item's class there for the item (:mod:`vap_bt.scene.identity`), and fuses its masked depth
  into a point cloud (:mod:`vap_bt.scene.pointcloud`); where a door or drawer stands
  now, fitted to the points of its piece of furniture (the map says how it moves; the frame says
  how far it has); and where the map lies in the frame the robot believes it stands in: every
  frame that shows mapped furniture registers the map to it (:mod:`skills.registration`), and the
  map is used shifted by that correction, carried across the base's motions by its odometry (the
  localiser's frame jumps when it updates, the wheels' does not), for a couple of metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from skills.registration import (Correction, RegistrationParams, corrected_articulation, corrected_map, corrected_piece,
                                 register, translation)
from vap_bt.motion import se3
from vap_bt.motion.collision import SceneBoxes
from vap_bt.motion.footprint import Obb, apart, footprint
from vap_bt.robot.frame import Frame, at_edge
from vap_bt.robot.labels import label_of
from vap_bt.robot.site_map import Articulation, FurnitureInfo, SiteMap
from vap_bt.scene.pointcloud import backproject, instance_cloud

#: a mask's rim bleeds onto what lies behind the item (the detector's boundary errors), and those
#: pixels' depth is the background's: points further from the camera than the item's nearest
#: (5th percentile) by more than its width across the view and this slack are not the item's
#: (a cup's bled rim put points 20 cm behind it on the microwave, and its box 4 cm off its middle)
BEHIND_SLACK = 0.03

#: an item whose points reach within this of the floor and stay below FLOOR_ITEM_TOP lies on the
#: floor (m) — if they rise FLOOR_ITEM_LEAST above it: a detection whose points are the floor
#: itself (a false positive on a patch of it) is nothing the base could run into (the flattest
#: item, a plate lying, stands 1.8 cm)
FLOOR_TOUCH, FLOOR_ITEM_TOP, FLOOR_ITEM_LEAST = 0.06, 0.3, 0.012
#: how high an item rises is read at this quantile of its points' heights: on a stereo camera's
#: depth a patch of floor has points a few centimetres up (the noise of a metre or two), and an
#: unnamed false positive on it, taken by its highest point, stood in the base's way
FLOOR_ITEM_QUANTILE = 0.75
#: m round a leaf (where it is believed to stand) within which a piece's points are the leaf's,
#: left out of registering the map (:meth:`SceneModel.relocalize`)
LEAF_CUT = 0.03
#: m beyond a mapped solid's faces a point is still that solid's (the depth noise of a metre or
#: two, 1-3 cm, and the localiser's error left after registration); a detection with fewer than
#: MAP_LEFT_LEAST points off the map is nothing new (a few noisy pixels)
MAP_SLACK, MAP_LEFT_LEAST = 0.05, 20
#: m the base already is from a floor item when it counts as touching it (see low_obstacles)
LOW_MARGIN = 0.01
#: what the keys of floor items nobody named start with; one seen again within this (m) of where
#: it was is the same (:meth:`SceneModel.note_items`)
ANONYMOUS, ANONYMOUS_NEAR = "?", 0.3
#: m: an unnamed floor item whose box comes this near the box of an item the hand just took was it
TAKEN_SLACK = 0.03
#: walls are where the map's room outlines are, this thick and high (a SLAM map's walls)
WALL_THICKNESS = 0.08
WALL_HEIGHT = 2.0
#: the floor is a slab this thick under each room (the wrist swung through it on a way round)
FLOOR_THICKNESS = 0.1
#: a door's fitted opening is searched over this many joint values between closed and open
DOOR_FIT_STEPS = 40
#: a door's handle is looked for among its points this near where the map puts it (m): the
#: localiser's error two metres off, with room to spare
HANDLE_SEARCH = 0.22
HANDLE_SEARCH_RANGE = 3.0  # m: beyond this a bar 2.4 cm thick is a few noisy pixels
#: m in front of the leaf's face the bar's points stand (the models' bar: its centre 4.5 cm out,
#: 2.4 cm thick), and how near the face a point lies on it (the depth noise of a metre or two)
BAR_STANDOUT = (0.025, 0.075)
BAR_FACE_BAND = 0.02
HANDLE_MIN_POINTS, HANDLE_MIN_BAR = 40, 8
#: m a furniture handle's bar must lie off the map before the leaf is moved onto it: on exact
#: depth, with no localisation error, the measure put bars 2 to 5 mm off (a fingers' width of
#: slack), and each such move replanned the handle's path onto another stance
HANDLE_LEAST = 0.01
#: percentiles of a bar's points across the leaf's face taken as its edges (a stray point or two
#: of depth noise beyond them)
BAR_EXTENT = (5.0, 95.0)
#: rad: a door's face seen turned up to this much from its fitted leaf is the leaf at another
#: joint value (more is not the face)
DOOR_TURN_FIX = 0.35
#: the planar offsets (m, m, rad) a room door's points may lie off its leaf in the map by, each
#: tried in a fit: the localiser's error (σ 5 cm, 2 degrees) at a door a metre or two away
DOOR_SLACK = tuple((dx, dy, dth) for dx in (-0.08, 0.0, 0.08) for dy in (-0.08, 0.0, 0.08) for dth in (-0.06, 0.0, 0.06))
#: points within this of a leaf's box count as the leaf's
LEAF_MARGIN = 0.03
#: points of a frame's cloud a new leaf fit must explain beyond the believed joint value before a
#: glance replaces the belief (:meth:`SceneModel.note_leaves`). A piece's instance cloud holds a
#: few hundred points; a door seen swung or shut explained 80-300 more than the stale belief in the
#: episodes looked at, an oblique frame of the foot of a leaf 0-10 either way (boil_water seed 16
#: with injection flipped an open cabinet door shut and open again on such frames)
LEAF_REFIT_POINTS = 40
#: what a point the camera saw through a leaf's face counts against that joint value, in points
#: on its box: a closed leaf's box overlaps the carcass's front edge, whose points accrue to it
#: whatever the leaf does, while a point seen through the face is possible only if the leaf is not
#: there. Counted once each, 83 points of an oven's front edge outweighed 40 seen through the shut
#: door it would have been, and a look into the cavity from above, its dropped door out of the
#: frame, refitted the wide-open door shut (heat_pie seed 0): the arm then struck the real door.
#: Hinged leaves only: a drawer's front slides out in front of the carcass's edge instead of
#: swinging off it, and weighted fits of the kitchen drawer made the arm strike it in the skill
#: tests' takeouts
THROUGH_WEIGHT = 3
#: depth this far past a doorway means the view goes through it
SEE_THROUGH = 0.3
HIDDEN_SHARE = 0.5  # a depth return nearer than this share of a point's distance is something in front of it
#: the handle bar's centre stands this far in front of its leaf's face (the furniture models')
HANDLE_STANDOUT = 0.045
#: m of a leaf's panel behind its face that a sight line cannot cross (a drawer's panel is only
#: its front: the tray behind it is open from above)
FACE_THICKNESS = 0.02
#: half size (m) of an appliance's switch (along the front, out of it, up): it stands proud of
#: the front, where a forearm sweeping past a low hollow would catch it
SWITCH = (0.03, 0.02, 0.022)
#: m the base may move from where the map was last registered to a view before the correction is
#: dropped: carried by odometry, it holds as well as odometry does (a wheeled base drifts by 1-2 %
#: of the way: 2-4 cm over 2 m, about a registration's own error)
ODOMETRY_HOLD = 2.0


@dataclass(frozen=True)
class Seen:
    """An item as one look shows it: centroid, box, the yaw of its longer side, and whether it is
    round seen from above (then any grasp direction across it will do)."""

    name: str
    centroid: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    yaw: float
    round: bool
    frame: Frame
    #: the corners (x, y) of the box round its points turned to its longer side (``yaw``): an
    #: item lying at a slant fills a fraction of its axis-aligned box
    outline: np.ndarray | None = None

    @property
    def top(self) -> float:
        """The height of the item's top (m, map frame)."""
        return float(self.hi[2])

    @property
    def bottom(self) -> float:
        """The height of the item's bottom (m, map frame)."""
        return float(self.lo[2])

    @property
    def extent(self) -> np.ndarray:
        """The box's size along x, y, z (m)."""
        return self.hi - self.lo

    def shown(self) -> tuple[bool, int]:
        """How much of the item this look showed, to choose among looks at an item that has not
        moved: first whether its mask is whole (clear of the image's edges: one the edge cuts is a
        part of it), then its pixels (a near look's box is the item's; a far look's few pixels
        make a box its mask's rim errors widen by a large share: a knife 2.2 cm wide measured 6
        cm from 58 pixels at 1.5 m, 2.6 cm from 519 at 0.7 m)."""
        mask = self.frame.mask(self.name)
        if mask is None:
            return False, 0
        return not at_edge(mask), int(np.count_nonzero(mask))

    def corners(self) -> np.ndarray:
        """The eight corners of its box, turned to its longer side when the look measured that."""
        xy = self.outline if self.outline is not None else \
            [(x, y) for x in (self.lo[0], self.hi[0]) for y in (self.lo[1], self.hi[1])]
        return np.array([[x, y, z] for x, y in xy for z in (self.lo[2], self.hi[2])])


def seen_from(frame: Frame, name: str) -> Seen | None:
    """An item's geometry from one identified frame (the detection named ``name``), or None when
    the frame does not show it (enough)."""
    d = frame.detection(name)
    cloud = instance_cloud(frame, d) if d is not None else None
    if cloud is None:
        return None
    pts = in_front(np.asarray(cloud.points), frame.camera_pose)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    xy = pts[:, :2] - pts[:, :2].mean(axis=0)
    evals, evecs = np.linalg.eigh(np.cov(xy.T) if len(xy) > 2 else np.eye(2))
    major = evecs[:, 1]
    along = xy @ evecs  # the points in the (minor, major) axes
    a0, a1 = along.min(axis=0), along.max(axis=0)
    mid = pts[:, :2].mean(axis=0)
    outline = np.array([mid + evecs @ np.array([u, v]) for u in (a0[0], a1[0]) for v in (a0[1], a1[1])])
    return Seen(name, pts.mean(axis=0), lo, hi, math.atan2(major[1], major[0]),
                bool(evals[1] < 1.6 * max(evals[0], 1e-9)), frame, outline)


def in_front(pts: np.ndarray, camera_pose: np.ndarray) -> np.ndarray:
    """An item's points (map frame) without those behind it (:data:`BEHIND_SLACK`): no item is
    deeper along the view than it is wide across it plus the slack (a thing lying along the
    view's ray is seen from above, and spans the view's height)."""
    if len(pts) < 3:
        return pts
    cam = (pts - camera_pose[:3, 3]) @ camera_pose[:3, :3]  # in the camera frame: z along the view
    wide = float(np.max(np.ptp(cam[:, :2], axis=0)))
    keep = cam[:, 2] <= np.percentile(cam[:, 2], 5) + wide + BEHIND_SLACK
    return pts[keep] if keep.sum() >= 3 else pts


def seen_in_hand(frame: Frame, name: str, tcp: np.ndarray) -> Seen | None:
    """An item held in the hand as the frame shows it when its depth does not: a stereo camera
    returns nothing for a thing under its minimum range, as an item between the fingers is. The
    item's centre is at the tcp (the fingers close on it), so its mask's pixels, back-projected to
    the tcp's depth, give its size across the image; along the optical axis it is taken as thick
    as it is narrow across. None when the frame does not show it."""
    d = frame.detection(name)
    if d is None or frame.masks is None or frame.intrinsics is None or frame.camera_pose is None:
        return None
    rows, cols = np.nonzero(frame.masks == d.mask_id)
    if len(rows) < 3:
        return None
    fx, fy, cx, cy = frame.intrinsics
    inv = np.linalg.inv(frame.camera_pose)
    z = float((inv[:3, :3] @ tcp[:3, 3] + inv[:3, 3])[2])
    if z <= 0.0:
        return None
    pts = np.stack([(cols - cx) / fx * z, (rows - cy) / fy * z, np.full(len(rows), z)], axis=1)
    thick = float(min(np.ptp(pts[:, 0]), np.ptp(pts[:, 1]))) / 2
    pts = np.vstack([pts + (0.0, 0.0, dz) for dz in (-thick, thick)])
    world = pts @ frame.camera_pose[:3, :3].T + frame.camera_pose[:3, 3]
    lo, hi = world.min(axis=0), world.max(axis=0)
    return Seen(name, (lo + hi) / 2, lo, hi, 0.0, False, frame)


class Furniture:
    """One mapped piece of furniture in its own frame (x along its front, y out of it, z up)."""

    def __init__(self, info: FurnitureInfo) -> None:
        self.info = info
        x, y, yaw = info.pose
        self.origin = np.array([x, y, 0.0])
        self.front = np.array([math.cos(yaw), math.sin(yaw), 0.0])
        self.along = np.array([self.front[1], -self.front[0], 0.0])
        self.width, self.depth = info.footprint
        self.height = info.height or 0.0

    @property
    def name(self) -> str:
        return self.info.name

    def to_world(self, local) -> np.ndarray:
        """A point (x, y, z) in the furniture's frame, in the map frame."""
        lx, ly, lz = local
        return self.origin + self.along * lx + self.front * ly + np.array([0.0, 0.0, lz])

    def local(self, p) -> np.ndarray:
        """A map-frame point in the furniture's frame."""
        d = np.asarray(p, float) - self.origin
        return np.array([d @ self.along, d @ self.front, p[2]])

    def yaw(self) -> float:
        """The direction its front faces (rad, map frame)."""
        return math.atan2(self.front[1], self.front[0])

    def outer(self) -> Obb:
        """Its outer box (footprint by height) in the map frame."""
        R = np.column_stack([self.along, self.front, (0.0, 0.0, 1.0)])
        return Obb(self.to_world((0.0, 0.0, self.height / 2)), R, np.array([self.width, self.depth, self.height]) / 2)

    def solids(self) -> list[Obb]:
        """The piece as solid boxes, its cavity carved out (the walls and floor round it remain)."""
        cav = self.info.cavity
        if cav is None:
            return [self.outer(), *self.switch_box()]
        R = np.column_stack([self.along, self.front, (0.0, 0.0, 1.0)])
        w, d, h, t = self.width, self.depth, self.height, cav.wall
        z0, z1 = cav.z

        def box(x0, x1, y0, y1, zlo, zhi) -> Obb:
            c = self.to_world(((x0 + x1) / 2, (y0 + y1) / 2, (zlo + zhi) / 2))
            return Obb(c, R, np.array([x1 - x0, y1 - y0, zhi - zlo]) / 2)

        parts = [box(-w / 2, w / 2, -d / 2, d / 2, 0.0, z0)]  # below the cavity
        if z1 < h - 1e-3:
            parts.append(box(-w / 2, w / 2, -d / 2, d / 2, z1, h))  # above it
        parts += [box(-w / 2, -w / 2 + t, -d / 2, d / 2, z0, z1), box(w / 2 - t, w / 2, -d / 2, d / 2, z0, z1)]
        if cav.open == "front":
            parts.append(box(-w / 2, w / 2, -d / 2, -d / 2 + t, z0, z1))  # the back wall
        else:
            parts += [box(-w / 2, w / 2, -d / 2, -d / 2 + t, z0, z1), box(-w / 2, w / 2, d / 2 - t, d / 2, z0, z1)]
        return parts + self.switch_box()

    def switch_box(self) -> list[Obb]:
        """The switch standing out of the front (where the map puts its face), as a small box."""
        if self.info.switch is None:
            return []
        R = np.column_stack([self.along, self.front, (0.0, 0.0, 1.0)])
        face = np.asarray(self.info.switch, float)
        return [Obb(face - self.front * SWITCH[1], R, np.array(SWITCH))]

    def top_point(self) -> np.ndarray:
        """The middle of its top (map frame)."""
        return self.to_world((0.0, 0.0, self.height))

    def in_front_cavity(self, p) -> bool:
        """Whether ``p`` lies in this piece's front-opening hollow (seen only from its level)."""
        cav = self.info.cavity
        if cav is None or cav.open != "front":
            return False
        lx, ly, lz = self.local(p)
        t = cav.wall  # inside its walls (a point on the front, where the leaf is, is not in it)
        return abs(lx) < self.width / 2 - t and abs(ly) < self.depth / 2 - t and cav.z[0] <= lz <= cav.z[1]

    def sight_over_rim(self, p, eye_height: float, toward) -> float:
        """How far from ``p`` (horizontally, in the direction ``toward``) an eye ``eye_height``
        high still sees the hollow's floor under ``p`` over the rim of this piece's top-open
        hollow (what is in it may lie on its floor, whatever height belief gives it): the near
        wall hides the bottom of a deep basket from a camera further off. Infinite when ``p`` is
        in no such hollow (or the eye is no higher than the rim)."""
        cav = self.info.cavity
        if cav is None or cav.open != "top":
            return math.inf
        lx, ly, lz = self.local(p)
        half = np.array([self.width / 2 - cav.wall, self.depth / 2 - cav.wall])
        rim = cav.z[1]
        if not (abs(lx) < half[0] and abs(ly) < half[1] and cav.z[0] <= lz < rim) or eye_height <= rim:
            return math.inf
        d = np.array([np.asarray(toward, float) @ self.along, np.asarray(toward, float) @ self.front])
        d /= max(float(np.linalg.norm(d)), 1e-9)
        pos = np.array([lx, ly])
        # horizontal way from p to the near wall's inner face, along d
        wall = min((half[k] - np.sign(d[k]) * pos[k]) / abs(d[k]) for k in range(2) if abs(d[k]) > 1e-9)
        floor = cav.z[0]
        return float(wall * (eye_height - floor) / (rim - floor))


class Leaf:
    """A door leaf or drawer as the map describes its motion; ``q`` is its joint value. ``turn``:
    the map's articulation has been turned by this much about the vertical (a correction of the
    map, :mod:`skills.registration`), and the leaf's box with it (its half sizes stay along the
    leaf's own axes)."""

    def __init__(self, name: str, art: Articulation, turn: float = 0.0) -> None:
        self.name, self.art = name, art
        self.origin, self.axis = np.array(art.origin), np.array(art.axis)
        self.base = se3.axis_angle(np.array([0.0, 0.0, 1.0]), turn)
        self.fitted_offset = (0.0, 0.0, 0.0)  # see :meth:`fit`

    def transform(self, q: float, q_from: float = 0.0):
        """How the leaf moves from joint value ``q_from`` to ``q``: the rotation and the point map (about
        the hinge, or along the slide) that take a leaf point at ``q_from`` to where it is at ``q``."""
        if self.art.prismatic:
            shift = self.axis * (q - q_from)
            return np.eye(3), (lambda p: np.asarray(p) + shift)
        R = se3.axis_angle(self.axis, q - q_from)
        return R, (lambda p: self.origin + R @ (np.asarray(p) - self.origin))

    def box(self, q: float) -> Obb:
        """The leaf's box in the map frame at joint value ``q``."""
        R, move = self.transform(q)
        return Obb(move(np.array(self.art.leaf_center)), R @ self.base, np.array(self.art.leaf_half))

    def panel(self, q: float) -> Obb:
        """The leaf (or drawer) without its handles at joint value ``q``: what a hand near the
        bar must not touch."""
        art = self.art
        normal, n = np.array(art.normal), np.abs(art.normal)
        centre, half = np.array(art.leaf_center), np.array(art.leaf_half)
        front = float(np.array(art.handle) @ normal) - HANDLE_STANDOUT
        back = float(centre @ normal - half @ n)
        if art.other_side is not None:
            back = max(back, front - art.other_side + 2 * HANDLE_STANDOUT)
        return self._slab(front, back, q)

    def face(self, q: float) -> Obb:
        """The front of the panel at joint value ``q``, ``FACE_THICKNESS`` deep: what hides the
        inside of the piece from a camera in front of it."""
        front = float(np.array(self.art.handle) @ np.array(self.art.normal)) - HANDLE_STANDOUT
        return self._slab(front, front - FACE_THICKNESS, q)

    def _slab(self, front: float, back: float, q: float) -> Obb:
        """The leaf's box at ``q`` cut to between ``front`` and ``back`` along its outward normal
        (as at q = 0)."""
        normal = np.array(self.art.normal)
        n = np.abs(self.base.T @ normal)  # the normal along the leaf's own axes
        centre, half = np.array(self.art.leaf_center), np.array(self.art.leaf_half)
        c = centre + normal * ((front + back) / 2 - float(centre @ normal))
        h = half * (1 - n) + n * (front - back) / 2
        R, move = self.transform(q)
        return Obb(move(c), R @ self.base, h)

    def fit(self, pts: np.ndarray, eye: np.ndarray | None, believed: float | None = None,
            slack: tuple[tuple[float, float, float], ...] = ((0.0, 0.0, 0.0),)) -> float | None:
        """The joint value that best explains ``pts`` (the piece's points, seen from ``eye``), or
        None when no joint value puts the leaf on any of them. A joint value is supported by the
        points on its leaf's box and contradicted (a hinged leaf :data:`THROUGH_WEIGHT` times as
        strongly) by the points the camera saw through the leaf's face there: the carcass's front
        edge lies where a closed leaf would be, so the points on it alone would call a wide-open
        fridge closed, but a closed leaf would have hidden the inside of the cavity the camera
        sees. With ``believed`` (where the leaf is thought to stand), the best value must explain :data:`LEAF_REFIT_POINTS` more points than the belief
        does, else the belief stands: a frame that shows only a leaf's foot or edge explains a few
        points either way, and the ties and near-ties between such values are not evidence.
        ``slack``: planar offsets (dx, dy, dθ about the hinge) the points may lie off the map's
        leaf by (a localisation error the map was not corrected for): each joint value scores its
        best offset."""
        lo, hi = sorted((self.art.lower, self.art.upper))
        values = np.linspace(lo, hi, DOOR_FIT_STEPS + 1)
        score = np.full(len(values), -np.inf)
        which = [(0.0, 0.0, 0.0)] * len(values)
        anything = False
        for dx, dy, dth in slack:
            c, s = math.cos(-dth), math.sin(-dth)
            p = np.asarray(pts, float).copy()
            xy = p[:, :2] - self.origin[:2] - (dx, dy)
            p[:, 0], p[:, 1] = c * xy[:, 0] - s * xy[:, 1] + self.origin[0], s * xy[:, 0] + c * xy[:, 1] + self.origin[1]
            e = None if eye is None else np.array([*(np.array([[c, -s], [s, c]]) @ (np.asarray(eye)[:2] - self.origin[:2] - (dx, dy))
                                                     + self.origin[:2]), eye[2]])
            on = np.array([int(self.box(q).contains(p, LEAF_MARGIN).sum()) for q in values])
            if on.max() == 0:
                continue
            anything = True
            through = np.zeros_like(on) if e is None else np.array(
                [int(seen_through(self.face(q), e, p, LEAF_MARGIN).sum()) for q in values])
            support = on - (1 if self.art.prismatic else THROUGH_WEIGHT) * through
            better = support > score
            which = [(dx, dy, dth) if b else w for b, w in zip(better, which)]
            score = np.where(better, support, score)
        if not anything:
            return None
        best = int(np.argmax(score))
        #: the offset the best joint value was found at (dx, dy, dθ about the hinge)
        self.fitted_offset = which[best]
        if believed is not None:
            now = int(np.argmin(np.abs(values - believed)))
            if score[best] - score[now] < LEAF_REFIT_POINTS:
                return believed
        return float(values[best])

    def handle_at(self, q: float, side: float = 1.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Handle grasp point, outward face normal and bar direction at joint value ``q`` (``side``
        -1: the handle on the other face of a room door)."""
        R, move = self.transform(q)
        normal = np.array(self.art.normal)
        centre = np.array(self.art.handle) if side > 0 else np.array(self.art.handle) - normal * self.art.other_side
        return move(centre), R @ (normal * side), R @ np.array(self.art.bar)


class SceneModel:
    """The map's geometry for planning, and perception's answers about where things are now."""

    def __init__(self, site: SiteMap) -> None:
        self.raw = site  # the map as the localiser places it
        #: how the map lies in the robot's frame from where it stands (none: as the localiser says)
        self.correction = Correction.none()
        self.registration = RegistrationParams()
        #: the correction as registered, and the body's mark then (localiser and wheels)
        self._registered: tuple[Correction, tuple[np.ndarray, np.ndarray]] | None = None
        #: the body's mark now, and the 4x4 carrying a point from a mark to now (set by the kit;
        #: without them a correction holds only until the base moves)
        self.mark = None
        self.since = None
        #: leaves whose handle a look showed lying off the map as corrected (:meth:`fix_handle`):
        #: where each leaf's map lies in the robot's frame now, and as measured, with the mark
        #: then (carried by the wheels, as the correction is)
        self.handle_fixes: dict[str, Correction] = {}
        self._fixed: dict[str, tuple[Correction, tuple[np.ndarray, np.ndarray] | None]] = {}
        #: told when the map's geometry changed (a correction taken or dropped)
        self.changed = lambda: None
        self._build(site)
        self.joint: dict[str, float] = {}  # where each leaf was last seen or left
        #: items last seen lying on the floor, as boxes: the base keeps off them (a drive into a
        #: dropped cup kicks it under the furniture, where no look finds it again)
        self.floor_items: dict[str, Obb] = {}

    def _build(self, site: SiteMap) -> None:
        fixes = self.handle_fixes
        # a piece whose handle a look placed is laid by its own correction, from the map as the
        # localiser places it: its carcass with its leaf (a leaf moved alone into its carcass was
        # fitted a third open by the next look)
        raw = {f.name: f for f in self.raw.furniture}
        site = replace(site, furniture=tuple(corrected_piece(raw[f.name], fixes[f.name]) if f.name in fixes else f
                                             for f in site.furniture))
        self.site = site
        turn = self.correction.dtheta
        self.furniture = {f.name: Furniture(f) for f in site.furniture if f.pose is not None and f.footprint}
        self.leaves = {f.name: Leaf(f.name, f.articulation, fixes[f.name].dtheta if f.name in fixes else turn)
                       for f in site.furniture if f.articulation}
        for d in site.doors:
            if d.articulation is not None:
                # a room door's leaf alone (its map is not turned with the correction: corrected_map)
                fix = fixes.get(d.name)
                self.leaves[d.name] = Leaf(d.name, d.articulation) if fix is None else \
                    Leaf(d.name, corrected_articulation(self.raw.door(d.name).articulation, fix), fix.dtheta)
        self.changed()

    def _leaf_correction(self, name: str) -> Correction:
        """How ``name``'s leaf lies in the robot's frame now: its handle's fix, else the map's
        correction (a room door: its shift only, :func:`corrected_map`)."""
        if name in self.handle_fixes:
            return self.handle_fixes[name]
        return translation(self.correction) if self.site.door(name) is not None else self.correction

    # -- where the map lies from here ----------------------------------------------------------

    def relocalize(self, frame: Frame) -> Correction | None:
        """Register the map's furniture to the frame's points of it (:func:`register`); when the
        fit holds, the map is used shifted by it from now on, carried across the base's motions
        (:meth:`base_moved`). Returns the correction, or None (nothing changes)."""
        raw = {f.name: Furniture(f) for f in self.raw.furniture if f.pose is not None and f.footprint}
        leaves = {f.name: Leaf(f.name, f.articulation) for f in self.raw.furniture if f.articulation}
        clouds, models = {}, {}
        for d in frame.detections:
            if d.name not in raw:
                continue
            cloud = instance_cloud(frame, d)
            if cloud is None:
                continue
            pts = np.asarray(cloud.points)
            if d.name in leaves:
                # the map is laid by what does not move: a leaf stands where it was last seen, as
                # far as anyone knows, and a fit that takes it for fixed slides the map along its
                # travel (a drawer pulled open, alone in view, moved the map 11 cm on exact depth)
                pts = pts[~leaves[d.name].box(self.joint.get(d.name, 0.0)).contains(pts, LEAF_CUT)]
            clouds[d.name] = pts
            models[d.name] = raw[d.name].solids()
        c = register(clouds, models, self.registration)
        if c is None:
            return None
        self._registered = (c, self._mark())
        self.correction = c
        self._build(corrected_map(self.raw, c))
        return c

    def _mark(self) -> tuple[np.ndarray, np.ndarray] | None:
        return self.mark() if self.mark is not None else None

    def _carried(self, c: Correction, mark) -> Correction | None:
        """``c``, taken at ``mark``, as it lies in the robot's frame now (carried by the wheels'
        motion since); None once the base has gone :data:`ODOMETRY_HOLD` from there, or when
        the body keeps no marks."""
        if mark is None or self.since is None:
            return None
        _, odom_then = mark
        _, odom_now = self.mark()
        if float(np.linalg.norm(odom_now[:2, 3] - odom_then[:2, 3])) > ODOMETRY_HOLD:
            return None
        return c.moved(self.since(mark))

    def base_moved(self) -> None:
        """The base moved: the correction, and each leaf's handle fix, is carried along by the
        wheels' motion (the localiser's frame may have jumped: a fridge's handle fixed from one
        stance was 14 cm off after the drive to the grasp stance), and dropped once the base has
        gone :data:`ODOMETRY_HOLD` from where it was measured; the map (the leaf) is then used as
        the localiser places it."""
        if self.correction.is_identity() and not self._fixed:
            return
        carried = {n: self._carried(*f) for n, f in self._fixed.items()}
        self.handle_fixes = {n: c for n, c in carried.items() if c is not None}
        self._fixed = {n: f for n, f in self._fixed.items() if carried[n] is not None}
        c = None if self._registered is None else self._carried(*self._registered)
        if c is None:
            self._registered = None
        self.correction = c or Correction.none()
        self._build(corrected_map(self.raw, self.correction))

    # -- where things are, by the map --------------------------------------------------------

    def note_items(self, frame: Frame, held: str | None = None) -> None:
        """Remember where the frame shows items lying on the floor (their points reach down to
        it and stay low); an item the frame shows anywhere else — or the one in the hand — is no
        longer on the floor. The frame is an identified one: an item nobody named (a thing of a
        class no goal was about, or a false positive) is remembered by class and place
        (:func:`anonymous_key`), one seen again near where it was replacing the old entry."""
        if held is not None:
            self.floor_items.pop(held, None)
        mapped = self.site.static_names()
        fixed = {label_of(n, self.site) for n in mapped}  # furniture and doors: the map's, never on the floor
        for d in frame.detections:
            if d.name in mapped or (d.name and d.name == held) or (not d.name and d.label in fixed):
                continue
            cloud = instance_cloud(frame, d)
            if cloud is None or not len(cloud.points):
                continue
            pts = self.unmapped(np.asarray(cloud.points))
            if len(pts) < MAP_LEFT_LEAST:
                if d.name:
                    self.floor_items.pop(d.name, None)
                continue  # what the map already holds (a mask spilled onto a leaf, a false positive on it)
            lo, hi = pts.min(axis=0), pts.max(axis=0)
            key = d.name or self._anonymous_key(d.label, (lo + hi) / 2)
            rise = float(np.quantile(pts[:, 2], FLOOR_ITEM_QUANTILE))  # not the highest: noise lifts a few
            if lo[2] < FLOOR_TOUCH and FLOOR_ITEM_LEAST < rise and hi[2] < FLOOR_ITEM_TOP:
                self.floor_items[key] = Obb.aabb((lo[0], lo[1], 0.0), (hi[0], hi[1], hi[2]))
            else:
                self.floor_items.pop(key, None)

    def taken(self, name: str, lo, hi) -> None:
        """The hand took ``name``, measured between ``lo`` and ``hi``: it is on the floor no more,
        under its name nor as any unnamed item a look remembered where it stood — a detection
        of it that went unnamed, of its class or another the detector gave it, was it. Left
        there, such ghosts kept the base off the spot the cup was taken from, which was the work
        pose in front of the tap (boil_water seed 7: '?cup#0', '?bottle#0' and '?mug#0' where the
        cup had lain, the fill's drive there refused every time: "no clear way")."""
        self.floor_items.pop(name, None)
        spot = Obb.aabb((lo[0], lo[1], 0.0), (hi[0], hi[1], max(hi[2], lo[2]))).polygon()
        for key in [k for k, box in self.floor_items.items()
                    if k.startswith(ANONYMOUS) and not apart(spot, box.polygon(), TAKEN_SLACK)]:
            del self.floor_items[key]

    def unmapped(self, pts: np.ndarray) -> np.ndarray:
        """Those of ``pts`` that no mapped solid explains — walls, furniture, leaves where they are
        believed — within :data:`MAP_SLACK`: the obstacle layer holds what the map does not. A
        detection of a log on a room door's open leaf (the detector's false positive, its points
        the leaf's foot) was remembered as a log on the floor beside the leaf, and no way past the
        leaf was clear (store_firewood on real sensors)."""
        if not len(pts):
            return pts
        boxes = self.walls() + [b for f in self.furniture.values() for b in f.solids()] + self.leaf_boxes()
        mapped = np.zeros(len(pts), bool)
        for b in boxes:
            mapped |= b.contains(pts, MAP_SLACK)
        return pts[~mapped]

    def _anonymous_key(self, label: str, centre: np.ndarray) -> str:
        """The key of an unnamed item of class ``label`` at ``centre``: that of one remembered
        within ``ANONYMOUS_NEAR`` of it, else a new one."""
        for key, box in self.floor_items.items():
            if key.startswith(f"{ANONYMOUS}{label}#") and np.linalg.norm(box.center[:2] - centre[:2]) < ANONYMOUS_NEAR:
                return key
        k = 0
        while f"{ANONYMOUS}{label}#{k}" in self.floor_items:
            k += 1
        return f"{ANONYMOUS}{label}#{k}"

    def note_leaves(self, frame: Frame) -> None:
        """Fit the leaf of every piece of furniture the frame shows, against where it is believed
        to stand (:meth:`fit_leaf` with ``gated``): a door the hand let go of may swing, or be
        knocked shut, after the action that set it. A fridge door that closed after a takeout was
        still believed open, and the arm's way to the pie on the floor in front of it went
        through the door as it really stood (heat_pie, seed 0 with injection). A glance changes
        the belief only on clear evidence (:data:`LEAF_REFIT_POINTS`): ungated, a frame showing
        only a leaf's foot called an open fridge or cabinet door closed. Room doors are fitted
        where a trip looks at them: only their own view shows enough of them."""
        for d in frame.detections:
            if d.name in self.leaves and self.site.door(d.name) is None:
                self.fit_leaf(d.name, frame, gated=True)

    def low_obstacles(self, base_now=None) -> list[np.ndarray]:
        """Outlines of the items on the floor, for the base alone (the arm passes over them);
        one the base at ``base_now`` already touches is left out: the way off it must stay open."""
        here = None if base_now is None else footprint(base_now)
        polys = [b.polygon() for b in self.floor_items.values()]
        return [p for p in polys if here is None or apart(here, p, LOW_MARGIN)]

    def in_front_cavity(self, p) -> bool:
        """Whether ``p`` lies in the hollow of a front-opening container (a microwave, a cabinet):
        a camera sees into it only from about its height, never from above its top."""
        return any(f.in_front_cavity(p) for f in self.furniture.values())

    def sight_over_rim(self, p, eye_height: float, toward) -> float:
        """How far off ``p`` horizontally (towards ``toward``) an eye ``eye_height`` high still
        sees it, when it lies in a top-open hollow (:meth:`Furniture.sight_over_rim`)."""
        return min((f.sight_over_rim(p, eye_height, toward) for f in self.furniture.values()), default=math.inf)

    def room_at(self, x: float, y: float) -> str | None:
        """The mapped room whose outline holds (x, y), or None."""
        return self.site.room_at(x, y)

    def room_center(self, room: str) -> np.ndarray:
        """The middle of room ``room``'s outline (x, y); the room must have geometry."""
        x0, y0, x1, y1 = self.site.room(room).bounds
        return np.array([(x0 + x1) / 2, (y0 + y1) / 2])

    def corridor_y(self) -> float:
        """The free middle line of the house (the rooms stand in a row along x)."""
        ys = [(r.bounds[1] + r.bounds[3]) / 2 for r in self.site.rooms if r.bounds]
        return float(np.mean(ys))

    def walls(self) -> list[Obb]:
        """The rooms' outlines as wall boxes, with the doorways left open."""
        out, t = [], WALL_THICKNESS
        gaps = [(d.pose[0], d.pose[1] - d.width / 2, d.pose[1] + d.width / 2) for d in self.site.doors if d.pose]
        for r in self.site.rooms:
            if r.bounds is None:
                continue
            x0, y0, x1, y1 = r.bounds
            out += [Obb.aabb((x0, y0 - t / 2, 0), (x1, y0 + t / 2, WALL_HEIGHT)),
                    Obb.aabb((x0, y1 - t / 2, 0), (x1, y1 + t / 2, WALL_HEIGHT))]
            for x in (x0, x1):
                y = y0
                for g0, g1 in sorted((a, b) for gx, a, b in gaps if abs(gx - x) < 1e-6):
                    if g0 > y:
                        out.append(Obb.aabb((x - t / 2, y, 0), (x + t / 2, g0, WALL_HEIGHT)))
                    y = max(y, g1)
                if y < y1:
                    out.append(Obb.aabb((x - t / 2, y, 0), (x + t / 2, y1, WALL_HEIGHT)))
        return out

    def leaf_boxes(self, skip: str | None = None) -> list[Obb]:
        """Every door leaf and drawer where it was last seen (closed when never seen otherwise)."""
        return [leaf.box(self.joint.get(name, 0.0)) for name, leaf in self.leaves.items() if name != skip]

    def door_leaf_polygons(self) -> list[np.ndarray]:
        """The room doors' leaves where they were last seen, from above (no arm reaches over one:
        they stand as tall as the walls; an appliance's door or a drawer it may reach over)."""
        return [leaf.box(self.joint.get(name, 0.0)).polygon() for name, leaf in self.leaves.items()
                if self.site.door(name) is not None]

    def tall_leaf_polygons(self, above: float) -> list[np.ndarray]:
        """Every leaf that stands higher than ``above`` (m) where it was last seen, from above: a
        room door's, and a piece's door as tall (a fridge's, a cabinet's: struck, it swings shut),
        not an oven's let down nor a drawer, which an arm reaches over."""
        boxes = [leaf.box(self.joint.get(name, 0.0)) for name, leaf in self.leaves.items()]
        return [b.polygon() for b in boxes if float(b.corners()[:, 2].max()) > above]

    def obstacles(self, moving: str | None = None) -> list[np.ndarray]:
        """What the base must keep off, seen from above: walls, furniture, door leaves as they
        stand (except ``moving``'s, which the planner places itself)."""
        boxes = self.walls() + [f.outer() for f in self.furniture.values()] + self.leaf_boxes(moving)
        return [b.polygon() for b in boxes]

    def floors(self) -> list[Obb]:
        """The rooms' floors as slabs under their outlines (their tops at z = 0)."""
        return [Obb.aabb((r.bounds[0], r.bounds[1], -FLOOR_THICKNESS), (r.bounds[2], r.bounds[3], 0.0))
                for r in self.site.rooms if r.bounds is not None]

    def solid_boxes(self, moving: str | None = None) -> SceneBoxes:
        """What the arm must keep clear of: walls, floors, furniture with its cavities carved out,
        leaves."""
        named = [(f"wall{i}", b) for i, b in enumerate(self.walls())]
        named += [(f"floor{i}", b) for i, b in enumerate(self.floors())]
        named += [(f"{f.name}:{k}", b) for f in self.furniture.values() for k, b in enumerate(f.solids())]
        named += [(f"leaf:{n}", leaf.box(self.joint.get(n, 0.0))) for n, leaf in self.leaves.items() if n != moving]
        return SceneBoxes(np.array([b.pose() for _, b in named]).reshape(-1, 4, 4),
                          np.array([2 * b.half for _, b in named]).reshape(-1, 3), tuple(n for n, _ in named))

    # -- where things are, by looking ----------------------------------------------------------

    @staticmethod
    def sees_through(frame: Frame, points, beyond: float = SEE_THROUGH) -> bool | None:
        """Whether the frame's depth reaches ``beyond`` past most of ``points`` (the view goes
        through an open doorway into the next room); None when no point is in the frame with a
        depth return. A point whose pixel shows something far nearer than the point is not
        counted: the robot's own hand, or what it holds, hides it, and says nothing of the way."""
        if frame.depth is None or frame.intrinsics is None or frame.camera_pose is None:
            return None
        fx, fy, cx, cy = frame.intrinsics
        inv = np.linalg.inv(frame.camera_pose)
        h, w = frame.depth.shape
        votes = []
        for point in np.atleast_2d(np.asarray(points, float)):
            p = inv[:3, :3] @ point + inv[:3, 3]
            if p[2] <= 0.05:
                continue
            u, v = int(round(fx * p[0] / p[2] + cx)), int(round(fy * p[1] / p[2] + cy))
            if not (2 <= u < w - 2 and 2 <= v < h - 2):
                continue
            window = frame.depth[v - 2:v + 3, u - 2:u + 3]
            returns = window[window > 0]
            if returns.size == 0 or np.median(returns) < HIDDEN_SHARE * p[2]:
                continue
            votes.append(bool(np.median(returns) > p[2] + beyond))
        return None if not votes else 2 * sum(votes) > len(votes)

    def fit_leaf(self, name: str, frame: Frame, hint: float | None = None, gated: bool = False,
                 handle: bool | None = None) -> float | None:
        """The joint value of ``name``'s leaf that best explains the frame's points of its piece
        of furniture (or door) (:meth:`Leaf.fit`), or ``hint`` when the frame does not show it.
        ``gated``: the believed value stands unless the frame clearly explains another better
        (a passing glance, or a second look from close by). ``handle``: the leaf's handle is
        placed where the frame shows it (:meth:`fix_handle`; by default a room door's when not
        ``gated``)."""
        leaf = self.leaves.get(name)
        d = frame.detection(name)
        cloud = instance_cloud(frame, d) if (leaf is not None and d is not None) else None
        if cloud is None:
            return hint
        eye = None if frame.camera_pose is None else np.asarray(frame.camera_pose)[:3, 3]
        # a room door is fitted allowing for the localiser's error: the map is registered to the
        # furniture in view, and a door is often seen with none, or far from what is
        door = self.site.door(name) is not None
        slack = DOOR_SLACK if door else ((0.0, 0.0, 0.0),)
        q = leaf.fit(np.asarray(cloud.points), eye, self.joint.get(name, 0.0) if gated else None, slack)
        if q is None:
            return hint
        self.joint[name] = q
        if (door and not gated) if handle is None else handle:
            self.fix_handle(name, frame)
            q = self.joint[name]  # the handle's face may have said the leaf stands a little further
        return q

    def fix_handle(self, name: str, frame: Frame, q: float | None = None) -> None:
        """Where the leaf's handle is, as the frame shows it: among the piece's points near where
        the map (as the fit placed the leaf) puts the handle, the leaf's face is the plane most of
        them lie on, and the bar is what stands out of it by :data:`BAR_STANDOUT`; the leaf is
        then shifted so that its handle is the bar seen (a room door, ``door``, also turned to the
        face's normal). A robot's localiser is a few centimetres and a couple of degrees off, two
        metres away that is up to 15 cm, and the fingers must close round a 2.4 cm bar; no
        furniture registration reaches a door across the room. Nor does it place a fridge's
        handle: the door, which fills the front, is left out of the fit (it moves), and the 4-cm
        side walls left slid the map 5 cm along the front — the fingers closed beside the bar.
        The leaf stands at ``q``, by default as last fitted (:meth:`fit_leaf`). The bar is looked
        for among the piece's pixels when the detector found it, else among all: where the map
        puts it, the depth alone shows a face and a bar (the detector missed a fridge filling the
        picture)."""
        leaf = self.leaves.get(name)
        if leaf is None or frame.depth is None:
            return
        d = frame.detection(name)
        mask = frame.masks == d.mask_id if d is not None and frame.masks is not None else np.ones(frame.depth.shape, bool)
        q = self.joint.get(name, 0.0) if q is None else q
        door = self.site.door(name) is not None
        pts = np.asarray(backproject(frame.depth, mask, frame.intrinsics, frame.camera_pose, HANDLE_SEARCH_RANGE).points)
        eye = np.asarray(frame.camera_pose)[:3, 3]
        for side in ((1.0, -1.0) if leaf.art.other_side is not None else (1.0,)):
            p, n, bar = leaf.handle_at(q, side)
            if (eye - p) @ n <= 0.0:
                continue  # that face is turned away from the camera
            near = pts[np.linalg.norm(pts - p, axis=1) < HANDLE_SEARCH]
            if len(near) < HANDLE_MIN_POINTS:
                return
            out = (near - p) @ n
            face = float(np.median(out))  # most of what is near the handle is the leaf's face
            on_face = near[np.abs(out - face) < BAR_FACE_BAND]
            stands = near[(out - face > BAR_STANDOUT[0]) & (out - face < BAR_STANDOUT[1])]
            if len(stands) < HANDLE_MIN_BAR or len(on_face) < HANDLE_MIN_POINTS:
                return
            # the face's normal from its points (the least spread), turned the way the map's faces
            xy = on_face[:, :2] - on_face[:, :2].mean(axis=0)
            w, v = np.linalg.eigh(xy.T @ xy)
            seen_n = v[:, 0] if v[:, 0] @ n[:2] > 0 else -v[:, 0]
            turn = math.atan2(n[0] * seen_n[1] - n[1] * seen_n[0], float(n[:2] @ seen_n))
            if door and not leaf.art.prismatic and abs(turn) <= DOOR_TURN_FIX:
                # the leaf stands turned by that much more than the fit said: a joint value a few
                # steps off (seen edge-on, an open leaf is hard to fit), which the localiser's
                # degree or two would not explain
                q = q + turn * float(np.sign(leaf.axis[2]) or 1.0)
                self.joint[name] = q
                p, n, bar = leaf.handle_at(q, side)
            # a room door's bar is placed by its points' mean, as since the doors' fix was
            # written: measured as a furniture leaf's, the hand closed 3 mm nearer the leaf, and
            # after a slip injected on door_lg the loose fingers went on to push it wide open
            shift = np.array([*(stands.mean(axis=0) - p)[:2], 0.0]) if door else bar_offset(stands, p, n, bar, face)
            if shift is None or math.hypot(shift[0], shift[1]) > self.registration.max_shift:
                return
            if not door and math.hypot(shift[0], shift[1]) < HANDLE_LEAST:
                return  # within the measure's own error: the leaf stays where the map has it
            # carried onto the bar seen: the leaf as it lay (corrected, or fixed before) moved by it
            fix = Correction(float(shift[0]), float(shift[1]), 0.0, (float(p[0]), float(p[1])), len(near), (name,), 1.0)
            leaf_now = self._leaf_correction(name).moved(fix.matrix())
            self.handle_fixes[name] = leaf_now
            self._fixed[name] = (leaf_now, self._mark())
            self._build(corrected_map(self.raw, self.correction))
            return


def bar_offset(pts: np.ndarray, p: np.ndarray, n: np.ndarray, bar: np.ndarray, face: float) -> np.ndarray | None:
    """How far (horizontally) a handle's bar seen as the points ``pts`` lies from where the map
    has it, ``p`` on a leaf facing ``n``, the bar along ``bar``, the face seen ``face`` along
    ``n`` from ``p``. Along the normal: the face seen against the map's face,
    :data:`HANDLE_STANDOUT` behind the bar (the bar's own points are its front and a side).
    Across the face, for an upright bar: the middle of the points' extent, not their mean (the
    bar's side seen obliquely lies at its edge, and the mean leaned 1.7 cm towards the camera on
    exact depth); a level bar is grasped anywhere along it, and a view that cuts it (at the
    picture's edge, or the search's) would move its middle. None for a face looking up or down (a
    dropped oven door), which has no horizontal across."""
    across = np.cross((0.0, 0.0, 1.0), n)
    if np.linalg.norm(across) < 0.5:
        return None
    across /= np.linalg.norm(across)
    normal = np.array([n[0], n[1], 0.0]) / np.linalg.norm(n[:2])
    shift = normal * (face + HANDLE_STANDOUT)
    if abs(float(np.asarray(bar) @ across)) < 0.5:
        lo, hi = np.percentile((pts - p) @ across, BAR_EXTENT)
        shift = shift + across * (lo + hi) / 2
    return shift


def seen_through(box: Obb, eye: np.ndarray, pts: np.ndarray, short: float) -> np.ndarray:
    """Which of ``pts`` (seen from ``eye``) the camera saw through ``box``: the sight line to the
    point crosses it before ending ``short`` of the point (a point on the box's own face is not
    seen through it)."""
    pts = np.asarray(pts, float)
    a = (np.asarray(eye, float) - box.center) @ box.R
    b = (pts - box.center) @ box.R
    length = np.linalg.norm(b - a, axis=1)
    end = np.clip(1.0 - short / np.maximum(length, 1e-9), 0.0, 1.0)
    d = b - a  # sight lines in the box's frame, a + t d for t in [0, end]
    with np.errstate(divide="ignore", invalid="ignore"):
        t1, t2 = (-box.half - a) / d, (box.half - a) / d
    flat = np.abs(d) < 1e-12  # parallel to a slab: inside it throughout or never
    inside = np.abs(a) <= box.half
    t_lo = np.where(flat, np.where(inside, -np.inf, np.inf), np.minimum(t1, t2)).max(axis=1)
    t_hi = np.where(flat, np.where(inside, np.inf, -np.inf), np.maximum(t1, t2)).min(axis=1)
    return (t_lo <= t_hi) & (t_hi >= 0.0) & (t_lo <= end)
