"""What a motion skill reads from its goal and gives back, apart from how it moves.

:class:`Where` is the executive's word on an item's place (the goal's hints); how the motion ended
is a :class:`vap_bt.outcome.Outcome`. They live apart from the motion modules (:mod:`skills.hands` and what it
imports: kinematics, collision, the camera's geometry) so that the skill classes, which every
run loads to learn which action each performs, import none of that until a skill moves a robot:
a symbolic run, whose world performs the actions itself, never does.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Where:
    """What the executive believes about an item's place: its support or container, and how far
    from the point it gave the item may be (``radius``, m; None: it did not say)."""

    on: str | None = None
    inside: str | None = None
    radius: float | None = None

    @property
    def place(self) -> str | None:
        """The container the item is believed in, else the support it is believed on (None: belief places
        it nowhere)."""
        return self.inside or self.on
