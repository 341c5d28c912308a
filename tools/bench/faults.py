"""Fault campaign: does the executive ever claim a goal the world denies, crash or hang, when
things go wrong — its own actions failing (Table II) and people disturbing the world?

N seeded episodes over every task in trees/ (episode i runs task i mod 9 with seed
``first_seed + i``), each with Table II situation injection on, the simulated VLM at its calibrated
model (``--vlm-noise 1``) and, with probability ``--disturbance``, one scripted disturbance
(:mod:`vap_bt.sim.disturbances`: after one of the first actions a person moves a thing the goal
names to another surface, or pushes a door or a cupboard's leaf half shut or shut). The world
does the disturbing and records it beside Table II's situations; the executive only perceives.

Every episode runs in a worker process under a watchdog: the executive's own time budget is half
the episode's ``--budget-s``, and a worker that has not answered by the whole budget is killed
and the episode counted as a *hang* (a worker that dies, or an exception escaping the episode, is
a *crash*). The measures, per episode, against the world's oracle:

* *false success* — the executive reported success (``success``) and the world denies the goal
  (``goal_satisfied`` false); its rate over all episodes with its 95 % Wilson interval (target
  <= 1 %);
* per fault kind (each Table II kind, each disturbance kind, and in pybullet the robot's actions
  that failed by physics alone, :mod:`vap_bt.sim.natural_failures`): how many were injected, how many
  *detected* — a situation the executive found names the thing the fault changed (what fell, was
  moved or pushed; for a failure that dropped nothing, the thing the action was about), at any
  point of the episode — and, over the episodes the kind occurred in, how many were *recovered*
  (success the world confirms), *aborted* with a reason naming the fault's thing or another
  reason, and false successes, with those where a fault of the kind went undetected.

One JSON line per episode is appended to ``--jsonl`` as it ends (default
``docs/figures/faults_<world>_<commit>.jsonl``); a run started again on the same file skips the
episodes it holds. The table is printed in markdown.

    python tools/bench/faults.py [--episodes 1000] [--world symbolic|pybullet] [--vlm-noise 1]
                                 [--disturbance 0.5] [--budget-s 120] [--jobs 1] [--first-seed 0]
                                 [--claim-risk P] [--jsonl PATH] [--table-only]

``--world pybullet`` runs the same campaign in the pybullet household (default 50 episodes,
budget 900 s each): the same disturbances as its scripted ones.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import re
import subprocess
import sys
import time
import traceback
from collections import deque
from dataclasses import asdict, dataclass, field
from multiprocessing.connection import wait
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.bench.intervals import wilson  # noqa: E402
from tools.progress import Progress  # noqa: E402
from vap_bt.sim.disturbances import KINDS as DISTURBANCES, DisturbanceModel  # noqa: E402

#: the default wall-clock budget of one episode, by world (s)
BUDGET_S = {"symbolic": 120.0, "pybullet": 900.0}


@dataclass(frozen=True)
class Job:
    """One episode to run."""

    task_file: str
    task: str
    seed: int
    world: str
    vlm_noise: float
    disturbance: float
    budget_s: float
    claim_risk: float | None  # None: the executive's default (lines written before it say nothing)


@dataclass
class Fault:
    """One fault the world recorded in an episode, and whether the executive noticed it."""

    kind: str
    source: str  # "table2", "disturbance" or "natural" (an action that failed by physics alone)
    step: int
    action: str
    affected: list[str]
    detected: bool


@dataclass(frozen=True)
class EpisodeRow(Job):
    """One episode's line in the JSONL: its job, and what came of it."""

    outcome: str  # recovered | false_success | aborted | crash | hang
    success: bool
    goal_satisfied: bool
    reason: str
    wall_s: float
    replans: int = 0
    situations: int = 0
    faults: list[dict] = field(default_factory=list)
    scheduled: list[dict] = field(default_factory=list)  # the disturbances the world drew
    error: str | None = None  # a crash's traceback

    @property
    def key(self) -> tuple[str, int]:
        return self.task, self.seed


# -- one episode, in a worker --------------------------------------------------------------------


