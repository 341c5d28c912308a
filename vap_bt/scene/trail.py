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
"""

from __future__ import annotations

import math

from vap_bt.scene.identity import Believed

#: m round the way the base drove within which a thing lost from the hand may lie: the hand holds
#: it about 0.55 m out from the base's centre while it drives (skills.hands' carry pose), and a
#: dropped thing bounces and rolls a little
LOST_MARGIN = 1.0

Point = tuple[float, float]


def lost_on_the_way(start: Point, end: Point, height: float = 0.0) -> Believed:
    """Where a thing lost from the hand lies, the base having driven from ``start`` (where the
    gripper last held it) to ``end`` (map frame): within :data:`LOST_MARGIN` of the straight way
    between them, as a disc round its middle (a way through a doorway is bent, but the disc
    round its ends' middle covers it too). On the floor (``height``), placed on nothing."""
    mid = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2, height)
    return Believed(mid, math.dist(start, end) / 2 + LOST_MARGIN)
