"""The robot's drivers over Zenoh: served where the robot is, used by skills anywhere.

A robot's arm, gripper, base and wrist camera (:mod:`vap_bt.robot.drivers`) live in one process
— a simulator's, or a real robot's driver host. :class:`DriverServer` offers them on Zenoh and
:class:`RemoteDrivers` gives a skill server in another process objects with the very same
interfaces, so a skill cannot tell where the robot is::

    vap/<robot>/driver/<call>            queryable: DriverCall -> DriverReply (or a Frame)
    vap/<robot>/driver/stop              published: stop a part's motion (DriverCall "stop")
    vap/<robot>/driver-client/<client>   liveliness token of a RemoteDrivers
    vap/<robot>/driver-host              liveliness token of the DriverServer (the robot's process)

``<call>`` is one of ``arm.state``, ``arm.tcp``, ``arm.follow``, ``arm.stop``, ``gripper.state``,
``gripper.move``, ``base.pose``, ``base.follow``, ``base.stop``, ``camera.capture``, and the
body's ``state`` and ``map``.

A motion (``arm.follow``, ``gripper.move``, ``base.follow``) blocks its caller until it ends, as
the local driver does. The server runs it on a worker thread of its own (one per part: the arm
and the base may move at once, each one motion at a time) and replies when it ends; the proxy
waits for that reply, polling the caller's ``cancelled()`` — when it turns true the proxy
publishes a stop for that part, and the motion ends at its next control cycle with
"cancelled". A proxy's liveliness token is its heartbeat: when the process that commanded a
motion dies, Zenoh drops the token and the server stops that client's motions at once — the
robot never finishes a trajectory for a skill that no longer exists (a real arm's protective
stop on a lost stream). A motion whose reply never comes (the driver host died) ends as not
completed, "transport", after its own duration plus ``MOTION_SLACK_S``.

The other way round, the server's own token (``driver-host``, declared once everything else is)
is the robot's heartbeat: :class:`HostWatch` tells a process whose skills drive the robot from
afar that the robot's process has gone — stopped, died (its link closed at once) or hung past
the link lease — rather than letting it wait, silent, for calls nobody will answer.
"""

from __future__ import annotations

import logging
import threading
import time
import uuid
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np
import zenoh

from vap_bt.errors import TransportError
from vap_bt.robot.drivers import Cancelled, GripperState, JointState, JointTrajectory
from vap_bt.outcome import Outcome
from vap_bt.robot.frame import Frame
from vap_bt.transport import keys
from vap_bt.transport.messages import DriverCall, DriverReply, ErrorReply, MessageError, decode, encode

log = logging.getLogger(__name__)

#: a quick call (a state, a pose, a frame) that takes longer than this has failed
CALL_TIMEOUT_S = 10.0
#: a motion's reply may come this long after the motion's own duration (settling, transport)
MOTION_SLACK_S = 30.0
#: the proxy looks at ``cancelled()`` this often while a motion runs
POLL_S = 0.005
MOTIONS = {"arm.follow": "arm", "gripper.move": "gripper", "base.follow": "base"}


def driver_key(robot: str, call: str) -> str:
    """The queryable of driver call ``call`` (``arm.follow``, ``state``, ...) on ``robot``."""
    return f"{keys.ROOT}/{keys.chunk('robot', robot)}/driver/{keys.chunk('driver call', call)}"


def client_token_key(robot: str, client: str) -> str:
    """The liveliness token of :class:`RemoteDrivers` ``client`` on ``robot``: its heartbeat."""
    return f"{keys.ROOT}/{keys.chunk('robot', robot)}/driver-client/{keys.chunk('client', client)}"


def host_token_key(robot: str) -> str:
    """The liveliness token of ``robot``'s :class:`DriverServer`: the robot process's heartbeat."""
    return f"{keys.ROOT}/{keys.chunk('robot', robot)}/driver-host"


# -- server ----------------------------------------------------------------------------------------


@dataclass
class _Motion:
    part: str
    client: str


