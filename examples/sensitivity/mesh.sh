#!/bin/sh
# mesh.sh A B - the rows' effects under two meshes: the "vs ref" columns
# of two reports of this study (report.sh's markdown, the same rows and
# velocities), side by side, row by row, with the reference's arc heights.
# Markdown on standard output.  make mesh runs it on REPORT-quick-0.1mm.md
# (0.1 mm) and the quick study of the reference without friction at
# 0.14 mm.
set -eu
a=$1 b=$2
for f in "$a" "$b"; do
	[ -s "$f" ] || { echo "mesh.sh: $f: missing" >&2; exit 1; }
done

# rows FILE: "group|choice|value" TAB the row's cells after the four names,
# for the table's body rows
rows() {
	awk -F'|' '/^\| (group|---)/ { next } /^\| / && NF > 8 {
		key = $2 "|" $3 "|" $4; gsub(/  +/, " ", key)
		rest = ""; for (i = 6; i < NF; i++) rest = rest "|" $i
		print key "\t" rest }' "$1"
}
# the velocities, from the header: "h(n) V" cells
vels=$(grep -m1 '^| group' "$a" | tr '|' '\n' | sed -n 's/^ h([0-9]*) \([0-9.]*\) $/\1/p' | uniq | tr '\n' ' ')
[ "$vels" = "$(grep -m1 '^| group' "$b" | tr '|' '\n' | sed -n 's/^ h([0-9]*) \([0-9.]*\) $/\1/p' | uniq | tr '\n' ' ')" ] ||
	{ echo "mesh.sh: $a and $b are not of the same velocities" >&2; exit 1; }
nv=$(echo $vels | wc -w)
echo "# sensitivity: the rows' effects under two meshes"
echo
echo "Written by mesh.sh from \`$a\` (A) and \`$b\` (B): each row's arc"
echo "height after the last n against its own reference (report.sh's \"vs ref\"; the"
echo "reference's row gives its arc height),"
echo "at $(echo $vels | sed 's/ $//; s/ / and /') m/s."
echo
hdr="| row |" sep="|---|"
for v in $vels; do hdr="$hdr A $v | B $v |"; sep="$sep---|---|"; done
echo "$hdr"
echo "$sep"
rows "$a" > "${TMPDIR:-/tmp}/mesh.a.$$"
rows "$b" > "${TMPDIR:-/tmp}/mesh.b.$$"
trap 'rm -f "${TMPDIR:-/tmp}/mesh.a.$$" "${TMPDIR:-/tmp}/mesh.b.$$"' EXIT
# each velocity's block of cells: h(n)..., change, vs ref, wall; "vs ref"
# is the last but one of each block
awk -F'\t' -v nv="$nv" 'NR == FNR { b[$1] = $2; next }
	($1 in b) {
		na = split($2, ca, "|"); nb = split(b[$1], cb, "|")
		k = (na - 1) / nv; name = $1; sub(/^ [^|]*\| /, "", name); gsub(/ \| /, ": ", name); gsub(/ *$/, "", name)
		line = "| " name " |"
		for (v = 1; v <= nv; v++) {
			i = v * k; x = ca[i]; y = cb[i]
			# the reference: its arc height (mm) instead of "-"
			if (x ~ /^ *- *$/) { x = ca[i - 2]; gsub(/ /, "", x); x = " h = " x " mm " }
			if (y ~ /^ *- *$/) { y = cb[i - 2]; gsub(/ /, "", y); y = " h = " y " mm " }
			line = line x "|" y "|"
		}
		print line }' "${TMPDIR:-/tmp}/mesh.b.$$" "${TMPDIR:-/tmp}/mesh.a.$$"
