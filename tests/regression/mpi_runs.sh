#!/usr/bin/env bash
# Distributed runs (docs/design.md 6): `mpirun -n 3` (rank 0 the master, two workers) gives the same bytes
# as `-j 1` for a small aero map (through `run` and the `aeromap` subcommand), a trim sweep and a
# 3-start optimisation; a map killed under mpirun (kill -9 of rank 1) resumes without MPI and with
# it, to the same bytes, without recomputing the journaled points. Skipped (exit 77) when the
# binary was built without MPI (ORNI_MPIRUN, set by tests/CMakeLists.txt, is empty).
#   usage: bash mpi_runs.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
if [[ -z "${ORNI_MPIRUN:-}" ]]; then
  echo "SKIPPED: ornithopter was built without MPI (apt-get install libopenmpi-dev openmpi-bin," \
       "then reconfigure with -DORNI_MPI=ON)"
  exit 77
fi
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
root=$(cd "$root" && pwd)
mpirun=("$ORNI_MPIRUN" --oversubscribe)
if [[ "$(id -u)" == 0 ]]; then mpirun+=(--allow-run-as-root); fi
efw="$root/studies/vehicles/efw_magpie.toml"
fixture="$root/tests/data/sensitivity/magpie_rigid_fixture.toml"

# Bad input under mpirun (issue 30, item 7): exit 2 and the message once, not once per rank.
bad="$root/tests/data/bad/study_sweep_bad_value.toml"
"${mpirun[@]}" -n 3 "$bin" run "$bad" -o "$scratch/bad_mpi" > /dev/null 2> "$scratch/bad_mpi.err"
rc=$?
check "mpirun -n 3 with bad input: exit 2 ($rc)" test $rc -eq 2
check "... the input error printed once ($(grep -c 'ornithopter: error:' "$scratch/bad_mpi.err"))" \
  test "$(grep -c 'ornithopter: error:' "$scratch/bad_mpi.err")" -eq 1

# The aero map: 24 points through the subcommand, the same grid through a study file.
grid=(--speed 10:14:3 --freq 10:16:2 --theta 0:15:4)
check "aeromap -j 1" "$bin" aeromap "$efw" "${grid[@]}" -j 1 -o "$scratch/map_j1"
check "mpirun -n 3 aeromap" "${mpirun[@]}" -n 3 "$bin" aeromap "$efw" "${grid[@]}" -o "$scratch/map_mpi" \
  2> "$scratch/map_mpi.err"
check "aeromap.csv identical for mpirun -n 3 and -j 1" cmp "$scratch/map_j1/aeromap.csv" "$scratch/map_mpi/aeromap.csv"
check "the master reports its messages" grep -q "^mpi: 24 points on 2 worker rank(s)" "$scratch/map_mpi.err"
check "no journal or temporary file left" bash -c "! ls '$scratch/map_mpi' | grep -q -e journal -e tmp"
check "mpirun -n 2 -j 2 run of the resolved study" "${mpirun[@]}" -n 2 "$bin" run \
  "$scratch/map_j1/study.resolved.toml" -j 2 -o "$scratch/map_run"
check "... the same bytes" cmp "$scratch/map_j1/aeromap.csv" "$scratch/map_run/aeromap.csv"

# A trim sweep (the cheap frozen rigid magpie, Eq. (4) trims at three frequencies).
cat > "$scratch/trims.toml" <<TOML
kind = "sweep"
vehicle = "$fixture"
[sweep]
run = "trim"
axes = [ { key = "trim.freq_hz", values = "11:13:3" } ]
[trim]
initial = { theta_mean_deg = 10.0, speed_mps = 10.0, tail_angle_deg = 10.0 }
refine_in_free_flight = false
TOML
check "trim sweep -j 1" "$bin" run "$scratch/trims.toml" -j 1 -o "$scratch/sweep_j1"
check "mpirun -n 3 trim sweep" "${mpirun[@]}" -n 3 "$bin" run "$scratch/trims.toml" -o "$scratch/sweep_mpi"
check "sweep.csv identical for mpirun -n 3 and -j 1" cmp "$scratch/sweep_j1/sweep.csv" "$scratch/sweep_mpi/sweep.csv"

