#!/bin/sh
# ringing.sh PNG OUT NAME - why run.sh averages: the block rings after the
# impact, so the sxx of one instant is not the residual.  (a) the centre-line
# sxx of NAME: the mean over the instants (OUT/NAME.mean), their range and
# the instant the pass ends; (b) sxx against time at the surface (top layer)
# and at the depth of the mean's peak (OUT/NAME.samples).
set -e
png=$1 out=$2 name=$3
series=$out/$name.ring
# the depth of the mean's most compressive point (m), then one row an instant
awk '!/^#/ && ($2 < mn || mn == "") { mn = $2; d = $1 } END { print d / 1e3 }' "$out/$name.mean" > "$series.tmp"
awk 'NR == FNR { dp = $1; next }
	/^# t / { if (n) print t, s, p; t = $3; n = 0; next }
	{ if (!n++) s = $2 / 1e6; if ($1 > dp - 1e-7 && $1 < dp + 1e-7) p = $2 / 1e6 }
	END { print t, s, p }' "$series.tmp" "$out/$name.samples" | sort -g > "$series"
rm -f "$series.tmp"
{
	echo "set terminal pngcairo size 1120,480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set multiplot layout 1,2 title \"The block rings after the impact: $name\""
	echo "set grid; set xzeroaxis lt -1"
	echo "set title '(a) centre-line sxx over the instants'"
	echo "set key bottom right; set xrange [0:20]"
	echo "set xlabel 'depth (mm)'; set ylabel 'sxx (MPa)'"
	echo "plot '$out/$name.mean' using 1:4:5 with filledcurves fs transparent solid 0.25 lc rgb 'grey50' title 'range over the instants', \\"
	echo "     '' using 1:2 with lines lw 2 lc rgb 'black' title 'mean (the residual profile)', \\"
	echo "     '' using 1:6 with lines dt 2 lw 1.5 lc rgb 'red' title 'at the end of the pass'"
	echo "set title '(b) sxx against time'"
	echo "set key top right; set autoscale x"
	echo "set xlabel 'time (us)'; set ylabel 'sxx (MPa)'"
	echo "plot '$series' using 1:2 with linespoints pt 7 ps 0.6 title 'surface (top layer)', \\"
	echo "     '' using 1:3 with linespoints pt 7 ps 0.6 title 'at the depth of the mean peak'"
	echo "unset multiplot"
} | gnuplot
