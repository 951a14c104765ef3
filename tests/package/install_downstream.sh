#!/usr/bin/env bash
# package.install_downstream: `cmake --install` of the build tree into a temporary prefix, then the
# C++ downstream example (examples/cpp_downstream) configured with find_package(ornithopter)
# against that prefix only, built and run on a vehicle; the installed CLI's --version and the
# installed Python module (when built) report the same version.
# Usage: install_downstream.sh BUILD_DIR SOURCE_DIR WORK_DIR VERSION [PYTHON_SITE_SUBDIR]
set -euo pipefail
build="$1" src="$2" work="$3" version="$4" pysite="${5:-}"
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in lib/cmake/ornithopter/ornithopterConfig.cmake \
         lib/cmake/ornithopter/ornithopterConfigVersion.cmake \
         lib/cmake/ornithopter/ornithopterTargets.cmake \
         include/ornithopter/core/version.hpp include/ornithopter/core/model/vehicle_model.hpp \
         include/ornithopter/trim/trim_solver.hpp include/ornithopter/optimize/optimizer.hpp \
         bin/ornithopter; do
  [[ -e "$prefix/$f" ]] || { echo "FAIL: not installed: $f"; exit 1; }
done
# Private headers stay private (an implementation detail: the ODE integrator's callback guard).
if [[ -e "$prefix/include/ornithopter/core/integrate/callback_guard.hpp" ]]; then
  echo "FAIL: a private header was installed"; exit 1
fi

"$prefix/bin/ornithopter" --version | tee "$work/version.txt"
grep -q "^ornithopter $version (git " "$work/version.txt" || { echo "FAIL: --version is not $version"; exit 1; }

# The downstream project sees nothing of the source tree: only the prefix.
cmake -S "$src/examples/cpp_downstream" -B "$work/downstream" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/downstream" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
# No architecture flag reaches the consumer (the package carries Eigen's alignment instead), and
# every header the example read from the prefix is under include/ornithopter/.
if grep -rq -- "-march" "$work/downstream/CMakeFiles/tethered_run.dir/flags.make"; then
  echo "FAIL: the package imposes -march on its consumer:"
  grep -- "-march" "$work/downstream/CMakeFiles/tethered_run.dir/flags.make"; exit 1
fi
deps=$(find "$work/downstream/CMakeFiles/tethered_run.dir" -name '*.o.d' | head -1)
[[ -n "$deps" ]] || { echo "FAIL: no dependency file of the example's object"; exit 1; }
outside=$(tr ' \\' '\n\n' <"$deps" | grep "^$prefix/" | { grep -v "^$prefix/include/ornithopter/" || true; } | sort -u)
if [[ -n "$outside" ]]; then echo "FAIL: headers outside include/ornithopter/:"; echo "$outside"; exit 1; fi
inside=$(tr ' \\' '\n\n' <"$deps" | grep -c "^$prefix/include/ornithopter/")
echo "downstream: no -march; ${inside} headers read from $prefix/include/ornithopter/"
"$work/downstream/tethered_run" "$src/studies/vehicles/rfw_tunnel.toml" | tee "$work/run.txt"
grep -q "^ornithopter $version: ok" "$work/run.txt" || { echo "FAIL: downstream run not ok"; exit 1; }

if [[ -n "$pysite" ]]; then
  got=$(cd "$work" && PYTHONPATH="$prefix/$pysite" "${PYTHON:-python3}" -c \
    'import ornithopter, os; print(ornithopter.__version__); print(ornithopter.__file__)')
  echo "python: $got"
  [[ "$(sed -n 1p <<<"$got")" == "$version" ]] || { echo "FAIL: python __version__"; exit 1; }
  [[ "$(sed -n 2p <<<"$got")" == "$prefix/"* ]] || { echo "FAIL: module not from the prefix"; exit 1; }
fi
echo "package.install_downstream: ok"
