#!/usr/bin/env bats
# Command-line tests of demform.  References: the free-plate closed form of
# DESIGN.md (curvature -12 (1-nu) int s z dz / (E h^3), arc height about
# kappa L^2 / 8) for an equi-biaxial stress profile; linearity of the
# elastic problem (half the profile, half the curvature); symmetry (the same
# profile on both faces bends nothing); the exit codes of DESIGN.md.  The
# profile streams are written by awk; the profile is a made-up
# shot-peening shape (it is the closed form that is the reference).

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	# depth (mm) and sxx = syy (MPa) of the profile; ep
	cat > "$T/shape" <<-EOF
	0 -300 0.05
	0.1 -400 0.0375
	0.2 -350 0.025
	0.35 -150 0.0125
	0.5 30 0
	0.6 0 0
	EOF
	# pass 1: half the stresses, pass 2: the profile
	profile_stream "$T/shape" > "$T/prof"
	cat > "$T/el.yaml" <<-EOF
	material: {E: 72 GPa, nu: 0.33}
	EOF
	cat > "$T/small.yaml" <<-EOF
	material: {E: 72 GPa, nu: 0.33}
	plate: {size: [60 mm, 20 mm, 4 mm], element: 10 mm, layers: 8, grading: 1.3}
	EOF
}

# The closed form of DESIGN.md for the profile SHAPE on a plate of
# thickness H (m): prints kappa (1/m).
closed_kappa() {
	awk -v h="$2" -v E=72e9 -v nu=0.33 '
	{ d[NR] = $1 * 1e-3; s[NR] = $2 * 1e6 }
	END {
		for (k = 1; k < NR; k++)
			for (g = 0; g <= 2; g++) {
				t = g / 2; x = d[k] + t * (d[k + 1] - d[k])
				w = (d[k + 1] - d[k]) * (g == 1 ? 4 : 1) / 6
				I1 += w * (s[k] + t * (s[k + 1] - s[k])) * (h / 2 - x)
			}
		printf "%.12g\n", -12 * (1 - nu) * I1 / (E * h * h * h)
	}' "$1"
}


@test "demform --help and --version: stdout, exit 0" {
	run --separate-stderr demform --help
	[ "$status" -eq 0 ]
	[[ ${lines[0]} == "Usage: demform "* ]]
	[ -z "$stderr" ]
	run --separate-stderr demform --version
	[ "$status" -eq 0 ]
	[[ $output =~ ^demform\ \(dem\ toolkit\)\ [0-9]+\.[0-9]+\.[0-9]+$ ]]
}

@test "demform: the Ch. 8.6 strip (4500 elements): curvatures and arc height within 3 % of the closed form, one Newton iteration" {
	demform -s "$T/el.yaml" "$T/prof" > "$T/sum" 2> "$T/err"
	[ "$(value elements "$T/sum")" -eq 4500 ]
	[ "$(value nodes "$T/sum")" -eq 5456 ]
	k=$(closed_kappa "$T/shape" 0.004)
	rel_close "$(value curvature_x "$T/sum")" "$k" 0.03
	rel_close "$(value curvature_y "$T/sum")" "$k" 0.03
	rel_close "$(value arc_height "$T/sum")" "$(awk -v k="$k" 'BEGIN { print k * 0.15 * 0.15 / 8 }')" 0.03
	[ "$(value iterations "$T/sum")" -eq 1 ]
	[ "$(grep -c '^newton: ' "$T/sum")" -eq 2 ]
	awk '$1 == "residual_rel:" { exit !($2 < 1e-8) }' "$T/sum"
	tail -n 1 "$T/err" | grep -q '^demform: cost: wall_s=.* factor_s=.* elements=4500 equations=16362 .*iterations=1 factorisations=1'
}

@test "demform --pass 1: half the profile, half the curvature (linear elastic problem)" {
	demform -s "$T/small.yaml" "$T/prof" > "$T/a" 2>/dev/null
	demform -s "$T/small.yaml" --pass 1 "$T/prof" > "$T/b" 2>/dev/null
	rel_close "$(value curvature_x "$T/b")" "$(awk -v k="$(value curvature_x "$T/a")" 'BEGIN { printf "%.12g", k / 2 }')" 1e-6
}

