"""Confidence intervals the benches report beside every rate (one formula, shared).

A rate measured over n episodes or checks is an estimate; the Wilson score interval is the 95 %
interval that stays inside [0, 1] and is honest at 0 of n (a false-success rate of 0 of 180 is
"at most about 2 %", not "0 %") and for small n.
"""

from __future__ import annotations

import math


def wilson(k: int, n: int, z: float = 1.96) -> tuple[float, float]:
    """The Wilson score interval of ``k`` successes in ``n`` trials (95 % for z = 1.96)."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    mid, half = (p + z * z / (2 * n)), z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    # clamped: at k = 0 or k = n rounding leaves a bound a hair outside [0, 1] ("-0.0 %")
    return max(0.0, (mid - half) / (1 + z * z / n)), min(1.0, (mid + half) / (1 + z * z / n))


def paired_difference(both: int, only_first: int, only_second: int, neither: int,
                      z: float = 1.96) -> tuple[float, float, float]:
    """The difference of two success rates measured on the same n episodes (second minus
    first), with Newcombe's interval for paired proportions (Statistics in Medicine 17, 1998,
    method 10: Wilson intervals of each rate, joined through the pairs' correlation). Pairing
    counts only the episodes the two runs decided differently: ``only_first`` succeeded in the
    first run alone, ``only_second`` in the second alone."""
    n = both + only_first + only_second + neither
    if n == 0:
        return 0.0, -1.0, 1.0
    p1, p2 = (both + only_first) / n, (both + only_second) / n
    (l1, u1), (l2, u2) = wilson(both + only_first, n, z), wilson(both + only_second, n, z)
    den = math.sqrt((both + only_first) * (only_second + neither) * (both + only_second) * (only_first + neither))
    phi = (both * neither - only_first * only_second) / den if den else 0.0
    d = p2 - p1
    lower = math.sqrt(max(0.0, (p2 - l2) ** 2 - 2 * phi * (p2 - l2) * (u1 - p1) + (u1 - p1) ** 2))
    upper = math.sqrt(max(0.0, (u2 - p2) ** 2 - 2 * phi * (u2 - p2) * (p1 - l1) + (p1 - l1) ** 2))
    return d, max(-1.0, d - lower), min(1.0, d + upper)


def mcnemar_p(only_first: int, only_second: int) -> float:
    """Two-sided exact McNemar p-value: how often the episodes the two runs decided differently
    would split at least this unevenly if neither run were better (a fair coin per episode)."""
    n, k = only_first + only_second, min(only_first, only_second)
    if n == 0:
        return 1.0
    tail = sum(math.comb(n, i) for i in range(k + 1)) / 2 ** n
    return min(1.0, 2 * tail)


def paired_t(diffs: list[float], level: float = 0.95) -> tuple[float, float, float]:
    """The mean of paired differences (one per seed or episode) with its Student t interval;
    (nan, nan, nan) with no difference, and the mean with an unbounded interval with one."""
    from scipy import stats

    n = len(diffs)
    if n == 0:
        return math.nan, math.nan, math.nan
    mean = sum(diffs) / n
    if n == 1:
        return mean, -math.inf, math.inf
    half = stats.t.ppf((1 + level) / 2, n - 1) * stats.tstd(diffs) / math.sqrt(n) if len(set(diffs)) > 1 else 0.0
    return mean, mean - half, mean + half
