"""The wrist camera as skills use it: aim it at a point, take a frame, measure an item in it.

The camera rides on the wrist and looks along the hand's approach axis, so aiming it is an arm
motion: a camera pose looking at the point from above the base (``CAMERA_EYE``, in the base
frame), solved by IK for the ``camera_optical`` frame and moved to like any other pose.

A held item is rigid in the camera's view — wherever the camera is aimed, the item shows in the
same part of the image. Looking at something past it therefore means turning the aim just
enough that the point shows beside the item (:meth:`Eyes.aim_past_held`); the item's box comes
from what the camera measured when the hand took it (:class:`Held`), never from the simulator.
The wrist camera is a stereo pair, and a thing this near (a hand's length, under its minimum
range) hides a wide band to its left from the right imager: the depth image has no returns
there, ``B·(1/z_item - 1/z)`` wide in normalised image units (a held knife 12 cm away blanks
everything left of it). The aim keeps the point out of that band too.

What skills learn from a frame is a :class:`~skills.scene_model.Seen`: where the item is, how
big, which way it lies — its masked depth fused into a point cloud. The camera's detector gives
class labels only; every frame the eyes take is named first (``identify``: the kit's
re-identification, :mod:`vap_bt.scene.identity`) — the map's furniture and doors by the map,
the item in the hand by the fingers, and the item a look is for by where it is believed to be
(:meth:`Eyes.measure`: the goal's hint).

A look again from the same camera pose is the same picture — the same detections, the same
misses (a detector's draw is the picture's, not the moment's) — so within one goal the eyes keep
the camera poses each item was looked for from (:class:`Views`), and a look again at an item goes
on to a view not yet taken for it: the eye raised, moved nearer, to either side, or back and low
(:data:`LOOKS`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import cv2
import numpy as np

from typing import Callable, Mapping

from skills.body import Body
from skills.scene_model import Seen, seen_from
from vap_bt.motion import se3
from vap_bt.robot.drivers import WristCamera
from vap_bt.robot.frame import Frame
from vap_bt.scene.identity import SEEN_RADIUS, Believed

#: where the camera looks from, in the base frame (above the base's front, the arm raised)
CAMERA_EYE = (0.50, 0.0, 1.20)
#: a camera aim turns off its point by one of these angles (rad) when the held item (or its stereo
#: shadow) covers it; the point then shows this far (normalised image units, ~4 degrees) outside
#: the item and the frame edge. Up to where the point reaches the frame's side (0.42 rad: the image
#: is 0.52 wide either way): a log held across the fingers fills the middle of the frame from top to
#: bottom, and only a turn that far shows past it (store_firewood seed 1: the basket behind the log
#: from every view, 4 % of it visible, which a detector does not find)
AIM_TURNS = (0.06, 0.1, 0.14, 0.18, 0.22, 0.26, 0.3, 0.34, 0.38, 0.42)
AIM_MARGIN = 0.07
#: an aim still counts as the last one when the camera moved less than this (m, rad); two camera
#: poses this near are one view (the same picture, in a world whose base stands still)
STILL = (0.03, 0.05)
#: the views a look for an item takes in turn, each (eye lift, eye moved towards the point, eye
#: moved across, left positive) in metres from the standard eye: the standard look and a raised
#: one (over something in front), then nearer, to either side, and back and low (a view from
#: above a standing bottle shows its top only; one from lower shows its side)
LOOKS = ((0.0, 0.0, 0.0), (0.2, 0.0, 0.0), (0.1, 0.25, 0.0), (0.1, 0.0, 0.25), (0.1, 0.0, -0.25),
         (-0.3, -0.3, 0.0), (0.3, 0.25, 0.0))
#: new views one measure takes at most when none shows the item (a look again from the same
#: place, after a base move that did not move the robot, goes on down :data:`LOOKS`)
VIEWS_PER_MEASURE = 3
#: an aim whose arm pose would hit the furniture is tried this much higher
RAISE = 0.15
#: the eye is at least this far above the point it looks at (a thin plate on a tall shelf is seen
#: from above, not edge-on), when the arm reaches that high
LOOK_OVER = 0.4
#: a point inside a front-opening hollow is looked at from this little above it (its roof is low)
LEVEL_OVER = 0.05
#: (cosine) a hand whose approach lies within 45 degrees of straight down an item's up holds it
#: over its top; a side grasp pitched down (0.6 rad) does not, a hand from above leaned back does
OVER_TOP = math.cos(math.pi / 4)
#: m: a held box is no thinner than this (a flat item seen from above measures no depth)
THINNEST = 0.005


def same_view(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether camera poses ``a`` and ``b`` (4x4) are one view: within :data:`STILL` of each
    other in place and in the direction they look."""
    return bool(np.linalg.norm(a[:3, 3] - b[:3, 3]) < STILL[0] and float(a[:3, 2] @ b[:3, 2]) > math.cos(STILL[1]))


