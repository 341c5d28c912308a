"""The pybullet household: the World contract over a physical simulation.

``PybulletWorld(task)`` arranges the task's Layout (:mod:`pb_layout`), builds it from the
catalogue (:mod:`pb_scene`), loads the robot (:mod:`pb_robot`) and then only ever changes the
scene by running physics: whoever moves the robot commands joint trajectories, steps run
(:meth:`PybulletWorld.step`), the physics rules (:mod:`pb_rules`: filling, switching on, heating,
cutting) turn contacts and poses into object states, and the truth (:mod:`pb_truth`) is read off
the result — through :attr:`oracle`, for the report and the simulated VLM only.

The world decides nothing about how the robot moves. Skills (in other processes even) move it
through its drivers, :attr:`drivers` (:mod:`pb_drivers`: arm, gripper, base, wrist camera), and
tell the world which action a goal is with the sim-only hooks :meth:`begin_action` /
:meth:`end_action`; Table II injection then draws once per action and makes the situation
physically so at the drivers (:mod:`pb_injection`). Scripted disturbances (a person moves an
object, a door left half open) apply before the action they name.

Its robot interfaces are what a real robot's drivers would give: the wrist camera
(:mod:`pb_camera`) renders RGB-D from wherever the arm and the base have put it, and the
segmentation is what an instance detector errs on (:class:`~vap_bt.sim.detector.DetectorModel`:
class labels only, misses that grow as things shrink and hide, false positives, confused labels,
rough masks; which instance produced each detection stays in the capture record); aiming it is
the skills' camera service's (:class:`skills.views.ViewService`), not the world's; the robot starts with its arm at
:data:`START_ARM`, looking ahead; the body reports the base pose, the room localization puts
it in, the arm's joints, the TCP pose and whether the gripper holds something; the site map
has the rooms' outlines, the doors and the furniture's footprints, nothing that moves.

Disturbances are dicts: ``{"at": 2, "move": "cup", "to": "counter"}`` (as the third action
starts, the cup is put on the counter), ``{"after": 0, ...}`` (once the first action is done,
before anything is checked for the next), or ``{"at": 0, "door": "door_lk", "open": 0.4}`` (the
door swung to 40 % of its travel). The simulation steps at ``DT`` with few solver iterations: episodes are
meant to be fast, not precise. A base drive's step in free space, while nothing else moves, is
taken without the physics (:meth:`PybulletWorld.glide`, :mod:`pb_glide`): the base is set on its
profile and the time, the rules and the injection advance as in a step. The world's mechanics
have a version, :data:`WORLD_VERSION`, in every report and campaign row.
"""

from __future__ import annotations

import dataclasses
import math
import threading

import numpy as np

from vap_bt.domain.atoms import Atom
from vap_bt.robot.camera import Aim
from vap_bt.robot.frame import Frame
from vap_bt.robot.labels import DOOR, class_of
from vap_bt.robot.site_map import Articulation, Cavity, DoorInfo, FurnitureInfo, RoomInfo, SiteMap
from vap_bt.robot.state import RobotState, quat_xyzw
from vap_bt.scene.layout import floor_of, layout_facts
from vap_bt.perception.backends.image import rgb_sha1
from vap_bt.sim.captures import CaptureLog, CaptureRecord
from vap_bt.sim.depth_noise import DepthNoiseModel
from vap_bt.sim.detector import DetectorModel
from vap_bt.sim.disturbances import HALF_OPEN, HALF_SHUT, MOVED, SHUT, DisturbanceModel
from vap_bt.sim.localization import Localization, LocalizationModel
from vap_bt.sim.natural_failures import NaturalFailures
from vap_bt.sim.oracle import FunctionOracle
from vap_bt.sim.pb import pb
from vap_bt.motion.se3 import look_pose
from vap_bt.sim.pb_camera import FILL, Render, doorway_pixels, mask_extents, name_image, pixel_counts, render, visibility
from vap_bt.sim.pb_catalog import load_catalog
from vap_bt.sim.pb_drivers import Drivers
from vap_bt.sim.pb_glide import Glide
from vap_bt.sim.pb_injection import Injection
from vap_bt.sim.pb_layout import plan_scene
from vap_bt.sim.pb_robot import Robot
from vap_bt.sim.pb_rules import Rules
from vap_bt.sim.pb_scene import Hinge, build_scene, switch_face, tap_outlet
from vap_bt.sim.pb_truth import Truth
from vap_bt.sim.pb_views import object_views
from vap_bt.sim.observability import PLAIN_SHARE
from vap_bt.sim.situations import SituationModel
from vap_bt.world import InjectedSituation

