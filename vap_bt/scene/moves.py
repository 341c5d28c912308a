"""Where belief had an item before a sighting moved it: the place to go back to when the search
that follows a failed check finds the item nowhere.

A sighting can put an item in the wrong place: a cup seen through the door of the microwave it
stands in, whose partial cloud the geometry reads as on the counter beside it (boil_water seed 4
in pybullet, after two takeouts from the microwave slipped). The plan then goes to the counter,
the check there cannot see the cup, and the re-survey that follows finds it nowhere (the sweep
does not look into the microwave) — so belief keeps it on the counter, the replan is the same plan,
and the same check fails again, until the replanning budget is gone. The place belief held before
that sighting is the better guess then: nothing the robot did has moved the item since, and the
one sighting that moved it is the one the checks could not confirm.

The record is dropped once belief moves the item some other way (an action, another sighting):
only the sighting's own place is taken back. Nor is a place taken back that a check had already
failed to find the item at (boil_water seed 8: the cup, believed in the microwave after a placing
that dropped it, could not be seen inside three times; the sighting that put it on the floor was
right, and going back to the microwave would have been the older error). A place a check only
could not make the item out at is a weaker doubt than one where a look said it is not there, or
where a skill looked for it to act on and did not see it: such a place is taken back once the
sighting's own place has had the stronger doubt (heat_pie seed 20 in pybullet: a sighting put the
pie, standing in the fridge the checks could not see into, on the counter; three grasps there saw
no pie, and belief kept it on the counter until the episode was stuck).

A placing whose effect a check denied moves the item the same way: belief takes the placing back,
the gripper is empty, and the item is placed nowhere. Where the hand let it go is then the place
to go back to if the search finds it nowhere (heat_pie seed 29 in pybullet: the pie set into the
oven, a look judged it not inside, the sweeps do not see into an oven, and with the pie placed
nowhere the planner found no plan). Believed there, it is tested again by the next check.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from vap_bt.domain.atoms import Atom


@dataclass
class SightingMoves:
    """Per item, the place belief gave it before the last sighting moved it, and the place the
    sighting gave it (each a set of location atoms)."""

    moves: dict[str, tuple[frozenset[Atom], frozenset[Atom]]] = field(default_factory=dict)
    #: places (``on``/``inside`` atoms) a check or a skill found their item not at
    doubted: set[Atom] = field(default_factory=set)
    #: places a check could not make their item out at (a weaker doubt: see the module docstring)
    unsure: set[Atom] = field(default_factory=set)

    def note(self, name: str, before: set[Atom], after: set[Atom]) -> None:
        """A sighting (or a denied placing) moved ``name`` from ``before`` to ``after`` (what
        belief held; ``before`` empty: it had no place, and there is nothing to go back to)."""
        if before and before != after:
            self.moves[name] = (frozenset(before), frozenset(after))

    def doubt(self, place: Atom, firm: bool = True) -> None:
        """A check or a skill found the item not at ``place`` (an ``on``/``inside`` atom about
        it); not ``firm``: a check could not make it out there."""
        (self.doubted if firm else self.unsure).add(place)

    def clear(self, name: str) -> None:
        """``name`` is in the hand: where it was, and where it was missed, say nothing of it now."""
        self.moves.pop(name, None)
        self.doubted = {a for a in self.doubted if a.args[0] != name}
        self.unsure = {a for a in self.unsure if a.args[0] != name}

    def taken_back(self, name: str, now: set[Atom]) -> frozenset[Atom] | None:
        """The place to believe ``name`` at again, when belief still has it where the last sighting
        put it (``now``) and no check found it not at the place before (nor could make it out
        there, unless ``now`` had the firmer doubt), else None. The record is used up, but for
        the wait for that firmer doubt (the search that follows the first check the sighting's
        place failed comes before the skill that looks there itself)."""
        move = self.moves.get(name)
        if move is None or move[1] != frozenset(now) or move[0] & self.doubted:
            self.moves.pop(name, None)
            return None
        if move[0] & self.unsure and not frozenset(now) & self.doubted:
            return None  # kept for the firmer doubt
        del self.moves[name]
        return move[0]
