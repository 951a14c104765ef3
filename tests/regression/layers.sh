#!/usr/bin/env bash
# The layer check (issue 15): no #include in core/, trim/, optimize/, studies/ or python/ runs up
# a layer (tests/support/layer_rules.sh: model < aero, integrate, structure, analysis < dynamics
# < trim < optimize < studies < python; grid beside aero..analysis, below trim; inside
# studies/runner config < output < distributed < points < plotting < commands < cli, mpi). The checker is shown to catch an upward include and a
# cycle in a scratch tree first, so that this test can fail; likewise a private header of a core
# folder (ORNI_PRIVATE_HEADERS) included from another folder.
#   usage: bash layers.sh <ornithopter-binary (unused)> <repo-root> <scratch-dir>
set -u
root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh"
root=$(cd "$root" && pwd)

# The checker on a small tree: a clean one passes, an upward include and a cycle fail.
t="$scratch/tree"
mkdir -p "$t/core/model" "$t/core/analysis" "$t/core/dynamics" "$t/trim" "$t/studies"
echo '#include "core/model/a.hpp"' > "$t/core/analysis/b.hpp"
echo '#include "core/analysis/b.hpp"' > "$t/core/dynamics/c.hpp"
echo '#include "core/dynamics/c.hpp"' > "$t/trim/d.hpp"
echo '#include <vector>' > "$t/core/model/a.hpp"
check "a clean tree passes" check_layers "$t"
echo '#include "trim/d.hpp"' > "$t/core/model/up.hpp"
check "an include from core/model up to trim fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"
rm "$t/core/model/up.hpp"
echo '#include "core/dynamics/c.hpp"' > "$t/core/analysis/cycle.hpp"
check "an analysis -> dynamics cycle fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"
rm "$t/core/analysis/cycle.hpp"
# core/grid sits beside aero..analysis: on core/model only, included from trim and above.
mkdir -p "$t/core/grid"
echo '#include "core/model/a.hpp"' > "$t/core/grid/g.hpp"
echo '#include "core/grid/g.hpp"' > "$t/trim/h.cpp"
echo '#include "core/grid/g.hpp"' > "$t/studies/i.cpp"
check "core/grid on core/model, included from trim and studies, passes" check_layers "$t"
for up in core/analysis/b.hpp core/dynamics/c.hpp trim/d.hpp; do
  echo "#include \"$up\"" > "$t/core/grid/up.hpp"
  check "an include from core/grid of ${up%/*} fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"
done
rm "$t/core/grid/up.hpp"
echo '#include "core/grid/g.hpp"' > "$t/core/dynamics/j.cpp"
check "an include from core/dynamics of core/grid (not linked) fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"
rm "$t/core/dynamics/j.cpp"
mkdir -p "$t/core/integrate"
echo '#include <vector>' > "$t/core/integrate/callback_guard.hpp"
echo '#include "core/integrate/callback_guard.hpp"' > "$t/core/integrate/e.cpp"
check "a private header included in its own folder passes" check_layers "$t"
echo '#include "core/integrate/callback_guard.hpp"' > "$t/core/dynamics/f.cpp"
check "a private header included from another folder fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"

# Inside core/dynamics: a result header including a driver header runs back up.
rm "$t/core/dynamics/f.cpp"
echo '#include <vector>' > "$t/core/dynamics/free_flight.hpp"
echo '#include "core/dynamics/load_sample.hpp"' > "$t/core/dynamics/flight_path_frame.hpp"
echo '#include <vector>' > "$t/core/dynamics/load_sample.hpp"
check "a result header on a result header passes" check_layers "$t"
echo '#include "core/dynamics/free_flight.hpp"' > "$t/core/dynamics/free_flight_recorder.hpp"
check "a result header including a driver header fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"
rm "$t/core/dynamics/free_flight_recorder.hpp"
# Inside studies/runner: a command may include a figure, a figure may not include a command.
mkdir -p "$t/studies/runner/commands" "$t/studies/runner/plotting"
echo '#include <string>' > "$t/studies/runner/commands/run.hpp"
echo '#include <string>' > "$t/studies/runner/plotting/fig.hpp"
echo '#include "studies/runner/plotting/fig.hpp"' > "$t/studies/runner/commands/run.cpp"
check "a command including a figure passes" check_layers "$t"
echo '#include "studies/runner/commands/run.hpp"' > "$t/studies/runner/plotting/fig.cpp"
check "a figure including a command fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"
rm "$t/studies/runner/plotting/fig.cpp"

# The repository.
report=$(check_layers "$root")
rc=$?
[[ -n $report ]] && echo "$report"
check "no include runs up a layer in the repository" test $rc -eq 0
exit $fail
