# Figure 'sensitivity_overview' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'sensitivity_overview.png.tmp'
set label 101 "sensitivity_magpie: the swing of each prediction over each parameter's range" at screen 0.5, 0.975 center noenhanced font ',13'
set label 102 "as a share of that prediction's largest swing (in brackets); empty: an end without a value (see tornado_<prediction> and sensitivity.csv)" at screen 0.5, 0.945 center noenhanced font ',10'
set tmargin at screen 0.91
set lmargin at screen 0.30
set bmargin at screen 0.22
set rmargin at screen 0.88
set xrange [0.5:14.5]
set yrange [0.5:9.5]
set xtics ("theta_mean_deg (3.681 deg)" 1, "speed_mps (4.17 m/s)" 2, "tail_angle_deg (9.317 deg)" 3, "hinge_power_W (0.261 W)" 4, "pitch_swing_deg (7.184 deg)" 5, "altitude_p2p_m (0.002577 m)" 6, "altitude_p2p_slow_m (0.5492 m)" 7, "norm_ratio_max (1.579)" 8, "CF_V_min (0.01902)" 9, "CF_V_max (0.2586)" 10, "CF_H_min (0.04267)" 11, "CF_H_max (0.04545)" 12, "CM_CG_min (0.05666)" 13, "CM_CG_max (0.04527)" 14) rotate by 40 right noenhanced font ',9'
set ytics ("body.pitch_inertia_kgm2" 9, "kinematics.hinge_x_m" 8, "body.drag_area_m2" 7, "materials.LE1.youngs_modulus_gpa" 6, "materials.CFRP_ROD.youngs_modulus_gpa" 5, "wing.p3_aft_of_le_m" 4, "aero.suction_efficiency" 3, "wing.skin.pretension_N_per_m" 2, "wing.fe.damping_ratio" 1) noenhanced font ',9'
unset grid
unset key
set cbrange [0:1]
set palette defined (0 '#ffffff', 1 '#c0392b')
set cblabel 'swing / largest swing of the prediction'
set style fill solid 1.0 border rgb '#999999'
plot 'tornado.csv' skip 2 using ($3):(10-$6):(($3)-0.5):(($3)+0.5):((10-$6)-0.5):((10-$6)+0.5):($14) with boxxyerror lc palette, \
  'tornado.csv' skip 2 using ($3):(10-$6):(sprintf('%.2f', ($14))) with labels font ',8'

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'sensitivity_overview.svg.tmp'
set label 101 "sensitivity_magpie: the swing of each prediction over each parameter's range" at screen 0.5, 0.975 center noenhanced font ',13'
set label 102 "as a share of that prediction's largest swing (in brackets); empty: an end without a value (see tornado_<prediction> and sensitivity.csv)" at screen 0.5, 0.945 center noenhanced font ',10'
set tmargin at screen 0.91
set lmargin at screen 0.30
set bmargin at screen 0.22
set rmargin at screen 0.88
set xrange [0.5:14.5]
set yrange [0.5:9.5]
set xtics ("theta_mean_deg (3.681 deg)" 1, "speed_mps (4.17 m/s)" 2, "tail_angle_deg (9.317 deg)" 3, "hinge_power_W (0.261 W)" 4, "pitch_swing_deg (7.184 deg)" 5, "altitude_p2p_m (0.002577 m)" 6, "altitude_p2p_slow_m (0.5492 m)" 7, "norm_ratio_max (1.579)" 8, "CF_V_min (0.01902)" 9, "CF_V_max (0.2586)" 10, "CF_H_min (0.04267)" 11, "CF_H_max (0.04545)" 12, "CM_CG_min (0.05666)" 13, "CM_CG_max (0.04527)" 14) rotate by 40 right noenhanced font ',9'
set ytics ("body.pitch_inertia_kgm2" 9, "kinematics.hinge_x_m" 8, "body.drag_area_m2" 7, "materials.LE1.youngs_modulus_gpa" 6, "materials.CFRP_ROD.youngs_modulus_gpa" 5, "wing.p3_aft_of_le_m" 4, "aero.suction_efficiency" 3, "wing.skin.pretension_N_per_m" 2, "wing.fe.damping_ratio" 1) noenhanced font ',9'
unset grid
unset key
set cbrange [0:1]
set palette defined (0 '#ffffff', 1 '#c0392b')
set cblabel 'swing / largest swing of the prediction'
set style fill solid 1.0 border rgb '#999999'
plot 'tornado.csv' skip 2 using ($3):(10-$6):(($3)-0.5):(($3)+0.5):((10-$6)-0.5):((10-$6)+0.5):($14) with boxxyerror lc palette, \
  'tornado.csv' skip 2 using ($3):(10-$6):(sprintf('%.2f', ($14))) with labels font ',8'

unset output
