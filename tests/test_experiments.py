"""tools/experiments: the four experiment commands on a Dask cluster of two workers, their
outputs, resuming, a worker dying mid-campaign, and bad input.

One LocalCluster of two worker processes serves the module (``--address``): the commands join
it unchanged, as they would a cluster of machines. Each command runs one quick task (S4,
halve_egg) on two seeds in the symbolic world.
"""

from __future__ import annotations

import csv
import dataclasses
import json
import os
import signal
import subprocess
import sys
import time

import matplotlib.image
import pytest

from conftest import ROOT, TREES

sys.path.insert(0, str(ROOT))  # tools/ (the workers spawned from here inherit the path)
from tools.experiments import engine, results  # noqa: E402
from tools.experiments.ablation import ABLATION, MODES  # noqa: E402
from tools.experiments import command  # noqa: E402
from tools.experiments.command import SEED_BLOCK, Campaign, choices, keys, main  # noqa: E402
from tools.experiments.failures import FAILURES  # noqa: E402
from tools.experiments.strategies import STRATEGIES  # noqa: E402
from tools.experiments.viewpoints import VIEWPOINTS  # noqa: E402
from vap_bt import taskfile  # noqa: E402
from vap_bt.perception.viewpoints import AROUND_ORDER  # noqa: E402
from vap_bt.settings import RunConfig  # noqa: E402

TASK = ["--tasks", "S4", "--seeds", "2"]


@pytest.fixture(scope="module")
def address():
    """A two-worker LocalCluster's scheduler address, for the module's campaigns to join."""
    with engine.open_client(workers=2) as client:
        assert engine.workers(client) == 2
        yield client.scheduler.address


def rows_of(out) -> list[dict]:
    with open(out / "episodes.csv", newline="") as f:
        reader = csv.DictReader(f)
        assert tuple(reader.fieldnames) == results.COLUMNS
        return list(reader)


def assert_images(out, *names: str) -> None:
    for name in names:
        image = matplotlib.image.imread(out / name)
        assert image.shape[0] > 100 and image.shape[1] > 100 and image.std() > 0, name  # not a blank canvas


def assert_run_json(out, episodes: int) -> dict:
    meta = json.loads((out / "run.json").read_text())
    assert meta["episodes"] == episodes and meta["workers"] == 2 and meta["seeds"] == "0-1"
    assert meta["tasks"] == ["halve_egg"] and meta["world"] == "symbolic" and len(meta["commit"]) >= 40
    assert meta["wall_s"] > 0 and meta["episodes_per_hour"] > 0 and meta["versions"]["distributed"]
    return meta


