"""Skills of the mobile base: moving the whole robot to a room or to a thing.

Both occupy the base, so a ``find`` never overlaps a ``navigate``; the arm's skills may run
beside them on the other server.
"""

from __future__ import annotations

import math

import numpy as np

from typing import TYPE_CHECKING

from skills.base import MotionSkill
from vap_bt.outcome import Outcome
from vap_bt.skill import Hint

if TYPE_CHECKING:
    from skills.kit import Kit


class BaseSkill(MotionSkill):
    """A skill of the mobile base (the ``base`` server; occupies the base)."""

    robot = "base"
    resource = "base"


class Navigate(BaseSkill):
    """navigate(from, to, door): drive into room ``to`` through ``door`` and look at the door."""

    action = "navigate"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        _, to_room, door = args[:3]
        kit.hands.carry()
        kit.nav.drive_to(kit.nav.door_pose(door, to_room, 1.0))
        kit.eyes.look_at(kit.nav.leaf_view_point(door))
        return Outcome(True)


class Find(BaseSkill):
    """find(from, target, room): go to ``target`` so that it is in view."""

    action = "find"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        target = args[1]
        point = kit.point(hints, target)
        where = kit.where(hints, target)
        kit.hands.carry()
        kit.nav.drive_to(kit.nav.standoff(target, point, where.place))
        kit.eyes.look_at(target_point(kit, target, point))
        return Outcome(True)


def target_point(kit: Kit, name: str, believed) -> np.ndarray:
    """Where to look at ``name``: a door's leaf as it stands, a container's cavity, a surface's top, a room
    ahead of the robot, an item where belief puts it."""
    scene = kit.scene
    if scene.site.door(name) is not None:
        return kit.nav.leaf_view_point(name)
    f = scene.furniture.get(name)
    if f is not None:
        cav = f.info.cavity
        if cav is not None:
            return f.to_world((0.0, f.depth / 4, sum(cav.z) / 2))
        return f.top_point()
    if believed is None:
        x, y, yaw = kit.body.base_pose()
        return np.array([x + 1.5 * math.cos(yaw), y + 1.5 * math.sin(yaw), 0.0])
    return np.asarray(believed, float)
