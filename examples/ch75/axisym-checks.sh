#!/bin/sh
# axisym-checks.sh OUT H ALPHA "HS" - where the axisymmetric and the 3D single
# impact differ (the second part of the axisym section of REPORT.md):
#
# 1. column by column: the peak compressive sxx of each element column of
#    the 3D run (the column at x = (i + 1/2) H, y = H/2, radius
#    sqrt(x^2 + y^2)) against the axisymmetric ring i (r = (i + 1/2) H), as
#    demprofile takes them (a region holding one column's centroid);
# 2. the axisymmetric model's sensitivity, each variant against its base
#    run (axisym.sh, OUT/axisym-H-ALPHA): global damping 0.02 and 0.1 (Ch. 7.5:
#    0.05), the penalty alpha 2 of the other figures (Ch. 7.5.1: 5), the
#    outer radius 4.513 mm (the disk of the 8 x 8 mm block's area; base 4 mm,
#    the sides' distance), the rim fixed (base: a roller, as the 3D sides),
#    and a pass run on to 1e-5 of its peak kinetic energy (base 0.01);
# 3. the contact of the 3D run and of the axisymmetric runs at HS.
#
# Runs the variants as OUT/axisym-H-ALPHA-TAG (axisym.sh); cost lines and
# messages of demprofile to OUT/cmp.log.
set -e
out=$1 h=$2 alpha=$3 hs=$4
bin=${BIN:-../../bin}
here=$(dirname "$0")
log=$out/cmp.log
three=$out/single-$h-$alpha-none-90-full.state
base=$out/axisym-$h-$alpha

# peak FILE: the most compressive sxx (MPa) of a profile, its depth (mm)
peak() {
	awk '!/^#/ && $3 < p { p = $3; d = $2 } END { printf "%.1f %.3f\n", p / 1e6, d * 1e3 }' "$1"
}
# column STATE X Y: the profile of the column whose centroid is at (X, Y) mm
column() {
	printf 'profile:\n  center: [%s mm, %s mm]\n  area: [%s mm, %s mm]\n  margin: 0 mm\n' \
		"$2" "$3" "$4" "$4" > "$out/cmp-col.yaml"
	"$bin"/demprofile -q -s "$out/cmp-col.yaml" "$1" 2>> "$log"
}

echo "### Where they differ"
echo
echo "Column by column (h = $h mm): the peak compressive sxx of the 3D element column at"
echo "(x, y) = ((i + 1/2) h, h/2) against the axisymmetric ring i at r = (i + 1/2) h (MPa, depth mm)."
echo
echo "| i | 3D radius | 3D peak | at depth | axisymmetric r | axisymmetric peak | at depth | difference |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|"
for i in 0 1 2 3 4; do
	x=$(awk -v h="$h" -v i="$i" 'BEGIN { print (i + 0.5) * h }')
	y=$(awk -v h="$h" 'BEGIN { print h / 2 }')
	half=$(awk -v h="$h" 'BEGIN { print h / 2 }')
	column "$three" "$x" "$y" "$half" > "$out/cmp-col3.prof"
	column "$base.state" "$x" 0 "$half" > "$out/cmp-col2.prof"
	p3=$(peak "$out/cmp-col3.prof")
	p2=$(peak "$out/cmp-col2.prof")
	echo "$i $x $y $p3 $p2" | awk '{ printf "| %d | %.4f | %.1f | %.3f | %.4f | %.1f | %.3f | %+.1f %% |\n",
		$1, sqrt($2 * $2 + $3 * $3), $4, $5, $2, $6, $7, 100 * ($6 - $4) / $4 }'
done
echo
echo "The axisymmetric model's sensitivity at h = $h mm: the peak over the disk r < $h mm and the"
echo "compressive depth, each variant against the base run (k_n = $alpha E, damping 0.05, r <= 4 mm,"
echo "rim on rollers, pass ended at 0.01 of the peak kinetic energy)."
echo
echo "| variant | peak sxx | at depth | compressive depth | peak change | depth change |"
echo "|---|---:|---:|---:|---:|---:|"
c=$(awk -v h="$h" 'BEGIN { print 2 * h }')
bm=
for v in base "damp0.02 run.damping=0.02" "damp0.1 run.damping=0.1" "alpha2 contact.alpha=2" \
	 "R4.513 block.size=[4.513 mm, 0.9 mm]" "rimfixed block.bc={xmax: fixed, bottom: fixed, top: free}" \
	 "steady1e-5 run.steady=1e-5"; do
	tag=${v%% *}
	if [ "$tag" = base ]; then
		st=$base.state
	else
		key=${v#* }
		BIN=$bin sh "$here/axisym.sh" "$out" "axisym-$h-$alpha-$tag" "$key" > /dev/null
		st=$out/axisym-$h-$alpha-$tag.state
	fi
	"$bin"/demprofile -q --area "${c}mm:${c}mm" --margin 0 --saturation "$out/cmp-var.sxx" \
		-o /dev/null "$st" 2>> "$log"
	m=$(awk '!/^#/ { printf "%.1f %.3f %.4f\n", $3 / 1e6, $4 * 1e3, $5 * 1e3 }' "$out/cmp-var.sxx")
	[ -n "$bm" ] || bm=$m
	printf '%s\n%s\n' "$m" "$bm" | awk -v t="$tag" 'NR == 1 { p = $1; d = $2; z = $3 } NR == 2 { bp = $1; bz = $3 }
		END { if (t == "base") { printf "| base | %.1f | %.3f | %.4f | | |\n", p, d, z; exit }
			printf "| %s | %.1f | %.3f | %.4f | %+.1f %% | %+.1f %% |\n", t, p, d, z,
				100 * (p - bp) / bp, 100 * (z - bz) / bz }'
done
echo
echo "The contact (force histories): the peak normal force on the shot (the resultant fz), the"
echo "time in contact and the coefficient of restitution e = J_z / (m v) - 1 (run.sh's)."
echo
echo "| run | peak force (N) | in contact (us) | e |"
echo "|---|---:|---:|---:|"
for f in "$out/single-$h-$alpha-none-90-full" $(for e in $hs; do echo "$out/axisym-$e-$alpha"; done); do
	awk -v name="$(basename "$f")" '!/^#/ {
		if ($8 > m) m = $8
		if ($8 > 0) { if (t0 == "") t0 = $3; t1 = $3 }
		if (n++) J += 0.5 * ($8 + pf) * ($3 - pt); pt = $3; pf = $8 }
		END {
			# the shot of scene.yaml: mass, speed
			mass = 4 / 3 * 3.14159265358979 * 0.0005^3 * 7800
			printf "| %s | %.1f | %.2f | %.3f |\n", name, m, (t1 - t0) * 1e6, J / (mass * 19) - 1 }' "$f.forces"
done
