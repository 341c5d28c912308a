"""The H2 bench of structural cases (tools/bench/viewpoint_cases.py): each strategy's check
starts from the same snapshot, so the same VLM seed gives the same first picture and answers —
the pairing its differences rest on — and greedy-all visits every direction the camera service
reaches."""

from __future__ import annotations

import pytest

from tools.bench.viewpoint_cases import CASES, CaseBench
from vap_bt.perception.viewpoints import AROUND_ORDER, STRATEGIES


@pytest.mark.slow  # 12-17 s: one pybullet household, three checks
def test_every_strategy_starts_from_the_same_picture_and_greedy_all_visits_what_the_camera_reaches():
    bench = CaseBench(CASES["occluder"])
    try:
        runs = {s: bench.check(s, 0) for s in STRATEGIES}
    finally:
        bench.close()
    firsts = {s: {k: v["rounds"][0][k] for k in ("answers", "sufficient", "identified")} for s, v in runs.items()}
    assert firsts["vlm"] == firsts["greedy"] == firsts["greedy-all"]
    assert all(v["first_settled"] is False for v in runs.values())  # the bowl hides the plate
    g = runs["greedy-all"]
    moved = [r["direction"] for r in g["rounds"] if r["moved"]]
    refused = [d for r in g["rounds"] for d in r.get("refused", [])]
    assert sorted(moved + refused) == sorted(AROUND_ORDER) and g["viewpoints"] == len(moved) == len(g["rounds"]) - 1
    assert all(v["viewpoints"] <= 3 for s, v in runs.items() if s != "greedy-all")
