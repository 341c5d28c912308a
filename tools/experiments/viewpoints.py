"""Viewpoint strategies compared (paper H2): how many viewpoints an uncertain check needs, for
every viewpoint strategy the settings declare (``RunConfig.viewpoints``, read at run time),
verification ``both``.

    .venv/bin/python tools/experiments/viewpoints.py --seeds 200

An uncertain check is one whose first view did not settle it; its viewpoints are the views it
moved to after the first, an unresolved check charged the full budget K
(:mod:`tools.experiments.measures` has the definition). Beside the mean: the resolution rate, the
settled accuracy (a resolved check's value against the world's truth), and the paired
difference of each strategy to ``vlm`` (per task and seed: the mean over the episode's uncertain
checks). Writes table.md, viewpoints.png (histogram, mean ± sd), episodes.jsonl/.csv and
run.json under docs/results/viewpoints/ (``--out``).
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the checkout's root: tools/, vap_bt/

import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before the tools load numpy)

from tools.experiments import compare, plots, tables  # noqa: E402
from tools.experiments.command import Campaign, Experiment, chosen, main  # noqa: E402

REFERENCE = "vlm"
STRATEGY = "both"


def views(rows: list[dict]) -> list[int]:
    """The viewpoints of every uncertain check of the rows."""
    return [v for r in rows for v in r["uncertain_viewpoints"] or ()]


def per_episode(rows: list[dict]) -> dict[tuple, float]:
    """(task, seed) -> the mean viewpoints over that episode's uncertain checks (episodes with some)."""
    return {(r["task"], r["seed"]): statistics.fmean(r["uncertain_viewpoints"])
            for r in rows if r["uncertain_viewpoints"]}


def report(rows: list[dict], campaign: Campaign) -> str:
    """Viewpoints per uncertain check, resolution and settled accuracy per strategy; the paired
    difference to vlm; per task means; the histogram and mean ± sd plot."""
    kinds = sorted({r["viewpoints"] for r in rows}, key=lambda k: (k != REFERENCE, k))
    mine = {k: [r for r in rows if r["viewpoints"] == k and r["runnable"] and not r["error"]] for k in kinds}
    summary = []
    for k in kinds:
        vs = views(mine[k])
        resolved = sum(r["uncertain_resolved"] for r in mine[k])
        correct = sum(r["uncertain_correct"] for r in mine[k])
        summary.append([k, tables.mean(vs).plain(2), f"{statistics.stdev(vs):.2f}" if len(vs) > 1 else "–",
                        tables.share(resolved, len(vs)).percent(), tables.share(correct, resolved).percent(),
                        tables.rate(r["success"] for r in mine[k]).percent()])
    out = tables.markdown(["viewpoints", "viewpoints per uncertain check", "sd", "resolved", "settled accuracy",
                           "episode success"], summary)
    diffs = [[f"{k} − {REFERENCE}", tables.paired(per_episode(mine[k]), per_episode(mine[REFERENCE])).plain(2)]
             for k in kinds if k != REFERENCE and REFERENCE in mine]
    if diffs:
        out += ("\nPaired difference in viewpoints per uncertain check (per task and seed: the episode's mean), "
                "95 % t interval:\n\n" + tables.markdown(["difference", "viewpoints"], diffs))
    cells = compare.by([r for k in kinds for r in mine[k]], "task", "viewpoints")
    out += "\nViewpoints per uncertain check by task:\n\n" + tables.markdown(
        ["task", *kinds], [[label, *(tables.mean(views(cells[(t, k)])).plain(2) for k in kinds)]
                           for t, label in campaign.tasks.items()])
    title = f"Viewpoints per uncertain check, {campaign.world} world, {compare.seeds_per_cell(rows)} seeds per task"
    plots.histogram_and_mean(campaign.out / "viewpoints.png", {k: views(mine[k]) for k in kinds},
                             xlabel="viewpoints per uncertain check", title=title)
    return f"# {title}\n\n{out}\n![viewpoints](viewpoints.png)\n"


def options(ap) -> None:
    """``--viewpoints``: the viewpoint strategies to run (default every one the settings declare)."""
    ap.add_argument("--viewpoints", nargs="+", metavar="KIND",
                    help="viewpoint strategies to run (default: every value of the settings' viewpoints)")


VIEWPOINTS = Experiment("viewpoints", __doc__.splitlines()[0], options=options, report=report,
                        configurations=lambda args: [(STRATEGY, k) for k in chosen(args.viewpoints, "viewpoints")])

if __name__ == "__main__":
    sys.exit(main(VIEWPOINTS))
