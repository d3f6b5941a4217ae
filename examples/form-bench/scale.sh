#!/bin/sh
# scale.sh DEMFORM PROFILE SCENE OUTDIR SIZE... - demform on the strip of
# SCENE (strip.yaml) with SIZE mm elements in plane and 16 layers, for each
# SIZE, under each BLAS of $BLAS (Debian's OpenBLAS builds, chosen by
# LD_LIBRARY_PATH: serial, pthread, openmp) and thread count: one line per
# run, tab-separated,
#
#   size blas threads equations elements factor_nnz assemble_s factor_s
#   solve_s wall_s cpu_s rss_mb load
#
# wall_s and rss_mb are GNU time's (the whole process), the rest demform's
# own cost line; load is the 1-minute load average before the run.  The
# variants of one size run one after the other, so that their ratio is
# from one run.  BLAS (default "serial:1 pthread:1 pthread:2 openmp:2") is
# a list of LIB:THREADS.
set -eu
here=$(dirname "$0")
. "$here/../lib.sh"
demform=$1 profile=$2 scene=$3 out=$4
shift 4
blas=${BLAS:-serial:1 pthread:1 pthread:2 openmp:2}
libdir=/usr/lib/x86_64-linux-gnu
for v in $blas; do
	[ -f "$libdir/openblas-${v%:*}/libblas.so.3" ] || {
		echo "scale.sh: no $libdir/openblas-${v%:*} (apt-get install libopenblas0-${v%:*})" >&2; exit 1; }
done
mkdir -p "$out"
printf '# size\tblas\tthreads\tequations\telements\tfactor_nnz\tassemble_s\tfactor_s\tsolve_s\twall_s\tcpu_s\trss_mb\tload\n'
for h in "$@"; do
	sed "s/element: 5 mm, layers: 15/element: $h mm, layers: 16/" "$scene" > "$out/strip$h.yaml"
	grep -q "element: $h mm, layers: 16" "$out/strip$h.yaml" ||
		{ echo "scale.sh: $scene has no 'element: 5 mm, layers: 15'" >&2; exit 1; }
	for v in $blas; do
		lib=${v%:*} t=${v#*:}
		err=$out/strip$h-$lib-$t.err
		load=$(loadavg)
		/usr/bin/time -f 'time: wall_s=%e rss_kb=%M' env LD_LIBRARY_PATH="$libdir/openblas-$lib" \
			OMP_NUM_THREADS="$t" OPENBLAS_NUM_THREADS="$t" \
			"$demform" -q -s "$out/strip$h.yaml" -o "$out/strip$h-$lib-$t.sum" "$profile" 2>"$err" ||
			{ cat "$err" >&2; exit 1; }
		tm=$(grep '^time: ' "$err" | tail -n 1)
		printf '%s\t%s\t%s\t%s\t%s\n' "$h" "$lib" "$t" \
			"$(cost_field "$err" equations elements factor_nnz assemble_s factor_s solve_s)" \
			"$(echo "$tm" | awk -v c="$(cost_field "$err" cpu_s)" -v l="$load" '{ split($2, w, "="); split($3, r, "="); printf "%s\t%s\t%.1f\t%s", w[2], c, r[2] / 1024, l }')"
	done
done
