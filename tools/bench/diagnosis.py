"""Situation diagnosis: how often the executive's reading of a situation matches the world's record.

Every task file in trees/ (or ``--tasks``), ``--seeds`` seeds each (from ``--first-seed``: a
held-out set of seeds is another range), in the symbolic world with
Table II injection on, the simulated VLM at its calibrated model and, with probability
``--disturbance``, one scripted disturbance per episode. Each situation's ``diagnosis`` (the
executive's, :mod:`vap_bt.bt.diagnosis`) is counted against its ``diagnosis_truth`` (the world's
record, :mod:`vap_bt.sim.situation_truth`) with :func:`vap_bt.report.confusion_matrix`; the share
right and the confusion matrix are printed in markdown, rows the truth and columns the diagnosis.

    python tools/bench/diagnosis.py [--seeds 30] [--first-seed 0] [--tasks boil_water,cut_lemon] [--disturbance 0.5]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.progress import Progress  # noqa: E402
from vap_bt import taskfile  # noqa: E402
from vap_bt.app.runner import RunConfig, Session  # noqa: E402
from vap_bt.report import DIAGNOSES, confusion_matrix  # noqa: E402


def run(paths: list[Path], seeds: int, disturbance: float, first: int = 0) -> list[dict]:
    """Every episode's report: each task of ``paths`` on seeds ``first`` .. ``first + seeds`` - 1."""
    progress, reports = Progress(len(paths) * seeds, "episodes"), []
    for path in paths:
        task = taskfile.load(path)
        session = Session(task, RunConfig.from_task(task, world="symbolic", injection=True, disturbance=disturbance))
        try:
            for seed in range(first, first + seeds):
                reports.append(session.episode(seed))
                progress.step()
        finally:
            session.close()
    return reports


def table(matrix: dict) -> str:
    """The share right and the confusion matrix (rows: truth; columns: diagnosis), in markdown."""
    share = matrix["correct"] / matrix["total"] if matrix["total"] else 0.0
    lines = [f"{matrix['correct']} of {matrix['total']} situations diagnosed as the world's record says ({share:.1%})",
             "", "| truth \\ diagnosis | " + " | ".join(DIAGNOSES) + " |", "|---" * (len(DIAGNOSES) + 1) + "|"]
    lines += [f"| {t} | " + " | ".join(str(matrix["confusion"][t][d]) for d in DIAGNOSES) + " |" for t in DIAGNOSES]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=30, help="seeds per task (default 30)")
    ap.add_argument("--first-seed", type=int, default=0, help="the first seed (default 0)")
    ap.add_argument("--tasks", help="comma-separated task names (default: every file in trees/)")
    ap.add_argument("--disturbance", type=float, default=0.5, help="probability of a disturbance per episode")
    args = ap.parse_args(argv)
    paths = sorted((ROOT / "trees").glob("*.yaml"))
    if args.tasks:
        paths = [p for p in paths if p.stem in set(args.tasks.split(","))]
    print(table(confusion_matrix(run(paths, args.seeds, args.disturbance, args.first_seed))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
