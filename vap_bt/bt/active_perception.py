"""ActivePerception: the retry decorator that moves the camera until a verification settles.

It wraps a check — a child that, each time it runs, produces one typed :class:`Round` (today a
:class:`~vap_bt.bt.verify_predicate.VerifyPredicate`) — and reads nothing of it but its status
and that round (paper Alg. 2). After each round it weighs every view of the check so far
(:func:`~vap_bt.perception.verification.verdict`): a settled round decides when no other view
said otherwise, and views that disagree need more settled rounds to be outvoted. A decided value
stands: SUCCESS if it matches the expectation; otherwise a *situation* is recorded on the context
and the decorator fails, which fails the plan's tree and hands control to the executive.

While nothing is decided the decorator moves the camera — at most K times — and runs the child
again: the viewpoint strategy (:mod:`vap_bt.perception.viewpoints`) gives the direction (the
VLM's suggestion about the last frame, or the next of the greedy round), and the move is work in
flight like any other; the child is not ticked meanwhile. A direction the robot cannot move to
is replaced at once by another (a frame from the same spot would show the same picture), and
when no direction is left, or the check is about the hand or what it holds (the wrist camera
moves with the hand: no base move shows it better), the views so far are all there are. Beyond
the paper (``ctx.second_look``, on by default): a *surprise* — a value against the plan's
expectation — and a *goal* value need a second view from a different picture that agrees (its
answers consistent, sufficient or not) while the budget allows a move, since a model's errors
are shared by every question about one picture; for a goal atom found as the goal wants it the
views' log odds, each view weighed by the backend's measured calibration (and, for where a thing
rests, by what the frame's detector reported of it), must also reach the claim's bound
(:mod:`vap_bt.perception.evidence`: a sequential probability-ratio test whose chance of claiming
an atom that does not hold is about ``ctx.claim_risk``, 5 %). A goal atom that the budget leaves
short of it is unsettled (success is not claimed on it). With
the budget spent and nothing decided, a value stands only if at least two views that showed the
atom's objects voted for it and none against (a view whose paraphrases disagreed votes neither
way: :func:`~vap_bt.perception.verification.verdict`); otherwise the check is *unsettled* (the paper
returns the last vote here; one vote from a view the VLM judged insufficient is too close to a
guess to rewrite the scene graph).

An unsettled *goal* atom withholds the executive's claim of success (the executive goes to look at
it and checks the goal again: :func:`~vap_bt.bt.executive.unconfirmed_goal`); an unsettled effect lets the
plan go on (the next action's preconditions are checked before it acts); an unsettled
*precondition* first asks the body (``ctx.felt``: the gripper knows whether it holds
something; where it is sure — the hand empty or not, an empty hand holding nothing — it also
overrules a camera that settled otherwise), then follows the context's ``unseen`` policy — by default it is a situation of kind
``unseen``: the action does not run, the executive looks for what the check was about and
replans. Under the lean protocol an atom verified earlier, that no action since could have
changed, is not asked again (``ctx.verified``) — mid-plan only: the goal's check, on which
success is claimed, looks under every protocol (an earlier check's views of the atom count
beside its own, never instead of them). A reused value is recorded as ``reused``, apart from
what was looked at or felt, and is never scored as verified
(:func:`vap_bt.report.verification_counts`).
"""

from __future__ import annotations

from concurrent.futures import Future

import py_trees
from py_trees.common import Status

from vap_bt.bt.context import BASIS, Basis, ExecutionContext, Outcome, Phase, Situation, Verification
from vap_bt.bt.inflight import cancel_all
from vap_bt.domain.knowledge import GroundAction
from vap_bt.errors import TransportError
from vap_bt.perception.evidence import claim_threshold
from vap_bt.perception.verification import Round, Verdict, choice, distinct, target_of, verdict, votes


