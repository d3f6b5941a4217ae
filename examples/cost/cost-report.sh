#!/bin/sh
# cost-report.sh OUT FIG - REPORT.md (on stdout) and the PNGs in FIG from
# the runs in OUT (shot-run.sh, form-run.sh, pack-run.sh and
# examples/detect-bench's measure.sh).  The knob lists come from the
# environment, as the Makefile exports them.  Needs awk and gnuplot
# (pngcairo).
set -e
out=$1 fig=$2
here=$(dirname "$0")
. "$here/../lib.sh"
pl=$out/plot
rm -rf "$pl"
mkdir -p "$pl" "$fig"
sdir=$out/shot fdir=$out/form pdir=$out/pack ddir=$out/detect

# ---- helpers --------------------------------------------------------------

last() { for x; do :; done; echo "$x"; }
least() { printf '%s\n' "$@" | sort -g | head -n 1; }
most() { printf '%s\n' "$@" | sort -g | tail -n 1; }
# dn H: "d/N" for an element size of H mm against the 1 mm shot
dn() { awk -v h="$1" 'BEGIN { printf "d/%g", 1 / h }'; }
# yn X: "yes" if |X| <= 5 (per cent), "-" for "-"
yn() { awk -v x="$1" 'BEGIN { if (x == "-") print "-"; else { x = x < 0 ? -x : x; print (x <= 5) ? "yes" : "no" } }'; }
# the gnuplot commands that start a PNG of panels: W H FILE LAYOUT TITLE
plot_start() {
	echo "set terminal pngcairo size $1,$2 font ',10' noenhanced"
	echo "set output '$3'"
	echo "set datafile separator '\t'"
	echo "set grid; set key top right"
	echo "set multiplot layout $4 title \"$5\""
}
# panel TITLE XLABEL YLABEL LOGX STYLE FILE... - the gnuplot commands of one
# panel: each FILE (tab-separated: label, x, y) is a series, titled by its
# name after "--", its points labelled, and joined if STYLE is linespoints
# (points: for settings that have no order)
panel() {
	title=$1 xl=$2 yl=$3 logx=$4 style=$5
	shift 5
	echo "set title '$title'"
	echo "set xlabel '$xl'; set ylabel '$yl'"
	if [ "$logx" = log ]; then echo "set logscale x"; else echo "unset logscale x"; fi
	printf 'plot '
	sep= k=1
	for f; do
		t=${f##*--}
		t=${t%.dat}
		printf "%s'%s' using 2:3 with $style pt 7 ps 0.8 lc %d title '%s', '' using 2:3:1 with labels offset char 0.5,0.5 left font ',8' tc lt %d notitle" \
			"$sep" "$f" "$k" "$t" "$k"
		sep=', '
		k=$((k + 1))
	done
	echo
}
# the series files of a panel, in the order of the lists
series() { for s in $2; do [ -r "$pl/$1--$s.dat" ] && printf "%s " "$pl/$1--$s.dat"; done; :; }

# ---- demshot ------------------------------------------------------------

sbase=$LAMBDA0-$PARTIAL0-$STRAIN0-none
base=$H0-$RULE0-$sbase
hmin=$(least $HS)
rbest=$(last $RULES)
lmin=$(least $LAMBDAS)

# compare A REF - A's profile and time against REF's: peak change (%), RMS
# (% of REF's peak), RMS (MPa), compressive depth of A and of REF (mm), wall
# time ratio A / REF, surface change (MPa), compressive depth change (%)
compare() {
	printf '%s\t%s\t%s\t%s\n' "$(awk -f "$here/profile.awk" "$sdir/$1.prof" "$sdir/$1.prof")" \
		"$(awk -f "$here/profile.awk" "$sdir/$2.prof" "$sdir/$2.prof")" \
		"$(awk -f "$here/profile.awk" "$sdir/$2.prof" "$sdir/$1.prof")" "$(cut -f11 "$sdir/$1.row") $(cut -f11 "$sdir/$2.row")" |
		awk -F'\t' '{ rp = $9 < 0 ? -$9 : $9; split($22, t, " ")
			dz = ($4 != "-" && $11 != "-" && $11 > 0) ? sprintf("%.1f", 100 * ($4 - $11) / $11) : "-"
			printf "%.1f %.1f %.1f %s %s %.2f %.1f %s\n", 100 * ($2 - $9) / rp, 100 * $19 / rp, $19, $4, $11, t[1] / t[2], $1 - $8, dz }'
}

