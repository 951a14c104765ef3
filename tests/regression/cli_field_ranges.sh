#!/usr/bin/env bash
# One range per key, wherever it is set (issue 14 defects 5 and 8, issue 15): the command line
# checks its options against the same field-table entries as the files, and every message prints
# the range that is checked and the value as the user wrote it (never "200.000000", never the
# int32 range). The extreme values of defect 5 are rejected with exit 2 before any work, from a
# file (tests/data/bad/extreme_*.toml, study_extreme_*.toml: the message quotes the file's text)
# and from the command line. `ornithopter keys` prints the table.
#   usage: bash cli_field_ranges.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
rfw="$root/studies/vehicles/rfw_tunnel.toml"
efw="$root/studies/vehicles/efw_magpie.toml"
bad="$root/tests/data/bad"
cd "$scratch" || exit 1

# expect2 "what" "message" args...: exit 2 at once, the message on stderr, no output folder.
expect2() {
  local what=$1 pattern=$2; shift 2
  "$bin" "$@" -o "$scratch/out" >"$scratch/out.txt" 2>"$scratch/err.txt"
  local rc=$?
  check "$what exits 2 ($rc)" test $rc -eq 2
  check "... says: $pattern" grep -qF -- "$pattern" "$scratch/err.txt"
  check "... prints no C-style number" bash -c "! grep -qE '[0-9]\.[0-9]{6}\b|2147483647' '$scratch/err.txt'"
  check "... writes nothing" test ! -e "$scratch/out"
  [[ $fail -eq 0 ]] || cat "$scratch/err.txt"
}

# Defect 8: the range printed is the range checked, the value as given.
expect2 "--freq 250" "option --freq: expected a number in [0.01, 200] (key simulate.freq_hz), got '250'" \
  simulate "$rfw" --freq 250
expect2 "--speed 1000" "option --speed: expected a number in [0.001, 100] (key simulate.speed_mps), got '1000'" \
  simulate "$rfw" --speed 1000
expect2 "--speed 1e6" "got '1e6'" simulate "$rfw" --speed 1e6
expect2 "--speed fast" "expected a number in [0.001, 100] (key simulate.speed_mps), got 'fast'" simulate "$rfw" --speed fast
expect2 "--theta 90" "expected a number in (-90, 90) (key simulate.theta_deg), got '90'" \
  simulate "$rfw" --theta 90
expect2 "--cycles 0" "option --cycles: expected an integer in [1, 100000] (key simulate.cycles), got '0'" \
  simulate "$rfw" --cycles 0
expect2 "--cycles 1.5" "(key simulate.cycles), got '1.5'" simulate "$rfw" --cycles 1.5
expect2 "trim --freq 0" "option --freq: expected a number in [0.01, 200] (key trim.freq_hz), got '0'" \
  trim "$efw" --freq 0
expect2 "trim --speed 1e6" "expected a number in [0.001, 100] (key trim.initial.speed_mps), got '1e6'" \
  trim "$efw" --freq 12 --speed 1e6
expect2 "aeromap --speed 0:1e6:3" "option --speed: expected A:B:N" \
  aeromap "$rfw" --speed 0:1e6:3 --freq 4:4:1 --theta 0:0:1
expect2 "aeromap --cycles 100001" "expected an integer in [1, 100000] (key aeromap.cycles), got '100001'" \
  aeromap "$rfw" --speed 6:6:1 --freq 4:4:1 --theta 0:0:1 --cycles 100001
expect2 "run -j 0" "option -j: expected an integer in [1, 1024] (key jobs), got '0'" \
  run "$root/studies/examples/rfw_theta20.toml" -j 0

# 200 Hz is inside [0.01, 200]: accepted, as the message says.
"$bin" simulate "$rfw" --freq 200 --cycles 1 -o "$scratch/f200" >/dev/null 2>"$scratch/err.txt"
rc=$?
check "--freq 200 is accepted ($rc)" test $rc -eq 0

# Defect 5 from files: exit 2, the key, its range and the value as written in the file.
expect_file() {
  local file=$1 pattern=$2 command=$3
  "$bin" "$command" "$bad/$file" -o "$scratch/out" >"$scratch/out.txt" 2>"$scratch/err.txt"
  local rc=$?
  check "$file exits 2 ($rc)" test $rc -eq 2
  check "... says: $pattern" grep -qF -- "$pattern" "$scratch/err.txt"
  [[ $fail -eq 0 ]] || cat "$scratch/err.txt"
}
expect_file extreme_semispan_1e308.toml \
  "key 'wing.semispan_m': expected a number in [0.005, 20], got 1e308" simulate
