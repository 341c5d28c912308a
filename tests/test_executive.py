"""The closed loop: plans run, situations are detected, the graph is corrected, replans happen."""

from __future__ import annotations

import pytest

from vap_bt.app.runner import RunConfig, Session
from vap_bt.taskfile import load

from conftest import DOMAINS, HOUSEHOLD_TASKS, LITERATURE, TREES, load_json, session


@pytest.mark.parametrize("domain,problem", LITERATURE)
def test_literature_domains_run_end_to_end(cli, domain, problem, tmp_path):
    code, out, _ = cli("run", "--domain", DOMAINS / domain, "--problem", DOMAINS / problem, "--world", "symbolic",
                       "--no-injection", "--vlm-noise", "0", "--report", tmp_path / "r.json", "-q", "--json")
    summary = load_json(out)
    assert code == 0 and summary["success"] and summary["goal_satisfied"]
    full = load_json((tmp_path / "r.json").read_text())
    if domain.startswith("blocksworld"):  # on/clear/holding have paraphrases; gripper's predicates do not
        assert full["verifications"], "with verification on, checks must have been asked"
    # nothing situated goes wrong here and the model reads every picture perfectly: no check
    # contradicts the plan. Every check confirms, by looking or — for what the hand holds, which no
    # move of the base shows better than the first view — by the gripper's feel, except one whose
    # every view showed too little of its relation (a view shows a thing partly: docs/perception.md),
    # which stays unsettled; what it said is right
    assert all(v["outcome"] in ("confirmed", "unsettled") or v["outcome"] == "felt" and v["predicate"].startswith("holding(")
               for v in full["verifications"])
    assert all(v["value"] == v["truth"] for v in full["verifications"] if v["outcome"] == "confirmed")
    assert sum(v["outcome"] == "unsettled" for v in full["verifications"]) <= 0.1 * len(full["verifications"])
    assert any(v["outcome"] == "confirmed" for v in full["verifications"]) or not full["verifications"]


@pytest.mark.parametrize("name", HOUSEHOLD_TASKS)
def test_household_task_succeeds_without_situations(name):
    r = session(name, injection=False, vlm_noise=0.0).episode(0)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    assert r["situations"] == [] and r["replans"] == 0


def test_the_survey_asks_only_whether_what_can_be_opened_is_open():
    """store_firewood seeds 7 and 10 in pybullet: a view judged the basket "not open", and no plan
    could put the logs in it. The map says a basket cannot be shut: it is not asked, it is open."""
    r = session("store_firewood.yaml", injection=False, vlm_noise=0.0).episode(0)
    asked = {st["predicate"] for st in r["perception"]["surveys"][0]["states"]}
    assert "open(door_ls)" in asked and not any("basket" in p for p in asked), asked
    assert r["success"] and r["goal_satisfied"]


def unsettled_at_survey(report: dict) -> set[str]:
    """Atoms the initial survey asked about and could not settle, with their complements."""
    out = set()
    for s in report["perception"]["surveys"][0]["states"]:
        if s["value"] is None:
            args = s["predicate"][s["predicate"].index("("):]
            out |= {s["predicate"], "closed" + args, "open" + args}
    return out


@pytest.mark.slow
def test_every_injected_situation_is_detected_and_recovered():
    """Noise off (VLM and detector): each situation the world injects is noticed once — as a
    situation at its action or later, or by the gripper feeling empty while another situation is
    handled — and the only other situations are the camera correcting a state the survey could
    not settle (a default belief about a door, say), caught as a precondition."""
    episodes = 0
    for name in HOUSEHOLD_TASKS:
        s = session(name, vlm_noise=0.0, max_replans=20, miss_rate=0.0, relation_noise=0.0)
        for seed in range(8):
            r = s.episode(seed)
            episodes += 1
            inj, det = r["injected"], r["situations"]
            unsettled = unsettled_at_survey(r)
            corrections = [d for d in det if d["kind"] == "precondition" and d["predicate"] in unsettled]
            felt = [c for c in r["belief_changes"] if c["cause"] == "gripper" and any(
                a.startswith("holding(") for a in c["removed"])]
            # no phantom situation; every injected one a situation, unless the gripper felt it first
            assert len(inj) + len(corrections) - len(felt) <= len(det) <= len(inj) + len(corrections), \
                (name, seed, inj, det, felt)
            assert r["replans"] == len(det)
            if r["success"]:
                assert r["goal_satisfied"], "a claimed success the world denies"
    assert episodes == 8 * len(HOUSEHOLD_TASKS)


