"""VerifyPredicate: one round of looking at an atom (paper Alg. 2, lines 2–7).

Each tick it takes a fresh frame aimed where belief puts the atom's objects, asks the N paraphrases,
votes, and — when the answers agree — asks whether the view was sufficient. It succeeds when the
round settles on the expected value and fails otherwise; whether a failure means "the world
disagrees" or "could not tell from here" is left in :attr:`round` for its
:class:`~vap_bt.bt.active_perception.ActivePerception` decorator to act on.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.domain.atoms import Atom
from vap_bt.perception.verification import Round, check_sufficiency, vote_round
from vap_bt.robot.frame import Frame


class VerifyPredicate(py_trees.behaviour.Behaviour):
    def __init__(self, ctx: ExecutionContext, atom: Atom, expected: bool = True) -> None:
        super().__init__(name=f"{'' if expected else 'not '}{atom}")
        self.ctx, self.atom, self.expected = ctx, atom, expected
        self.round: Round | None = None
        self.observation: Frame | None = None

    def initialise(self) -> None:
        self.round, self.observation = None, None

    def update(self) -> Status:
        obs = self.observation = self.ctx.camera.capture(self.ctx.aim(self.ctx.graph, self.atom.args))
        r = vote_round(self.ctx.vlm, obs, self.atom, self.ctx.vote, self.ctx.profile)
        if r.consistent and r.vote is not None:
            r.sufficient = check_sufficiency(self.ctx.vlm, obs, self.atom, r.questions[0])
        self.round = r
        self.feedback_message = f"vote={r.vote} consistent={r.consistent} sufficient={r.sufficient}"
        return Status.SUCCESS if r.settled and r.vote == self.expected else Status.FAILURE
