# bed.awk - the density of a bed of spheres, measured the same way for
# `dempack compress` (a text particle stream: x y z r rows) and for the
# LIGGGHTS pour (a custom dump: "ITEM: ATOMS id x y z radius" then rows),
# for `make peers`.  Usage:
#
#   awk -f bed.awk -v box="X0 Y0 Z0 X1 Y1 Z1" FILE
#
# box is the container (dempack's '# box'); the floor is Z0.  Prints one line
# of key=value:
#
#   spheres      the number of spheres
#   top          the height of the highest sphere's top above the floor (m)
#   density_top  the sphere volume over the box's floor area times top
#                (dempack's density_top)
#   density_mid  the sphere volume between 1/4 and 3/4 of top, over that
#                slab (the whole cross-section: the side walls are in it);
#                spheres cut by the slab's planes count their part inside
#                (exact spherical segments), so the rough top and the
#                layering on the floor are left out
#   above_lid    spheres reaching above the box's lid Z1
#   outside      spheres whose centre lies outside the box's side walls or
#                below its floor

BEGIN {
	pi = atan2(0, -1)
	if (split(box, b, " ") != 6) { print "bed.awk: box needs 6 numbers" > "/dev/stderr"; bad = 1; exit 1 }
	x0 = b[1]; y0 = b[2]; z0 = b[3]; x1 = b[4]; y1 = b[5]; z1 = b[6]
}

/^ITEM: ATOMS/ {
	dump = 1
	for (i = 3; i <= NF; i++) c[$i] = i - 2
	next
}
/^ITEM:/ { dump = 0; next }      # its values have fewer than 4 columns
/^#/ || NF < 4 { next }
{
	if (dump) { x = $c["x"]; y = $c["y"]; z = $c["z"]; r = $c["radius"] }
	else { x = $1; y = $2; z = $3; r = $4 }
	n++
	X[n] = x; Y[n] = y; Z[n] = z; R[n] = r
	if (z + r - z0 > top) top = z + r - z0
}

# the volume of the sphere (centre height zc, radius r) between heights a and b
function part(zc, r, a, b,    u1, u2) {
	u1 = a - zc; u2 = b - zc
	if (u1 < -r) u1 = -r
	if (u2 > r) u2 = r
	if (u2 <= u1) return 0
	return pi * (r * r * (u2 - u1) - (u2 ^ 3 - u1 ^ 3) / 3)
}

END {
	if (bad) exit 1
	if (n == 0) { print "bed.awk: " FILENAME ": no spheres" > "/dev/stderr"; exit 1 }
	area = (x1 - x0) * (y1 - y0)
	a = z0 + 0.25 * top; bb = z0 + 0.75 * top
	for (i = 1; i <= n; i++) {
		v += 4 / 3 * pi * R[i] ^ 3
		mid += part(Z[i], R[i], a, bb)
		if (Z[i] + R[i] > z1 * (1 + 1e-12)) lid++
		if (X[i] < x0 || X[i] > x1 || Y[i] < y0 || Y[i] > y1 || Z[i] < z0) out++
	}
	printf "spheres=%d top=%.6g density_top=%.6f density_mid=%.6f above_lid=%d outside=%d\n",
	    n, top, v / (area * top), mid / (area * (bb - a)), lid, out
}
