"""Building the household in pybullet from a :class:`~vap_bt.sim.pb_layout.ScenePlan`.

Every named thing of the task becomes one or more bodies, registered in a :class:`Scene` by name:

* floors (one thin slab per room, the ``floor_<room>`` surfaces) and walls (anonymous);
* room doors: a multibody whose only link is the leaf on a vertical revolute hinge, with a
  handle bar on each face;
* furniture: a static multibody built from boxes in its own frame (plinth, cavity walls, top,
  legs, basin, tap); an openable piece has a link for its door leaf (revolute: side or bottom
  hinge) or drawer tray (prismatic), with a handle bar; an appliance has a lamp link and a switch
  link (a button on its front that a fingertip presses, :mod:`pb_rules`);
* items: free rigid bodies (box, cylinder or sphere) resting where the plan put them.

Joints of doors and drawers are not position-held: a velocity motor with target 0 and a small
force acts as friction, so they stay where they are left and move only when pushed or pulled —
by the gripper holding the handle. :class:`Hinge` records where each joint and handle is, which
the site map hands the robot as the furniture model's articulation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from vap_bt.sim.pb import pb
from vap_bt.sim.pb_catalog import Catalog, Color, FurnitureKind, ItemKind
from vap_bt.sim.pb_layout import DoorPlan, FurniturePlan, ItemPlan, ScenePlan

HANDLE_HEIGHT = 0.95  # of room-door handles
HANDLE_STANDOUT = 0.045  # handle bar centre in front of the leaf surface
ROOM_HANDLE_RADIUS = 0.8  # room-door handle distance from the hinge
ROOM_DOOR_FRICTION = 15.0  # N m
STOP_FORCE = 2000.0  # N m (or N) of a door stop
#: a sink's tap, in the sink's frame: a post at the back edge, an arm reaching forward over the
#: basin; the water leaves the arm's underside at its tip (:func:`tap_outlet`)
TAP_POST = (0.02, 0.05)  # y range of the post, from the back edge
TAP_REACH = 0.22  # y of the arm's tip, from the back edge
TAP_HEIGHT = (0.22, 0.25)  # z range of the arm, above the sink's top
#: an appliance's switch: a button standing this far out of its front face, with these half
#: extents along the front and vertically; pressed from the front (:mod:`pb_rules`)
SWITCH_STANDOUT = 0.03
SWITCH_HALF = (0.025, 0.018)
SWITCH_COLOR = (0.85, 0.85, 0.80, 1)
#: m: the width of the control strip beside a side-hinged appliance door (lamp and switch)
CONTROL_STRIP = 0.1


@dataclass(frozen=True)
class Box:
    """A box part in some frame: centre, half extents, colour."""

    center: tuple[float, float, float]
    half: tuple[float, float, float]
    color: Color


@dataclass
class Hinge:
    """The joint of a door leaf or drawer and the handle on it, in world coordinates at q = 0."""

    body: int
    joint: int
    prismatic: bool
    full: float  # joint value when fully open (sign included; room doors: the side opening away)
    origin: np.ndarray
    axis: np.ndarray  # unit; a positive joint value rotates/translates about/along it
    handle: np.ndarray  # centre of the handle bar at q = 0
    normal: np.ndarray  # outward normal of the leaf face holding the handle, at q = 0
    bar: np.ndarray  # direction of the handle bar at q = 0 (the fingers close across it)
    bar_half: float = 0.09  # half the handle bar's length
    #: room doors have a second handle on the other face, this far behind the first one
    other_side: float | None = None
    #: the moving part's bounding box at q = 0 (world centre and half extents): what sweeps
    leaf_center: np.ndarray = field(default_factory=lambda: np.zeros(3))
    leaf_half: np.ndarray = field(default_factory=lambda: np.zeros(3))
    #: joint range and the friction of the joint (its velocity motor's force)
    lower: float = 0.0
    upper: float = 0.0
    friction: float = 0.0
    at_stop: bool = False  # the stop motor holds the joint at a limit

    def hold_limits(self, cid: int) -> None:
        """A door stop: pybullet's joint limits on these hand-built joints give way under a push,
        so past a limit a strong position motor holds the joint there; back inside the range the
        joint is free again (friction only)."""
        q = pb.getJointState(self.body, self.joint, physicsClientId=cid)[0]
        beyond = q < self.lower or q > self.upper
        if beyond:
            pb.setJointMotorControl2(self.body, self.joint, pb.POSITION_CONTROL, targetPosition=min(max(q, self.lower), self.upper),
                                     targetVelocity=0.0, force=STOP_FORCE, positionGain=1.0, velocityGain=1.0,
                                     physicsClientId=cid)
        elif self.at_stop:
            _friction(cid, self.body, self.joint, self.friction)
        self.at_stop = beyond

    def transform(self, q: float, q_from: float = 0.0):
        """Rotation matrix and point map taking geometry at ``q_from`` to joint value ``q``."""
        if self.prismatic:
            shift = self.axis * (q - q_from)
            return np.eye(3), (lambda p: np.asarray(p) + shift)
        R = _axis_angle(self.axis, q - q_from)
        return R, (lambda p: self.origin + R @ (np.asarray(p) - self.origin))

    def leaf(self, q: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The moving part at joint value ``q`` as an oriented box: centre, rotation, half extents."""
        R, move = self.transform(q)
        return move(self.leaf_center), R, self.leaf_half

    def plate(self, q: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The leaf or drawer front without its handles (what a hand near the bar must not touch),
        as an oriented box at joint value ``q``."""
        n = np.abs(self.normal)
        front = float(self.handle @ self.normal) - HANDLE_STANDOUT
        back = float(self.leaf_center @ self.normal - self.leaf_half @ n)
        if self.other_side is not None:
            back = max(back, front - self.other_side + 2 * HANDLE_STANDOUT)
        centre = self.leaf_center + self.normal * ((front + back) / 2 - float(self.leaf_center @ self.normal))
        half = self.leaf_half * (1 - n) + n * (front - back) / 2
        R, move = self.transform(q)
        return move(centre), R, half

    def handle_at(self, q: float, side: float = 1.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Handle grasp point, outward face normal and bar direction at joint value ``q``.

        ``side`` = -1 picks the handle on the other face (two-sided room doors)."""
        R, move = self.transform(q)
        centre = self.handle if side > 0 else self.handle - self.normal * self.other_side
        return move(centre), R @ (self.normal * side), R @ self.bar


@dataclass
class Thing:
    """One named object of the task in the simulation."""

    name: str
    pddl_type: str
    bodies: list[int]
    kind: FurnitureKind | ItemKind | None = None
    furniture: FurniturePlan | None = None
    item: ItemPlan | None = None
    door: DoorPlan | None = None
    hinge: Hinge | None = None
    light_link: int | None = None
    switch_link: int | None = None  # appliances: the button that switches them on
    room: str | None = None  # rooms and floors
    states: dict[str, float | bool] = field(default_factory=dict)

    @property
    def body(self) -> int:
        """Its first body: an item's only one, a piece of furniture's carcass."""
        return self.bodies[0]


@dataclass
class Scene:
    """The built household: every named thing's bodies in pybullet client ``client``, with the plan they
    were placed by."""

    client: int
    plan: ScenePlan
    things: dict[str, Thing]
    walls: list[int]

    def by_body(self) -> dict[int, str]:
        """The thing's name of every pybullet body id (walls have none)."""
        return {b: t.name for t in self.things.values() for b in t.bodies}

    def items(self) -> list[Thing]:
        """The things that are items (free bodies), not furniture, doors or floors."""
        return [t for t in self.things.values() if t.item is not None]

    def hold_limits(self) -> None:
        """Keep every door and drawer inside its joint range (call after each simulation step)."""
        for t in self.things.values():
            if t.hinge is not None:
                t.hinge.hold_limits(self.client)


def _axis_angle(axis: np.ndarray, angle: float) -> np.ndarray:
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def _shapes(cid: int, boxes: list[Box], frame_shift=(0.0, 0.0, 0.0)) -> tuple[int, int]:
    """A compound collision shape and visual shape from boxes (positions relative to a link frame)."""
    pos = [tuple(np.subtract(b.center, frame_shift)) for b in boxes]
    half = [b.half for b in boxes]
    col = pb.createCollisionShapeArray([pb.GEOM_BOX] * len(boxes), halfExtents=half, collisionFramePositions=pos,
                                       physicsClientId=cid)
    vis = pb.createVisualShapeArray([pb.GEOM_BOX] * len(boxes), halfExtents=half, visualFramePositions=pos,
                                    rgbaColors=[b.color for b in boxes], physicsClientId=cid)
    return col, vis


def _slab(x0, x1, y0, y1, z0, z1, color) -> Box:
    return Box(((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2), ((x1 - x0) / 2, (y1 - y0) / 2, (z1 - z0) / 2), color)


def _yaw_quat(yaw: float):
    return pb.getQuaternionFromEuler((0.0, 0.0, yaw))


# ---------------------------------------------------------------- rooms, walls, doors


def _build_rooms(cid: int, plan: ScenePlan, catalog: Catalog, things: dict[str, Thing]) -> list[int]:
    style = catalog.room
    walls: list[int] = []
    for room in plan.rooms.values():
        color = style.floor_colors[room.index % len(style.floor_colors)]
        # a thick slab: a falling object cannot pass through it within one time step
        col, vis = _shapes(cid, [_slab(room.x0, room.x1, room.y0, room.y1, -0.2, 0.0, color)])
        body = pb.createMultiBody(0, col, vis, physicsClientId=cid)
        name = f"floor_{room.name}"
        things[name] = Thing(name, "surface", [body], room=room.name)
        things[room.name] = Thing(room.name, "room", [], room=room.name)
    t, h = style.wall_thickness, style.wall_height
    xs = sorted({r.x0 for r in plan.rooms.values()} | {r.x1 for r in plan.rooms.values()})
    x_min, x_max = xs[0], xs[-1]
    boxes = [_slab(x_min - t / 2, x_max + t / 2, plan.depth - t / 2, plan.depth + t / 2, 0, h, style.wall_color),
             _slab(x_min - t / 2, x_max + t / 2, -t / 2, t / 2, 0, h, style.wall_color)]
    for x in xs:
        gaps = sorted((d.hinge_y, d.hinge_y + d.width) for d in plan.doors.values() if abs(d.x - x) < 1e-6)
        y = 0.0
        for g0, g1 in gaps + [(plan.depth, plan.depth)]:
            if g0 > y:
                boxes.append(_slab(x - t / 2, x + t / 2, y, g0, 0, h, style.wall_color))
            y = g1
    for b in boxes:
        col, vis = _shapes(cid, [b])
        walls.append(pb.createMultiBody(0, col, vis, physicsClientId=cid))
    return walls


def _build_door(cid: int, d: DoorPlan, catalog: Catalog) -> Thing:
    style = catalog.room
    h = style.wall_height - 0.04
    gap = style.wall_thickness / 2 + 0.012  # the leaf starts clear of the wall it hangs on
    leaf_w = d.width - gap - 0.02
    th = 0.035
    leaf = _slab(-th / 2, th / 2, gap, gap + leaf_w, 0.02, h, style.door_color)
    handles = [_slab(s * (th / 2 + HANDLE_STANDOUT) - 0.012, s * (th / 2 + HANDLE_STANDOUT) + 0.012,
                     ROOM_HANDLE_RADIUS - 0.012, ROOM_HANDLE_RADIUS + 0.012, HANDLE_HEIGHT - 0.09,
                     HANDLE_HEIGHT + 0.09, (0.75, 0.75, 0.7, 1)) for s in (1, -1)]
    posts = [_slab(s * (th / 2 + 0.005) - 0.006, s * (th / 2 + 0.005) + 0.006, ROOM_HANDLE_RADIUS - 0.006,
                   ROOM_HANDLE_RADIUS + 0.006, HANDLE_HEIGHT - 0.08, HANDLE_HEIGHT + 0.08, (0.6, 0.6, 0.55, 1))
             for s in (1, -1)]
    col, vis = _shapes(cid, [leaf, *handles, *posts])
    body = pb.createMultiBody(
        baseMass=0, baseCollisionShapeIndex=-1, baseVisualShapeIndex=-1, basePosition=(d.x, d.hinge_y, 0.0),
        linkMasses=[8.0], linkCollisionShapeIndices=[col], linkVisualShapeIndices=[vis],
        linkPositions=[(0, 0, 0)], linkOrientations=[(0, 0, 0, 1)], linkInertialFramePositions=[(0, 0, 0)],
        linkInertialFrameOrientations=[(0, 0, 0, 1)], linkParentIndices=[0], linkJointTypes=[pb.JOINT_REVOLUTE],
        linkJointAxis=[(0, 0, 1)], physicsClientId=cid)
    limit = style.door_open_angle + 0.05
    pb.changeDynamics(body, 0, jointLowerLimit=-limit, jointUpperLimit=limit, linearDamping=0.5, angularDamping=0.5,
                      physicsClientId=cid)
    hinge = Hinge(body, 0, False, -style.door_open_angle, np.array([d.x, d.hinge_y, 0.0]), np.array([0.0, 0.0, 1.0]),
                  handle=np.array([d.x + th / 2 + HANDLE_STANDOUT, d.hinge_y + ROOM_HANDLE_RADIUS, HANDLE_HEIGHT]),
                  normal=np.array([1.0, 0.0, 0.0]), bar=np.array([0.0, 0.0, 1.0]), bar_half=0.09,
                  other_side=th + 2 * HANDLE_STANDOUT, **_leaf_box(cid, body, 0), lower=-limit, upper=limit,
                  friction=ROOM_DOOR_FRICTION)
    pb.resetJointState(body, 0, d.angle, physicsClientId=cid)
    _friction(cid, body, 0, ROOM_DOOR_FRICTION)
    return Thing(d.name, "door", [body], door=d, hinge=hinge)


def _leaf_box(cid: int, body: int, link: int) -> dict:
    """Centre and half extents of a link's box (taken at q = 0, where leaves are axis-aligned)."""
    lo, hi = (np.array(v) for v in pb.getAABB(body, link, physicsClientId=cid))
    return {"leaf_center": (lo + hi) / 2, "leaf_half": (hi - lo) / 2}


def _friction(cid: int, body: int, joint: int, force: float) -> None:
    # velocity motor towards 0 with a small force: the joint stays put unless pushed
    pb.setJointMotorControl2(body, joint, pb.VELOCITY_CONTROL, targetVelocity=0.0, force=force, physicsClientId=cid)


# ---------------------------------------------------------------- furniture


def _furniture_parts(k: FurnitureKind) -> list[Box]:
    """The static boxes of a piece of furniture, in its own frame."""
    w, d, h = k.size
    c = k.color
    if k.cavity is None:
        if k.legs:
            top = 0.04
            parts = [_slab(-w / 2, w / 2, -d / 2, d / 2, h - top, h, c)]
            for sx in (-1, 1):
                for sy in (-1, 1):
                    x, y = sx * (w / 2 - k.legs), sy * (d / 2 - k.legs)
                    parts.append(_slab(x - k.legs / 2, x + k.legs / 2, y - k.legs / 2, y + k.legs / 2, 0, h - top, c))
            return parts
        if k.top_color:
            return [_slab(-w / 2, w / 2, -d / 2, d / 2, 0, h - 0.03, c), _slab(-w / 2, w / 2, -d / 2, d / 2, h - 0.03, h, k.top_color)]
        return [_slab(-w / 2, w / 2, -d / 2, d / 2, 0, h, c)]
    z0, z1 = k.cavity.z
    t = k.cavity.wall
    plinth_color = k.base[1] if k.base else c
    parts = []
    if k.base:
        parts.append(_slab(-w / 2 - 0.05, w / 2 + 0.05, -d / 2 - 0.05, d / 2, 0, k.base[0], plinth_color))
    floor_top = z0 - (t + 0.005 if k.door and k.door.prismatic else 0.0)  # a drawer tray has its own floor
    parts.append(_slab(-w / 2, w / 2, -d / 2, d / 2, k.base[0] if k.base else 0.0, floor_top, c))
    parts += [_slab(-w / 2, -w / 2 + t, -d / 2, d / 2, floor_top, z1, c), _slab(w / 2 - t, w / 2, -d / 2, d / 2, floor_top, z1, c),
              _slab(-w / 2, w / 2, -d / 2, -d / 2 + t, floor_top, z1, c)]
    if k.cavity.open == "top" and not (k.door and k.door.prismatic):
        parts.append(_slab(-w / 2, w / 2, d / 2 - t, d / 2, floor_top, z1, c))  # a basin's or basket's front wall
    if z1 < h:
        parts.append(_slab(-w / 2, w / 2, -d / 2, d / 2, z1, h, c))
    if _control_strip(k):  # the front beside the door, closing the cavity there
        parts.append(_slab(w / 2 - CONTROL_STRIP, w / 2, d / 2 - 0.02, d / 2, floor_top, z1, c))
    if k.tap:
        back, (z0, z1) = -d / 2, TAP_HEIGHT
        parts += [_slab(-0.015, 0.015, back + TAP_POST[0], back + TAP_POST[1], h, h + z1, k.tap),
                  _slab(-0.015, 0.015, back + TAP_POST[0], back + TAP_REACH, h + z0, h + z1, k.tap)]
    return parts


def _control_strip(k: FurnitureKind) -> bool:
    """A side-hinged appliance door leaves a strip of the front for its lamp and switch."""
    return bool(k.light and k.door and k.door.hinge != "bottom")


def _door_link(k: FurnitureKind):
    """The moving part of an openable piece: boxes in the joint frame, joint origin and axis,
    handle centre and bar direction (furniture frame)."""
    w, d, h = k.size
    z0, z1 = k.cavity.z
    t = k.cavity.wall
    dc = k.door.color
    hc = (0.75, 0.75, 0.72, 1)
    if k.door.prismatic:
        tw, td, th = w - 2 * t - 0.01, d - t - 0.02, z1 - z0
        origin = (0.0, d / 2, z0 - t)
        # tray in the joint frame: y from -td .. 0 (front panel at 0)
        parts = [_slab(-tw / 2, tw / 2, -td, 0, 0, t, dc), _slab(-tw / 2, -tw / 2 + t, -td, 0, 0, th, dc),
                 _slab(tw / 2 - t, tw / 2, -td, 0, 0, th, dc), _slab(-tw / 2, tw / 2, -td, -td + t, 0, th, dc),
                 _slab(-w / 2, w / 2, 0, 0.02, -0.01, th + 0.01, dc)]
        handle = (0.0, 0.02 + HANDLE_STANDOUT, th / 2)
        parts.append(_slab(-0.09, 0.09, handle[1] - 0.012, handle[1] + 0.012, handle[2] - 0.012, handle[2] + 0.012, hc))
        parts += [_slab(s * 0.07 - 0.006, s * 0.07 + 0.006, 0.02, handle[1], handle[2] - 0.006, handle[2] + 0.006, hc) for s in (-1, 1)]
        return parts, origin, (0.0, 1.0, 0.0), tuple(np.add(origin, handle)), (1.0, 0.0, 0.0)
    panel = CONTROL_STRIP if _control_strip(k) else 0.0
    lz0, lz1 = z0 - t, z1 + t
    if k.door.hinge == "bottom":
        origin = (0.0, d / 2 + 0.012, lz0)
        parts = [_slab(-w / 2 + 0.01, w / 2 - 0.01, -0.012, 0.012, 0.0, lz1 - lz0, dc)]
        handle = (0.0, 0.012 + HANDLE_STANDOUT, lz1 - lz0 - 0.05)
        parts.append(_slab(-0.16, 0.16, handle[1] - 0.012, handle[1] + 0.012, handle[2] - 0.012, handle[2] + 0.012, hc))
        parts += [_slab(s * 0.14 - 0.006, s * 0.14 + 0.006, 0.012, handle[1], handle[2] - 0.006, handle[2] + 0.006, hc) for s in (-1, 1)]
        return parts, origin, (-1.0, 0.0, 0.0), tuple(np.add(origin, handle)), (1.0, 0.0, 0.0)
    sign = -1.0 if k.door.hinge == "left" else 1.0  # hinge at local x = sign * w/2
    leaf_w = w - 0.01 - panel
    origin = (sign * (w / 2 - 0.005), d / 2 + 0.012, lz0)
    parts = [_slab(min(0, -sign * leaf_w), max(0, -sign * leaf_w), -0.012, 0.012, 0.0, lz1 - lz0, dc)]
    handle = (-sign * (leaf_w - 0.05), 0.012 + HANDLE_STANDOUT, (lz1 - lz0) / 2)
    parts.append(_slab(handle[0] - 0.012, handle[0] + 0.012, handle[1] - 0.012, handle[1] + 0.012, handle[2] - 0.09, handle[2] + 0.09, hc))
    parts += [_slab(handle[0] - 0.006, handle[0] + 0.006, 0.012, handle[1], handle[2] + s * 0.07 - 0.006, handle[2] + s * 0.07 + 0.006, hc) for s in (-1, 1)]
    axis = (0.0, 0.0, 1.0) if sign < 0 else (0.0, 0.0, -1.0)  # positive angles swing the leaf out
    return parts, origin, axis, tuple(np.add(origin, handle)), (0.0, 0.0, 1.0)


def tap_outlet(k: FurnitureKind) -> np.ndarray:
    """Where a sink's water leaves the tap (furniture frame): under the tip of its arm."""
    _, d, h = k.size
    return np.array([0.0, -d / 2 + TAP_REACH - 0.015, h + TAP_HEIGHT[0]])


def switch_center(k: FurnitureKind) -> np.ndarray:
    """Centre of an appliance's switch button (furniture frame): on the control strip below the
    lamp beside a side-hinged door, or beside the lamp above a bottom-hinged one — away from the
    handle, so that a hand opening the door does not press it."""
    w, d, _ = k.size
    if _control_strip(k):
        x, z = w / 2 - CONTROL_STRIP / 2, (k.cavity.z[0] + k.cavity.z[1]) / 2 - 0.075
    else:
        x, z = 0.2, k.cavity.z[1] + 0.06
    return np.array([x, d / 2 + SWITCH_STANDOUT / 2, z])


def switch_face(k: FurnitureKind) -> np.ndarray:
    """The middle of the switch button's front face (furniture frame): where a fingertip presses."""
    return switch_center(k) + np.array([0.0, SWITCH_STANDOUT / 2, 0.0])


def _build_furniture(cid: int, f: FurniturePlan, catalog: Catalog) -> Thing:
    k = f.kind
    col, vis = _shapes(cid, _furniture_parts(k))
    links: dict = {"linkMasses": [], "linkCollisionShapeIndices": [], "linkVisualShapeIndices": [], "linkPositions": [],
                   "linkOrientations": [], "linkInertialFramePositions": [], "linkInertialFrameOrientations": [],
                   "linkParentIndices": [], "linkJointTypes": [], "linkJointAxis": []}

    def add_link(mass, c, v, pos, jtype, axis):
        for key, val in zip(links, (mass, c, v, pos, (0, 0, 0, 1), (0, 0, 0), (0, 0, 0, 1), 0, jtype, axis)):
            links[key].append(val)
        return len(links["linkMasses"]) - 1

    door = None
    if k.door:
        parts, origin, axis, handle, bar = _door_link(k)
        dcol, dvis = _shapes(cid, parts)
        jtype = pb.JOINT_PRISMATIC if k.door.prismatic else pb.JOINT_REVOLUTE
        door = (add_link(1.5, dcol, dvis, origin, jtype, axis), origin, axis, handle, bar)
    light = None
    if k.light:
        w, d, _ = k.size
        z = (k.cavity.z[0] + k.cavity.z[1]) / 2 if k.door and k.door.hinge != "bottom" else k.cavity.z[1] + 0.04
        x = w / 2 - 0.05 if k.door and k.door.hinge != "bottom" else 0.0
        lcol = -1
        lvis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=(0.03, 0.006, 0.03), rgbaColor=k.light[0], physicsClientId=cid)
        light = add_link(0.0, lcol, lvis, (x, d / 2 + 0.006, z), pb.JOINT_FIXED, (0, 0, 1))
    switch = None
    if k.light:  # every appliance with a lamp has a switch
        half = (SWITCH_HALF[0], SWITCH_STANDOUT / 2, SWITCH_HALF[1])
        scol = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half, physicsClientId=cid)
        svis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half, rgbaColor=SWITCH_COLOR, physicsClientId=cid)
        switch = add_link(0.0, scol, svis, tuple(switch_center(k)), pb.JOINT_FIXED, (0, 0, 1))
    body = pb.createMultiBody(0, col, vis, basePosition=(f.x, f.y, 0.0), baseOrientation=_yaw_quat(f.yaw),
                              physicsClientId=cid, **links)
    thing = Thing(f.name, k.type, [body], kind=k, furniture=f, light_link=light, switch_link=switch)
    if door:
        j, origin, axis, handle, bar = door
        full = k.door.full
        pb.changeDynamics(body, j, jointLowerLimit=-0.02, jointUpperLimit=full + 0.02, physicsClientId=cid)
        thing.hinge = Hinge(body, j, k.door.prismatic, full, f.to_world(origin), f.direction(axis[:2]) + np.array([0, 0, axis[2]]),
                            f.to_world(handle), f.front, f.direction(bar[:2]) + np.array([0, 0, bar[2]]),
                            0.16 if k.door.hinge == "bottom" else 0.09, **_leaf_box(cid, body, j), lower=-0.02, upper=full + 0.02, friction=k.door.friction)
        state = f.state or "closed"
        pb.resetJointState(body, j, full if state == "open" else 0.0, physicsClientId=cid)
        _friction(cid, body, j, k.door.friction)
    return thing


