#!/bin/sh
# report.sh OUT "VELOCITIES" "ROWS" "AT" - the sensitivity study's report
# (markdown, on standard output) from OUT/ROW/vV/{row.txt,h.txt,time.txt},
# and OUT/tornado.dat for tornado.gp.  Everything printed is read from the
# runs' outputs; nothing is typed in.
#
# For each row and velocity: the arc height after each n of AT (passes of
# the grid, or the same shots per area), the change from the second to the
# last n, the difference of the last from the reference row's (ref), and
# the wall seconds of the stages the row ran (a profile or form row reuses
# the reference's state or profile and counts only its own stages).
set -eu
out=$1 vels=$2 rows=$3 at=$4

set -- $at
na=$#
a2=$(eval echo "\${$((na - 1))}")
alast=$(eval echo "\${$na}")

for r in $rows; do
	for v in $vels; do
		for f in row.txt h.txt time.txt; do
			[ -s "$out/$r/v$v/$f" ] || { echo "report.sh: $out/$r/v$v/$f: missing" >&2; exit 1; }
		done
	done
done

# the reference's mesh, as run (the study's MESH)
v1=$(set -- $vels; echo $1)
mesh=$(awk '/^block:/ { b = 1 } b && /^  element:/ { print $2, $3; exit }' "$out/ref/v$v1/scene.yaml")
mu=$(awk '/^contact:/ { c = 1; next } /^[^ #]/ { c = 0 } c && /^  friction:/ { f = $2 } END { print f == "" ? "none" : f }' "$out/ref/v$v1/scene.yaml")
fdepth=$(awk '/^block:/ { b = 1 } b && /^  fine_depth:/ { print $2, $3; exit }' "$out/ref/v$v1/scene.yaml")

h() { # h ROW V N: the arc height after N
	awk -v n="$3" '$1 == n { print $2 }' "$out/$1/v$2/h.txt"
}

echo "# sensitivity: what moves the arc height (report of \`$out/\`)"
echo
echo "Written by report.sh from the runs in \`$out/\`: the reference scene"
echo "(base.yaml, examples/airbus-strip/quick.yaml as of 2026-12-03, with $mesh elements in the impact area, $fdepth deep,"
echo "Coulomb friction $mu between shot and block, demshot --accuracy coarse)"
echo "with one modelling choice changed a row, arc height in mm over the 150 mm"
echo "length of the free strip after n passes of 16 shots (n = $(echo $at | sed 's/ /, /g')),"
echo "at $(echo $vels | sed 's/ / and /') m/s."
echo "\"$a2 to $alast\" is the change of the arc height from n = $a2 to n = $alast;"
echo "\"vs ref\" the arc height after $alast against the reference row's."
echo "Wall time: the seconds of the stages the row ran (shot rows: dempack, demshot,"
echo "demprofile, demform; profile rows: demprofile and demform on the reference's"
echo "state; form rows: demform on the reference's profile), with demshot's steps."
echo

hdr="| group | choice | value | stage |" sep="|---|---|---|---|"
for v in $vels; do
	for n in $at; do hdr="$hdr h($n) $v |"; sep="$sep---|"; done
	hdr="$hdr $a2 to $alast |  vs ref | wall s (steps) |"; sep="$sep---|---|---|"
done
echo "$hdr"
echo "$sep"
: > "$out/tornado.dat.tmp"
for r in $rows; do
	IFS='|' read -r group choice value stage < "$out/$r/v$(set -- $vels; echo $1)/row.txt"
	line="| $group | $choice | $value | $stage |"
	tl="\"$choice: $value\""
	for v in $vels; do
		for n in $at; do line="$line $(h $r $v $n) |"; done
		hl=$(h $r $v $alast) h2=$(h $r $v $a2) hr=$(h ref $v $alast)
		read -r wall steps _ < "$out/$r/v$v/time.txt"
		d=$(awk -v a="$hl" -v b="$hr" 'BEGIN { printf "%+.1f", 100 * (a / b - 1) }')
		line="$line $(awk -v a="$hl" -v b="$h2" 'BEGIN { printf "%+.1f %%", 100 * (a / b - 1) }') |"
		line="$line $( [ $r = ref ] && echo - || echo "$d %") | $wall ($steps) |"
		tl="$tl $d"
	done
	echo "$line"
	[ $r = ref ] || echo "$tl" >> "$out/tornado.dat.tmp"
done
echo

# the tornado: rows by the largest |change| over the velocities
awk '{ m = 0; for (i = NF; i > 0 && $i ~ /^[-+0-9.]+$/; i--) { a = $i < 0 ? -$i : $i; if (a > m) m = a }
	print m "\t" $0 }' "$out/tornado.dat.tmp" | sort -g | cut -f2- > "$out/tornado.dat"
rm -f "$out/tornado.dat.tmp"

echo "## The choices that move the arc height most"
echo
echo "By the largest change of the arc height after $alast against the reference,"
echo "over the velocities (the noise row, a change of the time step, left out):"
echo
grep -v '^"time step factor' "$out/tornado.dat" | tail -n 3 | awk 'BEGIN { k = 0 } { lines[++k] = $0 } END {
	for (i = k; i >= 1; i--) {
		l = lines[i]; s = l; sub(/^"/, "", s); q = index(s, "\""); name = substr(s, 1, q - 1)
		rest = substr(s, q + 1); printf "%d. %s:%s %%\n", k - i + 1, name, rest
	} }' | sed 's/ \([-+][0-9.]*\)/ \1 %/g; s/ % %$/ %/'
echo
echo "(One number a velocity, in the order $(echo $vels | sed 's/ /, /') m/s.)"
echo
echo "![tornado](tornado.png)"
echo
echo "## Cost"
echo
total=$(for r in $rows; do for v in $vels; do cut -d' ' -f1 "$out/$r/v$v/time.txt"; done; done |
	awk '{ s += $1 } END { printf "%.0f", s }')
echo "The stages of all the rows took $total s of wall time in all (the sum over the"
echo "runs; with make -j2 two run at once).  demshot's cost lines per row are in"
echo "\`$out/ROW/vV/demshot.log\`."
span=$(for r in $rows; do for v in $vels; do cut -d' ' -f3,4 "$out/$r/v$v/time.txt"; done; done |
	awk 'NF == 2 { if (!n++ || $1 < a) a = $1; if ($2 > b) b = $2 } END { if (n) printf "%.0f", b - a }')
[ -z "$span" ] || echo "From the first row's start to the last row's end: $span s ($(awk -v s="$span" 'BEGIN { printf "%d min %d s", s / 60, s % 60 }'))."
