"""Rendering: the wrist RGB-D camera (and an overview camera for pictures), with segmentation.

pybullet's TinyRenderer (``ER_TINY_RENDERER``, no GPU) draws colour, a non-linear depth buffer and
a segmentation mask. We turn the depth buffer into metres (``far*near / (far - (far-near)*d)``),
the mask into body ids (``seg & 0xFFFFFF``), and body ids into object names through the scene.

Visibility of an object is the number of its visible pixels divided by its *unoccluded* projected
size. The latter is estimated without a second render: the corners of the object's box are projected
into the image and the area of their convex hull (the union of the hulls of its links' boxes, for
furniture with leaves: an open door does not make the carcass look hidden) is scaled by a fill
factor for the object's shape (a sphere fills about half the hull of its box, a box nearly all of
it). An item's box turns with the item (a knife lying at 45 degrees fills a tenth of its
axis-aligned box, and counted as a quarter visible seen whole); furniture's boxes are
axis-aligned, as it stands.
A room door is seen as its doorway: the pixels inside its closed leaf's outline that show the leaf
or the room beyond (an open door is seen by seeing through it), over that outline's area. It counts
parts outside the frame as not visible, which is what a camera would show. The estimate is a
documented proxy, clipped to [0, 1].
"""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np

from robots.config import Camera
from vap_bt.sim.pb import pb
from vap_bt.sim.pb_robot import quat_of

#: m short of a doorway's plane a pixel's depth may end and still count as seen through it
DOORWAY_SLACK = 0.1
FILL = {"box": 0.9, "cylinder": 0.75, "sphere": 0.5, "furniture": 0.85, "door": 0.9}


@dataclass(frozen=True)
class Render:
    """One rendered camera image: colour, depth (m), the body (and link) each pixel shows, and the
    optical frame's pose in the world."""

    rgb: np.ndarray  # (H, W, 3) uint8
    depth: np.ndarray  # (H, W) float32 metres
    bodies: np.ndarray  # (H, W) int32 body id, -1 background
    pose: np.ndarray  # 4x4 optical frame (z forward, x right, y down)
    camera: Camera
    links: np.ndarray | None = None  # (H, W) int32 link index within the body (-1: its base), -2 background

    @property
    def intrinsics(self) -> tuple[float, float, float, float]:
        """The pinhole intrinsics (fx, fy, cx, cy) in pixels."""
        c = self.camera
        return (c.fx, c.fy, c.cx, c.cy)

    @property
    def pose7(self) -> tuple[float, ...]:
        """The optical frame's pose as position (x, y, z) and quaternion (x, y, z, w), world frame."""
        return (*map(float, self.pose[:3, 3]), *map(float, quat_of(self.pose[:3, :3])))

    def pixel_threshold(self) -> int:
        """Fewest visible pixels for an object to count as in view (0.05 % of the image, >= 12)."""
        return max(12, int(0.0005 * self.camera.width * self.camera.height))


def render(cid: int, pose: np.ndarray, camera: Camera, shadows: bool = False) -> Render:
    """Render from an optical-frame pose (4x4, world)."""
    eye = pose[:3, 3]
    view = pb.computeViewMatrix(tuple(eye), tuple(eye + pose[:3, 2]), tuple(-pose[:3, 1]))
    proj = pb.computeProjectionMatrixFOV(camera.vertical_fov_deg, camera.width / camera.height, camera.near, camera.far)
    w, h, rgba, depth, seg = pb.getCameraImage(
        camera.width, camera.height, view, proj, renderer=pb.ER_TINY_RENDERER, shadow=int(shadows),
        flags=pb.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX, physicsClientId=cid)
    rgb = np.asarray(rgba, np.uint8).reshape(h, w, 4)[:, :, :3].copy()
    d = np.asarray(depth, np.float32).reshape(h, w)
    metric = camera.far * camera.near / (camera.far - (camera.far - camera.near) * d)
    seg = np.asarray(seg, np.int64).reshape(h, w)
    bodies = np.where(seg >= 0, seg & 0xFFFFFF, -1).astype(np.int32)
    links = np.where(seg >= 0, (seg >> 24) - 1, -2).astype(np.int32)
    return Render(rgb, metric.astype(np.float32), bodies, pose, camera, links)


def name_image(r: Render, names: dict[int, str], ids: dict[str, int]) -> np.ndarray:
    """Segmentation in object ids (``ids`` numbers the names), -1 for anything unnamed."""
    out = np.full(r.bodies.shape, -1, np.int32)
    for body, name in names.items():
        out[r.bodies == body] = ids[name]
    return out


def box_corners(box: tuple[float, ...]) -> np.ndarray:
    """The eight corners (8, 3) of an axis-aligned box (x0, y0, z0, x1, y1, z1)."""
    lo, hi = np.array(box[:3]), np.array(box[3:])
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def world_points(r: Render) -> np.ndarray:
    """(H, W, 3) map-frame point of every pixel from the render's exact depth (world side only:
    the oracle's geometry of the picture, never a sensor's)."""
    c = r.camera
    h, w = r.depth.shape
    v, u = np.mgrid[0:h, 0:w]
    z = r.depth.astype(float)
    cam = np.stack([(u - c.cx) / c.fx * z, (v - c.cy) / c.fy * z, z], axis=-1)
    return cam @ r.pose[:3, :3].T + r.pose[:3, 3]