# ---------------------------------------------------------------- items


def item_shapes(cid: int, k: ItemKind, color: Color | None = None, half: bool = False):
    """Collision and visual shape of an item kind (``half``: one half after cutting, along x)."""
    color = color or k.color
    if k.shape == "sphere" or (k.shape == "cylinder" and half and not k.lying):
        # halves of round things are boxes of the same footprint: simple and stable on a table
        ex = k.extent
        he = (ex[0] / 4, ex[1] / 2, ex[2] / 2) if half else None
        if he:
            return (pb.createCollisionShape(pb.GEOM_BOX, halfExtents=he, physicsClientId=cid),
                    pb.createVisualShape(pb.GEOM_BOX, halfExtents=he, rgbaColor=color, physicsClientId=cid))
        r = k.size[0]
        return (pb.createCollisionShape(pb.GEOM_SPHERE, radius=r, physicsClientId=cid),
                pb.createVisualShape(pb.GEOM_SPHERE, radius=r, rgbaColor=color, physicsClientId=cid))
    if k.shape == "box":
        he = tuple(s / 2 for s in k.size)
        if half:
            he = (he[0] / 2, he[1], he[2])
        return (pb.createCollisionShape(pb.GEOM_BOX, halfExtents=he, physicsClientId=cid),
                pb.createVisualShape(pb.GEOM_BOX, halfExtents=he, rgbaColor=color, physicsClientId=cid))
    r, h = k.size
    if half:
        h = h / 2
    orn = pb.getQuaternionFromEuler((0, math.pi / 2, 0)) if k.lying else (0, 0, 0, 1)
    return (pb.createCollisionShape(pb.GEOM_CYLINDER, radius=r, height=h, collisionFrameOrientation=orn, physicsClientId=cid),
            pb.createVisualShape(pb.GEOM_CYLINDER, radius=r, length=h, visualFrameOrientation=orn, rgbaColor=color,
                                 physicsClientId=cid))