class DriverServer:
    """Serves ``robot``'s drivers (objects with ``arm``, ``gripper``, ``base``, ``camera`` and the
    body's ``state()``/``site_map()``) on an open Zenoh ``session``."""

    def __init__(self, session: zenoh.Session, robot: str, drivers: Any, body: Any) -> None:
        self.session, self.robot = session, keys.chunk("robot", robot)
        self.drivers, self.body = drivers, body
        self._declared: list[Any] = []
        self._lock = threading.Lock()
        self._running: dict[str, _Motion] = {}  # part -> the motion it runs
        self._part_locks = {p: threading.Lock() for p in ("arm", "gripper", "base")}

    def start(self) -> "DriverServer":
        """Declare every driver call, the stop subscriber and the client watch, then the host token
        (last: whoever sees it finds every call answered); returns self."""
        quick: dict[str, Callable[[DriverCall], Any]] = {
            "arm.state": lambda c: _joint_reply(self.drivers.arm.joint_state()),
            "arm.tcp": lambda c: DriverReply({}, {"pose": np.asarray(self.drivers.arm.tcp_pose(), float)}),
            "gripper.state": lambda c: _gripper_reply(self.drivers.gripper.state()),
            "base.pose": lambda c: DriverReply({"pose": list(map(float, self.drivers.base.pose()))}),
            "base.odometry": lambda c: DriverReply({"pose": list(map(float, self.drivers.base.odometry()))}),
            "camera.capture": lambda c: self.drivers.camera.capture(),
            "state": lambda c: self.body.state(),
            "map": lambda c: self.body.site_map(),
        }
        for call, handler in quick.items():
            self._declared.append(self.session.declare_queryable(driver_key(self.robot, call), _answer(handler)))
        for call in MOTIONS:
            self._declared.append(self.session.declare_queryable(
                driver_key(self.robot, call), lambda q, c=call: self._on_motion(q, c)))
        self._declared.append(self.session.declare_subscriber(driver_key(self.robot, "stop"), self._on_stop))
        self._declared.append(self.session.liveliness().declare_subscriber(
            f"{keys.ROOT}/{self.robot}/driver-client/*", self._on_client))
        # last: whoever sees the token finds every call above answered
        self._declared.append(self.session.liveliness().declare_token(host_token_key(self.robot)))
        log.info("driver server for robot %s up", self.robot)
        return self

    def close(self) -> None:
        for entity in self._declared:
            entity.undeclare()
        self._declared.clear()
        for part in ("arm", "base"):
            self._stop_part(part)

    # -- motions ---------------------------------------------------------------------------------

    def _on_motion(self, query: zenoh.Query, call: str) -> None:
        try:
            msg = decode(query.payload.to_bytes() if query.payload else b"", DriverCall)
        except MessageError as exc:
            query.reply(query.key_expr, encode(ErrorReply(f"bad driver call {call}: {exc}")))
            return
        threading.Thread(target=self._run_motion, args=(query, call, msg), name=f"driver-{call}", daemon=True).start()

    def _run_motion(self, query: zenoh.Query, call: str, msg: DriverCall) -> None:
        part = MOTIONS[call]
        try:
            with self._part_locks[part]:  # one motion per part at a time, in arrival order
                with self._lock:
                    self._running[part] = _Motion(part, msg.client)
                try:
                    reply = self._move(call, msg)
                finally:
                    with self._lock:
                        self._running.pop(part, None)
        except Exception as exc:  # the driver's failure is the caller's answer, not our crash
            log.exception("driver call %s failed", call)
            reply = ErrorReply(f"driver {call} failed: {type(exc).__name__}: {exc}")
        query.reply(query.key_expr, encode(reply))

    def _move(self, call: str, msg: DriverCall) -> DriverReply:
        never: Cancelled = lambda: False  # noqa: E731 - a stop reaches the driver through stop()
        if call == "arm.follow":
            a = msg.arrays
            traj = JointTrajectory(tuple(msg.values["joints"]), a["times"], a["positions"], a.get("velocities"))
            return _motion_reply(self.drivers.arm.follow(traj, never))
        if call == "base.follow":
            path = [tuple(map(float, p)) for p in msg.values["path"]]
            return _motion_reply(self.drivers.base.follow(path, float(msg.values["speed"]), never))
        return _gripper_reply(self.drivers.gripper.move(float(msg.values["width"]), float(msg.values["force"]), never))

    def _on_stop(self, sample: zenoh.Sample) -> None:
        try:
            msg = decode(sample.payload.to_bytes(), DriverCall)
        except MessageError:
            return
        self._stop_part(str(msg.values.get("part", "")))

    def _stop_part(self, part: str) -> None:
        driver = getattr(self.drivers, part, None) if part in ("arm", "base") else None
        if driver is not None:
            driver.stop()

    def _on_client(self, sample: zenoh.Sample) -> None:
        if sample.kind != zenoh.SampleKind.DELETE:
            return
        client = keys.last_chunks(sample.key_expr, 1)[0]
        with self._lock:
            lost = [m.part for m in self._running.values() if m.client == client]
        for part in lost:  # the commander is gone: its motion must not go on
            log.warning("driver client %s vanished: stopping the %s", client, part)
            self._stop_part(part)


