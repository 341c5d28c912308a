"""Action semantics: our GroundAction.apply / PlanningTask.validate against unified-planning's
SequentialSimulator and PlanValidator, on the same plans, in the same run.

The executive applies actions all the time: the compiler simulates every plan it compiles, the
scene graph applies each action, the symbolic world executes it, and a replan first tries every
tail of the previous plan. This measures what one action application and one plan validation
cost both ways, over the household tasks (trees/) and the PDDL feature domains (tests/domains),
with a Fast Downward plan for each. The simulator is built once per task and warmed up (its
grounding cached), the validator is called as a replan would call it (a fresh problem per
state); tests/test_pddl_features.py checks that both semantics agree.

    python tools/bench/semantics.py [--repeat 200]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
import vap_bt  # noqa: E402,F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before anything loads numpy)

from unified_planning.plans import ActionInstance  # noqa: E402
from unified_planning.shortcuts import SequentialSimulator  # noqa: E402

from vap_bt import taskfile  # noqa: E402
from vap_bt.domain import validation  # noqa: E402
from vap_bt.domain.pddl import load_task  # noqa: E402
from vap_bt.domain.planner import Planner  # noqa: E402

FEATURE_DOMAINS = ["microwave", "lamps", "hiking", "packing", "elevators", "fridge", "briefcase", "storage"]


def tasks():
    for f in sorted((ROOT / "trees").glob("*.yaml")):
        yield f.stem, taskfile.load(f).planning
    d = ROOT / "tests" / "domains"
    for name in FEATURE_DOMAINS:
        yield name, load_task(d / f"{name}-domain.pddl", d / f"{name}-p1.pddl")


def timed(fn, repeat: int) -> float:
    t0 = time.perf_counter()
    for _ in range(repeat):
        fn()
    return (time.perf_counter() - t0) / repeat


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=200)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    rows = []
    for name, task in tasks():
        plan = Planner(task).plan().actions
        problem = task.up_problem
        acts = {a.name: a for a in problem.actions}
        objs = {o.name: o for o in problem.all_objects}
        instances = [ActionInstance(acts[a.name], [objs[x] for x in a.args]) for a in plan]

        def ours_apply():
            s = task.init
            for a in plan:
                s = a.apply(s)

        with SequentialSimulator(problem) as sim:
            def up_apply():
                s = sim.get_initial_state()
                for ai in instances:
                    s = sim.apply(s, ai)

            up_apply()  # warm: the simulator grounds each action instance once
            steps = len(plan)
            rows.append((name, steps, timed(ours_apply, args.repeat) / steps, timed(up_apply, 5) / steps,
                         timed(lambda: task.validate(plan), args.repeat),
                         timed(lambda: validation.validate(task, plan), 3)))
    print(f"{'task':18s} {'steps':>5s} {'apply: ours':>12s} {'UP simulator':>13s} {'validate: ours':>15s} "
          f"{'UP validator':>13s}")
    for name, steps, oa, ua, ov, uv in rows:
        print(f"{name:18s} {steps:5d} {oa * 1e6:10.1f}us {ua * 1e6:11.1f}us {ov * 1e6:13.1f}us {uv * 1000:11.1f}ms")
    ratio_apply = statistics.median(ua / oa for _, _, oa, ua, _, _ in rows)
    ratio_val = statistics.median(uv / ov for _, _, _, _, ov, uv in rows)
    print(f"median over tasks: UP simulator / ours per action {ratio_apply:.0f}x; "
          f"UP validator / ours per plan {ratio_val:.0f}x")
    print(f"median per action: ours {statistics.median(r[2] for r in rows) * 1e6:.1f} us, "
          f"UP simulator {statistics.median(r[3] for r in rows) * 1e6:.1f} us; per plan: ours "
          f"{statistics.median(r[4] for r in rows) * 1e6:.1f} us, UP validator "
          f"{statistics.median(r[5] for r in rows) * 1000:.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
