"""Every task in trees/ in the pybullet household, Table II injection off and on, as a table.

Each episode is a full ``vap-bt run`` of the task (embedded default is Zenoh; here in-process
transport, the same skills and executive) in its own worker process: the house built for the
seed, the skills planning and moving the robot through the drivers, the executive perceiving
and replanning. A *success* is an episode the executive reported successful and the world
confirms (the oracle's ``goal_satisfied`` at the end); a *false success* one it reported that the
world denies; *unclaimed* one whose goal holds that the executive did not report (it could not
confirm it by looking). Wall time is per episode, on this machine, with ``--jobs`` episodes at once.

    python tools/bench/pybullet_tasks.py --seeds 20 --jobs 2 [--tasks boil_water,cut_lemon]
                                          [--injection off|on|both] [--protocol paper|lean]
                                          [--json docs/figures/pybullet_tasks.json]

``--protocol`` is the verification protocol every check asks with (the paper's Alg. 2 by default,
or the lean one: :mod:`vap_bt.perception.protocol`); a false success is as much a failure of one
as of the other.

Targets (issue: skills that move the robot): over 20 seeds per task, without injection >= 95 %
on every task; with injection >= 80 % on average; 0 false successes; median episode <= 30 s.
Issue "Perception that can fail" (the simulated VLM vlm-2, the detector and sensors that err):
without injection >= 95 %, with injection >= 75 %, claimed successes the world denies with their
rate and Wilson 95 % interval (target 0; printed below the table).
"""

from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import signal
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.bench.intervals import wilson  # noqa: E402
from vap_bt.report import verification_counts  # noqa: E402


def episode(job: tuple[str, bool, int, str, str]) -> dict:
    """One episode in this worker: (task file, injection, seed, protocol, sensors) -> the figures
    of its report."""
    path, injection, seed, protocol, sensors = job
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    task = taskfile.load(path)
    t0 = time.perf_counter()
    try:
        session = Session(task, RunConfig.from_task(task, world="pybullet", seed=seed, injection=injection,
                                                           protocol=protocol, sensors=sensors))
        try:
            rep = session.episode()
        finally:
            session.close()
    except Exception as exc:  # noqa: BLE001 - a crash is a failed episode, reported as such
        return {"task": task.name, "seed": seed, "injection": injection, "protocol": protocol, "sensors": sensors,
                "world_success": False, "claimed": False,
                "wall_s": time.perf_counter() - t0, "reason": f"crashed: {type(exc).__name__}: {exc}",
                "actions": 0, "replans": 0, "injected": 0, "looked": 0, "looked_right": 0, "graph": None}
    looked = verification_counts(rep["verifications"])
    return {"task": task.name, "seed": seed, "injection": injection, "protocol": protocol, "sensors": sensors,
            "world_success": bool(rep["goal_satisfied"]),
            "claimed": bool(rep["success"]), "wall_s": rep["wall_s"], "reason": rep["reason"],
            "actions": len(rep["actions_executed"]), "replans": rep["replans"], "injected": len(rep["injected"]),
            # how well the robot perceived, against the oracle: checks settled by looking that matched
            "looked": looked["looked"], "looked_right": looked["looked_correct"],
            "graph": (rep["perception"]["graph"]["initial"] or {}).get("relations_perceived")}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--first-seed", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--tasks", help="comma-separated task names (default: every file in trees/)")
    ap.add_argument("--injection", choices=("off", "on", "both"), default="both")
    ap.add_argument("--protocol", choices=("paper", "lean"), default="paper", help="how every check asks")
    ap.add_argument("--sensors", choices=("exact", "real"), default="exact",
                    help="the depth camera and the localiser (as `vap-bt run --sensors`)")
    ap.add_argument("--json", help="write every episode's figures here")
    args = ap.parse_args(argv)
    paths = sorted((ROOT / "trees").glob("*.yaml"))
    if args.tasks:
        wanted = set(args.tasks.split(","))
        paths = [p for p in paths if p.stem in wanted]
    modes = {"off": (False,), "on": (True,), "both": (False, True)}[args.injection]
    # seed by seed, both modes and every task in each: a run stopped early is still balanced
    jobs = [(str(p), inj, s, args.protocol, args.sensors) for s in range(args.first_seed, args.first_seed + args.seeds)
            for inj in modes for p in paths]
    rows: list[dict] = []
    t0 = time.perf_counter()
    # a kill stops the workers too, as Ctrl-C does: the pool's processes are not left running
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    pool = mp.get_context("spawn").Pool(args.jobs, maxtasksperchild=4)
    try:
        for r in pool.imap_unordered(episode, jobs):
            rows.append(r)
            done, took = len(rows), time.perf_counter() - t0
            mark = ("ok" if r["claimed"] else "unclaimed") if r["world_success"] else ("FALSE SUCCESS" if r["claimed"] else "failed")
            print(f"[{done}/{len(jobs)}] {r['task']} seed {r['seed']} injection {'on' if r['injection'] else 'off'}: "
                  f"{mark} in {r['wall_s']:.1f} s ({r['reason']}); {done / took * 60:.1f} episodes/min, "
                  f"about {(len(jobs) - done) * took / done:.0f} s left", file=sys.stderr, flush=True)
            if args.json:  # after every episode: what ran is kept if the run is stopped
                _write(Path(args.json), rows)
        pool.close()
    except KeyboardInterrupt:
        pool.terminate()
        print(f"stopped after {len(rows)} of {len(jobs)} episodes", file=sys.stderr)
        table(rows)
        return 130
    finally:
        pool.join()
    table(rows)
    return 0


