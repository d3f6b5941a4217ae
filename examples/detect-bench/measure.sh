#!/bin/sh
# measure.sh DEMDETECT REPS MAXS RUN DATA [WARMUP [REPEAT]] - time `demdetect -c`
# on DATA and print its cost line (the last line of its stderr), once per run.
#
# A run is one process, `demdetect --repeat REPEAT` (default 5): it reads DATA
# once and detects REPEAT times with a reusable workspace.  Its cost line gives
# detect_s, the first (cold) call, which pays for faulting fresh memory in, and
# detect_warm_s, the median of the REPEAT-1 later calls on warm buffers, the
# per-step cost of detection in a DE time loop.
#
# WARMUP untimed runs (default 0; each one detection, --repeat 1) come first.
# Then REPS timed runs, stopping early once they have taken MAXS seconds, so a
# slow algorithm (ASDT on 1M spheres) is run once or twice, not REPS times.
# RUN is the algorithm, with "-cF" for cell factor F: dcell, asdt, dcell-c1.5.
# One thread (OMP_NUM_THREADS=1): the targets are single-thread numbers.
set -eu
demdetect=$1 reps=$2 maxs=$3 run=$4 data=$5 warmup=${6:-0} repeat=${7:-5}
[ "$repeat" -ge 2 ] || { echo "measure.sh: REPEAT must be at least 2 (1 cold + warm calls)" >&2; exit 2; }
algo=${run%%-c*}
cell=
case $run in *-c*) cell="--cell ${run#*-c}" ;; esac
err=$(mktemp)
trap 'rm -f "$err"' EXIT
# which build of demdetect made these timings (the report warns on a mix)
echo "# binary $(cksum < "$demdetect" | awk '{ print $1 }')"
echo "# repeat $repeat"
i=0
while [ "$i" -lt "$warmup" ]; do
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=1 "$demdetect" -q -a "$algo" $cell --repeat 1 -c "$data" >/dev/null 2>&1 || true
	i=$((i + 1))
done
i=0 spent=0
while [ "$i" -lt "$reps" ]; do
	# shellcheck disable=SC2086 # cell is an option and its value
	if ! OMP_NUM_THREADS=1 "$demdetect" -q -a "$algo" $cell --repeat "$repeat" -c "$data" >/dev/null 2>"$err"; then
		cat "$err" >&2
		exit 1
	fi
	line=$(tail -n 1 "$err")
	case $line in
	*": cost: "*detect_warm_s=*) ;;
	*": cost: "*) echo "measure.sh: $data: no detect_warm_s in the cost line: is $demdetect too old for --repeat?" >&2; exit 1 ;;
	*) echo "measure.sh: $data: no cost line from $demdetect" >&2; exit 1 ;;
	esac
	echo "$line"
	i=$((i + 1))
	spent=$(echo "$line" | awk -v s="$spent" '{
		for (k = 1; k <= NF; k++) if ($k ~ /^wall_s=/) s += substr($k, 8)
		print s }')
	if awk -v s="$spent" -v m="$maxs" 'BEGIN { exit !(s > m) }'; then
		break
	fi
done
