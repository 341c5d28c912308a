"""The fault campaign (tools/bench/faults.py) and the scripted disturbances it relies on.

A disturbance is the world's doing, recorded in the world's injection log: these tests look there
(the report's ``injected`` is that log) and check that the executive either notices each kind as a
situation or at least never claims a goal the world denies after one.
"""

from __future__ import annotations

import json

import pytest

from tools.bench import faults
from vap_bt.domain.atoms import Atom
from vap_bt.app.runner import RunConfig, Session
from vap_bt.sim.disturbances import HALF_SHUT, KINDS, MOVED, SHUT, Disturbance, DisturbanceModel
from vap_bt.sim.symbolic import SymbolicWorld
from vap_bt.taskfile import load
from vap_bt.world import InjectedSituation

from conftest import TREES


def test_the_model_draws_one_seeded_disturbance_a_task_can_have():
    task = load(TREES / "collect_cup.yaml").planning
    model = DisturbanceModel(1.0)
    assert model.draw(task, 3) == model.draw(task, 3)  # the seed decides
    assert DisturbanceModel(0.0).draw(task, 3) == []
    for kind in KINDS:
        (d,) = model.draw(task, 0, kind=kind)
        assert d.kind == kind and d.target == ("cup" if kind == MOVED else "door_lk")
        assert d.to in (None, "counter", "floor_kitchen", "floor_living_room")
    # a task without a door or an openable thing: only moves are drawn
    plate = load(TREES / "pick_plate.yaml").planning
    assert {d.kind for s in range(20) for d in model.draw(plate, s)} == {MOVED}


@pytest.mark.parametrize("d, changed", [
    (Disturbance(MOVED, 0, "cup", "floor_living_room"), {"on(cup, floor_living_room)"}),
    (Disturbance(SHUT, 0, "door_lk"), {"closed(door_lk)"}),
    (Disturbance(HALF_SHUT, 0, "door_lk"), set()),  # ajar: neither open nor closed
])
def test_the_symbolic_world_applies_a_disturbance_after_its_action_and_records_it(d, changed):
    from vap_bt.transport.execution import GoalRun

    world = SymbolicWorld(load(TREES / "collect_cup.yaml").planning)
    world.disturbances = [d]
    before = set(world.atoms)
    world.perform("find", ("floor_living_room", "cup", "living_room"), GoalRun())
    (rec,) = world.injected()
    assert (rec.kind, rec.step, rec.affected) == (d.kind, 1, (d.target,))
    assert {str(a) for a in world.atoms - before} >= changed
    assert (Atom("open", ("door_lk",)) in world.atoms) == (d.kind == MOVED)
    world.perform("grasp", ("cup", "coffee_table", "living_room"), GoalRun())
    assert len(world.injected()) == 1  # once only


@pytest.mark.parametrize("d", [Disturbance(MOVED, 0, "cup", "floor_living_room"), Disturbance(SHUT, 1, "door_lk"),
                               Disturbance(HALF_SHUT, 1, "door_lk")], ids=lambda d: d.kind)
def test_each_disturbance_is_noticed_or_never_ends_in_a_false_success(d):
    task = load(TREES / "collect_cup.yaml")
    s = Session(task, RunConfig.from_task(task, world="symbolic"))
    try:
        s.world.disturbances = [d]
        r = s.episode(0)
        recorded = [i for i in s.world.oracle.injected() if i.kind in KINDS]
        assert [(i.kind, i.affected) for i in recorded] == [(d.kind, (d.target,))]
        (fault,) = [f for f in faults.faults_of(r["injected"], r["situations"]) if f.source == "disturbance"]
        assert fault.detected or not (r["success"] and not r["goal_satisfied"]), r["reason"]
        assert fault.detected  # on this seed the executive finds each of them
        assert r["success"] and r["goal_satisfied"], r["reason"]
    finally:
        s.close()


def test_a_small_campaign_records_every_disturbance_kind_and_prints_its_table(tmp_path, capsys):
    out = tmp_path / "faults.jsonl"
    # episodes 0-5 run tasks 0-5 on seeds 9-14, whose draws are a move, a half-shut and two shut leaves
    args = ["--episodes", "6", "--first-seed", "9", "--disturbance", "1", "--jsonl", str(out)]
    assert faults.main(args) == 0
    table = capsys.readouterr().out
    rows = [json.loads(line) for line in out.read_text().splitlines()]
    assert len(rows) == 6 and {r["seed"] for r in rows} == set(range(9, 15))
    assert all(r["outcome"] in ("recovered", "false_success", "aborted", "crash", "hang") for r in rows)
    assert not [r for r in rows if r["outcome"] in ("crash", "hang")], [r["error"] for r in rows]
    applied = [(r, f) for r in rows for f in r["faults"] if f["source"] == "disturbance"]
    assert {f["kind"] for _, f in applied} == set(KINDS)
    for r, f in applied:  # what the world recorded is what it had drawn for the episode
        assert any(s["kind"] == f["kind"] and [s["target"]] == f["affected"] for s in r["scheduled"])
    lines = table.splitlines()
    assert lines[2].startswith("| episodes | crashes | hangs |") and lines[4].startswith("| 6 | 0 | 0 |")
    kinds = [line for line in lines if line.startswith("| ") and "| disturbance |" in line]
    assert sorted(line.split(" | ")[0][2:] for line in kinds) == sorted(KINDS)
    assert all(line.count("|") == 12 for line in kinds)
    # started again on the same file, it runs nothing more and prints the same table
    assert faults.main(args) == 0
    assert len(out.read_text().splitlines()) == 6
    assert capsys.readouterr().out == table


def test_the_watchdog_counts_an_episode_past_its_budget_as_a_hang_and_goes_on():
    task = TREES / "collect_cup.yaml"
    # 0.3 s is less than the worker's first session takes to build (grounding, Fast Downward)
    jobs = [faults.Job(str(task), "collect_cup", seed, "symbolic", 1.0, 0.0, budget, None)
            for seed, budget in ((0, 0.3), (1, 120.0))]
    rows: list = []
    faults.run_campaign(jobs, 1, rows.append)
    assert [(r.seed, r.outcome) for r in rows][0] == (0, "hang")
    assert rows[1].seed == 1 and rows[1].outcome in ("recovered", "aborted"), rows[1].error


def test_a_failure_by_physics_alone_is_marked_natural_not_table_ii():
    """The pybullet world logs the robot's actions that failed with nothing drawn
    (:mod:`vap_bt.sim.natural_failures`) beside Table II's rows; the table tells them apart."""
    args = ("cup", "counter", "kitchen")
    injected = [InjectedSituation("grasp", args, "grasp_fails_object_unchanged", 2, ("cup",)).to_json(),
                *(InjectedSituation("grasp", args, kind, 2, ("cup",), "natural").to_json()
                  for kind in ("action_failed", "held_object_dropped"))]
    situations = [{"predicate": "holding(cup)", "action": "grasp(cup, counter, kitchen)"}]
    assert [(f.source, f.detected) for f in faults.faults_of(injected, situations)] == \
        [("table2", True), ("natural", True), ("natural", True)]
