"""The ``vap-bt parts`` command: who is on a Zenoh network, and which goals are in flight.

Every part of a connected set-up says it is there with a liveliness token (:mod:`.keys`), which
Zenoh withdraws when the part stops, dies, or hangs past its link lease:

==============================================  =============================================
``vap/part/sim/<name>``                         a ``vap-bt sim``
``vap/<robot>/driver-host``                     the sim's drivers of ``<robot>``
``vap/<robot>/alive/<server>``                  a skill server of ``<robot>``
``vap/part/executive/<name>``                   a ``vap-bt run --connect``
``vap/<robot>/alive/<server>/goal/<action>/<id>``  a goal that server runs now
==============================================  =============================================

So a census needs no part to answer anything: one liveliness query on ``vap/**`` (the router
answers with the tokens it knows) is a snapshot, and a liveliness subscriber with history is a
running account (``--watch``). Nothing is declared, nothing is polled, and the parts do no work
for it. The driver clients' tokens (``vap/<robot>/driver-client/*``, a skill server's link to the
drivers) are connections, not parts, and are left out.
"""

from __future__ import annotations

import argparse
import json
import signal
import threading
import time
from dataclasses import asdict, dataclass

import zenoh

from vap_bt.errors import EXIT_OK
from vap_bt.transport import keys
from vap_bt.app.arguments import add_settings
from vap_bt.settings import SNAPSHOT_TIMEOUT_S, Commands, Zenoh
from vap_bt.transport.config import open_session, part_settings

#: the order kinds are listed in: the world first, the executive last
KINDS = ("sim", "drivers", "skill server", "executive")


@dataclass(frozen=True)
class Part:
    """One part alive on the network, as its liveliness token (``key``) says: its kind (one of
    :data:`KINDS`), the robot it serves and its name."""

    kind: str
    robot: str  # "" for a part that is no one robot's (sim, executive)
    name: str  # "" for a robot's drivers
    key: str

    @property
    def label(self) -> str:
        """``robot/name`` without the empty ones: how the table names the part."""
        return "/".join(x for x in (self.robot, self.name) if x)


@dataclass(frozen=True)
class Goal:
    """A goal a skill server is running now: the robot and server, the action, the goal's id, and the
    token's key."""

    robot: str
    server: str
    action: str
    goal: str
    key: str


def classify(key: str) -> Part | Goal | None:
    """What the liveliness token ``key`` says is there; None for a token that is not a part's."""
    chunks = str(key).split("/")
    if len(chunks) < 3 or chunks[0] != keys.ROOT:
        return None
    if chunks[1] == "part" and len(chunks) == 4:
        return Part(chunks[2], "", chunks[3], key)
    robot, rest = chunks[1], chunks[2:]
    if rest == ["driver-host"]:
        return Part("drivers", robot, "", key)
    if rest[0] == "alive" and len(rest) == 2:
        return Part("skill server", robot, rest[1], key)
    if rest[0] == "alive" and len(rest) == 5 and rest[2] == "goal":
        return Goal(robot, rest[1], rest[3], rest[4], key)
    return None


def snapshot(session: zenoh.Session, timeout: float = SNAPSHOT_TIMEOUT_S) -> tuple[list[Part], list[Goal]]:
    """The parts and goals whose tokens are up now, in listing order."""
    found = set()
    for reply in session.liveliness().get(keys.EVERYTHING, timeout=timeout):
        if reply.ok is not None and (seen := classify(str(reply.ok.key_expr))) is not None:
            found.add(seen)
    parts = sorted((p for p in found if isinstance(p, Part)), key=_order)
    goals = sorted((g for g in found if isinstance(g, Goal)), key=lambda g: (g.robot, g.server, g.goal))
    return parts, goals


def _order(part: Part) -> tuple:
    return (KINDS.index(part.kind) if part.kind in KINDS else len(KINDS), part.kind, part.robot, part.name)


def table(parts: list[Part], goals: list[Goal]) -> str:
    """The census as text: a table of the parts, then one of the goals in flight."""
    lines = _columns(["PART", "ROBOT/NAME", "KEY"], [[p.kind, p.label, p.key] for p in parts]) if parts else \
        ["no parts alive"]
    lines.append("")
    if goals:
        lines.append("goals in flight:")
        lines += _columns(["ROBOT", "SERVER", "ACTION", "GOAL"], [[g.robot, g.server, g.action, g.goal] for g in goals])
    else:
        lines.append("no goals in flight")
    return "\n".join(lines)


def _columns(head: list[str], rows: list[list[str]]) -> list[str]:
    widths = [max(len(r[i]) for r in [head, *rows]) for i in range(len(head))]
    return ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in [head, *rows]]


def add_parts_arguments(p: argparse.ArgumentParser) -> None:
    """Declare ``vap-bt parts``' options on ``p`` (from :mod:`vap_bt.settings`)."""
    add_settings(p, "parts", Commands, Zenoh)


def run_parts(args: argparse.Namespace) -> int:
    """``vap-bt parts``: print one snapshot (a table, or JSON with ``--json``) or, with ``--watch``, follow
    the parts as they come and go until Ctrl-C; returns the exit code."""
    session = open_session(part_settings(args))
    try:
        if args.watch:
            return _watch(session)
        parts, goals = snapshot(session, args.timeout)
    finally:
        session.close()
    if args.json:
        print(json.dumps({"parts": [asdict(p) for p in parts], "goals": [asdict(g) for g in goals]}, indent=2))
    else:
        print(table(parts, goals))
    return EXIT_OK


def _watch(session: zenoh.Session) -> int:
    """One line per token that comes or goes, until SIGINT or SIGTERM."""
    stop = threading.Event()
    if threading.current_thread() is threading.main_thread():
        # both handlers set here: a process started with SIGINT ignored (by a parent that ignores
        # it: a test runner's worker, nohup) inherits the ignoring, and Python then installs no
        # KeyboardInterrupt of its own, so Ctrl-C would never end the watch
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, lambda *_: stop.set())

    def on_sample(sample: zenoh.Sample) -> None:  # Zenoh's thread: one short print, nothing more
        seen = classify(str(sample.key_expr))
        if seen is None:
            return
        sign = "+" if sample.kind == zenoh.SampleKind.PUT else "-"
        what = (f"{seen.kind} {seen.label}" if isinstance(seen, Part)
                else f"goal {seen.goal} {seen.action} on {seen.robot}/{seen.server}")
        print(f"[{time.perf_counter():.3f}] {sign} {what}  ({seen.key})", flush=True)

    subscriber = session.liveliness().declare_subscriber(keys.EVERYTHING, on_sample, history=True)
    try:
        while not stop.wait(0.5):  # short waits keep Ctrl-C responsive
            pass
    except KeyboardInterrupt:  # off the main thread no handler was set: Python's own
        pass
    finally:
        subscriber.undeclare()
    return EXIT_OK
