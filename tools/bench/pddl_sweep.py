"""Which public PDDL runs: every IPC classical domain's smallest problem, through `vap-bt run`.

For each domain under ``tools/bench/ipc/`` (one domain file and its smallest problem each, from
the Fast Downward benchmark collection; see that folder's README) this runs

1. **Fast Downward alone** (``lama-first``, the translator and search unified-planning ships),
   30 s at most: does a plan exist that a planner finds quickly?
2. **``vap-bt run --domain D --problem P``** in the symbolic world, noise off, no injection,
   90 s at most — the whole executive: parse, ground, plan, compile, tick every check, score.

and sorts the run into one outcome: ``ran`` (exit 0: the world confirms the goal), ``not_reached``
(exit 1), ``refused`` (exit 2 with one line saying why), ``no_plan`` (exit 3),
``planner_timeout`` (exit 5: Fast Downward gave up at the executive's 60 s), ``timeout`` (the
run over 90 s) or ``traceback`` (anything that printed a Python traceback, or any other exit). The issue's
promise: every problem Fast Downward solves within 30 s runs within 90 s, and none ends in a
traceback.

    python tools/bench/pddl_sweep.py [--jobs 2] [--out docs/figures/pddl_sweep.jsonl] [DOMAIN ...]

One JSON line per domain is appended to ``--out`` as it finishes, and domains already there are
skipped (``--fresh`` starts over): a stopped sweep continues where it stopped. The table goes to
stdout; progress to stderr.
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.progress import Progress  # noqa: E402

IPC = ROOT / "tools" / "bench" / "ipc"
FD_LIMIT_S = 30.0
RUN_LIMIT_S = 90.0
OUTCOMES = ("ran", "not_reached", "refused", "no_plan", "planner_timeout", "timeout", "traceback")
EXIT_OUTCOME = {0: "ran", 1: "not_reached", 2: "refused", 3: "no_plan", 5: "planner_timeout"}


def bounded(cmd: list[str], limit_s: float, **kw) -> subprocess.CompletedProcess | None:
    """``cmd`` run to its end, or None when it outlives ``limit_s``. It runs in a process group of
    its own, killed whole at the limit: a run's planner and translator are its children, and
    killing the run alone left them searching (two of them for 35 min of CPU, a translator at
    14 GB, in the first sweep)."""
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, **kw)
    try:
        out, err = proc.communicate(timeout=limit_s)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None
    finally:
        try:
            os.killpg(proc.pid, signal.SIGKILL)  # anything the command left behind in its group
        except ProcessLookupError:
            pass
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def fast_downward_command(tmp: str, *args: str) -> list[str]:
    """Fast Downward's driver as unified-planning ships it, its translated task in ``tmp``."""
    from up_fast_downward import FastDownwardPDDLPlanner

    driver = FastDownwardPDDLPlanner()._base_cmd("plan")[1]
    return [sys.executable, str(driver), "--sas-file", f"{tmp}/output.sas", *args]


