#!/bin/sh
# duration.sh PNG OUT NAME [NAME]... - the impact duration against the
# disk's mass per unit thickness (README.md, "The duration question"):
# the runs NAME (OUT/NAME.row: the same model with other disk densities)
# against two estimates from first principles (params.sh: R, v, E, the
# law, the largest flow stress of Table 7.1):
#  - the penalty alone, the disk on a rigid block: for F = k delta^m per
#    unit length (k = alpha E R^(1-m)), twice the time to stop,
#    2 I delta_max / v with (k / (m + 1)) delta_max^(m + 1) = mu v^2 / 2 and
#    I = B(1/(m + 1), 1/2) / (m + 1) (pi sqrt(mu / k) for m = 1);
#  - a lower bound on the time to stop: in a time T the disk moves at most
#    v T, so the contact is at most 2 sqrt(2 R v T) wide (no pile-up), and
#    it carries a pressure of at most p = (2 + pi) / sqrt(3) sigma_max (the
#    plane-strain punch of Prandtl, von Mises, at the largest flow stress);
#    the impulse mu v needs T >= (3 mu v / (4 p sqrt(2 R v)))^(2/3).
# and the 4 us that the thesis's end time (1e-5 s, "about 2.5 times the
# impact duration") implies.
set -e
png=$1 out=$2
shift 2
read -r R v t E m alpha smax rho <<EOF2
$(sh "$(dirname "$0")/params.sh" "$out" "$1")
EOF2
pts=$out/duration.dat
for n in "$@"; do
	awk -v R="$R" '!/^#/ { printf "%.6g %s\n", $6 * 3.141592653589793 * R * R, $11 }' "$out/$n.row"
done | sort -g > "$pts"
{
	echo "set terminal pngcairo size 640,480 font ',10' noenhanced"
	echo "set output '$png'"
	echo "set title 'Impact duration against the disk mass (Hertz law, alpha = 2.5)'"
	echo "set grid; set logscale xy; set key top left"
	echo "set xlabel 'disk mass per unit thickness (kg/m)'; set ylabel 'contact duration (us)'"
	echo "R = $R; v = $v; E = $E; m = $m; al = $alpha; smax = $smax"
	echo "k = al * E * R**(1 - m); p = (2 + pi) / sqrt(3) * smax"
	echo "I = gamma(1 / (m + 1)) * gamma(0.5) / gamma(1 / (m + 1) + 0.5) / (m + 1)"
	echo "pen(mu) = 1e6 * 2 * I * ((m + 1) * mu * v**2 / (2 * k))**(1 / (m + 1)) / v"
	echo "bnd(mu) = 1e6 * (3 * mu * v / (4 * p * sqrt(2 * R * v)))**(2. / 3)"
	echo "set xrange [0.05:20]; set yrange [0.5:100]"
	echo "steel = 7800 * pi * R * R"
	echo "set arrow from steel, graph 0 to steel, graph 1 nohead dt 3"
	echo "set label 'steel, 7800 kg/m^3' at steel, 0.7 right offset -0.5, 0"
	echo "plot '$pts' using 1:2 with linespoints pt 7 lw 1.5 title 'demshot (this model)', \\"
	echo "     pen(x) title 'penalty alone, rigid block', bnd(x) title 'lower bound: v T travel, p <= 2.97 sigma_max', \\"
	echo "     4 dt 2 lc rgb 'black' title '4 us (the thesis: 1e-5 s = 2.5 durations)'"
} | gnuplot
