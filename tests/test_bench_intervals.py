"""The intervals the benches print beside their rates (tools/bench/intervals.py)."""

from __future__ import annotations

import math

import pytest

from tools.bench.intervals import mcnemar_p, paired_difference, paired_t, wilson


def test_wilson_is_honest_at_none_of_n():
    lo, hi = wilson(0, 180)
    assert lo == 0.0 and 0.015 < hi < 0.025  # "at most about 2 %", not "0 %"


def test_a_paired_difference_counts_only_the_episodes_the_runs_decided_differently():
    """Newcombe (1998), the paired example 12 / 9 / 2 / 21: a difference of 7 in 44."""
    d, lo, hi = paired_difference(both=12, only_first=2, only_second=9, neither=21)
    assert d == pytest.approx(7 / 44) and 0.0 < lo < d < hi < 0.3
    # the same data the other way round: the interval mirrors
    d2, lo2, hi2 = paired_difference(both=12, only_first=9, only_second=2, neither=21)
    assert (d2, lo2, hi2) == pytest.approx((-d, -hi, -lo))
    # episodes both runs won or both lost widen nothing in the difference's sign
    assert paired_difference(30, 2, 9, 3)[0] == pytest.approx(7 / 44)


def test_the_exact_mcnemar_p_value():
    assert mcnemar_p(2, 9) == pytest.approx(2 * (1 + 11 + 55) / 2 ** 11)
    assert mcnemar_p(0, 0) == 1.0 and mcnemar_p(4, 4) == 1.0
    assert mcnemar_p(0, 10) == pytest.approx(2 / 2 ** 10) and math.isclose(mcnemar_p(10, 0), mcnemar_p(0, 10))


def test_the_paired_t_interval_of_per_seed_differences():
    """Differences 1, 2, 3: mean 2, sd 1, t(0.975, 2) = 4.303 -> 2 -/+ 4.303 / sqrt(3)."""
    d, lo, hi = paired_t([1.0, 2.0, 3.0])
    assert d == 2.0 and (lo, hi) == pytest.approx((2 - 4.3027 / math.sqrt(3), 2 + 4.3027 / math.sqrt(3)), abs=1e-3)
    assert paired_t([-1.0, -1.0]) == (-1.0, -1.0, -1.0)  # no spread: no width
    assert math.isnan(paired_t([])[0]) and paired_t([0.5])[1:] == (-math.inf, math.inf)
