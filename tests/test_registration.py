"""Registering the map's furniture to a view (:mod:`skills.registration`): a localisation error
of a few centimetres and degrees is recovered from the points a camera returns of a cabinet."""

from __future__ import annotations

import math

import numpy as np
import pytest

from skills.registration import Correction, corrected_map, register, surface_distance
from skills.scene_model import Furniture, SceneModel, bar_offset
from vap_bt.motion import se3
from vap_bt.motion.footprint import Obb
from vap_bt.robot.site_map import FurnitureInfo, RoomInfo, SiteMap

CABINET = FurnitureInfo("cabinet", "cabinet", "container", "kitchen", pose=(2.0, 3.8, -math.pi / 2),
                        footprint=(0.8, 0.5), height=0.9)
TABLE = FurnitureInfo("table", "table", "surface", "kitchen", pose=(3.4, 3.9, -math.pi / 2), footprint=(1.2, 0.7),
                      height=0.75)


def seen_faces(box: Obb, toward, step: float = 0.02) -> np.ndarray:
    """Points on the faces of ``box`` that face ``toward`` (a camera's direction) or up."""
    pts = []
    for axis in range(3):
        for sign in (-1, 1):
            n = box.R[:, axis] * sign
            if n @ toward <= 0 and not (axis == 2 and sign > 0):
                continue
            others = [k for k in range(3) if k != axis]
            u = np.arange(-box.half[others[0]], box.half[others[0]] + 1e-9, step)
            v = np.arange(-box.half[others[1]], box.half[others[1]] + 1e-9, step)
            for a in u:
                for b in v:
                    local = np.zeros(3)
                    local[axis], local[others[0]], local[others[1]] = sign * box.half[axis], a, b
                    pts.append(box.center + box.R @ local)
    return np.array(pts)


def view_of(info: FurnitureInfo, truth: Correction, noise: float, rng) -> np.ndarray:
    """The piece's points as a camera in front of it returns them, in a robot frame that the
    map lies in moved by ``truth``."""
    f = Furniture(info)
    pts = np.vstack([seen_faces(b, f.front) for b in f.solids()])
    pts = pts[pts[:, 2] > 0.02]  # its foot is hidden by the floor
    T = truth.matrix()
    pts = pts @ T[:3, :3].T + T[:3, 3]
    return pts + rng.normal(0.0, noise, pts.shape)


@pytest.mark.parametrize("dx,dy,dth", [(0.05, -0.04, 0.03), (-0.08, 0.02, -0.05), (0.0, 0.0, 0.0)])
def test_a_localisation_error_is_recovered_from_two_pieces(dx, dy, dth):
    rng = np.random.default_rng(1)
    truth = Correction(dx, dy, dth, (2.7, 3.0), 0, (), 1.0)
    clouds = {f.name: view_of(f, truth, 0.01, rng) for f in (CABINET, TABLE)}
    models = {f.name: Furniture(f).solids() for f in (CABINET, TABLE)}
    c = register(clouds, models)
    assert c is not None and set(c.pieces) == {"cabinet", "table"} and c.inliers > 0.8
    for p in ((2.0, 3.5, 0.5), (3.4, 3.6, 0.75)):  # where the map's points land, as the truth has them
        assert np.linalg.norm(c.point(p) - truth.point(p)) < 0.012
    assert abs(c.dtheta - dth) < 0.01


def test_a_fit_within_its_own_error_leaves_the_map_where_the_localiser_puts_it():
    """A centimetre's offset is within what a fit errs by on exact depth (the map's boxes are not
    the meshes): no correction, not a centimetre's wrong one; four centimetres are corrected."""
    rng = np.random.default_rng(3)
    for dx, corrected in ((0.01, False), (0.04, True)):
        truth = Correction(dx, 0.0, 0.0, (2.7, 3.0), 0, (), 1.0)
        clouds = {f.name: view_of(f, truth, 0.005, rng) for f in (CABINET, TABLE)}
        c = register(clouds, {f.name: Furniture(f).solids() for f in (CABINET, TABLE)})
        assert c is not None and c.is_identity() is not corrected
        if corrected:
            assert abs(c.point((2.0, 3.5, 0.5))[0] - truth.point((2.0, 3.5, 0.5))[0]) < 0.012


def test_points_the_map_does_not_explain_give_no_correction():
    rng = np.random.default_rng(2)
    clouds = {"cabinet": rng.uniform((1.5, 3.0, 0.0), (2.5, 4.0, 1.0), (300, 3))}  # not a cabinet's faces
    assert register(clouds, {"cabinet": Furniture(CABINET).solids()}) is None
    assert register({"cabinet": clouds["cabinet"][:20]}, {"cabinet": Furniture(CABINET).solids()}) is None


