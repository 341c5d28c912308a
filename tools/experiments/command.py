"""What every experiment command shares: its options, the campaign loop, and its outputs.

An experiment (:class:`Experiment`) says which (strategy, viewpoints) configurations it runs
and how it reports its rows; :func:`main` does the rest, the same way for each:

* options — ``--world``, ``--tasks`` (names, or the paper's ids S1-S5 / T1-T4, read from the task
  files' ``paper_task``), ``--seeds`` (``N``: seeds 0..N-1, or ``A-B``: A..B inclusive),
  ``--out``, ``--resume``, ``--report-only``, ``--rows``, ``--workers``, ``--address``;
* the campaign — the keys not yet in ``episodes.jsonl`` (all of them unless ``--resume``) run on
  the cluster (:mod:`tools.experiments.engine`), each row appended as it finishes; progress on
  stderr (:mod:`tools.progress`);
* the outputs — ``episodes.csv``, ``table.md`` and PNG plots from every row in the log, its
  tasks in the paper's order (also with ``--report-only``, from the rows alone), and ``run.json``: the command, seeds, commit,
  versions, worker count, wall time and episodes per hour, and the same for each earlier sitting of a
  resumed campaign (``sittings``; a sitting Ctrl-C stopped is recorded too, ``interrupted``). Each row records the commit it ran on, and table.md ends with
  them: a campaign that spans sittings may span changes to the code, and its table says so.

``--log FILE`` shares one episode log between experiments: an episode (world, task, strategy,
viewpoints, seed) another experiment already ran is not run again, and each experiment reports
every row of its configurations in the log. A pybullet campaign runs the strategies, then the
viewpoint kinds the strategies did not run, into one log; Table III is then read from it, not run.

``--rows FILE`` reads another campaign's episodes instead of running any: an episode is a pure
function of its world, task, strategy, viewpoints and seed, so the failure modes of the strategies'
episodes are the strategies campaign's rows read another way, not 8000 episodes run twice.

Bad input (an unknown task, a malformed seed range) is one line on stderr naming the option,
exit 2 (:data:`vap_bt.errors.EXIT_BAD_INPUT`), no traceback. Ctrl-C or SIGTERM stops the campaign
with one line (exit 130); the rows written so far stay, and ``--resume`` runs the rest.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import signal
import subprocess
import sys
import threading
import time
import typing
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable

import dask
import distributed

from tools.experiments import engine, results
from tools.experiments.engine import Key
from tools.progress import Progress, duration
from vap_bt import taskfile
from vap_bt.errors import EXIT_BAD_INPUT, EXIT_INTERRUPTED, EXIT_OK, InputError
from vap_bt.report import versions
from vap_bt.settings import RunConfig
from vap_bt.sim.sim_vlm import MODEL_VERSION
from vap_bt.yaml_file import read_model

ROOT = engine.ROOT
#: the paper's simulated tasks: the default set
DEFAULT_TASKS = ("S1", "S2", "S3", "S4", "S5")


@dataclass(frozen=True)
class Campaign:
    """What a command line asks for, resolved: tasks (name -> label), seeds, world, output directory."""

    tasks: dict[str, str]  # task name -> its label in tables ("S1 boil_water")
    seeds: list[int]
    world: str
    out: Path


@dataclass(frozen=True)
class Experiment:
    """One experiment: its name, its configurations, and how it writes ``table.md`` and plots."""

    name: str
    description: str
    #: the (strategy, viewpoints) configurations it compares, from the parsed options
    configurations: Callable[[argparse.Namespace], list[tuple[str, str]]]
    #: writes the plots into the campaign's directory and returns table.md's text
    report: Callable[[list[dict], Campaign], str]
    #: adds the experiment's own options to the parser
    options: Callable[[argparse.ArgumentParser], None] = field(default=lambda parser: None)


def parser(experiment: Experiment) -> argparse.ArgumentParser:
    """The command's options: the common ones and the experiment's own."""
    ap = argparse.ArgumentParser(prog=f"tools/experiments/{experiment.name}.py", description=experiment.description)
    ap.add_argument("--world", choices=("symbolic", "pybullet"), default="symbolic")
    ap.add_argument("--tasks", nargs="+", default=list(DEFAULT_TASKS), metavar="TASK",
                    help="task names (trees/<name>.yaml) or the paper's ids: S1-S5, T1-T4 (default S1-S5)")
    ap.add_argument("--seeds", default="50", help="N: seeds 0..N-1; A-B: seeds A..B inclusive (default 50)")
    ap.add_argument("--out", type=Path, help=f"output directory (default docs/results/{experiment.name})")
    ap.add_argument("--resume", action="store_true", help="keep episodes.jsonl and run only the missing episodes")
    ap.add_argument("--log", type=Path, metavar="FILE",
                    help="the episode log to append to and report from, kept as --resume keeps it (default "
                         "OUT/episodes.jsonl); experiments sharing one run each episode once")
    ap.add_argument("--report-only", action="store_true", help="write the table and plots from existing rows")
    ap.add_argument("--rows", type=Path, metavar="FILE",
                    help="report on another campaign's episodes.jsonl (the same episodes, read this experiment's "
                         "way: failures from strategies'), running nothing")
    ap.add_argument("--workers", type=int, help="LocalCluster worker processes (default: one per core)")
    ap.add_argument("--address", help="join this Dask scheduler (tcp://host:port) instead of a LocalCluster")
    experiment.options(ap)
    return ap


def choices(setting: str) -> tuple[str, ...]:
    """The values a run setting allows, read from its declaration at run time (``verify``: the
    verification strategies; ``viewpoints``: the viewpoint strategies), so that a strategy added to
    the settings is an experiment's column without touching the experiments."""
    return typing.get_args(RunConfig.__pydantic_fields__[setting].annotation)


