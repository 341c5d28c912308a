"""ZenohSkillClient, ZenohRobot and ZenohVLM: the executive's side of the Zenoh transport.

``send_goal`` never blocks. It picks a goal id, sends a :class:`GoalRequest` through a cached
Querier on ``vap/<robot>/skill/<action>`` and returns a :class:`ZenohGoalHandle` in PENDING.
What happens next updates the handle under the client's lock:

* the reply           -> ACTIVE (accepted) or REJECTED (with the server's reason);
* no reply at all     -> REJECTED ("no skill server ... answered");
* a status message    -> new feedback, or the terminal state and result;
* the server's liveliness token disappears -> every goal in flight on it ABORTED, "server vanished".

A goal that failed because its robot has no server left (vanished, or nobody answered) is not
the skill's failure but the transport's: :meth:`ZenohSkillClient.rejoin`, which the executive
calls before it replans an execution failure, waits up to :data:`REJOIN_TIMEOUT_S` for a server
of that robot to be up again (a restarted ``vap-bt serve``), and otherwise raises
:class:`~vap_bt.errors.TransportError` naming the robot, so the episode ends "transport down"
instead of replanning against a robot nobody drives.

The reply is the latency-critical step (a behaviour reports RUNNING once it is in), so it does not
go through a Python callback: Zenoh puts it in the query's own channel without taking the GIL,
and the handle reads it whenever someone looks — :meth:`~ZenohGoalHandle.state` takes it without
blocking, ``wait_answered``/``wait`` block on the channel itself, so the waiting thread wakes
straight from Zenoh's receiving thread instead of through a callback, a lock and a GIL hand-off.
Status messages and liveliness changes, which nobody waits on so tightly, stay on callbacks.

The client listens before it asks: per robot it subscribes to ``vap/<robot>/goal/*/status`` and
to the robots' liveliness tokens when it is created, so no early feedback or fast result is lost,
and it only ever subscribes to the namespaces of its own robots.

Which robot hosts which action comes from the plugin registry (:func:`vap_bt.plugins.routes`)
unless a routing table is passed in.
"""

from __future__ import annotations

import itertools
import threading
import time
from typing import Any, Iterable, Mapping

import zenoh

from vap_bt import plugins
from vap_bt.errors import TransportError
from vap_bt.skill import Feedback, GoalHandle, GoalState, Hint, SkillResult
from vap_bt.transport import keys
from vap_bt.transport.config import CAMERA_TIMEOUT_S, REJOIN_TIMEOUT_S
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
from vap_bt.perception.vlm import Answer, Query
from vap_bt.robot.camera import Aim, Viewpoint
from vap_bt.robot.frame import Frame
from vap_bt.robot.site_map import SiteMap
from vap_bt.robot.state import RobotState

#: how long a goal request may wait for its server's accept/reject
ACCEPT_TIMEOUT_S = 5.0


class ZenohGoalHandle(GoalHandle):
    """A goal in flight on a remote skill server.

    Status and liveliness callbacks update it; its accept/reject reply is read from the query's
    channel by whichever thread looks at it first (:meth:`state`, :meth:`wait_answered`,
    :meth:`wait`), so a PENDING goal only turns ACTIVE or REJECTED when someone asks.
    """

    def __init__(self, client: "ZenohSkillClient", goal_id: str, robot: str, action: str) -> None:
        super().__init__(goal_id)
        self.robot = robot
        self.action = action
        self.server = ""
        self._client = client
        self._replies: Any = None  # the request's reply channel until its answer is read
        self._expires = 0.0  # monotonic time by which Zenoh closes that channel
        self._reading = threading.Lock()  # one reader of the channel at a time

    def state(self) -> GoalState:
        if self._replies is not None:
            self._client._read_reply(self, 0.0)
        return self._state

    def cancel(self) -> None:
        if not self._state.terminal:
            self._client._cancel(self)

    def wait(self, timeout: float | None = None) -> GoalState:
        """Block until the goal ends (tools and tests; behaviours poll :meth:`state`)."""
        deadline = None if timeout is None else time.monotonic() + timeout
        self.wait_answered(timeout)  # a rejection only ever comes as the reply
        if not self._state.terminal:
            self._client._wait_for(lambda: self._state.terminal, deadline)
        return self._state

    def wait_answered(self, timeout: float | None = None) -> GoalState:
        """Block until the server accepted or the goal ended."""
        deadline = None if timeout is None else time.monotonic() + timeout
        if self._replies is not None:
            self._client._read_reply(self, timeout)
        if self._state is GoalState.PENDING:
            self._client._wait_for(lambda: self._state is not GoalState.PENDING, deadline)
        return self._state

    # state changes: called by the client with its lock held
    def _activate(self, server: str) -> None:
        if self._state is GoalState.PENDING:
            self._state = GoalState.ACTIVE
            self.server = server
            self._client._changed.notify_all()

    def _finish(self, state: GoalState, result: SkillResult) -> None:
        if not self._state.terminal:
            self._result, self._state = result, state
            self._client._changed.notify_all()