@test "demform: the same profile on both faces of a symmetric mesh bends nothing; on the bottom only it bends the other way" {
	cat > "$T/sym.yaml" <<-EOF
	material: {E: 72 GPa, nu: 0.33}
	plate: {size: [60 mm, 20 mm, 4 mm], element: 10 mm, layers: 8, grading: 1.3, two_sided: true}
	EOF
	cat "$T/sym.yaml" - > "$T/both.yaml" <<-EOF
	form:
	  step1: {top: {}, bottom: {}}
	EOF
	demform -s "$T/both.yaml" "$T/prof" > "$T/both" 2>/dev/null
	demform -s "$T/sym.yaml" "$T/prof" > "$T/top" 2>/dev/null
	awk -v a="$(value curvature_x "$T/both")" -v b="$(value curvature_x "$T/top")" \
		'BEGIN { exit !(a < 1e-6 * b && a > -1e-6 * b) }'
	cat "$T/sym.yaml" - > "$T/bot.yaml" <<-EOF
	form:
	  step1: {bottom: {}}
	EOF
	demform -s "$T/bot.yaml" "$T/prof" > "$T/bot" 2>/dev/null
	rel_close "$(value curvature_x "$T/bot")" "-$(value curvature_x "$T/top")" 1e-6
}

@test "demform: two steps report two shapes; the second adds its profile to the first's state" {
	cat "$T/small.yaml" - > "$T/two.yaml" <<-EOF
	form:
	  step1: {top: {pass: 1}}
	  step2: {top: {pass: 1}}
	EOF
	demform -s "$T/two.yaml" "$T/prof" > "$T/two" 2>/dev/null
	demform -s "$T/small.yaml" "$T/prof" > "$T/one" 2>/dev/null
	[ "$(grep -c '^step: ' "$T/two")" -eq 2 ]
	k2=$(awk '$1 == "curvature_x:" { k = $2 } END { print k }' "$T/two")
	rel_close "$k2" "$(value curvature_x "$T/one")" 1e-6
}

@test "demform --large: agrees with small strain for the 4 mm plate, in equilibrium" {
	demform -s "$T/small.yaml" "$T/prof" > "$T/s" 2>/dev/null
	demform -s "$T/small.yaml" --large "$T/prof" > "$T/l" 2>/dev/null
	grep -qx 'strain: large' "$T/l"
	rel_close "$(value arc_height "$T/l")" "$(value arc_height "$T/s")" 0.01
	awk '$1 == "residual_rel:" { exit !($2 < 1e-8) }' "$T/l"
	[ "$(value iterations "$T/l")" -gt 1 ]
}

@test "demform: a strain-hardened layer on a thin plate of SS316 (Table 7.2) yields the unpeened face; Newton converges in the plastic increment" {
	# the layer on its hardened flow surface, sxx = syy = -(366 MPa + 2430 MPa ep),
	# ep from 0.5 at the surface to 0 at 0.5 mm (test_fe_implicit.c,
	# test_j2_unpeened_face: the elastic face would be at 1.25 times the yield)
	cat > "$T/hard" <<-EOF
	0 -1581 0.5
	0.25 -973.5 0.25
	0.28 0 0.22
	0.5 0 0
	EOF
	profile_stream "$T/hard" > "$T/hprof"
	cat > "$T/ss.yaml" <<-EOF
	material: {E: 193 GPa, nu: 0.328, yield: 366 MPa, hardening: 2430 MPa}
	plate: {size: [6 mm, 6 mm, 0.75 mm], element: 0.5 mm, layers: 12, grading: 1.15, two_sided: true}
	EOF
	demform -s "$T/ss.yaml" --increments 4 --centre "$T/c" "$T/hprof" > "$T/sum" 2>/dev/null
	# the deepest point of the centre: virgin, now yielded, on its flow surface
	awk '!/^#/ { r = $0 } END { split(r, a); ep = a[8]; f = (366e6 + 2430e6 * ep) / -a[2]
		exit !(ep > 1e-4 && f > 0.995 && f < 1.005) }' "$T/c"
	# lambda 0.25, 0.5, 0.75 elastic (one iteration), 1 plastic (several)
	awk '$1 == "newton:" { n[$3]++ } END { exit !(n[1] == 2 && n[2] == 2 && n[3] == 2 && n[4] > 3) }' "$T/sum"
	awk '$1 == "residual_rel:" { exit !($2 < 1e-8) }' "$T/sum"
}

