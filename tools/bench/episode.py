"""Wall time of a full pybullet episode: the task's first plan executed open-loop in the world.

Plans once (Fast Downward through the project's planner), builds the pybullet household, runs
every action of the plan through ``PybulletWorld.perform`` and renders one wrist observation after
each (as the executive would to verify effects), then reports the wall time, simulated time,
the injected situations and whether the goal holds in the ground truth. No replanning: this
measures the world, not the executive.

    python tools/bench/episode.py                      # boil_water, seed 0, injection off and on
    python tools/bench/episode.py trees/heat_pie.yaml --seed 3 --image 160x120
"""

from __future__ import annotations

import argparse
import platform
import sys
import time
from pathlib import Path

from vap_bt.domain.planner import Planner
from vap_bt.sim.pybullet_world import DT, PybulletWorld
from vap_bt.taskfile import load

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from tools.progress import Progress  # noqa: E402


class Ctx:
    def feedback(self, progress: float, text: str = "") -> None: ...

    def cancelled(self) -> bool:
        return False


def episode(path: str, seed: int, injection: bool, size: tuple[int, int], verbose: bool) -> dict:
    task = load(path)
    plan = Planner(task.planning).plan()
    t0 = time.perf_counter()
    world = PybulletWorld(task, seed=seed, injection=injection, image_size=size)
    build = time.perf_counter() - t0
    per_action = []
    for a in plan.actions:
        t = time.perf_counter()
        out = world.perform(a.name, tuple(a.args), Ctx())
        vis = world.seen(tuple(a.args))
        per_action.append(time.perf_counter() - t)
        if verbose:
            print(f"  {a}: {'ok' if out.completed else 'FAILED'} {out.message} "
                  f"({per_action[-1]:.2f} s, targets visible {[round(vis.get(x, 0), 2) for x in a.args]})")
    goal = all(world.oracle.holds(lit.atom) == lit.positive for lit in task.planning.goal)
    wall = time.perf_counter() - t0
    result = {"task": task.name, "seed": seed, "injection": injection, "actions": len(plan.actions),
              "wall_s": round(wall, 2), "build_s": round(build, 2), "sim_s": round(world.ticks * DT, 1),
              "slowest_action_s": round(max(per_action, default=0.0), 2), "goal_satisfied": goal,
              "injected": [f"{s.action}:{s.kind}" for s in world.oracle.injected()]}
    world.close()
    return result


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("task", nargs="?", default="trees/boil_water.yaml")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--image", default="160x120", help="wrist image size WxH")
    ap.add_argument("--injection", choices=["off", "on", "both"], default="both")
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args(argv)
    size = tuple(int(v) for v in args.image.split("x"))
    print("$ python " + " ".join(sys.argv))
    print(f"python {platform.python_version()}, {platform.machine()}")
    modes = {"off": [False], "on": [True], "both": [False, True]}[args.injection]
    progress = Progress(len(modes), "episodes", every_s=0.0)
    for inj in modes:
        r = episode(args.task, args.seed, inj, size, args.verbose)
        print(r, flush=True)
        progress.step()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
