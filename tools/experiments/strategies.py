"""Strategies compared (paper H1): success per task for every verification strategy the settings
declare (``RunConfig.verify``, read at run time), its execution time and VLM queries.

    .venv/bin/python tools/experiments/strategies.py --seeds 200 [--verify both none ...]

A strategy that cannot run in this world or with this VLM backend (its episodes raise the
project's InputError, e.g. a planner that needs a real VLM) is "not runnable" in the table,
never estimated. Writes table.md (success with Wilson 95 % intervals, paired differences to
``both``; mean wall time and VLM queries with t intervals), strategies.png, success_vs_time.png,
episodes.jsonl/.csv and run.json under docs/results/strategies/ (``--out``).
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the checkout's root: tools/, vap_bt/

import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before the tools load numpy)

from tools.experiments import compare, plots, tables  # noqa: E402
from tools.experiments.command import Campaign, Experiment, chosen, main  # noqa: E402
from vap_bt.settings import default  # noqa: E402

REFERENCE = "both"


def strategies_in(rows: list[dict]) -> list[str]:
    """The strategies the rows ran, in the order the settings declare them (any others after)."""
    ran = {r["strategy"] for r in rows}
    declared = [s for s in chosen(None, "verify") if s in ran]
    return declared + sorted(ran - set(declared))


def report(rows: list[dict], campaign: Campaign) -> str:
    """Success per task and strategy, the paired differences, and cost per strategy."""
    strategies = strategies_in(rows)
    labels = {s: s for s in strategies}
    title = f"Strategies, {campaign.world} world, {compare.seeds_per_cell(rows)} seeds per bar"
    compare.success_bars(campaign.out / "strategies.png", rows, campaign.tasks, strategies, labels, title)
    ran = [s for s in strategies if compare.runnable(rows, s)]
    cost = {s: [r for r in rows if r["strategy"] == s] for s in ran}
    plots.success_vs_time(campaign.out / "success_vs_time.png",
                          {s: (tables.mean(r["wall_s"] for r in cost[s]), tables.rate(r["success"] for r in cost[s]))
                           for s in ran}, title=f"Success against execution time, {campaign.world} world")
    costs = tables.markdown(
        ["strategy", "wall time per episode, s", "VLM queries per episode", "claimed, world denies"],
        [[s, tables.mean(r["wall_s"] for r in cost[s]).plain(3), tables.mean(r["vlm_queries"] for r in cost[s]).plain(1),
          tables.rate(r["claimed_denied"] for r in cost[s]).percent()] for s in ran])
    reference = REFERENCE if REFERENCE in strategies else strategies[0]
    return (f"# {title}\n\n" + compare.success_table(rows, campaign.tasks, strategies, reference)
            + "\n![strategies](strategies.png)\n\n" + costs + "\n![success vs time](success_vs_time.png)\n")


def options(ap) -> None:
    """``--verify``: the strategies to run (default every one the settings declare)."""
    ap.add_argument("--verify", nargs="+", metavar="STRATEGY",
                    help="strategies to run (default: every value of the settings' verify)")


STRATEGIES = Experiment("strategies", __doc__.splitlines()[0], options=options, report=report,
                        configurations=lambda args: [(s, default("viewpoints")) for s in chosen(args.verify, "verify")])

if __name__ == "__main__":
    sys.exit(main(STRATEGIES))
