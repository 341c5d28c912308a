"""Writes the mobile manipulator's URDF from its YAML configuration and published dimensions.

Why generate rather than hand-write: joint limits, the arm mount, the TCP offset and the camera
mount are written once, in ``mobile_ur5e.yaml``; the URDF can then never disagree with what the
controllers are told. The shipped ``mobile_ur5e.urdf`` is this module's output (a test checks it);
regenerate after editing the YAML with ``python -m robots.build_urdf``.

Geometry is deliberately simple — boxes and cylinders, no meshes — sized from the datasheets:
the UR5e's link tubes (the DH table hides the shoulder/elbow offsets of 0.138 m and 0.131 m along
the joint axes; the tubes are placed there), the Robotiq 2F-85 body and fingers, the D435i
housing (90 x 25 x 25 mm). Masses are the published ones (UR5e 20.6 kg in total, 2F-85 0.9 kg,
D435i 72 g); inertias are those of the main shape of each link, which is plenty for a
position-controlled simulation.

Arm frames follow the DH table exactly (link *i*'s z axis is joint *i+1*'s axis), so the frame
``flange`` equals DH frame 6 expressed in ``arm_base_link`` (= DH frame 0).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

from robots.config import RobotConfig

HALF_PI = math.pi / 2

# Rotations that lay a URDF cylinder (axis z) along x or y.
ALONG_X = (0.0, HALF_PI, 0.0)
ALONG_Y = (HALF_PI, 0.0, 0.0)
ALONG_Z = (0.0, 0.0, 0.0)

# ROS convention: optical frame (z forward, x right, y down) from body frame (x forward, z up).
OPTICAL_FROM_BODY_RPY = (-HALF_PI, 0.0, -HALF_PI)


@dataclass(frozen=True)
class Box:
    """A box shape of full edge lengths ``size`` (m), placed at ``xyz``/``rpy`` in its link's frame."""

    size: tuple[float, float, float]
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = ALONG_Z


@dataclass(frozen=True)
class Cylinder:
    """A cylinder shape (m) along its z axis, placed at ``xyz``/``rpy`` in its link's frame
    (:data:`ALONG_X`, :data:`ALONG_Y` lay it down)."""

    radius: float
    length: float
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = ALONG_Z


Shape = Box | Cylinder


@dataclass
class Link:
    """A link; the first collision shape carries the mass (its inertia is the link's)."""

    name: str
    mass: float = 0.0
    shapes: list[Shape] = field(default_factory=list)  # collision and visual
    decor: list[Shape] = field(default_factory=list)  # visual only
    colour: str = "grey"


@dataclass
class Joint:
    """A URDF joint from ``parent`` to ``child`` at ``xyz``/``rpy``; ``limits`` (lower, upper, effort,
    velocity) for a moving one."""

    name: str
    kind: str  # fixed | revolute | prismatic
    parent: str
    child: str
    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    axis: tuple[float, float, float] = (0.0, 0.0, 1.0)
    limits: tuple[float, float, float, float] | None = None  # lower, upper, effort, velocity


COLOURS = {
    "grey": (0.6, 0.6, 0.62, 1.0),
    "dark": (0.15, 0.15, 0.17, 1.0),
    "blue": (0.25, 0.45, 0.75, 1.0),
    "silver": (0.8, 0.8, 0.82, 1.0),
    "black": (0.05, 0.05, 0.05, 1.0),
}

# Frames with no body still need a (tiny) inertia: pybullet gives inertia-less links 1 kg.
FRAME_MASS = 1e-3


def _inertia(shape: Shape, mass: float) -> tuple[float, float, float]:
    """Principal moments of a solid box/cylinder in its own frame."""
    if isinstance(shape, Box):
        x, y, z = shape.size
        return (
            mass * (y * y + z * z) / 12,
            mass * (x * x + z * z) / 12,
            mass * (x * x + y * y) / 12,
        )
    r, h = shape.radius, shape.length
    side = mass * (3 * r * r + h * h) / 12
    return (side, side, mass * r * r / 2)