def chosen(given: list[str] | None, setting: str) -> list[str]:
    """``given`` (an option's values) checked against the setting's values; all of them if None."""
    allowed = choices(setting)
    for word in given or ():
        if word not in allowed:
            raise InputError(f"--{setting}", f"unknown {setting} {word!r} (known: {', '.join(allowed)})")
    return list(given or allowed)


def tasks_named(given: list[str]) -> dict[str, str]:
    """Task names (or paper ids) -> {name: label}; an InputError naming the first unknown one."""
    known = {}
    for path in sorted((ROOT / "trees").glob("*.yaml")):
        paper = read_model(path, taskfile.TaskFile, "task file", "name:, paper_task:, ...").paper_task  # the header only
        known[path.stem] = known[paper or path.stem] = (path.stem, f"{paper} {path.stem}" if paper else path.stem)
    chosen = {}
    for word in given:
        if word not in known:
            raise InputError("--tasks", f"unknown task {word!r} (known: {', '.join(sorted(known))})")
        name, label = known[word]
        chosen[name] = label
    return chosen


def seeds_of(text: str) -> list[int]:
    """``N`` -> 0..N-1; ``A-B`` -> A..B inclusive; an InputError for anything else."""
    try:
        if "-" in text:
            first, last = (int(x) for x in text.split("-"))
            if first <= last:
                return list(range(first, last + 1))
        elif int(text) > 0:
            return list(range(int(text)))
    except ValueError:
        pass
    raise InputError("--seeds", f"{text!r} is not a count (50) or a range (1000-1199)")


#: seeds per block of a campaign's order (see :func:`keys`)
SEED_BLOCK = 10


