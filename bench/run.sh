#!/usr/bin/env bash
# Runs every benchmark suite (bench/run_<suite>.sh), each writing bench/results/<suite>.csv.
#
# Usage: bench/run.sh BUILD_DIR
# Environment:
#   MINK_BENCH_SUITES="hull gjk ..."   only these suites (default: all of them)
# Each suite's script documents its own environment variables.
set -euo pipefail

if [ $# -ne 1 ]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
build_dir=$1
bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

suites=${MINK_BENCH_SUITES:-}
if [ -z "$suites" ]; then
  for script in "$bench_dir"/run_*.sh; do
    name=$(basename "$script" .sh)
    suites+="${name#run_} "
  done
fi

status=0
for suite in $suites; do
  script=$bench_dir/run_$suite.sh
  if [ ! -x "$script" ]; then
    echo "run.sh: no benchmark suite '$suite' ($script)" >&2
    exit 2
  fi
  echo "== benchmark suite: $suite"
  "$script" "$build_dir" || status=$?
done
exit "$status"