def _names(situation: dict) -> set[str]:
    """The names a situation's atom and action mention."""
    return set(re.findall(r"[\w-]+", f"{situation.get('predicate') or ''} {situation.get('action') or ''}"))


def faults_of(injected: list[dict], situations: list[dict]) -> list[Fault]:
    """The world's record of the episode's faults, each marked detected when a situation the
    executive found names the thing it changed."""
    found = [_names(s) for s in situations]
    out = []
    for i in injected:
        affected = list(i.get("affected") or i["args"][:1])
        out.append(Fault(i["kind"], i["source"], i["step"],
                         f"{i['action']}({', '.join(i['args'])})", affected,
                         any(set(affected) & names for names in found)))
    return out


def outcome_of(success: bool, satisfied: bool) -> str:
    if success:
        return "recovered" if satisfied else "false_success"
    return "aborted"


def _session(job: Job, sessions: dict):
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    if job.task_file not in sessions:
        task = taskfile.load(job.task_file)
        # the executive's own clean end comes well before the watchdog's
        cfg = RunConfig.from_task(task, world=job.world, injection=True, vlm_noise=job.vlm_noise,
                                  disturbance=job.disturbance, max_seconds=job.budget_s / 2,
                                  claim_risk=job.claim_risk)
        sessions[job.task_file] = Session(task, cfg)
    return sessions[job.task_file]


def run_job(job: Job, sessions: dict) -> EpisodeRow:
    """Run ``job`` on the worker's session of its task (made on first use); an exception that
    escapes is a crash, scored from what the world recorded until then."""
    base = asdict(job)
    t0 = time.perf_counter()
    session = None
    try:
        session = _session(job, sessions)
        rep = session.episode(job.seed)
    except Exception:  # noqa: BLE001 - what the campaign measures
        injected = [i.to_json() for i in session.world.oracle.injected()] if session else []
        sessions.pop(job.task_file, None)  # a session an exception went through is not trusted again
        return EpisodeRow(**base, outcome="crash", success=False, goal_satisfied=False, reason="crash",
                          wall_s=round(time.perf_counter() - t0, 3), faults=[asdict(f) for f in faults_of(injected, [])],
                          scheduled=session.world_disturbances() if session else [], error=traceback.format_exc())
    return EpisodeRow(**base, outcome=outcome_of(rep["success"], rep["goal_satisfied"]), success=rep["success"],
                      goal_satisfied=rep["goal_satisfied"], reason=rep["reason"], wall_s=rep["wall_s"],
                      replans=rep["replans"], situations=len(rep["situations"]),
                      faults=[asdict(f) for f in faults_of(rep["injected"], rep["situations"])],
                      scheduled=rep["world"]["disturbances"])


def _serve(conn) -> None:
    """A worker: run the jobs sent until None, keeping one session per task."""
    sessions: dict = {}
    while (job := conn.recv()) is not None:
        conn.send(run_job(job, sessions))


# -- the watchdog --------------------------------------------------------------------------------


class Worker:
    """A worker process and the job it is running, with that job's deadline."""

    def __init__(self) -> None:
        ctx = mp.get_context("spawn")
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_serve, args=(child,), daemon=True)
        self.proc.start()
        child.close()
        self.job: Job | None = None
        self.deadline = 0.0

    def submit(self, job: Job) -> None:
        self.job, self.deadline = job, time.monotonic() + job.budget_s
        self.conn.send(job)

    def stop(self, kill: bool = False) -> None:
        if kill:
            self.proc.kill()
        else:
            try:
                self.conn.send(None)
            except OSError:
                pass
        self.proc.join(timeout=10)
        if self.proc.is_alive():
            self.proc.kill()
            self.proc.join()


def lost(job: Job, outcome: str, why: str, wall_s: float) -> EpisodeRow:
    """The row of an episode whose worker hung or died: no report; the disturbances it was to
    have are drawn again here (the model is deterministic in the seed)."""
    from vap_bt import taskfile

    scheduled = DisturbanceModel(job.disturbance).draw(taskfile.load(job.task_file).planning, job.seed)
    return EpisodeRow(**asdict(job), outcome=outcome, success=False, goal_satisfied=False, reason=why,
                      wall_s=round(wall_s, 3), scheduled=[d.to_json() for d in scheduled], error=why)


