"""The way a thing was carried: where what the hand lost on it may lie, and the spots of floor
along it, through the doorway between two rooms (:mod:`vap_bt.scene.trail`)."""

from __future__ import annotations

import math

from vap_bt.robot.site_map import DoorInfo, RoomInfo, SiteMap
from vap_bt.scene.trail import LOST_MARGIN, TRAIL_STEP, lost_on_the_way, trail_spots

#: gather_kindling's two rooms side by side, the doorway in their shared wall
HOUSE = SiteMap(rooms=(RoomInfo("living_room", "floor_living_room", (0.0, 0.0, 4.6, 4.4)),
                       RoomInfo("garden", "floor_garden", (4.6, 0.0, 9.2, 4.4))),
                doors=(DoorInfo("door_lg", ("living_room", "garden"), (4.6, 2.2, 0.0), 0.9),))
WOODPILE_STAND, LIVING_ROOM_STAND = (6.9, 3.35), (2.3, 2.95)


def test_the_way_from_room_to_room_goes_through_their_doorway():
    """From the woodpile's stand in the garden to a stand in the living room: spots from the
    start on, a step apart at most, through the doorway (not across the wall the straight line
    between the ends would cross), short of the end (the look round the base covers that)."""
    spots = trail_spots(HOUSE, WOODPILE_STAND, LIVING_ROOM_STAND)
    rooms = [room for room, _ in spots]
    assert rooms[0] == "garden" and rooms[-1] == "living_room" and rooms == sorted(rooms, key=rooms.index)
    assert spots[0][1] == WOODPILE_STAND and all(math.dist(p, LIVING_ROOM_STAND) > 0.1 for _, p in spots)
    assert all(math.dist(a, b) <= TRAIL_STEP + 1e-9 for (_, a), (_, b) in zip(spots, spots[1:]))
    assert min(math.dist(p, (4.6, 2.2)) for _, p in spots) < TRAIL_STEP / 2
    assert all(abs(p[0] - 4.6) > TRAIL_STEP or abs(p[1] - 2.2) < TRAIL_STEP for _, p in spots)


def test_within_one_room_the_way_is_straight():
    spots = trail_spots(HOUSE, (5.0, 1.0), (8.0, 1.0))
    assert [room for room, _ in spots] == ["garden"] * 4 and [p[1] for _, p in spots] == [1.0] * 4


def test_what_the_hand_lost_on_the_way_is_believed_within_reach_of_every_point_of_it():
    """gather_kindling seed 3: the stick the hand lost lay 0.5 m from the way the base drove."""
    b = lost_on_the_way((6.9, 3.35), (6.9, 2.6))
    assert math.dist(b.point[:2], (6.44, 2.85)) < b.radius and b.support is None and b.told
    assert b.radius == math.dist((6.9, 3.35), (6.9, 2.6)) / 2 + LOST_MARGIN
