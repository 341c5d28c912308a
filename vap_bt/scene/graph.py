"""The scene graph G = (O, R): the objects the robot knows and the ground facts it believes.

It is the executive's state, and the planner's initial state on every replan. It changes in the
two ways the paper names (Sec. IV-A, "Maintenance"), plus the bookkeeping they need:

* **action-driven** — :meth:`apply` makes the state difference of the action in current belief
  (:meth:`GroundAction.diff <vap_bt.domain.knowledge.GroundAction.diff>`: its delete list goes,
  its add list comes, and conditional effects only where their conditions are believed), and
  remembers what it changed so that :meth:`undo` can take it back when the camera shows the
  action did not happen;
* **observation-driven** — :meth:`correct` sets one atom to its verified value, and
  :meth:`relocate` replaces what is believed about where an object is (``on``, ``inside``,
  ``in_room``, ``holding``) by what the scene-graph builder sees now.

Every change is logged with its cause, so a report can show how belief evolved.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.world import ObjectInfo, SceneSnapshot

#: Predicates that say where an object is; an object's location is the set of these atoms whose
#: first argument is the object. ``hand_empty`` follows from ``holding``.
LOCATION_PREDICATES = frozenset({"on", "inside", "in_room", "holding"})


@dataclass
class Change:
    cause: str  # "apply", "undo", "correct", "relocate", "survey"
    added: frozenset[Atom]
    removed: frozenset[Atom]

    def to_json(self) -> dict:
        return {"cause": self.cause, "added": sorted(map(str, self.added)), "removed": sorted(map(str, self.removed))}


@dataclass
class SceneGraph:
    objects: dict[str, ObjectInfo]
    facts: set[Atom]
    #: keep hand_empty consistent with holding (domains that have both, like the household)
    tracks_hand: bool = False
    history: list[Change] = field(default_factory=list)
    _applied: list[tuple[GroundAction, Change]] = field(default_factory=list, repr=False)

    @classmethod
    def from_snapshot(cls, snap: SceneSnapshot, tracks_hand: bool = False) -> "SceneGraph":
        return cls({o.name: o for o in snap.objects}, set(snap.facts), tracks_hand=tracks_hand)

    def state(self) -> frozenset[Atom]:
        return frozenset(self.facts)

    def holds(self, atom: Atom) -> bool:
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

    def correct(self, atom: Atom, value: bool, complement: str | None = None) -> Change:
        """Set ``atom`` to ``value``; with ``complement`` (open for closed, say) set that atom over
        the same arguments to the opposite, if belief held either of the pair before."""
        add, remove = ({atom}, set()) if value else (set(), {atom})
        if complement is not None:
            other = Atom(complement, atom.args)
            if atom in self.facts or other in self.facts:
                (remove if value else add).add(other)
        return self._change("correct", add, remove)

    def location(self, obj: str) -> set[Atom]:
        return {a for a in self.facts if a.predicate in LOCATION_PREDICATES and a.args and a.args[0] == obj}

    def relocate(self, obj: str, observed: set[Atom]) -> Change:
        """Believe ``observed`` (this object's location atoms) instead of what was believed."""
        new = {a for a in observed if a.predicate in LOCATION_PREDICATES and a.args and a.args[0] == obj}
        ch = self._change("relocate", new, self.location(obj) - new)
        self._sync_hand()
        return ch

    def merge_survey(self, snap: SceneSnapshot) -> Change:
        """A fresh survey replaces every location fact; other facts are kept (they were verified)."""
        for o in snap.objects:
            self.objects.setdefault(o.name, o)
        old = {a for a in self.facts if a.predicate in LOCATION_PREDICATES}
        new = {a for a in snap.facts if a.predicate in LOCATION_PREDICATES}
        ch = self._change("survey", new, old - new)
        self._sync_hand()
        return ch

    def _sync_hand(self) -> None:
        # hand_empty is believed exactly when nothing is believed held
        if not self.tracks_hand:
            return
        held = any(a.predicate == "holding" for a in self.facts)
        empty = Atom("hand_empty")
        self._change("relocate", set() if held else {empty}, {empty} if held else set())
