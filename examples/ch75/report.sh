#!/bin/sh
# report.sh OUT H "HS" - the tables of REPORT.md from the runs' rows (run.sh)
# and profiles: one row per run, then the element-size comparison of
# Fig. 7.18 (each coarser profile against the finest, interpolated to its
# depths) and the szz ratio of Fig. 7.19.
set -e
out=$1 h=$2 hs=$3
finest=$(echo "$hs" | tr ' ' '\n' | sort -g | head -1)
echo "# Ch. 7.5 runs ($out)"
echo
echo "Measured $(date '+%F') on $(nproc) cores (load average at the end: $(cut -d' ' -f1-3 /proc/loadavg))."
echo "Stresses in MPa at the impact point (single shot: the 2 x 2 elements meeting there) or"
echo "averaged over the 4 x 4 mm impact area (multi); depths in mm; e: coefficient of restitution."
echo
echo "| run | elements | surface sxx | peak sxx | at depth | zero crossing | peak szz | e | wall s | cpu s |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for r in "$out"/*.row; do
	cpu=$(grep '^demshot: cost' "${r%.row}.log" | sed 's/.* cpu_s=\([0-9.]*\).*/\1/')
	awk -F'\t' -v cpu="$cpu" '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $8, $9, $10, $11, $12, $13, $14, $15, cpu }' "$r"
done
echo
echo "## Element size (Fig. 7.18): against h = $finest mm"
echo
echo "Largest difference of the area-averaged sxx over the depth of the finer profile,"
echo "as a share of the finest profile's peak |sxx|, and the difference of the peak."
echo
echo "| h (mm) | max abs difference (MPa) | of the peak | peak sxx | peak difference |"
echo "|---:|---:|---:|---:|---:|"
ref=$out/multi-$finest-2-none-90-full.prof
for e in $hs; do
	[ "$e" = "$finest" ] && continue
	awk -v h="$e" '
		!/^#/ && FILENAME == ARGV[1] { n++; d[n] = $2; s[n] = $3; if (-$3 > pk) pk = -$3 }
		!/^#/ && FILENAME == ARGV[2] { m++; dc[m] = $2; sc[m] = $3; if (-$3 > pc) pc = -$3 }
		END {
			for (j = 1; j <= m; j++) {
				if (dc[j] < d[1] || dc[j] > d[n]) continue
				for (i = 1; i < n && d[i + 1] < dc[j]; i++) ;
				w = (dc[j] - d[i]) / (d[i + 1] - d[i])
				dv = sc[j] - (s[i] + w * (s[i + 1] - s[i])); if (dv < 0) dv = -dv
				if (dv > mx) mx = dv
			}
			printf "| %s | %.1f | %.1f %% | %.1f | %.1f %% |\n", h, mx / 1e6, 100 * mx / pk,
				-pc / 1e6, 100 * (pc - pk) / pk
		}' "$ref" "$out/multi-$e-2-none-90-full.prof"
done
echo
echo "## Single and multiple shots (Fig. 7.19), h = $h mm"
echo
awk '
	!/^#/ && FILENAME == ARGV[1] { z = $5 < 0 ? -$5 : $5; if (z > zs) zs = z; if (-$3 > ps) ps = -$3 }
	!/^#/ && FILENAME == ARGV[2] { z = $5 < 0 ? -$5 : $5; if (z > zm) zm = z; if (-$3 > pm) pm = -$3 }
	END { printf "max |szz|: single %.1f MPa, multi %.1f MPa, ratio %.3f; peak compressive sxx: single %.1f, multi %.1f MPa, ratio %.2f\n",
		zs / 1e6, zm / 1e6, zm / zs, ps / 1e6, pm / 1e6, pm / ps }' \
	"$out/single-$h-2-none-90-full.prof" "$out/multi-$h-2-none-90-full.prof"