# group_head TITLE REF - a knob's heading and its reference run
group_head() {
	printf '\n### %s\n\nAgainst `%s`.\n\n' "$1" "$2"
}

# shot_group KEY TITLE REF NAME LABEL SERIES [NAME LABEL SERIES]... - the
# table of a knob against the run REF, and its points in pl/shot-KEY--SERIES.dat
shot_group() {
	key=$1 title=$2 ref=$3
	shift 3
	group_head "$title" "$ref"
	echo "| setting | elements | steps | runs | wall s | cpu s | surface sxx | peak sxx | at | compressive depth | RMS diff | of ref. peak | max diff | energy error |"
	echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
	while [ $# -ge 3 ]; do
		name=$1 label=$2 ser=$3
		shift 3
		m=$(awk -f "$here/profile.awk" "$sdir/$ref.prof" "$sdir/$name.prof")
		printf '%s\t%s\n' "$(cat "$sdir/$name.row")" "$m" | awk -F'\t' -v label="$label" -v dat="$pl/shot-$key--$ser.dat" '{
			rp = $24 < 0 ? -$24 : $24
			printf "| %s | %d | %d | %d | %.2f [%.2f-%.2f] | %.2f | %.1f | %.1f | %.3f | %s | %.2f | %.1f %% | %.1f | %.1e |\n",
				label, $8, $9, $10, $11, $13, $14, $12, $18, $19, $20, $21, $22, 100 * $22 / rp, $23, $16
			printf "%s\t%s\t%s\n", label, $11, $22 >> dat }'
	done
}

