#!/usr/bin/env bash
# CLI and output contract of studies of kind "continuation" (docs/theory.md 10.5): the branch of
# periodic trims of the magpie over the flapping frequency, its CSV and summary keys, the figure,
# the resolved study as a fixed point, the same bytes with -j 2 and after a kill and a resume, and exit 2 with
# file, line and key for bad input.
#   usage: bash cli_continuation.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
efw="$root/studies/vehicles/efw_magpie.toml"

# A short branch: 12 -> 12.4 Hz in steps from 0.2 Hz (a few points, ~10 s).
cat > "$scratch/branch.toml" <<EOF
kind = "continuation"
name = "branch"
vehicle = "$efw"
[trim]
freq_hz = 12.0
[continuation]
parameter = "freq_hz"
to = 12.4
step = 0.2
max_points = 10
EOF
out="$scratch/branch"
"$bin" run "$scratch/branch.toml" -o "$out" > "$scratch/branch.log" 2>&1
check "continuation exits 0" test $? -eq 0
for f in summary.json study.resolved.toml continuation.csv continuation.png continuation.svg \
         continuation.gp; do
  check "writes $f" test -s "$out/$f"
done
check "no journal left" test ! -e "$out/continuation.journal"
for key in kind status message version parameter control to points points_stable events \
           stable_stretches start friction_note period_maps; do
  check "summary has $key" grep -q "\"$key\":" "$out/summary.json"
done
check "kind is continuation" test "$(json "$out/summary.json" kind)" = continuation
check "status completed" test "$(json "$out/summary.json" status)" = completed
check "CSV names row" bash -c "head -1 '$out/continuation.csv' | grep -q '^point,freq_hz,freq_hz,theta_mean_deg,speed_mps,tail_angle_deg,cg_shift_m,power_aero_W,max_modulus,stable,leading_mu_real,leading_mu_imag,periodic_residual,corrector_iterations,arclength,theta_min_deg,theta_max_deg,altitude_p2p_m,event,leading_label$'"
rows=$(( $(wc -l < "$out/continuation.csv") - 2 ))
check "at least 3 points ($rows)" test "$rows" -ge 3
first=$(sed -n 3p "$out/continuation.csv" | cut -d, -f2); last=$(tail -1 "$out/continuation.csv" | cut -d, -f2)
check "starts at 12 Hz ($first)" awk_true "$first == 12"
check "ends at 12.4 Hz ($last)" awk_true "($last - 12.4) ^ 2 < 1e-20"
check "every point stable here (max |mu| < 1)" bash -c "tail -n +3 '$out/continuation.csv' | awk -F, '\$10 != 1 { exit 1 }'"
check "every periodic residual <= 1e-8" bash -c "tail -n +3 '$out/continuation.csv' | awk -F, '\$13 > 1e-8 { exit 1 }'"
check "no NaN in the table" bash -c "! grep -qiw nan '$out/continuation.csv'"
# Again from the resolved study, with the Jacobian columns on two threads: the same bytes.
check "resolved study re-runs (-j 2)" "$bin" run "$out/study.resolved.toml" -o "$scratch/resolved" -j 2 > /dev/null 2>&1
check "resolved study is a fixed point" cmp -s "$out/study.resolved.toml" "$scratch/resolved/study.resolved.toml"
check "same inputs give the same branch on two threads" cmp -s "$out/continuation.csv" "$scratch/resolved/continuation.csv"

# Killed mid-run, then run again: the same bytes (the journal keeps every accepted point).
killed="$scratch/killed"
"$bin" run "$scratch/branch.toml" -o "$killed" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do  # until the journal holds its header and two points (at most 60 s)
  if [[ -f "$killed/continuation.journal" ]] &&
     [[ $(wc -l < "$killed/continuation.journal") -ge 3 ]]; then break; fi
  sleep 0.1
done
kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
check "killed mid-run (a journal is left)" test -f "$killed/continuation.journal"
finished_before_kill=0
[[ -f "$killed/summary.json" ]] && finished_before_kill=1
"$bin" run "$scratch/branch.toml" -o "$killed" > "$scratch/resumed.log" 2>&1
check "resumed run exits 0" test $? -eq 0
# It must have resumed from the journal's points, not started again (a record that does not
# decode is dropped, and a fresh start would also give the same bytes).
[[ $finished_before_kill -eq 1 ]] ||
  check "resumed run continued from the journal" grep -q "resuming from" "$scratch/resumed.log"
check "resumed branch has the same bytes" cmp -s "$out/continuation.csv" "$killed/continuation.csv"

# Bad input: exit 2 with file, line and key.
bad() {  # bad NAME EXPECTED-TEXT [continuation lines...]
  local name=$1 want=$2; shift 2
  { printf 'kind = "continuation"\nvehicle = "%s"\n' "$efw"; printf '%s\n' "$@"; } > "$scratch/$name.toml"
  "$bin" run "$scratch/$name.toml" -o "$scratch/$name" > "$scratch/$name.log" 2>&1
  local rc=$?
  check "$name: exit 2" test $rc -eq 2
  check "$name: names $want" grep -q -- "$want" "$scratch/$name.log"
}
bad missing_section "continuation" '[trim]'
bad same_as_control "continuation.parameter" '[continuation]' 'parameter = "tail_angle_deg"' 'to = 20.0'
bad end_out_of_range "continuation.to" '[continuation]' 'parameter = "freq_hz"' 'to = 500.0'
bad bad_step "continuation.step" '[continuation]' 'parameter = "freq_hz"' 'to = 13.0' 'step = -1.0'
bad unknown_key "continuation.speed" '[continuation]' 'parameter = "freq_hz"' 'to = 13.0' 'speed = 1'
bad two_stage "trim.method" '[trim]' 'method = "two_stage"' '[continuation]' 'parameter = "freq_hz"' 'to = 13.0'
check "[continuation] in a trim study: exit 2" bash -c "printf 'kind = \"trim\"\nvehicle = \"$efw\"\n[continuation]\nparameter = \"freq_hz\"\nto = 13.0\n' > '$scratch/wrong_kind.toml'; '$bin' run '$scratch/wrong_kind.toml' -o '$scratch/wrong_kind' > /dev/null 2>&1; test \$? -eq 2"
exit $fail
