#!/bin/sh
# steady.sh OUT [F...] - what the end of a pass costs: the quick run at
# 46.5 m/s (quick.yaml, demshot --accuracy coarse, 16 passes of 8) with the pass
# ending when the block's kinetic energy has fallen to F times its peak
# (run.steady; default list 0.01, the default, then 0.05 and 0.2).  Most of
# a pass is the block ringing down after the shots have left, so F sets
# most of demshot's time; the table shows what it changes in the result.
#
# Writes OUT/F.yaml and the runs OUT/F/v46.5/ (through the Makefile), and
# prints a Markdown table: per F, demshot's wall time and steps, the arc
# height at each exposure n (curve.txt: in the thesis's passes of 16
# shots), and the change against the first F.
set -e
out=$1
shift
[ -n "$out" ] || { echo "usage: steady.sh OUT [F...]" >&2; exit 2; }
[ $# -gt 0 ] || set -- 0.01 0.05 0.2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
mkdir -p "$out"
for f in "$@"; do
	# quick.yaml with run.steady F (its run section gains the line)
	awk -v f="$f" '{ print } /^run:/ { print "  steady: " f }' "$here/quick.yaml" > "$out/$f.yaml"
	make -s --no-print-directory -C "$here" SCENE="$out/$f.yaml" OUT="$out/$f" VELOCITIES=46.5 \
		ACCURACY=coarse ${THREADS:+THREADS=$THREADS} ${BIN:+BIN=$BIN} \
		"$out/$f/v46.5/curve.txt" > "$out/$f.make.log" 2>&1
done
printf '| run.steady | demshot wall (s) | steps |'
awk '!/^#/ { printf " n = %s |", $1 }' "$out/$1/v46.5/curve.txt"
echo " after the last pass, against $1 |"
printf '|---|---|---|'
awk '!/^#/ { printf "---|" }' "$out/$1/v46.5/curve.txt"
echo "---|"
for f in "$@"; do
	c=$(cost_field "$out/$f/v46.5/demshot.log" wall_s steps)
	printf '| %s | %s | %s |' "$f" "$(echo "$c" | cut -f1)" "$(echo "$c" | cut -f2)"
	awk -v ref="$out/$1/v46.5/curve.txt" 'BEGIN { while ((getline l < ref) > 0) if (l !~ /^#/) { split(l, a, " "); h0 = a[3] } }
		!/^#/ { printf " %.3f |", $3; h = $3 }
		END { printf " %+.1f %% |\n", 100 * (h / h0 - 1) }' "$out/$f/v46.5/curve.txt"
done