def _write(path: Path, rows: list[dict]) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(json.dumps({"command": " ".join(sys.argv), "episodes": rows}, indent=1))
    tmp.replace(path)


def table(rows: list[dict]) -> None:
    """Per task and injection mode: *success* — the executive reported success and the world
    confirms it; *false* — reported, denied by the world; *unclaimed* — the world's goal holds but
    the executive did not report success (it could not confirm it by looking, or gave up)."""
    print(f"{'task':18s} {'injection':>9s} {'n':>4s} {'success':>8s} {'false':>6s} {'unclaimed':>10s} "
          f"{'median s':>9s} {'max s':>7s}")
    for inj in (False, True):
        sub = [r for r in rows if r["injection"] == inj]
        if not sub:
            continue
        rates = []
        for task in sorted({r["task"] for r in sub}):
            t = [r for r in sub if r["task"] == task]
            rates.append(_row(task, inj, t))
        _row("all", inj, sub, statistics.mean(rates))
        claimed = [r for r in sub if r["claimed"]]
        false = sum(not r["world_success"] for r in claimed)
        lo, hi = wilson(false, len(claimed))
        lo_all, hi_all = wilson(false, len(sub))
        looked, right = sum(r["looked"] for r in sub), sum(r["looked_right"] for r in sub)
        lo_v, hi_v = wilson(right, looked)
        print(f"  injection {'on' if inj else 'off'}: checks settled by looking that matched the world {right} of "
              f"{looked} ({right / looked if looked else 0:.3f}, 95 % interval {lo_v:.3f}-{hi_v:.3f})")
        print(f"  injection {'on' if inj else 'off'}: claimed successes the world denies {false} of {len(claimed)} claimed "
              f"({false / len(claimed) if claimed else 0:.1%}, 95 % interval {lo:.1%}-{hi:.1%}); of all episodes "
              f"{false} of {len(sub)} ({lo_all:.1%}-{hi_all:.1%})")


def _row(name: str, inj: bool, t: list[dict], rate: float | None = None) -> float:
    ok = sum(r["claimed"] and r["world_success"] for r in t)
    false = sum(r["claimed"] and not r["world_success"] for r in t)
    unclaimed = sum(r["world_success"] and not r["claimed"] for r in t)
    walls = [r["wall_s"] for r in t]
    rate = ok / len(t) if rate is None else rate  # "all": the mean of the tasks' rates
    print(f"{name:18s} {'on' if inj else 'off':>9s} {len(t):4d} {rate:8.0%} {false:6d} {unclaimed:10d} "
          f"{statistics.median(walls):9.1f} {max(walls):7.1f}")
    return rate


if __name__ == "__main__":
    raise SystemExit(main())
