"""Calibrate the VLM's views: how often each kind of view comes out when an atom holds and when not.

Runs seeded symbolic episodes of every task (Table II injection on, the simulated VLM at its
calibrated model, disturbances as in the fault campaign) and counts, per predicate, every view
a check took — its kinds (:func:`vap_bt.perception.evidence.view_kinds`: settled, consistent or
split, yes or no; and where the frame's detector put the item, for a location atom) — against
the world's truth for that check. The counts are what the executive weighs views by when it
claims a goal (:mod:`vap_bt.perception.evidence`); they are written to
``vap_bt/perception/calibration.yaml`` with the command, commit, seeds and model version that
produced them. The seeds start at 10000 by default: disjoint from the fault campaign's (0-999), so
the campaign tests what the calibration did not see.

    python tools/bench/calibrate.py [--episodes 900] [--first-seed 10000] [--jobs 2] [--out PATH]
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.progress import Progress  # noqa: E402
from vap_bt.perception.evidence import CALIBRATION, LOCATED_KINDS, Calibration, view_kinds  # noqa: E402
from vap_bt.perception.verification import Round  # noqa: E402

_SESSIONS: dict = {}


def _views(job: tuple[str, int]) -> list[tuple[str, str, bool]]:
    """(predicate, view kind, truth) for every view of one episode."""
    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    path, seed = job
    if path not in _SESSIONS:
        task = taskfile.load(path)
        cfg = RunConfig.from_task(task, world="symbolic", injection=True, vlm_noise=1.0, disturbance=0.5, max_seconds=60)
        _SESSIONS[path] = Session(task, cfg)
    rep = _SESSIONS[path].episode(seed)
    out = []
    for v in rep["verifications"]:
        if v.get("truth") is None:  # unsettled checks too: leaving them out would keep only the lucky views
            continue
        for r in v["rounds"]:
            view = Round(view=r["view"], vote=r["vote"], consistent=r["consistent"], sufficient=r["sufficient"],
                         unshown=tuple(r.get("unshown", ())), located=r.get("located"))
            out.extend((v["predicate"].split("(")[0], kind, bool(v["truth"])) for kind in view_kinds(view))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--episodes", type=int, default=900, help="episode i runs task i mod 9 with seed first-seed + i")
    ap.add_argument("--first-seed", type=int, default=10_000)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", type=Path, default=CALIBRATION)
    args = ap.parse_args(argv)
    tasks = sorted(str(p) for p in (ROOT / "trees").glob("*.yaml"))
    jobs = [(tasks[i % len(tasks)], args.first_seed + i) for i in range(args.episodes)]
    counts: dict[str, dict[str, list[int]]] = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    progress = Progress(total=len(jobs), unit="episodes")
    t0 = time.perf_counter()
    with mp.get_context("spawn").Pool(args.jobs) as pool:
        for views in pool.imap_unordered(_views, jobs, chunksize=4):
            for predicate, kind, truth in views:
                counts[predicate][kind][0 if truth else 1] += 1
            progress.step()
    from vap_bt.sim.sim_vlm import MODEL_VERSION

    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    source = {"backend": f"simulated VLM {MODEL_VERSION}", "world": "symbolic, Table II injection on, disturbance 0.5",
              "command": f"python tools/bench/calibrate.py --episodes {args.episodes} --first-seed {args.first_seed}",
              "commit": commit, "seeds": f"{args.first_seed}-{args.first_seed + args.episodes - 1}",
              "date": time.strftime("%Y-%m-%d"), "minutes": round((time.perf_counter() - t0) / 60, 1)}
    cal = Calibration({p: {k: tuple(v) for k, v in row.items()} for p, row in counts.items()}, source)
    args.out.write_text("# written by tools/bench/calibrate.py: counts of each view kind [when the atom held, when not]\n"
                        + cal.to_yaml(), encoding="utf-8")
    print(f"wrote {args.out}", file=sys.stderr)
    for p in sorted(counts):
        shown = ("settled_yes", "settled_no", *(LOCATED_KINDS if any(k in counts[p] for k in LOCATED_KINDS) else ()))
        ws = "  ".join(f"{k} {cal.weight(p, k):+.2f}" for k in shown)
        print(f"{p:12s} {ws}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
