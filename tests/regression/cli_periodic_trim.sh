#!/usr/bin/env bash
# CLI and output contract of the periodic-orbit trim (`ornithopter trim --method periodic`,
# [trim] method = "periodic") and `ornithopter stability` (docs/design.md 3, 4, issue 16): the
# contracted summary keys (the trim keys plus method, periodic_residual, floquet {multipliers,
# stable, max_modulus}), the CSV names and units rows, the figures, the resolved study as a fixed
# point, and exit 2 with file, line and key for bad input.
#   usage: bash cli_periodic_trim.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
efw="$root/studies/vehicles/efw_magpie.toml"

check "trim --help documents --method" bash -c "'$bin' trim --help | grep -q -- --method"
check "stability --help exits 0" bash -c "'$bin' stability --help > /dev/null"

# The magpie at 12 Hz (issue 16 acceptance).
out="$scratch/periodic12"
"$bin" trim "$efw" --freq 12 --method periodic -o "$out" > "$scratch/periodic12.log" 2>&1
check "trim --method periodic exits 0" test $? -eq 0
for f in summary.json study.resolved.toml periodic_iterations.csv periodic_orbit.csv floquet.csv \
         floquet_multipliers.png floquet_multipliers.svg floquet_multipliers.gp \
         periodic_orbit.png periodic_orbit.svg periodic_orbit.gp; do
  check "writes $f" test -s "$out/$f"
done
check "no temporary files left" bash -c "! ls -a '$out' | grep -q tmp"
for key in kind status message wall_time_s version converged freq_hz theta_mean_deg speed_mps \
           tail_angle_deg residual FV_N FH_N M_Nm free_flight bounded method periodic_residual \
           floquet multipliers modulus argument_deg stable max_modulus margin orbit_start mean \
           power_W stage1_equation4 period_maps; do
  check "summary has $key" grep -q "\"$key\":" "$out/summary.json"
done
check "kind is trim" test "$(json "$out/summary.json" kind)" = trim
check "method is periodic" test "$(json "$out/summary.json" method)" = periodic
check "status ok" test "$(json "$out/summary.json" status)" = ok
res=$(json "$out/summary.json" periodic_residual)
check "periodic_residual $res <= 1e-8" awk_true "$res <= 1e-8"
check "floquet stable" test "$(json "$out/summary.json" stable)" = true
mu=$(json "$out/summary.json" max_modulus)
check "max_modulus $mu in (0.9, 1)" awk_true "$mu > 0.9 && $mu < 1"
theta=$(json "$out/summary.json" theta_mean_deg); tail=$(json "$out/summary.json" tail_angle_deg)
check "theta $theta = 13.56 +- 0.05 deg" awk_true "($theta - 13.558) ^ 2 <= 0.0025"
check "tail $tail = 16.58 +- 0.05 deg" awk_true "($tail - 16.584) ^ 2 <= 0.0025"
check "floquet CSV names row" bash -c "head -1 '$out/floquet.csv' | grep -q '^rank,mu_real,mu_imag,modulus,argument,exponent_real,exponent_imag,damping_ratio,period,inside_unit_circle,label,dominant_states,refinement_change,resolved$'"
check "floquet CSV units row" bash -c "sed -n 2p '$out/floquet.csv' | grep -q '^-,-,-,-,deg,1/s,rad/s,-,'"
check "orbit CSV names row" bash -c "head -1 '$out/periodic_orbit.csv' | grep -q '^t,phase,delta_M,theta,U,W,Q,airspeed,x,h,FV,FH,M,power_aero$'"
check "orbit CSV has one period (201 rows)" test "$(( $(wc -l < "$out/periodic_orbit.csv") - 2 ))" -eq 201
check "no NaN in the tables" bash -c "! grep -qiw nan '$out/floquet.csv' '$out/periodic_orbit.csv' '$out/periodic_iterations.csv'"
check "resolved study says method periodic" grep -q '^method = "periodic"' "$out/study.resolved.toml"
check "resolved study re-runs" "$bin" run "$out/study.resolved.toml" -o "$scratch/resolved" > /dev/null
check "resolved study is a fixed point" cmp -s "$out/study.resolved.toml" "$scratch/resolved/study.resolved.toml"
check "same inputs give the same orbit" cmp -s "$out/periodic_orbit.csv" "$scratch/resolved/periodic_orbit.csv"
check "same inputs give the same multipliers" cmp -s "$out/floquet.csv" "$scratch/resolved/floquet.csv"
check "plot redraws the figures" "$bin" plot "$out"

