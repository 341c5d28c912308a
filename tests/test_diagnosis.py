"""Situation diagnosis: the executive's reading of each situation (perception error, world change,
execution failure) and the truth the world's record gives, side by side in every report."""

from __future__ import annotations

import pytest

from vap_bt.app.runner import RunConfig, Session
from vap_bt.bt.diagnosis import DIAGNOSES, Sightings, diagnose, placed, review
from vap_bt.bt.record import Situation
from vap_bt.domain.atoms import Atom
from vap_bt.report import confusion_matrix
from vap_bt.scene.graph import SceneGraph
from vap_bt.sim.disturbances import MOVED, Disturbance
from vap_bt.sim.situation_truth import Raised, situation_truths
from vap_bt.sim.situations import SituationModel
from vap_bt.taskfile import load
from vap_bt.world import InjectedSituation

from conftest import TREES

#: the camera and the model read every picture right: what is left to diagnose is the world's doing
EXACT = dict(vlm_noise=0.0, miss_rate=0.0, relation_noise=0.0)


def session(path, **cfg) -> Session:
    task = load(path)
    return Session(task, RunConfig.from_task(task, world="symbolic", planner="search", **cfg))


def test_a_grasp_table_ii_makes_fail_is_an_execution_failure_by_both_readings():
    s = session(TREES / "collect_cup.yaml", max_replans=2, **EXACT)  # every grasp fails: not to the end
    s.world.situations = SituationModel.forced("grasp", "grasp_fails_object_unchanged")
    r = s.episode(0)
    grasps = [x for x in r["situations"] if (x["action"] or "").startswith("grasp(cup")]
    assert grasps and r["injected"][0]["kind"] == "grasp_fails_object_unchanged"
    first = grasps[0]
    assert (first["diagnosis"], first["diagnosis_truth"]) == ("execution_failure", "execution_failure")
    assert first["truth_events"] == [0] and "did not" in first["diagnosis_basis"]


def test_a_cup_a_person_moved_after_the_robot_saw_it_is_a_world_change_by_both_readings():
    s = session(TREES / "collect_cup.yaml", injection=False, **EXACT)
    # after the first action (the robot drives to the living room), before it reaches the cup the
    # survey saw on the coffee table, a person puts the cup down on the living room's floor
    s.world.disturbances = [Disturbance(MOVED, 0, "cup", "floor_living_room")]
    r = s.episode(0)
    (moved,) = [i for i, e in enumerate(r["injected"]) if e["kind"] == MOVED]
    about = [x for x in r["situations"] if x["truth_events"] == [moved]]
    assert about, r["situations"]
    assert about[0]["diagnosis_truth"] == "world_change" and about[0]["diagnosis"] == "world_change", about[0]
    assert r["success"] and r["goal_satisfied"], r["reason"]


def test_a_cup_a_person_took_away_from_under_the_robot_s_eyes_is_a_world_change_by_both_readings():
    s = session(TREES / "collect_cup.yaml", injection=False, **EXACT)
    # the robot drives to the cup the survey saw on the coffee table; then a person takes it to
    # the kitchen's floor: the grasp's check cannot make the cup out (an unseen situation), the
    # look at the coffee table does not show it, and the search finds it in the kitchen
    s.world.disturbances = [Disturbance(MOVED, 0, "cup", "floor_kitchen")]
    r = s.episode(0)
    (moved,) = [i for i, e in enumerate(r["injected"]) if e["kind"] == MOVED]
    (first, *_) = [x for x in r["situations"] if x["truth_events"] == [moved]]
    assert first["kind"] == "unseen" and first["predicate"] == "inview(cup)", first
    assert (first["diagnosis"], first["diagnosis_truth"]) == ("world_change", "world_change"), first
    assert "on(cup, coffee_table)" in first["diagnosis_basis"] and "on(cup, floor_kitchen)" in first["diagnosis_basis"]
    assert r["success"] and r["goal_satisfied"], r["reason"]


def wrong_prior(tmp_path):
    """boil_water where the user says the cup is on the counter; it is in the closed cabinet, where
    no sweep sees it."""
    text = (TREES / "variants" / "boil_water_cup_on_counter.yaml").read_text()
    text = text.replace('"inside(cup, cabinet)"', '"on(cup, counter)"').replace("place: on counter", "place: inside cabinet")
    text = text.replace("../../domains", str(TREES.parent / "domains"))
    path = tmp_path / "wrong_prior.yaml"
    path.write_text(text)
    return path


