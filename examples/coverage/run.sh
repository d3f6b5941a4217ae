#!/bin/bash
# run.sh OUT - the plastic coverage of demprofile against the Avrami law
# (issue 25, acceptance 3), on the FE/DE model of examples/verification
# (Al 5052, Han 2004 Table 7.2; shot D = 0.28 mm at 50 m/s, normal to the
# surface; elements D/PER_D in the fine region; lengths in multiples of D).
#
#   1. the footprint radius a of one impact by the plastic threshold,
#      measured by footprint.sh (FOOTPRINT: its a.txt) on single impacts
#      at a grid of offsets in one element cell;
#   2. a random stream of independent impacts (dempack --pattern random
#      --per-pass 1: one shot a pass, so no separation within a pass skews
#      the positions from uniform) up to the impacts that the Avrami law
#      needs for 98 %, N98 = -ln(0.02) A / (pi a^2), A the impact area; the
#      plastic coverage of the profile region (the area less a margin of at
#      least a, so that every point of it sees impacts on all sides) after
#      every impact (demprofile --surface).
#
# Environment: BIN (../../bin), THREADS (demshot --threads, 1), PER_D (5),
# AREA_D (the side of the impact area in D, 8), SEED (1), D (0.28, mm),
# FOOTPRINT (footprint.sh's a.txt, required).
# Writes OUT/: scene.yaml, shots.txt, demshot.log, surface.txt (a row per
# pass: column 11 the plastic coverage); report.sh reads them.
set -eo pipefail
out=$1
here=$(cd "$(dirname "$0")" && pwd)
bin=$(cd "${BIN:-$here/../../bin}" && pwd)
seed=${SEED:-1}
footprint=$(cd "$(dirname "${FOOTPRINT:?run.sh: FOOTPRINT, the a.txt of footprint.sh, is not set}")" && pwd)/$(basename "$FOOTPRINT")
[ -s "$footprint" ] || { echo "run.sh: $footprint: missing (run footprint.sh first)" >&2; exit 1; }
mkdir -p "$out"
cd "$out"

. "$here/scene.sh"
scene 0 0 > scene.yaml

# 1. the footprint radius a of footprint.sh (FOOTPRINT, the file its
#    a.txt: the mean single-impact footprint over a stratified grid of
#    offsets in one element cell)
a=$(awk 'NR == 1 { print $1 }' "$footprint")
if ! awk -v a="$a" 'BEGIN { exit !(a > 0) }'; then
	echo "run.sh: $footprint: no footprint radius" >&2
	exit 3
fi
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
