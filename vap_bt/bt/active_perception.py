"""ActivePerception: the retry decorator that moves the camera until a verification settles.

It wraps a :class:`~vap_bt.bt.verify_predicate.VerifyPredicate` (paper Alg. 2). When the child's
round settles, the verdict stands: SUCCESS if the world agrees with the expectation; otherwise a
*situation* is recorded on the context and the decorator fails, which fails the plan's tree and
hands control to the executive. When the round does not settle (answers disagree, or the view is
judged insufficient), the decorator asks the VLM where to look from, moves there, and ticks the
child again — at most K moves. With the budget spent and no round settled, a value decides only if
every view's answers agreed on it; otherwise the check does not overturn belief and is recorded as
*unsettled* (the paper returns the last vote here; one vote from a view the VLM judged insufficient
is too close to a guess to rewrite the scene graph).
An unsettled *goal* atom withholds the executive's claim of success.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext, Phase, Situation, Verification
from vap_bt.bt.verify_predicate import VerifyPredicate
from vap_bt.domain.knowledge import GroundAction
from vap_bt.perception.verification import suggest_viewpoint, target_of


class ActivePerception(py_trees.decorators.Decorator):
    def __init__(self, ctx: ExecutionContext, child: VerifyPredicate, phase: Phase,
                 action: GroundAction | None, step: int) -> None:
        super().__init__(name=f"look(K={ctx.budget})", child=child)
        self.ctx, self.phase, self.action, self.step = ctx, phase, action, step
        self.verify = child
        self.rounds = []
        self.moves = 0

    def initialise(self) -> None:
        self.rounds, self.moves = [], 0

    def update(self) -> Status:
        r = self.verify.round
        if r is None:  # the child did not run (interrupted)
            return Status.FAILURE
        self.rounds.append(r)
        if self.verify.status == Status.SUCCESS:
            return self._settle(r.vote, "confirmed")
        if r.settled:
            return self._settle(r.vote, "contradicted")
        if self.moves < self.ctx.budget:
            atom = self.verify.atom
            target = target_of(atom)
            r.direction = suggest_viewpoint(self.ctx.vlm, self.verify.observation, atom, r.questions[0], target)
            r.moved = self.ctx.camera.move_view(target, r.direction) if r.direction else False
            self.moves += 1
            return Status.RUNNING
        # budget spent without a settled round: a value stands only if every view's answers agreed on
        # it (independent views agreeing is evidence; a model guessing about an object it cannot see
        # rarely agrees with itself view after view); otherwise belief stands
        votes = {x.vote for x in self.rounds if x.consistent}
        if all(x.consistent for x in self.rounds) and len(votes) == 1 and None not in votes:
            value = votes.pop()
            return self._settle(value, "confirmed" if value == self.verify.expected else "contradicted")
        return self._settle(self.verify.expected, "unsettled")

    def _settle(self, value: bool, outcome: str) -> Status:
        v = self.verify
        self.ctx.verifications.append(Verification(self.phase, str(self.action) if self.action else "goal",
                                                   v.atom, v.expected, value, outcome, list(self.rounds)))
        if self.phase == "goal" and outcome == "unsettled":
            self.ctx.unconfirmed_goal.append(v.atom)
        if outcome != "contradicted":
            return Status.SUCCESS
        kind = {"pre": "precondition", "eff": "effect", "goal": "goal"}[self.phase]
        self.ctx.situation = Situation(kind, self.action, self.step, v.atom, v.expected, value)
        self.ctx.progress(f"    situation: {kind} {'' if v.expected else 'not '}{v.atom} observed {value}")
        return Status.FAILURE
