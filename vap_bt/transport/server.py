"""SkillServer: one robot's skills (and camera) offered over Zenoh.

For every action it hosts the server declares a queryable on ``vap/<robot>/skill/<action>``.
A goal request is decided on the spot — accepted, or rejected because the action's resource is
busy with another goal — and answered at once; the goal itself then runs on the worker thread of
its resource (one long-lived thread per resource, so two goals never share an arm and Zenoh's
own threads never run a skill). While it runs, every ``ctx.feedback`` is published on
``vap/<robot>/goal/<id>/status``; the final result follows on the same key. A message on
``vap/<robot>/goal/<id>/cancel`` sets the goal's cancel flag, which the skill sees as
``ctx.cancelled()``.

The server's presence is a liveliness token ``vap/<robot>/alive/<name>``, declared after every
queryable so that a client that sees it finds them all there; when the process dies or hangs,
Zenoh drops the token and clients fail that server's goals at once. Each goal has a token of its
own while it runs, ``vap/<robot>/alive/<name>/goal/<action>/<id>`` (declared by its worker as it
starts, withdrawn once its result is published), which is how ``vap-bt parts`` sees the goals in
flight: two messages per goal, nothing per feedback.

Each goal is logged (INFO, this module's logger; ``vap-bt serve`` shows it) one line per event —
accepted, rejected, cancel requested, the result — each naming the robot, the goal id, the action
with its arguments and the skill class. Feedback is throttled: a goal's first feedback is logged,
then at most one line per :data:`FEEDBACK_LOG_S` seconds, which says how many samples went unlogged
since the line before (a skill that reports every control cycle writes one line a second, not
hundreds).

Given a world (or anything with the camera and body interfaces of :mod:`vap_bt.robot.camera`),
the server also answers ``vap/<robot>/camera/{capture,view,move}`` and
``vap/<robot>/body/{state,map}``; given a world-side VLM (the simulated one), ``vap/<robot>/vlm/ask``.
Those run on Zenoh's Python callback thread, not its network threads, and a failing world
becomes an error reply, never a dead server.
"""

from __future__ import annotations

import logging
import queue
import threading
import time
from dataclasses import dataclass, field
from typing import Any, Callable

import zenoh

from vap_bt.skill import Feedback, GoalState, Skill
from vap_bt.transport import keys
from vap_bt.transport.execution import GoalRun, run_goal
from vap_bt.transport.messages import (
    CancelRequest,
    ErrorReply,
    GoalReply,
    GoalRequest,
    GoalStatus,
    MessageError,
    CaptureRequest,
    MapRequest,
    MoveViewReply,
    MoveViewRequest,
    StateRequest,
    ViewRequest,
    VlmRequest,
    decode,
    encode,
)
from vap_bt.robot.frame import marked_frame

log = logging.getLogger(__name__)

#: a running goal's feedback is logged at most once per this many seconds (the first at once)
FEEDBACK_LOG_S = 1.0


@dataclass
class _Goal:
    goal_id: str
    skill: Skill
    args: tuple[str, ...]
    run: GoalRun
    action: str
    label: str  # how every log line names the goal: ``goal ID action(args) [Skill]``
    started: float = field(default_factory=time.monotonic)


