"""Render every task's pybullet scene to PNG files so a person can look at it.

For each task file in ``trees/`` (or those named), builds the pybullet household and writes two
images: ``<task>_overview.png`` (a bird's-eye view of the whole house) and ``<task>_wrist.png``
(what the wrist camera sees at the start, turned by the skills' camera service towards the first
goal's object).

    python tools/render_scenes.py --out docs/scenes
    python tools/render_scenes.py trees/boil_water.yaml --out /tmp/scenes
"""

from __future__ import annotations

import argparse
from pathlib import Path

import cv2

from skills.kit import kit_for
from skills.views import ViewService
from vap_bt.sim.pybullet_world import PybulletWorld
from vap_bt.taskfile import load


def render_task(path: Path, out: Path) -> list[Path]:
    task = load(path)
    world = PybulletWorld(task, seed=0, injection=False)
    try:
        goal_objects = [a for lit in task.planning.goal for a in lit.atom.args]
        obs = ViewService(kit_for(world)).capture(world.aim_at(tuple(goal_objects[:1])))
        files = [out / f"{task.name}_overview.png", out / f"{task.name}_wrist.png"]
        cv2.imwrite(str(files[0]), cv2.cvtColor(world.overview(), cv2.COLOR_RGB2BGR), [cv2.IMWRITE_PNG_COMPRESSION, 9])
        cv2.imwrite(str(files[1]), cv2.cvtColor(obs.rgb, cv2.COLOR_RGB2BGR), [cv2.IMWRITE_PNG_COMPRESSION, 9])
        return files
    finally:
        world.close()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("tasks", nargs="*", help="task files (default: trees/*.yaml)")
    ap.add_argument("--out", default="docs/scenes")
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    tasks = [Path(t) for t in args.tasks] or sorted(Path("trees").glob("*.yaml"))
    for t in tasks:
        for f in render_task(t, out):
            print(f"{f} ({f.stat().st_size // 1024} KB)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
