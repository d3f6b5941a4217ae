#!/bin/sh
# tests/layers.sh [ROOT] - the layers of lib/ run one way: every #include
# of a file in lib/FOLDER/ names a header of its own folder or of a folder
# on a lower line of LAYERS below.  Prints each include that points up (or
# sideways, or into a folder missing from the list) as FILE:LINE, and exits
# 1 when there is one; 0 and nothing printed when the layers hold.
# ROOT is the source tree (default: the one this script is in).
#
# This list is the one statement of the layer order (DESIGN.md "Layout"
# describes it); cmd/ and tests/ sit on top of all of it.
LAYERS='
core
mesh par
io contact detect
fe pack body
shot
'
# Within a folder: a front end and the header of its own .c.  No other
# file of the folder includes the front end: the algorithms build on the
# folder's shared types (detect/boxes.h), never on what dispatches to them.
FRONTS='
detect/detect.h detect/detect.c
'
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root" || exit 4
[ -d lib ] || { echo "layers.sh: no lib/ in $root" >&2; exit 4; }

# shellcheck disable=SC2086  # the file list is split on purpose
awk -v layers="$LAYERS" -v fronts="$FRONTS" '
BEGIN {
	n = split(layers, line, "\n")
	for (i = 1; i <= n; i++) {
		k = split(line[i], w, " ")
		if (k) rank_n++
		for (j = 1; j <= k; j++) rank[w[j]] = rank_n
		order = order (k ? (order == "" ? "" : " < ") line[i] : "")
	}
	n = split(fronts, line, "\n")
	for (i = 1; i <= n; i++)
		if (split(line[i], w, " ") == 2) front[w[1]] = w[2]
}
FNR == 1 {
	split(FILENAME, p, "/")
	folder = p[2]
	if (!(folder in rank)) {
		printf "%s: the folder %s is not in the layer order of tests/layers.sh\n", FILENAME, folder
		bad = 1
	}
}
/^[ \t]*#[ \t]*include[ \t]*["<][a-z_]+\/[a-z_0-9]+\.h[">]/ {
	h = $0
	sub(/^[^"<]*["<]/, "", h)
	sub(/[">].*$/, "", h)
	split(h, q, "/")
	to = q[1]
	if (!(to in rank))
		next            # a system header such as <gsl/gsl_errno.h>
	if (to == folder) {
		if ((h in front) && FILENAME != "lib/" front[h] && FILENAME != "lib/" h) {
			printf "%s:%d: includes its folder'"'"'s front end %s (only %s may)\n", FILENAME, FNR, h, front[h]
			bad = 1
		}
		next
	}
	if (folder in rank && rank[to] >= rank[folder]) {
		printf "%s:%d: includes %s: %s does not sit above %s (%s)\n", FILENAME, FNR, h, folder, to, order
		bad = 1
	}
}
END { exit bad }
' lib/*/*.c lib/*/*.h