#: the world's version, in every report (``world.physics``) and campaign row (``world_version``):
#: a change of its mechanics is a new version, and every figure is measured again.
#: pb-3: a Table II row is in the world's record when the world acts on it, not when it is drawn
#: (:mod:`pb_injection`); pb-2: the base glides through free space (:mod:`pb_glide`); pb-1 drove
#: every step by motors
WORLD_VERSION = "pb-3 (2026-12-06)"
DT = 1.0 / 60.0
SOLVER_ITERATIONS = 20
#: physics sub-steps per step: an item let go at carrying height meets the floor at 4 m/s, 7 cm in
#: one 60 Hz step — more than a lying bottle's radius. Sunk that deep, the contact pushes it out
#: sideways, every step: it rolls off across the room, gaining speed, and bounces from wall to
#: wall. At 120 Hz it lands and lies where it fell
SUBSTEPS = 2
#: physics sub-steps per step while a loose item (one the hand does not hold) moves faster than
#: LOOSE_SPEED m/s: at 120 Hz a lying cylinder of the catalog (a stick, r 0.014 m; a log, r
#: 0.032 m) gains energy as it rolls. Dropped from 0.3-1.2 m at 0.1-0.5 m/s it ran away across
#: the room in 47-55 of 90 drops, and put down rolling at 0.05-0.6 m/s in 15 of 30
#: (gather_kindling seed 9 with injection: a stick let go at x 2.3 m rolled, speeding up from 0.25
#: to 0.39 m/s, into the wall at x 0.07 m); at 180 Hz 8-16 of 90 drops ran away, at 240 Hz none:
#: rolling friction stops it within 0.2 m. The energy is the integrator's, not physics'. Only a
#: loose item in motion needs the finer step; the arm, the base and what rests keep the usual
#: one (a step costs 0.23 ms at 240 Hz, 0.13 ms at 120 Hz)
LOOSE_SUBSTEPS = 4
LOOSE_SPEED = 0.05
#: the arm's joints as an episode begins: the wrist camera over the front of the base, looking at
#: the floor 1.5 m ahead (where a look from the home pose leaves it). An initial condition, like
#: the base's start pose; the world never moves the arm itself
START_ARM = (-0.871783, -2.423916, 1.924805, -1.563887, -1.058653, 0.830359)

