"""The command line: plans, runs, and one clear line with a documented exit code for bad input."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from vap_bt.errors import EXIT_BAD_INPUT, EXIT_UNSOLVABLE

from conftest import DOMAINS, ROOT, TREES


def test_plan_prints_a_plan(cli):
    code, out, _ = cli("plan", DOMAINS / "gripper-domain.pddl", DOMAINS / "gripper-p4.pddl")
    assert code == 0 and "pick(" in out and "drop(" in out


@pytest.mark.parametrize("argv,code,needle", [
    (["plan", DOMAINS / "syntax-error-domain.pddl", DOMAINS / "gripper-p4.pddl"], EXIT_BAD_INPUT,
     "syntax-error-domain.pddl:8"),
    (["plan", DOMAINS / "blocksworld-domain.pddl", DOMAINS / "unsolvable-p.pddl"], EXIT_UNSOLVABLE, "no plan"),
    (["run", DOMAINS / "missing.yaml"], EXIT_BAD_INPUT, "no such task file"),
    (["run", TREES / "collect_cup.yaml", "--domain", "x"], EXIT_BAD_INPUT, "not both"),
    (["run", "--seed", "abc"], EXIT_BAD_INPUT, "invalid int"),
])
def test_bad_input_is_one_line_and_a_documented_code(cli, argv, code, needle):
    got, out, err = cli(*argv)
    assert got == code
    assert needle in err and "Traceback" not in err


def test_installed_command_reports_errors_without_traceback(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: t\ndomain: ../domains/household.pddl\nscene: {rooms: [a]}\ngoal: ['hand_empty']\n")
    exe = ROOT / ".venv" / "bin" / "vap-bt"
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "vap_bt"]
    p = subprocess.run([*cmd, "run", str(bad)], capture_output=True, text=True, timeout=120)
    assert p.returncode == EXIT_BAD_INPUT
    assert "field scene.robot" in p.stderr and "Traceback" not in p.stderr
    assert len(p.stderr.strip().splitlines()) == 1


def test_interrupted_run_still_writes_what_it_knew(cli, tmp_path, monkeypatch):
    """Ctrl-C in the middle of an episode: exit 130, and the report keeps the plans and actions so far."""
    from vap_bt.sim.symbolic import SymbolicWorld

    real = SymbolicWorld.perform
    calls = {"n": 0}

    def perform(self, action, args, ctx):  # the user presses Ctrl-C during the third action
        calls["n"] += 1
        if calls["n"] == 3:
            raise KeyboardInterrupt
        return real(self, action, args, ctx)

    monkeypatch.setattr(SymbolicWorld, "perform", perform)
    code, _, err = cli("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--transport", "inproc",
                       "--report", tmp_path / "r.json", "-q")
    assert code == 130 and "interrupted" in err
    import json

    r = json.loads((tmp_path / "r.json").read_text())
    assert r["interrupted"] and r["reason"] == "interrupted" and not r["success"]
    assert r["plans"] and len(r["actions_executed"]) == 2


def test_run_records_a_rerun_file_over_zenoh(cli, tmp_path):
    """The default run (skill servers over Zenoh) with --rerun save: the recording holds the tree."""
    rrd = tmp_path / "run.rrd"
    code, _, err = cli("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--seed", "8", "--no-injection",
                       "--rerun", "save", rrd)
    assert code == 0, err
    assert rrd.exists() and rrd.stat().st_size > 10_000
    exe = Path(sys.executable).with_name("rerun")  # the rerun CLI installed beside this interpreter
    p = subprocess.run([str(exe), "rrd", "print", str(rrd)], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0 and "tree" in p.stdout  # tests/test_viz.py checks the contents in depth
