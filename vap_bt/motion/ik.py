"""Inverse kinematics by damped least squares, restarted from several seeds, collision-aware.

For a target pose of a frame (default ``tcp``) we iterate Gauss-Newton steps on the pose error
``e = log6(current^-1 * target)`` (a twist in the current frame). Its Jacobian with respect to q
is ``Jlog6(err) * J_local``; the step solves ``(J J^T + lambda I) y = e``, ``dq = J^T y``. The
damping grows with the error (Levenberg-Marquardt style: ``lambda = lambda0 * (1 + |e|^2)``) so
that far-away seeds take cautious steps and the last steps are plain Newton steps, which converge
quadratically. Steps are capped per joint and the result brought back into the joint limits
(full-turn joints shift by 2 pi rather than stick at a limit).

A seed that stalls or runs out of iterations is abandoned for the next one. Seeds are, in order:
for the UR arm chain, the closed-form solutions of :mod:`ur_analytic` (nearest to the initial
guess first, each shifted by whole turns towards it), with which DLS merely polishes; the
caller's initial guess (if any); then configurations drawn from a generator seeded with
``options.seed`` — so the answer is deterministic — but for the UR chain only when some
closed-form branch failed to converge (near a singularity): when every branch converged, or
there is none (out of reach), random seeds would only find the same branches or nothing.
``analytic_seeds=False`` gives pure DLS.
A converged solution that collides (self or scene, :mod:`vap_bt.motion.collision`) is rejected
and the search goes on; so is one the caller's ``accept`` turns down (a solution the arm has no
clear way to from where it is: the next branch may have one).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

# toppra already depends on scipy; its raw LAPACK binding is the cheapest 6x6 SPD solve.
from scipy.linalg.lapack import dposv

from vap_bt.motion import se3, ur_analytic
from vap_bt.motion.collision import CollisionChecker
from vap_bt.motion.kinematics import Kinematics
from vap_bt.motion.se3 import wrap_angle


@dataclass(frozen=True)
class IKOptions:
    """Tolerances and search budget of :func:`solve`; the defaults are the arm's."""

    position_tolerance: float = 1e-4  # m
    orientation_tolerance: float = 1e-3  # rad
    max_iterations: int = 60  # per seed
    max_seeds: int = 20
    seed: int = 0
    damping: float = 1e-4
    max_step: float = 1.0  # rad (or m) per joint and iteration
    #: give up a seed when the error shrank less than this factor over ``stall_window`` iterations
    stall_ratio: float = 0.9
    stall_window: int = 5
    #: start from the closed-form UR solutions when the chain is the 6-joint arm
    analytic_seeds: bool = True


@dataclass(frozen=True)
class IKResult:
    """What the search found: ``q`` is the solution when ``success``, else the best configuration met,
    with ``reason`` saying why none was accepted."""

    success: bool
    q: np.ndarray  # best configuration found (the solution when success)
    position_error: float  # m
    orientation_error: float  # rad
    iterations: int  # total over all seeds
    seeds: int  # seeds tried
    reason: str  # "ok" | "unreachable" (no seed converged) | "collision" (all converged ones collide or were not accepted)


def _descend(
    kin: Kinematics, fid: int, target: pin.SE3, q: np.ndarray, opt: IKOptions
) -> tuple[np.ndarray, float, float, int]:
    """Run DLS from ``q``; returns (q, position error, orientation error, iterations used).

    This is the hot loop of every motion. Arrays here have six entries, where numpy's fixed cost
    per call dominates: scalar work is done on Python floats, the solve goes straight to LAPACK
    (``dposv``, ~4x cheaper than ``np.linalg.solve``), and limits are enforced only when crossed.
    """
    history: list[float] = []
    lower, upper = kin.lower_list, kin.upper_list
    eye = np.eye(6)  # J J^T is 6x6 whatever the number of joints
    pos = rot = math.inf
    it = 0
    for it in range(opt.max_iterations + 1):
        current, J = kin.pose_and_jacobian(q, fid)
        err = current.actInv(target)
        e = pin.log6(err).vector
        ex, ey, ez, wx, wy, wz = e.tolist()
        # |translation of err| equals the world distance; |angular part of log6| is the angle.
        pos = math.sqrt(sum(v * v for v in err.translation.tolist()))
        rot = math.sqrt(wx * wx + wy * wy + wz * wz)
        if pos <= opt.position_tolerance and rot <= opt.orientation_tolerance:
            return q, pos, rot, it
        if it == opt.max_iterations:
            break
        # Weighted error for the stall test: 1 rad ~ 0.1 m at arm scale.
        history.append(pos + 0.1 * rot)
        if len(history) > opt.stall_window and history[-1] > opt.stall_ratio * history[-1 - opt.stall_window]:
            break
        Je = pin.Jlog6(err) @ J
        lam = opt.damping * (1.0 + ex * ex + ey * ey + ez * ez + wx * wx + wy * wy + wz * wz)
        y, info = dposv(Je @ Je.T + lam * eye, e)[1:]
        if info != 0:  # not positive definite: only possible with zero damping
            break
        dq = (Je.T @ y).tolist()
        peak = max(abs(v) for v in dq)
        scale = opt.max_step / peak if peak > opt.max_step else 1.0
        qn = [a + scale * d for a, d in zip(q.tolist(), dq)]
        inside = all(lo <= v <= hi for v, lo, hi in zip(qn, lower, upper))
        q = np.array(qn) if inside else kin.clamp(np.array(qn))
    return q, pos, rot, it


