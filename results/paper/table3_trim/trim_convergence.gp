# Figure 'trim_convergence' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'trim_convergence.png.tmp'
set multiplot layout 2,1 title "table3_trim trim (ok), stage 1: paper Eq. (4) on tethered cycle means, max(|FV-W|, |FH|, |M|/c_mean) / W\nstage 2: level settled free flight moves the trim point (open circles)" noenhanced font ',13'
set lmargin 12
set rmargin 44
set tmargin 4
set key outside right top vertical Left reverse noenhanced
set xrange [-0.2:27.2]
set xlabel 'iteration'
set xtics 1
set logscale y
set format y '10^{%L}'
set ylabel 'scaled residual (-)'
set yrange [1e-05:*]
plot 'trim_progress.csv' skip 2 using 1:8 with linespoints lw 2 pt 7 lc rgb '#c0392b' title 'accepted iterate', 'trim_iterations.csv' skip 2 using ($3 == 0 && $4 == 1 ? $2 : 1/0):16 with points pt 6 ps 1.2 lc rgb '#2471a3' title 'residual runs (trial points)', 0.0001 with lines dt 2 lc rgb '#333333' title 'tolerance'
unset logscale y
set format y '%g'
set yrange [*:*]
set ylabel 'unknowns (deg, m/s, Hz)'
set xrange [-0.2:28.3]
set xtics add ('stage 2' 28)
set xlabel 'iteration (stage 1) / free-flight refinement (stage 2)'
plot 'trim_progress.csv' skip 2 using 1:3 with linespoints lw 2 pt 7 lc rgb '#9400d3' title 'theta mean (deg)', '' skip 2 using 1:4 with linespoints lw 2 pt 5 lc rgb '#009e73' title 'speed (m/s)', '' skip 2 using 1:5 with linespoints lw 2 pt 9 lc rgb '#56b4e9' title 'tail angle (deg)', '' skip 2 using 1:6 with linespoints lw 2 pt 11 lc rgb '#e69f00' title 'frequency (Hz)', '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#9400d3' title 'stage 2: theta = 8.88', '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#009e73' title 'stage 2: U = 10.84', '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#56b4e9' title 'stage 2: tail = 11.78'
28,8.87842603784994
e
28,10.835150450696137
e
28,11.776677068838184
e

unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'trim_convergence.svg.tmp'
set multiplot layout 2,1 title "table3_trim trim (ok), stage 1: paper Eq. (4) on tethered cycle means, max(|FV-W|, |FH|, |M|/c_mean) / W\nstage 2: level settled free flight moves the trim point (open circles)" noenhanced font ',13'
set lmargin 12
set rmargin 44
set tmargin 4
set key outside right top vertical Left reverse noenhanced
set xrange [-0.2:27.2]
set xlabel 'iteration'
set xtics 1
set logscale y
set format y '10^{%L}'
set ylabel 'scaled residual (-)'
set yrange [1e-05:*]
plot 'trim_progress.csv' skip 2 using 1:8 with linespoints lw 2 pt 7 lc rgb '#c0392b' title 'accepted iterate', 'trim_iterations.csv' skip 2 using ($3 == 0 && $4 == 1 ? $2 : 1/0):16 with points pt 6 ps 1.2 lc rgb '#2471a3' title 'residual runs (trial points)', 0.0001 with lines dt 2 lc rgb '#333333' title 'tolerance'
unset logscale y
set format y '%g'
set yrange [*:*]
set ylabel 'unknowns (deg, m/s, Hz)'
set xrange [-0.2:28.3]
set xtics add ('stage 2' 28)
set xlabel 'iteration (stage 1) / free-flight refinement (stage 2)'
plot 'trim_progress.csv' skip 2 using 1:3 with linespoints lw 2 pt 7 lc rgb '#9400d3' title 'theta mean (deg)', '' skip 2 using 1:4 with linespoints lw 2 pt 5 lc rgb '#009e73' title 'speed (m/s)', '' skip 2 using 1:5 with linespoints lw 2 pt 9 lc rgb '#56b4e9' title 'tail angle (deg)', '' skip 2 using 1:6 with linespoints lw 2 pt 11 lc rgb '#e69f00' title 'frequency (Hz)', '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#9400d3' title 'stage 2: theta = 8.88', '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#009e73' title 'stage 2: U = 10.84', '-' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#56b4e9' title 'stage 2: tail = 11.78'
28,8.87842603784994
e
28,10.835150450696137
e
28,11.776677068838184
e

unset multiplot

unset output
