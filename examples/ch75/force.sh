#!/bin/sh
# force.sh PNG TITLE FORCES LABEL [FORCES LABEL]... - the contact force on
# the first shot against time, from demshot's force histories (--forces),
# one curve per run (Fig. 7.16(a)): the magnitude of the resultant,
# |(fx, fy, fz)|.  (The history's fn column sums the magnitudes of the
# facets' normal forces: in a deep dimple they point along different
# normals, and their sum exceeds the resultant, by half at alpha 0.5.)
set -e
png=$1 title=$2
shift 2
{
	echo "set terminal pngcairo size 560,480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set title '$title'"
	echo "set grid; set key top right"
	echo "set xlabel 'time (us)'; set ylabel 'contact force on the shot (N)'"
	printf 'plot '
	sep=
	while [ $# -ge 2 ]; do
		printf "%s'%s' using (\$1 == 0 && \$2 == 0 ? \$3*1e6 : 1/0):(sqrt(\$6**2 + \$7**2 + \$8**2)) with lines title '%s'" "$sep" "$1" "$2"
		sep=', '
		shift 2
	done
	echo
} | gnuplot
