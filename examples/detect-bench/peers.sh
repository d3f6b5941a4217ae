#!/bin/sh
# peers.sh DEMDETECT PEER ROUNDS REPEAT "CUTOFF..." DATA - time demdetect
# (D-cell, the default) and its peer, CGAL's box_self_intersection_d
# (peer-cgal) with each CUTOFF (its parameter: below that many boxes a range
# is searched by brute force; 10 by default), on the same data set, back to
# back, ROUNDS times in turn (ours, CGAL with each cutoff, ours, ...), and
# print each process's cost line (the last line of its stderr) prefixed by
# "ours" or "cgal-kCUTOFF".  Each process reads DATA once and detects REPEAT
# times (`demdetect --repeat`, `peer-cgal -r`): detect_s is its first (cold)
# call, detect_warm_s the median of the others (warm).  One thread.
#
# Alternating the two codes within one run puts both under the same load, so
# the ratio holds where the absolute times swing from hour to hour.
set -eu
demdetect=$1 peer=$2 rounds=$3 repeat=$4 cutoffs=$5 data=$6
[ "$repeat" -ge 2 ] || { echo "peers.sh: REPEAT must be at least 2 (1 cold + warm calls)" >&2; exit 2; }
err=$(mktemp)
trap 'rm -f "$err"' EXIT
echo "# binary $(cksum < "$demdetect" | awk '{ print $1 }')"
echo "# repeat $repeat"
echo "# load $(cut -d' ' -f1 /proc/loadavg)"
i=0
while [ "$i" -lt "$rounds" ]; do
	for who in ours $(for k in $cutoffs; do echo "cgal-k$k"; done); do
		if [ "$who" = ours ]; then
			OMP_NUM_THREADS=1 "$demdetect" -q --repeat "$repeat" -c "$data" >/dev/null 2>"$err" ||
				{ cat "$err" >&2; exit 1; }
		else
			"$peer" -r "$repeat" -k "${who#cgal-k}" "$data" >/dev/null 2>"$err" || { cat "$err" >&2; exit 1; }
		fi
		line=$(tail -n 1 "$err")
		case $line in
		*": cost: "*detect_warm_s=*) echo "$who $line" ;;
		*) echo "peers.sh: $data: no cost line with detect_warm_s from $who" >&2; exit 1 ;;
		esac
	done
	i=$((i + 1))
done
echo "# load $(cut -d' ' -f1 /proc/loadavg)"
