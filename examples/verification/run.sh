#!/bin/bash
# run.sh OUT NAME - one case of the verification runs of Han (2004), Ch. 7.6:
# NAME = ALLOY-D-ANGLE, e.g. Al5052-0.28-90:
#
#   ALLOY  Al5052, SS316 or Ti6Al4V (the material section: ALLOY.yaml here,
#          Table 7.2)
#   D      shot diameter, mm (0.28 or 0.84, Ch. 7.6)
#   ANGLE  impingement angle to the surface, degrees (90 or 60, Ch. 7.6)
#
# Everything else is Ch. 7.6's peening (50 m/s, 200 % coverage) on the FE/DE
# model of Ch. 7.5, scaled with the shot (lengths in multiples of D), so that
# the element count, the steps per impact and the run time do not depend on D:
#
#   elements   D/PER_D in the fine region (PER_D = 10: d/10, Ch. 7.5.4)
#   impact     a 2D x 2D square, random impacts (dempack --pattern random),
#              3 a pass at least D apart, until COVERAGE % (SAE J2277 with
#              the dimple radius measured below)
#   block      2.4D x 2.4D x 1.5D; fine region 2D x 2D, 0.6D deep, growth 1.3
#              outside; bottom fixed, sides fixed normally, top free (Ch. 7.5)
#   profile    the impact area less D/4 along each edge; dimpled: indented
#              more than D/200
#
# Two runs, through the pipeline dempack | demshot | demprofile:
#
#   1. one shot at the centre, on the same block: its dimple radius (the
#      equivalent radius sqrt(A/pi) of the surface indented more than D/200:
#      dimple.sh on the last frame, and demprofile --surface over the whole
#      fine region) and the residual profile along the centre line (the
#      2 x 2 elements at the impact point);
#   2. the random impacts up to COVERAGE % for that dimple radius (dempack
#      --coverage --dimple-radius): the residual profile of every pass,
#      averaged over the area, the last one reported.
#
# Environment: BIN (../../bin), THREADS (demshot --threads, 2), PER_D (10),
# COVERAGE (200), SEED (1), MATDIR (the folder of ALLOY.yaml: here).  Writes OUT/NAME/: scene.yaml; single.{log,vtu,
# surf,sat,prof} (the single shot); dempack.log, shots.txt, demshot.log,
# demprofile.log, profile.txt (every pass), sxx.txt (demprofile's saturation
# table of sxx), surface.txt, last.dat (the last pass, for the plots); and
# OUT/NAME.row, the row of the report (described before the awk below).
set -eo pipefail
out=$1 name=$2
IFS=- read -r alloy d angle rest <<< "$name"
if [ -z "$angle" ] || [ -n "$rest" ]; then
	echo "run.sh: $name: expected ALLOY-D-ANGLE (e.g. Al5052-0.28-90)" >&2
	exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
mat=$(cd "${MATDIR:-$here}" && pwd)/$alloy.yaml
[ -f "$mat" ] || { echo "run.sh: $name: no material file $mat" >&2; exit 2; }
bin=$(cd "${BIN:-$here/../../bin}" && pwd)
threads=${THREADS:-2}
per_d=${PER_D:-10}
coverage=${COVERAGE:-200}
seed=${SEED:-1}
dir=$out/$name
mkdir -p "$dir"
trap 'echo "run.sh: $name: failed, see the logs in $dir" >&2' ERR
# the programs run in the case's folder, on relative names, so that the
# provenance in the outputs' headers does not depend on OUT (make repro
# compares runs in two folders byte for byte)
cd "$dir"
t0=$(date +%s.%N)

# the lengths of the model in mm, from D
read -r r h area side thick fdepth margin thr centre ptime <<< "$(awk -v d="$d" -v n="$per_d" 'BEGIN {
	printf "%.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g\n",
		d / 2, d / n, 2 * d, 2.4 * d, 1.5 * d, 0.6 * d, d / 4, d / 200, 2 * d / n, 2 * d / 50 * 1e3 }')"

