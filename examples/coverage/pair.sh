#!/bin/bash
# pair.sh OUT - do two impacts leave a larger plastic footprint than the
# two of them alone?  The Avrami law assumes they do not: a point is
# covered when one footprint covers it.  Plastic strain adds up, so a
# point that each impact alone strains by less than the threshold can pass
# it after both.
#
# On the model of run.sh (scene.sh): for each separation s (SEPS, in shot
# diameters D) two shots on the x axis, A at -s/2 in pass 0 and B at +s/2
# in pass 1, and B alone in a fresh block.  demprofile --surface over the
# whole impact area (margin 0) after each pass gives the footprints:
#
#   F_A   after pass 0 of the pair run (A alone, on a fresh block)
#   F_B   B alone
#   F_AB  after pass 1 of the pair run
#
# and the excess F_AB - F_A - F_B, which is 0 for independent footprints
# that do not overlap (for s over twice the footprint radius a: run.sh
# measures a = 0.56 D at D/5) and negative where they overlap.
#
# Writes OUT/pair.txt: s/D, F_A, F_B, F_AB (um^2), excess (um^2 and in
# per cent of F_A + F_B).
# Environment: BIN, THREADS (1), PER_D (5), AREA_D (8), D (0.28 mm),
# SEPS (the separations in D).
set -eo pipefail
out=$1
here=$(cd "$(dirname "$0")" && pwd)
bin=$(cd "${BIN:-$here/../../bin}" && pwd)
seps=${SEPS:-1.2 1.4 1.6 2 3}
mkdir -p "$out"
cd "$out"
. "$here/scene.sh"

# footprints FILE: the plastic footprint (um^2) after each pass of the
# surface table FILE, a line each
footprints() {
	awk '!/^#/ { printf "%.1f\n", $11 * $10 * 1e12 }' "$1"
}
# shot X: the stream of one shot at (X, 0) mm, pass 0
shot() {
	scene "$1" 0 > one.yaml
	"$bin"/dempack -s one.yaml shots --pattern grid --grid 1 --passes 1 -q
}

printf '# s/D F_A F_B F_AB excess excess%%  (footprints in um^2; demprofile --surface, threshold 0.002)\n' > pair.txt.tmp
for k in $seps; do
	s=$(awk -v k="$k" -v d="$d" 'BEGIN { printf "%.6g", k * d }')
	xa=$(awk -v s="$s" 'BEGIN { printf "%.6g", -s / 2 }')
	xb=$(awk -v s="$s" 'BEGIN { printf "%.6g", s / 2 }')
	# the streams take their header (the impact area, which demprofile
	# reads as its region) from a shot at the centre, their rows from A
	# and B
	shot 0 | sed -n '1,/^# data$/p' > head.shots
	rowa=$(shot "$xa" | sed -n '/^# data$/,/^# end/p' | sed '1d;$d')
	rowb=$(shot "$xb" | sed -n '/^# data$/,/^# end/p' | sed '1d;$d')
	{ cat head.shots; echo "$rowa"; echo "$rowb" | awk '{ $1 = 1; print }'; echo '# end 2'; } > ab.shots
	{ cat head.shots; echo "$rowb"; echo '# end 1'; } > b.shots
	scene 0 0 > pair.yaml
	for run in ab b; do
		"$bin"/demshot -s pair.yaml --threads "$threads" -q -o $run.state $run.shots
		"$bin"/demprofile -s pair.yaml -q --margin 0 --surface $run.surf -o /dev/null $run.state
	done
	{ footprints ab.surf | tr '\n' ' '; footprints b.surf; } |
		awk -v k="$k" '{ fa = $1; fab = $2; fb = $3; e = fab - fa - fb
			printf "%s %.1f %.1f %.1f %.1f %.2f\n", k, fa, fb, fab, e, 100 * e / (fa + fb) }' >> pair.txt.tmp
	rm -f ab.state b.state one.yaml head.shots
done
mv -f pair.txt.tmp pair.txt
cat pair.txt
