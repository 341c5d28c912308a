"""Where a thing the hand lost on the way lies: near the way it was carried.

An item that slips from the hand while the base drives (Table II's "held object drops during
navigation") lies between where the gripper last held it and where the base stood when the hand
was found empty — out to the side by the hand's reach from the base, and a little further where
it rolled. A search for it used to place it nowhere, so that it is taken wherever a detection of
its class is first seen; but a detection is first offered to the items belief does place, and
an item only the task file places "somewhere on the garden floor" took it (gather_kindling seed
3: the stick the hand lost 0.5 m from the base, seen from four stands, was taken each time for
the other stick, told to lie in the garden and never seen; the lost one was never found and no
plan was left). Believed along its way, the lost thing is the cheaper match for a detection
there (a told belief pays for its spread over a whole room: :func:`vap_bt.scene.identity._spread`).

Where a search's sweep does not show it, the floor along the way is looked at, spot by spot
(:func:`trail_spots`): a knife that slipped as the base set off from where it was grasped lay
2.5 m behind the base, where neither the look round the base nor the kitchen's sweep showed it
(halve_egg seed 1: "no plan"). A base goes from room to room through the doorway between them,
so the way is two straight legs through that doorway (one when both ends are in one room).
"""

from __future__ import annotations

import math

from vap_bt.robot.site_map import SiteMap
from vap_bt.scene.identity import Believed

#: m round the way the base drove within which a thing lost from the hand may lie: the hand holds
#: it about 0.55 m out from the base's centre while it drives (skills.hands' carry pose), and a
#: dropped thing bounces and rolls a little
LOST_MARGIN = 1.0
#: m between two spots of the floor looked at along the way (a look round a spot covers about a
#: metre of floor)
TRAIL_STEP = 0.8

Point = tuple[float, float]


def lost_on_the_way(start: Point, end: Point, height: float = 0.0) -> Believed:
    """Where a thing lost from the hand lies, the base having driven from ``start`` (where the
    gripper last held it) to ``end`` (map frame): within :data:`LOST_MARGIN` of the straight way
    between them, as a disc round its middle (a way through a doorway is bent, but the disc
    round its ends' middle covers it too). On the floor (``height``), placed on nothing — and,
    as a told belief, anywhere else a detection of its class no other object takes (it may have
    landed on a counter beside the way, or rolled further: heat_pie seed 0 lost a pie onto the
    counter's top, 0.9 m up, where a belief gated round the floor of the way may not reach; a
    thing placed nowhere, as before, took any detection of its class no one else took)."""
    mid = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2, height)
    return Believed(mid, math.dist(start, end) / 2 + LOST_MARGIN, told=True)


def trail_spots(site_map: SiteMap, start: Point, end: Point) -> list[tuple[str, Point]]:
    """Spots on the floor every :data:`TRAIL_STEP` along the way the base drove from ``start`` to
    ``end`` (map frame), from ``start`` on and short of ``end`` (the look round where the base
    stands covers that), each with its room: two straight legs through the doorway between the
    ends' rooms when they differ, else one. A spot in no room (the doorway itself) has no floor
    to look at and is left out."""
    spots = [p for a, b in _legs(site_map, start, end) for p in _along(a, b)]
    return [(room, p) for p in spots if (room := site_map.room_at(*p)) is not None]


def _legs(site_map: SiteMap, start: Point, end: Point) -> list[tuple[Point, Point]]:
    """The straight legs of the way: through the doorway between the ends' rooms, if they differ
    and a door joins them."""
    rooms = {site_map.room_at(*start), site_map.room_at(*end)}
    door = next((d for d in site_map.doors if d.pose is not None and set(d.rooms) == rooms), None) \
        if len(rooms) == 2 and None not in rooms else None
    if door is None:
        return [(start, end)]
    via = (door.pose[0], door.pose[1])
    return [(start, via), (via, end)]


def _along(a: Point, b: Point) -> list[Point]:
    """Points every TRAIL_STEP from ``a`` towards ``b``, ``a`` included, ``b`` not."""
    n = math.ceil(math.dist(a, b) / TRAIL_STEP)
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n)]
