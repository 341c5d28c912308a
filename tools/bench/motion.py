"""Motion benchmark: our IK against pybullet's, and toppra's time per path.

    .venv/bin/python tools/bench/motion.py [--n 500] [--seed 0] [--pos-tol 1e-4] [--rot-tol 1e-3]

IK: the same random reachable TCP targets (FK of random collision-free arm configurations, base
at the origin, fingers open) are given to

* ours — :func:`vap_bt.motion.ik.solve_ik`: damped least squares seeded with the closed-form UR
  solutions (the default), then random seeds, up to 20; with and without the collision check
  (pybullet's IK checks none, so the first row is the like-for-like one); and pure DLS from random
  seeds only (``analytic_seeds=False``), to show what the seeding buys;
* pybullet — ``calculateInverseKinematics`` in DIRECT mode on the same URDF. Its IK moves every
  movable joint, so the base and finger joints get a large ``jointDamping`` (they stay put) and
  only the arm joints of its answer are used. It is iterated: after each call the arm is set to
  the answer and the TCP pose read back; success is counted only when that FK error is within the
  same position *and* orientation tolerance. Up to ``--pb-calls`` calls per seed and the same 20
  random restarts as ours.

Timing: toppra on random 10-waypoint arm paths under the UR5e limits (sampled at 100 Hz).

Episode: the full closed loop of ``--episode-task`` (default boil_water) in the pybullet world,
injection off and on, as ``vap-bt run --world pybullet`` runs it (``--no-episode`` skips it).

Other rows can be added without editing this file: ``--extra module:function`` (repeatable)
imports ``function(args) -> Iterable[Row]`` and prints its rows in the same table — e.g. the full
pybullet episode time, once the world exists. :func:`register` does the same from Python.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass

import numpy as np
import pinocchio as pin
import pybullet as p

import robots
from vap_bt.motion import se3
from vap_bt.motion.collision import CollisionChecker
from vap_bt.motion.ik import IKOptions, solve_ik
from vap_bt.motion.kinematics import Kinematics
from vap_bt.motion.limits import arm_limits
from vap_bt.motion.timing import time_path


@dataclass(frozen=True)
class Row:
    name: str
    n: int
    seconds: float  # mean time per item
    success: float | None = None  # fraction, when meaningful
    group: str = ""  # rows of one group are compared with its first row
    note: str = ""


Bench = Callable[[argparse.Namespace], Iterable[Row]]
_REGISTERED: list[Bench] = []


def register(bench: Bench) -> Bench:
    """Add a row provider to every run of this benchmark (usable as a decorator)."""
    _REGISTERED.append(bench)
    return bench


def reachable_targets(kin: Kinematics, n: int, seed: int) -> list[np.ndarray]:
    checker = CollisionChecker(kin)
    rng = np.random.default_rng(seed)
    out: list[np.ndarray] = []
    while len(out) < n:
        q = kin.random_configuration(rng)
        if not checker.in_collision(q):
            out.append(kin.fk(q))
    return out


def bench_ours(kin: Kinematics, targets, args, *, analytic: bool, collision: bool) -> Row:
    options = IKOptions(
        position_tolerance=args.pos_tol, orientation_tolerance=args.rot_tol, seed=args.seed + 1, analytic_seeds=analytic
    )
    checker = CollisionChecker(kin) if collision else None
    start = time.perf_counter()
    results = [solve_ik(kin, T, collision=checker, options=options) for T in targets]
    elapsed = time.perf_counter() - start
    name = "ours: DLS, " + ("closed-form seeds" if analytic else "random seeds") + (" + collision" if collision else "")
    iters = np.mean([r.iterations for r in results])
    seeds = np.mean([r.seeds for r in results])
    note = f"{iters:.1f} iterations, {seeds:.1f} seeds /solve"
    return Row(name, len(targets), elapsed / len(targets), float(np.mean([r.success for r in results])), "ik", note)


class PybulletIK:
    """pybullet's IK on the same URDF, restricted to the arm and iterated to the tolerance."""

    def __init__(self, kin: Kinematics) -> None:
        cfg = kin.config
        self.client = p.connect(p.DIRECT)
        self.body = p.loadURDF(str(robots.urdf_path()), useFixedBase=True, physicsClientId=self.client)
        info = [p.getJointInfo(self.body, i, physicsClientId=self.client) for i in range(p.getNumJoints(self.body, physicsClientId=self.client))]
        joint = {i[1].decode(): i[0] for i in info}
        link = {i[12].decode(): i[0] for i in info}
        movable = [i[0] for i in info if i[2] != p.JOINT_FIXED]
        self.arm = [joint[n] for n in kin.joint_names]
        self.arm_dofs = [movable.index(j) for j in self.arm]  # positions in pybullet's IK answer
        self.movable = movable
        self.tcp = link[cfg.tcp]
        # Base and fingers must not move: damp them hard (pybullet has no way to lock a joint).
        self.damping = [1e-3 if j in self.arm else 1e3 for j in movable]
        for name, value in zip(cfg.gripper.joints, cfg.gripper.finger_positions(cfg.gripper.stroke), strict=True):
            p.resetJointState(self.body, joint[name], value, physicsClientId=self.client)

    def set_arm(self, q) -> None:
        for j, v in zip(self.arm, q, strict=True):
            p.resetJointState(self.body, j, float(v), physicsClientId=self.client)

    def tcp_pose(self) -> np.ndarray:
        state = p.getLinkState(self.body, self.tcp, computeForwardKinematics=True, physicsClientId=self.client)
        return se3.make_pose(state[4], np.array(p.getMatrixFromQuaternion(state[5])).reshape(3, 3))

    def current(self) -> list[float]:
        return [s[0] for s in p.getJointStates(self.body, self.movable, physicsClientId=self.client)]

    def solve(self, target: np.ndarray, seeds, args) -> bool:
        position = target[:3, 3].tolist()
        quat = pin.Quaternion(target[:3, :3]).coeffs().tolist()  # x, y, z, w like pybullet
        for seed in seeds:
            self.set_arm(seed)
            for _ in range(args.pb_calls):
                answer = p.calculateInverseKinematics(
                    self.body, self.tcp, position, quat,
                    jointDamping=self.damping, currentPositions=self.current(),
                    maxNumIterations=args.pb_iters, residualThreshold=args.pos_tol / 10,
                    physicsClientId=self.client,
                )  # fmt: skip
                self.set_arm([answer[d] for d in self.arm_dofs])
                pos, rot = se3.pose_error(self.tcp_pose(), target)
                if pos <= args.pos_tol and rot <= args.rot_tol:
                    return True
        return False


