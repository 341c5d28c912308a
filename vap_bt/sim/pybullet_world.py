"""The pybullet household: the World contract over a physical simulation.

``PybulletWorld(task)`` arranges the task's Layout (:mod:`pb_layout`), builds it from the
catalogue (:mod:`pb_scene`), loads the robot (:mod:`pb_robot`) and then only ever changes the
scene by running physics: primitives (:mod:`pb_primitives`) command joint trajectories, steps
run, the truth (:mod:`pb_truth`) is read off the result, the wrist camera (:mod:`pb_camera`)
renders it. Situation injection draws once per action from :class:`SituationModel` (Table II)
and changes the motion so that the situation physically happens; scripted disturbances (a person
moves an object, a door left half open) apply before the action they name.

Disturbances are dicts: ``{"at": 2, "move": "cup", "to": "counter"}`` (before the third action,
the cup is put on the counter) or ``{"at": 0, "door": "door_lk", "open": 0.4}`` (the door swung
to 40 % of its travel). The simulation steps at ``DT`` with few solver iterations: episodes are
meant to be fast, not precise.
"""

from __future__ import annotations

import dataclasses
import math
import threading

import numpy as np
import pybullet as pb

from vap_bt.domain.atoms import Atom
from vap_bt.scene.layout import layout_facts
from vap_bt.sim.pb_camera import FILL, Render, look_pose, name_image, pixel_counts, render, visibility
from vap_bt.sim.pb_catalog import load_catalog
from vap_bt.sim.pb_layout import plan_scene
from vap_bt.sim.pb_motion import Cancelled, Motion
from vap_bt.sim.pb_primitives import Primitives
from vap_bt.sim.pb_robot import Robot
from vap_bt.sim.pb_scene import build_scene
from vap_bt.sim.pb_truth import Truth
from vap_bt.sim.situations import SituationModel
from vap_bt.world import (VIEW_DIRECTIONS, ActionOutcome, GoalContext, InjectedSituation, ObjectInfo, Observation,
                          SceneSnapshot)

DT = 1.0 / 60.0
SOLVER_ITERATIONS = 20
LOCATIONS = ("on", "inside", "in_room", "holding")


class _NoContext:
    def feedback(self, progress: float, text: str = "") -> None: ...

    def cancelled(self) -> bool:
        return False


