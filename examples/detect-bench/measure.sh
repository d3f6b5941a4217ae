#!/bin/sh
# measure.sh DEMDETECT REPS MAXS RUN DATA [WARMUP] - time `demdetect -c` on DATA
# and print its cost line (the last line of its stderr), once per run.
#
# WARMUP untimed runs (default 1) come first: on this VM the first run after a
# while pays for faulting fresh memory in and can be twice as slow.  Then REPS
# timed runs, stopping early once they have taken MAXS seconds, so a slow
# algorithm (ASDT on 1M spheres) is timed once or twice, not five times.
# RUN is the algorithm, with "-cF" for cell factor F: dcell, asdt, dcell-c1.5.
# One thread (OMP_NUM_THREADS=1): the targets are single-thread numbers.
set -eu
demdetect=$1 reps=$2 maxs=$3 run=$4 data=$5 warmup=${6:-1}
algo=${run%%-c*}
cell=
case $run in *-c*) cell="--cell ${run#*-c}" ;; esac
err=$(mktemp)
trap 'rm -f "$err"' EXIT
# which build of demdetect made these timings (the report warns on a mix)
echo "# binary $(cksum < "$demdetect" | awk '{ print $1 }')"
i=0
while [ "$i" -lt "$warmup" ]; do
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=1 "$demdetect" -q -a "$algo" $cell -c "$data" >/dev/null 2>&1 || true
	i=$((i + 1))
done
i=0 spent=0
while [ "$i" -lt "$reps" ]; do
	# shellcheck disable=SC2086 # cell is an option and its value
	if ! OMP_NUM_THREADS=1 "$demdetect" -q -a "$algo" $cell -c "$data" >/dev/null 2>"$err"; then
		cat "$err" >&2
		exit 1
	fi
	line=$(tail -n 1 "$err")
	case $line in
	*": cost: "*) ;;
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
