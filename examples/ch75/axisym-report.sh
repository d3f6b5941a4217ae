#!/bin/sh
# axisym-report.sh OUT H ALPHA "HS" - the section of REPORT.md comparing the
# 3D single impact (run.sh: OUT/single-H-ALPHA-none-90-full) with the
# axisymmetric runs (axisym.sh: OUT/axisym-h-ALPHA for h in HS, H first), as
# Ch. 7.5.1 and Fig. 7.15 do.  Takes the profiles it compares (demprofile):
#
#   OUT/cmp-3d-c.prof     3D, the 2 x 2 elements at the impact point: the
#                         square |x|, |y| < H (the centre line)
#   OUT/cmp-3d-w.prof     3D, the 4 x 4 elements: the square |x|, |y| < 2H
#   OUT/cmp-2d-h-c.prof   axisymmetric, the disk r < H, weighted by ring
#   OUT/cmp-2d-h-w.prof   axisymmetric, the disk r < 2H
#   OUT/cmp-2d-H-*-cart.prof  the same at h = H, sxx replaced by the
#                         Cartesian mean (s_rr + s_tt) / 2
#
# A square of half-side a is compared with the disk of radius a.  In
# axisymmetry sxx is the radial stress s_rr (demprofile(1)); on the axis it
# equals the hoop stress and the Cartesian sxx.  Figures of each profile:
# the peak compressive sxx and its depth (a layer's centroid), the
# compressive depth (the first zero crossing below the peak, interpolated
# between layers), the plastic depth (where the effective plastic strain
# falls to 0.002, the 0.2 % offset convention demprofile's coverage uses,
# interpolated) and the plastic strain of the top layer; the cost of each
# run from demshot's cost line.
set -e
out=$1 h=$2 alpha=$3 hs=$4
bin=${BIN:-../../bin}
three=$out/single-$h-$alpha-none-90-full
c=$(awk -v h="$h" 'BEGIN { print 2 * h }')
w=$(awk -v h="$h" 'BEGIN { print 4 * h }')
log=$out/cmp.log           # demprofile's cost lines (and its message, if one fails)
"$bin"/demprofile -q --area "${c}mm:${c}mm" --margin 0 -o "$out/cmp-3d-c.prof" "$three.state" 2> "$log"
"$bin"/demprofile -q --area "${w}mm:${w}mm" --margin 0 -o "$out/cmp-3d-w.prof" "$three.state" 2>> "$log"
for e in $hs; do
	"$bin"/demprofile -q --area "${c}mm:${c}mm" --margin 0 -o "$out/cmp-2d-$e-c.prof" \
		"$out/axisym-$e-$alpha.state" 2>> "$log"
	"$bin"/demprofile -q --area "${w}mm:${w}mm" --margin 0 -o "$out/cmp-2d-$e-w.prof" \
		"$out/axisym-$e-$alpha.state" 2>> "$log"
done
# the Cartesian sxx of the axisymmetric run averaged over a disk: the mean
# of (s_rr + s_tt) / 2 (on the axis s_rr itself); a 3D square's mean sxx
# is the same mean of (s_rr + s_tt) / 2 by its x-y symmetry
for a in c w; do
	awk '/^#/ { print; next } { $3 = ($3 + $4) / 2; print }' "$out/cmp-2d-$h-$a.prof" \
		> "$out/cmp-2d-$h-$a-cart.prof"
done