def test_effect_failure_is_undone_then_corrected():
    # the first seed of boil_water that injects a failed turnon: heated(cup) is checked and found false
    s = session("boil_water.yaml", vlm_noise=0.0, miss_rate=0.0, relation_noise=0.0)
    r = next(r for r in map(s.episode, range(40)) if any(i["kind"] == "turnon_fails_object_off" for i in r["injected"]))
    kinds = [(s["kind"], s["predicate"]) for s in r["situations"]]
    assert ("effect", "heated(cup)") in kinds and r["success"] and r["goal_satisfied"]
    causes = [c["cause"] for c in r["belief_changes"]]
    # the expected effects were applied, then taken back when the camera contradicted them
    assert causes.count("apply") >= 1 and "undo" in causes
    undone = [c for c in r["belief_changes"] if c["cause"] == "undo"]
    assert any("heated(cup)" in c["removed"] for c in undone)
    assert r["plans"][1]["engine"] in ("reuse", "cache", "search")


def test_replanning_budget_bounds_the_episode():
    s = session("cut_lemon.yaml", vlm_noise=0.0, max_replans=0)
    r = next(r for r in map(s.episode, range(20)) if r["injected"])
    assert not r["success"] and "budget" in r["reason"] and r["replans"] == 0


def test_report_has_everything_to_rerun(tmp_path, cli):
    code, _, _ = cli("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--seed", "3", "--report",
                     tmp_path / "r.json", "-q")
    r = load_json((tmp_path / "r.json").read_text())
    for key in ("success", "goal_satisfied", "seed", "plans", "actions_executed", "situations", "replans",
                "vlm_queries", "wall_s", "versions", "config", "vlm", "world", "command", "injected"):
        assert key in r, key
    assert r["seed"] == 3 and r["vlm"]["backend"] == "sim" and r["vlm"]["version"].startswith("vlm-2") and "noise" in r["vlm"]
    graph = r["perception"]["graph"]["initial"]
    assert graph["relations"]["precision"] <= 1.0 and graph["views"] > 0 and "build_s" in graph
    assert r["world"]["detector"]["miss_rate"] == r["config"]["miss_rate"]
    assert isinstance(r["world"]["late_truth_readings"], int)  # answers read off a world that had moved on
    assert code == (0 if r["success"] and r["goal_satisfied"] else 1)
    # the same seed gives the same episode
    code2, _, _ = cli("run", TREES / "collect_cup.yaml", "--world", "symbolic", "--seed", "3", "--report",
                      tmp_path / "r2.json", "-q")
    r2 = load_json((tmp_path / "r2.json").read_text())
    assert [p["actions"] for p in r2["plans"]] == [p["actions"] for p in r["plans"]]
    assert r2["situations"] == r["situations"] and r2["vlm_queries"] == r["vlm_queries"]


def test_under_lean_the_goal_is_looked_at_before_success_is_claimed():
    """The lean protocol reuses what nothing since could have changed — but not for the goal:
    on(cup, counter), confirmed by placeon's effect check, is looked at again by the goal check
    (it was "reused", with no view, and success claimed on it), and the report says so."""
    r = session("collect_cup.yaml", protocol="lean").episode(0)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    checks = r["verifications"]
    assert any(v["phase"] == "eff" and v["predicate"] == "on(cup, counter)" and v["outcome"] == "confirmed"
               for v in checks), "the goal atom was verified mid-plan: the goal check could have reused it"
    assert any(v["outcome"] == "reused" for v in checks), "lean still reuses before actions"
    goal = [v for v in checks if v["phase"] == "goal"]
    assert goal and all(v["outcome"] != "reused" and v["views"] >= 1 and v["queries"] >= 1 for v in goal), goal
    assert all(v["basis"] == "vlm" for v in goal)
    evidence = r["goal_evidence"]
    assert [e["predicate"] for e in evidence["looked"]] == ["on(cup, counter)"]
    assert evidence["felt"] == evidence["unchecked"] == []
    looked = evidence["looked"][0]
    assert looked["outcome"] == "confirmed" and looked["value"] is True
    assert checks[looked["verification"]] == goal[-1], "it names the goal's last check, by its index"


def test_goal_atoms_left_to_the_body_or_the_map_are_reported_as_such(tmp_path):
    """A goal with atoms no camera is asked about: where the robot is (localization's), which
    room the cup is in (never checked) — and whether the hand is empty, which the first view of
    the wrist camera leaves to the gripper (seed 1: its paraphrases split). The claim lists each
    by what it rests on."""
    text = (TREES / "collect_cup.yaml").read_text()
    text = text.replace("../domains/household.pddl", str(TREES.parent / "domains" / "household.pddl"))
    text = text.replace('  - "on(cup, counter)"\n', '  - "on(cup, counter)"\n  - "robot_in(kitchen)"\n'
                                                      '  - "in_room(cup, kitchen)"\n  - "hand_empty"\n')
    (tmp_path / "goal.yaml").write_text(text)
    task = load(tmp_path / "goal.yaml")
    r = Session(task, RunConfig.from_task(task, world="symbolic", planner="search", protocol="lean")).episode(1)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    e = r["goal_evidence"]
    names = {kind: {x["predicate"] for x in e[kind]} for kind in e}
    assert names["looked"] == {"on(cup, counter)"}
    assert names["felt"] == {"robot_in(kitchen)", "hand_empty"}
    assert names["unchecked"] == {"in_room(cup, kitchen)"}
    felt = {x["predicate"]: x for x in e["felt"]}
    assert "proprioception" in felt["robot_in(kitchen)"]["reason"]  # the profile's source, no check
    hand = r["verifications"][felt["hand_empty"]["verification"]]  # the gripper settled its check
    assert hand["phase"] == "goal" and hand["basis"] == "proprioception"
    assert "never checked" in e["unchecked"][0]["reason"]


