"""The rules of one check, on their own: how views become a verdict and a verdict a settlement
(:mod:`vap_bt.perception.judgement`), and where the check looks next within its budget
(:class:`~vap_bt.perception.viewpoints.ViewpointSearch`). No behaviour tree, camera or model."""

from __future__ import annotations

from vap_bt.domain.atoms import Atom
from vap_bt.perception.evidence import Calibration
from vap_bt.perception.judgement import (JudgementRules, Settlement, Subject, conclude, evidence, judge,
                                         needs_second_look, reused)
from vap_bt.perception.verification import Round, Verdict, viewpoint_query
from vap_bt.perception.viewpoints import AROUND_ORDER, ViewpointSearch, ViewpointStrategy

CUP_ON_TABLE = Atom("on", ("cup", "table"))
HOLDING_CUP = Atom("holding", ("cup",))
HAND_EMPTY = Atom("hand_empty")
#: settled views right three times in four either way (likelihood ratio 3): odds of 19 to 1 (a
#: 5 % risk) take three settled views
RULES = JudgementRules(calibration=Calibration({"on": {"settled_yes": (600, 200), "settled_no": (200, 600)}}),
                       claim_risk=0.05)


def view(answers: str, sufficient: bool | None, stand: str | None = None) -> Round:
    """A round from answers like "yyyyn", voted 4-of-5 as the paper does, from ``stand``."""
    vals = [{"y": True, "n": False}[c] for c in answers]
    yes, no = vals.count(True), vals.count(False)
    return Round(view="f", questions=["Is the cup on the table?"] * len(vals), answers=vals, vote=yes > no,
                 consistent=max(yes, no) >= 4, sufficient=sufficient, stand=(stand,) if stand else None)


def pre(expected: bool = True) -> Subject:
    return Subject(CUP_ON_TABLE, expected, "pre")


def test_a_settled_view_that_confirms_the_plan_decides_at_once():
    assert judge(pre(), [view("yyyyy", True)], RULES, exhausted=False) == Verdict(True, "settled")


def test_a_surprise_waits_for_a_second_picture_while_the_budget_allows_one():
    one = [view("nnnnn", True, "a")]
    assert needs_second_look(pre(), False, one, RULES)
    assert judge(pre(), one, RULES, exhausted=False) is None
    assert judge(pre(), one, RULES, exhausted=True) == Verdict(False, "settled")  # all there is
    two = one + [view("nnnny", False, "b")]
    assert judge(pre(), two, RULES, exhausted=False) == Verdict(False, "settled")


def test_the_same_picture_again_is_no_second_look():
    twice = [view("nnnnn", True, "a"), view("nnnnn", True, "a")]
    assert needs_second_look(pre(), False, twice, RULES)


def test_an_atom_in_doubt_is_confirmed_only_by_a_second_picture():
    one = [view("yyyyy", True, "a")]
    assert judge(pre(), one, RULES, exhausted=False, doubted=False) == Verdict(True, "settled")
    assert judge(pre(), one, RULES, exhausted=False, doubted=True) is None


def test_the_papers_rule_believes_the_first_settled_view():
    papers = JudgementRules(second_look=False)
    assert judge(pre(), [view("nnnnn", True)], papers, exhausted=False) == Verdict(False, "settled")


def test_a_goal_is_claimed_only_on_odds_that_reach_the_bound():
    goal = Subject(CUP_ON_TABLE, True, "goal")
    two = [view("yyyyy", True, s) for s in "ab"]  # 9 to 1
    assert judge(goal, two, RULES, exhausted=False) is None
    assert judge(goal, two, RULES, exhausted=True) == Verdict(True, "unsettled")
    three = [view("yyyyy", True, s) for s in "abc"]  # 27 to 1
    assert judge(goal, three, RULES, exhausted=False) == Verdict(True, "settled")


def test_a_goal_check_weighs_earlier_views_of_the_atom_each_once():
    mine, earlier = view("yyyyy", True), view("yyyyy", True)
    goal = Subject(CUP_ON_TABLE, True, "goal")
    assert evidence(goal, [mine], [earlier, mine]) == [earlier, mine]
    assert evidence(pre(), [mine], [earlier]) == [mine]


