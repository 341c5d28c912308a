"""Spatial relations from geometry, as the paper's Sec. IV-A defines them.

Each perceived object has a centroid and an axis-aligned box (its fused cloud's, see
:mod:`vap_bt.scene.tracks`); the site map adds what a camera cannot see from one side — the
footprint of each piece of furniture, the outline of each room, and that floors lie at z = 0.
From these:

* ``on(o, s)`` — o's centroid lies above s's support surface within a threshold. Concretely: s's
  support height is the top of its box; o's bottom lies within ``on_below`` / ``on_above`` of it,
  o's centroid is above it and over s in x/y. ``on(o, floor_r)``: the same with the floor at z = 0
  and room r's outline as its extent.
* ``inside(o, c)`` — o's box lies within c's volume (grown by ``inside_margin``). The top is open:
  o may stick out of c as long as its centroid is below c's top, as a long item does from a
  basket. A thing that rests *on* a container (centroid above its top) is not inside it.
* ``near(a, b)`` — centroids closer than ``near``.
* ``in_room(x, r)`` — from the map: a mapped piece of furniture in its room, a door in both of
  its rooms, anything else where its centroid lies in a room's outline.
* ``blocking(b, o)`` — b rests on the same support as o, in front of o (towards the side the robot
  works from: the furniture's front in the map; on a floor, towards the room's centre) by at most
  ``block_depth``, and overlaps o sideways; ``reachable(o)``: nothing blocks o.

A furniture piece's extent is the hull of its observed box and its map footprint: the map knows
how deep a cabinet is when the camera has seen only its front, and an open drawer's tray, which
slides beyond the footprint, is in the observed box. Its top is the map's height where the map
has one: a detector's mask of a table bleeds a pixel or two onto the cup standing on it (and the
points it bled onto join the table's cloud), which would lift an observed top to the cup's rim,
while a table seen only at its front edge would have it low; the furniture model knows. An open door leaf swings out of the
footprint too, and sweeps the floor in front of the piece, so the hull alone would put a cup that
fell in front of an open microwave inside it: a thing lying on the floor outside a piece's
footprint is never inside that piece (a drawer's tray, beyond the footprint, is far above the
floor; a basket's cavity, at floor level, is within its own footprint). Nor is a thing whose
centroid lies below the floor of the piece's hollow, where the map gives one: a pie that fell at
the fridge's foot, a centimetre out of its front face, is within the footprint's margin, but the
fridge's hollow begins 0.78 m up (heat_pie seed 27 in pybullet: read inside the fridge, it was
looked for there by three take-outs while it lay on the floor).

An item gets at most one support: of the ``on``/``inside`` candidates that hold, an ``inside``
wins over an ``on`` (an item in a basket on the floor also rests near the floor; the container is
what the robot must reach into), the smallest container among several, the surface closest to
the item's bottom among several surfaces. Held items (proprioception says so) have no location.

Only atoms that type-check against the domain's predicate signatures are produced, so the same
code serves any domain; ``near`` is produced only if the domain has it. Every threshold is in
:class:`Thresholds`, with its reason.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.domain.roles import Roles
from vap_bt.robot.site_map import FurnitureInfo, RoomInfo, SiteMap


@dataclass(frozen=True)
class Thresholds:
    """Every threshold of the geometric relations (metres), each with its reason.

    They are the executive's own, chosen for what its sensors return: a wrist stereo camera of
    the RealSense D435 class, whose depth error grows with the square of the range (Intel's
    formula: 8 mm RMS at 1.5 m, where the sweep sees most items; 14 mm at 2 m) and which loses
    pixels at edges, and a base localised to a few centimetres, so that what one view measured
    and the map's footprints disagree by that much. Nothing here comes from the simulator: its
    oracle decides truth from contacts and the gripper's real size, never from these numbers."""

    #: o's bottom may lie this far below s's top: o's bottom is the low quantile of its noisy
    #: points (two RMS low: 1.6 cm), s's top the high quantile of its own (one RMS high: 0.8 cm),
    #: and voxel averaging on both clouds blurs each by up to a centimetre
    on_below: float = 0.035
    #: o's bottom may lie this far above s's top: the lowest point a camera sees of a round item
    #: viewed from 60 degrees above is half its radius over the contact (1.6 cm for a lemon), the
    #: low quantile leaves out a few more millimetres, edge holes eat a pixel of the item's lower
    #: outline (5 mm at 1.5 m), plus half a voxel and two RMS of depth noise (1.6 cm)
    on_above: float = 0.05
    #: o's centroid may lie this far outside s's extent in x/y: s's extent includes its map
    #: footprint, and the view that measured o was taken from a base localised to a few
    #: centimetres (AMCL-class: 2-5 cm), plus half a voxel of averaging on a cloud's edge
    on_margin: float = 0.05
    #: c's volume is grown by this on every side but the top for ``inside``: localisation between
    #: the view and c's map footprint (a few centimetres) and two RMS of depth noise on o's box
    inside_margin: float = 0.045
    #: centroids closer than this are ``near``: about a forearm, the distance within which people
    #: call two things on one table next to each other
    near: float = 0.3
    #: b blocks o when its centroid is at most this far in front of o's: the hand (16 cm from the
    #: flange to the fingertips) and the 14 cm it comes in along before it closes
    block_depth: float = 0.3
    #: sideways, b blocks o when their extents across the approach overlap or come closer than
    #: this: the gripper's fingers need about 2 cm either side, and the boxes' sides carry half a
    #: centimetre of depth noise
    block_side_margin: float = 0.025


