"""The robot's body as skills move it: drivers, kinematics, and motions planned then executed.

Skills never command motors. They plan with :mod:`vap_bt.motion` — inverse kinematics (pinocchio,
collision-checked against the scene's furniture and walls), time-optimal timing of a joint path
(toppra), point-to-point base moves (ruckig) — and hand the result to the drivers of
:mod:`vap_bt.robot.drivers`, which block until the motion ends or ``cancelled()`` turns true.
Everything starts from the *measured* state (joint encoders, localization), so a skill that
starts where another one left the arm plans from where the arm really is.

A motion of base and arm together (following a door's handle) is one whole-body trajectory over
the base's and the arm's joints; the arm's driver takes it whenever the base's joints are named.
"""

from __future__ import annotations

import math
from typing import Callable, Iterator

import numpy as np

import robots
from vap_bt.motion import se3
from vap_bt.motion.collision import Attached, CollisionChecker, SceneBoxes
from vap_bt.motion.ik import IKOptions, solve_ik
from vap_bt.motion.kinematics import Kinematics, world_to_base
from vap_bt.motion.limits import Limits, arm_limits, base_limits
from vap_bt.motion.timing import TimingError, time_path
from vap_bt.robot.drivers import Arm, Base, Gripper, JointTrajectory

#: joint samples per second of planned motions (the drivers interpolate between them)
RATE_HZ = 60.0
#: rad between the samples of a joint-space way checked for collisions
PATH_STEP = 0.05
#: rad: a waypoint this near where the joints are is where they are (toppra finds no timing for a
#: path of a few tenths of a milliradian, and a look already aimed was refused as unreachable)
NO_MOVE = 1e-3
#: rad the shoulder or the elbow may turn between two steps of a straight tcp line (a few
#: centimetres each): more is IK answering from another branch of the arm (the shoulder swung
#: 1.3 rad, the wrist half a turn round), and a spline through that jump sweeps the arm and
#: overshot a wrist past its limit (boil_water on real sensors: the takeout's way into the cabinet
#: was refused whole). The wrist's joints are held to it plus the angle the hand itself turns over
#: the step: a line whose end turns the hand turns them that much, and no more — IK answering the
#: next step with the wrist flipped (the branch that keeps it was in the furniture) turned the
#: hand half a turn round between two steps of a straight line down, and the spline through that
#: swept the fingers into the floor (heat_pie seed 0, a pie at a fridge's foot)
LINE_JOINT_JUMP = 0.8
#: of the arm's limits: backing off a strike, slowly
BACK_OFF_SPEED = 0.3
#: rad inside the joint limits a waypoint turned by a whole turn must stay
UNWIND_MARGIN = 0.5
#: an IK answer this near a joint limit is turned by a whole turn if it can be (a timed spline
#: through it overshoots the limit, and the driver refuses the trajectory)
LIMIT_EDGE = 0.1
#: the one turn a commanded shoulder lift is written in: a joint-space way between two values in it
#: never swings the upper arm through pointing straight down into its own mount (+pi/2, the same
#: pose as -3pi/2). Turned towards the last pose instead (the short way), a look swung it from
#: 0.8 rad forward-down to 3.4 rad back-up through the mount, the arm stalled against the base, and
#: the value drifted on to 5.59 rad, where the next line down crossed the 2 pi limit and was
#: refused (store_firewood seed 18)
SHOULDER_TURN = (-1.5 * np.pi, 0.5 * np.pi)
#: m the arm's links (not the hand, which works close to things) keep off walls and furniture: the
#: simulated arm's shapes carry a collision margin the model's cylinders do not. The camera's
#: housing on the flange too: above a pie at the foot of a fridge it scraped the carcass's front
#: by 5 mm on the way home (heat_pie seeds 1 and 8 with injection)
ARM_CLEARANCE = {"shoulder_link": 0.02, "upper_arm_link": 0.02, "forearm_link": 0.02, "wrist_1_link": 0.01,
                 "wrist_2_link": 0.01, "camera_link": 0.01}
