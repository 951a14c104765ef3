#!/usr/bin/env bash
# The layer check (issue 15): no #include in core/, trim/, optimize/, studies/ or python/ runs up
# a layer (tests/support/layer_rules.sh: model < aero, integrate, structure, analysis < dynamics
# < trim < optimize < studies < python). The checker is shown to catch an upward include and a
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
mkdir -p "$t/core/integrate"
echo '#include <vector>' > "$t/core/integrate/callback_guard.hpp"
echo '#include "core/integrate/callback_guard.hpp"' > "$t/core/integrate/e.cpp"
check "a private header included in its own folder passes" check_layers "$t"
echo '#include "core/integrate/callback_guard.hpp"' > "$t/core/dynamics/f.cpp"
check "a private header included from another folder fails" bash -c "! (source '$(dirname "${BASH_SOURCE[0]}")/../support/layer_rules.sh'; check_layers '$t' > /dev/null)"

# The repository.
report=$(check_layers "$root")
rc=$?
[[ -n $report ]] && echo "$report"
check "no include runs up a layer in the repository" test $rc -eq 0
exit $fail
