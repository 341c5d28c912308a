#!/usr/bin/env bash
# The demo: sets up if needed, then runs the boil-water task (paper S1) end to end, twice:
#  1. in the headless pybullet household — skill servers and executive in this one command,
#     talking over a loopback Zenoh link; every precondition and effect checked by looking;
#     the live view recorded for rerun (out/boil_water.rrd: `.venv/bin/rerun out/boil_water.rrd`);
#  2. in the symbolic world with the paper's Table II situations injected, to show situations
#     being detected, the scene graph corrected and the plan repaired.
# Reports (everything needed to rerun) in out/. Extra arguments go to both `vap-bt run` calls.
# Each run ends with its summary table; both runs always run, and the demo exits with the first
# run's non-zero code (1: the goal was not reached, as the world says), else the second's.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
mkdir -p out
# seed 1 by default. Not every seed reaches the goal in pybullet (docs/RESULTS.md, "Pybullet"):
# the default has moved with the skills (4 until 6fa9cd8: it then lost the cup when open(microwave)
# set it down to free the hand; 0 at 0b833f6 does not confirm filled(cup)); seed 1 reaches the
# goal in both worlds at the commit that made it the default
seed="${SEED:-1}"
status=0
echo "== 1/2: pybullet household, no injected situations ==" >&2
.venv/bin/vap-bt run trees/boil_water.yaml --world pybullet --no-injection --seed "$seed" \
  --report out/boil_water_pybullet.json --rerun save out/boil_water.rrd "$@" || status=$?
echo "== 2/2: symbolic world, Table II situations injected ==" >&2
.venv/bin/vap-bt run trees/boil_water.yaml --world symbolic --seed "$seed" \
  --report out/boil_water_symbolic.json "$@" || { code=$?; [ "$status" -ne 0 ] || status=$code; }
exit "$status"
