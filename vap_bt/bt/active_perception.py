"""ActivePerception: the retry decorator that moves the camera until a verification settles.

It wraps a check — a child that says what it checks (:class:`Check`: an atom and the value the
plan expects) and, each time it runs, produces one typed :class:`~vap_bt.perception.judgement.Look`
(a round of questions and the frame it asked them of; today a
:class:`~vap_bt.bt.verify_predicate.VerifyPredicate`) — and reads nothing of it but its status
and that look (paper Alg. 2). The rules live in :mod:`vap_bt.perception`, each tested on its own:
the views' verdict (:func:`~vap_bt.perception.judgement.judge`, over
:func:`~vap_bt.perception.verification.verdict`), where to look next within the budget
(:class:`~vap_bt.perception.viewpoints.ViewpointSearch`) and the body's word
(:func:`~vap_bt.perception.judgement.conclude`); this decorator runs them as work in flight and
maps what they say to a status. After each round it weighs every view of the check so far: a
settled round decides when no other view said otherwise, and views that disagree need more
settled rounds to be outvoted. A decided value
stands: SUCCESS if it matches the expectation; otherwise a *situation* is written to the board
and the decorator fails, which fails the plan's tree and hands control to the executive.

While nothing is decided the decorator moves the camera — at most K times — and runs the child
again: the viewpoint strategy (:mod:`vap_bt.perception.viewpoints`) gives the direction (the
VLM's suggestion about the last frame, or the next of the greedy round; ``greedy-all`` visits
every viewpoint of its round before its views are weighed together), and the move is work in
flight like any other; the child is not ticked meanwhile. A direction the robot cannot move to
is replaced at once by another (a frame from the same spot would show the same picture), and
a goal check whose frame did not show what its atom is about first goes to a view of where
belief puts it (``ctx.approach``: the plan is through, and the robot may stand in another room),
and when no direction is left, or the check is about the hand or what it holds (the wrist camera
moves with the hand: no base move shows it better), the views so far are all there are. Beyond
the paper (``ctx.second_look``, on by default) a surprise and a goal value need a second view
from a new picture, and a goal value odds that reach the claim's bound, while the budget allows
a move (:mod:`vap_bt.perception.judgement`); with the budget spent and nothing decided, a value
stands only if at least two views that showed the atom's objects voted for it and none against
(:func:`~vap_bt.perception.verification.verdict`), otherwise the check is *unsettled* (the paper
returns the last vote here; one vote from a view the VLM judged insufficient is too close to a
guess to rewrite the scene graph).

An unsettled *goal* atom withholds the executive's claim of success (the executive goes to look at
it and checks the goal again: :func:`~vap_bt.bt.executive.unconfirmed_goal`); an unsettled effect lets the
plan go on (the next action's preconditions are checked before it acts); an unsettled
*precondition* first asks the body (``ctx.felt``, in flight on a worker: the gripper knows
whether it holds something; where it is sure it also overrules a camera that settled otherwise),
then follows the context's ``unseen`` policy — by default it is a situation of kind
``unseen``: the action does not run, the executive looks for what the check was about and
replans. Under the lean protocol an atom verified earlier, that no action since could have
changed, is not asked again (the board's ``verified``) — mid-plan only: the goal's check, on which
success is claimed, looks under every protocol (an earlier check's views of the atom count
beside its own, never instead of them). A reused value is recorded as ``reused``, apart from
what was looked at or felt, and is never scored as verified
(:func:`vap_bt.report.verification_counts`).
"""

from __future__ import annotations

from concurrent.futures import Future
from typing import ClassVar, Protocol

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.inflight import cancel_all, in_flight
from vap_bt.bt.record import Situation, Verification
from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.errors import TransportError
from vap_bt.perception import judgement
from vap_bt.perception.judgement import Look, Phase, Settlement, Subject
from vap_bt.perception.verification import Round, Verdict, choice, distinct, target_of, votes
from vap_bt.perception.viewpoints import ViewpointSearch


