#!/bin/sh
# converge.sh BIN DIR SIZES LAWS - the table of the mesh study of make
# converge from impact.sh's runs DIR/SIZE/LAW.tsv (SIZE the element size in
# mm; each size's directory holds the runs' scenes, logs and states).
#
# The peak residual sxx is taken two ways from each run's state:
#   square  over the 0.2 x 0.2 mm square centred on the impact point, what
#           impact.sh samples (the 2 x 2 elements meeting there at d/10,
#           4 x 4 at d/20, 8 x 8 at d/40): the same region at every size,
#           so its limit is the mean over that square;
#   axis    over the 2 x 2 elements meeting at the impact point (a square of
#           2 h), demprofile run again here on the kept state: its limit is
#           the value on the shot's axis, the true peak.
# At d/10 the two are the same elements.  Within a square the peak is the
# largest magnitude over the element layers (their centroids' depths).
#
# One TSV row per law, sample and size, the sizes in the order given: law,
# sample, element (mm), d/h (d the shot's diameter), elements of the mesh,
# peak residual sxx (MPa) with one-point and with full integration, their
# gap relative to the full element's peak (%, negative: one-point more
# compressive), the wall seconds of each run (demshot's cost line: the same
# for both samples), the depth (mm) of each peak, the steps of each run.
set -eu
bin=$1 dir=$2 sizes=$3 laws=$4
printf 'law\tsample\telement_mm\td_over_h\telements\tpeak_one_point\tpeak_full\tgap_pct\twall_one_point_s\twall_full_s\tdepth_one_point_mm\tdepth_full_mm\tsteps_one_point\tsteps_full\n'
for law in $laws; do
	for sample in square axis; do
		for h in $sizes; do
			run=$dir/$h
			# the shot's radius in mm, as the scene writes it (0.5 mm)
			r=$(sed -n '/^shot:/,/^[a-z]/s/^  radius: \([0-9.eE+-]*\) mm.*/\1/p' "$run/$law.yaml")
			ne=$(sed -n 's/^demshot: cost: .* elements=\([0-9]*\) .*/\1/p' "$run/$law-one_point.log")
			ne_full=$(sed -n 's/^demshot: cost: .* elements=\([0-9]*\) .*/\1/p' "$run/$law-full.log")
			[ -n "$r" ] && [ -n "$ne" ] && [ "$ne" = "$ne_full" ] ||
				{ echo "converge.sh: $run: no shot radius or element count in the scene and logs of $law" >&2; exit 1; }
			if [ "$sample" = axis ]; then
				a=$(awk -v h="$h" 'BEGIN { printf "%.6gmm", 2 * h }')
				for rule in one_point full; do
					"$bin"/demprofile -q --area "$a:$a" --margin 0 --field sxx \
						--saturation "$run/$law-$rule-axis.sxx" -o /dev/null \
						"$run/$law-$rule.state" 2> "$run/$law-$rule-axis.log" ||
						{ cat "$run/$law-$rule-axis.log" >&2; exit 1; }
				done
			fi
			# the saturation table: pass, surface, peak, its depth, zero (SI)
			for rule in one_point full; do
				f=$run/$law-$rule.sxx
				[ "$sample" = axis ] && f=$run/$law-$rule-axis.sxx
				awk -v rule="$rule" '!/^#/ { printf "%s\t%.1f\t%.3f\n", rule, $3 / 1e6, $4 * 1e3 }' "$f"
			done |
			awk -F'\t' -v law="$law" -v sample="$sample" -v h="$h" -v r="$r" -v ne="$ne" -v runs="$run/$law.tsv" '
				{ p[$1] = $2; d[$1] = $3 }
				END {
					while ((getline line < runs) > 0) {
						split(line, f, "\t")
						if (f[1] == law) { s[f[2]] = f[7]; w[f[2]] = f[8] }
					}
					if (!("one_point" in p) || !("full" in p) || !("one_point" in w) || !("full" in w)) {
						print "converge.sh: " runs ": no one_point and full results for " law > "/dev/stderr"
						exit 1
					}
					a = p["one_point"]; b = p["full"]
					printf "%s\t%s\t%s\t%g\t%d\t%.1f\t%.1f\t%+.1f\t%s\t%s\t%.3f\t%.3f\t%s\t%s\n", law, sample, h, 2 * r / h, ne,
						a, b, 100 * (a - b) / (b < 0 ? -b : b), w["one_point"], w["full"],
						d["one_point"], d["full"], s["one_point"], s["full"]
				}'
		done
	done
done
