#!/bin/sh
# impact.sh BIN DIR - one shot of Ch. 7.5 (radius 0.5 mm, 19 m/s, normal)
# on the 8 x 8 x 0.9 mm block of examples/ch75 with elements of ELEMENT in
# its fine region (default 0.1 mm: d/10, the rule of Ch. 7.5.4) under each
# law of LAWS (default all four below), with one-point and with full
# integration: the residual sxx over the 0.2 x 0.2 mm square centred on the
# impact point (the 2 x 2 elements meeting there at 0.1 mm, 4 x 4 at 0.05
# mm).  Writes one TSV row per law and rule on stdout: law, rule, surface
# sxx, peak sxx (MPa), its depth (mm), the zero crossing (mm), steps, wall
# seconds.  The fine region is 1 x 1 x 0.6 mm: ELEMENT must divide it (0.2,
# 0.1, 0.05, 0.025 mm ...).  The laws:
#   linear    the aluminium of Ch. 7.5 (thesis-data.yaml shot_peening_3d):
#             E 68 GPa, yield 157 MPa, hardening 120 MPa
#   voce      the same yield with Q 100 MPa, b 20 (a shape, not data)
#   kinematic the linear law with one back-stress C 20 GPa, gamma 200 (a
#             shape, not data)
#   jc        Al 2024-T351 of the library (Johnson-Cook with its rate law)
# The shapes test the numerics (one-point against full integration), not
# a material.
set -eu
bin=$1 dir=$2
laws=${LAWS:-linear voce kinematic jc}
element=${ELEMENT:-0.1 mm}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$dir"
printf 'law\trule\tsurface_sxx\tpeak_sxx\tpeak_depth_mm\tzero_mm\tsteps\twall_s\n'
for law in $laws; do
	case $law in
	linear) mat='  E: 68 GPa
  nu: 0.33
  rho: 2700 kg/m^3
  yield: 157 MPa
  hardening: 120 MPa' ;;
	voce) mat='  E: 68 GPa
  nu: 0.33
  rho: 2700 kg/m^3
  law: voce
  yield: 157 MPa
  hardening: 120 MPa
  voce: {Q: 100 MPa, b: 20}' ;;
	kinematic) mat='  E: 68 GPa
  nu: 0.33
  rho: 2700 kg/m^3
  yield: 157 MPa
  hardening: 120 MPa
  kinematic: {C: [20 GPa], gamma: [200]}' ;;
	jc) mat='  use: Al2024-T351' ;;
	*) echo "impact.sh: $law: unknown law (linear, voce, kinematic, jc)" >&2; exit 2 ;;
	esac
	{
		echo "material:"
		echo "$mat"
		sh "$here/../ch75/scene.sh" "$here/../ch75/scene.yaml" "block.element=$element" |
			sed -n '/^block:/,$p'
	} > "$dir/$law.yaml"
	"$bin"/dempack -s "$dir/$law.yaml" shots --grid 1 --passes 1 --area 0.2mm:0.2mm \
		--seed 1 > "$dir/$law.shots" 2> /dev/null
	for rule in one_point full; do
		n=$dir/$law-$rule
		"$bin"/demshot -s "$dir/$law.yaml" --rule "$rule" --threads 1 \
			-o "$n.state" "$dir/$law.shots" 2> "$n.log" ||
			{ cat "$n.log" >&2; exit 1; }
		"$bin"/demprofile -q --area 0.2mm:0.2mm --margin 0 --field sxx \
			--saturation "$n.sxx" -o /dev/null "$n.state" 2>> "$n.log"
		awk -v law="$law" -v rule="$rule" '
			FILENAME ~ /\.log$/ && /^demshot: cost: / {
				for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
			FILENAME ~ /\.sxx$/ && !/^#/ { s = $2; p = $3; pd = $4; z = $5 }
			END { printf "%s\t%s\t%.1f\t%.1f\t%.3f\t%.3f\t%s\t%s\n", law, rule,
				s / 1e6, p / 1e6, pd * 1e3, z * 1e3, v["steps"], v["wall_s"] }' \
			"$n.log" "$n.sxx"
	done
done
