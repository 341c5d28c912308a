"""The ``vap-bt serve`` and ``vap-bt skills`` commands.

``vap-bt serve`` opens one Zenoh session, builds one world, and starts a
:class:`~vap_bt.transport.server.SkillServer` for each robot asked for (default: every robot that
has a skill plugin), all bound to that world through a :class:`LockedWorld`, so one simulator is
shared safely by the arm's and the base's skills. It prints one ``ready`` line on stdout once
everything is declared (``vap-bt serve: ready: ur5e skills [close, cut, …] with the camera, on
zenoh (connected to tcp/127.0.0.1:7447)``), logs each goal on stderr (accepted, throttled
feedback, result, cancel: :mod:`~vap_bt.transport.server`) and runs until SIGINT or SIGTERM.
``python -m vap_bt serve`` does the same without the ``vap-bt`` wrapper.

With ``--world remote`` the skills bind to a robot whose world runs in ``vap-bt sim``
(:class:`~vap_bt.app.remote_robot.RemoteRobot`: its drivers and action hook over Zenoh); the
server is then a client of the sim's router (``--connect``, default ``tcp/127.0.0.1:7447``), and
the camera robot's server (``ur5e``) hosts the camera service on the skills' own kit. Such a
server lives and dies with its sim: when the sim's driver token vanishes (the sim stopped, died
or hung; :class:`~vap_bt.transport.drivers.HostWatch`) it says so in one line on stderr and exits
4 — its skills' state (what the hand holds, the site map) belonged to that world, so a new sim
gets new servers rather than these waiting for it.

``vap-bt skills`` lists the installed skill plugins: action, robot, resource, where it comes
from; broken plugins and conflicting ones are reported too (a conflict exits with code 2).

Exit codes follow :mod:`vap_bt.errors`: 2 bad input, 4 the transport could not come up or, for
``--world remote``, the sim went away.
"""

from __future__ import annotations

import argparse
import json
import logging
import signal
import sys
import threading
import time
from typing import TYPE_CHECKING

from vap_bt.app.arguments import add_settings
from vap_bt.errors import EXIT_BAD_INPUT, EXIT_OK, EXIT_TRANSPORT, InputError, TransportError, VapBtError
from vap_bt.settings import Commands, Hosting, Zenoh
from vap_bt.transport.config import describe, open_session, part_settings, settings_from_args

if TYPE_CHECKING:  # the servers, the plugins and the worlds are imported by the commands that use them:
    from vap_bt import plugins  # the command line defines these commands' arguments on every start
    from vap_bt.transport.server import SkillServer

#: ``--world remote``: the robot of a world that ``vap-bt sim`` hosts
REMOTE = "remote"
#: how the one line on stdout that says everything is declared begins (``vap-bt launch`` waits for it)
READY = "vap-bt serve: ready"


def add_serve_arguments(p: argparse.ArgumentParser) -> None:
    """Declare ``vap-bt serve``'s options on ``p`` (from :mod:`vap_bt.settings`)."""
    add_settings(p, "serve", Hosting, Zenoh)


def run_serve(args: argparse.Namespace) -> int:
    """``vap-bt serve``: start the skill servers and serve until SIGINT or SIGTERM, or, on a remote world,
    until its sim goes (blocks); returns the exit code."""
    from vap_bt import plugins
    from vap_bt.app.locked_world import LockedWorld
    from vap_bt.app.world_factory import make_world, parse_world_args
    from vap_bt.transport.server import SkillServer

    _show_goal_log()
    entries = [e for e in plugins.discover_skills() if e.name not in set(args.exclude_skill)]
    table = plugins.skill_table(entries)
    robots = _robots(args.robot, table)
    if args.name and len(robots) > 1:
        raise InputError("--name", "a server name only fits one --robot")
    if args.world == REMOTE:
        return _serve_remote(args, entries, robots)
    world = make_world(args.world, args.task, args.seed, parse_world_args(args.world_arg))
    shared = LockedWorld(world)
    settings = settings_from_args(args, default_listen=True)
    try:
        session = open_session(settings)
    except BaseException:
        world.close()
        raise
    servers = [SkillServer(session, robot, plugins.instantiate(shared, robot, entries), camera=shared,
                           name=args.name) for robot in robots]
    return _serve_until_stopped(session, servers, settings, _Stop(), closing=[world])


def _serve_remote(args: argparse.Namespace, entries, robots: list[str]) -> int:
    """Skills over a robot whose world is ``vap-bt sim``'s (:class:`RemoteRobot`); the camera
    robot's server hosts the camera service, built on the same kit as its skills."""
    from vap_bt import plugins
    from vap_bt.app.runner import make_camera
    from vap_bt.transport.drivers import HostWatch, host_token_key
    from vap_bt.transport.server import SkillServer
    from vap_bt.app.embedded import CAMERA_ROBOT
    from vap_bt.app.remote_robot import RemoteRobot

    for option, given in (("--task", args.task), ("--world-arg", args.world_arg)):
        if given:
            raise InputError(option, "a remote world is vap-bt sim's: give the task to vap-bt sim")
    settings = part_settings(args)
    session = open_session(settings)
    bodies = {robot: RemoteRobot(session, robot) for robot in robots}
    try:
        for body in bodies.values():
            body.site_map()  # the sim serves this robot's drivers (else one TransportError, exit 4)
    except BaseException:
        for body in bodies.values():
            body.close()
        session.close()
        raise
    servers = [SkillServer(session, robot, plugins.instantiate(body, robot, entries), name=args.name,
                           camera=make_camera(body) if robot == CAMERA_ROBOT else None)
               for robot, body in bodies.items()]
    stop = _Stop()
    sim = ", ".join(settings.connect) or "the configured router"
    watches = {robot: HostWatch(session, robot, lambda robot=robot: stop.world_gone(sim, robot)) for robot in bodies}
    closing = [*watches.values(), *bodies.values()]
    for robot, watch in watches.items():  # ready means a lost sim is noticed: its tokens are known
        if not watch.seen.wait(settings.peer_timeout):
            for thing in closing:
                thing.close()
            session.close()
            raise TransportError(f"the sim at {sim} serves robot {robot}'s drivers but its liveliness token "
                                 f"({host_token_key(robot)}) did not come within {settings.peer_timeout:g} s")
    return _serve_until_stopped(session, servers, settings, stop, closing=closing)


