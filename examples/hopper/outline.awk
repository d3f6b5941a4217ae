# outline.awk - the outlines of the bodies of one frame of a body stream
# (dem-streams(5)), for gnuplot: one closed polyline per body, separated by
# blank lines; then the walls' faces (from the "# wall" header lines) with
# "wall" in a third column.  awk -v frame=F -f outline.awk STREAM
function sgnpow(c, e) { return (c < 0 ? -1 : 1) * (c < 0 ? -c : c) ^ e }
BEGIN { pi = atan2(0, -1); k = 72 }
/^# wall / { nw++; wx0[nw] = $3; wy0[nw] = $4; wx1[nw] = $5; wy1[nw] = $6; next }
/^#/ { next }
$1 == frame {
	a = $5; b = $6; m = $7; x = $8; y = $9; th = $10
	c = cos(th); s = sin(th)
	n = $4 == 1 ? m : k
	for (i = 0; i <= n; i++) {
		if ($4 == 0) {          # superquadric, Eq. 4.3 with exponent 2/m
			t = 2 * pi * i / n
			u = a * sgnpow(cos(t), 2 / m); v = b * sgnpow(sin(t), 2 / m)
		} else if ($4 == 1) {   # regular polygon, a side flat at theta = 0
			t = -pi / 2 + pi / m + 2 * pi * i / m
			u = a * cos(t); v = a * sin(t)
		} else {                # disk
			t = 2 * pi * i / n
			u = a * cos(t); v = a * sin(t)
		}
		printf "%.6g %.6g\n", 1000 * (x + c * u - s * v), 1000 * (y + s * u + c * v)
	}
	printf "\n"
}
END {
	for (w = 1; w <= nw; w++)
		printf "%.6g %.6g\n%.6g %.6g\n\n", 1000 * wx0[w], 1000 * wy0[w], 1000 * wx1[w], 1000 * wy1[w]
}
