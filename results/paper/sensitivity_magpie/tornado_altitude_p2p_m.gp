# Figure 'tornado_altitude_p2p_m' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'tornado_altitude_p2p_m.png.tmp'
set label 101 "sensitivity_magpie: altitude_p2p_m (free flight: altitude peak-to-peak at the flapping frequency)" at screen 0.5, 0.975 center noenhanced font ',13'
set label 102 "base vehicle: 0.005954 m; bars: the change with the parameter at the low and at the high end of its range, largest swing on top" at screen 0.5, 0.945 center noenhanced font ',10'
set tmargin at screen 0.91
set xlabel "change of altitude_p2p_m from the base vehicle's value (m)" noenhanced
set lmargin at screen 0.40
set rmargin at screen 0.96
set yrange [0.4:9.6]
set ytics ("kinematics.hinge_x_m: 0.01 .. 0.042 m (base 0.015)" 9, "body.pitch_inertia_kgm2: 4e-05 .. 0.00032 kg m^2 (base 0.00017)" 8, "aero.suction_efficiency: 0.3 .. 1 (base 0.98)" 7, "wing.skin.pretension_N_per_m: 0 .. 30 N/m (base 0)" 6, "wing.fe.damping_ratio: 0.005 .. 0.05 (base 0.015)" 5, "materials.CFRP_ROD.youngs_modulus_gpa: 100 .. 400 GPa (base 175)\nno value at low: see sensitivity.csv" 4, "body.drag_area_m2: 0 .. 0.001 m^2 (base 4e-04)\nno value at low: see sensitivity.csv" 3, "materials.LE1.youngs_modulus_gpa: 100 .. 400 GPa (base 250)\nno value at low: see sensitivity.csv" 2, "wing.p3_aft_of_le_m: 0.026 .. 0.078 m (base 0.052)\nno value at low: see sensitivity.csv" 1) noenhanced font ',9'
set grid noytics
set offsets graph 0.18, graph 0.18, 0, 0
set style fill solid 0.85 border rgb '#333333'
set key bottom right box opaque
lo(d) = d < 0 ? d : 0
hi(d) = d > 0 ? d : 0
set arrow 1 from first 0, graph 0 to first 0, graph 1 nohead lw 2 lc rgb '#333333'
plot 'tornado.csv' skip 2 every ::45::53 using (0.5*$11):(10-$4):(lo($11)):(hi($11)):((10-$4)-0.4):((10-$4)) with boxxyerror lc rgb '#2471a3' title 'parameter at the low end', \
  'tornado.csv' skip 2 every ::45::53 using (0.5*$12):(10-$4):(lo($12)):(hi($12)):((10-$4)):((10-$4)+0.4) with boxxyerror lc rgb '#c0392b' title 'parameter at the high end', \
  'tornado.csv' skip 2 every ::45::53 using ($11<0?$11:1/0):((10-$4)-0.2):(sprintf('%+.3g', $11)) with labels right offset -0.5,0 font ',9' notitle, \
  'tornado.csv' skip 2 every ::45::53 using ($11>=0?$11:1/0):((10-$4)-0.2):(sprintf('%+.3g', $11)) with labels left offset 0.5,0 font ',9' notitle, \
  'tornado.csv' skip 2 every ::45::53 using ($12<0?$12:1/0):((10-$4)+0.2):(sprintf('%+.3g', $12)) with labels right offset -0.5,0 font ',9' notitle, \
  'tornado.csv' skip 2 every ::45::53 using ($12>=0?$12:1/0):((10-$4)+0.2):(sprintf('%+.3g', $12)) with labels left offset 0.5,0 font ',9' notitle

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'tornado_altitude_p2p_m.svg.tmp'
set label 101 "sensitivity_magpie: altitude_p2p_m (free flight: altitude peak-to-peak at the flapping frequency)" at screen 0.5, 0.975 center noenhanced font ',13'
set label 102 "base vehicle: 0.005954 m; bars: the change with the parameter at the low and at the high end of its range, largest swing on top" at screen 0.5, 0.945 center noenhanced font ',10'
set tmargin at screen 0.91
set xlabel "change of altitude_p2p_m from the base vehicle's value (m)" noenhanced
set lmargin at screen 0.40
set rmargin at screen 0.96
set yrange [0.4:9.6]
set ytics ("kinematics.hinge_x_m: 0.01 .. 0.042 m (base 0.015)" 9, "body.pitch_inertia_kgm2: 4e-05 .. 0.00032 kg m^2 (base 0.00017)" 8, "aero.suction_efficiency: 0.3 .. 1 (base 0.98)" 7, "wing.skin.pretension_N_per_m: 0 .. 30 N/m (base 0)" 6, "wing.fe.damping_ratio: 0.005 .. 0.05 (base 0.015)" 5, "materials.CFRP_ROD.youngs_modulus_gpa: 100 .. 400 GPa (base 175)\nno value at low: see sensitivity.csv" 4, "body.drag_area_m2: 0 .. 0.001 m^2 (base 4e-04)\nno value at low: see sensitivity.csv" 3, "materials.LE1.youngs_modulus_gpa: 100 .. 400 GPa (base 250)\nno value at low: see sensitivity.csv" 2, "wing.p3_aft_of_le_m: 0.026 .. 0.078 m (base 0.052)\nno value at low: see sensitivity.csv" 1) noenhanced font ',9'
set grid noytics
set offsets graph 0.18, graph 0.18, 0, 0
set style fill solid 0.85 border rgb '#333333'
set key bottom right box opaque
lo(d) = d < 0 ? d : 0
hi(d) = d > 0 ? d : 0
set arrow 1 from first 0, graph 0 to first 0, graph 1 nohead lw 2 lc rgb '#333333'
plot 'tornado.csv' skip 2 every ::45::53 using (0.5*$11):(10-$4):(lo($11)):(hi($11)):((10-$4)-0.4):((10-$4)) with boxxyerror lc rgb '#2471a3' title 'parameter at the low end', \
  'tornado.csv' skip 2 every ::45::53 using (0.5*$12):(10-$4):(lo($12)):(hi($12)):((10-$4)):((10-$4)+0.4) with boxxyerror lc rgb '#c0392b' title 'parameter at the high end', \
  'tornado.csv' skip 2 every ::45::53 using ($11<0?$11:1/0):((10-$4)-0.2):(sprintf('%+.3g', $11)) with labels right offset -0.5,0 font ',9' notitle, \
  'tornado.csv' skip 2 every ::45::53 using ($11>=0?$11:1/0):((10-$4)-0.2):(sprintf('%+.3g', $11)) with labels left offset 0.5,0 font ',9' notitle, \
  'tornado.csv' skip 2 every ::45::53 using ($12<0?$12:1/0):((10-$4)+0.2):(sprintf('%+.3g', $12)) with labels right offset -0.5,0 font ',9' notitle, \
  'tornado.csv' skip 2 every ::45::53 using ($12>=0?$12:1/0):((10-$4)+0.2):(sprintf('%+.3g', $12)) with labels left offset 0.5,0 font ',9' notitle

unset output
