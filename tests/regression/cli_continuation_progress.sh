#!/usr/bin/env bash
# A continuation never reports a false success (issue 30, items 1 and 5):
#   - a first step too small to move the parameter (1e-12 Hz, 1e-9 Hz over 12 -> 12.6 Hz) ends
#     with status "failed" and the reason, exit 1; on the audited version it ended "completed:
#     the branch reached the end of the parameter range" with points 12, 11.99999999, 12;
#   - "completed" only when the last point is at `to`;
#   - `to` equal to the branch's start (the [trim] frequency, or CG shift 0) is bad input: exit 2
#     with file, line and key (it exited 1 after the start trim).
# Each run solves the magpie's periodic trim at 12 Hz first (a few seconds in Release).
#   usage: bash cli_continuation_progress.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
efw="$root/studies/vehicles/efw_magpie.toml"

study() {  # study NAME [continuation lines...]
  local name=$1; shift
  { printf 'kind = "continuation"\nname = "%s"\nvehicle = "%s"\n[trim]\nfreq_hz = 12.0\n' \
      "$name" "$efw"
    printf '[continuation]\n'; printf '%s\n' "$@"; } > "$scratch/$name.toml"
}

for step in 1e-12 1e-9; do
  name=tiny_step_$step
  study "$name" 'parameter = "freq_hz"' 'to = 12.6' "step = $step" 'max_points = 5'
  "$bin" run "$scratch/$name.toml" -o "$scratch/$name" > "$scratch/$name.log" 2>&1
  rc=$?
  sum="$scratch/$name/summary.json"
  check "step $step: exit 1 (failed), not 0 ($rc)" test $rc -eq 1
  check "step $step: status failed ($(json "$sum" status))" test "$(json "$sum" status)" = failed
  check "step $step: the message gives the reason (the step's floor)" \
    grep -q '"message": "[^"]*step[^"]*floor' "$sum"
  check "step $step: never 'completed'" bash -c "! grep -q 'completed' '$scratch/$name.log'"
  if [[ -s "$scratch/$name/continuation.csv" ]]; then
    last=$(tail -1 "$scratch/$name/continuation.csv" | cut -d, -f2)
    check "step $step: the branch did not reach 12.6 Hz ($last), and says so" \
      awk_true "($last - 12.6) ^ 2 > 1e-20"
  fi
done

# `to` at the branch's start: bad input, at once, naming file, line and key.
study to_equals_start 'parameter = "freq_hz"' 'to = 12.0'
start=$(date +%s)
"$bin" run "$scratch/to_equals_start.toml" -o "$scratch/to_equals_start" \
  > "$scratch/to_equals_start.log" 2>&1
rc=$?
check "to = start (freq): exit 2 ($rc)" test $rc -eq 2
check "to = start (freq): names file, line and key" \
  grep -q "to_equals_start.toml:[0-9]*:.*continuation.to" "$scratch/to_equals_start.log"
check "to = start (freq): before any computation" test $(( $(date +%s) - start )) -le 2
check "to = start (freq): no output folder" test ! -e "$scratch/to_equals_start/summary.json"
study cg_to_zero 'parameter = "cg_shift_m"' 'to = 0.0'
"$bin" run "$scratch/cg_to_zero.toml" -o "$scratch/cg_to_zero" > "$scratch/cg_to_zero.log" 2>&1
rc=$?
check "to = start (CG shift 0): exit 2 ($rc)" test $rc -eq 2
check "to = start (CG shift 0): names file, line and key" \
  grep -q "cg_to_zero.toml:[0-9]*:.*continuation.to" "$scratch/cg_to_zero.log"
exit $fail
