"""Table II injection at the drivers: a drawn situation made physically so, whoever moves the robot.

Skills plan and move the robot through the drivers (:mod:`pb_drivers`); the world does not know
how. What it is told — a sim-only hook, never part of a real robot — is which action a goal is:
:meth:`Injection.begin` when the goal starts, :meth:`Injection.end` when it ends. ``begin`` draws
from :class:`~vap_bt.sim.situations.SituationModel` exactly once per action and arms the drawn row. A
row is recorded (:class:`InjectedSituation`, the oracle's ``injected()``) when it happens, with what
it affects: a row that drops a held item when the item falls (the item: a drop drawn while the
hand holds nothing never happens and is not recorded), any other row the first time it acts (the
action's first argument) — the fingers refuse a grip they closed on, the gripper stays shut on
what it holds, a hand slips off a handle it took, a rule withholds an effect the physics made. A
row drawn for an action that never got that far (a grasp whose skill found nothing to close on:
belief had the item somewhere it was not) changed nothing and is not in the record, as the
symbolic world records none (:mod:`vap_bt.sim.symbolic`): the world's record says what happened,
and the runner scores the executive's diagnosis against it. From then on the situation happens
in the hardware, never by rewriting the truth:

===============================================  ================================================
Table II row                                     what happens, and when
===============================================  ================================================
grasp fails, object unchanged                    the closing fingers get no grip: they slip off
                                                 the item and close on nothing; it stays put
grasp fails, object drops nearby                 the grip forms, and is lost once the hand has
                                                 carried the item ``LIFT`` away (up, or out of a
                                                 cavity): the item falls on the floor
place fails, object in hand                      the gripper does not open while it holds an item
place fails, object drops nearby                 the grip is lost as the item is carried towards
                                                 its place: it falls on the floor
held object drops during navigation              released once the base has covered half of the
                                                 action's first path that goes somewhere (at least
                                                 ``MIN_PATH``; a turn on the spot is not one): floor
open/close fails                                 the hand takes the handle and slips off it after
                                                 the leaf has moved ``SLIP_TRAVEL`` of its travel
                                                 from where the action first took it (a second
                                                 grip slips at once): it stays closed (open)
turnon fails                                     the press does not register (:mod:`pb_rules`)
cut fails, knife in hand                         the blade does not split the item
cut fails, knife drops nearby                    the knife's grip is lost on the way: floor
fill: not fully filled                           the tap gives ``PARTIAL_FILL`` of a cup
fill: container drops nearby                     the cup's grip is lost on the way: floor
===============================================  ================================================

A lost grip drops the item only over open floor: at each step after the trigger it is released
the first time every ray straight down from its bottom (centre and corners) meets a floor before
anything else — not the furniture it came from, not the robot's base — so it lands on the floor
beside the robot. Were the item never carried over open floor before the goal ends, it is let go
at :meth:`end` wherever it is (it may then land on a surface: honest physics, not a teleport).
A slipping hand or item passes through the fingers until they are ``SEPARATION`` apart (the
fingers, closed at full force, would otherwise keep it by friction), and the gripper closes on
what it was asked for (:attr:`lost_grip`), as a real gripper does when its object slips out.

The rules consult :meth:`effect`, so a press or a cut injected to fail never registers.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from vap_bt.sim.pb import pb
from vap_bt.sim.pb_robot import Grip, Robot
from vap_bt.sim.pb_scene import Scene, Thing
from vap_bt.sim.situations import SituationModel, SituationSpec
from vap_bt.world import InjectedSituation

#: m the hand carries the item from where it took it before a "drops nearby" grasp loses it (a
#: lift, or a withdrawal out of a front-open cavity, has begun)
LIFT = 0.03
#: share of the joint's full travel a slipping hand moves a door or drawer before it slips off: far
#: below the "closed" threshold (0.06 of travel), so an open that fails leaves the leaf closed
SLIP_TRAVEL = 0.02
#: share of the first base path after which a held item slips out during navigation ("half way")
HALF_WAY = 0.5
#: m: a base path shorter than this (a turn on the spot, a nudge) is not "the path" of a navigation
MIN_PATH = 0.1
#: m between the robot and what slipped from it before the two collide again
SEPARATION = 0.01
#: the rays that decide "over open floor" start this far under the item and reach below the floor
RAY_START, RAY_END = 0.002, -0.1


@dataclass
class _Drop:
    """A held item to be let go: ``armed`` once its trigger fired; ``lift_from`` where the tcp
    was at the grip (trigger "lift")."""

    trigger: str  # "lift" (after the grip) | "now" | "half_way" (of the first base path)
    armed: bool = False
    lift_from: np.ndarray | None = None


@dataclass
class _Active:
    """The announced action, its drawn row, and what of it is still to happen."""

    action: str
    args: tuple[str, ...]
    spec: SituationSpec | None
    step: int = 0
    drop: _Drop | None = None
    happened: bool = False  # the drawn row (not a drop) has acted, and is in the record
    slip_from: tuple[Thing, float] | None = None  # the handle's thing and joint value at the grip
    paths: int = 0  # base paths started during the action


@dataclass
class _Ghost:
    """Collisions between the robot and ``body`` (one link or all) switched off until apart."""

    body: int
    link: int | None
    pairs: list[tuple[int, int]] = field(default_factory=list)


class Injection:
    """Table II for one built scene: the action running now, its drawn row, and its effects."""

    def __init__(self, situations: SituationModel, scene: Scene, robot: Robot,
                 log: list[InjectedSituation], lost_grip: Callable[[], None] = lambda: None) -> None:
        self.situations, self.scene, self.robot, self.log = situations, scene, robot, log
        self.cid = scene.client
        self.lost_grip = lost_grip
        self.active: _Active | None = None
        self._ghosts: list[_Ghost] = []
        self._floors = {b for t in scene.things.values() if t.room is not None for b in t.bodies}

    # ------------------------------------------------------------ the action

    def begin(self, action: str, args: tuple[str, ...], step: int) -> None:
        """Draw for ``action`` (once) and arm the drawn row (recorded when it happens)."""
        spec = self.situations.draw(action) if action in {s.action for s in self.situations.table} else None
        self.active = a = _Active(action, tuple(args), spec, step)
        if spec is not None and spec.drops is not None:
            if action in ("grasp", "takeout"):
                a.drop = _Drop("lift")
            elif spec.drops == "held":
                a.drop = _Drop("half_way")
            else:  # place, fill, cut: the grip is lost on the way
                a.drop = _Drop("now", armed=True)

    def end(self) -> None:
        """The action's goal ended: a drop still pending happens now."""
        a = self.active
        if a is not None and a.drop is not None and self._held_item() is not None:
            self._let_go()
        self.active = None

    # ------------------------------------------------------------ what drivers and rules ask

    def effect(self, action: str) -> bool:
        """Whether an effect of ``action`` the physics just made registers (a rule asks when a press,
        a fill or a cut would): not when the running action's drawn row withholds it."""
        a = self.active
        withheld = a is not None and a.spec is not None and a.action == action and not a.spec.effect
        return not self._happens(withheld)

    def _armed(self, *kinds: str) -> bool:
        a = self.active
        return a is not None and a.spec is not None and a.spec.kind in kinds

    def _happens(self, acts: bool) -> bool:
        """The running action's drawn row acts now (``acts``): recorded, the first time — a row that
        drops the item is recorded when it falls (:meth:`_let_go`). Returns ``acts``."""
        a = self.active
        if acts and not a.happened and a.spec.drops is None:
            a.happened = True
            self.log.append(InjectedSituation(a.action, a.args, a.spec.kind, a.step, a.args[:1]))
        return acts

    def refuses_grip(self) -> bool:
        """The fingers closing on an item get no grip on it (grasp fails, object unchanged)."""
        return self._happens(self._armed("grasp_fails_object_unchanged"))

    def gripper_stuck(self) -> bool:
        """The gripper does not open on the item it holds (place fails, object in hand)."""
        return self._happens(self._armed("place_fails_object_in_hand") and self._held_item() is not None)

    def on_grip(self, grip: Grip, thing: Thing) -> None:
        """A grip formed: remember where, for a drop after the lift or a slip off the handle."""
        a = self.active
        if a is None:
            return
        if grip.link == -1 and a.drop is not None and a.drop.trigger == "lift":
            a.drop.lift_from = self.robot.link_pose("tcp")[:3, 3]
        if grip.link != -1 and a.slip_from is None and self._armed("open_fails_object_closed", "close_fails_object_open"):
            h = thing.hinge
            a.slip_from = (thing, pb.getJointState(h.body, h.joint, physicsClientId=self.cid)[0])

    def base_path_started(self, length: float) -> None:
        """The base starts following a path ``length`` metres long."""
        if self.active is not None and length >= MIN_PATH:
            self.active.paths += 1

    def base_progress(self, share: float, length: float) -> None:
        """The base has covered ``share`` of the path it follows (``length`` long): half way along
        the action's first path, a navigation drop is armed."""
        a = self.active
        if (a is not None and a.drop is not None and a.drop.trigger == "half_way" and a.paths == 1
                and length >= MIN_PATH and share >= HALF_WAY):
            a.drop.armed = True

    # ------------------------------------------------------------ every physics step

    def step(self) -> None:
        """After one physics step, carry out the running action's drawn situation when its moment comes:
        a handle grip slips once the leaf has moved far enough, the held item drops once its trigger is
        reached."""
        if self._ghosts:
            self._ghosts = [g for g in self._ghosts if not self._apart(g)]
        a = self.active
        if a is None:
            return
        if a.slip_from is not None and self.robot.grip is not None and self.robot.grip.link != -1:
            thing, q0 = a.slip_from
            h = thing.hinge
            q = pb.getJointState(h.body, h.joint, physicsClientId=self.cid)[0]
            if abs(q - q0) >= SLIP_TRAVEL * abs(h.full):
                self._happens(True)
                self.slip(self.robot.grip)  # slip_from stays: a new grip in this action slips at once
        d = a.drop
        if d is None or self._held_item() is None:
            return
        if d.trigger == "lift" and not d.armed and d.lift_from is not None:
            d.armed = float(np.linalg.norm(self.robot.link_pose("tcp")[:3, 3] - d.lift_from)) >= LIFT
        if d.armed and self._over_floor(self._held_item()):
            self._let_go()

    # ------------------------------------------------------------ slipping

    def slip(self, grip: Grip | None = None, body: int | None = None, link: int | None = None) -> None:
        """The hand loses ``grip`` (or never gets hold of ``body``): the constraint goes and the
        robot passes the body until they are apart; the gripper closes on what it was asked for."""
        if grip is not None:
            self.robot.detach()
            body, link = grip.body, (None if grip.link == -1 else grip.link)
        thing = self.scene.things.get(self.scene.by_body().get(body, ""))
        bodies = thing.bodies if thing is not None and thing.item is not None else [body]
        for b in bodies:
            self._ghost(b, link)
        self.lost_grip()

    def _let_go(self) -> None:
        a, item = self.active, self._held_item()
        self.slip(self.robot.grip)
        if a.spec is not None and item is not None:  # what fell: the thing the executive should find
            self.log.append(InjectedSituation(a.action, a.args, a.spec.kind, a.step, (item.name,)))
        a.drop = None

    def _ghost(self, body: int, link: int | None) -> None:
        g = _Ghost(body, link)
        n = pb.getNumJoints(self.robot.id, physicsClientId=self.cid)
        links_b = [link] if link is not None else [-1, *range(pb.getNumJoints(body, physicsClientId=self.cid))]
        for la in range(-1, n):
            for lb in links_b:
                pb.setCollisionFilterPair(self.robot.id, body, la, lb, 0, physicsClientId=self.cid)
                g.pairs.append((la, lb))
        self._ghosts.append(g)

    def _apart(self, g: _Ghost) -> bool:
        """Whether the robot is SEPARATION clear of a ghost's body; if so, they collide again."""
        try:
            kw = {} if g.link is None else {"linkIndexB": g.link}
            near = pb.getClosestPoints(self.robot.id, g.body, SEPARATION, physicsClientId=self.cid, **kw)
        except pb.error:  # the body is gone (an item split in two)
            return True
        if near:
            return False
        for la, lb in g.pairs:
            pb.setCollisionFilterPair(self.robot.id, g.body, la, lb, 1, physicsClientId=self.cid)
        return True

    # ------------------------------------------------------------ geometry

    def _held_item(self) -> Thing | None:
        g = self.robot.grip
        return self.scene.things[g.name] if g is not None and g.link == -1 else None

    def _over_floor(self, t: Thing) -> bool:
        """Every ray straight down from the item's bottom (centre and corners) meets a floor first.
        The rays start below the fingers holding it too: a thin item (a knife) sits higher than
        its pads reach, and a ray from its bottom then began inside a pad — "over the floor" hung
        on a millimetre of how the item happened to sit in the hand."""
        lo = np.full(3, np.inf)
        hi = np.full(3, -np.inf)
        for b in t.bodies:
            a, c = pb.getAABB(b, -1, physicsClientId=self.cid)
            lo, hi = np.minimum(lo, a), np.maximum(hi, c)
        mid = (lo + hi) / 2
        xs = [(mid[0], mid[1])] + [(x, y) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
        pads = min(pb.getAABB(self.robot.id, j, physicsClientId=self.cid)[0][2] for j in self.robot.finger_joints)
        z = min(lo[2], pads) - RAY_START
        hits = pb.rayTestBatch([(x, y, z) for x, y in xs], [(x, y, RAY_END) for x, y in xs],
                               physicsClientId=self.cid)
        return all(h[0] in self._floors for h in hits)