THRESHOLDS = Thresholds()


class Located(Protocol):
    """Anything with a name, a centroid and a box (xmin, ymin, zmin, xmax, ymax, zmax) in the map
    frame: an :class:`~vap_bt.scene.tracks.ObjectTrack`, a scene-graph node."""

    name: str
    centroid: tuple[float, float, float]
    box: tuple[float, float, float, float, float, float]


@dataclass(frozen=True)
class Extent:
    """Where a support or container is: a box in the map frame, and the way its front faces."""

    name: str
    lo: np.ndarray  # (3,) xmin, ymin, zmin
    hi: np.ndarray  # (3,) xmax, ymax, zmax
    front: tuple[float, float] | None = None  # unit vector in x/y; None: no front (floors)
    #: the map footprint's x/y bounds (xmin, ymin, xmax, ymax), for mapped furniture
    footprint: tuple[float, float, float, float] | None = None
    #: the heights (z0, z1) of its hollow, for a mapped container whose map gives its cavity
    hollow: tuple[float, float] | None = None

    @property
    def top(self) -> float:
        """The height of its support surface: the box's top (metres)."""
        return float(self.hi[2])

    @property
    def volume(self) -> float:
        """The box's volume (cubic metres)."""
        return float(np.prod(self.hi - self.lo))

    def over(self, p: np.ndarray, margin: float) -> bool:
        """Is point ``p`` over this extent in x/y (within ``margin``)?"""
        return bool(np.all(p[:2] >= self.lo[:2] - margin) and np.all(p[:2] <= self.hi[:2] + margin))


# ------------------------------------------------------------------ extents of things


def footprint_corners(piece: FurnitureInfo) -> np.ndarray:
    """The four corners (x, y) of a mapped piece's footprint; (0, 2) if the map has no geometry."""
    if piece.pose is None or piece.footprint is None:
        return np.zeros((0, 2))
    x, y, yaw = piece.pose
    width, depth = piece.footprint
    normal = np.array([math.cos(yaw), math.sin(yaw)])  # out of the front
    along = np.array([-normal[1], normal[0]])  # along the front
    return np.array([[x, y] + sa * width / 2 * along + sn * depth / 2 * normal
                     for sa in (-1, 1) for sn in (-1, 1)])


def object_extent(obj: Located, site_map: SiteMap) -> Extent:
    """An object's box, widened to its map footprint (and down to the floor) if it is mapped."""
    lo, hi = np.array(obj.box[:3], float), np.array(obj.box[3:], float)
    piece = site_map.piece(obj.name)
    if piece is None:
        return Extent(obj.name, lo, hi)
    corners = footprint_corners(piece)
    footprint = None
    if len(corners):
        lo[:2] = np.minimum(lo[:2], corners.min(axis=0))
        hi[:2] = np.maximum(hi[:2], corners.max(axis=0))
        lo[2] = min(lo[2], 0.0)  # mapped furniture stands on the floor
        footprint = (*map(float, corners.min(axis=0)), *map(float, corners.max(axis=0)))
    if piece.height is not None:
        hi[2] = piece.height  # the model's top, not a mask's (see the module docstring)
    hollow = tuple(map(float, piece.cavity.z)) if piece.cavity is not None else None
    return Extent(obj.name, lo, hi, piece.front, footprint, hollow)


def floor_extent(room: RoomInfo) -> Extent | None:
    """A room's floor: its outline at z = 0 (None if the map has no outline)."""
    if room.bounds is None:
        return None
    x0, y0, x1, y1 = room.bounds
    return Extent(room.floor, np.array([x0, y0, 0.0]), np.array([x1, y1, 0.0]))


# ------------------------------------------------------------------ the relations themselves


def rests_on(obj: Located, support: Extent, th: Thresholds = THRESHOLDS) -> bool:
    """``on(obj, support)``: bottom at the support's top, centroid above it and over it."""
    c = np.asarray(obj.centroid, float)
    gap = obj.box[2] - support.top
    return bool(-th.on_below <= gap <= th.on_above and c[2] > support.top and support.over(c, th.on_margin))


