#!/bin/sh
# plot-density.sh PNG TITLE LABEL STAGES [LABEL STAGES]... - density against
# time from dempack compress --stages tables (seconds, phase, batch,
# spheres, added, iterations, density), one line per run, the relaxation
# stages marked.
set -eu
png=$1 title=$2
shift 2
plot=
lc=1
while [ $# -ge 2 ]; do
	plot="$plot${plot:+, }'$2' using 1:7 with linespoints lc $lc pt 7 ps 0.6 title '$1', \
'< awk -F\"\\t\" \"\\\$2 == \\\"relax\\\"\" $2' using 1:7 with points lc $lc pt 6 ps 1.6 notitle"
	lc=$((lc + 1))
	shift 2
done
gnuplot <<GP
set terminal pngcairo size 800,520
set output '$png'
set title '$title'
set xlabel 'time (s)'
set ylabel 'density (sphere volume / domain volume)'
set key bottom right
set grid
set yrange [0:0.7]
set label 1 'open circles: after a relaxation' at graph 0.02, graph 0.95
plot $plot
GP
