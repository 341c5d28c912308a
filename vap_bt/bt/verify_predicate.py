"""VerifyPredicate: one round of looking at an atom (paper Alg. 2, lines 2–7), never blocking.

A round is work in flight (:mod:`vap_bt.bt.inflight`): a frame captured where belief puts the
atom's objects, then the N paraphrased questions about that frame — sent as the verification
protocol says (one after another, or in waves all in flight at once) — their vote, and, when the
answers agree, the view-sufficiency question — unless the frame's detector did not find every
object the atom names (rooms and floors aside): a view that does not show a thing cannot settle
a question about it, so it is insufficient without asking; and, in a protocol that lets the
detector answer (lean), unless it shows every one of them whole, when it is sufficient — and
a view that does not show one is not asked about at all (its answers would vote nothing). Every
tick polls what is in flight and returns RUNNING until the round is done; ``terminate`` cancels what has not been sent. The behaviour
succeeds when the round settles on the expected value and fails otherwise; whether a failure
means "the world disagrees" or "could not tell from here" is in :attr:`round` for its
:class:`~vap_bt.bt.active_perception.ActivePerception` decorator to weigh.
"""

from __future__ import annotations

from concurrent.futures import Future

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.inflight import cancel_all
from vap_bt.domain.atoms import Atom
from vap_bt.perception.verification import Round, RoundAsker, shown_whole, sufficiency_query, unshown, yes_no
from vap_bt.perception.vlm import Answer
from vap_bt.robot.frame import Frame


class VerifyPredicate(py_trees.behaviour.Behaviour):
    """Ask about one atom of one fresh frame; SUCCESS when the round settles as expected."""

    def __init__(self, ctx: ExecutionContext, atom: Atom, expected: bool = True) -> None:
        super().__init__(name=f"{'' if expected else 'not '}{atom}")
        self.ctx, self.atom, self.expected = ctx, atom, expected
        self.round: Round | None = None
        self.observation: Frame | None = None
        self._frame: Future | None = None
        self._asker: RoundAsker | None = None
        self._answers: dict[int, Future] = {}
        self._sufficiency: Future | None = None
        self._voted: Round | None = None

    def initialise(self) -> None:
        self.round, self.observation, self._asker, self._voted = None, None, None, None
        self._answers, self._sufficiency = {}, None
        self._frame = self.ctx.submit(self.ctx.camera.capture, self.ctx.aim(self.ctx.graph, self.atom.args))
        self.feedback_message = "capturing"

    def update(self) -> Status:
        if self._frame is not None:
            if not self._frame.done():
                return Status.RUNNING
            self.observation, self._frame = self._frame.result(), None
            self._asker = RoundAsker(self.atom, self.observation, self.ctx.vote, self.ctx.profile, self.ctx.protocol)
            missing = unshown(self.observation, self.atom, self.ctx.undetectable)
            if missing and self.ctx.protocol.detector:
                # answers about a view that does not show the thing vote nothing: lean asks none
                r, self._asker = self._asker.finish(), None
                r.unshown, r.sufficient, r.sufficient_by = missing, False, "detector"
                return self._finish(r)
        if self._asker is not None:
            return self._ask()
        if self._sufficiency is not None:
            if not self._sufficiency.done():
                return Status.RUNNING
            self._voted.sufficient, self._voted.sufficient_by = yes_no(_answer(self._sufficiency)), "model"
            self._sufficiency = None
            return self._finish(self._voted)
        return Status.FAILURE if self.round is None else self._status(self.round)

    def _ask(self) -> Status:
        asker = self._asker
        for i, f in list(self._answers.items()):
            if f.done():
                asker.give(i, _answer(f))
                del self._answers[i]
        for i in asker.to_ask():
            self._answers[i] = self.ctx.submit(self.ctx.vlm.ask, asker.queries[i], self.observation)
        if not asker.done:
            self.feedback_message = f"asking {len(self._answers)} in flight, {len(asker.answers)} answered"
            return Status.RUNNING
        cancel_all(self._answers.values())  # early stop: what is left would not change the vote
        self._answers, self._asker = {}, None
        r = asker.finish()
        r.unshown = unshown(self.observation, self.atom, self.ctx.undetectable)
        if r.unshown:  # the detector did not find what the atom is about: not a view of it
            r.sufficient, r.sufficient_by = False, "detector"
            return self._finish(r)
        if r.consistent and r.vote is not None:
            protocol = self.ctx.protocol
            if protocol.detector and shown_whole(self.observation, self.atom, self.ctx.undetectable, protocol.whole_share):
                r.sufficient, r.sufficient_by = True, "detector"  # everything asked about is in view, whole
                return self._finish(r)
            self._voted = r
            self._sufficiency = self.ctx.submit(self.ctx.vlm.ask, sufficiency_query(self.atom, r.questions[0]),
                                                self.observation)
            self.feedback_message = f"vote={r.vote}: is the view sufficient?"
            return Status.RUNNING
        return self._finish(r)

    def _finish(self, r: Round) -> Status:
        self.round = r
        self.feedback_message = f"vote={r.vote} consistent={r.consistent} sufficient={r.sufficient}"
        return self._status(r)

    def _status(self, r: Round) -> Status:
        return Status.SUCCESS if r.settled and r.vote == self.expected else Status.FAILURE

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:  # halted mid-round: nothing more is sent
            cancel_all([self._frame, self._sufficiency, *self._answers.values()])
            self._frame, self._sufficiency, self._answers, self._asker = None, None, {}, None


def _answer(f: Future) -> Answer:
    """A future's answer; a backend that raised (none should) is no answer, never a crash."""
    try:
        return f.result()
    except Exception as exc:  # noqa: BLE001 - the contract is an abstention
        return Answer(f"error: {type(exc).__name__}: {exc}", None)
