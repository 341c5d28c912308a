"""How much a view weighs: the odds a check's views give that an atom holds, and when to claim it.

A view of an atom ends in one of six *kinds* (:func:`view_kind`): its paraphrases agreed and the
view was judged sufficient (``settled``), agreed on an insufficient or unjudged view
(``consistent``), or disagreed among themselves (``split``) — each with the majority's yes or no.
How often each kind comes out when the atom holds, against when it does not, is the backend's
*calibration*: counts per predicate, measured against the world's truth over labelled episodes
(:data:`CALIBRATION`, written by ``tools/bench/calibrate.py``; a deployment with another model
measures its own the same way). The ratio of the two frequencies is the view's likelihood ratio;
distinct pictures are separate draws of the model's errors, so their log ratios add
(:func:`log_odds`), starting from even odds: the executive assumes nothing about how often its
skills fail.

That sum is a sequential probability-ratio test (Wald): success is claimed on a goal atom only
once the views' log odds reach ``ln((1 − α) / α)`` (:func:`claim_threshold`). Whatever the
order the views came in and however long the robot kept looking, the chance of ever reaching
that bound from the views of an atom that does *not* hold is about ``α`` (:data:`CLAIM_RISK`):
the per-atom risk of a false claim, however weak the model is on that relation. A weak model
costs views, not false claims. A predicate counted too rarely to trust its own ratios (fewer than
:data:`MIN_VIEWS` views of either truth) takes the pooled counts of every predicate.

Wald's bound assumes the views independent, and one model's views of one atom are not: a thing
that fell beside a basket looks "inside" to the model from every nearby stand (its errors belong
to the relation as much as to the picture). A second sensor with errors of its own is what breaks
that: where the frame's detector reports where an item rests
(:func:`~vap_bt.perception.verification.located`), each view also weighs that report —
``located_yes`` or ``located_no``, calibrated the same way against the truth, in a group of its
own (its frequencies are of reports, not of votes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Mapping

import yaml

from vap_bt.perception.verification import Round, distinct
from vap_bt.settings import CLAIM_RISK  # a run's setting (--claim-risk), per atom (see the module docstring)

#: the six kinds of a view that voted (see the module docstring), in the calibration file's order
VIEW_KINDS = ("settled_yes", "consistent_yes", "split_yes", "split_no", "consistent_no", "settled_no")
#: what the frame's relation detector said of a location atom, where it said anything
LOCATED_KINDS = ("located_yes", "located_no")
#: every kind, by the group its frequencies are taken within
GROUPS = (VIEW_KINDS, LOCATED_KINDS)
KINDS = VIEW_KINDS + LOCATED_KINDS
#: the calibration measured for the simulated model (and the default for any backend)
CALIBRATION = Path(__file__).with_name("calibration.yaml")
#: views of each truth a predicate needs in the calibration for ratios of its own: rough from
#: 30, but the predicate's own — the pooled ratios mix a model's strong existence questions with
#: its weak state ones, and would weigh a rarely false ``filled`` as if it were ``inview``
MIN_VIEWS = 30


def view_kind(r: Round) -> str | None:
    """What one view's answers said, as a calibration kind; None for a view that voted nothing
    (no usable answer, or the detector did not find the atom's objects)."""
    if r.vote is None or r.unshown:
        return None
    strength = "settled" if r.settled else "consistent" if r.consistent else "split"
    return f"{strength}_{'yes' if r.vote else 'no'}"


def view_kinds(r: Round) -> tuple[str, ...]:
    """Every kind one view gives: its answers' (:func:`view_kind`) and its detector's report."""
    answers = view_kind(r)
    return (*(() if answers is None else (answers,)),
            *(() if r.located is None else (f"located_{'yes' if r.located else 'no'}",)))


@dataclass(frozen=True)
class Calibration:
    """Counts of each view kind when a predicate held and when it did not (``counts[predicate]
    [kind] = (when true, when false)``), and where they come from."""

    counts: Mapping[str, Mapping[str, tuple[int, int]]]
    source: Mapping[str, object] = field(default_factory=dict)
    #: each predicate's log likelihood ratios, worked out on first use (a goal check weighs every
    #: view it has, each tick it decides)
    _weights: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def row(self, predicate: str) -> Mapping[str, tuple[int, int]]:
        """The counts ``predicate``'s views are weighed by: its own, or the pooled ones when it
        has fewer than :data:`MIN_VIEWS` of either truth."""
        return self.group_row(predicate, VIEW_KINDS)

    def group_row(self, predicate: str, group: tuple[str, ...]) -> dict[str, tuple[int, int]]:
        """The counts of one group of kinds for ``predicate``: its own, or the pooled ones when it
        has fewer than :data:`MIN_VIEWS` of either truth in that group."""
        own = self.counts.get(predicate, {})
        row = {k: own[k] for k in group if k in own}
        if row and min(sum(t for t, _ in row.values()), sum(f for _, f in row.values())) >= MIN_VIEWS:
            return row
        return self.pooled(group)

    def pooled(self, group: tuple[str, ...] = VIEW_KINDS) -> dict[str, tuple[int, int]]:
        """Every predicate's counts summed, for each kind of ``group``: what a predicate with too few views
        of its own is weighed by."""
        return {k: (sum(r.get(k, (0, 0))[0] for r in self.counts.values()),
                    sum(r.get(k, (0, 0))[1] for r in self.counts.values())) for k in group}

    def weights(self, predicate: str) -> Mapping[str, float]:
        """The log likelihood ratio of each kind, for an atom of ``predicate`` holding, within its
        group (add-one-half smoothing: a kind never seen with one truth is rare with it, not
        impossible); a group never counted weighs nothing."""
        if predicate not in self._weights:
            weights = {}
            for group in GROUPS:
                row = self.group_row(predicate, group)
                true_n, false_n = sum(t for t, _ in row.values()), sum(f for _, f in row.values())
                for k in group:
                    t, f = row.get(k, (0, 0))
                    weights[k] = (math.log((t + 0.5) / (true_n + 1)) - math.log((f + 0.5) / (false_n + 1))
                                  if true_n and false_n else 0.0)
            self._weights[predicate] = weights
        return self._weights[predicate]

    def weight(self, predicate: str, kind: str) -> float:
        """The log likelihood ratio of a view of ``kind`` (see :meth:`weights`)."""
        return self.weights(predicate)[kind]

    def log_odds(self, predicate: str, rounds: Iterable[Round]) -> float:
        """The log odds that an atom of ``predicate`` holds, from even, given its views (rounds
        of one stand count once: the same picture is the same draw)."""
        w = self.weights(predicate)
        return sum(w[k] for r in distinct(list(rounds)) for k in view_kinds(r))

    def odds_for(self, predicate: str, rounds: Iterable[Round], value: bool) -> float:
        """:meth:`log_odds` for ``value``: positive when the views favour it, negative against."""
        odds = self.log_odds(predicate, rounds)
        return odds if value else -odds

    @classmethod
    def load(cls, path: Path = CALIBRATION) -> "Calibration":
        """The calibration a YAML file holds (default: the shipped :data:`CALIBRATION`), as :meth:`to_yaml`
        writes it."""
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        counts = {p: {k: (int(v[0]), int(v[1])) for k, v in row.items()} for p, row in data["counts"].items()}
        return cls(counts, data.get("source", {}))

    def to_yaml(self) -> str:
        """The calibration as YAML, its source and then the counts by predicate and kind, as :meth:`load`
        reads it."""
        counts = {p: {k: list(row.get(k, (0, 0))) for k in KINDS if k in row or k in VIEW_KINDS}
                  for p, row in sorted(self.counts.items())}
        return (yaml.safe_dump({"source": dict(self.source)}, sort_keys=False, width=1000)
                + yaml.safe_dump({"counts": counts}, sort_keys=False, default_flow_style=None))


def claim_threshold(risk: float = CLAIM_RISK) -> float:
    """The log odds at which an atom is claimed with ``risk`` of its being false."""
    return math.log((1.0 - risk) / risk)


_DEFAULT: Calibration | None = None


def default_calibration() -> Calibration:
    """:data:`CALIBRATION`, read once."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = Calibration.load()
    return _DEFAULT
