"""Arranging a task's Layout in space: where every room, door, piece of furniture and item goes.

The Layout says *what* is in the house and what stands on what; this module decides *where*, with
no physics involved, so that the arrangement is testable and reproducible. The recipe is fixed and
simple, like a stage set:

* rooms stand in a row along x, in the order a walk through the doors visits them (every door
  joins two neighbours in the row); each room is ``depth`` deep in y, wide enough for its furniture;
* a doorway is centred in the shared wall; its leaf hangs on a vertical hinge at the doorway's
  low-y edge and swings either way (angle > 0 into the lower-x room);
* furniture stands side by side against the room's back wall (high y), its front facing the room;
  the middle of the room (the corridor, ``y = depth / 2``) stays free for driving;
* items lie on their surface's top (a blocker in front of what it blocks), inside their
  container's cavity, or on the floor between the corridor and the front wall, each with a small
  seeded jitter.

Frames: a piece of furniture has its own frame (x along the wall, y out of its front, z up, origin
on the floor under its centre); ``FurniturePlan.to_world`` maps local points to world points.
"""

from __future__ import annotations

import math
import random
from collections import deque
from dataclasses import dataclass

import numpy as np

from vap_bt.scene.layout import Layout, floor_of
from vap_bt.sim.pb_catalog import Catalog, FurnitureKind, ItemKind

Pose2 = tuple[float, float, float]  # x, y, yaw


