#!/bin/sh
# run.sh OUT NAME - one run of the Ch. 7.4 plane-strain single shot,
# NAME = LAW-ALPHA-PARTIAL-RHO (e.g. hertz-2.5-area-7800):
#
#   LAW      linear (m = 1) or hertz (m = 3/2): the two laws of Eq. 3.45
#            that Ch. 7.4 compares (the thesis's "Hertz model" is the power
#            law with m = 3/2, not demshot's contact.law: hertz)
#   ALPHA    the thesis's non-dimensional alpha (k_n = alpha E, N and mm);
#            our alpha is alpha (R / 1 mm)^(2m - 2) (lib/contact/law.h,
#            dem_law_alpha_thesis2d): alpha itself for the linear law,
#            20 alpha for the Hertz law and the 20 mm disk
#   PARTIAL  area (Eq. 3.10), width (Eq. 3.11) or potential (beyond the
#            thesis, demshot's default; lib/contact/disk.h): the partial
#            contact scheme
#   RHO      the disk's density, kg/m^3 (7800: steel, demshot's default;
#            Ch. 7.4 gives none); other values only for the duration
#            question of README.md
#
# The model is scene.yaml with the shot of shot.txt; a run sets in it the
# law, alpha, the scheme and the density (../ch75/scene.sh).  The main run
# lasts END us (the pass ends there: the block has no damping and never
# comes to rest, README.md); its force history gives the impact, its cost
# the cost.  The block rings after the impact (a period of about 20 us),
# so the residual sxx of one instant swings by hundreds of MPa: with
# SAMPLE=1 (the default) the run is repeated to the instants WIN, WIN + DT,
# ..., END - DT (us) and the centre-line profiles of all these instants and
# END's are averaged: the mean is the residual profile, the standard
# deviation the ringing.  The centre line: the two elements whose common
# edge is on x = 0 (demprofile --area 2h:2h --margin 0, h the element).
#
# Environment: BIN (../../bin), END (200), WIN (100), DT (5), SAMPLE (1),
# THREADS (1).
# Writes OUT/NAME.{yaml,log,forces,state,prof} (the main run), OUT/NAME.fn
# (t in us, the force on the disk in N per mm of slab),
# OUT/NAME.samples (depth in m, sxx in Pa, one block per instant, its time
# in a "# t" line), OUT/NAME.mean (depth mm, mean, sd, min, max of sxx over
# the instants, sxx at END, MPa) and OUT/NAME.row (the row of the tables,
# fields named in its "#" line).
set -e
out=$1 name=$2
IFS=- read -r law alpha partial rho <<EOF
$name
EOF
[ -n "$rho" ] || { echo "run.sh: $name: expected LAW-ALPHA-PARTIAL-RHO" >&2; exit 2; }
case $law in
linear) m=1 ;;
hertz) m=1.5 ;;
*) echo "run.sh: unknown law '$law'" >&2; exit 2 ;;
esac
here=$(dirname "$0")
bin=${BIN:-$here/../../bin}
end=${END:-200} win=${WIN:-100} dt=${DT:-5} sample=${SAMPLE:-1} threads=${THREADS:-1}
mkdir -p "$out"
shots=$here/shot.txt

# the disk of the shot stream: radius (m) and speed (m/s)
read -r R v <<EOF
$(awk '!/^#/ { print $5, sqrt($6^2 + $8^2); exit }' "$shots")
EOF
ours=$(awk -v a="$alpha" -v m="$m" -v R="$R" 'BEGIN { printf "%.10g", a * (R / 1e-3)^(2 * m - 2) }')
sh "$here/../ch75/scene.sh" "$here/scene.yaml" "contact.m=$m" "contact.alpha=$ours" \
	"contact.partial=$partial" "shot.density=$rho kg/m^3" > "$out/$name.yaml"
# the resolved scene: the slab's thickness and the element size (m)
read -r t h <<EOF
$("$bin"/demshot -s "$out/$name.yaml" --dump-scene |
	awk '/^  thickness:/ { t = $2 } /^  element:/ { h = $2 } END { print t, h }')
EOF
area=$(awk -v h="$h" 'BEGIN { printf "%.10gmm", 2 * h * 1e3 }')

# one run to TIME us: the state stream and the centre-line profile
shoot() {  # shoot TIME STATE LOG [--forces FILE]
	_time=$1 _state=$2 _log=$3
	shift 3
	"$bin"/demshot -s "$out/$name.yaml" --threads "$threads" --pass-time "${_time}us" \
		--steady 1e-9 "$@" -o "$_state" "$shots" 2> "$_log"
}
profile() {  # profile STATE > PROFILE (its messages to the main log)
	"$bin"/demprofile -q --area "$area:$area" --margin 0 "$1" 2>> "$out/$name.log"
}

shoot "$end" "$out/$name.state" "$out/$name.log" --forces "$out/$name.forces"
# the force on the disk per mm of slab against time, for the figures:
# t (us), |F| (N/mm)
awk -v t="$t" '!/^#/ { printf "%.5f %.3f\n", $3 * 1e6, sqrt($6 * $6 + $8 * $8) / (t * 1e3) }' \
	"$out/$name.forces" > "$out/$name.fn"
