"""One robot's skill kit: its body, eyes, base paths, hands and handle follower, shared by its skills.

Every motion skill of a robot works through the same :class:`Kit`, built once from the robot's
interfaces (its ``drivers`` — arm, gripper, base, wrist camera, :mod:`vap_bt.robot.drivers` —,
its ``state()`` and its ``site_map()``),
because what one skill learns another needs: the grasp measured the item the place will set
down, an open saw where the door stands. A kit notices when the robot it serves starts over (a
new episode: the site map changed, or the robot's clock went back) and forgets what it knew.

:meth:`Kit.goal` wraps one goal: the goal's cancellation reaches every driver call (a cancelled
goal stops the arm or base within one control cycle and raises :class:`~skills.body.Stopped`),
progress goes to the goal's feedback, and the IK's scene is the map's.

The kit also names what the wrist camera's detector finds (:meth:`Kit.identify`, over
:mod:`vap_bt.scene.identity`): the map's furniture and doors by the map, the item in the hand by
the fingers, the item a look is for by where the goal's hint believes it, and the items the kit
saw lying on the floor by where it saw them. Skills never read a name a world gave.
"""

from __future__ import annotations

import threading
from contextlib import contextmanager
from dataclasses import replace
from typing import Iterator

from skills.body import Body
from skills.eyes import Eyes, Held
from skills.handles import Handles
from skills.goal import Where
from skills.hands import Hands
from skills.navigator import Navigator
from skills.scene_model import ANONYMOUS, SceneModel, seen_from, seen_in_hand
from vap_bt.robot.frame import Frame
from vap_bt.robot.labels import class_of
from vap_bt.scene.identity import SEEN_RADIUS, Believed, Identifier, IdentityParams
from vap_bt.skill import Hint
from vap_bt.world import GoalContext

#: s (the robot's clock) a drive goes on after the hand lost its item, before it stops: about
#: the time the item takes to fall from where it rides (0.95 m: 0.44 s). Stopped at once, the
#: base would leave the falling item flying on the way the base moved — onto the base's top
SLIP_FALL = 0.5

#: how the kit re-identifies (only an item's own class: see :meth:`Kit.identify`)
EXACT = IdentityParams(similar_cost=None)

_kits: dict[int, "Kit"] = {}
_lock = threading.Lock()


def kit_for(robot) -> "Kit":
    """The one kit of ``robot`` (built on first use)."""
    with _lock:
        kit = _kits.get(id(robot))
        if kit is None or kit.robot is not robot:
            kit = _kits[id(robot)] = Kit(robot)
        return kit


