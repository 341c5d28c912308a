"""Start-up of the ``vap-bt`` command: this checkout beside a baseline checkout, in one run.

Every command pays a fixed cost before it does anything: the interpreter, the imports, the parser.
This times whole processes from outside — ``python -m vap_bt`` from its start to its exit — for
``--help``, ``tree``, ``plan`` and a symbolic ``run``, each run alternately from this checkout and
from the baseline (``PYTHONPATH`` set to each; one interpreter for both), so that a machine whose
speed drifts during the call moves both sides alike. After one warm-up run of each, it prints per
command the min and median wall seconds of each side and the ratio this/baseline: of the medians,
and the median of the ratios taken pair by pair; then the median CPU seconds (user + system, the
command's child processes included: Fast Downward), which a machine shared with other work
inflates less than the wall time. Beside the wall time it reports what the command
itself says it spent on its work — ``plan``: the planner's own seconds (Fast Downward and the
validator) from its last stderr line; ``run``: the episode's ``wall_s`` from its JSON summary —
so that start-up and work can be told apart::

    git worktree add --detach ../base <commit>
    python tools/bench/startup.py --baseline ../base [--runs 9]

A command that fails (a non-zero exit) stops the benchmark with its stderr: a figure for a
command that did not do its work would measure nothing.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

#: the commands timed: a name and the arguments after ``python -m vap_bt`` (paths relative to a checkout)
COMMANDS = {
    "help": ["--help"],
    "tree": ["tree", "trees/collect_cup.yaml"],
    "plan": ["plan", "tests/domains/gripper-domain.pddl", "tests/domains/gripper-p4.pddl"],
    "run": ["run", "trees/collect_cup.yaml", "--world", "symbolic", "-q", "--json"],
}
_PLANNER_LINE = re.compile(r"; \d+ actions, cost \S+, \S+, ([0-9.]+) s")


@dataclass
class Side:
    """One checkout's timings of one command: wall seconds, and the work the command reported."""

    tree: Path
    wall: list[float] = field(default_factory=list)
    cpu: list[float] = field(default_factory=list)
    work: list[float] = field(default_factory=list)


def run_once(tree: Path, args: list[str]) -> tuple[float, float, float | None]:
    """One whole process of ``vap-bt ARGS`` from checkout ``tree``: its wall and CPU seconds and
    the work seconds it reports itself (None when it reports none)."""
    env = {**os.environ, "PYTHONPATH": str(tree)}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "vap_bt", *args], cwd=tree, env=env,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f"vap-bt {' '.join(args)} in {tree} exited {done.returncode}:\n{done.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, reported_work(args, done.stdout, done.stderr)


def reported_work(args: list[str], stdout: str, stderr: str) -> float | None:
    """The seconds a command says its own work took: the planner's, or the episode's."""
    if args[0] == "plan":
        found = _PLANNER_LINE.search(stderr)
        return float(found.group(1)) if found else None
    if args[0] == "run":
        return float(json.loads(stdout)["wall_s"])
    return None


def measure(args: list[str], sides: tuple[Side, Side], runs: int) -> None:
    """``runs`` alternating runs of each side (after one warm-up each), starting with a different
    side each round so neither always runs first."""
    for side in sides:
        run_once(side.tree, args)
    for k in range(runs):
        for side in (sides if k % 2 == 0 else sides[::-1]):
            wall, cpu, work = run_once(side.tree, args)
            side.wall.append(wall)
            side.cpu.append(cpu)
            if work is not None:
                side.work.append(work)


def _fmt(values: list[float]) -> str:
    return f"{min(values):.2f} / {statistics.median(values):.2f}" if values else "–"


def row(label: str, this: Side, base: Side) -> str:
    """A table row: wall min / median of each side, the ratio of medians and the median pairwise
    ratio; CPU medians and their ratio; the work each side reported (min / median)."""
    pairwise = statistics.median(a / b for a, b in zip(this.wall, base.wall))
    ratio = statistics.median(this.wall) / statistics.median(base.wall)
    cpu_base, cpu_this = statistics.median(base.cpu), statistics.median(this.cpu)
    return (f"| {label} | {_fmt(base.wall)} | {_fmt(this.wall)} | {ratio:.2f} | {pairwise:.2f} "
            f"| {cpu_base:.2f} / {cpu_this:.2f} ({cpu_this / cpu_base:.2f}) | {_fmt(base.work)} | {_fmt(this.work)} |")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--baseline", required=True, type=Path, help="a checkout of the baseline commit")
    ap.add_argument("--runs", type=int, default=9, help="timed runs of each side per command (default 9)")
    ap.add_argument("--only", action="append", choices=list(COMMANDS), help="time only these commands")
    args = ap.parse_args(argv)
    base_tree = args.baseline.resolve()
    if not (base_tree / "vap_bt" / "__main__.py").is_file():
        ap.error(f"{base_tree} is not a vap_bt checkout with a __main__")
    print(f"this: {ROOT}\nbaseline: {base_tree}\n{args.runs} alternating runs per side after one warm-up each; "
          f"wall seconds of the whole process\n")
    print("| command | baseline wall min / median s | this wall min / median s | ratio of medians "
          "| median pairwise ratio | CPU s median, baseline / this (ratio) | baseline work s | this work s |")
    print("|---|---|---|---|---|---|---|---|")
    for name in args.only or COMMANDS:
        sides = (Side(ROOT), Side(base_tree))
        measure(COMMANDS[name], sides, args.runs)
        print(row(f"`vap-bt {' '.join(COMMANDS[name])}`", *sides), flush=True)
    print("\nwork: plan, the planner's own seconds (Fast Downward and the validator, its stderr line); "
          "run, the episode's wall_s (its JSON summary)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
