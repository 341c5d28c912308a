"""How one pybullet frame shows what relations need: the simulated VLM's view of a render.

World side only. A relation is seen when the points that show it are: the line where an item
meets its support, the inside of a container, the face of a leaf, the top of a surface. For each
object, points are sampled on the surfaces its relations need, and a point counts as *seen*
when it projects into the image, faces the camera (points on the far side of a thing are hidden
by the thing itself, which is no occlusion) and the camera's sight line reaches it (pybullet's
ray test against the scene: a closed door, a bowl in front of a plate, a basket's wall stop it).
Each figure of the object's :class:`~vap_bt.sim.captures.ObjectView` is the share of its
camera-facing points seen (0 when none faces the camera); the rules that turn them into a
model's evidence are :mod:`vap_bt.sim.observability`:

* **contact** (items) — points round the item's bottom outline, :data:`CONTACT_LIFT` above its
  lowest point, facing out: a cup whose foot hides behind a plate shows that it is there, not
  what it stands on;
* **interior** (containers) — points on the cavity's floor and back wall (the drawer's tray
  where it has slid to), seen when the sight line ends inside the cavity (on its faces, or on
  what lies in it): through a shut door nothing of the inside is seen; a basket seen from the
  side shows its far wall but little of its floor;
* **leaf** (articulated furniture) — points on the leaf's outer face at its current joint value,
  seen when the ray meets the leaf itself; a room door's is its doorway's visibility (seeing
  through the doorway is how an open door shows);
* **top** (surfaces) — points on the top face, seen when the ray ends on the top or on something
  standing on it; a floor's is its share of the image over :data:`FLOOR_PLAIN`;
* **fingers** — the gripper fingers' visible pixels over :data:`FINGERS_FULL` (both fingers seen
  from the wrist camera cover about 2 300 px of the 320 x 240 image; 1 500 is "plainly seen").
"""

from __future__ import annotations

import math

import numpy as np

from vap_bt.sim.captures import ObjectView
from vap_bt.sim.pb import pb
from vap_bt.sim.pb_camera import Render

#: m above an item's lowest point at which its contact line is sampled
CONTACT_LIFT = 0.008
#: m short of a sampled point a ray may stop and still count as reaching it (the thing's own
#: surface, the support under a contact point)
REACH_SLACK = 0.015
#: m in front of the optical centre a sight line starts: the camera's own housing is a collision
#: shape round the optical centre, and a ray started inside it stops at once
RAY_START = 0.05
#: points per edge of an outline, per side of a face grid
EDGE_POINTS, GRID = 5, 4
#: a floor covering this share of the image is plainly shown
FLOOR_PLAIN = 0.3
#: visible finger pixels at which the hand is plainly in the picture
FINGERS_FULL = 1500


def object_views(r: Render, scene, truth, robot, visibility: dict[str, float],
                 shares: dict[str, float], counts: dict[str, int]) -> tuple[dict[str, ObjectView], float]:
    """Each scene thing's :class:`ObjectView` in render ``r``, and the fingers' share."""
    sight = _Sight(r, scene.client)
    out: dict[str, ObjectView] = {}
    for name, t in scene.things.items():
        n = int(counts.get(name, 0))
        if t.item is not None:
            out[name] = ObjectView(n, contact=_contact(sight, t, truth) if n else 0.0)
        elif t.furniture is not None:
            k = t.kind
            out[name] = ObjectView(
                n, interior=_interior(sight, t, truth) if k.cavity is not None else None,
                leaf=_leaf(sight, t, truth) if t.hinge is not None else None,
                top=_top(sight, t) if k.cavity is None or k.cavity.open == "top" else None)
        elif t.door is not None:
            out[name] = ObjectView(n, leaf=visibility.get(name, 0.0))
        elif t.room is not None:
            out[name] = ObjectView(n, top=min(1.0, shares.get(name, 0.0) / FLOOR_PLAIN))
    if r.links is None:
        return out, 1.0
    fingers = np.count_nonzero(np.isin(r.links, robot.finger_joints) & (r.bodies == robot.id))
    return out, min(1.0, fingers / FINGERS_FULL)


class _Sight:
    """Which sampled points of the scene the render's camera has a clear line of sight to."""

    def __init__(self, r: Render, client: int) -> None:
        self.r, self.client = r, client
        self.eye = r.pose[:3, 3]
        self.inv = np.linalg.inv(r.pose)

    def seen(self, points: np.ndarray, normals: np.ndarray, ok) -> float:
        """The share of the camera-facing ``points`` seen; ``ok(hit_body, hit_link, hit_point,
        point)`` says whether a ray stopped short of its point still shows it."""
        points, normals = np.asarray(points, float), np.asarray(normals, float)
        facing = np.einsum("ij,ij->i", normals, self.eye - points) > 0
        if not facing.any():
            return 0.0
        pts = points[facing]
        pc = pts @ self.inv[:3, :3].T + self.inv[:3, 3]
        c = self.r.camera
        with np.errstate(divide="ignore", invalid="ignore"):
            u, v = c.fx * pc[:, 0] / pc[:, 2] + c.cx, c.fy * pc[:, 1] / pc[:, 2] + c.cy
        inframe = (pc[:, 2] > c.near) & (pc[:, 2] < c.far) & (u >= 0) & (u < c.width) & (v >= 0) & (v < c.height)
        if not inframe.any():
            return 0.0
        targets = pts[inframe]
        ways = targets - self.eye
        lengths = np.linalg.norm(ways, axis=1)
        starts = self.eye + ways * (RAY_START / lengths)[:, None]
        hits = pb.rayTestBatch([tuple(a) for a in starts], [tuple(p) for p in targets], physicsClientId=self.client)
        seen = 0
        for p, length, (body, link, frac, hit, _) in zip(targets, lengths - RAY_START, hits):
            if body < 0 or frac * length >= length - REACH_SLACK or ok(body, link, np.asarray(hit), p):
                seen += 1
        return seen / len(pts)