@pytest.mark.slow(seconds=45)  # 18 s on 2 shared cores (54 s at a load average of 15)
def test_ablation_runs_every_mode_on_the_cluster_and_writes_table_iii(tmp_path, address):
    out = tmp_path / "ablation"
    p = subprocess.run([sys.executable, str(ROOT / "tools/experiments/ablation.py"), *TASK, "--address", address,
                        "--out", str(out)], capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert p.returncode == 0, p.stderr[-2000:]
    rows = rows_of(out)
    assert sorted((r["strategy"], r["seed"]) for r in rows) == sorted((m, s) for m in MODES for s in "01")
    assert all(r["runnable"] == "True" and r["vlm_version"].startswith("vlm-") for r in rows)
    assert all(r["openblas"] for r in rows)  # the worker's BLAS kernels, whatever it loaded
    table = (out / "table.md").read_text()
    assert p.stdout.strip() == table.strip()  # the table on stdout, the progress on stderr
    assert "| S4 halve_egg |" in table and "(n=2)" in table and "Paired difference" in table
    assert p.stderr.strip().splitlines()[-1].startswith("  [ablation: 8/8 episodes  100%")
    assert_images(out, "table3.png")
    assert_run_json(out, 8)


def test_strategies_reads_its_strategies_from_the_settings(tmp_path, address):
    out = tmp_path / "strategies"
    assert main(STRATEGIES, [*TASK, "--address", address, "--out", str(out), "--verify", "both", "none"]) == 0
    rows = rows_of(out)
    assert len(rows) == 4 and {r["strategy"] for r in rows} == {"both", "none"}
    assert {"both", "none"} <= set(choices("verify"))
    table = (out / "table.md").read_text()
    assert "| none | " in table and "wall time per episode" in table and "not runnable" not in table
    assert_images(out, "strategies.png", "success_vs_time.png")
    assert_run_json(out, 4)


def test_a_strategy_that_cannot_run_here_is_said_not_runnable(monkeypatch):
    """A configuration the runner refuses with an InputError (as it refuses a VLM planner without a
    real VLM backend) is a row saying so, and the table says "not runnable" instead of a rate."""
    from tools.experiments import compare
    from vap_bt.app import runner
    from vap_bt.errors import InputError

    real = runner.check_config

    def refuse_both(task, cfg):
        if cfg.verify == "both":
            raise InputError("--verify", "both needs a real VLM backend (a test's stand-in)")
        return real(task, cfg)

    monkeypatch.setattr(runner, "check_config", refuse_both)
    monkeypatch.setattr(engine, "SESSIONS", engine._Sessions())
    rows = [engine.episode_row(engine.Key("strategies", "symbolic", "halve_egg", s, "vlm", 0)) for s in ("both", "none")]
    assert [r["runnable"] for r in rows] == [False, True] and rows[0]["success"] is None
    table = compare.success_table(rows, {"halve_egg": "S4 halve_egg"}, ["both", "none"], "none")
    assert "| not runnable |" in table and "(n=1)" in table and "a test's stand-in" in table


def test_an_episode_that_raises_is_a_row_with_its_error_and_its_session_is_dropped(monkeypatch):
    from vap_bt.app.runner import Session

    def boom(self, seed=None):
        raise RuntimeError("boom")

    monkeypatch.setattr(engine, "SESSIONS", engine._Sessions())
    monkeypatch.setattr(Session, "episode", boom)
    row = engine.episode_row(engine.Key("strategies", "symbolic", "halve_egg", "none", "vlm", 0))
    assert row["error"] == "RuntimeError: boom" and row["failure_mode"] == "crash" and row["success"] is False
    assert not engine.SESSIONS.open  # the next episode gets a fresh session


def test_viewpoints_counts_views_of_uncertain_checks(tmp_path, address):
    out = tmp_path / "viewpoints"
    assert main(VIEWPOINTS, [*TASK, "--address", address, "--out", str(out)]) == 0
    kinds = set(choices("viewpoints"))
    rows = rows_of(out)
    assert {r["viewpoints"] for r in rows} == kinds and len(rows) == 2 * len(kinds)
    budget = RunConfig.from_task(taskfile.load(TREES / "halve_egg.yaml")).budget  # K: an unresolved check's charge
    views = {k: [int(v) for r in rows if r["viewpoints"] == k for v in r["uncertain_viewpoints"].split(";") if v]
             for k in kinds}
    # K caps what a check is charged, but greedy-all's: it visits its whole round (six without geometry)
    assert all(views[k] and all(0 <= v <= budget for v in views[k]) for k in kinds - {"greedy-all"})
    assert views["greedy-all"] and all(0 <= v <= len(AROUND_ORDER) for v in views["greedy-all"])
    table = (out / "table.md").read_text()
    assert "viewpoints per uncertain check" in table and "settled accuracy" in table and "greedy − vlm" in table
    assert_images(out, "viewpoints.png")
    assert_run_json(out, len(rows))


def test_failures_classes_every_failed_episode(tmp_path, address):
    out = tmp_path / "failures"
    assert main(FAILURES, [*TASK, "--address", address, "--out", str(out), "--verify", "both", "none"]) == 0
    rows = rows_of(out)
    assert len(rows) == 4
    assert all((r["failure_mode"] == "") == (r["success"] == "True") for r in rows)
    table = (out / "table.md").read_text()
    assert "visual ambiguity" in table and "Situations per episode" in table and "## Diagnosis" in table
    assert_images(out, "failure_modes.png", "situations.png")
    # the same episodes read from another campaign's rows (--rows): the same tables, nothing run
    again = tmp_path / "again"
    assert main(FAILURES, [*TASK, "--out", str(again), "--rows", str(out / "episodes.jsonl"),
                           "--verify", "both", "none"]) == 0
    assert (again / "table.md").read_text() == table and not (again / "episodes.jsonl").exists()
    assert json.loads((again / "run.json").read_text())["rows_from"] == str(out / "episodes.jsonl")


def test_the_rows_count_uncertain_checks_as_the_viewpoint_measure_does():
    """The rows' H2 columns are vap_bt.viewpoint_measure's: only checks whose first view did not
    decide, charged their moves, an unresolved one K (greedy-all: what it visited)."""
    from tools.experiments import measures

    def check(first_settled, viewpoints, outcome, value=True, truth=True, basis="vlm"):
        return {"phase": "pre", "action": "a", "predicate": "p", "first_settled": first_settled,
                "viewpoints": viewpoints, "outcome": outcome, "value": value, "truth": truth, "basis": basis}

    checks = [check(True, 1, "confirmed"),  # decided on its first view (a second look to confirm): not counted
              check(False, 2, "confirmed"),  # two moves, right
              check(False, 1, "unsettled", value=False, basis="belief"),  # never decided: charged K = 3
              check(False, 1, "contradicted", value=False, truth=True),  # decided, wrong
              check(None, 0, "felt", basis="proprioception")]  # the gripper's: no view counted
    report = {"config": {"budget": 3, "viewpoints": "vlm"}, "verifications": checks, "success": True,
              "goal_satisfied": True, "reason": "goal reached", "situations": []}
    row = measures.of(report)
    assert (row["uncertain_viewpoints"], row["uncertain_resolved"], row["uncertain_correct"]) == ([2, 3, 1], 2, 1)
    greedy_all = measures.of({**report, "config": {"budget": 3, "viewpoints": "greedy-all"}})
    assert greedy_all["uncertain_viewpoints"] == [2, 1, 1]  # what it visited, resolved or not


@pytest.mark.parametrize("claimed,holds,reason,kinds,wrong,mode", [
    (True, True, "goal reached", [], False, None),
    (True, False, "goal reached", [], False, "visual ambiguity"),  # a claimed success the world denies
    (False, False, "stuck: could not see whether sliced(egg) holds at the goal", ["goal"], False, "visual ambiguity"),
    (False, False, "replanning budget (20) exhausted", ["execution"] * 3, True, "visual ambiguity"),  # wrong belief kept
    (False, False, "no plan after execution situation: no plan reaches the goal", ["execution"], False, "state/access"),
    (False, False, "stuck: execution of placein(cup, microwave, kitchen) failed", ["execution"], False, "manipulation"),
    (False, False, "replanning budget (20) exhausted", ["execution", "execution", "effect"], False, "manipulation"),
    (False, False, "replanning budget (20) exhausted", ["effect", "effect", "execution"], False, "other"),
    (False, False, "time budget (900 s) exhausted", [], False, "other"),
])
def test_a_failed_episode_is_classed_by_the_first_rule_that_applies(claimed, holds, reason, kinds, wrong, mode):
    from tools.experiments import measures

    checks = [{"predicate": "holding(cup)", "basis": "vlm", "value": True, "truth": True},
              {"predicate": "holding(cup)", "basis": "vlm", "value": True, "truth": not wrong}]  # the last one counts
    report = {"success": claimed, "goal_satisfied": holds, "reason": reason, "verifications": checks,
              "situations": [{"kind": k} for k in kinds]}
    assert measures.failure_mode(report) == mode


def test_the_situation_trail_keeps_each_situation_with_its_diagnosis_truth_and_the_events_behind_it():
    """The log's trail names, per situation, what the diagnosis and its truth were and which of the
    world's logged events the truth rests on (by kind), its free text cut short."""
    from tools.experiments import measures

    injected = [{"kind": "grasp_fails_object_unchanged"}, {"kind": "moved"}]
    situations = [{"kind": "effect", "action": "grasp(cup, table, kitchen)", "predicate": "holding(cup)",
                   "detail": "", "diagnosis": "execution_failure", "diagnosis_basis": "x" * 500,
                   "diagnosis_truth": "execution_failure", "truth_events": [0]},
                  {"kind": "execution", "action": "open(fridge)", "predicate": None, "detail": "fridge: handle out of reach",
                   "diagnosis": "execution_failure", "diagnosis_basis": "the skill of open(fridge) reported failure",
                   "diagnosis_truth": "perception_error", "truth_events": []}]
    report = {"config": {"budget": 3, "viewpoints": "vlm"}, "verifications": [], "success": False,
              "goal_satisfied": False, "reason": "stuck", "situations": situations, "injected": injected}
    trail = measures.of(report)[measures.TRAIL]
    assert [(t["kind"], t["diagnosis"], t["truth"], t["events"]) for t in trail] == [
        ("effect", "execution_failure", "execution_failure", ["grasp_fails_object_unchanged"]),
        ("execution", "execution_failure", "perception_error", [])]
    assert len(trail[0]["basis"]) == measures.TRAIL_TEXT and trail[1]["detail"] == "fridge: handle out of reach"
    assert measures.TRAIL not in measures.COLUMNS  # the log's, not a CSV column


@pytest.mark.parametrize("kind,action,predicate,detail,raised", [
    ("execution", "open(oven)", None, "open(oven) stopped: blocked: the arm is 0.44 rad behind its set-point", "skill: blocked"),
    ("execution", "fill(cup, kitchen_sink)", None, "kitchen_sink: tap out of reach", "skill: tap out of reach"),
    ("execution", "grasp(cup, floor_kitchen, kitchen)", None, "cup is not where it was believed to be: not seen",
     "skill: not where it was believed to be"),
    ("execution", "find(a, b, c)", None, "no clear way to (6.90, 2.70): the base would run into an obstacle",
     "skill: no clear way to"),
    ("effect", "turnon(microwave, cup)", "turned_on(microwave)", "", "effect turned_on"),
    ("unseen", None, "filled(cup)", "goal reached in belief but not confirmed by looking: filled(cup)",
     "unseen filled at the goal"),
    ("effect", None, "holding(cup)", "the gripper holds nothing after open(microwave)", "effect holding"),
])
def test_a_situation_is_classed_by_what_raised_it_without_names_or_numbers(kind, action, predicate, detail, raised):
    from tools.experiments import measures

    assert measures.situation_class({"kind": kind, "action": action, "predicate": predicate, "detail": detail}) == raised


def test_the_failures_table_lists_wrong_diagnoses_by_what_raised_them():
    """Two blocked arms read as execution failures where the world's record says belief was wrong,
    one right: the table counts the two against the three so raised."""
    from tools.experiments import failures

    def t(truth):
        return {"kind": "execution", "action": "open(oven)", "predicate": None, "truth": truth,
                "detail": "open(oven) stopped: blocked: the arm is 0.44 rad behind its set-point",
                "diagnosis": "execution_failure"}

    rows = [{"strategy": "both", "situation_trail": [t("perception_error"), t("execution_failure")]},
            {"strategy": "both", "situation_trail": [t("perception_error")]}, {"strategy": "both"}]
    table = failures.wrong_by_class(rows)
    assert "| perception_error | execution_failure | skill: blocked | 2 | 3 |" in table
    assert "2 of 3 situations" in table and failures.wrong_by_class([{"strategy": "both"}]) == ""


#: the cheapest campaign: the closed-world baseline (no checks) on four seeds
QUICK = ["--tasks", "S4", "--seeds", "4", "--verify", "none"]


def test_a_campaign_stopped_part_way_has_every_cell_at_nearly_the_same_count():
    """Keys go block by block of seeds, so the first block's episodes cover every cell before any
    cell's next seeds run (a pybullet campaign spans sittings and stops part-way)."""
    configs = [("both", "vlm"), ("none", "vlm")]
    campaign = Campaign({"boil_water": "S1", "heat_pie": "S3"}, list(range(25)), "pybullet", ROOT)
    order = keys(ABLATION, campaign, configs)
    assert len(order) == len(set(order)) == 2 * 2 * 25
    first = order[:2 * 2 * SEED_BLOCK]
    assert {k.seed for k in first} == set(range(SEED_BLOCK))
    assert {(k.task, k.strategy) for k in first} == {(t, c) for t in ("boil_water", "heat_pie") for c in ("both", "none")}
    # within a block a configuration's episodes follow each other: its warm session serves them all
    assert [k.seed for k in first[:SEED_BLOCK]] == list(range(SEED_BLOCK)) and len({k.config() for k in first[:SEED_BLOCK]}) == 1
    # and the first configuration (the reference) covers every task before the next one starts
    assert {(k.task, k.strategy) for k in first[:2 * SEED_BLOCK]} == {("boil_water", "both"), ("heat_pie", "both")}


def test_the_commit_is_dirty_only_for_changes_that_could_change_an_episode(tmp_path, monkeypatch):
    """A campaign's rows and tables (docs/results) and the text beside them are written while
    campaigns run: they do not make the next campaign's commit "+dirty"; a changed module does."""
    from tools.experiments import command

    def git(*a: str) -> None:
        subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@t", *a], cwd=tmp_path, check=True,
                       capture_output=True)

    (tmp_path / "docs" / "results").mkdir(parents=True)
    (tmp_path / "docs" / "results" / "episodes.jsonl").write_text("{}\n")
    (tmp_path / "skill.py").write_text("X = 1\n")
    git("init", "-q")
    git("add", ".")
    git("commit", "-qm", "c")
    monkeypatch.setattr(command, "ROOT", tmp_path)
    (tmp_path / "docs" / "results" / "episodes.jsonl").write_text("")  # a campaign starting afresh
    assert not command._commit().endswith("+dirty") and len(command._commit()) == 40
    (tmp_path / "skill.py").write_text("X = 2\n")
    assert command._commit().endswith("+dirty")


