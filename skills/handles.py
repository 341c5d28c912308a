"""Opening and closing: following a handle with the whole robot while a door or drawer moves.

A door leaf or drawer moves only because the hand holding its handle moves. How the handle can
move is the map's (:class:`~vap_bt.robot.site_map.Articulation`: hinge or slide, where the
handle is at the closed position); where the leaf stands *now* is looked at (the frame's points
of the piece fitted to the leaf's motion, :meth:`~skills.scene_model.SceneModel.fit_leaf`).
What is not known is where the base must be at each point of the handle's path: a side-hinged
leaf swings through the space in front of its cabinet and turns its handle by up to 100 degrees,
a room door carries its handle into the next room, and no single base pose reaches the whole arc.

:class:`HandleFollower` therefore plans base and arm together, one waypoint of the handle's path
at a time (every few degrees or centimetres), and checks every candidate before any joint moves:

* the base's footprint keeps a margin from walls, furniture and the leaf in its pose at that
  waypoint (convex outlines, :mod:`vap_bt.motion.footprint`);
* the arm reaches the handle from that base (IK, arm alone), near the previous joint values, and
  no collision shape of the robot (fingers at the grip's opening) comes near the leaf's panel (the
  leaf without its handle) or itself (:class:`~vap_bt.motion.collision.CollisionChecker`);
* the hand may lag the leaf's rotation by up to ``MAX_LAG`` about the bar (a loosely closed hand
  lets the bar turn in it), which keeps the wrist comfortable.

The grasp is searched globally on a ring of base poses around the handle; for each of the best
few the whole path is planned and the first that gets through wins (else the one that gets
furthest). Later waypoints search locally around the previous base pose and lag, preferring the
pose in which the handle sits comfortably in front of the robot — so the base walks along with
the door. The result is one whole-body joint path, timed and followed like any other motion.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from skills.body import Body, Struck, angle_to
from skills.eyes import Eyes
from vap_bt.outcome import Outcome
from skills.hands import APPROACH, Hands
from skills.navigator import Navigator
from skills.scene_model import Leaf, SceneModel
from vap_bt.motion import se3
from vap_bt.motion.collision import CollisionChecker, SceneBoxes
from vap_bt.motion.footprint import Obb, base_free
from vap_bt.motion.kinematics import Kinematics

BASE_MARGIN = 0.04  # footprint to obstacles while the leaf moves with the hand (the grip is springy)
PARKED_MARGIN = 0.015  # footprint to obstacles when the leaf stands still
ARM_MARGIN = 0.04  # arm and base shapes to the leaf's panel
HAND_MARGIN = 0.006  # gripper and finger shapes to the panel (they hold a bar in front of it)
HAND_LINKS = ("gripper_base_link", "left_finger_link", "right_finger_link")
COMFORT = 0.66  # handle distance in front of the base centre that the arm reaches best
ANGLE_STEP = 0.07  # rad between revolute waypoints
SLIDE_STEP = 0.025  # m between prismatic waypoints
MAX_LAG = 1.4  # rad the hand may trail (or lead) the leaf's rotation about the bar
MAX_JOINT_JUMP = 0.45  # rad of any arm joint between consecutive waypoints
GRASP_LAGS = (0.0, 0.4, -0.4, 0.8, -0.8, 1.2, -1.2)
LOCAL_STEPS = ((-0.08, 0.0, 0.08), (-0.08, 0.0, 0.08), (-0.12, 0.0, 0.12))  # base forward, left, yaw
LAG_STEPS = (-0.15, 0.0, 0.15)
RING = dict(distance=(0.58, 0.66, 0.74, 0.84), bearing=(0.0, -0.35, 0.35, -0.7, 0.7, -1.0, 1.0), yaw=(0.0, -0.3, 0.3))
GLOBAL_TRIES = 6  # initial poses whose whole path is planned before settling for the furthest
OPEN_TO = 0.92  # share of its travel an opened door or drawer is pulled to
SHUT_BELOW = 0.1  # share of its travel under which a leaf a look fits is taken as shut
#: an opening the arm could not follow all the way that left the leaf below this share of its
#: travel is pulled again, from where the leaf stopped (a new stance, a new path): an oven's
#: drop-down door left at a third of its travel lay across the way into the cavity, and every
#: placein after the "successful" open found no arm pose (heat_pie seeds 4, 9, 10)
PULL_AGAIN_BELOW = 0.7
#: pulls an opening takes at most
PULLS = 2
#: how an opening or closing that the arm could not follow to its end says so (a handle that
#: slipped from the fingers is another matter: the leaf is where the slip left it, and pulling
#: again would fight whatever held it)
NOT_ALL_THE_WAY = "the arm could not follow the handle all the way"
#: m in front of the base's centre the camera looks at a handle from: from the usual eye (0.5),
#: over the hand's reach, a fridge filled the picture and the detector named nothing in it
HANDLE_LOOK_FORWARD = 0.2
#: a closing hand presses a furniture door a little past closed, against its stop: the grip is
#: springy and the joint's friction would otherwise leave the leaf a few per cent open (room doors
#: swing both ways and have no stop there)
CLOSE_TO = -0.03
LOOSE_GRIP = 0.05  # finger opening round a held handle bar: it may turn in the hand, not slip out
RELEASE_GRIP = 0.075  # finger opening that lets the bar go (the fingers part along the leaf's face)
GRIP_FORCE = 80.0
FOLLOW_SPEED = 0.3  # share of the joint limits while the hand carries a handle
#: m the grasp stance of a path planned again from it may lie off where the base stands before it
#: drives there first (the arm's first joint-space move should not drag the base along)
REPLAN_STEP = 0.02


@dataclass
class Waypoint:
    """Body joints (base x, y, yaw, arm), the tcp pose there, and how far the hand trails the leaf."""

    q: np.ndarray
    T: np.ndarray
    lag: float


@dataclass
class HandlePath:
    """Waypoints carrying the handle (the first is the grasp), the leaf's joint value at each, and
    the pre-grasp the hand comes from."""

    waypoints: list[Waypoint]
    joint_values: list[float]
    complete: bool
    pre: Waypoint | None = None


class HandleFollower:
    """Plans whole-body paths that carry a handle along its leaf's motion."""

    def __init__(self, body: Body, scene: SceneModel) -> None:
        self.body, self.scene = body, scene
        self.opening = -1.0
        self._kin: Kinematics | None = None
        self._checker: CollisionChecker | None = None

    def use_panel(self, leaf: Leaf, opening: float) -> None:
        """Set up the robot's collision check against ``leaf``'s panel, fingers ``opening`` apart."""
        if self._kin is None or self.opening != opening:
            cfg = self.body.cfg
            fingers = dict(zip(cfg.gripper.joints, cfg.gripper.finger_positions(opening)))
            self._kin = Kinematics(joints=cfg.base.joints + cfg.arm.joints, locked=fingers)
            self.opening = opening
        size = 2 * leaf.panel(0.0).half
        checker = CollisionChecker(self._kin, SceneBoxes(np.eye(4)[None], size[None]), margin=HAND_MARGIN)
        objs = checker.geometry.geometryObjects
        panel = checker.geometry.ngeoms - 1
        for pair, request in zip(checker.geometry.collisionPairs, checker.data.collisionRequests):
            if pair.second == panel and objs[pair.first].name.rsplit("_", 1)[0] not in HAND_LINKS:
                request.security_margin = ARM_MARGIN
        self._checker = checker

    def arm_clear(self, q: np.ndarray, panel: Obb) -> bool:
        """The robot (base, arm, gripper, fingers round the bar) keeps off the panel and itself."""
        geom = self._checker.geometry
        geom.geometryObjects[geom.ngeoms - 1].placement = pin.SE3(panel.pose())
        return not self._checker.in_collision(q)

    @staticmethod
    def hand_pose(leaf: Leaf, side: float, q: float, q0: float, G0: np.ndarray, lag: float) -> np.ndarray:
        """tcp pose holding the handle at joint value ``q``, the hand turned ``lag`` back from the
        leaf's rotation about the hinge axis (signed like the joint)."""
        p, _, _ = leaf.handle_at(q, side)
        T = np.eye(4)
        T[:3, 3] = p
        T[:3, :3] = G0[:3, :3] if leaf.art.prismatic else se3.axis_angle(leaf.axis, (q - q0) - lag) @ G0[:3, :3]
        return T

    def _solve(self, T, base, seed, panel: Obb, prev) -> np.ndarray | None:
        s = np.array(seed, float)
        s[:3] = base
        q = self.body.solve(T, seed=s, collide=False)
        if q is None or (prev is not None and np.max(np.abs(q[3:] - prev[3:])) > MAX_JOINT_JUMP):
            return None
        return q if self.arm_clear(q, panel) else None

    @staticmethod
    def comfort(base, T: np.ndarray) -> float:
        """How awkward it is to hold ``T`` from ``base``: handle off the comfortable spot in front,
        hand turned away from the base's forward direction."""
        x, y, yaw = base
        c, s = math.cos(yaw), math.sin(yaw)
        d = T[:2, 3] - (x, y)
        fwd, left = c * d[0] + s * d[1], -s * d[0] + c * d[1]
        a = T[:2, 2]
        a_fwd = (c * a[0] + s * a[1]) / max(np.linalg.norm(a), 1e-6)
        return (fwd - COMFORT) ** 2 + left ** 2 + 0.03 * (1.0 - a_fwd)

    def _free(self, pose, static, leaf_box: Obb, margin: float = BASE_MARGIN) -> bool:
        return base_free(pose, static + [leaf_box.polygon()], margin)

    def plan(self, leaf: Leaf, side: float, q0: float, goal: float, G0: np.ndarray, here,
             opening: float) -> HandlePath:
        """Whole-body waypoints that carry the handle from ``q0`` to ``goal`` with the fingers
        ``opening`` apart round it, preceded by a pre-grasp ``APPROACH`` back along the hand's
        axis. ``G0``: the hand square to the leaf's face at ``q0``; ``here``: the base pose now."""
        self.use_panel(leaf, opening)
        step = SLIDE_STEP if leaf.art.prismatic else ANGLE_STEP
        n = max(1, int(math.ceil(abs(goal - q0) / step)))
        values = [q0 + (goal - q0) * k / n for k in range(n + 1)]
        static = self.scene.obstacles(moving=leaf.name)
        best: HandlePath | None = None
        for pre, wp in self._grasp_poses(leaf, side, q0, G0, static, here):
            path = self._follow(leaf, side, values, G0, wp, static)
            path.pre = pre
            if best is None or len(path.waypoints) > len(best.waypoints):
                best = path
            if path.complete:
                break
        return best or HandlePath([], [], False)

    def _grasp_poses(self, leaf: Leaf, side: float, q0: float, G0: np.ndarray, static, here):
        """Feasible (pre-grasp, grasp) pairs, best first: base poses on a ring around the handle,
        the hand square to the leaf or turned about the bar."""
        p = G0[:3, 3]
        box, panel = leaf.box(q0), leaf.panel(q0)
        cands = []
        for lag in ((0.0,) if leaf.art.prismatic else GRASP_LAGS):
            T = self.hand_pose(leaf, side, q0, q0, G0, lag)
            out = -T[:3, 2]
            if np.hypot(out[0], out[1]) < 0.3:  # a hand from below or above: no base pose faces it
                continue
            bearing0 = math.atan2(out[1], out[0])
            for d, b, dyaw in itertools.product(RING["distance"], RING["bearing"], RING["yaw"]):
                x, y = p[0] + d * math.cos(bearing0 + b), p[1] + d * math.sin(bearing0 + b)
                pose = (x, y, math.atan2(p[1] - y, p[0] - x) + dyaw)
                cost = self.comfort(pose, T) + 0.05 * math.hypot(x - here[0], y - here[1]) + 0.02 * lag * lag
                cands.append((cost, pose, T, lag))
        tries = 0
        seed = self.body.q()
        for _, pose, T, lag in sorted(cands, key=lambda c: c[0]):
            if not self._free(pose, static, box):
                continue
            pose = np.array(pose)
            pose[2] = angle_to(here[2], pose[2])
            q = self._solve(T, pose, seed, panel, None)
            if q is None:
                continue
            P = T.copy()
            P[:3, 3] -= T[:3, 2] * APPROACH
            q_pre = self._solve(P, pose, q, panel, q)
            if q_pre is not None:
                yield Waypoint(q_pre, P, lag), Waypoint(q, T, lag)
                tries += 1
                if tries >= GLOBAL_TRIES:
                    return

    def _follow(self, leaf: Leaf, side: float, values: list[float], G0: np.ndarray, first: Waypoint, static) -> HandlePath:
        wps = [first]
        for q in values[1:]:
            prev = wps[-1]
            box, panel = leaf.box(q), leaf.panel(q)
            x, y, yaw = prev.q[:3]
            c, s = math.cos(yaw), math.sin(yaw)
            lags = (0.0,) if leaf.art.prismatic else tuple({min(MAX_LAG, max(-MAX_LAG, prev.lag + d)) for d in LAG_STEPS})
            cands = []
            for (df, dl, dyaw), lag in itertools.product(itertools.product(*LOCAL_STEPS), lags):
                base = (x + c * df - s * dl, y + s * df + c * dl, yaw + dyaw)
                T = self.hand_pose(leaf, side, q, values[0], G0, lag)
                moved = df * df + dl * dl + 0.1 * dyaw * dyaw
                cands.append((self.comfort(base, T) + 0.3 * moved + 0.01 * lag * lag, base, T, lag))
            found = None
            for _, base, T, lag in sorted(cands, key=lambda c: c[0]):
                if not self._free(base, static, box):
                    continue
                sol = self._solve(T, base, prev.q, panel, prev.q)
                if sol is not None:
                    found = Waypoint(sol, T, lag)
                    break
            if found is None:
                return HandlePath(wps, values[:len(wps)], False)
            wps.append(found)
        return HandlePath(wps, values, True)


