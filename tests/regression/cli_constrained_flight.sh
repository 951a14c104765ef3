#!/usr/bin/env bash
# The constrained flight test (paper Fig. 9, Eq. 7; issue acceptance "The constrained flight test
# writes the coefficient histories and epsilon(delta_M)"): the Fig. 9 study writes zmp.csv with
# its names and units rows, one whole cycle, strokes by the sign of d delta_M/dt, no NaN, an
# empty epsilon cell (never "nan") at the singular points, coefficients consistent with
# histories.csv, the summary object, the figure that `plot` redraws, and the same bytes again from
# the resolved study.
#   usage: bash cli_constrained_flight.sh <ornithopter-binary> <repo-root> <scratch-dir>
set -u
bin=${1:?}; root=${2:?}; scratch=${3:?}
rm -rf "$scratch"; mkdir -p "$scratch"
# check, json, awk_true and fail=0
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_checks.sh"

out="$scratch/fig9"
check "Fig. 9 study exits 0" "$bin" run "$root/studies/paper/fig9_constrained_flight_test.toml" -o "$out"
for f in zmp.csv zmp.png zmp.svg zmp.gp histories.csv summary.json study.resolved.toml; do
  check "writes $f" test -s "$out/$f"
done
z="$out/zmp.csv"
check "zmp.csv names row" test "$(sed -n 1p "$z")" = "t,delta_M,stroke,CF_V,CF_H,CM_CG,epsilon,CF_normal"
check "zmp.csv units row" test "$(sed -n 2p "$z")" = "s,deg,-,-,-,-,-,-"
check "one whole cycle: 100 rows (samples_per_cycle, endpoint excluded)" \
  test "$(( $(wc -l < "$z") - 2 ))" -eq 100
check "no nan or inf in zmp.csv" bash -c "! grep -qiE 'nan|inf' '$z'"
check "every row has 8 cells" bash -c "awk -F, 'NR > 2 && NF != 8 { bad = 1 } END { exit bad }' '$z'"
check "numbers in every cell but epsilon" bash -c "awk -F, 'NR > 2 { for (i = 1; i <= 8; ++i)
  if (i != 3 && i != 7 && \$i !~ /^-?[0-9.]+(e[-+]?[0-9]+)?\$/) bad = 1 } END { exit bad }' '$z'"
check "epsilon is a number or an empty cell" bash -c "awk -F, 'NR > 2 && \$7 != \"\" &&
  \$7 !~ /^-?[0-9.]+(e[-+]?[0-9]+)?\$/ { bad = 1 } END { exit bad }' '$z'"
check "50 downstroke and 50 upstroke samples" bash -c "[ \$(grep -c ',down,' '$z') -eq 50 ] && [ \$(grep -c ',up,' '$z') -eq 50 ]"
# delta_M = A sin(2 pi f t): "down" exactly where delta_M decreases (central difference; the two
# reversal samples, where it is zero, are skipped).
check "down where delta_M decreases, up where it increases" bash -c "awk -F, '
  NR > 2 { d[NR] = \$2; s[NR] = \$3; n = NR }
  END { for (i = 4; i < n; ++i) { c = d[i + 1] - d[i - 1];
          if (c < -1e-6 && s[i] != \"down\") bad = 1; if (c > 1e-6 && s[i] != \"up\") bad = 1 }
        exit bad }' '$z'"
defined=$(json "$out/summary.json" defined_samples)
empty=$(awk -F, 'NR > 2 && $7 == "" { ++n } END { print n + 0 }' "$z")
check "empty epsilon cells = samples - defined_samples ($empty = 100 - $defined)" \
  test "$empty" -eq "$((100 - defined))"
check "epsilon defined on most of the cycle ($defined of 100)" test "$defined" -ge 50

# Coefficients against the dimensional loads of histories.csv at the same instants.
q=$(json "$out/summary.json" dynamic_pressure_Pa); S=$(json "$out/summary.json" wing_area_m2)
c=$(json "$out/summary.json" mean_chord_m)
check "CF_V, CF_H, CM_CG = FV/(qS), FH/(qS), M/(qSc) (histories.csv)" bash -c "awk -F, -v q='$q' -v S='$S' -v c='$c' '
  FNR <= 2 { next }
  FILENAME ~ /histories/ { fv[\$1] = \$3; fh[\$1] = \$4; m[\$1] = \$5; next }
  { if (!(\$1 in fv)) { bad = 1; next }
    if ((\$4 - fv[\$1] / (q * S))^2 > 1e-20 || (\$5 - fh[\$1] / (q * S))^2 > 1e-20 ||
        (\$6 - m[\$1] / (q * S * c))^2 > 1e-20) bad = 1; ++n }
  END { exit bad || n != 100 }' '$out/histories.csv' '$z'"

# summary.json: the constrained_flight_test object, never NaN.
for key in constrained_flight_test reference CF_V CF_H CM_CG epsilon singular_fraction upstroke \
           downstroke weighted_mean of_mean_loads; do
  check "summary has $key" grep -q "\"$key\":" "$out/summary.json"
done
check "no NaN in summary.json" bash -c "! grep -qi nan '$out/summary.json'"
# The study flies at the vehicle's own trim (at_trim): the constrained flight test's reference
# (the last theta_mean_deg of the summary) is the flown theta (theta_deg), which is the trim's.
ref_theta=$(grep '"theta_mean_deg":' "$out/summary.json" | tail -1 | sed -E 's/.*: *([-+0-9.eE]+).*/\1/')
check "theta_mean_deg of the reference is the flown theta" \
  awk "BEGIN { exit !(($ref_theta - $(json "$out/summary.json" theta_deg))^2 < 1e-20) }"
check "the flown theta is the trim's" \
  awk "BEGIN { exit !(($(json "$out/summary.json" theta_deg) - $(json "$out/summary.json" theta_mean_deg))^2 < 1e-20) }"

# Figure: Fig. 9 layout, redrawn by `plot`.
check "figure script plots epsilon against delta_M per stroke" \
  bash -c "grep -q \"strcol(3) eq 'up'\" '$out/zmp.gp' && grep -q \"strcol(3) eq 'down'\" '$out/zmp.gp'"
rm -f "$out/zmp.png" "$out/zmp.svg"
check "plot redraws zmp" "$bin" plot "$out"
check "zmp.png and zmp.svg back" test -s "$out/zmp.png" -a -s "$out/zmp.svg"

# The resolved study re-runs to the same bytes.
check "resolved study re-runs" "$bin" run "$out/study.resolved.toml" -o "$scratch/again"
check "same zmp.csv from the resolved study" cmp -s "$z" "$scratch/again/zmp.csv"

# `ornithopter simulate` (tethered) writes it too.
check "simulate writes zmp.csv" bash -c "'$bin' simulate '$root/studies/vehicles/rfw_tunnel.toml' --cycles 3 -o '$scratch/rfw' >/dev/null && test -s '$scratch/rfw/zmp.csv' && ! grep -qi nan '$scratch/rfw/zmp.csv'"
exit $fail
