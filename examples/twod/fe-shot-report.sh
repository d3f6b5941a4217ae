#!/bin/sh
# fe-shot-report.sh OUT [H...] - the Markdown section of the rigid DE disk
# against the FE shot (fe-shot.sh's outputs in OUT): per run the peak
# contact force (N per mm: the slab is 1 mm thick), its time and the
# contact's duration (the force history's first and last rows), the mean
# step (the pass's end over demshot's steps), the
# most compressive residual sxx on the centre line and its depth, its
# difference from the DE disk's, and the cost (demshot's cost line); then
# the profiles side by side.  The issue's acceptance: the FE shot's peak
# residual sxx within 10 % of the DE disk's.
set -e
out=$1
shift
[ -n "$out" ] || { echo "usage: fe-shot-report.sh OUT [H...]" >&2; exit 2; }
[ $# -gt 0 ] || set -- 1 0.5
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"

# peak NAME: the most compressive sxx (MPa) and its depth (mm)
peak() {
	awk '!/^#/ { if (!n++ || $3 < m) { m = $3; d = $2 } } END { printf "%.1f %.2f", m / 1e6, d * 1e3 }' \
		"$out/$1.profile"
}
# force NAME: the peak force (N/mm), its time and the contact's end (us)
force() {
	awk '!/^#/ { if ($4 > m) { m = $4; t = $3 } if (!n++) on = $3; off = $3 }
	     END { printf "%.0f %.1f %.1f", m, t * 1e6, (off - on) * 1e6 }' "$out/$1.forces"
}

set -- de $(for h in "$@"; do printf 'fe-%s ' "$h"; done)
read -r dpk ddp <<EOT
$(peak de)
EOT
# the DE disk's partial contact scheme, as its log names it (the scene
# takes demshot's default)
scheme=$(sed -n 's/^demshot: effects: .*, partial \([a-z]*\),.*/\1/p' "$out/de.log" | head -n 1)
echo "## The FE shot against the rigid DE disk (make fe-shot)"
echo
echo "Ch. 7.4's comparison: the DE disk (law m = 1.5, alpha 2.5 in the"
echo "thesis's sense, partial contact scheme ${scheme:-unknown}, demshot's default)"
echo "and the disk meshed as an elastic FE shot, E_s = 100 E,"
echo "in node-to-segment penalty contact whose pressure is that law's"
echo "Winkler form (lib/shot/feshot2d.h), contact damping 0.3, no friction;"
echo "both run to 200 us (fe-shot.sh).  Forces in N per mm."
echo
echo "| run | shot elements | steps | step (ns) | wall s | CPU s | peak force | at (us) | contact (us) | peak sxx (MPa) | depth (mm) | sxx vs DE |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for r in "$@"; do
	read -r pk dp <<EOT
$(peak "$r")
EOT
	read -r fm tf tc <<EOT
$(force "$r")
EOT
	read -r w c s ne <<EOT
$(cost_field "$out/$r.log" wall_s cpu_s steps shot_elements)
EOT
	d=$(awk -v a="$pk" -v b="$dpk" 'BEGIN { printf "%+.1f %%", 100 * (a / b - 1) }')
	# the mean step: the pass's end over the steps
	dt=$(sed -n 's/^demshot: pass 0 done at t = \([^ ]*\) s$/\1/p' "$out/$r.log" | tail -n 1 |
		awk -v n="$s" '{ printf "%.1f", 1e9 * $1 / n }')
	case $r in de) name="DE rigid disk" ne="-" ;; *) name="FE shot, ${r#fe-} mm at the rim" ;; esac
	echo "| $name | $ne | $s | $dt | $w | $c | $fm | $tf | $tc | $pk | $dp | $d |"
done
echo
worst=0
for r in "$@"; do
	[ "$r" = de ] && continue
	read -r pk dp <<EOT
$(peak "$r")
EOT
	awk -v a="$pk" -v b="$dpk" 'BEGIN { exit !(((a - b) / b) ^ 2 <= 0.01) }' || worst=1
done
if [ $worst = 0 ]; then
	echo "Every FE shot's peak residual sxx is within 10 % of the DE disk's (the issue's acceptance)."
else
	echo "**Not every FE shot's peak residual sxx is within 10 % of the DE disk's.**"
fi
echo
echo "Residual sxx (MPa) on the centre line, the top 8 mm:"
echo
printf '| depth (mm) |'
for r in "$@"; do printf ' %s |' "$r"; done
echo
printf '|---|'
for r in "$@"; do printf -- '---|'; done
echo
files=
for r in "$@"; do files="$files $out/$r.profile"; done
awk 'FNR == 1 { f++ } !/^#/ { k = FNR; d[k] = $2; s[f, k] = $3; if (FNR > nk) nk = FNR }
     END { for (k = 1; k <= nk; k++) if (k in d && d[k] <= 8e-3) {
		printf "| %.2f |", d[k] * 1e3
		for (i = 1; i <= f; i++) printf " %.0f |", s[i, k] / 1e6
		print "" } }' $files