def test_resume_runs_only_what_a_stopped_campaign_had_not_finished(tmp_path, address):
    out = tmp_path / "strategies"
    argv = [*QUICK, "--address", address, "--out", str(out)]
    assert main(STRATEGIES, argv) == 0
    log = out / "episodes.jsonl"
    lines = log.read_text().splitlines()
    log.write_text("\n".join(lines[:2]) + "\n" + lines[2][:40])  # stopped while writing the third row
    assert main(STRATEGIES, [*argv, "--resume"]) == 0
    rows = results.EpisodeLog(log).rows()
    assert len(rows) == 4 and len({results.key_of(r) for r in rows}) == 4
    meta = json.loads((out / "run.json").read_text())
    assert meta["episodes"] == 2 and len(rows_of(out)) == 4
    # both sittings are on record, and every row says which code ran it, as the table does
    assert [s["episodes"] for s in meta["sittings"]] == [4, 2]
    assert {r["commit"] for r in rows} == {meta["commit"]} and len(meta["commit"]) >= 40
    assert f"Episodes run on: {meta['commit'][:12]}" in (out / "table.md").read_text()
    # run again with nothing left to run: the report is written, no empty sitting is recorded
    assert main(STRATEGIES, [*argv, "--resume"]) == 0
    assert [s["episodes"] for s in json.loads((out / "run.json").read_text())["sittings"]] == [4, 2]


