#!/usr/bin/env bash
# Large worlds: large_pyramid (sleeping on) and ragdolls built at the origin and 10^7 m out,
# stepped side by side until both sleep, in Minkowski and in Box2D v3's float and double
# (BOX2D_DOUBLE_PRECISION) builds at their own default settings (bench/engine/large_world.hpp).
# Writes bench/results/large_world.csv:
#   scene,implementation,origin_sleep_step,far_sleep_step,position_difference_m,
#   angle_difference_rad,finite
# the steps after which every dynamic body slept (-1: still awake after 3000), and the largest
# difference, body by body, of the far run's end (less the offset) from the origin's.
# Box2D v3's builds come from the target mink_bench_large_world_all; without Box2D v3 (see
# bench/run_step.sh) only ours runs.
#
# Usage: bench/run_large_world.sh BUILD_DIR
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init large_world "$@"
{
  echo "scene,implementation,origin_sleep_step,far_sleep_step,position_difference_m,angle_difference_rad,finite"
  "$binary"
  for build in float double; do
    rival=$build_dir/bin/mink_bench_large_world_v3_$build
    if [ -x "$rival" ]; then
      "$rival"
    else
      echo "$(basename "$0"): $rival not built; Box2D v3's $build build left out" >&2
    fi
  done
} > "$csv.tmp"
mv "$csv.tmp" "$csv"
cat "$csv"
echo "wrote $csv"
