#!/usr/bin/env bash
# CLI and output contract of `kind = "sweep"` studies (docs/design.md 3-6): the files, names and
# units rows, row order (first axis outermost), summary keys, byte-identical sweep.csv for -j 1
# and -j 2 and for the resolved study, the figure that `plot` redraws, a free-flight sweep, exit 2
# for a bad axis, the trim example over 10..16 Hz (status ok or not_converged per point, never
# NaN), and a kill -9 in the middle of a sweep followed by a resume that gives the same bytes.
#   usage: bash cli_sweep.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
no_nan() { ! grep -qiE '(^|,)-?(nan|inf)(,|$)' "$1"; }
root=$(cd "$root" && pwd)
rfw="$root/studies/vehicles/rfw_tunnel.toml"
efw="$root/studies/vehicles/efw_magpie.toml"

# The rigid RFW rig, tethered: pitch (analysis key) x flapping amplitude (vehicle key), 3 x 2.
cat > "$scratch/rig.toml" <<TOML
kind = "sweep"
vehicle = "$rfw"

[sweep]
run = "simulate"
axes = [
  { key = "simulate.theta_deg", values = "0:20:3" },
  { key = "kinematics.amplitude_deg", values = [25, 30] },
]

[simulate]
cycles = 3
TOML
a="$scratch/j1"; b="$scratch/j2"
check "rig sweep -j 1 exits 0" "$bin" run "$scratch/rig.toml" -j 1 -o "$a"
check "rig sweep -j 2 exits 0" "$bin" run "$scratch/rig.toml" -j 2 -o "$b"
check "sweep.csv identical for -j 1 and -j 2" cmp "$a/sweep.csv" "$b/sweep.csv"
for f in sweep.csv summary.json study.resolved.toml sweep.png sweep.svg sweep.gp; do
  check "writes $f" test -s "$a/$f"
done
check "no journal or temporary file left" bash -c "! ls '$a' | grep -q -e journal -e tmp"
check "CSV names row" bash -c "head -1 '$a/sweep.csv' | grep -q '^simulate.theta_deg,kinematics.amplitude_deg,status,FV_mean_N,FH_mean_N,M_mean_Nm,power_aero_W,'"
check "CSV units row" bash -c "sed -n 2p '$a/sweep.csv' | grep -q '^deg,deg,-,N,N,N m,W,'"
check "6 rows after the two header rows" test "$(( $(wc -l < "$a/sweep.csv") - 2 ))" -eq 6
check "first row is the first point" bash -c "sed -n 3p '$a/sweep.csv' | grep -q '^0,25,'"
check "the last axis varies fastest" bash -c "sed -n 4p '$a/sweep.csv' | grep -q '^0,30,'"
check "last row is the last point" bash -c "tail -1 '$a/sweep.csv' | grep -q '^20,30,'"
check "no NaN in the table" no_nan "$a/sweep.csv"
for key in kind status message wall_time_s version run mode points points_ok points_not_converged \
           points_diverged points_failed axes; do
  check "summary has $key" grep -q "\"$key\":" "$a/summary.json"
done
check "summary kind sweep" test "$(json "$a/summary.json" kind)" = sweep
check "summary points 6" test "$(json "$a/summary.json" points)" = 6
check "resolved study is a sweep" grep -q '^kind = "sweep"' "$a/study.resolved.toml"
check "resolved study re-runs" "$bin" run "$a/study.resolved.toml" -j 2 -o "$scratch/resolved"
check "resolved study gives the same bytes" cmp "$a/sweep.csv" "$scratch/resolved/sweep.csv"
check "resolved study is a fixed point" cmp "$a/study.resolved.toml" "$scratch/resolved/study.resolved.toml"
check "plot redraws the figure" bash -c "'$bin' plot '$a' | grep -q 'redrew 1 figure'"

# Free flight: the bounded-norm columns.
cat > "$scratch/free.toml" <<TOML
kind = "sweep"
vehicle = "$efw"
[sweep]
run = "simulate"
axes = [{ key = "simulate.tail_angle_deg", values = [11.85, 20] }]
[simulate]
mode = "free"
cycles = 20
TOML
check "free-flight sweep exits 0" "$bin" run "$scratch/free.toml" -j 2 -o "$scratch/free"
check "free-flight columns" bash -c "head -1 '$scratch/free/sweep.csv' | grep -q ',cycles_run,bounded,norm_ratio_max,theta_min_deg,theta_max_deg,altitude_p2p_m,dominant_freq_hz,message$'"
# The paper sweeps only trims: the tethered and free simulate columns are checked here.
"$bin" keys --outputs --check "$a" "$scratch/free" > "$scratch/outputs_check.txt" 2>&1
check "keys --outputs --check: every value and column of the simulate sweeps described" \
  test $? -eq 0
