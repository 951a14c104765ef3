#!/usr/bin/env bash
# The README's first command (`bash .ci/setup.sh main`, issue 14 defect 12) leaves `git status`
# clean: its runs (.ci/main_run.sh) go to a git-ignored folder, never into the committed
# results/paper/, are compared with results/paper/ with the paper_results tolerances, and the
# paper-vs-ours table comes from its own run: the calibrated vehicle's trim (a fit) beside the
# honest vehicle's (the prediction).
#   usage: bash setup_main.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
root=$(cd "$root" && pwd)
build=$(cd "$(dirname "$bin")/../.." && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"

check "setup.sh has no git-restore step" bash -c "! grep -q 'git checkout' '$root/.ci/setup.sh'"
check "setup.sh main runs .ci/main_run.sh into results/main-run" \
  grep -q 'bash .ci/main_run.sh "$build_dir" results/main-run' "$root/.ci/setup.sh"
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  check "results/main-run/ is git-ignored" \
    git -C "$root" check-ignore -q results/main-run/trim_magpie/summary.json
  before=$(git -C "$root" status --porcelain -- results)
fi

bash "$root/.ci/main_run.sh" "$build" "$scratch/main-run" > "$scratch/out.txt" 2>&1
rc=$?
check "main_run.sh exits 0 ($rc)" test $rc -eq 0
check "... compares with results/paper/ and every value matches" \
  grep -q 'orni_results compare: 7 runs, .*: 0 failed' "$scratch/out.txt"
check "... says so" grep -q 'matches the committed results/paper/' "$scratch/out.txt"
check "... prints the table from its own run" \
  grep -q "ours: $scratch/main-run/table3_trim/summary.json" "$scratch/out.txt"
ours=$(grep 'mean pitch theta_MEAN' "$scratch/out.txt" | awk '{ print $(NF-1) }')
run=$(json "$scratch/main-run/table3_trim/summary.json" theta_mean_deg)
check "... with its own calibrated trim pitch ($ours against $run)" awk_true "($ours - $run)^2 < 1e-4"
ours=$(grep 'mean pitch theta_MEAN' "$scratch/out.txt" | awk '{ print $NF }')
run=$(json "$scratch/main-run/trim_magpie/summary.json" theta_mean_deg)
check "... and its own honest trim pitch ($ours against $run)" awk_true "($ours - $run)^2 < 1e-4"
check "... naming the fit a fit" grep -q 'calibrated (fit)' "$scratch/out.txt"
check "... and claiming no reproduction" bash -c "! grep -qi 'reproduced' '$scratch/out.txt'"
# The regression on the published point (issue 26): the vehicle calibrated to Table 3 (a fit, no
# prediction) trims at 12 Hz within (0.5 deg, 0.3 m/s, 0.5 deg) of Table 3 (9.2 deg, 10.8 m/s,
# 11.85 deg), and released at Table 3's point it flies bounded (Eq. 5). The Eq. 5 check released
# at its trim (the horizon covering three periods of the release's 4.2-s phugoid,
# trim/free_flight_check.hpp) reaches a verdict. At the default rel_tol 1e-4 which one depended on
# round-off (0.80 bounded on an Intel Xeon, 1.49 unbounded on an AMD EPYC, 2026-12-05; released at
# Table 3's point, 0.40 / 1.34 from two builds whose membrane iterations differ in round-off,
# 2026-12-06): these free flights were not converged in the tolerance. The check now flies the
# nonlinear wing at 1e-5 and fig6_8_free_flight_table3 at 1e-6, where the two builds agree (0.371 /
# 0.371). The verdict is compared with the committed one above (the compare step); here only that
# it was reached.
t3="$scratch/main-run/table3_trim/summary.json"
check "table3_trim converged" test "$(json "$t3" status)" = ok
th=$(json "$t3" theta_mean_deg); u=$(json "$t3" speed_mps); ta=$(json "$t3" tail_angle_deg)
check "table3_trim theta $th = 9.2 +- 0.5 deg" awk_true "($th - 9.2) ^ 2 <= 0.25"
check "table3_trim U $u = 10.8 +- 0.3 m/s" awk_true "($u - 10.8) ^ 2 <= 0.09"
check "table3_trim tail $ta = 11.85 +- 0.5 deg" awk_true "($ta - 11.85) ^ 2 <= 0.25"
check "table3_trim's free flight (Eq. 5) reached a verdict" \
  grep -Eq '"status": "(bounded|unbounded)"' <(sed -n '/"free_flight": {/,/}/p' "$t3")
check "the calibrated vehicle released at Table 3's point flies bounded" \
  grep -q '"bounded": true' "$scratch/main-run/fig6_8_free_flight_table3/summary.json"
for r in fig2_rfw_theta0 fig2_rfw_theta20 table3_trim trim_magpie fig6_8_free_flight \
         fig6_8_free_flight_table3 fig9_constrained_flight_test; do
  check "... wrote $r" test -s "$scratch/main-run/$r/summary.json"
done
if [[ -n "${before+set}" ]]; then
  check "the committed results/ are untouched (git status)" \
    test "$(git -C "$root" status --porcelain -- results)" = "$before"
fi

# A stale baseline fails the comparison (and so `setup.sh main` and cli.paper_results); two of the
# runs are enough for that (ORNI_MAIN_RUNS), the nonlinear-wing trim is not run twice.
stale="$scratch/stale_root"
mkdir -p "$stale/.ci" "$stale/results" "$stale/studies"
cp "$root/.ci/main_run.sh" "$stale/.ci/"
cp -r "$root/studies/paper" "$root/studies/vehicles" "$stale/studies/"
cp -r "$root/results/paper" "$stale/results/"
sed -i -E 's/("theta_mean_deg": )([-0-9.e]+)/\1 12.5/' "$stale/results/paper/trim_magpie/summary.json"
ORNI_MAIN_RUNS="fig2_rfw_theta0 trim_magpie" \
  bash "$stale/.ci/main_run.sh" "$build" "$scratch/stale-run" > "$scratch/stale.txt" 2>&1
check "a stale results/paper/ makes main_run.sh exit 1" test $? -eq 1
check "... naming the value" grep -q 'FAIL .*trim_magpie/summary.json' "$scratch/stale.txt"

exit $fail
