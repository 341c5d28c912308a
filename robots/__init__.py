"""Robot descriptions shipped with vap_bt: URDF files and their per-robot YAML configuration.

A robot is named by its file stem (``mobile_ur5e``): ``robots/<name>.urdf`` holds geometry and the
kinematic tree, ``robots/<name>.yaml`` the joint groups, limits, home pose and camera. Both are
package data, so they resolve from an installed wheel as well as from the source tree, offline.
See ``robots/README.md`` for frame and joint names.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

from robots.config import Arm, Base, Camera, Gripper, JointGroup, Mount, RobotConfig

__all__ = [
    "DEFAULT_ROBOT",
    "Arm",
    "Base",
    "Camera",
    "Gripper",
    "JointGroup",
    "Mount",
    "RobotConfig",
    "available",
    "config_path",
    "load_config",
    "package_dir",
    "urdf_path",
]

DEFAULT_ROBOT = "mobile_ur5e"


def package_dir() -> Path:
    """Installed directory of the descriptions (also the URDF package root for mesh lookups)."""
    return Path(__file__).resolve().parent


def available() -> list[str]:
    """Names of the robots that have both a URDF and a YAML file."""
    d = package_dir()
    return sorted(p.stem for p in d.glob("*.yaml") if (d / f"{p.stem}.urdf").exists())


def _file(name: str, suffix: str) -> Path:
    path = package_dir() / f"{name}{suffix}"
    if not path.exists():
        raise FileNotFoundError(f"no robot {name!r} ({path} missing); available: {available()}")
    return path


def urdf_path(name: str = DEFAULT_ROBOT) -> Path:
    """Absolute path of the robot's URDF, e.g. for ``pin.buildModelFromUrdf`` or ``p.loadURDF``."""
    return _file(name, ".urdf")


def config_path(name: str = DEFAULT_ROBOT) -> Path:
    """Absolute path of the robot's YAML configuration; FileNotFoundError naming the robots available."""
    return _file(name, ".yaml")


@cache
def load_config(name: str = DEFAULT_ROBOT) -> RobotConfig:
    """The robot's typed configuration (cached: it is immutable)."""
    return RobotConfig.from_yaml(config_path(name))
