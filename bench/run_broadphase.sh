#!/usr/bin/env bash
# Runs the broadphase benchmark: bench/results/broadphase.csv (median time per step of
# Minkowski's sweep and prune and of Box2D 2.4.1's b2BroadPhase, measured in the same run).
#
# Usage: bench/run_broadphase.sh BUILD_DIR [Google Benchmark flags...]
# Environment:
#   MINK_BENCH_MAX_SIZE=N   largest number of boxes (default 100000)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init broadphase "$@"

args=(--csv="$csv")
if [ -n "${MINK_BENCH_MAX_SIZE:-}" ]; then args+=(--max-size="$MINK_BENCH_MAX_SIZE"); fi

started=$SECONDS
"$binary" "${args[@]}" "${bench_args[@]}"
echo "Broadphase benchmark took $((SECONDS - started)) s"

# Ours over Box2D per case and size, from this run's CSV.
awk -F, 'NR > 1 { t[$1 "," $2 "," $3] = $4; if (!seen[$1 "," $2]++) order[++n] = $1 "," $2 }
  END { for (i = 1; i <= n; ++i) { k = order[i]; o = t[k ",minkowski-sap"]; b = t[k ",box2d"];
    if (o != "" && b != "") printf "%-22s ours/box2d = %.3f\n", k, o / b } }' "$csv"