# The default method keeps the two-stage outputs (no periodic keys).
cat > "$scratch/two_stage_keys.toml" <<EOF
kind = "trim"
name = "two_stage_keys"
vehicle = "$efw"
[trim]
freq_hz = 12.0
max_iterations = 1
refine_in_free_flight = false
EOF
"$bin" run "$scratch/two_stage_keys.toml" -o "$scratch/two_stage" > /dev/null 2>&1
check "two-stage trim exits 0" test $? -eq 0
check "two-stage summary has no periodic keys" bash -c "! grep -q '\"periodic_residual\"\\|\"floquet\"' '$scratch/two_stage/summary.json'"
check "two-stage resolved study has no [trim.periodic]" bash -c "! grep -q 'trim.periodic' '$scratch/two_stage/study.resolved.toml'"

# ornithopter stability: every multiplier (the full monodromy).
"$bin" stability "$efw" --freq 12 -o "$scratch/stability" > /dev/null 2>&1
check "stability exits 0" test $? -eq 0
check "stability kind" test "$(json "$scratch/stability/summary.json" kind)" = stability
check "stability lists all 106 multipliers" test "$(( $(wc -l < "$scratch/stability/floquet.csv") - 2 ))" -eq 106
check "stability: complete" grep -q '"complete": true' "$scratch/stability/summary.json"
mu_all=$(json "$scratch/stability/summary.json" max_modulus)
check "stability max_modulus $mu_all equals the trim's $mu (1e-6)" awk_true "($mu_all - $mu) ^ 2 < 1e-12"
check "stability draws the multipliers" test -s "$scratch/stability/floquet_multipliers.png"
# The multiplier check (on in stability, off in trim): the phugoid pair resolved, the tiny aero-lag
# multipliers not; the trim's rows have empty check cells.
check "stability: multipliers checked" grep -q '"checked": true' "$scratch/stability/summary.json"
check "stability: the phugoid pair is resolved" bash -c \
  "sed -n '3,4p' '$scratch/stability/floquet.csv' | awk -F, '{ if (\$NF != 1) bad = 1 } END { exit bad }'"
check "stability: the smallest multiplier is not resolved" bash -c \
  "tail -1 '$scratch/stability/floquet.csv' | grep -q ',0$'"
check "stability: the console says how many are resolved" bash -c \
  "'$bin' stability '$efw' --freq 12 -o '$scratch/stability2' --no-figures | grep -q 'resolved'"
check "trim: not checked, empty check cells" bash -c \
  "grep -q '\"checked\": false' '$out/summary.json' && sed -n 3p '$out/floquet.csv' | grep -q ',,$'"
# Their outputs are in the output table (studies/runner/output/output_schema_table.cpp).
"$bin" keys --outputs --check "$out" "$scratch/stability" > "$scratch/outputs_check.txt" 2>&1
check "keys --outputs --check: every value and column of the periodic trim and stability described" \
  test $? -eq 0
grep -v ' 0 findings$' "$scratch/outputs_check.txt" | head -20

