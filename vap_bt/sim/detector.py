"""The detector model: what the simulated cameras report of the objects in a frame.

The paper assumes objects of interest are detectable. A simulated camera therefore returns
instance detections, and this model says, in one place, how they differ from the truth; its
parameters are printed in every report.

* pybullet: the renderer's segmentation stands for an instance-segmentation network. An object
  is detected when at least ``min_pixels`` of it are visible (and ``min_fraction`` of the image,
  whichever is more): below that a real detector's recall collapses, and a few stray pixels of a
  far-away object would otherwise count as a sighting. Its mask is the segmentation's.
* symbolic: no pixels, so an object in view is missed with probability ``miss_rate`` (one
  independent draw per object and frame), and its reported location (``on``/``inside`` its
  support) names a wrong support of the same kind in the same room with probability
  ``relation_error`` — the two ways a real RGB-D pipeline errs. ``relation_error`` is set to the
  error rate the pybullet builder actually shows against the oracle (``tools/bench/scene_graph.py``
  measures it: see docs/BENCHMARKS.md), so that symbolic campaigns see the kind of belief the
  pixel pipeline builds; ``miss_rate`` is a detector that misses one object in twenty.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass(frozen=True)
class DetectorModel:
    """Parameters of the simulated detectors (see the module docstring for their reasons)."""

    min_pixels: int = 12
    min_fraction: float = 0.0005
    miss_rate: float = 0.05
    relation_error: float = 0.02

    def pixel_threshold(self, width: int, height: int) -> int:
        return max(self.min_pixels, int(self.min_fraction * width * height))

    def describe(self) -> dict:
        return asdict(self)
