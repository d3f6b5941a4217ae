#!/bin/sh
# demo.sh DEMDETECT SCENE DATA - find the contact pairs of DATA (the scene's
# objects, packed by the Makefile) with each algorithm, and print one table:
# algorithm, pairs, detect seconds, ns per object, read seconds, peak memory.
# Each algorithm runs once untimed, then 3 times; the table shows the medians.
set -eu
demdetect=$1 scene=$2 data=$3
err=$(mktemp)
trap 'rm -f "$err" "$err.all"' EXIT
first=$("$demdetect" -s "$scene" --dump-scene | awk '$1 == "algorithm:" { print $2 }')
seen=
dim=$(sed -n 's/^# dim //p' "$data" | head -n 1)
printf '%-9s %10s %10s %10s %8s %8s\n' algorithm pairs detect_s ns/object read_s rss_MB
# the scene's algorithm first, then the others (brute force is O(N^2): left out)
for algo in $first dcell scell nbs adt asdt; do
	case " $seen " in *" $algo "*) continue ;; esac
	seen="$seen $algo"
	[ "$algo" = nbs ] && [ "$dim" != 2 ] && continue
	: > "$err.all"
	for run in 0 1 2 3; do
		OMP_NUM_THREADS=1 "$demdetect" -q -s "$scene" -a "$algo" -c "$data" >/dev/null 2>"$err" ||
			{ cat "$err" >&2; exit 1; }
		[ "$run" = 0 ] || tail -n 1 "$err" >> "$err.all"
	done
	awk -v a="$algo" '{
		for (k = 1; k <= NF; k++) { eq = index($k, "="); if (eq) v[substr($k, 1, eq - 1)] = substr($k, eq + 1) }
		det[NR] = v["detect_s"] + 0; rd[NR] = v["read_s"] + 0
	}
	END {   # the run with the median detect_s (sort the runs by it)
		for (i = 1; i <= NR; i++) for (j = i + 1; j <= NR; j++)
			if (det[j] < det[i]) {
				t = det[i]; det[i] = det[j]; det[j] = t
				t = rd[i]; rd[i] = rd[j]; rd[j] = t
			}
		m = int((NR + 1) / 2)
		printf "%-9s %10d %10.3f %10.0f %8.3f %8.1f\n", a, v["pairs"], det[m],
			det[m] / v["objects"] * 1e9, rd[m], v["rss_mb"] }' "$err.all"
done
echo "(one thread, the median of 3 runs; detect_s is detection alone, read_s reading the"
echo " stream; the targets and the thesis's times are in REPORT.md, made by 'make' here)"