def bench_pybullet(kin: Kinematics, targets, args) -> Row:
    ik = PybulletIK(kin)
    rng = np.random.default_rng(args.seed + 1)
    max_seeds = IKOptions().max_seeds
    start = time.perf_counter()
    ok = [ik.solve(T, (kin.random_configuration(rng) for _ in range(max_seeds)), args) for T in targets]
    elapsed = time.perf_counter() - start
    p.disconnect(ik.client)
    note = f"maxNumIterations={args.pb_iters}, <= {args.pb_calls} calls/seed"
    return Row("pybullet calculateInverseKinematics", len(targets), elapsed / len(targets), float(np.mean(ok)), "ik", note)


def bench_toppra(args) -> Row:
    limits = arm_limits()
    rng = np.random.default_rng(args.seed)
    start_q = np.array(robots.load_config().arm.home)
    paths = []
    for _ in range(args.paths):
        walk = start_q + np.cumsum(rng.uniform(-0.4, 0.4, (10, 6)), axis=0)
        paths.append(np.clip(walk, limits.lower + 0.3, limits.upper - 0.3))
    start = time.perf_counter()
    durations = [time_path(w, limits).duration for w in paths]
    elapsed = time.perf_counter() - start
    return Row("toppra, 10-waypoint arm path", len(paths), elapsed / len(paths), None, "timing", f"mean motion {np.mean(durations):.2f} s")


