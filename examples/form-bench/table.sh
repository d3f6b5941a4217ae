#!/bin/sh
# table.sh COST...: one line per run from demform's cost lines: elements,
# equations, Newton iterations, factorisations, wall time, and the time per
# Newton iteration (assembly + factorisation + solve over the iterations).
printf '%-14s %9s %9s %5s %5s %8s %8s %8s %10s\n' run elements equations iter fact wall_s asm_s fact_s s_per_iter
for f in "$@"; do
	awk -v run="$(basename "$f" .cost)" '{
		for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
		it = v["iterations"] > 0 ? v["iterations"] : 1
		printf "%-14s %9d %9d %5d %5d %8.2f %8.2f %8.2f %10.2f\n", run, v["elements"], v["equations"],
			v["iterations"], v["factorisations"], v["wall_s"], v["assemble_s"], v["factor_s"],
			(v["assemble_s"] + v["factor_s"] + v["solve_s"]) / it
	}' "$f"
done