class Views:
    """The camera poses each item was looked for from within one goal: a look again from one of
    them would be the same picture, and its detector's draw (a miss) the same again."""

    def __init__(self) -> None:
        self._taken: dict[str, list[np.ndarray]] = {}

    def clear(self) -> None:
        """Forget every view (a new goal: the world may have changed since)."""
        self._taken.clear()

    def add(self, name: str, pose: np.ndarray) -> None:
        """``name`` was looked for from camera pose ``pose`` (a frame was taken there)."""
        self._taken.setdefault(name, []).append(np.array(pose, float))

    def of(self, name: str) -> tuple[np.ndarray, ...]:
        """The camera poses ``name`` was looked for from in this goal."""
        return tuple(self._taken.get(name, ()))


@dataclass(frozen=True)
class Held:
    """What the hand holds, as the camera measured it when the hand took it: the item's box
    corners and its bottom, both in the tcp frame (they ride with the hand)."""

    name: str
    corners: np.ndarray  # (8, 3) in the tcp frame
    extent: np.ndarray  # box size (m)
    up: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]))  # the item's up when taken, in the tcp frame

    @classmethod
    def taken(cls, seen: Seen, tcp: np.ndarray, moved: np.ndarray | None = None) -> "Held":
        """The item as ``seen`` measured it, in the hand at ``tcp``; ``moved``: the 4x4 carrying
        the look's map frame to the one ``tcp`` is in (the base moved since the look)."""
        inv = np.linalg.inv(tcp) if moved is None else np.linalg.inv(tcp) @ moved
        pts = seen.corners() @ inv[:3, :3].T + inv[:3, 3]
        return cls(seen.name, pts, seen.extent, tcp[:3, :3].T @ np.array([0.0, 0.0, 1.0]))

    def upright(self, R: np.ndarray, toward) -> np.ndarray:
        """The hand's rotation that stands the item as it stood when taken, its approach axis
        turned as close to ``toward`` as that allows (looks since may have tilted it: the camera
        rides on the wrist). A vertical ``toward`` keeps the heading of ``R``."""
        u = self.up / np.linalg.norm(self.up)
        ez = np.array([0.0, 0.0, 1.0])
        axis = ez if abs(u @ ez) < 0.95 else np.array([1.0, 0.0, 0.0])  # tcp-frame reference
        v = axis - (axis @ u) * u
        v /= np.linalg.norm(v)
        d = np.asarray(toward, float)
        d = d - d[2] * ez
        if np.linalg.norm(d) < 1e-6 or abs(u @ ez) >= 0.95:  # keep the heading the hand has now
            d = R @ v
            d = d - d[2] * ez
        d /= np.linalg.norm(d)
        src = np.column_stack([u, v, np.cross(u, v)])
        dst = np.column_stack([ez, d, np.cross(ez, d)])
        return dst @ src.T

    def over_top(self) -> bool:
        """Whether the hand holds the item from above, over its top (a vessel's opening): its
        approach, the tcp's z, was nearer straight down the item's up than level when it took it."""
        return float(self.up[2]) < -OVER_TOP

    def corners_at(self, tcp: np.ndarray) -> np.ndarray:
        """The box's corners in the map frame for the hand at ``tcp``."""
        return self.corners @ tcp[:3, :3].T + tcp[:3, 3]

    def box(self) -> tuple[np.ndarray, np.ndarray]:
        """The item's box in the tcp frame: its centre's pose (4x4) and its size (no edge thinner
        than :data:`THINNEST`)."""
        c = self.corners
        axes = np.column_stack([c[4] - c[0], c[2] - c[0], c[1] - c[0]])  # corners as Seen.corners orders them
        lengths = np.linalg.norm(axes, axis=0)
        R = np.eye(3)
        if np.all(lengths > 1e-6):
            U, _, Vt = np.linalg.svd(axes / lengths)
            R = U @ Vt  # the nearest rotation (the edges of a measured box are square to each other)
            if np.linalg.det(R) < 0:  # a box turned to its outline may be mirrored: the same box, right-handed
                R[:, 2] = -R[:, 2]
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = R, c.mean(axis=0)
        return T, np.maximum(lengths, THINNEST)

    def below_tcp(self, tcp: np.ndarray) -> float:
        """How far the item's lowest corner hangs below the tcp (m), for the hand at ``tcp``."""
        return float(tcp[2, 3] - self.corners_at(tcp)[:, 2].min())