def bench_episode(args: argparse.Namespace) -> list[Row]:
    """The whole closed loop in the pybullet household: ``vap-bt run TASK --world pybullet`` as
    the CLI runs it (skill servers over a loopback Zenoh link, verification, replanning), with
    Table II injection off and on. Wall time per episode; success means the world agrees."""
    from pathlib import Path

    from vap_bt import taskfile
    from vap_bt.app.runner import RunConfig, Session

    root = Path(__file__).resolve().parents[2]
    sys.path.insert(0, str(root))
    from tools.progress import Progress

    task = taskfile.load(root / args.episode_task)
    rows = []
    progress = Progress(2, "episodes", label="pybullet", every_s=0.0)
    for injection in (False, True):
        session = Session(task, RunConfig.from_task(task, world="pybullet", transport="zenoh", seed=args.seed,
                                                    injection=injection))
        try:
            t0 = time.perf_counter()
            r = session.episode()
            wall = time.perf_counter() - t0
        finally:
            session.close()
        progress.step()
        ok = r["success"] and r["goal_satisfied"]
        rows.append(Row(f"pybullet episode, {task.name}, injection {'on' if injection else 'off'}", 1, wall,
                        float(ok), "", f"{len(r['actions_executed'])} actions, {r['replans']} replans, "
                        f"{len(r['injected'])} injected; target <= 60 s"))
    return rows


def extra_benches(specs: list[str]) -> list[Bench]:
    out = list(_REGISTERED)
    for spec in specs:
        module, _, func = spec.partition(":")
        out.append(getattr(importlib.import_module(module), func))
    return out


def format_table(rows: list[Row]) -> str:
    """One line per row; within a group, ``speed-up`` is the group's last row's time / this row's."""
    header = f"{'bench':42s} {'n':>5s} {'success':>8s} {'time/item':>11s} {'speed-up':>9s}  note"
    lines = [header, "-" * len(header)]
    sizes = {g: sum(r.group == g for r in rows) for g in {r.group for r in rows}}
    reference = {r.group: r.seconds for r in rows if r.group and sizes[r.group] > 1}
    for r in rows:
        success = "" if r.success is None else f"{100 * r.success:.1f}%"
        ref = reference.get(r.group)
        ratio = f"{ref / r.seconds:.1f}x" if ref and r.seconds > 0 else ""
        lines.append(f"{r.name:42s} {r.n:5d} {success:>8s} {1e3 * r.seconds:9.3f}ms {ratio:>9s}  {r.note}")
    return "\n".join(lines)


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=500, help="IK targets")
    ap.add_argument("--paths", type=int, default=30, help="toppra paths")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--pos-tol", type=float, default=IKOptions().position_tolerance, help="m")
    ap.add_argument("--rot-tol", type=float, default=IKOptions().orientation_tolerance, help="rad")
    ap.add_argument("--pb-iters", type=int, default=20, help="pybullet maxNumIterations per call")
    ap.add_argument("--pb-calls", type=int, default=10, help="pybullet calls per seed")
    ap.add_argument("--extra", action="append", default=[], metavar="MODULE:FUNC", help="more rows")
    ap.add_argument("--episode-task", default="trees/boil_water.yaml", help="task of the pybullet episode rows")
    ap.add_argument("--no-episode", action="store_true", help="skip the pybullet episode rows")
    return ap.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    kin = Kinematics.arm()
    targets = reachable_targets(kin, args.n, args.seed)
    rows = [
        bench_ours(kin, targets, args, analytic=True, collision=False),
        bench_ours(kin, targets, args, analytic=True, collision=True),
        bench_ours(kin, targets, args, analytic=False, collision=False),
        bench_pybullet(kin, targets, args),
        bench_toppra(args),
    ]
    if not args.no_episode:
        rows.extend(bench_episode(args))
    for bench in extra_benches(args.extra):
        rows.extend(bench(args))
    print(f"tolerance: {args.pos_tol:g} m, {args.rot_tol:g} rad; seed {args.seed}")
    print(format_table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