@test "demform --centre and --vtu: the centre stress table and the plate for ParaView" {
	demform -s "$T/small.yaml" --centre "$T/c" --vtu "$T/p.vtu" -o "$T/sum" "$T/prof" 2>/dev/null
	[ "$(grep -vc '^#' "$T/c")" -eq 16 ]
	tail -n 1 "$T/c" | grep -qx '# end 16'
	# the top row is compressive, the stress szz near zero (free faces)
	awk '!/^#/ { print; exit }' "$T/c" | awk '{ exit !($2 < -1e8 && $4 * $4 < 1e14) }'
	grep -q 'UnstructuredGrid' "$T/p.vtu"
	grep -q 'arc_height: ' "$T/sum"
}

@test "demform: gauge_height, the J442 gauge on the unpeened face, is kx lx^2/8 + ky ly^2/8 of the fitted curvatures; no reading on a plate smaller than the gauge; a rectangle off the plate is bad input" {
	# balls on grid nodes (10 mm elements): no interpolation in the reading
	printf 'form: {gauge: [40 mm, 20 mm]}\n' | cat "$T/small.yaml" - > "$T/g.yaml"
	demform -s "$T/g.yaml" "$T/prof" > "$T/sum" 2>/dev/null
	[ "$(value gauge "$T/sum")" = 0.04 ]
	ref=$(awk -v kx="$(value curvature_x "$T/sum")" -v ky="$(value curvature_y "$T/sum")" \
		'BEGIN { printf "%.12g", kx * 0.04 * 0.04 / 8 + ky * 0.02 * 0.02 / 8 }')
	rel_close "$(value gauge_height "$T/sum")" "$ref" 0.005
	# the default rectangle (31.75 x 15.875 mm) fits the 60 x 20 mm plate
	demform -s "$T/small.yaml" "$T/prof" > "$T/sum" 2>/dev/null
	grep -qx 'gauge: 0.03175 0.015875' "$T/sum"
	awk '$1 == "gauge_height:" { n++; ok = $2 > 0 } END { exit !(n == 1 && ok) }' "$T/sum"
	# a 30 x 10 mm plate: no reading, no error
	printf 'material: {E: 72 GPa, nu: 0.33}\nplate: {size: [30 mm, 10 mm, 4 mm], element: 5 mm, layers: 4}\n' > "$T/tiny.yaml"
	demform -s "$T/tiny.yaml" "$T/prof" > "$T/sum" 2>/dev/null
	grep -q '^arc_height: ' "$T/sum"
	! grep -q '^gauge' "$T/sum"
	printf 'form: {gauge: [70 mm, 10 mm]}\n' | cat "$T/small.yaml" - > "$T/bad.yaml"
	run --separate-stderr demform -s "$T/bad.yaml" -o "$T/o" "$T/prof"
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == "demform: "*"form.gauge"*"larger than the plate"* ]]
	[ ! -e "$T/o" ]
}

@test "demform: the assembly on 1 and 2 threads gives the same summary bit for bit on the Ch. 8.6 strip (coloured assembly, 560 elements a colour; the BLAS held to one thread)" {
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 demform -s "$T/el.yaml" -o "$T/s1" "$T/prof" 2> "$T/e1"
	OMP_NUM_THREADS=2 OPENBLAS_NUM_THREADS=1 demform -s "$T/el.yaml" -o "$T/s2" "$T/prof" 2> "$T/e2"
	cmp "$T/s1" "$T/s2"
	tail -n 1 "$T/e1" | grep -q ' threads=1 blas_threads=[01]$'
	tail -n 1 "$T/e2" | grep -q ' threads=2 blas_threads=[01]$'
}

