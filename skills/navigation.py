"""Skills of the mobile base: moving the whole robot.

Both occupy the base, so a ``find`` never overlaps a ``navigate``; the arm's skills may run
beside them on the other server.
"""

from __future__ import annotations

from skills.base import WorldActionSkill


class BaseSkill(WorldActionSkill):
    robot = "base"
    resource = "base"


class Navigate(BaseSkill):
    """navigate: drive between rooms."""

    action = "navigate"


class Find(BaseSkill):
    """find: go to an object so that it is in view."""

    action = "find"
