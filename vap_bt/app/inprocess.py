"""Skills and robot interfaces in the executive's own process: the fast path for symbolic campaigns.

:class:`InProcessSkillClient` runs each goal to the end inside ``send_goal`` — no threads, no
queues — and hands back a handle that is already terminal. A behaviour ticking it sees RUNNING
for zero ticks and the result at once, which is what thousands of symbolic episodes a minute
need. Because goals never overlap here, a busy resource cannot happen; unknown actions are
REJECTED with the same reason the Zenoh server gives.
"""

from __future__ import annotations

import itertools

from vap_bt.skill import GoalHandle, GoalState, Hint, Skill
from vap_bt.transport.execution import GoalRun, run_goal, unknown_action
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState
from vap_bt.world import World


class InProcessSkillClient:
    """A :class:`~vap_bt.skill.SkillClient` over a dict ``action -> Skill`` in this process."""

    def __init__(self, skills: dict[str, Skill]) -> None:
        self.skills = dict(skills)
        self._ids = itertools.count(1)

    def send_goal(self, action: str, args: tuple[str, ...], hints: tuple[Hint, ...] = ()) -> GoalHandle:
        goal_id = f"local-{next(self._ids)}"
        skill = self.skills.get(action)
        if skill is None:
            return GoalHandle(goal_id, GoalState.REJECTED, unknown_action(action, self.skills))
        ctx = GoalRun(hints=tuple(hints))
        state, result = run_goal(skill, tuple(args), ctx)
        return GoalHandle(goal_id, state, result, ctx.last_feedback)  # ended before the handle exists

    def close(self) -> None:
        """Nothing held."""


class InProcessRobot:
    """The camera service and body (:mod:`vap_bt.robot.camera`) of a world in this process.

    It forwards the robot-interface calls and nothing else: the executive holding it can capture
    frames, move to look, read the robot's state and the map, and cannot reach the world's truth
    through it (there is no attribute to reach it by)."""

    __slots__ = ("_capture", "_goto_view", "_move_view", "_state", "_site_map")

    def __init__(self, world: World) -> None:
        """``world``: anything with the camera and body interfaces (a world, a camera service)."""
        self._capture, self._goto_view, self._move_view = world.capture, world.goto_view, world.move_view
        self._state, self._site_map = world.state, world.site_map

    def capture(self, aim: Aim | None = None) -> Frame:
        return self._capture(aim)

    def goto_view(self, view: Viewpoint) -> bool:
        return self._goto_view(view)

    def move_view(self, aim: Aim, direction: str) -> bool:
        return self._move_view(aim, direction)

    def state(self) -> RobotState:
        return self._state()

    def site_map(self) -> SiteMap:
        return self._site_map()