@test "demform --threads: 1 and 2 threads (assembly and a threaded BLAS) agree to 1e-9 on curvatures and arc height; the cost line says how many" {
	demform --threads 1 -s "$T/el.yaml" -o "$T/s1" "$T/prof" 2> "$T/e1"
	demform --threads 2 -s "$T/el.yaml" -o "$T/s2" "$T/prof" 2> "$T/e2"
	for k in curvature_x curvature_y arc_height; do
		rel_close "$(value $k "$T/s2")" "$(value $k "$T/s1")" 1e-9
	done
	tail -n 1 "$T/e1" | grep -q ' threads=1 blas_threads=[01]$'
	tail -n 1 "$T/e2" | grep -q ' threads=2 blas_threads=[0-2]$'
}

@test "demform: usage errors" {
	usage_error demform --threads 0 "$T/prof"
	usage_error demform --threads x "$T/prof"
	usage_error demform -b "$T/prof"
	usage_error demform --bogus
	usage_error demform a b
}

@test "demform: bad input: exit 1, message, no summary" {
	run --separate-stderr demform -s "$T/small.yaml" --pass 7 -o "$T/o" "$T/prof"
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == "demform: "*"pass 7"* ]]
	[ ! -e "$T/o" ]
	printf 'material: {E: 72 GPa, nu: 0.33}\nplate: {layers: 0}\n' > "$T/bad.yaml"
	run --separate-stderr demform -s "$T/bad.yaml" -o "$T/o" "$T/prof"
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == "demform: "* ]]
	[ ! -e "$T/o" ]
	printf 'form: {wobble: 1}\n' | cat "$T/small.yaml" - > "$T/bad.yaml"
	run --separate-stderr demform -s "$T/bad.yaml" "$T/prof"
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == "demform: "*"wobble"* ]]
	head -n 5 "$T/prof" > "$T/trunc"
	run --separate-stderr demform -s "$T/small.yaml" -o "$T/o" "$T/trunc"
	[ "$status" -eq 1 ]
	[ ! -e "$T/o" ]
}

@test "demform: Newton that cannot converge within the cut-backs: exit 3, no summary" {
	printf 'form: {strain: large, iterations: 1, cutbacks: 1}\n' | cat "$T/small.yaml" - > "$T/nc.yaml"
	run --separate-stderr demform -s "$T/nc.yaml" -o "$T/o" "$T/prof"
	[ "$status" -eq 3 ]
	[[ ${stderr_lines[0]} == "demform: "*"cut-backs"* ]]
	[ ! -e "$T/o" ]
}

@test "demform --dump-scene: every default, then exit" {
	run --separate-stderr demform -s "$T/small.yaml" --dump-scene
	[ "$status" -eq 0 ]
	[[ $output == *"layers: 8"* ]]
	[[ $output == *"tolerance: "* ]]
	[[ $output == *"increments: 1"* ]]
}

# ---- a 2D plane-strain profile (issue 18, item 3) ---------------------------
# Reference: a strip in plane strain along y (eps_yy = 0, free in x and z)
# under an initial stress sxx(z) has the curvature
#   kappa_x = -12 int sxx z dz / (E' h^3),  E' = E / (1 - nu^2),
# z from the mid-plane: the free plate of DESIGN.md with the plane-strain
# modulus in place of the biaxial E / (1 - nu) (the moment balance
# int (sxx + E' (e0 + kappa z)) z dz = 0); no curvature about x; and the
# profile's syy, the constraint's stress, bends nothing.

# the plane-strain closed form for SHAPE on a plate of thickness H (m)
closed_kappa_plane() {
	awk -v h="$2" -v E=72e9 -v nu=0.33 '
	{ d[NR] = $1 * 1e-3; s[NR] = $2 * 1e6 }
	END {
		for (k = 1; k < NR; k++)
			for (g = 0; g <= 2; g++) {
				t = g / 2; x = d[k] + t * (d[k + 1] - d[k])
				w = (d[k + 1] - d[k]) * (g == 1 ? 4 : 1) / 6
				I1 += w * (s[k] + t * (s[k + 1] - s[k])) * (h / 2 - x)
			}
		printf "%.12g\n", -12 * (1 - nu * nu) * I1 / (E * h * h * h)
	}' "$1"
}

