"""ApplyEffects: the action-driven scene-graph update (paper Sec. IV-A, "Maintenance").

Right after a skill reports success, the belief takes on the action's expected effects: the
state difference of the action in current belief (the delete list goes, the add list comes;
conditional effects where their conditions are believed). Effect checks that follow confirm or
contradict them; a contradiction makes the executive undo this update before it writes what was
observed. The compiler chose those checks from the difference it expected; the feedback message
says so if belief made a different one.
"""

from __future__ import annotations

from typing import ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.domain.knowledge import GroundAction, StateDiff


class ApplyEffects(py_trees.behaviour.Behaviour):
    """Apply the action's effects to the scene graph."""

    KEYS: ClassVar[dict[str, Access]] = {}

    def __init__(self, ctx: ExecutionContext, action: GroundAction, expected: StateDiff | None = None) -> None:
        super().__init__(name="apply effects")
        self.ctx, self.action, self.expected = ctx, action, expected
        self.board = ctx.board.client(type(self).__name__, self.KEYS)

    def update(self) -> Status:
        change = self.ctx.graph.apply(self.action)
        self.feedback_message = f"+{len(change.added)} -{len(change.removed)}"
        if self.expected is not None and (change.added, change.removed) != (self.expected.added,
                                                                           self.expected.deleted):
            self.feedback_message += " (not the difference the checks were compiled for)"
        return Status.SUCCESS
