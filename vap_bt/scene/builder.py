"""BuildSceneGraph (paper Sec. IV-A; Alg. 1, line 1): the scene graph from what the robot sees.

The builder chooses an exploration sweep from the site map — for every room the robot can reach,
a look at each piece of furniture and door from in front of it and a look round the floor — and
the robot executes it through its camera service. Every frame is integrated:

* in a frame with depth, each detected instance's mask and depth become points in the map frame,
  fused across views into one cleaned cloud per object (:mod:`vap_bt.scene.geometry`); its
  centroid and box give the relations ``on``, ``inside``, ``in_room``, ``near`` by geometry
  (:mod:`vap_bt.scene.relations`, thresholds in one place);
* in a frame without pixels (the symbolic world), the relations come with the detection, as that
  world's relation detector reports them (possibly wrong); reports are voted across views.

Either way the result per object is its *observed location*: the atoms that say where it is.
Objects never detected keep what the task file says of them (a ``prior``, which may be wrong);
the map gives rooms, doors, furniture and rigid facts. After a situation the same builder
re-locates the objects involved from a fresh frame, and re-surveys a room when an object is not
where belief puts it.
"""

from __future__ import annotations

import math
import time
from collections import Counter
from dataclasses import dataclass, field
from typing import Callable, Protocol

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.domain.roles import Roles
from vap_bt.robot.camera import Aim, Camera, Viewpoint
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.scene.graph import SceneGraph, SceneObject
from vap_bt.scene.identity import SEEN_RADIUS, SUPPORT_MARGIN, Believed, centroid_of, named_relations
from vap_bt.skill import Hint

#: frames kept per object (the best views of it), for questions asked after the sweep
KEEP_FRAMES = 3
#: a relation among items the geometry establishes where a domain has it (beside the roles')
NEAR = "near"

# -- where the sweep looks from (metres, radians); a view that cannot be reached is skipped --------
#: base centre to the front face of a piece of furniture when looking at it, and again closer
#: over a surface's top (from closer in the camera looks down more steeply, over the front row of
#: things onto what stands behind them)
VIEW_STANDOFF = 1.6
TOP_VIEW_STANDOFF = 1.0
#: the last look of a search for what the sweeps did not find: the tops of the pieces things are
#: put on from this near (a small thing covers twice the pixels it did from TOP_VIEW_STANDOFF, and
#: a detector's miss belongs to the picture: a new one draws anew)
SEARCH_TOP_STANDOFF = 0.7
#: how a look at a top from each of those stands is labelled in logs and reports
TOP_LOOKS = {TOP_VIEW_STANDOFF: "its top, from close by", SEARCH_TOP_STANDOFF: "its top, from nearer"}
#: m of a top along its front that one look from SEARCH_TOP_STANDOFF shows: the camera stands
#: 0.2 m off the front, about 0.6 m from the top's middle, and its frame (55 degrees wide) spans
#: 0.6 m there. A longer top is looked at in parts (boil_water seed 102 in pybullet: the cup the
#: hand lost lay on the counter 0.48 m from its middle, outside the one look at its top)
NEAR_TOP_SPAN = 0.6
#: the same stands for a look into a cavity that opens at the front (a microwave, an oven, a
#: fridge), aimed at the cavity's middle: from them its top shows and what stands inside does not
#: (boil_water seed 6 in pybullet: the cup heated in the microwave, out of every such frame)
INSIDE_LOOKS = {TOP_VIEW_STANDOFF: "its inside, from close by", SEARCH_TOP_STANDOFF: "its inside, from nearer"}
#: the height aimed at on furniture whose height perception has not measured yet
FURNITURE_AIM_HEIGHT = 0.7
#: a look round the floor: this far from the room's centre, in these directions
FLOOR_LOOK_DISTANCE = 1.3
FLOOR_LOOK_HEADINGS = (-math.pi / 2, 0.0, math.pi, math.pi / 2)
#: the last look for a lost item: the floor along every wall of a room, at points this far in from
#: the wall and at most this far apart, each seen from this much further in. The look round the
#: floor from a room's middle leaves the walls' feet out of the frame, and a bottle that slipped
#: from the hand rolls to a wall (retrieve_bottles, seeds 7 and 12 with injection): no plan could
#: find it. At 1.2 m the frame (55 degrees wide) spans about 1.2 m of floor along the wall
WALL_LOOK_INSET = 0.3
WALL_LOOK_SPACING = 1.2
WALL_LOOK_DISTANCE = 1.2
#: the floor between the walls' looks and the middle's: a ring of points this far in from each
#: wall, seen the walls' way (from WALL_LOOK_DISTANCE further in, facing the wall). A wall's look
#: stands 1.5 m in and its frame spans the floor from the wall to about 0.8 m in; the middle's
#: stands see about 0.7 m round the middle: in a room 4.4 m across a band from 0.8 to 1.5 m off each
#: wall was in no search's frame (boil_water seed 129 in pybullet: the cup the hand lost lay 1.3 m
#: from the kitchen's wall, searched for three times, then no plan). From 2.4 m in, a frame spans
#: the floor from about 0.4 to 1.7 m off the wall
INNER_LOOK_INSET = 1.2
#: a look at the floor round a spot (where something slipped from the hand): from stands on every
#: side, each facing it, in two rings — (distance m, first heading rad), six stands 60 degrees
#: apart in each. Not from the spot itself: the camera never sees the floor under its own base (a
#: flat item the base drove over lies there), and a robot at work stands by furniture it cannot
#: turn on the spot beside. From 1.1 m the wrist camera looks steeply down at the spot and sees the
#: floor from half a metre short of it to 0.8 m past it; there a knife on the floor covers about
#: 150 pixels of 320 x 240, which a detector finds about one time in two (cut_lemon seed 2 with
#: injection: five such views missed it under where the base had stood). The second ring, 0.75 m
#: away and turned by half a step, shows it twice as large and in new pictures
SPOT_LOOK_RINGS = ((1.1, 0.0), (0.75, math.pi / 6))
SPOT_LOOK_HEADINGS = tuple(k * math.pi / 3 for k in range(6))
#: m out from a piece's front face to the floor where what slipped from a hand working at it lies
#: (a pie lost on the way out of the fridge lay 4 cm from its front: heat_pie seed 0 with injection)
FRONT_SPOT = 0.25
#: a door is looked at from this far inside the room, at this height
DOOR_VIEW_DISTANCE = 1.6
DOOR_AIM_HEIGHT = 0.8


