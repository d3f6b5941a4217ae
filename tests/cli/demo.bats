#!/usr/bin/env bats
# The demo's pipeline, dempack shots | demshot | demprofile | demform, on a
# much smaller version of its scene (examples/demo/scene.yaml): one shot of
# the Ch. 8.6 kind (S550, 46.5 m/s, Al 7050) on a 2.4 mm block, one pass.
# Checked: every stage exits 0; the block is left in compression at the
# surface under the shot (a shot peening profile, Fig. 8.5); the strip
# formed by it is convex on the peened face (arc height > 0) and its
# curvature is that of the closed form of a free elastic plate under the
# same profile; and examples/demo/Makefile runs the same scene to its plots
# and closing line, and does nothing the second time.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	# the Makefile of the example, its scene from SCENES
	DEMO=$ROOT/examples/demo
	SCENE=$SCENES/demo/scene.yaml
	# the bundled scene made small: a 1.4 mm tile with one shot, one pass,
	# a 2.4 mm block with its 0.1 mm elements under the tile only
	sed -e 's/^  area: \[2.8 mm, 2.8 mm\]$/  area: [1.4 mm, 1.4 mm]/' \
	    -e 's/^  grid: 2$/  grid: 1/' \
	    -e 's/^  passes: 4$/  passes: 1/' \
	    -e 's/^  size: \[4.4 mm, 4.4 mm, 4 mm\]$/  size: [2.4 mm, 2.4 mm, 4 mm]/' \
	    -e 's/^  fine: \[3.2 mm, 3.2 mm\]$/  fine: [1.4 mm, 1.4 mm]/' \
	    -e 's/^  fine_depth: 0.8 mm$/  fine_depth: 0.6 mm/' \
	    -e 's/^  margin: 0.28 mm$/  margin: 0.14 mm/' \
	    "$SCENE" > "$T/tiny.yaml"
	# every edit took (else the test would run the whole demo, or a
	# scene that no longer is the demo's)
	[ "$(diff "$SCENE" "$T/tiny.yaml" | grep -c '^>')" -eq 7 ]
}

# the closed form of a free elastic plate (E, nu, h) under the profile of
# the last pass of a profile stream, its stress released: in-plane strain
# e = -(sxx - nu (syy + szz))/E at each depth (linear between the points,
# constant beyond, as demform maps it), kappa_x = 12/h^3 int e z dz with z
# from the mid-plane (DESIGN.md's kappa = -12 (1-nu) int s z dz / (E h^3)
# for sxx = syy = s, szz = 0)
kappa_closed() {
	awk -v E=72e9 -v nu=0.33 -v h=0.004 '
		!/^#/ { if ($1 != p) n = 0; p = $1; n++; d[n] = $2; e[n] = -($3 - nu * ($4 + $5)) / E }
		END {
			N = 4000; I = 0
			for (k = 0; k < N; k++) {
				z = (k + 0.5) * h / N
				if (z <= d[1]) v = e[1]
				else if (z >= d[n]) v = e[n]
				else for (j = 1; j < n; j++) if (z <= d[j + 1]) { v = e[j] + (e[j + 1] - e[j]) * (z - d[j]) / (d[j + 1] - d[j]); break }
				I += v * (h / 2 - z) * h / N
			}
			print 12 * I / h ^ 3
		}' "$1"
}

@test "demo: dempack shots | demshot | demprofile | demform: every stage 0, compressive surface, convex strip" {
	cd "$T"
	run --separate-stderr bash -c 'dempack -s tiny.yaml shots --seed 1 | demshot -s tiny.yaml | tee state |
		demprofile -s tiny.yaml | tee prof | demform -s tiny.yaml > form; echo "${PIPESTATUS[*]}"'
	printf '%s\n' "${stderr_lines[@]}"
	[ "$status" -eq 0 ]
	[ "${lines[-1]}" = "0 0 0 0 0 0" ]
	# each program's cost line; one shot, one pass
	for p in dempack demshot demprofile demform; do grep -q "^$p: cost: wall_s=" <<< "$stderr"; done
	grep -q '^demshot: cost: .* passes=1 .*contacts=[1-9]' <<< "$stderr"
	# the scene leaves the shot to dempack's defaults: S550 at 46.5 m/s, normal
	dempack -s tiny.yaml shots --seed 1 2>/dev/null > shots
	grep -q '^# shot law=mono radius=0.0007 lambda=1 speed=46.5 speed_scatter=0 angle_deg=90 ' shots
	[ "$(grep -vc '^#' shots)" -eq 1 ]
	# the profile over the impacted region: compressive at the surface
	# (sxx, syy), plastic there, back to tension deeper (the balancing part)
	read -r sxx syy ep < <(grep -v '^#' prof | head -n 1 | awk '{ print $3 / 1e6, $4 / 1e6, $15 }')
	echo "region, top layer: sxx $sxx syy $syy MPa, ep $ep"
	awk -v a="$sxx" -v b="$syy" -v e="$ep" 'BEGIN { exit !(a < -50 && b < -50 && e > 0.01) }'
	grep -v '^#' prof | awk '$3 > 0 { t++ } END { exit !(t > 0) }'
	# under the shot (0.4 mm square at the impact point): deeper in
	# compression than the yield stress is high times a fifth
	read -r sxx syy < <(demprofile --area 0.4mm:0.4mm --margin 0 state 2>/dev/null |
		grep -v '^#' | head -n 1 | awk '{ print $3 / 1e6, $4 / 1e6 }')
	echo "under the shot, top layer: sxx $sxx syy $syy MPa"
	awk -v a="$sxx" -v b="$syy" 'BEGIN { exit !(a < -90 && b < -90) }'
	# the strip: convex on the peened face, bent the same both ways (one
	# shot at the centre of a square tile), as the closed form says
	arc=$(awk '$1 == "arc_height:" { print $2 }' form)
	kx=$(awk '$1 == "curvature_x:" { print $2 }' form)
	ky=$(awk '$1 == "curvature_y:" { print $2 }' form)
	kc=$(kappa_closed prof)
	echo "arc height $arc m, curvatures $kx $ky 1/m, closed form $kc 1/m"
	awk -v a="$arc" -v x="$kx" -v y="$ky" -v c="$kc" 'BEGIN {
		d = x / c - 1; if (d < 0) d = -d
		s = x / y - 1; if (s < 0) s = -s
		# arc height = kappa L^2 / 8 over the 150 mm chord, to 1 %
		r = a / (x * 0.15 * 0.15 / 8) - 1; if (r < 0) r = -r
		exit !(a > 0 && x > 0 && y > 0 && c > 0 && d < 0.02 && s < 0.02 && r < 0.01)
	}'
}

