"""The episode's board: what behaviours leave for each other and for the executive, key by key.

A behaviour writes what happened — the situation that fails the tree, each verification, the
actions run, the goal's evidence — and reads what earlier checks and the executive left: which
values a later check may reuse, which preconditions are in doubt, on trial or believed without
a view. Each behaviour class declares the keys it uses and how, as py_trees' blackboard clients
do (``KEYS = {"situation": Access.WRITE, ...}``, with :class:`py_trees.common.Access`), and
works through its own :class:`BoardClient`: reading a key it did not declare, or writing one it
did not declare for writing, raises; a collection it may only read is handed out as an immutable
copy. ``tests/test_board.py`` checks every behaviour class's declaration against what it does in
an episode.

Why not py_trees' blackboard itself: its storage is one dictionary per process (a class
attribute), shared by every tree in it, so two executives side by side (the campaigns' in-process
sessions, the tests) would need a namespace each and to clear it after every episode, and its
values are untyped. The board is one typed dataclass per episode — the executive makes it and
reads it when a tree fails; the report and the live view read it after — with the blackboard's
discipline of declared access.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from types import MappingProxyType
from typing import Any, Mapping

from py_trees.common import Access

from vap_bt.bt.diagnosis import Sightings
from vap_bt.bt.record import ActionCheck, GoalEvidence, Situation, Unchecked, Verification, Verified
from vap_bt.domain.atoms import Atom


@dataclass
class Board:
    """What one episode's behaviours write, and what they read of one another's writing."""

    #: the check or skill that failed the tree, for the executive to handle (it clears it)
    situation: Situation | None = None
    verifications: list[Verification] = field(default_factory=list)
    #: the action-level questions asked (the SuccessVQA/AffordanceVQA baselines: :mod:`vap_bt.bt.action_check`)
    action_checks: list[ActionCheck] = field(default_factory=list)
    #: goal atoms the final look could not settle: success is not claimed over them (the
    #: executive looks again, and clears this for the next tree)
    unconfirmed_goal: list[Atom] = field(default_factory=list)
    #: what the goal check of the tree last ticked through to it rested on (None: no tree since
    #: the last plan got there); recorded by :class:`~vap_bt.bt.goal_check.GoalCheck`
    goal_evidence: GoalEvidence | None = None
    #: each skill goal run, as the report lists it
    actions: list[dict] = field(default_factory=list)
    #: values verified earlier and not changeable since, and the views each atom was judged on
    verified: Verified = field(default_factory=Verified)
    #: what a sense last showed of each atom since an action could have changed it (a situation's
    #: diagnosis asks whether belief was confirmed by a view: :mod:`vap_bt.bt.diagnosis`)
    sightings: Sightings = field(default_factory=Sightings)
    #: preconditions the camera could not make out however often the robot looked again: it acts on
    #: belief there (the action's effects are checked), as the ``go_on`` policy does everywhere
    on_belief: set[Atom] = field(default_factory=set)
    #: preconditions of an action that failed when it ran (a failure is evidence against what the
    #: action presumed): a view that confirms one is a second opinion only with another view from
    #: a new picture that agrees (as for a surprise); cleared when a check settles it
    doubted: set[Atom] = field(default_factory=set)
    #: preconditions the camera denied, that no action can make true, after every doubt: the
    #: action itself is their test (its skill fails if the camera was right), so a check that
    #: contradicts one again lets the action run (the verification still says contradicted)
    on_trial: set[Atom] = field(default_factory=set)
    #: actions an AffordanceVQA question kept saying cannot be done, after looking afresh: the
    #: action itself is the test (its skill fails if the answer was right), so another "no" lets it
    #: run (the check still says contradicted); by ``str(action)``
    actions_on_trial: set[str] = field(default_factory=set)
    #: atoms the compiled trees leave unchecked, keyed by (phase, action, atom), in compile order
    #: (the compiler's, not a behaviour's)
    unchecked: dict[tuple, Unchecked] = field(default_factory=dict)

    def client(self, owner: str, keys: Mapping[str, Access]) -> "BoardClient":
        """A view of the board that allows ``owner`` the ``keys`` it declared, and nothing else."""
        unknown = set(keys) - KEYS
        if unknown:
            raise KeyError(f"{owner} declares keys the board does not have: {sorted(unknown)}")
        return BoardClient(self, owner, keys)


#: every key of the board
KEYS = frozenset(f.name for f in fields(Board))


class BoardClient:
    """One behaviour's access to the board: the keys it declared, read or written as declared."""

    __slots__ = ("_board", "_owner", "_keys")

    def __init__(self, board: Board, owner: str, keys: Mapping[str, Access]) -> None:
        object.__setattr__(self, "_board", board)
        object.__setattr__(self, "_owner", owner)
        object.__setattr__(self, "_keys", dict(keys))

    def __getattr__(self, key: str) -> Any:
        access = self._keys.get(key)
        if access is None:
            raise AttributeError(f"{self._owner} did not declare board key {key!r}")
        value = getattr(self._board, key)
        return value if access != Access.READ else _read_only(value)

    def __setattr__(self, key: str, value: Any) -> None:
        if self._keys.get(key) not in (Access.WRITE, Access.EXCLUSIVE_WRITE):
            raise AttributeError(f"{self._owner} did not declare board key {key!r} for writing")
        setattr(self._board, key, value)


def _read_only(value: Any) -> Any:
    """``value`` as one may read it without changing the board: collections copied immutable."""
    if isinstance(value, list):
        return tuple(value)
    if isinstance(value, set):
        return frozenset(value)
    if isinstance(value, dict):
        return MappingProxyType(value)
    return value
