#!/usr/bin/env bash
# The whole campaign of issue 24 in one world, over as many sittings as it takes: every strategy
# (strategies.py) and every viewpoint kind (viewpoints.py) on S1-S5, block by block of ten seeds,
# into ONE episode log, so the full method's episodes are run once and serve Table III, the
# strategy comparison and the viewpoint comparison alike; then Table III (ablation.py) and the
# failure modes (failures.py) are read from that log, not run.
#
#   bash tools/experiments/campaign.sh                 # pybullet, seeds 0-49, 2 workers
#   WORLD=symbolic SEEDS=200 bash tools/experiments/campaign.sh
#
# Run it again to continue: an episode already in the log is not run again (--log keeps the log
# as --resume does), so a sitting stopped by Ctrl-C, SIGTERM or a closed session loses only the episodes
# in flight. Each block's full method comes first (the configurations' order), so a campaign
# stopped part-way has measured it on every task before the baselines. Environment: WORLD
# (pybullet), SEEDS (50: seeds 0..SEEDS-1), WORKERS (2), DIR (docs/results/<WORLD>_campaign),
# TASKS (S1 S2 S3 S4 S5), ADDRESS (join a Dask scheduler instead of a local cluster).
# A campaign is one version of the world and the simulated VLM: a log whose rows another version
# ran is not continued (the commands say so and exit 2); give the new version its own DIR, e.g.
#   DIR=docs/results/pybullet_campaign_pb3 bash tools/experiments/campaign.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
PY=.venv/bin/python
WORLD=${WORLD:-pybullet}
SEEDS=${SEEDS:-50}
WORKERS=${WORKERS:-2}
DIR=${DIR:-docs/results/${WORLD}_campaign}
TASKS=${TASKS:-S1 S2 S3 S4 S5}
LOG=$DIR/episodes.jsonl
# shellcheck disable=SC2206  # TASKS is a list of words
common=(--world "$WORLD" --tasks $TASKS --log "$LOG")
if [[ -n "${ADDRESS:-}" ]]; then common+=(--address "$ADDRESS"); else common+=(--workers "$WORKERS"); fi

for ((first = 0; first < SEEDS; first += 10)); do
    last=$((first + 9 < SEEDS - 1 ? first + 9 : SEEDS - 1))
    echo "campaign: seeds $first-$last of 0-$((SEEDS - 1))" >&2
    "$PY" tools/experiments/strategies.py "${common[@]}" --seeds "$first-$last" --out "$DIR/strategies" >/dev/null
    "$PY" tools/experiments/viewpoints.py "${common[@]}" --seeds "$first-$last" --out "$DIR/viewpoints" >/dev/null
done
"$PY" tools/experiments/ablation.py "${common[@]}" --report-only --out "$DIR/ablation" >/dev/null
"$PY" tools/experiments/failures.py "${common[@]}" --report-only --out "$DIR/failures" >/dev/null
echo "campaign: tables in $DIR/{strategies,viewpoints,ablation,failures}/table.md" >&2
