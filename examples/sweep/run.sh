#!/bin/sh
# run.sh OUT [CASES] - the sweep on this machine: every case of CASES
# (default cases.txt) by case.sh, JOBS at once (default 1: each case takes
# every core), rows into OUT/rows/NAME.tsv.  With a host file, GNU parallel
# spreads the same commands over machines:
#   grep -v '^#' cases.txt | parallel --sshloginfile hosts --colsep '[ \t]+' \
#       "cd $PWD && sh case.sh out {1} {2} {3} > out/rows/{1}.tsv"
set -eu
out=$1 cases=${2:-cases.txt}
mkdir -p "$out/rows"
grep -v '^#' "$cases" | while read -r name mat speed; do
	[ -n "$name" ] || continue
	echo "sweep: $name ($mat, $speed m/s)" >&2
	sh case.sh "$out" "$name" "$mat" "$speed" > "$out/rows/$name.tsv"
done