class Handles:
    """Open and close doors and drawers: look where the leaf stands, plan, grip, follow, let go."""

    def __init__(self, body: Body, eyes: Eyes, nav: Navigator, scene: SceneModel, hands: Hands) -> None:
        self.body, self.eyes, self.nav, self.scene, self.hands = body, eyes, nav, scene, hands
        self.follower = HandleFollower(body, scene)

    def leaf_point(self, name: str) -> np.ndarray:
        """Where to look to see ``name``'s leaf: the door's middle, a cabinet's front."""
        if self.scene.site.door(name) is not None:
            return self.nav.door_point(name)
        f = self.scene.furniture[name]
        cav = f.info.cavity
        z = sum(cav.z) / 2 if cav is not None else f.height / 2
        return f.to_world((0.0, f.depth / 2, z))

    def joint_now(self, name: str, opening: bool, again: bool = False) -> float:
        """The leaf's joint value as a look shows it; else what the action presumes (closed before
        an open, open before a close). ``again``: a second look, from where the hand will work,
        changes the first one's value only on clear evidence (``gated``) — it is for where the
        handle is: from close above a drawer's front, every pulled-out value explains its points
        as well as the closed one (no sight line crosses a front pulled out under the camera),
        and a closed drawer was taken for one open 16 cm, the hand closing on air in front of it;
        a shut room door seen from beside its handle was fitted a quarter open, and the hand
        pushed it open on its way to where that handle would be."""
        leaf = self.scene.leaves[name]
        default = 0.0 if opening else leaf.art.opened * OPEN_TO
        door = self.scene.site.door(name) is not None
        q = self._looked(name, gated=again, handle=True if again and door else None)
        return q if q is not None else self.scene.joint.get(name, default)

    def _handle_looked(self, name: str, q: float) -> None:
        """A look at the handle of ``name``'s leaf standing at ``q``, placing it where the frame
        shows its bar (:meth:`SceneModel.fix_handle`): a furniture leaf's; a room door's look at
        its leaf shows its handle, and that look places it (:meth:`joint_now`). Aimed at the
        handle, not the leaf's middle: from a fridge's grasp stance the look at its front cut
        the bar at the image's edge."""
        if self.scene.site.door(name) is not None:
            return
        arm = self.body.q()
        if self.eyes.look_at(self.scene.leaves[name].handle_at(q)[0], forward=HANDLE_LOOK_FORWARD):
            self.scene.fix_handle(name, self.eyes.frame(), q)
            # the leaf stands as the look at it said: this frame's own fit was made with the
            # piece where the localiser put it (a shut fridge 13 cm off was fitted open 0.74)
            self.scene.joint[name] = q
            # and the arm goes back to where that look left it: the path is planned from the
            # arm as it stands (IK's seed), and from the handle's view a fridge's and an oven's
            # plans found other stances, with no clear way to the pre-pose
            self.body.through([arm])

    def _looked(self, name: str, **fit) -> float | None:
        """The leaf's joint value a look at it from here fits (:meth:`SceneModel.fit_leaf` with
        ``fit``), or None when no aim is clear or the frame does not show it."""
        if not self.eyes.look_at(self.leaf_point(name)):
            return None
        return self.scene.fit_leaf(name, self.eyes.frame(), **fit)

    def shut(self, name: str) -> bool:
        """Whether a look at ``name``'s leaf shows it shut (fitted under :data:`SHUT_BELOW` of its
        travel); False when ``name`` has no leaf or no look shows it. From where the motion left
        the robot first, then from the piece's standoff: on the localiser's and the depth
        camera's noise, the look from where a takeout ended did not show the fridge to the
        detector, the same look after the drive to its standoff did."""
        leaf = self.scene.leaves.get(name)
        if leaf is None:
            return False
        for stand in (None, self.nav.standoff(name)):
            if stand is not None:
                self.nav.approach(stand)
            q = self._looked(name)
            if q is not None:
                return abs(q) < SHUT_BELOW * abs(leaf.art.opened)
        return False

    def open_close(self, name: str, opening: bool) -> Outcome:
        """Open or close ``name`` with a free hand: something held is set down on the nearest
        surface of the room first and taken again afterwards, the way it was held."""
        if name not in self.scene.leaves:
            return Outcome(False, f"{name} has nothing to open")
        held = self.eyes.held
        if held is None or not self.body.holding():
            return self._pulls(name, opening)
        sideways = abs(self.body.pose("tcp")[2, 2]) < 0.8  # level or pitched, not from above
        surface = self.hands.set_down(sideways)
        if surface is None:
            return Outcome(False, f"{name}: the hand is full")
        out = self._pulls(name, opening)
        # taken again the way it was held: it may have to go into a low cavity next
        self.hands.take_again(held.name, surface, sideways)
        return out

    def _pulls(self, name: str, opening: bool) -> Outcome:
        """:meth:`_open_close`, and an opening the arm could not follow all the way that stopped
        short (:data:`PULL_AGAIN_BELOW`) once more from where the leaf stands, up to :data:`PULLS`
        in all."""
        out = self._open_close(name, opening)
        for _ in range(PULLS - 1):
            if not (opening and out.message.endswith(NOT_ALL_THE_WAY) and self._short(name)):
                break
            self.hands.progress(0.0, f"{name} stands short of open: pulling again")
            out = self._open_close(name, opening)
        return out

    def _short(self, name: str) -> bool:
        """Whether ``name``'s leaf, as last seen, stands below :data:`PULL_AGAIN_BELOW` of its travel."""
        art = self.scene.leaves[name].art
        return abs(self.scene.joint.get(name, 0.0)) < PULL_AGAIN_BELOW * abs(art.opened)

    def _plan(self, name: str, q0: float, opening: bool, here) -> tuple[HandlePath, float, float]:
        """The whole-body path carrying ``name``'s handle from ``q0`` to open or shut, planned
        from the base at ``here`` on the leaf as the scene model has it now; with the handle's
        side (room doors: the face towards the robot) and the goal's joint value."""
        leaf = self.scene.leaves[name]
        art = leaf.art
        side, goal_open = 1.0, art.opened
        if art.other_side is not None:  # a room door: the face towards the robot, pushed away from it
            p, n, _ = leaf.handle_at(q0)
            side = 1.0 if (np.array([*here[:2], p[2]]) - p) @ n > 0 else -1.0
            goal_open = abs(art.opened) * side
        goal = goal_open * OPEN_TO if opening else (0.0 if art.other_side is not None else art.opened * CLOSE_TO)
        p, n, bar = leaf.handle_at(q0, side)
        G = se3.frame_zx(-n, -bar if abs(bar[2]) > 0.5 else bar, p)
        return self.follower.plan(leaf, side, q0, goal, G, here, LOOSE_GRIP), side, goal

    def _open_close(self, name: str, opening: bool) -> Outcome:
        start = self.body.base_pose()
        q0 = self.joint_now(name, opening)
        path, _, _ = self._plan(name, q0, opening, start)
        if not path.waypoints:
            return Outcome(False, f"{name}: handle out of reach")
        grasp = path.waypoints[0]
        self.hands.progress(0.05, "approaching the handle")
        self.nav.approach(tuple(grasp.q[:3]))
        # the drive changed the localiser's error: from the grasp stance, a look at the leaf lays
        # the map onto what the camera shows (the handle within a centimetre or two of where the
        # fingers will close, however far the localiser is off) and the path is planned again
        here = self.body.base_pose()
        q0 = self.joint_now(name, opening, again=True)
        self._handle_looked(name, q0)
        again, _, _ = self._plan(name, q0, opening, here)
        ways = [path]
        if again.waypoints:
            # the path planned from here first; the one the base came for still serves if the new
            # one's pre-pose has no clear way to it (IK may answer another wrist), unless the base moves on
            ways = [again, path]
            if np.linalg.norm(np.subtract(again.waypoints[0].q[:2], here[:2])) > REPLAN_STEP:
                stance = again.waypoints[0].q[:3]
                self.nav.approach(tuple(stance))
                ways = [again]
                here = self.body.base_pose()
                if np.linalg.norm(np.subtract(stance[:2], here[:2])) > REPLAN_STEP:
                    # the base believes itself elsewhere than it drove to: the localiser's frame
                    # moved when it came to rest, and a path planned before was 14 cm off the bar
                    # (the map, and the handle fixed from the last stance, are carried by the
                    # wheels): planned once more in the frame believed now
                    moved, _, _ = self._plan(name, q0, opening, here)
                    ways = [moved] if moved.waypoints else ways
        self.hands.progress(0.1, "reaching for the handle")
        self.body.fingers(LOOSE_GRIP)  # wide enough round the bar, narrow enough beside the leaf
        path = next((p for p in ways if self.body.through([p.pre.q], 0.8)), None)
        if path is None:
            self.body.home()
            return Outcome(False, f"{name}: handle out of reach")
        grasp = path.waypoints[0]
        self.body.line(grasp.T, steps=4, speed=0.3)
        self.body.through([grasp.q], 0.3)
        if not self.body.fingers(0.0, GRIP_FORCE):
            self._retreat(name, q0, start)  # the hand slipped off the handle: the leaf stays
            return Outcome(True, f"{name}: the handle slipped")
        self.body.fingers(LOOSE_GRIP)  # the bar may now turn in the hand
        self.hands.progress(0.3, "moving the handle")
        struck = False
        try:
            self.body.through([w.q for w in path.waypoints[1:]], FOLLOW_SPEED)
        except Struck:
            # the hand or the leaf met what the path did not hold (the leaf's stop, the carcass):
            # the fingers must still let go of the bar, or every later motion drags the leaf along
            struck = True
        reached = path.joint_values[-1]
        if struck or not self.body.holding():
            # the handle slipped out of the hand on the way, or the way stopped short: the leaf is
            # not where the path ended, and backing off as if it were would push it; the wrist
            # camera, right at it, shows it
            seen = self.scene.fit_leaf(name, self.eyes.frame())
            reached = seen if seen is not None else q0
        self.scene.joint[name] = reached
        self.hands.progress(0.85, "letting go")
        self._retreat(name, reached, start)
        if struck or not path.complete:
            return Outcome(True, f"{name}: {NOT_ALL_THE_WAY}")
        return Outcome(True)

    def _retreat(self, name: str, q: float, start) -> None:
        """Let go of a leaf without dragging it: the fingers open and back off the bar along the
        hand's axis and away from the leaf's face, the base steps back, the arm folds (through a
        point above the base if folding straight would sweep through the leaf), and the base
        returns to where the action began if that way is clear of the leaf for the folded arm."""
        leaf = self.scene.leaves[name]
        box, panel = leaf.box(q), leaf.panel(q)
        self.body.fingers(RELEASE_GRIP)
        off = self.body.pose("tcp")
        off[:3, 3] -= off[:3, 2] * 0.12
        self.body.line(off, steps=3, speed=0.3)
        n = leaf.handle_at(q, 1.0)[1]
        n = n if (self.body.pose("tcp")[:3, 3] - panel.center) @ n > 0 else -n
        away = self.body.pose("tcp")
        away[:3, 3] += n * 0.1
        try:
            self.body.line(away, steps=2, speed=0.3)
        except Struck:
            pass  # the forearm met the carcass under an oven's dropped door: the hand is off the bar, fold from here
        static = self.scene.obstacles(moving=name) + [box.polygon()]
        here = np.array(self.body.base_pose())
        back = here - 0.25 * np.array([math.cos(here[2]), math.sin(here[2]), 0.0])
        if base_free(back, static, PARKED_MARGIN):
            self.body.drive([tuple(back)], 0.5)
        home = self.body.q()
        home[3:] = self.body.cfg.arm.home
        now = self.body.q()
        self.follower.use_panel(leaf, RELEASE_GRIP)
        if not all(self.follower.arm_clear(now + (home - now) * s, panel) for s in np.linspace(0, 1, 12)):
            inner = self.body.pose("tcp")
            inner[:3, 3] = self.body.in_base((0.45, 0.0, 1.1))
            self.body.line(inner, steps=4, speed=0.4)
        self.body.home()
        self.body.fingers(self.body.cfg.gripper.stroke)
        here = np.array(self.body.base_pose())
        goal = np.array(start)
        goal[2] = angle_to(here[2], goal[2])
        backward = -np.array([math.cos(here[2]), math.sin(here[2]), 0.0])
        for via in ([], [here + backward * 0.3], [here + backward * 0.6]):
            legs = [here, *via, goal]
            if all(base_free(a + (b - a) * s, static, PARKED_MARGIN, folded=True)
                   for a, b in zip(legs, legs[1:]) for s in np.linspace(0.05, 1, 12)):
                self.body.drive([tuple(p) for p in legs[1:]], 0.5)
                break
        if self.eyes.look_at(self.leaf_point(name)):  # where the leaf stands now, as the camera sees it
            self.scene.fit_leaf(name, self.eyes.frame(), hint=q)
