"""The physics rules turn contacts and poses into object states — and only those: a cup held still
under the tap fills, one held beside it or swung through the stream does not; a fingertip on the
switch turns the microwave on and heats what is inside, one on its front beside the switch does
nothing; a knife pressed down through a lemon halves it, one pushed against its side does not.
Scripted motions through the drivers (:mod:`driver_scripts`); no action is announced."""

from __future__ import annotations

import numpy as np
import pybullet as pb
import pytest
from driver_scripts import CLOSED, frame, hold, kitchen, line, moved, never, reach, stand_before, world_of

from vap_bt.domain.atoms import Atom
from vap_bt.sim.pb_rules import FILL_TIME

pytestmark = pytest.mark.slow

SINK = {"kitchen_sink": "type: sink"}
MICROWAVE = kitchen({"microwave": "type: appliance, state: closed", "counter": "type: surface"},
                    {"apple_pie": "place: inside microwave", "cup": "place: on counter"})
BOARD = kitchen({"cutting_board": "type: surface"}, {"lemon": "place: on cutting_board", "knife": "type: knife, place: held"})


def A(text):
    return Atom.parse(text)



# ------------------------------------------------------------ fill


def sink_world(tmp_path, fillable=True):
    w = world_of(tmp_path, "sink", kitchen(SINK, {"cup": "place: held" + (", fillable: true" if fillable else "")}))
    tap = np.array(w.site_map().piece("kitchen_sink").tap)
    assert stand_before(w.drivers, tap, (0, -1, 0), 0.75).completed
    return w, tap


def cup_at(w, point) -> np.ndarray:
    """The tcp pose (hand turned as it is) that puts the held cup's centre at ``point``."""
    T = w.drivers.arm.tcp_pose()
    return moved(T, np.asarray(point) - w.truth.center("cup"))


UNDER = np.array([0.0, 0.0, -0.18])  # the cup's centre below the outlet: its top 0.135 m under it


def test_a_cup_held_still_under_the_tap_fills(tmp_path):
    w, tap = sink_world(tmp_path)
    d = w.drivers
    assert reach(d, cup_at(w, tap + UNDER + (0.15, 0, 0))).completed
    assert line(d, cup_at(w, tap + UNDER), steps=3).completed
    assert hold(d, 0.5 * FILL_TIME).completed and not w.oracle.holds(A("filled(cup)"))  # not yet
    assert hold(d, 0.7 * FILL_TIME).completed and w.oracle.holds(A("filled(cup)"))
    w.close()


def test_beside_the_tap_or_swung_through_it_a_cup_stays_empty(tmp_path):
    w, tap = sink_world(tmp_path)
    d = w.drivers
    assert reach(d, cup_at(w, tap + UNDER + (0.12, 0, 0))).completed
    assert hold(d, 2 * FILL_TIME).completed  # beside the stream
    assert line(d, cup_at(w, tap + UNDER - (0.12, 0, 0)), steps=2, speed=0.6).completed  # through it
    assert hold(d, 2 * FILL_TIME).completed
    assert not w.oracle.holds(A("filled(cup)"))
    assert w.scene.things["cup"].states["filled"] == 0.0
    w.close()


def test_an_item_that_is_not_fillable_is_not_filled(tmp_path):
    w, tap = sink_world(tmp_path, fillable=False)
    d = w.drivers
    assert reach(d, cup_at(w, tap + UNDER + (0.12, 0, 0))).completed
    assert line(d, cup_at(w, tap + UNDER), steps=3).completed and hold(d, 2 * FILL_TIME).completed
    assert not w.oracle.holds(A("filled(cup)"))
    w.close()


# ------------------------------------------------------------ turnon and heat


def press(w, point, normal) -> None:
    """Closed fingertips pressed 4 mm into ``point`` from the front, then back off."""
    d = w.drivers
    n = np.asarray(normal, float)
    assert stand_before(d, point, n, 0.85).completed
    d.gripper.move(CLOSED, 60, never)
    G = frame(-n, (0, 0, -1), np.asarray(point) + n * (0.018 - 0.004))  # fingertips 0.018 m beyond the tcp
    assert reach(d, moved(G, n * 0.1)).completed
    assert line(d, G, steps=4, speed=0.2).completed
    assert line(d, moved(G, n * 0.1), steps=2).completed


def test_pressing_the_switch_turns_the_appliance_on_and_heats_what_is_inside(tmp_path):
    w = world_of(tmp_path, "mw", MICROWAVE)
    m = w.site_map().piece("microwave")
    assert not w.oracle.holds(A("turned_on(microwave)"))
    press(w, m.switch, (*m.front, 0.0))
    assert w.oracle.holds(A("turned_on(microwave)")) and w.oracle.holds(A("closed(microwave)"))
    assert w.oracle.holds(A("heated(apple_pie)"))  # inside, door closed
    assert not w.oracle.holds(A("heated(cup)"))  # on the counter
    w.close()


def test_pressing_beside_the_switch_does_nothing(tmp_path):
    w = world_of(tmp_path, "mw", MICROWAVE)
    m = w.site_map().piece("microwave")
    n = np.array([*m.front, 0.0])
    beside = np.array(m.switch) + (0, 0, 0.09) - n * 0.03  # the front face above the button
    press(w, beside, n)
    assert not w.oracle.holds(A("turned_on(microwave)")) and not w.oracle.holds(A("heated(apple_pie)"))
    w.close()


# ------------------------------------------------------------ cut


def blade(w) -> np.ndarray:
    """The knife's edge 0.08 m along the blade from its middle (clear of the fingers)."""
    pos, orn = pb.getBasePositionAndOrientation(w.scene.things["knife"].body, physicsClientId=w.cid)
    R = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
    return np.asarray(pos) + R[:, 0] * 0.08 - R[:, 2] * 0.009


def knife_at(w, point) -> np.ndarray:
    return moved(w.drivers.arm.tcp_pose(), np.asarray(point) - blade(w))


def board_world(tmp_path):
    w = world_of(tmp_path, "board", BOARD)
    c = w.truth.center("lemon")
    assert stand_before(w.drivers, c, (0, -1, 0), 0.62).completed
    return w, c, w.truth.aabb("lemon")[5]


def test_a_knife_pressed_down_on_a_lemon_halves_it(tmp_path):
    w, c, top = board_world(tmp_path)
    d = w.drivers
    assert reach(d, knife_at(w, (c[0], c[1], top + 0.03))).completed
    assert not w.oracle.holds(A("sliced(lemon)"))
    assert line(d, knife_at(w, c), steps=6, speed=0.15).completed
    assert w.oracle.holds(A("sliced(lemon)")) and len(w.scene.things["lemon"].bodies) == 2
    assert w.oracle.holds(A("holding(knife)"))
    w.close()


def test_a_knife_pushed_against_the_side_of_a_lemon_does_not_cut_it(tmp_path):
    w, c, top = board_world(tmp_path)
    d = w.drivers
    side = np.array([c[0] - 0.14, c[1], c[2]])
    assert reach(d, knife_at(w, side + (0, 0, 0.1))).completed and line(d, knife_at(w, side), steps=3).completed
    assert line(d, knife_at(w, side + (0.12, 0, 0)), steps=6, speed=0.15).completed  # sideways into it
    assert not w.oracle.holds(A("sliced(lemon)")) and len(w.scene.things["lemon"].bodies) == 1
    w.close()