def _projected(r: Render, corners: np.ndarray) -> np.ndarray | None:
    """Image points of a box's corners (None when it is all behind the camera)."""
    inv = np.linalg.inv(r.pose)
    pc = (inv[:3, :3] @ corners.T).T + inv[:3, 3]
    if np.all(pc[:, 2] < r.camera.near):
        return None
    z = np.maximum(pc[:, 2], r.camera.near)
    c = r.camera
    return np.stack([c.fx * pc[:, 0] / z + c.cx, c.fy * pc[:, 1] / z + c.cy], axis=1).astype(np.float32)


def projected_area(r: Render, boxes: list[np.ndarray]) -> float:
    """Area (pixels) of the union of the convex hulls of the boxes' projected corners (each box
    given by its eight corners): exact for one box, rasterised on a canvas three images wide for
    several (a carcass and its leaves)."""
    hulls = [cv2.convexHull(uv) for uv in (_projected(r, b) for b in boxes) if uv is not None]
    if len(hulls) <= 1:
        return float(cv2.contourArea(hulls[0])) if hulls else 0.0
    h, w = r.bodies.shape
    canvas = np.zeros((3 * h, 3 * w), np.uint8)
    for hull in hulls:
        pts = np.clip(hull.reshape(-1, 2) + (w, h), -10 * w, 10 * w).astype(np.int32)
        cv2.fillConvexPoly(canvas, pts, 1)
    return float(np.count_nonzero(canvas))


def visibility(r: Render, counts: dict[str, int], boxes: dict[str, list[np.ndarray]], fills: dict[str, float]) -> dict[str, float]:
    """Visible fraction of each named object (see the module docstring for the proxy)."""
    out = {}
    for name, parts in boxes.items():
        n = counts.get(name, 0)
        if n == 0:
            out[name] = 0.0
            continue
        area = projected_area(r, parts) * fills.get(name, 0.8)
        out[name] = float(min(1.0, n / area)) if area > 0 else 0.0
    return out


def doorway_pixels(r: Render, center, half, normal, bodies: set[int]) -> tuple[int, float, tuple[str, ...]]:
    """How a doorway shows: the pixels inside the projection of its closed leaf's box that show
    the leaf or reach past the doorway's plane (an open door is seen by seeing through it), that
    projection's whole area (pixels, parts outside the image included), and the image edges
    those pixels touch (as :func:`mask_extents` gives them for a body)."""
    uv = _projected(r, box_corners((*(np.asarray(center) - half), *(np.asarray(center) + half))))
    if uv is None:
        return 0, 0.0, ()
    hull = cv2.convexHull(uv)
    h, w = r.bodies.shape
    inside = np.zeros((h, w), np.uint8)
    cv2.fillConvexPoly(inside, np.clip(hull.reshape(-1, 2), -10 * w, 10 * w).astype(np.int32), 1)
    rows, cols = np.nonzero(inside)
    if len(rows) == 0:
        return 0, float(cv2.contourArea(hull)), ()
    c = r.camera
    rays = np.stack([(cols - c.cx) / c.fx, (rows - c.cy) / c.fy, np.ones(len(rows))], axis=1)
    R, eye = r.pose[:3, :3], r.pose[:3, 3]
    n = np.asarray(normal, float)
    denom = rays @ (R.T @ n)
    with np.errstate(divide="ignore", invalid="ignore"):
        z_plane = ((np.asarray(center) - eye) @ n) / denom  # optical depth of the doorway's plane
    through = (r.depth[rows, cols] >= z_plane - DOORWAY_SLACK) & (z_plane > 0)
    seen = through | np.isin(r.bodies[rows, cols], list(bodies))
    return int(np.count_nonzero(seen)), float(cv2.contourArea(hull)), _edges(rows[seen], cols[seen], h, w)


def _edges(rows: np.ndarray, cols: np.ndarray, h: int, w: int) -> tuple[str, ...]:
    """The image edges that pixels at ``rows``, ``cols`` touch."""
    if len(rows) == 0:
        return ()
    return tuple(e for e, hit in (("bottom", rows.max() == h - 1), ("left", cols.min() == 0),
                                  ("right", cols.max() == w - 1), ("top", rows.min() == 0)) if hit)


def pixel_counts(r: Render, names: dict[int, str]) -> dict[str, int]:
    """How many pixels of ``r`` show each named thing (the bodies in ``names``; others, and the
    background, are not counted)."""
    ids, counts = np.unique(r.bodies, return_counts=True)
    out: dict[str, int] = {}
    for b, n in zip(ids.tolist(), counts.tolist()):
        name = names.get(b)
        if name is not None:
            out[name] = out.get(name, 0) + n
    return out


def mask_extents(r: Render, names: dict[int, str]) -> dict[str, tuple[tuple[str, ...], float]]:
    """For each named object in the image: which image edges its pixels touch and the share of the
    image it covers (what a model reads off a picture about where to look next)."""
    h, w = r.bodies.shape
    out: dict[str, tuple[list[str], int]] = {}
    for body in np.unique(r.bodies).tolist():
        name = names.get(body)
        if name is None:
            continue
        rows, cols = np.nonzero(r.bodies == body)
        edges, n = out.get(name, ([], 0))
        out[name] = (sorted(set(edges) | set(_edges(rows, cols, h, w))), n + len(rows))
    return {k: (tuple(e), n / (w * h)) for k, (e, n) in out.items()}
