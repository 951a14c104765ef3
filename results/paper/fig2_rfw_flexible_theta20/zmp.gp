# Figure 'zmp' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'zmp.png.tmp'
set multiplot title "fig2_rfw_flexible_theta20 - constrained flight test (tethered): theta = 20 deg, f = 4 Hz, U = 6 m/s, no tail (rig), cycle 10" noenhanced font ',13'
set lmargin 13
set rmargin 12
set tmargin 0.5
set bmargin 0.5
set xrange [2.25:2.5]
set object 1 rect from 2.3125, graph 0 to 2.4375, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set format x ''
set size 1,0.18
set origin 0,0.75
set ylabel 'C_{F,V} (-)'
set y2label '{/Symbol d}_M (deg)'
set y2tics 20
set ytics 0.5 nomirror
set key top right box opaque font ',10'
plot 'zmp.csv' skip 2 using 1:4 with lines lw 2 lc rgb '#333333' title 'C_{F,V}', '' skip 2 using 1:2 axes x1y2 with lines dt 2 lw 1 lc rgb '#888888' title '{/Symbol d}_M (right axis)'
unset y2tics
unset y2label
set key off
set origin 0,0.57
set ytics 0.2 mirror
set ylabel 'C_{F,H} (-)'
plot 'zmp.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#333333'
set origin 0,0.36
set size 1,0.21
set bmargin 3
set format x '%g'
set ytics 0.2
set xlabel 'time (s); shaded: downstroke' offset 0,0.5
set ylabel 'C_{M,CG} (-)'
plot 'zmp.csv' skip 2 using 1:6 with lines lw 2 lc rgb '#333333'
unset object 1
set size 1,0.36
set origin 0,0
set tmargin 1
set bmargin 6.5
set ytics autofreq
set xrange [-40:40]
set xlabel '{/Symbol d}_M (deg)' offset 0,0.3
set ylabel '{/Symbol e} = (x_{ZMP} - x_{CG}) / c_{MEAN} (-)'
set key outside below center horizontal maxrows 2 box font ',10'
set label 1 'ZMP aft of the CG' at graph 0.01, graph 0.93 left font ',9'
set label 2 'ZMP ahead of the CG' at graph 0.01, graph 0.06 left font ',9'
set label 3 'gaps: no ZMP where |C_{F,normal}| < 10 % of its maximum' at graph 0.99, graph 0.06 right font ',9'
plot 0 with lines lc rgb '#555555' lw 1 title 'static moment equilibrium', 'zmp.csv' skip 2 using 2:(strcol(3) eq 'up' && strcol(7) ne '' ? real(strcol(7)) : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 lc rgb '#2471a3' title 'upstroke', '' skip 2 using 2:(strcol(3) eq 'down' && strcol(7) ne '' ? real(strcol(7)) : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 lc rgb '#c0392b' title 'downstroke', 0.213719 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'upstroke mean (|C_{F,normal}|-weighted)', 0.349976 with lines dt 2 lw 1.5 lc rgb '#c0392b' title 'downstroke mean (|C_{F,normal}|-weighted)'
unset label 1
unset label 2
unset label 3
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'zmp.svg.tmp'
set multiplot title "fig2_rfw_flexible_theta20 - constrained flight test (tethered): theta = 20 deg, f = 4 Hz, U = 6 m/s, no tail (rig), cycle 10" noenhanced font ',13'
set lmargin 13
set rmargin 12
set tmargin 0.5
set bmargin 0.5
set xrange [2.25:2.5]
set object 1 rect from 2.3125, graph 0 to 2.4375, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set format x ''
set size 1,0.18
set origin 0,0.75
set ylabel 'C_{F,V} (-)'
set y2label '{/Symbol d}_M (deg)'
set y2tics 20
set ytics 0.5 nomirror
set key top right box opaque font ',10'
plot 'zmp.csv' skip 2 using 1:4 with lines lw 2 lc rgb '#333333' title 'C_{F,V}', '' skip 2 using 1:2 axes x1y2 with lines dt 2 lw 1 lc rgb '#888888' title '{/Symbol d}_M (right axis)'
unset y2tics
unset y2label
set key off
set origin 0,0.57
set ytics 0.2 mirror
set ylabel 'C_{F,H} (-)'
plot 'zmp.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#333333'
set origin 0,0.36
set size 1,0.21
set bmargin 3
set format x '%g'
set ytics 0.2
set xlabel 'time (s); shaded: downstroke' offset 0,0.5
set ylabel 'C_{M,CG} (-)'
plot 'zmp.csv' skip 2 using 1:6 with lines lw 2 lc rgb '#333333'
unset object 1
set size 1,0.36
set origin 0,0
set tmargin 1
set bmargin 6.5
set ytics autofreq
set xrange [-40:40]
set xlabel '{/Symbol d}_M (deg)' offset 0,0.3
set ylabel '{/Symbol e} = (x_{ZMP} - x_{CG}) / c_{MEAN} (-)'
set key outside below center horizontal maxrows 2 box font ',10'
set label 1 'ZMP aft of the CG' at graph 0.01, graph 0.93 left font ',9'
set label 2 'ZMP ahead of the CG' at graph 0.01, graph 0.06 left font ',9'
set label 3 'gaps: no ZMP where |C_{F,normal}| < 10 % of its maximum' at graph 0.99, graph 0.06 right font ',9'
plot 0 with lines lc rgb '#555555' lw 1 title 'static moment equilibrium', 'zmp.csv' skip 2 using 2:(strcol(3) eq 'up' && strcol(7) ne '' ? real(strcol(7)) : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 lc rgb '#2471a3' title 'upstroke', '' skip 2 using 2:(strcol(3) eq 'down' && strcol(7) ne '' ? real(strcol(7)) : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 lc rgb '#c0392b' title 'downstroke', 0.213719 with lines dt 2 lw 1.5 lc rgb '#2471a3' title 'upstroke mean (|C_{F,normal}|-weighted)', 0.349976 with lines dt 2 lw 1.5 lc rgb '#c0392b' title 'downstroke mean (|C_{F,normal}|-weighted)'
unset label 1
unset label 2
unset label 3
unset multiplot

unset output
