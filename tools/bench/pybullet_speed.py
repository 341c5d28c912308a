"""Pybullet episode time, two checkouts side by side: the same episodes, and how much faster.

For each (task, seed) the episode runs once in each checkout, each in a fresh process of its own
(the world built first, as a campaign's worker does, and not counted), in turn — base, new, new,
base, ... so that a machine whose speed drifts slows both alike — and this prints per episode the
wall and CPU seconds of each and their ratios new/base, the medians, and whether the two
episodes were the same: their reports compared field for field, every field but those that say
how long something took or which commit ran (:data:`TIMING`). A speed-up is only one if that
holds for every episode. CPU seconds (:func:`cpu_seconds`: the process's own and its child
processes', as the planner's Fast Downward runs) are the figure to quote on a shared machine;
wall seconds count whatever else it ran meanwhile::

    git worktree add /tmp/base <commit>     # the checkout to compare against
    python tools/bench/pybullet_speed.py --base /tmp/base [--tasks S1 S3] [--seeds 0-1]
                                         [--json docs/figures/pybullet_speed.json]
    python tools/bench/pybullet_speed.py --base /tmp/base --episodes S1:1 halve_egg:0   # chosen episodes

The episodes are a campaign's (``tools/experiments/strategies.py --world pybullet``): strategy
``both``, the settings' default viewpoints, the task file's options, in-process skills.
Two campaigns' rows (``episodes.jsonl``, the same keys run at two commits) are compared field for
field, every field but ``wall_s``, with::

    python tools/bench/pybullet_speed.py --rows BASE/episodes.jsonl NEW/episodes.jsonl
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

#: report keys whose values are durations, clock readings or the code's version: the only ones
#: two runs of one episode may differ in. ``ticks`` too: the tree is ticked while the robot's
#: state service answers on a thread of its own (:func:`vap_bt.bt.inflight.body_executor`), so
#: how many ticks a wait takes is a matter of timing (one episode run twice on one commit:
#: 180 and 219 ticks, every other field the same)
TIMING = frozenset({"wall_s", "query_s", "build_s", "replan_ms", "clock_t0", "sent_s", "done_s", "seconds",
                    "versions", "ticks"})


def strip(value):
    """``value`` (a report, or a part of one) without the :data:`TIMING` keys, at any depth."""
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k not in TIMING}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


def differences(a, b, path: str = "") -> list[str]:
    """Where two stripped reports differ (paths, at most a few)."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = [f"{path}.{k}: only in one" for k in sorted(a.keys() ^ b.keys())]
        for k in sorted(a.keys() & b.keys()):
            out += differences(a[k], b[k], f"{path}.{k}")
        return out
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{path}[{i}]")]
    return [] if a == b else [f"{path}: {str(a)[:80]} != {str(b)[:80]}"]


def cpu_seconds() -> float:
    """User and system CPU seconds of this process, every thread, and of its child processes that
    have ended (a planner's subprocess: ``time.process_time`` leaves those out)."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def child(tree: Path, task_name: str, seed: int, keep: Path | None) -> None:
    """One episode in this process, with ``tree``'s code: prints its times and stripped report."""
    sys.path.insert(0, str(tree))
    os.chdir(tree)
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    task = taskfile.load(tree / "trees" / f"{task_name}.yaml")
    session = Session(task, RunConfig.from_task(task, world="pybullet", verify="both"))
    try:
        c0, t0 = cpu_seconds(), time.perf_counter()
        report = session.episode(seed)
        cpu, wall = cpu_seconds() - c0, time.perf_counter() - t0
    finally:
        session.close()
    # as a report file has it, the checkout's own paths (the task file's) put relative
    stripped = strip(json.loads(json.dumps(report, default=str).replace(str(tree) + "/", "")))
    if keep is not None:
        keep.write_text(json.dumps(stripped, indent=1, sort_keys=True))
    print(json.dumps({"wall_s": wall, "cpu_s": cpu, "report": stripped}))


