"""The scene graph's geometric half on every task scene in pybullet, against the oracle.

A check of ``vap_bt.scene`` alone (clouds, tracks, relations), not of the builder: the cameras
float free (no robot moves, no sweep is chosen), furniture doors are swung open by resetting their
joints (drawers stay shut: a teleported tray would leave its contents behind), and the detector is
the renderer's segmentation above the camera's pixel threshold. For each task and seed it builds
the household, renders two views of every piece of furniture and one of each room's floor area,
integrates them into tracks and compares the ``on``/``inside``/``in_room``/``blocking`` atoms
about the objects seen (and the map's floors and doors) with the oracle's.

    .venv/bin/python tools/experiments/scene_geometry.py            # 9 tasks x seeds 0 1 2
    .venv/bin/python tools/experiments/scene_geometry.py trees/pick_plate.yaml --seeds 0

Progress (scenes done, rate, time left) goes to stderr.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from itertools import product
from pathlib import Path

import vap_bt  # noqa: F401  (first: it pins numpy's kernels, vap_bt/numerics.py, before pybullet loads numpy)

import numpy as np
import pybullet as pb

from vap_bt.domain.atoms import Atom
from vap_bt.robot.frame import Detection, Frame
from vap_bt.robot.site_map import DoorInfo, FurnitureInfo, RoomInfo, SiteMap
from vap_bt.scene.relations import Signatures, scene_relations
from vap_bt.scene.tracks import Tracks
from vap_bt.motion.se3 import look_pose
from vap_bt.sim.pb_camera import render
from vap_bt.sim.pybullet_world import PybulletWorld
from vap_bt.taskfile import load

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from tools.progress import Progress  # noqa: E402

PREDICATES = ("on", "inside", "in_room", "blocking")


def site_map(world: PybulletWorld) -> SiteMap:
    """What a mapped house tells the robot: room outlines, doors, furniture footprints."""
    plan = world.plan
    rooms = tuple(RoomInfo(r.name, f"floor_{r.name}", (r.x0, r.y0, r.x1, r.y1)) for r in plan.rooms.values())
    doors = tuple(DoorInfo(d.name, (d.low, d.high)) for d in plan.doors.values())
    furniture = tuple(
        FurnitureInfo(f.name, f.kind.name, world.types[f.name], f.room,
                      (f.x, f.y, math.atan2(f.front[1], f.front[0])), (f.kind.size[0], f.kind.size[1]))
        for f in plan.furniture.values())
    return SiteMap(rooms, doors, furniture)


def views(world: PybulletWorld) -> list[tuple[np.ndarray, np.ndarray]]:
    """(eye, target): two views of each piece of furniture, one of each room's floor items."""
    out = []
    for f in world.plan.furniture.values():
        w, d, h = f.kind.size
        cavity = f.kind.cavity
        target = f.to_world((0.0, 0.0, h)) if cavity is None else f.to_world((0.0, d / 4, sum(cavity.z) / 2))
        out.append((f.to_world((0.0, d / 2 + 1.0, max(1.4, h + 0.5))), target))
        out.append((f.to_world((0.3, d / 2 + 0.6, max(1.6, h + 0.7))), target))
    for r in world.plan.rooms.values():
        cx = (r.x0 + r.x1) / 2
        out.append((np.array([cx, world.plan.depth / 2, 1.6]), np.array([cx + 0.6, 1.05, 0.0])))
    return out


def capture(world: PybulletWorld, eye, target, frame_id: str) -> Frame:
    """A frame whose detections are the named things above the pixel threshold (floors aside)."""
    r = render(world.cid, look_pose(eye, target), world.camera)
    ids = {n: i for i, n in enumerate(sorted(world.scene.things))}
    masks = np.full(r.bodies.shape, -1, np.int32)
    for body, name in world.scene.by_body().items():
        if world.types.get(name) != "room" and not name.startswith("floor_"):
            masks[r.bodies == body] = ids[name]
    dets = tuple(Detection(n, int(c), mask_id=i, name=n) for n, i in ids.items()
                 if (c := np.count_nonzero(masks == i)) >= r.pixel_threshold())
    return Frame(frame_id, 0.0, dets, depth=r.depth, masks=masks, intrinsics=r.intrinsics, camera_pose=r.pose)


def open_doors(world: PybulletWorld) -> None:
    for t in world.scene.things.values():
        if t.hinge is not None and t.furniture is not None and not t.hinge.prismatic:
            pb.resetJointState(t.hinge.body, t.hinge.joint, 0.97 * t.hinge.full, physicsClientId=world.cid)


def candidates(planning) -> set[Atom]:
    """Every typed atom of PREDICATES over the task's objects: what the oracle is asked about."""
    k = planning.knowledge
    return {Atom(p, (a, b)) for p in PREDICATES for a, b in product(planning.objects, repeat=2)
            if a != b and k.is_subtype(planning.objects[a], k.predicates[p][0])
            and k.is_subtype(planning.objects[b], k.predicates[p][1])}


def check(path: Path, seed: int) -> tuple[int, int, int, float]:
    task = load(path)
    world = PybulletWorld(task, seed=seed, injection=False)
    try:
        open_doors(world)
        smap = site_map(world)
        frames = [capture(world, eye, target, f"v{i}") for i, (eye, target) in enumerate(views(world))]
        tracks = Tracks()
        t0 = time.perf_counter()
        for f in frames:
            tracks.integrate(f)
        per_frame = (time.perf_counter() - t0) / len(frames)
        held = {world.truth.held()} - {None}
        sig = Signatures(task.planning.knowledge, task.planning.objects)
        mine = {a for a in scene_relations(tracks, smap, sig, held=held) if a.predicate in PREDICATES}
        known = set(tracks.names()) | smap.static_names()
        truth = {a for a in candidates(task.planning) if a.args[0] in known and world.truth.holds(a)}
        unseen = sorted(n for n, t in world.types.items() if t in ("item", "knife") and n not in tracks)
        print(f"{task.name:18s} seed {seed}: {len(frames)} frames, {per_frame * 1e3:5.1f} ms/frame to integrate; "
              f"wrong {sorted(map(str, mine - truth))} missed {sorted(map(str, truth - mine))} unseen {unseen}")
        return len(mine & truth), len(mine - truth), len(truth - mine), per_frame
    finally:
        world.close()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("tasks", nargs="*", type=Path, default=sorted(Path("trees").glob("*.yaml")))
    ap.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2])
    args = ap.parse_args()
    progress = Progress(len(args.tasks) * len(args.seeds), "scenes")
    rows = []
    for p in args.tasks:
        for s in args.seeds:
            rows.append(check(p, s))
            progress.step()
    tp, fp, fn = (sum(r[i] for r in rows) for i in range(3))
    times = [r[3] for r in rows]
    print(f"precision {tp / max(1, tp + fp):.3f}  recall {tp / max(1, tp + fn):.3f}  ({tp} right, {fp} wrong, "
          f"{fn} missed); integrate median {np.median(times) * 1e3:.1f} ms/frame")


if __name__ == "__main__":
    main()
