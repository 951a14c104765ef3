# Figure 'loads' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'loads.png.tmp'
set multiplot layout 4,1 title "fig9_constrained_flight_test_table3 (tethered): U = 10.8 m/s, f = 12 Hz, theta = 9.2 deg, cycles 8-10 of 10 (shaded: downstroke)" noenhanced font ',13'
set lmargin 12
set rmargin 22
set key outside right top vertical Left reverse
set xrange [0.583333:0.833333]
set object 8 rect from 0.604167, graph 0 to 0.645833, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set object 9 rect from 0.6875, graph 0 to 0.729167, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set object 10 rect from 0.770833, graph 0 to 0.8125, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set format x ''
set ylabel '{/Symbol d}_M (deg)'
plot 'histories.csv' skip 2 using 1:2 with lines lw 2 lc rgb '#333333' title 'flap angle'
set ylabel 'F_V (N)'
plot 'histories.csv' skip 2 using 1:3 with lines lw 2 lc rgb '#c0392b' title 'total', '' skip 2 using 1:8 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', '' skip 2 using 1:11 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'
set ylabel 'F_H (N)'
plot 'histories.csv' skip 2 using 1:4 with lines lw 2 lc rgb '#c0392b' title 'total', '' skip 2 using 1:9 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', '' skip 2 using 1:12 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'
set format x '%g'
set xlabel 'time (s)'
set ylabel 'M_{CG} (N m)'
plot 'histories.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#c0392b' title 'total', '' skip 2 using 1:10 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', '' skip 2 using 1:13 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'loads.svg.tmp'
set multiplot layout 4,1 title "fig9_constrained_flight_test_table3 (tethered): U = 10.8 m/s, f = 12 Hz, theta = 9.2 deg, cycles 8-10 of 10 (shaded: downstroke)" noenhanced font ',13'
set lmargin 12
set rmargin 22
set key outside right top vertical Left reverse
set xrange [0.583333:0.833333]
set object 8 rect from 0.604167, graph 0 to 0.645833, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set object 9 rect from 0.6875, graph 0 to 0.729167, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set object 10 rect from 0.770833, graph 0 to 0.8125, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set format x ''
set ylabel '{/Symbol d}_M (deg)'
plot 'histories.csv' skip 2 using 1:2 with lines lw 2 lc rgb '#333333' title 'flap angle'
set ylabel 'F_V (N)'
plot 'histories.csv' skip 2 using 1:3 with lines lw 2 lc rgb '#c0392b' title 'total', '' skip 2 using 1:8 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', '' skip 2 using 1:11 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'
set ylabel 'F_H (N)'
plot 'histories.csv' skip 2 using 1:4 with lines lw 2 lc rgb '#c0392b' title 'total', '' skip 2 using 1:9 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', '' skip 2 using 1:12 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'
set format x '%g'
set xlabel 'time (s)'
set ylabel 'M_{CG} (N m)'
plot 'histories.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#c0392b' title 'total', '' skip 2 using 1:10 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'wing aero', '' skip 2 using 1:13 with lines dt 3 lw 1.5 lc rgb '#27ae60' title 'wing inertia'
unset multiplot

unset output
