"""Shared paths and helpers for the test suite."""

from __future__ import annotations

import collections
import json
from functools import lru_cache
from pathlib import Path

import pytest

import vap_bt  # noqa: F401  (pins numpy's kernels, vap_bt/numerics.py, before a test module's matplotlib loads numpy: a bare pytest run computes as tools/test.sh's)

ROOT = Path(__file__).resolve().parents[1]
TREES = ROOT / "trees"
DOMAINS = Path(__file__).resolve().parent / "domains"
HOUSEHOLD = ROOT / "domains" / "household.pddl"
#: the paper beside the checkout (/work/main -> /work/shared), or beside a worktree's parent
PAPER = next((p for p in (ROOT.parent / "shared" / "paper" / "vap-tamp.tex",
                          ROOT.parent.parent / "shared" / "paper" / "vap-tamp.tex") if p.exists()),
             ROOT.parent / "shared" / "paper" / "vap-tamp.tex")

LITERATURE = [
    ("blocksworld-domain.pddl", "blocksworld-p6.pddl"),
    ("gripper-domain.pddl", "gripper-p4.pddl"),
    ("logistics-domain.pddl", "logistics-p1.pddl"),
]
HOUSEHOLD_TASKS = sorted(p.name for p in TREES.glob("*.yaml"))


@lru_cache(maxsize=1)
def household_profile():
    """The household domain's perception profile (domains/household.perception.yaml, resolved)."""
    from vap_bt.taskfile import load

    return load(TREES / "collect_cup.yaml").profile


@pytest.fixture(scope="module")
def cup():
    """The collect-cup task and a plan for it."""
    from vap_bt.domain.planner import Planner
    from vap_bt.taskfile import load

    task = load(TREES / "collect_cup.yaml").planning
    return task, Planner(task, first_engine="search").plan().actions


def tree_for(task, actions, mode: str):
    """The compiled tree of ``actions`` in verification ``mode`` (nothing is ticked)."""
    from vap_bt.bt.compiler import compile_plan
    from vap_bt.bt.context import ExecutionContext
    from vap_bt.scene.graph import SceneGraph
    from vap_bt.strategy import Strategy

    ctx = ExecutionContext(graph=SceneGraph.of_facts(task.init), vlm=None,
                           camera=None, skills=None, strategy=Strategy.parse(mode))
    return compile_plan(ctx, actions, task.goal, task.knowledge)


def session(name: str, **cfg):
    """A symbolic-world session of task ``trees/<name>`` with the search planner and settings ``cfg``."""
    from vap_bt.app.runner import RunConfig, Session
    from vap_bt.taskfile import load

    task = load(TREES / name)
    return Session(task, RunConfig.from_task(task, world="symbolic", planner="search", **cfg))


@pytest.fixture
def cli(capsys):
    """Run ``vap-bt`` in this process; returns (exit code, stdout, stderr)."""
    from vap_bt.app.cli import main

    def run(*argv: str):
        code = main([str(a) for a in argv])
        out, err = capsys.readouterr()
        return code, out, err

    return run


def load_json(text: str) -> dict:
    return json.loads(text)



#: what a test marked ``slow`` without ``seconds=`` counts for in the files' order: a physics
#: episode of a few actions, a campaign of symbolic episodes
SLOW_S = 10


def slow_seconds(item) -> float:
    """About how long ``item`` takes on CI, for ordering: its ``slow`` marker's ``seconds=`` (given
    where a test takes well over :data:`SLOW_S`: a process episode, a browser), else
    :data:`SLOW_S` for a slow test and 0 for any other."""
    marker = item.get_closest_marker("slow")
    return 0 if marker is None else marker.kwargs.get("seconds", SLOW_S)


def pytest_collection_modifyitems(config, items):
    """Longest files first. The suite runs one file per pytest-xdist worker (``--dist loadfile``),
    and xdist by default hands out files with the most tests first, which leaves the slow
    one-test files (a restarted skill server: a minute of real processes) for last, on one worker
    while the other idles. Files are ordered instead by the seconds their slow tests take
    (:func:`slow_seconds`; most first), collection order otherwise; tools/test.sh turns xdist's
    reordering off. Counting slow tests alone put a file of one 80-second test behind files of
    three 5-second ones. The order is the same on every worker (xdist requires it)."""
    def file_of(item):
        return item.nodeid.split("::")[0]

    seconds, first = collections.Counter(), {}
    for k, item in enumerate(items):
        seconds[file_of(item)] += slow_seconds(item)
        first.setdefault(file_of(item), k)
    items.sort(key=lambda item: (-seconds[file_of(item)], first[file_of(item)]))


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    """A test marked to fail (``xfail``) with ``fails_saying(text)`` fails as expected only when
    its failure's message holds ``text`` (:func:`skill_runs.skills_fail`); failing otherwise, it
    fails the run, naming what it said instead."""
    outcome = yield
    rep = outcome.get_result()
    says = item.get_closest_marker("fails_saying")
    if says is None or call.when != "call" or not hasattr(rep, "wasxfail") or call.excinfo is None:
        return
    message = str(call.excinfo.value)
    if says.args[0] not in message:
        del rep.wasxfail
        rep.outcome = "failed"
        rep.longrepr = (f"failed, but not as its marker says: expected a failure saying {says.args[0]!r}, "
                        f"got {call.excinfo.typename}: {message}")


@pytest.fixture
def worlds():
    """Builds pybullet worlds for one test (:func:`skill_runs.pybullet`'s arguments) and closes them
    after it, however it ended."""
    from skill_runs import pybullet

    made = []

    def make(name, situations=None, **kw):
        made.append(pybullet(name, situations, **kw))
        return made[-1]

    yield make
    for w in made:
        w.close()