def test_reused_values_are_counted_apart_never_as_verified():
    """A lean run's report counts as verified (and correct) only values a sense gave when the check
    ran — looked at or felt — and the reused ones apart, outside the accuracy's denominator."""
    r = session("collect_cup.yaml", protocol="lean").episode(0)
    checks, counts = r["verifications"], r["perception"]["verifications"]
    reused = [v for v in checks if v["outcome"] == "reused"]
    sensed = [v for v in checks if v["outcome"] in ("confirmed", "contradicted", "felt")]
    assert reused and counts["reused"] == len(reused)
    assert counts["n"] == len(sensed) and counts["n"] + counts["reused"] + counts["unsettled"] == len(checks)
    assert counts["correct"] == sum(v["value"] == v["truth"] for v in sensed)
    assert all(v["basis"] == "reused" and v["views"] == 0 for v in reused)
    looked = [v for v in sensed if v["basis"] == "vlm"]
    assert counts["looked"] == len(looked) < counts["n"]  # hand_empty after placeon was felt


@pytest.mark.slow
def test_zenoh_embedded_run_matches_the_in_process_run():
    """Same task, same seed: the loop over real Zenoh sessions makes the same episode."""
    runs = {}
    for transport in ("inproc", "zenoh"):
        s = session("boil_water.yaml", transport=transport)
        try:
            runs[transport] = s.episode(1)
        finally:
            s.close()
    a, b = runs["inproc"], runs["zenoh"]
    assert a["success"] and b["success"] and b["goal_satisfied"]
    assert [p["actions"] for p in a["plans"]] == [p["actions"] for p in b["plans"]]
    assert a["situations"] == b["situations"] and a["injected"] == b["injected"]
    assert [x["state"] for x in a["actions_executed"]] == [x["state"] for x in b["actions_executed"]]


def exact_episode(task, lines: list[str]) -> dict:
    """Seed 0 of ``task`` in the symbolic world without injection, its perception without noise —
    the detector's too: a missed cup sends the look afresh on to the other room, and where it ends
    changes the belief the loop breaker compares — and its progress lines appended to ``lines``."""
    return Session(task, RunConfig.from_task(task, world="symbolic", planner="search", injection=False, vlm_noise=0.0,
                                             miss_rate=0.0, relation_noise=0.0), lines.append).episode(0)


def camera_says(monkeypatch, when, settlement) -> None:
    """Make every check for which ``when(check)`` holds settle as ``settlement(check)`` (a
    :class:`~vap_bt.perception.judgement.Settlement`), whatever its views showed."""
    from vap_bt.bt.active_perception import ActivePerception

    settle = ActivePerception._settle
    monkeypatch.setattr(ActivePerception, "_settle",
                        lambda self, s: settle(self, settlement(self) if when(self) else s))


def test_a_failure_that_comes_back_unchanged_is_looked_at_afresh_then_stops_the_episode(monkeypatch):
    """A skill that fails the same way every time, from the same belief: the second time the
    executive re-surveys instead of only replanning, the third time it stops and says why —
    rather than spending the replanning budget on the same motion."""
    from vap_bt.sim.symbolic import SymbolicWorld
    from vap_bt.outcome import Outcome

    perform = SymbolicWorld.perform

    def no_grasp(self, action, args, ctx):
        if action == "grasp":
            return Outcome(False, f"{args[0]}: no arm pose reaches it")
        return perform(self, action, args, ctx)

    monkeypatch.setattr(SymbolicWorld, "perform", no_grasp)
    lines = []
    task = load(TREES / "collect_cup.yaml")
    r = Session(task, RunConfig.from_task(task, world="symbolic", planner="search", injection=False, vlm_noise=0.0),
                lines.append).episode(0)
    assert not r["success"] and r["reason"].startswith("stuck: execution of grasp(cup"), r["reason"]
    assert "no arm pose reaches it" in r["reason"] and r["replans"] == 2 < 10
    assert [s["kind"] for s in r["situations"]] == ["execution"] * 3
    assert any("again: re-surveying" in m for m in lines)
    assert len(r["perception"]["surveys"]) == 2  # the initial one and the fresh look


