#!/bin/sh
# report.sh OUT "VELOCITIES" SCENE - the run's report (markdown) from the
# files in OUT/vV/ of each velocity V: the arc height after each pass, the
# saturation pass, the profile and the redistributed stress after the last
# pass, the wall time of each stage (the programs' cost lines).  Everything
# printed is read from the run's outputs, nothing is typed in.
#
# Exposure: n in the thesis's passes (16 shots on the 5.6 mm square), from
# curve.txt (the Makefile's: pass p ends n = (p + 1) e, e = exposure.sh's
# exposure a pass, 1 on the thesis's grid, 0.5 with 8 random shots a pass).
# Saturation:  The point is the earliest n for which doubling the
# exposure raises the arc height by at most 10 %, h(2n) <= 1.1 h(n) (the
# rule of SAE J443; the thesis's check, Ch. 8.6.2, is the same with n = 16
# of 32 passes).  Needs 2n within the run.
#
# The gauge and the coverage (issue 25): fit.txt of each velocity
# (examples/almen's saturation.sh on curve.txt: demfit's two-parameter
# curve and the rule on the points, by the arc height and by demform's
# gauge_height), the gauge's ball rectangle, the chord and the plate from
# form.txt (demform's gauge:, chord: and plate: keys), the gauge reading
# and the plastic coverage of each pass from passes.txt.
set -eu
out=$1 vels=$2 scene=$3

for v in $vels; do
	for f in passes.txt curve.txt shots.txt fit.txt saturation.txt centre.txt form.txt demshot.log; do
		[ -s "$out/v$v/$f" ] || { echo "report.sh: $out/v$v/$f: missing" >&2; exit 1; }
	done
done

cost() { # cost FILE PROGRAM KEY: the KEY of PROGRAM's last cost line in FILE
	sed -n "s/^$2: cost: .*[ ]$3=\([^ ]*\).*/\1/p; s/^$2: cost: $3=\([^ ]*\).*/\1/p" "$1" | tail -n 1
}
costsum() { # costsum FILE PROGRAM KEY: the sum over all its cost lines
	sed -n "s/^$2: cost: $3=\([^ ]*\).*/\1/p" "$1" | awk '{ s += $1; n++ } END { printf "%.2f %d", s, n }'
}

