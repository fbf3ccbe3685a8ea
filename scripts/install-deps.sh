#!/usr/bin/env bash
# Installs the Debian 12 packages the build needs, and only those that are missing.
# Usage: scripts/install-deps.sh [build|python|test|bench|fuzz|all]
set -euo pipefail

profile=${1:-build}
build_pkgs=(build-essential cmake pkg-config libeigen3-dev libcli11-dev nlohmann-json3-dev libpng-dev libbox2d-dev
            libosmesa6-dev libegl-dev libgl-dev libsdl2-dev python3-dev pybind11-dev python3-numpy)
# What the Python module's sweeps use (its tests too).
python_pkgs=(python3-pandas python3-dask python3-distributed python3-tqdm)
test_pkgs=(libgtest-dev libgmock-dev libcgal-dev libgmp-dev libmpfr-dev libbox2d-dev xvfb xauth ffmpeg
           python3-pytest "${python_pkgs[@]}" python3-pip python3-setuptools python3-wheel)
bench_pkgs=(libbenchmark-dev libcgal-dev libgmp-dev libmpfr-dev libqhull-dev gnuplot-nox)
# The fuzz harnesses: clang 14 and its runtimes (libFuzzer, ASan, UBSan).
fuzz_pkgs=(clang-14 libclang-rt-14-dev)

case "$profile" in
  build) wanted=("${build_pkgs[@]}") ;;
  python) wanted=("${build_pkgs[@]}" "${python_pkgs[@]}") ;;
  test) wanted=("${build_pkgs[@]}" "${test_pkgs[@]}") ;;
  bench) wanted=("${build_pkgs[@]}" "${test_pkgs[@]}" "${bench_pkgs[@]}") ;;
  fuzz) wanted=("${build_pkgs[@]}" "${fuzz_pkgs[@]}") ;;
  all) wanted=("${build_pkgs[@]}" "${test_pkgs[@]}" "${bench_pkgs[@]}" "${fuzz_pkgs[@]}") ;;
  *) echo "install-deps: unknown profile '$profile' (build, python, test, bench, fuzz or all)" >&2; exit 2 ;;
esac

missing=()
for pkg in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