def test_a_check_that_comes_back_the_same_is_looked_at_afresh_but_does_not_stop_the_episode():
    """An effect the camera keeps contradicting may be chance (an injected slip): the executive
    re-surveys on its return, and only the replanning budget ends the episode."""
    from vap_bt.bt.context import Situation
    from vap_bt.bt.repeats import RepeatWatch, stuck
    from vap_bt.domain.atoms import Atom

    watch, belief = RepeatWatch(), frozenset({Atom.parse("hand_empty()")})
    slip = Situation("effect", None, 2, Atom.parse("holding(cup)"), True, False)
    failed = Situation("execution", None, 2, detail="cup: no arm pose reaches it")
    times = [watch.count(slip, belief) for _ in range(5)]
    assert times == [1, 2, 3, 4, 5] and not any(stuck(slip, t) for t in times)
    assert [stuck(failed, watch.count(failed, belief)) for _ in range(3)] == [False, False, True]
    assert watch.count(failed, belief | {Atom.parse("inview(cup)")}) == 1  # another belief: a new start
    # a precondition the camera could not make out, back the same after the fresh look, stops too
    unseen = Situation("unseen", None, 1, Atom.parse("inview(knife)"), True, None)
    assert [stuck(unseen, watch.count(unseen, belief)) for _ in range(3)] == [False, False, True]


def test_a_goal_the_camera_could_not_confirm_is_looked_at_again_before_success_is_claimed(monkeypatch):
    """The tree gets through but a goal check stays unsettled: the executive neither claims the
    goal nor gives up on it — it goes to look at what the atom is about and checks the goal again
    (an empty plan, the goal's checks only); a goal no view ever confirms stops as stuck."""
    from vap_bt.bt.active_perception import ActivePerception
    from vap_bt.perception.judgement import Settlement

    settle = ActivePerception._settle

    def blind_to_goal(times: int):
        left = {"n": times}

        def weigh(self, s: Settlement):
            if self.phase == "goal" and left["n"]:
                left["n"] -= 1
                return settle(self, Settlement(self.subject.expected, "unsettled", "belief"))
            return settle(self, s)
        return weigh

    task = load(TREES / "collect_cup.yaml")
    goal = str(task.planning.goal[0].atom)
    for times, success in ((1, True), (10, False)):
        monkeypatch.setattr(ActivePerception, "_settle", blind_to_goal(times))
        lines = []
        r = exact_episode(task, lines)
        unseen = [s for s in r["situations"] if s["kind"] == "unseen"]
        assert unseen and unseen[0]["action"] is None and unseen[0]["predicate"] == goal
        assert "not confirmed by looking" in unseen[0]["detail"]
        assert r["success"] is success and r["goal_satisfied"], r["reason"]
        if not success:
            assert r["reason"] == (f"stuck: could not see whether {goal} holds at the goal, 3 times from the same "
                                   "belief (looking afresh changed nothing)")
        goal_checks = [v for v in r["verifications"] if v["phase"] == "goal"]
        assert goal_checks[-1]["outcome"] == ("confirmed" if success else "unsettled")
        # the look after each unconfirmed goal moves the robot (a new belief about where it is): the
        # same belief comes back, and the episode stops, only once the views repeat
        assert len(goal_checks) == 2 if success else 3 <= len(goal_checks) < 10


@pytest.mark.parametrize("blind_after", [0, 2])
def test_a_goal_no_view_confirmed_is_done_again_once_before_the_episode_stops(monkeypatch, blind_after):
    """A cut that does not cut, and a camera that cannot tell (vlm-2 reads ``sliced`` poorly:
    halve_egg seed 3 in pybullet, the injected cut failed, its effect check and three goal checks
    unsettled, "stuck" with the egg whole): the goal rests on the plan alone, so the executive
    drops it from belief and cuts again rather than stopping; the second cut cuts, and is seen —
    at once, or (``blind_after``) only by the third goal check after it: the checks after the redo
    count anew (boil_water seed 128 in pybullet stopped at the first one, the fourth in all)."""
    from vap_bt.outcome import Outcome
    from vap_bt.perception.judgement import Settlement
    from vap_bt.sim.symbolic import SymbolicWorld

    perform, cuts = SymbolicWorld.perform, []

    def first_cut_fails_unseen(self, action, args, ctx):
        if action == "cut":
            cuts.append(args)
            if len(cuts) == 1:
                return Outcome(True)  # the skill says done; the egg is whole
        return perform(self, action, args, ctx)

    monkeypatch.setattr(SymbolicWorld, "perform", first_cut_fails_unseen)
    after = {"goal": 0}

    def blind(c) -> bool:  # to the whole egg, and to the halved one for its first goal checks
        if c.atom.predicate != "sliced":
            return False
        if len(cuts) < 2:
            return True
        after["goal"] += c.phase == "goal"
        return c.phase == "goal" and after["goal"] <= blind_after

    camera_says(monkeypatch, blind, lambda c: Settlement(c.subject.expected, "unsettled", "belief"))
    lines = []
    task = load(TREES / "halve_egg.yaml")
    r = exact_episode(task, lines)
    assert len(cuts) == 2 and any("sliced(egg) never confirmed" in m and "doing it again" in m for m in lines)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    goal_checks = [v for v in r["verifications"] if v["phase"] == "goal"]
    assert goal_checks[-1]["outcome"] == "confirmed"
    assert [v["outcome"] for v in goal_checks if v["predicate"] == "sliced(egg)"][-blind_after - 1:] \
        == ["unsettled"] * blind_after + ["confirmed"]