grep -v ' 0 findings$' "$scratch/outputs_check.txt" | head -20
check "free-flight summary mode free" test "$(json "$scratch/free/summary.json" mode)" = free
check "free-flight summary counts bounded points" grep -q '"points_bounded":' "$scratch/free/summary.json"
check "no NaN in the free-flight table" no_nan "$scratch/free/sweep.csv"

# A bad axis: exit 2, the message names the file, line and key.
sed 's/kinematics.amplitude_deg/kinematics.amplitude_dg/' "$scratch/rig.toml" > "$scratch/bad_axis.toml"
"$bin" run "$scratch/bad_axis.toml" -o "$scratch/bad" > /dev/null 2> "$scratch/bad.txt"
check "bad axis key exits 2" test $? -eq 2
check "... naming file, line and key" grep -q "bad_axis.toml:8: key 'sweep.axes\[1\].key'" "$scratch/bad.txt"
check "... with a suggestion" grep -q "did you mean 'amplitude_deg'" "$scratch/bad.txt"
check "bad input writes nothing" test ! -e "$scratch/bad"

# The trim example over 10..16 Hz (issue 5): one row per frequency, each ok or not_converged with
# its reason, exit 0 whatever the verdicts (the vehicle's calibration decides which converge).
ex="$scratch/trim_sweep_freq"
check "trim sweep example exits 0" "$bin" run "$root/studies/examples/trim_sweep_freq.toml" -j 2 -o "$ex"
check "7 frequencies" test "$(( $(wc -l < "$ex/sweep.csv") - 2 ))" -eq 7
check "frequencies 10..16 Hz in order" test "$(tail -n +3 "$ex/sweep.csv" | cut -d, -f1 | tr '\n' ' ')" = "10 11 12 13 14 15 16 "
check "every point ok or not_converged" bash -c "tail -n +3 '$ex/sweep.csv' | cut -d, -f2 | grep -qvE '^(ok|not_converged)$' && exit 1 || exit 0"
check "no NaN in the trim sweep" no_nan "$ex/sweep.csv"
check "trim sweep summary counts" test "$(( $(json "$ex/summary.json" points_ok) + $(json "$ex/summary.json" points_not_converged) ))" -eq 7
echo "info trim sweep: $(json "$ex/summary.json" points_ok) of 7 frequencies trimmed, $(json "$ex/summary.json" points_bounded) bounded"

# Kill -9 in the middle of a longer sweep, then resume: the same bytes as an uninterrupted run.
cat > "$scratch/long.toml" <<TOML
kind = "sweep"
vehicle = "$rfw"
[sweep]
run = "simulate"
axes = [{ key = "simulate.theta_deg", values = "0:20:10" }, { key = "simulate.speed_mps", values = "3:8:10" }]
[simulate]
cycles = 60
TOML
ref="$scratch/long_ref"; killed="$scratch/long_killed"
check "uninterrupted 100-point sweep" "$bin" run "$scratch/long.toml" -j 2 -o "$ref"
"$bin" run "$scratch/long.toml" -j 2 -o "$killed" > /dev/null 2>&1 &
pid=$!
journal="$killed/sweep.journal"
for _ in $(seq 1 3000); do  # up to 30 s for 10 journaled points
  if [ -f "$journal" ] && [ "$(wc -l < "$journal")" -ge 11 ]; then break; fi
  if ! kill -0 "$pid" 2>/dev/null; then break; fi
  sleep 0.01
done
kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
if [ -f "$journal" ]; then
  lines=$(( $(wc -l < "$journal") - 1 ))
  echo "info killed with $lines journaled points"
  printf '0123456789abcdef 99,ok,1.5' >> "$journal"   # a torn last write
  check "resume after kill -9 exits 0" "$bin" run "$scratch/long.toml" -j 1 -o "$killed"
  check "resumed sweep is byte-identical" cmp "$ref/sweep.csv" "$killed/sweep.csv"
  check "resumed points were not recomputed ($lines)" test "$(json "$killed/summary.json" points_resumed)" -eq "$lines"
  check "journal removed after the resume" test ! -e "$journal"
else
  echo "skip kill-and-resume: the sweep finished before it could be killed"
fi
exit $fail
