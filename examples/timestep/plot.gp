# plot.gp - Fig. 3.15: v_exit/v0 of the Box 3.1 test against lambda.
# Variables from the command line: in, out, lmax, ymin, ymax, ttl.
set terminal pngcairo size 900,600 font ",11" enhanced
set output out
set title "Rigid sphere/wall, Box 3.1 time step: ".ttl noenhanced
set xlabel "{/Symbol l}   (dt = {/Symbol l} dt_{cr}(u), Eq. 3.83)"
set ylabel "v_{exit} / v_0"
set xrange [0:lmax]
set yrange [ymin:ymax]
set key top left
set grid
set arrow from 0.3, graph 0 to 0.3, graph 1 nohead dt 2 lc rgb "gray40"
set arrow from 0.5, graph 0 to 0.5, graph 1 nohead dt 3 lc rgb "red"
plot in using 1:2 with lines lw 1.5 title "linear, m = 1", \
     in using 1:3 with lines lw 1.5 title "Hertz, m = 1.5", \
     in using 1:4 with lines lw 1.5 title "Winkler, m = 2", \
     1.001 with lines dt 4 lc rgb "black" title "1 + 1e-3"
