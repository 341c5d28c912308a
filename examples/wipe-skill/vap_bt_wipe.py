"""wipe(surface): a motion skill from a plugin, built on the robot's skill kit.

The skill moves the robot the way every built-in one does — through the kit's body, navigator
and map (:mod:`skills.kit`), which plan with :mod:`vap_bt.motion` and command the robot's drivers
— and reads only what the robot perceives: where the surface is and how high, from the site map.
Nothing in the simulator knows what a wipe is: the world hears that a ``wipe`` goal began and
ended (the sim-only hook every :class:`~skills.base.MotionSkill` sends), never how it went.

The motion: stand in front of the surface as for working it from above, close the fingers, bring
the fingertips down to just above the middle of its top, sweep them ``PASSES`` times along it
(``STROKE`` to each side of the middle, shorter on a narrow top), lift and fold the arm.
"""

from __future__ import annotations

import numpy as np

from skills.base import MotionSkill
from skills.goal import Outcome
from skills.kit import Kit
from vap_bt.motion import se3
from vap_bt.skill import Hint

#: m the fingertips pass above the top (they reach 0.02 m beyond the tcp)
HOVER = 0.02
FINGERTIP = 0.02
#: m to each side of the middle a stroke reaches, and strokes there and back
STROKE, PASSES = 0.15, 2
#: m the hand comes down from and goes back up to
APPROACH = 0.10


class Wipe(MotionSkill):
    """wipe(s): sweep the closed hand over the top of surface ``s``."""

    action = "wipe"
    robot = "ur5e"
    resource = "arm"

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        surface = args[0]
        top = kit.scene.furniture.get(surface)
        if top is None:
            return Outcome(False, f"{surface} is not on the robot's map")
        if kit.body.holding():
            return Outcome(False, f"wipe({surface}): the hand is full")
        middle = top.top_point()
        kit.nav.approach(kit.nav.work_pose(middle, top.front, "top", top.name))
        reach = min(STROKE, top.width / 2 - 0.05)
        z = top.height + HOVER + FINGERTIP
        ends = [middle + top.along * s * reach for s in (1.0, -1.0)]
        down = se3.frame_zx((0, 0, -1), top.along, (*ends[0][:2], z))  # the hand points down
        above = down.copy()
        above[2, 3] += APPROACH
        kit.body.fingers(0.0)
        if not kit.body.goto_pose(above):
            kit.body.home()
            return Outcome(False, f"{surface}: out of reach")
        kit.body.line(down, steps=3, speed=0.3)
        for k in range(2 * PASSES):
            along = down.copy()
            along[:3, 3] = (*ends[(k + 1) % 2][:2], z)
            kit.body.line(along, steps=6, speed=0.3)
        up = kit.body.pose("tcp")
        up[2, 3] += APPROACH
        kit.body.line(up, steps=2, speed=0.4)
        kit.body.home()
        return Outcome(True, f"wiped {surface}")