class ZenohSkillClient:
    """A :class:`~vap_bt.skill.SkillClient` that sends goals to skill servers over Zenoh."""

    def __init__(
        self,
        session: zenoh.Session,
        routes: Mapping[str, str] | None = None,
        *,
        accept_timeout: float = ACCEPT_TIMEOUT_S,
        rejoin_timeout: float = REJOIN_TIMEOUT_S,
        owns_session: bool = False,
    ) -> None:
        self.session = session
        self.routes = dict(plugins.routes(plugins.discover_skills()) if routes is None else routes)
        self.accept_timeout, self.rejoin_timeout = accept_timeout, rejoin_timeout
        self._owns_session = owns_session
        self._prefix = str(session.zid())[:12]
        self._ids = itertools.count(1)
        self._lock = threading.Lock()
        self._changed = threading.Condition(self._lock)  # any handle changed state
        self._inflight: dict[str, ZenohGoalHandle] = {}
        self._alive: dict[str, set[str]] = {}
        self._queriers: dict[tuple[str, str], zenoh.Querier] = {}
        self._declared: list[Any] = []
        for robot in sorted(set(self.routes.values())):
            self._watch(robot)

    # -- SkillClient -----------------------------------------------------------------------------

    def send_goal(self, action: str, args: tuple[str, ...], hints: tuple[Hint, ...] = ()) -> ZenohGoalHandle:
        robot = self.routes.get(action)
        handle = ZenohGoalHandle(self, f"{self._prefix}-{next(self._ids)}", robot or "", action)
        if robot is None:
            known = ", ".join(sorted(self.routes)) or "none"
            with self._lock:
                handle._finish(GoalState.REJECTED, SkillResult(
                    False, f"no skill plugin binds action {action!r} (known: {known})"))
            return handle
        payload = encode(GoalRequest(handle.goal_id, action, tuple(args), self._prefix, tuple(hints)))
        querier = self._querier(robot, action)
        with self._lock:
            self._inflight[handle.goal_id] = handle
        handle._expires = time.monotonic() + self.accept_timeout
        handle._replies = querier.get(payload=payload)  # a channel: see the module docstring
        return handle

    def servers(self, robot: str) -> frozenset[str]:
        """The names of ``robot``'s skill servers whose liveliness tokens are up now."""
        with self._lock:
            return frozenset(self._alive.get(robot, ()))

    def rejoin(self, action: str, timeout: float | None = None) -> str | None:
        """Make sure a skill server hosts ``action``'s robot: None when one is up now; a sentence
        when one came up within ``timeout`` (a restarted server); else a TransportError naming the
        robot and the command that serves it (``timeout``: the client's ``rejoin_timeout``). Blocks:
        called between trees, never from a tick."""
        timeout = self.rejoin_timeout if timeout is None else timeout
        robot = self.routes.get(action)
        if robot is None:
            return None
        t0 = time.monotonic()
        with self._changed:
            if self._alive.get(robot):
                return None
            if self._changed.wait_for(lambda: self._alive.get(robot), timeout):
                back = ", ".join(sorted(self._alive[robot]))
                return f"skill server {back} of robot {robot!r} is up again after {time.monotonic() - t0:.1f} s"
        raise TransportError(f"the skill server of robot {robot!r} is gone (it ran {action}) and none came "
                             f"back within {timeout:g} s (start `vap-bt serve --robot {robot} --world remote` again)")

    def close(self) -> None:
        """Fail goals still in flight, withdraw subscriptions; close the session if owned."""
        with self._lock:
            for handle in list(self._inflight.values()):
                handle._finish(GoalState.ABORTED, SkillResult(False, "skill client closed"))
                handle._replies = None
            self._inflight.clear()
        for entity in [*self._declared, *self._queriers.values()]:
            entity.undeclare()
        self._declared.clear()
        self._queriers.clear()
        if self._owns_session:
            self.session.close()

    # -- wiring ----------------------------------------------------------------------------------

    def _watch(self, robot: str) -> None:
        self._alive[robot] = set()
        sub = self.session.declare_subscriber
        self._declared.append(sub(keys.all_goal_status(robot), _direct(self._on_status)))
        self._declared.append(
            self.session.liveliness().declare_subscriber(
                keys.all_alive(robot), _direct(lambda s: self._on_liveliness(robot, s)), history=True
            )
        )

    def _querier(self, robot: str, action: str) -> zenoh.Querier:
        key = (robot, action)
        querier = self._queriers.get(key)
        if querier is None:
            querier = self.session.declare_querier(
                keys.skill(robot, action),
                target=zenoh.QueryTarget.BEST_MATCHING,
                consolidation=zenoh.ConsolidationMode.NONE,
                timeout=self.accept_timeout,
                congestion_control=zenoh.CongestionControl.BLOCK,  # a goal is never dropped
                express=True,  # no batching delay on the way out
            )
            self._queriers[key] = querier
        return querier

    def _wait_for(self, done: Any, deadline: float | None) -> None:
        with self._changed:
            self._changed.wait_for(done, None if deadline is None else max(0.0, deadline - time.monotonic()))

    # -- the reply channel (any thread that looks at a PENDING handle) ---------------------------

    def _read_reply(self, handle: ZenohGoalHandle, timeout: float | None) -> None:
        """Take the answer from ``handle``'s reply channel, waiting up to ``timeout`` (None: until
        Zenoh closes the channel, which it does within :attr:`accept_timeout`)."""
        if timeout is not None and timeout <= 0.0:
            timeout = 0.0
        if timeout == 0.0:
            if not handle._reading.acquire(blocking=False):
                return  # another thread is reading it; it will update the handle
        elif not handle._reading.acquire(timeout=-1 if timeout is None else timeout):
            return
        try:
            replies = handle._replies
            if replies is None:
                return
            try:
                if timeout == 0.0:
                    reply = replies.try_recv()
                elif timeout is None or time.monotonic() + timeout >= handle._expires:
                    reply = replies.recv()  # bounded by the query's own timeout
                else:
                    reply = _recv_until(replies, time.monotonic() + timeout)
            except zenoh.ZError:  # closed without an answer: nobody replied in time
                handle._replies = None
                self._on_no_reply(handle)
                return
            if reply is not None:
                handle._replies = None  # one answer per goal; Zenoh closes the channel itself
                self._on_reply(handle, reply)
        finally:
            handle._reading.release()

    def _on_reply(self, handle: ZenohGoalHandle, reply: zenoh.Reply) -> None:
        if reply.ok is None:
            self._end(handle, GoalState.REJECTED, _error_text(reply))
            return
        try:
            answer = decode(reply.ok.payload.to_bytes(), GoalReply)
        except MessageError as exc:
            self._end(handle, GoalState.REJECTED, f"unreadable reply from server: {exc}")
            return
        if not answer.accepted:
            self._end(handle, GoalState.REJECTED, answer.reason)
            return
        with self._lock:
            if answer.server not in self._alive.get(handle.robot, ()):
                # its token is gone already: the server died between accepting and now
                handle._finish(GoalState.ABORTED, SkillResult(False, "server vanished"))
                self._inflight.pop(handle.goal_id, None)
            else:
                handle._activate(answer.server)

    def _on_no_reply(self, handle: ZenohGoalHandle) -> None:
        if handle._state is GoalState.PENDING:
            self._end(handle, GoalState.REJECTED,
                      f"no skill server for {handle.action!r} on robot {handle.robot!r} answered "
                      f"within {self.accept_timeout:g} s")

    # -- callbacks (Zenoh threads: never block) --------------------------------------------------

    def _on_status(self, sample: zenoh.Sample) -> None:
        try:
            status = decode(sample.payload.to_bytes(), GoalStatus)
        except MessageError:
            return  # not ours to judge; the server logs its own errors
        with self._lock:
            handle = self._inflight.get(status.goal_id)
            if handle is None:
                return  # another client's goal on the same robot
            if status.state.terminal:
                handle._finish(status.state, status.result or SkillResult(False, status.state.value))
                if status.feedback is not None:
                    handle._feedback = status.feedback
                del self._inflight[status.goal_id]
            else:
                handle._activate(status.server)
                handle._feedback = status.feedback

    def _on_liveliness(self, robot: str, sample: zenoh.Sample) -> None:
        server = keys.last_chunks(sample.key_expr, 1)[0]
        with self._lock:
            if sample.kind == zenoh.SampleKind.PUT:
                self._alive[robot].add(server)
                self._changed.notify_all()  # rejoin() waits for it
                return
            self._alive[robot].discard(server)
            lost = [h for h in self._inflight.values() if h.robot == robot and h.server == server]
            for handle in lost:
                handle._finish(GoalState.ABORTED, SkillResult(False, "server vanished"))
                del self._inflight[handle.goal_id]

    def _end(self, handle: ZenohGoalHandle, state: GoalState, reason: str) -> None:
        with self._lock:
            handle._finish(state, SkillResult(False, reason))
            self._inflight.pop(handle.goal_id, None)

    def _cancel(self, handle: ZenohGoalHandle) -> None:
        self.session.put(
            keys.goal_cancel(handle.robot, handle.goal_id),
            encode(CancelRequest(handle.goal_id)),
            congestion_control=zenoh.CongestionControl.BLOCK,
            express=True,
        )


