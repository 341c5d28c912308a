"""Typed view of a robot's YAML configuration.

A robot is described twice: its geometry and kinematic tree live in the URDF, while the numbers a
controller needs (joint groups, velocity/acceleration/jerk limits, home pose, camera intrinsics)
live in a small YAML file next to it. The URDF is generated from the same YAML
(:mod:`robots.build_urdf`), so limits are written down once. This module turns the YAML into frozen
dataclasses so that the rest of the code never indexes into raw dictionaries.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

Vec = tuple[float, ...]


def _floats(values: Any, n: int | None = None) -> Vec:
    out = tuple(float(v) for v in values)
    if n is not None and len(out) != n:
        raise ValueError(f"expected {n} numbers, got {len(out)}: {values!r}")
    return out


@dataclass(frozen=True)
class Mount:
    """A fixed transform: parent frame name, translation (m), roll-pitch-yaw (rad)."""

    parent: str
    xyz: Vec
    rpy: Vec

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Mount:
        return cls(parent=str(d["parent"]), xyz=_floats(d["xyz"], 3), rpy=_floats(d["rpy"], 3))


@dataclass(frozen=True)
class JointGroup:
    """Joints that move together, with per-joint limits in SI units (m or rad)."""

    joints: tuple[str, ...]
    lower: Vec
    upper: Vec
    velocity: Vec
    acceleration: Vec
    jerk: Vec
    effort: Vec

    @property
    def dof(self) -> int:
        return len(self.joints)

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> JointGroup:
        joints = tuple(str(j) for j in d["joints"])
        n = len(joints)
        return cls(
            joints=joints,
            lower=_floats(d["lower"], n),
            upper=_floats(d["upper"], n),
            velocity=_floats(d["velocity"], n),
            acceleration=_floats(d["acceleration"], n),
            jerk=_floats(d["jerk"], n),
            effort=_floats(d["effort"], n),
        )


@dataclass(frozen=True)
class DH:
    """Standard Denavit-Hartenberg table (d, a, alpha per joint; theta is the joint value)."""

    d: Vec
    a: Vec
    alpha: Vec


@dataclass(frozen=True)
class Arm(JointGroup):
    """The manipulator: its joint group, where it is bolted on, and its published kinematics."""

    base_link: str = "arm_base_link"
    flange: str = "flange"
    mount: Mount = Mount("base_link", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    home: Vec = ()
    dh: DH = DH((), (), ())

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Arm:
        group = JointGroup.from_dict(d)
        dh = d["dh"]
        return cls(
            **group.__dict__,
            base_link=str(d["base_link"]),
            flange=str(d["flange"]),
            mount=Mount.from_dict(d["mount"]),
            home=_floats(d["home"], group.dof),
            dh=DH(
                d=_floats(dh["d"], group.dof),
                a=_floats(dh["a"], group.dof),
                alpha=_floats(dh["alpha"], group.dof),
            ),
        )


@dataclass(frozen=True)
class Base(JointGroup):
    """The holonomic base driven through virtual joints x, y, yaw from a world-fixed root."""

    link: str = "base_link"
    footprint: Vec = ()  # length (x), width (y) in metres

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Base:
        group = JointGroup.from_dict(d)
        return cls(**group.__dict__, link=str(d["link"]), footprint=_floats(d["footprint"], 2))


@dataclass(frozen=True)
class Gripper(JointGroup):
    """A parallel gripper: each finger joint is that finger's travel from the centre line (0 = closed),
    so the opening between the pads is the sum of the two joint values."""

    stroke: float = 0.085
    tcp: str = "tcp"
    tcp_offset: float = 0.0  # along the flange z axis

    def finger_positions(self, opening: float) -> Vec:
        """Joint values for a given opening width (m), clipped to the stroke."""
        half = min(max(opening, 0.0), self.stroke) / 2.0
        return (half,) * self.dof

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Gripper:
        group = JointGroup.from_dict(d)
        return cls(
            **group.__dict__,
            stroke=float(d["stroke"]),
            tcp=str(d["tcp"]),
            tcp_offset=float(d["tcp_offset"]),
        )


@dataclass(frozen=True)
class Camera:
    """A pinhole RGB-D camera. Intrinsics are given at (width, height); ``at`` rescales them."""

    link: str
    optical_frame: str
    mount: Mount
    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    near: float
    far: float
    sim_width: int
    sim_height: int
    #: m between a stereo depth camera's two imagers (0: not a stereo camera); the depth image is
    #: the left imager's, and a near thing hides what lies up to f·B·(1/z_near - 1/z) pixels to
    #: its left from the right imager: no depth there
    baseline: float = 0.0

    @property
    def vertical_fov_deg(self) -> float:
        """The vertical field of view (degrees), from the image height and ``fy``."""
        return math.degrees(2.0 * math.atan(self.height / (2.0 * self.fy)))

    def at(self, width: int, height: int) -> Camera:
        """The same camera rendered at another resolution (same field of view)."""
        sx, sy = width / self.width, height / self.height
        return Camera(
            link=self.link,
            optical_frame=self.optical_frame,
            mount=self.mount,
            width=width,
            height=height,
            fx=self.fx * sx,
            fy=self.fy * sy,
            cx=self.cx * sx,
            cy=self.cy * sy,
            near=self.near,
            far=self.far,
            sim_width=self.sim_width,
            sim_height=self.sim_height,
            baseline=self.baseline,
        )

    def for_sim(self) -> Camera:
        """The resolution the simulator renders at by default (smaller is faster)."""
        return self.at(self.sim_width, self.sim_height)

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Camera:
        return cls(
            link=str(d["link"]),
            optical_frame=str(d["optical_frame"]),
            mount=Mount.from_dict(d["mount"]),
            width=int(d["width"]),
            height=int(d["height"]),
            fx=float(d["fx"]),
            fy=float(d["fy"]),
            cx=float(d["cx"]),
            cy=float(d["cy"]),
            near=float(d["near"]),
            far=float(d["far"]),
            sim_width=int(d["sim_width"]),
            sim_height=int(d["sim_height"]),
            baseline=float(d.get("baseline", 0.0)),
        )


@dataclass(frozen=True)
class RobotConfig:
    """Everything about one robot that is not geometry."""

    name: str
    urdf: Path
    root_link: str
    base: Base
    arm: Arm
    gripper: Gripper
    camera: Camera
    #: link pairs that may touch by construction (e.g. the two closed fingers)
    allowed_collisions: tuple[tuple[str, str], ...]

    @property
    def tcp(self) -> str:
        """The name of the tool centre point's frame (the gripper's)."""
        return self.gripper.tcp

    @classmethod
    def from_yaml(cls, path: Path) -> RobotConfig:
        """The configuration in the YAML file at ``path`` (the URDF path resolved beside it)."""
        d = yaml.safe_load(path.read_text())
        return cls(
            name=str(d["name"]),
            urdf=path.parent / str(d["urdf"]),
            root_link=str(d["root_link"]),
            base=Base.from_dict(d["base"]),
            arm=Arm.from_dict(d["arm"]),
            gripper=Gripper.from_dict(d["gripper"]),
            camera=Camera.from_dict(d["camera"]),
            allowed_collisions=tuple(
                (str(a), str(b)) for a, b in d.get("allowed_collisions", [])
            ),
        )
