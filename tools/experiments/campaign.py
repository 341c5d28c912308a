"""The symbolic campaign: every task in trees/ over many seeds, Table II injection on.

Runs the symbolic world whatever world the task files name (theirs is pybullet, for ``vap-bt run``):
a campaign is thousands of episodes. Progress (episodes done, rate, time left) goes to stderr.

Per task: success (the executive claims it and the world agrees), false successes (claimed, the
world denies), situations detected, replans, re-surveys, VLM queries per executed action, and the
episode rate. Only the runner's report reads the world's truth; the executive perceives.

    python tools/experiments/campaign.py [--seeds 50] [--vlm-noise 1] [--out docs/figures/campaign.json]

``--code DIR`` runs another checkout's code with this script (the campaign uses only the task
files, ``RunConfig.from_task``, ``Session.episode`` and report keys that every version has), so a
before/after comparison is one command each:

    git worktree add /tmp/before <commit> && python tools/experiments/campaign.py --code /tmp/before
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # this checkout's tools/, whatever --code says
from tools.progress import Progress  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=50)
    ap.add_argument("--vlm-noise", type=float, default=1.0)
    ap.add_argument("--verify", default="both")
    ap.add_argument("--code", default=str(Path(__file__).resolve().parents[2]), help="checkout whose code runs")
    ap.add_argument("--out", help="write per-episode rows and the summary here (JSON)")
    args = ap.parse_args(argv)
    root = Path(args.code).resolve()
    sys.path.insert(0, str(root))
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    paths = sorted((root / "trees").glob("*.yaml"))
    total = len(paths) * args.seeds
    rows, t0 = [], time.perf_counter()
    progress = Progress(total, "episodes")
    print(f"{'task':18s} {'success':>8s} {'false':>5s} {'situations':>10s} {'replans':>7s} {'q/action':>8s}")
    for path in paths:
        task = taskfile.load(path)
        session = Session(task, RunConfig.from_task(task, world="symbolic", vlm_noise=args.vlm_noise,
                                                    verify=args.verify))
        mine = []
        for seed in range(args.seeds):
            r = session.episode(seed)
            actions = max(1, len(r["actions_executed"]))
            mine.append({"task": task.name, "seed": seed, "success": bool(r["success"] and r["goal_satisfied"]),
                         "false_success": bool(r["success"] and not r["goal_satisfied"]),
                         "situations": len(r["situations"]), "injected": len(r["injected"]),
                         "replans": r["replans"], "vlm_per_action": r["vlm_queries"] / actions,
                         "surveys": r["surveys"] if isinstance(r["surveys"], int) else len(r["surveys"])})
            progress.step()
        rows += mine
        print(f"{task.name:18s} {sum(m['success'] for m in mine) / len(mine):8.1%} "
              f"{sum(m['false_success'] for m in mine):5d} {statistics.mean(m['situations'] for m in mine):10.2f} "
              f"{statistics.mean(m['replans'] for m in mine):7.2f} "
              f"{statistics.mean(m['vlm_per_action'] for m in mine):8.1f}", flush=True)
    wall = time.perf_counter() - t0
    summary = {"episodes": len(rows), "success": sum(r["success"] for r in rows) / len(rows),
               "false_successes": sum(r["false_success"] for r in rows),
               "episodes_per_min": len(rows) / wall * 60, "wall_s": wall, "code": str(root),
               "command": " ".join(["python", *sys.argv]), "seeds": args.seeds, "vlm_noise": args.vlm_noise,
               "verify": args.verify}
    print(f"\n{len(rows)} episodes: success {summary['success']:.1%}, false successes "
          f"{summary['false_successes']}, {summary['episodes_per_min']:.0f} episodes/min (incl. every task's "
          f"first plan from Fast Downward)")
    if args.out:
        Path(args.out).parent.mkdir(parents=True, exist_ok=True)
        Path(args.out).write_text(json.dumps({"summary": summary, "rows": rows}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
