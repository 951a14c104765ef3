#!/usr/bin/env bash
# The README's speed table (between its speed:begin and speed:end markers), made from the output of
# the benchmarks (orni_bench, Google Benchmark, medians of 3 repetitions) and a timed 10,000-point
# aero map on 2 threads, with the machine they ran on. Prints the table; with --write also puts it
# into README.md. Takes 2-4 minutes; run it on an idle machine (the figures move by 10 % or more
# when another process shares the cores). With --instructions it also counts the instructions of
# one run of each 10-cycle kernel, the periodic trim and the periodic design evaluation under
# valgrind's callgrind (about 10 more minutes; stable where the times are not, and available where
# the machine exposes no hardware counters).
# --check only verifies that every benchmark the table names exists (tests/regression/
# speed_table_names.sh runs it), so that a renamed benchmark cannot leave a row "not run".
#   usage: bash tests/bench/speed_table.sh <build-dir> <repo-root> [--write] [--instructions]
#          bash tests/bench/speed_table.sh <build-dir> <repo-root> --check
set -euo pipefail
build=${1:?usage: speed_table.sh <build-dir> <repo-root> [--write] [--instructions]}
root=${2:?usage: speed_table.sh <build-dir> <repo-root> [--write] [--instructions]}
shift 2
mode='' instructions=''
for a in "$@"; do
  case $a in
    --write) mode=--write ;;
    --instructions) instructions=yes ;;
    --check) mode=--check ;;
    *) echo "speed_table: unknown option $a" >&2; exit 2 ;;
  esac