class _Queries:
    """Blocking request/reply calls on a robot's interface keys, one cached Querier per key."""

    def __init__(self, session: zenoh.Session, robot: str, key_of: dict[str, str], timeout: float,
                 what: str) -> None:
        self.robot, self.timeout, self.what = keys.chunk("robot", robot), timeout, what
        self._queriers = {verb: session.declare_querier(key, timeout=timeout) for verb, key in key_of.items()}

    def close(self) -> None:
        for querier in self._queriers.values():
            querier.undeclare()

    def ask(self, verb: str, request: Any, expect: type) -> Any:
        t0 = time.monotonic()
        replies = self._queriers[verb].get(payload=encode(request))
        try:
            answer = first_reply(replies, expect, f"{self.what} {verb} on robot {self.robot}", None)
        except TransportError:
            if time.monotonic() - t0 < 0.9 * self.timeout:
                raise  # the server's own error
            answer = None  # Zenoh's "Timeout" error reply: the query ran out its time
        if answer is not None:
            return answer
        # no answer: the query either ran out its time (a part that is up but does not answer),
        # or Zenoh closed it at once because nothing serves the key (the part's process is gone);
        # the report says which ("within 30 s" after 2 ms sent people looking for a hang)
        if time.monotonic() - t0 < 0.9 * self.timeout:
            raise TransportError(f"no {self.what} on robot {self.robot!r} is up to answer {verb} "
                                 f"(nothing serves it: its server is gone)")
        raise TransportError(f"no {self.what} on robot {self.robot!r} answered {verb} within {self.timeout:g} s")


