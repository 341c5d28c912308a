"""Motion primitives: what the robot physically does for each household action.

Each primitive moves the robot through :class:`~vap_bt.sim.pb_motion.Motion` (IK, timed joint
trajectories, motors) and lets the physics produce the effect: a grasp closes the fingers until
they touch the object and only then ties it to the hand; an ``open`` grips the handle and drags it
along its arc (or slide), so the door's joint turns because the arm pulled it; a ``push`` slides
the blocker aside with the closed fingers; a ``cut`` strokes the held knife down until it touches
the object, which then falls apart into two bodies.

A :class:`~vap_bt.sim.situations.SituationSpec` drawn for the action (Table II) is made physically
so by changing the motion, never the outcome directly: the fingers close short of the object, the
gripper opens over the floor beside the robot, the hand slips off the handle, the press misses
the switch, the knife stops short. The ground truth then shows what Table I describes.

Where the robot stands and looks follows one rule: furniture is worked from its standoff pose in
front of it; items from their support's standoff shifted sideways to face them (floor items from
the corridor side); the wrist camera then looks at the target from above the base.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import cv2
import numpy as np
import pybullet as pb

from vap_bt.motion.se3 import approach_pose as _frame
from vap_bt.sim.pb_articulation import PARKED_MARGIN, HandleFollower, Obb
from vap_bt.sim.pb_camera import look_pose
from vap_bt.sim.pb_catalog import Catalog
from vap_bt.sim.pb_motion import Motion
from vap_bt.sim.pb_robot import Robot
from vap_bt.sim.pb_rules import show_state, split, turn_on
from vap_bt.sim.pb_scene import Scene, Thing
from vap_bt.sim.pb_truth import Truth
from vap_bt.sim.situations import SituationSpec
from vap_bt.world import ActionOutcome

CAMERA_EYE = (0.50, 0.0, 1.20)  # where the camera looks from, in the base frame
CARRY = (0.30, 0.40, 0.95)  # where a held object rides, in the base frame (beside the base)
DROP = (0.30, 0.62, 0.55)  # where an object is let go "nearby": over the floor beside the base
CORRIDOR_SPEED = 1.0
APPROACH = 0.14  # pre-grasp distance along the approach axis
#: a side grasp keeps the hand level when the tcp can be this high above the item's bottom (the
#: gripper housing reaches 0.03 m and the wrist 0.045 m below the hand's axis); lower items are
#: taken with the hand pitched down by SIDE_PITCH, the tcp SIDE_PITCHED_HEIGHT above the bottom
SIDE_LEVEL_HEIGHT = 0.042
SIDE_PITCH = 0.6
SIDE_PITCHED_HEIGHT = 0.025
FINGERTIP = 0.02  # the fingertips reach this far beyond the tcp
WITHDRAW_MARGIN = 0.05  # an item taken out of a container clears its rim or front face by this much
EDGE_SPOT = 0.1  # a spot "at the front edge" of a surface: its centre this far behind the edge
#: base centre to the worked point, horizontally, for a top-down and a horizontal approach
WORK_DISTANCE = {"top": 0.62, "front": 0.74}
BASE_CLEARANCE = 0.40  # base centre to the front face of the furniture at least
WORK_SHIFTS = (0.0, 0.08, -0.08, 0.16, -0.16, 0.24, -0.24)  # sideways, to keep a work pose clear
WORK_BACKOFFS = (0.0, 0.05, 0.1, 0.15)  # further from the point, when no sideways shift is clear
WORK_MARGIN = 0.08
DETOUR_BACKOFFS = (0.5, 0.8, 1.1)  # via poses behind the start or the goal, when the straight way is blocked
LEAVE_SLACK = 0.1  # a drive may start close to an obstacle (a work pose): checked once this far away
ARM_SLACK = 0.5  # the last part of a drive, where the arm reaches over the furniture to be worked  # base footprint to obstacles at a work pose (the arm is wider than the base)
#: a camera aim turns off its point by one of these angles (rad) when the held item covers it; the
#: point then shows this far (normalised image units, ~4 degrees) outside the item and the frame edge
AIM_TURNS = (0.06, 0.1, 0.14, 0.18, 0.22, 0.26, 0.3)
AIM_MARGIN = 0.07
_BOX_SIGNS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
#: a room door is looked at from this far (base centre to the doorway): the leaf, 1.2 m wide, then
#: fits the wrist camera's frame (from the 0.95 m where the robot stops to open it, it overfills it)
DOOR_VIEW = 1.8
OPEN_TO = 0.92  # fraction of its travel an opened door or drawer is pulled to (limits: 1.0)
#: a closing hand presses a furniture door a little past closed, against its stop: the grip is
#: springy and the joint's friction would otherwise leave the leaf a few per cent open (room doors
#: swing both ways and have no stop there)
CLOSE_TO = -0.03
LOOSE_GRIP = 0.05  # finger opening round a held handle bar (the bar's diagonal is 0.034 m)
FOLLOW_SPEED = 0.3  # fraction of the joint limits while the hand carries a handle


def _rotation(axis, angle: float) -> np.ndarray:
    """Rotation matrix about a unit axis (Rodrigues)."""
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * (k @ k)


def _how(a) -> str:
    """A hand approaching along ``a`` works from above ("top") or from the side ("front", level or
    pitched down)."""
    return "top" if a[2] < -0.9 else "front"


class Primitives:
    def __init__(self, scene: Scene, robot: Robot, motion: Motion, truth: Truth, catalog: Catalog,
                 phase: Callable[[float, str], None]) -> None:
        self.scene, self.robot, self.motion, self.truth, self.catalog = scene, robot, motion, truth, catalog
        self.phase = phase
        self.cid = scene.client
        self.look_target: np.ndarray | None = None
        self.look_pose: np.ndarray | None = None  # the camera's pose when it was last aimed
        self.release_at: float | None = None  # progress of a base move at which to let go (Table II)
        self.follower = HandleFollower(scene, motion)

    # ================================================================ poses

    def base_T(self, q=None) -> np.ndarray:
        x, y, yaw = (self.robot.target if q is None else q)[:3]
        c, s = math.cos(yaw), math.sin(yaw)
        T = np.eye(4)
        T[:3, :3] = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
        T[:3, 3] = (x, y, 0)
        return T

    def in_base(self, p) -> np.ndarray:
        return (self.base_T() @ np.array([*p, 1.0]))[:3]

    def standoff(self, name: str) -> tuple[float, float, float]:
        t = self.scene.things[name]
        plan = self.scene.plan
        if t.furniture is not None:
            return t.furniture.standoff()
        if t.door is not None:
            return self._door_pose(t, self.truth.room_of_point(self.robot.base_pose[:2]) or t.door.low, DOOR_VIEW)
        if t.room is not None:  # a floor (or a room): the room's middle, on the corridor
            r = plan.rooms[t.room]
            return ((r.x0 + r.x1) / 2, plan.corridor_y, math.pi / 2)
        c = self.truth.center(name)
        support = self.truth.support_of(name) or self.truth.container_of(name)
        st = self.scene.things.get(support) if support else None
        if st is not None and st.furniture is not None:
            f = st.furniture
            lateral = float(self.truth._local(f, c)[0])
            lateral = max(-f.kind.size[0] / 2, min(f.kind.size[0] / 2, lateral))
            return f.standoff(lateral)
        # on a floor: from the corridor side, facing the front wall
        return (float(c[0]), float(min(c[1] + 0.72, plan.corridor_y + 0.3)), -math.pi / 2)

    def _door_pose(self, t: Thing, room: str, dist: float) -> tuple[float, float, float]:
        d = t.door
        side = -1.0 if room == d.low else 1.0
        return (d.x + side * dist, d.center_y, math.pi if side > 0 else 0.0)

    def work_pose(self, point, toward, how: str, clear_of: str | None = None) -> tuple[float, float, float]:
        """Base pose for manipulating at ``point``: ``toward`` is the horizontal direction from
        the point to where the robot stands; keep clear of the front of ``clear_of``, and step
        sideways (facing the point) when an open door leaf or other furniture is in the way."""
        f = np.array([toward[0], toward[1], 0.0])
        f /= np.linalg.norm(f)
        r = WORK_DISTANCE[how]
        t = self.scene.things.get(clear_of) if clear_of else None
        if t is not None and t.furniture is not None:
            fp = t.furniture
            front = fp.to_world((0.0, fp.kind.size[1] / 2, 0.0))
            behind = float((front - np.asarray(point))[:2] @ fp.front[:2])
            r = max(r, behind + BASE_CLEARANCE)
        side = np.array([-f[1], f[0], 0.0])
        obstacles = self.follower.obstacles()
        for back in WORK_BACKOFFS:  # further back only when no sideways step clears (an open drawer)
            p = np.asarray(point) + f * (r + back)
            for shift in WORK_SHIFTS:
                q = p + side * shift
                pose = (float(q[0]), float(q[1]), math.atan2(point[1] - q[1], point[0] - q[0]))
                if self.follower.base_free(pose, obstacles, margin=WORK_MARGIN):
                    return pose
        p = np.asarray(point) + f * r
        return (float(p[0]), float(p[1]), math.atan2(-f[1], -f[0]))

    def approach(self, pose) -> None:
        """Drive the base to a work pose (arm at home or carrying). A pose in another room is
        reached the way navigation goes, along the corridor and through the doorway (stopping in
        front of a door that is not open), never straight through a wall."""
        here, there = self.truth.room_of_point(self.robot.target[:2]), self.truth.room_of_point(pose[:2])
        if here is not None and there is not None and here != there:
            self.drive_to(pose)
            return
        for p in self.base_path(pose):
            self.motion.drive(p, 0.6)

    def base_path(self, pose) -> list[tuple[float, float, float]]:
        """Poses to drive through to ``pose`` without the base or the arm above it running into a
        wall, furniture or an open leaf: straight if that is clear, else through one via pose
        (backed off from the goal along its heading, or round a corner); straight if none is."""
        here = np.array(self.robot.target[:3], float)
        goal = np.array(pose, float)
        goal[2] = here[2] + math.remainder(goal[2] - here[2], 2 * math.pi)
        obstacles = self.follower.obstacles()
        heading = np.array([math.cos(goal[2]), math.sin(goal[2]), 0.0])
        vias = [goal - heading * k for k in DETOUR_BACKOFFS] + [np.array([goal[0], here[1], goal[2]]),
                                                               np.array([here[0], goal[1], here[2]])]
        turned = np.array([here[0], here[1], goal[2]])  # turning on the spot first swings the arm away
        paths = [[goal], *([v, goal] for v in vias), [turned, goal], *([turned, v, goal] for v in vias),
                 *([turned, turned - heading * k, v, goal] for k in DETOUR_BACKOFFS for v in vias[:len(DETOUR_BACKOFFS)])]
        for path in paths:
            legs = [here, *path]
            if all(self._leg_clear(a, b, obstacles) for a, b in zip(legs, legs[1:])):
                return [tuple(map(float, p)) for p in path]
        return [tuple(map(float, goal))]

    def _leg_clear(self, a: np.ndarray, b: np.ndarray, obstacles) -> bool:
        """A straight base move keeps the footprint off every obstacle once it has left ``a``, and
        the arm (folded or carrying, seen from above) too except near ``b``, where it works over
        the furniture."""
        def way(u, v) -> float:  # a turn on the spot counts as a way too (the arm sweeps)
            return float(np.linalg.norm((v - u)[:2]) + 0.4 * abs(v[2] - u[2]))

        n = max(2, int(way(a, b) / 0.08) + 1)
        for s in np.linspace(0.0, 1.0, n):
            q = a + (b - a) * s
            left, to_go = way(a, q), np.linalg.norm((b - q)[:2])
            if left < LEAVE_SLACK:
                continue
            if not self.follower.base_free(q, obstacles, folded=to_go > ARM_SLACK, margin=PARKED_MARGIN):
                return False
        return True

    # ================================================================ arm helpers

    def home(self) -> None:
        q = self.robot.target.copy()
        q[3:] = self.robot.cfg.arm.home
        self.motion.through([q], 0.8)

    def look_at(self, point, lift: float = 0.0, allow_base: bool = False) -> bool:
        """Aim the wrist camera at ``point`` from above the base (``lift`` higher). With something
        in the hand the aim turns off the point just enough that the held item, rigid in the
        camera's view, does not cover it (:meth:`aim_past_held`)."""
        eye = self.in_base((CAMERA_EYE[0], CAMERA_EYE[1], CAMERA_EYE[2] + lift))
        T = look_pose(eye, point)
        for pose in (self.aim_past_held(T), T):
            q = self.motion.solve(pose, "camera_optical", allow_base=allow_base)
            if q is not None:
                break
        else:
            return False
        self.motion.through([q], 0.8)
        self.look_target = np.asarray(point, float)
        self.look_pose = self.robot.link_pose("camera_optical")
        return True

    def held_corners(self) -> np.ndarray | None:
        """Corners (world) of the held item's oriented box(es), or None with an empty hand."""
        name = self.truth.held()
        if name is None:
            return None
        t = self.scene.things[name]
        ext = np.asarray(t.kind.extent) / 2
        pts = []
        for b in t.bodies:
            pos, orn = pb.getBasePositionAndOrientation(b, physicsClientId=self.cid)
            R = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
            pts.append(np.asarray(pos) + (_BOX_SIGNS * ext) @ R.T)
        return np.concatenate(pts)

    def aim_past_held(self, T: np.ndarray) -> np.ndarray:
        """``T`` (a camera pose looking along its z at a point) turned the least so that the point
        shows clear of the held item. The item is rigid with the camera, so where it appears in
        the image does not depend on the aim: its box is projected once (normalised image
        coordinates, from the camera pose now) and aims whose point falls outside that outline by
        AIM_MARGIN, and inside the frame, are tried from small turns to large ones. Returns ``T``
        when the point is not covered or no turn clears it."""
        corners = self.held_corners()
        if corners is None:
            return T
        cam = self.robot.cfg.camera
        C = np.linalg.inv(self.robot.link_pose("camera_optical"))
        pc = corners @ C[:3, :3].T + C[:3, 3]
        z = np.maximum(pc[:, 2], cam.near)
        hull = cv2.convexHull((pc[:, :2] / z[:, None]).astype(np.float32))
        half = np.array([cam.width / 2 / cam.fx, cam.height / 2 / cam.fy]) - AIM_MARGIN

        def clear(uv) -> bool:
            if np.any(np.abs(uv) > half):
                return False
            return cv2.pointPolygonTest(hull, (float(uv[0]), float(uv[1])), True) < -AIM_MARGIN

        if clear(np.zeros(2)):
            return T
        for r in AIM_TURNS:
            for ang in np.linspace(0.0, 2 * math.pi, 16, endpoint=False):
                uv = np.array([math.cos(ang), math.sin(ang)]) * math.tan(r)
                if clear(uv):
                    d = np.array([uv[0], uv[1], 1.0])
                    d /= np.linalg.norm(d)
                    # the turn taking the optical axis to d, undone: the point then shows at uv
                    axis = np.cross((0.0, 0.0, 1.0), d)
                    Q = _rotation(axis / np.linalg.norm(axis), math.acos(float(d[2])))
                    out = T.copy()
                    out[:3, :3] = T[:3, :3] @ Q.T
                    return out
        return T

    def aimed_at(self, point, tolerance: float = 0.15) -> bool:
        """Whether the wrist camera still looks as the last :meth:`look_at` aimed it, at a point
        within ``tolerance`` of ``point`` (an action since may have moved the arm: a remembered
        aim is no evidence of where the camera looks now)."""
        if self.look_target is None or self.look_pose is None:
            return False
        T = self.robot.link_pose("camera_optical")
        still = (np.linalg.norm(T[:3, 3] - self.look_pose[:3, 3]) < 0.03
                 and float(T[:3, 2] @ self.look_pose[:3, 2]) > math.cos(0.05))
        return bool(still and np.linalg.norm(np.asarray(point, float) - self.look_target) <= tolerance)

    def carry(self) -> None:
        """Arm to the carry pose: the held object beside the base (empty hand: home)."""
        if self.truth.held() is None:
            self.home()
            return
        T = self.motion.pose("tcp")
        rel = np.linalg.inv(self.base_T()) @ T
        rel[:3, 3] = CARRY
        q = self.motion.solve(self.base_T() @ rel, allow_base=False)
        if q is not None:
            self.motion.through([q], 0.8)

    def goto_pose(self, T: np.ndarray, speed: float = 0.8, allow_base: bool = False) -> bool:
        q = self.motion.solve(T, allow_base=allow_base)
        if q is None:
            return False
        return self.motion.through([q], speed)

    def open_hand(self) -> None:
        self.robot.detach()
        self.motion.fingers(self.robot.cfg.gripper.stroke)

    def drop_nearby(self) -> None:
        """Let the held object fall to the floor beside the robot."""
        T = self.motion.pose("tcp")
        T[:3, 3] = self.in_base(DROP)
        self.goto_pose(T, allow_base=False)
        self.open_hand()
        self.motion.settle(45)  # let it fall and come to rest

    # ================================================================ navigation

    def drive_to(self, pose) -> ActionOutcome:
        """Base along the corridor to ``pose``; stops at a closed door on the way."""
        plan = self.scene.plan
        self.carry()
        x, y, yaw = self.robot.base_pose
        legs = [(x, plan.corridor_y, yaw)]
        here = plan.rooms[self.truth.room_of_point((x, y))] if self.truth.room_of_point((x, y)) else None
        for d in sorted(plan.doors.values(), key=lambda d: abs(d.x - x)):
            crosses = (min(x, pose[0]) < d.x < max(x, pose[0])) and here is not None
            if crosses:
                side = -1.0 if x < d.x else 1.0
                legs.append((d.x + side * 0.95, d.center_y, 0.0 if side < 0 else math.pi))
                legs.append(("door", d.name))
                legs.append((d.x - side * 0.95, d.center_y, pose[2]))
        legs += [(pose[0], plan.corridor_y, pose[2]), tuple(pose)]
        drives = [leg for leg in legs if leg[0] != "door"]
        total = max(len(drives), 1)
        done = 0
        for leg in legs:
            if leg[0] == "door":
                if not self.truth._open(leg[1]):
                    self.look_at(self._door_look(leg[1]))
                    return ActionOutcome(False, f"door {leg[1]} is not open: stopped in front of it")
                continue
            self._drive_leg(leg, done / total, 1 / total)
            done += 1
        return ActionOutcome(True)

    def _drive_leg(self, pose, p0: float, span: float) -> None:
        def on_sample(s: float) -> None:
            if self.release_at is not None and p0 + s * span >= self.release_at and self.truth.held():
                self.release_at = None
                self.robot.detach()  # the object slips out mid-way
                self.robot.command_fingers(self.robot.cfg.gripper.stroke)
            self.phase(p0 + s * span, "driving")

        self.motion.on_sample = on_sample
        try:
            for p in self.base_path(pose):
                self.motion.drive(p, CORRIDOR_SPEED)
        finally:
            self.motion.on_sample = None

    def _door_look(self, door: str) -> np.ndarray:
        d = self.scene.things[door].door
        return np.array([d.x, d.center_y, 0.8])

    def target_point(self, name: str) -> np.ndarray:
        t = self.scene.things[name]
        if t.door is not None:
            return self._door_look(name)
        if t.room is not None:
            x, y, yaw = self.robot.base_pose
            return np.array([x + 1.5 * math.cos(yaw), y + 1.5 * math.sin(yaw), 0.0])
        if t.furniture is not None:
            f = t.furniture
            if f.kind.cavity is not None:
                z = sum(f.kind.cavity.z) / 2
                return f.to_world((0.0, f.kind.size[1] / 4, z))
            return f.to_world((0.0, 0.0, f.kind.size[2]))
        return self.truth.center(name)

    def find(self, target: str, sit: SituationSpec | None) -> ActionOutcome:
        if sit is not None and sit.drops == "held":
            self.release_at = 0.5
        try:
            out = self.drive_to(self.standoff(target))
        finally:
            self.release_at = None
        self.look_at(self.target_point(target))
        return out

    def navigate(self, to_room: str, door: str, sit: SituationSpec | None) -> ActionOutcome:
        if sit is not None and sit.drops == "held":
            self.release_at = 0.5
        t = self.scene.things[door]
        try:
            out = self.drive_to(self._door_pose(t, to_room, 1.0))
        finally:
            self.release_at = None
        self.look_at(self._door_look(door))
        return out

    # ================================================================ grasping

    def grasp_frame(self, name: str, sideways: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """Grasp pose of the tcp and the approach direction for an item where it is now: from the
        side out of a front-open container (or when asked), else from above."""
        t = self.scene.things[name]
        c = self.truth.center(name)
        container = self.truth.container_of(name)
        ct = self.scene.things.get(container) if container else None
        if (ct is not None and ct.furniture.kind.cavity.open == "front") or sideways:
            a = -ct.furniture.front if ct is not None else -self.toward_robot(c, self.truth.support_of(name))
            bottom = self.truth.aabb(name)[2]
            p = c.copy()
            if c[2] - bottom < SIDE_LEVEL_HEIGHT:
                # a level hand this low would put the gripper housing and the wrist into the
                # support: the hand comes in pitched down instead, its tcp a little higher
                a = math.cos(SIDE_PITCH) * a + np.array([0.0, 0.0, -math.sin(SIDE_PITCH)])
                p[2] = max(c[2], bottom + SIDE_PITCHED_HEIGHT)
            return _frame(a, (0, 0, -1), p), a
        _, orn = pb.getBasePositionAndOrientation(t.body, physicsClientId=self.cid)
        R = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
        left = self.base_T()[:3, 1]
        across = left if t.kind.shape == "sphere" or (t.kind.shape == "cylinder" and not t.kind.lying) else R[:, 1]
        across = np.array([across[0], across[1], 0.0])
        across /= np.linalg.norm(across)
        if across @ left < 0:
            across = -across
        z = np.array([0.0, 0.0, -1.0])
        x = np.cross(across, z)
        top = self.truth.aabb(name)[5]
        p = c.copy()
        # fingertips (0.018 m beyond the tcp) reach below the top, but stay off the support
        p[2] = max(top - 0.03, c[2], self.truth.aabb(name)[2] + 0.022)
        return _frame(z, x, p), z

    def toward_robot(self, point, support: str | None) -> np.ndarray:
        """Horizontal direction from a point to the side the robot works it from."""
        t = self.scene.things.get(support) if support else None
        if t is not None and t.furniture is not None:
            return t.furniture.front
        d = np.array([*self.robot.base_pose[:2], 0.0]) - np.asarray(point)
        d[2] = 0.0
        return d / max(np.linalg.norm(d), 1e-6)

    def grasp(self, name: str, sit: SituationSpec | None, sideways: bool = False) -> ActionOutcome:
        t = self.scene.things[name]
        G, a = self.grasp_frame(name, sideways)
        where = self.truth.container_of(name) or self.truth.support_of(name)
        self.approach(self.work_pose(G[:3, 3], self.toward_robot(G[:3, 3], where), _how(a), where))
        G, a = self.grasp_frame(name, sideways)
        self.phase(0.1, "pre-grasp")
        if self.reach_pre(G, a, where, APPROACH) is None:
            self.home()
            return ActionOutcome(False, f"{name}: no arm pose reaches it")
        self.motion.fingers(self.robot.cfg.gripper.stroke)
        target = G.copy()
        if sit is not None and sit.kind == "grasp_fails_object_unchanged":
            target[:3, 3] -= a * 0.09  # the fingers close short of the object
        self.phase(0.35, "approach")
        self.motion.line(target, steps=4, speed=0.3)
        self.phase(0.55, "closing")
        touching = self.motion.fingers(0.0, t.body, force=60.0)
        if touching >= 1:
            self.robot.attach(t.body, name)
        self.phase(0.75, "lifting")
        back = self.motion.pose("tcp")
        back[2, 3] += 0.12 if _how(a) == "top" else 0.02
        self.motion.line(back, steps=3, speed=0.3)
        wt = self.scene.things.get(where) if where else None
        if wt is not None and wt.furniture is not None and wt.furniture.kind.cavity is not None:
            self.withdraw(name if self.robot.grip is not None else None, where)
        elif _how(a) == "front":
            back[:3, 3] -= np.array([a[0], a[1], 0.0]) * 0.12
            self.motion.line(back, steps=3, speed=0.3)
        if self.robot.grip is None:
            self.open_hand()
            self.home()
            return ActionOutcome(True, f"grasp of {name} closed on nothing")
        if (dropped := self._drop_if(sit, 0, f"{name} slipped out of the gripper")) is not None:
            return dropped
        self.carry()
        return ActionOutcome(True)

    def way_out(self, container: str, pts) -> tuple[np.ndarray, float]:
        """The way out of a container's cavity (up for a top-open one, straight out of the front
        face for a front-open one) and how far the deepest of ``pts`` must still go that way to
        be WITHDRAW_MARGIN clear of the rim or the face."""
        f = self.scene.things[container].furniture
        if f.kind.cavity.open == "top":
            d = np.array([0.0, 0.0, 1.0])
            depth = max(f.kind.cavity.z[1] - p[2] for p in pts)
        else:
            d = np.array([f.front[0], f.front[1], 0.0])
            face = f.to_world((0.0, f.kind.size[1] / 2, 0.0))
            depth = max(float((face - p)[:2] @ d[:2]) for p in pts)
        return d, max(0.0, depth + WITHDRAW_MARGIN)

    def reach_pre(self, G: np.ndarray, a: np.ndarray, container: str | None, least: float, pts=()) -> np.ndarray | None:
        """Bring the hand to its pre-pose for going along ``a`` to ``G``: ``least`` back from
        ``G``, and with the fingertips and ``pts`` (a held item's corners when the hand is at
        ``G``) out of the container's cavity, so that the arm's joint-space move there cannot
        sweep through a wall. Out of a deep front-open cavity that is further than the arm
        reaches comfortably: the base steps back first, the arm goes to the pre-pose, and the base
        steps in again (carrying the arm unchanged) — the reverse of :meth:`withdraw`. Returns the
        pre-pose (the hand is there), or None when the arm cannot get there."""
        pre = G.copy()
        pre[:3, 3] -= a * least
        step = np.zeros(3)
        ct = self.scene.things.get(container) if container else None
        if ct is not None and ct.furniture is not None and ct.furniture.kind.cavity is not None:
            d, out = self.way_out(container, [p - a * least for p in (G[:3, 3] + a * FINGERTIP, *pts)])
            if d[2] > 0.5:  # a top-open cavity: the arm lifts the pre-pose
                pre[:3, 3] += d * out
            elif out > 0:
                x, y, yaw = self.robot.target[:3]
                obstacles = self.follower.obstacles()
                if all(self.follower.base_free((x + d[0] * out * s, y + d[1] * out * s, yaw), obstacles, margin=PARKED_MARGIN)
                       for s in np.linspace(0.25, 1.0, 4)):
                    step = d * out
                    self.motion.drive((x + step[0], y + step[1], yaw), 0.5)
                else:  # no room behind: the arm backs off further instead
                    pre[:3, 3] += d * out
        far = pre.copy()
        far[:3, 3] += step
        if not self.goto_pose(far):
            return None
        if step.any():
            x, y, yaw = self.robot.target[:3]
            self.motion.drive((x - step[0], y - step[1], yaw), 0.4)
        return pre

    def withdraw(self, name: str | None, container: str) -> None:
        """Bring a held item (``name``) or the empty hand out of a container's cavity the way it
        went in (:meth:`way_out`): up a top-open one by the arm, out of a front-open one by the base
        stepping back, which carries the arm along unchanged (else by the arm), so that the next
        joint-space move of the arm cannot sweep it through the walls or a door."""
        T = self.motion.pose("tcp")
        if name is not None:
            box = self.truth.aabb(name)
            pts = [np.array([box[i], box[j], box[2]]) for i in (0, 3) for j in (1, 4)]
        else:  # the open fingers: their tips and sides
            pts = [T[:3, 3] + T[:3, 2] * FINGERTIP + T[:3, 1] * s * 0.06 - np.array([0.0, 0.0, 0.02]) for s in (-1, 1)]
        d, out = self.way_out(container, pts)
        if out <= 0:
            return
        if d[2] < 0.5:
            x, y, yaw = self.robot.target[:3]
            obstacles = self.follower.obstacles()
            if all(self.follower.base_free((x + d[0] * out * s, y + d[1] * out * s, yaw), obstacles, margin=PARKED_MARGIN)
                   for s in np.linspace(0.25, 1.0, 4)):
                self.motion.drive((x + d[0] * out, y + d[1] * out, yaw), 0.4)
                return
        T[:3, 3] += d * out
        self.motion.line(T, steps=max(2, int(out / 0.04)), speed=0.3)

    # ================================================================ placing

    def free_spot(self, surface: str, item: str, edge: bool = False) -> np.ndarray:
        """Centre of a free spot on a surface's top (far from other items, near the robot); with
        ``edge``, close to the front edge (where a hand can take it from the side again)."""
        t = self.scene.things[surface]
        others = [self.truth.center(i.name) for i in self.scene.items() if i.name != item and self.truth._on(i.name, surface)]
        if t.room is not None:
            x, y, yaw = self.robot.base_pose
            cands = [np.array([x + 0.75 * math.cos(yaw) + dx * -math.sin(yaw), y + 0.75 * math.sin(yaw) + dx * math.cos(yaw), 0.0])
                     for dx in np.linspace(-0.3, 0.3, 7)]
        else:
            f = t.furniture
            w = f.kind.size[0] / 2 - 0.08
            ly = f.kind.size[1] / 2 - EDGE_SPOT if edge else 0.0
            cands = [f.to_world((lx, ly, f.kind.size[2])) for lx in np.linspace(-w, w, 9)]
        base = np.array(self.robot.base_pose[:2])

        def score(p):
            clear = min([np.linalg.norm(p[:2] - o[:2]) for o in others] + [1.0])
            return min(clear, 0.2) - 0.05 * np.linalg.norm(p[:2] - base)

        return max(cands, key=score)

    def cavity_spot(self, container: str) -> tuple[np.ndarray, np.ndarray]:
        """Centre of a container's cavity floor, and the direction to put things in from."""
        t = self.scene.things[container]
        f = t.furniture
        cav = f.kind.cavity
        depth = 0.03
        if t.hinge is not None and t.hinge.prismatic:  # the middle of the part of the tray that is out
            depth = f.kind.size[1] / 2 - f.kind.door.slide / 2
            depth += pb.getJointState(t.hinge.body, t.hinge.joint, physicsClientId=self.cid)[0]
        p = f.to_world((0.0, depth, cav.z[0]))
        a = -f.front if cav.open == "front" else np.array([0.0, 0.0, -1.0])
        return p, a

    def _drop_if(self, sit: SituationSpec | None, index: int, message: str) -> ActionOutcome | None:
        """Table II's "drops nearby" rows for the argument at ``index``: let go and fold the arm;
        the motion still completed, so the outcome is completed with ``message``."""
        if sit is None or sit.drops != index:
            return None
        self.drop_nearby()
        self.home()
        return ActionOutcome(True, message)

    def place(self, name: str, where: str, inside: bool, sit: SituationSpec | None, edge: bool = False) -> ActionOutcome:
        if self.truth.held() != name:
            return ActionOutcome(False, f"not holding {name}")
        t = self.scene.things[name]
        if (dropped := self._drop_if(sit, 0, f"{name} dropped on the way")) is not None:
            return dropped
        if inside:
            spot, a = self.cavity_spot(where)
        else:
            spot, a = self.free_spot(where, name, edge), np.array([0.0, 0.0, -1.0])
        self.approach(self.work_pose(spot, self.toward_robot(spot, where), _how(a), where))
        box = self.truth.aabb(name)
        c = self.truth.center(name)
        spot = spot.copy()
        spot[2] += (c[2] - box[2]) + 0.015  # its bottom just above the support
        T_tcp = self.robot.link_pose("tcp")
        _, orn = pb.getBasePositionAndOrientation(t.body, physicsClientId=self.cid)
        T_item = np.eye(4)
        T_item[:3, :3] = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
        T_item[:3, 3] = c
        hold = np.linalg.inv(T_tcp) @ T_item
        target_item = T_item.copy()
        target_item[:3, 3] = spot
        G = target_item @ np.linalg.inv(hold)
        corners = [spot + np.array([box[i], box[j], box[k]]) - c for i in (0, 3) for j in (1, 4) for k in (2, 5)]
        self.phase(0.2, "pre-place")
        pre = self.reach_pre(G, a, where if inside else None, 0.16, corners)
        if pre is None:
            self.carry()
            return ActionOutcome(False, f"{where}: no arm pose reaches it")
        self.phase(0.5, "placing")
        self.motion.line(G, steps=4, speed=0.3)
        if sit is not None and sit.kind == "place_fails_object_in_hand":
            self.motion.line(pre, steps=3, speed=0.3)  # the gripper never opened
            self.carry()
            return ActionOutcome(True, f"{name} still in the gripper")
        self.open_hand()
        self.motion.settle(20)
        self.phase(0.8, "retreat")
        # out of the grasp along the hand's axis first (a hand holding from the side would lift
        # the object on its fingers going straight up), then back along the way in
        out = self.motion.pose("tcp")
        out[:3, 3] -= out[:3, 2] * 0.1
        self.motion.line(out, steps=2, speed=0.4)
        if inside:
            self.withdraw(None, where)
        else:
            out[:3, 3] -= a * 0.1
            self.motion.line(out, steps=2, speed=0.4)
        self.home()
        return ActionOutcome(True)

    # ================================================================ doors and lids

    def open_close(self, name: str, opening: bool, sit: SituationSpec | None) -> ActionOutcome:
        """Open or close with a free hand: something held is set down on the nearest surface of
        the room first and picked up again afterwards, the same way it was held (from the side or
        from above: it may have to go into a low cavity next); the domain lets a full hand open
        doors."""
        held = self.truth.held()
        if held is None:
            return self._open_close(name, opening, sit)
        sideways = abs(self.robot.link_pose("tcp")[2, 2]) < 0.8  # level or pitched, not from above
        room = self.truth.room_of_point(self.robot.base_pose[:2])
        x, y, _ = self.robot.base_pose
        shelves = sorted((t for t in self.scene.things.values() if t.furniture is not None and
                          t.pddl_type == "surface" and t.furniture.room == room),
                         key=lambda t: math.hypot(t.furniture.x - x, t.furniture.y - y))
        if not shelves or not self.place(held, shelves[0].name, False, None, edge=sideways).completed:
            return ActionOutcome(False, f"{name}: the hand is full")
        out = self._open_close(name, opening, sit)
        self.grasp(held, None, sideways)
        return out

    def _open_close(self, name: str, opening: bool, sit: SituationSpec | None) -> ActionOutcome:
        t = self.scene.things[name]
        h = t.hinge
        if h is None:
            return ActionOutcome(False, f"{name} has nothing to open")
        start = self.robot.base_pose
        q0 = self.truth.joint_value(name)
        side = 1.0
        goal_open = h.full
        if h.other_side is not None:  # a room door: the face towards the robot, pushed away from it
            p, n, _ = h.handle_at(q0)
            side = 1.0 if (np.array([*start[:2], p[2]]) - p) @ n > 0 else -1.0
            goal_open = abs(h.full) * side
        if opening:
            goal = goal_open * OPEN_TO
        else:
            goal = 0.0 if h.other_side is not None else h.full * CLOSE_TO
        p, n, bar = h.handle_at(q0, side)
        G = _frame(-n, -bar if abs(bar[2]) > 0.5 else bar, p)
        path = self.follower.plan(h, side, q0, goal, G, start, LOOSE_GRIP, APPROACH)
        if not path.waypoints:
            return ActionOutcome(False, f"{name}: handle out of reach")
        grasp = path.waypoints[0]
        self.phase(0.05, "approaching the handle")
        self.approach(tuple(grasp.q[:3]))
        self.phase(0.1, "reaching for the handle")
        self.motion.fingers(LOOSE_GRIP)  # wide enough round the bar, narrow enough beside the leaf
        if not self.motion.through([path.pre.q], 0.8):
            self.home()
            return ActionOutcome(False, f"{name}: handle out of reach")
        self.motion.line(grasp.T, steps=4, speed=0.3, allow_base=False)
        self.motion.through([grasp.q], 0.3)
        touching = self.motion.fingers(0.0, h.body, h.joint, force=80.0)
        if touching == 0 or (sit is not None and not sit.effect):
            # the hand slips off the handle: the arm lets go and backs off, the joint stays
            self._retreat(name, start)
            return ActionOutcome(True, f"{name}: the handle slipped")
        # a ball joint at the tcp, the fingers loosely round the bar: the bar may turn in the hand
        self.robot.attach(h.body, name, h.joint, point=True)
        self.motion.fingers(LOOSE_GRIP)  # the bar may now turn in the hand
        self.phase(0.3, "moving the handle")

        def on_sample(s: float) -> None:
            self.phase(0.3 + 0.5 * s, "moving the handle")

        self.motion.on_sample = on_sample
        try:
            self.motion.through([w.q for w in path.waypoints[1:]], FOLLOW_SPEED)
        finally:
            self.motion.on_sample = None
        self.phase(0.85, "letting go")
        self._retreat(name, start)
        if not path.complete:
            return ActionOutcome(True, f"{name}: the arm could not follow the handle all the way")
        return ActionOutcome(True)

    def _retreat(self, name: str, start) -> None:
        """Let go of a leaf without dragging it: the loose fingers back off the bar along the hand's
        axis and away from the leaf's face, the base steps back, the arm folds (through a point
        above the base if folding straight would sweep through the leaf), and the base returns to
        where the action began if that way is clear of the leaf for the folded arm too."""
        h = self.scene.things[name].hinge
        q = self.truth.joint_value(name)
        leaf, plate = Obb(*h.leaf(q)), Obb(*h.plate(q))
        self.robot.detach()
        self.motion.fingers(LOOSE_GRIP)
        off = self.motion.pose("tcp")
        off[:3, 3] -= off[:3, 2] * 0.12
        self.motion.line(off, steps=3, speed=0.3, allow_base=False)
        n = h.handle_at(q, 1.0)[1]
        n = n if (self.motion.pose("tcp")[:3, 3] - plate.center) @ n > 0 else -n
        away = self.motion.pose("tcp")
        away[:3, 3] += n * 0.1
        self.motion.line(away, steps=2, speed=0.3, allow_base=False)
        static = self.follower.obstacles(h)
        here = np.array(self.robot.base_pose)
        back = here - 0.25 * np.array([math.cos(here[2]), math.sin(here[2]), 0.0])
        if self.follower.base_free(back, static, leaf, margin=PARKED_MARGIN):
            self.motion.drive(tuple(back), 0.5)
        home = self.robot.target.copy()
        home[3:] = self.robot.cfg.arm.home
        now = self.robot.target.copy()
        self.follower.use_panel(h, LOOSE_GRIP)
        if not all(self.follower.arm_clear(now + (home - now) * s, plate) for s in np.linspace(0, 1, 12)):
            inner = self.motion.pose("tcp")
            inner[:3, 3] = self.in_base((0.45, 0.0, 1.1))
            self.motion.line(inner, steps=4, speed=0.4, allow_base=False)
        self.home()
        self.motion.fingers(self.robot.cfg.gripper.stroke)
        here = np.array(self.robot.base_pose)
        goal = np.array(start)
        goal[2] = here[2] + math.remainder(goal[2] - here[2], 2 * math.pi)
        backward = -np.array([math.cos(here[2]), math.sin(here[2]), 0.0])
        for via in ([], [here + backward * 0.3], [here + backward * 0.6]):
            legs = [here, *via, goal]
            if all(self.follower.base_free(a + (b - a) * s, static, leaf, folded=True, margin=PARKED_MARGIN)
                   for a, b in zip(legs, legs[1:]) for s in np.linspace(0.05, 1, 12)):
                for p in legs[1:]:
                    self.motion.drive(tuple(p), 0.5)
                break
        self.look_at(self.target_point(name))

    # ================================================================ the rest

    def press(self, appliance: str, sit: SituationSpec | None) -> ActionOutcome:
        t = self.scene.things[appliance]
        if t.light_link is None:
            return ActionOutcome(False, f"{appliance} has no switch")
        lp = np.array(pb.getLinkState(t.body, t.light_link, physicsClientId=self.cid)[4])
        n = t.furniture.front
        self.approach(self.work_pose(lp, n, "front", appliance))
        G = _frame(-n, (0, 0, -1), lp + n * 0.012)
        pre = G.copy()
        pre[:3, 3] += n * 0.12
        self.motion.fingers(0.0)
        if not self.goto_pose(pre):
            self.home()
            return ActionOutcome(False, f"{appliance}: switch out of reach")
        miss = sit is not None and not sit.effect
        touch = G.copy()
        if miss:
            touch[:3, 3] += n * 0.06  # the press stops short of the switch
        self.motion.line(touch, steps=3, speed=0.3)
        if not miss:
            self._turn_on(t)
        self.motion.line(pre, steps=2, speed=0.4)
        self.motion.fingers(self.robot.cfg.gripper.stroke)
        self.home()
        self.look_at(self.target_point(appliance))
        return ActionOutcome(True)

    def _turn_on(self, t: Thing) -> None:
        turn_on(self.cid, t)
        for it in self.scene.items():
            if self.truth._inside(it.name, t.name):
                it.states["heated"] = True
                self.recolor(it)

    def recolor(self, it: Thing) -> None:
        """Show an item's state: water colour when filled, a warm tint when heated."""
        show_state(self.cid, self.catalog, it)

    def fill(self, name: str, sink: str, sit: SituationSpec | None) -> ActionOutcome:
        if self.truth.held() != name:
            return ActionOutcome(False, f"not holding {name}")
        t = self.scene.things[name]
        if (dropped := self._drop_if(sit, 0, f"{name} slipped out")) is not None:
            return dropped
        f = self.scene.things[sink].furniture
        tap = f.to_world((0.0, -f.kind.size[1] / 2 + 0.2, f.kind.size[2] + 0.08))
        self.approach(self.work_pose(tap, f.front, "top", sink))
        T = self.motion.pose("tcp")
        T[:3, 3] += tap - self.truth.center(name)
        self.phase(0.3, "under the tap")
        if not self.goto_pose(T):
            self.carry()
            return ActionOutcome(False, f"{sink}: tap out of reach")
        self.motion.settle(40)  # the water runs
        t.states["filled"] = 0.5 if (sit is not None and not sit.effect) else 1.0
        t.states["heated"] = False  # fresh water is cold
        self.recolor(t)
        self.carry()
        return ActionOutcome(True)

    def cut(self, name: str, knife: str, sit: SituationSpec | None) -> ActionOutcome:
        if self.truth.held() != knife:
            return ActionOutcome(False, f"not holding {knife}")
        if (dropped := self._drop_if(sit, 1, f"{knife} slipped out")) is not None:
            return dropped
        t = self.scene.things[name]
        c = self.truth.center(name)
        support = self.truth.support_of(name)
        self.approach(self.work_pose(c, self.toward_robot(c, support), "top", support))
        top = self.truth.aabb(name)[5]
        # the blade's lowest point, from the tcp: however the hand holds the knife, that point
        # goes over the object's centre and down through it
        kt = self.scene.things[knife]
        pos, orn = pb.getBasePositionAndOrientation(kt.body, physicsClientId=self.cid)
        R = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
        signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
        corners = np.asarray(pos) + (signs * np.asarray(kt.kind.extent) / 2) @ R.T
        edge = corners[np.argmin(corners[:, 2])] - self.robot.link_pose("tcp")[:3, 3]
        below = -edge[2]
        T = self.motion.pose("tcp")
        T[:3, 3] = (c[0] - edge[0], c[1] - edge[1], top + below + 0.06)
        if not self.goto_pose(T):
            self.carry()
            return ActionOutcome(False, f"{name}: out of reach")
        stroke = T.copy()
        short = sit is not None and not sit.effect
        stroke[2, 3] = (top + below + 0.03) if short else (c[2] + below)
        kb = self.scene.things[knife].body
        for k in range(1, 7):
            step = T.copy()
            step[2, 3] = T[2, 3] + (stroke[2, 3] - T[2, 3]) * k / 6
            self.goto_pose(step, 0.2, allow_base=False)
            if not t.states["sliced"] and any(pb.getClosestPoints(kb, b, 0.004, physicsClientId=self.cid) for b in t.bodies):
                self.split(t, T[:3, 1])
        self.goto_pose(T, 0.4, allow_base=False)
        self.carry()
        return ActionOutcome(True)

    def split(self, t: Thing, normal: np.ndarray) -> None:
        """The object falls apart into two halves on either side of the blade."""
        split(self.cid, self.catalog, t, self.truth.center(t.name), normal)

    def push(self, blocker: str, target: str, sit: SituationSpec | None) -> ActionOutcome:
        support = self.truth.support_of(blocker)
        if support is None:
            return ActionOutcome(False, f"{blocker} is not on a surface")
        front, side = self.truth._front_axes(support)
        b = self.truth.center(blocker)
        o = self.truth.center(target)
        self.approach(self.work_pose(b, front, "top", support))
        direction = side if (b - o)[:2] @ side[:2] >= 0 else -side  # away from what it blocks
        r = max(self.scene.things[blocker].kind.extent[:2]) / 2
        box = self.truth.aabb(blocker)
        z = box[2] + 0.6 * (box[5] - box[2])
        start = b - direction * (r + 0.05)
        start[2] = z + 0.1
        G = _frame((0, 0, -1), direction, start)
        self.motion.fingers(0.0)
        if not self.goto_pose(G):
            self.home()
            return ActionOutcome(False, f"{blocker}: out of reach")
        down = G.copy()
        down[2, 3] = z
        self.motion.line(down, steps=3, speed=0.3)
        along = down.copy()
        along[:3, 3] += direction * 0.22
        self.motion.line(along, steps=5, speed=0.2)
        up = along.copy()
        up[2, 3] += 0.12
        self.motion.line(up, steps=2, speed=0.4)
        self.motion.fingers(self.robot.cfg.gripper.stroke)
        self.home()
        self.look_at(self.target_point(target))
        return ActionOutcome(True)
