# Figure 'flight' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'flight.png.tmp'
set multiplot layout 3,2 columnsfirst title "fig6_8_free_flight_table3 (free flight): U0 = 10.8 m/s, f = 12 Hz, theta0 = 9.2 deg, tail = 11.85 deg" noenhanced font ',12'
set key off
set grid
set xlabel 'time (s)'
set ylabel '{/Symbol d}_M (deg)'
plot 'histories.csv' skip 2 using 1:2 with lines lc rgb '#333333'
set ylabel '{/Symbol q} (deg)'
plot 'histories.csv' skip 2 using 1:5 with lines lc rgb '#c0392b'
set ylabel 'h (m)'
plot 'histories.csv' skip 2 using 1:4 with lines lc rgb '#2471a3'
set xlabel 'f (Hz)'
set ylabel '|{/Symbol d}_M(f)| (deg)'
plot 'spectra.csv' skip 2 using 1:2 with impulses lw 2 lc rgb '#333333'
set ylabel '|{/Symbol q}(f)| (deg)'
plot 'spectra.csv' skip 2 using 1:3 with impulses lw 2 lc rgb '#c0392b'
set logscale y
set yrange [1e-5:1]
set format y '10^{%L}'
set ylabel '|h(f)| (m)'
plot 'spectra.csv' skip 2 using 1:($4 > 0 ? $4 : 1/0) with impulses lw 2 lc rgb '#2471a3'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'flight.svg.tmp'
set multiplot layout 3,2 columnsfirst title "fig6_8_free_flight_table3 (free flight): U0 = 10.8 m/s, f = 12 Hz, theta0 = 9.2 deg, tail = 11.85 deg" noenhanced font ',12'
set key off
set grid
set xlabel 'time (s)'
set ylabel '{/Symbol d}_M (deg)'
plot 'histories.csv' skip 2 using 1:2 with lines lc rgb '#333333'
set ylabel '{/Symbol q} (deg)'
plot 'histories.csv' skip 2 using 1:5 with lines lc rgb '#c0392b'
set ylabel 'h (m)'
plot 'histories.csv' skip 2 using 1:4 with lines lc rgb '#2471a3'
set xlabel 'f (Hz)'
set ylabel '|{/Symbol d}_M(f)| (deg)'
plot 'spectra.csv' skip 2 using 1:2 with impulses lw 2 lc rgb '#333333'
set ylabel '|{/Symbol q}(f)| (deg)'
plot 'spectra.csv' skip 2 using 1:3 with impulses lw 2 lc rgb '#c0392b'
set logscale y
set yrange [1e-5:1]
set format y '10^{%L}'
set ylabel '|h(f)| (m)'
plot 'spectra.csv' skip 2 using 1:($4 > 0 ? $4 : 1/0) with impulses lw 2 lc rgb '#2471a3'
unset multiplot

unset output
