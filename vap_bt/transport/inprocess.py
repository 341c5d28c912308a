"""Skills and camera in the executive's own process: the fast path for symbolic campaigns.

:class:`InProcessSkillClient` runs each goal to the end inside ``send_goal`` — no threads, no
queues — and hands back a handle that is already terminal. A behaviour ticking it sees RUNNING
for zero ticks and the result at once, which is what thousands of symbolic episodes a minute
need. Because goals never overlap here, a busy resource cannot happen; unknown actions are
REJECTED with the same reason the Zenoh server gives.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

from vap_bt.skill import Feedback, GoalState, Skill, SkillResult
from vap_bt.transport.execution import GoalRun, run_goal, unknown_action
from vap_bt.world import Observation, SceneSnapshot, World


@dataclass
class FinishedGoal:
    """A :class:`~vap_bt.skill.GoalHandle` whose goal has already ended."""

    goal_id: str
    _state: GoalState
    _result: SkillResult
    _feedback: Feedback | None = None

    def state(self) -> GoalState:
        return self._state

    def feedback(self) -> Feedback | None:
        return self._feedback

    def result(self) -> SkillResult | None:
        return self._result

    def cancel(self) -> None:
        """Nothing to cancel: the goal finished before the handle existed."""


class InProcessSkillClient:
    """A :class:`~vap_bt.skill.SkillClient` over a dict ``action -> Skill`` in this process."""

    def __init__(self, skills: dict[str, Skill]) -> None:
        self.skills = dict(skills)
        self._ids = itertools.count(1)

    def send_goal(self, action: str, args: tuple[str, ...]) -> FinishedGoal:
        goal_id = f"local-{next(self._ids)}"
        skill = self.skills.get(action)
        if skill is None:
            return FinishedGoal(goal_id, GoalState.REJECTED, unknown_action(action, self.skills))
        ctx = GoalRun()
        state, result = run_goal(skill, tuple(args), ctx)
        return FinishedGoal(goal_id, state, result, ctx.last_feedback)

    def close(self) -> None:
        """Nothing held."""


class InProcessCamera:
    """A :class:`~vap_bt.skill.Camera` that asks the world directly."""

    def __init__(self, world: World) -> None:
        self.world = world

    def observe(self, targets: tuple[str, ...]) -> Observation:
        return self.world.observe(tuple(targets))

    def survey(self) -> SceneSnapshot:
        return self.world.survey()

    def move_view(self, target: str, direction: str) -> bool:
        return self.world.move_view(target, direction)

    def survey(self) -> SceneSnapshot:
        return self.world.survey()
