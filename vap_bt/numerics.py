"""Numerical reproducibility: the same seed gives the same episode on any x86-64 machine.

numpy and scipy each carry an OpenBLAS built for many CPUs at once, which picks its kernels when
it loads, by the CPU it finds: on a machine with AVX-512 the SkylakeX kernels, elsewhere Haswell
or Zen ones. They sum in a different order and so round differently in the last bits, and a
pybullet episode is chaotic enough to carry that into its outcome: on an AVX-512 machine a cup
the fill skill holds under the tap stood outside the stream by a few millimetres, and a seed that
reached the goal on one machine did not on another (docs/BENCHMARKS.md, "The same seed on
another CPU"; tests/test_numerics.py holds the pin). So the package pins the kernel set before numpy loads: Haswell's (AVX2 and FMA,
which every x86-64 server since 2013 runs), unless ``OPENBLAS_CORETYPE`` is already set — by
whoever wants another, or by a shell script of tools/, which sets it for processes that load
numpy before this package. Other architectures are left alone (their OpenBLAS knows other
names). :func:`blas_cores` says which kernels each loaded OpenBLAS really runs, for the report.

numpy's own loops dispatch by CPU in the same way, and its AVX-512 ones of ``exp``, ``log1p`` and
``arccos`` (among others) give other last bits than its AVX2 ones: the package turns the AVX-512
targets off too (``NPY_DISABLE_CPU_FEATURES``, unless set), so numpy runs the loops of the AVX2
machines it runs on everywhere else. :func:`numpy_simd` says which targets numpy runs.
"""

from __future__ import annotations

import ctypes
import os
import platform
import sys
import warnings
from pathlib import Path

#: the OpenBLAS kernel set pinned on x86-64
CORETYPE = "Haswell"
#: numpy's dispatch targets above AVX2 (numpy 2.4's names: X86_V4 is AVX-512's Skylake set); a
#: name an older or newer numpy does not know is ignored by it
NPY_OFF = "X86_V4 AVX512_ICL AVX512_SPR"

if platform.machine().lower() in ("x86_64", "amd64"):
    if "numpy" in sys.modules and "OPENBLAS_CORETYPE" not in os.environ:
        # too late to pin: numpy chose its kernels when it loaded. Said, because the episode then
        # differs from a campaign's with the same seed from the first rounding on (a trace script
        # that imported pybullet, which loads numpy, before vap_bt: boil_water 102 and 135
        # succeeded there and failed through tools/experiments, stop 58)
        warnings.warn("numpy was loaded before vap_bt and OPENBLAS_CORETYPE is not set: its kernels are "
                      "this CPU's, and a seed's episode may differ from a campaign's; import vap_bt first "
                      f"or set OPENBLAS_CORETYPE={CORETYPE}", RuntimeWarning, stacklevel=2)
    os.environ.setdefault("OPENBLAS_CORETYPE", CORETYPE)
    os.environ.setdefault("NPY_DISABLE_CPU_FEATURES", NPY_OFF)


def numpy_simd() -> str:
    """The CPU targets numpy's dispatched loops run here among those it was built for ("X86_V3")."""
    from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__

    return " ".join(t for t in __cpu_dispatch__ if __cpu_features__.get(t)) or "baseline"


def blas_cores() -> dict[str, str]:
    """The kernel set each OpenBLAS loaded by numpy and scipy runs (``{"numpy": "Haswell"}``), read
    from the libraries themselves; a library not loaded (scipy not imported yet) is left out, and
    one that cannot say is "unknown"."""
    out = {}
    for package in ("numpy", "scipy"):
        module = sys.modules.get(package)
        if module is None:
            continue
        libs = sorted((Path(module.__file__).parent.parent / f"{package}.libs").glob("lib*openblas*.so*"))
        out[package] = _corename(libs[0]) if libs else "unknown"
    return out


def _corename(path: Path) -> str:
    """The core name an OpenBLAS library at ``path`` chose (it is already loaded: this opens the
    same copy)."""
    try:
        lib = ctypes.CDLL(str(path))
    except OSError:
        return "unknown"
    for symbol in ("scipy_openblas_get_corename64_", "scipy_openblas_get_corename", "openblas_get_corename"):
        fn = getattr(lib, symbol, None)
        if fn is not None:
            fn.restype = ctypes.c_char_p
            return fn().decode()
    return "unknown"
