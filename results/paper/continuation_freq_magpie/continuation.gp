# Figure 'continuation' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'continuation.png.tmp'
set multiplot layout 2,2 title "continuation_freq_magpie: trimmed flight over freq_hz (completed); solid stable, dashed unstable, circles events" noenhanced font ',12'
set grid
set key off
set xlabel 'freq_hz (Hz)' noenhanced
set ylabel 'control: tail angle (deg)' noenhanced
plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $6 : NaN) with lines lw 2 lc rgb '#1f77b4', '' skip 2 using 2:($10 == 0 ? $6 : NaN) with lines lw 2 dt 2 lc rgb '#d62728', '' skip 2 using 2:(strcol(19) ne '' ? $6 : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'
set ylabel 'cycle-mean theta (deg)' noenhanced
plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $4 : NaN) with lines lw 2 lc rgb '#1f77b4', '' skip 2 using 2:($10 == 0 ? $4 : NaN) with lines lw 2 dt 2 lc rgb '#d62728', '' skip 2 using 2:(strcol(19) ne '' ? $4 : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'
set ylabel 'mean airspeed (m/s)' noenhanced
plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $5 : NaN) with lines lw 2 lc rgb '#1f77b4', '' skip 2 using 2:($10 == 0 ? $5 : NaN) with lines lw 2 dt 2 lc rgb '#d62728', '' skip 2 using 2:(strcol(19) ne '' ? $5 : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'
set ylabel 'max |mu| (1 = stability limit)'
plot 'continuation.csv' skip 2 using 2:9 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#2ca02c', 1 with lines dt 3 lc rgb '#555555'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'continuation.svg.tmp'
set multiplot layout 2,2 title "continuation_freq_magpie: trimmed flight over freq_hz (completed); solid stable, dashed unstable, circles events" noenhanced font ',12'
set grid
set key off
set xlabel 'freq_hz (Hz)' noenhanced
set ylabel 'control: tail angle (deg)' noenhanced
plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $6 : NaN) with lines lw 2 lc rgb '#1f77b4', '' skip 2 using 2:($10 == 0 ? $6 : NaN) with lines lw 2 dt 2 lc rgb '#d62728', '' skip 2 using 2:(strcol(19) ne '' ? $6 : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'
set ylabel 'cycle-mean theta (deg)' noenhanced
plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $4 : NaN) with lines lw 2 lc rgb '#1f77b4', '' skip 2 using 2:($10 == 0 ? $4 : NaN) with lines lw 2 dt 2 lc rgb '#d62728', '' skip 2 using 2:(strcol(19) ne '' ? $4 : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'
set ylabel 'mean airspeed (m/s)' noenhanced
plot 'continuation.csv' skip 2 using 2:($10 == 1 ? $5 : NaN) with lines lw 2 lc rgb '#1f77b4', '' skip 2 using 2:($10 == 0 ? $5 : NaN) with lines lw 2 dt 2 lc rgb '#d62728', '' skip 2 using 2:(strcol(19) ne '' ? $5 : NaN) with points pt 6 ps 2 lw 2 lc rgb 'black'
set ylabel 'max |mu| (1 = stability limit)'
plot 'continuation.csv' skip 2 using 2:9 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#2ca02c', 1 with lines dt 3 lc rgb '#555555'
unset multiplot

unset output
