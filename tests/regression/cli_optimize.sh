#!/usr/bin/env bash
# CLI and output contract of `ornithopter optimize` and `kind = "optimize"` studies (docs/design.md
# 3-5, issue 6): a tiny optimisation (rigid magpie at 12 Hz, Eq. (4) trim only; tail area and arm; 2
# starts of 6 evaluations) writes the contracted summary keys, history.csv with names and units
# rows and one row per evaluation, the best design as a vehicle file and the convergence figure;
# history.csv is byte-identical for -j 1 and -j 2, through `run` and for the resolved study; the
# best vehicle re-runs through `ornithopter trim` with the reported objective (issue acceptance 3);
# a kill -9 followed by a resume gives the same bytes; the periodic trim with the Floquet constraint
# (docs/theory.md 10.3) reports the orbit's multipliers; bad input exits 2.
#   usage: bash cli_optimize.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
efw="$root/studies/vehicles/efw_magpie.toml"

study="$scratch/tiny.toml"
cat > "$study" <<EOF
kind = "optimize"
name = "tiny"
vehicle = "$efw"
[override]
wing.structure = "rigid"   # the machinery at a fraction of the flexible wing's cost
[optimize]
freq_hz = 12.0
max_evaluations = 6
starts = 2
variables = [
  { name = "tail.area_m2", lower = 0.004, upper = 0.012 },
  { name = "tail.arm_m", lower = 0.08, upper = 0.16 },
]
[optimize.constraints]
bounded = false   # the rigid magpie's Eq. (4) trim at 12 Hz does not fly bounded; trim only
[optimize.trim]
refine_in_free_flight = false
initial = { theta_mean_deg = 4.3, speed_mps = 13.6, tail_angle_deg = 8.4 }
EOF

check "optimize --help exits 0" bash -c "'$bin' optimize --help > /dev/null"
check "--help lists optimize" bash -c "'$bin' --help | grep -q optimize"
a="$scratch/j1"; b="$scratch/j2"
check "tiny optimisation -j 1 exits 0" "$bin" optimize "$study" -j 1 -o "$a"
check "tiny optimisation -j 2 exits 0" "$bin" optimize "$study" -j 2 -o "$b"
for f in summary.json history.csv best_vehicle.toml study.resolved.toml optimize_convergence.png \
         optimize_convergence.svg optimize_convergence.gp; do
  check "writes $f" test -s "$a/$f"
done
check "no journal or temporary file left" bash -c "! ls '$a' | grep -q -e journal -e tmp"
for f in history.csv best_vehicle.toml study.resolved.toml; do
  check "$f identical for -j 1 and -j 2" cmp "$a/$f" "$b/$f"
done
for key in kind status message wall_time_s version converged objective baseline_objective \
           evaluations design constraints_satisfied; do
  check "summary has $key" grep -q "\"$key\":" "$a/summary.json"
done
check "kind is optimize" test "$(json "$a/summary.json" kind)" = optimize
status=$(json "$a/summary.json" status)
check "status ok or not_converged ($status)" bash -c "[ '$status' = ok ] || [ '$status' = not_converged ]"
check "design names the variables" bash -c "grep -A3 '\"design\":' '$a/summary.json' | grep -q '\"tail.arm_m\":'"
check "12 evaluations" test "$(json "$a/summary.json" evaluations)" = 12
check "one history row per evaluation" test "$(( $(wc -l < "$a/history.csv") - 2 ))" -eq 12
check "history names row" bash -c "head -1 '$a/history.csv' | grep -q '^evaluation,start,start_evaluation,stage,tail.area_m2,tail.arm_m,objective,feasible,failed,violation,g_trimmed,status,'"
check "history units row" bash -c "sed -n 2p '$a/history.csv' | grep -q '^-,-,-,-,m^2,m,W,-,-,-,-,-,'"
check "no NaN in the history" bash -c "! grep -qi nan '$a/history.csv'"
check "a design satisfies the constraints" test "$(json "$a/summary.json" constraints_satisfied)" = true
obj=$(json "$a/summary.json" objective); base=$(json "$a/summary.json" baseline_objective)
check "objective $obj W <= baseline $base W" awk_true "$obj <= $base"
check "run gives the same history" bash -c "'$bin' run '$study' -o '$scratch/run' > /dev/null && cmp '$a/history.csv' '$scratch/run/history.csv'"
check "resolved study re-runs" "$bin" run "$a/study.resolved.toml" -j 2 -o "$scratch/resolved"
check "resolved study is a fixed point" cmp "$a/study.resolved.toml" "$scratch/resolved/study.resolved.toml"
check "resolved study gives the same history" cmp "$a/history.csv" "$scratch/resolved/history.csv"
check "plot redraws the convergence figure" bash -c "'$bin' plot '$a' | grep -q 'redrew 1 figure'"

# Issue acceptance 3: the best design re-runs through `ornithopter trim` with the same objective
# (the cycle-mean hinge power at its trim point; the vehicle's operating point is that trim point).
# The tiny study trims by Eq. (4) only, so the re-run does too (a [trim] study with the refinement
# off; `ornithopter trim` refines in free flight by default).
cat > "$scratch/trim_best.toml" <<EOF
kind = "trim"
vehicle = "$a/best_vehicle.toml"
[trim]
freq_hz = 12.0
refine_in_free_flight = false
EOF
"$bin" run "$scratch/trim_best.toml" -o "$scratch/trim_best" > /dev/null 2>&1
check "trim of best_vehicle.toml exits 0" test $? -eq 0
check "best vehicle trims" test "$(json "$scratch/trim_best/summary.json" status)" = ok
power=$(json "$scratch/trim_best/summary.json" hinge_power_W)
echo "info objective $obj W, trim of the best vehicle: hinge power $power W"
check "trim reproduces the objective ($power vs $obj)" awk_true "($power - $obj)^2 <= (1e-9 * $obj)^2"