def test_a_precondition_denied_that_leaves_no_plan_is_doubted_then_tried_against(monkeypatch):
    """A camera that keeps saying the cup is out of reach, with nothing in front of it: no plan
    makes it reachable. The observation is doubted twice (belief back, a new look); denied a
    third time it is put on trial — the grasp runs against it, and the world, where the cup is in
    reach, lets it succeed. The verifications still say what the camera said."""
    from vap_bt.perception.judgement import Settlement

    camera_says(monkeypatch, lambda c: c.phase == "pre" and c.atom.predicate == "reachable",
                lambda c: Settlement(False, "contradicted", "vlm"))
    lines = []
    task = load(TREES / "collect_cup.yaml")
    r = exact_episode(task, lines)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    assert sum("leaves no plan: doubting it" in m for m in lines) == 2
    assert any("the action will be tried against it" in m for m in lines)
    assert any("trying grasp(cup" in m for m in lines)
    denied = [v for v in r["verifications"] if v["predicate"] == "reachable(cup)"]
    assert len(denied) == 4 and all(v["outcome"] == "contradicted" and v["value"] is False for v in denied)


def test_a_precondition_denied_that_the_relocation_restores_each_time_is_tried_against(monkeypatch):
    """A camera that keeps denying the cup is on the table, where the re-location that follows
    each denial sees it again (heat_pie seed 1 in pybullet: the pie in the oven, seen there from
    the counter and "not inside" from the oven's front, until the replanning budget was gone).
    The replan is the same plan each time and brings the robot to the same views; from the third
    identical denial the grasp is tried against it, and the world, where the cup is, lets it
    succeed. Without the rule the episode ends with the budget spent."""
    from vap_bt.perception.judgement import Settlement

    camera_says(monkeypatch, lambda c: c.phase == "pre" and str(c.atom) == "on(cup, coffee_table)",
                lambda c: Settlement(False, "contradicted", "vlm"))
    lines = []
    task = load(TREES / "collect_cup.yaml")
    r = exact_episode(task, lines)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    assert any("on(cup, coffee_table) denied 3 times from the same belief" in m for m in lines)
    assert r["replans"] == 3
    denied = [v for v in r["verifications"] if v["predicate"] == "on(cup, coffee_table)" and v["phase"] == "pre"]
    assert len(denied) == 4 and all(v["outcome"] == "contradicted" for v in denied)


def test_an_action_acted_on_belief_for_one_unseen_precondition_is_for_the_others_about_the_same_thing(monkeypatch):
    """A camera that cannot make out anything about the cup before the grasp (retrieve_bottles
    seed 0 in pybullet: inview, reachable and on of a bottle the views never showed, each looked
    at three times, nine replans of the twenty). After the third look at the first of them the
    robot acts on belief for every precondition of the grasp about the cup, not one at a time."""
    from vap_bt.perception.judgement import Settlement

    camera_says(monkeypatch, lambda c: c.phase == "pre" and c.action.name == "grasp" and c.atom.args[:1] == ("cup",),
                lambda c: Settlement(c.subject.expected, "unsettled", "belief"))
    lines = []
    task = load(TREES / "collect_cup.yaml")
    r = exact_episode(task, lines)
    assert r["success"] and r["goal_satisfied"], r["reason"]
    unseen = [s for s in r["situations"] if s["kind"] == "unseen"]
    assert len(unseen) == 3 and len({s["predicate"] for s in unseen}) == 1
    assert sum("acting on belief" in m for m in lines) == 1


def test_the_preconditions_seen_together_are_those_about_the_same_thing():
    from vap_bt.bt.repeats import seen_together
    from vap_bt.domain.atoms import Atom

    task = load(TREES / "collect_cup.yaml")
    grasp = task.planning.knowledge.ground("grasp", ("cup", "coffee_table", "living_room"))
    together = seen_together(Atom("inview", ("cup",)), grasp)
    assert together == {a for a in grasp.pre_pos if a.args[:1] == ("cup",)}
    assert Atom("on", ("cup", "coffee_table")) in together and Atom("hand_empty", ()) not in together