class Geometry(Protocol):
    """Fused per-object geometry from frames with depth (see :mod:`vap_bt.scene.geometry`)."""

    def integrate(self, frame: Frame) -> list[str]:
        """Fuse the detections of ``frame`` that have a mask and depth into their objects' geometry;
        returns the names of the objects it changed."""

    def forget(self, names) -> None:
        """Drop what earlier frames measured of ``names`` (they may have moved)."""

    def relations(self, name: str, held=()) -> set[Atom]:
        """Every geometric atom about ``name``: its support, its room, what it blocks or is blocked by,
        whether it is reachable; ``held``: the items in the hand, which are in no place."""

    def centroid(self, name: str) -> tuple[float, float, float] | None:
        """``name``'s centroid (metres, map frame), or None when no frame measured it."""

    def box(self, name: str) -> tuple[float, ...] | None:
        """``name``'s axis-aligned box (xmin, ymin, zmin, xmax, ymax, zmax; metres, map frame), or None
        when no frame measured it."""


@dataclass
class Evidence:
    """What the frames so far say about one object."""

    label: str
    frames: int = 0
    reports: Counter = field(default_factory=Counter)  # relation atom -> frames that reported it
    last_frame: str = ""
    #: the frames that showed it best (most pixels first; the latest first on a tie)
    best: list[tuple[int, int, Frame]] = field(default_factory=list)


@dataclass
class SweepRecord:
    """One exploration sweep: where it looked, what it found, what it cost."""

    rooms: tuple[str, ...]
    views: int = 0
    reached: int = 0
    frames: int = 0
    seconds: float = 0.0
    detected: frozenset[str] = frozenset()
    unreached_rooms: tuple[str, ...] = ()
    last_view: Viewpoint | None = None
    last_frame: Frame | None = None

    def after(self, earlier: "SweepRecord") -> "SweepRecord":
        """This sweep and an earlier one as one record (the robot ends where this one ended)."""
        return SweepRecord(earlier.rooms + self.rooms, earlier.views + self.views, earlier.reached + self.reached,
                           earlier.frames + self.frames, earlier.seconds + self.seconds,
                           earlier.detected | self.detected, self.unreached_rooms,
                           self.last_view or earlier.last_view, self.last_frame or earlier.last_frame)

    def to_json(self) -> dict:
        return {"rooms": list(self.rooms), "views": self.views, "reached": self.reached, "frames": self.frames,
                "seconds": round(self.seconds, 4), "detected": sorted(self.detected),
                "unreached_rooms": list(self.unreached_rooms)}


