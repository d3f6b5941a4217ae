#!/bin/sh
# form-run.sh OUT NAME - one demform run of the accuracy study on the strip
# of examples/form-bench (Ch. 8.6: Al 7050-T7651, 150 x 50 x 4 mm, layers
# graded by 1.2 toward the peened face; the made-up equi-biaxial profile of
# form-bench/profile.sh), NAME = ELEMENT-LAYERS-INCREMENTS-STRAIN, e.g.
# 5-15-1-small (form-bench's strip):
#
#   ELEMENT     in-plane element size, mm (plate.element)
#   LAYERS      layers through the thickness (plate.layers)
#   INCREMENTS  initial load increments (demform --increments)
#   STRAIN      small or large (demform --large)
#
# One thread (OpenMP, OpenBLAS).  A run shorter than SHORT seconds (default
# 10) is repeated until REPS runs (default 3).  Writes OUT/NAME.{yaml,sum,log}
# and OUT/NAME.row: name, element, layers, increments, strain, elements,
# equations, iterations, runs, median wall s, median cpu s, min and max wall
# s, load average before the first run, arc height (m), max deflection (m),
# curvature x (1/m).
set -e
out=$1 name=$2
here=$(dirname "$0")
. "$here/../lib.sh"
IFS=- read -r elem layers incr strain <<EOF
$name
EOF
[ -n "$strain" ] || { echo "form-run.sh: $name: expected ELEMENT-LAYERS-INCREMENTS-STRAIN" >&2; exit 2; }
bin=${BIN:-../../bin}
reps=${REPS:-3}
short=${SHORT:-10}
mkdir -p "$out"
prof=$out/strip.prof
[ -s "$prof" ] || sh "$here/../form-bench/profile.sh" > "$prof"
cat > "$out/$name.yaml" <<EOF
# examples/form-bench/strip.yaml with ELEMENT and LAYERS of the run
material: {E: 72 GPa, nu: 0.33, yield: 450 MPa, hardening: 120 MPa}
plate: {size: [150 mm, 50 mm, 4 mm], element: $elem mm, layers: $layers, grading: 1.2}
EOF
large=
case $strain in
small) ;;
large) large=--large ;;
*) echo "form-run.sh: $name: strain small or large, not '$strain'" >&2; exit 2 ;;
esac
load=$(loadavg)
: > "$out/$name.times"
i=0
while :; do
	i=$((i + 1))
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 "$bin"/demform -s "$out/$name.yaml" $large \
		--increments "$incr" -o "$out/$name.sum" "$prof" 2> "$out/$name.log"
	cost_field "$out/$name.log" wall_s cpu_s >> "$out/$name.times"
	wall=$(cost_field "$out/$name.log" wall_s)
	[ "$i" -lt "$reps" ] && awk -v w="$wall" -v s="$short" 'BEGIN { exit !(w < s) }' || break
done
set -- $(cost_field "$out/$name.log" elements equations iterations)
wmed=$(cut -f1 "$out/$name.times" | median)
cmed=$(cut -f2 "$out/$name.times" | median)
wmin=$(cut -f1 "$out/$name.times" | sort -g | head -n 1)
wmax=$(cut -f1 "$out/$name.times" | sort -g | tail -n 1)
res=$(awk '$1 == "arc_height:" { a = $2 } $1 == "max_deflection:" { d = $2 } $1 == "curvature_x:" { k = $2 }
	END { printf "%s\t%s\t%s", a, d, k }' "$out/$name.sum")
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$elem" "$layers" "$incr" \
	"$strain" "$1" "$2" "$3" "$i" "$wmed" "$cmed" "$wmin" "$wmax" "$load" "$res" > "$out/$name.row"
cat "$out/$name.row"
