"""The camera service: aim the wrist camera, go to a viewpoint, capture a frame.

The executive never names a pose it does not believe: an :class:`Aim` carries the point in the
map frame where belief puts what it wants to see (from the scene graph or the map), the *place*
belief puts it at — the piece of furniture, door or floor it is believed on or in, or that it is
— and, for records, the names of those things. A pybullet camera aims at the point and ignores
the rest; the symbolic camera, which has no points, turns to the place. Neither is ever told
where a thing truly is: a thing that is not where belief puts it is not in the picture. A
:class:`Viewpoint` is a base pose plus an aim: where to stand and look from during an
exploration sweep (:mod:`vap_bt.scene.builder` chooses them from the map); a camera without
base poses stands at the aim's place.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState

#: Directions the viewpoint prompt offers (paper appendix, "Viewpoint Selection Prompt").
VIEW_DIRECTIONS: tuple[str, ...] = ("left", "right", "front", "behind", "above", "closer")


@dataclass(frozen=True)
class Aim:
    """Look at ``point`` (map frame, metres), where belief puts ``names``; ``place`` is the mapped
    thing belief puts the first of them it can place at (None: belief places none of them, or
    they are in the hand)."""

    names: tuple[str, ...] = ()
    point: tuple[float, float, float] | None = None
    place: str | None = None


@dataclass(frozen=True)
class Viewpoint:
    """Stand at ``base_pose`` in ``room`` and aim at ``aim``; ``base_pose`` None: stay put."""

    room: str
    aim: Aim
    base_pose: tuple[float, float, float] | None = None
    label: str = ""  # for people: "cabinet from the front", "kitchen, looking left"


class Camera(Protocol):
    """The wrist camera with the base motions it needs to look (what a robot's drivers offer)."""

    def capture(self, aim: Aim | None = None) -> Frame:
        """Aim at ``aim`` (None: as the camera is) and take one frame."""

    def goto_view(self, view: Viewpoint) -> bool:
        """Drive and aim to ``view``; False when it cannot be reached from here."""

    def move_view(self, aim: Aim, direction: str) -> bool:
        """Move the viewpoint ``direction`` (one of VIEW_DIRECTIONS) relative to ``aim``."""


class Body(Protocol):
    """Proprioception and localization, and the site map the localizer works in."""

    def state(self) -> RobotState: ...

    def site_map(self) -> SiteMap:
        """The map the localizer works in: rooms, doors and furniture, nothing that changes."""