def test_a_check_whose_views_showed_its_thing_finds_it_not_missing_though_unsettled():
    """heat_pie seed 30 in pybullet: "inside(apple_pie, fridge)" stayed unsettled though a frame
    of the check showed the pie in the fridge; a miss noted there vetoed the re-survey's sighting
    of it. A check that showed the thing did not find it missing; one that never showed it did,
    and so did a check that settled against it."""
    from vap_bt.bt.executive import shown_by_check
    from vap_bt.bt.record import Situation, Verification
    from vap_bt.domain.atoms import Atom
    from vap_bt.perception.verification import Round

    inside = Atom("inside", ("apple_pie", "fridge"))
    takeout = load(TREES / "heat_pie.yaml").planning.knowledge.ground("takeout", ("apple_pie", "fridge", "kitchen"))

    def check(*identified: dict, outcome="unsettled") -> list[Verification]:
        rounds = [Round(view=f"f{i}", identified=ids) for i, ids in enumerate(identified)]
        return [Verification("pre", str(takeout), inside, True, True, outcome, rounds, "vlm")]

    unseen = Situation("unseen", takeout, 2, inside, True, None)
    assert shown_by_check(unseen, check({"fridge": 0}, {"apple_pie": 1, "fridge": 0}))
    assert not shown_by_check(unseen, check({"fridge": 0}, {"fridge": 1}))
    assert not shown_by_check(unseen, [])
    denied = Situation("precondition", takeout, 2, inside, True, False)
    support = frozenset({"on", "inside"})
    assert not shown_by_check(denied, check({"apple_pie": 0}, outcome="contradicted"), support)


def test_a_place_denied_where_two_stands_showed_the_thing_is_no_miss():
    """gather_kindling seed 89 in pybullet: the stick lay on the garden floor, found there from two
    stands, and vlm-2 said "not on the floor"; the miss noted at the spot refused every later
    sighting of it there. A check that settled against where a thing rests, whose pictures from
    two stands showed the thing, found it there: no miss. One stand's pictures are one picture
    (a detector's phantom shows in every one of them), and a denial of whether it is in view at
    all, or one about a thing no picture showed, are misses as before."""
    from vap_bt.bt.executive import shown_by_check
    from vap_bt.bt.record import Situation, Verification
    from vap_bt.domain.atoms import Atom
    from vap_bt.perception.verification import Round

    on, inview = Atom("on", ("stick2", "floor_garden")), Atom("inview", ("stick2",))
    grasp = load(TREES / "gather_kindling.yaml").planning.knowledge.ground("grasp", ("stick2", "floor_garden", "garden"))
    support = frozenset({"on", "inside"})

    def denied(atom, *rounds: tuple[dict, tuple]) -> tuple[Situation, list[Verification]]:
        rs = [Round(view=f"f{i}", identified=ids, stand=stand) for i, (ids, stand) in enumerate(rounds)]
        return (Situation("precondition", grasp, 4, atom, True, False),
                [Verification("pre", str(grasp), atom, True, False, "contradicted", rs, "vlm")])

    two_stands = ({"stick2": 1}, (7.0, 1.5, 0.0)), ({"stick2": 0}, (7.9, 1.4, 3.1))
    assert shown_by_check(*denied(on, *two_stands), support)
    assert not shown_by_check(*denied(on, *two_stands))  # no support predicates named: none is one
    assert not shown_by_check(*denied(on, ({"stick2": 1}, (7.0, 1.5, 0.0)), ({"stick2": 1}, (7.0, 1.5, 0.0))), support)
    assert not shown_by_check(*denied(on, ({"stick2": 1}, (7.0, 1.5, 0.0)), ({}, (7.9, 1.4, 3.1))), support)
    assert not shown_by_check(*denied(inview, *two_stands), support)


def test_a_goal_no_goal_check_could_settle_rests_on_the_check_that_confirmed_it_since():
    """boil_water seed 2 in pybullet: the cup heated, confirmed so by the effect check at the
    microwave; three goal checks split between "yes" and "no" and the episode was given up. The
    goal rests on that confirmation while it stands: among the views since the last action that
    could change the atom, and no settled check since said otherwise."""
    from vap_bt.bt.goal_check import resting_on_earlier, standing_confirmation
    from vap_bt.bt.record import GoalAtomEvidence, GoalEvidence, Verification
    from vap_bt.domain.atoms import Atom
    from vap_bt.perception.verification import Round

    heated = Atom("heated", ("cup",))
    r = [Round(view=f"f{i}") for i in range(4)]

    def check(phase, outcome, value, *rounds) -> Verification:
        return Verification(phase, "turnon(microwave, cup)" if phase == "eff" else "goal", heated, True, value,
                            outcome, list(rounds), "vlm")

    confirmed, unsettled = check("eff", "confirmed", True, r[0]), check("goal", "unsettled", True, r[1], r[2])
    assert standing_confirmation(heated, True, [confirmed, unsettled], r[:3]) == 0
    assert standing_confirmation(heated, False, [confirmed, unsettled], r[:3]) is None  # not the goal's value
    assert standing_confirmation(heated, True, [confirmed, unsettled], r[1:3]) is None  # an action since could change it
    denied = check("goal", "contradicted", False, r[3])
    assert standing_confirmation(heated, True, [confirmed, denied, unsettled], r) is None  # a settled view since denied it
    assert standing_confirmation(heated, True, [unsettled], r[1:3]) is None  # nothing ever settled it

    evidence = GoalEvidence((GoalAtomEvidence(heated, True, "unchecked", 1, unsettled, "could not settle it"),))
    rested = resting_on_earlier(evidence, {heated: 0}, [confirmed, unsettled]).to_json()
    assert rested["unchecked"] == [] and rested["earlier"][0]["verification"] == 0
    assert "checked" not in rested["earlier"][0]  # its own check
    assert "eff check after turnon(microwave, cup)" in rested["earlier"][0]["reason"]


