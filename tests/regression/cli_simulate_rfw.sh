#!/usr/bin/env bash
# CLI and output contract of `ornithopter simulate` (docs/design.md 3, 4) on the paper's RFW
# wind-tunnel case (issue acceptance 2): contracted files, names and units rows, the physics of
# paper Fig. 2 read back from summary.json, exit codes.
#   usage: bash cli_simulate_rfw.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"

check "--version prints the version" bash -c "'$bin' --version | grep -q '^ornithopter [0-9]'"
check "--help lists the subcommands" bash -c "'$bin' --help | grep -q simulate"
for sub in simulate run modes aeromap trim optimize plot; do
  check "$sub --help exits 0" "$bin" "$sub" --help
done

out0="$scratch/theta0"; out20="$scratch/theta20"
check "simulate theta 0 exits 0" "$bin" simulate "$root/studies/vehicles/rfw_tunnel.toml" \
  --mode tethered --speed 6 --freq 4 --theta 0 --cycles 10 -o "$out0"
check "simulate theta 20 exits 0" "$bin" simulate "$root/studies/vehicles/rfw_tunnel.toml" \
  --mode tethered --speed 6 --freq 4 --theta 20 --cycles 10 -o "$out20"
for f in summary.json study.resolved.toml histories.csv cycles.csv loads.png loads.svg loads.gp \
         zmp.csv zmp.png zmp.svg zmp.gp; do
  check "writes $f" test -s "$out0/$f"
done
check "no temporary files left" bash -c "! ls '$out0' | grep -q tmp"
check "CSV names row" bash -c "head -1 '$out0/histories.csv' | grep -q '^t,delta_M,FV,FH,M,'"
check "CSV units row" bash -c "sed -n 2p '$out0/histories.csv' | grep -q '^s,deg,N,N,N m,'"
check "1001 samples (10 cycles x 100 + 1)" bash -c "[ \$(( \$(wc -l < '$out0/histories.csv') - 2 )) -eq 1001 ]"
check "no NaN in the tables" bash -c "! grep -qi nan '$out0/histories.csv' '$out0/cycles.csv'"
for key in kind status message wall_time_s version mode cycles FV_N FH_N M_Nm power_W; do
  check "summary has $key" grep -q "\"$key\":" "$out0/summary.json"
done
check "status ok" test "$(json "$out0/summary.json" status)" = ok
fv0=$(json "$out0/summary.json" FV_N)
amp0=$(json "$out0/summary.json" FV_amplitude_1f_N)
check "theta 0: |mean FV| < 1 % of its amplitude ($fv0 vs $amp0)" awk_true "($fv0) * ($fv0) < (0.01 * $amp0) * (0.01 * $amp0)"
fv2=$(json "$out0/summary.json" FV_amplitude_2f_N)
check "theta 0: FV oscillates at f (1f $amp0 >> 2f $fv2)" awk_true "$amp0 > 5 * $fv2"
peak=$(json "$out0/summary.json" FV_peak_phase)
check "theta 0: FV peaks in the downstroke (phase $peak in (0.25, 0.75))" awk_true "$peak > 0.25 && $peak < 0.75"
fh1=$(json "$out0/summary.json" FH_amplitude_1f_N); fh2=$(json "$out0/summary.json" FH_amplitude_2f_N)
check "theta 0: FH dominated by 2f ($fh2 vs 1f $fh1)" awk_true "$fh2 > 3 * $fh1"
fv20=$(json "$out20/summary.json" FV_N)
check "theta 20: mean FV positive ($fv20)" awk_true "$fv20 > 0"
sc=$(json "$out0/summary.json" steady_state_cycle)
check "periodic steady state detected (cycle $sc)" awk_true "$sc >= 2 && $sc <= 10"

# Study files and plot.
check "run the example study" "$bin" run "$root/studies/examples/rfw_theta20.toml" -o "$scratch/example"
check "resolved study re-runs" "$bin" run "$scratch/example/study.resolved.toml" -o "$scratch/resolved"
check "resolved study is a fixed point" cmp -s "$scratch/example/study.resolved.toml" "$scratch/resolved/study.resolved.toml"
check "plot redraws a run" "$bin" plot "$out0"
check "same inputs give the same histories" bash -c "'$bin' simulate '$root/studies/vehicles/rfw_tunnel.toml' --theta 0 -o '$scratch/again' >/dev/null && cmp -s '$out0/histories.csv' '$scratch/again/histories.csv'"

# Exit codes.
"$bin" simulate "$root/studies/vehicles/rfw_tunnel.toml" --speed -3 -o "$scratch/bad" 2>/dev/null
check "bad option value exits 2" test $? -eq 2
"$bin" simulate "$scratch/does_not_exist.toml" -o "$scratch/bad" 2>/dev/null
check "missing file exits 2" test $? -eq 2
# Free flight (issue 4 acceptance 3): an untrimmed case (tail angle 0) finishes with exit code 0
# and a verdict that is not bounded (or diverged), with a reason, and no NaN in any output.
"$bin" simulate "$root/studies/vehicles/efw_magpie.toml" --mode free --tail 0 --cycles 30 \
    -o "$scratch/free" >/dev/null
free_rc=$?
check "untrimmed free flight exits 0" test "$free_rc" -eq 0
check "untrimmed free flight is not bounded, with a reason" bash -c "grep -q '\"bounded\": false' '$scratch/free/summary.json' && grep -Eq '\"status\": \"diverged\"|\"message\": \".*not bounded' '$scratch/free/summary.json' && grep -Eq '\"message\": \".{20,}' '$scratch/free/summary.json'"
check "free-flight outputs have no NaN" bash -c "! grep -qi 'nan' '$scratch/free/histories.csv' '$scratch/free/summary.json'"
check "free-flight figures drawn" test -s "$scratch/free/flight.png"
exit $fail
