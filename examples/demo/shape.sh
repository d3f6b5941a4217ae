#!/bin/sh
# shape.sh VTU - the shape of the formed strip, from demform's --vtu file,
# as a table for gnuplot on stdout (lengths in mm):
#
#   index 0: x w      along the length, on the centre line y = 0
#   index 1: y w      across the width, on the line x = 0
#
# w is the deflection of the mid-surface, the mean of the top and bottom
# faces' uz (as demform's arc height takes it), measured from the chord
# through the line's two ends: the rigid rotation that demform's minimal
# supports leave in the deflection (they hold the centre and the +x edge at
# the same height) is taken out, and w at x = 0 in index 0 is the arc
# height over the strip's length (the ends are symmetric about the centre),
# positive when the peened (top) face is convex.  The VTU
# arrays are inline base64 of a UInt64 byte count and then little-endian
# Float64 values (the header of the file says so; checked below).
set -eu
vtu=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

grep -q 'byte_order="LittleEndian" header_type="UInt64"' "$vtu" || {
	echo "shape.sh: $vtu: expected a little-endian VTU with UInt64 headers" >&2; exit 1; }

# the values of the Float64 DataArray NAME, three a line
array() {
	awk -v name="$1" 'f { print; exit }
		/<DataArray / && index($0, "Name=\"" name "\"") { f = 1 }' "$vtu" |
		tr -d ' \t' | base64 -d | od -A n -v -t f8 -j 8 -w24
}
array Points > "$tmp/p"
array displacement > "$tmp/u"

paste -d ' ' "$tmp/p" "$tmp/u" | awk '
	function key(a) { return sprintf("%.6f", a * 1000) }
	{ n++; x[n] = $1; y[n] = $2; z[n] = $3; uz[n] = $6
	  if (n == 1 || $3 < zmin) zmin = $3; if (n == 1 || $3 > zmax) zmax = $3 }
	END {
		if (n == 0) { print "shape.sh: no points" > "/dev/stderr"; exit 1 }
		tol = 1e-9
		# the mean of top and bottom uz at each (x, y) on the two lines
		for (i = 1; i <= n; i++) {
			face = (z[i] > zmax - tol) || (z[i] < zmin + tol)
			if (!face) continue
			if (y[i] < tol && y[i] > -tol) { sx[key(x[i])] += uz[i]; cx[key(x[i])]++; X[key(x[i])] = x[i] }
			if (x[i] < tol && x[i] > -tol) { sy[key(y[i])] += uz[i]; cy[key(y[i])]++; Y[key(y[i])] = y[i] }
		}
		line(sx, cx, X, "x")
		printf "\n\n"
		line(sy, cy, Y, "y")
	}
	function line(s, c, P, name,    k, m, a, b, i, j, t, ord) {
		m = 0
		for (k in s) {
			if (c[k] != 2) { print "shape.sh: no node pair at " name " = " k " mm" > "/dev/stderr"; exit 1 }
			ord[++m] = k
		}
		if (m < 3) { print "shape.sh: no line along " name " through the centre" > "/dev/stderr"; exit 1 }
		# sort by position (insertion sort; a few dozen points)
		for (i = 2; i <= m; i++) { t = ord[i]; for (j = i - 1; j > 0 && P[ord[j]] > P[t]; j--) ord[j + 1] = ord[j]; ord[j + 1] = t }
		# the chord: w = a + b p through the two ends
		b = (s[ord[m]] - s[ord[1]]) / 2 / (P[ord[m]] - P[ord[1]])
		a = s[ord[1]] / 2 - b * P[ord[1]]
		printf "# %s:mm w:mm (mid-surface deflection from the chord through the ends)\n", name
		for (i = 1; i <= m; i++)
			printf "%.6g %.9g\n", P[ord[i]] * 1000, (s[ord[i]] / 2 - a - b * P[ord[i]]) * 1000
	}'
