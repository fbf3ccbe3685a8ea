#!/usr/bin/env bash
# Runs the sleep benchmark (about 20,000 boxes asleep against the same world awake) and writes
# bench/results/sleep.csv.
#
# Usage: bench/run_sleep.sh BUILD_DIR [--repetitions=N] [--steps=N]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init sleep "$@"
"$binary" --csv="$csv" "${bench_args[@]}"
echo "wrote $csv"