#: m above a pose the hand is brought to first, and lowered from straight down, when no joint way
#: to the pose itself is clear (to the floor right in front of furniture)
FROM_ABOVE = (0.25, 0.45)
#: IK tolerances: the hand within 2 mm and 0.6 degrees of where it is sent
IK = IKOptions(max_seeds=6, position_tolerance=2e-3, orientation_tolerance=1e-2)
#: an arm pose that must also have a clear way there tries every branch of the closed-form solution
IK_BRANCHES = IKOptions(max_seeds=10, position_tolerance=2e-3, orientation_tolerance=1e-2)
IK_MOBILE = IKOptions(max_seeds=1, max_iterations=200, position_tolerance=2e-3, orientation_tolerance=1e-2)


class Stopped(Exception):
    """A motion did not complete (cancelled, or the driver refused it); the skill ends."""


class Struck(Stopped):
    """An arm motion stopped against something (the driver's ``blocked``): the scene model did not
    hold it where it is — a piece of furniture a few centimetres off where the map, laid by a
    localiser's error and a registration's, puts it. A checked way backs off the way it came
    (:meth:`Body.through`); a line into a contact ends the skill."""


class Slipped(Stopped):
    """A drive stopped because the item the hand took slipped out of it (:meth:`Body.drive`):
    the skill ends, and whether its action still did what it should is for perception to say."""


def _concat(a: Limits, b: Limits) -> Limits:
    return Limits(a.names + b.names, *(np.concatenate((getattr(a, f), getattr(b, f)))
                                       for f in ("lower", "upper", "velocity", "acceleration", "jerk")))