def test_a_confirmation_stands_through_an_action_that_could_only_bring_its_value_about_again():
    """heat_pie seed 84 in pybullet: the effect checks after two presses of the oven's switch saw
    the pie heated, denied the oven on (vlm-2's error), and the third press's check could settle
    neither heated nor the goal's six checks after it: the episode was given up, though a view
    had seen the pie heated and a press cannot un-heat it. What settled an atom stands until an
    action could undo its value — not one that can only bring that value about again; a hand's
    atom goes after any action, as before."""
    from vap_bt.bt.goal_check import standing_confirmation
    from vap_bt.bt.record import Verification, Verified
    from vap_bt.domain.atoms import Atom
    from vap_bt.perception.verification import Round

    knowledge = load(TREES / "boil_water.yaml").planning.knowledge
    turnon = knowledge.ground("turnon", ("microwave", "cup"))
    fill = knowledge.ground("fill", ("cup", "kitchen_sink"))
    heated, hand = Atom("heated", ("cup",)), Atom("hand_empty", ())
    seen, press_check = Round(view="f0"), Round(view="f1")
    verified = Verified()
    verified.saw(heated, [seen])
    verified.settle(heated, True, [seen])
    verified.settle(hand, True, [seen])
    verified.executed(turnon)  # pressed again: it could only heat the cup
    assert verified.views(heated) == [] and verified.standing(heated) == [seen]
    assert verified.standing(hand) == []  # the hand's atoms go after every action
    checks = [Verification("eff", str(turnon), heated, True, True, "confirmed", [seen], "vlm"),
              Verification("eff", str(turnon), heated, True, True, "unsettled", [press_check], "vlm")]
    assert standing_confirmation(heated, True, checks, verified.standing(heated)) == 0

    denied = Verified()
    denied.settle(heated, False, [seen])
    denied.executed(turnon)  # a press could heat it: a view that saw it cold no longer stands
    assert denied.standing(heated) == []
    verified.executed(fill)  # fresh water is cold: the view of it heated no longer stands
    assert verified.standing(heated) == []
    verified.settle(heated, True, [seen])
    verified.distrust({heated})
    assert verified.standing(heated) == []


def test_a_goal_no_check_settled_rests_on_the_action_seen_to_have_made_it():
    """heat_pie seed 93 in pybullet: the pie seen inside the oven right before the press, the oven
    seen on right after it, and "heated" of a pie small in the oven's mouth never settled by any of
    eleven checks: the episode was given up with the pie heated. An action that ran with its
    preconditions about the thing confirmed, and another of whose effects a view confirmed right
    after, happened, and its effects come together — unless a precondition about the thing went
    unconfirmed (a pie dropped beside the oven), its skill failed, its other effect was denied, a
    later action could undo the atom, or a settled check since denied it."""
    from vap_bt.bt.goal_check import confirmed_by_its_action, resting_on_earlier
    from vap_bt.bt.record import GoalAtomEvidence, GoalEvidence, Verification
    from vap_bt.domain.atoms import Atom

    knowledge = load(TREES / "boil_water.yaml").planning.knowledge
    turnon = knowledge.ground("turnon", ("microwave", "cup"))
    fill = knowledge.ground("fill", ("cup", "kitchen_sink"))
    heated, on, inside = Atom("heated", ("cup",)), Atom("turned_on", ("microwave",)), Atom("inside", ("cup", "microwave"))
    hand = frozenset({"holding", "hand_empty"})

    def check(phase, atom, outcome, value=True, action=turnon) -> Verification:
        return Verification(phase, str(action) if phase != "goal" else "goal", atom, True, value, outcome, [], "vlm")

    def checks(inside_outcome="confirmed", on_outcome="confirmed"):
        return [check("pre", Atom("inview", ("microwave",)), "confirmed"), check("pre", inside, inside_outcome),
                check("eff", heated, "unsettled"), check("eff", on, on_outcome, on_outcome != "contradicted"),
                check("goal", heated, "unsettled")]

    assert confirmed_by_its_action(heated, True, checks(), [(turnon, 2, True)], hand) == 3
    assert confirmed_by_its_action(heated, True, checks("unsettled"), [(turnon, 2, True)], hand) is None
    assert confirmed_by_its_action(heated, True, checks(), [(turnon, 2, False)], hand) is None  # the skill failed
    assert confirmed_by_its_action(heated, True, checks(on_outcome="contradicted"), [(turnon, 2, True)], hand) is None
    assert confirmed_by_its_action(heated, True, checks(on_outcome="unsettled"), [(turnon, 2, True)], hand) is None
    assert confirmed_by_its_action(heated, False, checks(), [(turnon, 2, True)], hand) is None  # not the goal's value
    # pressed again with no check of the oven after it: the first press still shows it
    again = checks() + [check("pre", inside, "confirmed"), check("eff", heated, "unsettled")]
    assert confirmed_by_its_action(heated, True, again, [(turnon, 2, True), (turnon, 6, True)], hand) == 3
    assert confirmed_by_its_action(heated, True, checks(), [(turnon, 2, True), (fill, 5, True)], hand) is None
    denied = checks() + [check("goal", heated, "contradicted", False)]
    assert confirmed_by_its_action(heated, True, denied, [(turnon, 2, True)], hand) is None

    evidence = GoalEvidence((GoalAtomEvidence(heated, True, "unchecked", 4, checks()[4], "could not settle it"),))
    rested = resting_on_earlier(evidence, {heated: 3}, checks()).to_json()
    assert rested["earlier"][0]["verification"] == 3 and rested["earlier"][0]["checked"] == "turned_on(microwave)"
    assert "its eff check confirmed turned_on(microwave)" in rested["earlier"][0]["reason"]


