"""The speed bench's proof that two checkouts ran the same episodes (tools/bench/pybullet_speed.py)."""

from __future__ import annotations

import json

import pytest

from tools.bench.pybullet_speed import compare_rows, differences, strip


def test_durations_and_the_commit_are_left_out_at_any_depth_and_nothing_else():
    report = {"success": True, "wall_s": 3.2, "versions": {"commit": "abc"},
              "actions_executed": [{"name": "grasp", "sent_s": 1.0, "done_s": 2.0}],
              "perception": {"graph": {"initial": {"build_s": 0.4, "views": 7}}}}
    assert strip(report) == {"success": True, "actions_executed": [{"name": "grasp"}],
                             "perception": {"graph": {"initial": {"views": 7}}}}


def test_two_reports_differing_in_a_decision_are_told_apart_and_in_time_only_are_not():
    a = {"success": False, "plans": [{"actions": ["grasp(cup)"]}], "wall_s": 10.0, "ticks": 180}
    slower = {**a, "wall_s": 30.0, "ticks": 219}
    other = {**a, "plans": [{"actions": ["open(fridge)"]}]}
    assert differences(strip(a), strip(slower)) == []
    assert differences(strip(a), strip(other)) == [".plans[0].actions[0]: grasp(cup) != open(fridge)"]


def test_campaign_rows_agree_when_only_their_wall_time_differs(tmp_path, capsys):
    row = {"experiment": "strategies", "world": "pybullet", "task": "heat_pie", "strategy": "both",
           "viewpoints": "vlm", "seed": 1, "success": True, "vlm_queries": 186, "wall_s": 20.7}
    base, same, other = tmp_path / "base.jsonl", tmp_path / "same.jsonl", tmp_path / "other.jsonl"
    base.write_text(json.dumps(row) + "\n")
    same.write_text(json.dumps({**row, "wall_s": 9.0}) + "\n")
    other.write_text(json.dumps({**row, "wall_s": 9.0, "vlm_queries": 187}) + "\n")
    assert compare_rows(base, same) == 0
    assert compare_rows(base, other) == 1
    assert "DIFFER: vlm_queries" in capsys.readouterr().out


def test_cpu_seconds_count_a_child_process_s_cpu_as_well():
    # an episode's planner runs Fast Downward in a subprocess, whose CPU time.process_time misses
    import subprocess
    import sys
    import time

    from tools.bench.pybullet_speed import cpu_seconds

    c0, p0 = cpu_seconds(), time.process_time()
    subprocess.run([sys.executable, "-c", "import time\nt = time.process_time()\nwhile time.process_time() - t < 0.3: pass"],
                   check=True)
    assert cpu_seconds() - c0 >= 0.3 > time.process_time() - p0


def test_chosen_episodes_are_run_in_their_order_and_a_grid_otherwise():
    from tools.bench.pybullet_speed import episodes_of

    assert episodes_of(["S1"], "0-1", ["S1:1", "halve_egg:0"]) == [("boil_water", 1), ("halve_egg", 0)]
    assert episodes_of(["S1", "halve_egg"], "2-3", None) == [("boil_water", 2), ("boil_water", 3),
                                                             ("halve_egg", 2), ("halve_egg", 3)]
    with pytest.raises(SystemExit):
        episodes_of(["S1"], "0-1", ["boil_water"])