class ZenohRobot:
    """The camera service and body (:mod:`vap_bt.robot.camera`) of a robot's server; calls block."""

    def __init__(self, session: zenoh.Session, robot: str, timeout: float = CAMERA_TIMEOUT_S) -> None:
        key_of = {**{v: keys.camera(robot, v) for v in ("capture", "view", "move")},
                  **{v: keys.body(robot, v) for v in ("state", "map")}}
        self._q = _Queries(session, robot, key_of, timeout, "camera")
        self._map: SiteMap | None = None

    def capture(self, aim: Aim | None = None) -> Frame:
        return self._q.ask("capture", CaptureRequest(aim), Frame)

    def goto_view(self, view: Viewpoint) -> bool:
        return self._q.ask("view", ViewRequest(view), MoveViewReply).reachable

    def move_view(self, aim: Aim, direction: str) -> bool:
        return self._q.ask("move", MoveViewRequest(aim, direction), MoveViewReply).reachable

    def state(self) -> RobotState:
        return self._q.ask("state", StateRequest(), RobotState)

    def site_map(self) -> SiteMap:
        if self._map is None:  # the map is static: asked once
            self._map = self._q.ask("map", MapRequest(), SiteMap)
        return self._map

    def close(self) -> None:
        self._q.close()


class ZenohVLM:
    """A world-side VLM reached over Zenoh: the question and the frame's id travel, not the pixels
    (the world that took the frame answers about it). A lost link is no answer, never a crash."""

    def __init__(self, session: zenoh.Session, robot: str, description: dict | None = None,
                 timeout: float = CAMERA_TIMEOUT_S) -> None:
        self._q = _Queries(session, robot, {"ask": keys.vlm(robot)}, timeout, "vlm")
        self._description = dict(description or {"backend": "sim (over zenoh)"})
        self.name = str(self._description.get("backend", "sim"))

    def ask(self, query: Query, frame: Frame) -> Answer:
        try:
            return self._q.ask("ask", VlmRequest(query, frame.frame_id, frame.identified()), Answer)
        except TransportError as exc:
            return Answer(f"transport: {exc}", None)

    def describe(self) -> dict:
        return dict(self._description)

    def close(self) -> None:
        self._q.close()


