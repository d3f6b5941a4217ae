#!/bin/sh
# peers.sh DEMFORM SCENE PROFILE INP DIR - form the plate of SCENE with
# demform, then the same job with CalculiX (ccx, from INP, written by
# ccx-inp.sh), one after the other in one run, and print one line per code:
#
#   ours wall_s=... rss_mb=... arc_height=... equations=... (demform's cost line)
#   ccx  wall_s=... rss_mb=... arc_height=... equations=... ccx_total_s=...
#
# wall_s is the whole process, timed here the same way for both (GNU time):
# reading the input, building, assembling, solving and writing.  One thread
# for both: OMP_NUM_THREADS=1 and OPENBLAS_NUM_THREADS=1, and for ccx the
# CCX_NPROC_* variables (its SPOOLES solver and its element loops).
# CalculiX works in DIR (it writes JOB.dat, JOB.frd, JOB.sta, ... there).
set -eu
demform=$1 scene=$2 profile=$3 inp=$4 dir=$5
job=$(basename "$inp" .inp)
[ -f "$dir/$job.inp" ] && [ "$dir/$job.inp" -ef "$inp" ] ||
	{ echo "peers.sh: $inp must be DIR/JOB.inp" >&2; exit 2; }
err=$(mktemp)
sum=$(mktemp)
trap 'rm -f "$err" "$sum"' EXIT
echo "# load $(cut -d' ' -f1 /proc/loadavg)"

# demform: its own cost line has the phases; GNU time the process's wall
# clock and peak memory, measured as for ccx
/usr/bin/time -f 'time: wall_s=%e rss_kb=%M' env OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
	"$demform" -q -s "$scene" -o "$sum" "$profile" 2>"$err" || { cat "$err" >&2; exit 1; }
arc=$(awk '$1 == "arc_height:" { print $2 }' "$sum" | tail -n 1)
# demform's own wall_s, cpu_s and rss_mb renamed self_*: the line's first
# wall_s and rss_mb are GNU time's, as for ccx
cost=$(grep ': cost: ' "$err" | tail -n 1 | sed 's/^[^:]*: cost: //; s/^wall_s=/self_wall_s=/; s/ cpu_s=/ self_cpu_s=/; s/ rss_mb=/ self_rss_mb=/')
tm=$(grep '^time: ' "$err" | tail -n 1)
echo "ours $(echo "$tm" | awk '{ split($2, w, "="); split($3, r, "="); printf "wall_s=%s rss_mb=%.1f", w[2], r[2] / 1024 }') arc_height=$arc $cost"

# ccx: one thread everywhere
(cd "$dir" && /usr/bin/time -f 'time: wall_s=%e rss_kb=%M' env OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
	CCX_NPROC_EQUATION_SOLVER=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_RESULTS=1 \
	ccx -i "$job" > "$job.log" 2>"$err") || { cat "$err" "$dir/$job.log" >&2; exit 1; }
grep -q 'Job finished' "$dir/$job.log" || { echo "peers.sh: ccx did not finish: see $dir/$job.log" >&2; exit 1; }
arc=$(sh "$(dirname "$0")/ccx-arc.sh" "$inp" "$dir/$job.dat" | awk '{ print $2 }')
neq=$(awk 'p { print $1; exit } /number of equations/ { p = 1 }' "$dir/$job.log")
total=$(awk '/Total CalculiX Time:/ { print $4 }' "$dir/$job.log")
tm=$(grep '^time: ' "$err" | tail -n 1)
echo "ccx $(echo "$tm" | awk '{ split($2, w, "="); split($3, r, "="); printf "wall_s=%s rss_mb=%.1f", w[2], r[2] / 1024 }') arc_height=$arc equations=$neq ccx_total_s=$total"
echo "# load $(cut -d' ' -f1 /proc/loadavg)"
