#!/bin/sh
# force.sh PNG TITLE FORCES LABEL [FORCES LABEL]... - the normal contact force
# on the first shot against time, from demshot's force histories (--forces),
# one curve per run (Fig. 7.16(a)).
set -e
png=$1 title=$2
shift 2
{
	echo "set terminal pngcairo size 560,480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set title '$title'"
	echo "set grid; set key top right"
	echo "set xlabel 'time (us)'; set ylabel 'normal contact force (N)'"
	printf 'plot '
	sep=
	while [ $# -ge 2 ]; do
		printf "%s'%s' using (\$1 == 0 && \$2 == 0 ? \$3*1e6 : 1/0):4 with lines title '%s'" "$sep" "$1" "$2"
		sep=', '
		shift 2
	done
	echo
} | gnuplot