# metrics PROFILE LOG: peak (MPa), its depth, compressive depth, plastic
# depth (mm), top-layer ep, elements, wall s, cpu s
metrics() {
	awk '
	FILENAME == ARGV[1] && !/^#/ { n++; d[n] = $2; s[n] = $3; ep[n] = $15 }
	FILENAME == ARGV[2] && /^demshot: cost: / {
		for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
	END {
		ipk = 1
		for (i = 2; i <= n; i++) if (s[i] < s[ipk]) ipk = i
		zero = 0
		for (i = ipk + 1; i <= n; i++) if (s[i] >= 0) {
			zero = d[i - 1] + (d[i] - d[i - 1]) * s[i - 1] / (s[i - 1] - s[i]); break }
		pd = 0
		for (i = 2; i <= n; i++) if (ep[i - 1] >= 0.002 && ep[i] < 0.002) {
			pd = d[i - 1] + (d[i] - d[i - 1]) * (ep[i - 1] - 0.002) / (ep[i - 1] - ep[i]); break }
		printf "%.1f %.3f %.4f %.4f %.4f %s %.1f %.1f\n", s[ipk] / 1e6, d[ipk] * 1e3, zero * 1e3,
			pd * 1e3, ep[1], v["elements"], v["wall_s"], v["cpu_s"]
	}' "$1" "$2"
}

row() {  # row LABEL METRICS
	echo "$2" | awk -v l="$1" '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", l, $1, $2, $3, $4, $5, $6, $7, $8 }'
}

diff_row() {  # diff_row LABEL 2D-METRICS 3D-METRICS
	printf '%s\n%s\n' "$2" "$3" | awk -v l="$1" '
		NR == 1 { for (i = 1; i <= NF; i++) a[i] = $i }
		NR == 2 { for (i = 1; i <= NF; i++) b[i] = $i }
		END {
			printf "| %s | %+.1f %% | %+.1f %% | %+.1f %% | %+.1f %% | %.3f | %.3f |\n", l,
				100 * (a[1] - b[1]) / b[1], 100 * (a[3] - b[3]) / b[3],
				100 * (a[4] - b[4]) / b[4], 100 * (a[5] - b[5]) / b[5],
				a[7] / b[7], a[8] / b[8] }'
}

m3c=$(metrics "$out/cmp-3d-c.prof" "$three.log")
m3w=$(metrics "$out/cmp-3d-w.prof" "$three.log")
echo "## Axisymmetric against 3D (Ch. 7.5.1, Fig. 7.15), h = $h mm, k_n = $alpha E"
echo
echo "The single impact of scene.yaml in 3D (run.sh) and axisymmetric (axisym.sh: the cylinder"
echo "r <= 4 mm, 0.9 mm thick, the same element size, material, damping 0.05 and alpha; full"
echo "integration in both).  Profiles: the 3D square of half-side a about the impact point"
echo "(demprofile --area 2a:2a) against the disk r < a of the axisymmetric run, weighted by ring;"
echo "a = $h mm (the centre line: the 2 x 2 elements at the impact point, the first ring) and"
echo "a = $(awk -v h="$h" 'BEGIN { print 2 * h }') mm (4 x 4 elements, two rings).  3D sxx against the axisymmetric s_rr"
echo "(and, marked Cartesian, against the disk's mean of (s_rr + s_tt)/2, which a square's mean"
echo "sxx equals by its symmetry).  Peak: the most compressive sxx (MPa) and its depth;"
echo "compressive depth: the first zero crossing below the peak; plastic depth: where ep falls"
echo "to 0.002; ep top: the top layer's (h/2 deep, so it grows as h shrinks).  Depths in mm;"
echo "wall and CPU seconds of demshot (wall times on a shared machine)."
echo
echo "| run | peak sxx | at depth | compressive depth | plastic depth | ep top | elements | wall s | cpu s |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
row "3D, h = $h, square a = $h" "$m3c"
row "3D, h = $h, square a = $(awk -v h="$h" 'BEGIN { print 2 * h }')" "$m3w"
for e in $hs; do
	row "axisymmetric, h = $e, disk r < $h" "$(metrics "$out/cmp-2d-$e-c.prof" "$out/axisym-$e-$alpha.log")"
	row "axisymmetric, h = $e, disk r < $(awk -v h="$h" 'BEGIN { print 2 * h }')" \
		"$(metrics "$out/cmp-2d-$e-w.prof" "$out/axisym-$e-$alpha.log")"
	[ "$e" = "$h" ] || continue
	row "axisymmetric, h = $e, disk r < $h, Cartesian" \
		"$(metrics "$out/cmp-2d-$e-c-cart.prof" "$out/axisym-$e-$alpha.log")"
	row "axisymmetric, h = $e, disk r < $(awk -v h="$h" 'BEGIN { print 2 * h }'), Cartesian" \
		"$(metrics "$out/cmp-2d-$e-w-cart.prof" "$out/axisym-$e-$alpha.log")"
done
echo
echo "Differences of the axisymmetric runs from the 3D run at h = $h over the same radius"
echo "(axisymmetric minus 3D, over 3D), and the cost ratios (axisymmetric over 3D):"
echo
echo "| axisymmetric run | peak | compressive depth | plastic depth | ep top | wall ratio | cpu ratio |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for e in $hs; do
	diff_row "h = $e, a = $h" "$(metrics "$out/cmp-2d-$e-c.prof" "$out/axisym-$e-$alpha.log")" "$m3c"
	diff_row "h = $e, a = $(awk -v h="$h" 'BEGIN { print 2 * h }')" \
		"$(metrics "$out/cmp-2d-$e-w.prof" "$out/axisym-$e-$alpha.log")" "$m3w"
	[ "$e" = "$h" ] || continue
	diff_row "h = $e, a = $h, Cartesian" \
		"$(metrics "$out/cmp-2d-$e-c-cart.prof" "$out/axisym-$e-$alpha.log")" "$m3c"
	diff_row "h = $e, a = $(awk -v h="$h" 'BEGIN { print 2 * h }'), Cartesian" \
		"$(metrics "$out/cmp-2d-$e-w-cart.prof" "$out/axisym-$e-$alpha.log")" "$m3w"
done
echo
# the largest difference along the depth, centre line, same h
awk '
	FILENAME == ARGV[1] && !/^#/ { n++; d[n] = $2; s[n] = $3; if ($3 < pk) pk = $3 }
	FILENAME == ARGV[2] && !/^#/ { m++; if (d[m] != $2) bad = 1; x = $3 - s[m]; if (x < 0) x = -x
		if (x > mx) { mx = x; at = $2 } }
	END {
		if (bad || m != n) { print "(the two profiles have different depths)"; exit }
		printf "Centre line, h the same: the largest difference of sxx along the depth is %.1f MPa at %.3f mm (%.1f %% of the 3D peak).\n",
			mx / 1e6, at * 1e3, 100 * mx / -pk }' "$out/cmp-3d-c.prof" "$out/cmp-2d-$h-c.prof"
