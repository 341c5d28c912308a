"""The world logs the robot's own actions that fail by physics alone (:mod:`vap_bt.sim.natural_failures`),
so that the situations they raise are scored as execution failures, not as perception errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from vap_bt import taskfile
from vap_bt.domain.atoms import Atom
from vap_bt.sim.natural_failures import DROPPED, FAILED, NaturalFailures
from vap_bt.sim.situation_truth import Raised, situation_truths
from vap_bt.world import InjectedSituation

ROOT = Path(__file__).resolve().parents[1]
KNOWLEDGE = taskfile.load(ROOT / "trees" / "boil_water.yaml").planning.knowledge


class World:
    """A world's truth as a set of atoms and the item in the hand, changed by the test."""

    def __init__(self, *atoms: str, held: str | None = None) -> None:
        self.atoms = {Atom.parse(a) for a in atoms}
        self.hand = held

    def watcher(self) -> NaturalFailures:
        return NaturalFailures(lambda a: a in self.atoms, lambda: self.hand, KNOWLEDGE.ground)


GRASP_PRE = ("inview(cup)", "hand_empty", "reachable(cup)", "on(cup, counter)", "in_room(cup, kitchen)")
GRASP = ("grasp", ("cup", "counter", "kitchen"))


def run(world: World, action, then=lambda w: None, log=None, step=3) -> list[InjectedSituation]:
    log = [] if log is None else log
    nf = world.watcher()
    nf.begin(*action, step)
    then(world)
    nf.end(log)
    return log


def test_a_held_item_lost_during_an_action_not_meant_to_release_it_is_logged():
    w = World("inview(microwave)", "openable(microwave)", "holding(cup)", held="cup")

    def lose(w):
        w.hand = None

    log = run(w, ("open", ("microwave",)), lose)
    assert [(e.kind, e.affected, e.step, e.action, e.source) for e in log] == [(DROPPED, ("cup",), 3, "open", "natural")]


def test_an_item_the_action_puts_down_is_no_drop():
    w = World("holding(cup)", "inview(microwave)", "open(microwave)", "robot_in(kitchen)",
              "in_room(microwave, kitchen)", held="cup")

    def put(w):
        w.hand = None
        w.atoms = (w.atoms - {Atom.parse("holding(cup)")}) | {Atom.parse(a) for a in (
            "inside(cup, microwave)", "in_room(cup, kitchen)", "hand_empty")}

    assert run(w, ("placein", ("cup", "microwave", "kitchen")), put) == []


def test_putting_down_a_thing_taken_for_another_is_no_drop():
    """The hand holds a mug the robot took for the cup: placing "the cup" lets go of the mug."""
    w = World("holding(mug)", held="mug")

    def put(w):
        w.hand = None

    assert run(w, ("placeon", ("cup", "counter", "kitchen")), put) == []


def test_a_feasible_action_whose_effect_did_not_happen_is_logged():
    w = World(*GRASP_PRE)  # the fingers miss: nothing changes
    log = run(w, GRASP)
    assert [(e.kind, e.affected, e.source) for e in log] == [(FAILED, ("cup",), "natural")]


def test_a_feasible_action_that_did_what_it_should_is_not_logged():
    w = World(*GRASP_PRE)

    def take(w):
        w.hand = "cup"
        w.atoms = (w.atoms - {Atom.parse(a) for a in ("hand_empty", "on(cup, counter)", "in_room(cup, kitchen)")}) \
            | {Atom.parse("holding(cup)")}

    assert run(w, GRASP, take) == []


@pytest.mark.parametrize("false", GRASP_PRE)
def test_an_action_the_world_did_not_allow_is_no_execution_failure(false):
    """Belief was wrong (a precondition false as it began): the symbolic world's "nothing to act on"."""
    w = World(*(a for a in GRASP_PRE if a != false))
    assert run(w, GRASP) == []


def test_a_failure_table_ii_logged_for_the_action_is_not_logged_again():
    w = World(*GRASP_PRE)
    drawn = InjectedSituation("grasp", GRASP[1], "grasp_fails_object_unchanged", 3, ("cup",))
    assert run(w, GRASP, log=[drawn]) == [drawn]


def test_where_the_robot_stands_and_what_it_sees_are_no_action_outcome():
    """A find that leaves the thing a few pixels short of the camera's threshold did not fail."""
    w = World("robot_in(kitchen)", "in_room(cup, kitchen)", "robot_at(counter)")
    assert run(w, ("find", ("counter", "cup", "kitchen"))) == []


def test_a_situation_the_logged_failure_touches_is_scored_an_execution_failure():
    w = World(*GRASP_PRE)
    log = run(w, GRASP)
    truths = situation_truths([Raised(frozenset({"cup", "counter", "kitchen"}), len(log))], log)
    assert [t.diagnosis for t in truths] == ["execution_failure"]


@pytest.mark.slow
def test_the_pybullet_world_logs_what_its_actions_failed_to_do(tmp_path):
    """Wired into the world's action hooks: the knife the robot starts with, lost during a find
    (the hand lets go here; a slipping grip does the same), and an open of the drawer in view
    that never took its handle, are in ``injected()``; a find that keeps the knife logs nothing."""
    from driver_scripts import kitchen, world_of

    scene = kitchen({"counter": "type: surface", "drawer": "type: container, state: closed"},
                    {"knife": "type: knife, place: held"})
    w = world_of(tmp_path, "kitchen", scene)
    find = ("floor_kitchen", "drawer", "kitchen")
    try:
        w.begin_action("find", find)
        w.end_action("find", find)
        assert w.injected() == []
        w.begin_action("find", find)
        w.robot.detach()
        w.end_action("find", find)
        assert [(e.kind, e.affected) for e in w.injected()] == [(DROPPED, ("knife",))]
        assert w.oracle.holds(Atom.parse("inview(drawer)")) and w.oracle.holds(Atom.parse("closed(drawer)"))
        w.begin_action("open", ("drawer",))
        w.end_action("open", ("drawer",))
        assert [(e.kind, e.affected) for e in w.injected()][1:] == [(FAILED, ("drawer",))]
    finally:
        w.close()