# A vehicle far too heavy (10 kg): not_converged with the reason, exit 0, no orbit outputs, no NaN.
cat > "$scratch/heavy.toml" <<EOF
kind = "trim"
name = "heavy"
vehicle = "$efw"
[override]
body.mass_kg = 10.0
[trim]
freq_hz = 12.0
method = "periodic"
EOF
"$bin" run "$scratch/heavy.toml" -o "$scratch/heavy" > /dev/null 2>&1
check "impossible periodic trim exits 0" test $? -eq 0
check "impossible periodic trim is not_converged" test "$(json "$scratch/heavy/summary.json" status)" = not_converged
check "impossible periodic trim says why" grep -q '"message": "no Eq. (4) start' "$scratch/heavy/summary.json"
check "... periodic_residual null" test "$(json "$scratch/heavy/summary.json" periodic_residual)" = null
check "... no orbit table, no multiplier figure" bash -c "! ls '$scratch/heavy' | grep -q 'periodic_orbit.csv\\|floquet_multipliers.png'"
check "... no NaN in summary.json" bash -c "! grep -qiw nan '$scratch/heavy/summary.json'"

# Bad input: exit 2 with file, line and key.
bad() {  # name, expected text, study body lines...
  local name=$1 text=$2; shift 2
  printf 'kind = "trim"\nvehicle = "%s"\n' "$efw" > "$scratch/$name.toml"
  printf '%s\n' "$@" >> "$scratch/$name.toml"
  "$bin" run "$scratch/$name.toml" -o "$scratch/$name" > /dev/null 2> "$scratch/$name.err"
  check "$name exits 2" test $? -eq 2
  check "$name names $text" grep -q -- "$text" "$scratch/$name.err"
}
bad bad_method "bad_method.toml:4: key 'trim.method'" '[trim]' 'method = "periodc"'
bad bad_method_type "bad_method_type.toml:4: key 'trim.method'" '[trim]' 'method = 1'
bad refine_with_periodic "refine_with_periodic.toml:5: unknown key 'trim.refine_cycles'" \
    '[trim]' 'method = "periodic"' 'refine_cycles = 100'
bad periodic_without_method "unknown key 'trim.periodic'" '[trim]' 'freq_hz = 12.0' \
    '[trim.periodic]' 'control = "tail_angle_deg"'
bad bad_control "key 'trim.periodic.control'" '[trim]' 'method = "periodic"' '[trim.periodic]' \
    'control = "tail"'
bad bad_multipliers "key 'trim.periodic.multipliers'" '[trim]' 'method = "periodic"' \
    '[trim.periodic]' 'multipliers = 101'
bad bad_tolerance "key 'trim.periodic.residual_tol'" '[trim]' 'method = "periodic"' \
    '[trim.periodic]' 'residual_tol = 0.1'
"$bin" trim "$efw" --freq 12 --method periodik > /dev/null 2>&1
check "--method periodik exits 2" test $? -eq 2
"$bin" stability "$efw" --freq -3 > /dev/null 2>&1
check "stability --freq -3 exits 2" test $? -eq 2
cat > "$scratch/sweep_periodic.toml" <<EOF
kind = "sweep"
vehicle = "$efw"
[trim]
method = "periodic"
[sweep]
run = "trim"
axes = [{ key = "trim.freq_hz", values = [11.5, 12] }]
EOF
"$bin" run "$scratch/sweep_periodic.toml" -o "$scratch/sweep_periodic" > /dev/null 2> "$scratch/sweep_periodic.err"
check "a sweep of periodic trims exits 0" test $? -eq 0
check "... with the Floquet columns" bash -c "head -1 '$scratch/sweep_periodic/sweep.csv' | grep -q ',max_modulus,floquet_stable,message$'"
check "... both points ok and stable" test "$(grep -c ',ok,.*,1,' "$scratch/sweep_periodic/sweep.csv")" -eq 2
twelve=$(grep '^12,' "$scratch/sweep_periodic/sweep.csv" | cut -d, -f3)
check "... the 12 Hz row is the periodic trim's theta ($twelve = $theta)" awk_true "($twelve - $theta) ^ 2 < 1e-12"

exit $fail
