#!/bin/sh
# plot.sh OUT PNGDIR - draw the report's plots with gnuplot from OUT/results.tsv
# (and tables.tsv for the thesis's times):
#
#   cellsize-2d.png, cellsize-3d.png   D-cell warm time against the cell factor (Figs. 2.10-2.12)
#   scale.png                          D-cell time against N, ours (warm and cold) and the thesis's (Fig. 2.9)
#
# "Warm" is detect_warm_s (results.tsv column 18: the per-step time in a time
# loop), "cold" detect_s (column 11: the first call of a process).
#
# The environment gives N1M, SWEEP2D and SWEEP3D, as the Makefile exports them.
# shellcheck disable=SC2129 # the gnuplot script is written piece by piece
set -eu
out=$1 png=$2
dat=$out/plot
rm -rf "$dat"
mkdir -p "$dat" "$png"

# Sweep: one file per case, "factor ns/object" (warm), by factor.
awk -F'\t' -v dat="$dat" -v n1m="$N1M" '
	!/^#/ && $1 == "dcell" && $2 != "def" && $4 == n1m && $9 == "bin" {
		print $2, $18 / $4 * 1e9 | ("sort -n > " dat "/sweep-d" $3 "-rho" $6 "-lam" $7 ".dat")
	}' "$out/results.tsv"

# Scale: "N/1e6 warm-seconds cold-seconds" of D-cell, URD, lambda 1, square domain, per dimension
# and density; ours from the results, the thesis's from tables.tsv.
awk -F'\t' -v dat="$dat" '
	!/^#/ && $1 == "dcell" && $2 == "def" && $5 == "urd" && $7 == "1" && $8 == "-" && $9 == "bin" && $4 >= 100000 {
		print $4 / 1e6, $18, $11 | ("sort -n > " dat "/scale-d" $3 "-rho" $6 "-ours.dat")
	}' "$out/results.tsv"
awk -F'\t' -v dat="$dat" '
	!/^#/ && NF >= 9 && $8 == "dcell" && $4 == "urd" && $6 == "1" && $7 == "-" && $9 != "-" && !seen[$2, $3, $5]++ {
		print substr($2, 1, 1), $9 | ("sort -n > " dat "/scale-d" $3 "-rho" $5 "-thesis.dat")
	}' tables.tsv

gp=$dat/plots.gp
npanel=0
# panel TITLE DEFAULT FILE:LABEL... - one sweep panel, if any of its files exist
panel() {
	title=$1 def=$2
	shift 2
	cmd=""
	for fl in "$@"; do
		f=$dat/${fl%%:*}.dat
		[ -s "$f" ] || continue
		cmd="$cmd${cmd:+, }'$f' using 1:2 with linespoints linewidth 2 pointtype 7 title '${fl#*:}'"
	done
	[ -n "$cmd" ] || return 0
	npanel=$((npanel + 1))
	cat >> "$gp.panels" <<-EOF
	set title "$title"
	set arrow 1 from $def, graph 0 to $def, graph 1 nohead dashtype 2 linecolor rgb "gray40"
	plot $cmd
	EOF
}

sweepplot() { # DIM DEFAULT
	d=$1 def=$2
	rm -f "$gp.panels"
	npanel=0
	panel "λ 1, by density (Fig. 2.10)" "$def" \
		"sweep-d$d-rho0.1-lam1:ρ 0.1" "sweep-d$d-rho0.3-lam1:ρ 0.3" "sweep-d$d-rho0.6-lam1:ρ 0.6"
	panel "ρ 0.1, by size ratio (Fig. 2.11)" "$def" \
		"sweep-d$d-rho0.1-lam1:λ 1" "sweep-d$d-rho0.1-lam10:λ 10" "sweep-d$d-rho0.1-lam100:λ 100"
	panel "ρ 0.6, by size ratio (Fig. 2.12)" "$def" \
		"sweep-d$d-rho0.6-lam1:λ 1" "sweep-d$d-rho0.6-lam10:λ 10" "sweep-d$d-rho0.6-lam100:λ 100"
	[ "$npanel" -gt 0 ] || return 0
	what=$([ "$d" = 2 ] && echo disks || echo spheres)
	cat >> "$gp" <<-EOF
	set terminal pngcairo size $((480 * npanel + 60)),460 font "sans,10"
	set output "$png/cellsize-${d}d.png"
	set multiplot layout 1,$npanel title "D-cell: warm detection time (per step of a time loop) against cell size, $N1M $what, URD (dashed: the default, $def)" font "sans,12"
	set logscale x 2
	set xtics ("0.5" 0.5, "0.75" 0.75, "1" 1, "1.5" 1.5, "2" 2, "3" 3, "4" 4, "5" 5, "6" 6, "8" 8)
	set xlabel "cell size / mean object size"
	set ylabel "ns per object (warm)"
	set xrange [0.45:9]
	set yrange [0:*]
	set offsets 0, 0, graph 0.15, 0
	set key top center horizontal
	set grid
	EOF
	cat "$gp.panels" >> "$gp"
	printf 'unset multiplot\nreset\n' >> "$gp"
}

# scaleline DIM RHO COLOUR - ours warm (solid), ours cold (dotted) and the
# thesis's (dashed) for one density
scaleline() {
	o=$dat/scale-d$1-rho$2-ours.dat t=$dat/scale-d$1-rho$2-thesis.dat
	[ -s "$o" ] && scmd="$scmd${scmd:+, }'$o' using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb '$3' title 'ρ $2'"
	[ -s "$o" ] && scmd="$scmd${scmd:+, }'$o' using 1:3 with linespoints dashtype 3 pointtype 1 linecolor rgb '$3' notitle"
	[ -s "$t" ] && scmd="$scmd${scmd:+, }'$t' using 1:2 with linespoints dashtype 2 pointtype 6 linecolor rgb '$3' notitle"
	return 0
}

printf 'set encoding utf8\n' > "$gp"
sweepplot 2 3
sweepplot 3 2
cat >> "$gp" <<EOF
set terminal pngcairo size 1100,460 font "sans,10"
set output "$png/scale.png"
set multiplot layout 1,2 title "D-cell: detection time against the number of objects, λ 1, URD\nsolid, filled: ours warm (per step of a time loop); dotted: ours cold (first call); dashed, open: thesis on an Athlon 1.4 GHz" font "sans,11"
set xlabel "objects (millions)"
set ylabel "seconds"
set xrange [0:*]
set yrange [0:*]
set key outside right top
set grid
EOF
for d in 2 3; do
	scmd=""
	scaleline "$d" 0.1 "#1f77b4"
	scaleline "$d" 0.2 "#2ca02c"
	scaleline "$d" 0.3 "#ff7f0e"
	scaleline "$d" 0.6 "#d62728"
	title=$([ "$d" = 2 ] && echo "disks (Tables 2.3-2.5)" || echo "spheres (Tables 2.6-2.7)")
	printf 'set title "%s"\nplot %s\n' "$title" "${scmd:-NaN notitle}" >> "$gp"
done
printf 'unset multiplot\n' >> "$gp"
gnuplot "$gp"