def run_campaign(jobs: list[Job], workers: int, emit) -> None:
    """Run ``jobs`` on ``workers`` processes, calling ``emit(row)`` as each ends (in any order)."""
    if not jobs:
        return
    todo = deque(jobs)
    pool = [Worker() for _ in range(max(1, min(workers, len(jobs))))]
    try:
        while todo or any(w.job for w in pool):
            for w in pool:
                if w.job is None and todo:
                    w.submit(todo.popleft())
            busy = [w for w in pool if w.job is not None]
            ready = wait([w.conn for w in busy], timeout=max(0.0, min(w.deadline for w in busy) - time.monotonic()))
            for i, w in enumerate(pool):
                if w.job is None:
                    continue
                job, started = w.job, w.deadline - w.job.budget_s
                if w.conn in ready:
                    try:
                        row = w.conn.recv()
                    except (EOFError, OSError):
                        row = lost(job, "crash", f"worker died (exit {w.proc.exitcode})", time.monotonic() - started)
                        w.stop(kill=True)
                        pool[i] = w = Worker()
                elif time.monotonic() >= w.deadline:
                    row = lost(job, "hang", f"no end within the budget of {job.budget_s:g} s", job.budget_s)
                    w.stop(kill=True)  # the only way to stop an episode that does not end
                    pool[i] = w = Worker()
                else:
                    continue
                w.job = None
                emit(row)
    finally:
        for w in pool:
            w.stop(kill=w.job is not None)


# -- the table -----------------------------------------------------------------------------------


def _pct(k: int, n: int) -> str:
    lo, hi = wilson(k, n)
    return f"{k}/{n} = {k / n if n else 0:.1%} (95 % CI {lo:.1%}–{hi:.1%})"


def summary(rows: list[EpisodeRow]) -> str:
    n = len(rows)
    count = lambda o: sum(r.outcome == o for r in rows)  # noqa: E731
    claimed = sum(r.success for r in rows)
    false = count("false_success")
    return "\n".join([
        "| episodes | crashes | hangs | claimed success | recovered (world agrees) | aborted | false successes (of all episodes) |",
        "|---:|---:|---:|---:|---:|---:|---|",
        f"| {n} | {count('crash')} | {count('hang')} | {claimed} | {count('recovered')} | {count('aborted')} | {_pct(false, n)} |",
        "",
        f"False successes of claimed successes: {_pct(false, claimed)}.",
    ])


def _names_fault(row: EpisodeRow, faults: list[dict]) -> bool:
    words = set(re.findall(r"[\w-]+", row.reason))
    return any(set(f["affected"]) & words for f in faults)


