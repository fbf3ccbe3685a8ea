#!/usr/bin/env bash
# Runs the hull benchmark and plots it: bench/results/hull.csv and bench/results/hull.png.
#
# Usage: bench/run_hull.sh BUILD_DIR [Google Benchmark flags...]
# Environment:
#   MINK_BENCH_MAX_SIZE=N                largest n (default 10^7); 100000 makes a quick run
#   MINK_BENCH_IMPLEMENTATIONS=a,b,...   only these implementations, e.g. chan,divide-conquer,cgal
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init hull "$@"
png=$results_dir/hull.png
command -v gnuplot >/dev/null || { echo "run_hull.sh: gnuplot not found (apt install gnuplot-nox)" >&2; exit 1; }

args=(--csv="$csv")
if [ -n "${MINK_BENCH_MAX_SIZE:-}" ]; then args+=(--max-size="$MINK_BENCH_MAX_SIZE"); fi
if [ -n "${MINK_BENCH_IMPLEMENTATIONS:-}" ]; then
  args+=(--implementations="$MINK_BENCH_IMPLEMENTATIONS")
fi

started=$SECONDS
status=0
"$binary" "${args[@]}" "${bench_args[@]}" || status=$?
echo "Hull benchmark took $((SECONDS - started)) s"
# Status 3: something was not measured or a hull was wrong (listed above); plot the rest anyway.
if [ "$status" -ne 0 ] && [ "$status" -ne 3 ]; then exit "$status"; fi

# Cases and implementations in the order they appear in the CSV.
cases=$(awk -F, 'NR > 1 && !seen[$1]++ { printf "%s ", $1 }' "$csv")
implementations=$(awk -F, 'NR > 1 && !seen[$3]++ { printf "%s ", $3 }' "$csv")
if [ -z "$cases" ]; then
  echo "run_hull.sh: $csv has no results to plot" >&2
  exit 1
fi
# pngcairo draws smoother lines; the plain png terminal is the fallback.
terminal=png
if gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1; then terminal=pngcairo; fi
gnuplot -e "csv='$csv'; png='$png'; terminal='$terminal'; cases='$cases'; implementations='$implementations'" \
  "$bench_dir/plot_hull.gp"
echo "Wrote $png"
exit "$status"
