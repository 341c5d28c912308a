"""Where to look from next when a check has not settled: the VLM's suggestion, or a fixed round.

Three strategies, the paper's H2 comparison:

* ``vlm`` (VAP-TAMP) — ask the viewpoint-selection prompt about the last frame and move the way
  the model says (left, right, front, behind, above, closer);
* ``greedy`` (a *stopping* greedy) — go round the predefined viewpoints in greedy-all's order
  (:data:`AROUND_ORDER`), whatever the frame showed, and stop at the first view that decides,
  within the budget K;
* ``greedy-all`` (the paper's baseline: "exhaustively visits predefined viewpoints arranged
  around the target object") — once the first view has not decided, visit *every* predefined
  viewpoint around the target, whatever any of them showed, and only then weigh all the views
  together (:func:`~vap_bt.perception.judgement.judge` over every round, as any check pools its
  rounds). Its predefined set is the round of directions the camera service can reach around the
  target from where the check began (:data:`AROUND_ORDER`): a direction it refuses — a wall or
  furniture where the robot would stand, a doorway, as close as a view gets, an arm that reaches
  no higher — is no viewpoint of the set. How many there are (two to six) thus comes out of the
  target's surroundings, not out of a table; its budget is the set, not K. A world without
  geometry (the symbolic one) refuses nothing: its set is all six.

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

#: the round of predefined viewpoints around the target, which both greedy kinds go round and the
#: model's suggestions fall back on: the six directions, ordered so that each move — the camera
#: service moves relative to where the camera stands — reaches a picture not yet taken (after
#: "left", "right" would return to the first view's stand): round to the left, up, in closer,
#: across to the far side, back to a full view, and round again
AROUND_ORDER: tuple[str, ...] = ("left", "above", "closer", "behind", "front", "right")
#: the strategies' names, as ``--viewpoints`` takes them
STRATEGIES: tuple[str, ...] = ("vlm", "greedy", "greedy-all")


@dataclass(frozen=True)
class ViewpointStrategy:
    """``vlm``, ``greedy`` or ``greedy-all`` (see the module docstring)."""

    name: str = "vlm"

    def __post_init__(self) -> None:
        if self.name not in STRATEGIES:
            raise ValueError(f"unknown viewpoint strategy {self.name!r} ({', '.join(STRATEGIES)})")

    @property
    def exhaustive(self) -> bool:
        """Whether the strategy visits every predefined viewpoint before the views are weighed
        (``greedy-all``)."""
        return self.name == "greedy-all"

    def budget(self, k: int) -> int:
        """The moves a check may make: K, or every viewpoint of the round for ``greedy-all``."""
        return len(AROUND_ORDER) if self.exhaustive else k

    def next(self, move: int, atom: Atom, question: str, target: str,
             tried: frozenset[str] = frozenset()) -> str | Query | None:
        """The direction of the ``move``-th move (0-based), or the query that asks for it; for
        either greedy the first of the round not in ``tried`` (None once every one was)."""
        if self.name != "vlm":
            return self.instead(tried)
        return viewpoint_query(atom, question, target)

    def instead(self, tried: set[str] | frozenset[str]) -> str | None:
        """The direction to try where the chosen one could not be reached (or none was given):
        the first of the predefined round not in ``tried``; None once every one was."""
        return next((d for d in AROUND_ORDER if d not in tried), None)


class ViewpointSearch:
    """Where one check looks next, within its budget of ``budget`` moves (K; ``greedy-all``'s is
    its whole round): the strategy's direction (or the query for it), replaced by the predefined
    round where it was refused or not given."""

    def __init__(self, strategy: ViewpointStrategy, budget: int) -> None:
        self.strategy, self.budget = strategy, strategy.budget(budget)
        self.moves = 0  # moves made (a refused direction is no move)
        self.tried: set[str] = set()  # directions moved to or refused
        self.refused: set[str] = set()  # directions the robot could not move to

    @property
    def spent(self) -> bool:
        """Whether the check has made all K moves of its budget."""
        return self.moves >= self.budget

    @property
    def pools(self) -> bool:
        """Whether the views are weighed only once the whole round was visited (``greedy-all``)."""
        return self.strategy.exhaustive

    def next(self, atom: Atom, last: Round, profile: PerceptionProfile | None) -> str | Query | None:
        """The direction of the next move, or the query about the last round's frame that asks for
        it (the round's first question names what is looked for); None: no direction of the round
        is left to try."""
        question = last.questions[0] if last.questions else profile.questions(atom, 1)[0]
        return self.strategy.next(self.moves, atom, question, target_of(atom), frozenset(self.tried))

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


assert sorted(AROUND_ORDER) == sorted(VIEW_DIRECTIONS)