def test_experiments_sharing_a_log_run_each_episode_once(tmp_path, address):
    log = tmp_path / "campaign" / "episodes.jsonl"
    shared = ["--tasks", "S4", "--seeds", "2", "--address", address, "--log", str(log)]
    assert main(STRATEGIES, [*shared, "--verify", "both", "none", "--out", str(tmp_path / "strategies")]) == 0
    assert main(ABLATION, [*shared, "--out", str(tmp_path / "ablation")]) == 0
    rows = results.EpisodeLog(log).rows()
    # the ablation ran only the modes the strategies had not: eff and pre, two seeds each
    assert sorted((r["experiment"], r["strategy"]) for r in rows) == sorted(
        [("strategies", s) for s in ("both", "none") for _ in "01"] + [("ablation", m) for m in ("eff", "pre") for _ in "01"])
    assert json.loads((tmp_path / "ablation" / "run.json").read_text())["episodes"] == 4
    # and its table is read from all four modes' rows, the strategies' included
    assert sorted((r["strategy"], r["seed"]) for r in rows_of(tmp_path / "ablation")) == sorted(
        (m, s) for m in MODES for s in "01")
    assert len(rows_of(tmp_path / "strategies")) == 4  # the strategies' report: only its own configurations ran yet
    # a report that runs nothing reads the shared log and says so in its run.json
    assert main(FAILURES, [*shared, "--report-only", "--out", str(tmp_path / "failures")]) == 0
    meta = json.loads((tmp_path / "failures" / "run.json").read_text())
    assert meta["rows_from"] == str(log) and meta["episodes"] == 8 and "diagnosed right" in (
        tmp_path / "failures" / "table.md").read_text()
    # the table of a campaign that ran is written again from the log; its run.json (the sittings) stays
    ran = (tmp_path / "strategies" / "run.json").read_text()
    assert main(STRATEGIES, [*shared, "--report-only", "--out", str(tmp_path / "strategies")]) == 0
    assert (tmp_path / "strategies" / "run.json").read_text() == ran


