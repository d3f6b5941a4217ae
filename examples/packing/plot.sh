#!/bin/sh
# plot.sh STREAM OUTLINE PNG TITLE - draw a 2D packing (x y r text stream)
# as circles with the domain's outline (a file of x y rows, closed).
set -eu
stream=$1 outline=$2 png=$3 title=$4
gnuplot <<GP
set terminal pngcairo size 640,640
unset border
set output '$png'
set size ratio -1
set key off
unset xtics
unset ytics
set title '$title'
plot '$stream' using 1:2:3 with circles lc rgb '#3a6ea5' fs transparent solid 0.35 border lc rgb '#1f3d5c', \
     '$outline' using 1:2 with lines lw 2 lc rgb 'black'
GP
