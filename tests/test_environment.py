"""The set-up installed everything the project declares (catches a missing install step)."""

from __future__ import annotations

import importlib

import pytest

MODULES = ["py_trees", "zenoh", "unified_planning", "up_fast_downward", "pybullet", "pinocchio", "toppra",
           "ruckig", "open3d", "cv2", "rerun", "scipy", "yaml", "pydantic", "skills", "robots"]


@pytest.mark.parametrize("name", MODULES)
def test_dependency_imports(name):
    assert importlib.import_module(name) is not None


def test_fast_downward_engine_is_registered():
    from unified_planning.shortcuts import get_environment

    assert "fast-downward" in get_environment().factory.engines