def make_item_body(cid: int, k: ItemKind, position, yaw: float, color: Color | None = None, half: bool = False,
                   mass: float | None = None) -> int:
    """A free rigid body of kind ``k`` at ``position`` (its centre, world frame), turned ``yaw`` about z;
    ``half`` makes a half-filled look. Returns the body id."""
    col, vis = item_shapes(cid, k, color, half)
    body = pb.createMultiBody(mass if mass is not None else k.mass, col, vis, basePosition=position,
                              baseOrientation=_yaw_quat(yaw), physicsClientId=cid)
    pb.changeDynamics(body, -1, lateralFriction=0.9, rollingFriction=0.002, spinningFriction=0.002,
                      physicsClientId=cid)
    return body


# ---------------------------------------------------------------- the whole scene


def build_scene(cid: int, plan: ScenePlan, catalog: Catalog, types: dict[str, str]) -> Scene:
    """Build the plan in client ``cid``: rooms, walls, doors, furniture and items, each registered by
    name with its PDDL type from ``types``."""
    things: dict[str, Thing] = {}
    walls = _build_rooms(cid, plan, catalog, things)
    for d in plan.doors.values():
        things[d.name] = _build_door(cid, d, catalog)
    for f in plan.furniture.values():
        things[f.name] = _build_furniture(cid, f, catalog)
    for it in plan.items.values():
        body = make_item_body(cid, it.kind, it.position, it.yaw)
        things[it.name] = Thing(it.name, types[it.name], [body], kind=it.kind, item=it,
                                states={"filled": 0.0, "heated": False, "sliced": False})
    for name, t in things.items():
        if t.pddl_type == "appliance":
            t.states["turned_on"] = False
    return Scene(cid, plan, things, walls)
