"""Running one goal on one skill, the same way wherever the skill is hosted.

Both the in-process client and the Zenoh skill server run goals through :func:`run_goal`, so the
rules that turn what a skill did into a :class:`~vap_bt.skill.GoalState` live in one place:

* the skill returned a successful result          -> SUCCEEDED (even if a cancel came too late)
* it returned failure after a cancel was requested -> CANCELED
* it returned failure otherwise                    -> ABORTED
* it raised, or returned something that is not a SkillResult -> ABORTED, with the reason
"""

from __future__ import annotations

from typing import Callable

from vap_bt.skill import Feedback, GoalState, Hint, Skill, SkillResult


class GoalRun:
    """The :class:`~vap_bt.world.GoalContext` a running skill sees.

    Feedback is kept (latest wins) and forwarded to ``on_feedback``; cancellation is a one-way
    flag that any thread may set. A plain attribute suffices: it only ever goes False -> True.
    """

    def __init__(self, on_feedback: Callable[[Feedback], None] | None = None, hints: tuple[Hint, ...] = ()) -> None:
        self._on_feedback = on_feedback
        self.hints = {h.name: h for h in hints}
        self._cancelled = False
        self.last_feedback: Feedback | None = None

    def feedback(self, progress: float, text: str = "") -> None:
        fb = Feedback(min(1.0, max(0.0, float(progress))), str(text))
        self.last_feedback = fb
        if self._on_feedback is not None:
            self._on_feedback(fb)

    def cancelled(self) -> bool:
        return self._cancelled

    def request_cancel(self) -> None:
        """Ask the skill to stop: :meth:`cancelled` is true from now on (any thread may call it)."""
        self._cancelled = True


def run_goal(skill: Skill, args: tuple[str, ...], ctx: GoalRun) -> tuple[GoalState, SkillResult]:
    """Execute ``skill`` to the end and classify the outcome; never raises for a skill's fault."""
    try:
        result = skill.execute(tuple(args), ctx)
    except Exception as exc:  # a skill bug fails its goal, not the host
        return GoalState.ABORTED, SkillResult(
            False, f"{skill.action} raised {type(exc).__name__}: {exc}"
        )
    if not isinstance(result, SkillResult):
        return GoalState.ABORTED, SkillResult(
            False, f"{skill.action} returned {type(result).__name__}, not a SkillResult"
        )
    if result.success:
        return GoalState.SUCCEEDED, result
    return (GoalState.CANCELED if ctx.cancelled() else GoalState.ABORTED), result


def unknown_action(action: str, known: object) -> SkillResult:
    """The rejection every host gives for an action it does not serve."""
    names = ", ".join(sorted(known)) or "none"  # type: ignore[call-overload]
    return SkillResult(False, f"no skill for action {action!r} here (serving: {names})")