def keys(experiment: Experiment, campaign: Campaign, configurations: list[tuple[str, str]]) -> list[Key]:
    """Every episode of the campaign, in blocks of :data:`SEED_BLOCK` seeds: within a block grouped
    by configuration and task, so a worker's sessions stay warm for ten episodes; block after
    block, so a campaign stopped part-way (a pybullet one spans sittings) has every cell at nearly
    the same count of seeds, not some cells full and others empty. Within a block the
    configurations go in the order given, each over every task: the first (the reference, the full
    method) is measured on all tasks before the others start."""
    blocks = [campaign.seeds[i:i + SEED_BLOCK] for i in range(0, len(campaign.seeds), SEED_BLOCK)]
    return [Key(experiment.name, campaign.world, task, strategy, viewpoints, seed)
            for block in blocks for strategy, viewpoints in configurations for task in campaign.tasks
            for seed in block]


def main(experiment: Experiment, argv: list[str] | None = None, fault: Callable[[Key], None] | None = None) -> int:
    """Run the experiment's command line; ``fault`` is a test's hook (see :func:`engine.episode_row`)."""
    args = parser(experiment).parse_args(argv)
    try:
        campaign = Campaign(tasks_named(args.tasks), seeds_of(args.seeds), args.world,
                            args.out or ROOT / "docs" / "results" / experiment.name)
        configurations = experiment.configurations(args)
        if args.report_only and not (args.log or campaign.out / "episodes.jsonl").exists():
            raise InputError("--log" if args.log else "--out",
                             f"no episode log {args.log or campaign.out / 'episodes.jsonl'} to report on (run the experiment first)")
        if args.rows is not None and not args.rows.is_file():
            raise InputError("--rows", f"no such file: {args.rows}")
        if not args.report_only and (args.resume or args.log is not None):
            same_version(results.EpisodeLog(args.log or campaign.out / "episodes.jsonl"), campaign.world,
                         "--log" if args.log else "--resume")
    except InputError as exc:
        print(f"{experiment.name}: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    if args.rows is not None:
        return report_from(experiment, campaign, configurations, results.EpisodeLog(args.rows))
    log = results.EpisodeLog(args.log or campaign.out / "episodes.jsonl")
    campaign.out.mkdir(parents=True, exist_ok=True)  # the log may be elsewhere (--log)
    if not args.report_only:
        try:
            with stoppable():
                run(experiment, campaign, configurations, log, args, fault)
        except KeyboardInterrupt:  # the rows written so far are on disk; the episodes in flight are lost
            print(f"{experiment.name}: interrupted; {len(log.rows())} rows kept in {log.path}, --resume runs the "
                  "rest", file=sys.stderr)
            return EXIT_INTERRUPTED
    # the report covers every row of the log it could have run (a resumed campaign may have run
    # other tasks or strategies before; a shared log holds other experiments' rows of its configurations)
    every = set(experiment.configurations(parser(experiment).parse_args([])))
    rows = [r for r in log.rows() if (r["strategy"], r["viewpoints"]) in every]
    # a report-only run from a shared log says where its rows came from, unless a run's record is there
    read_from = args.report_only and args.log is not None and not (campaign.out / "run.json").exists()
    return report(experiment, campaign, rows, log if read_from else None)


def same_version(log: results.EpisodeLog, world: str, option: str) -> None:
    """An InputError if the log to continue holds rows of ``world`` run by another version of the
    world's mechanics or of the simulated VLM than this checkout's: a changed model is a new
    version, and its figures are measured anew, in a log of their own, never mixed into the old
    one's (a campaign's rows are told apart by those versions, not by the commit alone)."""
    now = {"world_version": current_world_version(world), "vlm_version": MODEL_VERSION}
    for r in log.rows():
        if r.get("world") != world or not r.get("runnable"):
            continue  # another world's rows, or a "not runnable" row, which ran no model
        # a crashed episode's row records no versions (results.crashed): it says nothing either way
        other = {k: v for k in now if (v := r.get(k)) is not None and v != now[k]}
        if other:
            raise InputError(option, f"{log.path} holds rows of {', '.join(f'{k} {v}' for k, v in other.items())}; "
                             f"this checkout is {', '.join(f'{now[k]}' for k in other)}: a new version starts a new "
                             "log (another --out or --log; campaign.sh: DIR=...)")


def current_world_version(world: str) -> str | None:
    """The version of ``world``'s mechanics that a row run by this checkout records (none for the
    symbolic world)."""
    if world != "pybullet":
        return None
    from vap_bt.sim.pybullet_world import WORLD_VERSION  # pybullet is loaded only for the pybullet world
    return WORLD_VERSION


@contextlib.contextmanager
def stoppable():
    """SIGTERM, and SIGINT even when the shell that started the command ignores it (a background
    job inherits SIGINT ignored, so Python never installs its Ctrl-C), stop the sitting as Ctrl-C
    does: rows kept, run.json written. Signal handlers belong to the main thread only."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum, frame):
        raise KeyboardInterrupt(signal.Signals(signum).name)

    previous = {sig: signal.signal(sig, stop) for sig in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def report_from(experiment: Experiment, campaign: Campaign, configurations: list[tuple[str, str]],
                source: results.EpisodeLog) -> int:
    """``--rows``: this experiment's table and plots from another campaign's rows of the same
    configurations and tasks (whatever experiment ran them), and a run.json saying where they came from."""
    wanted = set(configurations)
    rows = [r for r in source.rows() if (r["strategy"], r["viewpoints"]) in wanted and r["task"] in campaign.tasks]
    if not rows:
        print(f"{experiment.name}: --rows: {source.path} has no episode of these configurations and tasks",
              file=sys.stderr)
        return EXIT_BAD_INPUT
    return report(experiment, campaign, rows, source)


def report(experiment: Experiment, campaign: Campaign, rows: list[dict],
           read_from: results.EpisodeLog | None = None) -> int:
    """Write the outputs of ``rows`` into the campaign's directory — episodes.csv, table.md (the
    experiment's report, its tasks those the rows ran, in the paper's order) and its plots — and,
    when the rows were only read (``read_from``: ``--rows``, ``--report-only`` of a shared log), a
    run.json saying where they came from; print the table."""
    named = tasks_named(sorted({r["task"] for r in rows}))
    campaign = replace(campaign, tasks=dict(sorted(named.items(), key=lambda item: item[1])))
    campaign.out.mkdir(parents=True, exist_ok=True)
    results.write_csv(rows, campaign.out / "episodes.csv")
    (campaign.out / "table.md").write_text(experiment.report(rows, campaign) + provenance(rows))
    if read_from is not None:
        _read_from(experiment, campaign, read_from, rows)
    print((campaign.out / "table.md").read_text())
    return EXIT_OK


def _read_from(experiment: Experiment, campaign: Campaign, source: results.EpisodeLog, rows: list[dict]) -> None:
    """run.json of a report that ran nothing (``--rows``, ``--report-only``): where its rows came from."""
    meta = {"command": " ".join([sys.executable, *sys.argv]), "experiment": experiment.name, "rows_from": str(source.path),
            "episodes": len(rows), "seeds": _span(sorted({r["seed"] for r in rows})), "commit": _commit()}
    (campaign.out / "run.json").write_text(json.dumps(meta, indent=2) + "\n")


def run(experiment: Experiment, campaign: Campaign, configurations: list[tuple[str, str]],
        log: results.EpisodeLog, args: argparse.Namespace, fault) -> None:
    """Run the campaign's missing episodes, appending each row to ``log``; then write run.json,
    also when Ctrl-C stopped the sitting (marked ``interrupted``; the KeyboardInterrupt goes on).
    With nothing left to run, nothing is run and run.json is left as it is."""
    commit = _commit()  # before the log is touched: the code that runs is this checkout's as the campaign starts
    log.start(args.resume or args.log is not None)  # a shared log is never emptied by one of its experiments
    started = time.strftime("%Y-%m-%dT%H:%M:%S%z")
    done = log.episodes()
    todo = [k for k in keys(experiment, campaign, configurations) if k.episode() not in done]
    if not todo:  # a campaign script passing a finished block: no sitting to record, no cluster to start
        print(f"  [{experiment.name}: nothing to run, {len(done)} episodes already done]", file=sys.stderr, flush=True)
        return
    t0, written, stopped = time.perf_counter(), 0, False
    with engine.open_client(args.address, args.workers) as client:
        n_workers = engine.workers(client)
        progress = Progress(len(todo), "episodes", label=experiment.name)
        print(f"  [{experiment.name}: {len(todo)} episodes on {n_workers} workers"
              f"{f', {len(done)} already done' if done else ''}]", file=sys.stderr, flush=True)

        def emit(row: dict) -> None:
            nonlocal written
            log.append({**row, "commit": commit})  # which code ran it: a campaign may span sittings and commits
            written += 1
            progress.step()

        cpu0 = engine.cpu_times(client)
        try:
            engine.run(client, todo, emit, fault)
        except KeyboardInterrupt:
            stopped = True  # the sitting is still recorded below: its rows are in the log, and say which commit
        cpu = engine.cpu_since(client, cpu0) if not stopped else None
    wall = time.perf_counter() - t0
    meta = {"command": " ".join([sys.executable, *sys.argv]), "experiment": experiment.name,
            "world": campaign.world, "tasks": list(campaign.tasks), "seeds": _span(campaign.seeds),
            "configurations": [list(c) for c in configurations], "resumed": bool(done), "log": str(log.path), "episodes": written,
            "interrupted": stopped, "workers": n_workers, "cluster": args.address or "LocalCluster",
            "wall_s": round(wall, 1), "workers_cpu_s": round(cpu, 1) if cpu is not None else None,
            "client_cpu_s": round(time.process_time(), 1), "wall": duration(wall),
            "episodes_per_hour": round(written / wall * 3600) if wall > 0 else None,
            "commit": commit, "started": started, "versions": {**versions(), "dask": dask.__version__,
                                                                   "distributed": distributed.__version__}}
    # a resumed campaign keeps the record of its earlier sittings: each one's command, commit and rate
    meta["sittings"] = _sittings(campaign.out / "run.json") if done else []
    meta["sittings"].append({k: meta[k] for k in SITTING})
    (campaign.out / "run.json").write_text(json.dumps(meta, indent=2) + "\n")
    if stopped:
        raise KeyboardInterrupt


#: what run.json keeps of each sitting of a campaign
SITTING = ("command", "started", "commit", "episodes", "interrupted", "workers", "cluster", "wall", "wall_s", "episodes_per_hour")


def _sittings(path: Path) -> list[dict]:
    """The earlier sittings recorded in a campaign's run.json (one, from its top-level fields, when
    it was written before sittings were kept; none when there is no readable run.json)."""
    try:
        meta = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError):
        return []
    return meta.get("sittings") or [{k: meta.get(k) for k in SITTING}]


def provenance(rows: list[dict]) -> str:
    """table.md's last line: the commits its rows were run on (a campaign resumed on changed code
    mixes versions of the executive, and its table must say so)."""
    counts = Counter(row.get("commit") or "unrecorded" for row in rows)
    listed = ", ".join(f"{c[:12]}{c[40:]} ({n} episodes)" for c, n in counts.items())
    return f"\nEpisodes run on: {listed}.\n"


def _span(seeds: list[int]) -> str | list[int]:
    """``0-199`` for a contiguous run of seeds, else the list."""
    return f"{seeds[0]}-{seeds[-1]}" if seeds == list(range(seeds[0], seeds[-1] + 1)) else seeds


def _commit() -> str:
    """The checkout's commit, ``+dirty`` when tracked files that could change an episode differ
    from it: not those under docs/ (a campaign's own rows and tables, the text being written
    beside them), which made every campaign after the first of a sitting "+dirty"."""
    def git(*a: str) -> str:
        return subprocess.run(["git", *a], cwd=ROOT, capture_output=True, text=True).stdout.strip()

    changed = git("status", "--porcelain", "--untracked-files=no", "--", ".", ":(exclude)docs")
    return git("rev-parse", "HEAD") + ("+dirty" if changed else "")
