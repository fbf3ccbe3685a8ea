#!/usr/bin/env bash
# Runs libFuzzer harnesses of build-fuzz/bin, JOBS at a time, each for SECONDS on its seed
# corpus fuzz/corpus/NAME/ (what it learns collects in build-fuzz/corpus/NAME/, a crashing
# input is kept in build-fuzz/artifacts/NAME/). Each harness writes its log to
# build-fuzz/logs/NAME.log; the last lines of each are shown, all of a failing one's.
# Usage: scripts/run-fuzzers.sh SECONDS JOBS NAME...
set -euo pipefail
seconds=$1 jobs=$2
shift 2
cd "$(dirname "$0")/.."
mkdir -p build-fuzz/logs

run_one() {
  local name=$1 seconds=$2
  mkdir -p "build-fuzz/corpus/$name" "build-fuzz/artifacts/$name"
  local dict=()
  if [[ -f "fuzz/$name.dict" ]]; then dict=(-dict="fuzz/$name.dict"); fi
  if build-fuzz/bin/"fuzz_$name" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$name/" "${dict[@]}" \
    "build-fuzz/corpus/$name" "fuzz/corpus/$name" >"build-fuzz/logs/$name.log" 2>&1; then
    echo "== fuzz_$name: clean after ${seconds} s"
    grep -E "^stat::number_of_executed_units|^Done [0-9]+ runs" "build-fuzz/logs/$name.log" || true
  else
    echo "== fuzz_$name FAILED; its log (build-fuzz/logs/$name.log):"
    cat "build-fuzz/logs/$name.log"
    return 1
  fi
}
export -f run_one

printf '%s\n' "$@" | xargs -P "$jobs" -I{} bash -c 'run_one "$1" "$2"' _ {} "$seconds"
