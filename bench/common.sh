# Shared by the bench/run_<suite>.sh scripts, which source it after `set -euo pipefail`.

# bench_init SUITE "$@": takes BUILD_DIR from the script's arguments and sets build_dir,
# bench_dir, binary (BUILD_DIR/bin/mink_bench_SUITE), results_dir and csv
# (results/SUITE.csv); the remaining arguments, Google Benchmark flags, go to bench_args.
# Exits 2 without a BUILD_DIR and 1 when the binary has not been built.
bench_init() {
  local suite=$1
  shift
  if [ $# -lt 1 ]; then
    echo "usage: $0 BUILD_DIR [benchmark flags...]" >&2
    exit 2
  fi
  build_dir=$1
  shift
  bench_args=("$@")
  bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
  binary=$build_dir/bin/mink_bench_$suite
  results_dir=$bench_dir/results
  csv=$results_dir/$suite.csv
  if [ ! -x "$binary" ]; then
    echo "$(basename "$0"): $binary not found; build the target mink_bench_$suite first" >&2
    exit 1
  fi
  mkdir -p "$results_dir"
}

# gbench_medians RAW COLUMN DECIMALS: Google Benchmark's CSV report RAW (name,iterations,
# real_time,cpu_time,time_unit,...) as case,size,implementation,median_ns, from the rows named
# "case/size/implementation[/...]_median", taking the time in COLUMN (3 real, 4 CPU).
gbench_medians() {
  echo "case,size,implementation,median_ns"
  awk -F, -v column="$2" -v decimals="$3" '
    /^"/ {
      name = $1
      gsub(/"/, "", name)
      if (name !~ /_median$/) next
      sub(/_median$/, "", name)
      split(name, part, "/")
      unit = $5
      gsub(/"/, "", unit)
      scale = unit == "s" ? 1e9 : unit == "ms" ? 1e6 : unit == "us" ? 1e3 : 1
      printf "%s,%s,%s,%.*f\n", part[1], part[2], part[3], decimals, $column * scale
    }' "$1"
}
