#!/bin/sh
# run.sh OUT NAME - one run of the Ch. 7.5 model, NAME =
# MODEL-H-ALPHA-MU-ANGLE-RULE (e.g. single-0.05-2-none-90-full):
#
#   MODEL  single (one shot at the centre) or multi (4 x 4 shots, 1 mm apart,
#          one pass: the 16 "regularly packed" spheres of Ch. 7.5)
#   H      element size in the impact area, mm (0.2 = d/5, 0.1 = d/10,
#          0.05 = d/20)
#   ALPHA  penalty k_n = alpha E (Ch. 7.5.2)
#   MU     Coulomb friction coefficient (Ch. 7.5.3); none: no friction
#   ANGLE  impingement angle to the surface, degrees (90 normal, 75 Ch. 7.5.3)
#   RULE   one_point or full (demshot --rule)
#
# The model is scene.yaml (the data of Ch. 7.5 and what was chosen where the
# thesis gives none); a run sets in it the element size H, ALPHA, MU and,
# for the multi-shot model, the fine region over the 4 x 4 mm impact area
# (scene.sh), and gives ANGLE and RULE to the programs.
#
# Writes OUT/NAME.{yaml,shots,state,log,forces}, OUT/NAME.prof (the profile:
# the four elements at the impact point for a single shot, the 4 x 4 mm area
# for the multi-shot model), OUT/NAME.sxx and OUT/NAME.szz (demprofile's
# saturation rows of sxx and szz) and OUT/NAME.row (the row of the table).
set -e
out=$1 name=$2
IFS=- read -r model h alpha mu angle rule <<EOF
$name
EOF
[ -n "$rule" ] || { echo "run.sh: $name: expected MODEL-H-ALPHA-MU-ANGLE-RULE" >&2; exit 2; }
bin=${BIN:-../../bin}
here=$(dirname "$0")
threads=${THREADS:-1}
mkdir -p "$out"
case $model in
single)
	fine=1
	area=$(awk -v h="$h" 'BEGIN { print 2 * h }')   # the 2 x 2 elements at the centre
	"$bin"/dempack -s "$here/scene.yaml" shots --grid 1 --passes 1 --area 0.2mm:0.2mm \
		--angle "${angle}deg" --seed 1 > "$out/$name.shots" 2> /dev/null ;;
multi)
	fine=4
	area=4
	"$bin"/dempack -s "$here/scene.yaml" shots --grid 4 --passes 1 --area 4mm:4mm \
		--angle "${angle}deg" --seed 1 > "$out/$name.shots" 2> /dev/null ;;
*)
	echo "run.sh: unknown model '$model'" >&2; exit 2 ;;
esac
friction=
[ "$mu" = none ] || friction="contact.friction=$mu"
sh "$here/scene.sh" "$here/scene.yaml" "block.element=$h mm" "block.fine=[$fine mm, $fine mm]" \
	"contact.alpha=$alpha" $friction > "$out/$name.yaml"
"$bin"/demshot -s "$out/$name.yaml" --rule "$rule" -v --threads "$threads" --forces "$out/$name.forces" \
	-o "$out/$name.state" "$out/$name.shots" 2> "$out/$name.log"
"$bin"/demprofile -q --area "${area}mm:${area}mm" --margin 0 --field sxx \
	--saturation "$out/$name.sxx" -o "$out/$name.prof" "$out/$name.state" 2>> "$out/$name.log"
"$bin"/demprofile -q --area "${area}mm:${area}mm" --margin 0 --field szz \
	--saturation "$out/$name.szz" "$out/$name.state" 2>> "$out/$name.log" > /dev/null
# the row of the table: name, model, h, alpha, mu, angle, rule, elements,
# surface/peak/peak depth/zero depth of sxx (MPa, mm), peak szz (MPa),
# coefficient of restitution (rebound over impact speed, normal parts, from
# the force history: e = J_z / (m v_z) - 1, all shots), wall seconds
awk -v name="$name" -v model="$model" -v h="$h" -v alpha="$alpha" -v mu="$mu" \
	-v angle="$angle" -v rule="$rule" '
	FILENAME ~ /\.log$/ && /: cost: / && /^demshot/ {
		for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
	FILENAME ~ /\.sxx$/ && !/^#/ { s = $2; p = $3; pd = $4; z = $5 }
	FILENAME ~ /\.szz$/ && !/^#/ { pz = $3 }
	FILENAME ~ /\.forces$/ && !/^#/ {
		k = $1 " " $2
		if (k in t0) J += 0.5 * ($8 + f0[k]) * ($3 - t0[k])
		else n++
		t0[k] = $3; f0[k] = $8 }
	END {
		# the shot of scene.yaml: mass, normal speed
		m = 4 / 3 * 3.14159265358979 * 0.0005^3 * 7800
		vz = 19 * sin(angle * 3.14159265358979 / 180)
		e = n ? J / (n * m * vz) - 1 : 0
		printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.1f\t%.1f\t%.3f\t%.3f\t%.1f\t%.3f\t%.1f\n",
			name, model, h, alpha, mu, angle, rule, v["elements"], s / 1e6, p / 1e6,
			pd * 1e3, z * 1e3, pz / 1e6, e, v["wall_s"] }' \
	"$out/$name.log" "$out/$name.sxx" "$out/$name.szz" "$out/$name.forces" > "$out/$name.row"
cat "$out/$name.row"
