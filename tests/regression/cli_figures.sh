#!/usr/bin/env bash
# Figures (issue 14, defects 2, 3 and 9): every figure is complete or absent, degenerate aero-map
# grids are valid and drawn, and a run stopped while its figures are drawn costs nothing: its
# journal survives and the same command recomputes no point.
#   - gnuplot exits 0 even when it cannot write: a stand-in gnuplot (ORNI_GNUPLOT) that leaves a
#     truncated PNG and an empty SVG must not produce loads.png/loads.svg, nor leave temporary
#     files; and on a really full disk (a small tmpfs in a private mount namespace, when the
#     machine allows it) `plot` fails with no partial figure under a final name;
#   - a one-point map (6:6:1 x 4:4:1 x 0:0:1) and one with a repeated axis value (6:6:3) exit 0
#     with their four figures;
#   - a stand-in gnuplot that kills the run (kill -9 of the pid in the folder's lock file) while
#     the first aero-map figure is drawn; the rerun resumes every point from the journal.
#   usage: bash cli_figures.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
rfw="$root/studies/vehicles/rfw_tunnel.toml"

# No temporary file (NAME.tmp.PID.N, *.png.tmp) or drawing folder (.plot-*) in a folder.
no_leftovers() { ! ls -A "$1" | grep -q -e '\.tmp' -e '^\.plot-' -e '\.gnuplot\.log$'; }

