#!/bin/sh
# hertz.sh H OUT - a rigid sphere on a thick elastic block (issue 5, item 1),
# with element size H (a length with unit) in the contact region; appends a
# row to OUT/hertz.tsv: element, contact radius over element, largest
# force and contact time against the references.
#
# Set-up (as tests/unit/test_shot_impact.c, test_hertz, there on a coarse
# mesh): Hertz contact radius a = 4 mm, sphere radius R = 20 a, so the
# indentation is d = a^2 / R = 0.2 mm; block E = 100 MPa, nu = 0.3,
# rho = 1000 kg/m^3, 20 a wide and 20 a thick (bottom fixed, sides on
# rollers), impact speed 0.5 m/s (v / c = 1/730: quasi-static); the sphere's
# mass makes the Hertz indentation d: M = 16 E* sqrt(R) d^(5/2) / (15 v^2),
# i.e. a density of 34.97 kg/m^3 for R = 80 mm.  The contact law is a stiff
# penalty F = alpha E sqrt(R) delta^1.5 with alpha = 30.  In this conforming
# contact every facet under the sphere carries the law on its own small
# overlap, so the penalty's compliance is small (alpha 20 against 30 moves
# the force by 1 %) and the reference is Hertz's:
# F_max = 4/3 E* sqrt(R) d^(3/2), contact time 2.94327 d / v.
set -e
h=$1 out=$2
bin=../../bin
mkdir -p "$out"
tag=$(echo "$h" | tr -d ' ')
cat > "$out/hertz-$tag.yaml" <<YAML
material:
  E: 100 MPa
  nu: 0.3
  rho: 1000 kg/m^3
block:
  size: [80 mm, 80 mm, 80 mm]
  element: $h
  fine: [16 mm, 16 mm]
  fine_depth: 8 mm
  ratio: 1.3
shot:
  density: 34.97 kg/m^3
contact:
  alpha: 30
run:
  strain: small
  damping: 0
  pass_time: 1.6 ms
YAML
"$bin"/dempack shots --grid 1 --passes 1 --area 1mm:1mm --speed 0.5 --shot-radius 80mm \
	--seed 1 > "$out/shot.txt" 2> /dev/null
"$bin"/demshot -s "$out/hertz-$tag.yaml" --threads 2 -q --forces "$out/f-$tag.txt" \
	-o "$out/hertz-$tag.state" "$out/shot.txt" 2> "$out/hertz-$tag.log"
awk -v tag="$tag" '
	/: cost: / { for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
	END { printf "%s\t%s\t%s\t", v["elements"], v["steps"], v["wall_s"] > "/dev/stderr" }' "$out/hertz-$tag.log" 2> "$out/cost-$tag"
grep -v '^#' "$out/f-$tag.txt" | awk -v h="$h" -v cost="$(cat "$out/cost-$tag")" '
	BEGIN {
		E = 100e6; nu = 0.3; a = 4e-3; R = 20 * a; d = a * a / R; v = 0.5; alpha = 30
		Es = E / (1 - nu * nu)
		F = 4 / 3 * Es * sqrt(R) * d ^ 1.5; tc = 2.94327 * d / v
		split(h, hv, " "); hm = hv[1] * (hv[2] == "mm" ? 1e-3 : 1)
	}
	{ if ($8 > fmax) fmax = $8; if (t0 == "") t0 = $3; t1 = $3 }
	END {
		printf "%s\t%.1f\t%.5g\t%.5g\t%+.2f\t%.5g\t%.5g\t%+.2f\t%s\n", h, a / hm, fmax, F,
		       100 * (fmax / F - 1), t1 - t0, tc, 100 * ((t1 - t0) / tc - 1), cost
	}' >> "$out/hertz.tsv"
