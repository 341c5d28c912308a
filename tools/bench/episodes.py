"""Symbolic episodes per minute: the whole closed loop (survey, plan, compile, tick, verify with
the simulated VLM, situations, replans, report) over every task in trees/.

Table II injection on, VLM error 0.05, verification ``both``, in-process skills. The first
episode of each task includes its Fast Downward call; later ones hit the planner's cache, as a
campaign does. Both the cold and the warm rate are printed; progress goes to stderr. The task
files name pybullet (for ``vap-bt run``); this measures the symbolic world.

    python tools/bench/episodes.py [--episodes 600]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from vap_bt import taskfile  # noqa: E402
from vap_bt.app.runner import RunConfig, Session  # noqa: E402
from tools.progress import Progress  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--episodes", type=int, default=600)
    ap.add_argument("--verify", default="both")
    args = ap.parse_args()
    tasks = [taskfile.load(f) for f in sorted((ROOT / "trees").glob("*.yaml"))]
    t0 = time.perf_counter()
    sessions = [Session(t, RunConfig.from_task(t, world="symbolic", vlm_noise=1.0, verify=args.verify)) for t in tasks]
    for s in sessions:  # one cold episode per task: the Fast Downward call and grounding
        s.episode(10_000)
    cold = time.perf_counter() - t0
    ok = n = 0
    progress = Progress(args.episodes, "episodes")
    t1 = time.perf_counter()
    while n < args.episodes:
        s = sessions[n % len(sessions)]
        r = s.episode(n)
        ok += r["success"] and r["goal_satisfied"]
        n += 1
        progress.step()
    warm = time.perf_counter() - t1
    print(f"{n} episodes over {len(tasks)} tasks, verify={args.verify}: success {ok / n:.1%}")
    print(f"warm: {n / warm * 60:8.0f} episodes/min   ({warm / n * 1000:.1f} ms/episode)")
    print(f"incl. cold start of every task: {(n + len(tasks)) / (warm + cold) * 60:8.0f} episodes/min   "
          f"target >= 300")
    return 0


if __name__ == "__main__":
    sys.exit(main())
