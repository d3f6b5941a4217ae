#!/bin/sh
# report.sh DIR... - the plastic coverage against the Avrami law (markdown),
# from the runs of run.sh in DIR... (one seed each).  For each of the five
# levels of expected coverage C = 20, 40, 60, 80 and 98 %: the impacts the
# Avrami law needs, N = round(-ln(1 - C) A / (pi a^2)) (A the impact area,
# a the single impact's footprint radius), and after N impacts
#  - Avrami: 1 - exp(-N pi a^2 / A), the expected covered share;
#  - discs: the share of the profile region within a of one of the N
#    impacts of the stream (a raster of a/10 cells): what footprints that
#    were discs of radius a would cover with these very impacts, so that
#    discs - Avrami is the scatter of the random positions alone;
#  - FE: demprofile's plastic coverage after pass N - 1 (passes from 0).
# Nothing typed in: every figure is read from the runs' files.
set -eu
[ $# -ge 1 ] || { echo "usage: report.sh DIR..." >&2; exit 2; }
for d in "$@"; do
	for f in a.txt shots.txt surface.txt single.surf demshot.log; do
		[ -s "$d/$f" ] || { echo "report.sh: $d/$f: missing" >&2; exit 1; }
	done
done

echo "# coverage: the plastic coverage of demprofile against the Avrami law"
echo
echo "Written by report.sh from the runs in: $*."
echo
for d in "$@"; do
	awk -v dir="$d" -v a="$(cat "$d/a.txt")" '
	FILENAME ~ /shots\.txt$/ && /^# area / { AX0 = $3; AY0 = $4; AX1 = $5; AY1 = $6; next }
	FILENAME ~ /shots\.txt$/ && /^# seed / { seed = $3; next }
	FILENAME ~ /shots\.txt$/ && !/^#/ { n++; X[n] = $3; Y[n] = $4; next }
	FILENAME ~ /surface\.txt$/ && /^# region / { RX0 = $3; RY0 = $4; RX1 = $5; RY1 = $6; next }
	FILENAME ~ /surface\.txt$/ && !/^#/ { P[$1 + 1] = $11; last = $1 + 1; next }
	FILENAME ~ /demshot\.log$/ && /^demshot: cost: / { for (i = 3; i <= NF; i++) { split($i, kv, "="); c[kv[1]] = kv[2] } }
	END {
		pi = 3.141592653589793
		A = (AX1 - AX0) * (AY1 - AY0)
		# the first impact within a of each raster cell of the region
		h = a / 10; nx = int((RX1 - RX0) / h + 0.5); ny = int((RY1 - RY0) / h + 0.5)
		for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
			x = RX0 + (i + 0.5) * (RX1 - RX0) / nx; y = RY0 + (j + 0.5) * (RY1 - RY0) / ny
			f = n + 1
			for (k = 1; k < f; k++) if ((x - X[k])^2 + (y - Y[k])^2 < a * a) f = k
			first[f]++
		}
		cells = nx * ny
		printf "## seed %s (%s)\n\n", seed, dir
		printf "Impact area %.3f x %.3f mm, profile region %.3f x %.3f mm; single impact footprint radius a = %.1f um (plastic strain above the threshold); %d impacts, one a pass; demshot %s s wall, %s elements.\n\n", \
			(AX1 - AX0) * 1e3, (AY1 - AY0) * 1e3, (RX1 - RX0) * 1e3, (RY1 - RY0) * 1e3, a * 1e6, n, c["wall_s"], c["elements"]
		print "| expected C | impacts N | Avrami | discs | FE | FE - Avrami | FE - discs |"
		print "|---:|---:|---:|---:|---:|---:|---:|"
		split("0.2 0.4 0.6 0.8 0.98", L, " ")
		for (l = 1; l <= 5; l++) {
			N = int(-log(1 - L[l]) * A / (pi * a * a) + 0.5)
			if (N > last || N > n) { printf "| %.0f %% | %d | - | - | - (the run has %d passes) | | |\n", 100 * L[l], N, last; continue }
			av = 1 - exp(-N * pi * a * a / A)
			cov = 0; for (k = 1; k <= N; k++) cov += first[k]; disc = cov / cells
			fe = P[N]
			printf "| %.0f %% | %d | %.3f | %.3f | %.3f | %+.1f | %+.1f |\n", 100 * L[l], N, av, disc, fe, 100 * (fe - av), 100 * (fe - disc)
			print dir, L[l], N, av, disc, fe > "/dev/stderr"
		}
		print ""
	}' "$d/shots.txt" "$d/surface.txt" "$d/demshot.log" 2>> "${TMPDIR:-/tmp}/coverage-report.$$"
done
if [ $# -gt 1 ]; then
	echo "## Mean over the $# seeds"
	echo
	echo "| expected C | Avrami | discs | FE | FE - Avrami | FE - discs |"
	echo "|---:|---:|---:|---:|---:|---:|"
	awk '{ k = $2; n[k]++; av[k] += $4; di[k] += $5; fe[k] += $6 }
	END { split("0.2 0.4 0.6 0.8 0.98", L, " ")
		for (l = 1; l <= 5; l++) { k = L[l]; if (!n[k]) continue
			printf "| %.0f %% | %.3f | %.3f | %.3f | %+.1f | %+.1f |\n", 100 * k, av[k] / n[k], di[k] / n[k], fe[k] / n[k], 100 * (fe[k] - av[k]) / n[k], 100 * (fe[k] - di[k]) / n[k] } }' \
		"${TMPDIR:-/tmp}/coverage-report.$$"
	echo
fi
rm -f "${TMPDIR:-/tmp}/coverage-report.$$"
echo "Percentage points in the last two columns.  FE - discs is the footprint's"
echo "doing (elements covered whole, footprints that are not discs of radius a,"
echo "impacts that change what an earlier one left); discs - Avrami is the"
echo "scatter of the random positions, which shrinks as the region grows."
