"""Why episodes fail: the failure-mode distribution per verification strategy, situations per
task, and the diagnosis confusion matrix, for every strategy the settings declare.

    .venv/bin/python tools/experiments/failures.py --seeds 200 [--verify both none]

Each failed episode is classed from its report — visual ambiguity, state/access, manipulation,
other, crash — by the rules in :mod:`tools.experiments.measures`. Where the reports' situations
carry ``diagnosis`` and ``diagnosis_truth``, the matrix counts diagnoses (columns) against the
world's cause (rows); where they do not, table.md says so. Writes table.md,
failure_modes.png, situations.png, episodes.jsonl/.csv and run.json under
docs/results/failures/ (``--out``).
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # the checkout's root: tools/, vap_bt/

import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before the tools load numpy)

from tools.experiments import compare, plots, tables  # noqa: E402
from tools.experiments.command import Campaign, Experiment, chosen, main  # noqa: E402
from tools.experiments.measures import FAILURE_MODES, TRAIL, situation_class  # noqa: E402
from tools.experiments.strategies import options, strategies_in  # noqa: E402
from vap_bt.settings import default  # noqa: E402

NO_DIAGNOSIS = "No diagnosis in these reports (their situations carry no `diagnosis`/`diagnosis_truth`)."
#: how many kinds of wrong diagnosis the trail's table lists (the most frequent)
WRONG_KINDS = 15


def report(rows: list[dict], campaign: Campaign) -> str:
    """The three tables and two plots."""
    strategies = [s for s in strategies_in(rows) if compare.runnable(rows, s)]
    mine = {s: [r for r in rows if r["strategy"] == s] for s in strategies}
    shares = {s: [tables.share(sum(r["failure_mode"] == m for r in mine[s]), len(mine[s])) for m in FAILURE_MODES]
              for s in strategies}
    modes = tables.markdown(["strategy", "failed", *FAILURE_MODES],
                            [[s, tables.rate(not r["success"] for r in mine[s]).percent(),
                              *(e.percent() for e in shares[s])] for s in strategies])
    seeds = compare.seeds_per_cell(rows)
    plots.grouped_bars(campaign.out / "failure_modes.png", list(FAILURE_MODES), shares, percent=True,
                       ylabel="share of episodes, %", title=f"Failure modes, {campaign.world} world, {seeds} seeds")
    cells = compare.by(rows, "task", "strategy")
    situations = {s: [tables.mean(r["situations"] for r in cells[(t, s)]) for t in campaign.tasks]
                  for s in strategies}
    plots.grouped_bars(campaign.out / "situations.png", [campaign.tasks[t].replace(" ", "\n", 1) for t in campaign.tasks],
                       situations, ylabel="situations per episode", title=f"Situations per task, {seeds} seeds")
    per_task = tables.markdown(["task", *strategies], [[label, *(situations[s][i].plain(2) for s in strategies)]
                                                       for i, label in enumerate(campaign.tasks.values())])
    return (f"# Failure modes, {campaign.world} world, {seeds} seeds per task and strategy\n\n"
            "Share of all episodes (Wilson 95 % intervals); the classes are defined in "
            "tools/experiments/measures.py.\n\n" + modes + "\n![failure modes](failure_modes.png)\n\n"
            "## Situations per episode, by task (mean, 95 % t interval)\n\n" + per_task
            + "\n![situations](situations.png)\n\n## Diagnosis\n\n" + confusion(rows) + "\n")


def confusion(rows: list[dict]) -> str:
    """How often each strategy's diagnoses match the world's record, and the confusion matrix of
    each (the world's cause by row, the executive's diagnosis by column); or a line saying the
    reports have none. Per strategy, not pooled: the diagnosis rule reads what each strategy's
    checks saw, and a baseline's single answers give it less to go on."""
    strategies = [s for s in strategies_in(rows) if any(r["diagnoses"] for r in rows if r["strategy"] == s)]
    if not strategies:
        return NO_DIAGNOSIS
    pairs = {s: Counter(tuple(p) for r in rows if r["strategy"] == s for p in r["diagnoses"] or ())
             for s in strategies}
    right = {s: tables.share(sum(n for (d, t), n in pairs[s].items() if d == t), sum(pairs[s].values()))
             for s in strategies}
    out = ("Situations whose diagnosis matches the world's record, per strategy:\n\n"
           + tables.markdown(["strategy", "diagnosed right"], [[s, right[s].percent()] for s in strategies]))
    for s in strategies:
        said = sorted({d for d, _ in pairs[s]})
        truths = sorted({t for _, t in pairs[s]})
        out += (f"\n{s}:\n\n" + tables.markdown(["world's cause \\ diagnosis", *said],
                                                 [[t, *(pairs[s][(d, t)] for d in said)] for t in truths]))
        out += wrong_by_class([r for r in rows if r["strategy"] == s])
    return out


def wrong_by_class(rows: list[dict]) -> str:
    """The wrong diagnoses of ``rows`` by what raised the situation (:func:`situation_class`), the
    most frequent first, from the rows' situation trails; nothing where the rows carry none."""
    classed = [(t, situation_class(t)) for r in rows for t in r.get(TRAIL) or ()]
    if not classed:
        return ""
    wrong = Counter((t["truth"], t["diagnosis"], c) for t, c in classed if t["truth"] != t["diagnosis"])
    alike = Counter(c for _, c in classed)
    listed = wrong.most_common(WRONG_KINDS)
    return (f"\nWrong diagnoses by what raised the situation ({sum(wrong.values())} of {len(classed)} situations; "
            f"the {len(listed)} most frequent kinds; \"of its kind\": all situations so raised):\n\n"
            + tables.markdown(["world's cause", "diagnosis", "raised by", "wrong", "of its kind"],
                              [[t, d, c, n, alike[c]] for (t, d, c), n in listed]))


FAILURES = Experiment("failures", __doc__.splitlines()[0], options=options, report=report,
                      configurations=lambda args: [(s, default("viewpoints")) for s in chosen(args.verify, "verify")])

if __name__ == "__main__":
    sys.exit(main(FAILURES))
