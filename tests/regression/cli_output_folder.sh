#!/usr/bin/env bash
# Output folders (issue 14, defects 6 and 7): one writer per folder, and never an empty name.
#   - a run holds DIR/.ornithopter.lock (flock) with its pid: a second run into the same folder
#     exits 2 at once naming the holder's pid, for every command that writes a folder (run,
#     simulate, modes, aeromap, trim, optimize, plot; a multi-study run locks each DIR/<name>);
#   - a lock file left by a killed run (its pid is dead, nothing holds the lock) is taken over;
#   - two real runs started together into one folder: one computes, the other exits 2;
#   - `-o ""` (and an empty RUN_DIR or --export-ccx) exits 2 instead of meaning the default.
#   usage: bash cli_output_folder.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
rfw="$root/studies/vehicles/rfw_tunnel.toml"
efw="$root/studies/vehicles/efw_magpie.toml"
study="$root/studies/examples/rfw_theta20.toml"
cd "$scratch" || exit 1

# Hold DIR's lock from this shell (fd 9 stays open), with our pid in the file.
hold() {
  mkdir -p "$1"
  exec 9>>"$1/.ornithopter.lock"
  flock -n 9 || return 1
  echo $$ > "$1/.ornithopter.lock"
}
release() { exec 9>&-; }

busy="$scratch/busy"
hold "$busy" || { echo "FAIL cannot take the test lock"; exit 1; }
commands=(
  "simulate|simulate $rfw --cycles 2 -o $busy"
  "run|run $study -o $busy"
  "modes|modes $efw -o $busy"
  "aeromap|aeromap $rfw --speed 6:6:1 --freq 4:4:1 --theta 0:0:1 -o $busy"
  "trim|trim $efw --freq 12 -o $busy"
  "optimize|optimize $root/studies/paper/optimize_magpie.toml -o $busy"
  "run (several studies)|run $study $root/studies/paper/fig2_rfw_theta0.toml -o $scratch/multi"
)
mkdir -p "$scratch/multi"
for entry in "${commands[@]}"; do
  what=${entry%%|*}; args=${entry#*|}
  if [[ $what == "run (several studies)" ]]; then
    release; hold "$scratch/multi/fig2_rfw_theta0" || exit 1
  fi
  start=$(date +%s)
  # shellcheck disable=SC2086
  "$bin" $args >/dev/null 2>"$scratch/err.txt"
  rc=$?
  check "$what into a locked folder exits 2 ($rc)" test $rc -eq 2
  check "... at once" test $(( $(date +%s) - start )) -le 5
  check "... naming the holder's pid" grep -q "in use by another ornithopter run (pid $$)" "$scratch/err.txt"
done
check "the multi-study run started nothing (no summary for its other study)" \
  test ! -e "$scratch/multi/rfw_theta20/summary.json"
release
hold "$busy/run" || exit 1
mkdir -p "$busy/run"; printf '{"kind": "simulate"}\n' > "$busy/run/summary.json"
printf "set output 'x.png.tmp'\n" > "$busy/run/x.gp"
"$bin" plot "$busy/run" >/dev/null 2>"$scratch/err.txt"
check "plot of a locked folder exits 2 naming the pid" \
  bash -c "test $? -eq 2 && grep -q 'pid $$' '$scratch/err.txt'"
release

# A stale lock (a killed run's file; nothing holds it) is taken over, then removed.
stale="$scratch/stale"; mkdir -p "$stale"; echo 999999999 > "$stale/.ornithopter.lock"
"$bin" simulate "$rfw" --cycles 2 -o "$stale" >/dev/null
check "a stale lock is taken over" test $? -eq 0
check "... the run wrote its summary" test -s "$stale/summary.json"
check "... and removed the lock file" test ! -e "$stale/.ornithopter.lock"

# Two real runs into one folder at the same time: exactly one writes, the other exits 2.
# (100 points of the flexible EFW: about a second in Release, half a minute under the sanitizers; the
# second starts as soon as the first's lock file exists, within tens of milliseconds.)
race="$scratch/race"
grid=(--speed 8:20:5 --freq 8:20:5 --theta 0:20:4)
"$bin" aeromap "$efw" "${grid[@]}" -o "$race" >/dev/null 2>"$scratch/first.err" &
first=$!
for _ in $(seq 200); do [[ -s "$race/.ornithopter.lock" ]] && break; sleep 0.02; done
"$bin" aeromap "$efw" "${grid[@]}" -o "$race" >/dev/null 2>"$scratch/second.err"
second=$?
wait $first
first_rc=$?
check "two runs into one folder: the first finishes (exit $first_rc)" test $first_rc -eq 0
check "... the second exits 2 ($second)" test $second -eq 2
check "... naming the first's pid" grep -q "pid $first" "$scratch/second.err"
check "... the folder holds the first's complete map" test "$(json "$race/summary.json" points)" = 100

# Two studies of one name into one -o: refused before any work.
"$bin" run "$study" "$study" -o "$scratch/twice" >/dev/null 2>"$scratch/err.txt"
check "two studies into the same folder exit 2" \
  bash -c "test $? -eq 2 && grep -q 'both write into' '$scratch/err.txt'"

# An empty output name is bad input, never the default folder.
empty=(
  "simulate $rfw --cycles 1 -o"
  "run $study -o"
  "modes $efw -o"
  "aeromap $rfw --speed 6:6:1 --freq 4:4:1 --theta 0:0:1 -o"
  "trim $efw --freq 12 -o"
  "optimize $root/studies/paper/optimize_magpie.toml -o"
  "modes $efw -o $scratch/m --export-ccx"
  "plot"
)
for args in "${empty[@]}"; do
  # shellcheck disable=SC2086
  "$bin" $args "" >/dev/null 2>"$scratch/err.txt"
  rc=$?
  check "'${args%% *} ... ${args##* } \"\"' exits 2 ($rc)" test $rc -eq 2
  check "... saying the path is empty" grep -q "empty string" "$scratch/err.txt"
done
check "no results/ folder was written in the working folder" test ! -e "$scratch/results"

exit $fail
