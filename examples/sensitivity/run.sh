#!/bin/sh
# run.sh ROW V OUT PASSES "AT" - one row of the sensitivity study at one
# velocity: the reference scene (base.yaml, airbus-strip's quick.yaml as
# the study ran it) with one modelling choice changed, through the pipeline
#
#   dempack shots | demshot | demprofile --pass all | demform --pass n (n in AT)
#
# into OUT/ROW/vV/: scene.yaml (the scene as run), row.txt (group, choice,
# value, stage), h.txt (n and the arc height in mm after n passes' worth of
# shots, n in AT), time.txt (the wall seconds of the stages this row ran,
# demshot's steps, and the start and end of the row in seconds since the
# epoch).  PASSES: the passes of the grid run (pack.passes).
#
# A row changes one stage: "shot" rows run every stage; "profile" rows
# take the reference's state stream (OUT/ref/vV/peen.state) and rerun
# demprofile and demform; "form" rows take the reference's profile
# (OUT/ref/vV/profile.txt) and rerun demform.  The cost of a row is that of
# the stages it runs.  Every value changed is written beside its source.
#
# Environment: BIN (the programs), THREADS (demshot's threads; empty: the
# scene's/all), SEED (dempack's; 1), MESH (the element size of the impact
# area in mm; 0.1, base.yaml's own), FRICTION (the reference's mu; 0,
# base.yaml's own).
set -eu
row=$1 v=$2 out=$3 passes=$4 at=$5
BIN=${BIN:-../../bin}
SEED=${SEED:-1}
MESH=${MESH:-0.1}
FRICTION=${FRICTION:-0}
base=base.yaml
d=$out/$row/v$v
ref=$out/ref/v$v
mkdir -p "$d"

# sub PATTERN REPLACEMENT: edit the one line of $d/scene.yaml that matches
# PATTERN (a whole line, sed BRE); fails unless exactly one line matches
sub() {
	n=$(grep -c "^$1\$" "$d/scene.yaml" || true)
	[ "$n" = 1 ] || { echo "run.sh: $row: '$1' matches $n lines of the scene" >&2; exit 1; }
	sed "s|^$1\$|$2|" "$d/scene.yaml" > "$d/scene.yaml.tmp"
	mv -f "$d/scene.yaml.tmp" "$d/scene.yaml"
}

sed "s/^  passes: 8\$/  passes: $passes/" "$base" > "$d/scene.yaml"
grep -q "^  passes: $passes\$" "$d/scene.yaml" || { echo "run.sh: no 'passes: 8' line in $base" >&2; exit 1; }
# the study's mesh (MESH, in mm): the element of the impact area and
# fine_depth, the whole number of its layers nearest quick.yaml's 0.6 mm
# (0.14 mm = d/10 for the 1.4 mm S550 shot, the largest element Ch. 7.5.4
# allows; 0.1 is quick.yaml itself).  The profile's margin (0.56 mm) is
# left as it is.
# the reference's friction (FRICTION, Coulomb mu between shot and
# block): 0.2 by the literature reading of README.md (Han 2004 Ch. 7.5.3:
# the residual stress grows with mu up to 0.2 and hardly beyond; Wu et
# al., Surface Engineering 2018, doi:10.1080/02670844.2018.1470817:
# accurate residual stresses need mu of 0.2 or more); quick.yaml, as
# Ch. 8.6 states none, has no friction (FRICTION=0 runs it so)
if [ "$FRICTION" != 0 ]; then
	sub '  alpha: 2' "  alpha: 2\\
  friction: $FRICTION"
fi
if [ "$MESH" != 0.1 ]; then
	sub '  element: 0.1 mm' "  element: $MESH mm"
	sub '  fine_depth: 0.6 mm' "  fine_depth: $(awk -v h="$MESH" 'BEGIN { n = int(0.6 / h + 0.5); printf "%.10g", n * h }') mm"
fi

