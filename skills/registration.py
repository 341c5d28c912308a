"""Where the map lies in the frame the robot believes it stands in: registering furniture to a view.

A mobile base knows its pose from a localiser good to a few centimetres and a degree or two, so
the site map's annotations — a handle, a tap, a switch, a cavity's walls — are off by that much in
the frame the robot measures and moves in. From one stance that frame is consistent: what the
camera measures is where the arm goes. A robot that works at a piece of furniture therefore looks
at it from where it stands and lays the map's model of it onto what the camera shows, as a
technician's robot re-registers to the fixture it works on; the map, shifted by the correction,
is then right to within the fit's error *from this stance*, however wrong the localiser is.

The model of a piece is the map's: its solid boxes (a container's with its cavity carved out) and
its door leaf where it was last seen. The correction is planar — ``(dx, dy, dθ)``, the localiser's
own degrees of freedom — and found by least squares on the distance of the frame's points of the
mapped pieces to their model's surfaces (robust loss: a few stray points, an item in front, do not
pull it), with a weak prior towards no correction, so that what a view does not constrain (the
position along a long front of which it shows only the middle) stays as the localiser said.

A fit is accepted only when it explains the points: most of them lie near the model's surfaces
after it, and the shift stays within what a localiser plausibly errs by; otherwise there is no
correction (the map is used as the localiser places it). Parameters are in
:class:`RegistrationParams`, each with its reason.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy.optimize import least_squares

from vap_bt.motion.footprint import Obb
from vap_bt.robot.site_map import Articulation, DoorInfo, FurnitureInfo, RoomInfo, SiteMap


@dataclass(frozen=True)
class RegistrationParams:
    """When a view's points of the mapped furniture make a correction (metres, radians)."""

    #: fewest points (of all the pieces in the frame, cleaned and voxelised) for a fit
    min_points: int = 60
    #: most points a fit uses (every k-th beyond): three hundred points on a few faces fix three
    #: degrees of freedom well, and every frame the eyes take is registered (a fit costs ~0.1 ms
    #: per point)
    max_points: int = 300
    #: the robust loss's scale: the depth noise of points seen from a metre or two away
    scale: float = 0.02
    #: a point this near a model surface after the fit is explained by it (noise, voxel)
    inlier: float = 0.035
    #: share of the points a fit must explain to be taken
    min_inliers: float = 0.6
    #: the largest correction believed: a localiser further off has lost itself
    max_shift: float = 0.2
    max_turn: float = 0.15
    #: the prior's spread: about a localiser's error (5 cm, 2 degrees); its weight is that of a
    #: few points, so that only directions the points leave open stay where the localiser put them
    prior_shift: float = 0.05
    prior_turn: float = 0.035
    prior_points: float = 4.0
    #: a direction of the correction (a shift, or a turn seen a metre away) is believed only if the
    #: points pin it down as firmly as this many points on a face square to it would: along a long
    #: counter, or in the turn a low hearth seen alone leaves open, the fit says nothing, and a
    #: wrong turn carried across the room put a room door's leaf in its doorway (store_firewood).
    #: One point's worth: the fits of the episodes looked at that were right had a few at least in
    #: every direction (a box's edges pin a shift along its face), the wrong ones none
    min_constraint: float = 1.0
    #: metres at which a turn is weighed against a shift (a turn of 0.01 rad is a shift of 1 cm here)
    lever: float = 1.0
    #: a fit that moves the map less than this (at the pivot) and turns it less than ``least_turn``
    #: is no evidence against the localiser: the fit's own error, measured on exact depth with no
    #: localisation error at all, reached 1.9 cm and 0.013 rad (the map's boxes are not the
    #: furniture's meshes: a microwave's front, a drawer's), and such a "correction" put the
    #: fingers 1.9 cm beside a microwave's handle bar. The localiser is then taken as right
    least_shift: float = 0.025
    least_turn: float = 0.015