def per_kind(rows: list[EpisodeRow]) -> str:
    """Per fault kind: occurrences injected and detected; over the episodes it occurred in, their
    outcomes (see the module docstring)."""
    kinds = sorted({f["kind"] for r in rows for f in r.faults}, key=lambda k: (k in DISTURBANCES, k))
    out = ["| fault kind | source | injected | detected | episodes | recovered | aborted, reason names it "
           "| aborted, other reason | false success | of which undetected | crash / hang |",
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for kind in kinds:
        mine = [(r, [f for f in r.faults if f["kind"] == kind]) for r in rows]
        mine = [(r, fs) for r, fs in mine if fs]
        occ = [f for _, fs in mine for f in fs]
        by = lambda o: [(r, fs) for r, fs in mine if r.outcome == o]  # noqa: E731
        aborted = by("aborted")
        named = sum(_names_fault(r, fs) for r, fs in aborted)
        false = by("false_success")
        out.append(f"| {kind} | {occ[0]['source']} | {len(occ)} | {sum(f['detected'] for f in occ)} | {len(mine)} "
                   f"| {len(by('recovered'))} | {named} | {len(aborted) - named} | {len(false)} "
                   f"| {sum(any(not f['detected'] for f in fs) for _, fs in false)} "
                   f"| {len(by('crash')) + len(by('hang'))} |")
    clean = [r for r in rows if not r.faults]
    out.append(f"| (no fault recorded) | – | – | – | {len(clean)} | {sum(r.outcome == 'recovered' for r in clean)} "
               f"| – | {sum(r.outcome == 'aborted' for r in clean)} | {sum(r.outcome == 'false_success' for r in clean)} "
               f"| – | {sum(r.outcome in ('crash', 'hang') for r in clean)} |")
    return "\n".join(out)


def unapplied(rows: list[EpisodeRow]) -> str:
    """Disturbances drawn for an episode that did not happen (the episode ended first, the thing
    was in the hand, the leaf was already so)."""
    drawn = sum(len(r.scheduled) for r in rows)
    applied = sum(f["source"] == "disturbance" for r in rows for f in r.faults)
    return f"Disturbances drawn {drawn}, applied {applied} (the others came after the episode's end or changed nothing)."


def report(rows: list[EpisodeRow]) -> str:
    return "\n\n".join([summary(rows), per_kind(rows), unapplied(rows)])


# -- the command ---------------------------------------------------------------------------------


def _commit() -> str:
    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()


def load_rows(path: Path) -> list[EpisodeRow]:
    if not path.exists():
        return []
    return [EpisodeRow(**{"claim_risk": None, **json.loads(line)}) for line in path.read_text().splitlines() if line.strip()]


def make_jobs(args, paths: list[Path]) -> list[Job]:
    from vap_bt import taskfile

    names = [taskfile.load(p).name for p in paths]
    return [Job(str(paths[i % len(paths)]), names[i % len(paths)], args.first_seed + i, args.world, args.vlm_noise,
                args.disturbance, args.budget_s, args.claim_risk) for i in range(args.episodes)]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--episodes", type=int, help="default 1000 (symbolic), 50 (pybullet)")
    ap.add_argument("--world", choices=tuple(BUDGET_S), default="symbolic")
    ap.add_argument("--vlm-noise", type=float, default=1.0, help="the simulated VLM's error scale (1: calibrated)")
    ap.add_argument("--disturbance", type=float, default=0.5, help="probability of a disturbance per episode")
    ap.add_argument("--budget-s", type=float, help="wall-clock budget per episode (default 120 s symbolic, 900 s pybullet)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--first-seed", type=int, default=0)
    ap.add_argument("--claim-risk", type=float, help="the executive's accepted chance of a false claim per goal atom "
                                                      "(default: its own, vap_bt.perception.evidence.CLAIM_RISK)")
    ap.add_argument("--tasks", help="comma-separated task names (default: every file in trees/)")
    ap.add_argument("--jsonl", help="one line per episode; resumed if it exists (default docs/figures/faults_<world>_<commit>.jsonl)")
    ap.add_argument("--table-only", action="store_true", help="print the table of --jsonl, run nothing")
    args = ap.parse_args(argv)
    args.episodes = args.episodes if args.episodes is not None else (1000 if args.world == "symbolic" else 50)
    args.budget_s = args.budget_s or BUDGET_S[args.world]
    paths = sorted((ROOT / "trees").glob("*.yaml"))
    if args.tasks:
        paths = [p for p in paths if p.stem in set(args.tasks.split(","))]
    out = Path(args.jsonl or ROOT / "docs" / "figures" / f"faults_{args.world}_{_commit()}.jsonl")
    rows = load_rows(out)
    if not args.table_only:
        jobs = make_jobs(args, paths)
        done = {r.key for r in rows}
        todo = [j for j in jobs if (j.task, j.seed) not in done]
        print(f"{len(jobs)} episodes, {len(jobs) - len(todo)} already in {out}", file=sys.stderr)
        progress = Progress(len(todo), "episodes")
        out.parent.mkdir(parents=True, exist_ok=True)
        with out.open("a") as f:
            def emit(row: EpisodeRow) -> None:
                f.write(json.dumps(asdict(row)) + "\n")
                f.flush()  # what ran is kept if the campaign is stopped
                rows.append(row)
                progress.step(note="" if row.outcome in ("recovered", "aborted") else
                              f"{row.outcome}: {row.task} seed {row.seed}")

            run_campaign(todo, args.jobs, emit)
    print(f"Fault campaign, {args.world} world, {len(rows)} episodes ({out.name}):\n")
    print(report(rows))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
