"""A skill that moves the robot itself: through its kit (:mod:`skills.kit`) and the robot's drivers.

:class:`MotionSkill` is what every built-in skill is: it binds to a robot that offers the driver
interfaces (:mod:`vap_bt.robot.drivers`), runs one goal inside the robot's kit (cancellation
reaching every driver call, progress reaching the goal's feedback) and turns how the motion
ended into a :class:`~vap_bt.skill.SkillResult`: a motion that was stopped — cancelled, or a
driver refused it — fails with the reason; a trip stopped at a shut door fails naming the door;
everything else is the motion's own view (a grasp that closed on nothing still *completed*: that
it failed is for perception to find out). So is a drive the skill stopped because the item in
the hand slipped out (:class:`~skills.body.Slipped`): the robot did what it could, the item lies
beside it, and the checks that follow see what the action left undone — a chance event, not a
motion that would fail the same way again. A subclass sets ``action`` and implements :meth:`run`.

On a world without drivers (the symbolic one) these skills do not bind, and the world performs
their actions instead (:func:`vap_bt.plugins.instantiate`). A simulated world also hears when an
action's goal begins and ends (``begin_action``/``end_action``, :mod:`vap_bt.transport.world_hooks`):
the one thing a simulator is told, so that Table II injection draws once per action; a real robot
has no such hook.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from vap_bt.outcome import Outcome
from vap_bt.robot.drivers import has_drivers
from vap_bt.skill import Hint, Skill, SkillResult
from vap_bt.world import GoalContext

if TYPE_CHECKING:
    from skills.kit import Kit

class MotionSkill(Skill):
    """Perform ``self.action`` by moving the robot (a subclass implements :meth:`run`)."""

    @classmethod
    def binds(cls, world: Any) -> bool:
        return has_drivers(world)

    def execute(self, args: tuple[str, ...], ctx: GoalContext) -> SkillResult:
        # the motion modules on the first goal: a run whose world performs the actions never loads them
        from skills.body import Slipped, Stopped
        from skills.kit import kit_for
        from skills.navigator import Blocked

        call = f"{self.action}({', '.join(args)})"
        if ctx.cancelled():  # cancelled while queued: do not start moving
            return SkillResult(False, f"{call} cancelled before it started")
        ctx.feedback(0.0, f"{call} started")
        kit = kit_for(self.world)
        hooks = self.world if callable(getattr(self.world, "begin_action", None)) else None
        try:
            with kit.goal(ctx):
                if hooks is not None:  # a simulated world: Table II draws for this action now
                    hooks.begin_action(self.action, tuple(args))
                try:
                    out = self.run(kit, tuple(args), dict(getattr(ctx, "hints", {}) or {}))
                finally:
                    if hooks is not None:
                        hooks.end_action(self.action, tuple(args))
        except Slipped as e:
            return SkillResult(True, f"{call} stopped: {e}")
        except Stopped as e:
            return SkillResult(False, f"{call} stopped: {e}")
        except Blocked as e:
            return SkillResult(False, str(e))
        ctx.feedback(1.0, f"{call} {'completed' if out.completed else 'failed'}")
        return SkillResult.of(out, call)

    def run(self, kit: Kit, args: tuple[str, ...], hints: dict[str, Hint]) -> Outcome:
        """Move the robot for ``action(args)`` through ``kit``, looking where ``hints`` say, and say how
        the motion ended. Blocks until done; a cancelled goal raises :class:`~skills.body.Stopped` from
        the driver call it reached."""
        raise NotImplementedError