@pytest.mark.slow(seconds=40)
def test_the_campaign_script_runs_each_configuration_once_and_writes_the_four_tables(tmp_path, address):
    out = tmp_path / "campaign"
    env = {"PATH": "/usr/bin:/bin", "WORLD": "symbolic", "SEEDS": "2", "TASKS": "S4", "DIR": str(out), "ADDRESS": address}
    p = subprocess.run(["bash", str(ROOT / "tools/experiments/campaign.sh")], env=env, capture_output=True, text=True,
                       timeout=300, cwd=ROOT)
    assert p.returncode == 0, p.stderr[-2000:]
    rows = results.EpisodeLog(out / "episodes.jsonl").rows()
    configs = [(s, "vlm") for s in choices("verify")] + [("both", k) for k in choices("viewpoints") if k != "vlm"]
    assert sorted((r["strategy"], r["viewpoints"], r["seed"]) for r in rows) == sorted(
        (s, v, seed) for s, v in configs for seed in (0, 1))  # the full method once, though three tables read it
    for name in ("strategies", "viewpoints", "ablation", "failures"):
        assert "Episodes run on:" in (out / name / "table.md").read_text(), name
    assert {r["strategy"] for r in rows_of(out / "ablation")} == set(MODES)


def test_a_worker_killed_mid_campaign_loses_only_its_episode(tmp_path, address):
    marker = tmp_path / "crashed"
    out = tmp_path / "strategies"
    assert main(STRATEGIES, [*QUICK, "--address", address, "--out", str(out)], fault=engine.CrashOnce(str(marker))) == 0
    assert marker.exists()  # a worker did die
    rows = results.EpisodeLog(out / "episodes.jsonl").rows()
    assert len(rows) == 4 and len({results.key_of(r) for r in rows}) == 4 and not any(r["error"] for r in rows)


