#!/usr/bin/env bash
# Why does the literal Table 1 wing twist so much and lift so little? (issue 13 item 1)
#
# Flies studies/vehicles/efw_magpie.toml (Table 1's members and skin read literally: solid rods
# of the listed diameters) at the Table 3 point (theta 9.2 deg, U 10.8 m/s, f 12 Hz, tethered,
# the main wing alone: no tail, no body drag) for each candidate cause, one change at a time, and
# tabulates the tip twist and tip deflection amplitudes, the mean FV and FH of the wing pair, the
# static lift (no flapping: 0.5 Hz, 0.01 deg), the first mode, and where the whole vehicle with
# that change trims at 12 Hz (theta, U, tail angle). Writes
# results/paper/literal_wing_investigation/investigation.csv (names and units rows);
# results/README.md quotes it. About 3 minutes.
#
#   bash results/literal_wing_investigation.sh [path/to/ornithopter]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bin="${1:-$here/../build/studies/runner/ornithopter}"
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
vehicle="$here/../studies/vehicles/efw_magpie.toml"
out="$here/paper/literal_wing_investigation"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# name | what changes | [override] lines (separated by ';'), on top of the literal wing
candidates=(
  "literal|Table 1 read literally: solid rods; P3 universal joint with cross axis normal|"
  "rigid|the same wing rigid (no deformation)|wing.structure = \"rigid\""
  "p3_cross_span|P3 universal joint with cross axis span (rotation about y_W held): the committed vehicle|wing.fe.p3_cross_axis = \"span\""
  "nonlinear|the committed vehicle's wing (P3 cross axis span) geometrically nonlinear: the skin and members stretch (24 modes; not yet the default)|wing.fe.p3_cross_axis = \"span\";wing.fe.nonlinear = true"
  "p3_spherical|P3 ball joint (no rotation held)|wing.fe.p3_joint = \"spherical\""
  "p3_revolute_x|P3 pin along the flapping axis only (rotations about y_W and z_W held)|wing.fe.p3_joint = \"revolute_x\""
  "p3_clamped|stiffener roots driven in flap (P3 clamped)|wing.fe.p3_joint = \"clamped\""
  "root_edge_pinned|skin root edge pinned along the hinge line|wing.fe.root_edge = \"pinned\""
  "p3_quarter|P3 at 0.25 c0 (26 mm)|wing.p3_aft_of_le_m = 0.026"
  "p3_three_quarter|P3 at 0.75 c0 (78 mm)|wing.p3_aft_of_le_m = 0.078"
  "root_chord_123|root chord 123 mm (Table 2's aspect ratio instead of its area)|wing.root_chord_m = 0.123"
  "rods_600gpa|every rod at 600 GPa (the top of carbon)|materials.LE1.youngs_modulus_gpa = 600.0;materials.LE2.youngs_modulus_gpa = 600.0;materials.CFRP_ROD.youngs_modulus_gpa = 600.0"
  "rods_1200gpa|every rod at 1200 GPa, twice any carbon (a probe, not a design; the field table's upper bound: the old 100-times probe is no longer a valid vehicle)|materials.LE1.youngs_modulus_gpa = 1200.0;materials.LE2.youngs_modulus_gpa = 1200.0;materials.CFRP_ROD.youngs_modulus_gpa = 1200.0"
  "skin_x10|skin 10 times stiffer (a probe: the skin's bending carries the chord)|materials.SKIN.youngs_modulus_gpa = 1000.0"
  "no_stall|no stall (stall angles +-60 deg)|aero.stall_angle_max_deg = 60.0;aero.stall_angle_min_deg = -60.0"
  "suction_half|leading-edge suction efficiency 0.5|aero.suction_efficiency = 0.5"
  "diameters_x3115|the first wave's fit: every diameter x 3.115 (7 times the mass)|wing.member_diameter_scale = 3.11465"
  "softening_only|spin softening without geometric stiffening (the model before docs/theory.md 4.6)|wing.fe.inertial_stiffness = \"softening_only\""
  "no_inertial_stiffness|neither spin softening nor geometric stiffening|wing.fe.inertial_stiffness = \"none\""
)

overrides() {  # the base (the paper's reading of the universal joint) and the candidate's lines
  echo "wing.fe.p3_cross_axis = \"normal\""
  local IFS=';'
  for line in $1; do [[ -n "$line" ]] && echo "$line"; done
}

