#!/usr/bin/env bash
# A run's output folder (issue 30, items 2, 3 and 5):
#   - item 2: a folder that holds another study's journal (finished points of a killed run) is
#     refused with exit 2 naming the folder and --fresh, and the journal is kept byte for byte;
#     with --fresh it is discarded and the run starts afresh (the audited version printed
#     "starting afresh", deleted it and exited 0);
#   - item 3: a run owns its folder: it removes the outputs of an earlier run there (tethered then
#     free leaves no cycles.csv, zmp.csv or loads.*; aeromap then simulate no aeromap.*), and
#     `plot` draws only the figures of the kind the folder's summary.json names;
#   - item 5: every output-path problem exits 2 naming the path (-o at a file, at a symlink loop,
#     at a dangling symlink, at a read-only folder when not root, --export-ccx through a file);
#     none is "File exists".
#   usage: bash cli_run_folder.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
rfw="$root/studies/vehicles/rfw_tunnel.toml"
efw="$root/studies/vehicles/efw_magpie.toml"

# ---- item 2: another study's journal is refused, never deleted without --fresh -----------------
map="$scratch/map"; mkdir -p "$map"
# A journal of another grid (as a killed map leaves it): a header and one finished point.
printf '# ornithopter aeromap journal v1 fingerprint=0123456789abcdef points=1859\n' > "$map/aeromap.journal"
printf '0000000000000000 0,a finished point\n' >> "$map/aeromap.journal"
cp "$map/aeromap.journal" "$scratch/journal.orig"
grid=(--speed 6:6:1 --freq 4:4:1 --theta 0:10:2 --cycles 4)
"$bin" aeromap "$rfw" "${grid[@]}" -o "$map" > "$scratch/map.out" 2> "$scratch/map.err"
rc=$?
check "aeromap into a folder with another study's journal: exit 2 ($rc)" test $rc -eq 2
check "... naming the folder" grep -qF "$map" "$scratch/map.err"
check "... and the option that discards it (--fresh)" grep -q -- "--fresh" "$scratch/map.err"
check "... the journal is kept byte for byte" cmp -s "$map/aeromap.journal" "$scratch/journal.orig"
check "... nothing else written" test ! -e "$map/summary.json"
study="$scratch/map_study.toml"
printf 'kind = "aeromap"\nname = "map_study"\nvehicle = "%s"\n[aeromap]\nspeed_mps = "6:6:1"\nfreq_hz = "4:4:1"\ntheta_deg = "0:10:2"\ncycles = 4\n' "$rfw" > "$study"
"$bin" run "$study" -o "$map" > /dev/null 2> "$scratch/run.err"
rc=$?
check "run (aeromap study) into it: exit 2 ($rc), journal kept" \
  bash -c "test $rc -eq 2 && cmp -s '$map/aeromap.journal' '$scratch/journal.orig'"
"$bin" aeromap "$rfw" "${grid[@]}" -o "$map" --fresh > /dev/null 2> "$scratch/fresh.err"
rc=$?
check "with --fresh: exit 0 ($rc)" test $rc -eq 0
check "... the map is complete" test "$(json "$map/summary.json" points)" = 2
check "... its own journal removed at the end" test ! -e "$map/aeromap.journal"

# ---- item 3: a run owns its folder -------------------------------------------------------------
own="$scratch/own"
"$bin" simulate "$efw" --cycles 2 -o "$own" > /dev/null 2>&1
check "tethered run writes cycles.csv, zmp.csv and loads.png" \
  bash -c "test -s '$own/cycles.csv' && test -s '$own/zmp.csv' && test -s '$own/loads.png'"
echo "my notes" > "$own/notes.txt"
"$bin" simulate "$efw" --mode free --cycles 2 -o "$own" > /dev/null 2>&1
rc=$?
check "free run into the same folder: exit 0 ($rc)" test $rc -eq 0
for f in cycles.csv zmp.csv loads.png loads.svg loads.gp zmp.png zmp.gp; do
  check "... the tethered run's $f is gone" test ! -e "$own/$f"
done
check "... a file the program did not write is kept" test -s "$own/notes.txt"
check "... the free run's outputs are there" test -s "$own/summary.json"

mixed="$scratch/mixed"
"$bin" aeromap "$rfw" --speed 6:6:1 --freq 4:4:1 --theta 0:0:1 --cycles 4 -o "$mixed" > /dev/null 2>&1
check "aeromap writes aeromap.csv" test -s "$mixed/aeromap.csv"
"$bin" simulate "$rfw" --cycles 2 -o "$mixed" > /dev/null 2>&1
check "simulate into the map's folder removes aeromap.csv" test ! -e "$mixed/aeromap.csv"
check "... and the map's figures" bash -c "! ls '$mixed'/aeromap_* >/dev/null 2>&1"
check "... the summary is the simulate run's" test "$(json "$mixed/summary.json" kind)" = simulate
# A folder mixed by an older version: plot draws only what the summary's kind holds.
printf "set output 'aeromap_FV.png.tmp'\nplot x\n" > "$mixed/aeromap_FV.gp"
"$bin" plot "$mixed" > "$scratch/plot.out" 2> "$scratch/plot.err"
rc=$?
check "plot of a mixed folder: exit 0 ($rc)" test $rc -eq 0
check "... does not draw the aeromap figure" test ! -e "$mixed/aeromap_FV.png"
check "... redraws the simulate figures ($(cat "$scratch/plot.out"))" grep -q "redrew [1-9]" "$scratch/plot.out"

# ---- item 5: output-path problems are bad input naming the path --------------------------------
cd "$scratch" || exit 1
touch a_file
ln -s loop_b loop_a; ln -s loop_a loop_b
ln -s "$scratch/no/such/target" dangling
paths=(a_file loop_a dangling a_file/sub)
if [[ $(id -u) -ne 0 ]]; then
  mkdir -p read_only; chmod 555 read_only; paths+=(read_only/sub)
fi
for p in "${paths[@]}"; do
  "$bin" simulate "$rfw" --cycles 1 -o "$p" > /dev/null 2> "$scratch/path.err"
  rc=$?
  check "-o $p: exit 2 ($rc)" test $rc -eq 2
  check "... naming the path: $(head -c 200 "$scratch/path.err")" grep -qF "$p" "$scratch/path.err"
  check "... not 'File exists'" bash -c "! grep -q 'File exists' '$scratch/path.err'"
done
"$bin" aeromap "$rfw" --speed 6:6:1 --freq 4:4:1 --theta 0:0:1 -o a_file > /dev/null 2> "$scratch/path.err"
check "aeromap -o a_file: exit 2" test $? -eq 2
"$bin" run "$study" -o a_file > /dev/null 2> "$scratch/path.err"
check "run -o a_file: exit 2" test $? -eq 2
"$bin" modes "$efw" -o "$scratch/modes" --export-ccx a_file/wing.inp > /dev/null 2> "$scratch/path.err"
rc=$?
check "modes --export-ccx a_file/wing.inp: exit 2 ($rc), naming the path" \
  bash -c "test $rc -eq 2 && grep -qF a_file/wing.inp '$scratch/path.err'"
exit $fail