def test_views_since_the_action_that_lean_against_a_goal_atom_are_weighed_by_the_calibration():
    from vap_bt.bt.goal_check import leans_against
    from vap_bt.domain.atoms import Atom
    from vap_bt.perception.evidence import default_calibration
    from vap_bt.perception.verification import Round

    def view(yes: int, stand: tuple) -> Round:
        answers = [True] * yes + [False] * (5 - yes)
        return Round(view="f", questions=["Is the egg cut?"] * 5, answers=answers, vote=yes > 2,
                     consistent=max(yes, 5 - yes) >= 4, sufficient=True, stand=stand)

    cal, sliced = default_calibration(), Atom("sliced", ("egg",))
    confirmed = [view(5, (0,))]  # the effect check's one settled "yes"
    assert not leans_against(sliced, True, confirmed, cal) and leans_against(sliced, False, confirmed, cal)
    # then goal checks that split towards "no" and one that agreed on it
    doubted = confirmed + [view(2, (1,)), view(1, (2,)), view(0, (3,))]
    assert leans_against(sliced, True, doubted, cal)
    assert not leans_against(sliced, True, [], cal)  # no view: even, not against


def test_a_goal_atom_a_check_confirmed_but_whose_views_since_weigh_against_is_done_again_not_claimed():
    """Symbolic halve_egg seed 3: the cut's effect check confirmed sliced(egg), the goal checks
    after it could not settle it and their views weighed against it; the robot cuts again rather
    than claim the goal on that one check (seed 159: such a claim, the world denied), and the goal
    is then seen reached."""
    lines = []
    sess = session("halve_egg.yaml")
    sess.progress = lines.append
    r = sess.episode(3)
    sess.close()
    assert any("sliced(egg) weighed against by its views" in m and "doing it again" in m for m in lines), lines
    assert r["success"] and r["goal_satisfied"], r["reason"]
    assert "on the check that confirmed it" not in r["reason"]
    cuts = [a for a in r["actions_executed"] if a["action"].startswith("cut(")]
    assert len(cuts) >= 2


def test_an_episode_claims_a_goal_its_goal_checks_could_not_settle_on_the_effect_check_that_did():
    """The executive's side of it: symbolic heat_pie seed 18 — the oven's effect check confirmed
    heated(apple_pie), the goal checks after it could not settle it, three times. The claim rests on
    that effect check, the report names it, and the world holds the goal."""
    r = session("heat_pie.yaml").episode(18)
    goal_checks = [v for v in r["verifications"] if v["phase"] == "goal" and v["predicate"] == "heated(apple_pie)"]
    assert len(goal_checks) >= 3 and all(v["outcome"] == "unsettled" for v in goal_checks[-3:]), \
        "premise: the last three goal checks of heated(apple_pie) could not settle it"
    assert r["success"] and r["goal_satisfied"], r["reason"]
    assert "on the check that confirmed it" in r["reason"]
    [earlier] = r["goal_evidence"]["earlier"]
    assert earlier["predicate"] == "heated(apple_pie)" and earlier["outcome"] == "confirmed"
    named = r["verifications"][earlier["verification"]]
    assert named["phase"] == "eff" and named["value"] is True and named["action"].startswith("turnon(")
    assert all(v["outcome"] == "unsettled" for v in r["verifications"][earlier["verification"] + 1:]
               if v["predicate"] == "heated(apple_pie)"), "no settled check of it since"
