#!/usr/bin/env bash
# Bad input is exit 2 everywhere, with a message that says what is wrong (issue 14, defects 10
# and 11); the malformed files of tests/data/bad are checked by bad_inputs.sh, this script covers
# what a file cannot: special files, command-line values and folders.
#   - free flight of a vehicle without [body] (command line and study) and trim of it: exit 2;
#   - an aero-map grid of more than 10 million points on the command line: exit 2 (a study's
#     grid is tests/data/bad/study_aeromap_too_many_points.toml);
#   - `plot` on a missing folder, a file, an empty folder, a folder that is not a run: exit 2;
#   - a directory, a FIFO or /dev/null as the input file: exit 2 saying what it is;
#   - a study naming itself as its vehicle, or a vehicle file that is a study: exit 2, saying so;
#   - a mistyped subcommand: exit 2 with the nearest one ("did you mean 'simulate'?").
#   usage: bash cli_input_errors.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
rfw="$root/studies/vehicles/rfw_tunnel.toml"   # a tethered rig: no [body]
cd "$scratch" || exit 1

# expect2 "what" "message pattern" args...: exit 2 and the message on stderr.
expect2() {
  local what=$1 pattern=$2; shift 2
  "$bin" "$@" >"$scratch/out.txt" 2>"$scratch/err.txt"
  local rc=$?
  check "$what exits 2 ($rc)" test $rc -eq 2
  check "... '$pattern'" grep -qF -- "$pattern" "$scratch/err.txt"
  check "... and says nothing of a failure" bash -c "! grep -q 'failed' '$scratch/err.txt'"
}

expect2 "simulate --mode free of a vehicle without [body]" "missing required key 'body'" \
  simulate "$rfw" --mode free --cycles 2 -o "$scratch/free"
check "... writes nothing" test ! -e "$scratch/free"
printf 'kind = "simulate"\nvehicle = "%s"\n[simulate]\nmode = "free"\ncycles = 2\n' "$rfw" \
  > "$scratch/free_study.toml"
expect2 "a free-flight study of a vehicle without [body]" "without a [body] table" \
  run "$scratch/free_study.toml" -o "$scratch/free"
expect2 "trim of a vehicle without [body]" "missing required key 'body'" \
  trim "$rfw" --freq 4 -o "$scratch/trim"
expect2 "aeromap of 1000 x 1000 x 11 points" "at most 10000000 points" \
  aeromap "$rfw" --speed 1:10:1000 --freq 1:10:1000 --theta 0:10:11 -o "$scratch/big"
check "... writes nothing" test ! -e "$scratch/big"

expect2 "plot of a missing folder" "no such folder" plot "$scratch/nowhere"
touch "$scratch/a_file"
expect2 "plot of a file" "not a folder" plot "$scratch/a_file"
mkdir -p "$scratch/empty"
expect2 "plot of an empty folder" "not a run folder" plot "$scratch/empty"
mkdir -p "$scratch/no_figures"; printf '{"kind": "calibrate"}\n' > "$scratch/no_figures/summary.json"
expect2 "plot of a run without figure scripts" "no figure scripts" plot "$scratch/no_figures"

mkdir -p "$scratch/dir.toml"
mkfifo "$scratch/fifo.toml"
expect2 "a directory as the vehicle" "is a directory" simulate "$scratch/dir.toml"
expect2 "a FIFO as the vehicle" "not a regular file (a FIFO)" simulate "$scratch/fifo.toml"
expect2 "/dev/null as the vehicle" "not a regular file (a character device)" simulate /dev/null
expect2 "a directory as the study" "is a directory" run "$scratch/dir.toml"
expect2 "a missing vehicle file" "no such file" simulate "$scratch/missing.toml"

printf 'kind = "simulate"\nvehicle = "self.toml"\n' > "$scratch/self.toml"
expect2 "a study naming itself as its vehicle" "not the study itself" run "$scratch/self.toml"
expect2 "a study as the vehicle of simulate" "this is a study file, not a vehicle file" \
  simulate "$root/studies/examples/rfw_theta20.toml"

expect2 "ornithopter simulat" "did you mean 'simulate'?" simulat "$rfw"
expect2 "ornithopter aeromaps" "did you mean 'aeromap'?" aeromaps "$rfw"
expect2 "ornithopter frobnicate" "unknown subcommand 'frobnicate'" frobnicate

exit $fail
