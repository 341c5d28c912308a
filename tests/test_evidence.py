"""What a view weighs (vap_bt.perception.evidence): view kinds, the calibration's ratios, and the
claim's bound as a sequential test whose false-claim chance stays near its risk."""

from __future__ import annotations

import math
import random

import pytest

from vap_bt.domain.atoms import Atom
from vap_bt.perception.evidence import (
    CLAIM_RISK, MIN_VIEWS, VIEW_KINDS, Calibration, claim_threshold, default_calibration, view_kind, view_kinds)
from vap_bt.perception.verification import Round, located
from vap_bt.robot.frame import SELF, Detection, Frame, reference


def rnd(vote: bool | None, consistent: bool, sufficient: bool | None, stand=None, unshown=(), where=None) -> Round:
    return Round(view="f", vote=vote, consistent=consistent, sufficient=sufficient, stand=stand, unshown=unshown,
                 located=where)


def test_a_view_is_settled_consistent_or_split_with_its_majority():
    assert view_kind(rnd(True, True, True)) == "settled_yes"
    assert view_kind(rnd(False, True, False)) == "consistent_no"
    assert view_kind(rnd(True, True, None)) == "consistent_yes"
    assert view_kind(rnd(False, False, None)) == "split_no"
    assert view_kind(rnd(None, False, None)) is None  # no usable answer
    assert view_kind(rnd(True, True, True, unshown=("cup",))) is None  # the detector did not find the cup


def test_a_view_also_gives_what_its_detector_said_of_where_the_item_rests():
    assert view_kinds(rnd(True, True, True, where=False)) == ("settled_yes", "located_no")
    assert view_kinds(rnd(None, False, None, where=True)) == ("located_yes",)
    assert view_kinds(rnd(False, True, None)) == ("consistent_no",)


def _frame(*relations_of_wood) -> Frame:
    """wood1 and an open basket in view; the detector put wood1 where ``relations_of_wood`` say."""
    return Frame("f", 0.0, (Detection("wood", relations=relations_of_wood, name="wood1"),
                            Detection("basket", name="basket")))


def test_the_detector_locates_an_item_only_among_places_the_frame_shows():
    inside = Atom("inside", ("wood1", "basket"))
    assert located(_frame(Atom("inside", (SELF, reference(1)))), inside) is True
    floor = (Atom("on", (SELF, "floor_storage")), Atom("in_room", (SELF, "storage")))
    assert located(_frame(*floor), inside) is False
    assert located(_frame(*floor), Atom("on", ("wood1", "floor_storage")), frozenset({"floor_storage"})) is True
    assert located(_frame(Atom("in_room", (SELF, "storage"))), inside) is None  # no place reported
    assert located(_frame(Atom("holding", (SELF,))), inside) is False  # in the hand is elsewhere
    alone = Frame("f", 0.0, (Detection("wood", relations=floor, name="wood1"),))
    assert located(alone, inside) is None  # the basket is not in view: "not inside" would be no reading
    assert located(_frame(*floor), Atom("sliced", ("wood1",))) is None  # not a location


def test_the_detectors_reports_are_weighed_within_their_own_group():
    """A calibration counts answers and reports apart: each kind's frequency is of its own group,
    so adding reports leaves what the answers weigh unchanged."""
    answers = {"settled_yes": (300, 100), "settled_no": (100, 300)}
    plain = Calibration({"inside": answers})
    both = Calibration({"inside": {**answers, "located_yes": (900, 10), "located_no": (20, 200)}})
    assert both.weight("inside", "settled_yes") == pytest.approx(plain.weight("inside", "settled_yes"))
    assert both.weight("inside", "located_yes") == pytest.approx(math.log(900.5 / 921) - math.log(10.5 / 211))
    assert both.weight("inside", "located_no") < -2
    assert plain.weight("inside", "located_yes") == 0.0  # never counted: weighs nothing
    # a goal view whose answers say yes while the detector says elsewhere is evidence against
    assert both.log_odds("inside", [rnd(True, True, True, where=False)]) < 0


def test_a_predicate_counted_too_rarely_takes_the_pooled_ratios():
    rare = {"settled_yes": (5, 1), "settled_no": (1, 5)}
    common = {"settled_yes": (MIN_VIEWS, MIN_VIEWS // 2), "settled_no": (MIN_VIEWS // 2, MIN_VIEWS)}
    cal = Calibration({"rare": rare, "common": common})
    pooled = Calibration({"*": cal.pooled()})
    assert cal.weight("rare", "settled_yes") == pytest.approx(pooled.weight("anything", "settled_yes"))
    assert cal.weight("common", "settled_yes") != pytest.approx(cal.weight("rare", "settled_yes"))
    assert cal.weight("unknown", "settled_no") < 0 < cal.weight("unknown", "settled_yes")


def test_one_picture_counts_once_in_the_odds():
    cal = Calibration({"on": {"settled_yes": (300, 100), "settled_no": (100, 300)}})
    w = cal.weight("on", "settled_yes")
    same = [rnd(True, True, True, stand=(1, 2)), rnd(True, True, True, stand=(1, 2))]
    assert cal.log_odds("on", same) == pytest.approx(w)
    assert cal.log_odds("on", [*same, rnd(True, True, True, stand=(3, 4))]) == pytest.approx(2 * w)


def test_the_calibration_file_says_where_it_comes_from_and_kept_the_campaigns_seeds_out():
    cal = default_calibration()
    for key in ("backend", "command", "commit", "seeds"):
        assert cal.source.get(key), key
    first = int(str(cal.source["seeds"]).split("-")[0])
    assert first >= 1000  # the fault campaign runs seeds 0-999: it tests what calibration did not see
    assert {"sliced", "on", "holding"} <= set(cal.counts)


def _walk(cal: Calibration, predicate: str, truth: bool, rng: random.Random, cap: int) -> bool:
    """Views drawn from the calibration's own frequencies for ``truth``, weighed until the claim's
    bound is reached (True) or the cap or a strong contrary value ends the walk."""
    row = cal.row(predicate)
    freq = [row.get(k, (0, 0))[0 if truth else 1] for k in VIEW_KINDS]
    bound, odds = claim_threshold(CLAIM_RISK), 0.0
    for _ in range(cap):
        odds += cal.weight(predicate, rng.choices(VIEW_KINDS, freq)[0])
        if odds >= bound:
            return True
    return False


@pytest.mark.parametrize("predicate", ["sliced", "on", "holding"])
def test_an_atom_that_does_not_hold_is_claimed_about_as_rarely_as_the_risk_allows(predicate):
    """Wald's bound: views of an atom that does not hold reach odds of (1 − α)/α with chance at
    most about α, however long the robot looks — here up to 30 views, from the calibration's
    frequencies (a model weak on the relation, as vlm-2 is on ``sliced``, costs views instead)."""
    cal, rng = default_calibration(), random.Random(7)
    false_claims = sum(_walk(cal, predicate, False, rng, 30) for _ in range(4000)) / 4000
    true_claims = sum(_walk(cal, predicate, True, rng, 30) for _ in range(4000)) / 4000
    assert false_claims <= CLAIM_RISK * 1.2, false_claims
    assert true_claims >= 0.8, true_claims
    assert claim_threshold(0.05) == pytest.approx(math.log(19))
