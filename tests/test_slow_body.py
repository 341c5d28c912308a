"""A slow robot-state service never makes a tick slow: asking the gripper is work in flight.

The executive asks the robot's state service whether the fingers closed on something (FeelHand
after every action that leaves belief holding something; a check about the hand before it
settles). Over Zenoh that is a query a busy or distant robot may take long to answer; py_trees'
rule is that ``update()`` never waits, so the question is submitted and polled like a camera
frame or a VLM answer.
"""

from __future__ import annotations

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest
from py_trees.common import Status

from vap_bt.bt.context import ExecutionContext
from vap_bt.bt.feel_hand import FeelHand
from vap_bt.bt.plan_tree import PlanTree
from vap_bt.domain.atoms import Atom
from vap_bt.app.runner import RunConfig, Session
from vap_bt.scene.graph import SceneGraph
from vap_bt.sim.symbolic import SymbolicWorld
from vap_bt.taskfile import load

from conftest import TREES

#: the longest a tick may take (the issue's bound) and how slow the state service is made here
TICK_BOUND_S = 0.05
SLOW_S = 0.4


def test_feel_hand_asks_the_gripper_in_flight_and_waits_without_blocking():
    task = load(TREES / "collect_cup.yaml")
    action = task.planning.knowledge.ground("navigate", ("living_room", "kitchen", "door_lk", "cup"))
    asked = []

    def felt(graph, atom):
        asked.append(atom)
        time.sleep(SLOW_S)
        return False  # the hand came back empty

    with ThreadPoolExecutor(2) as pool:
        ctx = ExecutionContext(graph=SceneGraph.of_facts({Atom("holding", ("cup",))}), vlm=None, camera=None,
                               skills=None, felt=felt, executor=pool)
        node = FeelHand(ctx, action, 3)
        t0 = time.perf_counter()
        node.tick_once()
        assert node.status == Status.RUNNING and time.perf_counter() - t0 < TICK_BOUND_S
        while node.status == Status.RUNNING:
            t = time.perf_counter()
            node.tick_once()
            assert time.perf_counter() - t < TICK_BOUND_S
            time.sleep(0.01)
    assert node.status == Status.FAILURE and asked == [Atom("holding", ("cup",))]
    assert ctx.situation.atom == Atom("holding", ("cup",)) and ctx.situation.observed is False


@pytest.mark.slow
def test_a_slow_robot_state_service_never_makes_a_tick_take_longer_than_50_ms(monkeypatch):
    """A whole episode over Zenoh (the default transport) against a robot whose state service
    takes 0.4 s to answer: it still succeeds, no tick asks the state service itself (every query
    leaves from a worker thread while the tree goes on), and ticks stay under 50 ms. The bound is
    on the 99th percentile: in one full-suite run (two xdist workers busy with pybullet) a single
    tick of hundreds took 0.52 s, a run that did not record whether a query was in it; the guard
    on where queries leave from is exact, and fails on the code before (21 queries from ticks)."""
    from vap_bt.transport.client import ZenohRobot

    real_state, served = SymbolicWorld.state, []

    def slow_state(self):
        served.append(time.perf_counter())
        time.sleep(SLOW_S)
        return real_state(self)

    real_query, asked = ZenohRobot.state, []

    def query(self):
        asked.append((threading.get_ident(), time.perf_counter()))
        return real_query(self)

    ticks: list[tuple[int, float, float]] = []
    real_tick = PlanTree.tick  # the executive's tree (py_trees' BehaviourTree, without the whole-tree walk)

    def timed_tick(self, *args, **kwargs):
        t0 = time.perf_counter()
        try:
            return real_tick(self, *args, **kwargs)
        finally:
            ticks.append((threading.get_ident(), t0, time.perf_counter()))

    task = load(TREES / "collect_cup.yaml")
    session = Session(task, RunConfig.from_task(task, world="symbolic", transport="zenoh", injection=False))
    try:
        monkeypatch.setattr(SymbolicWorld, "state", slow_state)
        monkeypatch.setattr(ZenohRobot, "state", query)
        monkeypatch.setattr(PlanTree, "tick", timed_tick)
        r = session.episode(0)
    finally:
        session.close()
    assert r["success"] and r["goal_satisfied"], r["reason"]
    assert len(served) >= 3 and ticks  # the gripper was asked during the trees, which were ticked
    in_tick = [(t, q) for t, q in asked for thread, t0, t1 in ticks if thread == t and t0 <= q <= t1]
    assert in_tick == [], "a tick asked the robot-state service itself"
    durations = sorted(t1 - t0 for _, t0, t1 in ticks)
    assert durations[int(0.99 * (len(durations) - 1))] < TICK_BOUND_S, durations[-5:]