shot_section() {
	cat <<EOF

## demshot: the single shot of Ch. 7.5

Steel shot of radius 0.5 mm (d = 1 mm) at 19 m/s on the 8 x 8 x 0.9 mm aluminium block
of Ch. 7.5 (thesis-data.yaml, \`shot_peening_3d\`; the model of examples/ch75, run.sh),
alpha 2, global damping 0.05, one thread. Base case \`$base\` (the run names are
H-RULE-LAMBDA-PARTIAL-STRAIN-EFFECT, see shot-run.sh); each table varies one knob.
The result is the residual sxx profile (demprofile) averaged over the central
0.4 x 0.4 mm, the same area for every element size: surface (the top layer's centroid,
h/2 deep), most compressive value and its depth, the depth where sxx returns to 0
(compressive depth), and the RMS and largest difference from the reference profile
over the depths both cover, to 0.6 mm. Stresses in MPa, depths in mm; wall and cpu in
seconds (median of the runs; a run under $SHORT s is repeated to $REPS runs; min-max of the wall
times in brackets); energy error: the relative energy balance error of the run.
EOF
	set --
	for h in $HS; do for r in $RULES; do set -- "$@" "$h-$r-$sbase" "$(dn "$h") $r" "$r"; done; done
	shot_group size "Element size and integration rule (Ch. 7.5.4)" "$hmin-$rbest-$sbase" "$@"
	set --
	for l in $LAMBDAS; do set -- "$@" "$H0-$RULE0-$l-$PARTIAL0-$STRAIN0-none" "lambda $l" "lambda"; done
	shot_group lambda "Contact time step factor lambda (Box 3.1; above 0.3 a warning, above 0.5 --force)" \
		"$H0-$RULE0-$lmin-$PARTIAL0-$STRAIN0-none" "$@"
	set --
	for p in $PARTIALS; do set -- "$@" "$H0-$RULE0-$LAMBDA0-$p-$STRAIN0-none" "$p" "partial"; done
	shot_group partial "Partial contact factor (contact.partial, Eqs. 3.15-3.16)" \
		"$H0-$RULE0-$LAMBDA0-$PARTIAL0-$STRAIN0-none" "$@"
	set --
	for s in $STRAINS; do set -- "$@" "$H0-$RULE0-$LAMBDA0-$PARTIAL0-$s-none" "$s strain" "strain"; done
	shot_group strain "Small or large strain (--strain)" "$H0-$RULE0-$LAMBDA0-$PARTIAL0-large-none" "$@"
	set --
	for e in $EFFECTS; do
		case $e in
		none) d="none (the base)" ;;
		friction) d="friction mu 0.2" ;;
		friction0) d="friction mu 0" ;;
		cdamping) d="contact damping 0.1" ;;
		unload) d="hysteresis, unload 2" ;;
		rate) d="rate dependence m 0.0455" ;;
		undamped) d="no global damping" ;;
		*) d=$e ;;
		esac
		set -- "$@" "$H0-$RULE0-$LAMBDA0-$PARTIAL0-$STRAIN0-$e" "$d" "effects"
	done
	shot_group effects "Effects (DESIGN.md, \"Effects\"; dem-scene(5): contact and material sections)" \
		"$H0-$RULE0-$LAMBDA0-$PARTIAL0-$STRAIN0-none" "$@"
	if [ -r "$sdir/$H0-$RULE0-$LAMBDA0-$PARTIAL0-$STRAIN0-friction0.state" ] && [ -r "$sdir/$base.state" ]; then
		a=$(state_rows "$sdir/$base.state") b=$(state_rows "$sdir/$H0-$RULE0-$LAMBDA0-$PARTIAL0-$STRAIN0-friction0.state")
		echo
		printf 'Friction written as mu = 0 and no friction give the same state rows bit for bit: %s.\n' \
			"$([ "$a" = "$b" ] && echo yes || echo NO)"
	fi
	nd=$(cat "$sdir"/*.row | awk -F'\t' '$17 != "yes"' | wc -l)
	echo "Repeats of a run that gave other state rows than its first: $nd."
	ns=$(grep -l 'not steady after' "$sdir"/*.log 2> /dev/null | sed 's|.*/||; s|\.log$||' | tr '\n' ' ')
	[ -z "$ns" ] || echo "Passes ended by run.pass_time (200 us), not by the kinetic energy test: ${ns% }."
	{
		plot_start 1500 900 "$fig/shot.png" "2,3" "demshot, single shot of Ch. 7.5: RMS difference of the sxx profile against wall time (one thread)"
		panel "element size and rule (against $(dn "$hmin") $rbest)" "wall s" "RMS diff (MPa)" log linespoints $(series shot-size "$RULES")
		panel "lambda (against $lmin)" "wall s" "RMS diff (MPa)" lin linespoints $(series shot-lambda lambda)
		panel "partial contact (against $PARTIAL0)" "wall s" "RMS diff (MPa)" lin points $(series shot-partial partial)
		panel "strain (against large)" "wall s" "RMS diff (MPa)" lin points $(series shot-strain strain)
		panel "effects (against none)" "wall s" "RMS diff (MPa)" log points $(series shot-effects effects)
		echo "unset multiplot"
	} | gnuplot
	set --
	for h in $HS; do for r in $RULES; do set -- "$@" "$sdir/$h-$r-$sbase.prof" "$(dn "$h") $r"; done; done
	sh "$here/../ch75/plot.sh" "$fig/shot-profiles.png" \
		"Single shot of Ch. 7.5: sxx over the central 0.4 x 0.4 mm, element size and rule" sxx "$@"
	echo
	echo "![result change against time](shot.png)"
	echo
	echo "![profiles by element size and rule](shot-profiles.png)"
}

# ---- demform ---------------------------------------------------------------

# form_group KEY TITLE REF NAME LABEL [NAME LABEL]...
form_group() {
	key=$1 title=$2 ref=$3
	shift 3
	group_head "$title" "$ref"
	echo "| setting | elements | equations | Newton iterations | runs | wall s | cpu s | arc height mm | change um | change | max deflection mm | curvature x 1/m |"
	echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
	while [ $# -ge 2 ]; do
		name=$1 label=$2
		shift 2
		printf '%s\t%s\n' "$(cat "$fdir/$name.row")" "$(cut -f15 "$fdir/$ref.row")" |
			awk -F'\t' -v label="$label" -v dat="$pl/form-$key--$key.dat" '{
			c = $15 - $18
			printf "| %s | %d | %d | %d | %d | %.2f [%.2f-%.2f] | %.2f | %.4f | %.2f | %.3f %% | %.4f | %.5f |\n",
				label, $6, $7, $8, $9, $10, $12, $13, $11, $15 * 1e3, c * 1e6, 100 * c / $18, $16 * 1e3, $17
			printf "%s\t%s\t%s\n", label, $10, 100 * c / $18 >> dat }'
	done
}

# closed - the closed-form curvature of the free strip (E 72 GPa, nu 0.33,
# h 4 mm: form-run.sh's scene) under the profile of form-bench/profile.sh
# (the sxx of its one pass, linear between its points), integrated
# numerically
closed() {
	awk '!/^#/ { n++; d[n] = $2; s[n] = $3 }
		END { h = 0.004; E = 72e9; nu = 0.33; m = 100000; I = 0
			for (k = 0; k < m; k++) {
				z = d[1] + (d[n] - d[1]) * (k + 0.5) / m
				for (i = 1; i < n - 1 && d[i + 1] < z; i++) ;
				v = s[i] + (s[i + 1] - s[i]) * (z - d[i]) / (d[i + 1] - d[i])
				I += v * (h / 2 - z) * (d[n] - d[1]) / m
			}
			printf "%.5f", -12 * (1 - nu) * I / (E * h * h * h) }' "$fdir/strip.prof"
}

form_section() {
	cat <<EOF

## demform: the strip of Ch. 8.6

The strip of examples/form-bench: Al 7050-T7651, 150 x 50 x 4 mm, layers graded by 1.2
toward the peened face, the made-up equi-biaxial profile of form-bench/profile.sh
(elastic response), one thread (OpenMP and OpenBLAS). Base: $E0 mm in plane, $L0 layers,
$I0 increment, $FS0 strain (run names ELEMENT-LAYERS-INCREMENTS-STRAIN). The result is
the arc height over the 150 mm chord; change against the reference run of each knob.
An independent check (DESIGN.md, "Verification references"): the closed form of a free
plate under this equi-biaxial initial stress, kappa = -12 (1 - nu) int s z dz / (E h^3),
gives a curvature of $(closed) 1/m, to compare with the fitted curvature_x.
EOF
	set --
	for e in $ELEMS; do set -- "$@" "$e-$L0-$I0-$FS0" "$e mm"; done
	form_group element "In-plane element size (plate.element)" "$(least $ELEMS)-$L0-$I0-$FS0" "$@"
	set --
	for l in $LAYERS; do set -- "$@" "$E0-$l-$I0-$FS0" "$l layers"; done
	form_group layers "Layers through the thickness (plate.layers)" "$E0-$(most $LAYERS)-$I0-$FS0" "$@"
	set --
	for i in $INCRS; do set -- "$@" "$E0-$L0-$i-$INCSTRAIN" "$i"; done
	form_group increments "Load increments (--increments; $INCSTRAIN strain)" "$E0-$L0-$(most $INCRS)-$INCSTRAIN" "$@"
	set --
	for s in $FSTRAINS; do set -- "$@" "$E0-$L0-$I0-$s" "$s"; done
	form_group strain "Small or large strain (--large)" "$E0-$L0-$I0-large" "$@"
	{
		plot_start 1200 900 "$fig/form.png" "2,2" "demform, strip of Ch. 8.6: change of the arc height against wall time (one thread)"
		for k in element layers increments strain; do
			[ -r "$pl/form-$k--$k.dat" ] && st=linespoints; [ $k = strain ] && st=points
			panel "$k" "wall s" "arc height change (%)" log $st "$pl/form-$k--$k.dat"
		done
		echo "unset multiplot"
	} | gnuplot
	echo
	echo "![result change against time](form.png)"
}

# ---- dempack ---------------------------------------------------------------

pack_section() {
	cat <<EOF

## dempack compress: density against time

Mono-size spheres of 0.02 mm in a box ($BOX; the cube of examples/packing, smaller),
compressed (Ch. 6) at each setting with the seeds $SEEDS: the density is the mean over
the seeds, +- half its range; core: the density at least one diameter from every wall;
wall and cpu: the median over the seeds. Modes: relax, the default stages with the
relaxation under gravity; thesis, the stages of Boxes 6.1-6.4 only (--no-relax). Base:
tolerance $TOL0, $SHAKE0 shakes.
EOF
	for k in tolerance shakes; do
		echo
		if [ $k = tolerance ]; then echo "### Compression tolerance tau (Eq. 6.8; --tolerance)"; else echo "### Shakes per round (Box 6.2; --shakes)"; fi
		echo
		echo "| mode | tolerance | shakes | spheres | wall s | cpu s | density | core density | iterations |"
		echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
		for m in $MODES; do
			if [ $k = tolerance ]; then list=$TOLS; else list=$SHAKES; fi
			for v in $list; do
				if [ $k = tolerance ]; then n=$m-$v-$SHAKE0; else n=$m-$TOL0-$v; fi
				awk -F'\t' -v k="$k" -v dat="$pl/pack-$k--$m.dat" '{
					printf "| %s | %s | %s | %d | %.2f [%.2f-%.2f] | %.2f | %.4f +- %.4f | %.4f +- %.4f | %d |\n",
						$2, $3, $4, $6, $7, $9, $10, $8, $12, $13, $14, $15, $16
					printf "%s\t%s\t%s\n", (k == "tolerance" ? $3 : $4), $7, $12 >> dat }' "$pdir/$n.row"
			done
		done
	done
	{
		plot_start 1200 500 "$fig/pack.png" "1,2" "dempack compress, $BOX: density (mean over the seeds) against wall time"
		echo "set key bottom right"
		panel "tolerance" "wall s (median)" "density" log linespoints $(series pack-tolerance "$MODES")
		panel "shakes" "wall s (median)" "density" log linespoints $(series pack-shakes "$MODES")
		echo "unset multiplot"
	} | gnuplot
	echo
	echo "![density against time](pack.png)"
}

# ---- demdetect --------------------------------------------------------------

# detect_row RUN SET - run, median warm and cold ns/object, pairs (or
# "differ" when the runs disagree), runs
detect_row() {
	awk -v run="$1" '/: cost: / { for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
			n++; w[n] = v["detect_warm_s"]; c[n] = v["detect_s"]; o = v["objects"]
			if (n == 1) p = v["pairs"]; else if (p != v["pairs"]) p = "differ" }
		function med(a, n,    i, j, t) { for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
			return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
		END { if (n) printf "%s\t%.1f\t%.1f\t%s\t%d\n", run, med(w, n) / o * 1e9, med(c, n) / o * 1e9, p, n }' "$ddir/$1/$2.cost"
}

detect_section() {
	cat <<EOF

## demdetect: cell size and algorithm

Data sets of examples/detect-bench (\`dempack random --seed 1 -b\`, names
d<dim>-n<N>-<law>-rho<density>-lam<size ratio>), timed by its measure.sh: one thread,
$DREPS processes of \`demdetect --repeat $DREPEAT -c\`; warm: the median time of a detection
on warm buffers (the per-step cost in a time loop), cold: the first detection of a
process; in ns per object, the median over the processes. The result of a detection
is its pair set, which every setting must find whole: the pair counts are listed, and
"differ" would mark processes of one setting that disagree.
EOF
	echo
	echo "### D-cell cell size (--cell, a multiple of the mean object size)"
	echo
	printf '| cell factor |'
	for d in $DSETS; do printf ' %s warm | cold | pairs |' "$d"; done
	echo
	printf '|---:|'
	for d in $DSETS; do printf -- '---:|---:|---:|'; done
	echo
	for f in $FACTORS; do
		printf '| %s |' "$f"
		for d in $DSETS; do
			detect_row "dcell-c$f" "$d" | awk -F'\t' -v f="$f" -v dat="$pl/detect-cell--$d.dat" '{
				printf " %s | %s | %s |", $2, $3, $4; printf "%s\t%s\t%s\n", f, f, $2 >> dat }'
		done
		echo
	done
	echo
	echo "### Algorithm (default cell size)"
	echo
	printf '| algorithm |'
	for d in $DSETS; do printf ' %s warm | cold | pairs |' "$d"; done
	echo
	printf '|---|'
	for d in $DSETS; do printf -- '---:|---:|---:|'; done
	echo
	ai=0
	for a in $ALGOS; do
		ai=$((ai + 1))
		printf '| %s |' "$a"
		for d in $DSETS; do
			if [ -r "$ddir/$a/$d.cost" ]; then
				detect_row "$a" "$d" | awk -F'\t' -v a="$a" -v i="$ai" -v dat="$pl/detect-algo--$d.dat" '{
					printf " %s | %s | %s |", $2, $3, $4; printf "%s\t%s\t%s\n", a, i, $2 >> dat }'
			else
				printf ' - | - | - |'
			fi
		done
		echo
	done
	echo
	for d in $DSETS; do
		cat "$ddir"/*/"$d.cost" | awk -v d="$d" '/: cost: / { for (i = 3; i <= NF; i++) if ($i ~ /^pairs=/) p[substr($i, 7)]++; n++ }
			END { k = 0; for (x in p) { k++; s = x }
			      if (k == 1) printf "- %s: all %d processes (every cell size and algorithm) found %s pairs.\n", d, n, s
			      else { printf "- %s: the processes DISAGREE on the pair count:", d; for (x in p) printf " %s (%d)", x, p[x]; print "" } }'
	done
	{
		plot_start 1300 520 "$fig/detect.png" "1,2" "demdetect: warm ns per object (one thread)"
		echo "set logscale y"
		files=
		for d in $DSETS; do [ -r "$pl/detect-cell--$d.dat" ] && files="$files $pl/detect-cell--$d.dat"; done
		panel "D-cell: cell size" "cell factor (x mean object size)" "ns per object" log linespoints $files
		echo "set title 'algorithm (default cell size)'; set xlabel ''; unset logscale x"
		printf 'set xtics ('
		ai=0 sep=
		for a in $ALGOS; do ai=$((ai + 1)); printf "%s'%s' %d" "$sep" "$a" "$ai"; sep=', '; done
		echo "); set xrange [0.5:$ai.5]"
		printf 'plot '
		sep= k=1
		for d in $DSETS; do
			[ -r "$pl/detect-algo--$d.dat" ] || continue
			printf "%s'%s' using 2:3 with points pt 7 ps 1.2 lc %d title '%s'" "$sep" "$pl/detect-algo--$d.dat" "$k" "$d"
			sep=', ' k=$((k + 1))
		done
		echo
		echo "unset multiplot"
	} | gnuplot
	echo
	echo "![ns per object](detect.png)"
}

# ---- the report --------------------------------------------------------------

start=$(cat "$out/start" 2> /dev/null || echo "start ? ? 0 load ? ? ?")
t0=$(echo "$start" | awk '{ print $4 }')
loads=$( { cut -f15 "$sdir"/*.row; cut -f14 "$fdir"/*.row; cut -f11 "$pdir"/*.row; } 2> /dev/null |
	awk '/^[0-9.]+$/ { if (n++ == 0 || $1 < lo) lo = $1; if ($1 > hi) hi = $1 } END { if (n) printf "%.2f to %.2f", lo, hi }')
total=$( { cat "$sdir"/*.times "$fdir"/*.times 2> /dev/null | cut -f1; cut -f1 "$pdir"/*.seeds 2> /dev/null
	cat "$ddir"/*/*.cost 2> /dev/null | grep ': cost: ' | sed 's/.*wall_s=\([0-9.]*\).*/\1/'; } |
	awk '{ s += $1 } END { printf "%.0f", s }')
span=$(awk -v a="$t0" -v b="$(date +%s)" 'BEGIN { if (a > 0) printf "%.1f", (b - a) / 60; else printf "?" }')

body=$out/report.body
{
	shot_section
	form_section
	pack_section
	detect_section
} > "$body"

cat <<EOF
# What accuracy costs in time

Generated by \`make\` in examples/cost (shot-run.sh, form-run.sh, pack-run.sh,
examples/detect-bench's data.sh and measure.sh, cost-report.sh); issue 7. For each
accuracy knob of demshot, demform, dempack and demdetect, one small case is run at each
setting of the knob, the other knobs at their base values: the change in the result
against wall time. Elsewhere: the explicit element loop alone,
[REPORT-fe.md](REPORT-fe.md) (\`make fe\`); one peening pass of the Ch. 8.6 sample model,
[REPORT-pass.md](REPORT-pass.md) (\`make pass\`).

Machine: $(nproc) cores, the runs one at a time, one thread each. The first run started
$(echo "$start" | awk '{ print $2, $3 }') (load averages $(echo "$start" | cut -d' ' -f6-)); this report was written
$(date '+%F %T') (load averages $(cut -d' ' -f1-3 /proc/loadavg)), $span min later. The 1-minute
load when each run started: ${loads:-?}. A load above 1 means other jobs shared the
cores and stretched the wall times (compare the cpu column). The runs took $total s of
wall time in all ($(awk -v s="$total" 'BEGIN { printf "%.1f", s / 60 }') min).
EOF

# ---- findings: the key figures, from the tables' runs ----
echo
echo "## Key figures"
echo
d10=
for h in $HS; do [ "$(dn "$h")" = d/10 ] && d10=$h; done
if [ -n "$d10" ] && [ "$d10" != "$hmin" ]; then
	for r in $RULES; do
		set -- $(compare "$d10-$r-$sbase" "$hmin-$r-$sbase")
		echo "- **The d/10 rule ($r)**: d/10 against $(dn "$hmin"): peak sxx $1 % (within 5 %: **$(yn "$1")**),"
		echo "  compressive depth $4 against $5 mm, $8 % (**$(yn "$8")**), RMS difference of the profiles $3 MPa,"
		echo "  $2 % of the $(dn "$hmin") peak (**$(yn "$2")**); wall time $6 of $(dn "$hmin")'s."
	done
fi
for h in $HS; do
	[ "$RULES" != "${RULES#*one_point}" ] && [ "$RULES" != "${RULES#*full}" ] || break
	set -- $(compare "$h-one_point-$sbase" "$h-full-$sbase")
	echo "- One-point against full integration at $(dn "$h"): peak $1 %, RMS $3 MPa ($2 %), wall time $6 of full's."
done
lmax=$(most $LAMBDAS)
for l in $LAMBDAS; do
	[ "$l" = "$lmin" ] && continue
	set -- $(compare "$H0-$RULE0-$l-$PARTIAL0-$STRAIN0-none" "$H0-$RULE0-$lmin-$PARTIAL0-$STRAIN0-none")
	echo "- lambda $l against $lmin: peak $1 %, RMS $3 MPa ($2 %), wall time $6 of lambda $lmin's."
done
for p in $PARTIALS; do
	[ "$p" = "$PARTIAL0" ] && continue
	set -- $(compare "$H0-$RULE0-$LAMBDA0-$p-$STRAIN0-none" "$base")
	echo "- Partial contact by $p against $PARTIAL0: peak $1 %, RMS $3 MPa ($2 %), wall time $6."
done
for s in $STRAINS; do
	[ "$s" = large ] && continue
	set -- $(compare "$H0-$RULE0-$LAMBDA0-$PARTIAL0-$s-none" "$H0-$RULE0-$LAMBDA0-$PARTIAL0-large-none")
	echo "- $s strain against large: peak $1 %, RMS $3 MPa ($2 %), wall time $6."
done
for e in $EFFECTS; do
	[ "$e" = none ] && continue
	set -- $(compare "$H0-$RULE0-$LAMBDA0-$PARTIAL0-$STRAIN0-$e" "$base")
	echo "- Effect $e against none: peak $1 %, RMS $3 MPa ($2 %), wall time $6."
done
cat "$body"
