"""ApplyEffects: the action-driven scene-graph update (paper Sec. IV-A, "Maintenance").

Right after a skill reports success, the belief takes on the action's expected effects: the
delete list goes, the add list comes. Effect checks that follow confirm or contradict them; a
contradiction makes the executive undo this update before it writes what was observed.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.domain.knowledge import GroundAction


class ApplyEffects(py_trees.behaviour.Behaviour):
    def __init__(self, ctx: ExecutionContext, action: GroundAction) -> None:
        super().__init__(name="apply effects")
        self.ctx, self.action = ctx, action

    def update(self) -> Status:
        change = self.ctx.graph.apply(self.action)
        self.feedback_message = f"+{len(change.added)} -{len(change.removed)}"
        return Status.SUCCESS
