"""FeelHand: after an action and its checks, the gripper's word on what belief has in the hand.

An item can slip out of the hand during any action (Table II: a held object drops during
navigation; a cut, a fill or a place loses its grip on the way). The action's own checks see it
when the item was what it acted on; otherwise the first to notice would be the next action that
needs the item in the hand — after the robot has driven off, away from where it fell, or over it.
So after every action that leaves belief holding something, the gripper (``ctx.felt``: whether
its fingers closed on something) is asked, at no cost: an empty gripper is a situation of kind
``effect`` about ``holding``, observed false. Usually it names no action — the action did what
it did (the robot moved), only the hand lost its item — so nothing is undone; the plan's tail
after the action is what the replan may reuse. When the item lost is one the action worked with
(a knife that dropped mid-cut, a cup on its way to the tap) and the action does not move the
robot, the situation names the action: it is believed not done (the executive takes its effects
back, as for any effect found missing) and the replan does it again. A tool lost on the way did
not do the work, and a model asked afterwards is no second chance to believe it did: cut_lemon
seed 0 with injection claimed a lemon "sliced" on two views from nearly one spot, after the knife
fell before the stroke and the first views had said "not sliced".

Asking the gripper is a query to the robot's state service, which can be slow or gone: the
question is work in flight (``ctx.ask_body``: on a worker, never on the ticking thread, even where
the rest of the work runs inline), polled each tick and ignored once the behaviour is halted, like
a camera frame or a VLM answer — neither ``initialise()`` nor ``update()`` waits for it.
"""

from __future__ import annotations

from concurrent.futures import Future
from typing import ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.record import Situation
from vap_bt.bt.inflight import cancel_all, in_flight
from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import GroundAction


class FeelHand(py_trees.behaviour.Behaviour):
    """Whether the gripper still holds what belief has in it after ``action``."""

    KEYS: ClassVar[dict[str, Access]] = {"verified": Access.WRITE, "situation": Access.WRITE}

    def __init__(self, ctx: ExecutionContext, action: GroundAction, step: int) -> None:
        super().__init__(name="feel hand")
        self.ctx, self.action, self.step = ctx, action, step
        self.board = ctx.board.client(type(self).__name__, self.KEYS)
        self._job: Future | None = None

    def initialise(self) -> None:
        graph, held = self.ctx.graph, sorted(a for a in self.ctx.graph.facts if self.ctx.roles.is_held(a))
        self._job = self.ctx.ask_body(self._lost, graph, held) if held else None

    def _lost(self, graph, held: list[Atom]) -> Atom | None:
        """The first held atom the gripper denies (runs in flight: each answer is a query)."""
        return next((atom for atom in held if self.ctx.felt(graph, atom) is False), None)

    def update(self) -> Status:
        if self._job is None:
            return Status.SUCCESS
        if in_flight(self._job):
            return Status.RUNNING
        atom = self._job.result()  # a TransportError (the state service gone) ends the episode
        if atom is None:
            return Status.SUCCESS
        lost_its_tool = atom.args[0] in self.action.args and not self._moves_robot()
        if lost_its_tool:  # a value judged of its effects is not reused (the lean protocol)
            self.board.verified.distrust({a for a in self.action.may_add if a.predicate != self.ctx.roles.held})
        self.board.situation = Situation("effect", self.action if lost_its_tool else None,
                                        self.step if lost_its_tool else self.step + 1, atom, True, False,
                                        f"the gripper holds nothing after {self.action}")
        self.ctx.progress(f"    situation: the gripper holds nothing after {self.action}")
        return Status.FAILURE

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:
            cancel_all([self._job])
        self._job = None

    def _moves_robot(self) -> bool:
        """Whether the action changes where the robot is or what it has in view (a navigation
        carrying the item, a find: it got there, whatever the hand lost on the way)."""
        return any(a.predicate in self.ctx.roles.robot for a in self.action.may_add | self.action.may_delete)
