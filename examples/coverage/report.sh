#!/bin/sh
# report.sh FOOT DIR... - the plastic coverage against the Avrami law
# (markdown), from footprint.sh's run in FOOT and run.sh's runs in DIR...
# (one seed each).  For each of the five levels of expected coverage C =
# 20, 40, 60, 80 and 98 %: the impacts the Avrami law needs,
# N = round(-ln(1 - C) A / (pi a^2)) (A the impact area, a the footprint
# radius of FOOT), and after N impacts
#  - Avrami: 1 - exp(-N pi a^2 / A), the prediction;
#  - E[discs]: 1 - (1 - pi a^2 / A)^N, the exact expected share covered
#    by N discs of radius a centred uniformly on A (every disc about a
#    point of the profile region lies inside A: the margin is at least a);
#  - discs: the share of the profile region within a of one of the N
#    impacts of the stream (a raster of a/10 cells): what footprints that
#    were discs of radius a would cover with these very impacts;
#  - FE: demprofile's plastic coverage after pass N - 1 (passes from 0).
# Over the seeds: the mean of FE - Avrami with its standard error, and the
# same with the positions' scatter taken out by the discs as a control
# variate, FE - discs + E[discs] - Avrami (unbiased: the discs' expectation
# is known exactly; its scatter is the seed's, not the model's).
# Also writes FOOT/../curve.txt: the means over the seeds after every
# impact (plot.gp).  Nothing typed in: every figure is read from the runs.
set -eu
[ $# -ge 2 ] || { echo "usage: report.sh FOOT DIR..." >&2; exit 2; }
foot=$1
shift
for f in a.txt single.surf; do
	[ -s "$foot/$f" ] || { echo "report.sh: $foot/$f: missing" >&2; exit 1; }
done
for d in "$@"; do
	for f in shots.txt surface.txt demshot.log; do
		[ -s "$d/$f" ] || { echo "report.sh: $d/$f: missing" >&2; exit 1; }
	done
done
a=$(awk 'NR == 1 { print $1 }' "$foot/a.txt")
tmp=$(mktemp -d "${TMPDIR:-/tmp}/coverage-report.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# one line a seed and impact count: dir seed N A avrami edisc disc fe, and
# a line a seed: "cost dir seed impacts wall elements region"
for d in "$@"; do
	awk -v dir="$d" -v a="$a" '
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
		cells = nx * ny; p = pi * a * a / A
		m = n < last ? n : last
		cov = 0
		for (N = 1; N <= m; N++) {
			cov += first[N]
			printf "%s %s %d %.9g %.9g %.9g %.9g %.9g\n", dir, seed, N, A, 1 - exp(-N * p), 1 - (1 - p)^N, cov / cells, P[N]
		}
		printf "cost %s %s %d %s %s %.9g %.9g %.9g\n", dir, seed, n, c["wall_s"], c["elements"], RX1 - RX0, RY1 - RY0, AX1 - AX0
	}' "$d/shots.txt" "$d/surface.txt" "$d/demshot.log" >> "$tmp/rows"
done

echo "# coverage: the plastic coverage of demprofile against the Avrami law"
echo
echo "Written by report.sh from the footprint in $foot and the $# runs in: $*."
echo
awk -v a="$a" '
/^#/ { next }
{ n++; f = $11 * $10 * 1e12; s += f; s2 += f * f; if (n == 1 || f < lo) lo = f; if (n == 1 || f > hi) hi = f }
END {
	m = s / n; se = n > 1 ? sqrt((s2 / n - m * m) / (n - 1)) : 0
	print "## The footprint of one impact"
	print ""
	printf "%d single impacts at a stratified grid of offsets in one element cell: plastic footprint %.0f um^2 on the mean (standard error %.0f, from %.0f to %.0f), a = sqrt(mean / pi) = %.1f um.\n\n", n, m, se, lo, hi, a * 1e6
}' "$foot/single.surf"

awk '$1 == "cost" { n++; w[n] = $5 + 0; imp = $4; el = $6; rx = $7; ry = $8; ax = $9 }
END {
	# median wall time of the seeds
	for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (w[j] < w[i]) { t = w[i]; w[i] = w[j]; w[j] = t }
	med = n % 2 ? w[(n + 1) / 2] : (w[n / 2] + w[n / 2 + 1]) / 2
	print "## The runs"
	print ""
	printf "%d seeds; impact area %.3f x %.3f mm, profile region %.3f x %.3f mm, %s elements; %d impacts a seed, one a pass; demshot wall time a seed: median %.0f s (from %.0f to %.0f).\n\n", n, ax * 1e3, ax * 1e3, rx * 1e3, ry * 1e3, el, imp, med, w[1], w[n]
}' "$tmp/rows"

# the five levels: the rows of each seed at N(C)
awk -v a="$a" '
$1 != "cost" { key = $1 SUBSEP $3; row[key] = $0; A = $4; dirs[$1] = $2; if (!($1 in ord)) { nd++; ord[$1] = nd; dir[nd] = $1 } }
$1 == "cost" && !($2 in ord) { nd++; ord[$2] = nd; dir[nd] = $2; dirs[$2] = $3 }
END {
	pi = 3.141592653589793
	split("0.2 0.4 0.6 0.8 0.98", L, " ")
	for (l = 1; l <= 5; l++) NL[l] = int(-log(1 - L[l]) * A / (pi * a * a) + 0.5)
	# per seed: FE - Avrami and FE - discs at each level
	for (t = 1; t <= 2; t++) {
		if (t == 1) print "## FE - Avrami, each seed (percentage points)"
		else print "## FE - discs, each seed (percentage points): the positions scatter cancelled"
		print ""
		printf "| seed |"; for (l = 1; l <= 5; l++) printf " %.0f %% (N %d) |", 100 * L[l], NL[l]; print ""
		printf "|---:|"; for (l = 1; l <= 5; l++) printf "---:|"; print ""
		for (i = 1; i <= nd; i++) {
			printf "| %s |", dirs[dir[i]]
			for (l = 1; l <= 5; l++) {
				k = dir[i] SUBSEP NL[l]
				if (!(k in row)) { printf " - |"; continue }
				split(row[k], r, " ")
				printf " %+.1f |", 100 * (r[8] - (t == 1 ? r[5] : r[7]))
			}
			print ""
		}
		print ""
	}
	print "## Over the seeds"
	print ""
	print "Means with their standard errors (sd / sqrt(seeds)), percentage points"
	print "in the last four columns.  raw: FE - Avrami.  positions: discs -"
	print "E[discs], the scatter of the random impacts alone.  controlled: FE -"
	print "discs + E[discs] - Avrami, the raw difference with that scatter taken"
	print "out (the same impacts drive the FE and the discs)."
	print ""
	print "| expected C | N | seeds | Avrami | E[discs] | discs | FE | raw | positions | FE - discs | controlled |"
	print "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
	for (l = 1; l <= 5; l++) {
		ns = 0; s1 = s2 = s3 = s4 = q1 = q2 = q3 = q4 = sd = sf = 0
		for (i = 1; i <= nd; i++) {
			k = dir[i] SUBSEP NL[l]
			if (!(k in row)) continue
			split(row[k], r, " ")
			ns++; av = r[5]; ed = r[6]; sd += r[7]; sf += r[8]
			x1 = r[8] - r[5]; x2 = r[7] - r[6]; x3 = r[8] - r[7]; x4 = r[8] - r[7] + r[6] - r[5]
			s1 += x1; q1 += x1 * x1; s2 += x2; q2 += x2 * x2; s3 += x3; q3 += x3 * x3; s4 += x4; q4 += x4 * x4
		}
		if (!ns) { printf "| %.0f %% | %d | 0 | | | | | | | | |\n", 100 * L[l], NL[l]; continue }
		printf "| %.0f %% | %d | %d | %.3f | %.3f | %.3f | %.3f | %s | %s | %s | %s |\n", 100 * L[l], NL[l], ns, av, ed, sd / ns, sf / ns,
			pm(s1, q1, ns), pm(s2, q2, ns), pm(s3, q3, ns), pm(s4, q4, ns)
	}
	print ""
}
function pm(s, q, n,   m, v) {
	m = s / n
	v = n > 1 ? (q / n - m * m) * n / (n - 1) : 0
	if (v < 0) v = 0
	return n > 1 ? sprintf("%+.1f +- %.1f", 100 * m, 100 * sqrt(v / n)) : sprintf("%+.1f", 100 * m)
}' "$tmp/rows"

# the mean curves over the seeds after every impact, for plot.gp:
# N  N/N98-ish exposure (N pi a^2 / A)  Avrami  E[discs]  mean discs  mean FE  seeds
awk -v a="$a" '$1 != "cost" { N = $3; A = $4; av[N] = $5; ed[N] = $6; di[N] += $7; fe[N] += $8; n[N]++; if (N > top) top = N }
END {
	print "# N  N pi a^2 / A  Avrami  E[discs]  discs  FE  seeds  (means over the seeds; report.sh)"
	for (N = 1; N <= top; N++) if (n[N])
		printf "%d %.6g %.6g %.6g %.6g %.6g %d\n", N, N * 3.141592653589793 * a * a / A, av[N], ed[N], di[N] / n[N], fe[N] / n[N], n[N]
}' "$tmp/rows" > "$foot/../curve.txt"

echo "FE - discs is the footprint's doing (elements covered whole, footprints"
echo "that are not discs, plastic strain that adds up between neighbouring"
echo "impacts); discs - E[discs] is the scatter of the random positions, which"
echo "shrinks as the region grows or the seeds add up.  E[discs] exceeds the"
echo "Avrami law by the fixed number of impacts (1 - x)^N < exp(-N x)."
