#!/bin/sh
# fe-shot.sh OUT [H...] - Ch. 7.4's comparison of the rigid DE disk with an
# FE shot (issue 18): the scene of this folder (scene.yaml, shot.txt) run
# by demshot once with its rigid disk and once per H with the disk meshed
# as an elastic FE shot (shot.model: fe, E_s = 100 E, elements of H mm at
# its rim; feshot2d.h), each to the end of the impact (--pass-time 200us
# --steady 0.01, see README.md), and the residual profile of the centre
# line (demprofile --area 2mm:1mm) of each.
#
# Writes OUT/de.* and OUT/fe-H.* (the scene fe-H.yaml: scene.yaml with the
# shot keys added, so the two stay the same case; .forces the contact
# force history, .state, .profile, .log demshot's standard error with its
# cost line).  fe-shot-report.sh reads them.
set -e
out=$1
shift
[ -n "$out" ] || { echo "usage: fe-shot.sh OUT [H...]" >&2; exit 2; }
[ $# -gt 0 ] || set -- 1 0.5
here=$(cd "$(dirname "$0")" && pwd)
bin=${BIN:-$here/../../bin}
case $bin in /*) ;; *) bin=$(pwd)/$bin ;; esac
mkdir -p "$out"

# run NAME SCENE: demshot, then the centre line's profile
run() {
	echo "== fe-shot: $1 ($2)"
	"$bin/demshot" -s "$2" --pass-time 200us --steady 0.01 --forces "$out/$1.forces" \
		-o "$out/$1.state" "$here/shot.txt" 2> "$out/$1.log" ||
		{ cat "$out/$1.log" >&2; exit 1; }
	"$bin/demprofile" --area 2mm:1mm -o "$out/$1.profile" "$out/$1.state"
}

run de "$here/scene.yaml"
for h in "$@"; do
	# scene.yaml with the FE shot: its shot section gains the two keys
	awk -v h="$h" '{ print } /^shot:/ { print "  model: fe"; print "  element: " h " mm" }' \
		"$here/scene.yaml" > "$out/fe-$h.yaml"
	grep -q '^  model: fe' "$out/fe-$h.yaml" || { echo "fe-shot.sh: scene.yaml has no shot section" >&2; exit 1; }
	run "fe-$h" "$out/fe-$h.yaml"
done
