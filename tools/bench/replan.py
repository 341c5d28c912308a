"""Replanning latency: situation → new tree ticking, against a plain unified-planning + Fast
Downward call on the same corrected states, measured in the same run.

Runs symbolic episodes of every task in trees/ with Table II injection on. Each time the
executive replans, the corrected state is recorded together with the executive's own latency
(graph correction + replan + compiling the new tree). Afterwards, for each recorded state, the
baseline — ``OneshotPlanner(name="fast-downward").solve(problem)`` with the problem already built —
is timed on the same machine. Prints medians, p90 and the ratio; then what the in-process path
spends once per object set (unified-planning's grounder), and what unified-planning's
PlanValidator costs on the replanned plans — every plan a planner produced goes through it; a
reused or cached plan does not, and this line is why.

    python tools/bench/replan.py [--seeds 20] [--baseline-samples 40]

Symbolic world (the task files name pybullet, for ``vap-bt run``); progress goes to stderr.
"""

from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before anything loads numpy)

from unified_planning.shortcuts import OneshotPlanner  # noqa: E402

from vap_bt import taskfile  # noqa: E402
from vap_bt.domain import validation  # noqa: E402
from vap_bt.domain.grounding import ground  # noqa: E402
from vap_bt.domain.planner import Planner  # noqa: E402
from vap_bt.app.runner import RunConfig, Session  # noqa: E402
from tools.progress import Progress  # noqa: E402


class RecordingPlanner(Planner):
    """A planner that remembers the states it was asked to replan from."""

    def __init__(self, task):
        super().__init__(task, ground_eagerly=True)  # as the runner's Session does
        self.states = []

    def replan(self, state, previous=None, goal=None):
        plan = super().replan(state, previous, goal)
        self.states.append((state, plan.actions))
        return plan


def pct(xs, q):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(q * len(xs)))]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--baseline-samples", type=int, default=40)
    args = ap.parse_args()
    ours, samples, engines, by_engine = [], [], {}, {}
    paths = sorted((ROOT / "trees").glob("*.yaml"))
    progress = Progress(len(paths) * args.seeds, "episodes")
    for f in paths:
        task = taskfile.load(f)
        s = Session(task, RunConfig.from_task(task, world="symbolic", vlm_noise=1.0))
        s.planner = RecordingPlanner(task.planning)
        for seed in range(args.seeds):
            r = s.episode(seed)
            ours += [ms / 1000 for ms in r["replan_ms"]]
            for p, ms in zip(r["plans"][1:], r["replan_ms"]):
                engines[p["engine"]] = engines.get(p["engine"], 0) + 1
                by_engine.setdefault(p["engine"], []).append(ms / 1000)
            progress.step()
        samples += [(task.planning, st) for st in s.planner.states]
    random.Random(0).shuffle(samples)
    base, up_check, our_check = [], [], []
    calls = Progress(len(samples[: args.baseline_samples]), "calls", label="baseline")
    for planning, (state, _) in samples[: args.baseline_samples]:
        problem = planning.with_state(state).to_up()
        with OneshotPlanner(name="fast-downward") as fd:
            t0 = time.perf_counter()
            fd.solve(problem)
            base.append(time.perf_counter() - t0)
        calls.step()
    for planning, (state, actions) in samples[: args.baseline_samples]:
        task = planning.with_state(state)
        t0 = time.perf_counter()
        assert validation.validate(task, actions).valid
        up_check.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        assert task.validate(actions)
        our_check.append(time.perf_counter() - t0)
    grounding = []
    for f in sorted((ROOT / "trees").glob("*.yaml")):
        planning = taskfile.load(f).planning
        t0 = time.perf_counter()
        ground(planning)
        grounding.append(time.perf_counter() - t0)
    m_ours, m_base = statistics.median(ours), statistics.median(base)
    print(f"replans measured: {len(ours)} (engines: {engines}); baseline calls: {len(base)}")
    print(f"{'':38s} {'median':>9s} {'p90':>9s}")
    print(f"{'vap_bt: situation -> new tree':38s} {m_ours * 1000:8.2f}ms {pct(ours, .9) * 1000:8.2f}ms")
    for eng, xs in sorted(by_engine.items()):
        print(f"{'  of which ' + eng + f' ({len(xs)})':38s} {statistics.median(xs) * 1000:8.2f}ms "
              f"{pct(xs, .9) * 1000:8.2f}ms")
    print(f"{'plain UP + Fast Downward solve()':38s} {m_base * 1000:8.2f}ms {pct(base, .9) * 1000:8.2f}ms")
    print(f"ratio (ours / baseline, median): {m_ours / m_base:.3f}   target <= 0.333")
    worst = max(statistics.median(xs) for xs in by_engine.values())
    print(f"ratio of the slowest engine (in-process search) alone: {worst / m_base:.3f}")
    print(f"{'grounding, once per task (UP grounder)':38s} {statistics.median(grounding) * 1000:8.2f}ms "
          f"{max(grounding) * 1000:8.2f}ms (max)")
    print(f"{'UP PlanValidator on a replanned plan':38s} {statistics.median(up_check) * 1000:8.2f}ms "
          f"{pct(up_check, .9) * 1000:8.2f}ms")
    print(f"{'our semantics on the same plans':38s} {statistics.median(our_check) * 1000:8.3f}ms "
          f"{pct(our_check, .9) * 1000:8.3f}ms")
    print(f"validating every replan with UP would add {statistics.median(up_check) / m_base:.3f} "
          "of the baseline to the median")
    return 0


if __name__ == "__main__":
    sys.exit(main())
