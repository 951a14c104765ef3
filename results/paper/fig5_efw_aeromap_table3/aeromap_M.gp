# Figure 'aeromap_M' written by ornithopter; redraw with `ornithopter plot DIR`.
set datafile separator ','
set grid lc rgb '#dddddd'
set key top right box opaque
set terminal pngcairo size 1200,900 enhanced font 'DejaVu Sans,11'
set output 'aeromap_M.png.tmp'
set multiplot layout 2,3 title "fig5_efw_aeromap_table3: mean pitching moment M about the CG over pitch, speed and frequency (cf. paper Fig. 5)" noenhanced font ',13'
stats 'aeromap.csv' skip 2 using 7 nooutput
pad = 0.05 * (STATS_max - STATS_min)
if (pad == 0) pad = (STATS_max == 0 ? 1 : 0.05 * abs(STATS_max))
set yrange [STATS_min - pad : STATS_max + pad]
set xlabel '{/Symbol q}_{mean} (deg)'
set ylabel 'mean M (N m)'
set key top left font ',9' spacing 0.9
set title 'f = 10 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::0::4 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::30::34 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::60::64 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::90::94 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::120::124 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::150::154 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 12 Hz, {/Symbol d}_T = 11.85 deg'
unset key
plot 'aeromap.csv' skip 2 every 1::5::9 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::35::39 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::65::69 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::95::99 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::125::129 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::155::159 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 14 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::10::14 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::40::44 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::70::74 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::100::104 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::130::134 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::160::164 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 16 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::15::19 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::45::49 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::75::79 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::105::109 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::135::139 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::165::169 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 18 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::20::24 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::50::54 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::80::84 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::110::114 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::140::144 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::170::174 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 20 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::25::29 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::55::59 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::85::89 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::115::119 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::145::149 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::175::179 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
unset multiplot

unset output
set terminal svg size 1200,900 enhanced font 'DejaVu Sans,11' background rgb 'white'
set output 'aeromap_M.svg.tmp'
set multiplot layout 2,3 title "fig5_efw_aeromap_table3: mean pitching moment M about the CG over pitch, speed and frequency (cf. paper Fig. 5)" noenhanced font ',13'
stats 'aeromap.csv' skip 2 using 7 nooutput
pad = 0.05 * (STATS_max - STATS_min)
if (pad == 0) pad = (STATS_max == 0 ? 1 : 0.05 * abs(STATS_max))
set yrange [STATS_min - pad : STATS_max + pad]
set xlabel '{/Symbol q}_{mean} (deg)'
set ylabel 'mean M (N m)'
set key top left font ',9' spacing 0.9
set title 'f = 10 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::0::4 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::30::34 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::60::64 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::90::94 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::120::124 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::150::154 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 12 Hz, {/Symbol d}_T = 11.85 deg'
unset key
plot 'aeromap.csv' skip 2 every 1::5::9 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::35::39 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::65::69 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::95::99 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::125::129 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::155::159 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 14 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::10::14 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::40::44 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::70::74 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::100::104 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::130::134 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::160::164 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 16 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::15::19 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::45::49 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::75::79 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::105::109 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::135::139 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::165::169 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 18 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::20::24 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::50::54 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::80::84 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::110::114 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::140::144 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::170::174 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
set title 'f = 20 Hz, {/Symbol d}_T = 11.85 deg'
plot 'aeromap.csv' skip 2 every 1::25::29 using 3:7 with linespoints lt 1 dt 1 lw 2 pt 7 ps 0.7 title 'U = 10 m/s', \
     'aeromap.csv' skip 2 every 1::55::59 using 3:7 with linespoints lt 2 dt 1 lw 2 pt 7 ps 0.7 title 'U = 12 m/s', \
     'aeromap.csv' skip 2 every 1::85::89 using 3:7 with linespoints lt 3 dt 1 lw 2 pt 7 ps 0.7 title 'U = 14 m/s', \
     'aeromap.csv' skip 2 every 1::115::119 using 3:7 with linespoints lt 4 dt 1 lw 2 pt 7 ps 0.7 title 'U = 16 m/s', \
     'aeromap.csv' skip 2 every 1::145::149 using 3:7 with linespoints lt 5 dt 1 lw 2 pt 7 ps 0.7 title 'U = 18 m/s', \
     'aeromap.csv' skip 2 every 1::175::179 using 3:7 with linespoints lt 6 dt 1 lw 2 pt 7 ps 0.7 title 'U = 20 m/s'
unset multiplot

unset output
