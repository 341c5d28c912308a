"""What a motion skill reads from its goal and gives back, apart from how it moves.

:class:`Where` is the executive's word on an item's place (the goal's hints), :class:`Outcome` how
the motion ended. They live apart from the motion modules (:mod:`skills.hands` and what it
imports: kinematics, collision, the camera's geometry) so that the skill classes, which every
run loads to learn which action each performs, import none of that until a skill moves a robot:
a symbolic run, whose world performs the actions itself, never does.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Outcome:
    """A skill's motion ended: ``completed`` (its own view), and what happened in words."""

    completed: bool
    message: str = ""


@dataclass(frozen=True)
class Where:
    """What the executive believes about an item's place: its support or container, and how far
    from the point it gave the item may be (``radius``, m; None: it did not say)."""

    on: str | None = None
    inside: str | None = None
    radius: float | None = None

    @property
    def place(self) -> str | None:
        return self.inside or self.on
