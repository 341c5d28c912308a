"""Where a look found an item missing: sightings there are not trusted to have found it.

A detector errs by the picture: the same view gives the same false positive, a blob of a wall
or a floor labelled with an item's class, every time it is taken. A re-survey that repeats the
sweep's views therefore "finds" the phantom again where the last check could not see the item,
and the robot goes back to it, round and round (gather_kindling seed 1: a stick placed on the
living-room floor by a false positive was looked for there eight times while the real one lay in
the garden). The executive notes each spot where a check about an item's place or visibility
failed while belief had it at a measured point; a track that still puts the item within
:data:`MISS_RADIUS` of such a spot is not taken as found, so the search goes on to other rooms,
and the next sighting of its class may be taken for it. If nothing else turns up, the search ends
with the sighting it has: a model's "could not see" is not proof of absence either.

The notes are the executive's own (from its checks and its geometry), never the world's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

#: m between a measured centroid and a spot where the item was found missing, for the two to be
#: one place (the size of a small item plus the few centimetres a centroid from one side errs)
MISS_RADIUS = 0.25


@dataclass
class Misses:
    """Spots, per item, where a look did not find it where a measurement had put it."""

    spots: dict[str, list[tuple[float, float, float]]] = field(default_factory=dict)

    def note(self, name: str, point: tuple[float, float, float]) -> None:
        """A check could not find ``name`` at ``point`` (its measured centroid then)."""
        self.spots.setdefault(name, []).append(tuple(point))

    def at(self, name: str, point: tuple[float, float, float] | None) -> bool:
        """Whether ``point`` (a measured centroid of ``name``) is where it was found missing."""
        return point is not None and any(math.dist(point[:2], s[:2]) < MISS_RADIUS
                                         for s in self.spots.get(name, ()))

    def clear(self, name: str) -> None:
        """``name`` is in the hand or was put somewhere by the robot: old spots say nothing of it."""
        self.spots.pop(name, None)
