#!/usr/bin/env bash
# CLI and output contract of `kind = "sensitivity"` studies (docs/design.md 3-6) on a cheap case:
# a frozen rigid-wing magpie, two parameters (5 points), short free flights. The files, names and
# units rows, the row order (base, then each parameter low and high), statuses and empty cells
# (never NaN), summary keys, tornado.csv ranked by swing, the figures that `plot` redraws, exit 2
# for a bad range, and a -j 2 run killed (kill -9) in the middle and resumed that gives the same
# bytes as the -j 1 run without recomputing the journaled points. (Two runs, not three: the 15
# figures of a run take most of the time.)
#   usage: bash cli_sensitivity.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
no_nan() { ! grep -qiE '(^|,)-?(nan|inf)(,|$)' "$1"; }
root=$(cd "$root" && pwd)
# A frozen rigid-wing magpie (see its header): it trims cheaply, and its suction efficiency 0.5
# does not trim, which gives a not_converged row.
fixture="$root/tests/data/sensitivity/magpie_rigid_fixture.toml"

cat > "$scratch/sens.toml" <<TOML
kind = "sensitivity"
vehicle = "$fixture"

[sensitivity]
free_flight_cycles = 24
parameters = [
  { key = "body.pitch_inertia_kgm2", low = 1e-4, high = 3.2e-4 },
  { key = "aero.suction_efficiency", low = 0.5, high = 1.0 },
]

[trim]
freq_hz = 12.0
initial = { theta_mean_deg = 10.0, speed_mps = 10.0, tail_angle_deg = 10.0 }
refine_in_free_flight = false
TOML
a="$scratch/j1"
check "sensitivity -j 1 exits 0" "$bin" run "$scratch/sens.toml" -j 1 -o "$a"
for f in sensitivity.csv tornado.csv summary.json study.resolved.toml \
         tornado_theta_mean_deg.png tornado_theta_mean_deg.svg tornado_theta_mean_deg.gp \
         tornado_hinge_power_W.png tornado_CM_CG_max.png tornado_altitude_p2p_slow_m.png \
         sensitivity_overview.png sensitivity_overview.svg; do
  check "writes $f" test -s "$a/$f"
done
check "no journal or temporary file left" bash -c "! ls '$a' | grep -q -e journal -e tmp"

csv="$a/sensitivity.csv"
check "CSV names row" bash -c "head -1 '$csv' | grep -q '^point,parameter,side,value,value_unit,status,theta_mean_deg,speed_mps,tail_angle_deg,hinge_power_W,pitch_swing_deg,altitude_p2p_m,altitude_p2p_slow_m,norm_ratio_max,CF_V_min,CF_V_max,CF_H_min,CF_H_max,CM_CG_min,CM_CG_max,power_aero_W,hinge_power_eq4_W,bounded,theta_min_deg,theta_max_deg,climb_rate_mps,message$'"
check "CSV units row" bash -c "sed -n 2p '$csv' | grep -q '^-,-,-,value_unit,-,-,deg,m/s,deg,W,deg,m,m,-,-,-,-,-,-,-,W,W,-,deg,deg,m/s,-$'"
check "5 rows after the two header rows" test "$(( $(wc -l < "$csv") - 2 ))" -eq 5
check "row order: base, then each parameter low and high" test \
  "$(tail -n +3 "$csv" | cut -d, -f1-5 | tr '\n' ' ')" = \
  "0,,base,, 1,body.pitch_inertia_kgm2,low,1e-04,kg m^2 2,body.pitch_inertia_kgm2,high,0.00032,kg m^2 3,aero.suction_efficiency,low,0.5,- 4,aero.suction_efficiency,high,1,- "