class Body:
    """Drivers plus the kinematic model: where the robot is, and how to move it there."""

    def __init__(self, arm: Arm, gripper: Gripper, base: Base, name: str = robots.DEFAULT_ROBOT) -> None:
        self.arm, self.gripper, self.base = arm, gripper, base
        self.cfg = robots.load_config(name)
        self.kin_arm = Kinematics.arm()
        self.kin_mobile = Kinematics.mobile_arm()
        self.limits = _concat(base_limits(), arm_limits())
        self.base_limits = base_limits()
        self.cancelled: Callable[[], bool] = lambda: False  # the running goal's
        #: why a drive should stop: what the hand took is no longer between the fingers (the kit's
        #: word: it knows what the hand took, and when it went); None while it is (:meth:`drive`)
        self.slipped: Callable[[], str | None] = lambda: None
        #: told after every motion of the base (a drive, a whole-body trajectory): what was measured
        #: of the map from the last stance may no longer hold (the kit's scene model decides)
        self.base_moved: Callable[[], None] = lambda: None
        self._checker: CollisionChecker | None = None
        #: path_clear's answers for the scene and held item as they are now, by the two joint
        #: vectors: a way is checked when an arm pose is chosen (:meth:`reachable`) and again when
        #: the arm is sent along it (:meth:`through`), and the collision checks were a tenth of a
        #: pybullet episode's CPU, half of them asked before. Emptied with the checker
        self._clear: dict[bytes, bool] = {}
        self._scene: SceneBoxes = SceneBoxes.empty()
        self._held: Attached | None = None

    # -- the measured state ------------------------------------------------------------------

    def q(self) -> np.ndarray:
        """Base (x, y, yaw) and the six arm joints, as measured."""
        return np.array([*self.base.pose(), *self.arm.joint_state().positions])

    def base_pose(self) -> tuple[float, float, float]:
        """Where the localiser puts the base now (x, y, yaw, map frame)."""
        return tuple(map(float, self.base.pose()))

    def base_T(self, q=None) -> np.ndarray:
        """The base footprint frame in the map (4x4), for measured joints or the given ``q``."""
        x, y, yaw = (self.q() if q is None else q)[:3]
        return se3.planar_pose(x, y, yaw)

    def mark(self) -> tuple[np.ndarray, np.ndarray]:
        """Where the base is now as the localiser and as the wheels have it (4x4 each): what a
        measurement taken now needs to be carried across later motions (:meth:`since`)."""
        return self.base_T(), se3.planar_pose(*self.base.odometry())

    def since(self, mark: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
        """4x4 taking a point of the map frame as the robot had it at ``mark`` to the map frame as
        it has it now. The localiser's frame jumps when it updates (a few centimetres, a degree
        or two), the wheels' does not: a point is carried by the wheels' motion since, and set in
        the localiser's frame as it is now — the identity while the localiser has not updated."""
        B0, O0 = mark
        B1, O1 = self.mark()
        return B1 @ np.linalg.inv(O1) @ O0 @ np.linalg.inv(B0)

    def in_base(self, p) -> np.ndarray:
        """A point given in the base footprint frame, in the map frame (as the base stands now)."""
        return (self.base_T() @ np.array([*p, 1.0]))[:3]

    def pose(self, frame: str = "tcp", q=None) -> np.ndarray:
        """Pose of a robot frame in the map frame, from measured (or given) joints."""
        return self.kin_mobile.fk(self.q() if q is None else q, frame)

    def holding(self) -> bool:
        """Whether the gripper says its fingers stopped on something while closing."""
        return self.gripper.state().holding

    # -- the scene IK keeps off --------------------------------------------------------------

    def set_scene(self, boxes: SceneBoxes) -> None:
        """The furniture and walls (map frame) that IK solutions must keep clear of."""
        self._scene, self._checker, self._clear = boxes, None, {}

    def hold(self, pose: np.ndarray | None, size=None) -> None:
        """The item in the hand as a box (its centre's ``pose`` in the tcp frame, its ``size``), or
        None: IK solutions and arm ways keep it off the scene and off the arm's own links, as
        they keep the arm (a carried log swung into the forearm stops the arm)."""
        if pose is None and self._held is None:
            return
        # a new checker for any other item (an Attached holds arrays: no == between two of them)
        self._held = None if pose is None else Attached("tcp", np.asarray(pose, float), np.asarray(size, float))
        self._checker, self._clear = None, {}

    def _collision(self, base_pose) -> CollisionChecker | None:
        if not len(self._scene):
            return None
        local = self._scene.transformed(np.linalg.inv(self.base_T(np.array([*base_pose, *np.zeros(6)]))))
        if self._checker is None:
            self._checker = CollisionChecker(self.kin_arm, local, scene_margins=ARM_CLEARANCE, attached=self._held)
        else:
            self._checker.place_boxes(local.poses)
        return self._checker

    # -- planning ----------------------------------------------------------------------------

    def solve(self, target: np.ndarray, frame: str = "tcp", seed: np.ndarray | None = None,
              allow_base: bool = False, collide: bool = True, accept=None) -> np.ndarray | None:
        """Body joints putting ``frame`` at ``target`` (map 4x4): the arm alone from where the base
        is (clear of the scene's furniture and walls, and ``accept``-ed when given: a test of the
        body joints, tried on every branch of the arm's solution), else — when allowed — arm and
        base."""
        seed = self.q() if seed is None else np.asarray(seed, float)
        local = world_to_base(target, tuple(seed[:3]))

        def body(arm: np.ndarray) -> np.ndarray:
            q = seed.copy()
            q[3:] = _nearest_turn(arm, seed[3:], self.kin_arm.lower, self.kin_arm.upper)
            return q

        r = solve_ik(self.kin_arm, local, frame=frame, q_init=seed[3:], options=IK if accept is None else IK_BRANCHES,
                     collision=self._collision(seed[:3]) if collide else None,
                     accept=None if accept is None else (lambda arm: accept(body(arm))))
        if r.success:
            return body(r.q)
        if not allow_base:
            return None
        r = solve_ik(self.kin_mobile, target, frame=frame, q_init=seed, options=IK_MOBILE)
        if not r.success:
            return None
        q = r.q.copy()
        q[2:] = _nearest_turn(q[2:], seed[2:], self.kin_mobile.lower[2:], self.kin_mobile.upper[2:])
        return q

    def reachable(self, target: np.ndarray, frame: str = "tcp", seed: np.ndarray | None = None,
                  allow_base: bool = False) -> np.ndarray | None:
        """:meth:`solve`, for an arm pose the arm has a clear way to from ``seed`` (default: as it
        is), round the scene by :meth:`routed`: the nearest branch of the solution may have none
        where another has (a held log would sweep through the forearm on the way)."""
        seed = self.q() if seed is None else np.asarray(seed, float)
        return self.solve(target, frame, seed, allow_base, accept=lambda q: self.routed(seed, [q]) is not None)

    # -- executing -----------------------------------------------------------------------------

    def path_clear(self, qa: np.ndarray, qb: np.ndarray) -> bool:
        """Whether the arm's straight joint-space way from ``qa`` to ``qb`` (body joints, the base
        where it is) keeps clear of the scene. An arm that starts touching something may leave
        it: only the way after its first free sample counts. One that starts clear must stay
        clear: taken as leaving from the start, a way from a free pose whose first sample was
        already in a fridge's front went on through it (the carry out of a grasp at the fridge's
        foot, heat_pie seed 0), and the arm struck it."""
        if not len(self._scene):
            return True
        key = np.concatenate((qa, qb)).astype(float).tobytes()
        clear = self._clear.get(key)
        if clear is None:  # the answer is the checker's alone: the same for the same two poses
            clear = self._clear[key] = self._check_way(self._collision(qa[:3]), qa, qb)
        return clear

    @staticmethod
    def _check_way(checker: CollisionChecker, qa: np.ndarray, qb: np.ndarray) -> bool:
        n = max(2, int(np.max(np.abs(qb[3:] - qa[3:])) / PATH_STEP) + 1)
        leaving = checker.in_collision(qa[3:])
        for s in np.linspace(0.0, 1.0, n + 1)[1:]:
            hit = checker.in_collision(qa[3:] + (qb[3:] - qa[3:]) * s)
            if hit and not leaving:
                return False
            leaving = leaving and hit
        return True

    def routed(self, start: np.ndarray, qs: list[np.ndarray]) -> list[np.ndarray] | None:
        """``qs`` with detours (:meth:`_detours`) put in before a waypoint whose straight way
        there would sweep the arm through the scene or itself; None when no detour is clear
        either (the motion is refused rather than run into the furniture)."""
        out, here = [], start
        for q in qs:
            q = self._unwound(here, [q])[0]
            if not self.path_clear(here, q):
                for via in self._detours(here, q):
                    q_via = self._unwound(via[-1], [q])[0]  # as near the detour's end as it goes
                    if self._clear_through([here, *via, q_via]):
                        out += via
                        q = q_via
                        break
                else:
                    return None
            out.append(q)
            here = q
        return out

    def _detours(self, here: np.ndarray, q: np.ndarray) -> list[list[np.ndarray]]:
        """Ways round, fewest joints changed at once first: by home; the upper arm lifted first;
        the wrist turned first or last (a wrist turning while the elbow folds can sweep the hand
        into the forearm), at home or where the arm is."""
        tucked, lifted = here.copy(), here.copy()
        tucked[3:] = self.cfg.arm.home
        lifted[4:6] = self.cfg.arm.home[1:3]  # shoulder lift and elbow as at home, the wrist kept
        wrist_first, arm_first, home_wrist = here.copy(), here.copy(), tucked.copy()
        wrist_first[6:], arm_first[3:6], home_wrist[6:] = q[6:], q[3:6], q[6:]
        return [[tucked], [lifted, tucked], [lifted], [wrist_first], [arm_first],
                [tucked, home_wrist], [lifted, tucked, home_wrist]]

    def _clear_through(self, pts: list[np.ndarray]) -> bool:
        return all(self.path_clear(a, b) for a, b in zip(pts, pts[1:]))

    def through(self, qs: list[np.ndarray], speed: float = 1.0, check: bool = True) -> bool:
        """Move through body-joint waypoints from the measured state (toppra-timed); False when
        the path cannot be timed, or (``check``) an arm-only way would hit the scene even round by
        the home pose. A checked way is driven one straight joint-space segment at a time (a
        spline through the waypoints would leave the checked segments); a straight line into a
        contact is not checked. The base's joints are driven along only when they change."""
        start = self.q()
        qs = self._unwound(start, [np.asarray(q, float) for q in qs])
        if len(qs) == 1 and np.max(np.abs(qs[0] - start)) < NO_MOVE:
            return True
        whole = np.max(np.abs(np.array(qs)[:, :3] - start[:3])) > NO_MOVE
        if whole or not check:
            return self._timed([start, *qs], whole, speed)
        route = self.routed(start, qs)
        if route is None:
            return False
        for q in route:
            # each segment from where the joints are (an arm held off its set-point by something
            # it touched would have the next segment refused as starting elsewhere)
            before = self.q()
            try:
                if not self._timed([before, q], False, speed):
                    return False
            except Struck:
                # the way was clear of the scene as modelled, not as it stands: back the way it
                # came (a second strike ends the skill) and let the caller try another way
                self._timed([self.q(), before], False, BACK_OFF_SPEED)
                return False
        return True

    def _unwound(self, start: np.ndarray, qs: list[np.ndarray]) -> list[np.ndarray]:
        """Each waypoint's arm joints turned by whole turns to the same pose nearest the one
        before, well within the limits (a timed spline overshoots a little): IK may answer a wrist a full turn away, and driving that
        turn sweeps the hand round through whatever is beside it. The shoulder's lift is written
        in :data:`SHOULDER_TURN` instead: the short way round may lead through the arm's mount."""
        lo, hi = np.array(self.cfg.arm.lower), np.array(self.cfg.arm.upper)
        out, prev = [], start
        turns = 2 * np.pi * np.arange(-2, 3)[:, None]
        for q in qs:
            q = q.copy()
            arm = q[3:] + 2 * np.pi * np.round((prev[3:] - q[3:]) / (2 * np.pi))
            ok = (arm >= lo + UNWIND_MARGIN) & (arm <= hi - UNWIND_MARGIN)
            # IK's own answer where the nearest turn is not well within the limits — unless that
            # answer is so near a limit that the timed spline would overshoot it (a wrist at
            # -6.2 rad): then the nearest whole-turn copy that is well within them
            options = q[3:] + turns
            inside = (options >= lo + UNWIND_MARGIN) & (options <= hi - UNWIND_MARGIN)
            best = options[np.argmin(np.where(inside, np.abs(options - prev[3:]), np.inf), axis=0), np.arange(len(lo))]
            edge = (q[3:] < lo + LIMIT_EDGE) | (q[3:] > hi - LIMIT_EDGE)
            raw = np.where(edge & inside.any(axis=0), best, q[3:])
            q[3:] = _shoulder_in_turn(np.where(ok, arm, raw))
            out.append(q)
            prev = q
        return out

    def _timed(self, pts: list[np.ndarray], whole: bool, speed: float) -> bool:
        pts = np.array(pts)
        names = (self.cfg.base.joints if whole else ()) + self.cfg.arm.joints
        limits = self.limits if whole else arm_limits()
        # within the limits, the start too: a joint driven to its limit is measured a hair past
        # it after the physics settles, and a path from there is refused — every one, for good
        path = np.clip(pts if whole else pts[:, 3:], limits.lower, limits.upper)
        if len(path) == 2 and np.max(np.abs(path[1] - path[0])) < NO_MOVE:
            return True
        try:
            traj = time_path(path, limits.scaled(speed), dt=1.0 / RATE_HZ)
        except TimingError:
            return False
        try:
            self._follow(JointTrajectory(tuple(names), traj.t, traj.q, traj.qd))
        finally:
            if whole:
                self.base_moved()
        return True

    def _follow(self, traj: JointTrajectory) -> None:
        res = self.arm.follow(traj, self.cancelled)
        if not res.completed:
            if res.message.startswith("blocked") and not self.cancelled():
                raise Struck(res.message)
            raise Stopped(res.message or "the arm stopped")

    def goto_pose(self, T: np.ndarray, speed: float = 0.8, allow_base: bool = False, frame: str = "tcp") -> bool:
        """Move ``frame`` to ``T`` by an arm pose with a clear way there (:meth:`reachable`); the
        tcp, when no branch of the arm has one, by a hand lowered straight down (:meth:`from_above`)."""
        q = self.reachable(T, frame, allow_base=allow_base)
        if q is not None and self.through([q], speed):
            return True
        return frame == "tcp" and any(self.through([up], speed) and self.line(T, steps=4, speed=0.4, collide=True)
                                      for up in self.from_above(T))

    def from_above(self, T: np.ndarray) -> Iterator[np.ndarray]:
        """Arm poses (the base where it is) putting the tcp :data:`FROM_ABOVE` over ``T``, each
        with a clear way there: whence the hand goes straight down to ``T`` when no branch of the
        arm has a clear joint way to ``T`` itself (to the floor right in front of a counter, every
        joint way sweeps the hand or the forearm through the counter's front)."""
        for up in FROM_ABOVE:
            U = np.array(T, float)
            U[2, 3] += up
            q = self.reachable(U)
            if q is not None:
                yield q

    def line(self, target: np.ndarray, frame: str = "tcp", steps: int = 5, speed: float = 0.4,
             collide: bool = False) -> bool:
        """Move ``frame`` along a straight line to ``target`` (orientation interpolated). A line is
        the last stretch to a contact (into a grasp, onto a support), where the hand must come near
        the furniture: by default it is not kept off the scene's boxes."""
        qs = self.line_way(self.pose(frame), target, self.q(), frame, steps, collide)
        if not qs:
            return False
        self.through(qs, speed, check=False)
        return len(qs) == steps

    def line_way(self, start: np.ndarray, target: np.ndarray, seed: np.ndarray, frame: str = "tcp",
                 steps: int = 5, collide: bool = False) -> list[np.ndarray]:
        """Body joints at ``steps`` even points of ``frame``'s straight line from ``start`` to
        ``target`` (orientation interpolated), each solved from the last (the first from
        ``seed``); as far as IK follows the line: fewer than ``steps`` where it stops. Plans, does
        not move."""
        qs: list[np.ndarray] = []
        before = np.asarray(start, float)
        for k in range(1, steps + 1):
            T = se3.interpolate(start, target, k / steps)
            q = self.solve(T, frame, seed, collide=collide)
            turn = _rotation_angle(before[:3, :3].T @ T[:3, :3])  # the hand's own turn over this step
            if q is None or _turned_by(q[3:6], seed[3:6]) > LINE_JOINT_JUMP \
                    or _turned_by(q[6:], seed[6:]) > LINE_JOINT_JUMP + turn:
                break  # IK lost the line, or left it for another branch of the arm
            qs.append(q)
            seed, before = q, T
        return qs

    def drive(self, poses: list[tuple[float, float, float]], speed: float = 1.0) -> None:
        """Drive the base through ``poses`` (x, y, yaw), the arm held as it is. A drive stops when
        the item the hand took has slipped out (the gripper's object detection; :attr:`slipped`),
        as a real robot's would: driving on would leave it behind — or drive over it — where
        nobody looks for it; stopped beside it, the robot finds it on the floor round where it
        stands. Raises :class:`Slipped` then."""
        if not poses:
            return
        try:
            res = self.base.follow([tuple(map(float, p)) for p in poses], speed,
                                   lambda: self.cancelled() or self.slipped() is not None)
        finally:
            self.base_moved()
        if not res.completed:
            slipped = self.slipped()
            if slipped is not None and not self.cancelled():
                raise Slipped(slipped)
            raise Stopped(res.message or "the base stopped")

    def fingers(self, width: float, force: float = 40.0) -> bool:
        """Open or close the fingers to ``width`` (m between them); True when they hold something."""
        return self.gripper.move(width, force, self.cancelled).holding

    def hold_still(self, seconds: float) -> None:
        """Keep every joint where it is for ``seconds`` (a trajectory that stands still)."""
        q = self.q()[3:]
        self._follow(JointTrajectory(tuple(self.cfg.arm.joints), np.array([0.0, seconds]), np.array([q, q]),
                                     np.zeros((2, len(q)))))

    def home(self) -> None:
        """Fold the arm to its home pose (the base stays); blocks until it gets there."""
        q = self.q()
        q[3:] = self.cfg.arm.home
        self.through([q], 0.8)


def _turned_by(q: np.ndarray, ref: np.ndarray) -> float:
    """The largest joint change from ``ref`` to ``q``, each the short way round (rad)."""
    return float(np.max(np.abs(np.remainder(np.asarray(q) - ref + np.pi, 2 * np.pi) - np.pi)))


def _rotation_angle(R: np.ndarray) -> float:
    """The angle (rad) of a rotation matrix."""
    return float(np.arccos(np.clip((np.trace(R) - 1.0) / 2.0, -1.0, 1.0)))


def _nearest_turn(q: np.ndarray, ref: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Shift revolute values by whole turns towards ``ref`` (within limits): the short way round."""
    shifted = q - 2 * np.pi * np.round((q - ref) / (2 * np.pi))
    ok = (shifted >= lower) & (shifted <= upper)
    return np.where(ok, shifted, q)


def _shoulder_in_turn(arm: np.ndarray) -> np.ndarray:
    """The arm's joints with the shoulder's lift written in :data:`SHOULDER_TURN`."""
    lo, hi = SHOULDER_TURN
    out = np.array(arm, float)
    if not lo <= out[1] < hi:  # (only then: the same value written back may differ in its last bit)
        out[1] = lo + (out[1] - lo) % (hi - lo)
    return out


def angle_to(a: float, b: float) -> float:
    """``b`` unwrapped to within half a turn of ``a``."""
    return a + math.remainder(b - a, 2 * math.pi)
