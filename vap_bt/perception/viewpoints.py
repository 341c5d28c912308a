"""Where to look from next when a check has not settled: the VLM's suggestion, or a fixed round.

Two strategies, the paper's H2 comparison:

* ``vlm`` (VAP-TAMP) — ask the viewpoint-selection prompt about the last frame and move the way
  the model says (left, right, front, behind, above, closer);
* ``greedy`` (the paper's baseline) — visit predefined viewpoints around the target in a fixed
  order, whatever the frame showed: to its left, to its right, behind it, above it, closer, in
  front of it.

A strategy gives, for the k-th move of a check, either a direction at once or the query whose
answer is the direction (the caller sends it and polls, :mod:`vap_bt.bt.inflight`). A direction
the robot cannot move to (a wall, a doorway, already as close as a view gets), or no answer at
all, is replaced by the first of the predefined round not yet tried in this check
(:meth:`ViewpointStrategy.instead`): looking again from the same spot would show the same picture.
"""

from __future__ import annotations

from dataclasses import dataclass

from vap_bt.domain.atoms import Atom
from vap_bt.perception.verification import viewpoint_query
from vap_bt.perception.vlm import Query
from vap_bt.robot.camera import VIEW_DIRECTIONS

#: the greedy round of predefined viewpoints around the target
GREEDY_ORDER: tuple[str, ...] = ("left", "right", "behind", "above", "closer", "front")


@dataclass(frozen=True)
class ViewpointStrategy:
    """``vlm`` or ``greedy`` (see the module docstring)."""

    name: str = "vlm"

    def __post_init__(self) -> None:
        if self.name not in ("vlm", "greedy"):
            raise ValueError(f"unknown viewpoint strategy {self.name!r} (vlm, greedy)")

    def next(self, move: int, atom: Atom, question: str, target: str) -> str | Query:
        """The direction of the ``move``-th move (0-based), or the query that asks for it."""
        if self.name == "greedy":
            return GREEDY_ORDER[move % len(GREEDY_ORDER)]
        return viewpoint_query(atom, question, target)

    @staticmethod
    def instead(tried: set[str]) -> str | None:
        """The direction to try where the chosen one could not be reached (or none was given):
        the first of the predefined round not in ``tried``; None once every one was."""
        return next((d for d in GREEDY_ORDER if d not in tried), None)


assert set(GREEDY_ORDER) == set(VIEW_DIRECTIONS)