class SkillServer:
    """Hosts ``skills`` (action -> Skill) for ``robot`` on an open Zenoh ``session``.

    The session stays the caller's; :meth:`close` withdraws what the server declared.
    """

    def __init__(
        self,
        session: zenoh.Session,
        robot: str,
        skills: dict[str, Skill],
        camera: Any | None = None,
        name: str | None = None,
        vlm: Any | None = None,
    ) -> None:
        self.session = session
        self.robot = keys.chunk("robot", robot)
        self.skills = dict(skills)
        self.camera = camera
        self.vlm = vlm
        self.name = keys.chunk("server", name or keys.instance(robot, session.zid()))
        self._lock = threading.Lock()
        self._goals: dict[str, _Goal] = {}
        self._busy: dict[str, str] = {}  # resource -> goal id
        self._queues: dict[str, queue.SimpleQueue[_Goal | None]] = {}
        self._threads: list[threading.Thread] = []
        self._declared: list[Any] = []
        self._token: Any = None

    # -- lifecycle -------------------------------------------------------------------------------

    def start(self) -> "SkillServer":
        """Start a worker thread per resource and declare every queryable, then the server's liveliness
        token (last: a client that sees it finds them all); returns self."""
        for resource in sorted({s.resource for s in self.skills.values()}):
            self._queues[resource] = q = queue.SimpleQueue()
            t = threading.Thread(target=self._work, args=(q,), name=f"skill-{resource}", daemon=True)
            t.start()
            self._threads.append(t)
        declare = self.session.declare_queryable
        fast = _network_callback  # replies are decided without blocking: no thread hop
        self._declared.append(
            self.session.declare_subscriber(keys.all_goal_cancel(self.robot), fast(self._on_cancel))
        )
        for action in self.skills:
            key = zenoh.KeyExpr(keys.skill(self.robot, action))  # parsed once, used per reply
            on_query = fast(lambda q, a=action, k=key: self._on_goal(q, a, k))
            self._declared.append(declare(key, on_query))
        if self.camera is not None:
            for verb, handler in (("capture", self._capture), ("view", self._goto_view), ("move", self._move_view)):
                self._declared.append(declare(keys.camera(self.robot, verb), _camera_reply(handler)))
            for verb, handler in (("state", self._state), ("map", self._map)):
                self._declared.append(declare(keys.body(self.robot, verb), _camera_reply(handler)))
        if self.vlm is not None:
            self._declared.append(declare(keys.vlm(self.robot), _camera_reply(self._ask)))
        # announce last: a client that sees the token must find every queryable already there
        self._token = self.session.liveliness().declare_token(keys.alive(self.robot, self.name))
        log.info("skill server %s hosts %s on robot %s", self.name, sorted(self.skills), self.robot)
        return self

    def close(self) -> None:
        """Withdraw the token and queryables, cancel running goals, stop the workers."""
        if self._token is not None:
            self._token.undeclare()
            self._token = None
        for entity in self._declared:
            entity.undeclare()
        self._declared.clear()
        with self._lock:
            for goal in self._goals.values():
                goal.run.request_cancel()
        for q in self._queues.values():
            q.put(None)
        for t in self._threads:
            t.join(timeout=5.0)
        self._threads.clear()

    def __enter__(self) -> "SkillServer":
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- goals -----------------------------------------------------------------------------------

    def _on_goal(self, query: zenoh.Query, action: str, key: zenoh.KeyExpr) -> None:
        payload = query.payload
        try:
            req = decode(b"" if payload is None else payload.to_bytes(), GoalRequest)
        except MessageError as exc:
            query.reply_err(f"bad goal request for {action}: {exc}")
            return
        goal = self._admit(req, action)
        accepted = isinstance(goal, _Goal)
        reason = "" if accepted else goal
        reply = GoalReply(req.goal_id, accepted, reason, self.name)
        query.reply(key, encode(reply), express=True)  # no batching delay
        if accepted:  # queued only after the reply, so the client hears "accepted" first
            self._queues[goal.skill.resource].put(goal)
        else:
            log.info("%s goal %s %s: rejected: %s", self.robot, req.goal_id, _call(action, req.args), reason)

    def _admit(self, req: GoalRequest, action: str) -> "_Goal | str":
        """Register the goal and claim its resource; the rejection reason otherwise."""
        if req.action != action:
            return f"request for {req.action!r} sent to the {action!r} queryable"
        try:
            keys.chunk("goal", req.goal_id)
        except ValueError as exc:
            return str(exc)
        if not all(isinstance(a, str) for a in req.args):
            return f"arguments of {action} must be strings, got {req.args!r}"
        skill = self.skills[action]
        with self._lock:
            if req.goal_id in self._goals:
                return f"goal id {req.goal_id} is already in use"
            holder = self._busy.get(skill.resource)
            if holder is not None:
                return (
                    f"resource {skill.resource!r} of robot {self.robot} is busy with goal "
                    f"{holder}; send {action} again when it has ended"
                )
            label = f"goal {req.goal_id} {_call(action, req.args)} [{type(skill).__name__}]"
            run = GoalRun(on_feedback=self._feedback_publisher(req.goal_id, label), hints=req.hints)
            goal = self._goals[req.goal_id] = _Goal(req.goal_id, skill, tuple(req.args), run, action, label)
            self._busy[skill.resource] = req.goal_id
        return goal

    def _work(self, q: "queue.SimpleQueue[_Goal | None]") -> None:
        while (goal := q.get()) is not None:
            log.info("%s %s: accepted", self.robot, goal.label)
            token = self._goal_token(goal)
            state, result = run_goal(goal.skill, goal.args, goal.run)
            with self._lock:  # free the resource before telling the client, so it can resend
                self._goals.pop(goal.goal_id, None)
                self._busy.pop(goal.skill.resource, None)
            self._publish(GoalStatus(goal.goal_id, state, goal.run.last_feedback, result, self.name))
            log.info("%s %s: %s after %.2f s: %s", self.robot, goal.label, state.value, time.monotonic() - goal.started,
                     result.message or "(no message)")
            if token is not None:
                _undeclare(token)

    def _goal_token(self, goal: _Goal) -> Any:
        """The goal's liveliness token (None if the session is closing: the goal runs regardless)."""
        try:
            return self.session.liveliness().declare_token(
                keys.goal_alive(self.robot, self.name, goal.action, goal.goal_id))
        except zenoh.ZError as exc:
            log.debug("no liveliness token for %s: %s", goal.label, exc)
            return None

    def _feedback_publisher(self, goal_id: str, label: str) -> Callable[[Feedback], None]:
        logged_at: float | None = None  # when the last feedback line was logged
        skipped = 0  # samples since then

        def publish(fb: Feedback) -> None:
            nonlocal logged_at, skipped
            self._publish(GoalStatus(goal_id, GoalState.ACTIVE, fb, None, self.name))
            now = time.monotonic()
            if logged_at is not None and now - logged_at < FEEDBACK_LOG_S:
                skipped += 1
                return
            more = f" ({skipped} more sample{'s' * (skipped > 1)} since the last line)" if skipped else ""
            log.info("%s %s: feedback %.0f%% %s%s", self.robot, label, 100 * fb.progress, fb.text, more)
            logged_at, skipped = now, 0

        return publish

    def _publish(self, status: GoalStatus) -> None:
        final = status.state.terminal  # a result must not be dropped under congestion
        self.session.put(
            keys.goal_status(self.robot, status.goal_id),
            encode(status),
            congestion_control=zenoh.CongestionControl.BLOCK if final else zenoh.CongestionControl.DROP,
            express=True,
        )

    def _on_cancel(self, sample: zenoh.Sample) -> None:
        try:
            goal_id = decode(sample.payload.to_bytes(), CancelRequest).goal_id
        except MessageError as exc:
            log.warning("ignored a bad cancel on %s: %s", sample.key_expr, exc)
            return
        with self._lock:
            goal = self._goals.get(goal_id)
        if goal is not None:
            goal.run.request_cancel()
            log.info("%s %s: cancel requested", self.robot, goal.label)

    # -- camera ----------------------------------------------------------------------------------

    def _capture(self, payload: bytes) -> Any:
        return self.camera.capture(decode(payload, CaptureRequest).aim)

    def _goto_view(self, payload: bytes) -> Any:
        return MoveViewReply(bool(self.camera.goto_view(decode(payload, ViewRequest).view)))

    def _move_view(self, payload: bytes) -> Any:
        req = decode(payload, MoveViewRequest)
        return MoveViewReply(bool(self.camera.move_view(req.aim, req.direction)))

    def _state(self, payload: bytes) -> Any:
        decode(payload, StateRequest)
        return self.camera.state()

    def _map(self, payload: bytes) -> Any:
        decode(payload, MapRequest)
        return self.camera.site_map()

    def _ask(self, payload: bytes) -> Any:
        req = decode(payload, VlmRequest)
        # the world-side VLM knows its camera's frames by id: the pixels need not travel back
        return self.vlm.ask(req.query, marked_frame(req.frame_id, req.identified))


def _call(action: str, args: tuple[str, ...]) -> str:
    return f"{action}({', '.join(map(str, args))})"


def _undeclare(entity: Any) -> None:
    try:
        entity.undeclare()
    except zenoh.ZError:  # the session closed under it: the token went with it
        pass


def _network_callback(fn: Callable[[Any], None]) -> zenoh.handlers.Callback:
    """Run ``fn`` directly on Zenoh's receiving thread; ``fn`` must never block."""
    return zenoh.handlers.Callback(fn, indirect=False)


def _camera_reply(handler: Callable[[bytes], Any]) -> Callable[[zenoh.Query], None]:
    """A queryable callback that answers with ``handler``'s message, or an ErrorReply."""

    def on_query(query: zenoh.Query) -> None:
        payload = query.payload.to_bytes() if query.payload else b""
        try:
            answer = handler(payload)
        except MessageError as exc:
            answer = ErrorReply(f"bad camera request: {exc}")
        except Exception as exc:  # the world's failure is the caller's answer, not our crash
            answer = ErrorReply(f"camera failed: {type(exc).__name__}: {exc}")
        query.reply(query.key_expr, encode(answer))

    return on_query
