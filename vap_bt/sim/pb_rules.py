"""Physics rules: the object-state effects of a household, caused by contacts and poses.

A real kitchen fills a cup held under a running tap, switches a microwave on when a finger presses
its button, heats what is inside it, and a knife pressed into a lemon cuts it. The simulation has
no water, no electricity and no fracture, so these effects are rules, evaluated after every
physics step (:meth:`Rules.step`) from what that step left — contacts and their forces, poses,
velocities, the grasp constraint — and never from which action is running: skills move the robot
through the drivers, and nothing tells the physics what they are trying to do. The only thing an
action's name can do here is what Table II injection asks for (:mod:`pb_injection`): for the
action it was drawn for, an effect does not happen (a press that does not register, a cut that
does not split, a tap that gives only half a cup).

The rules, with their thresholds (all below, with reasons):

* **fill** — a fillable item (the rigid fact ``fillable``) held in the gripper, its centre within
  ``FILL_RADIUS`` horizontally of a tap's outlet (:func:`~vap_bt.sim.pb_scene.tap_outlet`), its
  top below the outlet by at most ``FILL_FALL``, moving slower than ``STILL_SPEED``, for
  ``FILL_TIME`` of simulated time without a break: filled to level 1.0 (``PARTIAL_FILL`` when the
  injection says "not fully filled"), and no longer heated (fresh water is cold). Held beside the
  tap, above it, or swung through the stream, nothing happens.
* **turnon** — a finger link of the gripper touching an appliance's switch button with a summed
  contact normal force of at least ``PRESS_FORCE``: the appliance is on and its lamp lit. Brushing
  it with the wrist or the gripper housing does not count; nothing turns it off again.
* **heat** — an item inside an appliance that is on is heated at that step, whether the
  appliance's door is closed or not (the domain's ``turnon`` asks only for the item inside; the
  door is the plan's business). It is immediate because the simulation only advances while the
  robot moves: an effect that needed time after the press would wait for the next motion.
* **cut** — the held knife touching another item (not sliced yet) from above: contact normal
  forces summed to at least ``CUT_FORCE`` with their force-weighted normal within
  ``CUT_CONE`` of vertical. The item falls apart into two halves across the blade (:func:`split`)
  and is sliced. A knife lying on an item, or pushed against it from the side, cuts nothing.
"""

from __future__ import annotations

import math
from typing import Protocol

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.sim.pb import pb
from vap_bt.sim.pb_catalog import Catalog
from vap_bt.sim.pb_robot import Robot
from vap_bt.sim.pb_scene import Scene, Thing, make_item_body, tap_outlet
from vap_bt.sim.pb_truth import Truth

#: the stream is about as wide as a cup's opening: a cup (radius 0.033 m) with its centre this
#: close under the outlet catches it
FILL_RADIUS = 0.04
#: the outlet is at most this far above the item's top (a tall bottle still fits under it, an item
#: held at the sink's rim level does not count as under the tap)
FILL_FALL = 0.30
#: m an item may drift while "held still" (a held cup jitters by millimetres in the grasp, at
#: speeds up to a few cm/s, so stillness is judged by where it stays, not by its velocity)
STILL_DRIFT = 0.015
#: s of simulated time under the running tap to fill a cup
FILL_TIME = 1.0
#: the level a "not fully filled" injection leaves (``filled`` needs 0.95)
PARTIAL_FILL = 0.5
#: N: a deliberate press (the button's weight is nothing; a brush of a finger gives fractions of a
#: newton, the arm pressing under position control tens)
PRESS_FORCE = 2.0
#: N pressed down through the blade: far more than the knife's own weight (1 N, and a held knife
#: rests on nothing), far less than the arm pressing
CUT_FORCE = 5.0
#: the blade presses from above: the contact normal within this angle of vertical
CUT_CONE = math.radians(60.0)


class EffectGate(Protocol):
    """What Table II injection says about the action running now (:class:`pb_injection.Injection`)."""

    def effect(self, action: str) -> bool:
        """Whether ``action``'s intended effect may happen (False: injected to fail)."""


