#!/usr/bin/env bash
# Python's batch arrays against the same loop in C++ on 1,000 bodies, with the per-body Python
# loop beside them (bench/python/batch_bench.py), and writes bench/results/python.csv.
#
# Usage: bench/run_python.sh BUILD_DIR [--rounds R] [--steps K]
# Needs the module (BUILD_DIR/python) and mink_bench_python_twin (MINK_BUILD_BENCH with
# MINK_WITH_PYTHON); PYTHON names the interpreter the module was built for (default python3).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init python_twin "$@"
csv=$results_dir/python.csv
"${PYTHON:-python3}" "$bench_dir/python/batch_bench.py" "$build_dir" "$csv" "${bench_args[@]}"