@dataclass(frozen=True)
class Correction:
    """The map as it lies in the robot's frame now: ``(dx, dy, dθ)`` about ``pivot`` (x, y), with
    how many points and which pieces the fit rested on."""

    dx: float
    dy: float
    dtheta: float
    pivot: tuple[float, float]
    points: int
    pieces: tuple[str, ...]
    inliers: float

    @classmethod
    def none(cls) -> "Correction":
        """No correction: the map as the localiser places it."""
        return cls(0.0, 0.0, 0.0, (0.0, 0.0), 0, (), 1.0)

    def matrix(self) -> np.ndarray:
        """4x4: a map point to where the robot's frame has it."""
        c, s = math.cos(self.dtheta), math.sin(self.dtheta)
        T = np.eye(4)
        T[:2, :2] = [[c, -s], [s, c]]
        p = np.asarray(self.pivot, float)
        T[:2, 3] = p + np.array([self.dx, self.dy]) - T[:2, :2] @ p
        return T

    def point(self, p) -> np.ndarray:
        """A map point where the robot's frame has it."""
        T = self.matrix()
        return T[:3, :3] @ np.asarray(p, float) + T[:3, 3]

    def vector(self, v) -> np.ndarray:
        """A map direction as the robot's frame has it (turned by ``dtheta``, not shifted)."""
        return self.matrix()[:3, :3] @ np.asarray(v, float)

    def pose(self, x: float, y: float, yaw: float) -> tuple[float, float, float]:
        """A planar pose (x, y, heading) of the map in the robot's frame."""
        p = self.point((x, y, 0.0))
        return float(p[0]), float(p[1]), float(yaw + self.dtheta)

    def is_identity(self) -> bool:
        """Whether it moves nothing (no fit was accepted, or it found no error)."""
        return self.dx == 0.0 and self.dy == 0.0 and self.dtheta == 0.0

    def moved(self, T: np.ndarray) -> "Correction":
        """This correction followed by the planar 4x4 ``T`` (the robot's frame moved), about the
        same pivot."""
        M = np.asarray(T, float) @ self.matrix()
        th = math.atan2(M[1, 0], M[0, 0])
        p = np.asarray(self.pivot, float)
        d = M[:2, 3] + M[:2, :2] @ p - p
        return Correction(float(d[0]), float(d[1]), th, self.pivot, self.points, self.pieces, self.inliers)


def surface_distance(pts: np.ndarray, boxes: list[Obb]) -> np.ndarray:
    """Each point's distance to the nearest face of any of ``boxes`` (inside a box: to its nearest
    face too), (N,)."""
    best = np.full(len(pts), np.inf)
    for b in boxes:
        local = (pts - b.center) @ b.R
        q = np.abs(local) - b.half
        outside = np.linalg.norm(np.maximum(q, 0.0), axis=1)
        inside = -np.minimum(q.max(axis=1), 0.0)
        best = np.minimum(best, outside + inside)
    return best


def register(clouds: dict[str, np.ndarray], models: dict[str, list[Obb]],
             params: RegistrationParams = RegistrationParams()) -> Correction | None:
    """The correction that lays ``models`` (map frame, by piece) onto ``clouds`` (the frame's
    points of each piece, robot frame), or None when the points do not support one."""
    names = tuple(n for n in clouds if n in models and len(clouds[n]))
    if not names:
        return None
    pts = np.vstack([clouds[n] for n in names])
    if len(pts) < params.min_points:
        return None
    owner = np.concatenate([np.full(len(clouds[n]), i) for i, n in enumerate(names)])
    stride = max(1, math.ceil(len(pts) / params.max_points))
    pts, owner = pts[::stride], owner[::stride]
    pivot = pts[:, :2].mean(axis=0)
    weight = math.sqrt(params.prior_points)

    def to_map(x) -> np.ndarray:
        """The robot-frame points moved by the inverse of the correction ``x`` (into the map)."""
        dx, dy, th = x
        c, s = math.cos(-th), math.sin(-th)
        xy = pts[:, :2] - pivot - (dx, dy)
        out = pts.copy()
        out[:, 0] = c * xy[:, 0] - s * xy[:, 1] + pivot[0]
        out[:, 1] = s * xy[:, 0] + c * xy[:, 1] + pivot[1]
        return out

    def residuals(x) -> np.ndarray:
        moved = to_map(x)
        r = np.empty(len(pts))
        for i, n in enumerate(names):
            sel = owner == i
            r[sel] = surface_distance(moved[sel], models[n])
        prior = weight * np.array([x[0] / params.prior_shift, x[1] / params.prior_shift, x[2] / params.prior_turn])
        return np.concatenate([r / params.scale, prior])

    fit = least_squares(residuals, np.zeros(3), loss="soft_l1", f_scale=1.0, x_scale=(0.02, 0.02, 0.02),
                        diff_step=1e-3, max_nfev=40, ftol=1e-4, xtol=1e-4)
    def cost(x) -> float:
        """The points' robust cost (soft L1, as fitted), without the prior."""
        z = np.square(residuals(x)[:len(pts)])
        return float(np.sum(2.0 * (np.sqrt(1.0 + z) - 1.0)))

    x = _constrained(fit.x, cost, params)
    dx, dy, th = map(float, x)
    if math.hypot(dx, dy) > params.max_shift or abs(th) > params.max_turn:
        return None
    d = residuals(x)[:len(pts)] * params.scale
    share = float(np.mean(d < params.inlier))
    if share < params.min_inliers:
        return None
    if math.hypot(dx, dy) < params.least_shift and abs(th) < params.least_turn:
        dx = dy = th = 0.0  # within the fit's own error: the map stands where the localiser puts it
    return Correction(dx, dy, th, (float(pivot[0]), float(pivot[1])), len(pts) * stride, names, share)