class Kit:
    """Body, eyes, navigator, hands and handles over one robot's drivers and site map."""

    def __init__(self, robot) -> None:
        self.robot = robot
        d = robot.drivers
        self.body = Body(d.arm, d.gripper, d.base)
        self.eyes = Eyes(self.body, d.camera, level_with=lambda p: self.scene.in_front_cavity(p),
                         noticed=self._noticed, identify=self.identify)
        self._map = None
        self._stamp = -1.0
        self.busy = threading.Lock()  # one goal moves the robot at a time
        self._slip_at: float | None = None  # when the gripper was first found to have lost its item
        self._start()

    def identify(self, frame: Frame, expect: dict[str, Believed], holding: str | None = None) -> Frame:
        """Name the frame's detections: ``expect`` (what a look is for, where believed), the
        items last seen on the floor where they were, the held item (measured, or ``holding``)
        at the fingers while the gripper feels it, the map's things by the map."""
        held = self.eyes.held.name if self.eyes.held is not None else holding
        if held is not None and not self.body.holding():
            held = None
        belief = {n: Believed(tuple(float(v) for v in box.center), SEEN_RADIUS)
                  for n, box in self.scene.floor_items.items() if not n.startswith(ANONYMOUS)}
        belief.update(expect)
        vocabulary = {n: class_of(n) for n in (*belief, *([held] if held else []))}
        x, y, _ = self.body.base_pose()
        hand = tuple(float(v) for v in self.body.pose("tcp")[:3, 3])
        # only an item's own class: the kit knows its goal's objects, not what else of a
        # confusable class stands there (a bowl on the plate is not the plate)
        named = Identifier(vocabulary, self.scene.site, EXACT).identify(frame, belief, held, hand, self.scene.room_at(x, y))
        return self._held_by_place(named, held)

    def _held_by_place(self, frame: Frame, held: str | None) -> Frame:
        """``frame`` with the held item named where the camera shows it when its depth did not put
        it at the fingers (:meth:`~skills.eyes.Eyes.in_hand`)."""
        if held is None or any(d.name == held for d in frame.detections):
            return frame
        k = self.eyes.in_hand(frame, lambda label: label == class_of(held))
        if k is None:
            return frame
        dets = list(frame.detections)
        dets[k] = replace(dets[k], name=held)
        return replace(frame, detections=tuple(dets))

    def _noticed(self, frame, held: str | None) -> None:
        """What every frame the eyes take tells the scene model: where the map lies from here (the
        furniture it shows registered), items on the floor, leaves."""
        self.scene.relocalize(frame)
        self.scene.note_items(frame, held)
        self.scene.note_leaves(frame)

    def _start(self) -> None:
        site = self.robot.site_map()
        self._map = site
        self.scene = SceneModel(site)
        self.nav = Navigator(self.body, self.scene, self.eyes)
        self.hands = Hands(self.body, self.eyes, self.nav, self.scene)
        self.handles = Handles(self.body, self.eyes, self.nav, self.scene, self.hands)
        # what was registered of the map is carried across the base's motions by its odometry
        self.scene.mark, self.scene.since = self.body.mark, self.body.since
        self.body.base_moved = self.scene.base_moved
        # the arm's ways keep off the map as it lies from where the robot stands
        self.scene.changed = lambda: self.body.set_scene(self.scene.solid_boxes())
        self.eyes.held = None

    def _refresh(self) -> None:
        """Start over when the robot did (another episode), and forget a held item the gripper
        no longer holds."""
        stamp = float(self.robot.state().stamp)
        site = self.robot.site_map()
        if stamp < self._stamp or site != self._map:
            self._start()
        self._stamp = stamp
        if not self.body.holding():
            self.eyes.held = None

    @contextmanager
    def goal(self, ctx: GoalContext) -> Iterator["Kit"]:
        """The kit for one goal: the goal's cancellation reaches every driver call, progress reaches its
        feedback, and IK keeps off the map's solids (leaves where last seen). Waits while another goal of
        this robot uses the kit; restores the idle hooks when the goal ends."""
        with self.busy:
            self._refresh()
            self.body.set_scene(self.scene.solid_boxes())  # leaves where they were last seen
            self.eyes.views.clear()  # an item looked for in an earlier goal may have moved since
            self.body.cancelled = ctx.cancelled
            self._slip_at = None
            self.body.slipped = self._slipped
            self.hands.progress = ctx.feedback
            try:
                yield self
            finally:
                self.body.cancelled = lambda: False
                self.body.slipped = lambda: None
                self.hands.progress = lambda p, text: None

    @contextmanager
    def looking(self, cancelled) -> Iterator["Kit"]:
        """One camera-service call (:mod:`skills.views`): like a goal, without feedback."""
        with self.busy:
            self._refresh()
            self.body.set_scene(self.scene.solid_boxes())
            self.body.cancelled = cancelled
            try:
                yield self
            finally:
                self.body.cancelled = lambda: False

    def _slipped(self) -> str | None:
        """Why a drive of this goal should stop: the item the hand took slipped out of it, and
        has had the time to fall (:data:`SLIP_FALL`)."""
        held = self.eyes.held
        if held is None or self.body.holding():
            return None
        now = float(self.robot.state().stamp)
        if self._slip_at is None:
            self._slip_at = now
        return f"{held.name} slipped from the gripper" if now - self._slip_at >= SLIP_FALL else None

    # -- what the goal says the executive believes ---------------------------------------------

    @staticmethod
    def point(hints: dict[str, Hint], name: str):
        """The map-frame point the goal's hint for ``name`` gives, or None."""
        h = hints.get(name)
        return None if h is None or h.position is None else h.position

    @staticmethod
    def where(hints: dict[str, Hint], name: str) -> Where:
        """Where the goal's hint for ``name`` believes it is (on, inside, radius); an empty
        :class:`Where` without a hint."""
        h = hints.get(name)
        return Where() if h is None else Where(on=h.on, inside=h.inside, radius=h.radius)

    def holding(self, name: str) -> bool:
        """Whether the hand holds ``name``, with its geometry known: a held item the kit did not
        take itself (it was in the hand when the episode began) is measured in a frame first —
        it rides in the wrist camera's view (from its mask, when it is too near for depth)."""
        if not self.body.holding():
            return False
        held = self.eyes.held
        if held is not None and held.name == name:
            return True
        frame, tcp = self.eyes.frame(holding=name), self.body.pose("tcp")
        # in the hand it is nearer than the camera's minimum range: usually no depth at all
        seen = seen_from(frame, name) or seen_in_hand(frame, name, tcp)
        if seen is None:
            return False
        self.eyes.held = Held.taken(seen, tcp)
        return True