def test_a_wrong_prior_the_survey_could_not_see_past_is_a_perception_error_by_both_readings(tmp_path):
    r = session(wrong_prior(tmp_path), injection=False, **EXACT).episode(0)
    assert r["injected"] == [] and r["situations"], r["reason"]
    first = r["situations"][0]
    assert "cup" in first["predicate"], first
    assert (first["diagnosis"], first["diagnosis_truth"]) == ("perception_error", "perception_error"), first


def test_a_skill_that_did_not_find_its_thing_where_belief_put_it_is_a_perception_error_by_both_readings(tmp_path):
    # nothing checks before the grasp: the skill goes for the cup on the counter and finds nothing
    # there. Before the skill named what it missed, this read as an execution failure
    r = session(wrong_prior(tmp_path), injection=False, verify="none", max_replans=1, **EXACT).episode(0)
    failed = [x for x in r["situations"] if x["kind"] == "execution"]
    assert failed and failed[0]["missing"] == "cup" and failed[0]["action"].startswith("grasp(cup, counter"), r["situations"]
    assert (failed[0]["diagnosis"], failed[0]["diagnosis_truth"]) == ("perception_error", "perception_error"), failed[0]


@pytest.mark.parametrize("name", ["boil_water.yaml", "cut_lemon.yaml"])
def test_every_situation_of_a_batch_carries_a_legal_diagnosis_and_truth(name):
    s = session(TREES / name, disturbance=0.5)
    reports = [s.episode(seed) for seed in range(3)]
    situations = [x for r in reports for x in r["situations"]]
    assert situations, "with Table II on, three episodes raise situations"
    for x in situations:
        assert x["diagnosis"] in DIAGNOSES and x["diagnosis_truth"] in DIAGNOSES and x["diagnosis_basis"], x
    for r in reports:
        d = r["diagnosis"]
        assert d["total"] == len(r["situations"])
        assert d["correct"] == sum(x["diagnosis"] == x["diagnosis_truth"] for x in r["situations"])
        assert sum(n for row in d["confusion"].values() for n in row.values()) == d["total"]


def test_the_report_names_the_diagnoses_the_executive_gives():
    from vap_bt import report

    assert report.DIAGNOSES == DIAGNOSES == ("perception_error", "world_change", "execution_failure")


def test_the_confusion_helper_sums_the_situations_of_many_reports():
    def rep(*pairs):
        return {"situations": [{"diagnosis": d, "diagnosis_truth": t} for d, t in pairs]}

    reports = [rep(("world_change", "world_change"), ("perception_error", "world_change")),
               rep(("execution_failure", "execution_failure")), {"situations": []}, {"error": "crashed"}]
    m = confusion_matrix(reports)
    assert (m["correct"], m["total"]) == (2, 3)
    assert m["confusion"]["world_change"] == {"perception_error": 1, "world_change": 1, "execution_failure": 0}
    assert m["confusion"]["execution_failure"]["execution_failure"] == 1
    assert set(m["confusion"]) == set(DIAGNOSES) and sum(m["confusion"]["perception_error"].values()) == 0