def _recv_until(replies: Any, deadline: float) -> zenoh.Reply | None:
    """The channel's next reply, polling until ``deadline`` (a wait shorter than the query's life:
    Zenoh's blocking ``recv`` has no timeout of its own)."""
    pause = 0.00005
    while (reply := replies.try_recv()) is None:
        left = deadline - time.monotonic()
        if left <= 0:
            return None
        time.sleep(min(pause, left))
        pause = min(pause * 2, 0.002)
    return reply


def _direct(fn: Any) -> zenoh.handlers.Callback:
    return zenoh.handlers.Callback(fn, indirect=False)


def first_reply(replies: Iterable[zenoh.Reply], expect: type, what: str, silence: str | None) -> Any:
    """The first reply of a query decoded as ``expect``; a TransportError naming ``what`` for an
    error reply or a payload that is not one (with the server's own explanation when it sent an
    ErrorReply), and ``silence`` when nobody answered (None: return None, the caller says why)."""
    for reply in replies:
        if reply.ok is None:
            raise TransportError(f"{what}: {_error_text(reply)}")
        payload = reply.ok.payload.to_bytes()
        try:
            return decode(payload, expect)
        except MessageError as exc:
            try:  # the server's own explanation, if that is what came back
                reason = decode(payload, ErrorReply).reason
            except MessageError:
                reason = str(exc)
            raise TransportError(f"{what}: {reason}") from None
    if silence is None:
        return None
    raise TransportError(silence)


def _error_text(reply: zenoh.Reply) -> str:
    err = reply.err
    if err is None:
        return "empty reply"
    try:
        return err.payload.to_string()
    except Exception:  # a non-UTF-8 error payload
        return repr(err.payload.to_bytes())
