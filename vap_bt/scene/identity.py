"""Re-identification: which known object each detection of a frame is.

A detector reports class labels ("bottle"), never which bottle (:mod:`vap_bt.robot.frame`). The
robot names its detections itself, in every frame, from what it knew before it looked; the
executive and the skills reason only about frames so named (:class:`Identifier`,
:class:`IdentifyingCamera`). The rules, in order:

* **the map names its own things.** A detection labelled as a piece of furniture's kind whose
  points lie on that piece's footprint (grown by a margin, and out in front by the reach of its
  door leaf) is that piece — the largest such detection, since a false positive on furniture is
  a blob of it; a "door" whose points lie within a leaf's width of a doorway is that door (a
  door seen through its open doorway, with no points of its own, is the mapped door whose
  doorway the camera looks at). In a frame without pixels, the rooms the detection is reported
  in say which piece or door of its kind it is. A mapped thing is never anything else.
* **a mapped surface is no item.** A detection whose points all lie in the plane of the floor or
  of a piece's top (rising no more than ``surface_least`` above it) is that surface seen — a
  false positive on a patch of it — and nobody takes it; so is one half of whose points or more
  lie in the floor's plane, whatever else its mask holds: a blob of the house's own pixels takes
  the wall behind the patch of floor with it, and an item standing on the floor shows its own
  surface, above the floor's plane.
* **the hand names what it holds.** When the gripper feels something and belief says what, the
  detection at the fingers (its points within ``hand_radius`` of the tool point; without pixels,
  the detection reported held) is that object, and no other detection is.
* **belief names the items.** Each detection's 3-D centroid — robustly, the median of its mask's
  points with depth: a mask that bled onto the table behind keeps its median on the object —
  is matched to where belief puts each object (:class:`Believed`) by an optimal assignment
  (the Hungarian method, :func:`scipy.optimize.linear_sum_assignment`) over the distances,
  each normalised by and gated at how far from its point belief allows the object to be: a
  measured centroid (``SEEN_RADIUS``), anywhere on the top of the piece it is believed on,
  anywhere on the floor of a room — plus what a vague belief pays for its spread, so that a
  detection near where one bottle was measured is that bottle, not another believed only
  "somewhere on this counter". A label the detector confuses with the object's class
  (:func:`vap_bt.robot.labels.similar`) matches at a cost (``similar_cost``). Two bottles are
  two tracks: each takes the detection nearest where it was; an object believed somewhere far
  away takes nothing here. In a frame without pixels the detection's reported support decides
  (the one believed: best; another in the believed room: at ``room_cost``; another room: no
  match; where neither says a room, the label alone, behind both), and a support reported as
  another detection (``"#k"``) counts once that one is named.
* **first sightings.** An object belief places nowhere takes a detection of its own class that
  no believed object took — objects in name order, detections in the order the detector lists
  them: two bottles the user did not tell apart become bottle1 and bottle2 as first seen; then a
  detection of a confusable class that no object of the task has (a "firewood" where the task
  has only logs). The executive withholds belief about an
  object it is looking for (it was lost), so that it is taken wherever it is found — until a
  frame has placed it on or in something: a false positive of its class against a wall, which
  places it nowhere, does not pin it there, and the next sighting replaces that one.

What matches nothing stays unnamed (``name == ""``): a false positive far from every belief, a
thing of a class the task does not name, an object belief puts elsewhere. The executive notices a
believed object missing from a frame that should show it, and looks for it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable, Mapping

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.domain.roles import Roles
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import SELF, Detection, Frame, detection_index
from vap_bt.robot.labels import DOOR, similar
from vap_bt.robot.site_map import FurnitureInfo, SiteMap

Vec3 = tuple[float, float, float]

#: m: how far from a measured centroid belief allows the object still to be. Above a view's
#: centroid noise and partial-view bias (a few cm, :mod:`vap_bt.scene.tracks`) and a nudge by the
#: hand (a grasp that slipped), below the 0.3 m a person's move of a thing takes it at least
#: beyond: a thing further off is taken for another, or for one moved
SEEN_RADIUS = 0.25
#: m a believed support's extent is grown by (an item stands on the top, its centroid above it)
SUPPORT_MARGIN = 0.15
#: m: heights on a doorway's middle line, one of which a frame looking at the doorway shows
DOORWAY_HEIGHTS = (0.2, 0.6, 1.0, 1.4, 1.8)
#: m over which the cost of taking a detection beyond a told belief's radius grows by one: far
#: beyond any house
TOLD_SCALE = 1000.0
#: what taking a detection beyond a told belief's radius costs at least: above any match within
#: a gate (the distance term is at most 1, the spread term at most 2·ln(house / SEEN_RADIUS) < 8),
#: so that such a match only ever comes after every one within a gate
BEYOND_GATE = 100.0
#: gated assignments get this cost instead (never chosen over any real one)
_GATED = 1e6


@dataclass(frozen=True)
class Believed:
    """Where belief puts one object, for telling which detection it is: a ``point`` in the map
    frame with the ``radius`` round it where belief allows the object to be (worlds with
    geometry), and what it is believed on or in and the room (worlds without)."""

    point: Vec3 | None = None
    radius: float = SEEN_RADIUS
    support: str | None = None
    room: str | None = None
    #: only the user's word places it (the task file's belief; no frame — a survey's, a check's —
    #: has shown it yet): the word may be wrong, so a detection of its class anywhere may be it,
    #: though one where the word puts it is preferred (a wrong prior would otherwise hide the
    #: thing from the robot)
    told: bool = False
    #: belief has it inside a container it believes closed: no camera sees it there, so no
    #: detection with depth is taken for it (a detector's false positive on the closed door, of
    #: its class, would otherwise pin it to the door's face, and the real thing, once the door is
    #: open, would lie beyond the radius of that "sighting"). Without pixels a world's reports
    #: say what its view shows, and the reported support decides
    hidden: bool = False
    #: belief has it inside ``support`` (not on it): see :attr:`IdentityParams.behind_front`
    inside: bool = False


@dataclass(frozen=True)
class IdentityParams:
    """The identifier's own thresholds (the robot's, not the world's), each with its reason."""

    #: a detection of a confusable class costs this much more than one of the object's own
    #: class at the same distance (in gate units: half the gate); None: only its own class
    #: (a skill, which knows only its goal's objects, cannot tell a bowl taken for a plate from
    #: a bowl)
    similar_cost: float | None = 0.5
    #: without pixels: a detection reported on another support in the believed room
    room_cost: float = 0.5
    #: m from the tool point within which a held thing's centroid lies (the pads hold it; a
    #: bottle's centroid rides up to its half length off them)
    hand_radius: float = 0.15
    #: m a piece of furniture's footprint is grown by for its points (depth noise at its edges)
    footprint_margin: float = 0.1
    #: m beyond its doorway's width a door leaf's points may lie (an open leaf stands out into a
    #: room by its own width)
    door_reach: float = 0.3
    #: m: a door leaf's points have their median at least this high (a leaf stands from the
    #: floor to the lintel; a "door" whose points lie on the floor is a false positive)
    leaf_least: float = 0.15
    #: m: a detection whose points rise no more than this above a mapped surface (the floor, a
    #: piece's top) is that surface: the flattest item, a plate, stands 1.8 cm
    surface_least: float = 0.01
    #: m: a thing believed inside a container that opens at the front is taken only for a
    #: detection whose points lie at least this far behind the container's front (as the map has
    #: it). A detector's false positive on the door's face, of the thing's class, stands in the
    #: front's plane, and one sighting of it would pin the thing there; an item stands in the
    #: cavity, 0.1 m or more behind it. The robot's localisation error along the normal (σ 5 cm,
    #: see docs/perception.md) puts the face this far back about one time in twenty
    behind_front: float = 0.08
    #: depth returns beyond this are not used (as :class:`vap_bt.scene.pointcloud.CloudParams`)
    max_range: float = 4.0
    #: most mask pixels back-projected per detection (a median needs few)
    max_points: int = 400