{
	echo "# scene of $name, written by run.sh (examples/verification): Han (2004),"
	echo "# Ch. 7.6, on the model of Ch. 7.5; lengths in multiples of D = $d mm."
	echo
	cat "$mat"
	cat <<EOF

# the impact area, 2D x 2D (our choice).  The single shot: dempack
# --pattern grid --grid 1; the peening: --pattern random --per-pass 3
# (separation 1: the shots of a pass at least D apart) up to --coverage
# $coverage with the measured --dimple-radius (the thesis gives no pattern)
pack:
  method: shots
  area: [$area mm, $area mm]

# Ch. 7.6: 50 m/s, diameter $d mm, $angle deg to the surface; steel shot,
# rigid, 7800 kg/m^3 (not in the thesis: handbook value)
shot:
  radius: $r mm
  speed: 50 m/s
  angle: $angle deg
  density: 7800 kg/m^3

# elements D/$per_d in the fine region (Ch. 7.5.4: no larger than d/10);
# block, fine region and growth our choice, scaled with D; boundary
# conditions of Ch. 7.5 (the defaults): bottom fixed, sides normal, top free
block:
  size: [$side mm, $side mm, $thick mm]
  element: $h mm
  fine: [$area mm, $area mm]
  fine_depth: $fdepth mm
  ratio: 1.3

# Hertz-form power law (Eq. 3.45, m 1.5), alpha 2 (1 to 5, Ch. 7.5.2); no
# friction (Ch. 7.6 gives none)
contact:
  m: 1.5
  alpha: 2

# global damping 0.05 of critical (Ch. 7.5); one-point elements with
# hourglass control, large strain (the defaults).  pass_time 2 D/v, our
# bound: a pass ends when the shots have left and the block is steady, after
# about D/(2v) here, but a shot knocked downwards by another one never
# "leaves" and held a pass open for the default 200 us (README.md, "Defects")
run:
  damping: 0.05
  pass_time: $ptime us

# the area less D/4 at each edge; dimpled where indented more than D/200
profile:
  margin: $margin mm
  threshold: $thr mm
EOF
} > "scene.yaml"

# 1. one shot at the centre: the dimple radius and the centre-line profile
"$bin"/dempack -s "scene.yaml" shots --pattern grid --grid 1 --passes 1 --seed "$seed" -q \
		2> "single.log" |
	"$bin"/demshot -s "scene.yaml" --threads "$threads" -q --vtu "single.vtu" \
		-o "single.state" 2>> "single.log"
"$bin"/demprofile -s "scene.yaml" -q --margin 0 --surface "single.surf" \
	-o /dev/null "single.state" 2>> "single.log"
"$bin"/demprofile -s "scene.yaml" -q --area "${centre}mm:${centre}mm" --margin 0 \
	--saturation "single.sat" -o "single.prof" "single.state" 2>> "single.log"
read -r a depth <<< "$("$here"/dimple.sh "single.vtu" "${thr}e-3")"
if ! awk -v a="$a" 'BEGIN { exit !(a > 0) }'; then
	echo "run.sh: $name: the single impact left no dimple deeper than $thr mm" >&2
	exit 3
fi

# 2. random impacts up to the coverage, the profile of every pass
"$bin"/dempack -s "scene.yaml" shots --pattern random --per-pass 3 --separation 1 \
		--coverage "$coverage" --dimple-radius "$a" --seed "$seed" \
		2> "dempack.log" |
	tee "shots.txt" |
	"$bin"/demshot -s "scene.yaml" --threads "$threads" 2> "demshot.log" |
	"$bin"/demprofile -s "scene.yaml" -q --saturation "sxx.txt" --surface "surface.txt" \
		-o "profile.txt" 2> "demprofile.log"
t2=$(date +%s.%N)
rm -f "single.state"

# the last pass for the plots: depth (mm), depth / D, sxx, syy, szz (MPa), ep
awk -v d="$d" '!/^#/ { if ($1 != p) { p = $1; n = 0 } n++
		r[n] = sprintf("%.6g %.6g %.6g %.6g %.6g %.6g", $2 * 1e3, $2 * 1e3 / d, $3 / 1e6, $4 / 1e6, $5 / 1e6, $15) }
	END { print "# pass " p ": depth:mm depth/D sxx:MPa syy:MPa szz:MPa ep:-"; for (i = 1; i <= n; i++) print r[i] }' \
	profile.txt > last.dat

# the row (tab-separated): name, alloy, D (mm), angle, element (mm),
# elements, shots, passes; the dimple of the single shot: radius (dimple.sh),
# demprofile's radius (whole nodes), the Hertz and the fully plastic
# estimates, depth (um); after the last pass: the indented share of the
# profile region; the area averages of the last pass: sxx at the top layer,
# peak sxx (MPa), its depth, the depth where sxx turns tensile (mm,
# interpolated between layers; 0: it does not, down to the bottom), syy at
# the top layer and its most compressive value (MPa), plastic strain at the
# top layer; single shot, centre line: sxx at the top layer, peak (MPa),
# zero depth (mm, as above); demshot's steps and energy balance error; wall
# seconds of demshot (random impacts) and of the whole case; the depths where
# sxx rises to 5 % of its peak (mm; after the last pass, single shot); the
# passes that demshot ended at run.pass_time ("not steady").
# a material section 'use: NAME' of the library: its file for E, nu and
# the yield stress (A of Johnson-Cook)
libmat=
use=$(sed -n 's/^ *use: *\([^ #]*\).*/\1/p' "scene.yaml" | head -n 1)
if [ -n "$use" ]; then
	libmat=$here/../../share/materials/$use.yaml
	[ -f "$libmat" ] || { echo "run.sh: $name: no library material $libmat" >&2; exit 2; }
