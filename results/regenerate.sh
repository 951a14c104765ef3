#!/usr/bin/env bash
# Regenerate the committed paper results: run every study of studies/paper/ into results/paper/
# (and the literal wing's investigation, results/literal_wing_investigation.sh) and rebuild
# results/README.md from results/README.template.md and the new summaries/CSVs.
#
#   bash results/regenerate.sh [ORNITHOPTER [ORNI_RESULTS]]
#
# ORNITHOPTER defaults to build/studies/runner/ornithopter (relative to the repository root),
# ORNI_RESULTS (the README filler) to studies/tools/orni_results of the same build tree. -j is
# ${ORNI_JOBS:-2}. Journals (*.journal) are removed first so that nothing is resumed from an older
# run, and the run is timed into results/paper/regenerate_timing.json. Afterwards commit
# results/paper and results/README.md; tests/regression/paper_results.sh compares against them.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
# Paths given on the command line are relative to the caller's folder; the defaults to the root.
abs() { if [[ -e "$1" ]]; then echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; else echo "$1"; fi; }
if [[ $# -ge 1 ]]; then bin="$(abs "$1")"; else bin="$root/build/studies/runner/ornithopter"; fi
if [[ $# -ge 2 ]]; then set -- "$1" "$(abs "$2")"; fi
cd "$root"

# The filler sits beside the runner in the same build tree (studies/tools/ next to studies/runner/).
filler="${2:-$(dirname "$bin")/../tools/orni_results}"
jobs="${ORNI_JOBS:-2}"
out="results/paper"

for exe in "$bin" "$filler"; do
  if [[ ! -x "$exe" ]]; then
    echo "regenerate: $exe not found; build first:" >&2
    echo "  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j 2" >&2
    exit 2
  fi
done

mkdir -p "$out"
studies=(studies/paper/*.toml)
# Start clean: no journal of an older version is resumed, no stale file survives. Only the
# studies' own folders: literal_wing_investigation/ is results/literal_wing_investigation.sh's
# (run below; results/README.md quotes it).
for s in "${studies[@]}"; do
  d="$out/$(basename "$s" .toml)"
  if [[ -d "$d" ]]; then rm -rf "$d"; fi
done
start=$(date +%s.%N)
"$bin" run "${studies[@]}" -o "$out" -j "$jobs"
end=$(date +%s.%N)
rm -f "$out"/*/*.journal "$out"/*/*.tmp*
# The committed folders keep the PNGs only (.gitignore): the SVGs go, and every report
# (index.html, and results/paper/index.html over all the studies) is written again from what is
# committed, so that no committed report links an uncommitted file (cli.paper_results checks the
# committed reports in a browser on a fresh clone).
find "$out" -name '*.svg' -delete
"$bin" report "$out" >/dev/null

# The literal wing's investigation flies the same core (tethered runs and trims): regenerated with
# the studies so that the page never mixes two versions.
bash results/literal_wing_investigation.sh "$bin" >/dev/null

awk -v a="$start" -v b="$end" -v n="${#studies[@]}" -v j="$jobs" -v c="$(nproc 2>/dev/null || echo 0)" \
  'BEGIN { printf "{\n  \"command\": \"ornithopter run studies/paper/*.toml -o results/paper -j %s\",\n  \"studies\": %d,\n  \"cores\": %d,\n  \"wall_time_s\": %.1f\n}\n", j, n, c, b - a }' \
  > "$out/regenerate_timing.json"

"$filler" fill results/README.template.md results > results/README.md.tmp
mv results/README.md.tmp results/README.md
du -sh results | awk '{ print "regenerate: results/ is " $1 }'
echo "regenerate: done ($(grep wall_time_s "$out/regenerate_timing.json" | tr -d " ,")); commit results/paper and results/README.md"