profile "$out/$name.state" > "$out/$name.prof"
{
	echo "# t $end us"
	awk '!/^#/ { print $2, $3 }' "$out/$name.prof"
} > "$out/$name.samples"
scpu=0
if [ "$sample" = 1 ]; then
	tmp=$out/$name.sample
	for s in $(awk -v a="$win" -v b="$end" -v d="$dt" 'BEGIN { for (x = a; x < b - d / 2; x += d) print x }'); do
		shoot "$s" "$tmp.state" "$tmp.log"
		echo "# t $s us"
		profile "$tmp.state" | awk '!/^#/ { print $2, $3 }'
		c=$(grep '^demshot: cost:' "$tmp.log" | sed 's/.* cpu_s=\([0-9.]*\).*/\1/')
		scpu=$(awk -v a="$scpu" -v b="$c" 'BEGIN { print a + b }')
	done >> "$out/$name.samples"
	rm -f "$tmp.state" "$tmp.log"
fi

# the mean over the instants, depth by depth (the last block is END's)
awk -v end="$end" '
	/^# t / { now = $3; next }
	{ k = sprintf("%.9f", $1); if (!(k in n)) { d[++nd] = $1; key[nd] = k }
	  v = $2 / 1e6; n[k]++; s[k] += v; q[k] += v * v
	  if (n[k] == 1 || v < lo[k]) lo[k] = v; if (n[k] == 1 || v > hi[k]) hi[k] = v
	  if (now == end) e[k] = v }
	END {
		print "# depth_mm mean_MPa sd_MPa min_MPa max_MPa end_MPa (sxx on the centre line, " n[key[1]] " instants)"
		for (i = 1; i <= nd; i++) { k = key[i]; mu = s[k] / n[k]; var = q[k] / n[k] - mu * mu
			printf "%.4f %.2f %.2f %.2f %.2f %.2f\n", d[i] * 1e3, mu, sqrt(var > 0 ? var : 0), lo[k], hi[k], e[k] } }' \
	"$out/$name.samples" > "$out/$name.mean"

# the row.  Force per mm of slab (N/mm = the history's N over t in mm).
# Impulse J = int fz dt over the history's rows (one a step while the disk
# touches; a gap longer than a microsecond is out of contact), e = J / (m v)
# - 1 with m = rho pi R^2 t, the disk's travel from v(t) = v - J(t) / m.
# Oscillation: the total variation of |F| over twice its peak, less 1 (0
# for one smooth hump).  Residual sxx from NAME.mean: the surface (top
# layer), the most compressive point and its depth, the zero crossing
# below it, the standard deviation there (the ringing).
awk -v name="$name" -v law="$law" -v alpha="$alpha" -v ours="$ours" -v partial="$partial" \
	-v rho="$rho" -v R="$R" -v v="$v" -v t="$t" -v scpu="$scpu" -v end="$end" '
	FILENAME ~ /\.log$/ && /^demshot: cost: / {
		for (i = 3; i <= NF; i++) { split($i, kv, "="); c[kv[1]] = kv[2] } }
	FILENAME ~ /\.forces$/ && !/^#/ {
		F = sqrt($6 * $6 + $8 * $8) / (t * 1e3)
		if (nr && $3 - tp < 1e-6) {
			dJ = 0.5 * ($8 + fzp) * ($3 - tp); J += dJ
			vel = v - J / mass; s += 0.5 * (vel + velp) * ($3 - tp); velp = vel
			if (s > smax) smax = s
		} else if (!nr) { velp = v } else { s += velp * ($3 - tp) }
		tv += nr ? (F > Fp ? F - Fp : Fp - F) : F
		if (F > 0) { if (t0 == "") t0 = $3; t1 = $3 }
		if (F > pk) { pk = F; tpk = $3 }
		if ($8 !~ /^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$/ || $8 < 0) bad++
		tp = $3; fzp = $8; Fp = F; nr++ }
	FILENAME ~ /\.mean$/ && !/^#/ { nd++; D[nd] = $1; M[nd] = $2; S[nd] = $3; E[nd] = $6 }
	BEGIN { pi = 3.141592653589793; mass = rho * pi * R * R * t }
	END {
		tv += Fp
		e = J / (mass * v) - 1
		for (i = 1; i <= nd; i++) if (M[i] < M[ip] || !ip) ip = i
		for (i = 1; i <= nd; i++) if (E[i] < E[ie] || !ie) ie = i
		z = "-"
		for (i = ip; i < nd; i++) if (M[i + 1] >= 0) { z = sprintf("%.2f", D[i] + (D[i + 1] - D[i]) * (0 - M[i]) / (M[i + 1] - M[i])); break }
		print "# name law alpha_t alpha partial rho peak_N_mm t_peak_us t_on_us t_off_us duration_us impulse_Ns e travel_mm oscillation negative_rows surface_MPa surface_sd peak_MPa peak_depth_mm peak_sd zero_mm end_surface_MPa end_peak_MPa end_peak_depth_mm end_us wall_s cpu_s steps sample_cpu_s contact_s ns_per_contact"
		printf "%s\t%s\t%s\t%s\t%s\t%s\t%.0f\t%.2f\t%.2f\t%.2f\t%.2f\t%.5g\t%.3f\t%.4f\t%.3f\t%d\t%.1f\t%.1f\t%.1f\t%.2f\t%.1f\t%s\t%.1f\t%.1f\t%.2f\t%s\t%s\t%s\t%s\t%.1f\t%s\t%s\n",
			name, law, alpha, ours, partial, rho, pk, tpk * 1e6, t0 * 1e6, t1 * 1e6, (t1 - t0) * 1e6,
			J, e, smax * 1e3, tv / (2 * pk) - 1, bad, M[1], S[1], M[ip], D[ip], S[ip], z,
			E[1], E[ie], D[ie], end, c["wall_s"], c["cpu_s"], c["steps"], scpu, c["contact_s"], c["ns_per_contact"] }' \
	"$out/$name.log" "$out/$name.forces" "$out/$name.mean" > "$out/$name.row"
tail -n 1 "$out/$name.row"
