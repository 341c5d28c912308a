#!/usr/bin/env bash
# The test suite: sets up if needed, then runs every test (slow ones included), one pytest-xdist
# worker per core and one more (VAP_BT_TEST_WORKERS to change it; 0 runs in this process): the
# process tests spend most of their time waiting on the parts they start, so with one worker a core
# a quarter of the machine idled (15.2 CPU-minutes in 10.3 minutes on two cores; three workers: 9.5).
# One file per worker, the files with the most slow tests first (tests/conftest.py), so that
# the long process tests do not end the run on one worker while the other idles.
# pytest exits 5 when it collects no test; that is a failure here, never a silent pass.
set -uo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh || exit 1
# The suite starts a few hundred Python processes (CLI runs, skill servers, worlds): with bytecode
# writing off (PYTHONDONTWRITEBYTECODE, set on some machines) each one compiled the package from
# source again (0.15 CPU-s each) and pytest re-rewrote every test module per worker. The caches go
# into __pycache__/, which git ignores.
unset PYTHONDONTWRITEBYTECODE
# numpy's BLAS kernels and SIMD loops, pinned as importing vap_bt pins them (vap_bt/numerics.py), also for the test
# modules that load numpy before the package: on an AVX-512 machine two physics tests failed unpinned.
if [ "$(uname -m)" = x86_64 ]; then
  export OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-Haswell}
  export NPY_DISABLE_CPU_FEATURES=${NPY_DISABLE_CPU_FEATURES:-X86_V4 AVX512_ICL AVX512_SPR}
fi
.venv/bin/python -m pytest -q -n "${VAP_BT_TEST_WORKERS:-$(( $(nproc) + 1 ))}" --dist loadfile --no-loadscope-reorder "$@"
code=$?
if [ "$code" -eq 5 ]; then
  echo "test.sh: pytest collected no test — treating as a failure" >&2
  exit 1
fi
exit "$code"