def _f(values: tuple[float, ...]) -> str:
    return " ".join(f"{v:.10g}" for v in values)


def _geometry(shape: Shape) -> str:
    if isinstance(shape, Box):
        return f'<box size="{_f(shape.size)}"/>'
    return f'<cylinder radius="{shape.radius:.10g}" length="{shape.length:.10g}"/>'


def _link_xml(link: Link) -> list[str]:
    out = [f'  <link name="{link.name}">']
    if link.shapes and link.mass > 0:
        main = link.shapes[0]
        ixx, iyy, izz = _inertia(main, link.mass)
        # Inertia is given about the main shape's centre, in its own orientation.
        out += [
            "    <inertial>",
            f'      <origin xyz="{_f(main.xyz)}" rpy="{_f(main.rpy)}"/>',
            f'      <mass value="{link.mass:.10g}"/>',
            f'      <inertia ixx="{ixx:.6g}" ixy="0" ixz="0" iyy="{iyy:.6g}" iyz="0" izz="{izz:.6g}"/>',
            "    </inertial>",
        ]
    else:
        m = FRAME_MASS
        out += [
            "    <inertial>",
            f'      <mass value="{m}"/>',
            '      <inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/>',
            "    </inertial>",
        ]
    for shape in link.shapes + link.decor:
        out += [
            "    <visual>",
            f'      <origin xyz="{_f(shape.xyz)}" rpy="{_f(shape.rpy)}"/>',
            f"      <geometry>{_geometry(shape)}</geometry>",
            f'      <material name="{link.colour}"/>',
            "    </visual>",
        ]
    for shape in link.shapes:
        out += [
            "    <collision>",
            f'      <origin xyz="{_f(shape.xyz)}" rpy="{_f(shape.rpy)}"/>',
            f"      <geometry>{_geometry(shape)}</geometry>",
            "    </collision>",
        ]
    out.append("  </link>")
    return out


def _joint_xml(joint: Joint) -> list[str]:
    out = [
        f'  <joint name="{joint.name}" type="{joint.kind}">',
        f'    <parent link="{joint.parent}"/>',
        f'    <child link="{joint.child}"/>',
        f'    <origin xyz="{_f(joint.xyz)}" rpy="{_f(joint.rpy)}"/>',
    ]
    if joint.kind != "fixed":
        lower, upper, effort, velocity = joint.limits  # type: ignore[misc]
        out += [
            f'    <axis xyz="{_f(joint.axis)}"/>',
            f'    <limit lower="{lower:.17g}" upper="{upper:.17g}" effort="{effort:.10g}" '
            f'velocity="{velocity:.17g}"/>',
        ]
    out.append("  </joint>")
    return out


def _group_limits(group, i: int) -> tuple[float, float, float, float]:
    return (group.lower[i], group.upper[i], group.effort[i], group.velocity[i])


def _base(cfg: RobotConfig) -> tuple[list[Link], list[Joint]]:
    """World-fixed root, virtual x/y/yaw joints, the base body with mast and mounting plate."""
    b = cfg.base
    length, width = b.footprint
    mast_x = cfg.arm.mount.xyz[0]
    plate_top = cfg.arm.mount.xyz[2]
    body_top = 0.34
    links = [
        Link(cfg.root_link),
        Link("base_x_link", mass=1.0, shapes=[]),
        Link("base_y_link", mass=1.0, shapes=[]),
        Link(
            b.link,
            mass=70.0,
            shapes=[
                # Body kept 4 cm off the floor: the base is position-driven, not rolled.
                Box((length, width, body_top - 0.04), (0.0, 0.0, (body_top + 0.04) / 2)),
                Box((0.16, 0.16, plate_top - 0.02 - body_top), (mast_x, 0.0, (plate_top - 0.02 + body_top) / 2)),
                Box((0.24, 0.24, 0.02), (mast_x, 0.0, plate_top - 0.01)),
            ],
            decor=[
                Cylinder(0.09, 0.06, (sx * 0.20, sy * (width / 2 + 0.035), 0.09), ALONG_Y)
                for sx in (-1, 1)
                for sy in (-1, 1)
            ],
            colour="dark",
        ),
    ]
    # Virtual links have no shapes but some mass so that pybullet's motors have something to move.
    joints = [
        Joint("base_x_joint", "prismatic", cfg.root_link, "base_x_link", axis=(1.0, 0.0, 0.0), limits=_group_limits(b, 0)),
        Joint("base_y_joint", "prismatic", "base_x_link", "base_y_link", axis=(0.0, 1.0, 0.0), limits=_group_limits(b, 1)),
        Joint("base_yaw_joint", "revolute", "base_y_link", b.link, axis=(0.0, 0.0, 1.0), limits=_group_limits(b, 2)),
    ]
    return links, joints