def _near(q: np.ndarray, ref: np.ndarray, kin: Kinematics) -> np.ndarray:
    """``q`` with full-turn joints shifted by whole turns towards ``ref``, kept within limits."""
    shifted = np.where(kin.wraps, ref + wrap_angle(q - ref), q)
    return kin.clamp(shifted)


def _analytic_seeds(kin: Kinematics, frame: str, target: np.ndarray, q_ref: np.ndarray | None) -> Iterator[np.ndarray]:
    offsets = kin.flange_offsets(frame)
    if offsets is None:
        return
    world_arm_base, flange_frame = offsets
    flange_in_arm_base = se3.inverse(world_arm_base) @ target @ se3.inverse(flange_frame)
    solutions = ur_analytic.iter_solutions(flange_in_arm_base, kin.config.arm.dh)
    if q_ref is None:  # any solution will do: compute them lazily
        yield from solutions
        return
    near = [_near(q, q_ref, kin) for q in solutions]
    yield from sorted(near, key=lambda q: float(np.abs(q - q_ref).sum()))


def _seeds(kin: Kinematics, frame: str, target: np.ndarray, q_init: np.ndarray | None, opt: IKOptions):
    """(seed, kind) in order: kind "analytic", "initial" or "random"."""
    if opt.analytic_seeds:
        for q in _analytic_seeds(kin, frame, target, q_init):
            yield q, "analytic"
    if q_init is not None:
        yield kin.clamp(q_init), "initial"
    rng = np.random.default_rng(opt.seed)
    while True:
        yield kin.random_configuration(rng), "random"


def solve_ik(
    kin: Kinematics,
    target: np.ndarray,
    *,
    frame: str = "tcp",
    q_init: np.ndarray | None = None,
    collision: CollisionChecker | None = None,
    options: IKOptions = IKOptions(),
    accept: Callable[[np.ndarray], bool] | None = None,
) -> IKResult:
    """Joint values putting ``frame`` at ``target`` (4x4, in the chain's world frame), clear of
    collisions and (if given) ``accept``-ed."""
    fid = kin.frame_id(frame)
    goal = pin.SE3(np.asarray(target, dtype=float))
    best: tuple[float, np.ndarray, float, float] | None = None
    total = 0
    converged_but_colliding = False
    q0 = None if q_init is None else np.asarray(q_init, dtype=float)
    seeds = _seeds(kin, frame, np.asarray(target, dtype=float), q0, options)
    # The closed form lists every branch of the arm: when each of them converged (and was turned
    # down) or there is none (the target is out of reach), random seeds only find the same
    # branches again or nothing. Most failed searches are of these two kinds (a work-pose search
    # asks for hands the arm cannot reach, or reaches only into the furniture), and random seeds
    # made them the bulk of an episode's planning time.
    closed_form = options.analytic_seeds and kin.flange_offsets(frame) is not None
    branches_failed = False
    q, pos, rot, n = (kin.clamp(np.zeros(len(kin.lower))) if q0 is None else q0), math.inf, math.inf, 0
    for _ in range(options.max_seeds):
        q_seed, kind = next(seeds)
        if kind == "random" and closed_form and not branches_failed:
            break
        n += 1
        q, pos, rot, its = _descend(kin, fid, goal, q_seed, options)
        total += its
        ok = pos <= options.position_tolerance and rot <= options.orientation_tolerance
        branches_failed |= kind == "analytic" and not ok
        if ok and ((collision is not None and collision.in_collision(q)) or (accept is not None and not accept(q))):
            converged_but_colliding = True
            continue
        if ok:
            return IKResult(True, q, pos, rot, total, n, "ok")
        score = pos + 0.1 * rot
        if best is None or score < best[0]:
            best = (score, q, pos, rot)
    reason = "collision" if converged_but_colliding else "unreachable"
    if best is None:  # every seed converged into a collision, or none was worth trying
        return IKResult(False, q, pos, rot, total, n, reason)
    return IKResult(False, best[1], best[2], best[3], total, n, reason)
