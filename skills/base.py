"""A skill that performs its action by asking the world to do it.

Worlds already know how to carry out every domain action (motion in pybullet, fact updates in the
symbolic world), so the built-in skills are thin: they report that they started, hand the action
to :meth:`World.perform`, and turn the world's :class:`~vap_bt.world.ActionOutcome` into a
:class:`~vap_bt.skill.SkillResult`. A subclass only names its action, robot and resource.
"""

from __future__ import annotations

from vap_bt.skill import Skill, SkillResult
from vap_bt.world import GoalContext


class WorldActionSkill(Skill):
    """Perform ``self.action`` on ``self.world``; a subclass sets ``action`` (and robot/resource)."""

    def execute(self, args: tuple[str, ...], ctx: GoalContext) -> SkillResult:
        call = f"{self.action}({', '.join(args)})"
        if ctx.cancelled():  # cancelled while queued: do not start moving
            return SkillResult(False, f"{call} cancelled before it started")
        ctx.feedback(0.0, f"{call} started")
        outcome = self.world.perform(self.action, tuple(args), ctx)
        ctx.feedback(1.0, f"{call} {'completed' if outcome.completed else 'failed'}")
        return SkillResult(outcome.completed, outcome.message or call)