def _contact(sight: _Sight, t, truth) -> float:
    """Points round the bottom outline of the item's (turned) box, facing out of it."""
    corners = truth.outline(t.name)[0]
    bottom = corners[np.argsort(corners[:, 2])[:4]]
    z = float(bottom[:, 2].min()) + CONTACT_LIFT
    centre = bottom[:, :2].mean(axis=0)
    ring = bottom[np.argsort(np.arctan2(*(bottom[:, :2] - centre).T[::-1]))][:, :2]  # corners in order round it
    pts, normals = [], []
    for a, b in zip(ring, np.roll(ring, -1, axis=0)):
        out = np.array([b[1] - a[1], a[0] - b[0]])
        out = out / (np.linalg.norm(out) or 1.0)
        if out @ ((a + b) / 2 - centre) < 0:
            out = -out
        for s in np.linspace(0.1, 0.9, EDGE_POINTS):
            pts.append((*(a + s * (b - a)), z))
            normals.append((*out, 0.3))  # a little upwards: the line is seen from above as well
    own = set(t.bodies)
    return sight.seen(np.array(pts), np.array(normals), lambda body, link, hit, p: body in own)


def _local(f, p) -> np.ndarray:
    c, s = math.cos(f.yaw), math.sin(f.yaw)
    dx, dy = p[0] - f.x, p[1] - f.y
    return np.array([c * dx + s * dy, -s * dx + c * dy, p[2]])


def _interior(sight: _Sight, t, truth) -> float:
    """Points on the cavity's floor and back wall, seen when the ray ends inside the cavity."""
    f, k = t.furniture, t.kind
    w, d, _ = k.size
    cav = k.cavity
    shift = truth.joint_value(t.name) if t.hinge is not None and t.hinge.prismatic else 0.0  # a drawer's tray
    hw = w / 2 - cav.wall
    y0, y1 = -d / 2 + cav.wall + shift, d / 2 + shift
    xs = np.linspace(-hw, hw, GRID + 2)[1:-1]
    floor = [(x, y, cav.z[0] + 0.005) for x in xs for y in np.linspace(y0, y1, GRID + 2)[1:-1]]
    back = [(x, y0 + 0.005, z) for x in xs for z in np.linspace(*cav.z, GRID + 2)[1:-1]]
    up, forward = (0.0, 0.0, 1.0), tuple(f.direction((0.0, 1.0)))
    pts = np.array([f.to_world(p) for p in floor + back])
    normals = np.array([up] * len(floor) + [forward] * len(back))

    def within(body, link, hit, p) -> bool:
        q = _local(f, hit)
        return (abs(q[0]) <= hw + 0.01 and y0 - 0.01 <= q[1] <= y1 and cav.z[0] - 0.01 <= q[2] <= cav.z[1] + 0.01)

    return sight.seen(pts, normals, within)


def _leaf(sight: _Sight, t, truth) -> float:
    """Points on the leaf's outer face (the one holding the handle) at its joint value."""
    h = t.hinge
    centre, R, half = h.leaf(truth.joint_value(t.name))
    n = R @ h.normal
    local_n = np.asarray(h.normal, float)
    axes = [i for i in range(3) if abs(local_n[i]) < 0.5]
    pts = []
    for a in np.linspace(-0.8, 0.8, GRID):
        for b in np.linspace(-0.8, 0.8, GRID):
            q = np.zeros(3)
            q[axes[0]], q[axes[1]] = a * half[axes[0]], b * half[axes[1]]
            q += local_n * half @ np.abs(local_n)
            pts.append(centre + R @ q)
    return sight.seen(np.array(pts), np.repeat(n[None], len(pts), axis=0),
                      lambda body, link, hit, p: body == h.body and link == h.joint)


def _top(sight: _Sight, t) -> float:
    """Points on the top face, seen when the ray ends on it or on what stands on it."""
    f, k = t.furniture, t.kind
    w, d, h = k.size
    pts = np.array([f.to_world((x, y, h + 0.003)) for x in np.linspace(-0.4, 0.4, GRID) * w
                    for y in np.linspace(-0.4, 0.4, GRID) * d])
    return sight.seen(pts, np.repeat([[0.0, 0.0, 1.0]], len(pts), axis=0),
                      lambda body, link, hit, p: hit[2] >= h - 0.01 and abs(_local(f, hit)[0]) <= w / 2
                      and abs(_local(f, hit)[1]) <= d / 2)
