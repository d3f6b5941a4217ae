#!/bin/sh
# report.sh DEMDETECT OUT - write the report (Markdown, on stdout) from
# OUT/results.tsv and tables.tsv.  The other settings come from the
# environment, as the Makefile exports them: N1M N2M N5M FACTORS SWEEP2D
# SWEEP3D REPS REPEAT MAXS WARMUP SWEEPREPS.
set -eu
demdetect=$1 out=$2
# the data sets' sizes, for the I/O table
for f in "$out"/data/*; do
	[ -f "$f" ] && printf '%s\t%s\n' "${f##*/}" "$(wc -c < "$f")"
done > "$out/sizes.tsv"
cpu=$(awk -F': *' '/^model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null)
mem=$(awk '/^MemTotal/ { printf "%.0f GB RAM", $2 / 1048576 }' /proc/meminfo 2>/dev/null)
exec awk -f report.awk \
	-v n1m="$N1M" -v n2m="$N2M" -v n5m="$N5M" -v factors="$FACTORS" \
	-v sweep2="$SWEEP2D" -v sweep3="$SWEEP3D" -v reps="$REPS" -v maxs="$MAXS" -v warmup="$WARMUP" \
	-v repeat="$REPEAT" -v sweepreps="$SWEEPREPS" \
	-v date="$(date -u '+%Y-%m-%d %H:%M UTC')" -v cpu="${cpu:-unknown CPU}" \
	-v ncpu="$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?')" -v mem="${mem:-unknown RAM}" \
	-v version="$("$demdetect" --version 2>/dev/null | head -n 1)" \
	-v rev="$(git describe --always --dirty 2>/dev/null || echo 'no git')" \
	"$out/results.tsv" "$out/sizes.tsv" tables.tsv
