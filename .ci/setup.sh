#!/usr/bin/env bash
# Set up a fresh Debian 12 machine, build, and run: `bash .ci/setup.sh main` (the paper's
# wind-tunnel rig, trim point, free flight and constrained flight test into results/main-run/,
# checked against the committed results/paper/, ending with a paper-vs-ours table of the trim
# point) or `bash .ci/setup.sh test` (every test). Idempotent: packages already
# present are not reinstalled and the build folder is reused. Only Debian packages are downloaded.
set -euo pipefail
cd "$(dirname "$0")/.."

what="${1:-main}"
jobs="$(nproc 2>/dev/null || echo 2)"
build_dir="${ORNI_BUILD_DIR:-build}"
werror="OFF"
if [[ "${CI:-}" == "true" ]]; then werror="ON"; fi

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libsundials-dev libceres-dev libnlopt-dev libnlopt-cxx-dev libspectra-dev
  libtomlplusplus-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev gnuplot-nox
  calculix-ccx
  # the Python module ornithopter (python/), its pytest suite and example
  pybind11-dev python3-numpy python3-pytest python3-matplotlib
  # `pip install .` into a venv and the wheel (python3 -m build) of python.pytest
  python3-venv python3-setuptools python3-wheel python3-build
  # the HTML reports checked in a real browser (cli.paper_results)
  chromium
  # the readers' libFuzzer target (.ci/run); flock and unshare of the CLI tests
  clang-14 libclang-rt-14-dev util-linux
  # distributed runs (mpirun -n N ornithopter run STUDY) and their test cli.mpi_runs
  libopenmpi-dev openmpi-bin
)

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    echo "setup: all ${#packages[@]} Debian packages present"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=""
  if [[ "$(id -u)" != "0" ]]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DORNI_WARNINGS_AS_ERRORS="$werror" >/dev/null
  cmake --build "$build_dir" -j "$jobs"
}

install_packages
build
case "$what" in
  main)
    # The paper reproduced in one command (.ci/main_run.sh): the wind-tunnel rig (Fig. 2), the
    # published trim point (Table 3), its free flight (Figs. 6-8) and the constrained flight test
    # (Fig. 9) into the git-ignored results/main-run/, checked against the committed
    # results/paper/, ending with a paper-vs-ours table of the trim point.
    bash .ci/main_run.sh "$build_dir" results/main-run
    ;;
  test)
    ctest --test-dir "$build_dir" --output-on-failure -j "$jobs"
    ;;
  *)
    echo "usage: bash .ci/setup.sh [main|test]" >&2
    exit 2
    ;;
esac
