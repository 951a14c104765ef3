#!/usr/bin/env bash
# Interrupts (docs/design.md 4.4): SIGINT or SIGTERM at any phase of a run ends it with exit 130 or
# 143 and status "interrupted" in summary.json (never "ok"), the journal kept, no temporary file,
# drawing folder or lock left, and the figure program (gnuplot) stopped too.
#   - while computing (a long tethered simulation): SIGINT -> 130, SIGTERM -> 143;
#   - while a figure is drawn (a stand-in gnuplot that sleeps, ORNI_GNUPLOT): SIGINT to the main
#     process alone -> 130 at once and the stand-in gone (the audited version ignored it while
#     gnuplot ran, and Ctrl-C to the group gave exit 1 "gnuplot failed ... said: nothing" or exit
#     0 with summary.json "ok");
#   - an aero map: the journal keeps the finished points and the same command resumes.
#   usage: bash cli_interrupts.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
# Job control: each background run in its own process group, with SIGINT not ignored (as a run
# started from a terminal has it).
set -m
bin=${1:?}; root=${2:?}; scratch=${3:?}
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
rfw="$root/studies/vehicles/rfw_tunnel.toml"

wait_for() {  # wait_for SECONDS TEST...: polls every 0.05 s
  local tries=$(( $1 * 20 )); shift
  for _ in $(seq "$tries"); do "$@" && return 0; sleep 0.05; done
  return 1
}
clean_folder() {  # no temporary file, drawing folder or lock left in $1
  ! ls -A "$1" | grep -qE '\.tmp\.[0-9]+\.[0-9]+$|^\.plot-|^\.ornithopter\.lock$'
}

# ---- while computing ---------------------------------------------------------------------------
for sig in INT TERM; do
  out="$scratch/compute_$sig"
  "$bin" simulate "$rfw" --cycles 100000 -o "$out" > "$scratch/compute_$sig.log" 2>&1 &
  pid=$!
  wait_for 20 test -e "$out/.ornithopter.lock"
  sleep 1
  kill -"$sig" "$pid"
  start=$(date +%s)
  wait "$pid"; rc=$?
  want=$([[ $sig == INT ]] && echo 130 || echo 143)
  check "SIG$sig while computing: exit $want ($rc)" test "$rc" -eq "$want"
  check "... within 5 s" test $(( $(date +%s) - start )) -le 5
  check "... summary.json says interrupted ($(json "$out/summary.json" status))" \
    test "$(json "$out/summary.json" status)" = interrupted
  check "... no temporary file or lock left" clean_folder "$out"
done

# ---- while a figure is drawn: a stand-in gnuplot that sleeps -----------------------------------
fake="$scratch/slow_gnuplot"
printf '#!/bin/sh\necho $$ > "%s/fake.pid"\nexec sleep 30\n' "$scratch" > "$fake"
chmod +x "$fake"
out="$scratch/figures"
ORNI_GNUPLOT="$fake" "$bin" simulate "$rfw" --cycles 2 -o "$out" > "$scratch/figures.log" 2>&1 &
pid=$!
wait_for 30 test -s "$scratch/fake.pid"
check "the run reached its figures" test -s "$scratch/fake.pid"
kill -INT "$pid"  # the main process alone
start=$(date +%s)
wait "$pid"; rc=$?
check "SIGINT to the main process while drawing: exit 130 ($rc)" test "$rc" -eq 130
check "... at once (not after the drawing)" test $(( $(date +%s) - start )) -le 5
check "... summary.json says interrupted, not ok ($(json "$out/summary.json" status))" \
  test "$(json "$out/summary.json" status)" = interrupted
check "... the figure program is stopped" bash -c "! kill -0 $(cat "$scratch/fake.pid" 2>/dev/null || echo 999999) 2>/dev/null"
check "... no temporary file, drawing folder or lock left" clean_folder "$out"
check "... no 'gnuplot failed' message" bash -c "! grep -q 'gnuplot failed' '$scratch/figures.log'"

# Ctrl-C at a terminal: SIGINT to the whole process group, the figure program included.
rm -f "$scratch/fake.pid"
out="$scratch/figures_group"
ORNI_GNUPLOT="$fake" "$bin" simulate "$rfw" --cycles 2 -o "$out" > "$scratch/figures_group.log" 2>&1 &
pid=$!
wait_for 30 test -s "$scratch/fake.pid"
kill -INT -- "-$pid"  # the job's process group (set -m: its leader is the run)
wait "$pid"; rc=$?
check "SIGINT to the process group while drawing: exit 130 ($rc)" test "$rc" -eq 130
check "... summary.json says interrupted ($(json "$out/summary.json" status))" \
  test "$(json "$out/summary.json" status)" = interrupted
check "... no 'gnuplot failed' message" bash -c "! grep -q 'gnuplot failed' '$scratch/figures_group.log'"
check "... no temporary file, drawing folder or lock left" clean_folder "$out"

# ---- an aero map: the journal is kept and the same command resumes ------------------------------
out="$scratch/map"
grid=(--speed 4:8:5 --freq 3:5:5 --theta 0:20:5 --cycles 6)
"$bin" aeromap "$rfw" "${grid[@]}" -o "$out" > /dev/null 2>&1 &
pid=$!
wait_for 60 bash -c "test -f '$out/aeromap.journal' && test \$(wc -l < '$out/aeromap.journal') -ge 3"
kill -INT "$pid"
wait "$pid"; rc=$?
check "SIGINT during an aero map: exit 130 ($rc)" test "$rc" -eq 130
check "... the journal is kept" test -s "$out/aeromap.journal"
check "... summary.json says interrupted" test "$(json "$out/summary.json" status)" = interrupted
check "... no temporary file or lock left" clean_folder "$out"
"$bin" aeromap "$rfw" "${grid[@]}" -o "$out" > "$scratch/resume.log" 2>&1
rc=$?
check "the same command resumes and finishes (exit $rc)" test "$rc" -eq 0
check "... from the journal" grep -q "resuming" "$scratch/resume.log"
check "... the summary is the finished map's" test "$(json "$out/summary.json" status)" != interrupted
exit $fail