study() {  # name kind extra-overrides section
  local file="$work/$1.toml"
  {
    echo "kind = \"$2\""
    echo "vehicle = \"$vehicle\""
    echo "[override]"
    overrides "$3" | tac | awk -F' = ' '!seen[$1]++' | tac  # the last value of a key wins
    echo "$4"
  } > "$file"
  echo "$file"
}

json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); v=d
for k in sys.argv[2].split('.'): v=v[k]
print(v)" "$1" "$2"; }

rows=()
for c in "${candidates[@]}"; do
  IFS='|' read -r name what lines <<< "$c"
  flap=$(study "$name" simulate "$lines" $'[simulate]\nmode = "tethered"\nspeed_mps = 10.8\nfreq_hz = 12.0\ntheta_deg = 9.2\ncycles = 20\nwing_only = true')
  static=$(study "${name}_static" simulate "$lines" $'[simulate]\nmode = "tethered"\nspeed_mps = 10.8\nfreq_hz = 0.5\ntheta_deg = 9.2\ncycles = 3\nwing_only = true')
  "$bin" run "$flap" -o "$work/r_$name" > /dev/null
  # The static run: flapping amplitude 0.01 deg at 0.5 Hz (a wing held at theta in the tunnel).
  sed -i 's/^\[override\]$/[override]\nkinematics.amplitude_deg = 0.01/' "$static"
  "$bin" run "$static" -o "$work/s_$name" > /dev/null
  trim=$(study "${name}_trim" trim "$lines" $'[trim]\nfreq_hz = 12.0')
  "$bin" run "$trim" -o "$work/t_$name" > /dev/null
  t="$work/t_$name/summary.json"
  trim_status=$(json "$t" status)
  trim_converged=$([[ "$trim_status" == "ok" ]] && echo 1 || echo 0)
  if [[ "$trim_status" == "ok" || "$trim_status" == "not_converged" ]]; then  # the point reached
    trim_theta=$(printf '%.2f' "$(json "$t" theta_mean_deg)")
    trim_speed=$(printf '%.2f' "$(json "$t" speed_mps)")
    trim_tail=$(printf '%.2f' "$(json "$t" tail_angle_deg)")
  else
    trim_theta=""; trim_speed=""; trim_tail=""
  fi
  s="$work/r_$name/summary.json"
  structure=$(json "$s" structure)
  if [[ "$structure" == "flexible" ]]; then
    modes=$(study "${name}_modes" modes "$lines" "")
    "$bin" run "$modes" -o "$work/m_$name" > /dev/null
    f1=$(python3 -c "import json; print('%.1f' % json.load(open('$work/m_$name/summary.json'))['frequencies_hz'][0])")
    mass=$(python3 -c "import json; print('%.2f' % (1000*json.load(open('$work/m_$name/summary.json'))['wing_mass_kg']))")
    twist=$(printf '%.1f' "$(json "$s" last_cycle.tip_twist_amplitude_deg)")
    defl=$(python3 -c "print('%.1f' % (1000*$(json "$s" last_cycle.tip_deflection_amplitude_m)))")
  else
    f1=""; twist="0.0"; defl="0.0"
    mass=$(printf '%.2f' "$(python3 -c "print(1000*$(json "$s" wing_mass_kg))")")
  fi
  fv=$(printf '%.3f' "$(json "$s" mean.FV_N)")
  fh=$(printf '%.3f' "$(json "$s" mean.FH_N)")
  fv_static=$(printf '%.3f' "$(json "$work/s_$name/summary.json" mean.FV_N)")
  rows+=("$name,${what//,/;},$mass,$f1,$twist,$defl,$fv,$fh,$fv_static,$trim_status,$trim_converged,$trim_theta,$trim_speed,$trim_tail")
  echo "  $name: twist $twist deg, deflection $defl mm, FV $fv N, FH $fh N, static FV $fv_static N, f1 $f1 Hz; trim $trim_status $trim_theta deg $trim_speed m/s $trim_tail deg"
done

mkdir -p "$out"
tmp="$out/investigation.csv.tmp.$$"
{
  echo "candidate,change,wing_mass_g,first_mode_hz,tip_twist_amplitude_deg,tip_deflection_amplitude_mm,FV_mean_N,FH_mean_N,FV_static_N,trim_status,trim_converged,trim_theta_mean_deg,trim_speed_mps,trim_tail_angle_deg"
  echo "-,-,g,Hz,deg,mm,N,N,N,-,1=yes,deg,m/s,deg"
  printf '%s\n' "${rows[@]}"
} > "$tmp"
mv "$tmp" "$out/investigation.csv"
echo "-> $out/investigation.csv"
