#!/bin/sh
# report.sh OUT - REPORT.md of examples/materials from its outputs:
# law-bench's table (ns per element-cycle of each law), the baseline
# comparison of the linear law, the one-point against full integration
# impacts, the curves of the library.
set -eu
out=$1
echo "# The hardening and rate laws: cost and checks"
echo
echo "Measured $(date '+%F') on $(nproc) cores (load average at the end: $(cut -d' ' -f1-3 /proc/loadavg))."
echo
echo "## Cost per element-cycle (law-bench, every element flowing)"
echo
awk -F'\t' 'NR == 1 { next }
	{ k = $1 "/" $2; w[k] = $7; mn[k] = $8; mx[k] = $9; ns[k] = $10; pf[k] = $11
	  if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } ne = $4; thr = $3 }
	END {
		printf "Block of %d elements, %d thread(s).  Median process CPU time per element-cycle\n", ne, thr
		printf "(ns) over the repeats, and against the linear law in the same run; the wall clock\n"
		printf "of the one-point runs (median, fastest-slowest) shows the machine'"'"'s noise.  \"plastic\"\n"
		printf "is the share of the points that flowed: the worst case, every point returning at\n"
		printf "every step (in a peening run only the points under a shot flow at a time).\n\n"
		printf "| law | one-point CPU ns | vs linear | full CPU ns | vs linear | one-point wall ns | plastic share |\n"
		printf "|---|---:|---:|---:|---:|---:|---:|\n"
		for (i = 1; i <= n; i++) {
			l = order[i]; a = l "/1pt"; b = l "/full"
			printf "| %s | %.1f | %.2f | %.1f | %.2f | %.1f (%.1f-%.1f) | %.2f |\n", l,
				ns[a], ns[a] / ns["linear/1pt"], ns[b], ns[b] / ns["linear/full"],
				w[a], mn[a], mx[a], pf[a]
		}
	}' "$out/laws.tsv"
echo
echo "## The linear law before and after (examples/cost/fe-bench.c, alternating runs)"
echo
echo "fe-bench built on the code before the laws and on this checkout, run one after"
echo "the other in rounds (block 40 x 40 x 25, 1 thread); ns per element-cycle, the"
echo "median over the rounds of each round's median: wall clock, and process CPU time"
echo "(the steadier of the two on a loaded machine)."
echo
for col in 11 14; do
[ "$col" = 11 ] && echo "Wall clock:" || echo "CPU time:"
echo
awk -F'\t' -v col="$col" 'NR == 1 { next }
	{ k = $1 SUBSEP $3; v[k, ++c[k]] = $col; cfg[$3] = 1 }
	function med(k,   i, j, t, n, a) {
		n = c[k]
		for (i = 1; i <= n; i++) a[i] = v[k, i]
		for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
		return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1])
	}
	END {
		printf "| configuration | before (ns) | after (ns) | after / before | rounds |\n|---|---:|---:|---:|---:|\n"
		for (f in cfg) {
			b = med("base" SUBSEP f); a = med("this" SUBSEP f)
			printf "| %s | %.1f | %.1f | %.3f | %d |\n", f, b, a, a / b, c["this" SUBSEP f]
		}
	}' "$out/baseline.tsv"
echo
done
echo
echo "## A peening pass at full size: the floor of the static curve (floor.sh)"
echo
echo "One pass of examples/airbus-strip's full scene (139 240 hex8, 16 S550 shots at"
echo "36 m/s, 2 threads), on the code before the floor and on this one, alternately."
echo "Without back-stresses, a lane whose trial stress lies below the static curve's"
echo "initial yield is left out of the general return (which would find it elastic)."
echo "Median wall ns per element-cycle (demshot's cost line) over the rounds."
echo
awk -F'\t' 'NR == 1 { next }
	{ k = $1 SUBSEP $3; n = ++c[k]; v[k, n] = $6; w[k, n] = $4; st[k] = $5
	  if (!($3 in seen)) { seen[$3] = 1; order[++nl] = $3 }
	  if ($1 == "this") { all++; same += $8 } }
	function med(k, a,   i, j, t, n, x) {
		n = c[k]
		for (i = 1; i <= n; i++) x[i] = a == "v" ? v[k, i] : w[k, i]
		for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
		return n % 2 ? x[(n + 1) / 2] : 0.5 * (x[n / 2] + x[n / 2 + 1])
	}
	END {
		printf "| law | before (ns) | after (ns) | after / before | wall s before / after | steps | rounds |\n"
		printf "|---|---:|---:|---:|---:|---:|---:|\n"
		for (i = 1; i <= nl; i++) {
			l = order[i]; b = med("base" SUBSEP l, "v"); a = med("this" SUBSEP l, "v")
			printf "| %s | %.1f | %.1f | %.3f | %.1f / %.1f | %s | %d |\n", l == "jc" ? "Johnson-Cook (Al7075-T651-jc)" : "linear (thesis)",
				b, a, a / b, med("base" SUBSEP l, "w"), med("this" SUBSEP l, "w"), st["this" SUBSEP l], c["this" SUBSEP l]
		}
		printf "\nThe pass state after equals the one before bit for bit in %d of %d runs.\n", same, all
	}' "$out/floor.tsv"
echo
echo "## One shot, one-point against full integration (impact.sh)"
echo
# the element size of the scene impact.sh wrote for the table's first law
element=$(sed -n 's/^  element: //p' "$out/impact/$(awk 'NR == 2 { print $1 }' "$out/impact.tsv").yaml")
echo "Ch. 7.5's shot (0.5 mm, 19 m/s) on the examples/ch75 block with $element elements;"
echo "residual sxx (MPa) at the impact point.  The acceptance asks the two rules to agree"
echo "within 5 % of the peak."
echo
awk -F'\t' 'NR == 1 { next }
	{ r[$1, $2] = $0; p[$1, $2] = $4; if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } }
	END {
		printf "| law | rule | surface sxx | peak sxx | at depth (mm) | zero (mm) | steps | wall s |\n"
		printf "|---|---|---:|---:|---:|---:|---:|---:|\n"
		for (i = 1; i <= n; i++) for (k = 0; k < 2; k++) {
			rule = k ? "full" : "one_point"; split(r[order[i], rule], f, "\t")
			printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8]
		}
		printf "\n| law | peak, one-point against full |\n|---|---:|\n"
		for (i = 1; i <= n; i++) {
			a = p[order[i], "one_point"]; b = p[order[i], "full"]
			printf "| %s | %+.1f %% |\n", order[i], 100 * (a - b) / (b < 0 ? -b : b)
		}
	}' "$out/impact.tsv"
echo
echo "## The library's curves"
echo
echo "![uniaxial curves of share/materials](curves.png)"
echo
echo "Monotonic tension and three cycles of +-1 % strain of every file in share/materials,"
echo "through the same return as the explicit and implicit stages (curve.c)."