class ActivePerception(py_trees.decorators.Decorator):
    """Look again, from elsewhere, until a check's views decide (budget K)."""

    def __init__(self, ctx: ExecutionContext, child: py_trees.behaviour.Behaviour, phase: Phase,
                 action: GroundAction | None, step: int) -> None:
        super().__init__(name=f"look(K={ctx.budget})", child=child)
        self.ctx, self.phase, self.action, self.step = ctx, phase, action, step
        self.verify = child
        self.rounds: list[Round] = []
        self.moves = 0
        self._job: Future | None = None  # the viewpoint answer, the move or the gripper's word, in flight
        self._stage = "look"  # look | choose | move | feel
        self._verdict: Verdict | None = None  # the views' verdict while the gripper is asked

    @property
    def atom(self):
        return self.verify.atom

    @property
    def stage(self) -> str:
        """What the check is doing: ``look`` (its child runs), ``choose`` (asking where to look
        next), ``move`` (going there) or ``feel`` (asking the gripper)."""
        return self._stage

    def initialise(self) -> None:
        self.rounds, self.moves, self._job, self._stage = [], 0, None, "look"
        self._refused: set[str] = set()  # directions this check could not move to
        self._tried: set[str] = set()  # directions this check moved to or was refused

    def tick(self):
        if self.status != Status.RUNNING:
            self.initialise()
            # lean: verified before, and nothing since could have changed it. Never the goal's check:
            # success is claimed on it, so it looks (an earlier value is evidence only beside its own views)
            reused = None if self.phase == "goal" else self.ctx.verified.get(self.atom)
            if reused is not None:
                self._end_tick(self._settle(reused, "reused"))
                yield self
                return
        if self._stage == "look":  # while a viewpoint is chosen or reached, the check waits
            yield from self.decorated.tick()
        self._end_tick(self.update())
        yield self

    def _end_tick(self, new: Status) -> None:
        if new != Status.RUNNING:
            self.stop(new)
        self.status = new

    def update(self) -> Status:
        if self._stage == "look":
            if self.verify.status == Status.RUNNING:
                return Status.RUNNING
            return self._weigh()
        if self._stage == "choose":
            return self._chosen()
        if self._stage == "feel":
            return self._body_answered()
        return self._moved()

    def _weigh(self) -> Status:
        r = self.verify.round
        if r is None:  # the child did not run (interrupted)
            return Status.FAILURE
        self.rounds.append(r)
        return self._decide(exhausted=self.moves >= self.ctx.budget or self._in_hand())

    def _in_hand(self) -> bool:
        """Whether the check is about the hand or what belief has in it: the wrist camera moves
        with the hand, so no move of the base shows it better (the gripper's feel decides what
        the first view could not). Another domain's 0-ary atoms (movie's ``have-chips``) are about
        the scene, which a move does show anew."""
        roles = self.ctx.roles
        if not self.atom.args:
            return self.atom.predicate in roles.hand
        return roles.holding(self.atom.args[0]) in self.ctx.graph.facts

    def _decide(self, exhausted: bool) -> Status:
        v = verdict(self._evidence(), exhausted)
        if v is not None and v.outcome != "unsettled" and self._look_twice(v.value):
            if not exhausted:
                v = None  # one picture is one draw of the model's errors: another view before believing it
            elif self.phase == "goal" and v.value == self.verify.expected:
                v = Verdict(v.value, "unsettled")  # success is never claimed on views short of the bound
        if v is None:
            r = self.rounds[-1]
            question = r.questions[0] if r.questions else self.ctx.profile.questions(self.atom, 1)[0]
            nxt = self.ctx.viewpoints.next(self.moves, self.atom, question, target_of(self.atom))
            if isinstance(nxt, str):
                return self._move(nxt)
            self._job, self._stage = self.ctx.submit(self.ctx.vlm.ask, nxt, self.verify.observation), "choose"
            return Status.RUNNING
        if self.ctx.feels(self.atom):  # the gripper may overrule: ask it, and wait without blocking
            self._verdict = v
            self._job, self._stage = self.ctx.submit(self.ctx.felt, self.ctx.graph, self.atom), "feel"
            return self._body_answered()  # done at once in process: no tick spent waiting
        return self._conclude(v, None)

    def _body_answered(self) -> Status:
        if not self._job.done():
            return Status.RUNNING
        try:
            felt = self._job.result()
        except TransportError:  # the robot's state service is gone: the episode ends
            raise
        except Exception:  # noqa: BLE001 - no word from the body: the camera's verdict stands
            felt = None
        self._job = None
        return self._conclude(self._verdict, felt)

    def _conclude(self, v: Verdict, felt: bool | None) -> Status:
        """The check's outcome from the views' verdict and the body's word (None: it has none)."""
        if v.outcome == "unsettled":
            if felt is not None:  # the camera could not tell; the gripper can
                return self._feel(felt)
            return self._settle(self.verify.expected, "unsettled")
        if felt is not None and felt != v.value and (felt is False or not self.atom.args):
            # the gripper is surer than a camera where it can be: fingers that closed on nothing
            # hold nothing, and whether the hand is empty at all is theirs to say
            return self._feel(felt)
        return self._settle(v.value, "confirmed" if v.value == self.verify.expected else "contradicted")

    def _look_twice(self, value: bool) -> bool:
        """Whether a value one view gave needs a second view from a new picture first: a surprise
        (it would correct belief and make the robot replan) or a goal (success would be claimed on
        it), when the context asks for second looks. A model's errors belong to the picture — its
        five paraphrases can agree and be wrong — so only another view is a second opinion
        (docs/perception.md): one more view that showed the atom's objects and whose answers
        agreed on the same value, sufficient or not — and for a goal atom found as the goal
        wants it, on which success will be claimed, that and views whose log odds reach the
        claim's bound (:mod:`vap_bt.perception.evidence`: every view weighed by the backend's
        calibration, views against included, so that a model weak on a relation must show it
        more often; the chance of claiming an atom that does not hold stays about
        ``ctx.claim_risk``). An atom in doubt
        (``ctx.doubted``: a precondition of an action that failed when it last ran) is treated as
        a surprise even when confirmed: the failure is evidence against it (an oven the survey
        took for open, into which no arm pose reaches)."""
        doubted = self.atom in self.ctx.doubted
        if not self.ctx.second_look or (value == self.verify.expected and self.phase != "goal" and not doubted):
            return False
        rounds = distinct(self._evidence())
        voted = votes(rounds)
        agreeing = voted.count(value)
        if self.phase == "goal" and value == self.verify.expected:  # success is claimed on it
            odds = self.ctx.calibration.log_odds(self.atom.predicate, rounds)
            return agreeing < 2 or (odds if value else -odds) < claim_threshold(self.ctx.claim_risk)
        return agreeing < 2

    def _evidence(self) -> list[Round]:
        """The views this check weighs: its own; for a goal atom also those earlier checks judged
        it on since the last action that could change it (a cup confirmed filled at the sink,
        whose inside no view into the microwave shows, is still filled)."""
        if self.phase != "goal":
            return self.rounds
        return [*(r for r in self.ctx.verified.views(self.atom) if not any(r is o for o in self.rounds)), *self.rounds]

    def _chosen(self) -> Status:
        if not self._job.done():
            return Status.RUNNING
        try:
            direction = choice(self._job.result())
        except TransportError:  # the VLM's server is gone: the episode ends (verify_predicate._answer)
            raise
        except Exception:  # noqa: BLE001 - no answer: another way is taken (see _move)
            direction = None
        return self._move(direction)

    def _move(self, direction: str | None) -> Status:
        r = self.rounds[-1]
        if direction is None or direction in self._refused:  # no answer, or a way already refused
            direction = self.ctx.viewpoints.instead(self._tried)
        if direction is None:  # no way to a new view from here: what the views said is all there is
            r.moved = False
            return self._decide(exhausted=True)
        r.direction = direction
        self._tried.add(direction)
        aim = self.ctx.aim(self.ctx.graph, (target_of(self.atom), *self.atom.args))
        self._job, self._stage = self.ctx.submit(self.ctx.camera.move_view, aim, direction), "move"
        return Status.RUNNING

    def _moved(self) -> Status:
        if not self._job.done():
            return Status.RUNNING
        r = self.rounds[-1]
        try:
            r.moved = bool(self._job.result())
        except Exception:  # noqa: BLE001 - a move that failed outright is a move not made
            r.moved = False
        self._job = None
        if not r.moved:  # the same spot would show the same picture: try another way at once
            self._refused.add(r.direction)
            r.refused += (r.direction,)
            return self._move(None)
        self.moves += 1
        self._stage = "look"
        return Status.RUNNING  # the child runs again next tick, from the new view

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:
            cancel_all([self._job])
            self._job, self._stage = None, "look"

    def _feel(self, felt: bool) -> Status:
        """Settle on the gripper's word (it can contradict the plan as well as confirm it)."""
        return self._settle(felt, "felt" if felt == self.verify.expected else "contradicted", "proprioception")

    def _settle(self, value: bool, outcome: Outcome, basis: Basis | None = None) -> Status:
        v = self.verify
        self.ctx.verified.saw(v.atom, self.rounds)
        self.ctx.verifications.append(Verification(self.phase, str(self.action) if self.action else "goal",
                                                   v.atom, v.expected, value, outcome, list(self.rounds),
                                                   basis or BASIS[outcome]))
        self.ctx.record(self.ctx.verifications[-1])
        if outcome != "unsettled":
            self.ctx.doubted.discard(v.atom)
        if outcome in ("confirmed", "contradicted", "felt"):
            self.ctx.verified.remember(v.atom, value)
        if self.phase == "goal" and outcome == "unsettled":
            self.ctx.unconfirmed_goal.append(v.atom)
        if outcome == "unsettled" and self.phase == "pre" and self.ctx.unseen != "go_on" \
                and v.atom not in self.ctx.on_belief:
            self.ctx.situation = Situation("unseen", self.action, self.step, v.atom, v.expected, None,
                                           detail=f"could not see whether {v.atom} holds")
            self.ctx.progress(f"    situation: could not see {'' if v.expected else 'not '}{v.atom}")
            return Status.FAILURE
        if outcome != "contradicted":  # confirmed, felt, reused, or unsettled where the plan may go on
            return Status.SUCCESS
        if self.phase == "pre" and v.atom in self.ctx.on_trial:
            self.ctx.progress(f"    {v.atom} observed {value} again: trying {self.action} against it")
            return Status.SUCCESS
        kind = {"pre": "precondition", "eff": "effect", "goal": "goal"}[self.phase]
        self.ctx.situation = Situation(kind, self.action, self.step, v.atom, v.expected, value)
        self.ctx.progress(f"    situation: {kind} {'' if v.expected else 'not '}{v.atom} observed {value}")
        return Status.FAILURE
