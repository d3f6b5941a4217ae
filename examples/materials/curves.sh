#!/bin/sh
# curves.sh DIR PNG - the uniaxial curves of the library materials
# (DIR/NAME.tsv from curve.c): monotonic tension on the left, the first
# strain cycles of +-1 % on the right, one colour per material.
set -eu
dir=$1 png=$2
plots1= plots2=
for f in "$dir"/*.tsv; do
	n=$(basename "$f" .tsv)
	plots1="$plots1${plots1:+, }'$f' using 1:(\$4 == 0 ? \$2 : 1/0) with lines title '$n'"
	plots2="$plots2${plots2:+, }'$f' using 1:(\$4 >= 1 ? \$2 : 1/0) with lines title '$n'"
done
gnuplot <<GP
set terminal pngcairo size 1400,600 font ',10'
set output '$png'
set multiplot layout 1,2 title 'share/materials: uniaxial stress (dem\\_mat\\_uniaxial, static)'
set xlabel 'axial strain'
set ylabel 'axial stress (MPa)'
set key left top font ',8'
set grid
set title 'monotonic tension'
set xrange [0:0.04]
plot $plots1
set title 'three cycles at +-1 % strain'
set xrange [-0.012:0.012]
set key outside right
set key left top font ',8'
plot $plots2
unset multiplot
GP
