"""Every way an episode ends halts the tree, and halting cancels the goal in flight.

The world's actions here never finish on their own: an action runs until its goal is cancelled
(and records that it was), the way a skill moving a robot runs until the motion ends. The goals
go over real Zenoh sessions on loopback (the embedded transport), so the cancel travels as it
would to a skill server in another process.
"""

from __future__ import annotations

import threading
import time

import pytest

from conftest import TREES
from vap_bt.app.runner import EpisodeInterrupted, RunConfig, Session
from vap_bt.sim.symbolic import SymbolicWorld
from vap_bt.taskfile import load

pytestmark = pytest.mark.timeout(120)


@pytest.fixture
def endless(monkeypatch):
    """Make the symbolic world's actions run until cancelled; returns what each saw."""
    seen: list[dict] = []
    started = threading.Event()

    def perform(self, action, args, ctx):
        rec = {"action": action, "cancelled": False, "t0": time.monotonic()}
        seen.append(rec)
        started.set()
        while not ctx.cancelled():
            if time.monotonic() - rec["t0"] > 30:
                raise AssertionError("the goal was never cancelled")
            time.sleep(0.005)
        rec["cancelled"], rec["t1"] = True, time.monotonic()
        from vap_bt.outcome import Outcome

        return Outcome(False, "cancelled")

    monkeypatch.setattr(SymbolicWorld, "perform", perform)
    return seen, started


def _cancelled_before_close(seen: list[dict], within: float = 2.0) -> bool:
    """Whether the last action saw its cancel while the session is still open (the skill
    server's own close cancels its goals too: that must not be what stopped it)."""
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        if seen and seen[-1]["cancelled"]:
            return True
        time.sleep(0.01)
    return False


def _session(**cfg) -> Session:
    task = load(TREES / "collect_cup.yaml")
    return Session(task, RunConfig.from_task(task, world="symbolic", transport="zenoh", injection=False,
                                             vlm_noise=0.0, **cfg))


def test_the_time_budget_halts_the_tree_and_cancels_the_goal_in_flight(endless):
    seen, _ = endless
    session = _session(max_seconds=3.0)
    try:
        t0 = time.monotonic()
        report = session.episode()
        halted = _cancelled_before_close(seen)
    finally:
        session.close()
    assert "time budget (3 s) exhausted" in report["reason"] and not report["success"]
    assert seen, "an action should have been started"
    assert halted, "the goal in flight at the budget must be cancelled by the halt"
    assert seen[-1]["t1"] - t0 >= 3.0  # not before the budget ran out


def test_ctrl_c_halts_the_tree_and_cancels_the_goal_in_flight(endless, monkeypatch):
    from vap_bt.bt.executive import Executive

    seen, started = endless
    real = Executive._tick_until_done

    def ticking(self, tree, ctx, plan, out, *rest):
        def press_ctrl_c(tree, ticks):  # the user presses Ctrl-C while the first action runs
            if started.is_set() and ticks > 5:
                raise KeyboardInterrupt

        self.on_tree = press_ctrl_c
        return real(self, tree, ctx, plan, out, *rest)

    monkeypatch.setattr(Executive, "_tick_until_done", ticking)
    session = _session()
    try:
        with pytest.raises(EpisodeInterrupted) as stop:
            session.episode()
        halted = _cancelled_before_close(seen)
    finally:
        session.close()
    assert stop.value.report["reason"] == "interrupted"
    assert halted, "Ctrl-C must cancel the goal in flight (the halt, before anything is closed)"
    assert len(seen) == 1, "no further action may start after the interruption"


def test_the_time_budget_halts_a_replanned_tree_and_cancels_its_goal_in_flight(endless, monkeypatch):
    """The first action fails at once, so the executive replans and ticks a new tree; the budget
    ends while that tree's goal runs: it is the one halted, and its goal cancelled."""
    from vap_bt.outcome import Outcome

    seen, _ = endless
    endless_perform = SymbolicWorld.perform
    calls = {"n": 0}

    def fail_first(self, action, args, ctx):
        calls["n"] += 1
        if calls["n"] == 1:
            seen.append({"action": action, "cancelled": False, "failed": True})
            return Outcome(False, "the first try fails")
        return endless_perform(self, action, args, ctx)

    monkeypatch.setattr(SymbolicWorld, "perform", fail_first)
    session = _session(max_seconds=3.0)
    try:
        report = session.episode()
        halted = _cancelled_before_close(seen)
    finally:
        session.close()
    assert "time budget (3 s) exhausted" in report["reason"] and report["replans"] >= 1
    assert len(seen) >= 2 and not seen[-1].get("failed"), "the replanned tree's action should be running"
    assert halted, "the goal in flight in the replanned tree must be cancelled by the halt"


def test_work_in_flight_left_by_a_ctrl_c_is_cancelled_not_waited_for():
    """Leaving a ``working`` block on a Ctrl-C cancels the questions still queued and waits for none
    (``Executor``'s own ``with`` would run every queued question first)."""
    from vap_bt.bt.inflight import MAX_IN_FLIGHT, working

    release, started = threading.Event(), threading.Semaphore(0)

    def question() -> None:
        started.release()
        release.wait(30.0)

    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        with working(True) as executor:
            futures = [executor.submit(question) for _ in range(3 * MAX_IN_FLIGHT)]
            for _ in range(MAX_IN_FLIGHT):  # every worker has taken its question: the rest are queued
                assert started.acquire(timeout=10.0)
            raise KeyboardInterrupt
    left = time.monotonic() - t0
    release.set()
    assert left < 5.0
    assert sum(f.cancelled() for f in futures) == 2 * MAX_IN_FLIGHT  # all but those already started