def test_the_rule_reads_what_the_senses_showed_since_the_robot_last_acted():
    k = load(TREES / "collect_cup.yaml").planning.knowledge
    grasp = k.ground("grasp", ("cup", "coffee_table", "living_room"))
    find = k.ground("find", ("floor_living_room", "cup", "living_room"))
    on = Atom("on", ("cup", "coffee_table"))
    graph = SceneGraph.of_facts({on, Atom("inview", ("cup",))})
    sightings = Sightings()

    def diagnosis(s: Situation) -> str:
        return diagnose(s, sightings, graph)[0]

    denied = Situation("precondition", grasp, 1, on, True, False)
    not_in_sight = Situation("effect", find, 0, Atom("inview", ("cup",)), True, False)
    assert diagnosis(denied) == diagnosis(not_in_sight) == "perception_error"  # believed, never seen
    sightings.saw((on,), True, "survey")
    assert diagnosis(denied) == diagnosis(not_in_sight) == "world_change"  # seen so, and untouched since
    sightings.executed(find)  # naming the cup does not move it
    assert diagnosis(denied) == "world_change"
    sightings.executed(grasp)  # a grasp of it could have
    assert diagnosis(denied) == "perception_error" and sightings.get(on) is None
    lost = Situation("effect", None, 2, Atom("holding", ("cup",)), True, False, "the gripper holds nothing")
    assert diagnosis(lost) == "execution_failure"
    assert diagnosis(Situation("effect", grasp, 1, Atom("holding", ("cup",)), True, False)) == "execution_failure"
    assert diagnosis(Situation("execution", grasp, 1)) == "execution_failure"
    # the skill looked where belief put the cup and did not see it: belief, not the motion
    assert diagnosis(Situation("execution", grasp, 1, missing="cup")) == "perception_error"
    # the skill found a precondition of its action false where it looked: belief again
    assert diagnosis(Situation("execution", grasp, 1, unmet=Atom("reachable", ("cup",)))) == "perception_error"
    sightings.saw((on,), True, "survey")
    assert diagnosis(Situation("unseen", grasp, 1, on, True, None)) == "perception_error"  # nothing seen to differ


def test_a_contradiction_the_check_s_own_views_disagreed_on_is_no_world_change():
    """A shut cabinet the survey read "open" (5 to 0), and the precondition check's first view too,
    then "shut" from two more stands (pybullet boil_water seed 182): the model erred about the leaf
    within the check itself, so the survey's "open" is no ground for a world change."""
    k = load(TREES / "boil_water.yaml").planning.knowledge
    takeout = k.ground("takeout", ("cup", "cabinet", "kitchen"))
    opened = Atom("open", ("cabinet",))
    graph, sightings = SceneGraph.of_facts({opened}), Sightings()
    sightings.saw((opened,), True, "survey")
    unanimous = Situation("precondition", takeout, 1, opened, True, False)
    split = Situation("precondition", takeout, 1, opened, True, False, split=True)
    assert diagnose(unanimous, sightings, graph)[0] == "world_change"
    d, basis = diagnose(split, sightings, graph)
    assert d == "perception_error" and "views disagreed" in basis and "survey" in basis
    # only a world change is read again: belief that rested on no view was wrong either way
    fresh = Sightings()
    assert diagnose(split, fresh, graph) == diagnose(unanimous, fresh, graph)


def test_a_check_that_contradicts_belief_says_whether_its_own_views_disagreed():
    """The decorator marks the situation it raises: ``split`` when a view of the check voted the
    value belief had, however the check then settled."""
    from test_active_perception import CUP_ON_TABLE, Camera, ScriptedCheck, run, view

    # a precondition an action failed on needs a second view: "yes", then "no" twice
    doubted = ScriptedCheck(CUP_ON_TABLE, [view("yyyyy", True), view("nnnnn", True), view("nnnnn", True)])
    split = run(doubted, Camera(), doubted={CUP_ON_TABLE})[2].board.situation
    unanimous = run(ScriptedCheck(CUP_ON_TABLE, [view("nnnnn", True), view("nnnny", False)]), Camera())[2].board.situation
    assert (split.kind, split.observed, split.split) == ("precondition", False, True)
    assert (unanimous.kind, unanimous.observed, unanimous.split) == ("precondition", False, False)
    assert split.to_json()["split"] is True


def test_a_world_change_a_later_look_overturns_before_any_action_is_a_perception_error():
    k = load(TREES / "collect_cup.yaml").planning.knowledge
    grasp = k.ground("grasp", ("cup", "coffee_table", "living_room"))
    on = Atom("on", ("cup", "coffee_table"))
    sightings = Sightings()
    kept, overturned = (Situation("precondition", grasp, 1, on, True, False, diagnosis="world_change")
                        for _ in range(2))
    sightings.watch(kept)
    sightings.saw((on,), False, "check")  # the situation's own observation: it stands
    sightings.executed(grasp)  # the grasp could have changed it: no later look overturns it
    sightings.saw((on,), True, "check")
    assert kept.diagnosis == "world_change"
    sightings.watch(overturned)
    sightings.saw((on,), True, "re-location")  # seen as belief had it, nothing done in between
    assert overturned.diagnosis == "perception_error" and "again before any action" in overturned.diagnosis_basis