check "every status is a known word" bash -c "tail -n +3 '$csv' | cut -d, -f6 | grep -qvE '^(ok|not_converged|diverged|failed)$' && exit 1 || exit 0"
check "no NaN in sensitivity.csv" no_nan "$csv"
check "no NaN in tornado.csv" no_nan "$a/tornado.csv"
# A point that is ok has every prediction; one that is not ok has empty cells where it lacks them.
check "ok rows fill the 14 predictions" bash -c "tail -n +3 '$csv' | awk -F, '\$6 == \"ok\" { for (c = 7; c <= 20; ++c) if (\$c == \"\") exit 1 }'"
check "the base trims (ok)" test "$(sed -n 3p "$csv" | cut -d, -f6)" = ok
check "a point without a trim: not_converged, every result cell empty, a reason" bash -c \
  "sed -n 6p '$csv' | awk -F, '\$6 != \"not_converged\" || \$0 !~ /trim: / { exit 1 }
     { for (c = 7; c <= 26; ++c) if (\$c != \"\") exit 1 }'"
check "its tornado bars say so" grep -q 'no value at low: see sensitivity.csv' "$a/tornado_theta_mean_deg.gp"

# tornado.csv: 14 predictions x 2 parameters, ranked by swing within each prediction.
t="$a/tornado.csv"
check "tornado names row" bash -c "head -1 '$t' | grep -q '^prediction,prediction_unit,prediction_index,rank,parameter,parameter_index,label,base,low_value,high_value,delta_low,delta_high,swing,swing_share$'"
check "tornado has 28 rows" test "$(( $(wc -l < "$t") - 2 ))" -eq 28
check "ranks decrease in swing" bash -c "tail -n +3 '$t' | awk -F, '{ if (\$4 == 2 && prev != \"\" && \$13 != \"\" && \$13 > prev + 0) exit 1; prev = \$13 }'"
check "a swing is |high - low|" bash -c "tail -n +3 '$t' | awk -F, '\$13 != \"\" { d = \$10 - \$9; if (d < 0) d = -d; if (d - \$13 > 1e-12 * (d + 1) || \$13 - d > 1e-12 * (d + 1)) exit 1 }'"

s="$a/summary.json"
for key in kind status message wall_time_s version points points_ok points_not_converged \
           points_diverged points_failed parameters base predictions ranking effects \
           base_inside_range free_flight_cycles; do
  check "summary has $key" grep -q "\"$key\":" "$s"
done
check "summary kind sensitivity" test "$(json "$s" kind)" = sensitivity
check "summary points 5" test "$(json "$s" points)" = 5
check "resolved study is a sensitivity study" grep -q '^kind = "sensitivity"' "$a/study.resolved.toml"
check "plot redraws 15 figures" bash -c "'$bin' plot '$a' | grep -q 'redrew 15 figure'"
echo "info base: $(sed -n 3p "$csv" | cut -d, -f6-10)"

# A bad range: exit 2, the message names the file, line and key.
sed 's/low = 0.5, high = 1.0/low = 0.5, high = 1.5/' "$scratch/sens.toml" > "$scratch/bad_range.toml"
"$bin" run "$scratch/bad_range.toml" -o "$scratch/bad" > /dev/null 2> "$scratch/bad.txt"
check "bad range exits 2" test $? -eq 2
check "... naming file, line and key" grep -q "bad_range.toml:8: key 'sensitivity.parameters\[1\].high'" "$scratch/bad.txt"
check "bad input writes nothing" test ! -e "$scratch/bad"

# -j 2, killed (kill -9) after two journaled points, then resumed with -j 2: the same bytes as the
# uninterrupted -j 1 run.
killed="$scratch/killed"
"$bin" run "$scratch/sens.toml" -j 2 -o "$killed" > /dev/null 2>&1 &
pid=$!
journal="$killed/sensitivity.journal"
for _ in $(seq 1 3000); do  # up to 30 s for 2 journaled points
  if [ -f "$journal" ] && [ "$(wc -l < "$journal")" -ge 3 ]; then break; fi
  if ! kill -0 "$pid" 2>/dev/null; then break; fi
  sleep 0.01
done
kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
if [ -f "$journal" ]; then
  lines=$(( $(wc -l < "$journal") - 1 ))
  echo "info killed with $lines journaled points"
  printf '0123456789abcdef 4,ok,1.5' >> "$journal"   # a torn last write
  check "resume after kill -9 exits 0" "$bin" run "$scratch/sens.toml" -j 2 -o "$killed"
  check "resumed points were not recomputed ($lines)" test "$(json "$killed/summary.json" points_resumed)" -eq "$lines"
  check "journal removed after the resume" test ! -e "$journal"
else
  echo "info the -j 2 run finished before it could be killed: compared without a resume"
fi
for f in sensitivity.csv tornado.csv study.resolved.toml; do
  check "$f identical for -j 1 and for -j 2 (killed and resumed)" cmp "$a/$f" "$killed/$f"
done
meta='"(wall_time_s|threads|version|points_computed|points_resumed)":'
check "summary.json identical but the run metadata" \
  cmp <(grep -vE "$meta" "$a/summary.json") <(grep -vE "$meta" "$killed/summary.json")
exit $fail