# Kill -9 in the middle of a longer run, then resume: the same bytes as an uninterrupted run.
long="$scratch/long.toml"
sed -e 's/max_evaluations = 6/max_evaluations = 12/' -e 's/name = "tiny"/name = "long"/' "$study" > "$long"
check "uninterrupted longer run" "$bin" optimize "$long" -j 2 -o "$scratch/long_ref"
killed="$scratch/long_killed"
"$bin" optimize "$long" -j 2 -o "$killed" > /dev/null 2>&1 &
pid=$!
journal="$killed/optimize.journal"
for _ in $(seq 1 3000); do  # up to 30 s for 6 journaled evaluations
  if [ -f "$journal" ] && [ "$(wc -l < "$journal")" -ge 7 ]; then break; fi
  if ! kill -0 "$pid" 2>/dev/null; then break; fi
  sleep 0.01
done
kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
if [ -f "$journal" ]; then
  lines=$(( $(wc -l < "$journal") - 1 ))
  echo "info killed with $lines journaled evaluations"
  printf '0123456789abcdef 1,3,ok,0.0051' >> "$journal"   # a torn last write
  check "resume after kill -9 exits 0" "$bin" optimize "$long" -j 1 -o "$killed"
  check "resumed history is byte-identical" cmp "$scratch/long_ref/history.csv" "$killed/history.csv"
  check "resumed evaluations were replayed ($lines)" test "$(json "$killed/summary.json" evaluations_resumed)" -eq "$lines"
  check "journal removed after the resume" test ! -e "$journal"
else
  echo "skip kill-and-resume: the run finished before it could be killed"
fi

# The periodic trim and the Floquet constraint (docs/theory.md 10.3): the flexible magpie, tail area only, 3
# evaluations. The baseline design's largest multiplier is the one `trim --method periodic` reports
# for the same vehicle and frequency (the same code path: the same digits).
periodic="$scratch/periodic.toml"
cat > "$periodic" <<EOF
kind = "optimize"
name = "periodic"
vehicle = "$efw"
[optimize]
freq_hz = 12.0
max_evaluations = 3
starts = 1
variables = [ { name = "tail.area_m2", lower = 0.006, upper = 0.009 } ]
[optimize.constraints]
bounded = false
floquet_max_modulus = 0.99
[optimize.trim]
method = "periodic"
EOF
p="$scratch/periodic_out"
check "periodic-trim optimisation exits 0" "$bin" optimize "$periodic" -o "$p"
check "history.csv has g_floquet_max_modulus" bash -c "head -1 '$p/history.csv' | grep -q ',g_floquet_max_modulus,'"
check "history.csv has floquet_max_modulus, floquet_stable, periodic_residual" \
  bash -c "head -1 '$p/history.csv' | grep -q ',floquet_max_modulus,floquet_stable,periodic_residual,'"
check "resolved study keeps the method and the limit" \
  bash -c "grep -q 'method = \"periodic\"' '$p/study.resolved.toml' && grep -q 'floquet_max_modulus = 0.99' '$p/study.resolved.toml'"
"$bin" trim "$efw" --freq 12 --method periodic -o "$scratch/periodic_trim" > /dev/null 2>&1
mu_opt=$(python3 -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['baseline']['floquet_max_modulus']))" "$p/summary.json")
mu_trim=$(python3 -c "import json,sys; print(repr(json.load(open(sys.argv[1]))['floquet']['max_modulus']))" "$scratch/periodic_trim/summary.json")
check "baseline max |mu| equals trim --method periodic's ($mu_opt vs $mu_trim)" test "$mu_opt" = "$mu_trim"
g=$(python3 -c "import json,sys; d=json.load(open(sys.argv[1]))['baseline']; print(abs(d['constraints']['floquet_max_modulus'] - (d['floquet_max_modulus'] / 0.99 - 1)) < 1e-15)" "$p/summary.json")
check "g_floquet_max_modulus = max |mu| / limit - 1" test "$g" = True
sed -e 's/^method = "periodic"$//' "$periodic" > "$scratch/floquet_two_stage.toml"
"$bin" optimize "$scratch/floquet_two_stage.toml" -o "$scratch/bad" 2> "$scratch/bad.txt"
check "floquet_max_modulus with the two-stage trim exits 2" test $? -eq 2
check "... naming the key" grep -q 'optimize.constraints.floquet_max_modulus' "$scratch/bad.txt"

# Exit codes for bad input.
"$bin" optimize "$root/studies/examples/efw_trim.toml" -o "$scratch/bad" 2> "$scratch/bad.txt"
check "optimize of a trim study exits 2" test $? -eq 2
check "... and says why" grep -q 'kind \\"optimize\\"\|kind "optimize"' "$scratch/bad.txt"
"$bin" optimize "$scratch/missing.toml" -o "$scratch/bad" 2> /dev/null
check "missing study exits 2" test $? -eq 2
"$bin" optimize "$study" -j 0 -o "$scratch/bad" 2> /dev/null
check "-j 0 exits 2" test $? -eq 2
check "bad input writes nothing" test ! -e "$scratch/bad"
exit $fail
