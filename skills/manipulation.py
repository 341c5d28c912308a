"""Skills of the UR5e arm and its gripper: everything the hand does to things.

Each class binds a PDDL action of the household domain to the arm and says which of the goal's
arguments it works on; how the hand moves is :mod:`skills.hands` (and :mod:`skills.handles` for
doors and drawers), from what the camera measures where the goal's hints say to look.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from skills.base import MotionSkill
from skills.goal import Where
from vap_bt.outcome import Outcome
from vap_bt.skill import Hint

if TYPE_CHECKING:
    from skills.kit import Kit


class ArmSkill(MotionSkill):
    """A skill of the arm and gripper (the ``ur5e`` server; occupies the arm)."""

    robot = "ur5e"
    resource = "arm"


class Grasp(ArmSkill):
    """grasp(o, s, r): pick ``o`` up from surface ``s``."""

    action = "grasp"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        o, s = args[:2]
        return kit.hands.grasp(o, kit.point(hints, o), Where(on=s, radius=kit.where(hints, o).radius))


def _at_open(kit: Kit, c: str, out: Outcome) -> Outcome:
    """``out`` of a motion into container ``c``; failed where a look at ``c`` finds it shut, the
    failure of the action's precondition ``open(c)`` instead: heat_pie seed 141 in pybullet took
    the pie out of a fridge whose opening had failed unseen, and three times in a row saw only
    the door ("not seen"); looked for in the room after each, the pie never was."""
    if out.completed or not kit.handles.shut(c):
        return out
    return Outcome(False, f"{c} is shut", unmet=f"open({c})")


class TakeOut(ArmSkill):
    """takeout(o, c, r): grasp ``o`` from inside the open container ``c``."""

    action = "takeout"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        o, c = args[:2]
        return _at_open(kit, c, kit.hands.grasp(o, kit.point(hints, o), Where(inside=c, radius=kit.where(hints, o).radius)))


class PlaceIn(ArmSkill):
    """placein(o, c, r): put the held ``o`` inside the open container ``c``."""

    action = "placein"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        o, c = args[:2]
        if not kit.holding(o):
            return Outcome(False, f"not holding {o}")
        return _at_open(kit, c, kit.hands.place(o, c, inside=True))


class PlaceOn(ArmSkill):
    """placeon(o, s, r): put the held ``o`` on surface ``s``."""

    action = "placeon"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        o, s = args[:2]
        if not kit.holding(o):
            return Outcome(False, f"not holding {o}")
        return kit.hands.place(o, s, inside=False)


class Open(ArmSkill):
    """open(x): open a door, a cabinet's door or a drawer by its handle."""

    action = "open"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        return kit.handles.open_close(args[0], opening=True)


class Close(ArmSkill):
    """close(x): close a door, a cabinet's door or a drawer by its handle."""

    action = "close"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        return kit.handles.open_close(args[0], opening=False)


class TurnOn(ArmSkill):
    """turnon(a, o): press appliance ``a``'s switch."""

    action = "turnon"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        return kit.hands.press(args[0])


class Cut(ArmSkill):
    """cut(o, k): cut ``o`` with the held knife ``k``."""

    action = "cut"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        o, k = args[:2]
        if not kit.holding(k):
            return Outcome(False, f"not holding {k}")
        return kit.hands.cut(o, k, kit.point(hints, o), kit.where(hints, o))


class Fill(ArmSkill):
    """fill(o, s): fill the held vessel ``o`` at sink ``s``."""

    action = "fill"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        o, s = args[:2]
        if not kit.holding(o):
            return Outcome(False, f"not holding {o}")
        return kit.hands.fill(o, s)


class Push(ArmSkill):
    """push(b, o): push ``b`` aside so that ``o`` becomes reachable."""

    action = "push"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        b, o = args[:2]
        return kit.hands.push(b, o, {n: kit.point(hints, n) for n in (b, o)}, kit.where(hints, b))