class Rules:
    """Evaluates the rules above after every physics step of one built scene."""

    def __init__(self, scene: Scene, robot: Robot, truth: Truth, catalog: Catalog, gate: EffectGate,
                 dt: float) -> None:
        self.scene, self.robot, self.truth, self.catalog, self.gate = scene, robot, truth, catalog, gate
        self.cid = scene.client
        self.fill_steps = max(1, math.ceil(FILL_TIME / dt))
        self._under = 0  # consecutive steps the held item has been still under a tap
        self._anchor: np.ndarray | None = None  # where it was when those steps began
        things = scene.things.values()
        self.outlets = [t.furniture.to_world(tap_outlet(t.kind)) for t in things
                        if t.furniture is not None and t.kind.tap]
        self.switches = [t for t in things if t.switch_link is not None]

    def step(self) -> None:
        """Apply every rule to the state after one physics step: fill at a tap, press a switch, heat, cut
        with a held knife."""
        held = self.truth.held()
        self._fill(held)
        self._press()
        self._heat()
        if held is not None and self.scene.things[held].pddl_type == "knife":
            self._cut(self.scene.things[held])

    # ------------------------------------------------------------ fill

    def _fill(self, held: str | None) -> None:
        if held is None or not self.outlets or Atom("fillable", (held,)) not in self.truth.rigid:
            self._under = 0
            return
        t = self.scene.things[held]
        c = self.truth.center(held)
        if not self._under_tap(t, c):
            self._under = 0
            return
        if self._under == 0 or np.linalg.norm(c - self._anchor) > STILL_DRIFT:
            self._under, self._anchor = 0, c  # (re)starts counting where it is now
        self._under += 1
        if self._under >= self.fill_steps:
            level = 1.0 if self.gate.effect("fill") else PARTIAL_FILL
            if t.states.get("filled") != level:
                t.states["filled"] = level
                t.states["heated"] = False  # fresh water is cold
                show_state(self.cid, self.catalog, t)

    def _under_tap(self, t: Thing, c: np.ndarray) -> bool:
        top = self.truth.aabb(t.name)[5]
        return any(math.hypot(c[0] - o[0], c[1] - o[1]) <= FILL_RADIUS and 0.0 <= o[2] - top <= FILL_FALL
                   for o in self.outlets)

    # ------------------------------------------------------------ turnon and heat

    def _press(self) -> None:
        off = {(t.body, t.switch_link): t for t in self.switches if not t.states.get("turned_on")}
        if not off:
            return
        fingers = set(self.robot.finger_joints)
        force: dict[str, float] = {}
        for p in pb.getContactPoints(self.robot.id, physicsClientId=self.cid):  # one query for all switches
            t = off.get((p[2], p[4]))
            if t is not None and p[3] in fingers:
                force[t.name] = force.get(t.name, 0.0) + p[9]
        for name, f in force.items():
            if f >= PRESS_FORCE and self.gate.effect("turnon"):
                turn_on(self.cid, self.scene.things[name])

    def _heat(self) -> None:
        on = [t for t in self.switches if t.states.get("turned_on")]
        if not on:
            return
        held = self.truth.held()
        for it in self.scene.items():
            if it.states.get("heated") or it.name == held:
                continue
            if any(self.truth._inside(it.name, a.name) for a in on):
                it.states["heated"] = True
                show_state(self.cid, self.catalog, it)

    # ------------------------------------------------------------ cut

    def _cut(self, knife: Thing) -> None:
        owner = self.scene.by_body()
        pushes: dict[str, tuple[float, np.ndarray]] = {}
        for p in pb.getContactPoints(knife.body, physicsClientId=self.cid):
            name = owner.get(p[2])
            t = self.scene.things.get(name) if name else None
            if t is None or t.item is None or t is knife or t.states.get("sliced"):
                continue
            force, weighted = pushes.get(name, (0.0, np.zeros(3)))
            # the normal on the item points towards the knife: up when the blade presses from above
            pushes[name] = (force + p[9], weighted + p[9] * np.asarray(p[7]))
        for name, (force, weighted) in pushes.items():
            if force < CUT_FORCE or weighted[2] / force < math.cos(CUT_CONE):
                continue
            if not self.gate.effect("cut"):
                continue
            R = np.array(pb.getMatrixFromQuaternion(pb.getBasePositionAndOrientation(
                knife.body, physicsClientId=self.cid)[1])).reshape(3, 3)
            split(self.cid, self.catalog, self.scene.things[name], self.truth.center(name),
                  np.cross(R[:, 0], (0.0, 0.0, 1.0)))  # the blade's plane holds its length and the vertical


# ---------------------------------------------------------------- effects


def turn_on(cid: int, t: Thing) -> None:
    """An appliance is on: its lamp lights."""
    t.states["turned_on"] = True
    pb.changeVisualShape(t.body, t.light_link, rgbaColor=t.kind.light[1], physicsClientId=cid)


def show_state(cid: int, catalog: Catalog, it: Thing) -> None:
    """Show an item's state: water colour when filled, a warm tint when heated."""
    k = it.kind
    color = np.array(k.color)
    level = float(it.states.get("filled", 0.0))
    if level >= 0.95 and k.filled_color:
        color = np.array(k.filled_color)
    elif level > 0:
        color = np.array(catalog.half_filled_color)
    if it.states.get("heated"):
        color = 0.5 * color + 0.5 * np.array(catalog.heated_tint)
    for b in it.bodies:
        pb.changeVisualShape(b, -1, rgbaColor=tuple(color), physicsClientId=cid)


def split(cid: int, catalog: Catalog, t: Thing, center: np.ndarray, normal: np.ndarray) -> None:
    """The object falls apart into two halves on either side of the blade (``normal``: the blade
    plane's normal; only its horizontal part counts)."""
    ex = t.kind.extent
    pb.removeBody(t.body, physicsClientId=cid)
    n = np.array([normal[0], normal[1], 0.0])
    n /= np.linalg.norm(n)
    yaw = math.atan2(n[1], n[0])
    bodies = []
    for s in (-1, 1):
        p = center + n * s * (ex[0] / 4 + 0.012)
        p[2] = center[2] + 0.002
        bodies.append(make_item_body(cid, t.kind, tuple(p), yaw, half=True, mass=t.kind.mass / 2))
    t.bodies = bodies
    t.states["sliced"] = True
    show_state(cid, catalog, t)
