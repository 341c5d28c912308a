"""Estimates with 95 % intervals, and markdown tables of them.

A rate (successes of n episodes) gets the Wilson score interval (scipy's ``binomtest``): it
stays inside [0, 1] and is honest at 0 % and 100 %, where the normal approximation collapses to a
point. A mean gets Student's t interval. A comparison of two strategies is a *paired* difference:
the two ran the same tasks with the same seeds, so the difference is taken per (task, seed) pair
and its mean gets a t interval — much tighter than comparing two independent rates, because most
of an episode's luck (the injected situations, the model's draws) is shared by the pair.
"""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass
from typing import Iterable, Sequence

from scipy import stats

LEVEL = 0.95


@dataclass(frozen=True)
class Estimate:
    """A point estimate, its 95 % interval and the sample size behind it (``low``/``high`` NaN when
    the sample is too small for an interval)."""

    value: float
    low: float
    high: float
    n: int

    def percent(self) -> str:
        """``71.5 % [65.2, 77.1] (n=200)``: a rate as a table cell (``–`` for no sample)."""
        if not self.n:
            return "–"
        return f"{100 * self.value:.1f} % [{100 * self.low:.1f}, {100 * self.high:.1f}] (n={self.n})"

    def plain(self, digits: int = 2) -> str:
        """``2.41 [2.20, 2.63] (n=200)``: a mean as a table cell (``–`` for no sample)."""
        if not self.n:
            return "–"
        if math.isnan(self.low):
            return f"{self.value:.{digits}f} (n={self.n})"
        return f"{self.value:.{digits}f} [{self.low:.{digits}f}, {self.high:.{digits}f}] (n={self.n})"

    @property
    def errors(self) -> tuple[float, float]:
        """The distances from the value to the interval's ends (for matplotlib's ``yerr``; 0 if none)."""
        if math.isnan(self.low):
            return 0.0, 0.0
        return self.value - self.low, self.high - self.value


NONE = Estimate(math.nan, math.nan, math.nan, 0)


def rate(flags: Iterable[bool]) -> Estimate:
    """The share of true flags, with its Wilson score interval."""
    flags = list(flags)
    return share(sum(map(bool, flags)), len(flags))


def share(k: int, n: int) -> Estimate:
    """``k`` of ``n``, with its Wilson score interval."""
    if not n:
        return NONE
    ci = stats.binomtest(k, n).proportion_ci(LEVEL, method="wilson")
    return Estimate(k / n, ci.low, ci.high, n)


def mean(values: Iterable[float]) -> Estimate:
    """The mean, with its t interval (no interval below two values, or when they are all equal:
    the mean itself is then the interval). A value that is None is not there: a crashed episode's
    row has no counts (:func:`results.crashed`), and they are not zeros."""
    xs = [float(x) for x in values if x is not None]
    if not xs:
        return NONE
    m = statistics.fmean(xs)
    if len(xs) < 2:
        return Estimate(m, math.nan, math.nan, 1)
    half = stats.t.ppf((1 + LEVEL) / 2, len(xs) - 1) * statistics.stdev(xs) / math.sqrt(len(xs))
    return Estimate(m, m - half, m + half, len(xs))


def paired(a: dict, b: dict) -> Estimate:
    """The mean of ``a[k] - b[k]`` over the pairs both have (keys such as (task, seed)), with its t
    interval."""
    return mean(float(a[k]) - float(b[k]) for k in sorted(a.keys() & b.keys()))


def markdown(header: Sequence[str], rows: Iterable[Sequence[object]]) -> str:
    """A GitHub markdown table."""
    lines = ["| " + " | ".join(map(str, header)) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(map(str, row)) + " |" for row in rows]
    return "\n".join(lines) + "\n"