def test_a_world_change_the_recovery_re_located_unchanged_is_revised_to_a_perception_error():
    k = load(TREES / "collect_cup.yaml").planning.knowledge
    find = k.ground("find", ("floor_living_room", "cup", "living_room"))
    where = {Atom("on", ("cup", "coffee_table")), Atom("in_room", ("cup", "living_room"))}
    graph = SceneGraph.of_facts(where | {Atom("inview", ("cup",))})
    s = Situation("effect", find, 0, Atom("inview", ("cup",)), True, False, diagnosis="world_change")
    before = placed(s, graph)
    assert before.where == {"cup": frozenset(where)} and before.seen == {}  # no sightings given
    review(s, before, set(), graph)  # not re-located: the diagnosis stands
    assert s.diagnosis == "world_change"
    graph.relocate("cup", {Atom("on", ("cup", "floor_living_room")), Atom("in_room", ("cup", "living_room"))})
    review(s, before, {"cup"}, graph)  # found elsewhere: it did move
    assert s.diagnosis == "world_change"
    graph.relocate("cup", where)
    review(s, before, {"cup"}, graph)  # found where belief had it: the view erred
    assert s.diagnosis == "perception_error" and s.diagnosis_basis.startswith("re-located where belief had it")


def test_a_thing_seen_at_a_missed_there_and_found_at_b_is_a_world_change():
    # the survey saw the cup on the coffee table; the grasp's check could not make it out; the
    # recovery's look at the coffee table did not show it, and the search found it on the floor
    k = load(TREES / "collect_cup.yaml").planning.knowledge
    grasp = k.ground("grasp", ("cup", "coffee_table", "living_room"))
    find = k.ground("find", ("floor_living_room", "cup", "living_room"))
    where = {Atom("on", ("cup", "coffee_table")), Atom("in_room", ("cup", "living_room"))}
    floor = {Atom("on", ("cup", "floor_living_room")), Atom("in_room", ("cup", "living_room"))}

    def case(seen_by_survey: bool, acted: bool = False):
        graph, sightings = SceneGraph.of_facts(where | {Atom("inview", ("cup",))}), Sightings()
        if seen_by_survey:
            sightings.saw(where, True, "survey")
        sightings.executed(find)  # naming the cup does not move it
        if acted:
            sightings.executed(grasp)  # a grasp of it could have
        s = Situation("unseen", grasp, 1, Atom("inview", ("cup",)), True, None)
        s.diagnosis, s.diagnosis_basis = diagnose(s, sightings, graph)
        assert s.diagnosis == "perception_error"  # nothing seen differed from belief, yet
        return s, placed(s, graph, sightings), graph

    s, before, graph = case(seen_by_survey=True)
    assert before.seen == {"cup": "survey"}
    graph.relocate("cup", floor)
    review(s, before, {"cup"}, graph, missed=set())  # the look showed it (a support mis-read): no sign it moved
    assert s.diagnosis == "perception_error"
    review(s, before, {"cup"}, graph, missed={"cup"})  # not at A when looked at, found at B
    assert s.diagnosis == "world_change" and s.diagnosis_basis.startswith("the survey showed"), s.diagnosis_basis
    s, before, graph = case(seen_by_survey=True)
    review(s, before, {"cup"}, graph, missed={"cup"})  # missed, then found where it was: the look erred
    assert s.diagnosis == "perception_error"
    for s, before, graph in (case(seen_by_survey=False), case(seen_by_survey=True, acted=True)):
        assert before.seen == {}  # belief's place rested on no view since the robot acted on it
        graph.relocate("cup", floor)
        review(s, before, {"cup"}, graph, missed={"cup"})  # a wrong belief, as well as a move
        assert s.diagnosis == "perception_error"


