"""The camera service skills offer the executive: aim, go to a viewpoint, move the view, capture.

The executive perceives through :class:`~vap_bt.robot.camera.Camera` — capture a frame aimed at
a point where belief puts something, go to a viewpoint of a sweep, move the view left, closer,
above — and never says how. :class:`ViewService` is that interface on the robot's side, built on
the same kit as the motion skills (so an aim moves the arm exactly as a skill's look does, and
one goal or one look moves the robot at a time): viewpoints are reached along the navigator's
base paths, a shut door on the way makes a viewpoint unreachable, and a viewpoint off the floor
of the robot's room, or on furniture, is refused before anything moves. The simulator only
renders what the camera, wherever the arm and base have put it, shows.

:meth:`ViewService.stop` cancels a view motion in flight (a check the executive stopped caring
about): the drivers stop within a control cycle and the call returns False.
"""

from __future__ import annotations

import math
import threading

import numpy as np

from skills.body import Stopped
from skills.eyes import CAMERA_EYE
from skills.kit import Kit
from skills.navigator import Blocked
from vap_bt.robot.camera import VIEW_DIRECTIONS, Aim, Viewpoint
from vap_bt.robot.frame import Frame

#: a viewpoint counts as reached when the base stops this close to it (m)
VIEW_REACHED = 0.25
#: a "front" view steps back to this distance from the point, squarely facing it: far enough to
#: see all of a tall piece of furniture (a 1.05 m shelf needs about 1.8 m); a point in a deep
#: top-open hollow (a log in a basket) only as far as the eye still sees it over the rim
FRONT_VIEW = 1.8
SIDE_TURN = 0.5  # rad round the point for a view from the left or the right
#: a view "closer" halves the distance to the point, stepping at least ``CLOSER_STEP`` and no
#: nearer than ``CLOSEST``: a thing small in the picture from 2.5 m is about as small after a fixed
#: quarter-metre step (pick_plate seed 1: the plate took two "closer" moves to show enough)
CLOSER_STEP, CLOSEST = 0.25, 0.75
ABOVE = 0.3  # m higher than the eye is for a view from above
#: a move shorter than this (m, or rad of turn) is no move: the camera would show the same view
SAME_VIEW = 0.1


