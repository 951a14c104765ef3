# Figure 'sweep' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'sweep.png.tmp'
set multiplot layout 3,2 margins 0.08,0.74,0.07,0.92 spacing 0.09,0.1 title "placement_sweep_magpie: trim sweep, 9 points" noenhanced font ',13'
set key at screen 0.76,0.92 left top Left reverse noenhanced box title 'wing.p3_aft_of_le_m (m)' noenhanced font ',10'
set xlabel 'kinematics.hinge_x_m (m)' noenhanced
set xrange [-0.0018:0.0318]
set xtics (0, 0.015, 0.03)
set ylabel 'theta_mean_deg (deg)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:4 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:4 with linespoints lw 2 pt 7 title '0.078'
unset key
set ylabel 'speed_mps (m/s)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:5 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:5 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'tail_angle_deg (deg)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:6 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:6 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'freq_hz (Hz)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:7 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:7 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'power_aero_W (W)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:8 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:8 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'norm_ratio_max (-)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:18 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:18 with linespoints lw 2 pt 7 title '0.078', 1 with lines dt 2 lc rgb '#333333' title 'bound (bounded below 1)'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'sweep.svg.tmp'
set multiplot layout 3,2 margins 0.08,0.74,0.07,0.92 spacing 0.09,0.1 title "placement_sweep_magpie: trim sweep, 9 points" noenhanced font ',13'
set key at screen 0.76,0.92 left top Left reverse noenhanced box title 'wing.p3_aft_of_le_m (m)' noenhanced font ',10'
set xlabel 'kinematics.hinge_x_m (m)' noenhanced
set xrange [-0.0018:0.0318]
set xtics (0, 0.015, 0.03)
set ylabel 'theta_mean_deg (deg)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:4 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:4 with linespoints lw 2 pt 7 title '0.078'
unset key
set ylabel 'speed_mps (m/s)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:5 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:5 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'tail_angle_deg (deg)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:6 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:6 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'freq_hz (Hz)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:7 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:7 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'power_aero_W (W)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:8 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:8 with linespoints lw 2 pt 7 title '0.078'
set ylabel 'norm_ratio_max (-)' noenhanced
plot 'sweep.csv' skip 2 every 3::1 using 1:18 with linespoints lw 2 pt 7 title '0.052', 'sweep.csv' skip 2 every 3::2 using 1:18 with linespoints lw 2 pt 7 title '0.078', 1 with lines dt 2 lc rgb '#333333' title 'bound (bounded below 1)'
unset multiplot

unset output
