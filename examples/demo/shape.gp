# shape.gp - the formed strip: the mid-surface deflection from the chord,
# along the length and across the width (shape.sh's table).  Variables from
# the command line:
#   shape  the table of shape.sh (index 0 along x, index 1 along y)
#   arc    the arc height printed by demform, mm
#   out    the PNG
set terminal pngcairo size 900,560 font ",11" enhanced
set output out
set title sprintf("The formed strip (150 x 50 x 4 mm, free): arc height %.3f mm over the 150 mm length", arc)
set xlabel "position along the line (mm)"
set ylabel "deflection of the mid-surface from the chord (mm)"
set grid
set key top right
set offsets 0, 0, graph 0.15, 0
set xrange [-80:80]
set yrange [0:*]
plot shape index 0 using 1:2 with linespoints lw 2 pt 7 ps 0.6 title "along the length (y = 0), x", \
     shape index 1 using 1:2 with linespoints lw 2 pt 5 ps 0.6 title "across the width (x = 0), y"
