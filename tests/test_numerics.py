"""numpy's BLAS kernels and SIMD loops are pinned, so a seed's episode does not depend on the
machine's CPU (vap_bt/numerics.py)."""

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
    """blas_cores() and numpy_simd() (as "simd") in a fresh interpreter that imports ``imports`` in that order."""
    code = "; ".join(f"import {m}" for m in imports) + "; import json; from vap_bt.numerics import blas_cores, " \
        "numpy_simd; print(json.dumps({**blas_cores(), 'simd': numpy_simd()}))"
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def bare_env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_CORETYPE", "NPY_DISABLE_CPU_FEATURES")}
    return {**env, "PYTHONPATH": str(ROOT), **extra}


def test_importing_the_package_pins_the_kernels_numpy_and_scipy_load():
    got = cores("vap_bt", "numpy", "scipy.linalg", env=bare_env())
    assert got == {"numpy": "Haswell", "scipy": "Haswell", "simd": "X86_V3"}  # AVX2's, on an AVX-512 machine too


def test_numpy_loaded_before_the_package_is_said_once_too_late_to_pin():
    """A script that loads numpy (or pybullet, which loads it) before vap_bt runs the CPU's
    kernels: the package cannot pin them then, and says so; loaded after it, or with the kernels
    chosen by the environment, nothing is said."""
    def stderr(code: str, env: dict[str, str]) -> str:
        return subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True,
                              check=True).stderr

    assert "numpy was loaded before vap_bt" in stderr("import numpy; import vap_bt", bare_env())
    assert "numpy was loaded before vap_bt" not in stderr("import vap_bt; import numpy", bare_env())
    assert "numpy was loaded before vap_bt" not in stderr("import numpy; import vap_bt",
                                                           bare_env(OPENBLAS_CORETYPE="Haswell"))


@pytest.mark.parametrize("command", ["experiments/ablation", "experiments/failures", "experiments/strategies",
                                     "experiments/viewpoints", "experiments/scene_geometry", "bench/viewpoint_cases",
                                     "bench/replan", "bench/semantics", "bench/viz_load"])
def test_each_experiment_command_pins_the_kernels_before_its_tools_load_numpy(command):
    """RESULTS.md's commands are run as they are, with no OPENBLAS_CORETYPE: an experiment's
    modules (tables, plots) load numpy, and imported before the package they left the command's
    own process on the CPU's kernels, said by the warning above on every campaign's first line."""
    out = subprocess.run([sys.executable, f"tools/{command}.py", "--help"], cwd=ROOT, env=bare_env(),
                         capture_output=True, text=True, check=True)
    assert "numpy was loaded before vap_bt" not in out.stderr


def test_a_kernel_set_someone_chose_is_kept():
    got = cores("vap_bt", "numpy", env=bare_env(OPENBLAS_CORETYPE="Sandybridge", NPY_DISABLE_CPU_FEATURES="X86_V3"))
    assert got["numpy"] == "Sandybridge" and "X86_V3" not in got["simd"]


def test_the_suite_itself_runs_on_the_pinned_kernels():
    """tools/test.sh pins them: a plugin (pytest-randomly) loads numpy before any test module
    could import the package."""
    import numpy  # noqa: F401

    from vap_bt.numerics import blas_cores, numpy_simd
    from vap_bt.report import versions

    assert blas_cores()["numpy"] == "Haswell" and "X86_V4" not in numpy_simd(), \
        "run the suite by tools/test.sh (it sets OPENBLAS_CORETYPE and NPY_DISABLE_CPU_FEATURES)"
    assert "numpy Haswell" in versions()["openblas"] and versions()["numpy_simd"] == numpy_simd()
