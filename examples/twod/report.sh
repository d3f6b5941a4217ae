#!/bin/sh
# report.sh OUT "ALPHAS" RHO "MASS_RHOS" - REPORT.md (markdown on standard
# output) from the runs of run.sh in OUT: the impact and the residual sxx
# of every run (Figs. 7.9-7.11), the spread across alpha, linear against
# Hertz, the three partial contact schemes, the ringing of the block, and
# the duration question (README.md).  Nothing typed in: every figure is
# read from the runs' files (the model's data through params.sh).  The FE
# shot's section is FE-SHOT.md (make fe-shot) when it is there.
set -e
out=$1 alphas=$2 rho=$3 mass_rhos=$4
here=$(dirname "$0")
main=hertz-2.5-area-$rho
for n in $main linear-2.5-area-$rho hertz-2.5-width-$rho hertz-2.5-potential-$rho; do
	[ -s "$out/$n.row" ] || { echo "report.sh: $out/$n.row: missing" >&2; exit 1; }
done
read -r R v t E m alpha smax dens <<EOF
$(sh "$here/params.sh" "$out" "$main")
EOF
row() { tail -n 1 "$out/$1.row"; }
# the runs of the tables: the sweep (both laws), the width and potential
# schemes
runs=
for l in linear hertz; do
	for a in $alphas; do
		[ -s "$out/$l-$a-area-$rho.row" ] && runs="$runs $l-$a-area-$rho"
	done
done
runs="$runs hertz-2.5-width-$rho hertz-2.5-potential-$rho"
instants=$(grep -c '^# t ' "$out/$main.samples")
win=$(grep '^# t ' "$out/$main.samples" | awk '{ print $3 }' | sort -g | head -n 1)

echo "# twod: the 2D plane-strain single shot of Ch. 7.4 (Figs. 7.9-7.11)"
echo
echo "Written by report.sh from the runs in $out/; measured $(date '+%F') on $(nproc) cores"
echo "(load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)), code of $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '(no git)')."
awk -v R="$R" -v v="$v" -v t="$t" -v E="$E" -v dens="$dens" -v smax="$smax" -v end="$(row "$main" | cut -f26)" \
	-v n="$instants" -v win="$win" 'BEGIN {
	mu = dens * 3.141592653589793 * R * R
	printf "Disk R = %g mm at %g m/s, %g kg/m^3: %.3f kg per m of slab (%.2f g per mm), momentum %.4f N s per mm; block E = %g GPa, largest flow stress of Table 7.1 %g MPa; slab %g mm thick, forces in N per mm.  ", R * 1e3, v, dens, mu, mu, mu * v * 1e-3, E / 1e9, smax / 1e6, t * 1e3
	printf "Each pass ends at %s us (the block has no damping and rings for ever); the residual sxx is the mean over %d instants, %s to %s us, of the centre line (the two elements at x = 0), sd its standard deviation over them (the ringing).\n", end, n, win, end }'
echo

echo "## The impact (Figs. 7.9(c,e), 7.10(a), 7.11(a))"
echo
echo "Peak: the largest |F| on the disk; duration: first to last step with a force;"
echo "e = J / (m v) - 1 from the impulse of the history; travel: the disk's deepest"
echo "point below where it first touched; oscillation: the force history's total"
echo "variation over twice its peak, less 1 (0 for one smooth hump); penalty alone:"
echo "the duration the law alone would give on a rigid block (duration.sh); cost: demshot's"
echo "cost line for the run to the end of the pass (the sampling runs are in the next table)."
echo
echo "| law | alpha (thesis) | alpha (ours) | scheme | peak F (N/mm) | at (us) | duration (us) | penalty alone (us) | e | travel (mm) | oscillation | steps | wall s | cpu s | contact s | ns per contact |"
echo "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in $runs; do
	row "$n"
done | awk -F'\t' -v R="$R" -v v="$v" -v E="$E" 'function gam(x) { return exp(lgam(x)) }
	# ln Gamma by Lanczos (g = 7): awk has no gamma function
	function lgam(x,   c, s, i, tt) {
		split("0.99999999999980993 676.5203681218851 -1259.1392167224028 771.32342877765313 -176.61502916214059 12.507343278686905 -0.13857109526572012 9.9843695780195716e-6 1.5056327351493116e-7", c, " ")
		x -= 1; s = c[1]; for (i = 1; i < 9; i++) s += c[i + 1] / (x + i)
		tt = x + 7.5; return 0.5 * log(2 * 3.141592653589793) + (x + 0.5) * log(tt) - tt + log(s) }
	{
		m = ($2 == "linear") ? 1 : 1.5
		mu = $6 * 3.141592653589793 * R * R; k = $4 * E * R^(1 - m)
		I = gam(1 / (m + 1)) * gam(0.5) / gam(1 / (m + 1) + 0.5) / (m + 1)
		pen = 2 * I * ((m + 1) * mu * v * v / (2 * k))^(1 / (m + 1)) / v
		printf "| %s | %s | %s | %s | %s | %s | %s | %.1f | %s | %s | %s | %s | %s | %s | %s | %.0f |\n",
			$2, $3, $4, $5, $7, $8, $11, pen * 1e6, $13, $14, $15, $29, $27, $28, $31, $32 }'
