"""The VLM-planner baseline (paper Sec. V-B): the VLM writes the plan, one action at a time.

"VLM-planner uses the VLM to generate task plans directly, similar to SayCan; we provide domain
knowledge in prompts for fair comparison." (``--verify vlm_planner``). After the survey (the
robot builds its scene graph by looking, as in every strategy) there is no PDDL planner and no
check: each step is two small trees the executive ticks one after the other,

* ``ProposeNextAction`` (:mod:`vap_bt.bt.propose_action`): the model, shown the current frame,
  the domain knowledge, what the robot believes and what it has done, names the next action or
  says ``done`` (:mod:`vap_bt.perception.action_proposal`);
* the action through the executive's own skill path: ``ExecuteSkill`` then ``ApplyEffects`` (the
  action-driven update of belief), with no precondition or effect checks around them.

A skill that reports failure is no situation here — nothing replans — but the next prompt lists
the action as failed, as SayCan's history does, and belief keeps what it held before it. The
episode ends when the model says ``done`` (the executive then *claims* success, on the model's
word alone: whether the goal holds is the world's to say in the report), when it gives no usable
action even when asked again (the reason says why), after ``max_steps`` steps, or when the time
budget is spent.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import py_trees

from vap_bt.bt.apply_effects import ApplyEffects
from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.execute_skill import ExecuteSkill
from vap_bt.bt.plan_tree import PlanTree
from vap_bt.bt.propose_action import ProposeNextAction
from vap_bt.domain.atoms import Atom
from vap_bt.domain.task import PlanningTask
from vap_bt.perception.action_proposal import Proposal
from vap_bt.perception.vlm import TextModel

#: ``drive(tree, deadline)``: tick ``tree`` to its end (the executive's), False when the deadline came first
Drive = Callable[[py_trees.trees.BehaviourTree, float], bool]


@dataclass
class VlmPlanRun:
    """How the VLM-planner's episode went: the executive's claim, why it ended, and every step."""

    success: bool = False
    reason: str = ""
    proposals: list[Proposal] = field(default_factory=list)


class VlmPlanner:
    """Asks the model for each next action and executes it, until ``done`` or a budget ends it."""

    def __init__(self, ctx: ExecutionContext, model: TextModel, task: PlanningTask, instruction: str,
                 max_steps: int, drive: Drive, rejoin: Callable[[str], None] = lambda action: None) -> None:
        self.ctx, self.model, self.task, self.instruction = ctx, model, task, instruction
        self.max_steps, self.drive, self.rejoin = max_steps, drive, rejoin
        self.record = VlmPlanRun()

    def run(self, deadline: float) -> VlmPlanRun:
        """Step until the model says ``done``, fails to name an action, or a budget ends the episode."""
        rec, history = self.record, []
        for step in range(self.max_steps):
            propose = ProposeNextAction(self.ctx, self.model, self.task, self.instruction, step, history)
            if not self.drive(PlanTree(propose), deadline):
                return self._ended(False, "time budget exhausted while the VLM chose an action")
            p = propose.proposal
            rec.proposals.append(p)
            if p.done:
                self.ctx.progress(f"  step {step}: the VLM says done")
                return self._ended(True, "the VLM said done")
            if p.action is None:
                asked = "asked again" if p.reasked else "asked once"
                return self._ended(False, f"no usable action from the VLM at step {step} ({asked}): {p.error}")
            if not self._act(p, step, deadline):
                return self._ended(False, f"time budget exhausted while executing {p.action}")
            history.append(f"{Atom(p.action.name, p.action.args).pddl()}: {p.result}")
        return self._ended(False, f"step budget ({self.max_steps}) exhausted before the VLM said done")

    def _act(self, p: Proposal, step: int, deadline: float) -> bool:
        """Execute the proposed action and believe its effects if its skill succeeded; False when
        the time budget ran out first."""
        action = p.action
        tree = PlanTree(py_trees.composites.Sequence(f"a{step}: {action}", memory=True, children=[
            ExecuteSkill(self.ctx, action, step), ApplyEffects(self.ctx, action)]))
        if not self.drive(tree, deadline):
            return False
        board = self.ctx.board
        failed, board.situation = board.situation, None  # nothing replans: the model reads it in the history
        p.result = "succeeded" if failed is None else f"failed ({failed.detail})"
        if failed is not None:
            self.rejoin(action.name)  # a robot without a server is no fact to plan around: wait, or end
        return True

    def _ended(self, success: bool, reason: str) -> VlmPlanRun:
        self.record.success, self.record.reason = success, reason
        return self.record

