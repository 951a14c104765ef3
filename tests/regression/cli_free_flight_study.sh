#!/usr/bin/env bash
# Free-flight study files (paper Figs. 6-8) and their [simulate.free] keys: the Figs. 6-8 study
# runs (exit 0 whatever the verdict), its bounds reach summary.json, the resolved study writes
# every free-flight option back and re-runs to the same bytes, a study's own bounds are honoured,
# and a free run writes no constrained-flight-test output.
#   usage: bash cli_free_flight_study.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=$(cd "${2:?}" && pwd); scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
same() { awk "BEGIN { exit !(($1 - $2)^2 < 1e-18) }"; }

out="$scratch/fig6_8"
check "Figs. 6-8 study exits 0" "$bin" run "$root/studies/paper/fig6_8_free_flight.toml" -o "$out"
for f in summary.json study.resolved.toml histories.csv flight.png phase.png; do
  check "writes $f" test -s "$out/$f"
done
check "mode free" test "$(json "$out/summary.json" mode)" = free
check "no zmp.csv in free flight" test ! -e "$out/zmp.csv"
bound() {  # bound FILE KEY: KEY inside the "bounds" object of summary.json
  grep -A8 '"bounds"' "$1" | json /dev/stdin "$2"
}
check "bounds in summary: theta 40 deg" same "$(bound "$out/summary.json" theta_deg)" 40
r="$out/study.resolved.toml"
check "resolved study has [simulate.free]" grep -q '^\[simulate.free\]$' "$r"
for key in bound_speed_mps bound_W_mps bound_theta_deg bound_Q_degps bound_h_m transient_fraction \
           divergence_ratio initial_altitude_m; do
  check "resolved study writes $key" grep -q "^$key = " "$r"
done
check "resolved study re-runs" "$bin" run "$r" -o "$scratch/again"
check "resolved study is a fixed point" cmp -s "$r" "$scratch/again/study.resolved.toml"
check "same histories from the resolved study" cmp -s "$out/histories.csv" "$scratch/again/histories.csv"

# A study's own bounds and settings are used.
own="$scratch/own.toml"
cat > "$own" <<EOF
kind = "simulate"
vehicle = "$root/studies/vehicles/efw_magpie.toml"
[simulate]
mode = "free"
cycles = 6
[simulate.free]
bound_speed_mps = 3.5
bound_theta_deg = 25
bound_Q_degps = 1000
bound_h_m = 0.5
transient_fraction = 0.5
divergence_ratio = 50
initial_altitude_m = 30
EOF
check "own bounds: run exits 0" "$bin" run "$own" -o "$scratch/own"
s="$scratch/own/summary.json"
check "own bounds: U 3.5 m/s" same "$(bound "$s" U_mps)" 3.5
check "own bounds: theta 25 deg" same "$(bound "$s" theta_deg)" 25
check "own bounds: Q 1000 deg/s" same "$(bound "$s" Q_degps)" 1000
check "own bounds: h 0.5 m" same "$(bound "$s" h_m)" 0.5
check "own settings: first analysed cycle 4 of 6 (transient 0.5)" \
  test "$(json "$s" first_analysed_cycle)" = 4
check "own settings: initial altitude 30 m" \
  bash -c "awk -F, 'NR == 3 { exit !((\$4 - 30)^2 < 1e-18) }' '$scratch/own/histories.csv'"
exit $fail
