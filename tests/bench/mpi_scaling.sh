#!/usr/bin/env bash
# Scripted measurement of distributed runs (issue 18; docs/speed.md, docs/user-guide.md): the
# 180-point aero map of paper Fig. 5 (studies/paper/fig5_efw_aeromap.toml) single-process -j 1,
# and under mpirun with 1 and 2 worker ranks (-n 2 and -n 3: rank 0 is the master), wall times,
# the speed-up from 1 to 2 workers, the master's own line (messages, bytes, busy time per point),
# and the bytes of aeromap.csv against -j 1. Run it on an idle machine (it prints the load).
#   usage: bash tests/bench/mpi_scaling.sh <ornithopter-binary> <repo-root> <scratch-dir> [repeats]
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}; repeats=${4:-3}
# --bind-to none: Open MPI binds -n 2 to one core each (and -n 3, oversubscribed, to none); unbound
# ranks compare like with like and move off a core that another process takes.
mpirun=(mpirun --oversubscribe --bind-to none)
if [[ "$(id -u)" == 0 ]]; then mpirun+=(--allow-run-as-root); fi
study="$root/studies/paper/fig5_efw_aeromap.toml"
rm -rf "$scratch"; mkdir -p "$scratch"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# Best over `repeats` runs of the map's own time: the points phase that the run reports on stdout
# ("180 points (180 computed): ..., 0.81 s"), without the start-up, the FE model and the figures,
# which are the same for any rank count. The last run's output is kept.
best() {
  local label=$1; shift
  local t_best=""
  for _ in $(seq 1 "$repeats"); do
    rm -rf "$scratch/$label"
    "$@" -o "$scratch/$label" > "$scratch/$label.out" 2> "$scratch/$label.err" ||
      { echo "$label failed" >&2; cat "$scratch/$label.err" >&2; exit 1; }
    local t
    t=$(grep -m1 -oE '[0-9.e+-]+ s$' "$scratch/$label.out" | cut -d' ' -f1)
    if [[ -z "$t_best" ]] || awk "BEGIN { exit !($t < $t_best) }"; then t_best=$t; fi
  done
  echo "$t_best"
}
t_j1=$(best j1 "$bin" run "$study" -j 1)
t_j2=$(best j2 "$bin" run "$study" -j 2)
t_n2=$(best n2 "${mpirun[@]}" -n 2 "$bin" run "$study" -j 1)
t_n3=$(best n3 "${mpirun[@]}" -n 3 "$bin" run "$study" -j 1)
printf 'single process -j 1:        %.3f s\n' "$t_j1"
printf 'single process -j 2:        %.3f s\n' "$t_j2"
printf 'mpirun -n 2 (1 worker):     %.3f s\n' "$t_n2"
printf 'mpirun -n 3 (2 workers):    %.3f s\n' "$t_n3"
awk "BEGIN { printf \"speed-up 1 -> 2 workers:    %.2f\\n\", $t_n2 / $t_n3 }"
awk "BEGIN { printf \"speed-up -j 1 -> 2 workers: %.2f\\n\", $t_j1 / $t_n3 }"
grep -h "^mpi:" "$scratch/n2.err" "$scratch/n3.err"
for d in n2 n3; do
  if cmp -s "$scratch/j1/aeromap.csv" "$scratch/$d/aeromap.csv"; then
    echo "$d: aeromap.csv byte-identical to -j 1"
  else
    echo "$d: aeromap.csv DIFFERS from -j 1"; exit 1
  fi
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
