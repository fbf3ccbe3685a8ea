#!/usr/bin/env bash
# Runs the step benchmark (ours against Box2D 2.4.1 in the same run) and writes
# bench/results/step.csv.
#
# Usage: bench/run_step.sh BUILD_DIR [Google Benchmark flags...]
# Environment:
#   MINK_BENCH_STEP_REPETITIONS=N   fresh worlds per case and engine (default 3)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init step "$@"
started=$SECONDS
"$binary" --csv="$csv" --repetitions="${MINK_BENCH_STEP_REPETITIONS:-3}" "${bench_args[@]}"
echo "Step benchmark took $((SECONDS - started)) s; wrote $csv"
