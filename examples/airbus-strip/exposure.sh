#!/bin/sh
# exposure.sh SHOTS [SIDE_M SHOTS_REF] - the exposure of one pass of a shot
# stream (dempack shots) in reference passes: the shots a pass puts on a
# unit of area over those of one reference pass, SHOTS_REF shots on a
# SIDE_M x SIDE_M square (metres).  The default reference is Ch. 8.6.1's,
# 16 shots on the 5.6 x 5.6 mm area (examples/airbus-strip: its grid gives
# 1, its random scenes' 8 a pass 0.5); examples/almen passes its own,
# 4 shots on the 1.68 mm tile.  Read from the stream's header (method:
# per_pass=; area: x0 y0 x1 y1 in m).
set -eu
side=${2:-5.6e-3} ref=${3:-16}
awk -v side="$side" -v ref="$ref" '$1 == "#" && $2 == "method" { for (i = 3; i <= NF; i++) if ($i ~ /^per_pass=/) { sub(/^per_pass=/, "", $i); n = $i } }
	$1 == "#" && $2 == "area" { a = ($5 - $3) * ($6 - $4) }
	$1 == "#" && $2 == "data" { exit }
	END { if (!(n > 0) || !(a > 0)) { print "exposure.sh: no per_pass or area in the header of " FILENAME > "/dev/stderr"; exit 1 }
		printf "%.10g\n", n / a * (side * side) / ref }' "$1"
