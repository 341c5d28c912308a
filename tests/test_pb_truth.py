"""The oracle decides truth from physics (:mod:`vap_bt.sim.pb_truth`): support from contacts,
containment from the cavity, blocking from the gripper's approach corridor — never from the
executive's perception thresholds."""

from __future__ import annotations

import numpy as np
import pybullet as pb
import pytest
from skill_runs import pybullet

from vap_bt.domain.atoms import Atom


def holds(w, text: str) -> bool:
    return w.oracle.holds(Atom.parse(text))


def shift(w, name: str, d) -> None:
    """Put ``name`` ``d`` (x, y, z) from where it is, without stepping the physics."""
    body = w.scene.things[name].body
    p, q = pb.getBasePositionAndOrientation(body, physicsClientId=w.cid)
    pb.resetBasePositionAndOrientation(body, tuple(np.add(p, d)), q, physicsClientId=w.cid)


def test_on_follows_contact():
    w = pybullet("collect_cup")
    try:
        assert holds(w, "on(cup, coffee_table)")
        shift(w, "cup", (0, 0, 0.02))  # lifted 2 cm: nothing supports it
        assert not holds(w, "on(cup, coffee_table)") and w.truth.support_of("cup") is None
        for _ in range(40):  # let go, it falls back and rests
            w.step()
        assert holds(w, "on(cup, coffee_table)")
        shift(w, "cup", (0, 0, 0.003))  # within the contact gap: still resting
        assert holds(w, "on(cup, coffee_table)")
    finally:
        w.close()


def test_on_a_floor_is_contact_with_the_rooms_floor():
    w = pybullet("retrieve_bottles")
    try:
        assert holds(w, "on(bottle2, floor_garden)") and not holds(w, "on(bottle2, floor_kitchen)")
        assert not holds(w, "on(bottle1, floor_garden)")  # on the bench, not touching the floor
        shift(w, "bottle2", (0, 0, 0.02))
        assert not holds(w, "on(bottle2, floor_garden)")
    finally:
        w.close()


def test_inside_a_closed_cabinet_holds():
    w = pybullet("boil_water")
    try:
        assert holds(w, "closed(cabinet)") and holds(w, "inside(cup, cabinet)")
        assert not holds(w, "on(cup, counter)")
    finally:
        w.close()


def test_blocking_is_the_grippers_approach_corridor():
    w = pybullet("pick_plate")
    try:
        assert w.truth.gripper_width == pytest.approx(0.11, abs=0.005)  # the 2F-85's body, open
        assert holds(w, "blocking(bowl, plate)") and not holds(w, "reachable(plate)")
        assert not holds(w, "blocking(plate, bowl)") and holds(w, "reachable(bowl)")
        f = w.scene.things["dining_table"].furniture
        front = np.array([*f.front[:2], 0.0])
        side = np.array([-front[1], front[0], 0.0])
        shift(w, "bowl", side * 0.2)  # beside the way in: the hand passes it
        assert not holds(w, "blocking(bowl, plate)") and holds(w, "reachable(plate)")
        shift(w, "bowl", -side * 0.2 + front * 0.12)  # further forward, still on the way in
        assert holds(w, "blocking(bowl, plate)")
        shift(w, "bowl", -front * 0.5)  # behind the plate, still on the table: not in the way
        for _ in range(20):
            w.step()
        assert w.truth.support_of("bowl") == "dining_table" and not holds(w, "blocking(bowl, plate)")
    finally:
        w.close()
