"""Ground truth: which household atoms hold, read off the physics state.

Every predicate of ``domains/household.pddl`` is decided from physics — contacts, geometry,
joints, constraints or the visible state of an object — never from what the plan expected, and
never from a threshold the executive's perception also uses (its own are in
:mod:`vap_bt.scene.relations`, chosen for what a camera can measure):

* ``on(o, s)``: s supports o. Some body of o touches s — pybullet's closest points between them
  within ``CONTACT_GAP`` (a resting body sits on its support within a millimetre, a lifted one is
  clear by its lift) — with the contact normal pointing up from s (within 45° of vertical: o
  presses down on s, it does not lean on its side), and o is not held; or o rests so on another
  item that s supports (a bowl standing on a plate on the table is supported by the table).
  ``on(o, floor_r)``: the same with room r's floor slab, o's centre inside the room's outline;
* ``holding(o)``: the grasp constraint ties o to the hand; ``hand_empty``: no item is held;
* ``open``/``closed``: the hinge or slide's fraction of its full travel against the catalogue's
  thresholds (a half-open door is neither); things without a door (a basket) are always open;
* ``in_room``, ``robot_in``: positions inside a room's floor rectangle (a held item is in no room;
  a door is in both of its rooms); ``robot_at(x)``: the base stands in x's room within
  ``AT_DISTANCE`` of x (floors: anywhere in the room; held items: always);
* ``inview(x)``: x covers at least the camera's pixel threshold in the current wrist image;
* ``blocking(b, o)``: b stands on o's support inside the volume the gripper sweeps reaching o
  from the support's front (the side the robot works from; a floor's: the room's corridor): a
  corridor as wide as the open gripper (the wider of its body and its open fingers, read off the
  robot's collision shapes), from o's front face to the support's front edge (on a floor: the
  gripper's length, flange to tcp, in front of o) — part of b's footprint lies in it, and b's
  centre is in front of o's; ``reachable(o)``: nothing blocks o;
* ``filled``, ``sliced``, ``heated``, ``turned_on``: the object's physical state;
* ``clear``, ``openable``, ``fillable``, ``connects``: rigid facts of the layout.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.sim.pb import pb
from vap_bt.sim.pb_camera import box_corners
from vap_bt.sim.pb_catalog import Catalog
from vap_bt.sim.pb_robot import Robot
from vap_bt.sim.pb_scene import Scene, Thing

AT_DISTANCE = 1.3  # m from the base centre to the thing's box
RIGID = ("clear", "openable", "fillable", "connects")
#: m between two bodies within which they touch: pybullet keeps resting bodies within a millimetre
#: of each other (slightly interpenetrating); 5 mm absorbs the solver's jitter, and anything lifted
#: off its support by more is not resting on it
CONTACT_GAP = 0.005
#: a contact supports o when its normal, from s towards o, is within 45 degrees of vertical
SUPPORT_NORMAL = math.cos(math.radians(45.0))


class Truth:
    """The household atoms that hold now, decided from the physics state (the oracle of the pybullet
    world). Each fluent predicate is a method ``_<predicate>``; rigid facts are the layout's."""

    def __init__(self, scene: Scene, robot: Robot, catalog: Catalog, rigid: set[Atom],
                 visible_names: Callable[[], set[str]]) -> None:
        self.scene, self.robot, self.catalog = scene, robot, catalog
        self.rigid = rigid
        self.visible_names = visible_names  # names above the pixel threshold in the wrist view
        #: how wide the gripper sweeps reaching for something, and how long it is (m)
        self.gripper_width, self.gripper_length = _gripper_size(robot)

    # ------------------------------------------------------------ geometry

    def aabb(self, name: str) -> tuple[float, ...]:
        """The world-frame box (x0, y0, z0, x1, y1, z1) around every link of the thing named ``name``."""
        boxes = self.link_boxes(name)
        lo = np.min([b[:3] for b in boxes], axis=0)
        hi = np.max([b[3:] for b in boxes], axis=0)
        return (*map(float, lo), *map(float, hi))

    def link_boxes(self, name: str) -> list[tuple[float, ...]]:
        """The axis-aligned box of every link of the thing (one for an item, the carcass and
        each leaf for furniture): an open door's swing is not part of what the camera can see."""
        t = self.scene.things[name]
        if t.room is not None and not t.bodies:  # a room: its floor rectangle
            r = self.scene.plan.rooms[name]
            return [(r.x0, r.y0, 0.0, r.x1, r.y1, self.catalog.room.wall_height)]
        out = []
        for b in t.bodies:
            links = range(-1, pb.getNumJoints(b, physicsClientId=self.scene.client))
            for link in links:
                a, c = pb.getAABB(b, link, physicsClientId=self.scene.client)
                if a[0] > c[0]:  # a link without shapes
                    continue
                out.append((*map(float, a), *map(float, c)))
        return out

    def outline(self, name: str) -> list[np.ndarray]:
        """The corners (8, 3) of every box the thing fills: an item's own box, turned with it
        (a half after a cut: half its length), else :meth:`link_boxes`."""
        t = self.scene.things[name]
        if t.item is None or t.kind is None:
            return [box_corners(b) for b in self.link_boxes(name)]
        ex = np.array(t.kind.extent, float)
        if t.states.get("sliced"):
            ex[0] /= 2
        unit = box_corners((*(-ex / 2), *(ex / 2)))
        out = []
        for b in t.bodies:
            p, q = pb.getBasePositionAndOrientation(b, physicsClientId=self.scene.client)
            R = np.array(pb.getMatrixFromQuaternion(q)).reshape(3, 3)
            out.append(unit @ R.T + np.asarray(p))
        return out

    def center(self, name: str) -> np.ndarray:
        """Where the thing is (world frame): an item's body origin (the mean of its pieces once sliced),
        anything else's box centre."""
        t = self.scene.things[name]
        if t.item is not None:
            return np.mean([pb.getBasePositionAndOrientation(b, physicsClientId=self.scene.client)[0]
                            for b in t.bodies], axis=0)
        a = self.aabb(name)
        return (np.array(a[:3]) + np.array(a[3:])) / 2

    def room_of_point(self, p) -> str | None:
        """The room whose floor holds point ``p`` (its x, y), or None."""
        return self.scene.plan.room_at(float(p[0]), float(p[1]))

    def joint_value(self, name: str) -> float:
        """The door or drawer joint of ``name`` now: hinge angle (rad) or slide (m)."""
        h = self.scene.things[name].hinge
        return pb.getJointState(h.body, h.joint, physicsClientId=self.scene.client)[0]

    def joint_fraction(self, t: Thing) -> float:
        """How far ``t``'s door or drawer is open: 0 shut, 1 at its full travel."""
        return abs(self.joint_value(t.name)) / abs(t.hinge.full)

    def held(self) -> str | None:
        """The item in the hand, or None (an empty hand, or one holding a handle)."""
        g = self.robot.grip
        return g.name if g is not None and g.link == -1 else None

    # ------------------------------------------------------------ predicates

    def holds(self, atom: Atom) -> bool:
        """Whether ground atom ``atom`` holds now; an unknown predicate or object does not hold."""
        if atom.predicate in RIGID:
            return atom in self.rigid
        fn = getattr(self, "_" + atom.predicate, None)
        if fn is None:
            return False
        try:
            return bool(fn(*atom.args))
        except KeyError:  # an object this world does not have
            return False

    def _hand_empty(self) -> bool:
        return self.held() is None

    def _holding(self, o: str) -> bool:
        return self.held() == o

    def _robot_in(self, r: str) -> bool:
        x, y, _ = self.robot.base_pose
        return self.scene.plan.rooms[r].contains(x, y)

    def _in_room(self, x: str, r: str) -> bool:
        t = self.scene.things[x]
        if t.door is not None:
            return r in (t.door.low, t.door.high)
        if t.furniture is not None:
            return t.furniture.room == r
        if t.room is not None:
            return t.room == r
        if self.held() == x:
            return False
        return self.room_of_point(self.center(x)) == r

    def _robot_at(self, x: str) -> bool:
        t = self.scene.things[x]
        bx, by, _ = self.robot.base_pose
        if t.room is not None and t.bodies:  # a floor: anywhere in its room
            return self._robot_in(t.room)
        if self.held() == x:
            return True
        rooms = (t.door.low, t.door.high) if t.door else (t.furniture.room if t.furniture else self.room_of_point(self.center(x)),)
        if self.room_of_point((bx, by)) not in rooms:
            return False
        a = self.aabb(x)
        dx = max(a[0] - bx, 0.0, bx - a[3])
        dy = max(a[1] - by, 0.0, by - a[4])
        return math.hypot(dx, dy) <= AT_DISTANCE

    def _inview(self, x: str) -> bool:
        return x in self.visible_names()

    def _open(self, x: str) -> bool:
        t = self.scene.things[x]
        if t.hinge is None:
            return t.pddl_type in ("container", "appliance")
        return self.joint_fraction(t) >= self.catalog.open_above

    def _closed(self, x: str) -> bool:
        t = self.scene.things[x]
        return t.hinge is not None and self.joint_fraction(t) <= self.catalog.closed_below

    def _on(self, o: str, s: str) -> bool:
        return self._supported(o, s, frozenset())

    def _supported(self, o: str, s: str, via: frozenset[str]) -> bool:
        """Does ``s`` support item ``o`` (directly, or through items in ``via``'s complement)?"""
        held = self.held()
        if held == o:
            return False
        to, ts = self.scene.things[o], self.scene.things[s]
        if to.item is None:
            return False
        if ts.room is not None:  # a floor: its slab, and o inside the room's outline
            c = self.center(o)
            if not (ts.bodies and self.scene.plan.rooms[ts.room].contains(c[0], c[1])):
                return False
        elif ts.furniture is None:
            return False
        if self._presses_on(to.bodies, ts.bodies):
            return True
        # through another item standing on s (not one already on the way: no cycles)
        for t in self.scene.items():
            if t.name in (o, held) or t.name in via:
                continue
            if self._presses_on(to.bodies, t.bodies) and self._supported(t.name, s, via | {o}):
                return True
        return False

    def _presses_on(self, upper: list[int], lower: list[int]) -> bool:
        """Do any of the ``upper`` bodies touch any of the ``lower`` ones from above?"""
        cid = self.scene.client
        for a in upper:
            for b in lower:
                # the normal on B points from B towards A: up, when B carries A
                if any(p[7][2] >= SUPPORT_NORMAL for p in pb.getClosestPoints(a, b, CONTACT_GAP, physicsClientId=cid)):
                    return True
        return False

    def _inside(self, o: str, c: str) -> bool:
        if self.held() == o:
            return False
        t = self.scene.things[c]
        f = t.furniture
        if f is None or f.kind.cavity is None:
            return False
        p = self._local(f, self.center(o))
        w, d, _ = f.kind.size
        cav = f.kind.cavity
        shift = 0.0
        if t.hinge is not None and t.hinge.prismatic:  # the cavity is the tray, which slides out
            shift = pb.getJointState(t.hinge.body, t.hinge.joint, physicsClientId=self.scene.client)[0]
        return (abs(p[0]) <= w / 2 - cav.wall + 0.01 and -d / 2 + shift <= p[1] <= d / 2 + shift + 0.02
                and cav.z[0] - 0.03 <= p[2] <= cav.z[1] + 0.02)

    def _blocking(self, b: str, o: str) -> bool:
        if b == o or self.held() in (b, o):
            return False
        tb, to = self.scene.things[b], self.scene.things[o]
        if tb.item is None or to.item is None:
            return False
        support = self._support(o)
        if support is None or support != self._support(b):
            return False
        front, side = self._front_axes(support)
        co = self.center(o)
        if float((self.center(b) - co)[:2] @ front[:2]) <= 0.0:
            return False  # behind o or beside it: not on the way in
        # o's and b's footprints in the corridor's axes (ahead of o's centre, across)
        po = np.concatenate(self.outline(o))[:, :2] - co[:2]
        pb_ = np.concatenate(self.outline(b))[:, :2] - co[:2]
        a_o = float((po @ front[:2]).max())  # o's front face
        ahead, across = pb_ @ front[:2], pb_ @ side[:2]
        t = self.scene.things[support]
        if t.furniture is not None:  # as far as the support's front edge
            end = float((np.asarray(t.furniture.to_world((0.0, t.furniture.kind.size[1] / 2, 0.0)))[:2] - co[:2]) @ front[:2])
        else:  # on a floor: the gripper's own length in front of o
            end = a_o + self.gripper_length
        half = self.gripper_width / 2
        return bool(ahead.max() > a_o and ahead.min() < end and across.max() > -half and across.min() < half)

    def _reachable(self, o: str) -> bool:
        if self.scene.things[o].item is None:
            return False
        return not any(self._blocking(b.name, o) for b in self.scene.items())

    def _filled(self, o: str) -> bool:
        return float(self.scene.things[o].states.get("filled", 0.0)) >= 0.95

    def _sliced(self, o: str) -> bool:
        return bool(self.scene.things[o].states.get("sliced", False))

    def _heated(self, o: str) -> bool:
        return bool(self.scene.things[o].states.get("heated", False))

    def _turned_on(self, a: str) -> bool:
        return bool(self.scene.things[a].states.get("turned_on", False))

    # ------------------------------------------------------------ helpers

    @staticmethod
    def _local(f, p) -> np.ndarray:
        c, s = math.cos(f.yaw), math.sin(f.yaw)
        dx, dy = p[0] - f.x, p[1] - f.y
        return np.array([c * dx + s * dy, -s * dx + c * dy, p[2]])

    def _support(self, o: str) -> str | None:
        """The surface an item rests on now (furniture or floor), if any."""
        for t in self.scene.things.values():
            if (t.furniture is not None and t.pddl_type == "surface") or (t.room is not None and t.bodies):
                if self._on(o, t.name):
                    return t.name
        return None

    def _front_axes(self, support: str) -> tuple[np.ndarray, np.ndarray]:
        """Unit vectors towards the side the robot works from, and along that side."""
        t = self.scene.things[support]
        if t.furniture is not None:
            f = np.asarray(t.furniture.front, float)
        else:  # floor items are approached from the corridor
            f = np.array([0.0, 1.0, 0.0])
        return f, np.array([-f[1], f[0], 0.0])

    def support_of(self, o: str) -> str | None:
        """The surface or floor item ``o`` rests on now, or None (held, inside something, or falling)."""
        return self._support(o)

    def container_of(self, o: str) -> str | None:
        """The container (not a sink) item ``o`` is inside now, or None."""
        for t in self.scene.things.values():
            if t.furniture is not None and t.furniture.kind.cavity is not None and t.pddl_type != "sink":
                if self._inside(o, t.name):
                    return t.name
        return None


def _gripper_size(robot: Robot) -> tuple[float, float]:
    """The gripper's width across its fingers, open (the wider of its body and its fingers at the
    full stroke with their pads), and its length from the flange to the tcp — from the robot's own
    collision shapes and configuration."""
    g = robot.cfg.gripper
    width = 0.0
    for link in ("gripper_base_link", *(_finger_links(robot))):
        for shape in pb.getCollisionShapeData(robot.id, robot.link[link], physicsClientId=robot.cid):
            if shape[2] == pb.GEOM_BOX:
                dims = shape[3]  # full extents; the fingers slide along the flange's y axis
                width = max(width, dims[1] if link == "gripper_base_link" else g.stroke + 2 * dims[1])
    return width, float(g.tcp_offset)


def _finger_links(robot: Robot) -> list[str]:
    return [n for n in robot.link if "finger" in n]
