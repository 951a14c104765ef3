#!/usr/bin/env bash
# Set up a fresh Debian 12 machine, build, and run: `bash .ci/setup.sh main` (the paper's
# wind-tunnel rig, trim point, free flight and constrained flight test, ending with a paper-vs-ours
# table of the trim point) or `bash .ci/setup.sh test` (every test). Idempotent: packages already
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
    # The paper reproduced in one command: the wind-tunnel rig (Fig. 2), the published trim point
    # (Table 3), its free flight (Figs. 6-8) and the constrained flight test (Fig. 9), into the
    # committed results/paper/ (results/README.md has the whole paper-vs-ours table).
    bin="$build_dir/studies/runner/ornithopter"
    "$bin" run studies/paper/fig2_rfw_theta0.toml studies/paper/fig2_rfw_theta20.toml \
      studies/paper/table3_trim.toml studies/paper/fig6_8_free_flight.toml \
      studies/paper/fig9_constrained_flight_test.toml -o results/paper
    # The outputs are the committed files byte for byte except the run metadata of summary.json
    # (wall_time_s, version); a summary whose only change is that metadata is restored, so that
    # `git status` stays clean (the run's own times are in the lines printed above).
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
      # The list first, then the restores: a `git diff` still running in a pipe would hold the
      # index lock that `git checkout` needs.
      mapfile -t touched < <(git diff --name-only -- results/paper)
      for f in "${touched[@]}"; do
        changed="$(git diff -U0 -- "$f" | grep -E '^[-+][^-+]' | grep -vE '"(wall_time_s|version)":' || true)"
        if [[ -z "$changed" ]]; then
          git checkout -q -- "$f"
        fi
      done
    fi
    tpl="$(mktemp)"
    cat > "$tpl" <<'TABLE'
setup: the published trim point reproduced (paper Table 3 and section 4; ours: results/paper/table3_trim/summary.json)
                                 paper      ours
  flapping frequency (Hz)        12.0       {{ j:paper/table3_trim/summary.json:freq_hz %.1f }}
  mean pitch theta_MEAN (deg)    9.2        {{ j:paper/table3_trim/summary.json:theta_mean_deg %.2f }}
  flight speed U (m/s)           10.8       {{ j:paper/table3_trim/summary.json:speed_mps %.2f }}
  tail angle delta_T (deg)       11.85      {{ j:paper/table3_trim/summary.json:tail_angle_deg %.2f }}
  free-flight pitch range (deg)  0 to 20    {{ j:paper/table3_trim/summary.json:free_flight.theta_min_deg %.1f }} to {{ j:paper/table3_trim/summary.json:free_flight.theta_max_deg %.1f }} (bounded: {{ s:paper/table3_trim/summary.json:free_flight.bounded }})
  altitude p2p at 12 Hz (cm)     ~1         {{ j:paper/table3_trim/summary.json:free_flight.altitude_p2p_m 100 * %.1f }}
setup: figures: results/paper/table3_trim/trim_convergence.png (the trim solve) and
setup:          results/paper/fig6_8_free_flight/flight.png (free flight at Table 3's point, paper Fig. 7)
setup: every paper result against ours: results/README.md
TABLE
    "$build_dir/studies/tools/orni_results" fill "$tpl" results
    rm -f "$tpl"
    ;;
  test)
    ctest --test-dir "$build_dir" --output-on-failure -j "$jobs"
    ;;
  *)
    echo "usage: bash .ci/setup.sh [main|test]" >&2
    exit 2
    ;;
esac
