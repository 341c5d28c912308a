"""VerifyAction: one action-level question about one fresh frame — the baselines' check, never blocking.

The paper compares its predicate checks with strategies that ask about the action as a whole
(:mod:`vap_bt.strategy`): SuccessVQA after it, "Did the robot successfully <action>?", and
AffordanceVQA before it, "Is it possible to <action>?" (the templates: ``prompts.yaml``). Each is
one question about one frame captured where belief puts what the action is about: no
paraphrases, no vote, no view-sufficiency question, no viewpoint move. The question is work in
flight like any other (:mod:`vap_bt.bt.inflight`): the frame, then the answer, each polled every
tick, and cancelled in ``terminate``.

What a question implies: the :class:`~vap_bt.perception.vlm.Query` carries, in ``about``, the
atoms whose conjunction a "yes" claims — after the action, the effect atoms the ``eff`` phase
would check (:mod:`vap_bt.domain.expectation`: what the action adds, of the predicates the
perception profile asks the camera about); before it, the precondition atoms the ``pre`` phase
would check. A real model reads only the prompt and the picture; the simulated one judges the
conjunction of the facts the question implies, as it judges every question (weakest
observability, all apparent: :mod:`vap_bt.sim.sim_vlm`), with no bonus or penalty of its own. A
question is asked only where it implies something the camera can see (a ``find`` has no
precondition the camera judges), as the compiler leaves out an empty phase. Negated literals (a
deletion a later step relies on) are left out of the conjunction: the model judges facts that
hold, and a question about an action's success claims what it brought about.

What a "no" means, having no predicate to correct (the baselines' natural semantics):

* **SuccessVQA "no"** — the action did not happen: a situation of kind ``action_failed``; the
  executive takes back the action's effects (belief returns to what held before it, as for an
  effect found missing), re-locates the action's objects, and replans from that action, which the
  new plan retries;
* **AffordanceVQA "no"** — the action cannot be done now: a situation of kind
  ``action_infeasible``; the action does not run, and the executive handles it as a skill that
  failed to act — the robot's placement for it is stale (the new plan re-approaches), its objects
  are re-located and, when lost, looked for — then replans. The same "no" from the same belief
  makes the robot look afresh; a third puts the action on trial (the board's
  ``actions_on_trial``): the next "no" lets it run, and its skill is the test — as a denied
  precondition that leaves no plan is tried against the camera under the predicate strategies
  (:meth:`~vap_bt.bt.executive.Executive._replan`). A model answers one picture the same way every
  time, and the same plan brings the robot back to the same pictures.

No answer (an abstention) lets the plan go on: belief stands. Each check is recorded on the
board's ``action_checks`` (:class:`~vap_bt.bt.record.ActionCheck`) and handed to ``ctx.record``,
where the runner scores it against the conjunction's truth; the situation's ``detail`` is the
question asked.
"""

from __future__ import annotations

from concurrent.futures import Future
from typing import ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.inflight import cancel_all, in_flight
from vap_bt.bt.record import ActionCheck, Situation
from vap_bt.bt.verify_predicate import answer_of
from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction
from vap_bt.perception import prompts
from vap_bt.perception.judgement import Phase
from vap_bt.perception.profile import PerceptionProfile
from vap_bt.perception.verification import Round, stand_of, yes_no
from vap_bt.perception.vlm import Query
from vap_bt.robot.frame import Frame

#: each phase's question template (a PromptBook field) and the situation a "no" to it is
PHASES: dict[Phase, tuple[str, str]] = {"pre": ("affordance_vqa", "action_infeasible"),
                                        "eff": ("success_vqa", "action_failed")}


def action_query(phase: Phase, action: GroundAction, implied: tuple[Atom, ...],
                 profile: PerceptionProfile | None = None) -> Query:
    """The action-level question of ``phase`` about ``action``, implying ``implied``; the action said
    as the domain's perception profile says it."""
    template = getattr(prompts.book(), PHASES[phase][0])
    objects = tuple(dict.fromkeys(o for a in implied for o in a.args))
    phrase = (profile.action_phrase if profile is not None else prompts.action_phrase)(action.name, action.args)
    return Query(template.format(action=phrase), purpose="action", about=implied, objects=objects)


class VerifyAction(py_trees.behaviour.Behaviour):
    """Ask one action-level question of one fresh frame; FAILURE (a situation) when the answer is no."""

    KEYS: ClassVar[dict[str, Access]] = {"action_checks": Access.WRITE, "situation": Access.WRITE,
                                         "actions_on_trial": Access.READ}

    def __init__(self, ctx: ExecutionContext, phase: Phase, action: GroundAction, step: int,
                 implied: tuple[Atom, ...]) -> None:
        self.query = action_query(phase, action, implied, ctx.profile)
        super().__init__(name=self.query.prompt)
        self.ctx, self.phase, self.action, self.step, self.implied = ctx, phase, action, step, implied
        self.board = ctx.board.client(type(self).__name__, self.KEYS)
        self.check: ActionCheck | None = None
        self._tried = False  # a "no" this action is tried against (the board's actions_on_trial)
        self._frame: Future | None = None
        self._answer: Future | None = None
        self._observation: Frame | None = None

    def initialise(self) -> None:
        self.check, self._answer, self._observation, self._tried = None, None, None, False
        self._frame = self.ctx.submit(self.ctx.camera.capture, self.ctx.aim(self.ctx.graph, self.query.objects))
        self.feedback_message = "capturing"

    def update(self) -> Status:
        if self._frame is not None:
            if in_flight(self._frame):
                return Status.RUNNING
            self._observation, self._frame = self._frame.result(), None
            self._answer = self.ctx.submit(self.ctx.vlm.ask, self.query, self._observation)
            self.feedback_message = "asking"
        if self._answer is not None:
            if in_flight(self._answer):
                return Status.RUNNING
            value, self._answer = yes_no(answer_of(self._answer)), None
            return self._settle(value)
        return Status.FAILURE if self.check is None else self._status(self.check)

    def _settle(self, value: bool | None) -> Status:
        """Record the answer; a "no" is the phase's situation."""
        frame = self._observation
        r = Round(view=frame.frame_id, questions=[self.query.prompt], answers=[value], vote=value,
                  consistent=value is not None, stand=stand_of(frame),
                  identified={n: k for n, k in frame.identified().items() if n in self.query.objects})
        outcome = "unsettled" if value is None else ("confirmed" if value else "contradicted")
        self.check = ActionCheck(self.phase, str(self.action), self.query.prompt, self.implied, value, outcome, r)
        self.board.action_checks.append(self.check)
        self.ctx.record(self.check)
        self.feedback_message = {None: "no answer", True: "yes", False: "no"}[value]
        self._tried = value is False and str(self.action) in self.board.actions_on_trial
        if self._tried:
            self.ctx.progress(f"    {self.query.prompt} no again: trying {self.action} against it")
        elif value is False:
            kind = PHASES[self.phase][1]
            self.board.situation = Situation(kind, self.action, self.step, None, True, False, detail=self.query.prompt)
            self.ctx.progress(f"    situation: {kind}: {self.query.prompt} no")
        return self._status(self.check)

    def _status(self, check: ActionCheck) -> Status:
        return Status.FAILURE if check.value is False and not self._tried else Status.SUCCESS

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:  # halted mid-question: nothing more is sent
            cancel_all([self._frame, self._answer])
            self._frame, self._answer = None, None
