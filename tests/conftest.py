"""Shared paths and helpers for the test suite."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TREES = ROOT / "trees"
DOMAINS = Path(__file__).resolve().parent / "domains"
HOUSEHOLD = ROOT / "domains" / "household.pddl"
PAPER = ROOT.parent / "shared" / "paper" / "vap-tamp.tex"

LITERATURE = [
    ("blocksworld-domain.pddl", "blocksworld-p6.pddl"),
    ("gripper-domain.pddl", "gripper-p4.pddl"),
    ("logistics-domain.pddl", "logistics-p1.pddl"),
]
HOUSEHOLD_TASKS = sorted(p.name for p in TREES.glob("*.yaml"))


@pytest.fixture
def cli(capsys):
    """Run ``vap-bt`` in this process; returns (exit code, stdout, stderr)."""
    from vap_bt.cli import main

    def run(*argv: str):
        code = main([str(a) for a in argv])
        out, err = capsys.readouterr()
        return code, out, err

    return run


def load_json(text: str) -> dict:
    return json.loads(text)