stage=shot pack="" shot="" prof="" form="" k=1
case $row in
# reference: quick.yaml as it is (examples/airbus-strip/README.md gives the source of each value)
ref) group=reference; choice="quick.yaml"; value="as airbus-strip" ;;
# sample block sides (Ch. 8.6.1: fixed normally)
free) group=sides; choice="block sides"; value="free"
	sub '  bc: {xmin: normal, xmax: normal, ymin: normal, ymax: normal, bottom: fixed, top: free}' \
	    '  bc: {xmin: free, xmax: free, ymin: free, ymax: free, bottom: fixed, top: free}' ;;
periodic) group=sides; choice="block sides"; value="periodic x, y"
	sub '  bc: {xmin: normal, xmax: normal, ymin: normal, ymax: normal, bottom: fixed, top: free}' \
	    '  bc: {xmin: periodic, xmax: periodic, ymin: periodic, ymax: periodic, bottom: fixed, top: free}' ;;
# sample size and depth (Ch. 8.6.1: 8 x 8 x 4 mm)
size12) group=sample; choice="block size"; value="12 x 12 x 4 mm"
	sub '  size: \[8 mm, 8 mm, 4 mm\]' '  size: [12 mm, 12 mm, 4 mm]' ;;
depth2) group=sample; choice="block size"; value="8 x 8 x 2 mm"
	sub '  size: \[8 mm, 8 mm, 4 mm\]' '  size: [8 mm, 8 mm, 2 mm]' ;;
depth8) group=sample; choice="block size"; value="8 x 8 x 8 mm"
	sub '  size: \[8 mm, 8 mm, 4 mm\]' '  size: [8 mm, 8 mm, 8 mm]' ;;
# damping (Ch. 7.5: 0.05 "global damping") and the end of a pass
damp0) group=damping; choice="damping ratio"; value="0"; shot="--damping 0" ;;
damp02) group=damping; choice="damping ratio"; value="0.2"; shot="--damping 0.2" ;;
steady05) group=damping; choice="end of pass (run.steady)"; value="0.05 of peak KE"; shot="--steady 0.05" ;;
# contact law (Eq. 3.45; Ch. 7.5.2 recommends alpha 1 to 5)
alpha1) group=contact; choice="penalty alpha"; value="1"; sub '  alpha: 2' '  alpha: 1' ;;
alpha5) group=contact; choice="penalty alpha"; value="5"; sub '  alpha: 2' '  alpha: 5' ;;
linear) group=contact; choice="contact exponent m"; value="1 (linear)"; sub '  m: 1.5' '  m: 1' ;;
mu02) group=contact; choice="friction"; value="0.2"
	[ "$FRICTION" = 0 ] || { echo "run.sh: mu02: the reference has friction" >&2; exit 2; }
	sub '  alpha: 2' '  alpha: 2\
  friction: 0.2' ;;
mu0) group=contact; choice="friction"; value="0 (none)"
	[ "$FRICTION" != 0 ] || { echo "run.sh: mu0: the reference has no friction" >&2; exit 2; }
	sub "  friction: $FRICTION" '  friction: 0' ;;
mu05) group=contact; choice="friction"; value="0.5"
	[ "$FRICTION" != 0 ] || { echo "run.sh: mu05: the reference has no friction" >&2; exit 2; }
	sub "  friction: $FRICTION" '  friction: 0.5' ;;
# the noise floor: not a modelling choice but a change that should not
# matter, the explicit time step at 0.85 of the stable step instead of 0.9
# (demshot(1)); the passes' frames then differ by what the ringing block
# and the contact history make of a different step sequence
dtf085) group=noise; choice="time step factor (numerical)"; value="0.85 of stable"; shot="--dt-factor 0.85" ;;
# explicit stage
small) group=explicit; choice="strain (demshot)"; value="small"; shot="--strain small" ;;
full) group=explicit; choice="integration"; value="2x2x2 B-bar"; shot="--rule full" ;;
# shot pattern: random impacts, the same shots per unit area.  Random
# addition places about 8 shots a pass on the 5.6 mm square (dempack(1)),
# not the grid's 16, so it runs twice the passes of 8: pass 2n of the
# random run is the exposure of pass n of the grid
random) group=pattern; choice="impact positions"; value="random, 8 a pass"
	sub '  pattern: grid' '  pattern: random'
	sub '  grid: 4' '  per_pass: 8'
	sub "  passes: $passes" "  passes: $((2 * passes))"
	k=2 ;;