# UR5e link masses (kg), from Universal Robots' published dynamics parameters.
UR5E_MASS = (4.0, 3.761, 8.058, 2.846, 1.37, 1.3, 0.365)
UR5E_LINKS = ("shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link")
SHOULDER_OFFSET = 0.138  # upper-arm tube sits this far along the shoulder-lift axis


def _arm(cfg: RobotConfig) -> tuple[list[Link], list[Joint]]:
    a = cfg.arm
    d1, _, _, d4, d5, d6 = a.dh.d
    _, a2, a3, _, _, _ = a.dh.a
    links = [
        Link(a.base_link, UR5E_MASS[0], [Cylinder(0.075, 0.09, (0.0, 0.0, 0.045))], colour="silver"),
        Link("shoulder_link", UR5E_MASS[1], [Cylinder(0.06, 0.135, (0.0, 0.0, -0.0125))], colour="blue"),
        Link(
            "upper_arm_link",
            UR5E_MASS[2],
            [
                Cylinder(0.045, abs(a2) - 0.05, (a2 / 2, 0.0, SHOULDER_OFFSET), ALONG_X),
                Cylinder(0.06, 0.17, (0.0, 0.0, 0.105)),
            ],
            colour="silver",
        ),
        Link(
            "forearm_link",
            UR5E_MASS[3],
            [
                Cylinder(0.038, abs(a3) - 0.06, (a3 / 2, 0.0, 0.0), ALONG_X),
                Cylinder(0.05, 0.19, (0.0, 0.0, 0.085)),
            ],
            colour="silver",
        ),
        Link("wrist_1_link", UR5E_MASS[4], [Cylinder(0.04, 0.215, (0.0, 0.0, -0.0625))], colour="blue"),
        Link("wrist_2_link", UR5E_MASS[5], [Cylinder(0.04, 0.09, (0.0, 0.0, 0.0))], colour="blue"),
        Link("wrist_3_link", UR5E_MASS[6], [Cylinder(0.04, 0.05, (0.0, 0.0, -0.025))], colour="silver"),
        Link(a.flange),
    ]
    names = a.joints
    lim = lambda i: _group_limits(a, i)  # noqa: E731
    # Joint origins are the DH table: translations along a joint's own axis are moved before the
    # joint (they commute with it), which keeps each link frame on its motor.
    joints = [
        Joint("arm_mount_joint", "fixed", a.mount.parent, a.base_link, a.mount.xyz, a.mount.rpy),
        Joint(names[0], "revolute", a.base_link, UR5E_LINKS[0], (0.0, 0.0, d1), limits=lim(0)),
        Joint(names[1], "revolute", UR5E_LINKS[0], UR5E_LINKS[1], rpy=(a.dh.alpha[0], 0.0, 0.0), limits=lim(1)),
        Joint(names[2], "revolute", UR5E_LINKS[1], UR5E_LINKS[2], (a2, 0.0, 0.0), limits=lim(2)),
        Joint(names[3], "revolute", UR5E_LINKS[2], UR5E_LINKS[3], (a3, 0.0, d4), limits=lim(3)),
        # alpha4 = +pi/2: joint 5's axis is -y of wrist_1; d5 is along that axis.
        Joint(names[4], "revolute", UR5E_LINKS[3], UR5E_LINKS[4], (0.0, -d5, 0.0), (a.dh.alpha[3], 0.0, 0.0), limits=lim(4)),
        # alpha5 = -pi/2: joint 6's axis is +y of wrist_2; d6 is along that axis.
        Joint(names[5], "revolute", UR5E_LINKS[4], UR5E_LINKS[5], (0.0, d6, 0.0), (a.dh.alpha[4], 0.0, 0.0), limits=lim(5)),
        Joint("flange_joint", "fixed", UR5E_LINKS[5], a.flange),
    ]
    return links, joints


