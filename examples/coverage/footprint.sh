#!/bin/bash
# footprint.sh OUT - the plastic footprint of one impact, averaged over
# where the impact falls on the element grid (issue 25, acceptance 3: a is
# "the radius of one impact's footprint by the same plastic-strain
# threshold, measured on a single impact of the same shot").
#
# demprofile counts a top-layer element whole when its mean plastic strain
# passes the threshold, so one impact's footprint is a set of elements and
# its area depends on the impact's offset from the grid (24, 26, 23 and 23
# elements at the four offsets run.sh used to take).  The Avrami law needs
# the footprint's mean over impacts uniform on the surface: for element
# counting, an element is hit by one impact with probability E[footprint]
# / A whatever the footprint's shape.  The fine mesh repeats with the
# element h, so the mean over uniform positions is the mean over offsets
# in one cell [0, h)^2; this takes it on a stratified grid of OFFSETS x
# OFFSETS offsets ((i + 1/2) h / OFFSETS, (j + 1/2) h / OFFSETS), one
# single-impact run each, on the scene of scene.sh (the same block, shot
# and threshold as the random streams).
#
# Writes OUT/single.surf (demprofile --surface's row per offset, the whole
# impact area, margin 0, "# offset fx fy" in elements at its end) and
# OUT/a.txt: a = sqrt(mean footprint / pi) in m, then the number of
# offsets, the mean footprint (m^2) and its standard error over offsets.
# Environment: BIN, THREADS (1), PER_D (5), AREA_D (8), D (0.28 mm),
# OFFSETS (8).
set -eo pipefail
out=$1
here=$(cd "$(dirname "$0")" && pwd)
bin=$(cd "${BIN:-$here/../../bin}" && pwd)
noff=${OFFSETS:-8}
mkdir -p "$out"
cd "$out"
. "$here/scene.sh"

: > single.surf.tmp
: > single.log
for j in $(seq 0 $((noff - 1))); do
	for i in $(seq 0 $((noff - 1))); do
		fx=$(awk -v i="$i" -v n="$noff" 'BEGIN { printf "%.6g", (i + 0.5) / n }')
		fy=$(awk -v i="$j" -v n="$noff" 'BEGIN { printf "%.6g", (i + 0.5) / n }')
		scene "$(awk -v f="$fx" -v h="$h" 'BEGIN { print f * h }')" \
			"$(awk -v f="$fy" -v h="$h" 'BEGIN { print f * h }')" > single.yaml
		"$bin"/dempack -s single.yaml shots --pattern grid --grid 1 --passes 1 -q 2>> single.log |
			"$bin"/demshot -s single.yaml --threads "$threads" -q -o single.state 2>> single.log
		"$bin"/demprofile -s single.yaml -q --margin 0 --surface single.tmp -o /dev/null single.state 2>> single.log
		# the table's header once, then a row per offset (in elements)
		awk -v o="$fx $fy" -v head="$([ -s single.surf.tmp ] && echo 0 || echo 1)" \
			'/^#/ { if (head) print; next } { print $0, "# offset", o }' single.tmp >> single.surf.tmp
	done
done
rm -f single.state single.tmp single.yaml
mv -f single.surf.tmp single.surf
# a = sqrt(mean footprint / pi), the footprint the plastic share times the
# region's area (column 10 the area, 11 the plastic share)
awk '!/^#/ { n++; f = $11 * $10; s += f; s2 += f * f } END {
	m = n ? s / n : 0
	if (!(m > 0)) { print "footprint.sh: the single impact left no plastic footprint" > "/dev/stderr"; exit 3 }
	se = n > 1 ? sqrt((s2 / n - m * m) * n / (n - 1) / n) : 0
	printf "%.9g %d %.9g %.9g\n", sqrt(m / 3.141592653589793), n, m, se }' single.surf > a.txt.tmp
mv -f a.txt.tmp a.txt
