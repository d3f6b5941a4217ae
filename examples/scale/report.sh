#!/bin/sh
# report.sh OUT - REPORT.md of the scale runs from OUT/ROW.txt (run.sh).
set -eu
out=$1
key() { # key FILE PROGRAM KEY
	sed -n "s/^$2: cost: .*[ ]$3=\([^ ]*\).*/\1/p; s/^$2: cost: $3=\([^ ]*\).*/\1/p" "$1" | head -n 1
}
echo "# scale: 10^7 objects and a stream over 4 GiB (report of \`$out/\`)"
echo
echo "Written by report.sh from the cost lines of the runs (run.sh) on $(date '+%F')"
echo "($(nproc) cores, $(awk '/MemTotal/ { printf "%.1f", $2 / 1048576 }' /proc/meminfo) GiB of memory; load average at the end $(cut -d' ' -f1-3 /proc/loadavg))."
echo "Random sets of dempack (rho 0.6, lambda 1, seed 1), detection by demdetect's"
echo "default (D-cell), counting the pairs (-c)."
echo
echo "| run | objects | pairs | dempack wall s | dempack peak MB | demdetect wall s | demdetect peak MB | demdetect bytes per object | read s | detect s |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for r in disks2d spheres3d big; do
	f=$out/$r.txt
	[ -s "$f" ] || { echo "| $r | (not run) |||||||||"; continue; }
	obj=$(key "$f" demdetect objects)
	rss=$(key "$f" demdetect rss_mb)
	echo "| $r | $obj | $(key "$f" demdetect pairs) | $(key "$f" dempack wall_s) | $(key "$f" dempack rss_mb) | $(key "$f" demdetect wall_s) | $rss | $(awk -v m="$rss" -v n="$obj" 'BEGIN { printf "%.0f", m * 1048576 / n }') | $(key "$f" demdetect read_s) | $(key "$f" demdetect detect_s) |"
done
echo
if [ -s "$out/big.pairs" ]; then
	bytes=$(sed -n 's/^stream_bytes=//p' "$out/big.txt")
	echo "The large stream: $bytes bytes of text ($(awk -v b="$bytes" 'BEGIN { printf "%.2f", b / 2 ^ 30 }') GiB, 4 GiB = 4294967296),"
	echo "written by dempack and read back whole by demdetect (the reader checks the"
	echo "trailer's row count, a 64-bit integer, against the rows it read)."
	p1=$(cat "$out/big.pairs") p2=$(cat "$out/big.binpairs")
	echo "Pairs from the text file: $p1; from the same set through a binary pipe: $p2"
	if [ "$p1" = "$p2" ]; then echo "(equal)."; else echo "(**they differ**)."; fi
	echo
fi
echo "Peak memory: each program's resident set high-water mark (its cost line's"
echo "rss_mb, from getrusage), so dempack's is that of streaming its rows out and"
echo "demdetect's that of holding every object, its cells and the sort."
