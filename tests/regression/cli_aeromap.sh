#!/usr/bin/env bash
# CLI and output contract of `ornithopter aeromap` (docs/design.md 3, 4; paper Fig. 5): the
# files, names and units rows, summary keys, byte-identical aeromap.csv for -j 1 and -j 2 and for
# the resolved study, figures that `plot` redraws, exit 2 for malformed grid specs, and a
# kill -9 in the middle of a map followed by a resume that gives the same bytes.
#   usage: bash cli_aeromap.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
vehicle="$root/studies/vehicles/efw_magpie.toml"
grid=(--speed 10:14:3 --freq 10:16:2 --theta 0:15:4)   # 24 points

check "aeromap --help exits 0" bash -c "'$bin' aeromap --help >/dev/null"
a="$scratch/j1"; b="$scratch/j2"
check "small map -j 1 exits 0" "$bin" aeromap "$vehicle" "${grid[@]}" -j 1 -o "$a"
check "small map -j 2 exits 0" "$bin" aeromap "$vehicle" "${grid[@]}" -j 2 -o "$b"
check "aeromap.csv identical for -j 1 and -j 2" cmp "$a/aeromap.csv" "$b/aeromap.csv"
for f in aeromap.csv summary.json study.resolved.toml aeromap_FV.png aeromap_FV.svg aeromap_FV.gp \
         aeromap_FH.png aeromap_FH.svg aeromap_M.png aeromap_power.png; do
  check "writes $f" test -s "$a/$f"
done
check "no journal or temporary file left" bash -c "! ls '$a' | grep -q -e journal -e tmp"
check "CSV names row" bash -c "head -1 '$a/aeromap.csv' | grep -q '^speed_mps,freq_hz,theta_deg,tail_angle_deg,FV_mean_N,FH_mean_N,M_mean_Nm,power_W,'"
check "CSV units row" bash -c "sed -n 2p '$a/aeromap.csv' | grep -q '^m/s,Hz,deg,deg,N,N,N m,W,'"
check "24 rows after the two header rows" test "$(( $(wc -l < "$a/aeromap.csv") - 2 ))" -eq 24
check "first row is the first grid point" bash -c "sed -n 3p '$a/aeromap.csv' | grep -q '^10,10,0,11.85,'"
check "last row is the last grid point" bash -c "tail -1 '$a/aeromap.csv' | grep -q '^14,16,15,11.85,'"
check "no NaN in the table" bash -c "! grep -qi nan '$a/aeromap.csv'"
for key in kind status message wall_time_s version points points_ok points_not_converged; do
  check "summary has $key" grep -q "\"$key\":" "$a/summary.json"
done
check "summary kind aeromap" test "$(json "$a/summary.json" kind)" = aeromap
check "summary points 24" test "$(json "$a/summary.json" points)" = 24
check "every point ok" test "$(json "$a/summary.json" points_ok)" = 24
check "resolved study re-runs" "$bin" run "$a/study.resolved.toml" -j 2 -o "$scratch/resolved"
check "resolved study gives the same bytes" cmp "$a/aeromap.csv" "$scratch/resolved/aeromap.csv"
check "plot redraws the four figures" bash -c "'$bin' plot '$a' | grep -q 'redrew 4 figure'"

# Bad grid specs: exit 2 with a message naming the option.
for bad in "--speed 10:20" "--speed 10:20:1" "--freq 10:20:2.5" "--theta 0:90:3" "--speed 0:10:2"; do
  case ${bad%% *} in
    --speed) args=(--freq 12:12:1 --theta 0:0:1) ;;
    --freq) args=(--speed 10:12:2 --theta 0:0:1) ;;
    --theta) args=(--speed 10:12:2 --freq 12:12:1) ;;
  esac
  # shellcheck disable=SC2086
  "$bin" aeromap "$vehicle" "${args[@]}" $bad -o "$scratch/bad" 2>"$scratch/bad.txt" >/dev/null
  rc=$?
  check "'$bad' exits 2 ($rc)" test "$rc" -eq 2
  check "'$bad' message names the option" grep -q -e "option ${bad%% *}:" "$scratch/bad.txt"
done
check "bad specs write nothing" test ! -e "$scratch/bad"

# Kill -9 in the middle of a larger map, then resume: the same bytes as an uninterrupted run.
big=(--speed 8:20:10 --freq 8:20:10 --theta 0:20:6)   # 600 points
ref="$scratch/big_ref"; killed="$scratch/big_killed"
check "uninterrupted 600-point map" "$bin" aeromap "$vehicle" "${big[@]}" -j 2 -o "$ref"
"$bin" aeromap "$vehicle" "${big[@]}" -j 2 -o "$killed" >/dev/null 2>&1 &
pid=$!
journal="$killed/aeromap.journal"
for _ in $(seq 1 3000); do  # up to 30 s for 40 journaled points
  if [ -f "$journal" ] && [ "$(wc -l < "$journal")" -ge 41 ]; then break; fi
  if ! kill -0 "$pid" 2>/dev/null; then break; fi
  sleep 0.01
done
kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
if [ -f "$journal" ]; then
  lines=$(( $(wc -l < "$journal") - 1 ))
  echo "info killed with $lines journaled points"
  printf '0123456789abcdef 599,ok,3,3,0.0001,1.2' >> "$journal"   # a torn last write
  cp -r "$killed" "$scratch/big_other"
  check "resume after kill -9 exits 0" "$bin" aeromap "$vehicle" "${big[@]}" -j 1 -o "$killed"
  check "resumed map is byte-identical" cmp "$ref/aeromap.csv" "$killed/aeromap.csv"
  check "resumed points were not recomputed ($lines)" test "$(json "$killed/summary.json" points_resumed)" -eq "$lines"
  check "journal removed after the resume" test ! -e "$journal"
  "$bin" aeromap "$vehicle" "${big[@]}" --cycles 30 -j 2 -o "$scratch/big_other" >/dev/null 2>"$scratch/other.txt"
  check "another study's journal is refused (exit 2, naming --fresh)" \
    bash -c "test $? -eq 2 && grep -q -- --fresh '$scratch/other.txt'"
  "$bin" aeromap "$vehicle" "${big[@]}" --cycles 30 -j 2 -o "$scratch/big_other" --fresh >/dev/null 2>"$scratch/other.txt"
  check "with --fresh another study discards the journal" grep -q "starting afresh" "$scratch/other.txt"
  check "... and computes every point" test "$(json "$scratch/big_other/summary.json" points_resumed)" -eq 0
else
  echo "skip kill-and-resume: the map finished before it could be killed"
fi
exit $fail