def lies_inside(obj: Located, container: Extent, th: Thresholds = THRESHOLDS) -> bool:
    """``inside(obj, container)``: box within the container's volume (open at the top, where the
    centroid must stay below the container's top)."""
    lo, hi = np.asarray(obj.box[:3], float), np.asarray(obj.box[3:], float)
    m = th.inside_margin
    if container.hollow is not None and obj.centroid[2] < container.hollow[0] - m:
        return False  # below the hollow's floor: at the piece's foot or under it, not in it
    if container.footprint is not None and lo[2] <= th.on_above:  # lying on the floor ...
        fx0, fy0, fx1, fy1 = container.footprint
        cx, cy = obj.centroid[0], obj.centroid[1]
        if not (fx0 - m <= cx <= fx1 + m and fy0 - m <= cy <= fy1 + m):
            return False  # ... outside the footprint: in front of the piece, not in it
    return bool(np.all(lo >= container.lo - m) and np.all(hi[:2] <= container.hi[:2] + m)
                and obj.centroid[2] <= container.top)


def is_near(a: Located, b: Located, th: Thresholds = THRESHOLDS) -> bool:
    """``near(a, b)``: centroids closer than ``th.near``."""
    return float(np.linalg.norm(np.subtract(a.centroid, b.centroid))) < th.near


def approach_of(obj: Located, support: Extent, site_map: SiteMap) -> np.ndarray | None:
    """Unit vector (x, y) towards the side the robot reaches ``obj`` from on ``support``: the
    furniture's front; on a floor, towards the middle of the room, where the robot drives."""
    if support.front is not None:
        return np.asarray(support.front, float)
    room = next((r for r in site_map.rooms if r.floor == support.name), None)
    if room is None or room.bounds is None:
        return None
    x0, y0, x1, y1 = room.bounds
    d = np.array([(x0 + x1) / 2 - obj.centroid[0], (y0 + y1) / 2 - obj.centroid[1]])
    n = float(np.linalg.norm(d))
    return d / n if n > 1e-9 else None


def _half_width(box, direction: np.ndarray) -> float:
    """Half the extent of an axis-aligned box along a horizontal unit vector."""
    return 0.5 * (abs(direction[0]) * (box[3] - box[0]) + abs(direction[1]) * (box[4] - box[1]))


def blocks(b: Located, o: Located, front: np.ndarray, th: Thresholds = THRESHOLDS) -> bool:
    """``blocking(b, o)`` for two items on one support whose approach side is ``front``."""
    side = np.array([-front[1], front[0]])
    d = np.subtract(b.centroid[:2], o.centroid[:2])
    ahead = float(d @ front)
    lateral = abs(float(d @ side))
    reach = _half_width(b.box, side) + _half_width(o.box, side) + th.block_side_margin
    return bool(0.0 < ahead <= th.block_depth and lateral < reach)


# ------------------------------------------------------------------ the scene's atoms


@dataclass(frozen=True)
class Signatures:
    """The domain's predicate signatures with the objects' types: what may be said of whom."""

    knowledge: DomainKnowledge
    types: Mapping[str, str]  # object name -> PDDL type (the planning task's objects)
    #: which predicates say on, inside, in a room, blocking, reachable (default: the household's)
    roles: Roles = field(default_factory=Roles)

    def has(self, predicate: str | None, arity: int) -> bool:
        """Whether the domain has ``predicate`` with ``arity`` arguments (never for None: a role the domain
        leaves unfilled)."""
        sig = self.knowledge.predicates.get(predicate) if predicate is not None else None
        return sig is not None and len(sig) == arity

    def fits(self, predicate: str | None, position: int, name: str) -> bool:
        """Can ``name`` stand at ``position`` of ``predicate``?"""
        sig = self.knowledge.predicates.get(predicate) if predicate is not None else None
        t = self.types.get(name)
        return sig is not None and t is not None and position < len(sig) and self.knowledge.is_subtype(t, sig[position])

    def typed(self, atom: Atom) -> bool:
        """Whether ``atom`` is of a predicate the domain has, each argument of a type the predicate takes."""
        return self.has(atom.predicate, len(atom.args)) and all(
            self.fits(atom.predicate, i, a) for i, a in enumerate(atom.args))


