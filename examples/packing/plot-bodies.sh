#!/bin/sh
# plot-bodies.sh STREAM PNG TITLE - draw a body stream of polygons (shape
# 1) and ellipses (shape 0, m = 2) by their outlines, with its walls.
# The outline of a row is computed from its columns as dem-streams(5)
# defines them: polygon points (a cos p, b sin p), p = -pi/2 + pi/m +
# 2 pi k/m, turned by theta; an ellipse by 48 points.
set -eu
stream=$1 png=$2 title=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
awk -v pi=3.14159265358979 '
/^# wall / { print $3, $4 > W; print $5, $6 > W; print "" > W; next }
/^#/ { next }
{ m = $4 == 1 ? $7 : 48; c = cos($10); s = sin($10)
  for (k = 0; k <= m; k++) {
	p = $4 == 1 ? -pi / 2 + pi / m + 2 * pi * k / m : 2 * pi * k / m
	u = $5 * cos(p); w = $6 * sin(p)
	print $8 + c * u - s * w, $9 + s * u + c * w
  }
  print "" }' W="$tmp/walls" "$stream" > "$tmp/bodies"
gnuplot <<GP
set terminal pngcairo size 640,640
unset border
set output '$png'
set size ratio -1
set key off
unset xtics
unset ytics
set title '$title'
plot '$tmp/bodies' using 1:2 with filledcurves closed lc rgb '#3a6ea5' fs transparent solid 0.35 border lc rgb '#1f3d5c', \
     '$tmp/walls' using 1:2 with lines lw 2 lc rgb 'black'
GP
