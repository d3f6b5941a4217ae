# saturation.gp - the arc height of the strip formed by each pass's profile
# against the exposure (curve.txt), one curve a velocity (the saturation curves,
# Fig. 8.7 of the thesis).  Variables from the command line:
#   runs  the run directories (each with curve.txt), space separated
#   vels  their velocities (m/s), in the same order
#   out   the PNG
set terminal pngcairo size 900,560 font ",11" enhanced
set output out
set title "Saturation curves: arc height of the 150 x 50 x 4 mm strip over 150 mm"
set xlabel "exposure (the thesis's passes: 16 shots on the 5.6 x 5.6 mm area)"
set ylabel "arc height (mm)"
set grid
set key bottom right
set yrange [0:*]
set xrange [0:*]
plot for [i=1:words(runs)] word(runs, i)."/curve.txt" using 1:3 \
         with linespoints lw 2 pt 7 ps 0.8 lc i title sprintf("v = %s m/s", word(vels, i))