class Identifier:
    """Names the detections of frames (see the module docstring). ``vocabulary``: every object
    of the task by name, with its class (:func:`vap_bt.robot.labels.label_of`)."""

    def __init__(self, vocabulary: Mapping[str, str], site_map: SiteMap,
                 params: IdentityParams = IdentityParams(), roles: Roles | None = None) -> None:
        self.vocabulary = dict(vocabulary)
        self.site_map = site_map
        self.p = params
        #: which reported relations say held, on, inside, in a room (a detector reports the domain's)
        self.roles = roles or Roles()
        self.mapped = site_map.static_names()

    def identify(self, frame: Frame, belief: Mapping[str, Believed] = {}, held: str | None = None,
                 hand: Vec3 | None = None, room: str | None = None) -> Frame:
        """``frame`` with its detections named where they could be. ``belief``: where each
        object is believed to be (an object absent from it is placed nowhere: a first sighting
        may name it); ``held``: what belief says the hand holds, when the gripper feels
        something; ``hand``: the tool point (map frame); ``room``: the room localization puts
        the robot in (a frame without pixels sees no other)."""
        dets = [replace(d, name="") for d in frame.detections]
        clouds = [points_of(frame, d, self.p.max_range, self.p.max_points) for d in dets]
        points = [None if c is None else np.median(c, axis=0) for c in clouds]
        names: dict[int, str] = {}
        self._map_things(frame, dets, points, names, room)
        # a detection whose points all lie in the plane of a mapped surface is that surface seen
        # (a false positive on a patch of floor or table top), no item on it: nobody takes it
        names.update({k: "" for k, c in enumerate(clouds) if k not in names and c is not None and self._flat(c)})
        if held is not None:
            k = self._in_hand(dets, points, names, held, hand)
            if k is not None:
                names[k] = held
        items = [n for n in sorted(self.vocabulary) if n not in self.mapped and n != held]
        known = {n: belief[n] for n in items if n in belief}
        # relations naming another detection ("#k") count once that one is named: a few rounds
        for strict in (True, True, False):
            self._match(dets, points, names, known, strict, [n for n in items if n not in known])
        self._first_sightings(dets, names, [n for n in items if n not in known])
        return replace(frame, detections=tuple(replace(d, name=names.get(k, "")) for k, d in enumerate(dets)))

    def _flat(self, cloud: np.ndarray) -> bool:
        """Whether ``cloud`` lies in a mapped surface's plane: its top (95th percentile of height)
        within ``surface_least`` of the floor (z = 0) or of the top of the piece whose footprint
        holds its median; or its median height within ``surface_least`` of the floor's."""
        top = float(np.percentile(cloud[:, 2], 95))
        if top < self.p.surface_least:
            return True
        mid = np.median(cloud, axis=0)
        # a blob of the house's own pixels spans floor and wall, and its top is the wall's
        # (boil_water seeds 13, 41 and 47 in pybullet: such a "cup" on the floor by the robot's
        # feet, taken while the cup was looked for, sent three grasps to an empty floor). The
        # flattest item on a floor, a stick lying there, 2.8 cm across, shows half its points
        # higher (none of 205 stick sightings in three gather_kindling episodes fell below); not
        # for a piece's top, where a knife or a plate lies flat, 1.8 cm thin, and the depth's
        # error brought the median within a centimetre of the top for 20 of 2007 knife sightings
        if abs(float(mid[2])) < self.p.surface_least:
            return True
        for piece in self.site_map.furniture:
            if piece.height is not None and abs(top - piece.height) < self.p.surface_least \
                    and _in_footprint(piece, mid, 0.0):
                return True
        return False

    def _behind_front(self, container: str | None, point) -> bool:
        """Whether ``point`` lies :attr:`IdentityParams.behind_front` behind the front of
        ``container`` (always, for a container the map does not have or that opens at the top)."""
        piece = self.site_map.piece(container) if container else None
        if piece is None or piece.pose is None or not piece.footprint or piece.cavity is None \
                or piece.cavity.open != "front":
            return True
        out = float(np.subtract(point[:2], piece.pose[:2]) @ piece.front)  # along the front's normal
        return piece.footprint[1] / 2 - out >= self.p.behind_front

    # -- the map's things -----------------------------------------------------------------------

    def _map_things(self, frame: Frame, dets: list[Detection], points: list, names: dict[int, str],
                    room: str | None) -> None:
        cands: list[tuple[tuple, int, str]] = []  # (preference, detection, mapped name)
        for k, d in enumerate(dets):
            if d.label == DOOR:
                for door in self.site_map.doors:
                    fit = self._door_fit(frame, d, points[k], door, room)
                    if fit is not None:
                        cands.append(((-d.pixels, fit, door.name), k, door.name))
            else:
                for piece in self.site_map.furniture:
                    if piece.label != d.label:
                        continue
                    fit = self._piece_fit(frame, d, points[k], piece, room)
                    if fit is not None:
                        cands.append(((-d.pixels, fit, piece.name), k, piece.name))
        # the largest detection of each (furniture is big; a false positive on it is a blob)
        for _, k, name in sorted(cands):
            if k not in names and name not in names.values():
                names[k] = name

    def _piece_fit(self, frame: Frame, d: Detection, point, piece: FurnitureInfo, room: str | None) -> float | None:
        """How far (in footprint units) the detection's points lie from ``piece``'s middle, or
        None when they are not on it (no points with depth: when the frame does not look at it;
        without pixels: when it is not reported in its room)."""
        if piece.pose is None or not piece.footprint or frame.depth is None:
            rooms = _reported_rooms(d, self.roles) or ({room} if room else set())
            return 0.0 if piece.room in rooms or not rooms else None
        x, y, yaw = piece.pose
        if point is None:
            uv = _project(frame, np.array([x, y, (piece.height or 1.0) / 2]))
            return None if uv is None else float(uv[2]) / self.p.max_range
        front = np.array([math.cos(yaw), math.sin(yaw)])
        along = np.array([front[1], -front[0]])
        rel = np.asarray(point[:2]) - (x, y)
        lx, ly = float(rel @ along), float(rel @ front)
        w, depth = piece.footprint
        m = self.p.footprint_margin
        reach = depth / 2 + m + (w if piece.articulation is not None else 0.0)  # a door leaf swings out
        top = (piece.height or 2.5) + m
        if abs(lx) > w / 2 + m or not -depth / 2 - m <= ly <= reach or not -m <= point[2] <= top:
            return None
        return math.hypot(lx / (w / 2 + m), ly / (depth / 2 + m))

    def _door_fit(self, frame: Frame, d: Detection, point, door, room: str | None) -> float | None:
        """How far the detection's points lie from ``door``'s doorway (in leaf widths), or None
        when they are not by it; a door with no points of its own (seen through its doorway) is
        the door whose doorway the frame looks at."""
        if door.pose is None or frame.depth is None:
            rooms = _reported_rooms(d, self.roles) or ({room} if room else set())
            return 0.0 if rooms <= set(door.rooms) or not rooms else None
        width = door.width or 1.0
        centre = np.array([door.pose[0], door.pose[1], 0.0])
        if point is None:  # the doorway's middle line, somewhere in the picture
            seen = [uv for z in DOORWAY_HEIGHTS if (uv := _project(frame, centre + (0.0, 0.0, z))) is not None]
            return None if not seen else min(float(uv[2]) for uv in seen) / self.p.max_range
        dist = float(np.hypot(*(np.asarray(point[:2]) - centre[:2])))
        # a leaf stands up from the floor: points lying on it are a false positive's
        return dist / width if dist <= width + self.p.door_reach and point[2] >= self.p.leaf_least else None

    # -- the hand -------------------------------------------------------------------------------

    def _in_hand(self, dets, points, names, held: str, hand: Vec3 | None) -> int | None:
        """The detection at the fingers that could be ``held``: nearest the tool point within
        ``hand_radius`` (without pixels: the one reported held)."""
        cls = self.vocabulary.get(held)
        best: tuple[float, int] | None = None
        for k, d in enumerate(dets):
            if k in names or not _compatible(d.label, cls):
                continue
            if points[k] is not None and hand is not None:
                dist = float(np.linalg.norm(np.subtract(points[k], hand)))
                if dist <= self.p.hand_radius and (best is None or dist < best[0]):
                    best = (dist, k)
            elif points[k] is None and self.roles.holding(SELF) in d.relations:
                best = best or (0.0, k)
        return None if best is None else best[1]

    # -- belief ---------------------------------------------------------------------------------

    def _match(self, dets, points, names: dict[int, str], known: Mapping[str, Believed], strict: bool,
               unknown: list[str]) -> None:
        """Assign the still unnamed detections to the still unnamed believed objects (see the
        module docstring); ``strict``: a report naming an unnamed detection ("#k") decides
        nothing yet. A detection of a class some object of the task has, that this object could
        be — placed nowhere, or believed near it — goes to no object of another class: a bowl
        seen where the plate should be is the bowl, not a plate taken for a bowl."""
        objs = [n for n in known if n not in names.values()]
        free = [k for k in range(len(dets)) if k not in names]
        if not objs or not free:
            return
        cost = np.full((len(free), len(objs)), _GATED)
        for i, k in enumerate(free):
            own = [n for n in (*objs, *unknown) if self.vocabulary.get(n) == dets[k].label and n not in names.values()]
            claimed = any(n not in known or self._cost(dets[k], points[k], known[n], dets[k].label, names, strict)
                          is not None for n in own)
            for j, n in enumerate(objs):
                if claimed and self.vocabulary.get(n) != dets[k].label:
                    continue
                c = self._cost(dets[k], points[k], known[n], self.vocabulary.get(n), names, strict)
                if c is not None:
                    cost[i, j] = c
        from scipy.optimize import linear_sum_assignment  # on first use: scipy.optimize costs 0.6 s at start-up

        rows, cols = linear_sum_assignment(cost)
        for i, j in zip(rows, cols):
            if cost[i, j] < _GATED:
                names[free[i]] = objs[j]

    def _cost(self, d: Detection, point, b: Believed, cls: str | None, names: dict[int, str],
              strict: bool) -> float | None:
        """The cost of taking ``d`` for an object believed at ``b`` of class ``cls`` (None: it
        cannot be)."""
        if d.label != cls and (self.p.similar_cost is None or not _compatible(d.label, cls)):
            return None
        extra = 0.0 if d.label == cls else self.p.similar_cost
        if point is not None:
            if b.point is None or b.hidden or b.inside and not self._behind_front(b.support, point):
                return None
            dist = float(np.linalg.norm(np.subtract(point, b.point)))
            if dist <= b.radius:
                return dist / b.radius + _spread(b.radius) + extra
            return BEYOND_GATE + dist / TOLD_SCALE + extra if b.told else None
        if not d.relations or self.roles.holding(SELF) in d.relations:
            return None  # nothing to place it by (or it is in the hand, and not what belief holds)
        support, unresolved = _reported_support(d, names, self.roles)
        if unresolved and strict:
            return None
        rooms = _reported_rooms(d, self.roles)
        if b.support is not None and support == b.support:
            return extra
        if b.room is not None and rooms and b.room in rooms:
            return self.p.room_cost + extra
        if b.room is None and not rooms and (support is None or b.support is None):
            # nothing to place it by either way (a domain without rooms, a support not named
            # yet): the label alone, behind any match by place
            return 2 * self.p.room_cost + extra
        # elsewhere than belief puts it: only the task file's word can be that wrong
        return 3 * self.p.room_cost + extra if b.told else None

    def _first_sightings(self, dets: list[Detection], names: dict[int, str], unknown: list[str]) -> None:
        """Objects placed nowhere take the detections of their own class nobody took, in order;
        then those of a class a detector confuses theirs with that no object of the task has (a
        "firewood" where the task has only logs: a log misread; a "cup" where it has a cup too
        is that cup's)."""
        classes = set(self.vocabulary.values())
        for exact in (True, False):
            for n in unknown:
                cls = self.vocabulary.get(n)
                if n in names.values():
                    continue
                k = next((k for k, d in enumerate(dets) if k not in names and (
                    d.label == cls if exact else d.label not in classes and _compatible(d.label, cls))), None)
                if k is not None:
                    names[k] = n


