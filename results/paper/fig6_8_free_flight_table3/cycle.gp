# Figure 'cycle' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'cycle.png.tmp'
set multiplot layout 2,1 title "fig6_8_free_flight_table3 (free flight): U0 = 10.8 m/s, f = 12 Hz, theta0 = 9.2 deg, tail = 11.85 deg, cycle 60 (shaded: downstroke)" noenhanced font ',12'
set key off
set grid
set xrange [4.91667:5]
set object 1 rect from 4.9375, graph 0 to 4.97917, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set ylabel '{/Symbol d}_M (deg)'
plot 'histories.csv' skip 2 using 1:2 with lines lw 2 lc rgb '#333333'
set xlabel 'time (s)'
set ylabel '{/Symbol q} (deg)'
plot 'histories.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#c0392b'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'cycle.svg.tmp'
set multiplot layout 2,1 title "fig6_8_free_flight_table3 (free flight): U0 = 10.8 m/s, f = 12 Hz, theta0 = 9.2 deg, tail = 11.85 deg, cycle 60 (shaded: downstroke)" noenhanced font ',12'
set key off
set grid
set xrange [4.91667:5]
set object 1 rect from 4.9375, graph 0 to 4.97917, graph 1 behind fc rgb '#e8e8f0' fs solid noborder
set ylabel '{/Symbol d}_M (deg)'
plot 'histories.csv' skip 2 using 1:2 with lines lw 2 lc rgb '#333333'
set xlabel 'time (s)'
set ylabel '{/Symbol q} (deg)'
plot 'histories.csv' skip 2 using 1:5 with lines lw 2 lc rgb '#c0392b'
unset multiplot

unset output
