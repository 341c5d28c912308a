"""The perception bench's viewpoint statistics (tools/bench/perception.py): the bootstrap interval
of VLM-guided minus greedy viewpoints per resolution, resampling whole episodes."""

from __future__ import annotations

import sys

from conftest import ROOT

sys.path.insert(0, str(ROOT / "tools" / "bench"))
import perception  # noqa: E402


def episode(resolved: int, moves: int) -> dict:
    return {"resolved": resolved, "moves_resolved": moves}


def test_the_same_moves_under_both_strategies_give_an_interval_of_zero():
    pairs = [(episode(3, 4), episode(3, 4)), (episode(2, 2), episode(2, 2))]
    assert perception.bootstrap(pairs) == (0.0, 0.0)


def test_a_strategy_that_always_needs_one_move_more_is_told_apart():
    pairs = [(episode(2, 2), episode(2, 4)) for _ in range(20)]
    lo, hi = perception.bootstrap(pairs)
    assert lo == hi == -1.0


def test_noisy_episodes_give_an_interval_that_holds_the_pooled_difference():
    pairs = [(episode(2, 2 + (i % 3 == 0)), episode(2, 2 + (i % 2 == 0))) for i in range(30)]
    pooled = perception._per_resolution([a for a, _ in pairs]) - perception._per_resolution([b for _, b in pairs])
    lo, hi = perception.bootstrap(pairs)
    assert lo < pooled < hi and lo < 0 < hi


def test_the_bench_counts_what_the_report_counts_and_reused_values_not_at_all():
    """A lean episode's figures: verified and correct are the report's (values looked at or felt),
    the per-relation accuracy only what was looked at; the reused values apart, in neither."""
    from vap_bt.app.runner import RunConfig, Session
    from vap_bt.taskfile import load

    task = load(ROOT / "trees" / "collect_cup.yaml")
    rep = Session(task, RunConfig.from_task(task, world="symbolic", planner="search", protocol="lean")).episode(0)
    f, checks = perception.figures(rep), rep["verifications"]
    reused = sum(v["outcome"] == "reused" for v in checks)
    assert reused and f["reused"] == reused
    assert f["verified"] == sum(v["outcome"] in ("confirmed", "contradicted", "felt") for v in checks)
    looked = [v for v in checks if v["outcome"] in ("confirmed", "contradicted")]
    assert sum(n for _, n in f["settled"].values()) == len(looked)
    assert sum(k for k, _ in f["settled"].values()) == sum(v["value"] == v["truth"] for v in looked)
