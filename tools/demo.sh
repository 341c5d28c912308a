#!/usr/bin/env bash
# The demo: sets up if needed, then runs the boil-water task (paper S1) end to end — plan, compile,
# tick, verify every precondition and effect, handle injected situations — and writes the report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
mkdir -p out
exec .venv/bin/vap-bt run trees/boil_water.yaml --seed "${SEED:-1}" --report out/boil_water.json "$@"