def _answer(handler: Callable[[DriverCall], Any]) -> Callable[[zenoh.Query], None]:
    def on_query(query: zenoh.Query) -> None:
        try:
            answer = handler(decode(query.payload.to_bytes() if query.payload else b"", DriverCall))
        except MessageError as exc:
            answer = ErrorReply(f"bad driver call: {exc}")
        except Exception as exc:  # noqa: BLE001
            answer = ErrorReply(f"driver failed: {type(exc).__name__}: {exc}")
        query.reply(query.key_expr, encode(answer))

    return on_query


def _joint_reply(s: JointState) -> DriverReply:
    return DriverReply({"joints": list(s.joints), "positions": list(s.positions), "velocities": list(s.velocities)})


def _gripper_reply(s: GripperState) -> DriverReply:
    return DriverReply({"width": float(s.width), "holding": bool(s.holding)})


def _motion_reply(r: Outcome) -> DriverReply:
    return DriverReply({"completed": bool(r.completed), "message": r.message})


# -- client ----------------------------------------------------------------------------------------


class HostWatch:
    """Calls ``on_lost`` when ``robot``'s driver host withdraws its token (it stopped, died or hung
    past the lease). Zenoh tells a subscriber of the loss only of a token it was told of, and the
    history that tells it comes a round trip after the subscriber: :attr:`seen` is set once it
    has, and a host lost before that is never reported (so wait for it before relying on this)."""

    def __init__(self, session: zenoh.Session, robot: str, on_lost: Callable[[], None]) -> None:
        self._on_lost = on_lost
        self.seen = threading.Event()
        self._subscriber = session.liveliness().declare_subscriber(host_token_key(robot), self._on_sample,
                                                                   history=True)

    def _on_sample(self, sample: zenoh.Sample) -> None:
        if sample.kind == zenoh.SampleKind.DELETE:
            self._on_lost()
        else:
            self.seen.set()

    def close(self) -> None:
        self._subscriber.undeclare()


class _Link:
    """Calls on one robot's driver keys from one client (its liveliness token is the heartbeat)."""

    def __init__(self, session: zenoh.Session, robot: str) -> None:
        self.session, self.robot = session, keys.chunk("robot", robot)
        self.client = f"c{uuid.uuid4().hex[:12]}"
        self._token = session.liveliness().declare_token(client_token_key(self.robot, self.client))

    def close(self) -> None:
        self._token.undeclare()

    def call(self, call: str, values: dict | None = None, arrays: dict | None = None,
             expect: type = DriverReply, timeout: float = CALL_TIMEOUT_S) -> Any:
        msg = encode(DriverCall(call, self.client, dict(values or {}), dict(arrays or {})))
        for reply in self.session.get(driver_key(self.robot, call), payload=msg, timeout=timeout):
            return self._read(call, reply, expect)
        raise TransportError(f"no driver of robot {self.robot!r} answered {call} within {timeout:g} s")

    def motion(self, call: str, values: dict, arrays: dict | None, duration: float, cancelled: Cancelled) -> Any:
        """Start a motion and wait for its end, stopping it when ``cancelled()`` turns true."""
        msg = encode(DriverCall(call, self.client, values, dict(arrays or {})))
        timeout = duration + MOTION_SLACK_S
        replies = self.session.get(driver_key(self.robot, call), payload=msg, timeout=timeout)
        stopped = False
        deadline = time.monotonic() + timeout + 1.0
        while time.monotonic() < deadline:
            try:
                reply = replies.try_recv()
            except zenoh.ZError:  # closed without an answer
                break
            if reply is not None:
                return self._read(call, reply, DriverReply)
            if not stopped and cancelled():
                self.session.put(driver_key(self.robot, "stop"),
                                 encode(DriverCall("stop", self.client, {"part": MOTIONS[call]}, {})))
                stopped = True
            time.sleep(POLL_S)
        return None

    def _read(self, call: str, reply: zenoh.Reply, expect: type) -> Any:
        if reply.ok is None:
            raise TransportError(f"driver {call} on robot {self.robot}: {reply.err.payload.to_string()}")
        payload = reply.ok.payload.to_bytes()
        try:
            return decode(payload, expect)
        except MessageError:
            try:
                reason = decode(payload, ErrorReply).reason
            except MessageError as exc:
                reason = str(exc)
            raise TransportError(f"driver {call} on robot {self.robot}: {reason}") from None


def _motion_result(reply: DriverReply | None, cancelled: Cancelled) -> Outcome:
    if reply is None:
        return Outcome(False, "transport: the driver host did not answer")
    done, why = bool(reply.values["completed"]), str(reply.values.get("message", ""))
    if not done and why == "stopped" and cancelled():
        why = "cancelled"
    return Outcome(done, why)