#: the direction a round records when the check went to a view of where belief puts its objects
APPROACH = "to its place"


class Check(Protocol):
    """What ActivePerception decorates: a behaviour that checks ``atom`` against ``expected`` and
    leaves what its last run saw in ``look`` (None until a run is done)."""

    atom: Atom
    expected: bool
    look: Look | None
    status: Status


class ActivePerception(py_trees.decorators.Decorator):
    """Look again, from elsewhere, until a check's views decide (budget K)."""

    KEYS: ClassVar[dict[str, Access]] = {
        "verifications": Access.WRITE, "situation": Access.WRITE, "unconfirmed_goal": Access.WRITE,
        "verified": Access.WRITE, "doubted": Access.WRITE, "on_belief": Access.READ, "on_trial": Access.READ,
        "sightings": Access.WRITE}

    def __init__(self, ctx: ExecutionContext, child: py_trees.behaviour.Behaviour, phase: Phase,
                 action: GroundAction | None, step: int) -> None:
        super().__init__(name=f"look(K={ctx.budget})", child=child)
        self.ctx, self.phase, self.action, self.step = ctx, phase, action, step
        self.board = ctx.board.client(type(self).__name__, self.KEYS)
        self.verify: Check = child
        self.subject = Subject(child.atom, child.expected, phase)
        self.rules = ctx.rules
        self.rounds: list[Round] = []
        self.search = ViewpointSearch(ctx.viewpoints, ctx.budget)
        self._job: Future | None = None  # the viewpoint answer, the move or the gripper's word, in flight
        self._stage = "look"  # look | choose | move | feel
        self._verdict: Verdict | None = None  # the views' verdict while the gripper is asked
        self._look: Look | None = None  # the child's last look (its frame is asked where to look next)
        self._reused: bool | None = None  # an earlier check's value this one stands on (lean)
        #: whether the first view decided the check (None: not judged yet, or a check of the hand,
        #: which no move shows better): the H2 measure's "uncertain" checks are those it did not
        self._first_settled: bool | None = None
        self._approached = False  # whether this check went to a view of where belief puts its objects

    @property
    def atom(self) -> Atom:
        """The atom the wrapped check is about."""
        return self.subject.atom

    @property
    def moves(self) -> int:
        """The viewpoint moves made so far in this check (at most the budget K)."""
        return self.search.moves

    @property
    def stage(self) -> str:
        """What the check is doing: ``look`` (its child runs), ``choose`` (asking where to look
        next), ``move`` (going there) or ``feel`` (asking the gripper)."""
        return self._stage

    def initialise(self) -> None:
        self.rounds, self._job, self._stage, self._look, self._first_settled = [], None, "look", None, None
        self._approached = False
        self.search = ViewpointSearch(self.ctx.viewpoints, self.ctx.budget)
        # lean: verified before, and nothing since could have changed it. Never the goal's check:
        # success is claimed on it, so it looks (an earlier value is evidence only beside its own views)
        self._reused = None if self.phase == "goal" else self.board.verified.get(self.atom)

    def tick(self):
        """py_trees' decorator tick, but the child runs only while the check looks: while a
        viewpoint is chosen or reached, or the gripper asked, it stays as its last run left it."""
        if self.status != Status.RUNNING:
            self.initialise()
        if self._stage == "look" and self._reused is None:
            yield from self.decorated.tick()
        new = self.update()
        if new != Status.RUNNING:
            self.stop(new)
        self.status = new
        yield self

    def update(self) -> Status:
        if self._reused is not None:
            return self._settle(judgement.reused(self._reused))
        if self._stage == "look":
            if self.verify.status == Status.RUNNING:
                return Status.RUNNING
            return self._weigh()
        if in_flight(self._job):
            return Status.RUNNING
        return {"choose": self._chosen, "move": self._moved, "feel": self._body_answered}[self._stage]()

    def _weigh(self) -> Status:
        look = self.verify.look
        if look is None:  # the child did not run (interrupted)
            return Status.FAILURE
        self._look = look
        self.rounds.append(look.round)
        return self._decide(exhausted=self.search.spent or self._in_hand())

    def _in_hand(self) -> bool:
        """Whether the check is about the hand or what belief has in it: the wrist camera moves
        with the hand, so no move of the base shows it better (the gripper's feel decides what
        the first view could not). Another domain's 0-ary atoms (movie's ``have-chips``) are about
        the scene, which a move does show anew."""
        if not self.atom.args:
            return self.atom.predicate in self.ctx.roles.hand
        return self.ctx.roles.holding(self.atom.args[0]) in self.ctx.graph.facts

    def _evidence(self) -> list[Round]:
        return judgement.evidence(self.subject, self.rounds, self.board.verified.views(self.atom),
                                  self.ctx.roles.supports(self.atom))

    def _decide(self, exhausted: bool) -> Status:
        # greedy-all, once the first view did not decide, weighs the views only when it has them all
        pooling = self.search.pools and len(self.rounds) > 1 and not exhausted
        v = None if pooling else judgement.judge(self.subject, self._evidence(), self.rules, exhausted,
                                                 self.atom in self.board.doubted)
        if len(self.rounds) == 1 and self._first_settled is None and not self._in_hand():
            self._first_settled = v is not None and v.outcome != "unsettled"
        if v is None and self._out_of_sight():  # first to where belief puts what the frame did not show
            return self._approach()
        if v is None:  # look again: where, the strategy says (or the model, asked about the last frame)
            nxt = self.search.next(self.atom, self.rounds[-1], self.ctx.profile)
            if nxt is None or isinstance(nxt, str):
                return self._move(nxt)
            return self._start("choose", self.ctx.submit(self.ctx.vlm.ask, nxt, self._look.frame))
        if self.ctx.feels(self.atom):  # the gripper may overrule: ask it, and wait without blocking
            self._verdict = v
            return self._start("feel", self.ctx.ask_body(self.ctx.felt, self.ctx.graph, self.atom))
        return self._settle(judgement.conclude(self.subject, v, None))

    def _out_of_sight(self) -> bool:
        """Whether a goal check's last frame showed neither what its atom is about nor the place
        belief puts it at, and the check has not gone to look at it yet. The plan is through, and
        the robot may stand anywhere — in another room after a search, where every move round the
        target is refused at a doorway (retrieve_bottles seed 4: a bottle on the counter checked
        from the garden, three times "could not see"): a move relative to that stand shows the
        target no better, a view of where belief puts it does. Where the frame shows the place
        (a cutting board, and no egg on it: a detector's miss of a small thing), the robot is
        where it should look from, and the moves round the target stay (a floor, which no detector
        finds, tells nothing). Mid-plan the robot stands where the plan's actions brought it,
        which the next action presumes: the checks there keep to moves round the target."""
        if self.phase != "goal" or self._approached or not self.rounds[-1].unshown or self.search.spent:
            return False
        place = self.ctx.aim(self.ctx.graph, self.atom.args).place
        return place is None or place in self.ctx.undetectable or place not in self._look.frame.detected()

    def _approach(self) -> Status:
        """Go to a view of where belief puts the atom's objects (one move of the budget)."""
        self._approached = True
        self.rounds[-1].direction = APPROACH
        return self._start("move", self.ctx.submit(self.ctx.approach, self.ctx.graph, self.atom.args))

    def _start(self, stage: str, job: Future) -> Status:
        self._stage, self._job = stage, job
        return Status.RUNNING

    def _body_answered(self) -> Status:
        try:
            felt = self._job.result()
        except TransportError:  # the robot's state service is gone: the episode ends
            raise
        except Exception:  # noqa: BLE001 - no word from the body: the camera's verdict stands
            felt = None
        self._job = None
        return self._settle(judgement.conclude(self.subject, self._verdict, felt))

    def _chosen(self) -> Status:
        try:
            direction = choice(self._job.result())
        except TransportError:  # the VLM's server is gone: the episode ends (verify_predicate.answer_of)
            raise
        except Exception:  # noqa: BLE001 - no answer: another way is taken (see _move)
            direction = None
        return self._move(direction)

    def _move(self, direction: str | None) -> Status:
        r = self.rounds[-1]
        direction = self.search.pick(direction)
        if direction is None:  # no way to a new view from here: what the views said is all there is
            r.moved = False
            return self._decide(exhausted=True)
        r.direction = direction
        aim = self.ctx.aim(self.ctx.graph, (target_of(self.atom), *self.atom.args))
        return self._start("move", self.ctx.submit(self.ctx.camera.move_view, aim, direction))

    def _moved(self) -> Status:
        r = self.rounds[-1]
        try:
            r.moved = bool(self._job.result())
        except Exception:  # noqa: BLE001 - a move that failed outright is a move not made
            r.moved = False
        self._job = None
        if not r.moved:  # the same spot would show the same picture: try another way at once
            self.search.refuse(r.direction)
            r.refused += (r.direction,)
            return self._move(None)
        self.search.moved()
        self._stage = "look"
        return Status.RUNNING  # the child runs again next tick, from the new view

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:
            cancel_all([self._job])
            self._job, self._stage = None, "look"

    def _settle(self, s: Settlement) -> Status:
        """Record the check and map its settlement to a status: a situation (FAILURE) where the
        plan must not go on, SUCCESS otherwise."""
        atom, expected, board = self.atom, self.subject.expected, self.board
        board.verified.saw(atom, self.rounds)
        v = Verification(self.phase, str(self.action) if self.action else "goal", atom, expected, s.value,
                         s.outcome, list(self.rounds), s.basis, self.search.moves, self._first_settled)
        board.verifications.append(v)
        self.ctx.record(v)
        if s.outcome != "unsettled":
            board.doubted.discard(atom)
        if s.outcome in ("confirmed", "contradicted", "felt"):
            board.verified.remember(atom, s.value)
            board.verified.settle(atom, s.value, self.rounds)
        if self.phase == "goal" and s.outcome == "unsettled":
            board.unconfirmed_goal.append(atom)
        if s.outcome == "unsettled" and self.phase == "pre" and self.ctx.unseen != "go_on" \
                and atom not in board.on_belief:
            board.situation = Situation("unseen", self.action, self.step, atom, expected, None,
                                        detail=f"could not see whether {atom} holds")
            self.ctx.progress(f"    situation: could not see {'' if expected else 'not '}{atom}")
            return Status.FAILURE
        # what a sense showed and belief takes in (a contradiction that raises a situation is taken
        # in, and so seen, when the executive corrects belief: its diagnosis reads what came before)
        if s.outcome in ("confirmed", "felt"):
            board.sightings.saw((atom,), s.value, _sense(s))
        if s.outcome != "contradicted":  # confirmed, felt, reused, or unsettled where the plan may go on
            return Status.SUCCESS
        if self.phase == "pre" and atom in board.on_trial:
            board.sightings.saw((atom,), s.value, _sense(s))
            self.ctx.progress(f"    {atom} observed {s.value} again: trying {self.action} against it")
            return Status.SUCCESS
        kind = {"pre": "precondition", "eff": "effect", "goal": "goal"}[self.phase]
        board.situation = Situation(kind, self.action, self.step, atom, expected, s.value,
                                    split=expected in votes(distinct(self.rounds)))
        self.ctx.progress(f"    situation: {kind} {'' if expected else 'not '}{atom} observed {s.value}")
        return Status.FAILURE


def _sense(s: Settlement) -> str:
    """Which sense settled a check: the gripper (proprioception), or the camera's views."""
    return "gripper" if s.basis == "proprioception" else "check"