def _gripper(cfg: RobotConfig) -> tuple[list[Link], list[Joint]]:
    """Robotiq 2F-85-like: coupling + body on the flange, two pads sliding along the flange y axis."""
    g = cfg.gripper
    body_top = 0.100  # fingers start here
    pad_len = 0.063  # fingertips 0.163 m from the flange
    links = [
        Link(
            "gripper_base_link",
            0.9,
            [Box((0.06, 0.11, body_top - 0.012), (0.0, 0.0, (body_top + 0.012) / 2)), Cylinder(0.0375, 0.012, (0.0, 0.0, 0.006))],
            colour="black",
        ),
        Link("left_finger_link", 0.05, [Box((0.022, 0.012, pad_len), (0.0, 0.006, pad_len / 2))], colour="dark"),
        Link("right_finger_link", 0.05, [Box((0.022, 0.012, pad_len), (0.0, -0.006, pad_len / 2))], colour="dark"),
        Link(g.tcp),
    ]
    joints = [
        Joint("gripper_mount_joint", "fixed", cfg.arm.flange, "gripper_base_link"),
        Joint(g.joints[0], "prismatic", "gripper_base_link", "left_finger_link", (0.0, 0.0, body_top), axis=(0.0, 1.0, 0.0), limits=_group_limits(g, 0)),
        Joint(g.joints[1], "prismatic", "gripper_base_link", "right_finger_link", (0.0, 0.0, body_top), axis=(0.0, -1.0, 0.0), limits=_group_limits(g, 1)),
        Joint("tcp_joint", "fixed", "gripper_base_link", g.tcp, (0.0, 0.0, g.tcp_offset)),
    ]
    return links, joints


def _camera(cfg: RobotConfig) -> tuple[list[Link], list[Joint]]:
    c = cfg.camera
    links = [
        Link(c.link, 0.072, [Box((0.025, 0.09, 0.025))], colour="grey"),
        Link(c.optical_frame),
    ]
    joints = [
        Joint("camera_mount_joint", "fixed", c.mount.parent, c.link, c.mount.xyz, c.mount.rpy),
        Joint("camera_optical_joint", "fixed", c.link, c.optical_frame, rpy=OPTICAL_FROM_BODY_RPY),
    ]
    return links, joints


def urdf_text(cfg: RobotConfig) -> str:
    """The whole URDF of the robot ``cfg`` describes (base, arm, gripper, camera), as text."""
    links: list[Link] = []
    joints: list[Joint] = []
    for part in (_base, _arm, _gripper, _camera):
        part_links, part_joints = part(cfg)
        links += part_links
        joints += part_joints
    out = [
        '<?xml version="1.0"?>',
        "<!-- Generated by robots/build_urdf.py from mobile_ur5e.yaml; do not edit by hand. -->",
        f'<robot name="{cfg.name}">',
    ]
    for name, rgba in COLOURS.items():
        out.append(f'  <material name="{name}"><color rgba="{_f(rgba)}"/></material>')
    for link in links:
        out += _link_xml(link)
    for joint in joints:
        out += _joint_xml(joint)
    out.append("</robot>")
    return "\n".join(out) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Write the URDF of each robot named in ``argv`` (default ``mobile_ur5e``) beside its YAML; returns
    the exit code."""
    from robots import load_config

    names = (argv if argv is not None else sys.argv[1:]) or ["mobile_ur5e"]
    for name in names:
        cfg = load_config(name)
        Path(cfg.urdf).write_text(urdf_text(cfg))
        print(f"wrote {cfg.urdf}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
