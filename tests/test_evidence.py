"""What a view weighs (vap_bt.perception.evidence): view kinds, the calibration's ratios, and the
claim's bound as a sequential test whose false-claim chance stays near its risk."""

from __future__ import annotations

import math
import random

import pytest

from vap_bt.perception.evidence import (
    CLAIM_RISK, MIN_VIEWS, VIEW_KINDS, Calibration, claim_threshold, default_calibration, view_kind)
from vap_bt.perception.verification import Round


def rnd(vote: bool | None, consistent: bool, sufficient: bool | None, stand=None, unshown=()) -> Round:
    return Round(view="f", vote=vote, consistent=consistent, sufficient=sufficient, stand=stand, unshown=unshown)


def test_a_view_is_settled_consistent_or_split_with_its_majority():
    assert view_kind(rnd(True, True, True)) == "settled_yes"
    assert view_kind(rnd(False, True, False)) == "consistent_no"
    assert view_kind(rnd(True, True, None)) == "consistent_yes"
    assert view_kind(rnd(False, False, None)) == "split_no"
    assert view_kind(rnd(None, False, None)) is None  # no usable answer
    assert view_kind(rnd(True, True, True, unshown=("cup",))) is None  # the detector did not find the cup


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
