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
