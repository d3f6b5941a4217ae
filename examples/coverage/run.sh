#!/bin/bash
# run.sh OUT - the plastic coverage of demprofile against the Avrami law
# (issue 25, acceptance 3), on the FE/DE model of examples/verification
# (Al 5052, Han 2004 Table 7.2; shot D = 0.28 mm at 50 m/s, normal to the
# surface; elements D/PER_D in the fine region; lengths in multiples of D).
#
#   1. one shot at the centre of the area, four times, the area moved by
#      fractions of an element: its footprint by the plastic threshold
#      (demprofile --surface, plastic share times the region's area, the
#      whole impact area), a = sqrt(mean footprint / pi);
#   2. a random stream of independent impacts (dempack --pattern random
#      --per-pass 1: one shot a pass, so no separation within a pass skews
#      the positions from uniform) up to the impacts that the Avrami law
#      needs for 98 %, N98 = -ln(0.02) A / (pi a^2), A the impact area; the
#      plastic coverage of the profile region (the area less a margin of at
#      least a, so that every point of it sees impacts on all sides) after
#      every impact (demprofile --surface).
#
# Environment: BIN (../../bin), THREADS (demshot --threads, 1), PER_D (5),
# AREA_D (the side of the impact area in D, 8), SEED (1), D (0.28, mm).
# Writes OUT/: scene.yaml, single.* (the single impact), shots.txt,
# demshot.log, surface.txt (a row per pass: column 11 the plastic
# coverage), a.txt (the footprint); report.sh reads them.
set -eo pipefail
out=$1
here=$(cd "$(dirname "$0")" && pwd)
bin=$(cd "${BIN:-$here/../../bin}" && pwd)
seed=${SEED:-1}
mkdir -p "$out"
cd "$out"

. "$here/scene.sh"
scene 0 0 > scene.yaml

# 1. one shot at the centre of the area, the area moved by 0, h/2 along x,
#    h/2 along both, h/4 along both (h the element): where an impact falls
#    on the grid changes the elements it covers.  Each footprint over the
#    whole area (margin 0); a from their mean.
: > single.surf
: > single.log
for off in "0 0" "0.5 0" "0.5 0.5" "0.25 0.25"; do
	set -- $off
	scene "$(awk -v f="$1" -v h="$h" 'BEGIN { print f * h }')" \
		"$(awk -v f="$2" -v h="$h" 'BEGIN { print f * h }')" > single.yaml
	"$bin"/dempack -s single.yaml shots --pattern grid --grid 1 --passes 1 --seed "$seed" -q 2>> single.log |
		"$bin"/demshot -s single.yaml --threads "$threads" -q -o single.state 2>> single.log
	"$bin"/demprofile -s single.yaml -q --margin 0 --surface single.tmp -o /dev/null single.state 2>> single.log
	# the table's header once, then a row per offset (in elements)
	awk -v o="$off" -v head="$([ -s single.surf ] && echo 0 || echo 1)" \
		'/^#/ { if (head) print; next } { print $0, "# offset", o }' single.tmp >> single.surf
done
rm -f single.state single.tmp single.yaml
# a = sqrt(mean footprint / pi), the footprint the plastic share times the
# region's area
awk '!/^#/ { n++; s += $11 * $10 } END {
	a = n ? sqrt(s / n / 3.141592653589793) : 0
	if (!(a > 0)) { print "run.sh: the single impact left no plastic footprint" > "/dev/stderr"; exit 3 }
	printf "%.9g\n", a }' single.surf > a.txt
a=$(cat a.txt)
if ! awk -v a="$a" -v m="$margin" 'BEGIN { exit !(a <= m * 1e-3) }'; then
	echo "run.sh: the footprint radius $a m is larger than the margin $margin mm" >&2
	exit 3
fi

# 2. the impacts the Avrami law needs for 98 %, one a pass
n98=$(awk -v a="$a" -v s="$area" 'BEGIN { A = (s * 1e-3)^2; n = -log(0.02) * A / (3.141592653589793 * a * a); printf "%d\n", n == int(n) ? n : int(n) + 1 }')
"$bin"/dempack -s scene.yaml shots --pattern random --per-pass 1 --passes "$n98" --seed "$seed" \
		-o shots.txt 2> dempack.log
"$bin"/demshot -s scene.yaml --threads "$threads" shots.txt 2> demshot.log |
	"$bin"/demprofile -s scene.yaml -q --surface surface.txt -o profile.txt 2> demprofile.log