class SceneGraphBuilder:
    """Builds and refreshes the scene graph's objects and location facts from frames."""

    def __init__(self, knowledge: DomainKnowledge, objects: dict[str, str], site_map: SiteMap,
                 geometry: Callable[[DomainKnowledge, dict[str, str], SiteMap, Roles], Geometry] | None = None,
                 roles: Roles | None = None) -> None:
        self.knowledge, self.objects, self.site_map = knowledge, objects, site_map
        #: which predicates say where things are (default: the household's)
        self.roles = roles or Roles()
        self.geometry = geometry(knowledge, objects, site_map, self.roles) if geometry is not None else None
        self.evidence: dict[str, Evidence] = {}
        #: every name a frame has ever shown (integrated or not: a check's frames count, see
        #: :meth:`saw`): :meth:`forget` drops what frames said of a thing, not that the robot has
        #: seen it (only a never-seen thing is placed by the user's word)
        self.sighted: set[str] = set()
        self._static = site_map.static_names()

    # -- the sweep ---------------------------------------------------------------------------

    def views(self, room: str) -> list[Viewpoint]:
        """Where to look from in ``room``: every piece of furniture and door from in front of it,
        then round the floor from the room's middle (where the sweep of a room ends)."""
        info = self.site_map.room(room)
        out: list[Viewpoint] = []
        for f in self.site_map.furniture:
            if f.room == room:
                out.append(self._furniture_view(f))
                if self._has_top(f):
                    out.append(self._top_view(f, TOP_VIEW_STANDOFF))
        for d in self.site_map.doors:
            if room in d.rooms:
                out.append(self._door_view(d, room))
        if info is not None and info.bounds is not None:
            out += self.floor_views(room)
        elif info is not None and info.floor in self.objects:
            out.append(Viewpoint(room, Aim((info.floor,), place=info.floor), None, f"{room} floor"))
        return out

    def floor_views(self, room: str) -> list[Viewpoint]:
        """A look round ``room``'s floor from its middle; none for a room the map gives no outline."""
        info = self.site_map.room(room)
        if info is None or info.bounds is None:
            return []
        x0, y0, x1, y1 = info.bounds
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        out = []
        for h in FLOOR_LOOK_HEADINGS:
            point = (cx + FLOOR_LOOK_DISTANCE * math.cos(h), cy + FLOOR_LOOK_DISTANCE * math.sin(h), 0.0)
            out.append(Viewpoint(room, Aim((info.floor,), point, info.floor), (cx, cy, h), f"{room} floor, heading {h:+.2f}"))
        return out

    def middle_views(self, room: str) -> list[Viewpoint]:
        """A look at the floor round ``room``'s middle from the stands round it
        (:meth:`spot_views`): the look round the floor from the middle (:meth:`floor_views`) sees
        the floor from about half a metre out, and the floor at the robot's feet there is no view's
        (gather_kindling seed 1 in pybullet: the stick the hand lost lay 0.5 m from the living
        room's middle, shown by one view of the whole search, which missed it); none for a room the
        map gives no outline."""
        info = self.site_map.room(room)
        if info is None or info.bounds is None:
            return []
        x0, y0, x1, y1 = info.bounds
        return self.spot_views(room, ((x0 + x1) / 2, (y0 + y1) / 2))

    def wall_views(self, room: str) -> list[Viewpoint]:
        """A look at ``room``'s floor along each of its walls, corners included: points
        ``WALL_LOOK_INSET`` in from the wall, at most ``WALL_LOOK_SPACING`` apart, each from
        ``WALL_LOOK_DISTANCE`` further in, facing the wall; none for a room the map gives no
        outline."""
        return self._floor_ring(room, WALL_LOOK_INSET, "by the wall")

    def inner_views(self, room: str) -> list[Viewpoint]:
        """A look at ``room``'s floor between the walls' looks and the middle's: points
        ``INNER_LOOK_INSET`` in from each wall, along the part of it that is no corner, seen the
        way :meth:`wall_views` sees theirs; none for a room the map gives no outline, nor along a
        wall whose ring would reach past the room's middle (a narrow room's walls and middle
        looks see all of it)."""
        return self._floor_ring(room, INNER_LOOK_INSET, "off the wall", corners=False)

    def _floor_ring(self, room: str, inset: float, label: str, corners: bool = True) -> list[Viewpoint]:
        """Floor points ``inset`` in from each wall of ``room``, at most ``WALL_LOOK_SPACING``
        apart along it (from corner to corner, or between the points ``inset`` in from each end),
        each seen from ``WALL_LOOK_DISTANCE`` further in, facing the wall."""
        info = self.site_map.room(room)
        if info is None or info.bounds is None:
            return []
        x0, y0, x1, y1 = info.bounds
        out = []
        # each wall: its start corner, the way along it, its length, the way into the room and the
        # room's depth that way
        for (ax, ay), (ux, uy), length, (nx, ny), across in (
                ((x0, y0), (1, 0), x1 - x0, (0, 1), y1 - y0), ((x1, y0), (0, 1), y1 - y0, (-1, 0), x1 - x0),
                ((x1, y1), (-1, 0), x1 - x0, (0, -1), y1 - y0), ((x0, y1), (0, -1), y1 - y0, (1, 0), x1 - x0)):
            start = 0.0 if corners else inset
            span = length - 2 * start
            if span <= 0 or 2 * inset >= across:
                continue
            n = max(1, math.ceil(span / WALL_LOOK_SPACING))
            for k in range(n):
                s = start + (k + 0.5) * span / n
                px, py = ax + ux * s + nx * inset, ay + uy * s + ny * inset
                stand = (px + nx * WALL_LOOK_DISTANCE, py + ny * WALL_LOOK_DISTANCE, math.atan2(-ny, -nx))
                out.append(Viewpoint(room, Aim((info.floor,), (px, py, 0.0), info.floor), stand,
                                     f"{room} floor {label} at ({px:.2f}, {py:.2f})"))
        return out

    def near_top_views(self, room: str) -> list[Viewpoint]:
        """A look at the top of every piece in ``room`` that things are put on, from nearer than
        the sweep's (:data:`SEARCH_TOP_STANDOFF`)."""
        out = []
        for f in self.site_map.furniture:
            if f.room != room or not self._has_top(f):
                continue
            width = f.footprint[0] if f.footprint else 0.0
            n = max(1, math.ceil(width / NEAR_TOP_SPAN - 1e-9))
            out += [self._top_view(f, SEARCH_TOP_STANDOFF, (k + 0.5) * width / n - width / 2,
                                   f", part {k + 1} of {n}" if n > 1 else "") for k in range(n)]
        return out

    def spot_views(self, room: str, spot: tuple[float, float]) -> list[Viewpoint]:
        """A look at ``room``'s floor round ``spot`` from stands all round it in the room, each
        facing it, in rings (see :data:`SPOT_LOOK_RINGS`); a stand the base does not fit at
        (furniture, too near a wall) is the camera service's to refuse."""
        info = self.site_map.room(room)
        if info is None:
            return []
        sx, sy = spot
        out = []
        for distance, h in ((d, h0 + h) for d, h0 in SPOT_LOOK_RINGS for h in SPOT_LOOK_HEADINGS):
            bx, by = sx + distance * math.cos(h), sy + distance * math.sin(h)
            if info.bounds is not None and not (info.bounds[0] < bx < info.bounds[2] and info.bounds[1] < by < info.bounds[3]):
                continue  # through the wall: that floor is another room's, and the spot is not seen from it
            out.append(Viewpoint(room, Aim((info.floor,), (sx, sy, 0.0), info.floor), (bx, by, _wrap(h + math.pi)),
                                 f"{room} floor round ({sx:.2f}, {sy:.2f}), from heading {h:+.2f}"))
        return out

    def front_spot(self, name: str) -> tuple[float, float] | None:
        """The floor just in front of the mapped piece ``name`` (:data:`FRONT_SPOT` out from its
        front face, at its middle), where what slips from a hand working at it falls; None for
        what the map does not place."""
        piece = self.site_map.piece(name)
        if piece is None or piece.pose is None:
            return None
        x, y, yaw = piece.pose
        d = (piece.footprint[1] if piece.footprint else 0.5) / 2 + FRONT_SPOT
        return (x + d * math.cos(yaw), y + d * math.sin(yaw))

    def opens_on_top(self, name: str) -> bool:
        """Whether ``name`` is a mapped container whose inside shows from above (a basket, a drawer
        pulled out), not through a door at its front."""
        piece = self.site_map.piece(name)
        return piece is not None and piece.pose is not None and piece.cavity is not None and piece.cavity.open == "top"

    @property
    def geometric(self) -> frozenset[str]:
        """The relations the builder establishes about items (by geometry, or from a relation
        detector): where each is, what blocks it, whether it is reachable, what it is near."""
        r = self.roles
        return r.location | {p for p in (r.blocking, r.reachable, NEAR) if p is not None}

    def _has_top(self, f) -> bool:
        """Whether things are put on this placed piece of furniture (the domain's ``on`` takes its type)."""
        sig = self.knowledge.predicates.get(self.roles.on) if self.roles.on is not None else None
        return f.pose is not None and sig is not None and len(sig) == 2 and self.knowledge.is_subtype(f.type, sig[1])

    def _top_view(self, f, standoff: float, along: float = 0.0, part: str = "") -> Viewpoint:
        return self._furniture_view(f, standoff, TOP_LOOKS[standoff] + part, along=along)

    def _inside_view(self, f, standoff: float) -> Viewpoint:
        return self._furniture_view(f, standoff, INSIDE_LOOKS[standoff], z=sum(f.cavity.z) / 2)

    def _furniture_view(self, f, standoff: float = VIEW_STANDOFF, label: str = "from the front",
                        z: float | None = None, along: float = 0.0) -> Viewpoint:
        """A look at piece ``f`` from ``standoff`` in front of it, aimed at its middle at height
        ``z`` — or ``along`` metres from the middle along its front (towards the piece's own left, as
        it faces out)."""
        if f.pose is None:
            return Viewpoint(f.room, Aim((f.name,), place=f.name), None, f"{f.name}")
        x, y, yaw = f.pose
        x, y = x - along * math.sin(yaw), y + along * math.cos(yaw)
        depth = f.footprint[1] if f.footprint else 0.5
        box = self.geometry.box(f.name) if self.geometry else None
        # the measured top once the piece has been seen (a look at its top), else a usual height
        if z is None:
            z = box[5] if box is not None and standoff != VIEW_STANDOFF else FURNITURE_AIM_HEIGHT
        d = depth / 2 + standoff
        base = (x + d * math.cos(yaw), y + d * math.sin(yaw), yaw + math.pi)
        return Viewpoint(f.room, Aim((f.name,), (x, y, z), f.name), base, f"{f.name} {label}")

    def _door_view(self, d, room: str) -> Viewpoint:
        if d.pose is None or self.site_map.room(room).bounds is None:
            return Viewpoint(room, Aim((d.name,), place=d.name), None, f"{d.name}")
        x, y, _ = d.pose
        x0, y0, x1, y1 = self.site_map.room(room).bounds
        # stand inside this room on the line through the doorway's centre, facing it
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        ux, uy = cx - x, cy - y
        n = math.hypot(ux, uy) or 1.0
        bx, by = x + ux / n * DOOR_VIEW_DISTANCE, y + uy / n * DOOR_VIEW_DISTANCE
        return Viewpoint(room, Aim((d.name,), (x, y, DOOR_AIM_HEIGHT), d.name), (bx, by, math.atan2(y - by, x - bx)),
                         f"{d.name} from {room}")

    def sweep(self, camera: Camera, rooms: list[str], first: tuple[Viewpoint, ...] = ()) -> SweepRecord:
        """Go round ``rooms`` in order, looking from each of their views (after the ``first`` views,
        which count as their room's); integrate every frame."""
        return self.look_round(camera, [(room, [*(v for v in first if v.room == room), *self.views(room)])
                                        for room in rooms])

    def look_round(self, camera: Camera, rooms: list[tuple[str, list[Viewpoint]]],
                   until: Callable[[], bool] | None = None) -> SweepRecord:
        """Look from each room's given views in order, integrating every frame (a sweep, or a
        search of particular spots such as :meth:`wall_views`); a search stops as soon as
        ``until()`` holds after a frame."""
        t0 = time.perf_counter()
        rec = SweepRecord(tuple(room for room, _ in rooms))
        detected: set[str] = set()
        unreached = []
        found = False
        for room, views in rooms:
            reached_here = 0
            for view in views:
                rec.views += 1
                if not camera.goto_view(view):
                    continue
                reached_here += 1
                frame = camera.capture(view.aim)
                rec.frames += 1
                detected |= self.integrate(frame)
                rec.last_view, rec.last_frame = view, frame
                found = until is not None and until()
                if found:
                    break
            rec.reached += reached_here
            if not reached_here:
                unreached.append(room)
            if found:
                break
        rec.detected, rec.unreached_rooms = frozenset(detected), tuple(unreached)
        rec.seconds = time.perf_counter() - t0
        return rec

    # -- frames ------------------------------------------------------------------------------

    def integrate(self, frame: Frame) -> set[str]:
        """Fold one identified frame (:mod:`vap_bt.scene.identity`) into the evidence; returns
        the names detected in it."""
        names = set()
        for k, d in enumerate(frame.detections):
            if d.name not in self.objects:
                continue  # unnamed (nothing known), or outside the task's vocabulary: not of this plan
            ev = self.evidence.setdefault(d.name, Evidence(d.label))
            ev.frames += 1
            ev.last_frame = frame.frame_id
            ev.reports.update(set(named_relations(frame, k)))
            ev.best = sorted([*ev.best, (d.pixels, ev.frames, frame)], key=lambda b: (-b[0], -b[1]))[:KEEP_FRAMES]
            names.add(d.name)
        self.saw(names)
        if self.geometry is not None and frame.depth is not None:
            self.geometry.integrate(frame)
        return names

    def saw(self, names) -> None:
        """``names`` were identified in a frame (a survey's, a check's or a skill's)."""
        self.sighted.update(n for n in names if n in self.objects)

    def forget(self, names) -> None:
        """Drop what earlier frames said of ``names`` (they may have moved since)."""
        for n in names:
            self.evidence.pop(n, None)
        if self.geometry is not None:
            self.geometry.forget(names)

    def detected(self, name: str) -> bool:
        """Whether a frame has detected ``name`` since it was last forgotten."""
        return name in self.evidence

    def best_frames(self) -> dict[str, list[Frame]]:
        """For every object seen, the frames that showed it best, best first."""
        return {n: [f for _, _, f in ev.best] for n, ev in self.evidence.items() if ev.best}

    def observed(self, name: str, held=()) -> set[Atom]:
        """What the frames say of where ``name`` is (its location and blocking facts); empty when
        they never showed it. ``held``: items the hand holds (geometry gives them no place)."""
        ev = self.evidence.get(name)
        if ev is None:
            return set()
        if self.geometry is not None and self.geometry.centroid(name) is not None:
            return self.geometry.relations(name, held)
        return self._voted(name, ev)

    def placed(self, name: str, held=()) -> bool:
        """Whether the frames put ``name`` on or in something (or in the hand)."""
        return any((self.roles.supports(a) or self.roles.is_held(a)) and a.args[0] == name
                   for a in self.observed(name, held))

    def glimpsed(self, name: str) -> tuple[float, float] | None:
        """Where (map frame, x and y) a frame showed ``name`` too little to measure it: a few
        pixels of it, far off or at an image's edge, named by where they lie but too few points
        for a centroid (:class:`vap_bt.scene.pointcloud.CloudParams`). None when no frame showed it,
        when its frames measured it, or without depth."""
        ev = self.evidence.get(name)
        if ev is None or self.geometry is None or self.geometry.centroid(name) is not None:
            return None
        for _, _, frame in ev.best:
            d = next((d for d in frame.detections if d.name == name), None)
            c = centroid_of(frame, d) if d is not None else None
            if c is not None:
                return float(c[0]), float(c[1])
        return None

    def _voted(self, name: str, ev: Evidence) -> set[Atom]:
        """Reports voted across the frames that saw the object: one support, one room, and every
        other fact more than half of them reported."""
        out: set[Atom] = set()
        support, in_room = self.roles.support, (self.roles.in_room,)
        for preds in (support, in_room):
            cands = [(n, a) for a, n in ev.reports.items() if a.predicate in preds and a.args[0] == name]
            if cands:
                out.add(max(cands, key=lambda c: (c[0], str(c[1])))[1])
        out |= {a for a, n in ev.reports.items() if a.predicate not in (*support, *in_room)
                and n * 2 > ev.frames}
        return out

    def node(self, name: str) -> SceneObject:
        """The graph node for ``name`` as perception knows it now."""
        label = self.objects.get(name, "object")
        if name in self._static:
            piece = self.site_map.piece(name)
            src = "map"
            room = piece.room if piece else None
        else:
            src = "perceived" if name in self.evidence else "prior"
            room = None
        ev = self.evidence.get(name)
        geo = self.geometry
        c = geo.centroid(name) if geo else None
        box = geo.box(name) if geo else None
        if room is None and c is not None:
            room = self.site_map.room_at(c[0], c[1])
        return SceneObject(name, ev.label if ev else label, src, room, c, box, ev.frames if ev else 0)

    # -- where to look ----------------------------------------------------------------------

    def view_of(self, graph: SceneGraph, name: str) -> Viewpoint | None:
        """The sweep's own view of ``name`` (a piece of furniture, a door), or of what belief says
        an item rests on or in, or of the floor of the room belief puts it in."""
        for _ in range(3):
            piece, door = self.site_map.piece(name), self.site_map.door(name)
            if piece is not None:
                return self._furniture_view(piece)
            if door is not None:
                rooms = {a.args[0] for a in graph.facts if a.predicate == self.roles.robot_in} & set(door.rooms)
                return self._door_view(door, sorted(rooms)[0] if rooms else door.rooms[0])
            support = [a.args[1] for a in sorted(graph.location(name)) if self.roles.supports(a)]
            if not support:
                break
            name = support[0]
        room = next((r for r in self.site_map.rooms if r.floor == name), None)
        rooms = [a.args[1] for a in graph.facts if a.predicate == self.roles.in_room and a.args[0] == name]
        room = room or (self.site_map.room(rooms[0]) if rooms else None)
        views = self.views(room.name) if room is not None else []
        return views[-1] if views else None  # the look round its floor

    def near_views(self, graph: SceneGraph, name: str) -> list[Viewpoint]:
        """Views from close by of an item where belief puts it, for a check that could not make
        it out from afar (a lemon's cut, a cup's water, a log in a basket): the top of the piece it
        rests on or in from the sweep's close stand and from nearer, or, for an item inside a piece
        that opens at the front, the middle of its cavity from the same stands (the sweep's front
        view from afar left heat_pie seed 0's "heated" unconfirmed; the top hid boil_water seed 6's
        cup in the microwave from every frame), or the floor round it from all sides. ``name`` may be the piece itself
        (a basket a check relates an item to)."""
        place = self.place_of(graph, name)
        piece = self.site_map.piece(place) if place else None
        if piece is not None and piece.pose is not None and self._in_front_opening(graph, name, piece):
            return [self._inside_view(piece, standoff) for standoff in INSIDE_LOOKS]
        if piece is not None and piece.pose is not None:
            return [self._top_view(piece, standoff) for standoff in TOP_LOOKS]
        room = next((r for r in self.site_map.rooms if r.floor == place), None)
        p = self.point_of(graph, name)
        return self.spot_views(room.name, p[:2]) if room is not None and p is not None else []

    def _in_front_opening(self, graph: SceneGraph, name: str, piece) -> bool:
        """Whether belief puts item ``name`` right inside ``piece``, whose cavity opens at the front."""
        return piece.cavity is not None and piece.cavity.open == "front" \
            and Atom(self.roles.inside, (name, piece.name)) in graph.facts

    def aim(self, graph: SceneGraph, names: tuple[str, ...]) -> Aim:
        """Aim at the first of ``names`` that belief can place (the object a question is about,
        else what it rests on): the point and the place where belief puts it; neither when belief
        places none of them (or holds them)."""
        for n in names:
            p, place = self.point_of(graph, n), self.place_of(graph, n)
            if p is not None or place is not None:
                return Aim(tuple(names), p, place)
        return Aim(tuple(names))

    def place_of(self, graph: SceneGraph, name: str, depth: int = 0) -> str | None:
        """The mapped thing where belief puts ``name``: a piece of furniture, a door, a floor or a
        room is its own place; an item is at the place of what belief says it rests on or in. None
        for what the hand holds and for an item belief places on or in nothing."""
        if self.roles.holding(name) in graph.facts or depth > 3:
            return None
        if name in self._static:
            return name
        for a in sorted(graph.location(name)):
            if self.roles.supports(a):
                return self.place_of(graph, a.args[1], depth + 1)
        return None

    def undetectable(self) -> frozenset[str]:
        """What no detector finds in a frame: the map's rooms and their floors."""
        return frozenset([*(r.name for r in self.site_map.rooms), *(r.floor for r in self.site_map.rooms)])

    def hints(self, graph: SceneGraph, names: tuple[str, ...]) -> tuple[Hint, ...]:
        """What belief says about each of ``names``, for a goal: where it is (and how far from
        there belief allows it to be: a skill re-identifies it in its own frames) and on or in
        what."""
        out = []
        for n in names:
            loc = sorted(a for a in graph.location(n) if self.roles.supports(a))
            on = next((a.args[1] for a in loc if a.predicate != self.roles.inside), None)
            inside = next((a.args[1] for a in loc if a.predicate == self.roles.inside), None)
            b = self.believed(graph, n)
            point = self.point_of(graph, n)
            out.append(Hint(n, point, on, inside, b.radius if b is not None and b.point is not None else None))
        return tuple(out)

    def believed(self, graph: SceneGraph, name: str, seen_first: bool = False) -> Believed | None:
        """Where belief puts ``name``, for re-identifying it in a frame (:mod:`vap_bt.scene.identity`):
        a point (as :meth:`point_of`) with how far from it the object may be — a measured
        centroid's :data:`SEEN_RADIUS`; the extent of the piece it is believed on or in; the
        room's for one believed on a floor or only in a room — and its support and room (what
        worlds without geometry match by). None for the map's things (the map names them), for
        what belief has in the hand (the hand names it) and for what belief places nowhere.
        ``seen_first``: during the first sweep, what the frames showed so far outranks what the
        task file said."""
        if name in self._static or self.roles.holding(name) in graph.facts:
            return None
        loc = graph.location(name)
        if seen_first:
            c = self.geometry.centroid(name) if self.geometry is not None else None
            if c is not None:
                return Believed(c, SEEN_RADIUS)
            seen = self.observed(name)
            location = self.roles.location
            if any(a.args and a.args[0] == name and a.predicate in location for a in seen):
                loc = {a for a in seen if a.predicate in location and a.args and a.args[0] == name}
        place = next((a for a in sorted(loc) if self.roles.supports(a)), None)
        room = next((a.args[1] for a in sorted(loc) if a.predicate == self.roles.in_room and len(a.args) == 2), None)
        if place is None and room is None:
            return None
        support = place.args[1] if place is not None else None
        inside = place is not None and place.predicate == self.roles.inside
        hidden = inside and Atom(self.roles.closed, (support,)) in graph.facts
        obj = graph.objects.get(name)
        if not seen_first and obj is not None and obj.centroid is not None and obj.located == frozenset(loc):
            return Believed(obj.centroid, SEEN_RADIUS, support, room, hidden=hidden, inside=inside)
        point, radius = self._extent(graph, place, room)
        # never detected: only the task file's word places it, and the word may be wrong
        return Believed(point, radius, support, room, told=name not in self.sighted, hidden=hidden, inside=inside)

    def _extent(self, graph: SceneGraph, place: Atom | None, room: str | None) -> tuple[tuple[float, float, float] | None, float]:
        """A point of where ``place`` (on or in something) or ``room`` puts a thing, and how far
        from it the thing may be: anywhere on a piece's top or in its cavity, anywhere on a
        floor, near an item it rests on."""
        support = place.args[1] if place is not None else None
        piece = self.site_map.piece(support) if support else None
        if piece is not None and piece.pose is not None and piece.footprint:
            w, d = piece.footprint
            inside = place.predicate == self.roles.inside and piece.cavity is not None
            z = sum(piece.cavity.z) / 2 if inside else (piece.height or FURNITURE_AIM_HEIGHT)
            return (piece.pose[0], piece.pose[1], z), math.hypot(w, d) / 2 + SUPPORT_MARGIN
        if support is not None and support in self.objects and support not in self._static:
            p = self.point_of(graph, support)  # on another item: near where that one is
            return p, 2 * SEEN_RADIUS
        info = self.site_map.room(self.site_map.floors().get(support) or room) if (support or room) else None
        if info is not None and info.bounds is not None:
            x0, y0, x1, y1 = info.bounds
            return ((x0 + x1) / 2, (y0 + y1) / 2, 0.0), math.hypot(x1 - x0, y1 - y0) / 2
        return None, SEEN_RADIUS

    def point_of(self, graph: SceneGraph, name: str, depth: int = 0) -> tuple[float, float, float] | None:
        """Where belief puts ``name``, in the map frame: its measured centroid while belief still
        places it where it was measured, else a point of what belief says it rests on or in."""
        if self.roles.holding(name) in graph.facts or depth > 3:
            return None
        obj = graph.objects.get(name)
        if obj is not None and obj.centroid is not None and obj.located == frozenset(graph.location(name)):
            return obj.centroid
        for a in sorted(graph.location(name)):
            if self.roles.supports(a):
                return self._place_point(a) or self.point_of(graph, a.args[1], depth + 1)
        return self._map_point(name)

    def _place_point(self, atom: Atom) -> tuple[float, float, float] | None:
        """Where on or in a mapped piece of furniture a thing it holds would be: the middle of its
        top for ``on``, of its cavity for ``inside`` (the map's furniture model); None when the
        map does not model the piece."""
        piece = self.site_map.piece(atom.args[1])
        if piece is None or piece.pose is None:
            return None
        x, y, _ = piece.pose
        if atom.predicate == self.roles.inside and piece.cavity is not None:
            return (x, y, sum(piece.cavity.z) / 2)
        if atom.predicate != self.roles.inside and piece.height is not None:
            return (x, y, piece.height)
        return None

    def _map_point(self, name: str) -> tuple[float, float, float] | None:
        piece = self.site_map.piece(name)
        if piece is not None and piece.pose is not None:
            c = self.geometry.centroid(name) if self.geometry else None
            return (piece.pose[0], piece.pose[1], c[2] if c else FURNITURE_AIM_HEIGHT)
        door = self.site_map.door(name)
        if door is not None and door.pose is not None:
            return (door.pose[0], door.pose[1], DOOR_AIM_HEIGHT)
        room = next((r for r in self.site_map.rooms if r.floor == name or r.name == name), None)
        if room is not None and room.bounds is not None:
            x0, y0, x1, y1 = room.bounds
            return ((x0 + x1) / 2, (y0 + y1) / 2, 0.0)
        return None


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


