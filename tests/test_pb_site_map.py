"""The site map's furniture models match the scene: each annotation is checked against the
bodies by probing the physics with a tiny sphere — the handle is inside its bar and the space
behind the bar is free, the switch is the button's face, the tap's outlet is the underside of its
arm, a cavity is hollow, a surface's top is at its height — and a leaf turned or slid by the joint
carries its handle to where the map's articulation says. It all crosses the wire unchanged."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pybullet as pb
import pytest
from scipy.spatial.transform import Rotation

from vap_bt.sim.pybullet_world import PybulletWorld
from vap_bt.taskfile import load
from vap_bt.transport.messages import decode, encode
from vap_bt.robot.site_map import SiteMap

TREES = Path(__file__).resolve().parents[1] / "trees"
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module", params=["boil_water", "heat_pie", "halve_egg", "gather_kindling"])
def world(request):
    w = PybulletWorld(load(TREES / f"{request.param}.yaml"), seed=0, injection=False, image_size=(80, 60))
    yield w
    w.close()


def touches(w, point, body, link=None, radius=0.004) -> bool:
    """Whether a sphere of ``radius`` at ``point`` overlaps ``body`` (one of its links)."""
    shape = pb.createCollisionShape(pb.GEOM_SPHERE, radius=radius, physicsClientId=w.cid)
    probe = pb.createMultiBody(0, shape, basePosition=tuple(map(float, point)), physicsClientId=w.cid)
    try:
        kw = {} if link is None else {"linkIndexB": link}
        return bool(pb.getClosestPoints(probe, body, 0.0, physicsClientId=w.cid, **kw))
    finally:
        pb.removeBody(probe, physicsClientId=w.cid)


def handle_at(art, q, side=1.0):
    n = np.asarray(art.normal)
    p = np.asarray(art.handle) - (0 if side > 0 else n * art.other_side)
    if art.prismatic:
        return p + np.asarray(art.axis) * q
    R = Rotation.from_rotvec(np.asarray(art.axis) * q).as_matrix()
    return np.asarray(art.origin) + R @ (p - np.asarray(art.origin))


def leaves(w):
    m = w.site_map()
    return [(f.name, f.articulation) for f in m.furniture if f.articulation] + \
           [(d.name, d.articulation) for d in m.doors if d.articulation]


def test_handles_are_where_the_bars_are_at_any_joint_value(world):
    found = leaves(world)
    assert found
    for name, art in found:
        h = world.scene.things[name].hinge
        n = np.asarray(art.normal)
        sides = (1.0, -1.0) if art.other_side is not None else (1.0,)
        for q in (0.0, 0.6 * art.opened):
            pb.resetJointState(h.body, h.joint, q, physicsClientId=world.cid)
            R = np.eye(3) if art.prismatic else Rotation.from_rotvec(np.asarray(art.axis) * q).as_matrix()
            for side in sides:
                p = handle_at(art, q, side)
                assert touches(world, p, h.body, h.joint), (name, q, side)
                # between the bar and the leaf's face the hand's fingers have room
                assert not touches(world, p - R @ n * side * 0.023, h.body, h.joint), (name, q, side)
        pb.resetJointState(h.body, h.joint, 0.0, physicsClientId=world.cid)
        assert art.lower <= min(0.0, art.opened) and max(0.0, art.opened) <= art.upper
        lo, hi = (np.array(v) for v in pb.getAABB(h.body, h.joint, physicsClientId=world.cid))
        assert np.allclose(art.leaf_center, (lo + hi) / 2, atol=1e-3) and np.allclose(art.leaf_half, (hi - lo) / 2, atol=1e-3)


def test_switches_taps_heights_and_cavities_are_where_the_bodies_are(world):
    for f in world.site_map().furniture:
        t = world.scene.things[f.name]
        front = np.array([*f.front, 0.0])
        plan = world.plan.furniture[f.name]
        corner = plan.to_world((f.footprint[0] / 2 - 0.01, -f.footprint[1] / 2 + 0.01, f.height))  # back right
        assert touches(world, corner - (0, 0, 0.006), t.body) and not touches(world, corner + (0, 0, 0.006), t.body)
        if f.switch is not None:
            sw = np.asarray(f.switch)
            assert touches(world, sw - front * 0.006, t.body, t.switch_link)  # just behind the face
            assert not touches(world, sw + front * 0.006, t.body)  # just in front of it: air
        if f.tap is not None:
            tap = np.asarray(f.tap)
            assert touches(world, tap + (0, 0, 0.006), t.body)  # the arm's underside
            assert not touches(world, tap - (0, 0, 0.01), t.body)  # the water's way down
        if f.cavity is not None:
            z = sum(f.cavity.z) / 2
            inner = plan.to_world((0.0, 0.0, z))
            assert not touches(world, inner, t.body, -1, radius=0.02)  # hollow
            assert f.cavity.open in ("front", "top")
    kinds = {f.label: f for f in world.site_map().furniture}
    assert all(kinds[k].switch is not None for k in ("microwave", "oven") if k in kinds)
    assert all(kinds[k].tap is not None for k in ("sink",) if k in kinds)


def test_the_site_map_crosses_the_wire_unchanged(world):
    m = world.site_map()
    back = decode(encode(m), SiteMap)
    assert back == m
    assert any(f.articulation for f in back.furniture) or any(d.articulation for d in back.doors)
