#!/bin/sh
# demo.sh DEMPACK DEMDETECT SCENE DIR - pack the scene's objects once (binary, in
# DIR), find their contact pairs with each algorithm, and print one table:
# algorithm, pairs, detect seconds, ns per object, read seconds, peak memory.
set -eu
dempack=$1 demdetect=$2 scene=$3 dir=$4
mkdir -p "$dir"
data=$dir/scene.bin
if [ ! -s "$data" ] || [ "$scene" -nt "$data" ] || [ "$dempack" -nt "$data" ]; then
	echo "demo: packing $scene into $data"
	"$dempack" random -q -s "$scene" --seed 1 -b -o "$data" 2>/dev/null
fi
err=$(mktemp)
trap 'rm -f "$err"' EXIT
first=$("$demdetect" -s "$scene" --dump-scene | awk '$1 == "algorithm:" { print $2 }')
seen=
dim=$(sed -n 's/^# dim //p' "$data" | head -n 1)
printf '%-9s %10s %10s %10s %8s %8s\n' algorithm pairs detect_s ns/object read_s rss_MB
# the scene's algorithm first, then the others (brute force is O(N^2): left out)
for algo in $first dcell scell nbs adt asdt; do
	case " $seen " in *" $algo "*) continue ;; esac
	seen="$seen $algo"
	[ "$algo" = nbs ] && [ "$dim" != 2 ] && continue
	OMP_NUM_THREADS=1 "$demdetect" -q -s "$scene" -a "$algo" -c "$data" >/dev/null 2>"$err" ||
		{ cat "$err" >&2; exit 1; }
	tail -n 1 "$err" | awk -v a="$algo" '{
		for (k = 1; k <= NF; k++) { eq = index($k, "="); if (eq) v[substr($k, 1, eq - 1)] = substr($k, eq + 1) }
		printf "%-9s %10d %10.3f %10.0f %8.3f %8.1f\n", a, v["pairs"], v["detect_s"],
			v["detect_s"] / v["objects"] * 1e9, v["read_s"], v["rss_mb"] }'
done
echo "(one thread; detect_s is detection alone, read_s the stream; the targets and the"
echo " thesis's times are in REPORT.md, made by 'make' in examples/detect-bench)"
