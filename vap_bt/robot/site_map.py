"""The site map: what a robot knows of a house before it looks — rooms, doors, furniture.

A deployed mobile manipulator has a map built once (SLAM plus a person naming rooms and
furniture): room outlines, doorways and which rooms they join, and where the big furniture
stands. It also has knowledge of kinds of things (a cabinet can be opened; a cup can be filled),
given here as rigid facts (``connects``, ``openable``, ``fillable``, ``clear``). What the map does
not hold is anything that changes: where the items are, whether a door or a cabinet is open, what
is in the hand. Those are perceived.

A symbolic world's map has names and no geometry (``bounds``, ``pose`` and ``footprint`` are None).
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


@dataclass(frozen=True)
class FurnitureInfo:
    """A piece of furniture: its footprint's centre and heading (the way its front faces)."""

    name: str
    label: str  # kind, e.g. "cabinet"
    type: str  # PDDL type: surface, container, appliance, sink
    room: str
    pose: tuple[float, float, float] | None = None  # x, y, yaw of the front's outward normal
    footprint: tuple[float, float] | None = None  # width along the front, depth (m)

    @property
    def front(self) -> tuple[float, float] | None:
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
        return next((r for r in self.rooms if r.name == name), None)

    def room_at(self, x: float, y: float) -> str | None:
        return next((r.name for r in self.rooms if r.contains(x, y)), None)

    def piece(self, name: str) -> FurnitureInfo | None:
        return next((f for f in self.furniture if f.name == name), None)

    def door(self, name: str) -> DoorInfo | None:
        return next((d for d in self.doors if d.name == name), None)

    def floors(self) -> dict[str, str]:
        """floor name -> room name"""
        return {r.floor: r.name for r in self.rooms}

    def static_names(self) -> frozenset[str]:
        """Everything the map places: rooms, floors, doors, furniture."""
        return frozenset([*(r.name for r in self.rooms), *(r.floor for r in self.rooms),
                          *(d.name for d in self.doors), *(f.name for f in self.furniture)])
