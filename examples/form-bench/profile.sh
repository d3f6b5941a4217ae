#!/bin/sh
# profile.sh - the bench's profile stream on stdout: one pass of an
# equi-biaxial shot-peening shape (compressive surface, deeper peak, zero
# at 0.6 mm; the shape of Fig. 8.5, made up, not data).
awk 'BEGIN {
	print "# dem profile 1"
	printf "# columns pass:u32:- depth:f64:m sxx:f64:Pa syy:f64:Pa szz:f64:Pa sxy:f64:Pa syz:f64:Pa szx:f64:Pa"
	printf " exx:f64:- eyy:f64:- ezz:f64:- exy:f64:- eyz:f64:- ezx:f64:- ep:f64:-"
	printf " sd_sxx:f64:Pa sd_syy:f64:Pa sd_szz:f64:Pa sd_sxy:f64:Pa sd_syz:f64:Pa sd_szx:f64:Pa"
	print " sd_exx:f64:- sd_eyy:f64:- sd_ezz:f64:- sd_exy:f64:- sd_eyz:f64:- sd_ezx:f64:- sd_ep:f64:- n:u32:-"
	print "# format text"
	print "# data"
	split("0 0.1 0.2 0.35 0.5 0.6", d, " ")
	split("-300 -400 -350 -150 30 0", s, " ")
	split("0.05 0.0375 0.025 0.0125 0 0", ep, " ")
	for (k = 1; k <= 6; k++) {
		printf "1 %g %g %g 0 0 0 0 0 0 0 0 0 0 %g", d[k] * 1e-3, s[k] * 1e6, s[k] * 1e6, ep[k]
		for (c = 0; c < 13; c++) printf " 0"
		print " 1"
	}
	print "# end 6"
}'
