# Figure 'optimize_convergence' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'optimize_convergence.png.tmp'
set multiplot layout 2,1 title "optimize_magpie_floquet optimisation (cobyla, 2 start(s)): objective power per evaluation" noenhanced font ',13'
set lmargin 12
set rmargin 30
set tmargin 3
set key outside right top vertical Left reverse noenhanced
set xlabel 'evaluation (starts in order)'
set xrange [-0.5:79.5]
set ylabel 'objective (W)'
plot 'history.csv' skip 2 using 1:(($11 == 0 && $10 == 0) ? $9 : 1/0) with points pt 6 ps 1.2 lc rgb '#c0392b' title 'infeasible', '' skip 2 using 1:($10 == 1 ? $9 : 1/0) with points pt 7 ps 1.2 lc rgb '#1e8449' title 'feasible', '' skip 2 using 1:39 with steps lw 2 lc rgb '#2471a3' title 'best feasible so far'
set logscale y
set format y '10^{%L}'
set ylabel 'max constraint g (-)'
set yrange [1e-4:*]
plot 'history.csv' skip 2 using 1:(($11 == 0 && $10 == 0) ? ($12 > 1e-4 ? $12 : 1e-4) : 1/0) with points pt 6 ps 1.2 lc rgb '#c0392b' title 'infeasible: violation', '' skip 2 using 1:($10 == 1 ? 1e-4 : 1/0) with points pt 7 ps 1.2 lc rgb '#1e8449' title 'feasible (at 1e-4)', '' skip 2 using 1:($11 == 1 ? $12 : 1/0) with points pt 2 ps 1.2 lc rgb '#333333' title 'failed (penalty)'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'optimize_convergence.svg.tmp'
set multiplot layout 2,1 title "optimize_magpie_floquet optimisation (cobyla, 2 start(s)): objective power per evaluation" noenhanced font ',13'
set lmargin 12
set rmargin 30
set tmargin 3
set key outside right top vertical Left reverse noenhanced
set xlabel 'evaluation (starts in order)'
set xrange [-0.5:79.5]
set ylabel 'objective (W)'
plot 'history.csv' skip 2 using 1:(($11 == 0 && $10 == 0) ? $9 : 1/0) with points pt 6 ps 1.2 lc rgb '#c0392b' title 'infeasible', '' skip 2 using 1:($10 == 1 ? $9 : 1/0) with points pt 7 ps 1.2 lc rgb '#1e8449' title 'feasible', '' skip 2 using 1:39 with steps lw 2 lc rgb '#2471a3' title 'best feasible so far'
set logscale y
set format y '10^{%L}'
set ylabel 'max constraint g (-)'
set yrange [1e-4:*]
plot 'history.csv' skip 2 using 1:(($11 == 0 && $10 == 0) ? ($12 > 1e-4 ? $12 : 1e-4) : 1/0) with points pt 6 ps 1.2 lc rgb '#c0392b' title 'infeasible: violation', '' skip 2 using 1:($10 == 1 ? 1e-4 : 1/0) with points pt 7 ps 1.2 lc rgb '#1e8449' title 'feasible (at 1e-4)', '' skip 2 using 1:($11 == 1 ? $12 : 1/0) with points pt 2 ps 1.2 lc rgb '#333333' title 'failed (penalty)'
unset multiplot

unset output
