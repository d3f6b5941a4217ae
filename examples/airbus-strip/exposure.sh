#!/bin/sh
# exposure.sh SHOTS - the exposure of one pass of a shot stream (dempack
# shots), in the thesis's passes: the shots a pass puts on a unit of area
# over those of one pass of Ch. 8.6.1, 16 shots on the 5.6 x 5.6 mm area.
# The grid of the thesis gives 1, the random scenes' 8 a pass 0.5.  Read
# from the stream's header (method: per_pass=; area: x0 y0 x1 y1 in m).
set -eu
awk '$1 == "#" && $2 == "method" { for (i = 3; i <= NF; i++) if ($i ~ /^per_pass=/) { sub(/^per_pass=/, "", $i); n = $i } }
	$1 == "#" && $2 == "area" { a = ($5 - $3) * ($6 - $4) }
	$1 == "#" && $2 == "data" { exit }
	END { if (!(n > 0) || !(a > 0)) { print "exposure.sh: no per_pass or area in the header of " FILENAME > "/dev/stderr"; exit 1 }
		printf "%.10g\n", n / a * (5.6e-3 * 5.6e-3) / 16 }' "$1"
