# Figure 'phase' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'phase.png.tmp'
set title "fig6_8_free_flight_table3 (free flight): U0 = 10.8 m/s, f = 12 Hz, theta0 = 9.2 deg, tail = 11.85 deg" noenhanced font ',12'
set key off
set grid
set xlabel '{/Symbol q} (deg)'
set ylabel 'Q (deg/s)'
plot 'histories.csv' skip 2 using ($1 >= 1 ? $5 : 1/0):8 with lines lc rgb '#8e44ad'

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'phase.svg.tmp'
set title "fig6_8_free_flight_table3 (free flight): U0 = 10.8 m/s, f = 12 Hz, theta0 = 9.2 deg, tail = 11.85 deg" noenhanced font ',12'
set key off
set grid
set xlabel '{/Symbol q} (deg)'
set ylabel 'Q (deg/s)'
plot 'histories.csv' skip 2 using ($1 >= 1 ? $5 : 1/0):8 with lines lc rgb '#8e44ad'

unset output
