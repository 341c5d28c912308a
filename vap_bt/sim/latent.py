"""The latent score of model vlm-2: how a simulated reader of a picture comes to a yes or a no.

Two world-side readers judge relations from a frame: the simulated VLM (:mod:`vap_bt.sim.sim_vlm`)
and the symbolic world's relation detector (:mod:`vap_bt.sim.relation_reports`). Both read the
same evidence (:mod:`vap_bt.sim.observability`: the apparent answer and how observable the
relation is in this picture) and both decide the same way. A reading is *yes* iff

    z = ± o · Φ⁻¹(A) + noise · [ b (1 − o) + Σ √r_k e_k ]

is positive: ± the apparent answer, ``o`` the observability, ``A`` the reader's accuracy at full
observability for the relation's class, ``b`` a bias towards yes that grows as the evidence fades,
and ``e_k`` standard normal parts with shares ``r_k`` of the noise's variance (summing to 1), each
drawn from the run's seed, the *picture* and a key naming what it is shared by (every reading of
one relation class in the picture, every reading of one atom, one wording). The same seed,
picture and key always give the same draw: the same picture is read the same way every time, and
only a genuinely new view draws anew.
"""

from __future__ import annotations

import random
from statistics import NormalDist

_NORMAL = NormalDist()


def probit(p: float) -> float:
    """Φ⁻¹(p), with p held within [0.5, 1): an accuracy below chance is chance."""
    return _NORMAL.inv_cdf(min(max(p, 0.5), 1.0 - 1e-9))


def signal(observability: float, accuracy: float) -> float:
    """The evidence's pull on the score: ``o · Φ⁻¹(A)``."""
    return observability * probit(accuracy)


def score(apparent: bool, d: float, observability: float, noise: float, yes_bias: float, shared: float) -> float:
    """The latent score ``z`` of the module docstring, given the signal ``d`` and the sum of the
    drawn parts ``shared``."""
    return (d if apparent else -d) + noise * (yes_bias * (1.0 - observability) + shared)


def draw_normal(seed: int, picture: str, *key: str) -> float:
    """A standard normal part, the same for the same seed, picture and key."""
    return random.Random("|".join((str(seed), picture, *key))).gauss(0.0, 1.0)


def draw_uniform(seed: int, picture: str, *key) -> float:
    """A uniform draw in [0, 1), the same for the same seed, picture and key."""
    return random.Random("|".join((str(seed), picture, *map(str, key)))).random()


def cdf(x: float) -> float:
    """Φ(x)."""
    return _NORMAL.cdf(x)
