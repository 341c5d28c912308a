"""Where the base stands and how it gets there: standoff and work poses, paths round obstacles.

Two rules say where the robot stands. To look at a piece of furniture it stands squarely in
front of it at a *standoff*; to look at an item, at its support's standoff shifted sideways to
face the item (floor items from the corridor side). To work with the hand it stands at a *work
pose*: a reach away from the worked point (``WORK_DISTANCE``, less for a top-down approach than
for a horizontal one), stepped sideways or back until the base keeps clear of everything the map
and the last looks place there (walls, furniture, door leaves as last seen) and the arm reaches
the poses the skill will need from there (IK clear of the scene, checked before the base moves).

A base path is straight when that is clear of those obstacles — for the base's footprint and,
except on the last stretch where the arm reaches over what it works, for the folded arm too —
else it goes through one via pose backed off from the goal or round a corner. A trip to another
room follows the house's corridor through the doorways; before each it looks at the door, and a
door it does not see open (:meth:`~skills.scene_model.SceneModel.fit_leaf`) stops the trip.
"""

from __future__ import annotations

import math
from typing import Iterator

import numpy as np

from skills.body import Body, angle_to
from skills.eyes import Eyes
from skills.scene_model import SceneModel
from vap_bt.motion.footprint import FOLDED_ARM, apart, base_free, footprint, hull, near, placed

#: base centre to the worked point, horizontally, for a top-down and a horizontal approach
WORK_DISTANCE = {"top": 0.62, "front": 0.74}
BASE_CLEARANCE = 0.40  # base centre to the front face of the furniture at least
WORK_SHIFTS = (0.0, 0.08, -0.08, 0.16, -0.16, 0.24, -0.24)  # sideways, to keep a work pose clear
WORK_BACKOFFS = (0.0, 0.05, 0.1, 0.15, 0.25, 0.35, 0.45)  # further back, when no sideways step is clear or reaches (an oven's door lies open in front)
WORK_MARGIN = 0.08  # base footprint to obstacles at a work pose (the arm is wider than the base)
PARKED_MARGIN = 0.015  # footprint to obstacles along a drive
#: the arm's outline to a room door's leaf (the outline is the folded arm's, and the base lags its
#: set-point on a turn: an arm passing 3 cm off an open leaf on paper struck it)
LEAF_MARGIN = 0.08
#: turns (rad) of the way from a worked point to the robot, tried in order when nothing in front of
#: the point says which side to work it from (an item on the floor): a leaf or a piece of furniture
#: beside it can keep the arm from one side and not from another
AROUND = (0.0, math.pi / 4, -math.pi / 4, math.pi / 2, -math.pi / 2, 3 * math.pi / 4, -3 * math.pi / 4, math.pi)
#: m between a work pose tried again and one the arm failed to work from (a different stand)
AVOID_RADIUS = 0.1
DETOUR_BACKOFFS = (0.5, 0.8, 1.1)  # via poses behind the goal when the straight way is blocked
#: via poses off to either side of the straight way (m), at these shares of it, when neither the
#: straight way nor one by the vias behind the goal or round a corner is clear: an item dropped
#: on the way (a stick that slipped from the hand on the corridor's line) lies across every
#: one of those when the goal is straight ahead (gather_kindling seed 1: "no clear way")
DETOUR_ASIDE, DETOUR_ALONG = (0.4, 0.7, 1.0), (0.5, 0.75, 0.25)
LEAVE_SLACK = 0.1  # a drive may start close to an obstacle (a work pose): checked once this far away
HAND_RADIUS = 0.07  # the gripper round its tcp, seen from above
WRIST_BEHIND = 0.15  # the wrist behind the tcp along the hand's axis
ARM_SLACK = 0.5  # the last part of a drive, where the arm reaches over the furniture to be worked
#: base centre to a piece of furniture's front when looking at it; a surface higher than the
#: camera's eye line is looked at from further back, to see its top
STANDOFF, TALL_STANDOFF, TALL = 1.05, 1.8, 1.0
#: m along a furniture's front a look pose moves off one where the base would not stand clear
FRONT_SHIFTS = (0.0, 0.2, -0.2, 0.4, -0.4)
FLOOR_STANDOFF = 0.72  # base centre to a floor item, from the corridor side
CORRIDOR_SLACK = 0.3  # m past the corridor's middle the robot may stand to look at a floor item
FLOOR_NEAREST = 0.5  # base centre to a floor item at least (the base's half length and a margin)
#: base centre to a floor item, for the poses round it tried when the preferred one is not clear
FLOOR_AROUND = (FLOOR_STANDOFF, 0.85, 0.6, FLOOR_NEAREST)
DOOR_VIEW = 1.8  # base centre to a doorway when looking at its door: the whole leaf in the frame
DOOR_STOP = 0.95  # base centre to a doorway when it stops in front of it on a trip
#: a door counts as open for the base to pass once it has swung this share of its travel
DOOR_PASSABLE = 0.55
DOOR_LOOK_HEIGHT = 0.8
DOOR_LOOK_LIFT = 0.2  # m higher the eye goes when the usual look at a door is not clear
DOORWAY_SPREAD = (-0.3, 0.0, 0.3)  # across the opening, in shares of the door's width
DOORWAY_HEIGHTS = (0.5, 0.8, 1.1, 1.4)
CORRIDOR_SPEED = 1.0
APPROACH_SPEED = 0.6
#: poses along a straight last stretch checked for collisions (:meth:`Navigator.reaches`)
LINE_CHECK_STEPS = 4

