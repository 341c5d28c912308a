"""A sighting inside a container belief holds shut is not the lost item: a pybullet episode of
heat_pie where a failed take-out leaves the pie in the fridge and a false positive shows in the
shut oven (vap_bt/bt/executive.py, ``_behind_shut_door``)."""

from __future__ import annotations

import pytest

from vap_bt.app.runner import RunConfig, Session
from vap_bt.sim.natural_failures import KINDS as NATURAL
from vap_bt.taskfile import load

from conftest import TREES


@pytest.mark.slow(seconds=90)
def test_an_item_seen_inside_a_shut_oven_is_not_taken_for_the_lost_one():
    """heat_pie seed 2 in pybullet with injection: the take-out fails, the pie stays in the fridge,
    and a re-survey's detector reports a pie-like false positive where the shut oven stands. Taken
    for the pie it put the pie in the oven: the oven was turned on with no pie in it, and no goal
    check could see the pie ("stuck: could not see whether heated(apple_pie) holds"). No camera
    sees into a shut oven: such a sighting is not the pie."""
    task = load(TREES / "heat_pie.yaml")
    s = Session(task, RunConfig.from_task(task, world="pybullet", verify="both", viewpoints="vlm", transport="inproc"))
    try:
        r = s.episode(2)
    finally:
        s.close()
    drawn = [i for i in r["injected"] if i["kind"] not in NATURAL]  # Table II's, not physics' own failures
    assert any(i["action"] == "takeout" for i in drawn), "the episode this test is about has its take-out fail"
    relocated = [c for c in r["belief_changes"] if c["cause"] == "relocate"]
    assert not any("inside(apple_pie, oven)" in c["added"] for c in relocated), relocated
