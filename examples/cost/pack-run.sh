#!/bin/sh
# pack-run.sh OUT NAME - dempack compress runs of the accuracy study, NAME =
# MODE-TOLERANCE-SHAKES, e.g. relax-0.001-5 (the defaults):
#
#   MODE       relax (the default stages with the relaxation under gravity)
#              or thesis (Boxes 6.1-6.4 only: --no-relax)
#   TOLERANCE  tau of the energy test, Eq. 6.8 (--tolerance), written without
#              an exponent (0.0001, not 1e-4: "-" separates the fields)
#   SHAKES     shakes per round of Box 6.2 (--shakes)
#
# The case is the cube of examples/packing made smaller: mono-size spheres of
# 0.02 mm in the box BOX (default a 0.5 mm cube, about 2100 spheres).  One run
# per seed of SEEDS (default "1 2 3"): the density of one packing varies with
# the seed by about as much as some knobs change it.  Writes OUT/NAME-SEED.log
# and OUT/NAME.row: name, mode, tolerance, shakes, seeds, mean spheres, median
# wall s, median cpu s, min and max wall s, load average before the first
# run, mean density, half its range over the seeds, mean core density, half
# its range, mean compression iterations.
set -e
out=$1 name=$2
here=$(dirname "$0")
. "$here/../lib.sh"
IFS=- read -r mode tol shakes <<EOF
$name
EOF
[ -n "$shakes" ] || { echo "pack-run.sh: $name: expected MODE-TOLERANCE-SHAKES" >&2; exit 2; }
bin=${BIN:-../../bin}
seeds=${SEEDS:-1 2 3}
box=${BOX:-0:0:0:0.5mm:0.5mm:0.5mm}
case $mode in
relax) relax= ;;
thesis) relax=--no-relax ;;
*) echo "pack-run.sh: $name: mode relax or thesis, not '$mode'" >&2; exit 2 ;;
esac
mkdir -p "$out"
load=$(loadavg)
: > "$out/$name.seeds"
for s in $seeds; do
	"$bin"/dempack compress -q --box "$box" --rmin 0.02mm --law mono $relax --tolerance "$tol" \
		--shakes "$shakes" --seed "$s" -o "$out/$name-$s.txt" 2> "$out/$name-$s.log"
	cost_field "$out/$name-$s.log" wall_s cpu_s objects density density_core iterations >> "$out/$name.seeds"
	rm -f "$out/$name-$s.txt"
done
wmed=$(cut -f1 "$out/$name.seeds" | median)
cmed=$(cut -f2 "$out/$name.seeds" | median)
awk -F'\t' -v name="$name" -v mode="$mode" -v tol="$tol" -v shakes="$shakes" -v w="$wmed" -v c="$cmed" -v load="$load" '
	{ n++; wmin = (n == 1 || $1 < wmin) ? $1 : wmin; wmax = (n == 1 || $1 > wmax) ? $1 : wmax
	  o += $3; d += $4; dc += $5; it += $6
	  dlo = (n == 1 || $4 < dlo) ? $4 : dlo; dhi = (n == 1 || $4 > dhi) ? $4 : dhi
	  clo = (n == 1 || $5 < clo) ? $5 : clo; chi = (n == 1 || $5 > chi) ? $5 : chi }
	END { printf "%s\t%s\t%s\t%s\t%d\t%.0f\t%s\t%s\t%s\t%s\t%s\t%.5f\t%.5f\t%.5f\t%.5f\t%.0f\n", name, mode, tol, shakes, n,
	      o / n, w, c, wmin, wmax, load, d / n, (dhi - dlo) / 2, dc / n, (chi - clo) / 2, it / n }' \
	"$out/$name.seeds" > "$out/$name.row"
cat "$out/$name.row"
