#!/bin/sh
# plot.sh PNG TITLE FIELDS PROFILE LABEL [PROFILE LABEL]... - residual stress
# against depth from demprofile's profile streams, one curve per profile,
# one panel per field of FIELDS (sxx, syy, szz, ep, comma-separated), as the
# thesis draws them (Figs. 7.15-7.19: stress in MPa across, depth in mm; ep
# the effective plastic strain, Fig. 7.15(b)).
set -e
png=$1 title=$2 fields=$3
shift 3
n=$(echo "$fields" | tr ',' '\n' | wc -l)
{
	echo "set terminal pngcairo size $((560 * n)),480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set multiplot layout 1,$n title \"$title\""
	echo "set grid; set key bottom right; set xzeroaxis lt -1"
	echo "set xlabel 'depth (mm)'"
	for f in $(echo "$fields" | tr ',' ' '); do
		case $f in sxx) c=3 ;; syy) c=4 ;; szz) c=5 ;; ep) c=15 ;; *) echo "plot.sh: field $f" >&2; exit 2 ;; esac
		if [ "$f" = ep ]; then
			scale=1
			echo "set ylabel 'effective plastic strain'; set key top right"
		else
			scale=1e6
			echo "set ylabel '$f (MPa)'; set key bottom right"
		fi
		printf 'plot '
		sep=
		i=1
		while [ $i -lt $# ]; do
			eval "file=\${$i}; label=\${$((i + 1))}"
			printf "%s'%s' using (\$2*1000):(\$%d/%s) with linespoints pt 7 ps 0.6 title '%s'" \
				"$sep" "$file" "$c" "$scale" "$label"
			sep=', '
			i=$((i + 2))
		done
		echo
	done
	echo "unset multiplot"
} | gnuplot