def test_a_place_only_a_re_location_showed_grounds_no_world_change():
    """A re-location is the recovery's reading of where a thing it lost track of is; belief takes
    it in and the next check tests it. A check that denies it says the re-location erred, not
    that a person moved the thing; nor does a look aimed at its place that misses it, with the
    thing found elsewhere: the miss tests that reading (a place a survey or a check showed, missed
    and found elsewhere, still reads as moved)."""
    k = load(TREES / "collect_cup.yaml").planning.knowledge
    grasp = k.ground("grasp", ("cup", "coffee_table", "living_room"))
    find = k.ground("find", ("floor_living_room", "cup", "living_room"))
    on = Atom("on", ("cup", "coffee_table"))
    where = {on, Atom("in_room", ("cup", "living_room"))}
    floor = {Atom("on", ("cup", "floor_living_room")), Atom("in_room", ("cup", "living_room"))}
    for sense, expect in (("survey", "world_change"), ("check", "world_change"), ("re-location", "perception_error")):
        graph, sightings = SceneGraph.of_facts(where | {Atom("inview", ("cup",))}), Sightings()
        sightings.saw(where, True, sense)
        denied = Situation("precondition", grasp, 1, on, True, False)
        not_in_sight = Situation("effect", find, 0, Atom("inview", ("cup",)), True, False)
        assert diagnose(denied, sightings, graph)[0] == diagnose(not_in_sight, sightings, graph)[0] == expect, sense
        s = Situation("unseen", grasp, 1, Atom("inview", ("cup",)), True, None)
        s.diagnosis, s.diagnosis_basis = diagnose(s, sightings, graph)
        before = placed(s, graph, sightings)
        graph.relocate("cup", floor)
        review(s, before, {"cup"}, graph, missed={"cup"})  # not at A when looked at, found at B
        assert s.diagnosis == ("perception_error" if sense == "re-location" else "world_change"), sense


def test_an_effect_a_later_sense_shows_done_before_any_action_is_a_perception_error():
    k = load(TREES / "collect_cup.yaml").planning.knowledge
    grasp = k.ground("grasp", ("cup", "coffee_table", "living_room"))
    navigate = k.ground("navigate", ("living_room", "kitchen", "door_lk", "cup"))
    holding = Atom("holding", ("cup",))
    graph, sightings = SceneGraph.of_facts({Atom("on", ("cup", "coffee_table"))}), Sightings()
    kept, overturned = (Situation("effect", grasp, 1, holding, True, False) for _ in range(2))
    for s in (kept, overturned):
        s.diagnosis, s.diagnosis_basis = diagnose(s, sightings, graph)
        assert s.diagnosis == "execution_failure"
    sightings.watch(kept)
    sightings.executed(navigate)  # any move could lose what the hand holds: a later feel says nothing
    sightings.saw((holding,), True, "gripper")
    assert kept.diagnosis == "execution_failure"
    sightings.watch(overturned)
    sightings.saw((holding,), False, "check")  # the situation's own view: it stands
    sightings.saw((holding,), True, "gripper")  # the fingers hold it: the grasp worked, the look erred
    assert overturned.diagnosis == "perception_error" and "gripper" in overturned.diagnosis_basis


def test_the_truth_takes_each_event_once_in_the_world_s_order():
    events = [InjectedSituation("grasp", ("cup", "table", "kitchen"), "grasp_fails_object_drops_nearby", 1, ("cup",)),
              InjectedSituation("find", ("floor", "bowl", "kitchen"), MOVED, 2, ("bowl",))]
    raised = [Raised(frozenset({"cup", "table"}), 1),  # after the failed grasp
              Raised(frozenset({"bowl"}), 1),  # before the bowl was moved
              Raised(frozenset({"cup", "bowl"}), 2),  # after both, the grasp already noticed
              Raised(frozenset({"cup"}), 2)]  # nothing new about the cup
    assert [(t.diagnosis, t.events) for t in situation_truths(raised, events)] == [
        ("execution_failure", (0,)), ("perception_error", ()), ("world_change", (1,)), ("perception_error", ())]


def test_the_bench_prints_the_share_right_and_the_matrix_of_its_episodes(capsys):
    from tools.bench import diagnosis as bench

    assert bench.main(["--seeds", "1", "--tasks", "boil_water", "--disturbance", "0"]) == 0
    lines = capsys.readouterr().out.splitlines()
    right, total = (int(w) for w in lines[0].split(" situations")[0].split(" of "))
    rows = {line.split(" | ")[0][2:]: [int(x) for x in line.strip(" |").split(" | ")[1:]] for line in lines[4:]}
    assert set(rows) == set(DIAGNOSES) and lines[2] == "| truth \\ diagnosis | " + " | ".join(DIAGNOSES) + " |"
    assert sum(map(sum, rows.values())) == total > 0 and sum(rows[d][i] for i, d in enumerate(DIAGNOSES)) == right
