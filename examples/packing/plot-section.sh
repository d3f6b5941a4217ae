#!/bin/sh
# plot-section.sh STREAM PNG TITLE - the spheres of a 3D particle stream
# cut by the vertical plane through the middle of the domain (y = Y0):
# circles of radius sqrt(r^2 - (y - Y0)^2) in the x-z plane.
set -eu
stream=$1 png=$2 title=$3
cut=$png.cut.tmp
awk '/^# box / { y0 = ($4 + $7) / 2 } /^# cylinder / { y0 = $4 } /^#/ { next }
     { d = $2 - y0; if (d * d < $4 * $4) print $1, $3, sqrt($4 * $4 - d * d) }' "$stream" >"$cut"
gnuplot <<GP
set terminal pngcairo size 480,860
set output '$png'
set size ratio -1
set key off
set title '$title' font ',10'
set xlabel 'x (m)'
set xtics 0.0002
set ylabel 'z (m)'
plot '$cut' using 1:2:3 with circles lc rgb '#3a6ea5' fs transparent solid 0.35 border lc rgb '#1f3d5c'
GP
rm -f "$cut"
