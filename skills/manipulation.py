"""Skills of the UR5e arm and its gripper: everything the hand does to objects.

Each class only binds a PDDL action of the household domain to the arm; what the action means is
the domain's business (``domains/household.pddl``) and how it moves is the world's.
"""

from __future__ import annotations

from skills.base import WorldActionSkill


class ArmSkill(WorldActionSkill):
    robot = "ur5e"
    resource = "arm"


class Grasp(ArmSkill):
    """grasp: pick an object up from a surface."""

    action = "grasp"


class TakeOut(ArmSkill):
    """takeout: grasp an object from inside an open container."""

    action = "takeout"


class PlaceIn(ArmSkill):
    """placein: put the held object inside an open container."""

    action = "placein"


class PlaceOn(ArmSkill):
    """placeon: put the held object on a surface."""

    action = "placeon"


class Open(ArmSkill):
    """open: open a door or lid."""

    action = "open"


class Close(ArmSkill):
    """close: close a door or lid."""

    action = "close"


class TurnOn(ArmSkill):
    """turnon: switch an appliance on."""

    action = "turnon"


class Cut(ArmSkill):
    """cut: cut an object with a held tool."""

    action = "cut"


class Fill(ArmSkill):
    """fill: fill a vessel, e.g. at the sink."""

    action = "fill"


class Push(ArmSkill):
    """push: push a blocking object aside so that another becomes reachable."""

    action = "push"
