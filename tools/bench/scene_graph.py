"""The initial scene graph, built by looking, against the oracle: every task scene in trees/.

For each task and seed the pybullet household is built, the executive runs only its
BuildSceneGraph (the exploration sweep, the fusion of every frame's depth and masks into
per-object point clouds, the geometric relations, the VLM's answers on what is open, the task
file's prior for what no view shows), and the runner scores the result against the oracle at
that moment: precision and recall of the ``on``/``inside``/``in_room`` relations of the items
(all of them, and only those the camera saw), detection recall, and the time the build took.

    python tools/bench/scene_graph.py [--seeds 3] [--sensors real|exact] [--json out.json]

``--sensors real`` (the default here) builds from the D435i-like depth and with the AMCL-like
localisation error (docs/world.md); ``exact`` from the renderer's depth and the true base pose.

Progress (scenes done, rate, time left) goes to stderr.

Targets (issue: the robot perceives): relation precision >= 0.95 and recall >= 0.90 per scene.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from vap_bt import taskfile  # noqa: E402
from vap_bt.report import versions  # noqa: E402
from vap_bt.app.runner import RunConfig, Session  # noqa: E402
from tools.progress import Progress  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--sensors", choices=("real", "exact"), default="real", help="depth camera and localiser")
    ap.add_argument("--json", help="write every scene's figures here")
    args = ap.parse_args(argv)
    rows = []
    paths = sorted((ROOT / "trees").glob("*.yaml"))
    progress = Progress(len(paths) * args.seeds, "scenes")
    print(f"{'task':18s} {'seed':>4s} {'P':>6s} {'R':>6s} {'P seen':>7s} {'R seen':>7s} {'det R':>6s} "
          f"{'views':>5s} {'build s':>8s}  wrong / missing")
    for path in paths:
        task = taskfile.load(path)
        session = Session(task, RunConfig.from_task(task, world="pybullet", injection=False, sensors=args.sensors))
        try:
            for seed in range(args.seeds):
                s = session.build_graph(seed)
                rows.append({"task": task.name, "seed": seed, **s})
                rel, seen, det = s["relations"], s["relations_perceived"], s["detections"]
                print(f"{task.name:18s} {seed:4d} {rel['precision']:6.3f} {rel['recall']:6.3f} "
                      f"{seen['precision']:7.3f} {seen['recall']:7.3f} {det['recall']:6.3f} {s['views']:5d} "
                      f"{s['build_s']:8.2f}  {', '.join(s.get('wrong', []))} / {', '.join(s.get('missing', []))}",
                      flush=True)
                progress.step()
        finally:
            session.close()

    def pooled(key: str) -> tuple[float, float]:
        tp = sum(r[key]["tp"] for r in rows)
        fp = sum(r[key]["fp"] for r in rows)
        fn = sum(r[key]["fn"] for r in rows)
        return tp / (tp + fp) if tp + fp else 1.0, tp / (tp + fn) if tp + fn else 1.0

    p, r = pooled("relations")
    ps, rs = pooled("relations_perceived")
    worst_p = min(x["relations"]["precision"] for x in rows)
    worst_r = min(x["relations"]["recall"] for x in rows)
    builds = [x["build_s"] for x in rows]
    print(f"\npooled over {len(rows)} scenes: relations P {p:.3f} R {r:.3f}; seen by the camera P {ps:.3f} "
          f"R {rs:.3f}; worst scene P {worst_p:.3f} R {worst_r:.3f}")
    for title, key in (("per predicate", "by_predicate"), ("per predicate, seen by the camera", "by_predicate_perceived"),
                       ("affordances between items the camera saw (not in the headline)", "affordances_perceived")):
        preds = sorted({p for x in rows for p in x.get(key, {})})
        if not preds:
            continue
        cells = []
        for pred in preds:
            tp = sum(x[key][pred]["tp"] for x in rows if pred in x.get(key, {}))
            fp = sum(x[key][pred]["fp"] for x in rows if pred in x.get(key, {}))
            fn = sum(x[key][pred]["fn"] for x in rows if pred in x.get(key, {}))
            cells.append(f"{pred} P {tp / (tp + fp) if tp + fp else 1.0:.3f} R {tp / (tp + fn) if tp + fn else 1.0:.3f} "
                         f"({tp} tp, {fp} fp, {fn} fn)")
        print(f"{title}: " + "; ".join(cells))
    print(f"build time per scene: median {statistics.median(builds):.2f} s, max {max(builds):.2f} s; "
          f"targets P >= 0.95 and R >= 0.90 per scene: {'met' if worst_p >= 0.95 and worst_r >= 0.90 else 'NOT met'}")
    if args.json:
        Path(args.json).write_text(json.dumps({"command": " ".join(["python", *sys.argv]), "seeds": args.seeds,
                                               "versions": versions(), "rows": rows}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
