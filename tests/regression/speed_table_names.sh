#!/usr/bin/env bash
# The README's speed table (tests/bench/speed_table.sh) names its benchmarks: each must exist in
# orni_bench, or a renamed benchmark would leave its row "not run" at the next regeneration.
# Skipped (exit 77) when the benchmarks are not built (no Google Benchmark).
#   usage: bash speed_table_names.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}
build=$(cd "$(dirname "$bin")/../.." && pwd)
if [[ ! -x $build/tests/orni_bench ]]; then
  echo "SKIPPED: $build/tests/orni_bench is not built (needs Google Benchmark)"
  exit 77
fi
bash "$root/tests/bench/speed_table.sh" "$build" "$root" --check