def test_the_corrected_map_moves_furniture_and_is_carried_by_odometry():
    site = SiteMap((RoomInfo("kitchen", "floor_kitchen", (0.0, 0.0, 5.0, 4.4)),), (), (CABINET, TABLE))
    c = Correction(0.04, -0.03, 0.02, (2.0, 3.0), 100, ("cabinet",), 0.9)
    moved = corrected_map(site, c)
    assert np.allclose(moved.piece("cabinet").pose[:2], c.point((2.0, 3.8, 0.0))[:2])
    assert moved.piece("cabinet").pose[2] == pytest.approx(-math.pi / 2 + 0.02)
    assert moved.room("kitchen").bounds[0] == pytest.approx(float(c.point((2.0, 3.0, 0.0))[0] - 2.0))
    # a base whose localiser jumps 5 cm when it moves, and whose wheels say how far it went
    body = {"believed": se3.planar_pose(2.0, 2.5, math.pi / 2), "odom": se3.planar_pose(0.0, 0.0, 0.0)}

    def mark():
        return body["believed"].copy(), body["odom"].copy()

    def since(m):
        B0, O0 = m
        B1, O1 = mark()
        return B1 @ np.linalg.inv(O1) @ O0 @ np.linalg.inv(B0)

    scene = SceneModel(site)
    scene.mark, scene.since = mark, since
    scene.correction, scene._registered = c, (c, mark())
    scene._build(moved)
    top = scene.furniture["cabinet"].top_point()
    drive = se3.planar_pose(0.5, 0.0, 0.0)  # half a metre forward, and the localiser jumps 5 cm aside
    body["odom"] = body["odom"] @ drive
    body["believed"] = se3.planar_pose(0.05, 0.0, 0.0) @ body["believed"] @ drive
    scene.base_moved()
    assert np.allclose(scene.furniture["cabinet"].top_point(), top + (0.05, 0.0, 0.0))  # the jump, not the drive
    body["odom"] = body["odom"] @ se3.planar_pose(2.5, 0.0, 0.0)  # far: odometry no longer holds it
    body["believed"] = body["believed"] @ se3.planar_pose(2.5, 0.0, 0.0)
    scene.base_moved()
    assert scene.correction.is_identity() and np.allclose(scene.furniture["cabinet"].origin[:2], (2.0, 3.8))


def test_surface_distance_is_zero_on_a_face_and_grows_off_it():
    box = Obb.aabb((0, 0, 0), (1, 1, 1))
    d = surface_distance(np.array([[0.5, 0.5, 1.0], [0.5, 0.5, 1.1], [0.5, 0.5, 0.9], [0.5, 0.5, 0.5]]), [box])
    assert np.allclose(d, [0.0, 0.1, 0.1, 0.5])


def test_a_bar_is_placed_by_the_middle_of_its_points_across_the_face_and_by_the_face_along_it():
    """A fridge's handle as a look shows it: the bar (2.4 cm square, its centre 4.5 cm in front of
    the leaf's face) 3 cm along the face and 1 cm out from where the map has it; the camera sees
    its front and one side. The side's points lie at the bar's edge, so their mean leans that way."""
    p, n = np.array([1.0, 2.0, 1.0]), np.array([0.0, -1.0, 0.0])
    across = np.array([1.0, 0.0, 0.0])
    centre = p + 0.03 * across + 0.01 * n
    zs = np.linspace(-0.1, 0.1, 21)
    front = [centre + u * across + 0.012 * n + (0, 0, z) for u in np.linspace(-0.012, 0.012, 7) for z in zs]
    side = [centre - 0.012 * across + v * n + (0, 0, z) for v in np.linspace(-0.012, 0.012, 7) for z in zs]
    bar = np.array(front + side)
    face = float((centre - 0.045 * n - p) @ n)  # where the face's points lie along the normal
    up = np.array([0.0, 0.0, 1.0])
    assert np.allclose(bar_offset(bar, p, n, up, face), centre - p, atol=1e-3)
    assert abs((bar.mean(axis=0) - centre) @ across) > 0.004  # what the mean would have said
    assert np.allclose(bar_offset(bar, p, n, across, face), 0.01 * n, atol=1e-3)  # a level bar: not along it
    assert bar_offset(bar, p, up, across, face) is None  # a face looking up
