"""The detector model: what the simulated cameras report of the objects in a frame.

The paper assumes objects of interest are detectable. A simulated camera therefore returns
instance detections, and this model says, in one place, how they differ from the truth; its
parameters are printed in every report (``world.detector``).

* pybullet: the renderer's segmentation stands for an instance-segmentation network. An object
  is detected when at least ``min_pixels`` of it are visible (and ``min_fraction`` of the image,
  whichever is more): below that a real detector's recall collapses, and a few stray pixels of a
  far-away object would otherwise count as a sighting. Its mask is the segmentation's.
* symbolic: no pixels, so an object in view is missed with probability ``miss_rate`` (one
  independent draw per object and frame: a detector that misses one object in twenty), and the
  relations reported with each item — where it rests, what blocks it, whether it can be reached —
  err by model vlm-2's rule over how the view shows each relation
  (:mod:`vap_bt.sim.relation_reports`): a report is right iff its latent score
  ``o · Φ⁻¹(accuracy) + relation_noise · (√view_correlation e_class + √(1 − view_correlation) e_atom)``
  is positive, ``o`` the relation's observability in the view. ``accuracy`` is a geometric
  pipeline's at full observability: the pybullet builder perceived 72 item relations over every
  task scene × 3 seeds without an error (docs/BENCHMARKS.md, "The scene graph from RGB-D"), 95 %
  bound 3/72 ≈ 4 %; at 0.9999 the symbolic views (shares drawn in [0.3, 1]) misread an item's
  support 2.5 % of the time on average (13 % at the poorest contact, none at a full one), within
  that bound, and the voting over views stays exercised. ``view_correlation`` is vlm-2's share of
  the latent noise common to one relation class in one picture (0.15): a view that shows contacts
  poorly confuses every item's support in it together. ``relation_noise`` scales the noise (0: the
  reports say what the view shows wherever it shows the relation at all).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

from vap_bt.sim.latent import cdf, probit


@dataclass(frozen=True)
class DetectorModel:
    """Parameters of the simulated detectors (see the module docstring for their reasons)."""

    min_pixels: int = 12
    min_fraction: float = 0.0005
    miss_rate: float = 0.05
    #: symbolic relation reports: accuracy at full observability, for every relation
    accuracy: float = 0.9999
    #: share of a report's latent noise common to every report of one relation class in one view
    view_correlation: float = 0.15
    #: scale of the reports' noise (1: the model; 0: what the view shows, read perfectly)
    relation_noise: float = 1.0

    def pixel_threshold(self, width: int, height: int) -> int:
        return max(self.min_pixels, int(self.min_fraction * width * height))

    def error_at(self, observability: float) -> float:
        """The chance that one report about a relation shown at ``observability`` is wrong."""
        if self.relation_noise == 0:
            return 0.0 if observability > 0 else 1.0
        return cdf(-observability * probit(self.accuracy) / self.relation_noise)

    def describe(self) -> dict:
        return {**asdict(self), "relations": "symbolic: each report right iff o * probit(accuracy) + relation_noise * "
                "(sqrt(view_correlation) e_class + sqrt(1 - view_correlation) e_atom) > 0, o the relation's "
                "observability in the view, the draws the same for the same view (model vlm-2's rule, "
                "vap_bt/sim/relation_reports.py); an item in a shut container is never reported",
                "error_at_observability": {str(o): round(self.error_at(o), 4) for o in (0.3, 0.5, 0.75, 1.0)}}