@test "demform: a 2D plane-strain profile forms a plane-strain strip: kappa_x = -12 M / (E' h^3) within 0.5 %, no kappa_y, syy bends nothing" {
	# the stream as demprofile passes it on from a 2D plane-strain state
	# stream; syy = sxx here, a made-up constraint stress
	sed '/^# format text/a # twod mode=plane thickness=0.001' "$T/prof" > "$T/prof2"
	# and with syy = 0
	awk '/^# data/ { f = 1 } f && !/^#/ { $4 = 0 } { print }' "$T/prof2" > "$T/prof2z"
	# a strip 2 elements wide (3 node rows: the fit sees kappa_y)
	cat > "$T/strip.yaml" <<-EOF
	material: {E: 72 GPa, nu: 0.33}
	plate: {size: [60 mm, 4 mm, 4 mm], element: 2 mm, layers: 15}
	EOF
	run --separate-stderr demform -s "$T/strip.yaml" "$T/prof2"
	echo "$output"; echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q '^demform: step 1: plane strain along y (the profile is of a 2D plane-strain block)' <<< "$stderr"
	echo "$output" > "$T/a"
	[ "$(value plane_strain "$T/a")" = true ]
	k=$(closed_kappa_plane "$T/shape" 0.004)
	kx=$(value curvature_x "$T/a")
	echo "kappa_x $kx, closed form $k"
	rel_close "$kx" "$k" 0.005
	awk -v y="$(value curvature_y "$T/a")" -v x="$kx" 'BEGIN { exit !(y < 1e-9 * x && y > -1e-9 * x) }'
	demform -s "$T/strip.yaml" -q "$T/prof2z" > "$T/z"
	rel_close "$(value curvature_x "$T/z")" "$kx" 1e-9
	# a 3D profile with form.plane_strain: true: the same strip
	cat "$T/strip.yaml" - > "$T/on.yaml" <<-EOF
	form: {plane_strain: true}
	EOF
	demform -s "$T/on.yaml" -q "$T/prof" > "$T/on"
	[ "$(value curvature_x "$T/on")" = "$kx" ]
	# form.plane_strain: false: the profile applied as it stands, syy an
	# initial stress too (a free plate bent both ways)
	cat "$T/strip.yaml" - > "$T/off.yaml" <<-EOF
	form: {plane_strain: false}
	EOF
	demform -s "$T/off.yaml" -q "$T/prof2" > "$T/off"
	[ "$(value plane_strain "$T/off")" = false ]
	awk -v a="$(value curvature_x "$T/off")" -v b="$kx" 'BEGIN { r = a / b - 1; exit !(r > 0.1 || r < -0.1) }'
	awk -v y="$(value curvature_y "$T/off")" 'BEGIN { exit !(y > 0.1) }'
}

@test "demform: a step mixing a 2D plane-strain profile with a 3D one needs form.plane_strain" {
	sed '/^# format text/a # twod mode=plane thickness=0.001' "$T/prof" > "$T/prof2"
	cat "$T/small.yaml" - > "$T/mix.yaml" <<-EOF
	form:
	  step1: {top: {}, bottom: {file: "$T/prof"}}
	EOF
	run --separate-stderr demform -s "$T/mix.yaml" -o "$T/mix" "$T/prof2"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q 'step 1: profiles of a 2D plane-strain block and of a 3D one: set form.plane_strain' <<< "$stderr"
	[ ! -e "$T/mix" ]
	sed 's/^form:$/form:\n  plane_strain: false/' "$T/mix.yaml" > "$T/mix2.yaml"
	run --separate-stderr demform -s "$T/mix2.yaml" -o "$T/mix" "$T/prof2"
	[ "$status" -eq 0 ]
}