@test "demo: examples/demo/Makefile runs the scene to its plots and closing line; a second make redoes nothing" {
	bin=$(dirname "$(command -v demshot)")
	run --separate-stderr make -C "$DEMO" --no-print-directory SCENE="$T/tiny.yaml" OUT="$T/out" SHOWN="$T/out" BIN="$bin"
	printf '%s\n' "${lines[@]}" "${stderr_lines[@]}"
	[ "$status" -eq 0 ]
	# a banner per stage, each program's cost line, the closing line
	[ "$(grep -c '^== [1-4]/4 ' <<< "$output")" -eq 4 ]
	for p in dempack demshot demprofile demform; do grep -q "^$p: cost: wall_s=" <<< "$output"; done
	[ "$(grep -c '^demshot: pass 0: t = ' <<< "$output")" -eq 0 ]
	[[ ${lines[-1]} =~ ^arc\ height:\ ([0-9.]+)\ mm\ \(over\ the\ 150\ mm\ span\)\;\ plots:\ (.*)/\*\.png$ ]]
	shown=${BASH_REMATCH[1]}
	[ "${BASH_REMATCH[2]}" = "$T/out" ]
	# the line gives demform's arc height, and the shape table's deflection
	# at the centre of the length is that arc height
	arc=$(awk '$1 == "arc_height:" { printf "%.3f", $2 * 1000 }' "$T/out/form.txt")
	[ "$shown" = "$arc" ]
	awk -v a="$arc" '/^$/ { exit } !/^#/ && $1 == 0 { w = $2 } END { d = w - a; exit !(d < 0.0006 && d > -0.0006) }' "$T/out/shape.txt"
	# the check line: the closed form within 2 % of demform's curvature
	grep '^strip: ' <<< "$output" | awk '{
		kx = $3; for (i = 1; i <= NF; i++) if ($i == "(curvature") kc = $(i + 1)
		d = kx / kc - 1; if (d < 0) d = -d; exit !(kx > 0 && d < 0.02) }'
	# the plots are PNGs
	for f in profile shape; do
		[ "$(head -c 8 "$T/out/$f.png" | od -A n -t x1 | tr -d ' ')" = 89504e470d0a1a0a ]
	done
	# a second make: only the closing lines, the same arc height
	run --separate-stderr make -C "$DEMO" --no-print-directory SCENE="$T/tiny.yaml" OUT="$T/out" SHOWN="$T/out" BIN="$bin"
	[ "$status" -eq 0 ]
	[ "$(grep -c '^== [1-4]/4 ' <<< "$output")" -eq 0 ]
	[ "${lines[0]}" = "== result" ]
	[[ ${lines[-1]} == "arc height: $arc mm "* ]]
	# a failing stage fails the demo, its message shown (through tee): a
	# demform that refuses its input, newer than the run's outputs
	cp -rp "$T/out" "$T/out2"
	printf '#!/bin/sh\necho "demform: stdin: row 1: bad input" >&2\nexit 1\n' > "$T/demform"
	chmod +x "$T/demform"
	run --separate-stderr make -C "$DEMO" --no-print-directory SCENE="$T/tiny.yaml" OUT="$T/out2" SHOWN="$T/out2" BIN="$bin" DEMFORM="$T/demform"
	printf '%s\n' "${lines[@]}" "${stderr_lines[@]}"
	[ "$status" -ne 0 ]
	[ "$(grep -c '^== [1-3]/4 ' <<< "$output")" -eq 0 ]
	grep -q '^== 4/4 ' <<< "$output"
	grep -q '^demform: stdin: row 1: bad input$' <<< "$output"
	[ "$(grep -c '^arc height: ' <<< "$output")" -eq 0 ]
}
