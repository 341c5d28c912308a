"""Closed-form inverse kinematics of a UR-type arm (three parallel middle axes, spherical-ish
wrist offsets), from its DH table — used to *seed* the numerical IK.

The UR geometry decouples: the wrist-centre (origin of DH frame 5) lies ``d6`` behind the flange
along its z axis, which fixes the shoulder pan (two choices); the flange position then fixes
wrist 2 (two choices) and the flange orientation wrist 3; what remains is a planar two-link
problem for shoulder lift and elbow (two choices) and wrist 1 closes the chain. Up to 8 solutions.

Numerical IK from random seeds wastes most of its iterations finding the right branch; starting
from these solutions it only polishes (the URDF is built from the same table, so they are exact up
to rounding). Near singular configurations (wrist 2 at 0 or pi, target on the shoulder axis) the
formulas lose digits — the polishing step and the random-seed fallback in :mod:`ik` take over.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from robots.config import DH
from vap_bt.motion.se3 import inverse


def dh_transform(theta: float, d: float, a: float, alpha: float) -> np.ndarray:
    """Standard DH link transform Rz(theta) Tz(d) Tx(a) Rx(alpha)."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array([[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0.0, sa, ca, d], [0.0, 0.0, 0.0, 1.0]])


def dh_fk(q, dh: DH) -> np.ndarray:
    """Flange (DH frame 6) in DH frame 0."""
    T = np.eye(4)
    for theta, d, a, alpha in zip(q, dh.d, dh.a, dh.alpha, strict=True):
        T = T @ dh_transform(theta, d, a, alpha)
    return T


def _clip_unit(x: float) -> float | None:
    """acos/asin argument, tolerating rounding just outside [-1, 1]; None if truly outside."""
    if x > 1.0 + 1e-9 or x < -1.0 - 1e-9:
        return None
    return max(-1.0, min(1.0, x))


def solve(T06: np.ndarray, dh: DH) -> list[np.ndarray]:
    """All closed-form solutions (each in (-pi, pi]) for the flange pose ``T06`` in DH frame 0."""
    return list(iter_solutions(T06, dh))


def iter_solutions(T06: np.ndarray, dh: DH) -> Iterator[np.ndarray]:
    """The solutions one at a time (a caller that needs only the first valid one stops early)."""
    d1, _, _, d4, d5, d6 = dh.d
    _, a2, a3, _, _, _ = dh.a
    p6 = T06[:3, 3]
    p5 = p6 - d6 * T06[:3, 2]
    r = math.hypot(p5[0], p5[1])
    c = _clip_unit(d4 / r) if r > 1e-12 else None
    if c is None:
        return
    psi, phi = math.atan2(p5[1], p5[0]), math.acos(c)
    T60 = inverse(T06)
    for q1 in (psi + phi + math.pi / 2, psi - phi + math.pi / 2):
        s1, c1 = math.sin(q1), math.cos(q1)
        c5 = _clip_unit((p6[0] * s1 - p6[1] * c1 - d4) / d6)
        if c5 is None:
            continue
        for q5 in (math.acos(c5), -math.acos(c5)):
            s5 = math.sin(q5)
            if abs(s5) < 1e-9:  # wrist singularity: q6 is free, pick 0
                q6 = 0.0
            else:
                q6 = math.atan2((-T60[1, 0] * s1 + T60[1, 1] * c1) / s5, (T60[0, 0] * s1 - T60[0, 1] * c1) / s5)
            T01 = dh_transform(q1, d1, 0.0, dh.alpha[0])
            T46 = dh_transform(q5, d5, 0.0, dh.alpha[4]) @ dh_transform(q6, d6, 0.0, dh.alpha[5])
            T14 = inverse(T01) @ T06 @ inverse(T46)
            p13 = T14 @ np.array([0.0, -d4, 0.0, 1.0])
            n13 = math.hypot(p13[0], p13[1])
            c3 = _clip_unit((n13 * n13 - a2 * a2 - a3 * a3) / (2 * a2 * a3))
            if c3 is None:
                continue
            for q3 in (math.acos(c3), -math.acos(c3)):
                s = _clip_unit(a3 * math.sin(q3) / n13) if n13 > 1e-12 else None
                if s is None:
                    continue
                q2 = -math.atan2(p13[1], -p13[0]) + math.asin(s)
                T13 = dh_transform(q2, 0.0, a2, dh.alpha[1]) @ dh_transform(q3, 0.0, a3, dh.alpha[2])
                T34 = inverse(T13) @ T14
                q4 = math.atan2(T34[1, 0], T34[0, 0])
                # Each angle into (-pi, pi]: the caller shifts full-turn joints as it needs.
                yield np.array([math.atan2(math.sin(v), math.cos(v)) for v in (q1, q2, q3, q4, q5, q6)])
