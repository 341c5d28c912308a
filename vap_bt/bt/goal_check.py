"""GoalCheck: the last node of every compiled plan — does the belief now satisfy the goal?

Effects were verified along the way, so the belief is grounded; this node only fails when it is
not (a plan compiled for a goal the belief does not reach is a bug or a stale tree), and its
failure is a situation of kind ``goal``.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext, Situation
from vap_bt.domain.atoms import Literal


class GoalCheck(py_trees.behaviour.Behaviour):
    def __init__(self, ctx: ExecutionContext, goal: tuple[Literal, ...], step: int) -> None:
        super().__init__(name="goal check")
        self.ctx, self.goal, self.step = ctx, goal, step

    def update(self) -> Status:
        missing = [l for l in self.goal if self.ctx.graph.holds(l.atom) != l.positive]
        if not missing:
            return Status.SUCCESS
        l = missing[0]
        self.ctx.situation = Situation("goal", None, self.step, l.atom, l.positive, not l.positive,
                                       detail="belief does not satisfy the goal")
        return Status.FAILURE
