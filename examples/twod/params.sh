#!/bin/sh
# params.sh OUT NAME - the model of run NAME in SI units, for report.sh and
# duration.sh: one line "R v t E m alpha sigma_max rho" (the disk's radius
# and speed from shot.txt; from the resolved scene OUT/NAME.yaml, demshot
# --dump-scene: the slab's thickness, Young's modulus, the law's exponent
# and our alpha, the last flow stress of the hardening table, the disk's
# density).
set -e
here=$(dirname "$0")
bin=${BIN:-$here/../../bin}
{
	awk '!/^#/ { print "R", $5; print "v", sqrt($6^2 + $8^2); exit }' "$here/shot.txt"
	"$bin"/demshot -s "$1/$2.yaml" --dump-scene | awk '
		/^[a-z]/ { sec = $1 }
		sec == "material:" && $1 == "E:" { print "E", $2 }
		sec == "material:" && $1 == "stress:" { gsub(/[][,]/, " "); print "sigma_max", $(NF - 1) }
		sec == "block:" && $1 == "thickness:" { print "t", $2 }
		sec == "contact:" && $1 == "m:" { print "m", $2 }
		sec == "contact:" && $1 == "alpha:" { print "alpha", $2 }
		sec == "shot:" && $1 == "density:" { print "rho", $2 }'
} | awk '{ v[$1] = $2 } END { print v["R"], v["v"], v["t"], v["E"], v["m"], v["alpha"], v["sigma_max"], v["rho"] }'
