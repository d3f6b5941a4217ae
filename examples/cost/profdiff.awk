# profdiff.awk - awk -f profdiff.awk REF RUN: how far the profile stream
# RUN (demprofile's, text) is from REF, as one number: the largest
# difference of a floating-point column over the largest magnitude of
# REF's columns of the same unit (all the stresses share one scale, all the
# strains another: a shear stress that is round-off noise around zero is
# measured against the stresses, not against itself).  The integer columns
# (pass, n) and the row count must be equal: otherwise it prints "rows",
# "columns" or "integers" and exits 1.
FNR == 1 { f++ }
f == 1 && /^# columns / {
	for (i = 3; i <= NF; i++) {
		split($i, c, ":")
		kind[i - 2] = c[2]; unit[i - 2] = c[3]
	}
	next
}
/^#/ { next }
f == 1 { a[++n] = $0; nc = NF; next }
{
	k++
	if (k > n) { bad = "rows"; exit 1 }
	if (NF != nc) { bad = "columns"; exit 1 }
	split(a[k], x)
	for (i = 1; i <= NF; i++) {
		if (kind[i] != "f64") {
			if (x[i] != $i) { bad = "integers"; exit 1 }
			continue
		}
		d = x[i] - $i; if (d < 0) d = -d
		if (d > dm[i]) dm[i] = d
		v = x[i] < 0 ? -x[i] : x[i]
		if (v > s[unit[i]]) s[unit[i]] = v
	}
}
END {
	if (bad == "" && (k != n || n == 0)) bad = "rows"
	if (bad != "") { print bad; exit 1 }
	m = 0
	for (i = 1; i <= nc; i++)
		if (kind[i] == "f64" && s[unit[i]] > 0 && dm[i] / s[unit[i]] > m) m = dm[i] / s[unit[i]]
	printf "%.3g\n", m
}