def test_where_a_thing_rests_counts_earlier_views_only_once_the_goal_checks_own_showed_it():
    earlier, unshown = view("yyyyy", True), view("nynyy", False)
    unshown.unshown = ("cup",)
    goal = Subject(CUP_ON_TABLE, True, "goal")
    assert evidence(goal, [unshown], [earlier], whereabouts=True) == [unshown]
    assert evidence(goal, [unshown], [earlier], whereabouts=False) == [earlier, unshown]
    shown = view("yyyyy", True)
    assert evidence(goal, [unshown, shown], [earlier], whereabouts=True) == [earlier, unshown, shown]


def test_the_gripper_settles_what_the_camera_could_not():
    subject = Subject(HOLDING_CUP, True, "eff")
    unsettled = Verdict(False, "unsettled")
    assert conclude(subject, unsettled, None) == Settlement(True, "unsettled", "belief")  # belief stands
    s = conclude(subject, unsettled, True)
    assert (s.value, s.outcome, s.basis) == (True, "felt", "proprioception")
    s = conclude(subject, unsettled, False)
    assert (s.value, s.outcome, s.basis) == (False, "contradicted", "proprioception")


def test_empty_fingers_overrule_a_camera_that_saw_the_cup_held():
    subject = Subject(HOLDING_CUP, True, "eff")
    s = conclude(subject, Verdict(True, "settled"), False)
    assert (s.value, s.outcome, s.basis) == (False, "contradicted", "proprioception")
    # fingers closed on something do not say it is the cup: the camera's word stands
    s = conclude(Subject(HOLDING_CUP, False, "eff"), Verdict(False, "settled"), True)
    assert (s.value, s.outcome, s.basis) == (False, "confirmed", "vlm")
    # whether the hand is empty at all is the gripper's to say, either way
    s = conclude(Subject(HAND_EMPTY, True, "pre"), Verdict(True, "settled"), False)
    assert (s.value, s.outcome) == (False, "contradicted")


def test_a_reused_value_rests_on_no_look():
    assert reused(False) == Settlement(False, "reused", "reused")


def test_the_search_takes_the_strategys_direction_or_the_first_untried_of_the_round():
    search = ViewpointSearch(ViewpointStrategy("vlm"), budget=2)
    asked = search.next(CUP_ON_TABLE, view("yyyyy", False), None)
    assert asked == viewpoint_query(CUP_ON_TABLE, "Is the cup on the table?", "cup")
    assert search.pick("closer") == "closer"
    search.refuse("closer")
    assert search.pick("closer") == AROUND_ORDER[0]  # refused before: the round instead
    assert search.pick(None) == AROUND_ORDER[1]  # no answer: the round's next untried
    assert not search.spent
    search.moved()
    search.moved()
    assert search.spent and search.moves == 2


def test_the_greedy_all_search_takes_its_whole_round_whatever_k_and_pools_the_views():
    search = ViewpointSearch(ViewpointStrategy("greedy-all"), budget=2)
    assert search.budget == len(AROUND_ORDER) and search.pools
    seen = []
    while (d := search.next(CUP_ON_TABLE, view("yyyyy", False), None)) is not None:
        seen.append(search.pick(d))
        search.moved()
    assert seen == list(AROUND_ORDER) and search.spent
    assert not ViewpointSearch(ViewpointStrategy("greedy"), budget=2).pools


def test_an_unknown_viewpoint_strategy_is_refused_by_name():
    import pytest

    with pytest.raises(ValueError, match="'sideways'.*greedy-all"):
        ViewpointStrategy("sideways")


def test_the_greedy_search_goes_round_and_ends_when_every_way_was_tried():
    search = ViewpointSearch(ViewpointStrategy("greedy"), budget=3)
    assert search.pick(search.next(CUP_ON_TABLE, view("yyyyy", False), None)) == AROUND_ORDER[0]
    search.moved()
    # the next of the round not yet tried: never back to where the first move came from
    assert search.pick(search.next(CUP_ON_TABLE, view("yyyyy", False), None)) == AROUND_ORDER[1]
    for d in AROUND_ORDER[2:]:
        assert search.pick(d) == d
    assert search.pick(None) is None