class ViewService:
    """The :class:`~vap_bt.robot.camera.Camera` interface over one robot's kit."""

    def __init__(self, kit: Kit) -> None:
        self.kit = kit
        self._stop = threading.Event()

    def stop(self) -> None:
        """Cancel the view motion in flight, if any."""
        self._stop.set()

    # the body: proprioception and the map, as the robot reports them
    def state(self):
        return self.kit.robot.state()

    def site_map(self):
        return self.kit.robot.site_map()

    def _looking(self):
        self._stop.clear()
        return self.kit.looking(self._stop.is_set)

    def _point(self, aim: Aim) -> np.ndarray | None:
        """Where to aim for ``aim``: its point; for a room door, the middle of its leaf as the
        robot last saw it stand (belief places a door at its doorway: open, the leaf stands out
        into the room beside the doorway, off a frame aimed there from that room's side)."""
        if aim.point is None:
            return None
        door = aim.names[0] if aim.names else None
        if door is not None and self.kit.scene.site.door(door) is not None and door in self.kit.scene.leaves:
            return self.kit.nav.leaf_view_point(door)
        return np.asarray(aim.point, float)

    def capture(self, aim: Aim | None = None) -> Frame:
        """Aim at ``aim``'s point (:meth:`_point`; if given and not already aimed there) and
        take a frame — as the camera gave it: the executive names its detections itself (the
        kit names them too, for what it remembers of the floor and the leaves)."""
        with self._looking() as kit:
            point = None if aim is None else self._point(aim)
            if point is not None and not kit.eyes.aimed_at(point):
                try:
                    kit.eyes.look_at(point)
                except Stopped:
                    pass  # the frame shows wherever the camera stopped
            kit.eyes.frame()
            return kit.eyes.raw

    def goto_view(self, view: Viewpoint) -> bool:
        """Drive to the viewpoint's base pose (through doors, stopping at a shut one) and aim."""
        with self._looking() as kit:
            try:
                if view.base_pose is not None:
                    x, y = view.base_pose[:2]
                    if not kit.nav.base_fits(x, y):
                        return False
                    kit.nav.approach(tuple(view.base_pose), careful=True)
                    bx, by, _ = kit.body.base_pose()
                    if math.hypot(bx - x, by - y) > VIEW_REACHED:
                        return False
                if view.aim.point is None:
                    return True
                return kit.eyes.look_at(self._point(view.aim))
            except (Stopped, Blocked):
                return False

    def move_view(self, aim: Aim, direction: str) -> bool:
        """Move the viewpoint ``direction`` relative to the point belief puts the target at: a
        base move within the robot's room, then an aim at the point."""
        if direction not in VIEW_DIRECTIONS or aim.point is None:
            return False
        with self._looking() as kit:
            p = self._point(aim)
            x, y, yaw = kit.body.base_pose()
            eye = kit.body.pose("camera_optical")
            # square on, but not so far off that the rim of a deep hollow hides the point
            reach = kit.scene.sight_over_rim(p, CAMERA_EYE[2], (x - p[0], y - p[1], 0.0)) + CAMERA_EYE[0]
            target = _moved_to(direction, (x, y, yaw), p, min(FRONT_VIEW, reach))
            if target is None:
                return False
            nx, ny, nyaw, lift = target
            moves = math.hypot(nx - x, ny - y) > SAME_VIEW or abs(_wrap(nyaw - yaw)) > SAME_VIEW
            if not moves and lift == 0.0:
                return False  # already there: the same view again would show nothing new
            # a view from elsewhere must be in this room: a base move for a view never goes
            # through a wall or a doorway
            if moves and not kit.nav.base_fits(nx, ny, kit.scene.room_at(x, y)):
                return False
            try:
                if moves:
                    kit.nav.approach((nx, ny, nyaw), careful=True)
                # from above: higher than the eye is now, as high as the arm reaches (close in,
                # the highest eye may need the wrist bent further than it goes)
                now = max(0.0, float(eye[2, 3]) - CAMERA_EYE[2])
                lifts = (now + lift, now + 2 * lift / 3, now + lift / 3) if lift > 0 else (0.0,)
                if not any(kit.eyes.look_at(p, lift=h) for h in lifts):
                    return False
            except (Stopped, Blocked):
                return False
            # a move that leaves the camera where it was (the arm could not go higher, the base
            # stopped short) is no move: the same picture again would show nothing new
            return _other_view(eye, kit.body.pose("camera_optical"))


def _other_view(before: np.ndarray, after: np.ndarray) -> bool:
    """Whether two camera poses see differently: the eye moved ``SAME_VIEW`` m, or turned
    ``SAME_VIEW`` rad."""
    turned = math.acos(float(np.clip(before[:3, 2] @ after[:3, 2], -1.0, 1.0)))
    return bool(np.linalg.norm(after[:3, 3] - before[:3, 3]) > SAME_VIEW or turned > SAME_VIEW)


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _moved_to(direction: str, here, p: np.ndarray, front: float = FRONT_VIEW):
    """Base pose (x, y, yaw) and eye lift for a view ``direction`` of point ``p`` from ``here``
    (``front``: the distance a view from the front steps back to); None when there is no such
    move (already as close as a view gets)."""
    x, y, yaw = here
    lift = 0.0
    if direction in ("left", "right"):
        ang = SIDE_TURN if direction == "left" else -SIDE_TURN
        dx, dy = x - p[0], y - p[1]
        c, s = math.cos(ang), math.sin(ang)
        nx, ny = p[0] + c * dx - s * dy, p[1] + s * dx + c * dy
    elif direction == "closer":
        v = np.array([p[0] - x, p[1] - y])
        d = float(np.linalg.norm(v))
        step = min(max(CLOSER_STEP, d / 2), max(0.0, d - CLOSEST))
        if step <= 0.02:
            return None
        nx, ny = np.array([x, y]) + v / d * step
    elif direction == "front":  # square on to the point, from a good viewing distance
        v = np.array([x - p[0], y - p[1]])
        v = v / (np.linalg.norm(v) or 1.0)
        nx, ny = p[0] + v[0] * front, p[1] + v[1] * front
    elif direction == "behind":
        nx, ny = 2 * p[0] - x, 2 * p[1] - y
    else:  # above
        nx, ny, lift = x, y, ABOVE
    nyaw = math.atan2(p[1] - ny, p[0] - nx) if direction != "above" else yaw
    return float(nx), float(ny), float(nyaw), lift
