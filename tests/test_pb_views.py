"""What a pybullet picture shows of a relation (vap_bt/sim/pb_views.py), on real renders.

The camera is placed by hand in front of the boil-water kitchen's cabinet and cup: the inside of
the cabinet is seen only through its open door, a cup's contact with the counter only while
nothing stands in front of its foot, and what a frame shows decides the simulated VLM's evidence.
"""

from __future__ import annotations

import numpy as np
import pybullet as pb
import pytest

from vap_bt import taskfile
from vap_bt.domain.atoms import Atom
from vap_bt.sim import pb_views
from vap_bt.motion.se3 import look_pose
from vap_bt.sim.pb_camera import render

from conftest import TREES


@pytest.fixture(scope="module")
def world():
    from vap_bt.sim.pybullet_world import PybulletWorld

    w = PybulletWorld(taskfile.load(TREES / "boil_water.yaml"), seed=0, injection=False)
    yield w
    w.close()


def sight_from(world, eye, target) -> pb_views._Sight:
    return pb_views._Sight(render(world.cid, look_pose(np.asarray(eye, float), np.asarray(target, float)), world.camera), world.cid)


def in_front(world, name: str, distance: float, height: float):
    t = world.scene.things[name]
    f, k = t.furniture, t.kind
    eye = f.to_world((0.0, k.size[1] / 2 + distance, height))
    return eye, t


def test_a_shut_cabinet_shows_nothing_of_its_inside_and_an_open_one_does(world):
    eye, cab = in_front(world, "cabinet", 1.2, 1.2)
    target = cab.furniture.to_world((0.0, 0.0, sum(cab.kind.cavity.z) / 2))
    h = cab.hinge
    try:
        pb.resetJointState(h.body, h.joint, 0.0, physicsClientId=world.cid)
        assert pb_views._interior(sight_from(world, eye, target), cab, world.truth) == 0.0
        assert pb_views._leaf(sight_from(world, eye, target), cab, world.truth) > 0.8  # the shut door, face on
        pb.resetJointState(h.body, h.joint, h.full, physicsClientId=world.cid)
        assert pb_views._interior(sight_from(world, eye, target), cab, world.truth) > 0.8
    finally:
        pb.resetJointState(h.body, h.joint, 0.0, physicsClientId=world.cid)


def test_a_cups_contact_line_is_seen_until_something_stands_in_front_of_its_foot(world):
    """The counter's top with a cup put on it: from in front, the cup's contact line is in view;
    a box set down in front of the cup hides its foot, not its top."""
    cup = world.scene.things["cup"]
    counter = world.scene.things["counter"]
    f, k = counter.furniture, counter.kind
    top = f.to_world((0.0, 0.0, k.size[2]))
    pos, orn = pb.getBasePositionAndOrientation(cup.body, physicsClientId=world.cid)
    cup_box = world.truth.aabb("cup")
    pb.resetBasePositionAndOrientation(cup.body, (top[0], top[1], k.size[2] + (pos[2] - cup_box[2]) + 0.001), orn,
                                       physicsClientId=world.cid)
    eye = f.to_world((0.0, k.size[1] / 2 + 1.0, k.size[2] + 0.45))
    wall = None
    try:
        seen = pb_views._contact(sight_from(world, eye, top), cup, world.truth)
        assert seen > 0.8
        front = f.to_world((0.0, 0.12, k.size[2] + 0.03))  # a 6 cm high board in front of the cup
        shape = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=(0.12, 0.01, 0.03), physicsClientId=world.cid)
        wall = pb.createMultiBody(0, shape, basePosition=tuple(front), physicsClientId=world.cid)
        hidden = pb_views._contact(sight_from(world, eye, top), cup, world.truth)
        assert hidden < 0.3 < seen
    finally:
        if wall is not None:
            pb.removeBody(wall, physicsClientId=world.cid)
        pb.resetBasePositionAndOrientation(cup.body, pos, orn, physicsClientId=world.cid)


def test_every_capture_records_what_the_relations_need(world):
    frame = world.capture()
    rec = world.captures.get(frame.frame_id)
    assert rec.picture_key == rec.image_sha1 and rec.fingers is not None and 0.0 <= rec.fingers <= 1.0
    assert set(rec.views) == set(world.scene.things) and rec.labels["cup"] == "cup"
    assert rec.views["cabinet"].interior == 0.0  # the cabinet starts shut
    assert rec.views["cup"].contact is not None and rec.views["counter"].top is not None
    # the same picture is the same record key: a second capture from the same pose, nothing moved
    again = world.captures.get(world.capture().frame_id)
    assert again.picture_key == rec.picture_key and again.holds(Atom("inside", ("cup", "cabinet")))
