"""VerifyPredicate: one round of looking at an atom (paper Alg. 2, lines 2–7), never blocking.

A round is work in flight (:mod:`vap_bt.bt.inflight`): a frame captured where belief puts the
atom's objects, then the N paraphrased questions about that frame — sent as the verification
protocol says (one after another, or in waves all in flight at once) — their vote, and, when the
answers agree, the view-sufficiency question (none in a protocol that never asks it: the view is
then taken as sufficient) — unless the frame's detector did not find every
object the atom names (rooms and floors aside): a view that does not show a thing cannot settle
a question about it, so it is insufficient without asking. In a protocol that lets the detector
answer (lean), a view that shows every one of them plainly (whole, or large) is sufficient
without asking, a view that does not show one is not asked about at all (its answers would vote
nothing), and otherwise the sufficiency question goes out with the first wave of questions.
Every tick polls what is in flight and returns RUNNING until the round is done; ``terminate``
cancels what has not been sent. The behaviour succeeds when the round settles on the expected
value and fails otherwise; whether a failure means "the world disagrees" or "could not tell from
here" is in :attr:`round` for its :class:`~vap_bt.bt.active_perception.ActivePerception`
decorator to weigh, with the frame it was asked of (:attr:`look`). It reads and writes nothing
of the board: what a check concludes is its decorator's to record.
"""

from __future__ import annotations

from concurrent.futures import Future
from dataclasses import dataclass, field
from typing import ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.inflight import cancel_all
from vap_bt.domain.atoms import Atom
from vap_bt.errors import TransportError
from vap_bt.perception.judgement import Look
from vap_bt.perception.verification import (Round, RoundAsker, located, shown_plainly, sufficiency_query, unshown,
                                           yes_no)
from vap_bt.perception.vlm import Answer
from vap_bt.robot.frame import Frame


@dataclass(frozen=True)
class RoundProgress:
    """Where a round in flight stands, for whoever watches: its stage and the answers so far."""

    stage: str  # idle | capturing | asking | judging the view | done
    questions: tuple[str, ...] = ()
    #: answers in by question index (None: the model abstained); a question not in it is pending
    answers: dict[int, bool | None] = field(default_factory=dict)


