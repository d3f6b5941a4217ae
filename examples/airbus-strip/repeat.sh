#!/bin/sh
# repeat.sh OUT [N] - one S550 shot at 46.5 m/s N times (default 8) on the
# same point of the quick sample block (quick.yaml), one impact a pass:
# does the surface shake down under repeated impacts (the plastic strain
# added by each impact falling to nothing), or does it keep flowing?  The
# full run's surface layer keeps hardening from pass to pass (README.md);
# this separates the repetition itself from the offsets between passes.
#
# Writes OUT/{shots.txt,scene.yaml,peen.state,forces.txt,demshot.log,
# sat.txt,surf.txt} and prints a Markdown table: per impact, the deepest
# indentation, the plastic strain of the top layer averaged over the
# 1 x 1 mm square around the point, what the impact added to it, and the
# coefficient of restitution e = J_z / (m v) - 1 from the force history (J_z
# the impulse on the shot; e rising to 1 would be a shake-down to elastic
# impacts).
set -e
out=$1 n=${2:-8}
[ -n "$out" ] || { echo "usage: repeat.sh OUT [N]" >&2; exit 2; }
bin=${BIN:-../../bin}
here=$(dirname "$0")
mkdir -p "$out"
# quick.yaml with the grid pattern (the random pattern's keys out)
sed -e 's/^  pattern: random$/  pattern: grid/' -e '/^  per_pass: /d' -e '/^  separation: /d' \
	"$here/quick.yaml" > "$out/scene.yaml"
# N passes of one shot, all at the centre (the grid pattern of one shot,
# whatever the scene's pattern; the grid offsets each pass, the offsets
# are set to zero here)
"$bin"/dempack -s "$out/scene.yaml" shots --grid 1 --area 1mm:1mm --passes "$n" --speed 46.5m/s \
	--seed 1 2> /dev/null | awk '/^#/ { print; next } { $3 = 0; $4 = 0; print }' > "$out/shots.txt"
"$bin"/demshot -s "$out/scene.yaml" ${THREADS:+--threads "$THREADS"} --forces "$out/forces.txt" \
	-o "$out/peen.state" "$out/shots.txt" 2> "$out/demshot.log"
"$bin"/demprofile -q -s "$out/scene.yaml" --area 1mm:1mm --margin 0 --field ep \
	--saturation "$out/sat.txt" --surface "$out/surf.txt" -o /dev/null "$out/peen.state"
echo "| impact | deepest indentation (um) | top-layer ep, 1 x 1 mm mean | added by the impact | restitution e |"
echo "|---|---|---|---|---|"
# the shot of quick.yaml: radius 0.7 mm, 7800 kg/m^3, 46.5 m/s down
awk 'FNR == 1 { f++ } /^#/ { next }
	f == 1 { ep[$1] = $2 }
	f == 2 { d[$1] = $4 }
	f == 3 { p = $1; if (p in t0) J[p] += 0.5 * ($8 + f0[p]) * ($3 - t0[p]); t0[p] = $3; f0[p] = $8 }
	END { m = 4 / 3 * 3.14159265358979 * 0.0007^3 * 7800
		for (i = 0; i in ep; i++)
			printf "| %d | %.1f | %.4f | %.4f | %.3f |\n", i + 1, 1e6 * d[i], ep[i],
				ep[i] - (i ? ep[i - 1] : 0), J[i] / (m * 46.5) - 1 }' \
	"$out/sat.txt" "$out/surf.txt" "$out/forces.txt"
grep 'demshot: cost:' "$out/demshot.log" | sed 's/^/\n    /'
