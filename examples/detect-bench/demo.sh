#!/bin/sh
# demo.sh DEMDETECT SCENE DATA - find the contact pairs of DATA (the scene's
# objects, packed by the Makefile) with each algorithm, and print one table:
# algorithm, pairs, detect seconds warm and cold, ns per object warm and cold,
# read seconds, peak memory.
# Each algorithm runs in one process, `demdetect --repeat 5`: it reads the
# stream once, then detects 5 times with a reusable workspace.  Cold is the
# first call (it also faults fresh memory in); warm is the median of the other
# 4, the per-step cost of detection in a DE time loop.
set -eu
demdetect=$1 scene=$2 data=$3
repeat=5
err=$(mktemp)
trap 'rm -f "$err"' EXIT
first=$("$demdetect" -s "$scene" --dump-scene | awk '$1 == "algorithm:" { print $2 }')
seen=
dim=$(sed -n 's/^# dim //p' "$data" | head -n 1)
printf '%-9s %10s %8s %8s %8s %8s %8s %8s\n' algorithm pairs warm_s cold_s ns/obj_w ns/obj_c read_s rss_MB
# the scene's algorithm first, then the others (brute force is O(N^2): left out)
for algo in $first dcell scell nbs adt asdt; do
	case " $seen " in *" $algo "*) continue ;; esac
	seen="$seen $algo"
	[ "$algo" = nbs ] && [ "$dim" != 2 ] && continue
	OMP_NUM_THREADS=1 "$demdetect" -q -s "$scene" -a "$algo" --repeat "$repeat" -c "$data" >/dev/null 2>"$err" ||
		{ cat "$err" >&2; exit 1; }
	tail -n 1 "$err" | awk -v a="$algo" '{
		for (k = 1; k <= NF; k++) { eq = index($k, "="); if (eq) v[substr($k, 1, eq - 1)] = substr($k, eq + 1) }
		if (!("detect_warm_s" in v)) { print "demo.sh: no detect_warm_s: demdetect too old for --repeat" > "/dev/stderr"; exit 1 }
		w = v["detect_warm_s"]; c = v["detect_s"]; n = v["objects"]
		printf "%-9s %10d %8.3f %8.3f %8.0f %8.0f %8.3f %8.1f\n", a, v["pairs"], w, c,
			w / n * 1e9, c / n * 1e9, v["read_s"], v["rss_mb"] }'
done
echo "(one thread, one process per algorithm detecting $repeat times: cold is the first call,"
echo " warm the median of the other $((repeat - 1)) (the per-step cost in a time loop); read_s is"
echo " reading the stream; the targets and the thesis's times are in REPORT.md, made by 'make' here)"
