#!/bin/sh
# ccx-arc.sh INP DAT - the arc height of a CalculiX job written by ccx-inp.sh,
# from the displacements of set NARC in its .dat file, computed as demform
# computes it: w at the centre less the mean of w at the chord's ends, w the
# deflection of the mid-surface (the mean of the top and bottom nodes' uz).
# Prints "arc_height: VALUE" (m).  The node numbers come from the .inp's
# NARC set: centre bottom, centre top, -x end bottom, top, +x end bottom, top.
set -eu
inp=$1 dat=$2
awk '
FILENAME == ARGV[1] && /^\*NSET, NSET=NARC/ { want = 1; next }
FILENAME == ARGV[1] && want { gsub(/,/, " "); for (i = 1; i <= NF; i++) id[i] = $i; want = 0; next }
FILENAME == ARGV[2] && /displacements \(vx,vy,vz\) for set NARC/ { inset = 1; next }
FILENAME == ARGV[2] && inset && NF == 4 && $1 ~ /^[0-9]+$/ { uz[$1] = $4; seen++ }
FILENAME == ARGV[2] && inset && NF == 0 && seen { inset = 0 }
END {
	for (i = 1; i <= 6; i++)
		if (!(id[i] in uz)) { print "ccx-arc.sh: " ARGV[2] ": no displacement of node " id[i] > "/dev/stderr"; exit 1 }
	wc = (uz[id[1]] + uz[id[2]]) / 2
	wa = (uz[id[3]] + uz[id[4]]) / 2
	wb = (uz[id[5]] + uz[id[6]]) / 2
	printf "arc_height: %.9g\n", wc - (wa + wb) / 2
}' "$inp" "$dat"