# -- the map as it lies in the robot's frame ------------------------------------------------------


def _constrained(x: np.ndarray, cost, params: RegistrationParams) -> np.ndarray:
    """``x`` (dx, dy, dθ) with its component along every direction the points do not pin down
    taken out (left where the localiser put it). The points' robust cost ``cost(x)`` is probed a
    step either way (finite differences: a box's edge pins a shift along its face only over a
    step, not in the gradient) for its curvature, in metres (a turn times
    :attr:`RegistrationParams.lever`); a point on a face square to a direction curves it by
    ``2/scale²``, so a direction curved less than ``min_constraint`` such points' worth is open."""
    S = np.diag([1.0, 1.0, 1.0 / params.lever])  # metres -> parameters
    h = PROBE
    y0 = np.linalg.solve(S, x)
    c0 = cost(x)
    E = np.eye(3) * h
    f1 = [cost(S @ (y0 + E[i])) for i in range(3)]
    H = np.empty((3, 3))
    for i in range(3):
        for j in range(i, 3):
            fij = cost(S @ (y0 + E[i] + E[j]))
            H[i, j] = H[j, i] = (fij - f1[i] - f1[j] + c0) / (h * h)
    w, V = np.linalg.eigh(H)
    firm = 2.0 * params.min_constraint / params.scale ** 2
    y = y0.copy()
    for k in range(3):
        if w[k] < firm:
            y = y - (y @ V[:, k]) * V[:, k]
    return S @ y


#: m (a turn: m at the lever) the registration's cost is probed by for its curvature
PROBE = 0.02


def corrected_map(site: SiteMap, c: Correction) -> SiteMap:
    """``site`` moved by the correction: every piece of furniture (its pose, leaf, switch, tap)
    turned and shifted; rooms, doors and their leaves shifted by the correction's shift at its
    pivot, where the robot stands (room outlines stay axis-aligned, and a doorway's gap in a wall
    must stay where the wall is: a turn of a degree or two moves them a few centimetres at the
    far end of a room, where a correction taken here says little anyway)."""
    if c.is_identity():
        return site
    moved = translation(c)
    shift = (moved.dx, moved.dy)

    def room(r: RoomInfo) -> RoomInfo:
        if r.bounds is None:
            return r
        x0, y0, x1, y1 = r.bounds
        return replace(r, bounds=(x0 + shift[0], y0 + shift[1], x1 + shift[0], y1 + shift[1]))

    def door(d: DoorInfo) -> DoorInfo:
        pose = None if d.pose is None else moved.pose(*d.pose)
        return replace(d, pose=pose, articulation=_articulation(d.articulation, moved))

    return replace(site, rooms=tuple(map(room, site.rooms)), doors=tuple(map(door, site.doors)),
                   furniture=tuple(corrected_piece(f, c) for f in site.furniture))


def corrected_piece(f: FurnitureInfo, c: Correction) -> FurnitureInfo:
    """A piece of furniture (its pose, leaf, switch, tap) moved by ``c``."""
    return replace(f, pose=None if f.pose is None else c.pose(*f.pose),
                   articulation=_articulation(f.articulation, c),
                   switch=None if f.switch is None else _vec(c.point(f.switch)),
                   tap=None if f.tap is None else _vec(c.point(f.tap)))


def translation(c: Correction) -> Correction:
    """``c``'s shift at its pivot without its turn: how :func:`corrected_map` moves rooms and doors."""
    shift = c.point((*c.pivot, 0.0))[:2] - np.asarray(c.pivot, float)
    return Correction(float(shift[0]), float(shift[1]), 0.0, c.pivot, c.points, c.pieces, c.inliers)


def _vec(v) -> tuple[float, float, float]:
    return (float(v[0]), float(v[1]), float(v[2]))


def corrected_articulation(a: Articulation | None, c: Correction) -> Articulation | None:
    """A door's or drawer's articulation moved by ``c`` (its leaf's box keeps its own axes: the
    leaf turned by ``c.dtheta`` with it, see :class:`~skills.scene_model.Leaf`)."""
    return _articulation(a, c)


def _articulation(a: Articulation | None, c: Correction) -> Articulation | None:
    if a is None:
        return None
    return replace(a, origin=_vec(c.point(a.origin)), axis=_vec(c.vector(a.axis)), handle=_vec(c.point(a.handle)),
                   normal=_vec(c.vector(a.normal)), bar=_vec(c.vector(a.bar)), leaf_center=_vec(c.point(a.leaf_center)))
