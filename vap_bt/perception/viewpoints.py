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

:class:`ViewpointSearch` is one check's use of a strategy: at most K moves (its budget), the
directions tried and refused so far, and the question to ask where the strategy asks the model.
"""

from __future__ import annotations

from dataclasses import dataclass

from vap_bt.domain.atoms import Atom
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import Round, target_of, viewpoint_query
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


class ViewpointSearch:
    """Where one check looks next, within its budget of ``budget`` moves: the strategy's direction
    (or the query for it), replaced by the predefined round where it was refused or not given."""

    def __init__(self, strategy: ViewpointStrategy, budget: int) -> None:
        self.strategy, self.budget = strategy, budget
        self.moves = 0  # moves made (a refused direction is no move)
        self.tried: set[str] = set()  # directions moved to or refused
        self.refused: set[str] = set()  # directions the robot could not move to

    @property
    def spent(self) -> bool:
        """Whether the check has made all K moves of its budget."""
        return self.moves >= self.budget

    def next(self, atom: Atom, last: Round, profile: PerceptionProfile | None) -> str | Query:
        """The direction of the next move, or the query about the last round's frame that asks for
        it (the round's first question names what is looked for)."""
        question = last.questions[0] if last.questions else profile.questions(atom, 1)[0]
        return self.strategy.next(self.moves, atom, question, target_of(atom))

    def pick(self, direction: str | None) -> str | None:
        """The direction to move to: ``direction`` (the strategy's or the model's), unless it is none
        or was refused already, then the first of the round not yet tried; None once every one was."""
        if direction is None or direction in self.refused:
            direction = self.strategy.instead(self.tried)
        if direction is not None:
            self.tried.add(direction)
        return direction

    def refuse(self, direction: str) -> None:
        """The robot could not move to ``direction``."""
        self.refused.add(direction)

    def moved(self) -> None:
        """Count one move the robot made (a refused direction is not one: :meth:`refuse`)."""
        self.moves += 1


assert set(GREEDY_ORDER) == set(VIEW_DIRECTIONS)