Pose = tuple[float, float, float]


class Blocked(Exception):
    """A trip stopped short: a door on the way is not open (the message names it)."""


class Navigator:
    """Base poses and paths, from the map and what the camera shows."""

    def __init__(self, body: Body, scene: SceneModel, eyes: Eyes) -> None:
        self.body, self.scene, self.eyes = body, scene, eyes

    # -- where to stand ----------------------------------------------------------------------

    def standoff(self, name: str, point=None, support: str | None = None) -> Pose:
        """Where to stand to look at ``name``: furniture from its front, a door from the robot's
        side of it, a room from its middle, an item (believed at ``point`` on ``support``) from
        its support's front, facing it, or from the corridor side when it is on the floor."""
        f = self.scene.furniture.get(name)
        if f is not None:
            return self._clear_front(name)
        door = self.scene.site.door(name)
        if door is not None:
            here = self.scene.room_at(*self.body.base_pose()[:2]) or door.rooms[0]
            return self.door_pose(name, here, DOOR_VIEW)
        room = self.scene.site.room(name) or self.scene.site.room(self.scene.site.floors().get(name, ""))
        if room is not None:
            c = self.scene.room_center(room.name)
            return (float(c[0]), self.scene.corridor_y(), math.pi / 2)
        if point is None:
            raise ValueError(f"no belief of where {name} is")
        sup = self.scene.furniture.get(support or "")
        if sup is not None:
            lateral = float(np.clip(sup.local(point)[0], -sup.width / 2, sup.width / 2))
            return self._clear_front(sup.name, lateral)
        # on the floor: from the corridor's side, facing it, at most a little past the corridor's
        # middle (the far side is the furniture's). An item near that line is looked at from its
        # near side, facing the furniture: a pose held short of it stood on a slipped cup, facing
        # away, and the drive there kicked it under the cabinet. One well past the line is looked at
        # from the line, facing away as before: facing it, the grasp of a knife half under a table
        # picks another work pose whose last, unchecked stretch strikes the table's edge (the
        # arm's last stretch is not yet checked against the scene: see Hands.straight_in)
        cap = self.scene.corridor_y() + CORRIDOR_SLACK
        y = min(point[1] + FLOOR_STANDOFF, cap)
        if y - point[1] >= FLOOR_NEAREST or point[1] >= cap + FLOOR_NEAREST:
            preferred = (float(point[0]), float(y), -math.pi / 2)
        else:
            preferred = (float(point[0]), float(point[1] - FLOOR_STANDOFF), math.pi / 2)
        return self._clear_floor_standoff(point, preferred)

    def _clear_floor_standoff(self, point, preferred: Pose) -> Pose:
        """``preferred`` when the base stands clear there; else the first clear pose round the
        item, facing it, ``FLOOR_STANDOFF`` away along the turned ways of :data:`AROUND` (from the
        preferred side on; closer, down to ``FLOOR_NEAREST``, after that), in the item's room
        first, the arm folded over the base clear too first. An item dropped by a doorway left
        both the corridor-side and the near-side pose in the wall, and the drive there ran the
        base into it. ``preferred`` (the drive will find no clear way) when none is clear."""
        obstacles, low = self.scene.obstacles(), self.scene.low_obstacles()
        room = self.scene.room_at(*point[:2])

        def clear(pose: Pose, folded: bool, same_room: bool) -> bool:
            where = self.scene.room_at(*pose[:2])
            return (where is not None and (not same_room or where == room)
                    and base_free(pose, obstacles, PARKED_MARGIN, folded=folded, low=low))

        if clear(preferred, False, False):
            return preferred
        toward = math.atan2(preferred[1] - point[1], preferred[0] - point[0])
        poses = [(float(point[0] + d * math.cos(toward + t)), float(point[1] + d * math.sin(toward + t)),
                  float(math.remainder(toward + t + math.pi, 2 * math.pi)))
                 for d in FLOOR_AROUND for t in AROUND]
        for same_room, folded in ((True, True), (True, False), (False, True), (False, False)):
            for pose in poses:
                if clear(pose, folded, same_room):
                    return pose
        return preferred

    def _clear_front(self, name: str, lateral: float = 0.0) -> Pose:
        """:meth:`_front_of` where the base stands clear there, else the nearest clear pose along
        the furniture's front (:data:`FRONT_SHIFTS`): a knife dropped in front of the cutting board
        lay under the pose to look at the egg from, and the find failed on it three times.
        The first pose (the drive will find no clear way) when none is clear."""
        obstacles, low = self.scene.obstacles(), self.scene.low_obstacles()
        poses = [self._front_of(name, lateral + d) for d in FRONT_SHIFTS]
        return next((p for p in poses if base_free(p, obstacles, PARKED_MARGIN, low=low)), poses[0])

    def _front_of(self, name: str, lateral: float = 0.0) -> Pose:
        f = self.scene.furniture[name]
        tall = f.info.type == "surface" and f.height > TALL
        p = f.to_world((lateral, f.depth / 2 + (TALL_STANDOFF if tall else STANDOFF), 0.0))
        return (float(p[0]), float(p[1]), math.atan2(-f.front[1], -f.front[0]))

    def door_pose(self, door: str, room: str, dist: float) -> Pose:
        """Facing ``door`` from ``room``, ``dist`` from the doorway."""
        d = self.scene.site.door(door)
        x, y, _ = d.pose
        low = self.scene.room_center(d.rooms[0])[0] < x  # rooms[0] lies on the low-x side
        side = -1.0 if (room == d.rooms[0]) == low else 1.0
        return (x + side * dist, y, math.pi if side > 0 else 0.0)

    def door_point(self, door: str) -> np.ndarray:
        """The point a look at door ``door`` aims at: its pose in the map, at ``DOOR_LOOK_HEIGHT``."""
        x, y, _ = self.scene.site.door(door).pose
        return np.array([x, y, DOOR_LOOK_HEIGHT])

    def leaf_view_point(self, door: str) -> np.ndarray:
        """Where to look to see ``door`` itself: the middle of its leaf as it stands (as last
        seen; closed, that is the doorway's middle). Open, a room door's leaf stands out into the
        room it swung into from one side of the doorway: from a pose in front of the doorway on
        that side it lies off to the side, outside a frame aimed at the doorway's middle (the
        camera's half angle across is ~27 degrees), which shows the room beyond, not the door."""
        p = self.door_point(door)
        leaf = self.scene.leaves.get(door)
        if leaf is None:
            return p
        c = leaf.box(self.scene.joint.get(door, 0.0)).center
        return np.array([c[0], c[1], DOOR_LOOK_HEIGHT])

    def doorway_points(self, door: str) -> np.ndarray:
        """Points spread over ``door``'s opening: the view through it is judged at each, so that a
        held item in front of the camera hides only some of them."""
        d = self.scene.site.door(door)
        x, y, _ = d.pose
        return np.array([[x, y + s * d.width, z] for s in DOORWAY_SPREAD for z in DOORWAY_HEIGHTS])

    def work_poses(self, point, toward, how: str, clear_of: str | None = None, plain: bool = True) -> Iterator[Pose]:
        """Base poses for working at ``point``, best first: ``toward`` is the horizontal direction
        from the point to where the robot stands; a reach away from it (and clear of the front of
        ``clear_of``), stepped sideways (facing the point) and then back, keeping the base clear of
        walls, furniture and leaves as last seen. The plain pose comes last (if ``plain``)."""
        f, r = self._work_axis(point, toward, how, clear_of)
        side = np.array([-f[1], f[0], 0.0])
        obstacles, low = self.scene.obstacles(), self.scene.low_obstacles()
        leaves, arm = self.scene.door_leaf_polygons() + self.over_arm(), self.arm_outline()
        for back in WORK_BACKOFFS:
            p = np.asarray(point) + f * (r + back)
            for shift in WORK_SHIFTS:
                q = p + side * shift
                pose = (float(q[0]), float(q[1]), math.atan2(point[1] - q[1], point[0] - q[0]))
                # the arm reaches over a table's top, not over a room door's leaf (tall, and it
                # swings) nor into furniture as tall as the folded hand (a fridge's corner)
                if base_free(pose, obstacles, WORK_MARGIN, low=low) and self.arm_off(pose, leaves, arm):
                    yield pose
        if plain:
            yield self._plain_pose(point, toward, how, clear_of)

    def _work_axis(self, point, toward, how: str, clear_of: str | None) -> tuple[np.ndarray, float]:
        """The unit way from ``point`` to the robot and the reach along it (clear of the front of
        ``clear_of``)."""
        f = np.array([toward[0], toward[1], 0.0])
        f /= np.linalg.norm(f)
        r = WORK_DISTANCE[how]
        piece = self.scene.furniture.get(clear_of or "")
        if piece is not None:
            front = piece.to_world((0.0, piece.depth / 2, 0.0))
            r = max(r, float((front - np.asarray(point))[:2] @ piece.front[:2]) + BASE_CLEARANCE)
        return f, r

    def _plain_pose(self, point, toward, how: str, clear_of: str | None) -> Pose:
        """A reach away along ``toward``, facing the point, clear or not."""
        f, r = self._work_axis(point, toward, how, clear_of)
        p = np.asarray(point) + f * r
        return (float(p[0]), float(p[1]), math.atan2(-f[1], -f[0]))

    def work_pose(self, point, toward, how: str, clear_of: str | None = None, reach=None,
                  straight: bool = False, drivable: bool = False) -> Pose:
        """The first of :meth:`work_poses` from which the arm reaches every tcp pose (map 4x4)
        ``reach(base_pose)`` lists — IK clear of the scene, and the arm's joint way from how it is
        now to the first of them (a pre-pose) clear too, checked from that base before it moves
        (``straight``: and the straight line from each to the next, the last stretch the hand is
        moved unchecked; ``drivable``: and the base has a way there, :meth:`drivable`); the first
        clear one when none does (the motion then finds out). A point
        on no piece of furniture (the floor) is also tried from the other sides round it
        (:data:`AROUND`)."""
        if reach is None:
            return next(self.work_poses(point, toward, how, clear_of))
        return (self.reaching_pose(point, toward, how, clear_of, reach, routed=True, straight=straight,
                                   drivable=drivable)
                or next(self.work_poses(point, toward, how, clear_of)))

    def reaching_pose(self, point, toward, how: str, clear_of: str | None, reach, avoid=(),
                      routed: bool = False, straight: bool = False, drivable: bool = False) -> Pose | None:
        """The work pose of :meth:`work_pose` from which the arm reaches ``reach(base_pose)``, not
        within ``AVOID_RADIUS`` of the poses in ``avoid`` (stood at already); None when there is
        none. ``routed``: the arm's joint way from how it is now to the first pose (a pre-pose:
        the rest are reached by straight lines) must be clear too; ``straight``: those lines;
        ``drivable``: the base must have a way there (:meth:`drivable`)."""
        return next((p for p in self._candidates(point, toward, how, clear_of, True)
                     if not any(math.dist(p[:2], q[:2]) < AVOID_RADIUS for q in avoid)
                     and self.reaches(p, reach(p), routed, straight)
                     and (not drivable or self.drivable(p))), None)

    def drivable(self, pose: Pose) -> bool:
        """Whether :meth:`approach` has a way to ``pose`` (plans, does not move): within the room
        the base stands in, round the obstacles or straight on where that is clear; a pose in
        another room is gone to along the corridor, and taken as reachable here. A work pose
        free itself may have no way to it past what lies on the floor beside it (a bottle
        dropped at the counter's foot: retrieve_bottles seed 5)."""
        x, y, _ = self.body.base_pose()
        here, there = self.scene.room_at(x, y), self.scene.room_at(*pose[:2])
        if here is not None and there is not None and here != there:
            return True
        return self.base_path(pose, True) is not None or self.straight_free(pose)

    def reaches(self, pose: Pose, targets, routed: bool = False, straight: bool = False) -> bool:
        """Whether the arm reaches every one of ``targets`` from the base at ``pose`` (``routed``:
        the first by a clear way from how the arm is now, on any branch of the arm; a hand lowered
        from above, :meth:`~skills.body.Body.from_above`, is the motion's last resort, not counted;
        ``straight``: each after the first along a straight line from the one before, the arm
        clear of the scene all along: a place's last stretch down onto a counter swept the upper
        arm into the counter's edge from a stand whose end poses were clear). A target None is
        one the skill has no pose for from this base: not reached."""
        seed = self.body.q()
        seed[:3] = pose
        prev = None
        for k, T in enumerate(targets):
            if T is None:
                return False
            q = self.body.reachable(T, seed=seed) if routed and k == 0 else self.body.solve(T, seed=seed)
            if q is None:
                return False
            if straight and prev is not None:
                steps = LINE_CHECK_STEPS
                if len(self.body.line_way(targets[k - 1], T, prev, steps=steps, collide=True)) < steps:
                    return False
            if straight:  # the line starts where the arm solved the pose before it
                prev = seed = q
        return True

    def _candidates(self, point, toward, how: str, clear_of: str | None, around: bool) -> Iterator[Pose]:
        """The clear :meth:`work_poses` along ``toward`` and (for a point on no furniture, when
        ``around``) along the turned ways of :data:`AROUND`; the plain pose along ``toward`` last."""
        turns = AROUND if around and clear_of not in self.scene.furniture else AROUND[:1]
        for turn in turns:
            c, s = math.cos(turn), math.sin(turn)
            yield from self.work_poses(point, (c * toward[0] - s * toward[1], s * toward[0] + c * toward[1], 0.0),
                                       how, clear_of, plain=False)
        yield self._plain_pose(point, toward, how, clear_of)

    def toward_robot(self, point, support: str | None, base: Pose | None = None) -> np.ndarray:
        """Horizontal direction from a point to the side the robot works it from (standing at
        ``base``, default where it is)."""
        piece = self.scene.furniture.get(support or "")
        if piece is not None:
            return piece.front
        d = np.array([*(base or self.body.base_pose())[:2], 0.0]) - np.asarray(point, float)
        d[2] = 0.0
        return d / max(np.linalg.norm(d), 1e-6)

    def base_fits(self, x: float, y: float, room: str | None = None) -> bool:
        """The base could stand at (x, y), any heading: inside a room (``room`` if given), clear
        of walls and furniture."""
        here = self.scene.room_at(x, y)
        if here is None or (room is not None and here != room):
            return False
        obstacles, low = self.scene.obstacles(), self.scene.low_obstacles()
        return any(base_free((x, y, yaw), obstacles, PARKED_MARGIN, low=low) for yaw in (0.0, math.pi / 2))

    # -- getting there -----------------------------------------------------------------------

    def approach(self, pose: Pose, speed: float = APPROACH_SPEED, careful: bool = False) -> None:
        """Drive to a pose (arm folded or carrying): within a room round the obstacles, to
        another room along the corridor and through the doorways (:meth:`drive_to`). A
        ``careful`` trip (one that only serves a look) raises :class:`Blocked` where no clear way
        is found, instead of driving straight on."""
        x, y, _ = self.body.base_pose()
        here, there = self.scene.room_at(x, y), self.scene.room_at(*pose[:2])
        if here is not None and there is not None and here != there:
            self.drive_to(pose, careful)
            return
        self.body.drive(self._path(pose, True, careful), speed)

    def _path(self, pose: Pose, reach_over: bool, careful: bool) -> list[Pose]:
        """:meth:`base_path` to ``pose``; where it finds no clear way, straight there — unless the
        trip is ``careful`` or the straight way runs the base itself into a known obstacle (a
        wall, furniture, a leaf, an item on the floor): then :class:`Blocked`, so the skill fails
        and the executive replans, instead of the base pushing against the wall (a standoff by a
        doorway: the drive stopped against the wall and the find failed the same way thrice)."""
        path = self.base_path(pose, reach_over, careful)
        if path is not None:
            return path
        if careful:
            raise Blocked("no clear way there")
        if not self.straight_free(pose):
            raise Blocked(f"no clear way to ({pose[0]:.2f}, {pose[1]:.2f}): the base would run into an obstacle")
        return [tuple(map(float, pose))]

    def straight_free(self, pose: Pose) -> bool:
        """A straight base move from where the base stands to ``pose`` keeps the base's footprint
        (the base alone, no margin) off the walls, furniture, leaves and floor items, once it has
        left its start (:meth:`_leg_clear`'s ``LEAVE_SLACK``). An obstacle the base already
        overlaps where it stands is left out, as :meth:`SceneModel.low_obstacles` leaves out a
        floor item under it: the way off it must stay open (gather_kindling seed 1: a leaf fitted
        half open across where the base stood after passing the doorway refused every way on)."""
        here = np.array(self.body.base_pose(), float)
        goal = np.array(pose, float)
        goal[2] = angle_to(here[2], goal[2])
        start = footprint(tuple(here))
        obstacles = [o for o in self.scene.obstacles() if apart(start, o, 0.0)]
        low = self.scene.low_obstacles(tuple(here))
        n = max(2, int(np.linalg.norm((goal - here)[:2]) / 0.05) + 1)
        return all(base_free(q, obstacles, 0.0, low=low) for q in _past_start(here, goal, n))

    def _stop_clear(self, pose: Pose) -> bool:
        """The base could stand at ``pose`` (a corridor stop of a trip) clear of everything known."""
        return base_free(pose, self.scene.obstacles(), PARKED_MARGIN, low=self.scene.low_obstacles())

    def drive_to(self, pose: Pose, careful: bool = False) -> None:
        """Along the corridor to ``pose``, through the doorways on the way; raises
        :class:`Blocked` in front of a door that is not open."""
        x, y, _ = self.body.base_pose()
        cy = self.scene.corridor_y()
        # on the way the arm points where the base goes: turned towards a wall or a leaf swung
        # open beside the corridor, the folded arm would reach into it
        along = 0.0 if pose[0] > x else math.pi
        # a corridor stop the base cannot stand at (an item dropped in the corridor lies there) is
        # left out: the way goes on to the next stop round it
        legs: list = [(x, cy, along)] if self._stop_clear((x, cy, along)) else []
        crossing = [d for d in self.scene.site.doors if d.pose is not None
                    and min(x, pose[0]) < d.pose[0] < max(x, pose[0])]
        if self.scene.room_at(x, y) is not None:
            for d in sorted(crossing, key=lambda d: abs(d.pose[0] - x)):
                side = -1.0 if x < d.pose[0] else 1.0
                legs += [(d.pose[0] + side * DOOR_STOP, d.pose[1], 0.0 if side < 0 else math.pi), d.name,
                         (d.pose[0] - side * DOOR_STOP, d.pose[1], along)]
        legs += [(pose[0], cy, pose[2])] if self._stop_clear((pose[0], cy, pose[2])) else []
        legs.append(tuple(pose))
        for k, leg in enumerate(legs):
            if isinstance(leg, str):
                if not self.door_open(leg):
                    raise Blocked(f"door {leg} is not open: stopped in front of it")
                continue
            self.body.drive(self._path(leg, k == len(legs) - 1, careful), CORRIDOR_SPEED)

    def door_open(self, door: str) -> bool:
        """Look at ``door`` and judge from the frame whether the base can pass: the leaf's points
        fitted to its hinge say how far it stands open; a doorway that shows no leaf at all must
        show the room beyond (the depth through it goes on past the doorway)."""
        leaf = self.scene.leaves.get(door)
        if leaf is None:
            return True
        point = self.door_point(door)
        if not (self.eyes.look_at(point) or self.eyes.look_at(point, lift=DOOR_LOOK_LIFT)):
            # no look at it from here (the arm would strike something): what was last seen of it
            q = self.scene.joint.get(door)
            return q is not None and abs(q) >= DOOR_PASSABLE * abs(leaf.art.opened)
        frame = self.eyes.frame()
        q = self.scene.fit_leaf(door, frame)
        if q is not None:
            travel = abs(leaf.art.opened)
            return abs(q) >= DOOR_PASSABLE * travel
        through = bool(self.scene.sees_through(frame, self.doorway_points(door)))
        if through and door not in self.scene.joint:
            # no leaf where the map would have it, and the view goes through: wide open (which
            # way it swung is not known; either way it stands against a wall, out of the way)
            self.scene.joint[door] = leaf.art.opened
        return through

    def base_path(self, pose: Pose, reach_over: bool = True, careful: bool = False) -> list[Pose] | None:
        """Poses to drive through to ``pose`` without the base or the arm above it running into a
        wall, furniture or an open leaf: straight if that is clear, else through a via pose
        (backed off from the goal along its heading, or round a corner, or off to one side of
        the straight way); None if none is.
        With ``reach_over`` the arm may reach over what stands in front of the goal (a work pose);
        a stop on the way (a corridor or door pose of a trip) gets no such slack. A goal that puts
        the arm at a room door's leaf is taken to be there on purpose (a handle's grasp) and the
        leaves are left to the arm's own planning — unless the trip is ``careful`` (it only serves
        a look), which goes to no leaf on purpose."""
        here = np.array(self.body.base_pose(), float)
        goal = np.array(pose, float)
        goal[2] = angle_to(here[2], goal[2])
        obstacles, low = self.scene.obstacles(), self.scene.low_obstacles(tuple(here))
        arm, leaves = self.arm_outline(), self.scene.door_leaf_polygons()
        if careful:
            # a view is at no leaf on purpose, a piece's door included: the views of boil_water
            # seed 28 (a look at the floor by the wall behind the open cabinet, a look "closer"
            # and one "above" at the cup inside) held the arm out over the cabinet's open door and
            # pushed it shut, 0.92 -> 0.01 of its travel, and the take-outs that followed saw no cup
            leaves = self.scene.tall_leaf_polygons(self.folded_underside())
        elif not self.arm_off(goal, leaves, arm):
            # a goal at a leaf on purpose (its handle's grasp): the arm's own planning. A view is
            # never at one on purpose: a look "closer" at door_kg, open, drove the arm, held out
            # as the last look left it with bottle2 in the hand, over the leaf and pushed it to its
            # stop, and a later drive dragged the bottle along it until a finger pad sank into it
            # (retrieve_bottles seed 2): such a view is refused (no way there) instead
            leaves = []
        heading = np.array([math.cos(goal[2]), math.sin(goal[2]), 0.0])
        vias = [goal - heading * k for k in DETOUR_BACKOFFS] + [np.array([goal[0], here[1], goal[2]]),
                                                               np.array([here[0], goal[1], here[2]])]
        turned = np.array([here[0], here[1], goal[2]])  # turning on the spot first swings the arm away
        # out of a work pose (the arm over a table, the base close by): straight back first
        facing = np.array([math.cos(here[2]), math.sin(here[2]), 0.0])
        backs = [here - facing * k for k in DETOUR_BACKOFFS]
        way = (goal - here)[:2]
        across = np.array([-way[1], way[0], 0.0]) / max(float(np.linalg.norm(way)), 1e-9)
        aside = [here + (goal - here) * t + across * side * d
                 for d in DETOUR_ASIDE for t in DETOUR_ALONG for side in (1.0, -1.0)]
        paths = [[goal], *([v, goal] for v in vias), [turned, goal], *([turned, v, goal] for v in vias),
                 *([turned, turned - heading * k, v, goal] for k in DETOUR_BACKOFFS for v in vias[:len(DETOUR_BACKOFFS)]),
                 *([b, goal] for b in backs), *([b, v, goal] for b in backs for v in vias),
                 *([a, goal] for a in aside), *([turned, a, goal] for a in aside)]
        # the arm may reach over things only near the goal; failing that anywhere, near each stop
        # (it can swing into an open leaf there, but that is still better than the straight way)
        for slack_at_stops in (False, True):
            for path in paths:
                legs = [here, *path]
                if all(self._leg_clear(a, b, b if slack_at_stops else (goal if reach_over else None), obstacles, arm, low,
                                       leaves)
                       for a, b in zip(legs, legs[1:])):
                    return [tuple(map(float, p)) for p in path]
        return None

    def arm_outline(self) -> np.ndarray:
        """The arm as it stands now, seen from above in the base frame: the folded arm's outline
        grown to take in the hand and its wrist (a drive holds the arm as it is — a look may have
        left the hand out to one side)."""
        T = np.linalg.inv(self.body.base_T()) @ self.body.pose("tcp")
        hand = [T[:3, 3], T[:3, 3] - WRIST_BEHIND * T[:3, 2]]
        r = HAND_RADIUS
        pts = [np.array(FOLDED_ARM)] + [p[:2] + np.array([[r, r], [r, -r], [-r, r], [-r, -r]]) for p in hand]
        return hull(np.vstack(pts))

    def over_arm(self) -> list[np.ndarray]:
        """The outlines (from above) of the furniture that reaches up to the folded hand: the arm
        does not pass over it (a work pose at a fridge's foot turned the base in with the folded
        hand inside the fridge's corner: 539 N against its front)."""
        underside = self.folded_underside()
        return [f.outer().polygon() for f in self.scene.furniture.values() if f.height > underside]

    def folded_underside(self) -> float:
        """The height (m) of the folded hand: what stands higher, the folded arm does not pass over."""
        q = self.body.q()
        q[3:] = self.body.cfg.arm.home
        return float(self.body.pose("tcp", q)[2, 3])

    @staticmethod
    def arm_off(pose, leaves, arm=FOLDED_ARM) -> bool:
        """The arm (``arm``'s outline in the base frame) at base ``pose`` keeps LEAF_MARGIN off
        every one of ``leaves`` (room doors' leaves from above)."""
        shape = placed(arm, pose)
        return all(apart(shape, o, LEAF_MARGIN) for o in near(shape, leaves, LEAF_MARGIN))

    @staticmethod
    def _leg_clear(a: np.ndarray, b: np.ndarray, slack_at: np.ndarray | None, obstacles, arm=FOLDED_ARM,
                   low=(), leaves=()) -> bool:
        """A straight base move from ``a`` to ``b`` keeps the footprint off every obstacle once it
        has left ``a``, and the arm too except near ``slack_at`` (the path's goal, where it works
        over the furniture; None: nowhere — a via pose gets no slack, the arm would sweep into an
        open leaf there). The arm keeps off ``leaves`` (room doors' leaves as they stand) even
        there: it reaches over a table's top, but such a leaf is tall and swings when struck (an
        arm swung into a room door's open leaf beside a floor item pushed it half shut, and the
        door, neither open nor closed, could be neither passed nor opened)."""
        for q in _past_start(a, b, max(2, int(_way(a, b) / 0.08) + 1)):
            if not base_free(q, obstacles, PARKED_MARGIN, folded=slack_at is None or np.linalg.norm((slack_at - q)[:2]) > ARM_SLACK,
                             arm=arm, low=low):
                return False
            if leaves and not Navigator.arm_off(q, leaves, arm):
                return False
        return True


def _way(u: np.ndarray, v: np.ndarray) -> float:
    """Length of a base move, a turn on the spot counting too (the arm sweeps)."""
    return float(np.linalg.norm((v - u)[:2]) + 0.4 * abs(v[2] - u[2]))


def _past_start(a: np.ndarray, b: np.ndarray, n: int):
    """``n`` evenly spaced poses of the straight base move from ``a`` to ``b``, less those within
    ``LEAVE_SLACK`` of ``a`` (a drive may start close to an obstacle)."""
    for s in np.linspace(0.0, 1.0, n):
        q = a + (b - a) * s
        if _way(a, q) >= LEAVE_SLACK:
            yield q
