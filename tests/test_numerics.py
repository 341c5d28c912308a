"""numpy's BLAS kernels are pinned, so a seed's episode does not depend on the machine's CPU
(vap_bt/numerics.py)."""

from __future__ import annotations

import json
import os
import platform
import subprocess
import sys

import pytest

from conftest import ROOT

X86 = platform.machine().lower() in ("x86_64", "amd64")
pytestmark = pytest.mark.skipif(not X86, reason="the pin is for x86-64's OpenBLAS kernel names only")


def cores(*imports: str, env: dict[str, str]) -> dict:
    """blas_cores() in a fresh interpreter that imports ``imports`` in that order."""
    code = "; ".join(f"import {m}" for m in imports) + \
        "; import json; from vap_bt.numerics import blas_cores; print(json.dumps(blas_cores()))"
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def bare_env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_CORETYPE"}
    return {**env, "PYTHONPATH": str(ROOT), **extra}


def test_importing_the_package_pins_the_kernels_numpy_and_scipy_load():
    assert cores("vap_bt", "numpy", "scipy.linalg", env=bare_env()) == {"numpy": "Haswell", "scipy": "Haswell"}


def test_a_kernel_set_someone_chose_is_kept():
    assert cores("vap_bt", "numpy", env=bare_env(OPENBLAS_CORETYPE="Sandybridge")) == {"numpy": "Sandybridge"}


def test_the_suite_itself_runs_on_the_pinned_kernels():
    """tools/test.sh pins them: a plugin (pytest-randomly) loads numpy before any test module
    could import the package."""
    import numpy  # noqa: F401

    from vap_bt.numerics import blas_cores
    from vap_bt.report import versions

    assert blas_cores()["numpy"] == "Haswell", "run the suite by tools/test.sh, or with OPENBLAS_CORETYPE=Haswell"
    assert "numpy Haswell" in versions()["openblas"]