def test_ctrl_c_keeps_the_rows_written_and_says_how_to_resume(tmp_path, address, monkeypatch, capsys):
    real = engine.run

    def stopped(client, keys, emit, fault=None):
        real(client, keys[:2], emit)  # two episodes finish, then the user presses Ctrl-C
        raise KeyboardInterrupt

    monkeypatch.setattr(engine, "run", stopped)
    out = tmp_path / "strategies"
    assert main(STRATEGIES, [*QUICK, "--address", address, "--out", str(out)]) == 130
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith("strategies: interrupted; 2 rows kept")
    assert len(results.EpisodeLog(out / "episodes.jsonl").rows()) == 2
    # the stopped sitting is on record too, so a campaign resumed later keeps its command and commit
    sitting = json.loads((out / "run.json").read_text())["sittings"][-1]
    assert sitting["interrupted"] is True and sitting["episodes"] == 2


def test_sigterm_stops_the_sitting_as_ctrl_c_does(tmp_path, address, monkeypatch, capsys):
    """A campaign started in the background (where SIGINT is ignored) is stopped with SIGTERM: its
    sitting must still be recorded, not lost with the process."""
    real = engine.run

    def terminated(client, keys, emit, fault=None):
        real(client, keys[:1], emit)
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(5)  # the handler interrupts this; reaching the end means SIGTERM was not caught
        raise AssertionError("SIGTERM did not stop the sitting")

    monkeypatch.setattr(engine, "run", terminated)
    before = signal.getsignal(signal.SIGTERM)
    out = tmp_path / "strategies"
    assert main(STRATEGIES, [*QUICK, "--address", address, "--out", str(out)]) == 130
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith("strategies: interrupted; 1 rows kept")
    assert json.loads((out / "run.json").read_text())["sittings"][-1]["interrupted"] is True
    assert signal.getsignal(signal.SIGTERM) is before  # the command leaves the process's handlers as it found them


