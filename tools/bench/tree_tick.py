"""Ticking a long plan's tree: vap_bt's PlanTree beside py_trees' BehaviourTree, in one run.

A compiled plan has about a dozen nodes per action (precondition checks, each a retry decorator
over a check, the execute leaf, the effect checks, the effects' application). py_trees'
BehaviourTree walks every node after every tick; PlanTree skips that walk when no visitor asks
for the whole tree (:mod:`vap_bt.bt.plan_tree`). This builds trees of that shape for plans of
several lengths — every leaf running for two ticks, then succeeding — ticks each to the end with
both classes, alternately, and prints the microseconds per tick and the ratio.

    python tools/bench/tree_tick.py [--lengths 10,100,300] [--repeats 3]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

import py_trees  # noqa: E402
from py_trees.common import Status  # noqa: E402

from vap_bt.bt.plan_tree import PlanTree  # noqa: E402

CHECKS = 4  # precondition and effect checks per action, as a household action has about


def _leaf(name: str) -> py_trees.behaviour.Behaviour:
    return py_trees.behaviours.StatusQueue(name, queue=[Status.RUNNING, Status.RUNNING], eventually=Status.SUCCESS)


def _checks(name: str) -> py_trees.composites.Sequence:
    return py_trees.composites.Sequence(name, memory=True, children=[
        py_trees.decorators.Retry(f"look{k}", _leaf(f"{name}{k}"), num_failures=2) for k in range(CHECKS // 2)])


def plan_tree(length: int) -> py_trees.composites.Sequence:
    """``length`` actions of the compiled shape: pre checks, execute, effect checks, apply."""
    return py_trees.composites.Sequence("plan", memory=True, children=[
        py_trees.composites.Sequence(f"a{k}", memory=True, children=[
            _checks(f"pre{k}"), _leaf(f"exec{k}"), _checks(f"eff{k}"), _leaf(f"apply{k}")])
        for k in range(length)])


def per_tick_us(tree_class, length: int) -> tuple[float, int]:
    tree = tree_class(plan_tree(length))
    t0 = time.perf_counter()
    while tree.root.status != Status.SUCCESS:
        tree.tick()
    return (time.perf_counter() - t0) / tree.count * 1e6, tree.count


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lengths", default="10,100,300", help="plan lengths (actions), comma-separated")
    ap.add_argument("--repeats", type=int, default=3, help="runs of each class per length (the best counts)")
    args = ap.parse_args(argv)
    print("| actions | nodes | ticks | BehaviourTree (µs/tick) | PlanTree (µs/tick) | PlanTree / BehaviourTree |")
    print("|---:|---:|---:|---:|---:|---:|")
    for length in (int(x) for x in args.lengths.split(",")):
        best = {py_trees.trees.BehaviourTree: float("inf"), PlanTree: float("inf")}
        for _ in range(args.repeats):
            for cls in best:  # alternately: the machine's drift falls on both
                us, ticks = per_tick_us(cls, length)
                best[cls] = min(best[cls], us)
        nodes = sum(1 for _ in plan_tree(length).iterate())
        old, new = best[py_trees.trees.BehaviourTree], best[PlanTree]
        print(f"| {length} | {nodes} | {ticks} | {old:.0f} | {new:.0f} | {new / old:.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
