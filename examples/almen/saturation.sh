#!/bin/sh
# saturation.sh CURVE [BIN] - the saturation point of an Almen saturation
# curve (rows: exposure, coverage, arc height in mm, curvatures x and y, and
# in runs since issue 25 the gauge reading in mm and the plastic coverage),
# as 'key value' lines, by the library's fitter (demfit(1), SAE J2597's
# forms fitted by GSL's nonlinear least squares; SAE J443's saturation
# point H(2T) = 1.1 H(T)):
#  - fit_*, T, intensity: the two-parameter curve h(n) = a (1 - exp(-b n))
#    on the arc height (T = ln 10 / b, h(T) = 0.9 a);
#  - fit3_*, T3, intensity3: the three-parameter curve a (1 - exp(-b n^c))
#    (T3 0: it does not saturate);
#  - data_T, data_h: the rule on the points (0: no point qualifies);
#  - gauge_T, gauge_intensity, gauge_data_T, gauge_data_h: the same (the
#    two-parameter curve and the rule) on the gauge reading, when the curve
#    has it.
# Lengths in mm, exposures as in the curve's first column.
set -eu
curve=$1
bin=${2:-../../bin}
err=$(mktemp)
trap 'rm -f "$err"' EXIT
fit() { # fit COLUMN PREFIX: demfit's keys renamed, heights in mm
	r=$("$bin"/demfit -q --unit mm --columns "1:$1" "$curve" 2> "$err") ||
		{ grep -v '^demfit: cost:' "$err" >&2; exit 1; }
	printf '%s\n' "$r" | awk -v p="$2" '
	{ v[$1] = $2 }
	END {
		mm = 1e3
		if (p == "") {
			printf "fit_a %.6g\nfit_b %.6g\nfit_rms %.4g\n", v["exp2_a:"] * mm, v["exp2_b:"], v["exp2_rms:"] * mm
			printf "T %.4g\nintensity %.5g\n", v["exp2_T:"], v["exp2_H:"] * mm
			printf "fit3_a %.6g\nfit3_b %.6g\nfit3_c %.6g\nfit3_rms %.4g\n", v["exp3_a:"] * mm, v["exp3_b:"], v["exp3_c:"], v["exp3_rms:"] * mm
			printf "T3 %.4g\nintensity3 %.5g\n", v["exp3_saturates:"] ? v["exp3_T:"] : 0, v["exp3_saturates:"] ? v["exp3_H:"] * mm : 0
			printf "data_T %g\ndata_h %.5g\n", v["points_saturates:"] ? v["points_T:"] : 0, v["points_saturates:"] ? v["points_H:"] * mm : 0
		} else {
			printf "%sT %.4g\n%sintensity %.5g\n", p, v["exp2_T:"], p, v["exp2_H:"] * mm
			printf "%sdata_T %g\n%sdata_h %.5g\n", p, v["points_saturates:"] ? v["points_T:"] : 0, p, v["points_saturates:"] ? v["points_H:"] * mm : 0
		}
	}'
}
fit 3 ""
# the gauge reading, when the curve has the column
if awk '!/^#/ { exit !(NF >= 6) }' "$curve"; then
	fit 6 gauge_
fi
awk '!/^#/ { n = $1 } END { printf "nmax %g\n", n }' "$curve"
