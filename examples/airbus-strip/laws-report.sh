#!/bin/sh
# laws-report.sh "LAWS" [PNG] - REPORT-laws.md of `make laws` (and the
# curves of every law in one plot, PNG, laws.gp): the quick preset
# to the exposure of 32 of the thesis's passes with each library law
# (out-laws/LAW/vV/curve.txt: exposure n, in the thesis's passes of 16
# shots, then passes.txt's columns) beside the linear law of the thesis on the same
# preset (REPORT-long.md's table, from `make long`: the linear law's code
# path is unchanged since) and the thesis's computed 2.2 / 2.45 mm after 32
# passes (Ch. 8.6.2).  Per law and velocity: h(8), h(16), h(32), the
# change from 16 to 32 (the thesis's saturation test: within 10 %), the
# J443 rule on the points (the earliest n with h(2n) <= 1.1 h(n)), the
# surface sxx and ep after the last pass, demshot's time.
set -eu
laws=$1
vels="36 46.5"
echo "# airbus-strip: the material laws (quick preset, exposure 32)"
echo
echo "Written by \`make laws\` (laws-report.sh) on $(date '+%F') ($(nproc) cores, load average at"
echo "the end $(cut -d' ' -f1-3 /proc/loadavg)).  The quick preset (quick.yaml: 0.1 mm elements,"
echo "demshot --accuracy coarse) run to the exposure of 32 of the thesis's passes (n, the shots"
echo "on the 5.6 mm square over 16) with the material section taken from the"
echo "library (share/materials); the linear row is the same preset with the thesis's law"
echo "(REPORT-long.md).  Thesis (Ch. 8.6.2, its own model, 0.05 mm elements): 2.2 mm (36 m/s)"
echo "and 2.45 mm (46.5 m/s) after 32 passes, saturated by pass 16."
echo
echo "| law | v (m/s) | h(8) mm | h(16) | h(32) | 16 to 32 | saturated (16-32 within 10 %) | J443 point n (h(2n)/h(n)) | surface sxx (MPa) | demshot s |"
echo "|---|---|---:|---:|---:|---:|---|---|---:|---:|"
for v in $vels; do
	col=$([ "$v" = 36 ] && echo 2 || echo 4)
	# the first table only (arc height per pass); later ones (the gauge's)
	# also start with the exposure
	awk -F'|' -v c="$col" '/^\| [0-9.]+ \|/ { t = 1; n = $2 + 0; if (n <= 32) print n, 0, $(c + 1) + 0; next }
		t { exit }' REPORT-long.md \
		> "/tmp/laws-linear-$$-$v.txt"
done
row() {   # law v curve-file saturation-file demshot-log
	awk -v law="$1" -v v="$2" -v sat="$4" -v lg="$5" '
		FILENAME == sat && !/^#/ { s = $2; e = $0 }
		FILENAME == lg && /^demshot: cost: / { for (i = 3; i <= NF; i++) { split($i, kv, "="); if (kv[1] == "wall_s") w = kv[2] } }
		FILENAME != sat && FILENAME != lg && !/^#/ { n = sprintf("%.10g", $1); k++; x[k] = n; h[n] = $3; N = n }
		END {
			p = ""
			for (i = 1; i <= k; i++) { d = sprintf("%.10g", 2 * x[i])
				if ((d in h) && h[x[i]] > 0 && h[d] <= 1.1 * h[x[i]]) { p = x[i]; break } }
			j = p != "" ? sprintf("%s (%.3f)", p, h[sprintf("%.10g", 2 * p)] / h[p]) : "none within " N
			d = h[16] > 0 ? 100 * (h[32] / h[16] - 1) : 0
			printf "| %s | %s | %.3f | %.3f | %.3f | %+.1f %% | %s | %s | %s | %s |\n", law, v,
				h[8], h[16], h[32], d, (d <= 10 && d >= -10) ? "yes" : "no", j,
				s != "" ? sprintf("%.0f", s / 1e6) : "-", w != "" ? w : "-"
		}' "$3" ${4:+"$4"} ${5:+"$5"}
}
label() {
	case $1 in
	ideal) echo "ideal (thesis yield, no hardening: the saturated limit)" ;;
	*) echo "$1" ;;
	esac
}
for v in $vels; do
	row "linear (thesis, REPORT-long.md)" "$v" "/tmp/laws-linear-$$-$v.txt" "" ""
	for l in $laws; do
		d=out-laws/$l/v$v
		[ -f "$d/curve.txt" ] || { echo "| $(label "$l") | $v | (not run) ||||||||"; continue; }
		row "$(label "$l")" "$v" "$d/curve.txt" "$d/saturation.txt" "$d/demshot.log"
	done