class _Stop:
    """Why serving ends, and its exit code: SIGINT or SIGTERM (0), or the remote world gone (4,
    said in one line: a server that only waits would look alive and serve nothing)."""

    def __init__(self) -> None:
        self.event = threading.Event()
        self.code = EXIT_OK
        self._lock = threading.Lock()  # the robots' tokens vanish together: one line, not one each

    def world_gone(self, sim: str, robot: str) -> None:
        with self._lock:
            if self.event.is_set():  # stopping already (a signal, or another robot's token)
                return
            self.code = EXIT_TRANSPORT
            print(f"vap-bt serve: the sim at {sim} is gone (robot {robot}'s drivers withdrew their liveliness "
                  "token): stopping, exit 4 — start `vap-bt sim` again, then this server",
                  file=sys.stderr, flush=True)
            self.event.set()


def _serve_until_stopped(session, servers: list[SkillServer], settings, stop: _Stop, closing: list) -> int:
    """Start ``servers``, say ``ready``, wait for SIGINT/SIGTERM or ``stop``; then close everything."""
    started: list[SkillServer] = []
    try:
        for server in servers:
            started.append(server.start())
        _on_signals(stop.event)
        hosted = "; ".join(f"{s.robot} skills [{', '.join(sorted(s.skills))}]"
                           f"{' with the camera' if s.camera is not None else ''}" for s in servers)
        print(f"{READY}: {hosted}, on zenoh ({describe(settings)})", flush=True)
        while not stop.event.wait(0.5):  # short waits keep Ctrl-C responsive
            pass
    except KeyboardInterrupt:
        pass
    finally:
        for server in started:
            server.close()
        session.close()
        for thing in closing:
            thing.close()
    return stop.code


def add_skills_arguments(p: argparse.ArgumentParser) -> None:
    """Declare ``vap-bt skills``' options on ``p`` (from :mod:`vap_bt.settings`)."""
    add_settings(p, "skills", Commands)


def run_skills(args: argparse.Namespace) -> int:
    """``vap-bt skills``: the installed skill plugins as a table (``--json``: JSON), and the problems met
    loading them as warnings on stderr."""
    from vap_bt import plugins

    found = plugins.discover()
    rows = [
        {"action": e.action, "robot": e.robot, "resource": e.resource, "entry_point": e.name,
         "class": e.module, "distribution": f"{e.distribution} {e.version}"}
        for e in sorted(found.entries, key=lambda e: (e.robot, e.action, e.name))
    ]
    if args.json:
        print(json.dumps({"skills": rows, "problems": [str(p) for p in found.problems]}, indent=2))
    else:
        _print_table(rows)
        for problem in found.problems:
            print(f"warning: {problem}", file=sys.stderr)
    try:
        plugins.skill_table(found.entries)
    except plugins.SkillConflictError as exc:
        print(f"vap-bt: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    return EXIT_OK


def _robots(asked: list[str], table: dict[str, plugins.SkillEntry]) -> list[str]:
    available = sorted({e.robot for e in table.values()})
    for robot in asked:
        if robot not in available:
            raise InputError("--robot", f"no skill plugin is bound to robot {robot!r} "
                                        f"(robots with skills: {', '.join(available) or 'none'})")
    return sorted(set(asked)) or available


class _ServerLog(logging.StreamHandler):
    """The skill servers' log lines on stderr as ``vap-bt serve: [t] …`` (``warning: …`` and worse
    say so), ``t`` the monotonic clock the runner's reports and the sim's lines count in."""

    def __init__(self) -> None:
        super().__init__(sys.stderr)
        self.setFormatter(logging.Formatter("vap-bt serve: [%(clock).3f] %(level)s%(message)s"))

    def emit(self, record: logging.LogRecord) -> None:
        record.clock = time.perf_counter()
        record.level = f"{record.levelname.lower()}: " if record.levelno > logging.INFO else ""
        super().emit(record)


def _show_goal_log() -> None:
    """The skill servers' goal lines (INFO: accepted, feedback, result, cancel) on stderr, however
    quiet the rest of the logging is (once per process, in this format only)."""
    from vap_bt.transport import server as server_module

    logger = logging.getLogger(server_module.__name__)
    for old in [h for h in logger.handlers if isinstance(h, _ServerLog)]:
        logger.removeHandler(old)
    logger.addHandler(_ServerLog())
    logger.propagate = False
    if logger.getEffectiveLevel() > logging.INFO:
        logger.setLevel(logging.INFO)


def _on_signals(stop: threading.Event) -> None:
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, lambda *_: stop.set())


def _print_table(rows: list[dict[str, str]]) -> None:
    if not rows:
        print("no skill plugins installed (entry-point group vap_bt.skills)")
        return
    cols = ["action", "robot", "resource", "entry_point", "class", "distribution"]
    widths = {c: max(len(c), *(len(r[c]) for r in rows)) for c in cols}
    print("  ".join(c.upper().ljust(widths[c]) for c in cols).rstrip())
    for r in rows:
        print("  ".join(r[c].ljust(widths[c]) for c in cols).rstrip())
