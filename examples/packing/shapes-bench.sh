#!/bin/sh
# shapes-bench.sh DEMPACK SIDES... - dempack front --shape polygon and
# ellipse (open form, URD sizes [0.5, 1], URD aspect ratios [1, 5]) in
# squares of the given sides, one run each; prints a table: shape, side,
# bodies, density, pack_s, wall_s, cpu_s, and CPU ns per body placed
# (cpu_s over bodies placed: on a shared machine the wall time measures the
# load),
# and for ellipses Newton's solves, refused solves and fall-backs.
set -eu
dempack=$1
shift
printf 'shape\tside\tbodies\tplaced\tdensity\tpack_s\twall_s\tcpu_s\tcpu_ns_per_body\tnewton\trefused\tfallbacks\n'
for shape in ${SHAPES:-polygon ellipse}; do
	for side in "$@"; do
		sides=
		[ "$shape" = ellipse ] || sides="--sides 6"
		cost=$("$dempack" front --shape "$shape" $sides --ratio-min 1 --ratio-max 5 \
			--domain 0:0:"$side":"$side" --rmin 0.5 --lambda 2 --seed 1 -b -o /dev/null 2>&1 | tail -1)
		echo "$cost" | awk -v s="$shape" -v d="$side" '{
			for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
			printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.0f\t%s\t%s\t%s\n", s, d, v["objects"], v["placed"],
			       v["density"], v["pack_s"], v["wall_s"], v["cpu_s"], 1e9 * v["cpu_s"] / v["placed"],
			       s == "ellipse" ? v["newton"] : "-", s == "ellipse" ? v["newton_refused"] : "-",
			       s == "ellipse" ? v["fallbacks"] : "-" }'
	done
done
