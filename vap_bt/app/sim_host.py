"""The ``vap-bt sim TASK`` command: the pybullet world in a process of its own, over Zenoh.

It builds the task's household (``--seed``, ``--no-injection``) and offers, on one Zenoh session:

* the robot's drivers and body for every robot that has skills (``ur5e``, ``base``: one mobile
  UR5e, two namespaces) — :class:`~vap_bt.transport.drivers.DriverServer`;
* the sim-only action hook that arms Table II injection —
  :class:`~vap_bt.transport.world_hooks.ActionHookServer`;
* the simulated VLM on the camera robot's ``vlm/ask`` key —
  :class:`~vap_bt.transport.world_services.VlmServer`;
* the oracle the runner scores its report by —
  :class:`~vap_bt.transport.world_services.OracleServer`.

Its session is a Zenoh **router** listening on ``--listen`` (default :data:`SIM_ENDPOINT`, loopback),
so the skill servers (``vap-bt serve --world remote``) and the executive (``vap-bt run
--connect``) only need its address; every message between them is routed through it. Everything
runs under the world's own lock (pybullet is not thread-safe). Once all is declared it declares
its own liveliness token, ``vap/part/sim/<task>-<pid>-<zid>`` (what ``vap-bt parts`` lists), and
prints one ``ready`` line on stdout, then one line on stderr per action announced (stamped
with the monotonic clock the runner's reports count from), and runs until SIGINT or
SIGTERM, then withdraws everything and exits 0.
"""

from __future__ import annotations

import argparse
import signal
import sys
import threading
import time

from vap_bt.app.arguments import add_settings
from vap_bt.errors import EXIT_OK, InputError, VapBtError
from vap_bt.settings import Hosting, RunConfig, Zenoh
from vap_bt.transport import keys
from vap_bt.transport.config import SIM_ENDPOINT, describe, open_session, settings_from_args

#: the command's one-line description for ``--help``: this docstring's first line, as plain text
DESCRIPTION = __doc__.split("\n\n")[0].replace("``", "")
#: how the one line on stdout that says everything is declared begins (``vap-bt launch`` waits for it)
READY = "vap-bt sim: ready"


def add_sim_arguments(p: argparse.ArgumentParser) -> None:
    """Declare ``vap-bt sim``'s options on ``p`` (from :mod:`vap_bt.settings`): hosting and Zenoh, and the
    run's settings that shape the world."""
    add_settings(p, "sim", Hosting, RunConfig, Zenoh)  # the injection and the VLM's noise: a run's settings


class _Announcer:
    """The world's action hook, saying each announcement on stderr (what ran when, for the logs)."""

    def __init__(self, world) -> None:
        self.world = world

    def begin_action(self, action: str, args: tuple[str, ...]) -> None:
        self.world.begin_action(action, args)
        _say(f"begin {action}({', '.join(args)})")

    def end_action(self, action: str | None = None, args: tuple[str, ...] | None = None) -> None:
        self.world.end_action(action, args)
        _say(f"end {action}({', '.join(args or ())})")


def _say(what: str) -> None:
    """One log line on stderr, stamped with the monotonic clock the runner's reports count from
    (``clock_t0``), so the logs of all the parts line up."""
    print(f"vap-bt sim: [{time.perf_counter():.3f}] {what}", file=sys.stderr, flush=True)


def run_sim(args: argparse.Namespace) -> int:
    """``vap-bt sim``: build the task's household and serve it until SIGINT or SIGTERM (blocks); returns
    the exit code."""
    # the world's servers here, not at the top: the command line defines this command's arguments on every start
    from vap_bt import plugins, taskfile
    from vap_bt.app import runner
    from vap_bt.app.embedded import CAMERA_ROBOT
    from vap_bt.app.locked_world import LockedWorld
    from vap_bt.transport.drivers import DriverServer
    from vap_bt.transport.world_hooks import ActionHookServer
    from vap_bt.transport.world_services import OracleServer, VlmServer, WorldFacts

    task = taskfile.load(args.household)
    if task.spec.scene is None:
        raise InputError(args.household, "vap-bt sim builds a household from a task file's scene:; this task has none")
    cfg = RunConfig.from_task(task, world="pybullet", seed=args.seed, **RunConfig.given(args, "sim"))
    robots = tuple(sorted({e.robot for e in plugins.skill_table(plugins.discover_skills()).values()}))
    settings = settings_from_args(args, default_listen=True, default_endpoint=SIM_ENDPOINT, mode="router")
    world = runner.make_world(task, cfg)
    shared = LockedWorld(world, world.lock)  # the drivers hold this lock too
    vlm = LockedWorld(runner.sim_vlm(task, world, cfg), world.lock)
    stop = threading.Event()
    parts: list = []
    session = token = None
    try:
        session = open_session(settings)
        parts += [DriverServer(session, robot, world.drivers, shared).start() for robot in robots]
        parts.append(ActionHookServer(session, robots, _Announcer(shared)))
        parts.append(VlmServer(session, CAMERA_ROBOT, vlm))
        parts.append(OracleServer(session, shared, WorldFacts(task.name, vlm)))
        if threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGTERM, lambda *_: stop.set())
        # last: whoever sees the sim's token (`vap-bt parts`) finds everything above there
        token = session.liveliness().declare_token(keys.part("sim", keys.instance(task.name, session.zid())))
        print(f"{READY}: world {task.name} (seed {cfg.seed}, injection {'on' if cfg.injection else 'off'}) with "
              f"drivers of {' and '.join(robots)}, the simulated VLM on {CAMERA_ROBOT} and the oracle, on zenoh "
              f"({describe(settings)})", flush=True)
        while not stop.wait(0.5):  # short waits keep Ctrl-C responsive
            pass
    except KeyboardInterrupt:
        pass
    finally:
        if token is not None:  # the sim is gone before its services are
            token.undeclare()
        for part in reversed(parts):
            part.close()
        if session is not None:
            session.close()
        world.close()
    return EXIT_OK
