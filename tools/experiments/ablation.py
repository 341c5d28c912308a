"""Verification ablation (paper Table III): success per task for each verification mode — both,
effects only, preconditions only, none (the closed-world baseline) — with Table II injection.

    .venv/bin/python tools/experiments/ablation.py --seeds 200 --workers 2

Writes episodes.jsonl/.csv, table.md (success with Wilson 95 % intervals, each mode's paired
difference to both), table3.png and run.json under docs/results/ablation/ (``--out``). The
options common to every experiment are in :mod:`tools.experiments.command`.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the checkout's root: tools/, vap_bt/

import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before the tools load numpy)

from tools.experiments import compare  # noqa: E402
from tools.experiments.command import Campaign, Experiment, main  # noqa: E402
from vap_bt.settings import default  # noqa: E402

MODES = ("both", "eff", "pre", "none")
LABELS = {"both": "both (full)", "eff": "effects only", "pre": "preconditions only", "none": "none (closed world)"}


def report(rows: list[dict], campaign: Campaign) -> str:
    """Table III and its bar chart."""
    title = (f"Verification ablation, {campaign.world} world, Table II injection, "
             f"{compare.seeds_per_cell(rows)} seeds per bar")
    compare.success_bars(campaign.out / "table3.png", rows, campaign.tasks, list(MODES), LABELS, title)
    return (f"# {title}\n\n" + compare.success_table(rows, campaign.tasks, list(MODES), "both", LABELS)
            + "\n![Table III](table3.png)\n")


ABLATION = Experiment("ablation", __doc__.splitlines()[0],
                      configurations=lambda args: [(mode, default("viewpoints")) for mode in MODES], report=report)

if __name__ == "__main__":
    sys.exit(main(ABLATION))