# -- what a detection shows -----------------------------------------------------------------------

def _spread(radius: float) -> float:
    """What a belief pays for being vague: 2·ln(radius / SEEN_RADIUS), the part of a negative
    log-likelihood that a density spread over a disc of that radius adds (zero for a measured
    centroid). Without it a distance normalised by the radius alone makes a loose belief the
    cheaper one: a bottle seen 7 cm from where bottle1 was measured was taken for bottle2,
    believed "anywhere on the counter" (radius 0.82 m) after a place that slipped, because 0.10 /
    0.82 < 0.07 / 0.25 — and the goal was claimed from a view of bottle1 (retrieve_bottles seed 5,
    injection on)."""
    return 2.0 * math.log(max(radius, SEEN_RADIUS) / SEEN_RADIUS)


def centroid_of(frame: Frame, d: Detection, max_range: float = 4.0, max_points: int = 400) -> np.ndarray | None:
    """The median (map frame) of the points of ``d``'s mask with a depth return within
    ``max_range``; None when the frame has no pixels or the mask none with depth. The median, not
    the mean: a mask that bled onto the surface behind keeps its median on the object."""
    pts = points_of(frame, d, max_range, max_points)
    return None if pts is None else np.median(pts, axis=0)


def points_of(frame: Frame, d: Detection, max_range: float = 4.0, max_points: int = 400) -> np.ndarray | None:
    """Up to about ``max_points`` points (map frame) of ``d``'s mask with a depth return within
    ``max_range``, evenly sampled; None when there are none (or no pixels)."""
    if frame.depth is None or frame.masks is None or frame.intrinsics is None or frame.camera_pose is None \
            or d.mask_id < 0:
        return None
    rows, cols = np.nonzero(frame.masks == d.mask_id)
    z = frame.depth[rows, cols].astype(np.float64)
    ok = (z > 0.0) & (z <= max_range)
    rows, cols, z = rows[ok], cols[ok], z[ok]
    if z.size == 0:
        return None
    step = max(1, z.size // max_points)
    rows, cols, z = rows[::step], cols[::step], z[::step]
    fx, fy, cx, cy = frame.intrinsics
    cam = np.stack([(cols - cx) / fx * z, (rows - cy) / fy * z, z], axis=1)
    pose = np.asarray(frame.camera_pose, np.float64)
    return cam @ pose[:3, :3].T + pose[:3, 3]


def _project(frame: Frame, point: np.ndarray) -> np.ndarray | None:
    """(u, v, depth) of a map point in ``frame``'s image, or None when it is not in it."""
    if frame.intrinsics is None or frame.camera_pose is None or frame.depth is None:
        return None
    inv = np.linalg.inv(np.asarray(frame.camera_pose, np.float64))
    x, y, z = inv[:3, :3] @ point + inv[:3, 3]
    if z <= 0.0:
        return None
    fx, fy, cx, cy = frame.intrinsics
    u, v = fx * x / z + cx, fy * y / z + cy
    h, w = frame.depth.shape
    return np.array([u, v, z]) if 0 <= u < w and 0 <= v < h else None


def _in_footprint(piece: FurnitureInfo, point, margin: float) -> bool:
    """Whether ``point`` (x, y) lies over ``piece``'s footprint grown by ``margin``."""
    if piece.pose is None or not piece.footprint:
        return False
    x, y, yaw = piece.pose
    front = np.array([math.cos(yaw), math.sin(yaw)])
    rel = np.asarray(point[:2], float) - (x, y)
    w, depth = piece.footprint
    return abs(float(rel @ (front[1], -front[0]))) <= w / 2 + margin and abs(float(rel @ front)) <= depth / 2 + margin


def _compatible(label: str, cls: str | None) -> bool:
    return cls is not None and (label == cls or similar(label, cls))


def _reported_rooms(d: Detection, roles: Roles) -> set[str]:
    return {a.args[1] for a in d.relations if a.predicate == roles.in_room and len(a.args) == 2 and a.args[0] == SELF}


def _reported_support(d: Detection, names: dict[int, str], roles: Roles) -> tuple[str | None, bool]:
    """What ``d`` is reported on or in (resolving "#k" through the names given so far), and
    whether the report names a detection not named yet."""
    for a in d.relations:
        if roles.supports(a) and a.args[0] == SELF:
            k = detection_index(a.args[1])
            if k is None:
                return a.args[1], False
            return names.get(k), k not in names
    return None, False


def named_relations(frame: Frame, k: int) -> tuple[Atom, ...]:
    """The relation reports of the frame's ``k``-th detection in the executive's names: the
    detection itself and the detections it refers to by their identified names, the map's things
    by theirs; a report about an unnamed detection is dropped (it says nothing of a known
    object)."""
    d = frame.detections[k]
    if not d.name:
        return ()
    out = []
    for a in d.relations:
        args = []
        for x in a.args:
            j = detection_index(x)
            if x == SELF:
                args.append(d.name)
            elif j is not None:
                args.append(frame.detections[j].name if j < len(frame.detections) else "")
            else:
                args.append(x)
        if all(args):
            out.append(Atom(a.predicate, tuple(args)))
    return tuple(out)


# -- a camera whose frames come identified --------------------------------------------------------

@dataclass
class IdentifyingCamera:
    """A camera service (:class:`vap_bt.robot.camera.Camera`) whose every frame is identified
    (``identify``, usually an :class:`Identifier` over current belief) before anyone sees it:
    what the executive perceives through."""

    camera: object
    identify: Callable[[Frame], Frame]

    def capture(self, aim: Aim | None = None) -> Frame:
        return self.identify(self.camera.capture(aim))

    def goto_view(self, view: Viewpoint) -> bool:
        return self.camera.goto_view(view)

    def move_view(self, aim: Aim, direction: str) -> bool:
        return self.camera.move_view(aim, direction)

    def __getattr__(self, name: str):  # stop(), state(), site_map(): the wrapped service's own
        if name.startswith("__") or name in ("camera", "identify"):
            raise AttributeError(name)
        return getattr(self.camera, name)