done
# the curves in one plot (laws.gp), the linear law's from REPORT-long.md
if [ -n "${2:-}" ] && command -v gnuplot > /dev/null; then
	files= labels=
	for v in $vels; do
		files="$files /tmp/laws-linear-$$-$v.txt" labels="$labels linear_thesis_${v}_m/s"
		for l in $laws; do
			[ -f "out-laws/$l/v$v/curve.txt" ] || continue
			files="$files out-laws/$l/v$v/curve.txt" labels="$labels ${l}_${v}_m/s"
		done
	done
	gnuplot -e "out='$2'; files='$files'; labels='$labels'" laws.gp
fi
rm -f /tmp/laws-linear-$$-*.txt
echo
echo "Surface sxx: the saturation table's surface value after the last pass (demprofile)."
echo "The laws and their sources: share/materials/LAW.yaml and share/README.md.  The"
echo "ideal row is no library material: the thesis's 450 MPa yield with the hardening"
echo "modulus set to zero, the state every saturating isotropic law (Voce) tends to."

# the full scene at one velocity (make laws-full), beside the linear law's
# full run (REPORT-full.md, the same scene and demshot settings)
full=
for d in out-laws-full/*/; do
	[ -f "$d/REPORT.md" ] && full="$full $(basename "$d")"
done
[ -n "$full" ] || exit 0
echo
echo "## Full size (scene.yaml: 0.05 mm elements, 139 240 hex8, exposure 32, 2 threads)"
echo
echo "\`make laws-full\`: the full scene at one velocity with the library law, beside the"
echo "linear law's full run (REPORT-full.md, \`make\`, an earlier day: its time is"
echo "comparable only as a figure of that day).  Issue 16 asks for at most 30 min."
echo
echo "| law | v (m/s) | h(16) mm | h(32) | 16 to 32 | demshot wall (min) | steps | ns per element-cycle |"
echo "|---|---|---:|---:|---:|---:|---:|---:|"
fullrow() {   # label v report column
	awk -F'|' -v law="$1" -v v="$2" -v c="$4" '
		/^\| [0-9.]+ \|/ { h[$2 + 0] = $(c) + 0 }
		/^- v = / && index($0, "v = " v " m/s:") {
			for (i = 1; i <= split($0, f, " "); i++) { split(f[i], kv, "=");
				if (kv[1] == "wall_s") w = kv[2]; if (kv[1] == "steps") st = kv[2];
				if (kv[1] == "ns_per_elem_cycle") ns = kv[2] } }
		END { printf "| %s | %s | %.3f | %.3f | %+.1f %% | %.1f | %d | %.1f |\n", law, v,
			h[16], h[32], 100 * (h[32] / h[16] - 1), w / 60, st, ns }' "$3"
}
for l in $full; do
	v=$(ls -d out-laws-full/$l/v* | head -1 | sed 's/.*\/v//')
	fullrow "linear (thesis, REPORT-full.md)" "$v" REPORT-full.md "$([ "$v" = 36 ] && echo 3 || echo 5)"
	fullrow "$(label "$l")" "$v" "out-laws-full/$l/REPORT.md" 3
done