echo
bad=$(for n in $runs; do row "$n"; done | awk -F'\t' '{ s += $16 } END { print s + 0 }')
echo "Rows of the force histories with a negative or non-finite normal force: $bad."
echo

echo "## The residual sxx on the centre line (Figs. 7.9(d,f), 7.10(b), 7.11(b))"
echo
echo "MPa and mm; mean and sd over the instants; the surface is the top layer (0.25 mm deep);"
echo "zero: where the mean turns tensile below its peak; at the end: the single instant the pass"
echo "ends at (what one run to a fixed end time shows); sampling cpu s: the runs to the other instants."
echo
echo "| law | alpha (thesis) | scheme | surface | sd | peak | at depth | sd | zero | at the end: surface | peak | at depth | sampling cpu s |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in $runs; do
	row "$n"
done | awk -F'\t' '{ printf "| %s | %s | %s | %+.0f | %.0f | %.0f | %s | %.0f | %s | %+.0f | %.0f | %s | %s |\n",
	$2, $3, $5, $17, $18, $19, $20, $21, $22, $23, $24, $25, $30 }'
echo

echo "## The spread across alpha (Fig. 7.9)"
echo
echo "Over the alphas in 0.5 to 5, for each law: the range of the peak force and the"
echo "duration, the range of the residual peak, and the largest difference between any two"
echo "of the mean profiles at one depth (over the whole centre line), against the ringing's"
echo "largest sd at that depth; then alpha 10: its oscillation against the largest in 0.5-5"
echo "and how far its profile leaves their envelope."
echo
echo "| law | alphas | peak F (N/mm) | duration (us) | residual peak (MPa) | largest profile difference (MPa) | at depth (mm) | sd there | oscillation 0.5-5 | alpha 10: oscillation | outside the envelope (MPa) |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for l in linear hertz; do
	set --
	for a in $alphas; do
		in=$(awk -v a="$a" 'BEGIN { print (a >= 0.5 && a <= 5) }')
		[ "$in" = 1 ] && [ -s "$out/$l-$a-area-$rho.row" ] && set -- "$@" "$l-$a-area-$rho"
	done
	[ $# -ge 2 ] || continue
	ten=$l-10-area-$rho
	[ -s "$out/$ten.row" ] || ten=
	for n in "$@"; do
		echo "R $(row "$n")"
		awk -v n="$n" '!/^#/ { print "P", n, $1, $2, $3 }' "$out/$n.mean"
	done > "$out/spread-$l.tmp"
	if [ -n "$ten" ]; then
		echo "T $(row "$ten")" >> "$out/spread-$l.tmp"
		awk '!/^#/ { print "Q", $1, $2 }' "$out/$ten.mean" >> "$out/spread-$l.tmp"
	fi
	awk -v law="$l" '
		$1 == "R" { split($0, f, "\t"); sub(/^R /, "", f[1]); k++; if (k == 1 || f[7] < F0) F0 = f[7]; if (k == 1 || f[7] > F1) F1 = f[7]
			if (k == 1 || f[11] < D0) D0 = f[11]; if (k == 1 || f[11] > D1) D1 = f[11]
			if (k == 1 || f[19] < P0) P0 = f[19]; if (k == 1 || f[19] > P1) P1 = f[19]
			if (f[15] > O) O = f[15]; al = al (al == "" ? "" : ", ") f[3] }
		$1 == "P" { d = $3; if (!(d in lo) || $4 < lo[d]) lo[d] = $4; if (!(d in hi) || $4 > hi[d]) hi[d] = $4
			if ($5 > sd[d]) sd[d] = $5; dep[d] = d }
		$1 == "T" { split($0, f, "\t"); O10 = f[15]; ten = 1 }
		$1 == "Q" { q[$2] = $3 }
		END {
			for (d in dep) { x = hi[d] - lo[d]; if (x > W) { W = x; Wd = d } }
			if (ten) { for (d in q) if (d in lo) { x = lo[d] - q[d]; if (q[d] - hi[d] > x) x = q[d] - hi[d]; if (x > Out) Out = x }
				o10 = sprintf("%.3f", O10); out10 = sprintf("%.0f", Out) } else { o10 = "-"; out10 = "-" }
			printf "| %s | %s | %s to %s (%.1f %%) | %.1f to %.1f | %.0f to %.0f | %.0f | %.2f | %.0f | %.3f | %s | %s |\n",
				law, al, F0, F1, 100 * (F1 - F0) / F1, D0, D1, P1, P0, W, Wd, sd[Wd], O, o10, out10 }' "$out/spread-$l.tmp"
	rm -f "$out/spread-$l.tmp"
done
echo

# the largest difference between two mean profiles, its depth, and the peaks
pair() {  # pair NAME1 NAME2
	awk 'FNR == 1 { f++ } !/^#/ { if (f == 1) a[$1] = $2; else if ($1 in a) { x = $2 - a[$1]; if (x < 0) x = -x; if (x > W) { W = x; Wd = $1 } } }
		END { printf "%.0f MPa at %.2f mm", W, Wd }' "$out/$1.mean" "$out/$2.mean"
}
echo "## Linear against Hertz at alpha = 2.5 (Fig. 7.10)"
echo
l=$(row "linear-2.5-area-$rho") h=$(row "$main")
printf '%s\n%s\n' "$l" "$h" | awk -F'\t' 'NR == 1 { F = $7; D = $11; P = $19 } NR == 2 {
	printf "Peak force %s (linear) against %s N/mm (Hertz), %+.1f %%; duration %s against %s us; residual peak %.0f against %.0f MPa; ", F, $7, 100 * ($7 - F) / F, D, $11, P, $19 }'
