"""The campaign engine: episodes as Dask tasks, each worker keeping its worlds warm between them.

An experiment is a set of episode keys (:class:`Key`: experiment, world, task, strategy,
viewpoints, seed). Each key is one Dask task, :func:`episode_row`, that runs the episode in a
worker process and returns its row (:mod:`tools.experiments.results`): the report stays on the
worker, only the row travels. An episode is a pure function of its key — a worker's
:class:`~vap_bt.app.runner.Session` resets its world to the seed — so the rows are the same
whatever the number of workers or the order they ran in.

A worker builds one Session per (task, world, strategy, viewpoints) and keeps it for the next
episode of that configuration (a pybullet world is built once per worker, not once per
episode); :class:`CloseSessions`, a worker plugin, closes them when the worker shuts down.

A worker that dies (a segfault in the physics, the machine's OOM killer) loses only its
episode in flight. That is the scheduler's business, not ``retries=`` (which re-runs a task that
*raised*, and an episode is deterministic: it would raise again): the scheduler hands a lost
worker's tasks to another worker, until a task has been on ``allowed-failures`` dead workers,
when it is declared a ``KilledWorker``. :func:`open_client` sets that to
:data:`ALLOWED_FAILURES` for the cluster it starts; a scheduler you start yourself reads it from
its own config (``DASK_DISTRIBUTED__SCHEDULER__ALLOWED_FAILURES``). An episode that raises is a
row with its ``error``, not a lost campaign.

By default :func:`open_client` starts a ``distributed.LocalCluster`` on this machine: one
process per worker, one thread each (the executive is single-threaded Python), no dashboard,
listening on 127.0.0.1 only. ``address`` joins a running scheduler unchanged instead
(``dask scheduler`` / ``dask worker tcp://...``; docs/RESULTS.md).
"""

from __future__ import annotations

import logging
import os
import time
import warnings
from collections import OrderedDict
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable, Iterable, Iterator

import dask
from distributed import Client, LocalCluster, WorkerPlugin, as_completed

#: dead workers a task may outlive before the scheduler gives up on it (Dask's default is 3)
ALLOWED_FAILURES = 5
#: sessions a worker keeps warm per world; the least recently used is closed beyond this (a
#: pybullet world holds a physics server and its meshes; a symbolic one is a few objects)
KEEP_SESSIONS = {"symbolic": 64, "pybullet": 2}
ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True, order=True)
class Key:
    """One episode of an experiment: what it runs and with which seed (a row's identity)."""

    experiment: str
    world: str
    task: str
    strategy: str  # the verification strategy: RunConfig.verify
    viewpoints: str  # where active perception looks next: RunConfig.viewpoints
    seed: int

    @property
    def name(self) -> str:
        """The Dask task's name (unique within a campaign, readable in a scheduler's logs)."""
        return f"episode-{self.experiment}-{self.world}-{self.task}-{self.strategy}-{self.viewpoints}-{self.seed}"

    def config(self) -> tuple[str, str, str, str]:
        """What a worker's session is built for: every field but the experiment and the seed."""
        return self.world, self.task, self.strategy, self.viewpoints

    def episode(self) -> tuple[str, str, str, str, int]:
        """What the episode is, whichever experiment asks for it: an episode is a pure function of
        these, so experiments that share a log (``--log``) run it once."""
        return (*self.config(), self.seed)


class _Sessions:
    """A worker process's warm sessions, by configuration (least recently used closed first)."""

    def __init__(self) -> None:
        self.open: OrderedDict[tuple, object] = OrderedDict()

    def get(self, key: Key):
        """The session for ``key``'s configuration, built on first use; an InputError if the
        configuration cannot run here (remembered, so a strategy that cannot run fails fast)."""
        config = key.config()
        if config not in self.open:
            self.open[config] = _start(key)
            self._evict(key.world)
        self.open.move_to_end(config)
        return self.open[config]

    def _evict(self, world: str) -> None:
        mine = [c for c in self.open if c[0] == world]
        for config in mine[:max(0, len(mine) - KEEP_SESSIONS.get(world, 1))]:
            _close(self.open.pop(config))

    def discard(self, key: Key) -> None:
        """Close and forget ``key``'s session (one that raised mid-episode may be left half-way)."""
        _close(self.open.pop(key.config(), None))

    def close(self) -> None:
        """Close every session (a pybullet world's physics server with it)."""
        while self.open:
            _close(self.open.popitem()[1])


