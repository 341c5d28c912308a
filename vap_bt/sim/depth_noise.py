"""Depth as a wrist stereo camera of the Intel RealSense D435i's kind returns it, not as rendered.

The renderer's depth is exact to the float. A D435i computes depth by matching the two infrared
imagers' views (active stereo), and what it returns differs from the truth in four ways, each
modelled here from the sensor's published geometry (:class:`DepthNoiseModel` holds every
parameter with its source; every report prints them in ``world.depth_noise``):

1. **Axial error growing with the square of the range.** Depth is ``z = f·B / d`` for a
   disparity ``d`` measured to a fraction of a pixel, so an error of ``s`` pixels in ``d`` is an
   error of ``z² · s / (f·B)`` in ``z`` (Intel's RMS-error formula: *Tuning depth cameras for best
   performance*, Grunnet-Jepsen et al., Intel 2019), times a factor ``k`` for ordinary household
   surfaces, on which measured noise runs several times Intel's floor. ``f`` is the depth
   imager's own focal length at its native resolution — not the simulated image's: the disparity
   is searched on the imager's pixels, and the simulated frame's 320 px width is a rendering
   cost, which must not change how noisy the sensor is.
2. **Spatially correlated.** Stereo matching aggregates costs over a window and smooths the
   disparity (semi-global matching), so errors come in patches a few native pixels across, not as
   per-pixel white noise: a flat wall looks gently wavy. The noise is a coarse grid of normal draws
   upsampled to the image (patches ``patch_deg`` across) plus a small per-pixel part, together of
   RMS ``σ(z)``.
3. **Holes.** A background point that the left imager (whose view the depth image is) sees but the
   right imager does not — hidden behind a nearer object to its right — has no match: a band of no
   return to the left of every foreground edge, ``f·B·(1/z_near − 1/z_far)`` wide (the stereo
   occlusion "shadow"). Pixels at a depth discontinuity straddle two surfaces: most are invalidated
   by the matcher's consistency checks, some return a depth between the two (flying pixels). A
   small share of all pixels have no return anyway (the projector's pattern washed out, a
   specular spot).
4. **A working range.** Closer than the minimum range (the largest disparity the matcher searches)
   and beyond the maximum range there is no return; where the renderer met nothing before its far
   plane there is nothing to return either. Depth is reported in whole millimetres (Z16).

No return is depth 0, as the RealSense SDK writes it. The fingers and anything held in them ride
nearer the camera than its minimum range (the tcp is 0.105 m in front of the optical centre): a
real D435i returns no depth for them, and neither does this one.

The draws are seeded by the world's seed and the picture itself (the SHA-1 of the rgb image): the
same picture — the same pose in the same scene — gives the same depth, as a real camera looking
at an unchanged scene returns the same pattern; only a genuinely different view draws anew.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import cv2
import numpy as np


@dataclass(frozen=True)
class DepthNoiseModel:
    """A D435i-like wrist depth camera (metres, pixels of the native depth imager unless stated).

    Sources, as collected in /work/notes/perception_sources.md, section 7 and calibration (g)
    (status there: FOUND, FOUND-2nd, judgment): Intel's white paper *Tuning depth cameras for best
    performance* (Grunnet-Jepsen, Sweetser, Woodfill) for the RMS-error formula, its D435 curve's
    parameters (848 px, 90° HFOV, 50 mm baseline, 0.08 px subpixel) and the minimum range
    ``f·B/126``; Carfagni et al., Sensors 19(3):489, 2019 (a D415 on a plain wall: 3-5 times
    Intel's floor) for the household factor. The shares of correlated noise and of holes are
    modelling choices sized to what D435 depth maps show, stated as such."""

    #: stereo baseline of the D435/D435i (Intel's D435 RMS curve: 50 mm; FOUND-2nd)
    baseline: float = 0.050
    #: horizontal field of view Intel uses for the D435's depth (90°; FOUND in Intel's *Subpixel
    #: Linearity Improvement for D400*; the datasheet's 87° is within its ±3°)
    hfov_deg: float = 90.0
    #: native depth width the disparity is computed at: 848 × 480 is Intel's recommended depth
    #: resolution for the D435 (white paper; FOUND), the one a robot streams
    native_width: int = 848
    #: RMS subpixel error of the disparity (white paper: 0.08 px in Intel's D435 curve; below 0.1
    #: and approaching 0.05 on a well-textured target; FOUND-2nd)
    subpixel: float = 0.08
    #: measured noise over Intel's floor on ordinary household surfaces (the note's calibration
    #: (g): 2-3, judgment from a D415 measuring 3-5 times the floor on a plain wall; the middle)
    household: float = 2.5
    #: disparities the matcher searches (D400 default: 126); with ``f`` and ``baseline`` this sets
    #: the minimum range, ``f·B/126`` = 0.168 m at 848 × 480 (Intel BKM; FOUND-2nd)
    disparities: int = 126
    #: beyond this no depth is returned (datasheet: ideal range to 3 m, returns to ~10 m); the
    #: renderer's far plane (5 m) cuts first: past it there is no surface to return
    max_range: float = 10.0
    #: share of the noise's variance that is spatially correlated (a modelling choice: stereo
    #: noise on a flat target is mostly low-frequency waviness with little pixel-to-pixel grain)
    correlated_share: float = 0.8
    #: angular size of a correlated patch: about eight native pixels (0.1° each at 848 px over
    #: 90°), the span of the matcher's aggregation window
    patch_deg: float = 0.8
    #: a neighbour this much nearer or further (share of the range, at least ``edge_min`` m) is
    #: across a depth discontinuity
    edge_jump: float = 0.05
    edge_min: float = 0.03
    #: of the pixels at a discontinuity: the share with no return, and the share returning a depth
    #: between the two surfaces (flying pixels); the rest keep their own surface's depth
    edge_hole: float = 0.5
    edge_flying: float = 0.15
    #: share of all other pixels with no return (a modelling choice: about one pixel in a hundred)
    dropout: float = 0.01
    #: depth resolution of the Z16 stream (1 mm units)
    quantum: float = 0.001
    #: False: the rendered depth as it is (for tests of other things than perception)
    enabled: bool = True

    @classmethod
    def exact(cls) -> "DepthNoiseModel":
        """A perfect depth camera: the renderer's depth, unchanged."""
        return cls(enabled=False)

    @property
    def focal_px(self) -> float:
        """The depth imager's focal length in native pixels: 0.5·W / tan(HFOV / 2) (424 px)."""
        return 0.5 * self.native_width / math.tan(math.radians(self.hfov_deg) / 2)

    @property
    def min_range(self) -> float:
        """The nearest depth returned: the largest disparity searched at the native focal length."""
        return self.focal_px * self.baseline / self.disparities

    def sigma(self, z) -> np.ndarray:
        """RMS axial error (m) at range ``z`` (m): k · z² · subpixel / (f · B) (9.4 mm at 1 m)."""
        return np.square(z) * (self.household * self.subpixel / (self.focal_px * self.baseline))

    def describe(self) -> dict:
        """The model's parameters with the derived focal length, minimum range and RMS error at 1, 2 and
        3 m, for the report."""
        return {**asdict(self), "focal_px": round(self.focal_px, 1), "min_range": round(self.min_range, 3),
                "rms_at_1m": round(float(self.sigma(1.0)), 4), "rms_at_2m": round(float(self.sigma(2.0)), 4),
                "rms_at_3m": round(float(self.sigma(3.0)), 4)}

    # ------------------------------------------------------------ the noise

    def apply(self, depth: np.ndarray, fx: float, far: float, key: tuple[int, ...]) -> np.ndarray:
        """What the camera returns for the rendered (exact, metric) ``depth`` of an image whose
        focal length is ``fx`` pixels, rendered with its far plane at ``far``; ``key`` seeds the
        draws (the world's seed and the picture's hash)."""
        if not self.enabled:
            return np.asarray(depth, np.float32).copy()
        rng = np.random.default_rng(list(key))
        z = np.asarray(depth, np.float64)
        h, w = z.shape
        out = z + self.sigma(z) * self._field(rng, h, w, fx)
        edge = self._discontinuities(z)
        u = rng.random((h, w))
        holes = (edge & (u < self.edge_hole)) | (~edge & (u < self.dropout))
        flying = edge & (u >= self.edge_hole) & (u < self.edge_hole + self.edge_flying)
        if flying.any():  # somewhere between the pixel's surface and its nearest neighbour's
            near = cv2.erode(z.astype(np.float32), np.ones((3, 3), np.uint8)).astype(np.float64)
            out[flying] = near[flying] + (z[flying] - near[flying]) * rng.random(int(flying.sum()))
        holes |= self._shadow(z, fx)
        holes |= (z >= far * 0.999)  # the renderer met nothing
        out = np.round(out / self.quantum) * self.quantum
        holes |= (z < self.min_range) | (out < self.min_range) | (out > self.max_range)
        out[holes] = 0.0
        return out.astype(np.float32)

    def _field(self, rng: np.random.Generator, h: int, w: int, fx: float) -> np.ndarray:
        """Unit-RMS noise: correlated patches (a coarse grid, upsampled) and per-pixel grain."""
        cell = max(1.0, fx * math.tan(math.radians(self.patch_deg)))  # patch size in image pixels
        gh, gw = int(math.ceil(h / cell)) + 2, int(math.ceil(w / cell)) + 2
        coarse = cv2.resize(rng.standard_normal((gh, gw)).astype(np.float32), (int(gw * cell), int(gh * cell)),
                            interpolation=cv2.INTER_CUBIC)[:h, :w].astype(np.float64)
        coarse /= max(float(coarse.std()), 1e-9)  # upsampling smooths the variance away: back to 1
        fine = rng.standard_normal((h, w))
        return math.sqrt(self.correlated_share) * coarse + math.sqrt(1.0 - self.correlated_share) * fine

    def _discontinuities(self, z: np.ndarray) -> np.ndarray:
        """Pixels with a 4-neighbour across a depth jump."""
        jump = np.maximum(self.edge_jump * z, self.edge_min)
        edge = np.zeros(z.shape, bool)
        dy = np.abs(np.diff(z, axis=0)) > np.minimum(jump[1:], jump[:-1])
        dx = np.abs(np.diff(z, axis=1)) > np.minimum(jump[:, 1:], jump[:, :-1])
        edge[1:] |= dy
        edge[:-1] |= dy
        edge[:, 1:] |= dx
        edge[:, :-1] |= dx
        return edge

    def _shadow(self, z: np.ndarray, fx: float) -> np.ndarray:
        """Pixels the right imager cannot see: hidden behind something nearer up to ``k`` pixels to
        their right with f·B·(1/z_near − 1/z) ≥ k (``fx`` converts the angle to image pixels)."""
        inv = 1.0 / np.maximum(z, 1e-6)
        fb = fx * self.baseline
        # no shadow is wider than the nearest and the furthest surface in the picture make it
        span = float(inv.max() - inv.min()) if inv.size else 0.0
        reach = min(z.shape[1] - 1, int(math.ceil(fb * span)))
        out = np.zeros(z.shape, bool)
        for k in range(1, reach + 1):
            out[:, :-k] |= (inv[:, k:] - inv[:, :-k]) * fb >= k
        return out
