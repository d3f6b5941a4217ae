#!/bin/sh
# report.sh OUT SCENE - the Almen run's report (markdown), from the files in
# OUT: the saturation curve, the saturation point and intensity (fit.txt of
# saturation.sh: demfit, the library's fitter), the Almen gauge's reading
# and its intensity (runs since issue 25), the wall time of each stage.
# Nothing typed in.
set -eu
out=$1 scene=$2
for f in curve.txt fit.txt saturation.txt demshot.log demform.log; do
	[ -s "$out/$f" ] || { echo "report.sh: $out/$f: missing" >&2; exit 1; }
done
val() { awk -v k="$1" '$1 == k { print $2 }' "$out/fit.txt"; }
cost() { sed -n "s/^$2: cost: .*[ ]$3=\([^ ]*\).*/\1/p; s/^$2: cost: $3=\([^ ]*\).*/\1/p" "$1" | tail -n 1; }

elements=$(sed -n 's/^demshot: block of \([0-9]*\) elements.*/\1/p' "$out/demshot.log" | head -n 1)
echo "# almen: report of the run in \`$out/\`"
echo
echo "Written by report.sh from the run's outputs (scene \`$scene\`, sample block of $elements hex8)."
echo
echo "## Saturation point and intensity"
echo
awk '$1 != "" { v[$1] = $2 } END {
	T = v["T"]; I = v["intensity"]; N = v["nmax"]
	printf "- fit h(n) = a (1 - exp(-b n)): a = %.4f mm, b = %.4f per unit of exposure, rms misfit %.4f mm\n", v["fit_a"], v["fit_b"], v["fit_rms"]
	printf "- **saturation point T = %.1f** (exposure; h(2T) = 1.1 h(T): T = ln 10 / b)%s\n", T, \
		(2 * T <= N ? "" : sprintf(" -- 2T = %.1f is beyond the run (exposure %g): extrapolated", 2 * T, N))
	printf "- **intensity h(T) = %.4f mm = %.4f in, i.e. %.4f A** (usable range of the A strip 0.004-0.024 in: %s)\n", \
		I, I / 25.4, I / 25.4, (I / 25.4 >= 0.004 && I / 25.4 <= 0.024 ? "inside" : "OUTSIDE")
	if (v["T3"] > 0)
		printf "- the three-parameter curve h(n) = a (1 - exp(-b n^c)) (a = %.4f mm, b = %.4f, c = %.4f, rms %.4f mm): T = %.2f, h(T) = %.4f mm%s\n", \
			v["fit3_a"], v["fit3_b"], v["fit3_c"], v["fit3_rms"], v["T3"], v["intensity3"], \
			(2 * v["T3"] <= N ? "" : sprintf(" -- 2T = %.1f is beyond the run (exposure %g): extrapolated", 2 * v["T3"], N))
	else
		printf "- the three-parameter curve h(n) = a (1 - exp(-b n^c)) (a = %.4f mm, b = %.4f, c = %.4f, rms %.4f mm): 2^c <= 1.1, no saturation point\n", \
			v["fit3_a"], v["fit3_b"], v["fit3_c"], v["fit3_rms"]
	if (v["data_T"] > 0)
		printf "- the rule on the points themselves: n = %g, h = %.4f mm (h(2n) <= 1.1 h(n))\n", v["data_T"], v["data_h"]
	else
		printf "- the rule on the points themselves: no n with 2n measured satisfies h(2n) <= 1.1 h(n)\n"
	if ("gauge_T" in v) {
		G = v["gauge_intensity"]
		printf "- **as the J442 gauge reads it** (the unpeened face on four balls, 31.75 x 15.875 mm, demform gauge_height): fit T = %.1f%s, **intensity %.4f mm = %.4f A**", v["gauge_T"], \
			(2 * v["gauge_T"] <= N ? "" : sprintf(" (2T = %.1f beyond the run: extrapolated)", 2 * v["gauge_T"])), G, G / 25.4
		if (v["gauge_data_T"] > 0)
			printf "; on the points n = %g, %.4f mm = %.4f A", v["gauge_data_T"], v["gauge_data_h"], v["gauge_data_h"] / 25.4
		printf "; gauge over chord %.3f\n", G / I
	}
}' "$out/fit.txt"
echo
echo "## The curve"
echo
echo "| exposure n | coverage (indented) | plastic coverage | arc height (mm) | (in) | h(2n)/h(n) | gauge (mm) | curvature x, y (1/m) | surface sxx of the held block (MPa) |"
echo "|---|---|---|---|---|---|---|---|---|"
awk 'FNR == NR { if (!/^#/) s[++S] = $2; next }
	!/^#/ { n[++N] = $1; c[N] = $2; h[N] = $3; H[$1] = $3; kx[N] = $4; ky[N] = $5
		g[N] = NF >= 6 ? sprintf("%.4f", $6) : "-"; pc[N] = NF >= 7 ? sprintf("%.3f", $7) : "-" }
	END { for (i = 1; i <= N; i++) {
		r = (2 * n[i]) in H ? sprintf("%.3f", H[2 * n[i]] / h[i]) : "-"
		printf "| %g | %.2f | %s | %.4f | %.5f | %s | %s | %.3f, %.3f | %.0f |\n", n[i], c[i], pc[i], h[i], h[i] / 25.4, r, g[i], kx[i], ky[i], s[i] / 1e6 } }' \
	"$out/saturation.txt" "$out/curve.txt"
awk '!/^#/ && NF >= 7 && $7 >= 0.98 { printf "\nPlastic coverage (demprofile, ep > 0.002 on the top layer) reaches 98 %% at exposure %g.\n", $1; f = 1; exit }
	!/^#/ && NF >= 7 { m = $7; n = $1 }
	END { if (!f && n) printf "\nPlastic coverage stays below 98 %% (%.3f at exposure %g).\n", m, n }' "$out/curve.txt"
echo
echo "## Wall time (s)"
echo
nf=$(sed -n 's/^demform: cost: wall_s=\([^ ]*\).*/\1/p' "$out/demform.log" | awk '{ s += $1; n++ } END { printf "%.1f (%d runs)", s, n }')
echo "dempack $(cost "$out/dempack.log" dempack wall_s), demshot $(cost "$out/demshot.log" demshot wall_s), demprofile $(cost "$out/demprofile.log" demprofile wall_s), demform $nf"
echo
echo "demshot: $(grep '^demshot: cost:' "$out/demshot.log" | tail -n 1 | sed 's/^demshot: cost: //')"
echo
echo "Plot: \`$out/saturation.png\`."