@pytest.mark.slow(seconds=20)  # 10 s on 2 shared cores
def test_an_episode_is_the_same_whatever_worker_runs_it(tmp_path, address):
    """The cluster's rows equal the same episodes run here, in order, in one process."""
    out = tmp_path / "strategies"
    assert main(STRATEGIES, [*QUICK, "--address", address, "--out", str(out), "--verify", "none", "eff",
                             "--seeds", "2"]) == 0
    there = sorted(results.EpisodeLog(out / "episodes.jsonl").rows(), key=results.key_of)
    here = [json.loads(json.dumps(engine.episode_row(results.key_of(r)))) for r in there]
    # the wall time varies; the commit is stamped by the campaign, not by the episode
    strip = lambda r: {k: v for k, v in r.items() if k not in ("wall_s", "commit")}  # noqa: E731
    assert len(there) == 4 and [strip(r) for r in here] == [strip(r) for r in there]


@pytest.mark.parametrize("argv,option", [(["--tasks", "boil_wter"], "--tasks"), (["--seeds", "9-3"], "--seeds"),
                                         (["--verify", "bogus"], "--verify")])
def test_bad_input_is_one_line_and_exit_2(argv, option, capsys, tmp_path):
    assert main(STRATEGIES, [*argv, "--out", str(tmp_path)]) == 2  # returned: no exception, no traceback
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and err.startswith(f"strategies: {option}: "), err
    assert not list(tmp_path.iterdir())  # nothing started, nothing written


def test_a_log_of_another_models_version_is_not_continued(tmp_path, capsys):
    """A changed model is a new version, measured in a log of its own: continuing a log whose rows
    another version of the simulated VLM ran is refused before anything runs, the log untouched."""
    log = tmp_path / "episodes.jsonl"
    key = engine.Key("strategies", "symbolic", "halve_egg", "both", "vlm", 0)
    row = {**results.crashed(key, RuntimeError("an older model's episode"), 1.0), "vlm_version": "vlm-0 (2020-01-01)"}
    log.write_text(json.dumps(row) + "\n")
    # a crashed episode of this version records no versions, and does not stop a log from going on
    assert command.same_version(results.EpisodeLog(_log_of(tmp_path, results.crashed(
        dataclasses.replace(key, world="pybullet"), RuntimeError("x"), 1.0))),
                                "pybullet", "--log") is None
    before = log.read_text()
    assert main(STRATEGIES, [*TASK, "--verify", "both", "--log", str(log), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and err.startswith("strategies: --log: "), err
    assert "vlm-0 (2020-01-01)" in err and "new log" in err
    assert log.read_text() == before and not (tmp_path / "out").exists()
    # report-only reads it as it is: the old version's tables stay writable, a crashed episode's
    # row (no counts) among them
    for experiment, word in ((STRATEGIES, "| both |"), (FAILURES, "crash")):
        assert main(experiment, [*TASK, "--log", str(log), "--out", str(tmp_path / experiment.name),
                                 "--report-only"]) == 0
        assert word in (tmp_path / experiment.name / "table.md").read_text()


def _log_of(tmp_path, row: dict):
    path = tmp_path / "one_row.jsonl"
    path.write_text(json.dumps(row) + "\n")
    return path