echo "largest difference of the mean profiles $(pair "linear-2.5-area-$rho" "$main")."
echo
echo "### The FE shot (Figs. 7.9(a,b), 7.10)"
echo
if [ -s "$here/FE-SHOT.md" ]; then
	echo "From FE-SHOT.md (\`make fe-shot\`: fe-shot.sh, fe-shot-report.sh), where both the DE disk and"
	echo "the FE shot are read at the pass's end, not averaged over instants:"
	echo
	sed -n '/^| run /,/^$/p' "$here/FE-SHOT.md"
	grep '^Every FE shot\|^\*\*Not every FE shot' "$here/FE-SHOT.md" || true
else
	echo "Not run (\`make fe-shot\`): the disk as elastic finite elements, E_s = 100 E, with"
	echo "node-to-segment penalty contact, against the rigid DE disk."
fi
echo

echo "## The three partial contact schemes (Fig. 7.11)"
echo
# scheme: the second against area, the thesis's scheme of the sweep
scheme() {  # scheme NAME LABEL
	printf '%s\n%s\n' "$h" "$(row "$1")" | awk -F'\t' -v lab="$2" 'NR == 1 { F = $7; D = $11; P = $19; C = $31; N = $32 } NR == 2 {
	printf "Hertz, alpha 2.5: peak force %s (area, Eq. 3.10) against %s N/mm (%s), %+.2f %%; duration %s against %s us; residual peak %.0f against %.0f MPa; contact time %s against %s s (%.0f against %.0f ns per contact); ", F, $7, lab, 100 * ($7 - F) / F, D, $11, P, $19, C, $31, N, $32 }'
	echo "largest difference of the mean profiles $(pair "$main" "$1")."
}
scheme "hertz-2.5-width-$rho" "width, Eq. 3.11"
echo
scheme "hertz-2.5-potential-$rho" "potential, demshot's default"
echo

echo "## The ringing (ringing.png)"
echo
awk -v win="$win" '
	/^# t / { t = $3; next }
	!n[t]++ { s[t] = $2 / 1e6; T[++k] = t }
	END {
		for (i = 1; i <= k; i++) mu += s[T[i]] / k
		# sort the instants, count the crossings of the mean
		for (i = 1; i <= k; i++) for (j = i + 1; j <= k; j++) if (T[j] < T[i]) { x = T[i]; T[i] = T[j]; T[j] = x }
		for (i = 2; i <= k; i++) if ((s[T[i]] - mu) * (s[T[i - 1]] - mu) < 0) c++
		for (i = 1; i <= k; i++) { if (i == 1 || s[T[i]] < lo) lo = s[T[i]]; if (i == 1 || s[T[i]] > hi) hi = s[T[i]] }
		printf "Hertz, alpha 2.5: the surface sxx of the %d instants from %s to %s us runs from %+.0f to %+.0f MPa about its mean %+.0f; it crosses the mean %d times, a period of about %.0f us (%s us between instants: a coarse estimate).\n",
			k, T[1], T[k], lo, hi, mu, c, c ? 2 * (T[k] - T[1]) / c : 0, T[2] - T[1] }' "$out/$main.samples"
