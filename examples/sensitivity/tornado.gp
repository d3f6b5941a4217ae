# tornado.gp - the tornado plot of the sensitivity study: for each row
# (a modelling choice changed from the reference), the change of the arc
# height after the last n against the reference, one bar a velocity, the
# rows sorted by their largest change (the largest at the top).
# Variables from the command line:
#   data  tornado.dat (report.sh): "choice: value" then one change (%) a velocity
#   vels  the velocities (m/s), in the order of the columns
#   n     the passes of the compared arc height
#   out   the PNG
set terminal pngcairo size 1000,760 font ",10" enhanced
set output out
set title sprintf("What moves the arc height: change after %s passes against the reference scene", n)
set xlabel "arc height against the reference (%)"
stats data using 0 nooutput
nrow = STATS_records
set yrange [-0.7:nrow - 0.3]
set ytics scale 0
set grid xtics
set yzeroaxis lt -1
set key outside right top
set style fill solid 0.8 border -1
nv = words(vels)
bw = 0.8 / nv
# the labels once a row, at its centre; then one bar a velocity
plot data using (0):($0):ytic(1) with points pt -1 notitle, \
     for [i=1:nv] data using (0.5 * column(i + 1)):($0 - 0.4 + (i - 0.5) * bw):(0.5 * abs(column(i + 1))):(bw / 2) \
     with boxxyerror lc i title sprintf("v = %s m/s", word(vels, i))
