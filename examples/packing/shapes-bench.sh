#!/bin/sh
# shapes-bench.sh DEMPACK SIDES... - dempack front --shape polygon and
# ellipse (open form, URD sizes [0.5, 1], URD aspect ratios [1, 5]) in
# squares of the given sides, one run each; prints a table: shape, side,
# bodies, density, pack_s, wall_s, cpu_s, and CPU ns per body placed
# (cpu_s over bodies placed: on a shared machine the wall time measures the
# load),
# and for ellipses Newton's solves, refused solves and fall-backs.
# RATIOS: the aspect ratio laws, MIN:MAX each (URD in [MIN, MAX]; default
# 1:5), a row per law, shape and side.  Each row is the run of median CPU
# time of REPS (default 3); pack_s is the packing alone (no start, no
# output), the other times the whole run's.
set -eu
dempack=$1
shift
printf 'shape\tratio\tside\tbodies\tplaced\tdensity\tpack_s\twall_s\tcpu_s\tcpu_ns_per_body\tpack_ns_per_body\tnewton\trefused\tfallbacks\n'
for shape in ${SHAPES:-polygon ellipse}; do
	for ratio in ${RATIOS:-1:5}; do
		for side in "$@"; do
			sides=
			[ "$shape" = ellipse ] || sides="--sides 6"
			# REPS runs (default 3); the one of median CPU time
			cost=$(k=0; while [ "$k" -lt "${REPS:-3}" ]; do
				"$dempack" front --shape "$shape" $sides --ratio-min "${ratio%:*}" \
					--ratio-max "${ratio#*:}" --domain 0:0:"$side":"$side" --rmin 0.5 \
					--lambda 2 --seed 1 -b -o /dev/null 2>&1 | tail -1
				k=$((k + 1))
			done | awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^cpu_s=/) { split($i, kv, "="); print kv[2], $0 } }' |
				sort -g | awk '{ l[NR] = $0 } END { m = l[int((NR + 1) / 2)]; sub(/^[^ ]* /, "", m); print m }')
			echo "$cost" | awk -v s="$shape" -v r="$ratio" -v d="$side" '{
				for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
				printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.0f\t%.0f\t%s\t%s\t%s\n", s, r, d, v["objects"], v["placed"],
				       v["density"], v["pack_s"], v["wall_s"], v["cpu_s"], 1e9 * v["cpu_s"] / v["placed"],
				       1e9 * v["pack_s"] / v["placed"],
				       s == "ellipse" ? v["newton"] : "-", s == "ellipse" ? v["newton_refused"] : "-",
				       s == "ellipse" ? v["fallbacks"] : "-" }'
		done
	done
done