fi
awk -v name="$name" -v alloy="$alloy" -v d="$d" -v angle="$angle" -v h="$h" -v a="$a" -v depth="$depth" \
	-v tcase="$(awk -v a="$t0" -v b="$t2" 'BEGIN { print b - a }')" '
	function si(v, u) { return u == "GPa" ? v * 1e9 : u == "MPa" ? v * 1e6 : v }
	# the depth where the profile P (n points from the top) first rises to
	# f times its most compressive value below that point, linear between
	# the points; 0: never (f = 0: where it turns tensile)
	function cross(P, D, n, f,    i, k, v) {
		k = 1
		for (i = 2; i <= n; i++) if (P[i] < P[k]) k = i
		v = f * P[k]
		for (i = k + 1; i <= n; i++)
			if (P[i] >= v) return D[i - 1] + (D[i] - D[i - 1]) * (v - P[i - 1]) / (P[i] - P[i - 1])
		return 0
	}
	FILENAME ~ /\.yaml$/ && $1 == "E:" { E = si($2, $3) }
	FILENAME ~ /\.yaml$/ && $1 == "nu:" { nu = $2 }
	FILENAME ~ /\.yaml$/ && $1 == "yield:" { Y = si($2, $3) }
	FILENAME ~ /\.yaml$/ && $1 == "A:" { Y = si($2, $3) }   # Johnson-Cook
	FILENAME ~ /demshot\.log$/ && /not steady after/ { late++ }
	FILENAME ~ /demshot\.log$/ && /^demshot: cost: / {
		for (i = 3; i <= NF; i++) { split($i, kv, "="); c[kv[1]] = kv[2] } }
	FILENAME ~ /sxx\.txt$/ && !/^#/ { s = $2; p = $3; pd = $4 }
	FILENAME ~ /surface\.txt$/ && !/^#/ { cov = $3 }
	FILENAME ~ /single\.surf$/ && !/^#/ { adp = $6 }
	FILENAME ~ /single\.prof$/ && !/^#/ { n1++; P1[n1] = $3; D1[n1] = $2; if ($3 < p1) p1 = $3 }
	FILENAME ~ /profile\.txt$/ && !/^#/ {
		if ($1 != last) { last = $1; n = 0; ymin = 0 }
		n++; P[n] = $3; D[n] = $2
		if (n == 1) { ys = $4; eps = $15 }
		if ($4 < ymin) ymin = $4 }
	FILENAME ~ /shots\.txt$/ && !/^#/ { ns++; np = $1 + 1 }
	END {
		pi = 3.14159265358979
		R = d / 2 * 1e-3; rho = 7800; vn = 50 * sin(angle * pi / 180)
		m = 4 / 3 * pi * R^3 * rho
		Es = E / (1 - nu * nu)
		dH = (15 * m * vn^2 / (16 * Es * sqrt(R)))^0.4     # Hertz: largest indentation
		aH = sqrt(R * dH)                                  # and contact radius
		aP = R * (8 * rho * vn^2 / (3 * 3 * Y))^0.25       # fully plastic, p_m = 3 Y
		printf "%s\t%s\t%s\t%s\t%s\t%d\t%d\t%d\t%.1f\t%.1f\t%.1f\t%.1f\t%.2f\t%.3f\t%.1f\t%.1f\t%.4f\t%.4f\t%.1f\t%.1f\t%.3f\t%.1f\t%.1f\t%.4f\t%d\t%.2g\t%.1f\t%.1f\t%.4f\t%.4f\t%d\n",
			name, alloy, d, angle, h, c["elements"], ns, np,
			a * 1e6, adp * 1e6, aH * 1e6, aP * 1e6, depth * 1e6, cov,
			s / 1e6, p / 1e6, pd * 1e3, cross(P, D, n, 0) * 1e3, ys / 1e6, ymin / 1e6, eps,
			P1[1] / 1e6, p1 / 1e6, cross(P1, D1, n1, 0) * 1e3,
			c["steps"], c["energy_error"], c["wall_s"], tcase,
			cross(P, D, n, 0.05) * 1e3, cross(P1, D1, n1, 0.05) * 1e3, late }' \
	"scene.yaml" ${libmat:+"$libmat"} "demshot.log" "sxx.txt" "surface.txt" "single.surf" \
	"single.prof" "profile.txt" "shots.txt" > ../"$name.row.tmp"
mv -f ../"$name.row.tmp" ../"$name.row"
cat ../"$name.row"