class Eyes:
    """Aim the wrist camera, take frames, and measure items in them."""

    def __init__(self, body: Body, camera: WristCamera, level_with=lambda point: False,
                 noticed=lambda frame, held: None,
                 identify: Callable[[Frame, Mapping[str, Believed], str | None], Frame] = lambda f, e, h: f) -> None:
        self.body, self.camera = body, camera
        self.level_with = level_with  # points seen only from their own height (inside a hollow)
        self.noticed = noticed  # told of every frame taken, and of the item in the hand
        #: names a raw frame's detections (what a look is for where it is believed, the held item)
        self.identify = identify
        self.raw: Frame | None = None  # the last frame as the camera gave it (labels, no names)
        self._held: Held | None = None
        self.cam = body.cfg.camera
        self._aim: tuple[np.ndarray, np.ndarray] | None = None  # point, camera pose of the last aim
        self.views = Views()  # cleared by the kit at each goal's start

    @property
    def held(self) -> Held | None:
        """What the hand holds as the camera measured it (None: nothing, as far as the skills know)."""
        return self._held

    @held.setter
    def held(self, held: Held | None) -> None:
        self._held = held
        self.body.hold(*(held.box() if held is not None else (None,)))

    # -- aiming --------------------------------------------------------------------------------

    def look_at(self, point, lift: float = 0.0, allow_base: bool = False, forward: float = CAMERA_EYE[0],
                shift: tuple[float, float] = (0.0, 0.0), avoid=()) -> bool:
        """Aim the camera at ``point`` from above the base (``lift`` higher, or higher still when
        that pose would put the arm into the furniture; a point inside a front-opening hollow
        from its own height first; ``forward`` of the base's centre, then ``shift``: towards the
        point and across, :data:`LOOKS`); with something in the hand the aim turns off the point
        just enough that the item does not cover it. No camera pose that is one view with one of
        ``avoid`` is taken. False when no aim is clear."""
        low = CAMERA_EYE[2] + lift
        over = max(low, float(point[2]) + LOOK_OVER)  # a high surface's top is seen from above it
        heights = (over, low, low + RAISE)
        if self.level_with(point):  # into a hollow through its front: from its height, first
            heights = (float(point[2]) + LEVEL_OVER + lift, *heights)
        xy = self._eye_xy(point, forward, shift)
        for z in dict.fromkeys(heights):
            eye = np.array([*xy, z])
            T = se3.look_pose(eye, point)
            for pose in (self.aim_past_held(T, float(np.linalg.norm(np.asarray(point, float) - eye))), T):
                if any(same_view(pose, a) for a in avoid):
                    continue
                if self.body.goto_pose(pose, 0.8, allow_base, "camera_optical"):
                    self._aim = (np.asarray(point, float), self.body.pose("camera_optical"))
                    return True
        return False

    def _eye_xy(self, point, forward: float, shift: tuple[float, float]) -> np.ndarray:
        """Where the eye stands over the floor: ``forward`` of the base's centre, moved ``shift``
        (towards ``point`` and across to its left; along the base's heading for a point under it)."""
        xy = np.asarray(self.body.in_base((forward, CAMERA_EYE[1], 0.0)), float)[:2]
        if not any(shift):
            return xy
        d = np.asarray(point, float)[:2] - xy
        if np.linalg.norm(d) < 1e-3:
            d = xy - np.asarray(self.body.in_base((0.0, 0.0, 0.0)), float)[:2]
        d /= np.linalg.norm(d)
        return xy + shift[0] * d + shift[1] * np.array([-d[1], d[0]])

    def aimed_at(self, point, tolerance: float = 0.15) -> bool:
        """Whether the camera still looks as the last aim left it, at a point within ``tolerance``
        of ``point`` (an action since may have moved the arm)."""
        if self._aim is None:
            return False
        target, pose = self._aim
        return same_view(self.body.pose("camera_optical"), pose) and \
            bool(np.linalg.norm(np.asarray(point, float) - target) <= tolerance)

    def aim_past_held(self, T: np.ndarray, distance: float = math.inf) -> np.ndarray:
        """``T`` (a camera pose looking along its z at a point ``distance`` away) turned the least
        so that the point shows clear of the held item, which is rigid with the camera, and of the
        band left of it that the stereo pair cannot see past it: the item's box is projected once
        (normalised image coordinates, from the camera pose now), widened to the left by its
        stereo shadow at that distance, and aims whose point falls outside that outline by
        AIM_MARGIN, and inside the frame, are tried from small turns to large ones; when none
        clears the shadow too, the item alone (the shadow costs depth only, the picture still
        shows the point: a knife held across the view cast a shadow that no turn cleared, and the
        aim went straight at the egg behind the blade). Returns ``T`` when the point is not
        covered or no turn clears it."""
        if self.held is None:
            return T
        item, z = self._held_in_view()
        outlines = [item]
        if self.cam.baseline > 0.0:  # the right imager's view of the point is blocked this far left of the item
            shadow = item.copy()
            shadow[:, 0] -= self.cam.baseline * np.maximum(1.0 / z - 1.0 / max(distance, 1e-3), 0.0)
            outlines.insert(0, np.vstack([item, shadow]))
        half = np.array([self.cam.width / 2 / self.cam.fx, self.cam.height / 2 / self.cam.fy]) - AIM_MARGIN
        for outline in outlines:
            hull = cv2.convexHull(outline.astype(np.float32))

            def clear(uv, hull=hull) -> bool:
                if np.any(np.abs(uv) > half):
                    return False
                return cv2.pointPolygonTest(hull, (float(uv[0]), float(uv[1])), True) < -AIM_MARGIN

            if clear(np.zeros(2)):
                return T
            for r in AIM_TURNS:
                for ang in np.linspace(0.0, 2 * math.pi, 16, endpoint=False):
                    uv = np.array([math.cos(ang), math.sin(ang)]) * math.tan(r)
                    if clear(uv):
                        return _turned_to(T, uv)
        return T

    def _held_in_view(self) -> tuple[np.ndarray, np.ndarray]:
        """The held item's box corners in normalised image coordinates from the camera now, and
        their depths (no nearer than the camera's minimum range)."""
        corners = self.held.corners_at(self.body.pose("tcp"))
        C = np.linalg.inv(self.body.pose("camera_optical"))
        pc = corners @ C[:3, :3].T + C[:3, 3]
        z = np.maximum(pc[:, 2], self.cam.near)
        return pc[:, :2] / z[:, None], z

    def in_hand(self, frame: Frame, label_fits: Callable[[str], bool]) -> int | None:
        """The detection of ``frame`` (by index) whose mask centres where the held item shows —
        the item is rigid in the wrist camera's view — and whose label fits it; None when none
        does. Its depth cannot tell: under the stereo's minimum range the item has no returns,
        and its mask's rim gives the floor's behind it (an unnamed cup there was remembered on
        the floor of a doorway, and the base found no way through it)."""
        if self.held is None or frame.masks is None or frame.intrinsics is None:
            return None
        hull = cv2.convexHull(self._held_in_view()[0].astype(np.float32))
        fx, fy, cx, cy = frame.intrinsics
        for k, d in enumerate(frame.detections):
            if d.name or not label_fits(d.label):
                continue
            rows, cols = np.nonzero(frame.masks == d.mask_id)
            if len(rows) and cv2.pointPolygonTest(hull, (float((cols.mean() - cx) / fx), float((rows.mean() - cy) / fy)),
                                                  False) >= 0:
                return k
        return None

    # -- seeing --------------------------------------------------------------------------------

    def frame(self, expect: Mapping[str, Believed] | None = None, holding: str | None = None) -> Frame:
        """Take a frame and name its detections: ``expect`` says where the things a look is for
        are believed to be; ``holding``: what the gripper holds, when the eyes have not measured
        it yet (else the held item they measured)."""
        self.raw = self.camera.capture()
        frame = self.identify(self.raw, dict(expect or {}), holding)
        self.noticed(frame, None if self._held is None else self._held.name)
        return frame

    def measure(self, name: str, point, allow_base: bool = False, radius: float = SEEN_RADIUS,
                inside: str | None = None, short: Callable[[Seen], float] = lambda seen: 0.0) -> Seen | None:
        """Look at ``point`` (where ``name`` is believed to be, within ``radius``; ``inside``: in
        that container) and measure ``name`` in the frame: the detection of its class there; None
        when no look shows it. The looks go down :data:`LOOKS`, each from a view not yet taken for
        ``name`` in this goal (:class:`Views`), at most :data:`VIEWS_PER_MEASURE` that do not show
        it. ``short`` says how much of the item a measure leaves out below (m; more than 0: a view
        from above a standing bottle measures its top, not its middle): one more look then goes
        from the lowest eye left, and the measure that leaves out least is returned."""
        believed = Believed(tuple(map(float, point)), radius, inside, inside=inside is not None)
        looks, misses, best = list(LOOKS), 0, None
        while looks and misses < VIEWS_PER_MEASURE:
            lift, toward, across = looks.pop(0)
            if not self.look_at(point, lift=lift, allow_base=allow_base, shift=(toward, across),
                                avoid=self.views.of(name)):
                continue
            self.views.add(name, self.body.pose("camera_optical"))
            seen = seen_from(self.frame({name: believed}), name)
            if seen is None:
                misses += 1
                continue
            if short(seen) <= 0.0:
                return seen
            if best is not None:  # the second view of a short measure: the better of the two
                return min((best, seen), key=short)
            best = seen
            looks.sort(key=lambda look: look[0])  # from lower: more of its side
        return best


def _turned_to(T: np.ndarray, uv: np.ndarray) -> np.ndarray:
    """The camera pose ``T`` turned so that the point on its optical axis shows at ``uv``
    (normalised image coordinates): the turn taking the axis to that direction, undone."""
    d = np.array([uv[0], uv[1], 1.0])
    d /= np.linalg.norm(d)
    axis = np.cross((0.0, 0.0, 1.0), d)
    out = T.copy()
    out[:3, :3] = T[:3, :3] @ se3.axis_angle(axis / np.linalg.norm(axis), math.acos(float(d[2]))).T
    return out
