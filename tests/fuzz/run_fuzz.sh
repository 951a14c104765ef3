#!/usr/bin/env bash
# Run the readers' fuzz target (fuzz_readers.cpp) for a time budget and report executions and
# coverage; exit 1 on any crash, sanitizer report, finding, hang (> 20 s on one input) or memory
# blow-up (> 2 GB).
#   usage: bash tests/fuzz/run_fuzz.sh <orni_fuzz_readers> [seconds=60] [work-dir=build-fuzz/run]
# Seed corpus: every vehicle and study of studies/ and every malformed file of tests/data/bad
# (their vehicle paths rewritten to be relative to studies/paper/, where the target pretends its
# input lives). The corpus grows in WORK/corpus and is reused by the next run; crash and timeout
# reproducers are written to WORK/artifacts/.
set -euo pipefail
fuzzer=${1:?usage: run_fuzz.sh <orni_fuzz_readers> [seconds] [work-dir]}
seconds=${2:-60}
root="$(cd "$(dirname "$0")/../.." && pwd)"
work=${3:-$root/build-fuzz/run}
fuzzer="$(cd "$(dirname "$fuzzer")" && pwd)/$(basename "$fuzzer")"
mkdir -p "$work/seeds" "$work/corpus" "$work/artifacts"

n=0
for f in "$root"/studies/vehicles/*.toml "$root"/studies/paper/*.toml "$root"/studies/examples/*.toml \
         "$root"/tests/data/bad/*.toml; do
  n=$((n + 1))
  sed -e 's#"\.\./\.\./\.\./studies/vehicles/#"../vehicles/#' \
      -e 's#"\.\./\.\./\.\./studies/paper/#"../paper/#' "$f" > "$work/seeds/$(basename "$f")"
done
echo "fuzz: $n seed files; ${seconds} s; reproducers go to $work/artifacts/"

log="$work/fuzz.log"
set +e
# One worker, one job: the budget is wall time on a shared 2-core machine.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$fuzzer" "$work/corpus" "$work/seeds" -max_total_time="$seconds" -timeout=20 \
  -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
  > "$log" 2>&1
rc=$?
set -e
# Coverage: instrumented edges of the binary, then the first and last status lines
# ("#N INITED|DONE cov: C ft: F corp: ...": C edges covered, F features) and the statistics.
grep -m1 -E 'INFO: Seed:' "$log" || true
grep -m1 -E 'INFO: Loaded [0-9]+ modules' "$log" || true
grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)' "$log" || true
grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb|new_units_added)' \
  "$log" || true
if [[ $rc -ne 0 ]] || grep -qE 'ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer)|FINDING|runtime error:' "$log"; then
  echo "fuzz: FAILED (exit $rc); the end of $log:"
  tail -40 "$log"
  exit 1
fi
echo "fuzz: 0 crashes, 0 hangs, 0 findings"
