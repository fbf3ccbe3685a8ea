#!/usr/bin/env bash
# Runs the GJK benchmark: bench/results/gjk.csv (case,size,implementation,median_ns).
#
# Cases: cold/warm (our boolean and distance query against Box2D's b2Distance on the same
# pairs; warm starts reuse each pair's simplex cache from the previous step), manifold
# (collide_hulls against b2CollidePolygons on boxes and octagons). median_ns is the median over
# repetitions of the CPU time per query (CPU time, not wall time: the machine may be shared).
#
# Usage: bench/run_gjk.sh BUILD_DIR [Google Benchmark flags...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init gjk "$@"

raw=$(mktemp)
trap 'rm -f "$raw"' EXIT
started=$SECONDS
"$binary" --benchmark_format=csv "${bench_args[@]}" >"$raw"
echo "GJK benchmark took $((SECONDS - started)) s"

gbench_medians "$raw" 4 1 >"$csv"
echo "Wrote $csv"

# The ratios the narrowphase must show, from this one run.
awk -F, '
  NR > 1 { t[$1 "/" $2 "/" $3] = $4 }
  END {
    b8 = t["cold/8/mink-gjk-boolean"]; r8 = t["cold/8/box2d-b2distance"]
    b256 = t["cold/256/mink-gjk-boolean"]
    m4 = t["manifold/4/mink-collide-hulls"]; x4 = t["manifold/4/box2d-b2collidepolygons"]
    if (b8 > 0 && r8 > 0) printf "boolean at 8 vertices / b2Distance at 8: %.2f (must be <= 0.5)\n", b8 / r8
    if (b8 > 0 && b256 > 0) printf "boolean at 256 / boolean at 8: %.2f (must be <= 3)\n", b256 / b8
    if (m4 > 0 && x4 > 0) printf "collide_hulls / b2CollidePolygons on boxes: %.2f\n", m4 / x4
  }' "$csv"
