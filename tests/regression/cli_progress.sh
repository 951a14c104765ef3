#!/usr/bin/env bash
# Long runs show progress (docs/design.md 4.4): a run with no points to count (simulate, trim,
# stability, calibrate, continuation) writes "KIND: working, N s elapsed" on stderr from its 2nd
# second on (every 10 s in a log), and a short run nothing more than before. ~6 s in Release. The audited version
# printed nothing for over 120 s (`stability efw_magpie.toml --freq 0.01`, and trim there).
#   usage: bash cli_progress.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
set -m  # each background run in its own process group
bin=${1:?}; root=${2:?}; scratch=${3:?}
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
rfw="$root/studies/vehicles/rfw_tunnel.toml"
efw="$root/studies/vehicles/efw_magpie.toml"

# Starts a run in the background with stderr to $2 and waits (at most 20 s: the line is due at
# 2 s; the margin is for the sanitizer build's slower start) for a progress line, then stops it.
# Leaves the run's exit status in $rc and the seconds waited in $waited.
watch_run() {  # watch_run PATTERN ERRFILE COMMAND...
  local pattern=$1 err=$2; shift 2
  "$@" > /dev/null 2> "$err" &
  local pid=$! start=$SECONDS
  for _ in $(seq 100); do
    grep -q "$pattern" "$err" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.2
  done
  waited=$(( SECONDS - start ))
  kill -TERM "$pid" 2>/dev/null; wait "$pid"; rc=$?
}

# A long simulation (100000 cycles of the rig, tens of seconds).
watch_run "^simulate: working, [0-9.]* s elapsed" "$scratch/long.err" \
  "$bin" simulate "$rfw" --cycles 100000 -o "$scratch/long"
check "simulate: a progress line ($(head -1 "$scratch/long.err"), after ${waited} s)" \
  grep -q "^simulate: working, [0-9.]* s elapsed" "$scratch/long.err"

# The same for stability at 0.01 Hz (in range; the audited case: silent for over 120 s).
watch_run "^stability: working" "$scratch/slow.err" \
  "$bin" stability "$efw" --freq 0.01 -o "$scratch/slow"
if [[ $rc -eq 0 || $rc -eq 1 ]] && ! grep -q working "$scratch/slow.err"; then
  echo "ok   stability --freq 0.01 ended within ${waited} s (exit $rc): nothing to show"
else
  check "stability --freq 0.01: a progress line (after ${waited} s)" \
    grep -q "^stability: working, [0-9.]* s elapsed" "$scratch/slow.err"
fi

# A short run prints no progress line.
"$bin" simulate "$rfw" --cycles 2 -o "$scratch/short" > /dev/null 2> "$scratch/short.err"
check "a short run (exit $?) prints no progress line" bash -c "! grep -q working '$scratch/short.err'"
exit $fail
