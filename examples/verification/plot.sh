#!/bin/sh
# plot.sh PNG ALLOY OUT "DIAMS" "ANGLES" COVERAGE - the residual sxx of one alloy after
# the last pass (area average; OUT/ALLOY-D-ANGLE/last.dat, run.sh) against
# depth, one curve per shot diameter and angle: in mm (left) and in shot
# diameters (right).  The single impacts (centre line) are not drawn.
set -e
png=$1 alloy=$2 out=$3 diams=$4 angles=$5 coverage=$6
case $alloy in
Al5052) title="Al 5052" ;;
SS316) title="316 stainless steel" ;;
Ti6Al4V) title="Ti-6Al-4V" ;;
*) title=$alloy ;;
esac
curves() { # curves XCOLUMN
	sep=
	for d in $diams; do
		for g in $angles; do
			lt=$([ "$g" = 90 ] && echo 1 || echo 2)
			printf "%s'%s' using %d:3 with linespoints dt %d pt 7 ps 0.5 lw 1.5 lc '%s' title 'd = %s mm, %s deg'" \
				"$sep" "$out/$alloy-$d-$g/last.dat" "$1" "$lt" \
				"$([ "$d" = "$(echo $diams | cut -d' ' -f1)" ] && echo '#1f77b4' || echo '#d62728')" "$d" "$g"
			sep=', '
		done
	done
	echo
}
{
	echo "set terminal pngcairo size 1120,480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set multiplot layout 1,2 title \"$title: residual sxx after $coverage % coverage at 50 m/s (area average, Han 2004, Ch. 7.6)\""
	echo "set grid; set key bottom right; set xzeroaxis lt -1"
	echo "set ylabel 'sxx (MPa)'"
	echo "set xlabel 'depth (mm)'"
	printf 'plot '; curves 1
	echo "set xlabel 'depth / shot diameter'"
	printf 'plot '; curves 2
	echo "unset multiplot"
} | gnuplot
