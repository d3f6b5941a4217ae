#!/bin/sh
# run.sh OUT ROW - one row of the scale runs (issue 21, item 3) into
# OUT/ROW.txt: the cost lines of the programs it ran (wall and CPU time,
# peak resident memory, objects, pairs) and, for the large stream, its size.
#
#   disks2d    10^7 disks (rho 0.6, lambda 1), dempack random -b | demdetect -c
#   spheres3d  10^7 spheres, the same
#   big        a text stream of N2 disks (BIG, default 115 000 000: over
#              4 GiB) written to OUT/big-stream.txt by dempack (removed after), read back by
#              demdetect -c; the same set (same seed) through a binary pipe
#              must give the same pair count
#
# Environment: BIN (the programs), N (the 10^7 rows' count), BIG.
set -eu
out=$1 row=$2
BIN=${BIN:-../../bin}
N=${N:-10000000}
BIG=${BIG:-115000000}
mkdir -p "$out"
log=$out/$row.log
: > "$log"
case $row in
disks2d | spheres3d)
	dim=2
	[ "$row" = spheres3d ] && dim=3
	"$BIN/dempack" random --dim "$dim" -n "$N" --seed 1 -b 2>> "$log" | "$BIN/demdetect" -c 2>> "$log" > "$out/$row.pairs"
	;;
big)
	"$BIN/dempack" random -n "$BIG" --seed 1 -o "$out/big-stream.txt" 2>> "$log"
	echo "stream_bytes=$(stat -c %s "$out/big-stream.txt")" >> "$log"
	"$BIN/demdetect" -c "$out/big-stream.txt" 2>> "$log" > "$out/$row.pairs"
	"$BIN/dempack" random -n "$BIG" --seed 1 -b 2> /dev/null | "$BIN/demdetect" -c 2> /dev/null > "$out/$row.binpairs"
	rm -f "$out/big-stream.txt"
	;;
*)
	echo "run.sh: unknown row '$row'" >&2
	exit 2
	;;
esac
grep -h 'cost:\|^stream_bytes' "$log" > "$out/$row.txt"