done
bench=$build/tests/orni_bench
cli=$build/studies/runner/ornithopter
[[ -x $bench && -x $cli ]] || { echo "speed_table: build $bench and $cli first" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cat >"$scratch/table.py" <<'EOF'
import json, sys
rows = [  # (what, benchmark, target in s or None)
    ("10 cycles of free flight, flexible wing (24 modes)", "BM_FreeEfwFlexible10Cycles", 5e-3),
    ("10 cycles of free flight, rigid wing", "BM_FreeEfwRigid10Cycles", 2e-3),
    ("10 tethered cycles, flexible wing, 24 modes",
     "BM_TetheredEfwFlexible10Cycles/explicit:0/modes:0/nonlinear:0", None),
    ("the same, 12 modes", "BM_TetheredEfwFlexible10Cycles/explicit:0/modes:12/nonlinear:0", 3e-3),
    ("the same, 24 modes, nonlinear (membrane) wing",
     "BM_TetheredEfwFlexible10Cycles/explicit:0/modes:0/nonlinear:1", None),
    ("10 tethered cycles recorded at 100 samples a cycle, loads interpolated (the default)",
     "BM_TetheredEfwFlexible10CyclesHistories/interpolated:1", None),
    ("the same, loads evaluated (`sampled_loads = \"evaluated\"`)",
     "BM_TetheredEfwFlexible10CyclesHistories/interpolated:0", None),
    ("two-stage trim at 12 Hz (Eq. 4, free-flight refinement and check)", "BM_TrimEfw12Hz", 0.5),
    ("periodic trim at 12 Hz with 8 Floquet multipliers", "BM_PeriodicTrimEfw12Hz", 0.15),
    ("a design evaluation of `optimize` (periodic trim, Floquet constraint)",
     "BM_DesignEvaluationPeriodicFloquet", 0.25),
    ("aero map, 180 points, 2 threads", "BM_AeroMapEfw180/threads:2/real_time", None),
    ("continuation of the periodic trim, 10-16 Hz, 30 points, 2 threads",
     "BM_ContinuationEfw/10/16/30/2/iterations:1", 3.0),
    ("the FE model and its 24 modes, linear wing", "BM_EfwModalWingBuild/modes:0/nonlinear:0", None),
    ("the same with the membrane's identification (nonlinear wing)",
     "BM_EfwModalWingBuild/modes:0/nonlinear:1", 0.5),
]

if sys.argv[1] == "check":  # check LIST: every row's benchmark is in orni_bench's list
    listed = set(open(sys.argv[2]).read().split())
    missing = [name for _, name, _ in rows if name not in listed]
    for name in missing:
        print(f"FAIL the speed table names {name}, which orni_bench does not have")
    print("ok   every benchmark of the speed table exists" if not missing else "")
    sys.exit(1 if missing else 0)

bench, map_summary, t0, t1, machine, instructions_file = sys.argv[2:]
instructions = {}
for line in open(instructions_file):
    name, count = line.split()
    instructions[name] = float(count)
data = json.load(open(bench))
median = {}
for b in data["benchmarks"]:
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median":
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
        median[b["run_name"]] = b["real_time"] * scale

def fmt(s):
    if s >= 1.0:
        return f"{s:.2f} s"
    return f"{s * 1e3:.1f} ms" if s < 0.1 else f"{s * 1e3:.0f} ms"

print(f"Measured by `bash tests/bench/speed_table.sh build .` on {machine}, "
      f"{data['context']['date'][:10]}; medians of 3 (`build/tests/orni_bench`), one thread "
      "unless said" + ("; instructions of one run counted by callgrind (`--instructions`)"
                       if instructions else "") + ".\n")
print("| what | benchmark | median | instructions | target |")
print("| --- | --- | --- | --- | --- |")
base = median.get("BM_TetheredEfwFlexible10Cycles/explicit:0/modes:0/nonlinear:0")
for what, name, target in rows:
    if name not in median:
        print(f"| {what} | `{name}` | not run | | |")
        continue
    value = fmt(median[name])
    if base and "Histories" in name:
        value += f" (+{100 * (median[name] / base - 1):.0f} %)"
    if base and name.endswith("nonlinear:1") and "Tethered" in name:
        value += f" ({median[name] / base:.0f}x the linear wing)"
    goal = "" if target is None else ("<= " + fmt(target) + (" met" if median[name] <= target else " not met"))
    if "Histories" in name:
        goal = "<= +20 %"
    if name.endswith("nonlinear:1") and "Tethered" in name:
        goal = "<= 2x the linear wing"
    count = f"{instructions[name] / 1e6:.1f} M" if name in instructions else ""
    print(f"| {what} | `{name}` | {value} | {count} | {goal} |")
summary = json.load(open(map_summary))
points, ok = summary["points"], summary["points_ok"]
wall = float(t1) - float(t0)
print(f"| **{points:,}-point aero map** (`aeromap efw_magpie.toml --speed 10:20:25 --freq 8:20:20 "
      f"--theta 0:20:20 -j 2`; {ok:,} points periodic) | CLI, wall time from start to exit "
      f"(the map itself: {summary['wall_time_s']:.1f} s) | **{wall:.1f} s**, "
      f"{1e3 * wall / points:.2f} ms a point | | <= 10 s{' met' if wall <= 10 else ' not met'} |")
EOF
if [[ $mode == --check ]]; then
  "$bench" --benchmark_list_tests=true >"$scratch/list.txt" 2>/dev/null
  python3 "$scratch/table.py" check "$scratch/list.txt"
  exit 0
fi

# The benchmarks of the speed issue's table, and what the histories and the nonlinear wing cost.
filter='^(BM_FreeEfwFlexible10Cycles|BM_FreeEfwRigid10Cycles'
filter+='|BM_TetheredEfwFlexible10Cycles/explicit:0/modes:(0|12)/nonlinear:0'
filter+='|BM_TetheredEfwFlexible10Cycles/explicit:0/modes:0/nonlinear:1'
filter+='|BM_TetheredEfwFlexible10CyclesHistories/interpolated:[01]'
filter+='|BM_TrimEfw12Hz|BM_PeriodicTrimEfw12Hz|BM_DesignEvaluationPeriodicFloquet'
filter+='|BM_AeroMapEfw180/threads:2/real_time|BM_ContinuationEfw/10/16/30/2/iterations:1'
filter+='|BM_EfwModalWingBuild/modes:0/nonlinear:[01])$'
"$bench" --benchmark_filter="$filter" --benchmark_repetitions=3 --benchmark_format=json \
  >"$scratch/bench.json" 2>"$scratch/bench.log" ||
  { cat "$scratch/bench.log" >&2; exit 1; }

# The 10,000-point map of paper Fig. 5's kind (the issue's grid), wall time on 2 threads.
t0=$(date +%s.%N)
"$cli" aeromap "$root/studies/vehicles/efw_magpie.toml" --speed 10:20:25 --freq 8:20:20 \
  --theta 0:20:20 -j 2 -o "$scratch/map" --no-figures >"$scratch/map.log" 2>&1 ||
  { cat "$scratch/map.log" >&2; exit 1; }
t1=$(date +%s.%N)

# Instructions of one iteration of a kernel: callgrind collecting inside the function the
# benchmark loop calls (not the model's set-up), divided by the iterations the benchmark ran.
count_instructions() {  # benchmark toggle-function
  local name=$1 fn=$2 out
  out=$scratch/cg_${name//[^A-Za-z0-9]/_}
  valgrind --tool=callgrind --callgrind-out-file="$out.cg" --toggle-collect="$fn" \
    "$bench" --benchmark_filter="^$name\$" --benchmark_min_time=0.01 --benchmark_format=json \
    >"$out.json" 2>"$out.log" || { echo "speed_table: callgrind of $name failed" >&2; return 1; }
  python3 -c 'import json, sys
ir = int(next(l for l in open(sys.argv[1]) if l.startswith("summary:")).split()[1])
its = json.load(open(sys.argv[2]))["benchmarks"][0]["iterations"]
print(sys.argv[3], ir / its)' "$out.cg" "$out.json" "$name" >>"$scratch/instructions.txt"
}
: >"$scratch/instructions.txt"
if [[ -n $instructions ]]; then
  command -v valgrind >/dev/null || { echo "speed_table: --instructions needs valgrind" >&2; exit 1; }
  # Two at a time (2 cores); each is the model's set-up plus one run, 50x slower than native.
  count_instructions BM_FreeEfwFlexible10Cycles 'orni::simulateFree*' &
  count_instructions BM_FreeEfwRigid10Cycles 'orni::simulateFree*' &
  wait
  count_instructions BM_TetheredEfwFlexible10Cycles/explicit:0/modes:0/nonlinear:0 \
    'orni::simulateTethered*' &
  count_instructions BM_TetheredEfwFlexible10Cycles/explicit:0/modes:12/nonlinear:0 \
    'orni::simulateTethered*' &
  wait
  count_instructions BM_TetheredEfwFlexible10CyclesHistories/interpolated:0 \
    'orni::simulateTethered*' &
  count_instructions BM_TetheredEfwFlexible10CyclesHistories/interpolated:1 \
    'orni::simulateTethered*' &
  wait
  # The two trims whose times this VM moves most (about 4 minutes each under callgrind).
  count_instructions BM_PeriodicTrimEfw12Hz 'orni::solvePeriodicTrim*' &
  count_instructions BM_DesignEvaluationPeriodicFloquet 'orni::opt::evaluateDesign*' &
  wait
fi

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
virt=$(systemd-detect-virt 2>/dev/null || true)
machine="$cpu, $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB${virt:+, virtualised ($virt)}"

python3 "$scratch/table.py" table "$scratch/bench.json" "$scratch/map/summary.json" "$t0" "$t1" \
  "$machine" "$scratch/instructions.txt" >"$scratch/table.md"
cat "$scratch/table.md"

if [[ $mode == --write ]]; then
  readme=$root/README.md
  begin='<!-- speed:begin (generated by `bash tests/bench/speed_table.sh build . --write`) -->'
  end='<!-- speed:end -->'
  grep -qxF -- "$begin" "$readme" && grep -qxF -- "$end" "$readme" ||
    { echo "speed_table: README.md has no block $begin ... $end" >&2; exit 1; }
  awk -v b="$begin" -v e="$end" -v f="$scratch/table.md" '
    $0 == b { print; while ((getline line < f) > 0) print line; skip = 1; next }
    $0 == e { skip = 0 }
    !skip { print }' "$readme" >"$scratch/README.md"
  cp "$scratch/README.md" "$readme"
  echo "wrote the speed table into $readme"
fi
