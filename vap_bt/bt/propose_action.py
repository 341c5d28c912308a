"""ProposeNextAction: the VLM-planner asks the model which action comes next (work in flight).

The behaviour of the VLM-planner baseline (:mod:`vap_bt.bt.vlm_planner`). ``initialise`` fills
the prompt from what the robot believes now (:func:`~vap_bt.perception.action_proposal.next_action_prompt`)
and starts the request in flight: a frame from the camera as it stands, then the model's free
text about it (:meth:`~vap_bt.perception.vlm.TextModel.complete`). ``update`` polls it, and never
waits: RUNNING while the model thinks. A reply that is not a usable action is asked again once,
with the error, about the same frame (nothing moved meanwhile); the behaviour then succeeds with
an action or ``done`` in :attr:`proposal`, or fails with the reason in it. ``terminate`` cancels
a request that has not started (one on the wire is let finish and its reply dropped).
"""

from __future__ import annotations

from concurrent.futures import Future
from typing import ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.inflight import cancel_all, in_flight
from vap_bt.domain.task import PlanningTask
from vap_bt.perception.action_proposal import Proposal, judge, next_action_prompt, reask
from vap_bt.perception.vlm import Attempt, Completion, TextModel
from vap_bt.robot.frame import Frame


class ProposeNextAction(py_trees.behaviour.Behaviour):
    """Ask ``model`` for step ``step``'s action toward ``task``'s goal, given the actions done so far
    (``history``: one line each, as the prompt lists them)."""

    #: the board keys it uses (:mod:`vap_bt.bt.board`): none — its proposal is its own (:attr:`proposal`)
    KEYS: ClassVar[dict[str, Access]] = {}

    def __init__(self, ctx: ExecutionContext, model: TextModel, task: PlanningTask, instruction: str, step: int,
                 history: list[str]) -> None:
        super().__init__(name=f"propose step {step}")
        self.ctx, self.model, self.task, self.instruction = ctx, model, task, instruction
        self.step, self.history = step, history
        self.proposal = Proposal(step)
        self._objects: tuple[str, ...] = ()
        self._first = ""
        self._job: Future | None = None

    def initialise(self) -> None:
        graph = self.ctx.graph
        self.proposal = Proposal(self.step)
        self._objects = tuple(sorted(graph.objects))
        self._first = next_action_prompt(self.instruction, self.task, self._objects, graph.state(), self.history)
        self.feedback_message = "asking the model"
        self._job = self.ctx.submit(self._ask, self._first, None)

    def _ask(self, prompt: str, frame: Frame | None) -> tuple[str, Frame, Completion]:
        """The request (on the executor): a frame, unless a re-ask reuses its step's, and the reply."""
        frame = frame if frame is not None else self.ctx.camera.capture()
        return prompt, frame, self.model.complete(prompt, "plan", frame)

    def update(self) -> Status:
        if self._job is None or in_flight(self._job):
            return Status.RUNNING
        prompt, frame, reply = self._job.result()  # a server gone raises here, and ends the episode
        self._job = None
        action, error = judge(reply, self.task, self._objects)
        self.proposal.attempts.append(Attempt(prompt, reply.text, reply.outcome, error, reply.latency_s,
                                              frame.frame_id))
        if error is None:
            self.proposal.action, self.proposal.done = action, action is None
            self.feedback_message = "done" if action is None else str(action)
            return Status.SUCCESS
        if not self.proposal.reasked and reply.replied:
            self.feedback_message = f"asking again: {error}"
            self._job = self.ctx.submit(self._ask, reask(self._first, reply.text or "", error), frame)
            return Status.RUNNING
        self.feedback_message = error
        return Status.FAILURE

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:
            cancel_all([self._job])
        self._job = None