@dataclass
class RemoteArm:
    """:class:`~vap_bt.robot.drivers.Arm` of a robot served elsewhere."""

    link: _Link

    def joint_state(self) -> JointState:
        v = self.link.call("arm.state").values
        return JointState(tuple(v["joints"]), tuple(v["positions"]), tuple(v["velocities"]))

    def tcp_pose(self) -> np.ndarray:
        return self.link.call("arm.tcp").arrays["pose"]

    def follow(self, trajectory: JointTrajectory, cancelled: Cancelled) -> Outcome:
        arrays = {"times": np.asarray(trajectory.times, float), "positions": np.asarray(trajectory.positions, float)}
        if trajectory.velocities is not None:
            arrays["velocities"] = np.asarray(trajectory.velocities, float)
        try:
            reply = self.link.motion("arm.follow", {"joints": list(trajectory.joints)}, arrays,
                                     trajectory.duration, cancelled)
        except TransportError as exc:
            return Outcome(False, f"transport: {exc}")
        return _motion_result(reply, cancelled)

    def stop(self) -> None:
        self.link.session.put(driver_key(self.link.robot, "stop"),
                              encode(DriverCall("stop", self.link.client, {"part": "arm"}, {})))


@dataclass
class RemoteGripper:
    """:class:`~vap_bt.robot.drivers.Gripper` of a robot served elsewhere."""

    link: _Link

    def state(self) -> GripperState:
        v = self.link.call("gripper.state").values
        return GripperState(float(v["width"]), bool(v["holding"]))

    def move(self, width: float, force: float, cancelled: Cancelled) -> GripperState:
        try:
            reply = self.link.motion("gripper.move", {"width": float(width), "force": float(force)}, None, 2.0,
                                     cancelled)
        except TransportError:
            reply = None
        if reply is None:
            return self.state()
        return GripperState(float(reply.values["width"]), bool(reply.values["holding"]))


@dataclass
class RemoteBase:
    """:class:`~vap_bt.robot.drivers.Base` of a robot served elsewhere."""

    link: _Link

    def pose(self) -> tuple[float, float, float]:
        return tuple(map(float, self.link.call("base.pose").values["pose"]))

    def odometry(self) -> tuple[float, float, float]:
        return tuple(map(float, self.link.call("base.odometry").values["pose"]))

    def follow(self, path: list[tuple[float, float, float]], speed: float, cancelled: Cancelled) -> Outcome:
        here = np.array(self.pose()[:2])
        length = sum(float(np.linalg.norm(np.array(b[:2]) - np.array(a[:2])))
                     for a, b in zip([tuple(here), *path], path))
        duration = 10.0 + 4.0 * length / max(speed, 0.05)  # generous: ruckig's time is the server's
        try:
            reply = self.link.motion("base.follow", {"path": [list(map(float, p)) for p in path], "speed": float(speed)},
                                     None, duration, cancelled)
        except TransportError as exc:
            return Outcome(False, f"transport: {exc}")
        return _motion_result(reply, cancelled)

    def stop(self) -> None:
        self.link.session.put(driver_key(self.link.robot, "stop"),
                              encode(DriverCall("stop", self.link.client, {"part": "base"}, {})))


@dataclass
class RemoteCamera:
    """:class:`~vap_bt.robot.drivers.WristCamera` of a robot served elsewhere."""

    link: _Link

    def capture(self) -> Frame:
        return self.link.call("camera.capture", expect=Frame)


@dataclass
class RemoteDrivers:
    """A robot's drivers and body, served by a :class:`DriverServer` elsewhere, with the same
    interfaces as local ones (what :func:`skills.kit.kit_for` needs)."""

    session: zenoh.Session
    robot: str
    link: _Link = field(init=False)

    def __post_init__(self) -> None:
        self.link = _Link(self.session, self.robot)
        self.arm, self.gripper = RemoteArm(self.link), RemoteGripper(self.link)
        self.base, self.camera = RemoteBase(self.link), RemoteCamera(self.link)
        self._map = None
        self._stamp = float("-inf")

    @property
    def drivers(self) -> "RemoteDrivers":
        """Itself: it has the four drivers (what :func:`vap_bt.robot.drivers.has_drivers` looks for)."""
        return self

    def state(self):
        from vap_bt.robot.state import RobotState

        state = self.link.call("state", expect=RobotState)
        if float(state.stamp) < self._stamp:  # the robot's clock went back: a new episode, maybe a new site
            self._map = None
        self._stamp = float(state.stamp)
        return state

    def site_map(self):
        from vap_bt.robot.site_map import SiteMap

        if self._map is None:  # the map is static within an episode: asked once per episode
            self._map = self.link.call("map", expect=SiteMap)
        return self._map

    def close(self) -> None:
        self.link.close()
