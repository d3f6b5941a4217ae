# profile.awk - awk -f profile.awk REF RUN: the residual sxx profile of RUN
# (a demprofile stream: column 2 depth in m, column 3 sxx in Pa) and its
# difference from REF, on one line (stresses in MPa, depths in mm):
#
#   surface  sxx at the shallowest point (the top layer's centroid, h/2 deep)
#   peak     the most compressive sxx
#   at       its depth
#   zero     the depth of the compressive layer: below the peak, where sxx
#            first reaches 0 (linear between the points; "-" if it does not)
#   rms      the root mean square of RUN - REF over the depths both cover,
#            to 0.6 mm at most (the fine region), on 200 evenly spaced
#            depths, each profile linear between its points
#   max      the largest |RUN - REF| there
#   refpeak  REF's most compressive sxx
function interp(d, D, S, n,    i, w) {
	if (d <= D[1]) return S[1]
	if (d >= D[n]) return S[n]
	for (i = 1; i < n && D[i + 1] < d; i++) ;
	w = (d - D[i]) / (D[i + 1] - D[i])
	return S[i] + w * (S[i + 1] - S[i])
}
function stats(D, S, n, R,    i, k) {
	k = 1
	for (i = 2; i <= n; i++) if (S[i] < S[k]) k = i
	R["peak"] = S[k]; R["at"] = D[k]; R["zero"] = "-"
	for (i = k; i < n; i++)
		if (S[i + 1] >= 0) { R["zero"] = sprintf("%.3f", D[i] + (D[i + 1] - D[i]) * (0 - S[i]) / (S[i + 1] - S[i])); break }
}
FNR == 1 { f++ }
/^#/ { next }
f == 1 { nr++; Dr[nr] = $2 * 1e3; Sr[nr] = $3 / 1e6; next }
{ n++; D[n] = $2 * 1e3; S[n] = $3 / 1e6 }
END {
	if (!n || !nr) { print "profile.awk: empty profile" > "/dev/stderr"; exit 1 }
	stats(D, S, n, R)
	stats(Dr, Sr, nr, RR)
	lo = D[1] > Dr[1] ? D[1] : Dr[1]
	hi = D[n] < Dr[nr] ? D[n] : Dr[nr]
	if (hi > 0.6) hi = 0.6
	m = 200; s2 = 0; mx = 0
	for (j = 0; j < m; j++) {
		d = lo + (hi - lo) * (j + 0.5) / m
		dv = interp(d, D, S, n) - interp(d, Dr, Sr, nr)
		s2 += dv * dv
		if (dv < 0) dv = -dv
		if (dv > mx) mx = dv
	}
	printf "%.1f\t%.1f\t%.3f\t%s\t%.2f\t%.2f\t%.1f\n", S[1], R["peak"], R["at"], R["zero"], sqrt(s2 / m), mx, RR["peak"]
}
