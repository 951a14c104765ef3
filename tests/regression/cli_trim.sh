#!/usr/bin/env bash
# CLI and output contract of `ornithopter trim` and `kind = "trim"` studies (docs/design.md 3-5):
# the contracted summary keys, status ok or not_converged with exit 0, the CSV names and units rows,
# the resolved study as a fixed point, the figure, exit codes for bad input.
#   usage: bash cli_trim.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)  # absolute: the study file below names the vehicle from $scratch
efw="$root/studies/vehicles/efw_magpie.toml"

check "trim --help exits 0" bash -c "'$bin' trim --help > /dev/null"
check "trim --help documents --unknowns" bash -c "'$bin' trim --help | grep -q -- --unknowns"

# The paper's vehicle at the Table 3 frequency.
out="$scratch/efw12"
"$bin" trim "$efw" --freq 12 -o "$out" > "$scratch/efw12.log" 2>&1
check "trim efw_magpie --freq 12 exits 0" test $? -eq 0
for f in summary.json study.resolved.toml trim_iterations.csv trim_progress.csv \
         trim_convergence.png trim_convergence.svg trim_convergence.gp; do
  check "writes $f" test -s "$out/$f"
done
check "no temporary files left" bash -c "! ls '$out' | grep -q tmp"
for key in kind status message wall_time_s version converged freq_hz theta_mean_deg speed_mps \
           tail_angle_deg residual FV_N FH_N M_Nm free_flight bounded norm_ratio_max \
           theta_min_deg theta_max_deg altitude_p2p_m dominant_freq_hz iterations evaluations; do
  check "summary has $key" grep -q "\"$key\":" "$out/summary.json"
done
check "kind is trim" test "$(json "$out/summary.json" kind)" = trim
status=$(json "$out/summary.json" status)
check "status ok or not_converged ($status)" bash -c "[ '$status' = ok ] || [ '$status' = not_converged ]"
converged=$(json "$out/summary.json" converged)
expected_converged=false; [ "$status" = ok ] && expected_converged=true
check "converged agrees with status ($converged)" test "$converged" = "$expected_converged"
check "a non-empty message" grep -q '"message": "[^"]' "$out/summary.json"
check "freq_hz is 12" awk_true "$(json "$out/summary.json" freq_hz) == 12"
check "CSV names row" bash -c "head -1 '$out/trim_iterations.csv' | grep -q '^evaluation,iteration,purpose,ok,cycles,theta_mean,speed,tail_angle,freq,FV_mean,FH_mean,M_mean,residual_FV,residual_FH,residual_M,'"
check "CSV units row" bash -c "sed -n 2p '$out/trim_iterations.csv' | grep -q '^-,-,0=residual 1=derivative,-,-,deg,m/s,deg,Hz,N,N,N m,N,N,N m,'"
runs=$(( $(wc -l < "$out/trim_iterations.csv") - 2 ))
check "one CSV row per periodic run ($runs)" test "$runs" -eq "$(json "$out/summary.json" evaluations)"
check "progress CSV units row" bash -c "sed -n 2p '$out/trim_progress.csv' | grep -q '^-,-,deg,m/s,deg,Hz,'"
check "no NaN in the tables" bash -c "! grep -qi nan '$out/trim_iterations.csv' '$out/trim_progress.csv'"
check "resolved study re-runs" "$bin" run "$out/study.resolved.toml" -o "$scratch/resolved"
check "resolved study is a fixed point" cmp -s "$out/study.resolved.toml" "$scratch/resolved/study.resolved.toml"
check "same inputs give the same evaluations" cmp -s "$out/trim_iterations.csv" "$scratch/resolved/trim_iterations.csv"
check "plot redraws the convergence figure" "$bin" plot "$out"

# Regression on the committed prediction (results/paper/trim_magpie): the 12 Hz trim of the honest
# vehicle (issue 13) is theta 13.56 +- 0.1 deg, U 18.02 +- 0.05 m/s, tail 16.59 +- 0.1 deg (the
# periodic orbit of `trim --method periodic`; measured 13.562, 18.017, 16.588; 16.21, 16.50, 19.74
# before the strip loads went on at the quarter chord as a flat plate's nodal loads; 16.35, 16.32,
# 19.98 before the refinement's free flights were flown until settled), with the Eq. (4) residuals below 1e-4 of the weight, and its
# free flight is bounded. It is not the paper's Table 3 point (theta 9.2 deg, U 10.8 m/s, tail
# 11.85 deg): results/README.md says why.
status12=$(json "$out/summary.json" status)
check "12 Hz trim converges ($status12)" test "$status12" = ok
theta=$(json "$out/summary.json" theta_mean_deg); speed=$(json "$out/summary.json" speed_mps)
tail=$(json "$out/summary.json" tail_angle_deg)
check "theta $theta = 13.56 +- 0.1 deg" awk_true "($theta - 13.56) ^ 2 <= 0.01"
check "U $speed = 18.02 +- 0.05 m/s" awk_true "($speed - 18.02) ^ 2 <= 0.0025"
check "tail $tail = 16.59 +- 0.1 deg" awk_true "($tail - 16.59) ^ 2 <= 0.01"
fv=$(json "$out/summary.json" FV_N); w=$(json "$out/summary.json" weight_N)
check "12 Hz residual |FV - W| = |$fv| < 1e-4 W" awk_true "($fv) * ($fv) < (1e-4 * $w) * (1e-4 * $w)"
check "12 Hz trim flies bounded" grep -q '"status": "bounded"' "$out/summary.json"
cat > "$scratch/heavy.toml" <<EOF
kind = "trim"
name = "heavy"
vehicle = "$efw"
[override]
body.mass_kg = 10.0
[trim]
freq_hz = 12.0
EOF
"$bin" run "$scratch/heavy.toml" -o "$scratch/heavy" > /dev/null 2>&1
check "impossible trim (10 kg) exits 0" test $? -eq 0
check "impossible trim is not_converged" test "$(json "$scratch/heavy/summary.json" status)" = not_converged
check "impossible trim says why" grep -q '"message": ".*tolerance' "$scratch/heavy/summary.json"

# Exit codes for bad input.
"$bin" trim "$efw" -o "$scratch/bad" 2>/dev/null
check "missing --freq exits 2" test $? -eq 2
"$bin" trim "$efw" --freq 12 --unknowns theta,sped -o "$scratch/bad" 2>/dev/null
check "bad --unknowns exits 2" test $? -eq 2
"$bin" trim "$efw" --freq 12 --theta 60 -o "$scratch/bad" 2>/dev/null
check "initial guess outside the bounds exits 2" test $? -eq 2
"$bin" trim "$root/studies/vehicles/rfw_tunnel.toml" --freq 4 -o "$scratch/bad" 2>/dev/null
check "vehicle without [body] exits 2" test $? -eq 2
exit $fail
