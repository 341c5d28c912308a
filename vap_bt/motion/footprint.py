"""The robot and its obstacles seen from above: convex outlines and whether two keep apart.

A base move is safe when the base's footprint — and, when the arm is folded over the base's
front, the arm's outline too — keeps a margin from every obstacle's outline (walls, furniture,
door leaves as they stand). Outlines are convex polygons (the hull of a box's corners dropped to
the floor, so a box turned about any axis — an oven door hinged at its bottom — has its true
shadow); two of them keep apart when some edge normal separates their projections by more than
the margin (the separating axis test).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

#: half length and half width of the base's box
FOOTPRINT = (0.31, 0.26)
#: the folded arm (home pose) seen from above, in the base frame: it reaches past the base's front
FOLDED_ARM = ((0.31, -0.06), (0.72, -0.06), (0.72, 0.2), (0.31, 0.2))


@dataclass(frozen=True)
class Obb:
    """An oriented box: centre, rotation (columns are its axes), half extents."""

    center: np.ndarray
    R: np.ndarray
    half: np.ndarray

    @classmethod
    def aabb(cls, lo, hi) -> "Obb":
        """The axis-aligned box between corners ``lo`` and ``hi``."""
        lo, hi = np.asarray(lo, float), np.asarray(hi, float)
        return cls((lo + hi) / 2, np.eye(3), (hi - lo) / 2)

    def corners(self) -> np.ndarray:
        """Its eight corners (8, 3), in the frame its centre is given in."""
        signs = np.array(list(itertools.product((-1, 1), repeat=3)), float)
        return self.center + (signs * self.half) @ self.R.T

    def polygon(self) -> np.ndarray:
        """Its outline seen from above (convex polygon, counter-clockwise)."""
        return hull(self.corners()[:, :2])

    def contains(self, pts: np.ndarray, margin: float) -> np.ndarray:
        """Which of ``pts`` lie within the box grown by ``margin``."""
        local = np.abs((np.asarray(pts) - self.center) @ self.R)
        return np.all(local <= self.half + margin, axis=1)

    def pose(self) -> np.ndarray:
        """Its centre and axes as a 4x4 transform."""
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = self.R, self.center
        return T


def hull(pts: np.ndarray) -> np.ndarray:
    """Convex hull of 2-D points (monotone chain), counter-clockwise."""
    P = sorted(map(tuple, np.round(pts, 9)))
    if len(P) <= 2:
        return np.array(P)

    def half(seq):
        out: list = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out

    lower, upper = half(P), half(reversed(P))
    return np.array(lower[:-1] + upper[:-1])


def _normals(poly: np.ndarray) -> np.ndarray:
    """A convex polygon's unit edge normals (degenerate edges left out)."""
    edges = np.roll(poly, -1, axis=0) - poly
    normals = np.stack([edges[:, 1], -edges[:, 0]], axis=1)
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-9
    return normals[keep] / lengths[keep, None]


def apart(a: np.ndarray, b: np.ndarray, margin: float) -> bool:
    """True when two convex polygons are separated by more than ``margin`` along some axis: x, y
    (their bounding boxes, the quick test) or an edge normal of either."""
    if (a.min(0) > b.max(0) + margin).any() or (b.min(0) > a.max(0) + margin).any():
        return True
    n = np.concatenate([_normals(a), _normals(b)])
    pa, pb = a @ n.T, b @ n.T
    return bool(np.any((pa.min(0) > pb.max(0) + margin) | (pb.min(0) > pa.max(0) + margin)))


def near(shape: np.ndarray, polys: list[np.ndarray], margin: float) -> list[np.ndarray]:
    """The ``polys`` whose bounding boxes come within ``margin`` of ``shape``'s: the others are
    :func:`apart` from it already. One pass over all of them: a base pose is tested against every
    wall and piece of furniture of the house, thousands of times per work-pose search, and nearly
    all of them are far away."""
    if not polys:
        return []
    pts = np.concatenate(polys)
    starts = np.cumsum([0] + [len(p) for p in polys[:-1]])
    lo, hi = np.minimum.reduceat(pts, starts), np.maximum.reduceat(pts, starts)
    close = np.all((lo <= shape.max(0) + margin) & (shape.min(0) <= hi + margin), axis=1)
    return [p for p, c in zip(polys, close) if c]


def placed(local, pose) -> np.ndarray:
    """A polygon given in the base frame, in the world for base ``pose`` (x, y, yaw)."""
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    return np.asarray(local, float) @ np.array([[c, s], [-s, c]]) + (x, y)


def footprint(pose) -> np.ndarray:
    """The base's rectangle (``FOOTPRINT``) in the world for base ``pose`` (x, y, yaw),
    counter-clockwise."""
    L, W = FOOTPRINT
    return placed([(L, W), (-L, W), (-L, -W), (L, -W)], pose)


def base_free(pose, obstacles: list[np.ndarray], margin: float, folded: bool = False, arm=FOLDED_ARM,
              low: list[np.ndarray] = ()) -> bool:
    """The base (and, if ``folded``, the arm above it: ``arm``'s outline in the base frame, the
    folded arm's by default) keeps ``margin`` off every obstacle; the base alone keeps it off the
    ``low`` ones (items on the floor, which the arm passes over)."""
    base = footprint(pose)
    shapes = [base] + ([placed(arm, pose)] if folded else [])
    return (all(apart(s, o, margin) for s in shapes for o in near(s, obstacles, margin))
            and all(apart(base, o, margin) for o in near(base, list(low), margin)))