@dataclass(frozen=True)
class RoomPlan:
    """A room's floor rectangle in the world (m), and its place ``index`` in the row of rooms."""

    name: str
    x0: float
    x1: float
    y0: float
    y1: float
    index: int

    def contains(self, x: float, y: float, margin: float = 0.0) -> bool:
        """Whether (x, y) lies on the room's floor, grown by ``margin`` m on every side."""
        return self.x0 - margin <= x <= self.x1 + margin and self.y0 - margin <= y <= self.y1 + margin

    @property
    def center(self) -> tuple[float, float]:
        """The middle of the floor (x, y)."""
        return ((self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2)


@dataclass(frozen=True)
class DoorPlan:
    """A doorway in the wall at ``x`` between rooms ``low`` and ``high``, its leaf hinged at ``hinge_y``."""

    name: str
    low: str  # room on the low-x side
    high: str  # room on the high-x side
    x: float  # the wall's x
    hinge_y: float
    width: float
    angle: float  # initial hinge angle (0 closed; > 0 swings into ``low``)

    @property
    def center_y(self) -> float:
        """The y of the doorway's middle."""
        return self.hinge_y + self.width / 2


@dataclass(frozen=True)
class FurniturePlan:
    """Where a piece of furniture stands: its centre on the floor (x, y), ``yaw`` of its local frame, and
    its initial articulation ``state`` (open, closed, None)."""

    name: str
    kind: FurnitureKind
    room: str
    x: float
    y: float
    yaw: float
    state: str | None

    def to_world(self, local) -> np.ndarray:
        """A point (x, y, z) in the furniture's frame, in the world."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        lx, ly, lz = local
        return np.array([self.x + c * lx - s * ly, self.y + s * lx + c * ly, lz])

    def direction(self, local_xy) -> np.ndarray:
        """A horizontal direction (x, y) in the furniture's frame, in the world (z = 0)."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return np.array([c * local_xy[0] - s * local_xy[1], s * local_xy[0] + c * local_xy[1], 0.0])

    @property
    def front(self) -> np.ndarray:
        """The world direction its front faces (local +y)."""
        return self.direction((0.0, 1.0))

    def standoff(self, lateral: float = 0.0, extra: float = 0.0) -> Pose2:
        """Base pose facing the front, ``lateral`` metres along the front (local x)."""
        p = self.to_world((lateral, self.kind.size[1] / 2 + self.kind.standoff + extra, 0.0))
        f = self.front
        return (float(p[0]), float(p[1]), math.atan2(-f[1], -f[0]))


@dataclass(frozen=True)
class ItemPlan:
    """Where an item starts: its centre and yaw in the world, and what it is ``on`` or ``inside`` (its
    ``support``; None on the floor or in the hand)."""

    name: str
    kind: ItemKind
    relation: str  # "on" | "inside" | "held"
    support: str | None
    position: tuple[float, float, float]  # centre of the item
    yaw: float


@dataclass(frozen=True)
class ScenePlan:
    """The whole arrangement: every room, door, piece of furniture and item, and the robot's start pose."""

    rooms: dict[str, RoomPlan]
    doors: dict[str, DoorPlan]
    furniture: dict[str, FurniturePlan]
    items: dict[str, ItemPlan]
    robot: Pose2
    depth: float

    @property
    def corridor_y(self) -> float:
        """The y of the free lane through the middle of every room, where the base drives."""
        return self.depth / 2

    def room_at(self, x: float, y: float) -> str | None:
        """The room whose floor holds (x, y), or None (outside every room)."""
        for r in self.rooms.values():
            if r.contains(x, y):
                return r.name
        return None


def _room_order(layout: Layout) -> list[str]:
    """Rooms in the order a walk through the doors reaches them (so doors join row neighbours)."""
    nbrs: dict[str, list[str]] = {r: [] for r in layout.rooms}
    for d in layout.doors.values():
        a, b = d.between
        nbrs[a].append(b)
        nbrs[b].append(a)
    order: list[str] = []
    for start in layout.rooms:
        if start in order:
            continue
        queue = deque([start])
        while queue:
            r = queue.popleft()
            if r not in order:
                order.append(r)
                queue.extend(n for n in nbrs[r] if n not in order)
    return order


def plan_scene(layout: Layout, catalog: Catalog, seed: int = 0) -> ScenePlan:
    """Arrange ``layout`` with the catalogue's kinds: rooms in a row joined by doors, furniture along the
    back walls, items on, in or beside their supports, jittered by ``seed``. A door between rooms that
    cannot be row neighbours is a ValueError."""
    rng = random.Random(seed)
    style = catalog.room
    types = layout.objects()
    kinds = {n: catalog.furniture_kind(n, f.type) for n, f in layout.furniture.items()}
    order = _room_order(layout)
    rooms: dict[str, RoomPlan] = {}
    x = 0.0
    for i, name in enumerate(order):
        members = [n for n, f in layout.furniture.items() if f.room == name]
        need = sum(kinds[n].size[0] for n in members) + style.furniture_gap * len(members) + 2.0  # 1 m free at each end
        width = max(style.width, need)
        rooms[name] = RoomPlan(name, x, x + width, 0.0, style.depth, i)
        x += width

    doors: dict[str, DoorPlan] = {}
    for name, d in layout.doors.items():
        a, b = sorted(d.between, key=lambda r: rooms[r].index)
        if rooms[b].index != rooms[a].index + 1:
            raise ValueError(f"door {name!r}: rooms {a!r} and {b!r} are not neighbours in the row {order}")
        angle = 0.0 if d.state == "closed" else -style.door_open_angle  # open ones swing into the far room
        doors[name] = DoorPlan(name, a, b, rooms[a].x1, style.depth / 2 - style.doorway / 2, style.doorway, angle)

    furniture: dict[str, FurniturePlan] = {}
    for room in rooms.values():
        members = [n for n, f in layout.furniture.items() if f.room == room.name]
        total = sum(kinds[n].size[0] for n in members) + style.furniture_gap * max(len(members) - 1, 0)
        cx = (room.x0 + room.x1) / 2 - total / 2
        for n in members:
            k = kinds[n]
            fx = cx + k.size[0] / 2
            fy = room.y1 - style.wall_thickness / 2 - k.size[1] / 2 - 0.01
            furniture[n] = FurniturePlan(n, k, room.name, fx, fy, math.pi, layout.furniture[n].state)
            cx += k.size[0] + style.furniture_gap

    items = _place_items(layout, catalog, types, furniture, rooms, rng, style.depth)
    robot = _robot_start(layout, rooms, furniture, style.depth)
    return ScenePlan(rooms, doors, furniture, items, robot, style.depth)


def _robot_start(layout: Layout, rooms, furniture, depth: float) -> Pose2:
    at = layout.robot.at
    if at in furniture:
        return furniture[at].standoff()
    r = rooms[layout.robot.room]
    return ((r.x0 + r.x1) / 2, depth / 2, math.pi / 2)


def _place_items(layout, catalog, types, furniture, rooms, rng: random.Random, depth: float) -> dict[str, ItemPlan]:
    out: dict[str, ItemPlan] = {}
    blockers = {b: n for n, it in layout.items.items() for b in it.blocked_by}
    groups: dict[str, list[str]] = {}
    for n, it in layout.items.items():
        if it.held:
            continue
        support = it.on or it.inside
        if n in blockers and layout.items[blockers[n]].place == it.place:
            continue  # placed in front of what it blocks
        groups.setdefault(support, []).append(n)

    def jitter(s: float = 0.015) -> float:
        return rng.uniform(-s, s)

    for support, names in groups.items():
        kinds = [catalog.item_kind(n, types[n]) for n in names]
        widths = [k.extent[0] for k in kinds]
        gap = 0.1
        total = sum(widths) + gap * (len(names) - 1)
        lx = -total / 2
        for n, k, w in zip(names, kinds, widths):
            along = lx + w / 2 + jitter()
            lx += w + gap
            rel = "on" if layout.items[n].on else "inside"
            if support in furniture:
                f = furniture[support]
                # a blocked item sits towards the back, its blocker in front of it
                ly = (-0.1 if layout.items[n].blocked_by else 0.0) + jitter(0.01)
                if rel == "on":
                    z = f.kind.size[2]
                else:
                    cav = f.kind.cavity
                    z = cav.z[0]  # the cavity's floor
                    ly = (0.04 if cav.open == "front" else 0.0) + jitter(0.01)
                    if f.kind.door is not None and f.kind.door.prismatic:
                        # in a drawer: on the part of the tray that slides out of the body (the
                        # rest stays under the top and cannot be reached from above)
                        ly = f.kind.size[1] / 2 - f.kind.door.slide / 2 + jitter(0.01)
                p = f.to_world((along, ly, z + k.extent[2] / 2 + 0.002))
                yaw = f.yaw + jitter(0.1)
                out[n] = ItemPlan(n, k, rel, support, tuple(map(float, p)), yaw)
                for b in layout.items[n].blocked_by:
                    if layout.items[b].place == layout.items[n].place:
                        bk = catalog.item_kind(b, types[b])
                        pb = f.to_world((along + jitter(), ly + 0.04 + (k.extent[1] + bk.extent[1]) / 2,
                                         z + bk.extent[2] / 2 + 0.002))
                        out[b] = ItemPlan(b, bk, "on", support, tuple(map(float, pb)), f.yaw + jitter(0.1))
            else:  # a room's floor: between the corridor and the front wall
                room = next(r for r in rooms.values() if floor_of(r.name) == support)
                cx, _ = room.center
                p = (cx + along + 0.6, depth / 2 - 1.15 + jitter(0.03), k.extent[2] / 2 + 0.002)
                out[n] = ItemPlan(n, k, "on", support, p, math.pi / 2 + jitter(0.2))
    for n, it in layout.items.items():
        if it.held:
            out[n] = ItemPlan(n, catalog.item_kind(n, types[n]), "held", None, (0.0, 0.0, 1.0), 0.0)
    return out
