"""The base's localisation error: the robot's map frame is where it believes it is, not where it is.

A real mobile base knows its pose from a localiser (AMCL against a 2-D laser map, typically) that
is right to a few centimetres and a degree or two. Everything the robot reports in the map frame
— its base pose, its tcp, the pose of every camera frame — is therefore in its *believed* frame,
and everything it is told in the map frame — a path for the base, a whole-body trajectory — is
carried out in that believed frame too: the base controller drives until the *believed* pose
reaches the commanded one, so the true base ends where the command is minus the error.

The error is a planar rigid transform ``M`` (believed ← true): believed pose = true pose offset
by ``(dx, dy, dθ)``, the offset drawn from a zero-mean normal truncated at ``bound`` standard
deviations per component (beyond that a localiser has lost itself: a failure of another kind,
not modelled). It is drawn when the base comes to rest after having moved at least
``update_distance`` or turned ``update_angle`` since the last draw — the thresholds at which AMCL
updates its particle filter (ROS ``amcl`` defaults: 0.2 m, π/6) — and held while the base stands
still or moves less (over a short move odometry is nearly exact, and the filter does not update).
Consequences, all physical:

* from one stance a constant error is harmless: what the camera measures and what the arm is then
  sent to are in the same (believed) frame, so a look-then-act lands where it looked;
* between stances the error changes: a thing measured from one stance is, seen from the next, a
  few centimetres and a degree or so from where belief puts it, and the map (walls, furniture,
  handles, taps, switches, in the true frame) is off by the current error from what the camera
  shows. A robot that re-measures its target from where it stands before it acts is unaffected.

The base also reports its odometry — its motion in a frame fixed where it started — as a real
base's wheel encoders do: it never jumps, so a skill can carry what it measured from one stance
to the next by the motion between them. Odometry drift is not modelled (neither while moving nor
over a long way), nor is any localisation error in height, roll or pitch (a planar localiser has
none to give).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np


@dataclass(frozen=True)
class LocalizationModel:
    """Parameters of the simulated localiser (metres, radians).

    Sources, as collected in /work/notes/perception_sources.md, section 8 and calibration (h):
    ``sigma_xy`` = 5 cm and ``sigma_yaw`` = 2° per arrival is the note's point for plain AMCL with
    a 2-D lidar in a home (judgment), bracketed by published figures — 6.7 cm mean for a ROS
    floor-plan localiser with Kinects (Schmitt et al., IPIN 2012) above, under 1 cm / 1° for
    scan-matching systems (Röwekämper et al., IROS 2012; Costa et al.) below;
    ``update_distance`` / ``update_angle``: ROS 1 ``amcl``'s ``update_min_d`` / ``update_min_a``
    defaults (FOUND in the ROS amcl wiki)."""

    sigma_xy: float = 0.05
    sigma_yaw: float = math.radians(2.0)
    #: the error never exceeds this many standard deviations per component (12.5 cm, 5°: a
    #: localiser further off has lost itself, a failure of another kind)
    bound: float = 2.5
    update_distance: float = 0.2
    update_angle: float = math.pi / 6

    @classmethod
    def perfect(cls) -> "LocalizationModel":
        """No error at all (for tests of the drivers' physics, not of perception)."""
        return cls(sigma_xy=0.0, sigma_yaw=0.0)

    @property
    def max_xy(self) -> float:
        """The largest error per axis (m)."""
        return self.bound * self.sigma_xy

    @property
    def max_yaw(self) -> float:
        """The largest heading error (rad)."""
        return self.bound * self.sigma_yaw

    def describe(self) -> dict:
        """The model's parameters (yaw in degrees too), for the report."""
        return {**asdict(self), "sigma_yaw_deg": round(math.degrees(self.sigma_yaw), 3)}


class Localization:
    """The error in force now: maps base poses and 4x4 poses between the true and the believed
    map frame, and draws a new error when the base has come to rest after moving far enough."""

    def __init__(self, model: LocalizationModel, seed: int) -> None:
        self.model = model
        self.seed = seed
        self.draws = 0
        self.offset = np.zeros(3)  # (dx, dy, dθ) of the believed base pose over the true one
        self._start = np.zeros(3)  # the true pose the odometry frame is fixed at
        self._M = np.eye(3)  # believed <- true, planar homogeneous
        self._at: np.ndarray | None = None  # the true base pose at the last draw

    def reset(self, true_pose) -> None:
        """A new episode: the robot starts at rest, localised with a fresh error; its odometry
        starts at zero there."""
        self.draws = 0
        self._start = np.asarray(true_pose, float).copy()
        self._draw(np.asarray(true_pose, float))

    def odometry(self, true_pose) -> tuple[float, float, float]:
        """A true base pose in the odometry frame: the start pose's frame (x forward, y left)."""
        x0, y0, a0 = self._start
        c, s = math.cos(a0), math.sin(a0)
        dx, dy = true_pose[0] - x0, true_pose[1] - y0
        return float(c * dx + s * dy), float(-s * dx + c * dy), float(true_pose[2] - a0)

    def settle(self, true_pose) -> bool:
        """The base has come to rest at ``true_pose``: a new error if it moved far enough since
        the last draw (returns whether it drew)."""
        p = np.asarray(true_pose, float)
        if self._at is not None:
            moved = math.hypot(p[0] - self._at[0], p[1] - self._at[1])
            turned = abs(math.remainder(p[2] - self._at[2], 2 * math.pi))
            if moved < self.model.update_distance and turned < self.model.update_angle:
                return False
        self._draw(p)
        return True

    def _draw(self, true_pose: np.ndarray) -> None:
        rng = np.random.default_rng([self.seed, 0x10CA1, self.draws])
        self.draws += 1
        m = self.model
        e = [_truncated(rng, s, m.bound) for s in (m.sigma_xy, m.sigma_xy, m.sigma_yaw)]
        self.offset = np.array(e)
        c, s = math.cos(e[2]), math.sin(e[2])
        R = np.array([[c, -s], [s, c]])
        t = true_pose[:2] + self.offset[:2] - R @ true_pose[:2]  # the true base maps to true + offset
        self._M = np.eye(3)
        self._M[:2, :2], self._M[:2, 2] = R, t
        self._at = true_pose.copy()

    # ------------------------------------------------------------ frames

    def believed(self, pose) -> tuple[float, float, float]:
        """A true base pose (x, y, yaw) as the robot believes it (yaw unwrapped as given)."""
        p = self._M @ np.array([pose[0], pose[1], 1.0])
        return float(p[0]), float(p[1]), float(pose[2] + self.offset[2])

    def true(self, pose) -> tuple[float, float, float]:
        """A base pose commanded in the believed frame, where the true base goes for it."""
        p = np.linalg.solve(self._M, np.array([pose[0], pose[1], 1.0]))
        return float(p[0]), float(p[1]), float(pose[2] - self.offset[2])

    def believed_T(self, T: np.ndarray) -> np.ndarray:
        """A true 4x4 pose in the map frame as the robot reports it."""
        return self._lift() @ np.asarray(T, float)

    def true_T(self, T: np.ndarray) -> np.ndarray:
        """A 4x4 pose the robot gives in its believed map frame, in the true one (the inverse of
        :meth:`believed_T`)."""
        return np.linalg.inv(self._lift()) @ np.asarray(T, float)

    def _lift(self) -> np.ndarray:
        L = np.eye(4)
        L[:2, :2], L[:2, 3] = self._M[:2, :2], self._M[:2, 2]
        return L


def _truncated(rng: np.random.Generator, sigma: float, bound: float) -> float:
    """A zero-mean normal draw of ``sigma`` within ``bound`` sigmas (redrawn beyond)."""
    if sigma <= 0.0:
        return 0.0
    while True:
        v = float(rng.standard_normal())
        if abs(v) <= bound:
            return v * sigma
