"""Recovery in the tree: what the robot does about a situation, ticked like everything else.

A situation (a check that contradicted belief, a skill that failed) is handled in steps that
take time on a robot: belief is corrected from what was observed, the camera goes to look at what
a check could not make out, the gripper is asked what it holds, the items involved are looked
for where belief puts them, and rooms are swept for the ones that are gone. Each of those waits
on the robot — a drive to a viewpoint, a frame, a query to its state service — so none may run
inside ``update()``. Here each is a :class:`Step`: a behaviour whose routine is work in flight
(:mod:`vap_bt.bt.inflight`), polled every tick, in a :func:`recovery_tree` the executive ticks
between the failed plan's tree and the next plan's. The live view draws it as it runs, and a
halt (the time budget, a Ctrl-C) stops it as it stops a plan: ``terminate()`` raises the halt
flag, and the routine's next camera call (:class:`Halting`) ends it with :class:`Halted`.

The steps are the executive's own routines (it knows belief, the scene-graph builder and the
site map); this module only gives them the shape of behaviours. A routine runs on the
executive's executor: in-process (the symbolic campaigns) the whole recovery completes in its
first tick, exactly as before it was a tree; against a remote robot each step is in flight on a
thread while the tree is ticked. Belief is the routine's while it runs; nothing else writes it
then (the plan's tree is not ticked during a recovery), and the live view reads it only after.
"""

from __future__ import annotations

import threading
from concurrent.futures import Executor, Future
from typing import Any, Callable, ClassVar

import py_trees
from py_trees.common import Access, Status

from vap_bt.bt.inflight import cancel_all
from vap_bt.bt.plan_tree import PlanTree


class Halted(Exception):
    """A recovery step's routine stopped at a camera call because its tree was halted."""


class Step(py_trees.behaviour.Behaviour):
    """One recovery step: ``routine()`` run as work in flight; SUCCESS when it returns (its value
    in :attr:`result`), and an exception it raises is raised from the tick that sees it (a
    transport gone ends the episode, as from any behaviour)."""

    #: the board keys it uses (:mod:`vap_bt.bt.board`): none — its routine is the executive's, which
    #: owns the board
    KEYS: ClassVar[dict[str, Access]] = {}

    def __init__(self, name: str, routine: Callable[[], Any], executor: Executor, halt: threading.Event) -> None:
        super().__init__(name=name)
        self.routine, self.executor, self.halt = routine, executor, halt
        self.result: Any = None
        self._job: Future | None = None

    def initialise(self) -> None:
        self.halt.clear()
        self.feedback_message = "in flight"
        self._job = self.executor.submit(self.routine)

    def update(self) -> Status:
        if self._job is None or not self._job.done():
            return Status.RUNNING
        self.result = self._job.result()
        self.feedback_message = "done"
        return Status.SUCCESS

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID and self._job is not None and not self._job.done():
            self.halt.set()  # the routine stops at its next camera call
            cancel_all([self._job])
            self.feedback_message = "halted"
        self._job = None


class RecoveryRoot(py_trees.composites.Sequence):
    """The root of a recovery tree: its steps in order, each once (``memory``); ``reason`` says
    what it recovers from (the live view's title for it)."""

    def __init__(self, reason: str, steps: list[Step]) -> None:
        super().__init__(name=f"recover: {reason}", memory=True, children=steps)
        self.reason = reason


def recovery_tree(reason: str, steps: list[Step]) -> PlanTree:
    """The tree the executive ticks to recover from ``reason``: ``steps`` in order."""
    return PlanTree(RecoveryRoot(reason, steps))


class Halting:
    """A camera service (:class:`vap_bt.robot.camera.Camera`) that refuses to move or capture once
    ``halt`` is set: how a halted recovery step's routine, running on a thread, comes to a stop
    at its next look instead of sweeping on."""

    def __init__(self, camera: Any, halt: threading.Event) -> None:
        self.camera, self.halt = camera, halt

    def _go_on(self) -> None:
        if self.halt.is_set():
            raise Halted("the recovery was halted")

    def capture(self, aim=None):
        self._go_on()
        return self.camera.capture(aim)

    def goto_view(self, view) -> bool:
        self._go_on()
        return self.camera.goto_view(view)

    def move_view(self, aim, direction: str) -> bool:
        self._go_on()
        return self.camera.move_view(aim, direction)

    def __getattr__(self, name: str):  # stop(), state(), site_map(): the wrapped service's own
        if name.startswith("__") or name in ("camera", "halt"):
            raise AttributeError(name)
        return getattr(self.camera, name)