def fast_downward(domain: Path, problem: Path) -> dict:
    """Fast Downward's own verdict on the problem within FD_LIMIT_S."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = fast_downward_command(tmp, "--plan-file", f"{tmp}/plan", "--alias", "lama-first", str(domain),
                                    str(problem))
        t0 = time.perf_counter()
        done = bounded(cmd, FD_LIMIT_S, cwd=tmp)
        if done is None:
            return {"fd": "timeout", "fd_s": FD_LIMIT_S}
        seconds = time.perf_counter() - t0
        plans = sorted(Path(tmp).glob("plan*"))
        steps = sum(1 for line in plans[-1].read_text().splitlines() if line.startswith("(")) if plans else None
    status = "solved" if plans else ("unsolvable" if done.returncode in (11, 12) else f"exit {done.returncode}")
    return {"fd": status, "fd_s": round(seconds, 2), "fd_steps": steps}


def vap_bt_run(domain: Path, problem: Path) -> dict:
    """The executive's run of the problem within RUN_LIMIT_S, sorted into one outcome."""
    cmd = [sys.executable, "-m", "vap_bt", "run", "--domain", str(domain), "--problem", str(problem),
           "--world", "symbolic", "--vlm-noise", "0", "--no-injection", "--seed", "0", "--json", "-q"]
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    t0 = time.perf_counter()
    done = bounded(cmd, RUN_LIMIT_S, env=env, cwd=ROOT)
    if done is None:
        return {"outcome": "timeout", "run_s": RUN_LIMIT_S, "exit": None, "message": ""}
    seconds = time.perf_counter() - t0
    err = [line for line in done.stderr.splitlines() if line.strip()]
    outcome = EXIT_OUTCOME.get(done.returncode, "traceback")
    if "Traceback (most recent call last)" in done.stderr:
        outcome = "traceback"
    message = err[-1] if err and outcome != "ran" else ""
    steps = None
    if done.returncode in (0, 1):
        try:
            summary = json.loads(done.stdout)
        except ValueError:
            summary = {}
        steps = summary.get("actions_executed")  # a count in the summary (the report lists them)
        if done.returncode == 1:
            message = summary.get("reason", message)  # why the goal was not reached, not the table's last line
    return {"outcome": outcome, "run_s": round(seconds, 2), "exit": done.returncode, "message": message[:300],
            "steps": steps}


def sweep_one(name: str) -> dict:
    folder = IPC / name
    domain, problem = folder / "domain.pddl", folder / "problem.pddl"
    return {"domain": name, **fast_downward(domain, problem), **vap_bt_run(domain, problem)}


def table(rows: list[dict]) -> str:
    """Outcome counts, then the exceptions with their one line, as markdown."""
    by = collections.Counter(r["outcome"] for r in rows)
    fd_fast = [r for r in rows if r["fd"] == "solved" and r["fd_s"] <= FD_LIMIT_S]
    broken = [r for r in fd_fast if r["outcome"] != "ran"]
    lines = [f"{len(rows)} domains, one problem each; Fast Downward alone solves {len(fd_fast)} within "
             f"{FD_LIMIT_S:.0f} s", "", "| outcome | domains |", "|---|---:|"]
    lines += [f"| {o} | {by.get(o, 0)} |" for o in OUTCOMES]
    lines += ["", f"Of the {len(fd_fast)} Fast Downward solves, {len(fd_fast) - len(broken)} run end to end "
                  f"within {RUN_LIMIT_S:.0f} s; the others:", "",
              "| domain | FD (s) | outcome | vap-bt (s) | message |", "|---|---:|---|---:|---|"]
    lines += [f"| {r['domain']} | {r['fd_s']} | {r['outcome']} | {r['run_s']} | {r['message'] or ''} |"
              for r in sorted(broken, key=lambda r: (r["outcome"], r["domain"]))]
    return "\n".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("domains", nargs="*", help="domain folders under tools/bench/ipc (default: all)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "figures" / "pddl_sweep.jsonl")
    ap.add_argument("--fresh", action="store_true", help="start over instead of skipping domains in --out")
    args = ap.parse_args()
    names = args.domains or sorted(p.name for p in IPC.iterdir() if (p / "domain.pddl").is_file())
    unknown = [n for n in names if not (IPC / n / "domain.pddl").is_file()]
    if unknown:
        print(f"pddl_sweep: no such domain under {IPC}: {', '.join(unknown)}", file=sys.stderr)
        return 2
    if args.fresh and args.out.exists():
        args.out.unlink()
    done = {}
    if args.out.exists():
        done = {r["domain"]: r for r in map(json.loads, args.out.read_text().splitlines()) if r["domain"] in names}
    todo = [n for n in names if n not in done]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    progress = Progress(total=len(todo), unit="domains")
    with ThreadPoolExecutor(args.jobs) as pool, args.out.open("a") as out:
        for future in as_completed([pool.submit(sweep_one, n) for n in todo]):
            row = future.result()
            done[row["domain"]] = row
            out.write(json.dumps(row) + "\n")
            out.flush()
            progress.step(note=f"{row['domain']}: {row['outcome']}")
    print(table([done[n] for n in names]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