SESSIONS = _Sessions()  # this process's: each worker process has its own


def _start(key: Key):
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session
    from vap_bt.errors import InputError

    task = taskfile.load(ROOT / "trees" / f"{key.task}.yaml")
    try:
        return Session(task, RunConfig.from_task(task, world=key.world, verify=key.strategy,
                                                 viewpoints=key.viewpoints))
    except InputError as exc:
        return exc


def _close(session) -> None:
    if hasattr(session, "close"):
        session.close()


class CloseSessions(WorkerPlugin):
    """Closes a worker's warm sessions when it shuts down: a pybullet world holds a physics server
    and its meshes, and a worker of a cluster one joins may outlive the campaign."""

    name = "vap-bt-close-sessions"

    def teardown(self, worker) -> None:
        """Called by the worker as it closes."""
        SESSIONS.close()


def episode_row(key: Key, fault: Callable[[Key], None] | None = None) -> dict:
    """Run ``key``'s episode in this worker and return its row. ``fault``, for tests only, is
    called first (it may kill the worker, to show the campaign survives it)."""
    from tools.experiments import results
    from vap_bt.errors import InputError

    if fault is not None:
        fault(key)
    session = SESSIONS.get(key)
    if isinstance(session, InputError):
        return results.not_runnable(key, session)
    t0 = time.perf_counter()
    try:
        report = session.episode(key.seed)
    except InputError as exc:  # the configuration cannot run here: said when the episode began
        return results.not_runnable(key, exc)
    except Exception as exc:  # noqa: BLE001 - a crash is a result of the campaign, not its end
        SESSIONS.discard(key)  # the next episode of this configuration starts from a fresh session
        return results.crashed(key, exc, time.perf_counter() - t0)
    return results.episode_row(key, report)


@dataclass(frozen=True)
class CrashOnce:
    """A fault for tests: the first episode to start after ``marker`` is gone kills its worker
    process outright (no exception, no cleanup: as a segfault would), once across the cluster —
    the marker file, created atomically, says it has happened."""

    marker: str

    def __call__(self, key: Key) -> None:
        """Kill this worker unless the marker exists (and create it)."""
        try:
            os.close(os.open(self.marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
        except FileExistsError:
            return
        os._exit(70)


@contextmanager
def open_client(address: str | None = None, workers: int | None = None) -> Iterator[Client]:
    """A client of the scheduler at ``address``, or of a LocalCluster of ``workers`` processes
    (default: one per core) started here and stopped on exit. Each worker closes its sessions as it
    shuts down (:class:`CloseSessions`)."""
    if address:
        with Client(address) as client:
            client.register_plugin(CloseSessions())
            yield client
        return
    # without a dashboard the scheduler still serves its health routes, on the host given: when
    # its usual port is taken (another cluster on the machine) it takes a free one and warns
    with dask.config.set({"distributed.scheduler.allowed-failures": ALLOWED_FAILURES}), warnings.catch_warnings():
        warnings.filterwarnings("ignore", "Port .* is already in use", UserWarning)
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None, silence_logs=logging.ERROR)
    with cluster, Client(cluster) as client:
        client.register_plugin(CloseSessions())
        yield client


def run(client: Client, keys: Iterable[Key], emit: Callable[[dict], None],
        fault: Callable[[Key], None] | None = None) -> None:
    """Run every key's episode on ``client``'s cluster and ``emit`` each row as it finishes (in the
    order they finish). The episodes are submitted all at once; the scheduler keeps every worker
    busy."""
    futures = [client.submit(episode_row, key, fault, key=key.name, pure=False) for key in keys]
    for future in as_completed(futures):
        emit(future.result())
        future.release()


def cpu_times(client: Client) -> dict[str, float]:
    """The CPU time each of the client's workers has used so far (by address): beside the wall
    time it tells a campaign slowed by other load on the machine from a slow one."""
    return client.run(time.process_time)


def cpu_since(client: Client, before: dict[str, float]) -> float:
    """The CPU seconds the workers used since ``before`` (:func:`cpu_times`); a worker started
    since counts from zero, one that died since is not counted (a lower bound then)."""
    return sum(t - before.get(w, 0.0) for w, t in cpu_times(client).items())


def workers(client: Client) -> int:
    """How many workers the client's scheduler has now."""
    return len(client.scheduler_info()["workers"])


def key_of(row: dict) -> Key:
    """The key a row was written for."""
    return Key(**{name: row[name] for name in asdict(Key("", "", "", "", "", 0))})
