#!/usr/bin/env bash
# Runs the render benchmark and writes bench/results/render.csv.
#
# Usage: bench/run_render.sh BUILD_DIR [Google Benchmark flags...]
# Environment:
#   MINK_BENCH_REPETITIONS=N   repetitions per case, the CSV keeps their median (default 5)
#
# Cases, at 1280 x 720 for the engine's large_pyramid scene, 5050 boxes, drawn by World::draw
# (bench/render/bench_scene.hpp):
#   draw_readback     one frame (shapes) drawn and read back as RGBA, per headless backend
#   draw_readback_contacts  the same with the contact points layer on
#   readback_only     the readback alone
#   record_triangles  the CPU share: draw calls turned into triangles, no GL
#   encode_frame      one frame through ffmpeg, per encoder (30-frame clips, start and end
#                     included)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init render "$@"
raw=$(mktemp /tmp/mink-render-bench-XXXXXX.csv)
trap 'rm -f "$raw"' EXIT

"$binary" --benchmark_repetitions="${MINK_BENCH_REPETITIONS:-5}" \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$raw" --benchmark_out_format=csv "${bench_args[@]}"

# Names look like "case/size/implementation[/iterations:N/manual_time]_median"; the real
# time column holds the manual times.
gbench_medians "$raw" 3 0 >"$csv"
echo "Wrote $csv"

# Ratios, and the 60 fps budget for draw + readback on OSMesa.
awk -F, '
  NR > 1 { t[$1 "/" $3] = $4 }
  END {
    if (("draw_readback/osmesa" in t) && ("draw_readback/egl" in t))
      printf "draw + readback: egl / osmesa = %.2f\n", t["draw_readback/egl"] / t["draw_readback/osmesa"]
    if (("encode_frame/libx264" in t) && ("encode_frame/mpeg4" in t))
      printf "encode per frame: mpeg4 / libx264 = %.2f\n", t["encode_frame/mpeg4"] / t["encode_frame/libx264"]
    if ("draw_readback/osmesa" in t) {
      ms = t["draw_readback/osmesa"] / 1e6
      printf "draw + readback on OSMesa: %.2f ms per frame (60 fps budget 16.7 ms: %s)\n", ms,
             ms <= 16.7 ? "met" : "NOT met"
    }
  }' "$csv"
