"""Telling a simulated world which action a goal is: the sim-only hook of Table II injection.

A real robot has nothing of the kind. A simulated one injects the paper's Table II situations
once per action (:mod:`vap_bt.sim.pb_injection`), while the skills that move it run elsewhere,
behind their skill servers, possibly in other processes: so a skill server tells the world when a
goal starts and ends — :meth:`ActionHooks.begin_action` before the skill's first driver command,
:meth:`ActionHooks.end_action` once it has returned, however it ended. The world draws and arms the
situation on ``begin`` and never says what it drew.

In one process the world itself is the hooks (:class:`~vap_bt.sim.pybullet_world.PybulletWorld`
has both methods). Across processes they go over Zenoh on ``vap/<robot>/world/action``
(:func:`vap_bt.transport.keys.world_action`): :class:`ZenohActionHooks` on the skill server's
side, :class:`ActionHookServer` on the simulator's. It is a query with an acknowledgement, not a
publication, on purpose: the skill's first driver command (another key) must find the situation
already armed, and the reply to a query is the only order Zenoh guarantees between two keys. A
world that does not answer within the timeout (none is running, or a real robot) leaves the goal
unannounced: a warning, never a failed goal.
"""

from __future__ import annotations

import logging
import time
from typing import Any, Protocol

import zenoh

from vap_bt.transport import keys
from vap_bt.outcome import Outcome
from vap_bt.transport.messages import ActionEvent, MessageError, decode, encode

log = logging.getLogger(__name__)

#: s a skill server waits for the world's acknowledgement before moving anyway
ACK_TIMEOUT_S = 2.0


class ActionHooks(Protocol):
    """Where a skill server announces its goals (a simulated world, in-process or over Zenoh)."""

    def begin_action(self, action: str, args: tuple[str, ...]) -> None:
        """Goal ``action(args)`` starts: the world draws and arms its situation. Returns once it has,
        before the skill's first driver command (over Zenoh: or at the timeout, with a warning)."""

    def end_action(self, action: str | None = None, args: tuple[str, ...] | None = None) -> None:
        """The goal's skill has returned, however it ended: the world ends the action (a drop still
        pending happens now); a late call naming another action than the open one does nothing."""


class ZenohActionHooks:
    """The skill server's side: announces goals of ``robot`` to the world over ``session``."""

    def __init__(self, session: zenoh.Session, robot: str, timeout: float = ACK_TIMEOUT_S) -> None:
        self._querier = session.declare_querier(
            keys.world_action(robot), target=zenoh.QueryTarget.ALL, timeout=timeout,
            congestion_control=zenoh.CongestionControl.BLOCK, express=True)
        self.robot, self.timeout = robot, timeout

    def begin_action(self, action: str, args: tuple[str, ...]) -> None:
        self._announce(ActionEvent("begin", action, tuple(args)))

    def end_action(self, action: str | None = None, args: tuple[str, ...] | None = None) -> None:
        self._announce(ActionEvent("end", action or "", tuple(args or ())))

    def _announce(self, event: ActionEvent) -> bool:
        """Send ``event``; whether a world acknowledged it."""
        if not self._matched():
            log.warning("no simulated world acknowledged %s %s on robot %s (none is there)", event.phase,
                        event.action, self.robot)
            return False
        for reply in self._querier.get(payload=encode(event)):
            if reply.ok is not None:
                try:
                    ack = decode(reply.ok.payload.to_bytes(), Outcome)
                except MessageError as exc:
                    log.warning("unreadable acknowledgement of %s %s: %s", event.phase, event.action, exc)
                    continue
                if ack.completed:
                    return True
                log.warning("the world refused %s %s: %s", event.phase, event.action, ack.message)
        log.warning("no simulated world acknowledged %s %s on robot %s", event.phase, event.action, self.robot)
        return False

    def _matched(self) -> bool:
        """Whether a world's queryable is there, waiting up to the timeout for one to be declared
        (a world that has just started may not have reached this peer yet)."""
        deadline = time.monotonic() + self.timeout
        while not self._querier.matching_status.matching:
            if time.monotonic() > deadline:
                return False
            time.sleep(0.005)
        return True

    def close(self) -> None:
        self._querier.undeclare()


class ActionHookServer:
    """The simulator's side: answers ``vap/<robot>/world/action`` for each of ``robots`` by calling
    the world's ``begin_action`` / ``end_action``."""

    def __init__(self, session: zenoh.Session, robots: tuple[str, ...], world: Any) -> None:
        self.world = world
        self._declared = [session.declare_queryable(keys.world_action(r), self._on_event) for r in robots]

    def _on_event(self, query: zenoh.Query) -> None:
        try:
            event = decode(query.payload.to_bytes() if query.payload else b"", ActionEvent)
            if event.phase == "begin":
                self.world.begin_action(event.action, event.args)
            elif event.phase == "end":
                self.world.end_action(event.action or None, event.args if event.action else None)
            else:
                raise MessageError(f"phase {event.phase!r} is neither begin nor end")
            ack = Outcome(True)
        except MessageError as exc:
            ack = Outcome(False, f"bad action event: {exc}")
        except Exception as exc:  # the world's failure is the caller's answer, not our crash
            ack = Outcome(False, f"world failed: {type(exc).__name__}: {exc}")
        query.reply(query.key_expr, encode(ack))

    def close(self) -> None:
        for entity in self._declared:
            entity.undeclare()
        self._declared.clear()
