"""Predicate roles: which of a domain's predicates and types play the parts the executive acts on.

The executive is robot-agnostic, but some of what it does needs to know what a predicate *means*:
that one atom says the robot has a thing in view (a skill that failed makes it stale), that
another says the gripper holds an item (the gripper's feel can deny it), which two say an item
rests on or in something (where to look for it), which type of object can be carried away and
lost track of. A domain names these as it likes; its perception profile says which name plays
which role (``roles:`` in :mod:`vap_bt.perception.profile`), and everything in ``bt/`` and
``scene/`` reads the names from a :class:`Roles` value, never from a literal.

The household's names are the defaults, here and nowhere else: a profile that says nothing of
roles gets each household name the domain has with the role's arity (so an IPC domain that
happens to share ``holding/1`` gets the gripper's feel for it, as it always did), and a role the
domain lacks is None — the behaviour that needs it is off. :meth:`Roles.for_domain` does that
filtering; a profile can also switch a role off with ``null``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Iterable, Protocol

from vap_bt.domain.atoms import Atom


class _Domain(Protocol):
    """What :meth:`Roles.for_domain` reads of a domain (a :class:`~vap_bt.domain.knowledge.DomainKnowledge`)."""

    predicates: dict[str, tuple[str, ...]]
    parents: dict[str, str | None]


#: each predicate role's arity (the arguments its atoms have, in this order)
ARITY: dict[str, int] = {
    "in_view": 1,  # the robot is placed to act on X and sees it
    "robot_at": 1,  # the robot stands at X
    "robot_in": 1,  # the robot is in room X
    "in_room": 2,  # thing X is in room Y
    "held": 1,  # the gripper holds X
    "hand_empty": 0,  # the gripper holds nothing
    "open": 1,  # X (a door, a container) is open
    "closed": 1,  # X is closed
    "openable": 1,  # X can be opened and closed (rigid)
    "on": 2,  # X rests on surface Y
    "inside": 2,  # X is inside container Y
    "connects": 3,  # door X joins room Y to room Z (rigid)
    "clear": 1,  # something can be put on surface X (rigid)
    "fillable": 1,  # X can be filled (rigid)
    "reachable": 1,  # the arm can reach X
    "blocking": 2,  # X stands in the way of Y
}


@dataclass(frozen=True)
class Roles:
    """The predicate (and type) of the domain that plays each role; None: the domain has none.

    The defaults are the household domain's names (``domains/household.pddl``)."""

    in_view: str | None = "inview"
    robot_at: str | None = "robot_at"
    robot_in: str | None = "robot_in"
    in_room: str | None = "in_room"
    held: str | None = "holding"
    hand_empty: str | None = "hand_empty"
    open: str | None = "open"
    closed: str | None = "closed"
    openable: str | None = "openable"
    on: str | None = "on"
    inside: str | None = "inside"
    connects: str | None = "connects"
    clear: str | None = "clear"
    fillable: str | None = "fillable"
    reachable: str | None = "reachable"
    blocking: str | None = "blocking"
    #: types whose objects are placed somewhere, carried about, and so can be lost track of
    portable: tuple[str, ...] = ("item",)
    room: str | None = "room"
    container: str | None = "container"

    def predicate_roles(self) -> dict[str, str | None]:
        """Role -> the predicate that plays it."""
        return {r: getattr(self, r) for r in ARITY}

    def for_domain(self, domain: _Domain) -> "Roles":
        """These roles, each kept only where ``domain`` has the predicate with the role's arity
        (or the type): what a profile that says nothing of roles gets."""
        keep = {r: p for r, p in self.predicate_roles().items()
                if p in domain.predicates and len(domain.predicates[p]) == ARITY[r]}
        return replace(self, **{r: keep.get(r) for r in ARITY},
                       portable=tuple(t for t in self.portable if t in domain.parents),
                       room=self.room if self.room in domain.parents else None,
                       container=self.container if self.container in domain.parents else None)

    # -- the sets the executive reads ------------------------------------------------------------

    @staticmethod
    def _present(names: Iterable[str | None]) -> frozenset[str]:
        return frozenset(n for n in names if n is not None)

    @property
    def support(self) -> tuple[str, ...]:
        """The predicates that put an object on or in another (``on``, ``inside``)."""
        return tuple(n for n in (self.on, self.inside) if n is not None)

    @property
    def location(self) -> frozenset[str]:
        """The predicates that say where an object is: on or in something, in a room, in the hand.
        An object's location is the set of these atoms whose first argument is the object."""
        return self._present((self.on, self.inside, self.in_room, self.held))

    @property
    def robot(self) -> frozenset[str]:
        """What localization and the last frame establish about the robot itself."""
        return self._present((self.robot_in, self.robot_at, self.in_view))

    @property
    def hand(self) -> frozenset[str]:
        """What the gripper can say anything of: whether it holds X, whether it is empty."""
        return self._present((self.held, self.hand_empty))

    @property
    def tracks_hand(self) -> bool:
        """Whether the domain has both hand predicates (``hand_empty`` then follows ``held``)."""
        return self.held is not None and self.hand_empty is not None

    def supports(self, atom: Atom) -> bool:
        """``atom`` puts its first argument on or in its second."""
        return atom.predicate in self.support and len(atom.args) == 2

    def is_held(self, atom: Atom) -> bool:
        """``atom`` says the gripper holds its (one) argument."""
        return self.held is not None and atom.predicate == self.held and len(atom.args) == 1

    def holding(self, obj: str) -> Atom | None:
        """The atom that says the gripper holds ``obj`` (None: no such role)."""
        return Atom(self.held, (obj,)) if self.held is not None else None


#: the household's roles, unfiltered: the defaults (a domain's own are ``Roles().for_domain(k)``)
HOUSEHOLD = Roles()
