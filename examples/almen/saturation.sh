#!/bin/sh
# saturation.sh CURVE - the saturation point of an Almen saturation curve
# (rows: passes, coverage, arc height in mm, ...), as 'key value' lines.
#
# SAE J443's rule: the saturation point is the earliest exposure T at which
# doubling the exposure raises the arc height by at most 10 %,
# h(2T) <= 1.1 h(T).  Two readings of it:
#  - fit: the two-parameter curve h(n) = a (1 - exp(-b n)) fitted by least
#    squares (b by a golden-section search on log b, a in closed form);
#    h(2T) = 1.1 h(T) gives exp(-b T) = 0.1, so T = ln 10 / b and the
#    intensity is h(T) = 0.9 a;
#  - fit3: h(n) = a (1 - exp(-b n)) + c n, for a curve that keeps rising
#    after the knee (b by golden section, a and c by linear least squares);
#    T the earliest exposure with h(2T) <= 1.1 h(T), by a scan in steps of
#    0.01 pass up to the last pass (none if the ratio never comes down to
#    1.1 within the run);
#  - data: the earliest measured n with h(2n) <= 1.1 h(n) (2n measured).
set -eu
awk '!/^#/ { N++; n[N] = $1; h[N] = $3; H[$1] = $3 }
function sse(b,    i, sf, sh, a, s, f) {
	sf = 0; sh = 0
	for (i = 1; i <= N; i++) { f = 1 - exp(-b * n[i]); sf += f * f; sh += f * h[i] }
	A = sh / sf; s = 0
	for (i = 1; i <= N; i++) { f = h[i] - A * (1 - exp(-b * n[i])); s += f * f }
	return s
}
function h3(t, b) { return A3 * (1 - exp(-b * t)) + C3 * t }
function sse3(b,    i, f, Sff, Sfn, Snn, Sfh, Snh, det, s, r) {
	Sff = Sfn = Snn = Sfh = Snh = 0
	for (i = 1; i <= N; i++) {
		f = 1 - exp(-b * n[i])
		Sff += f * f; Sfn += f * n[i]; Snn += n[i] * n[i]; Sfh += f * h[i]; Snh += n[i] * h[i]
	}
	det = Sff * Snn - Sfn * Sfn
	if (det <= 0) return 1e300
	A3 = (Sfh * Snn - Snh * Sfn) / det; C3 = (Sff * Snh - Sfn * Sfh) / det
	s = 0
	for (i = 1; i <= N; i++) { r = h[i] - h3(n[i], b); s += r * r }
	return s
}
END {
	if (N < 4) { print "saturation.sh: fewer than 4 points" > "/dev/stderr"; exit 1 }
	# golden section on x = log b over [log 1e-4, log 10]
	lo = log(1e-4); hi = log(10); g = (sqrt(5) - 1) / 2
	x1 = hi - g * (hi - lo); x2 = lo + g * (hi - lo); f1 = sse(exp(x1)); f2 = sse(exp(x2))
	for (k = 0; k < 200; k++) {
		if (f1 < f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = sse(exp(x1)) }
		else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = sse(exp(x2)) }
	}
	b = exp((lo + hi) / 2); s = sse(b); a = A
	T = log(10) / b
	printf "fit_a %.6g\nfit_b %.6g\nfit_rms %.4g\n", a, b, sqrt(s / N)
	printf "T %.4g\nintensity %.5g\n", T, 0.9 * a
	# the three-parameter curve
	lo = log(1e-4); hi = log(10)
	x1 = hi - g * (hi - lo); x2 = lo + g * (hi - lo); f1 = sse3(exp(x1)); f2 = sse3(exp(x2))
	for (k = 0; k < 200; k++) {
		if (f1 < f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = sse3(exp(x1)) }
		else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = sse3(exp(x2)) }
	}
	b3 = exp((lo + hi) / 2); s3 = sse3(b3)
	T3 = 0
	for (t = 0.01; t <= n[N] + 1e-9; t += 0.01)
		if (h3(2 * t, b3) <= 1.1 * h3(t, b3)) { T3 = t; break }
	printf "fit3_a %.6g\nfit3_b %.6g\nfit3_c %.6g\nfit3_rms %.4g\n", A3, b3, C3, sqrt(s3 / N)
	printf "T3 %.4g\nintensity3 %.5g\n", T3, T3 ? h3(T3, b3) : 0
	# the rule on the data themselves
	data_T = 0
	for (i = 1; i <= N; i++) { m = n[i]; if ((2 * m) in H && H[2 * m] <= 1.1 * H[m]) { data_T = m; break } }
	printf "data_T %d\ndata_h %.5g\nnmax %d\n", data_T, data_T ? H[data_T] : 0, n[N]
}' "$1"
