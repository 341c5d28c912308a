"""What recording the live view costs: symbolic episodes with and without a TreeRecorder.

The same episodes (every task in trees/, seeds 0..N-1, Table II injection on, VLM error 0.05,
in-process skills) run twice in one process: without a recorder (the baseline) and with one
saving to a temporary .rrd. Printed: wall time per episode both ways and their ratio, and the
recorder's own time per tick (its ``on_tree`` callback, timed around the call) over all ticks,
split into ticks that logged something and ticks that did not. Then the cost of one unchanged
tick on a compiled 20-action tree (the signature pass alone), the case a long skill in flight
produces tick after tick.

    python tools/bench/viz.py [--episodes 200]

Progress goes to stderr.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

from vap_bt import taskfile  # noqa: E402
from vap_bt.app.runner import RunConfig, Session  # noqa: E402
from vap_bt.viz import TreeRecorder  # noqa: E402
from tools.progress import Progress  # noqa: E402


class TimedRecorder:
    """Times every call of the recorder's callback, and notes whether it logged anything."""

    def __init__(self, recorder: TreeRecorder) -> None:
        self.recorder, self.samples = recorder, []

    def on_tree(self, tree, tick: int) -> None:
        before = self.recorder._signature  # changes exactly when the tree was drawn again
        t0 = time.perf_counter()
        self.recorder.on_tree(tree, tick)
        self.samples.append((time.perf_counter() - t0, self.recorder._signature is not before))

    def note(self, text: str) -> None:
        self.recorder.note(text)

    def scored(self, situations, truths) -> None:
        self.recorder.scored(situations, truths)


def episodes(tasks, n: int, recorder=None) -> float:
    sessions = [Session(t, RunConfig.from_task(t, world="symbolic", vlm_noise=1.0, transport="inproc"),
                        recorder=recorder) for t in tasks]
    for s in sessions:  # warm the planner caches outside the timing, both ways alike
        s.episode(10_000)
    progress = Progress(n, "episodes", label="recorded" if recorder is not None else "unrecorded")
    t0 = time.perf_counter()
    for i in range(n):
        sessions[i % len(sessions)].episode(i)
        progress.step()  # a clock read per episode, both ways alike; a line on stderr every few seconds
    elapsed = time.perf_counter() - t0
    for s in sessions:
        s.close()
    return elapsed / n


def unchanged_tick_us(repeats: int = 2000) -> float:
    import py_trees

    from test_viz_tree import compiled, plan_of, running_at

    _, a = plan_of("gather_kindling.yaml")
    _, b = plan_of("retrieve_bottles.yaml")
    root = compiled(actions=(list(a) + list(b))[:20])
    tree = py_trees.trees.BehaviourTree(root)
    with tempfile.TemporaryDirectory() as d, TreeRecorder.open(["save", str(Path(d) / "t.rrd")]) as rec:
        running_at(root, 10)
        rec.on_tree(tree, 1)
        t0 = time.perf_counter()
        for tick in range(2, repeats + 2):
            rec.on_tree(tree, tick)
        return (time.perf_counter() - t0) / repeats * 1e6


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--episodes", type=int, default=200)
    args = ap.parse_args()
    tasks = [taskfile.load(f) for f in sorted((ROOT / "trees").glob("*.yaml"))]
    plain = episodes(tasks, args.episodes)
    with tempfile.TemporaryDirectory() as d:
        rec = TimedRecorder(TreeRecorder.open(["save", str(Path(d) / "bench.rrd")]))
        recorded = episodes(tasks, args.episodes, rec)
        rec.recorder.close()
        size = (Path(d) / "bench.rrd").stat().st_size
    logged = [t for t, did in rec.samples if did]
    quiet = [t for t, did in rec.samples if not did]
    print(f"{args.episodes} symbolic episodes over {len(tasks)} tasks (injection on, VLM error 0.05, inproc)")
    print(f"unrecorded (baseline): {plain * 1000:7.2f} ms/episode")
    print(f"recorded to .rrd:      {recorded * 1000:7.2f} ms/episode   ratio x{recorded / plain:.2f}   "
          f"file {size / 1e6:.1f} MB")
    print(f"on_tree per tick: median {statistics.median(t for t, _ in rec.samples) * 1e3:.3f} ms over "
          f"{len(rec.samples)} ticks; ticks that drew the tree ({len(logged)}): median "
          f"{statistics.median(logged) * 1e3:.3f} ms, p90 {statistics.quantiles(logged, n=10)[-1] * 1e3:.3f} ms; "
          f"ticks with nothing new ({len(quiet)}): median "
          f"{(statistics.median(quiet) * 1e3 if quiet else float('nan')):.3f} ms")
    print(f"20-action tree, tick with nothing new: {unchanged_tick_us():.1f} us")
    return 0


if __name__ == "__main__":
    sys.exit(main())
