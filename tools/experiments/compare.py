"""Strategies compared over tasks: success per task and strategy with Wilson intervals, the
paired difference of each strategy to a reference, and the grouped bar chart (paper Table III).

A strategy whose episodes could not run in this world or with this VLM backend (their rows say
``runnable: false``) is written "not runnable" in the table and left out of the bars; nothing is
estimated for it.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from tools.experiments import plots, tables
from tools.experiments.tables import Estimate

NOT_RUNNABLE = "not runnable"


def by(rows: list[dict], *fields: str) -> dict[tuple, list[dict]]:
    """Rows grouped by the values of ``fields`` (in the rows' order)."""
    out: dict[tuple, list[dict]] = defaultdict(list)
    for r in rows:
        out[tuple(r[f] for f in fields)].append(r)
    return out


def runnable(rows: list[dict], strategy: str) -> bool:
    """Whether a strategy's episodes ran (a strategy with no rows has not been run: False)."""
    mine = [r for r in rows if r["strategy"] == strategy]
    return bool(mine) and all(r["runnable"] for r in mine)


def success_table(rows: list[dict], tasks: dict[str, str], strategies: list[str], reference: str,
                  labels: dict[str, str] | None = None) -> str:
    """Markdown: one row per task and one for all of them, one column per strategy (success with
    its interval); then each strategy's paired difference to ``reference`` over (task, seed)."""
    labels = labels or {s: s for s in strategies}
    cells = by(rows, "task", "strategy")

    def cell(task_rows: list[dict], strategy: str) -> str:
        if not runnable(rows, strategy):
            return NOT_RUNNABLE
        return tables.rate(r["success"] for r in task_rows).percent()

    body = [[tasks[t], *(cell(cells[(t, s)], s) for s in strategies)] for t in tasks]
    body.append(["**all**", *(cell([r for r in rows if r["strategy"] == s], s) for s in strategies)])
    out = tables.markdown(["task", *(labels[s] for s in strategies)], body)
    diffs = [[labels[s], difference(rows, s, reference)] for s in strategies if s != reference]
    if diffs:
        out += (f"\nPaired difference in success to {labels[reference]}, percentage points, per (task, seed), "
                f"mean with 95 % t interval:\n\n" + tables.markdown(["strategy", f"− {labels[reference]}"], diffs))
    reasons = {r["reason"] for r in rows if not r["runnable"]}
    if reasons:
        out += "\n" + "\n".join(f"- {why}" for why in sorted(reasons)) + "\n"
    return out


def difference(rows: list[dict], strategy: str, reference: str, measure: str = "success") -> str:
    """``strategy − reference`` of ``measure``, paired by (task, seed), in points (a table cell)."""
    if not (runnable(rows, strategy) and runnable(rows, reference)):
        return NOT_RUNNABLE
    a, b = ({(r["task"], r["seed"]): 100 * r[measure] for r in rows if r["strategy"] == s}
            for s in (strategy, reference))
    return tables.paired(a, b).plain(1)


def success_bars(path: Path, rows: list[dict], tasks: dict[str, str], strategies: list[str],
                 labels: dict[str, str], title: str) -> None:
    """Grouped bars: success per task (and overall) for each runnable strategy, 95 % Wilson bars."""
    cells = by(rows, "task", "strategy")
    series: dict[str, list[Estimate]] = {
        labels[s]: [*(tables.rate(r["success"] for r in cells[(t, s)]) for t in tasks),
                    tables.rate(r["success"] for r in rows if r["strategy"] == s)]
        for s in strategies if runnable(rows, s)}
    plots.grouped_bars(path, [*(tasks[t].replace(" ", "\n", 1) for t in tasks), "all"], series,
                       ylabel="success (world's truth), %", title=title, percent=True)


def seeds_per_cell(rows: list[dict]) -> str:
    """``200 seeds per cell`` (or a range when the cells differ)."""
    counts = {len(v) for v in by(rows, "task", "strategy", "viewpoints").values()}
    return f"{min(counts)}–{max(counts)}" if len(counts) > 1 else f"{next(iter(counts), 0)}"