class PybulletWorld:
    name = "pybullet"

    def __init__(self, task, seed: int = 0, gui: bool = False, injection: bool = True,
                 situations: SituationModel | None = None, disturbances: list[dict] | None = None,
                 image_size: tuple[int, int] = (320, 240)) -> None:
        self.task = task
        self.layout = task.spec.scene
        if self.layout is None:
            raise ValueError("the pybullet world needs a task with a scene: layout")
        self.catalog = load_catalog()
        self.gui = gui
        self.situations = situations or SituationModel(enabled=injection, seed=seed)
        self.disturbances = list(disturbances or [])
        self.camera = _camera(image_size)
        self._lock = threading.RLock()
        self.cid = -1
        self.reset(seed)

    # ------------------------------------------------------------ life cycle

    def reset(self, seed: int) -> None:
        with self._lock:
            if self.cid >= 0:
                pb.disconnect(self.cid)
            self.seed = seed
            self.situations.reseed(seed)
            self.cid = pb.connect(pb.GUI if self.gui else pb.DIRECT)
            pb.setGravity(0, 0, -9.81, physicsClientId=self.cid)
            pb.setPhysicsEngineParameter(fixedTimeStep=DT, numSolverIterations=SOLVER_ITERATIONS, numSubSteps=1,
                                         physicsClientId=self.cid)
            self.types = self.layout.objects()
            self.plan = plan_scene(self.layout, self.catalog, seed)
            self.scene = build_scene(self.cid, self.plan, self.catalog, self.types)
            self.robot = Robot(self.cid)
            q0 = np.array([*self.plan.robot, *self.robot.cfg.arm.home])
            self.robot.reset(q0)
            rigid = {a for a in layout_facts(self.layout) if a.predicate in ("clear", "openable", "fillable", "connects")}
            self.truth = Truth(self.scene, self.robot, self.catalog, rigid, self._visible_names)
            self.motion = Motion(self.robot, self._tick, DT)
            self.ctx: GoalContext = _NoContext()
            self._progress = (0.0, 1.0)
            self.prims = Primitives(self.scene, self.robot, self.motion, self.truth, self.catalog, self._phase)
            self.ticks = 0
            self.actions = 0
            self._injected: list[InjectedSituation] = []
            self._view: Render | None = None
            self._view_tick = -1
            self.view_index = 0
            for name, it in self.layout.items.items():
                if it.held:
                    self._start_held(name)
            for _ in range(30):  # let everything settle onto its support
                self._tick()
            self.prims.look_at(self.prims.target_point(self.layout.robot.at or f"floor_{self.layout.robot.room}"))

    def _start_held(self, name: str) -> None:
        t = self.scene.things[name]
        T = self.motion.pose("tcp")
        pb.resetBasePositionAndOrientation(t.body, tuple(T[:3, 3] - T[:3, 2] * 0.0), (0, 0, 0, 1),
                                           physicsClientId=self.cid)
        self.robot.attach(t.body, name)
        self.robot.command_fingers(0.0, 40.0)

    def close(self) -> None:
        with self._lock:
            if self.cid >= 0:
                pb.disconnect(self.cid)
                self.cid = -1

    # ------------------------------------------------------------ stepping

    def _tick(self) -> None:
        if self.ctx.cancelled():
            raise Cancelled()
        pb.stepSimulation(physicsClientId=self.cid)
        self.scene.hold_limits()
        self.ticks += 1

    def _phase(self, progress: float, text: str) -> None:
        lo, span = self._progress
        self.ctx.feedback(min(1.0, lo + span * progress), text)

    # ------------------------------------------------------------ actions

    def perform(self, action: str, args: tuple[str, ...], ctx: GoalContext) -> ActionOutcome:
        with self._lock:
            self.ctx = ctx
            step = self.actions
            self.actions += 1
            self._disturb(step, action, args)
            spec = self.situations.draw(action) if action in {s.action for s in self.situations.table} else None
            if spec is not None:
                self._injected.append(InjectedSituation(action, tuple(args), spec.kind, step))
            try:
                return self._run(action, tuple(args), spec)
            except Cancelled:
                return ActionOutcome(False, f"{action} cancelled")
            finally:
                self.ctx = _NoContext()
                self._view = None

    def _run(self, action: str, a: tuple[str, ...], spec) -> ActionOutcome:
        p = self.prims
        if action == "find":
            return p.find(a[1], spec)
        if action == "navigate":
            return p.navigate(a[1], a[2], spec)
        if action in ("grasp", "takeout"):
            return p.grasp(a[0], spec)
        if action in ("placeon", "placein"):
            return p.place(a[0], a[1], action == "placein", spec)
        if action in ("open", "close"):
            return p.open_close(a[0], action == "open", spec)
        if action == "turnon":
            return p.press(a[0], spec)
        if action == "cut":
            return p.cut(a[0], a[1], spec)
        if action == "fill":
            return p.fill(a[0], a[1], spec)
        if action == "push":
            return p.push(a[0], a[1], spec)
        return ActionOutcome(False, f"unknown action {action!r}")

    def _disturb(self, step: int, action: str, args) -> None:
        for d in self.disturbances:
            if d.get("at") != step:
                continue
            if "move" in d:
                name, to = d["move"], d["to"]
                if self.truth.held() == name:
                    continue
                spot = self.prims.free_spot(to, name)
                t = self.scene.things[name]
                box = self.truth.aabb(name)
                c = self.truth.center(name)
                spot[2] += (c[2] - box[2]) + 0.01
                # a person's hand is not simulated: the object is set down at its new place
                pb.resetBasePositionAndOrientation(t.body, tuple(spot), pb.getBasePositionAndOrientation(
                    t.body, physicsClientId=self.cid)[1], physicsClientId=self.cid)
                kind = "object_moved_by_person"
            elif "door" in d:
                h = self.scene.things[d["door"]].hinge
                pb.resetJointState(h.body, h.joint, h.full * float(d.get("open", 0.4)), physicsClientId=self.cid)
                kind = "door_left_half_open"
            else:
                continue
            for _ in range(20):
                self._tick()
            self._injected.append(InjectedSituation(action, tuple(args), kind, step))

    def injected(self) -> list[InjectedSituation]:
        return list(self._injected)

    # ------------------------------------------------------------ truth

    def holds(self, atom: Atom) -> bool:
        with self._lock:
            return self.truth.holds(atom)

    def wrist_view(self) -> Render:
        """The wrist camera's current image (cached until the simulation steps)."""
        if self._view is None or self._view_tick != self.ticks:
            pose = self.robot.link_pose("camera_optical")
            self._view = render(self.cid, pose, self.camera)
            self._view_tick = self.ticks
        return self._view

    def _visible_names(self) -> set[str]:
        r = self.wrist_view()
        counts = pixel_counts(r, self.scene.by_body())
        return {n for n, c in counts.items() if c >= r.pixel_threshold()}

    def atoms(self) -> list[Atom]:
        """Every atom of the household predicates over this scene's objects (typed)."""
        by: dict[str, list[str]] = {}
        for n, t in self.types.items():
            by.setdefault(t, []).append(n)
        items = by.get("item", []) + by.get("knife", [])
        things = [n for n, t in self.types.items() if t != "room"]
        surfaces = by.get("surface", [])
        containers = by.get("container", []) + by.get("appliance", [])
        rooms = by.get("room", [])
        out = [Atom("hand_empty")]
        out += [Atom("robot_in", (r,)) for r in rooms]
        out += [Atom("in_room", (x, r)) for x in things for r in rooms]
        out += [Atom(p, (x,)) for p in ("robot_at", "inview", "open", "closed") for x in things]
        out += [Atom("on", (o, s)) for o in items for s in surfaces]
        out += [Atom("inside", (o, c)) for o in items for c in containers]
        out += [Atom(p, (o,)) for p in ("holding", "reachable", "filled", "sliced", "heated") for o in items]
        out += [Atom("blocking", (b, o)) for b in items for o in items if b != o]
        out += [Atom("turned_on", (a,)) for a in by.get("appliance", [])]
        return out

    def survey(self) -> SceneSnapshot:
        with self._lock:
            objects = []
            for n, t in self.scene.things.items():
                if self.types.get(n) == "room":
                    continue
                box = self.truth.aabb(n)
                c = self.truth.center(n)
                label = t.kind.name if t.kind is not None else self.types.get(n, "thing")
                room = self.truth.room_of_point(c) if t.item is not None else (
                    t.furniture.room if t.furniture else (t.room or (t.door.low if t.door else None)))
                objects.append(ObjectInfo(n, label, room, tuple(map(float, c)), tuple(map(float, box))))
            facts = {a for a in self.atoms() if self.truth.holds(a)}
            facts |= self.truth.rigid
            return SceneSnapshot(objects, facts)

    # ------------------------------------------------------------ camera

    def observe(self, targets: tuple[str, ...]) -> Observation:
        with self._lock:
            known = [t for t in targets if t in self.scene.things and self.truth.held() != t]
            if known:
                point = np.mean([self.prims.target_point(t) for t in known], axis=0)
                if not self.prims.aimed_at(point):
                    self.prims.look_at(point)
            r = self.wrist_view()
            names = self.scene.by_body()
            ids = {n: i for i, n in enumerate(sorted(self.scene.things))}
            counts = pixel_counts(r, names)
            boxes = {n: self.truth.aabb(n) for n in counts if n in self.scene.things}
            fills = {n: self._fill(n) for n in boxes}
            vis = visibility(r, counts, boxes, fills)
            for t in targets:
                vis.setdefault(t, 0.0)
            rel = set()
            for n in counts:
                if counts[n] >= r.pixel_threshold():
                    rel |= {a for a in self.atoms() if a.predicate in LOCATIONS and n in a.args[:1] and self.truth.holds(a)}
            self.view_index += 1
            return Observation(
                view_index=self.view_index, targets=tuple(targets), visibility=vis, rgb=r.rgb, depth=r.depth,
                segmentation=name_image(r, names, ids), segment_names={i: n for n, i in ids.items()},
                relations=frozenset(rel), intrinsics=r.intrinsics, camera_pose=r.pose7, stamp=self.ticks * DT)

    def _fill(self, name: str) -> float:
        t = self.scene.things[name]
        if t.item is not None:
            return FILL.get(t.kind.shape, 0.8)
        return FILL["door"] if t.door is not None else FILL["furniture"]

    def move_view(self, target: str, direction: str) -> bool:
        if direction not in VIEW_DIRECTIONS or target not in self.scene.things:
            return False
        with self._lock:
            p = self.prims.target_point(target)
            x, y, yaw = self.robot.base_pose
            lift = 0.0
            if direction in ("left", "right"):
                ang = 0.5 if direction == "left" else -0.5
                dx, dy = x - p[0], y - p[1]
                c, s = math.cos(ang), math.sin(ang)
                nx, ny = p[0] + c * dx - s * dy, p[1] + s * dx + c * dy
            elif direction == "closer":
                v = np.array([p[0] - x, p[1] - y])
                step = min(0.25, max(0.0, np.linalg.norm(v) - 0.75))
                if step <= 0.02:
                    return False
                nx, ny = np.array([x, y]) + v / np.linalg.norm(v) * step
            elif direction == "front":
                nx, ny, _ = self.prims.standoff(target)
            elif direction == "behind":
                nx, ny = 2 * p[0] - x, 2 * p[1] - y
            else:  # above
                nx, ny, lift = x, y, 0.3
            nyaw = math.atan2(p[1] - ny, p[0] - nx) if direction != "above" else yaw
            moves = (nx, ny) != (x, y)
            # a view from where the base stands needs no room; one from elsewhere must be in this
            # room (a base move for a view never goes through a wall or a doorway)
            if moves and not self._base_fits(nx, ny, self.truth.room_of_point((x, y))):
                return False
            try:
                if moves:
                    self.prims.approach((nx, ny, nyaw))  # round open leaves, like any base move
                # from above: as high over the base as the arm reaches (close in, the highest eye
                # may need the wrist bent further than it goes)
                lifts = (lift, 2 * lift / 3, lift / 3) if lift > 0 else (0.0,)
                return any(self.prims.look_at(p, lift=h, allow_base=False) for h in lifts)
            except Cancelled:
                return False
            finally:
                self._view = None

    def _base_fits(self, x: float, y: float, room: str | None = None) -> bool:
        """The base footprint (as a circle) stays inside a room (``room`` if given) and off the
        furniture."""
        r = 0.42
        here = self.truth.room_of_point((x, y))
        if here is None or (room is not None and here != room):
            return False
        room = here
        rp = self.plan.rooms[room]
        if not (rp.x0 + r <= x <= rp.x1 - r and rp.y0 + r <= y <= rp.y1 - r):
            return False
        for t in self.scene.things.values():
            if t.furniture is None:
                continue
            a = self.truth.aabb(t.name)
            if a[0] - r < x < a[3] + r and a[1] - r < y < a[4] + r:
                return False
        return True

    # ------------------------------------------------------------ pictures

    def overview(self, width: int = 480, height: int = 360) -> np.ndarray:
        """A bird's-eye picture of the whole house (for people, not for perception)."""
        xs = [r.x0 for r in self.plan.rooms.values()] + [r.x1 for r in self.plan.rooms.values()]
        cx, cy = (min(xs) + max(xs)) / 2, self.plan.depth / 2
        span = max(max(xs) - min(xs), self.plan.depth)
        eye = np.array([cx, cy - 0.75 * span, 0.95 * span])
        cam = dataclasses.replace(_camera((width, height)), far=4 * span)
        return render(self.cid, look_pose(eye, (cx, cy + 0.4, 0.0)), cam, shadows=False).rgb


def _camera(size: tuple[int, int]):
    import robots

    cam = robots.load_config().camera.at(*size)
    return cam
