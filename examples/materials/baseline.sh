#!/bin/sh
# baseline.sh BASE DIR - the explicit element loop of the linear law timed
# on the code of commit BASE (before the hardening laws) and on this
# checkout, in one run: examples/cost/fe-bench.c built against each
# library, the two binaries run alternately ROUNDS times (one-point and
# full integration, large strain, plastic and elastic, 1 thread), so that
# both see the same machine.  Writes fe-bench's TSV rows with a first
# column "code" (base or this) on stdout; DIR keeps the base build.
set -eu
base=$1 dir=$2
top=$(cd "$(dirname "$0")/../.." && pwd)
rounds=${ROUNDS:-3}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
if [ ! -f "$dir/src/lib/libdem.a" ]; then
	rm -rf "$dir/src"
	git -C "$top" worktree prune
	git -C "$top" worktree add --detach "$dir/src" "$base" >&2
	make -C "$dir/src" build -j2 >&2
fi
cflags="-std=c11 -O2 -D_POSIX_C_SOURCE=200809L -fopenmp"
libs="-lgsl -lgslcblas -lyaml -lz -lcholmod -lm"
cc $cflags -I"$dir/src/lib" "$top/examples/cost/fe-bench.c" "$dir/src/lib/libdem.a" $libs -o "$dir/fe-bench-base"
cc $cflags -I"$top/lib" "$top/examples/cost/fe-bench.c" "$top/lib/libdem.a" $libs -o "$dir/fe-bench-this"
cfg=1pt-large-plastic,full-large-plastic,1pt-large-elastic
first=1
i=0
while [ "$i" -lt "$rounds" ]; do
	for v in base this; do
		"$dir/fe-bench-$v" -n 40,40,25 -s 20 -r 5 -w 20 -t 1 -c "$cfg" > "$dir/$v.$i.tsv"
		if [ "$first" = 1 ]; then
			head -n 1 "$dir/$v.$i.tsv" | sed 's/^/code\tround\t/'
			first=0
		fi
		tail -n +2 "$dir/$v.$i.tsv" | sed "s/^/$v\t$i\t/"
	done
	i=$((i + 1))
done
