#!/bin/sh
# fig.sh PNG TITLE OUT NAME LABEL [NAME LABEL]... - a figure of Ch. 7.4 as
# the thesis draws them (Figs. 7.9-7.11): (a) the normal contact force on
# the disk against time, N per mm of slab (OUT/NAME.fn), (b) the residual
# sxx along the centre line against depth (OUT/NAME.mean: the mean over
# the instants of run.sh), one curve per run.  A NAME whose files are
# missing is left out (the FE shot, before it is run).
set -e
png=$1 title=$2 out=$3
shift 3
plots() {  # plots FILE-SUFFIX USING
	sep=
	while [ $# -ge 4 ]; do
		[ -s "$out/$3.fn" ] && [ -s "$out/$3.mean" ] &&
			{ printf "%s'%s/%s.%s' using %s with lines lw 1.5 title '%s'" "$sep" "$out" "$3" "$1" "$2" "$4"; sep=', '; }
		a=$1 b=$2
		shift 4
		set -- "$a" "$b" "$@"
	done
	echo
}
{
	echo "set terminal pngcairo size 1120,480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set multiplot layout 1,2 title \"$title\""
	echo "set grid; set key top right"
	echo "set title '(a) normal contact force'"
	echo "set xlabel 'time (us)'; set ylabel 'F_n (N/mm)'"
	printf 'plot '; plots fn '1:2' "$@"
	echo "set title '(b) residual sxx along the centre line'"
	echo "set key bottom right; set xzeroaxis lt -1; set xrange [0:20]"
	echo "set xlabel 'depth (mm)'; set ylabel 'sxx (MPa)'"
	printf 'plot '; plots mean '1:2' "$@"
	echo "unset multiplot"
} | gnuplot
