"""FeelHand: after an action and its checks, the gripper's word on what belief has in the hand.

An item can slip out of the hand during any action (Table II: a held object drops during
navigation; a cut, a fill or a place loses its grip on the way). The action's own checks see it
when the item was what it acted on; otherwise the first to notice would be the next action that
needs the item in the hand — after the robot has driven off, away from where it fell, or over it.
So after every action that leaves belief holding something, the gripper (``ctx.felt``: whether
its fingers closed on something) is asked, at no cost: an empty gripper is a situation of kind
``effect`` about ``holding``, observed false. It names no action — the action did what it did
(the robot moved), only the hand lost its item — so nothing is undone; the plan's tail after the
action is what the replan may reuse. When the item lost is one the action worked with (a knife
that dropped mid-cut), the action's other effects are put in doubt (``ctx.doubted``): views
judged before count for nothing, and a confirming view needs a second from a new picture.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext, Situation
from vap_bt.domain.knowledge import GroundAction


class FeelHand(py_trees.behaviour.Behaviour):
    """Whether the gripper still holds what belief has in it after ``action``."""

    def __init__(self, ctx: ExecutionContext, action: GroundAction, step: int) -> None:
        super().__init__(name="feel hand")
        self.ctx, self.action, self.step = ctx, action, step

    def update(self) -> Status:
        for atom in sorted(a for a in self.ctx.graph.facts if a.predicate == "holding"):
            if self.ctx.felt(self.ctx.graph, atom) is False:
                if atom.args[0] in self.action.args:
                    # the action lost the very thing it worked with (the knife dropped mid-cut):
                    # what it was to bring about is in doubt, and views judged before the hand
                    # was felt are no evidence for it (cut_lemon seed 1 with injection: a lemon
                    # "sliced" on one view, and on one more at the goal, that was never cut)
                    effects = {a for a in self.action.may_add if a.predicate != "holding"}
                    self.ctx.doubted |= effects
                    self.ctx.verified.distrust(effects)
                self.ctx.situation = Situation("effect", None, self.step + 1, atom, True, False,
                                               f"the gripper holds nothing after {self.action}")
                self.ctx.progress(f"    situation: the gripper holds nothing after {self.action}")
                return Status.FAILURE
        return Status.SUCCESS
