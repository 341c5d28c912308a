"""The site map: what a robot knows of a house before it looks — rooms, doors, furniture.

A deployed mobile manipulator has a map built once (SLAM plus a person naming rooms and
furniture): room outlines, doorways and which rooms they join, and where the big furniture
stands. It also has knowledge of kinds of things (a cabinet can be opened; a cup can be filled),
given here as rigid facts (``connects``, ``openable``, ``fillable``, ``clear``). What the map does
not hold is anything that changes: where the items are, whether a door or a cabinet is open, what
is in the hand. Those are perceived.

A symbolic world's map has names and no geometry (``bounds``, ``pose`` and ``footprint`` are None).

For manipulation the map also carries what a furniture model annotates once per piece, as a
semantic map of a home does: its height, its cavity (where things go in, and from which side),
how its door or drawer moves (:class:`Articulation`: hinge or slide, where the handle is), and
where its switch or tap is. Where a door stands *now* — open, half open, shut — is not in the
map: it is perceived, or felt through the handle while the hand pulls it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from vap_bt.domain.atoms import Atom


@dataclass(frozen=True)
class RoomInfo:
    """A room: its name, its floor surface's name and its outline (x0, y0, x1, y1) in metres."""

    name: str
    floor: str
    bounds: tuple[float, float, float, float] | None = None

    def contains(self, x: float, y: float, margin: float = 0.0) -> bool:
        """Whether (x, y) in the map frame lies in the room, at least ``margin`` m inside its walls; a
        room without bounds contains nothing."""
        if self.bounds is None:
            return False
        x0, y0, x1, y1 = self.bounds
        return x0 + margin <= x <= x1 - margin and y0 + margin <= y <= y1 - margin


@dataclass(frozen=True)
class DoorInfo:
    """A doorway with its door leaf; ``pose`` is the doorway's centre and the normal's heading."""

    name: str
    rooms: tuple[str, str]
    pose: tuple[float, float, float] | None = None
    width: float | None = None
    articulation: Articulation | None = None


Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class Articulation:
    """How a door leaf or a drawer moves, in the map frame, at its closed position (q = 0).

    A revolute leaf turns about ``axis`` through ``origin``; a prismatic drawer slides along
    ``axis``. ``handle`` is the middle of the handle bar, ``normal`` the outward normal of the face
    holding it, ``bar`` the bar's direction (fingers close across it); ``opened`` is the joint value
    when fully open (sign included), ``lower``/``upper`` the joint's range. ``other_side``: room
    doors have a second handle on the other face, this far behind the first. ``leaf_center`` and
    ``leaf_half``: the moving part's box at q = 0 (what sweeps through the room)."""

    prismatic: bool
    origin: Vec3
    axis: Vec3
    handle: Vec3
    normal: Vec3
    bar: Vec3
    opened: float
    lower: float
    upper: float
    leaf_center: Vec3
    leaf_half: Vec3
    other_side: float | None = None


@dataclass(frozen=True)
class Cavity:
    """A container's hollow: its height range, wall thickness, and the side it opens on."""

    z: tuple[float, float]
    wall: float
    open: str  # "front" (through a door) or "top"


@dataclass(frozen=True)
class FurnitureInfo:
    """A piece of furniture: its footprint's centre and heading (the way its front faces)."""

    name: str
    label: str  # kind, e.g. "cabinet"
    type: str  # PDDL type: surface, container, appliance, sink
    room: str
    pose: tuple[float, float, float] | None = None  # x, y, yaw of the front's outward normal
    footprint: tuple[float, float] | None = None  # width along the front, depth (m)
    height: float | None = None  # of the outer box (a surface's top)
    cavity: Cavity | None = None
    articulation: Articulation | None = None
    switch: Vec3 | None = None  # where an appliance is switched on (pressed from the front)
    tap: Vec3 | None = None  # where a sink's water runs

    @property
    def front(self) -> tuple[float, float] | None:
        """The unit vector (x, y) of the front's outward normal, or None without a pose."""
        if self.pose is None:
            return None
        return (math.cos(self.pose[2]), math.sin(self.pose[2]))


@dataclass(frozen=True)
class SiteMap:
    """Rooms, doors, furniture and the rigid facts of one site."""

    rooms: tuple[RoomInfo, ...]
    doors: tuple[DoorInfo, ...] = ()
    furniture: tuple[FurnitureInfo, ...] = ()
    facts: frozenset[Atom] = field(default_factory=frozenset)  # rigid: connects, openable, fillable, clear

    def room(self, name: str) -> RoomInfo | None:
        """The room called ``name``, or None."""
        return next((r for r in self.rooms if r.name == name), None)

    def room_at(self, x: float, y: float) -> str | None:
        """The room whose bounds contain (x, y) in the map frame, or None (a doorway, outside, or no
        geometry)."""
        return next((r.name for r in self.rooms if r.contains(x, y)), None)

    def piece(self, name: str) -> FurnitureInfo | None:
        """The piece of furniture called ``name``, or None."""
        return next((f for f in self.furniture if f.name == name), None)

    def door(self, name: str) -> DoorInfo | None:
        """The door called ``name``, or None."""
        return next((d for d in self.doors if d.name == name), None)

    def floors(self) -> dict[str, str]:
        """floor name -> room name"""
        return {r.floor: r.name for r in self.rooms}

    def static_names(self) -> frozenset[str]:
        """Everything the map places: rooms, floors, doors, furniture."""
        return frozenset([*(r.name for r in self.rooms), *(r.floor for r in self.rooms),
                          *(d.name for d in self.doors), *(f.name for f in self.furniture)])
