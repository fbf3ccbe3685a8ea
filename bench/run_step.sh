#!/usr/bin/env bash
# Runs the step benchmark (ours against Box2D 2.4.1 in the same run) and writes
# bench/results/step.csv.
#
# Usage: bench/run_step.sh BUILD_DIR [Google Benchmark flags...]
# Environment:
#   MINK_BENCH_STEP_REPETITIONS=N   fresh worlds per case and engine (default 3)
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [benchmark flags...]" >&2
  exit 2
fi
build_dir=$1
shift
bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
binary=$build_dir/bin/mink_bench_step
results_dir=$bench_dir/results
csv=$results_dir/step.csv

if [ ! -x "$binary" ]; then
  echo "run_step.sh: $binary not found; build the target mink_bench_step first" >&2
  exit 1
fi
mkdir -p "$results_dir"
started=$SECONDS
"$binary" --csv="$csv" --repetitions="${MINK_BENCH_STEP_REPETITIONS:-3}" "$@"
echo "Step benchmark took $((SECONDS - started)) s; wrote $csv"
