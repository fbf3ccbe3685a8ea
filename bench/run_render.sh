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

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [benchmark flags...]" >&2
  exit 2
fi
build_dir=$1
shift
bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
binary=$build_dir/bin/mink_bench_render
results_dir=$bench_dir/results
csv=$results_dir/render.csv
raw=$(mktemp /tmp/mink-render-bench-XXXXXX.csv)
trap 'rm -f "$raw"' EXIT

if [ ! -x "$binary" ]; then
  echo "run_render.sh: $binary not found; build the target mink_bench_render first" >&2
  exit 1
fi
mkdir -p "$results_dir"

"$binary" --benchmark_repetitions="${MINK_BENCH_REPETITIONS:-5}" \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$raw" --benchmark_out_format=csv "$@"

# Google Benchmark's CSV: name,iterations,real_time,cpu_time,time_unit,...; names look like
# "case/size/implementation[/iterations:N/manual_time]_median".
awk -F, '
  BEGIN { print "case,size,implementation,median_ns" }
  /^"/ {
    name = $1
    gsub(/"/, "", name)
    if (name !~ /_median$/) next
    sub(/_median$/, "", name)
    split(name, part, "/")
    scale = ($5 == "ms") ? 1e6 : ($5 == "us") ? 1e3 : ($5 == "s") ? 1e9 : 1
    printf "%s,%s,%s,%.0f\n", part[1], part[2], part[3], $3 * scale
  }' "$raw" > "$csv"
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