class VerifyPredicate(py_trees.behaviour.Behaviour):
    """Ask about one atom of one fresh frame; SUCCESS when the round settles as expected."""

    KEYS: ClassVar[dict[str, Access]] = {}

    def __init__(self, ctx: ExecutionContext, atom: Atom, expected: bool = True) -> None:
        super().__init__(name=f"{'' if expected else 'not '}{atom}")
        self.ctx, self.atom, self.expected = ctx, atom, expected
        self.board = ctx.board.client(type(self).__name__, self.KEYS)
        self.round: Round | None = None
        self.observation: Frame | None = None
        self._frame: Future | None = None
        self._asker: RoundAsker | None = None
        self._answers: dict[int, Future] = {}
        self._sufficiency: Future | None = None
        self._voted: Round | None = None
        self._plain = False  # the detector shows everything the atom names plainly (lean)

    def initialise(self) -> None:
        self.round, self.observation, self._asker, self._voted = None, None, None, None
        self._answers, self._sufficiency, self._plain = {}, None, False
        self._frame = self.ctx.submit(self.ctx.camera.capture, self.ctx.aim(self.ctx.graph, self.atom.args))
        self.feedback_message = "capturing"

    @property
    def look(self) -> Look | None:
        """What the last run saw: its round and the frame it asked about (None until it is done)."""
        return None if self.round is None else Look(self.round, self.observation)

    def progress(self) -> RoundProgress:
        """The round so far (read by the live view between ticks; changes nothing)."""
        if self.round is not None:
            return RoundProgress("done", tuple(self.round.questions), dict(enumerate(self.round.answers)))
        if self._frame is not None:
            return RoundProgress("capturing")
        if self._asker is not None:
            return RoundProgress("asking", tuple(self._asker.questions), dict(self._asker.answers))
        if self._voted is not None:
            return RoundProgress("judging the view", tuple(self._voted.questions), dict(enumerate(self._voted.answers)))
        return RoundProgress("idle")

    def update(self) -> Status:
        if self._frame is not None:
            if not self._frame.done():
                return Status.RUNNING
            self.observation, self._frame = self._frame.result(), None
            return self._start()
        if self._asker is not None:
            return self._ask()
        if self._sufficiency is not None and self._voted is not None:
            if not self._sufficiency.done():
                return Status.RUNNING
            self._voted.sufficient, self._voted.sufficient_by = yes_no(answer_of(self._sufficiency)), "model"
            self._sufficiency = None
            return self._finish(self._voted)
        return Status.FAILURE if self.round is None else self._status(self.round)

    def _start(self) -> Status:
        """The frame is in: start the round (or, in a protocol that lets the detector answer,
        end it at once when the frame does not show what the atom is about)."""
        protocol = self.ctx.protocol
        self._asker = RoundAsker(self.atom, self.observation, self.ctx.vote, self.ctx.profile, protocol, self.expected)
        if protocol.detector:
            if unshown(self.observation, self.atom, self.ctx.undetectable):
                # answers about a view that does not show the thing vote nothing: lean asks none
                r, self._asker = self._asker.finish(), None
                return self._judged_by_detector(r)
            self._plain = shown_plainly(self.observation, self.atom, self.ctx.undetectable,
                                        protocol.whole_share, protocol.large_share)
        if protocol.concurrent and protocol.sufficiency and not self._plain:  # it rides the first wave
            self._ask_sufficiency(self._asker.questions[0])
        return self._ask()

    def _ask_sufficiency(self, question: str) -> None:
        self._sufficiency = self.ctx.submit(self.ctx.vlm.ask, sufficiency_query(self.atom, question), self.observation)

    def _ask(self) -> Status:
        asker = self._asker
        for i, f in list(self._answers.items()):
            if f.done():
                asker.give(i, answer_of(f))
                del self._answers[i]
        for i in asker.to_ask():
            self._answers[i] = self.ctx.submit(self.ctx.vlm.ask, asker.queries[i], self.observation)
        if not asker.done:
            self.feedback_message = f"asking {len(self._answers)} in flight, {len(asker.answers)} answered"
            return Status.RUNNING
        cancel_all(self._answers.values())  # early stop: what is left would not change the vote
        self._answers, self._asker = {}, None
        r = asker.finish()
        if unshown(self.observation, self.atom, self.ctx.undetectable):
            return self._judged_by_detector(r)  # the detector did not find what the atom is about
        if not (r.consistent and r.vote is not None):
            cancel_all([self._sufficiency])  # nothing to judge a view by: the answers disagree
            self._sufficiency = None
            return self._finish(r)
        if self._plain:  # everything asked about is plainly in view
            r.sufficient, r.sufficient_by = True, "detector"
            return self._finish(r)
        if not self.ctx.protocol.sufficiency:  # a protocol that never asks takes every view as good enough
            r.sufficient, r.sufficient_by = True, "assumed"
            return self._finish(r)
        self._voted = r
        if self._sufficiency is None:
            self._ask_sufficiency(r.questions[0])
        self.feedback_message = f"vote={r.vote}: is the view sufficient?"
        return self.update()

    def _judged_by_detector(self, r: Round) -> Status:
        """The frame's detector did not find every object the atom names: an insufficient view."""
        cancel_all([self._sufficiency])
        self._sufficiency = None
        r.unshown = unshown(self.observation, self.atom, self.ctx.undetectable)
        r.sufficient, r.sufficient_by = False, "detector"
        return self._finish(r)

    def _finish(self, r: Round) -> Status:
        r.located = located(self.observation, self.atom, self.ctx.undetectable, self.ctx.roles)
        self.round = r
        self.feedback_message = f"vote={r.vote} consistent={r.consistent} sufficient={r.sufficient}"
        return self._status(r)

    def _status(self, r: Round) -> Status:
        return Status.SUCCESS if r.settled and r.vote == self.expected else Status.FAILURE

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:  # halted mid-round: nothing more is sent
            cancel_all([self._frame, self._sufficiency, *self._answers.values()])
            self._frame, self._sufficiency, self._answers, self._asker = None, None, {}, None


def answer_of(f: Future) -> Answer:
    """A future's answer; a backend that raised (none should) is no answer, never a crash —
    except a TransportError: the VLM's server stopped answering (``StopWhenSilent``), and the
    episode ends "transport down" as when any part goes away, not on abstentions for ever."""
    try:
        return f.result()
    except TransportError:
        raise
    except Exception as exc:  # noqa: BLE001 - the contract is an abstention
        return Answer(f"error: {type(exc).__name__}: {exc}", None)
