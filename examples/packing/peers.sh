#!/bin/sh
# peers.sh DEMPACK DIR "MU..." COMPRESS-OPTION... - fill a box with
# `dempack compress COMPRESS-OPTION...`, then pour as many spheres of the
# same size into the same box with LIGGGHTS (liggghts-in.sh), once per
# friction coefficient MU, all in one run, one process after the other, and
# print one line per code:
#
#   dempack wall_s=... rss_mb=... <bed.awk's figures> <dempack's cost line>
#   liggghts mu=... wall_s=... rss_mb=... steps=... ke=... ke_stop=... <bed.awk's figures>
#
# wall_s and rss_mb are the whole process, timed the same way for both (GNU
# time); one thread each (OMP_NUM_THREADS=1; LIGGGHTS runs on one MPI rank).
# Everything is written in DIR: dempack.txt, pour-muMU.in, its log and dump.
set -eu
dempack=$1 dir=$2 mus=$3
shift 3
here=$(dirname "$0")
err=$(mktemp)
trap 'rm -f "$err"' EXIT
mkdir -p "$dir"
echo "# load $(cut -d' ' -f1 /proc/loadavg)"

/usr/bin/time -f 'time: wall_s=%e rss_kb=%M' env OMP_NUM_THREADS=1 \
	"$dempack" compress -q "$@" -o "$dir/dempack.txt" 2>"$err" || { cat "$err" >&2; exit 1; }
box=$(awk '/^# box / { print $3, $4, $5, $6, $7, $8; exit }' "$dir/dempack.txt")
cost=$(grep ': cost: ' "$err" | tail -n 1 | sed 's/^[^:]*: cost: //; s/^wall_s=/self_wall_s=/; s/ cpu_s=/ self_cpu_s=/; s/ rss_mb=/ self_rss_mb=/; s/ density/ self_density/g')
tm=$(grep '^time: ' "$err" | tail -n 1 | awk '{ split($2, w, "="); split($3, r, "="); printf "wall_s=%s rss_mb=%.1f", w[2], r[2] / 1024 }')
echo "dempack $tm $(awk -f "$here/bed.awk" -v box="$box" "$dir/dempack.txt") $cost"

for mu in $mus; do
	in=$dir/pour-mu$mu.in dump=pour-mu$mu.dump log=pour-mu$mu.log
	rm -f "$dir/$dump"
	sh "$here/liggghts-in.sh" "$dir/dempack.txt" "$mu" "$dump" > "$in"
	(cd "$dir" && /usr/bin/time -f 'time: wall_s=%e rss_kb=%M' env OMP_NUM_THREADS=1 \
		liggghts -in "${in##*/}" -log "$log" -echo none > "pour-mu$mu.out" 2>"$err") ||
		{ cat "$err" >&2; tail -n 20 "$dir/pour-mu$mu.out" >&2; exit 1; }
	[ -f "$dir/$dump" ] || { echo "peers.sh: LIGGGHTS wrote no $dir/$dump: see $dir/$log" >&2; exit 1; }
	tm=$(grep '^time: ' "$err" | tail -n 1 | awk '{ split($2, w, "="); split($3, r, "="); printf "wall_s=%s rss_mb=%.1f", w[2], r[2] / 1024 }')
	# the last thermo row (step atoms ke cpu) and the stop threshold of the script
	last=$(awk '$1 == "Step" { t = 1; next } t && $1 ~ /^[0-9]+$/ && NF == 4 { s = $1; k = $3 } END { print "steps=" s, "ke=" k }' "$dir/$log")
	stop=$(sed -n 's/^if "${ke} < \([^"]*\)".*/\1/p' "$in")
	echo "liggghts mu=$mu $tm $last ke_stop=$stop $(awk -f "$here/bed.awk" -v box="$box" "$dir/$dump")"
done
echo "# load $(cut -d' ' -f1 /proc/loadavg)"
