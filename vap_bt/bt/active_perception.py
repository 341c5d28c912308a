"""ActivePerception: the retry decorator that moves the camera until a verification settles.

It wraps a :class:`~vap_bt.bt.verify_predicate.VerifyPredicate` (paper Alg. 2). After each of
the child's rounds it weighs every view of the check so far
(:func:`~vap_bt.perception.verification.verdict`): a settled round decides when no other view
said otherwise, and views that disagree need more settled rounds to be outvoted. A decided value
stands: SUCCESS if it matches the expectation; otherwise a *situation* is recorded on the context
and the decorator fails, which fails the plan's tree and hands control to the executive. While
nothing is decided, the decorator asks the VLM where to look from, moves there, and ticks the
child again — at most K moves. With the budget spent and nothing decided, a value stands only if
every view's answers agreed on it; otherwise the check does not overturn belief and is recorded as
*unsettled* (the paper returns the last vote here; one vote from a view the VLM judged insufficient
is too close to a guess to rewrite the scene graph).
An unsettled *goal* atom withholds the executive's claim of success; an unsettled effect lets the
plan go on (the next action's preconditions are checked before it acts); an unsettled
*precondition* first asks the body (``ctx.felt``: the gripper knows whether it holds
something), then follows the context's ``unseen`` policy — by default it is a situation of kind
``unseen``: the action does not run, the executive looks for what the check was about and
replans.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext, Phase, Situation, Verification
from vap_bt.bt.verify_predicate import VerifyPredicate
from vap_bt.domain.knowledge import GroundAction
from vap_bt.perception.verification import suggest_viewpoint, target_of, verdict


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
        v = verdict(self.rounds, exhausted=self.moves >= self.ctx.budget)
        if v is None:
            atom = self.verify.atom
            target = target_of(atom)
            r.direction = suggest_viewpoint(self.ctx.vlm, self.verify.observation, atom, r.questions[0], target)
            aim = self.ctx.aim(self.ctx.graph, (target, *atom.args))
            r.moved = self.ctx.camera.move_view(aim, r.direction) if r.direction else False
            self.moves += 1
            return Status.RUNNING
        if v.outcome == "unsettled":
            felt = self.ctx.felt(self.ctx.graph, self.verify.atom)
            if felt is not None:  # the camera could not tell; the gripper can
                return self._settle(felt, "felt" if felt == self.verify.expected else "contradicted")
            return self._settle(self.verify.expected, "unsettled")
        return self._settle(v.value, "confirmed" if v.value == self.verify.expected else "contradicted")

    def _settle(self, value: bool, outcome: str) -> Status:
        v = self.verify
        self.ctx.verifications.append(Verification(self.phase, str(self.action) if self.action else "goal",
                                                   v.atom, v.expected, value, outcome, list(self.rounds)))
        if self.phase == "goal" and outcome == "unsettled":
            self.ctx.unconfirmed_goal.append(v.atom)
        if outcome == "unsettled" and self.phase == "pre" and self.ctx.unseen != "go_on":
            self.ctx.situation = Situation("unseen", self.action, self.step, v.atom, v.expected, None,
                                           detail=f"could not see whether {v.atom} holds")
            self.ctx.progress(f"    situation: could not see {'' if v.expected else 'not '}{v.atom}")
            return Status.FAILURE
        if outcome != "contradicted":  # confirmed, felt, or unsettled where the plan may go on
            return Status.SUCCESS
        kind = {"pre": "precondition", "eff": "effect", "goal": "goal"}[self.phase]
        self.ctx.situation = Situation(kind, self.action, self.step, v.atom, v.expected, value)
        self.ctx.progress(f"    situation: {kind} {'' if v.expected else 'not '}{v.atom} observed {value}")
        return Status.FAILURE