class PybulletWorld:
    """The pybullet household: physics, Table II injection, disturbances, the oracle, and the
    robot interfaces of a mobile UR5e with a wrist RGB-D camera."""

    name = "pybullet"
    dt = DT

    def __init__(self, task, seed: int = 0, gui: bool = False, injection: bool = True,
                 situations: SituationModel | None = None, disturbances: list[dict] | None = None,
                 image_size: tuple[int, int] = (320, 240), detector: DetectorModel | None = None,
                 depth_noise: DepthNoiseModel | None = None, localization: LocalizationModel | None = None,
                 disturbance_model: DisturbanceModel | None = None) -> None:
        self.task = task
        self.layout = task.spec.scene
        if self.layout is None:
            raise ValueError("the pybullet world needs a task with a scene: layout")
        self.catalog = load_catalog()
        self.gui = gui
        self.situations = situations or SituationModel(enabled=injection, seed=seed)
        self.disturbances = list(disturbances or [])
        #: draws each episode's disturbances on reset (:mod:`vap_bt.sim.disturbances`), replacing the script
        self.disturbance_model = disturbance_model
        self.camera = _camera(image_size)
        self.detector = detector or DetectorModel()
        #: what the wrist depth camera returns (:mod:`depth_noise`) and how well the base knows
        #: where it is (:mod:`localization`): sensors of a real robot's kind, not perfect ones
        self.depth_noise = depth_noise or DepthNoiseModel()
        self.localization_model = localization or LocalizationModel()
        self.captures = CaptureLog()
        self.oracle = FunctionOracle(self._holds, self.injected, self._position)
        self._lock = threading.RLock()
        self.cid = -1
        self.reset(seed)
        #: the robot's drivers, for skills that move it themselves (valid across resets)
        self.drivers = Drivers.of(self)

    @property
    def lock(self) -> threading.RLock:
        """Held by every call that reads or steps the simulation."""
        return self._lock

    # ------------------------------------------------------------ life cycle

    def reset(self, seed: int) -> None:
        """Build the household afresh for ``seed`` (a new physics client): the scene plan, the robot at
        its start, localization, truth, rules, injection and disturbances, every draw from ``seed``."""
        with self._lock:
            if self.cid >= 0:
                pb.disconnect(self.cid)
            self.seed = seed
            self.situations.reseed(seed)
            if self.disturbance_model is not None:
                self.disturbances = [d.script() for d in self.disturbance_model.draw(self.task.planning, seed)]
            self.cid = pb.connect(pb.GUI if self.gui else pb.DIRECT)
            pb.setGravity(0, 0, -9.81, physicsClientId=self.cid)
            pb.setPhysicsEngineParameter(fixedTimeStep=DT, numSolverIterations=SOLVER_ITERATIONS, numSubSteps=SUBSTEPS,
                                         physicsClientId=self.cid)
            self._substeps = SUBSTEPS
            self.types = self.layout.objects()
            self.plan = plan_scene(self.layout, self.catalog, seed)
            self.scene = build_scene(self.cid, self.plan, self.catalog, self.types)
            self.robot = Robot(self.cid)
            q0 = np.array([*self.plan.robot, *START_ARM])
            self.robot.reset(q0)
            self.localization = Localization(self.localization_model, seed)
            self.localization.reset(self.robot.base_pose)
            rigid = {a for a in layout_facts(self.layout) if a.predicate in ("clear", "openable", "fillable", "connects")}
            self.truth = Truth(self.scene, self.robot, self.catalog, rigid, self._visible_names)
            self._injected: list[InjectedSituation] = []
            self.injection = Injection(self.situations, self.scene, self.robot, self._injected,
                                       lost_grip=lambda: self.drivers.gripper.lost_grip())
            # the robot's actions that fail by physics alone, with nothing drawn, go in the same log
            self.natural = NaturalFailures(self.truth.holds, self.truth.held, self.task.planning.knowledge.ground)
            self.rules = Rules(self.scene, self.robot, self.truth, self.catalog, self.injection, DT)
            self._glide = Glide(self.robot, self.scene, DT)
            self._action: tuple[int, str, tuple[str, ...]] | None = None  # the action running now
            self.ticks = 0
            self.actions = 0
            self._view: Render | None = None
            self._view_tick = -1
            self.view_index = 0
            self.captures.clear()
            self._map = self._site_map()
            for name, it in self.layout.items.items():
                if it.held:
                    self._start_held(name)
            for _ in range(30):  # let everything settle onto its support
                self.step()

    def _start_held(self, name: str) -> None:
        t = self.scene.things[name]
        T = self.robot.link_pose("tcp")
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

    def step(self) -> None:
        """One physics step; then door stops, the physics rules and Table II's effects."""
        with self._lock:
            substeps = LOOSE_SUBSTEPS if self._loose_moving() else SUBSTEPS
            if substeps != self._substeps:
                pb.setPhysicsEngineParameter(numSubSteps=substeps, physicsClientId=self.cid)
                self._substeps = substeps
            self.robot.sync()
            pb.stepSimulation(physicsClientId=self.cid)
            self._glide.stepped()
            self.scene.hold_limits()
            self._tick()

    def glide(self, body: np.ndarray, vel: np.ndarray) -> bool:
        """One step of a base drive without the physics, if it would do no more than set the base
        at its set-point ``body`` (velocity ``vel``; :mod:`pb_glide`): the time, the physics rules
        and Table II's effects advance as in :meth:`step`. False (nothing done) when the step is
        the physics' — the base would touch something, or something else moves."""
        with self._lock:
            if not self._glide.place(body, vel):
                return False
            self._tick()
            return True

    def _tick(self) -> None:
        self.ticks += 1
        self.rules.step()
        self.injection.step()

    def _loose_moving(self) -> bool:
        """Whether an item the hand does not hold moves faster than :data:`LOOSE_SPEED`."""
        held = self.robot.grip.body if self.robot.grip is not None else None
        return any(np.linalg.norm(pb.getBaseVelocity(b, physicsClientId=self.cid)[0]) > LOOSE_SPEED
                   for t in self.scene.things.values() if t.item is not None for b in t.bodies if b != held)

    @property
    def physics(self) -> dict:
        """How pybullet integrates the household, for the report: results depend on it."""
        return {"version": WORLD_VERSION, "base": "kinematic in free space (pb_glide)", "dt": DT,
                "substeps": SUBSTEPS, "loose_substeps": LOOSE_SUBSTEPS, "loose_speed": LOOSE_SPEED,
                "solver_iterations": SOLVER_ITERATIONS}

    # ------------------------------------------------------------ actions

    def begin_action(self, action: str, args: tuple[str, ...]) -> None:
        """Sim-only hook: a goal for ``action(args)`` starts, and skills will move the robot
        through :attr:`drivers`. Scripted disturbances for this step apply, Table II draws once
        and its situation is armed at the drivers (:mod:`pb_injection`). An action still open
        ends first. Nothing drawn is returned: the skill must find out by perceiving."""
        with self._lock:
            if self._action is not None:
                self._end()
            self._begin(action, tuple(args))

    def end_action(self, action: str | None = None, args: tuple[str, ...] | None = None) -> None:
        """Sim-only hook: the goal ended (however). A drop still pending happens now, then the
        disturbances scripted for after this step. Naming another action than the open one (a
        late message) does nothing."""
        with self._lock:
            a = self._action
            if a is None or (action is not None and (action, tuple(args or ())) != (a[1], a[2])):
                return
            self._end()

    def _begin(self, action: str, args: tuple[str, ...]) -> None:
        step = self.actions
        self.actions += 1
        self._disturb(step, action, args)
        self._action = (step, action, args)
        self.injection.begin(action, args, step)
        self.natural.begin(action, args, step)

    def _end(self) -> None:
        step, action, args = self._action
        self.injection.end()
        self.natural.end(self._injected)
        self._action = None
        self._disturb(step, action, args, when="after")

    def _disturb(self, step: int, action: str, args, when: str = "at") -> None:
        for d in self.disturbances:
            if d.get(when) != step:
                continue
            if "move" in d:
                name, to = d["move"], d["to"]
                if self.truth.held() == name:
                    continue
                spot = self._free_spot(to, name)
                t = self.scene.things[name]
                box = self.truth.aabb(name)
                c = self.truth.center(name)
                spot[2] += (c[2] - box[2]) + 0.01
                # a person's hand is not simulated: the object is set down at its new place
                pb.resetBasePositionAndOrientation(t.body, tuple(spot), pb.getBasePositionAndOrientation(
                    t.body, physicsClientId=self.cid)[1], physicsClientId=self.cid)
                kind, affected = MOVED, name
            elif "door" in d:
                h = self.scene.things[d["door"]].hinge
                fraction = float(d.get("open", HALF_OPEN))
                pb.resetJointState(h.body, h.joint, h.full * fraction, physicsClientId=self.cid)
                kind, affected = (HALF_SHUT if fraction > 0 else SHUT), d["door"]
            else:
                continue
            for _ in range(20):
                self.step()
            self._injected.append(InjectedSituation(action, tuple(args), kind, step, (affected,), "disturbance"))

    def _free_spot(self, surface: str, item: str) -> np.ndarray:
        """Where a person sets ``item`` down on ``surface``: the centre of a spot on its top far
        from the other items on it and near the robot (on a floor: in front of the robot)."""
        t = self.scene.things[surface]
        others = [self.truth.center(i.name) for i in self.scene.items() if i.name != item and self.truth._on(i.name, surface)]
        x, y, yaw = self.robot.base_pose
        if t.room is not None:
            cands = [np.array([x + 0.75 * math.cos(yaw) + dx * -math.sin(yaw), y + 0.75 * math.sin(yaw) + dx * math.cos(yaw), 0.0])
                     for dx in np.linspace(-0.3, 0.3, 7)]
        else:
            f = t.furniture
            w = f.kind.size[0] / 2 - 0.08
            cands = [f.to_world((lx, 0.0, f.kind.size[2])) for lx in np.linspace(-w, w, 9)]
        base = np.array((x, y))

        def score(p):
            clear = min([np.linalg.norm(p[:2] - o[:2]) for o in others] + [1.0])
            return min(clear, 0.2) - 0.05 * np.linalg.norm(p[:2] - base)

        return max(cands, key=score)

    def injected(self) -> list[InjectedSituation]:
        """The situations the world caused this episode (Table II or a disturbance script), and
        the robot's actions that failed by physics alone (:mod:`natural_failures`), in order."""
        return list(self._injected)

    # ------------------------------------------------------------ truth (the oracle's)

    def _holds(self, atom: Atom) -> bool:
        with self._lock:
            return self.truth.holds(atom)

    def _position(self, name: str) -> tuple[float, float, float] | None:
        with self._lock:
            return _point(self.truth.center(name)) if name in self.scene.things else None

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

    # ------------------------------------------------------------ robot interfaces: camera

    def capture(self, aim: Aim | None = None) -> Frame:
        """Render what the wrist camera shows now and detect. ``aim`` only labels the frame (what
        it was taken for): aiming is whoever moves the arm's (:class:`skills.views.ViewService`)."""
        with self._lock:
            return self._frame(aim)

    def _frame(self, aim: Aim | None) -> Frame:
        r = self.wrist_view()
        names = self.scene.by_body()
        counts = pixel_counts(r, names)
        doorways = self._doorways(r)
        for name, (n, _, _) in doorways.items():  # a detector finds a doorway, open or shut
            counts[name] = max(counts.get(name, 0), n)
        # the simulated VLM's record: how much of each object this frame shows (world side only)
        boxes = {n: self.truth.outline(n) for n in counts if n in self.scene.things}
        vis = visibility(r, counts, boxes, {n: self._fill(n) for n in boxes})
        vis.update({n: min(1.0, k / (a * FILL["door"])) if a > 0 else 0.0 for n, (k, a, _) in doorways.items()})
        extents = mask_extents(r, names)
        pixels = r.bodies.size
        for name, (k, _, edges) in doorways.items():  # the doorway is how a door shows: its extent
            if k and k / pixels > extents.get(name, ((), 0.0))[1]:
                extents[name] = (edges, k / pixels)
        sha = rgb_sha1(r.rgb)
        found = self._detect(r, names, counts, vis, sha)
        self.view_index += 1
        frame_id = f"pb-{self.seed}-{self.view_index}"
        seen = {n: 1.0 if extents.get(n, ((), 0.0))[1] >= PLAIN_SHARE else v for n, v in vis.items()}
        views, fingers = object_views(r, self.scene, self.truth, self.robot, seen,
                                      {n: e[1] for n, e in extents.items()}, counts)
        self.captures.add(CaptureRecord(frame_id, self.ticks, vis, self.oracle, lambda: self.ticks,
                                        masks=extents, image_sha1=sha, instances=found.instances, marked=True,
                                        views=views, fingers=fingers,
                                        labels={n: self._label(n) for n, x in self.scene.things.items() if x.room is None}))
        # the sensors' own errors: stereo depth, and the pose in the frame the robot believes it is in
        depth = self.depth_noise.apply(r.depth, r.camera.fx, r.camera.far, (self.seed, int(sha[:15], 16)))
        return Frame(frame_id, self.ticks * DT, found.detections, rgb=r.rgb, depth=depth, masks=found.masks,
                     intrinsics=r.intrinsics, camera_pose=self.localization.believed_T(r.pose),
                     aim=tuple(aim.names) if aim else ())

    def _detect(self, r: Render, names: dict[int, str], counts: dict[str, int], vis: dict[str, float], sha: str):
        """What the detector (:mod:`vap_bt.sim.detector`) reports of the rendered picture: class
        labels, misses, false positives, rough masks, each draw seeded by the seed and the picture."""
        shown = sorted(n for n in counts if self._detectable(n))
        ids = {n: i for i, n in enumerate(shown)}
        return self.detector.detect(name_image(r, {b: n for b, n in names.items() if n in ids}, ids), shown,
                                    [counts[n] for n in shown], [vis.get(n, 0.0) for n in shown],
                                    [self._label(n) for n in shown], r.depth, self._classes, f"{self.seed}|{sha}")

    def _doorways(self, r: Render) -> dict[str, tuple[int, float, tuple[str, ...]]]:
        """Each room door's doorway as the frame shows it (see :func:`doorway_pixels`)."""
        out = {}
        for t in self.scene.things.values():
            if t.door is not None and t.hinge is not None:
                h = t.hinge
                out[t.name] = doorway_pixels(r, h.leaf_center, h.leaf_half, h.normal, set(t.bodies))
        return out

    def _detectable(self, name: str) -> bool:
        t = self.scene.things.get(name)
        return t is not None and t.room is None  # rooms and floors are the map's

    def _label(self, name: str) -> str:
        """The class a detector reports (:mod:`vap_bt.robot.labels`): a door, a piece of
        furniture's kind (the map's), an item's class."""
        t = self.scene.things[name]
        if t.door is not None:
            return DOOR
        if t.item is None and t.kind is not None:
            return t.kind.name
        return class_of(name)

    @property
    def _classes(self) -> list[str]:
        """Every class the scene holds (a false positive takes one)."""
        return sorted({self._label(n) for n in self.scene.things if self._detectable(n)})

    def _fill(self, name: str) -> float:
        t = self.scene.things[name]
        if t.item is not None:
            return FILL.get(t.kind.shape, 0.8)
        return FILL["door"] if t.door is not None else FILL["furniture"]

    def aim_at(self, names: tuple[str, ...]) -> Aim:
        """An aim at where ``names`` truly are — for tests and tools that stage a view (a camera
        service then turns the camera there). It reads the truth: the executive never calls it
        (it aims from belief)."""
        with self._lock:
            known = [n for n in names if n in self.scene.things and self.truth.held() != n]
            point = np.mean([self._target_point(n) for n in known], axis=0) if known else None
            return Aim(tuple(names), None if point is None else tuple(map(float, point)))

    def _target_point(self, name: str) -> np.ndarray:
        """Where to look at ``name``: a door's middle, a cavity's, a surface's top, the floor ahead
        of the robot for a room, an item's centre."""
        t = self.scene.things[name]
        if t.door is not None:
            return np.array([t.door.x, t.door.center_y, 0.8])
        if t.room is not None:
            x, y, yaw = self.robot.base_pose
            return np.array([x + 1.5 * math.cos(yaw), y + 1.5 * math.sin(yaw), 0.0])
        if t.furniture is not None:
            f = t.furniture
            if f.kind.cavity is not None:
                return f.to_world((0.0, f.kind.size[1] / 4, sum(f.kind.cavity.z) / 2))
            return f.to_world((0.0, 0.0, f.kind.size[2]))
        return self.truth.center(name)

    # ------------------------------------------------------------ robot interfaces: body and map

    def state(self) -> RobotState:
        """The body's state as its drivers report it: poses in the map frame the robot believes
        it is in (:mod:`localization`)."""
        with self._lock:
            x, y, yaw = self.localization.believed(self.robot.base_pose)
            T = self.localization.believed_T(self.robot.link_pose("tcp"))
            return RobotState(self.ticks * DT, self.plan.room_at(x, y), (x, y, yaw),
                              tuple(float(v) for v in self.robot.q()[3:]),
                              (*map(float, T[:3, 3]), *quat_xyzw(T[:3, :3])),
                              float(np.sum(self.robot.finger_q())),
                              # the fingers stopped on something: what a gripper's object detection says
                              self.robot.grip is not None and self.robot.grip.link == -1)

    def site_map(self) -> SiteMap:
        return self._map

    def _site_map(self) -> SiteMap:
        """Rooms, doors and furniture as a semantic map has them: outlines, footprints, and what a
        furniture model annotates (height, cavity, how its door moves, switch, tap), all in the
        map frame, which is pybullet's world frame; doors and drawers at their closed position."""
        plan = self.plan
        rooms = tuple(RoomInfo(r.name, floor_of(r.name), (r.x0, r.y0, r.x1, r.y1)) for r in plan.rooms.values())
        doors = tuple(DoorInfo(d.name, (d.low, d.high), (d.x, d.center_y, 0.0), d.width,
                               _articulation(self.scene.things[d.name].hinge)) for d in plan.doors.values())
        furniture = []
        for f in plan.furniture.values():
            k, t = f.kind, self.scene.things[f.name]
            furniture.append(FurnitureInfo(
                f.name, k.name, self.types[f.name], f.room, (f.x, f.y, math.atan2(f.front[1], f.front[0])),
                (k.size[0], k.size[1]), height=float(k.size[2]),
                cavity=Cavity(tuple(map(float, k.cavity.z)), float(k.cavity.wall), k.cavity.open) if k.cavity else None,
                articulation=_articulation(t.hinge) if t.hinge is not None else None,
                switch=_point(f.to_world(switch_face(k))) if t.switch_link is not None else None,
                tap=_point(f.to_world(tap_outlet(k))) if k.tap else None))
        return SiteMap(rooms, doors, tuple(furniture), frozenset(self.truth.rigid))

    # ------------------------------------------------------------ pictures

    def overview(self, width: int = 480, height: int = 360) -> np.ndarray:
        """A bird's-eye picture of the whole house (for people, not for perception)."""
        xs = [r.x0 for r in self.plan.rooms.values()] + [r.x1 for r in self.plan.rooms.values()]
        cx, cy = (min(xs) + max(xs)) / 2, self.plan.depth / 2
        span = max(max(xs) - min(xs), self.plan.depth)
        eye = np.array([cx, cy - 0.75 * span, 0.95 * span])
        cam = dataclasses.replace(_camera((width, height)), far=4 * span)
        return render(self.cid, look_pose(eye, (cx, cy + 0.4, 0.0)), cam, shadows=False).rgb


def _point(p) -> tuple[float, float, float]:
    return (float(p[0]), float(p[1]), float(p[2]))


def _articulation(h: Hinge) -> Articulation:
    """The map's model of a door leaf or drawer, from the simulation's hinge (closed, q = 0)."""
    return Articulation(h.prismatic, _point(h.origin), _point(h.axis), _point(h.handle), _point(h.normal),
                        _point(h.bar), float(h.full), float(h.lower), float(h.upper), _point(h.leaf_center),
                        _point(h.leaf_half), None if h.other_side is None else float(h.other_side))


def _camera(size: tuple[int, int]):
    import robots

    cam = robots.load_config().camera.at(*size)
    return cam