def _best_support(obj: Located, surfaces: list[Extent], containers: list[Extent],
                  th: Thresholds, roles: Roles) -> Atom | None:
    """The one location atom of ``obj`` (see the module docstring for the order); ``surfaces``
    and ``containers`` are empty where the domain has no on or inside role."""
    inside = [c for c in containers if c.name != obj.name and lies_inside(obj, c, th)]
    if inside:
        return Atom(roles.inside, (obj.name, min(inside, key=lambda c: c.volume).name))
    on = [s for s in surfaces if s.name != obj.name and rests_on(obj, s, th)]
    if on:
        # what the centroid lies over without the margin first: by a doorway both rooms' floors
        # are at the item's bottom and within the margin of it, and the one it lies in is its
        # room's (retrieve_bottles seed 7: on the kitchen's floor, in the garden)
        c = np.asarray(obj.centroid, float)
        return Atom(roles.on, (obj.name, min(on, key=lambda s: (not s.over(c, 0.0), abs(obj.box[2] - s.top))).name))
    return None


def room_of(obj: Located, site_map: SiteMap) -> tuple[str, ...]:
    """The rooms ``obj`` is in: the map's for furniture and doors, else where its centroid is."""
    piece = site_map.piece(obj.name)
    if piece is not None:
        return (piece.room,)
    door = site_map.door(obj.name)
    if door is not None:
        return door.rooms
    room = site_map.room_at(obj.centroid[0], obj.centroid[1])
    return (room,) if room is not None else ()


def room_atoms(site_map: SiteMap, sig: Signatures) -> frozenset[Atom]:
    """``in_room`` of what the map places before anything is seen: floors, doors, furniture."""
    in_room = sig.roles.in_room
    if in_room is None:
        return frozenset()
    atoms = {Atom(in_room, (r.floor, r.name)) for r in site_map.rooms}
    atoms |= {Atom(in_room, (d.name, r)) for d in site_map.doors for r in d.rooms}
    atoms |= {Atom(in_room, (f.name, f.room)) for f in site_map.furniture}
    return frozenset(a for a in atoms if sig.typed(a))


def scene_relations(objects: Iterable[Located], site_map: SiteMap, sig: Signatures,
                    held: Collection[str] = (), th: Thresholds = THRESHOLDS) -> frozenset[Atom]:
    """The geometric atoms among ``objects`` (perceived geometry) and what the map places:
    ``on``/``inside`` (one per item), ``in_room`` (with :func:`room_atoms`), ``near`` (if the
    domain has it), ``blocking`` and ``reachable`` (if it has them). ``held``: items in the hand,
    which are in no place and block nothing (and nothing blocks them)."""
    roles = sig.roles
    objs = [o for o in objects if o.box is not None and o.centroid is not None]
    placed = [o for o in objs if o.name not in held]
    extents = {o.name: object_extent(o, site_map) for o in placed}
    floors = [e for e in map(floor_extent, site_map.rooms) if e is not None]
    surfaces = {e.name: e for e in (*extents.values(), *floors) if sig.fits(roles.on, 1, e.name)}
    containers = [e for e in extents.values() if sig.fits(roles.inside, 1, e.name)]
    atoms: set[Atom] = set(room_atoms(site_map, sig))
    support: dict[str, Atom] = {}
    for o in placed:
        best = _best_support(o, list(surfaces.values()) if sig.fits(roles.on, 0, o.name) else [],
                             containers if sig.fits(roles.inside, 0, o.name) else [], th, roles)
        if best is not None:
            support[o.name] = best
        if roles.in_room is not None:
            atoms |= {Atom(roles.in_room, (o.name, r)) for r in room_of(o, site_map)}
    atoms |= set(support.values())
    if sig.has("near", 2):
        atoms |= {Atom("near", (a.name, b.name)) for a in objs for b in objs if a.name != b.name and is_near(a, b, th)}
    blocking = _blocking_atoms(placed, support, surfaces, site_map, th, roles) \
        if sig.has(roles.blocking, 2) else set()
    atoms |= blocking
    if sig.has(roles.reachable, 1):
        blocked = {a.args[1] for a in blocking if sig.typed(a)}
        atoms |= {Atom(roles.reachable, (o.name,)) for o in objs if o.name not in blocked}
    return frozenset(a for a in atoms if sig.typed(a))


def _blocking_atoms(placed: list[Located], support: dict[str, Atom], surfaces: Mapping[str, Extent],
                    site_map: SiteMap, th: Thresholds, roles: Roles) -> set[Atom]:
    """``blocking(b, o)`` between items resting on one surface."""
    atoms: set[Atom] = set()
    for o in placed:
        s = support.get(o.name)
        if s is None or s.predicate != roles.on:
            continue
        front = approach_of(o, surfaces[s.args[1]], site_map)
        if front is None:
            continue
        atoms |= {Atom(roles.blocking, (b.name, o.name)) for b in placed
                  if b.name != o.name and support.get(b.name) == Atom(roles.on, (b.name, s.args[1]))
                  and blocks(b, o, front, th)}
    return atoms