first=$(set -- $vels; echo "$1")
elements=$(sed -n 's/^demshot: block of \([0-9]*\) elements.*/\1/p' "$out/v$first/demshot.log" | head -n 1)
npass=$(awk '!/^#/ { n++ } END { print n }' "$out/v$first/passes.txt")
nexp=$(awk '!/^#/ { n = $1 } END { print n }' "$out/v$first/curve.txt")
pattern=$(awk '$2 == "method" { for (i = 3; i <= NF; i++) if ($i ~ /^(pattern|per_pass)=/) { split($i, a, "="); v[a[1]] = a[2] } }
	$2 == "data" { exit } END { printf "%s shots a pass, %s", v["per_pass"], v["pattern"] == "random" ? "at random" : "on the offset grid" }' "$out/v$first/shots.txt")
echo "# airbus-strip: report of the run in \`$out/\`"
echo
echo "Written by report.sh from the run's outputs (scene \`$scene\`: sample block of"
echo "$elements hex8, $npass passes of $pattern, the exposure of $nexp of the"
echo "thesis's passes of 16 shots; strip 4500 hex8, free, small strain).  Exposure n:"
echo "in the thesis's passes (the shots on the 5.6 mm square over 16)."
echo

# join_passes CELL - the curves (curve.txt: exposure n, then the columns of
# passes.txt) of the velocities joined row by row: a row per pass, the
# exposure, and for each velocity the cells that the awk expression CELL
# makes of the row's fields c[1..] (a row a velocity lacks: CELL of empty
# fields)
join_passes() {
	awk -v vels="$vels" -v out="$out" 'BEGIN {
		nv = split(vels, V, " ")
		for (i = 1; i <= nv; i++) {
			f = out "/v" V[i] "/curve.txt"; k = 0
			while ((getline l < f) > 0) {
				if (l ~ /^#/) continue
				split(l, c, " "); k++; row[i, k] = '"$1"'
				if (!(k in n)) n[k] = c[1]
				if (k > last) last = k
			}
		}
		for (k = 1; k <= last; k++) {
			s = "| " n[k] " |"
			for (i = 1; i <= nv; i++) {
				if (!((i, k) in row)) { split("", c); row[i, k] = '"$1"' }
				s = s row[i, k]
			}
			print s
		}
	}'
}

echo "## Arc height after each pass (mm, over the 150 mm length)"
echo
hdr="| exposure n |" sep="|---|"
for v in $vels; do hdr="$hdr v = $v m/s | coverage |"; sep="$sep---|---|"; done
echo "$hdr"; echo "$sep"
join_passes 'sprintf(" %.4f | %.2f |", c[3], c[2])'
echo
echo "(coverage: the share of the profile region indented by more than 1 um.)"
echo

echo "## Saturation"
echo
half=$(awk -v n="$nexp" 'BEGIN { printf "%.10g", n / 2 }')
echo "| v (m/s) | saturation point: exposure n, h(2n) / h(n) | arc height there (mm) | change from n = $half to $nexp | arc height at n = $nexp (mm) |"
echo "|---|---|---|---|---|"
for v in $vels; do
	# exposures as curve.txt writes them (%.10g), so that 2n is found by its key
	awk -v v="$v" '!/^#/ { k++; n[k] = $1; h[$1] = $3; N = $1 }
	END {
		sat = ""
		for (i = 1; i <= k; i++) { d = sprintf("%.10g", 2 * n[i]); if (!(d in h) || h[n[i]] <= 0) continue
			r = h[d] / h[n[i]]
			if (sat == "" && r <= 1.1) sat = n[i]
			if (rmin == "" || r < rmin) { rmin = r; nmin = n[i] } }
		s = sat != "" ? sprintf("%s, %.3f", sat, h[sprintf("%.10g", 2 * sat)] / h[sat]) : sprintf("not reached within n = %s (smallest h(2n)/h(n): %.3f at n = %s)", N, rmin, nmin)
		a = sat != "" ? sprintf("%.4f", h[sat]) : "-"
		m = sprintf("%.10g", N / 2)
		printf "| %s | %s | %s | %+.1f %% | %.4f |\n", v, s, a, 100 * (h[N] - h[m]) / h[m], h[N]
	}' "$out/v$v/curve.txt"
done
echo
echo "Rule: the earliest n with h(2n) <= 1.1 h(n) (doubling the exposure raises"
echo "the arc height by at most 10 %; SAE J443).  The thesis checks pass 16"
echo "against pass 32 (Ch. 8.6.2); the column before last is that check at the"
echo "same exposure."
echo

echo "## Intensity as a gauge reads it, and coverage"
echo
# the gauge's rectangle, the chord and the plate as demform read them
# (form.txt, the last pass; lengths in m, printed in mm)
set -- $(awk '$1 == "gauge:" { g = $2 " " $3 } $1 == "chord:" { c = $2 } $1 == "plate:" { p = $2 " " $3 " " $4 }
	END { if (g == "") g = "0 0"; print g, c, p }' "$out/v$first/form.txt")
glx=$1 gly=$2 chord=$3
plate=$(awk -v L="$4" -v W="$5" -v h="$6" 'BEGIN { printf "%g x %g x %g", L * 1e3, W * 1e3, h * 1e3 }')
span=$(awk -v lx="$glx" -v ly="$gly" 'BEGIN { printf "%g x %g", lx * 1e3, ly * 1e3 }')
along=$(awk -v lx="$glx" -v ly="$gly" 'BEGIN { printf "%g mm along the strip and %g mm across", lx * 1e3, ly * 1e3 }')
cmm=$(awk -v c="$chord" 'BEGIN { printf "%g", c * 1e3 }')
if [ "$glx" = 0 ]; then
	echo "No gauge reading: the gauge's ball rectangle does not fit on the plate"
	echo "(demform(1), form.gauge)."
	echo
else
sph=$(awk -v lx="$glx" -v ly="$gly" -v c="$chord" 'BEGIN { printf "%.4f", ((lx / 2) ^ 2 + (ly / 2) ^ 2) / (c / 2) ^ 2 }')
echo "The gauge (demform's gauge_height): the face opposite the peened one rests on"
echo "four balls at the corners of a $span mm rectangle centred on the strip"
echo "(form.gauge; demform's default, 31.75 x 15.875 mm, is the SAE J442 Almen gauge's),"
echo "and the reading is the height of that face's centre over the balls' plane."
echo "This strip ($plate mm) is not an Almen strip (A: 76.2 x 19.05 x 1.29 mm):"
echo "the reading is that of an Almen gauge set on its middle, a span of"
echo "$along, against the arc height's"
echo "$cmm mm chord along the length.  It is not an Almen intensity, and no A, N or C"
echo "designation applies.  For w = -(kx x^2 + ky y^2)/2 the gauge over the chord is"
echo "(kx p^2 + ky q^2) / (kx (L/2)^2), p and q the half sides, L the chord: $sph"
echo "when kx = ky."
echo
echo "Saturation point (SAE J443: h(2T) = 1.1 h(T)) by examples/almen's saturation.sh"
echo "(demfit: the fit h(n) = a (1 - exp(-b n)), T = ln 10 / b, h(T) = 0.9 a; and the"
echo "rule on the points, the earliest n with h(2n) <= 1.1 h(n)); T and n in the"
echo "thesis's passes, heights in mm:"
echo
echo "| v (m/s) | arc height: fit T, h(T) | arc height: points n, h(n) | **gauge: fit T, h(T)** | **gauge: points n, h(n)** | gauge over chord: the fits' h(T); at n = $nexp; closed form | exposure to 98 % plastic coverage |"
echo "|---|---|---|---|---|---|---|"
for v in $vels; do
	awk -v v="$v" -v lx="$glx" -v ly="$gly" -v c="$chord" '
	FNR == NR { f[$1] = $2; next }
	!/^#/ { n = $1; h = $3; kx = $4; ky = $5; g = $6; pc = $7; N = n
		if (pc >= 0.98 && n98 == "") n98 = n }
	END {
		for (k = 0; k < 2; k++) {
			p = k ? "gauge_" : ""
			T = f[p "T"]; I = f[p "intensity"]
			s[k] = sprintf("%.2f, %.4f%s", T, I, 2 * T > N ? sprintf(" (2T = %.2f > %s: extrapolated)", 2 * T, N) : "")
			d[k] = f[p "data_T"] > 0 ? sprintf("%s, %.4f", f[p "data_T"], f[p "data_h"]) : sprintf("none within %s", N)
		}
		r = sprintf("%.4f; %.4f; %.4f", f["gauge_intensity"] / f["intensity"], g / h,
			(kx * (lx / 2) ^ 2 + ky * (ly / 2) ^ 2) / (kx * (c / 2) ^ 2))
		c98 = n98 != "" ? n98 : sprintf("stays below (%.3f at %s)", pc, N)
		printf "| %s | %s | %s | %s | %s | %s | %s |\n", v, s[0], d[0], s[1], d[1], r, c98
	}' "$out/v$v/fit.txt" "$out/v$v/curve.txt"
done
echo
echo "(Closed form: with the last pass's curvatures kx, ky.  Plastic coverage:"
echo "demprofile's share of the region's top whose plastic strain exceeds"
echo "profile.plastic_threshold (0.002 by default), the FE counterpart of the dimpled"
echo "area of SAE J2277, where 100 % coverage is 98 % of the surface dimpled.)"
echo
hdr="| exposure n |" sep="|---|"
for v in $vels; do hdr="$hdr v = $v m/s: gauge (mm) | gauge / arc height | plastic coverage |"; sep="$sep---|---|---|"; done
echo "$hdr"; echo "$sep"
join_passes 'sprintf(" %.5f | %.4f | %.3f |", c[6], c[3] > 0 ? c[6] / c[3] : 0, c[7])'
echo
fi

echo "## Residual profile of the sample block and the formed strip (last pass)"
echo
echo "| v (m/s) | surface sxx (MPa) | peak sxx (MPa) at depth (mm) | compressive to (mm) | ep at surface | strip centre, peened face sxx (MPa) | peak tension (MPa) at depth (mm) | unpeened face sxx (MPa) | curvature x, y (1/m) |"
echo "|---|---|---|---|---|---|---|---|---|"
for v in $vels; do
	prof=$(awk '!/^#/ { l = $0 } END { split(l, c, " "); printf "%.0f | %.0f at %.2f | %.2f | %.3f", c[2] / 1e6, c[3] / 1e6, c[4] * 1e3, c[5] * 1e3, c[6] }' "$out/v$v/saturation.txt")
	cen=$(awk '!/^#/ { n++; if (n == 1) top = $2; if ($2 > mx) { mx = $2; dm = $1 } bot = $2 }
		END { printf "%.0f | %.0f at %.2f | %.0f", top / 1e6, mx / 1e6, dm * 1e3, bot / 1e6 }' "$out/v$v/centre.txt")
	curv=$(awk '{ c[$1] = $2 } END { printf "%.3f, %.3f", c["curvature_x:"], c["curvature_y:"] }' "$out/v$v/form.txt")
	echo "| $v | $prof | $cen | $curv |"
done
echo

echo "## Wall time of each stage (s)"
echo
echo "| v (m/s) | dempack | demshot | demshot per pass | demprofile | demform, every pass (runs) | demform, last pass with --centre |"
echo "|---|---|---|---|---|---|---|"
for v in $vels; do
	d=$out/v$v
	# a resumed run: the whole run's time (total_wall_s), not the last process's
	shot=$(cost "$d/demshot.log" demshot total_wall_s)
	[ -n "$shot" ] || shot=$(cost "$d/demshot.log" demshot wall_s)
	set -- $(costsum "$d/demform-passes.log" demform wall_s)
	echo "| $v | $(cost "$d/dempack.log" dempack wall_s) | $shot | $(awk -v s="$shot" -v n="$npass" 'BEGIN { printf "%.1f", s / n }') | $(cost "$d/demprofile.log" demprofile wall_s) | $1 ($2) | $(cost "$d/demform.log" demform wall_s) |"
done
echo
echo "demshot's cost lines (elements, steps, ns per element cycle; a resumed run's"
echo "figures are those of its last process, total_wall_s the whole run's):"
echo
for v in $vels; do
	echo "- v = $v m/s: $(grep '^demshot: cost:' "$out/v$v/demshot.log" | tail -n 1 | sed 's/^demshot: cost: //')"
done
echo
echo "Plots: \`$out/saturation.png\` (arc height against exposure), \`$out/profiles.png\`"
echo "(sxx and ep against depth per pass), \`$out/redistributed.png\` (sxx through"
echo "the strip, imposed and redistributed)."
