"""The scene graph G = (O, R): the objects the robot knows and the ground facts it believes.

It is the executive's state, and the planner's initial state on every replan. It is built by
looking (:mod:`vap_bt.scene.builder`) and changes in the two ways the paper names (Sec. IV-A,
"Maintenance"), plus the bookkeeping they need:

* **action-driven** — :meth:`apply` makes the state difference of the action in current belief
  (:meth:`GroundAction.diff <vap_bt.domain.knowledge.GroundAction.diff>`: its delete list goes,
  its add list comes, and conditional effects only where their conditions are believed), and
  remembers what it changed so that :meth:`undo` can take it back when the camera shows the
  action did not happen;
* **observation-driven** — :meth:`correct` sets one atom to its verified value, and
  :meth:`relocate` replaces what is believed about where an object is (the domain's predicates of
  the location roles, :attr:`~vap_bt.domain.roles.Roles.location`: the household's ``on``,
  ``inside``, ``in_room``, ``holding``) by what the scene-graph builder sees now.

Every change is logged with its cause, so a report can show how belief evolved. Each object
records where its node came from: the site ``map``, ``perceived`` (detected in a frame), or a
``prior`` the task file stated (believed, not yet seen).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Literal

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.domain.roles import Roles

Source = Literal["map", "perceived", "prior"]


@dataclass(frozen=True)
class SceneObject:
    """One node of the graph: an object with what perception knows of its geometry."""

    name: str
    label: str
    source: Source = "prior"
    room: str | None = None
    centroid: tuple[float, float, float] | None = None
    #: axis-aligned box as (xmin, ymin, zmin, xmax, ymax, zmax), metres, map frame
    box: tuple[float, float, float, float, float, float] | None = None
    frames: int = 0  # frames it was detected in
    #: where belief placed it when ``centroid`` was measured; once belief moves it (an action
    #: carried it away), the centroid is stale and its support says where to look instead
    located: frozenset[Atom] = frozenset()

    def seen(self, **changes) -> "SceneObject":
        """This node with what a new look changed (its centroid, box, frames, where belief put it)."""
        return replace(self, **changes)


@dataclass
class Change:
    """One change of belief: its cause and the atoms it added and removed."""

    cause: str  # "apply", "undo", "correct", "relocate", "survey"
    added: frozenset[Atom]
    removed: frozenset[Atom]

    def to_json(self) -> dict:
        return {"cause": self.cause, "added": sorted(map(str, self.added)), "removed": sorted(map(str, self.removed))}


@dataclass
class SceneGraph:
    """Objects and believed facts, with the log of every change."""

    objects: dict[str, SceneObject]
    facts: set[Atom]
    #: keep the hand-empty atom consistent with the held ones (domains that have both, like the household)
    tracks_hand: bool = False
    #: which predicates say where a thing is, what the hand holds, what blocks what
    roles: Roles = field(default_factory=Roles)
    history: list[Change] = field(default_factory=list)
    _applied: list[tuple[GroundAction, Change]] = field(default_factory=list, repr=False)

    @classmethod
    def of_facts(cls, facts, tracks_hand: bool = False, roles: Roles | None = None) -> "SceneGraph":
        """A graph of bare facts, without object nodes (planning and tests)."""
        return cls({}, set(facts), tracks_hand=tracks_hand, roles=roles or Roles())

    def state(self) -> frozenset[Atom]:
        return frozenset(self.facts)

    def holds(self, atom: Atom) -> bool:
        """Whether ``atom`` is believed (the world is closed: an atom not in the facts is false)."""
        return atom in self.facts

    def _change(self, cause: str, add: set[Atom], remove: set[Atom]) -> Change:
        removed = frozenset(a for a in remove if a in self.facts)
        self.facts -= removed
        added = frozenset(a for a in add if a not in self.facts)
        self.facts |= added
        ch = Change(cause, added, removed)
        if added or removed:
            self.history.append(ch)
        return ch

    def apply(self, action: GroundAction) -> Change:
        """Believe ``action`` done: its state difference in current belief, remembered so that :meth:`undo`
        can take it back. Returns the change."""
        diff = action.diff(self.facts)
        ch = self._change("apply", set(diff.added), set(diff.deleted))
        self._applied.append((action, ch))
        return ch

    def undo(self, action: GroundAction) -> bool:
        """Take back the last :meth:`apply` of ``action``; False if it was not the last applied."""
        if not self._applied or self._applied[-1][0] != action:
            return False
        _, ch = self._applied.pop()
        self._change("undo", set(ch.removed), set(ch.added))
        return True

    def correct(self, atom: Atom, value: bool, complement: str | None = None, cause: str = "correct") -> Change:
        """Set ``atom`` to ``value``; with ``complement`` (open for closed, say) set that atom over
        the same arguments to the opposite, if belief held either of the pair before. ``cause``
        names the sense that said so ("correct": a verification; "gripper": proprioception)."""
        add, remove = ({atom}, set()) if value else (set(), {atom})
        if complement is not None:
            other = Atom(complement, atom.args)
            if atom in self.facts or other in self.facts:
                (remove if value else add).add(other)
        return self._change(cause, add, remove)

    def location(self, obj: str) -> set[Atom]:
        """The believed atoms that say where ``obj`` is (its location roles' atoms)."""
        return {a for a in self.facts if a.predicate in self.roles.location and a.args and a.args[0] == obj}

    def relocate(self, obj: str, observed: set[Atom]) -> Change:
        """Believe ``observed`` (this object's location atoms, and what the frames show standing in
        its way) instead of what was believed. Whether it can be reached is left to the checks: a
        blocker seen is a reason the planner can act on (push it), a verdict is not overturned."""
        location, blocking = self.roles.location, self.roles.blocking
        new = {a for a in observed if a.args and (a.predicate in location and a.args[0] == obj
                                                  or a.predicate == blocking and a.args[-1] == obj)}
        old = self.location(obj) | {a for a in self.facts if a.predicate == blocking and a.args[-1] == obj}
        ch = self._change("relocate", new, old - new)
        self._sync_hand()
        return ch

    def replace_predicates(self, predicates: frozenset[str] | set[str], atoms: set[Atom], cause: str) -> Change:
        """Believe exactly ``atoms`` for ``predicates`` (where the robot is and what it sees, after
        it moved to look: localization and the last frame say so)."""
        old = {a for a in self.facts if a.predicate in predicates}
        return self._change(cause, {a for a in atoms if a.predicate in predicates}, old)

    def _sync_hand(self) -> None:
        # the hand is believed empty exactly when nothing is believed held
        if not self.tracks_hand or not self.roles.tracks_hand:
            return
        held = any(a.predicate == self.roles.held for a in self.facts)
        empty = Atom(self.roles.hand_empty)
        self._change("relocate", set() if held else {empty}, {empty} if held else set())
