"""ExecuteSkill: a plan action sent as a goal to whatever hosts the skill (ROS-action style).

``initialise`` sends the goal, with what belief says about its objects (where the scene graph
places them: a skill looks there and measures for itself); the behaviour is RUNNING while the goal is in flight and reports
progress from the skill's feedback; it succeeds or fails with the goal's result. If the tree
interrupts it (a higher-priority branch, a halted tree), ``terminate`` cancels the goal so the
robot does not keep moving for a plan that no longer exists. A failed goal is a situation of
kind ``execution``.
"""

from __future__ import annotations

from typing import ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.record import Situation
from vap_bt.domain.atoms import Atom, AtomSyntaxError
from vap_bt.domain.knowledge import GroundAction
from vap_bt.skill import GoalHandle, GoalState


class ExecuteSkill(py_trees.behaviour.Behaviour):
    """Send one plan action to its skill server and follow the goal to its result."""

    KEYS: ClassVar[dict[str, Access]] = {"verified": Access.WRITE, "actions": Access.WRITE,
                                         "situation": Access.WRITE, "sightings": Access.WRITE,
                                         "verifications": Access.READ}

    def __init__(self, ctx: ExecutionContext, action: GroundAction, step: int) -> None:
        super().__init__(name=f"execute {action}")
        self.ctx, self.action, self.step = ctx, action, step
        self.board = ctx.board.client(type(self).__name__, self.KEYS)
        self.handle: GoalHandle | None = None
        self._sent_at = 0.0

    def initialise(self) -> None:
        self._sent_at = self.ctx.now()
        self.ctx.progress(f"  a{self.step}: {self.action}")
        hints = self.ctx.hints(self.ctx.graph, tuple(self.action.args))
        self.handle = self.ctx.skills.send_goal(self.action.name, self.action.args, hints)

    def update(self) -> Status:
        state = self.handle.state()
        fb = self.handle.feedback()
        if fb is not None:
            self.feedback_message = f"{fb.progress:.0%} {fb.text}"
        if not state.terminal:
            return Status.RUNNING
        result = self.handle.result()
        ok = state == GoalState.SUCCEEDED and result is not None and result.success
        # whatever it did, what it touched must be looked at again
        self.board.verified.executed(self.action, len(self.board.verifications), ok)
        self.board.sightings.executed(self.action)  # and what was seen of it is no longer what is
        self.board.actions.append({"step": self.step, "action": str(self.action), "state": state.value,
                                 "message": result.message if result else "", "sent_s": self._sent_at,
                                 "done_s": self.ctx.now()})
        self.ctx.progress(f"  a{self.step}: {state.value} in {(self.ctx.now() - self._sent_at) * 1000:.0f} ms"
                          + (f" ({result.message})" if result and result.message and not ok else ""))
        if ok:
            return Status.SUCCESS
        detail = result.message if result else state.value
        self.board.situation = Situation("execution", self.action, self.step, detail=detail,
                                         missing=result.missing if result else None,
                                         unmet=self._unmet(result.unmet if result else None))
        self.ctx.progress(f"    situation: execution of {self.action} failed ({detail})")
        return Status.FAILURE

    def _unmet(self, text: str | None) -> Atom | None:
        """The action's positive precondition the skill named as found false (in either notation);
        None for anything else (what a skill may correct is a precondition of the action it was given)."""
        try:
            atom = Atom.parse(text) if text else None
        except AtomSyntaxError:
            return None
        return atom if any(lit.positive and lit.atom == atom for lit in self.action.preconditions) else None

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID and self.handle is not None and not self.handle.state().terminal:
            self.handle.cancel()
