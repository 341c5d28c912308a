"""Verification ablation (paper Table III) in the symbolic world: success rate per task for each
verification mode — both, effects only, preconditions only, none — with Table II injection.

Writes a CSV with every episode, a JSON with the parameters needed to rerun, and a bar chart.
Success counts only when the world agrees (``success and goal_satisfied``). Progress (episodes
done, rate, time left) goes to stderr.

    python tools/experiments/verification_ablation.py --seeds 50 --vlm-noise 1 --out docs/figures
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from vap_bt import taskfile  # noqa: E402
from vap_bt.report import versions  # noqa: E402
from vap_bt.app.runner import RunConfig, Session  # noqa: E402
from tools.progress import Progress  # noqa: E402

MODES = ("both", "eff", "pre", "none")
LABELS = {"both": "both (full)", "eff": "effects only", "pre": "preconditions only", "none": "none (closed world)"}


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=50)
    ap.add_argument("--vlm-noise", type=float, default=1.0)
    ap.add_argument("--out", default="docs/figures")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    tasks = [taskfile.load(f) for f in sorted((ROOT / "trees").glob("*.yaml"))]
    rows = []
    progress = Progress(len(tasks) * len(MODES) * args.seeds, "episodes")
    for task in tasks:
        for mode in MODES:
            s = Session(task, RunConfig.from_task(task, world="symbolic", verify=mode, vlm_noise=args.vlm_noise,
                                                  planner="search"))
            for seed in range(args.seeds):
                r = s.episode(seed)
                rows.append({"task": task.name, "paper": task.spec.paper_task, "mode": mode, "seed": seed,
                             "success": int(r["success"] and r["goal_satisfied"]), "claimed": int(r["success"]),
                             "situations": len(r["situations"]), "injected": len(r["injected"]),
                             "replans": r["replans"], "vlm_queries": r["vlm_queries"]})
                progress.step()
    with open(out / "verification_ablation.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    rate = {(t.name, m): np.mean([r["success"] for r in rows if r["task"] == t.name and r["mode"] == m])
            for t in tasks for m in MODES}
    meta = {"command": " ".join(["python", *sys.argv]), "seeds": args.seeds, "vlm": "symbolic",
            "vlm_noise": args.vlm_noise, "injection": "Table II", "world": "symbolic", "versions": versions(),
            "success_rate": {m: round(float(np.mean([rate[(t.name, m)] for t in tasks])), 4) for m in MODES}}
    (out / "verification_ablation.json").write_text(json.dumps(meta, indent=2) + "\n")
    _plot(tasks, rate, meta, out / "verification_ablation.png")
    print(json.dumps(meta["success_rate"], indent=2))
    return 0


def _plot(tasks, rate, meta, path: Path) -> None:
    names = [f"{t.spec.paper_task}\n{t.name.replace('_', ' ')}" for t in tasks] + ["mean"]
    x = np.arange(len(names))
    width = 0.2
    fig, ax = plt.subplots(figsize=(12, 4.2), dpi=110)
    for i, m in enumerate(MODES):
        vals = [rate[(t.name, m)] for t in tasks] + [meta["success_rate"][m]]
        ax.bar(x + (i - 1.5) * width, np.array(vals) * 100, width, label=LABELS[m])
    ax.set_xticks(x, names, fontsize=8)
    ax.set_ylabel("success (world's truth), %")
    ax.set_ylim(0, 105)
    ax.set_title(f"Verification ablation, symbolic world, Table II injection, VLM noise {meta['vlm_noise']}, "
                 f"{meta['seeds']} seeds per bar", fontsize=10)
    ax.legend(ncol=4, fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.2), frameon=False)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)


if __name__ == "__main__":
    sys.exit(main())
