#!/bin/sh
# dimple.sh VTU THRESHOLD - the dimple of a single impact, from the last frame
# demshot --vtu wrote: prints "radius depth" in metres.
#
# The dimple is the part of the top surface indented (-uz) more than
# THRESHOLD (metres); its radius is the equivalent radius sqrt(A/pi) of that
# part, as demprofile's (demprofile(1), "Surface metrics"), but A is
# measured on the deformed surface and between the nodes: each quad of the
# top face is cut into two triangles (both diagonals, averaged), the
# indentation taken linear on each, and the part of each triangle above the
# threshold added exactly.  demprofile counts whole nodes (a quarter of each
# face around an indented node, in the reference plane), so its radius moves
# in steps of about h^2 / (2 pi a): 5 to 10 um at d/10 here.  depth is the
# deepest indentation.
#
# The VTU file holds the displacement (point data) and the reference Points
# as base64 binary Float64 arrays after a UInt64 byte count; the top nodes
# (reference z = 0) come last, x fastest then y (lib/fe/mesh.h).
set -e
vtu=$1 thr=$2
[ -f "$vtu" ] && [ -n "$thr" ] || { echo "usage: dimple.sh VTU THRESHOLD" >&2; exit 2; }
array() {
	awk -v n="$1" 'f { print; exit } index($0, "Name=\"" n "\"") { f = 1 }' "$vtu" |
		tr -d ' ' | base64 -d | od -A n -t f8 -v -j 8 -w24
}
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
array displacement > "$tmp"
array Points | paste - "$tmp" | awk -v t="$thr" '
	# area of the part of triangle (a, b, c) where the linear w exceeds t
	function tri(a, b, c,    A, ga, gb, gc, n) {
		A = 0.5 * ((X[b] - X[a]) * (Y[c] - Y[a]) - (X[c] - X[a]) * (Y[b] - Y[a]))
		if (A < 0) A = -A
		ga = W[a] - t; gb = W[b] - t; gc = W[c] - t
		n = (ga > 0) + (gb > 0) + (gc > 0)
		if (n == 0) return 0
		if (n == 3) return A
		if (n == 1) {   # the corner above: its sub-triangle
			if (ga > 0) return A * ga * ga / ((ga - gb) * (ga - gc))
			if (gb > 0) return A * gb * gb / ((gb - ga) * (gb - gc))
			return A * gc * gc / ((gc - ga) * (gc - gb))
		}
		# two above: all but the sub-triangle of the corner below
		if (ga <= 0) return A * (1 - ga * ga / ((ga - gb) * (ga - gc)))
		if (gb <= 0) return A * (1 - gb * gb / ((gb - ga) * (gb - gc)))
		return A * (1 - gc * gc / ((gc - ga) * (gc - gb)))
	}
	NF == 6 && $3 == 0 {
		if (k == 0) y0 = $2
		if ($2 == y0) nx++
		X[k] = $1 + $4; Y[k] = $2 + $5; W[k] = -$6
		if (W[k] > dmax) dmax = W[k]
		k++
	}
	END {
		if (nx < 2 || k % nx) { print "dimple.sh: the top nodes are not a grid" > "/dev/stderr"; exit 3 }
		ny = k / nx
		for (j = 0; j + 1 < ny; j++)
			for (i = 0; i + 1 < nx; i++) {
				p = i + nx * j; q = p + 1; r = p + nx + 1; s = p + nx
				area += 0.5 * (tri(p, q, r) + tri(p, r, s) + tri(p, q, s) + tri(q, r, s))
			}
		printf "%.6g %.6g\n", sqrt(area / 3.14159265358979), dmax
	}'
