#!/usr/bin/env bats
# Command-line tests of the material and shot library (share/, issue 16):
# every file loads through a scene's use: and passes the scene reader's
# checks (the laws' keys, ranges and units), its dump loads again to the
# same dump, and the shot files' radii are those of the SAE J444 sizes
# (the size number is the nominal sieve opening in 1e-4 in, the radius
# half of it).  demform reads a kinematic law as its monotonic curve and
# says so.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
}

@test "library: every material file loads through use: and its dump loads again to the same dump" {
	n=0
	for f in "$DATA"/materials/*.yaml; do
		name=$(basename "$f" .yaml)
		printf 'material: {use: %s}\n' "$name" > "$T/s.yaml"
		run --separate-stderr demform -s "$T/s.yaml" --dump-scene
		echo "$name: status $status: $stderr"
		[ "$status" -eq 0 ]
		grep -q "^  use: $name" <<< "$output"
		grep -q '^  E: ' <<< "$output"
		# the dump without the use: line is a scene of its own
		grep -v '^  use: ' <<< "$output" > "$T/d.yaml"
		run --separate-stderr demform -s "$T/d.yaml" --dump-scene
		[ "$status" -eq 0 ]
		diff <(grep -v '^  use: ' "$T/d.yaml") <(printf '%s\n' "$output")
		n=$((n + 1))
	done
	[ "$n" -ge 8 ]
}

@test "library: the shot files give the SAE J444 radii" {
	n=0
	for f in "$DATA"/shots/S*.yaml; do
		size=$(basename "$f" .yaml)
		size=${size#S}
		printf 'shot: {use: S%s, speed: 50 m/s}\npack: {method: shots}\n' "$size" > "$T/s.yaml"
		run --separate-stderr dempack -s "$T/s.yaml" shots --dump-scene
		echo "S$size: status $status: $stderr"
		[ "$status" -eq 0 ]
		r=$(awk '$1 == "radius:" { print $2 }' <<< "$output")
		awk -v r="$r" -v s="$size" 'BEGIN { w = s * 1e-4 * 0.0254 / 2; d = r - w; exit !(d < 1e-12 && d > -1e-12) }'
		n=$((n + 1))
	done
	[ "$n" -eq 8 ]
}

@test "library: an unknown name is refused with the position of use: and the folder searched" {
	printf 'material:\n  use: Al9999\n' > "$T/s.yaml"
	run --separate-stderr demform -s "$T/s.yaml" --dump-scene
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == *"s.yaml:2:8: material.use: unknown library 'Al9999'"* ]]
	# the folder is the source tree's share/, or where the programs were
	# installed to (compiled in; DEM_DATA for a staged install)
	if [ -n "${DEM_TEST_DESTDIR:-}" ]; then
		[[ $stderr == *"no Al9999.yaml in $DATA/materials (from DEM_DATA)" ]]
	elif [ -n "${DEM_TEST_DATA:-}" ]; then
		[[ $stderr == *"no Al9999.yaml in $DATA/materials (the compiled-in data directory; "* ]]
	else
		[[ $stderr == *"no Al9999.yaml in $ROOT/share/materials (the source tree's share/ above the program, "* ]]
	fi
}

@test "demform: a kinematic law is read as its monotonic curve, and said so" {
	# one back-stress C 20 GPa, gamma 200 on a 100 MPa yield: its monotonic
	# curve is the Voce law 100 MPa + 100 MPa (1 - exp(-200 ep)); a profile
	# beyond it makes the strip flow, and both give the same strip
	cat > "$T/shape" <<-EOF
	0 -300 0.05
	0.1 -400 0.0375
	0.2 -350 0.025
	0.35 -150 0.0125
	0.5 30 0
	0.6 0 0
	EOF
	profile_stream "$T/shape" > "$T/prof"
	plate='plate: {size: [60 mm, 20 mm, 4 mm], element: 10 mm, layers: 8, grading: 1.3}'
	printf 'material: {E: 72 GPa, nu: 0.33, yield: 100 MPa, kinematic: {C: [20 GPa], gamma: [200]}}\n%s\n' "$plate" > "$T/k.yaml"
	printf 'material: {E: 72 GPa, nu: 0.33, law: voce, yield: 100 MPa, voce: {Q: 100 MPa, b: 200}}\n%s\n' "$plate" > "$T/v.yaml"
	run --separate-stderr demform -s "$T/k.yaml" --pass 2 "$T/prof"
	[ "$status" -eq 0 ]
	[[ $stderr == *"kinematic hardening read as its monotonic curve"* ]]
	hk=$(awk '$1 == "arc_height:" { print $2 }' <<< "$output")
	run --separate-stderr demform -s "$T/v.yaml" --pass 2 "$T/prof"
	[ "$status" -eq 0 ]
	hv=$(awk '$1 == "arc_height:" { print $2 }' <<< "$output")
	echo "kinematic $hk, Voce $hv"
	awk -v a="$hk" -v b="$hv" 'BEGIN { exit !(a > 0 && (a - b) / b < 1e-9 && (b - a) / b < 1e-9) }'
	# and the strip did flow: the elastic strip bends otherwise
	printf 'material: {E: 72 GPa, nu: 0.33}\n%s\n' "$plate" > "$T/e.yaml"
	run --separate-stderr demform -s "$T/e.yaml" --pass 2 "$T/prof"
	he=$(awk '$1 == "arc_height:" { print $2 }' <<< "$output")
	echo "elastic $he"
	awk -v a="$hk" -v b="$he" 'BEGIN { d = (a - b) / b; exit !(d > 1e-3 || d < -1e-3) }'
}