echo

echo "## The duration question"
echo
awk -F'\t' -v R="$R" -v v="$v" -v E="$E" -v smax="$smax" -v dens="$dens" '
	BEGIN { pi = 3.141592653589793 }
	{ F = $7 * 1e3; D = $11 }  # N/m
	END {
		mu = dens * pi * R * R; p = (2 + pi) / sqrt(3) * smax
		tb = (3 * mu * v / (4 * p * sqrt(2 * R * v)))^(2 / 3)
		T4 = 4e-6; mub = 4 / 3 * p * sqrt(2 * R * v) * T4^1.5 / v
		k = 2.5 * E; mul = k * (T4 / pi)^2
		printf "Measured, Hertz at alpha 2.5: the disk (%.2f kg/m) touches for %s us.  From first principles, for this mass:\n\n", mu, D
		printf "- momentum over the largest force: the impulse is at least m v = %.0f N s/m, the force at most its peak %.0f N/mm, so the contact lasts at least m v / F_peak = %.1f us (with e = %s, J / F_peak = %.1f us);\n", mu * v, F / 1e3, 1e6 * mu * v / F, $13, 1e6 * mu * v * (1 + $13) / F
		printf "- a bound that does not need the run: in a time T the disk moves at most v T, so the contact is at most 2 sqrt(2 R v T) wide (no pile-up) and carries at most p = (2 + pi)/sqrt(3) sigma_max = %.2f GPa (the plane-strain punch at the largest flow stress of Table 7.1); stopping the disk takes T >= (3 m v / (4 p sqrt(2 R v)))^(2/3) = %.1f us;\n", p / 1e9, tb * 1e6
		printf "- the linear penalty alone on a rigid block, alpha 2.5: pi sqrt(m / (alpha E)) = %.1f us (the table above gives it for every run).\n\n", 1e6 * pi * sqrt(mu / k)
		printf "For 4 us (the thesis: 1e-5 s is about 2.5 impact durations): the bound allows at most %.2f kg/m (a density of %.0f kg/m^3, %.1f times lighter than steel); the linear penalty alone at alpha 2.5 gives 4 us for %.2f kg/m (%.0f kg/m^3).\n", mub, mub / (pi * R * R), mu / mub, mul, mul / (pi * R * R) }' <<EOF
$h
EOF
echo
if [ -n "$mass_rhos" ]; then
	echo "The same run with lighter disks (Hertz, alpha 2.5; force histories only):"
	echo
	echo "| density (kg/m^3) | mass (kg/m) | peak F (N/mm) | duration (us) | e |"
	echo "|---:|---:|---:|---:|---:|"
	for r in $rho $mass_rhos; do
		[ -s "$out/hertz-2.5-area-$r.row" ] && row "hertz-2.5-area-$r"
	done | sort -t"$(printf '\t')" -k6,6g | tee "$out/mass.tmp" | awk -F'\t' -v R="$R" '{
		printf "| %s | %.4g | %s | %s | %s |\n", $6, $6 * 3.141592653589793 * R * R, $7, $11, $13 }'
	echo
	awk -F'\t' -v R="$R" '{ x[++n] = log($6); y[n] = log($11); r[n] = $6 }
		END {
			for (i = 1; i <= n; i++) { sx += x[i]; sy += y[i]; sxx += x[i] * x[i]; sxy += x[i] * y[i] }
			b = (n * sxy - sx * sy) / (n * sxx - sx * sx); a = (sy - b * sx) / n
			t4 = log(4)
			for (i = 1; i < n; i++) if ((y[i] - t4) * (y[i + 1] - t4) <= 0) { w = (t4 - y[i]) / (y[i + 1] - y[i]); r4 = exp(x[i] + w * (x[i + 1] - x[i])); how = "interpolated between the two runs around it" }
			if (!r4) { r4 = exp((t4 - a) / b); how = "extrapolated by the fit" }
			printf "Duration against mass: a power %.2f by least squares over the %d runs (1/2 for a linear spring, 2/5 for the Hertz penalty alone, 2/3 for the rigid-plastic bound).  4 us needs a density of %.0f kg/m^3 (%s), %.0f times lighter than %s kg/m^3.\n",
				b, n, r4, how, r[n] / r4, r[n] }' "$out/mass.tmp"
	rm -f "$out/mass.tmp"
fi