# A 3-start optimisation of two evaluations each (the cheap frozen rigid magpie, Eq. (4) trims).
cat > "$scratch/opt.toml" <<EOT
kind = "optimize"
name = "tiny3"
vehicle = "$fixture"
[optimize]
freq_hz = 12.0
max_evaluations = 2
starts = 3
variables = [
  { name = "tail.area_m2", lower = 0.004, upper = 0.012 },
  { name = "tail.arm_m", lower = 0.08, upper = 0.16 },
]
[optimize.constraints]
bounded = false
[optimize.trim]
refine_in_free_flight = false
initial = { theta_mean_deg = 10.0, speed_mps = 10.0, tail_angle_deg = 10.0 }
EOT
check "optimisation -j 1" "$bin" run "$scratch/opt.toml" -j 1 -o "$scratch/opt_j1"
check "mpirun -n 3 optimisation" "${mpirun[@]}" -n 3 "$bin" optimize "$scratch/opt.toml" -o "$scratch/opt_mpi"
for f in history.csv best_vehicle.toml; do
  check "$f identical for mpirun -n 3 and -j 1" cmp "$scratch/opt_j1/$f" "$scratch/opt_mpi/$f"
done
check "evaluations counted as computed" test "$(json "$scratch/opt_mpi/summary.json" evaluations_computed)" = \
  "$(json "$scratch/opt_j1/summary.json" evaluations_computed)"

# Kill rank 1 in the middle of a 240-point map, then resume without MPI and with it.
big=(--speed 8:20:8 --freq 8:20:6 --theta 0:20:5)
check "240-point map -j 2" "$bin" aeromap "$efw" "${big[@]}" -j 2 -o "$scratch/big_ref"
killed="$scratch/big_killed"
"${mpirun[@]}" -n 3 "$bin" aeromap "$efw" "${big[@]}" -o "$killed" > /dev/null 2>&1 &
launcher=$!
journal="$killed/aeromap.journal"
for _ in $(seq 1 3000); do  # up to 30 s for 30 journaled points
  if [ -f "$journal" ] && [ "$(wc -l < "$journal")" -ge 31 ]; then break; fi
  if ! kill -0 "$launcher" 2>/dev/null; then break; fi
  sleep 0.01
done
rank1=""
for p in $(pgrep -P "$launcher"); do
  if tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1"; then rank1=$p; fi
done
if [ -n "$rank1" ]; then
  kill -9 "$rank1"
  wait "$launcher"; rc=$?
  check "the job ends with an error when rank 1 is lost ($rc)" test "$rc" -ne 0
  check "the journal is still there" test -f "$journal"
  lines=$(( $(wc -l < "$journal") - 1 ))
  echo "info rank 1 killed with $lines journaled points"
  cp -r "$killed" "$scratch/big_killed_mpi"
  check "resume without MPI exits 0" "$bin" aeromap "$efw" "${big[@]}" -j 1 -o "$killed"
  check "... byte-identical" cmp "$scratch/big_ref/aeromap.csv" "$killed/aeromap.csv"
  check "... journaled points not recomputed ($lines)" test "$(json "$killed/summary.json" points_resumed)" -eq "$lines"
  check "resume with mpirun -n 3 exits 0" "${mpirun[@]}" -n 3 "$bin" aeromap "$efw" "${big[@]}" -o "$scratch/big_killed_mpi"
  check "... byte-identical" cmp "$scratch/big_ref/aeromap.csv" "$scratch/big_killed_mpi/aeromap.csv"
  check "... journaled points not recomputed ($lines)" test "$(json "$scratch/big_killed_mpi/summary.json" points_resumed)" -eq "$lines"
else
  wait "$launcher"
  echo "FAIL kill rank 1: the map finished (or no rank 1 was found) before it could be killed"
  fail=1
fi
exit "$fail"