def run_one(tree: Path, task: str, seed: int, keep: Path | None) -> dict:
    cmd = [sys.executable, str(Path(__file__).resolve()), "--child", str(tree), task, str(seed)]
    if keep is not None:
        cmd += ["--keep", str(keep)]
    env = {**os.environ, "PYTHONPATH": str(tree)}
    out = subprocess.run(cmd, cwd=tree, env=env, capture_output=True, text=True, check=False)
    if out.returncode != 0:
        raise SystemExit(f"{tree}: {task} seed {seed} failed:\n{out.stderr[-2000:]}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def compare_rows(base: Path, new: Path) -> int:
    """Print whether two campaigns' rows of the same keys agree in every field but ``wall_s``;
    0 when all the keys both hold agree."""
    def rows(path: Path) -> dict[tuple, dict]:
        out = {}
        for line in path.read_text().splitlines():
            r = json.loads(line)
            out[(r["experiment"], r["world"], r["task"], r["strategy"], r["viewpoints"], r["seed"])] = r
        return out

    a, b = rows(base), rows(new)
    both = sorted(a.keys() & b.keys())
    differ = 0
    for key in both:
        diff = [f for f in sorted(a[key].keys() | b[key].keys()) if f != "wall_s" and a[key].get(f) != b[key].get(f)]
        differ += bool(diff)
        print(f"{key[2]:18} {key[5]:4d}  {'same' if not diff else 'DIFFER: ' + ', '.join(diff)}  "
              f"wall {a[key]['wall_s']:.1f} s -> {b[key]['wall_s']:.1f} s")
    print(f"{len(both) - differ} of {len(both)} keys agree in every field but wall_s "
          f"({len(a.keys() - b.keys())} only in {base}, {len(b.keys() - a.keys())} only in {new})")
    return 0 if differ == 0 else 1


def seeds_of(text: str) -> list[int]:
    a, _, b = text.partition("-")
    return list(range(int(a), int(b or a) + 1))


def episodes_of(tasks: list[str], seeds: str, chosen: list[str] | None) -> list[tuple[str, int]]:
    """(task name, seed) to run: each ``TASK:SEED`` of ``chosen`` (a name or paper id, as
    ``--tasks`` takes), in order; else every task of ``tasks`` at every seed of ``seeds``."""
    from tools.experiments.command import tasks_named

    if chosen:
        pairs = [word.rpartition(":") for word in chosen]
        if any(not task or not seed.isdigit() for task, _, seed in pairs):
            raise SystemExit(f"--episodes takes TASK:SEED words, not {' '.join(chosen)}")
        return [(next(iter(tasks_named([task]))), int(seed)) for task, _, seed in pairs]
    return [(task, seed) for task in tasks_named(tasks) for seed in seeds_of(seeds)]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", type=Path, help="the checkout to compare against")
    ap.add_argument("--new", type=Path, default=ROOT, help="the checkout measured (default: this one)")
    ap.add_argument("--tasks", nargs="+", default=["S1", "S2", "S3", "S4", "S5"],
                    help="task names or the paper's ids S1-S5 (default S1-S5)")
    ap.add_argument("--seeds", default="0-1", help="A-B: seeds A..B inclusive (default 0-1)")
    ap.add_argument("--episodes", nargs="+", metavar="TASK:SEED",
                    help="run these episodes instead of --tasks by --seeds (e.g. S1:1 halve_egg:0)")
    ap.add_argument("--json", type=Path, help="write every episode's figures here")
    ap.add_argument("--keep", type=Path, help="directory for each run's stripped report (to diff by hand)")
    ap.add_argument("--rows", nargs=2, type=Path, metavar=("BASE", "NEW"),
                    help="compare two campaigns' episodes.jsonl instead of running episodes")
    ap.add_argument("--child", nargs=3, metavar=("TREE", "TASK", "SEED"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        tree, task, seed = args.child
        child(Path(tree), task, int(seed), args.keep)
        return 0
    if args.rows:
        return compare_rows(*args.rows)
    if args.base is None:
        ap.error("--base CHECKOUT is required")
    sys.path.insert(0, str(ROOT))
    episodes = episodes_of(args.tasks, args.seeds, args.episodes)
    base, new = args.base.resolve(), args.new.resolve()
    if args.keep is not None:
        args.keep.mkdir(parents=True, exist_ok=True)
    rows, k = [], 0
    print(f"{'task':18} {'seed':>4} {'base wall':>9} {'new wall':>8} {'ratio':>6} "
          f"{'base cpu':>8} {'new cpu':>7} {'ratio':>6}  same episode")
    for task, seed in episodes:
        order = [("base", base), ("new", new)] if k % 2 == 0 else [("new", new), ("base", base)]
        k += 1
        got = {name: run_one(tree, task, seed, args.keep / f"{task}-{seed}-{name}.json" if args.keep else None)
               for name, tree in order}
        diff = differences(got["base"]["report"], got["new"]["report"])
        row = {"task": task, "seed": seed, "same": not diff, "differences": diff[:10],
               **{f"{n}_{m}": round(got[n][m], 3) for n in ("base", "new") for m in ("wall_s", "cpu_s")},
               "success": got["new"]["report"]["success"], "vlm_queries": got["new"]["report"]["vlm_queries"]}
        row["wall_ratio"] = round(row["new_wall_s"] / row["base_wall_s"], 3)
        row["cpu_ratio"] = round(row["new_cpu_s"] / row["base_cpu_s"], 3)
        rows.append(row)
        print(f"{task:18} {seed:4d} {row['base_wall_s']:9.1f} {row['new_wall_s']:8.1f} {row['wall_ratio']:6.3f} "
              f"{row['base_cpu_s']:8.1f} {row['new_cpu_s']:7.1f} {row['cpu_ratio']:6.3f}  "
              f"{'yes' if row['same'] else 'NO: ' + '; '.join(diff[:3])}", flush=True)
    total = {m: sum(r[m] for r in rows) for m in ("base_wall_s", "new_wall_s", "base_cpu_s", "new_cpu_s")}
    summary = {"episodes": len(rows), "same": sum(r["same"] for r in rows),
               "median_wall_ratio": statistics.median(r["wall_ratio"] for r in rows),
               "median_cpu_ratio": statistics.median(r["cpu_ratio"] for r in rows),
               "total_wall_ratio": round(total["new_wall_s"] / total["base_wall_s"], 3),
               "total_cpu_ratio": round(total["new_cpu_s"] / total["base_cpu_s"], 3), **total}
    print(f"{summary['same']} of {len(rows)} episodes the same; new/base: median wall {summary['median_wall_ratio']:.3f}, "
          f"median CPU {summary['median_cpu_ratio']:.3f}; all episodes' CPU {total['base_cpu_s']:.0f} s -> "
          f"{total['new_cpu_s']:.0f} s ({summary['total_cpu_ratio']:.3f})")
    if args.json is not None:
        args.json.write_text(json.dumps({"command": " ".join(sys.argv), "base": str(base), "new": str(new),
                                         "summary": summary, "episodes": rows}, indent=1) + "\n")
    return 0 if summary["same"] == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
