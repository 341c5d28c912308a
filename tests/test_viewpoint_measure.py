"""The H2 measure (:mod:`vap_bt.viewpoint_measure`): viewpoints per uncertain check, resolution
rate and settled accuracy, read off a report — on reports written by hand, and on a real
symbolic episode's."""

from __future__ import annotations

import pytest

from vap_bt.app.runner import Session
from vap_bt.settings import RunConfig
from vap_bt.taskfile import load
from vap_bt.viewpoint_measure import pooled, viewpoint_measure

from conftest import TREES


def check(first_settled, viewpoints=0, outcome="confirmed", basis="vlm", value=True, truth=True) -> dict:
    """One verification as the report writes it, with what the measure reads."""
    return {"phase": "pre", "action": "a", "predicate": "on(cup, table)", "first_settled": first_settled,
            "viewpoints": viewpoints, "outcome": outcome, "basis": basis, "value": value, "truth": truth}


def report(strategy: str, *verifications: dict, budget: int = 3) -> dict:
    return {"config": {"viewpoints": strategy, "budget": budget}, "verifications": list(verifications)}


def test_only_checks_whose_first_view_did_not_decide_count_and_an_unresolved_one_is_charged_k():
    rep = report("vlm",
                 check(True),  # the first view decided: not uncertain
                 check(None, outcome="reused", basis="reused"),  # nothing looked at
                 check(False, viewpoints=1),  # resolved with one move
                 check(False, viewpoints=2, outcome="unsettled", basis="belief"),  # unresolved: charged K
                 check(False, viewpoints=1, outcome="felt", basis="proprioception"),  # the gripper's, not a view's
                 check(False, viewpoints=2, outcome="contradicted", value=False, truth=True))  # resolved, wrong
    m = viewpoint_measure(rep)
    assert m["uncertain"] == 4 and m["resolved"] == 2
    assert [c["charged"] for c in m["checks"]] == [1, 3, 3, 2]
    assert m["viewpoints_per_check"] == pytest.approx(9 / 4)
    assert m["resolution_rate"] == pytest.approx(0.5) and m["settled_accuracy"] == pytest.approx(0.5)


def test_greedy_all_is_charged_what_it_visited_resolved_or_not():
    rep = report("greedy-all", check(False, viewpoints=4, outcome="unsettled", basis="belief"),
                 check(False, viewpoints=6))
    m = viewpoint_measure(rep)
    assert [c["charged"] for c in m["checks"]] == [4, 6] and m["viewpoints_per_check"] == 5.0


def test_nothing_uncertain_divides_by_nothing_and_pooling_adds_the_checks():
    empty = viewpoint_measure(report("vlm", check(True)))
    assert empty["uncertain"] == 0 and empty["viewpoints_per_check"] is None and empty["settled_accuracy"] is None
    one = viewpoint_measure(report("vlm", check(False, viewpoints=1)))
    two = viewpoint_measure(report("vlm", check(False, viewpoints=2, outcome="unsettled", basis="belief"),
                                   check(False, viewpoints=1, truth=None)))
    both = pooled([empty, one, two])
    assert both["episodes"] == 3 and both["uncertain"] == 3 and both["viewpoints_per_check"] == pytest.approx(5 / 3)
    assert both["scored"] == 1 and both["settled_accuracy"] == 1.0  # a check without a truth is not scored


@pytest.mark.parametrize("strategy", ["vlm", "greedy-all"])
def test_on_a_real_episode_the_measure_reads_what_the_checks_did(strategy):
    task = load(TREES / "boil_water.yaml")
    rep = Session(task, RunConfig.from_task(task, world="symbolic", planner="search", viewpoints=strategy)).episode(3)
    m = viewpoint_measure(rep)
    uncertain = [v for v in rep["verifications"] if v["first_settled"] is False]
    assert m["uncertain"] == len(uncertain) > 0 and m["strategy"] == strategy
    for v, c in zip(uncertain, m["checks"]):
        assert c["viewpoints"] == v["viewpoints"] == sum(bool(r["moved"]) for r in v["rounds"])
        assert c["resolved"] == (v["outcome"] in ("confirmed", "contradicted") and v["basis"] == "vlm")
    if strategy == "greedy-all":  # the symbolic world refuses no direction: the whole round, every time
        assert {c["charged"] for c in m["checks"]} == {6}
    else:
        assert all(c["charged"] == (c["viewpoints"] if c["resolved"] else 3) for c in m["checks"])
        assert all(c["viewpoints"] <= 3 for c in m["checks"])
    settled = [v for v in rep["verifications"] if v["first_settled"]]
    assert settled and all(v["viewpoints"] == 0 and len(v["rounds"]) == 1 for v in settled)