# profile (Ch. 8.4: element layers over the impacted region)
# (bins of the element size, 0.1 mm, hold one element layer each down to
# 0.6 mm and give the layers' profile to the digit: the row takes two)
bins) stage=profile; group=profile; choice="depth averaging"; value="0.2 mm bins"; prof="--bin-size 0.2mm" ;;
margin0) stage=profile; group=profile; choice="averaging area"; value="5.6 mm (impact area)"; prof="--margin 0" ;;
margin112) stage=profile; group=profile; choice="averaging area"; value="3.36 mm (margin 1.12)"; prof="--margin 1.12mm" ;;
# forming stage (Ch. 8.5, 8.6.2)
noep) stage=form; group=form; choice="initial state"; value="stress only (ep 0)" ;;
flarge) stage=form; group=form; choice="strain (demform)"; value="large"; form="--large" ;;
incr10) stage=form; group=strip; choice="load increments"; value="10"; form="--increments 10" ;;
grading1) stage=form; group=strip; choice="layer grading"; value="1.0 (uniform)"; sub '  grading: 1.2' '  grading: 1.0' ;;
elastic) stage=form; group=strip; choice="strip material"; value="elastic"
	sub '  yield: 450 MPa            # Ch. 8.6' ''
	sub '  hardening: 120 MPa        # Ch. 8.6, linear, per unit plastic strain' '' ;;
*) echo "run.sh: unknown row '$row'" >&2; exit 2 ;;
esac
printf '%s|%s|%s|%s\n' "$group" "$choice" "$value" "$stage" > "$d/row.txt"

now() { date +%s.%N; }
t0=$(now)
steps=-
if [ $stage = shot ]; then
	# shellcheck disable=SC2086
	"$BIN/dempack" -s "$d/scene.yaml" shots --speed "${v}m/s" --seed "$SEED" $pack -o "$d/shots.txt" 2> "$d/dempack.log"
	# shellcheck disable=SC2086
	"$BIN/demshot" -s "$d/scene.yaml" --accuracy coarse ${THREADS:+--threads $THREADS} $shot \
		-o "$d/peen.state" "$d/shots.txt" 2> "$d/demshot.log"
	state=$d/peen.state
	steps=$(sed -n 's/^demshot: cost: .* steps=\([0-9]*\).*/\1/p' "$d/demshot.log" | tail -n 1)
else
	state=$ref/peen.state
fi
if [ $stage = form ]; then
	profile=$ref/profile.txt
	if [ $row = noep ]; then
		# the same profile with the effective plastic strain set to 0:
		# demform then raises no history (stress only)
		col=$(grep -m1 '^# columns' "$profile" | tr ' ' '\n' | grep -n '^ep:' | cut -d: -f1)
		[ -n "$col" ] || { echo "run.sh: noep: no ep column in $profile" >&2; exit 1; }
		col=$((col - 2))
		awk -v c="$col" '/^#/ { print; next } { $c = 0; print }' "$profile" > "$d/profile.txt"
		profile=$d/profile.txt
	fi
else
	# shellcheck disable=SC2086
	"$BIN/demprofile" -s "$d/scene.yaml" --pass all $prof -o "$d/profile.txt" "$state" 2> "$d/demprofile.log"
	profile=$d/profile.txt
fi
: > "$d/demform.log"
: > "$d/h.txt.tmp"
for n in $at; do
	p=$((k * n - 1))
	# shellcheck disable=SC2086
	h=$("$BIN/demform" -s "$d/scene.yaml" -q --pass $p $form "$profile" 2>> "$d/demform.log" |
		awk '$1 == "arc_height:" { printf "%.4f", $2 * 1e3 }')
	[ -n "$h" ] || { echo "run.sh: $row v$v: demform gave no arc height for pass $p" >&2; exit 1; }
	echo "$n $h" >> "$d/h.txt.tmp"
done
t1=$(now)
awk -v a="$t0" -v b="$t1" -v s="$steps" 'BEGIN { printf "%.1f %s %.1f %.1f\n", b - a, s, a, b }' > "$d/time.txt"
mv -f "$d/h.txt.tmp" "$d/h.txt"