# --- stand-in gnuplot that "succeeds" without writing whole files ----------------------------
fake="$scratch/fake_bin"; mkdir -p "$fake"
cat > "$fake/truncating_gnuplot" <<'EOF'
#!/usr/bin/env bash
# Like gnuplot on a full disk: exit 0, a PNG cut after its signature, an empty SVG.
script=${!#}; stem=$(basename "$script" .gp)
printf '\211PNG\r\n\032\n\0\0\0\rIHDR' > "$stem.png.tmp"
: > "$stem.svg.tmp"
exit 0
EOF
cat > "$fake/failing_gnuplot" <<'EOF'
#!/usr/bin/env bash
echo "line 7: fake gnuplot error" >&2
exit 1
EOF
cat > "$fake/killing_gnuplot" <<'EOF'
#!/usr/bin/env bash
# Kills the ornithopter run drawing this figure: its pid is in the folder's lock file (gnuplot
# runs in a drawing folder inside the output folder).
kill -9 "$(cat ../.ornithopter.lock)"
sleep 1
EOF
chmod +x "$fake"/*

out="$scratch/truncated"
ORNI_GNUPLOT="$fake/truncating_gnuplot" "$bin" simulate "$rfw" --cycles 2 -o "$out" \
  >/dev/null 2>"$scratch/truncated.err"
rc=$?
check "incomplete figures: the run fails (exit 1, got $rc)" test $rc -eq 1
check "... saying the figure is incomplete" grep -q "incomplete loads.png" "$scratch/truncated.err"
check "... no loads.png under its final name" test ! -e "$out/loads.png"
check "... no loads.svg under its final name" test ! -e "$out/loads.svg"
check "... no temporary file or drawing folder left" no_leftovers "$out"
check "... the data files are complete" test -s "$out/histories.csv"

out="$scratch/failing"
ORNI_GNUPLOT="$fake/failing_gnuplot" "$bin" simulate "$rfw" --cycles 2 -o "$out" \
  >/dev/null 2>"$scratch/failing.err"
rc=$?
check "gnuplot error: the run fails (exit 1, got $rc)" test $rc -eq 1
check "... with gnuplot's message" grep -q "fake gnuplot error" "$scratch/failing.err"
check "... no figure, no temporary file, no log left" \
  bash -c "test ! -e '$out/loads.png' && ! ls -A '$out' | grep -q -e tmp -e '^\.plot-' -e log"

# A real full disk: a 2 MB tmpfs in a private mount namespace (root only; skipped elsewhere).
if unshare -m true 2>/dev/null && [[ $(id -u) == 0 ]]; then
  cat > "$scratch/full_disk.sh" <<'EOF'
set -u
bin=$1; rfw=$2; mnt=$3
mount -t tmpfs -o size=2m tmpfs "$mnt" || exit 77
"$bin" simulate "$rfw" --cycles 2 -o "$mnt/run" >/dev/null 2>&1 || exit 78
rm -f "$mnt/run/loads.png" "$mnt/run/loads.svg" "$mnt/run/zmp.png" "$mnt/run/zmp.svg"
# Fill the disk but one page: enough for the lock file, too little for a figure.
dd if=/dev/zero of="$mnt/pad" bs=4k count=1 status=none
dd if=/dev/zero of="$mnt/fill" bs=64k status=none 2>/dev/null
rm -f "$mnt/pad"
"$bin" plot "$mnt/run" > "$mnt/../plot.out" 2>&1
echo "rc=$?"
ls -A "$mnt/run"
EOF
  mkdir -p "$scratch/mnt"
  unshare -m bash "$scratch/full_disk.sh" "$bin" "$rfw" "$scratch/mnt" > "$scratch/full_disk.txt" 2>&1
  urc=$?
  if [[ $urc -eq 77 ]]; then
    echo "skip full disk: tmpfs cannot be mounted here"
  else
    check "full disk: the setup ran" test $urc -eq 0
    check "full disk: plot fails (exit 1)" grep -qx "rc=1" "$scratch/full_disk.txt"
    check "full disk: no loads.png or loads.svg under the final name" \
      bash -c "! grep -qx -e loads.png -e loads.svg -e zmp.png -e zmp.svg '$scratch/full_disk.txt'"
    check "full disk: no temporary file or drawing folder left" \
      bash -c "! grep -q -e tmp -e '^\.plot-' -e '\.lock' '$scratch/full_disk.txt'"
  fi
else
  echo "skip full disk: needs root and unshare"
fi

# --- degenerate aero-map grids are valid ------------------------------------------------------
for grid in "6:6:1 4:4:1 0:0:1" "6:6:3 4:4:1 0:10:2" "5:7:2 4:4:1 20:20:1"; do
  read -r sp fr th <<< "$grid"
  out="$scratch/map_${sp//:/_}_${th//:/_}"
  "$bin" aeromap "$rfw" --speed "$sp" --freq "$fr" --theta "$th" --cycles 6 -o "$out" \
    >/dev/null 2>"$out.err"
  rc=$?
  check "aeromap --speed $sp --freq $fr --theta $th exits 0 ($rc)" test $rc -eq 0
  for f in aeromap_FV aeromap_FH aeromap_M aeromap_power; do
    check "... draws $f.png" test -s "$out/$f.png"
  done
  check "... no gnuplot warning of an empty range" bash -c "! grep -qi 'empty' '$out.err'"
done

# --- killed while drawing: the journal survives, the rerun computes nothing --------------------
out="$scratch/killed_map"
map=(--speed 5:7:3 --freq 4:4:1 --theta 0:10:2 --cycles 6)
ORNI_GNUPLOT="$fake/killing_gnuplot" "$bin" aeromap "$rfw" "${map[@]}" -o "$out" >/dev/null 2>&1
rc=$?
check "killed while drawing (exit 137, got $rc)" test $rc -eq 137
check "... the journal survives" test -s "$out/aeromap.journal"
check "... no figure under its final name" test ! -e "$out/aeromap_FV.png"
"$bin" aeromap "$rfw" "${map[@]}" -o "$out" >/dev/null 2>&1
check "rerun exits 0" test $? -eq 0
check "... computes no point" test "$(json "$out/summary.json" points_computed)" = 0
check "... resumes all 6" test "$(json "$out/summary.json" points_resumed)" = 6
check "... draws the four figures" \
  bash -c "for f in FV FH M power; do test -s '$out/aeromap_'\$f.png || exit 1; done"
check "... then removes the journal" test ! -e "$out/aeromap.journal"
check "... and leaves nothing temporary (the killed run's drawing folder included)" \
  no_leftovers "$out"
check "... nor the lock file" test ! -e "$out/.ornithopter.lock"

exit $fail
