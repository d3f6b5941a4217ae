# plotc.gp - Fig. 3.15 (c): v_exit/v0 of the Box 3.1 test over the
# recommended range of lambda (Eq. 3.84), the thesis scheme (thin) and with
# the separation correction of lib/contact/model.h (thick; beyond the thesis).
# Variables from the command line: in, out.
set terminal pngcairo size 900,600 font ",11" enhanced
set output out
set title "Rigid sphere/wall, Box 3.1 time step: (c) lambda in (0, 0.3], thesis scheme and corrected" noenhanced
set xlabel "{/Symbol l}   (dt = {/Symbol l} dt_{cr}(u), Eq. 3.83)"
set ylabel "v_{exit} / v_0"
set xrange [0:0.3]
set yrange [0.985:1.05]
set key top left
set grid
plot in using 1:2 with lines lw 1 dt 2 lc rgb "#1f77b4" title "linear, thesis scheme", \
     in using 1:3 with lines lw 1 dt 2 lc rgb "#d62728" title "Hertz, thesis scheme", \
     in using 1:4 with lines lw 1 dt 2 lc rgb "#2ca02c" title "Winkler, thesis scheme", \
     in using 1:5 with lines lw 4 lc rgb "#1f77b4" title "linear, corrected", \
     in using 1:6 with lines lw 2.5 lc rgb "#d62728" title "Hertz, corrected", \
     in using 1:7 with lines lw 1 lc rgb "#2ca02c" title "Winkler, corrected", \
     1.001 with lines dt 4 lc rgb "black" title "1 {/Symbol \261} 1e-3", \
     0.999 with lines dt 4 lc rgb "black" notitle
