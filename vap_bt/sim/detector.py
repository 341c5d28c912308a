"""The detector model: what the simulated cameras report of the objects in a frame.

A real instance-segmentation network returns, per instance it finds, a class label, a mask and a
score — never which bottle it is, and not always right. This model says, in one place, how the
simulated detectors differ from the truth; its parameters are printed in every report
(``world.detector``). Figures come from /work/notes/perception_sources.md (sections 6 and (f));
where a value is a judgment layered on published figures, it says so.

**pybullet** (:meth:`DetectorModel.detect`: the renderer's segmentation is the truth it errs on):

* *labels, not names* — a detection carries its class (:mod:`vap_bt.robot.labels`); the world
  keeps, on its side, which instance produced it (for scoring and the simulated VLM only);
* *misses grow as things shrink and hide* — an instance is never found below ``max(min_pixels,
  min_fraction x image)`` visible pixels; above, with probability ``recall(area) x (1 - o) **
  occlusion_power``. ``recall`` follows COCO's size bins (small < 32², medium < 96², large,
  in pixels of a 640 x 480 image — ``reference_pixels``: the frame stands for a D435i's 640 x 480
  colour stream, so an area counts as its share of the image): 0.45, 0.80, 0.92, from Mask R-CNN's
  AP_S : AP_M : AP_L = 15.5 : 38.1 : 52.4 (He et al., ICCV 2017, Table 1; absolute recalls at
  IoU 0.5 are the note's judgment), interpolated in log area between the bins' geometric
  centres (the form is judgment). ``o`` is the occluded share (1 − the visible fraction the world
  computes, parts cut off by the frame included), ignored for a thing covering at least
  ``plain_share`` of the image (a table top filling the view is not "hidden" by the frame's
  edge); ``(1 − o) ** 1.5`` falls to about 0.3 at 60 % occluded (pedestrian detectors' miss rate
  several times higher when heavily occluded: Repulsion Loss, CVPR 2018, CityPersons — recalled
  in the note, not verified);
* *false positives* — Poisson(``false_positives``) per image (0.2 at a 0.5 score threshold in
  clutter: the note's judgment; Borji, arXiv 2004.02877, finds many boxes on empty regions): a
  blob (an ellipse of random size and shape) of one region's pixels — another object's or the
  background's — labelled with a class uniformly drawn from the scene's, with a low score;
* *label confusion* — a found instance is given a similar class (:data:`SIMILAR
  <vap_bt.robot.labels.SIMILAR>`: cup/mug, plate/bowl, ...) with probability ``confusion``
  (0.05: the note's judgment; similar-class confusion is the largest source of top false
  positives, 33-74 %, in Hoiem et al., ECCV 2012);
* *masks are not the renderer's* — each mask's boundary moves by ``round(N(0, boundary_sigma))``
  pixels (clipped to ``boundary_band``; dilated outward bleeds onto the neighbour or background,
  eroded inward leaves its rim to the background) and each pixel of its one-pixel rim flips with
  probability ``boundary_flip``: Mask R-CNN's errors live within 1-3 px of the boundary (Tang et
  al., BPR, arXiv 2104.05239: fixing those pixels gains +9.4/+14.2/+17.8 AP) and its Boundary
  IoU is far below its mask IoU (69 % vs 89 % on the horse of Cheng et al., Boundary IoU, CVPR
  2021). Masks are painted far to near, so a near thing keeps its own pixels.

Every draw is seeded by the world's seed, the picture (the SHA-1 of its pixels) and the
instance: the same picture gives the same detections — a miss is systematic for a view, as a
real network's is — and only a different view draws anew.

**symbolic** (no pixels): an object in view is missed with probability ``miss_rate`` (one
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

import hashlib
import math
import random
from dataclasses import asdict, dataclass
from typing import Sequence

import cv2
import numpy as np

from vap_bt.robot.frame import Detection
from vap_bt.robot.labels import partners
from vap_bt.sim.latent import cdf, probit


@dataclass(frozen=True)
class Detected:
    """What the detector returns for one picture, and what the world keeps of it."""

    masks: np.ndarray  # (H, W) int32: the detection's index, -1 for no detection
    detections: tuple[Detection, ...]
    #: world side only: the instance behind each detection, by index ("" for a false positive)
    instances: tuple[str, ...]


@dataclass(frozen=True)
class DetectorModel:
    """Parameters of the simulated detectors (see the module docstring for their reasons)."""

    min_pixels: int = 12
    min_fraction: float = 0.0005
    #: the image size COCO's size bins are counted in (see the module docstring)
    reference_pixels: int = 640 * 480
    recall_small: float = 0.45
    recall_medium: float = 0.80
    recall_large: float = 0.92
    occlusion_power: float = 1.5
    plain_share: float = 0.1
    false_positives: float = 0.2
    confusion: float = 0.05
    boundary_sigma: float = 1.5
    boundary_band: int = 3
    boundary_flip: float = 0.25
    miss_rate: float = 0.05
    #: symbolic relation reports: accuracy at full observability, for every relation
    accuracy: float = 0.9999
    #: share of a report's latent noise common to every report of one relation class in one view
    view_correlation: float = 0.15
    #: scale of the reports' noise (1: the model; 0: what the view shows, read perfectly)
    relation_noise: float = 1.0

    def pixel_threshold(self, width: int, height: int) -> int:
        """Fewest visible pixels for a thing to be detectable in a ``width`` x ``height`` image."""
        return max(self.min_pixels, int(self.min_fraction * width * height))

    def error_at(self, observability: float) -> float:
        """The chance that one report about a relation shown at ``observability`` is wrong."""
        if self.relation_noise == 0:
            return 0.0 if observability > 0 else 1.0
        return cdf(-observability * probit(self.accuracy) / self.relation_noise)

    def describe(self) -> dict:
        """The model's parameters, its sources, the symbolic relation-report rule and its error at a few
        observabilities, for the report."""
        return {**asdict(self), "source": "/work/notes/perception_sources.md (sections 6, (f)); see vap_bt/sim/detector.py",
                "relations": "symbolic: each report right iff o * probit(accuracy) + relation_noise * "
                "(sqrt(view_correlation) e_class + sqrt(1 - view_correlation) e_atom) > 0, o the relation's "
                "observability in the view, the draws the same for the same view (model vlm-2's rule, "
                "vap_bt/sim/relation_reports.py); an item in a shut container is never reported",
                "error_at_observability": {str(o): round(self.error_at(o), 4) for o in (0.3, 0.5, 0.75, 1.0)}}

    # -- pybullet ------------------------------------------------------------------------------

    def recall(self, area: float, image: int, visible: float = 1.0) -> float:
        """Chance of finding an instance with ``area`` visible pixels in an ``image``-pixel frame,
        ``visible`` of it shown (see the module docstring)."""
        a = area * self.reference_pixels / image  # in pixels of the reference image
        # the bins' geometric centres: small from the pixel floor (12 px) to 32², medium 32²-96²,
        # large 96² to four times that
        anchors = ((12 * 32, self.recall_small), (32 * 96, self.recall_medium), (96 * 384, self.recall_large))
        if a <= anchors[0][0]:
            r = anchors[0][1]
        elif a >= anchors[-1][0]:
            r = anchors[-1][1]
        else:
            (a0, r0), (a1, r1) = next((p, q) for p, q in zip(anchors, anchors[1:]) if p[0] <= a <= q[0])
            r = r0 + (r1 - r0) * (math.log(a) - math.log(a0)) / (math.log(a1) - math.log(a0))
        occluded = 0.0 if area >= self.plain_share * image else 1.0 - min(1.0, max(0.0, visible))
        return r * (1.0 - occluded) ** self.occlusion_power

    def detect(self, instances: np.ndarray, names: Sequence[str], pixels: Sequence[int], visible: Sequence[float],
               labels: Sequence[str], depth: np.ndarray, classes: Sequence[str], key: str) -> Detected:
        """Detections in one picture. ``instances`` is the renderer's segmentation (index into
        ``names``, -1 elsewhere); per instance its visible ``pixels`` (what the detector has to go
        on: a doorway counts its opening), its ``visible`` fraction and class ``labels``;
        ``depth`` in metres; ``classes`` those the scene holds (false positives take one);
        ``key`` seeds every draw (the world's seed and the picture)."""
        h, w = instances.shape
        image = h * w
        threshold = self.pixel_threshold(w, h)
        found: list[tuple[str, str, np.ndarray, float]] = []  # name, label, mask, score
        beyond: list[int] = []  # pixels the instance counts beyond its own mask (a doorway's opening)
        for i, name in enumerate(names):
            rng = random.Random(f"{key}|{name}")
            p = self.recall(pixels[i], image, visible[i]) if pixels[i] >= threshold else 0.0
            if rng.random() >= p:
                continue
            label = labels[i]
            others = partners(label)
            if others and rng.random() < self.confusion:
                label = rng.choice(others)
            own = instances == i
            mask = self._boundary(own, _np_rng(key, name), rng)
            found.append((name, label, mask, round(0.5 + 0.5 * p, 3)))
            beyond.append(max(0, int(pixels[i]) - int(own.sum())))
        fps = self._false_positives(instances, classes, threshold, key)
        # paint far to near: a near thing keeps its pixels where a far one's mask bled onto it
        order = sorted(range(len(found)), key=lambda k: -_depth_of(depth, found[k][2]))
        painted = np.full((h, w), -1, np.int32)
        for k in order:
            painted[found[k][2]] = k
        for j, (_, mask, _) in enumerate(fps):
            painted[mask] = len(found) + j
        items = [(n, lb, s) for n, lb, _, s in found] + [("", lb, s) for lb, _, s in fps]
        # a network lists its detections in no order of identity: here left to right in the image
        # (a door found by its doorway alone, its leaf out of the picture, has no mask: first)
        cols = {k: _column(painted == k) for k in range(len(items))}
        kept = sorted(range(len(items)), key=lambda k: (cols[k], k))
        masks = np.full((h, w), -1, np.int32)
        dets, owners = [], []
        for new, k in enumerate(kept):
            m = painted == k
            masks[m] = new
            name, label, score = items[k]
            dets.append(Detection(label, int(m.sum()) + (beyond[k] if k < len(beyond) else 0), new, score))
            owners.append(name)
        return Detected(masks, tuple(dets), tuple(owners))

    def _boundary(self, mask: np.ndarray, nprng: np.random.Generator, rng: random.Random) -> np.ndarray:
        """``mask`` with its boundary moved and roughened (see the module docstring)."""
        if not mask.any():
            return mask
        shift = int(max(-self.boundary_band, min(self.boundary_band, round(rng.gauss(0.0, self.boundary_sigma)))))
        m = mask.astype(np.uint8)
        kernel = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (3, 3))
        if shift > 0:
            m = cv2.dilate(m, kernel, iterations=shift)
        elif shift < 0:
            eroded = cv2.erode(m, kernel, iterations=-shift)
            while not eroded.any() and shift < 0:  # a thin thing's mask keeps its core
                shift += 1
                eroded = cv2.erode(m, kernel, iterations=-shift) if shift < 0 else m
            m = eroded
        rim = (cv2.dilate(m, kernel) - cv2.erode(m, kernel)).astype(bool)
        flip = rim & (nprng.random(mask.shape) < self.boundary_flip)
        out = m.astype(bool) ^ flip
        return out if out.any() else m.astype(bool)

    def _false_positives(self, instances: np.ndarray, classes: Sequence[str], threshold: int,
                         key: str) -> list[tuple[str, np.ndarray, float]]:
        """Spurious detections: blobs of one region's pixels with a class from the scene."""
        rng = random.Random(f"{key}|false positives")
        if not classes or self.false_positives <= 0.0:
            return []
        h, w = instances.shape
        out = []
        for _ in range(_poisson(rng, self.false_positives)):
            label = rng.choice(sorted(set(classes)))
            v, u = rng.randrange(h), rng.randrange(w)
            area = math.exp(rng.uniform(math.log(2 * threshold), math.log(0.02 * h * w)))
            ratio = rng.uniform(0.5, 1.0)
            a = math.sqrt(area / (math.pi * ratio))
            blob = np.zeros((h, w), np.uint8)
            cv2.ellipse(blob, (u, v), (max(1, round(a)), max(1, round(a * ratio))), rng.uniform(0, 180), 0, 360, 1, -1)
            mask = blob.astype(bool) & (instances == instances[v, u])  # one object's pixels, or the background's
            if mask.sum() >= threshold:
                out.append((label, mask, round(rng.uniform(0.5, 0.75), 3)))
        return out

    # -- symbolic ------------------------------------------------------------------------------

    def missed(self, key: str) -> bool:
        """A systematic miss of a symbolic detection (``key``: seed, view and object)."""
        return random.Random(f"{key}|miss").random() < self.miss_rate


def _np_rng(key: str, name: str) -> np.random.Generator:
    return np.random.default_rng(int.from_bytes(hashlib.sha256(f"{key}|{name}|mask".encode()).digest()[:8], "little"))


def _poisson(rng: random.Random, mean: float) -> int:
    """A Poisson draw (Knuth's method: the means here are small)."""
    limit, k, p = math.exp(-mean), 0, rng.random()
    while p > limit:
        k += 1
        p *= rng.random()
    return k


def _depth_of(depth: np.ndarray, mask: np.ndarray) -> float:
    vals = depth[mask]
    vals = vals[vals > 0]
    return float(np.median(vals)) if vals.size else 0.0


def _column(mask: np.ndarray) -> float:
    cols = np.nonzero(mask)[1]
    return float(cols.mean()) if cols.size else -1.0