expect_file extreme_youngs_modulus_1e300.toml \
  "key 'materials.FILM.youngs_modulus_gpa': expected a number in [1e-4, 1200], got 1e300" simulate
expect_file extreme_element_size_1e-4.toml \
  "key 'wing.fe.element_size_m': expected a number in [0.001, 20], got 1e-4" simulate
expect_file study_extreme_override_element_size.toml \
  "key 'override.wing.fe.element_size_m': expected a number in [0.001, 20], got 6e-4" run
expect_file study_extreme_override_mesh_nodes.toml "at most 50000 mesh nodes" run
expect_file study_extreme_sweep_semispan.toml "(the range of wing.semispan_m), got 1e6 at index 1" run
expect_file study_extreme_simulate_speed.toml \
  "key 'simulate.speed_mps': expected a number in [0.001, 100], got 1e6" run
expect_file study_extreme_simulate_tolerance.toml \
  "key 'simulate.rel_tol': expected a number in [1e-12, 0.01], got 1e-300" run
# The same in `modes` (which meshes a rigid wing too).
printf 'kind = "modes"\nvehicle = "%s"\n[override]\nwing.fe.element_size_m = 6e-4\n' "$efw" \
  > "$scratch/modes.toml"
"$bin" run "$scratch/modes.toml" -o "$scratch/out" >/dev/null 2>"$scratch/err.txt"
rc=$?
check "modes with a 0.6 mm mesh exits 2 ($rc)" test $rc -eq 2
check "... naming override.wing.fe.element_size_m" grep -qF "override.wing.fe.element_size_m" \
  "$scratch/err.txt"

# ornithopter keys: the table.
"$bin" keys vehicle >"$scratch/keys.txt" 2>&1
check "keys vehicle exits 0" test $? -eq 0
check "... lists wing.semispan_m with unit and range" \
  grep -qE '^wing\.semispan_m +m +\[0\.005, 20\] +required' "$scratch/keys.txt"
check "... lists every vehicle group's key" grep -qE '^operating_point\.freq_hz +Hz +\[0\.01, 200\]' \
  "$scratch/keys.txt"
"$bin" keys vehicl >"$scratch/out.txt" 2>"$scratch/err.txt"
check "keys vehicl exits 2" test $? -eq 2
check "... suggests vehicle" grep -qF "did you mean 'vehicle'?" "$scratch/err.txt"

# ornithopter keys --outputs: the output table (output_schema.hpp), all of it or one run kind's.
"$bin" keys --outputs trim >"$scratch/outputs.txt" 2>&1
check "keys --outputs trim exits 0" test $? -eq 0
check "... lists trim's summary values with unit and meaning" \
  grep -qE '^theta_mean_deg +deg +[a-z,]*trim[a-z,]* +.*pitch' "$scratch/outputs.txt"
check "... and only what trim writes" bash -c "! grep -qF '[aeromap.csv]' '$scratch/outputs.txt'"
"$bin" keys --outputs >"$scratch/outputs_all.txt" 2>&1
check "keys --outputs lists every CSV the runs write" grep -qF '[aeromap.csv]' "$scratch/outputs_all.txt"
# The wing's modes (a kind the paper studies do not run): its outputs are in the table.
"$bin" modes "$root/studies/vehicles/efw_magpie.toml" -o "$scratch/modes" --no-figures >/dev/null 2>&1
check "modes exits 0" test $? -eq 0
"$bin" keys --outputs --check "$scratch/modes" >"$scratch/modes_check.txt" 2>&1
check "keys --outputs --check: every value and column of modes described" test $? -eq 0
grep -v ' 0 findings$' "$scratch/modes_check.txt" | head -20
# ... and the check finds an undescribed value.
sed 's/"kind": "modes",/"kind": "modes", "no_such_value": 1,/' "$scratch/modes/summary.json" \
  >"$scratch/modes/summary.json.new" && mv "$scratch/modes/summary.json.new" "$scratch/modes/summary.json"
"$bin" keys --outputs --check "$scratch/modes" >"$scratch/modes_check.txt" 2>&1
check "keys --outputs --check exits 1 on an undescribed value" test $? -eq 1
check "... naming it" grep -qF "summary.json no_such_value: not in the output table" "$scratch/modes_check.txt"
"$bin" keys --outputs trm >"$scratch/out.txt" 2>"$scratch/err.txt"
check "keys --outputs trm exits 2" test $? -eq 2
check "... suggests trim" grep -qF "did you mean 'trim'?" "$scratch/err.txt"

exit $fail
