"""Grounding cost: vap_bt's grounder beside unified-planning's and Fast Downward's translator.

The executive grounds every action instance the rigid facts allow once per object set
(:func:`vap_bt.domain.grounding.ground`, for the in-process replanner). Until 2ca9117 the
instances came from unified-planning's ``GrounderHelper`` — its parameter enumeration pruned by
static fluents, then ``ground_action`` per instance; now from vap_bt's own lifted templates
(:mod:`vap_bt.domain.instances`). This measures, in one run on the same problems:

* **ours**: ``ground(task)`` (the problem already parsed);
* **unified-planning**: the old path — ``get_possible_parameters`` with pruning, ``ground_action``
  per candidate (``raises`` where its pruning fails: the bug of tests/domains/up-grounder-*);
* **Fast Downward**: its translator alone (``fast-downward.py --translate``: parsing,
  invariant synthesis, relaxed reachability and grounding, in its own process; it grounds from the
  initial state, which the executive cannot: it replans from corrected belief).

    python tools/bench/grounding.py [DOMAIN ...]     # folders under tools/bench/ipc

Prints a markdown table with the instance counts and the ratios ours / unified-planning and
ours / Fast Downward. Progress goes to stderr.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.bench.pddl_sweep import IPC, fast_downward_command  # noqa: E402
from tools.progress import Progress  # noqa: E402
from vap_bt.domain.grounding import ground  # noqa: E402
from vap_bt.domain.pddl import load_task  # noqa: E402

DEFAULT = ["gripper", "blocks", "logistics00", "driverlog", "elevators-opt08-strips", "depot",
           "nomystery-opt11-strips", "pegsol-08-strips", "scanalyzer-08-strips", "visitall-opt11-strips"]


def ours(task) -> tuple[float, int]:
    t0 = time.perf_counter()
    g = ground(task)
    return time.perf_counter() - t0, len(g.actions)


def unified_planning(task) -> tuple[float | None, int | None]:
    """The old path, on the problem with quantifiers compiled away (as the instances see it)."""
    from unified_planning.engines.compilers import GrounderHelper

    problem = task.knowledge.instances.problem
    t0 = time.perf_counter()
    pruning, exact = GrounderHelper(problem, prune_actions=True), GrounderHelper(problem, prune_actions=False)
    n = 0
    try:
        for action in problem.actions:
            for params in pruning.get_possible_parameters(action):
                exact.ground_action(action, params)
                n += 1
    except ValueError:
        return None, None
    return time.perf_counter() - t0, n


def fast_downward(domain: Path, problem: Path) -> tuple[float, int]:
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        subprocess.run(fast_downward_command(tmp, "--translate", str(domain), str(problem)),
                       capture_output=True, check=True, cwd=tmp)
        seconds = time.perf_counter() - t0
        operators = len(re.findall(r"^begin_operator$", (Path(tmp) / "output.sas").read_text(), flags=re.M))
    return seconds, operators


def fmt(x: float | None, unit: str = " s") -> str:
    return "raises" if x is None else f"{x:.2f}{unit}"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("domains", nargs="*", default=DEFAULT)
    args = ap.parse_args()
    rows = []
    progress = Progress(total=len(args.domains), unit="domains", every_s=0)
    for name in args.domains:
        domain, problem = IPC / name / "domain.pddl", IPC / name / "problem.pddl"
        task = load_task(domain, problem)
        (t_ours, n_ours), (t_up, n_up), (t_fd, n_fd) = ours(task), unified_planning(task), fast_downward(domain, problem)
        rows.append((name, n_ours, t_ours, n_up, t_up, n_fd, t_fd))
        progress.step(note=name)
    print("| domain | ours: instances | ours | unified-planning: instances | unified-planning | FD translator: "
          "operators | FD translator | ours / UP | ours / FD |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, n_ours, t_ours, n_up, t_up, n_fd, t_fd in rows:
        ratio_up = "—" if t_up is None else f"{t_ours / t_up:.3f}"
        print(f"| {name} | {n_ours} | {fmt(t_ours)} | {n_up if n_up is not None else '—'} | {fmt(t_up)} | {n_fd} | "
              f"{fmt(t_fd)} | {ratio_up} | {t_ours / t_fd:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
