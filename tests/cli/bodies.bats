#!/usr/bin/env bats
# Command-line tests of demshot's DE-only run (a scene with bodies: rigid
# 2D superquadrics, polygons and disks with walls and gravity, Han 2004
# Ch. 4).  References: the resting depth of a disk on a floor under the
# linear law of Table 4.2 (F = kn bw, bw the chord: the centre settles at
# h = sqrt(r^2 - (m g / (2 kn))^2)); the body stream's frames and trailer
# (dem-streams(5)); the exit codes of DESIGN.md.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	cat > "$T/disk.yaml" <<'YAML'
bodies:
  shape: disk
  a: 5 mm
  density: 2500 kg/m^3
  at: [0 mm, 8 mm]
walls:
  segments: [-50 mm, 0 mm, 50 mm, 0 mm]
contact:
  law: linear
  kn: 1000 Pa
  damping: 0.5
run:
  gravity: [0, -9.81 m/s^2]
  end: 0.5 s
  frames: 5
YAML
	cat > "$T/box.yaml" <<'YAML'
bodies:
  shape: superquadric
  a: 4.5 mm
  b: 3.5 mm
  m: 5
  count: 12
  region: [-30 mm, 10 mm, 30 mm, 60 mm]
walls:
  segments: [-40 mm, 80 mm, -40 mm, 0 mm, -40 mm, 0 mm, 40 mm, 0 mm, 40 mm, 0 mm, 40 mm, 80 mm]
contact:
  kn: 1e5 Pa
  friction: 0.5
  damping: 0.8
run:
  gravity: [0, -9.81 m/s^2]
  end: 20 ms
  frames: 4
YAML
}

@test "bodies: a damped disk comes to rest on the floor at the depth of the linear law" {
	run --separate-stderr demshot -s "$T/disk.yaml" --seed 1 -o "$T/d.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	[[ $stderr == *"effects: gravity (0, -9.81) m/s^2, viscous damping xi=0.5"* ]]
	[[ $stderr == *"demshot: cost: "*"contacts="* ]]
	# the last frame's centre against the closed form (m = rho pi r^2)
	awk '!/^#/ && $1 == 5 {
		r = 0.005; m = 2500 * 3.141592653589793 * r * r; q = m * 9.81 / 2000
		h = sqrt(r * r - q * q); d = r - h
		printf "y %.9g h %.9g depth %.4g error %.3g\n", $9, h, d, ($9 - h) / d
		exit !(($9 - h) / d < 1e-3 && ($9 - h) / d > -1e-3 && $11 * $11 < 1e-12)
	}' "$T/d.txt"
}

@test "bodies: the body stream has each frame's rows, its times, the walls and its trailer" {
	run --separate-stderr demshot -s "$T/box.yaml" --seed 3 -o "$T/b.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	head -1 "$T/b.txt" | grep -qx '# dem bodies 1'
	grep -q '^# columns frame:u32:- t:f64:s id:u32:- shape:u32:- a:f64:m b:f64:m m:f64:- x:f64:m y:f64:m theta:f64:rad vx:f64:m/s vy:f64:m/s w:f64:rad/s$' "$T/b.txt"
	[ "$(grep -c '^# wall ' "$T/b.txt")" -eq 3 ]
	grep -q '^# prog demshot .* seed=3 ' "$T/b.txt"
	tail -1 "$T/b.txt" | grep -qx '# end 60'
	# 5 frames of 12 bodies, at 0, 5, 10, 15, 20 ms (to the step)
	awk '!/^#/ { n[$1]++; t[$1] = $2 } END {
		for (f = 0; f <= 4; f++) if (n[f] != 12 || (t[f] - 0.005 * f)^2 > 1e-8) exit 1 }' "$T/b.txt"
	# binary and gzip carry the same rows
	run --separate-stderr demshot -s "$T/box.yaml" --seed 3 -z -q -o "$T/b.gz"
	[ "$status" -eq 0 ]
	cmp <(grep -v '^# \(prog\|format\)' "$T/b.txt") <(zcat "$T/b.gz" | grep -v '^# \(prog\|format\)')
}

@test "bodies: friction absent and friction 0 give the same stream; damping absent and 0 too" {
	demshot -s "$T/box.yaml" --seed 5 -q -o "$T/f.txt"
	sed 's/friction: 0.5/friction: 0/' "$T/box.yaml" > "$T/f0.yaml"
	sed '/friction: 0.5/d' "$T/box.yaml" > "$T/fa.yaml"
	demshot -s "$T/f0.yaml" --seed 5 -q -o "$T/f0.txt"
	demshot -s "$T/fa.yaml" --seed 5 -q -o "$T/fa.txt"
	cmp <(grep -v '^# prog' "$T/f0.txt") <(grep -v '^# prog' "$T/fa.txt")
	! cmp -s <(grep -v '^# prog' "$T/f.txt") <(grep -v '^# prog' "$T/fa.txt")
	sed 's/damping: 0.8/damping: 0/' "$T/fa.yaml" > "$T/d0.yaml"
	sed '/damping: 0.8/d' "$T/fa.yaml" > "$T/da.yaml"
	demshot -s "$T/d0.yaml" --seed 5 -q -o "$T/d0.txt"
	run --separate-stderr demshot -s "$T/da.yaml" --seed 5 -o "$T/da.txt"
	[[ $stderr == *"effects: gravity (0, -9.81) m/s^2;"* || $stderr == *"effects: gravity (0, -9.81) m/s^2"$'\n'* ]]
	cmp <(grep -v '^# prog' "$T/d0.txt") <(grep -v '^# prog' "$T/da.txt")
}

@test "bodies: --vtu writes the last frame as polygons; --dump-scene shows the defaults" {
	run --separate-stderr demshot -s "$T/box.yaml" --seed 1 -q -o "$T/v.txt" --vtu "$T/v.vtu"
	[ "$status" -eq 0 ]
	grep -q 'NumberOfCells="15"' "$T/v.vtu"
	run --separate-stderr demshot -s "$T/box.yaml" --dump-scene
	[ "$status" -eq 0 ]
	[[ $output == *"tau: 0.01"* ]]
	[[ $output == *"lambda: 0.2"* ]]
	[[ $output == *"density: 2500 kg/m^3"* ]]
}

@test "bodies: scene mistakes are bad input naming file:line:col, with no output" {
	sed 's/^  m: 5/  m: 5\n  colour: red/' "$T/box.yaml" > "$T/k.yaml"
	run --separate-stderr demshot -s "$T/k.yaml" -o "$T/k.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == "demshot: $T/k.yaml:6:3: unknown key 'bodies.colour'"* ]]
	[ ! -e "$T/k.txt" ]
	sed '/kn:/d' "$T/box.yaml" > "$T/nokn.yaml"
	run --separate-stderr demshot -s "$T/nokn.yaml"
	[ "$status" -eq 1 ]
	[[ $stderr == *"contact.kn: missing"* ]]
	[ -z "$output" ]
	sed 's/count: 12/count: 500/' "$T/box.yaml" > "$T/full.yaml"
	run --separate-stderr demshot -s "$T/full.yaml"
	[ "$status" -eq 1 ]
	[[ $stderr == *"full.yaml:7:11: bodies.region: room for "*" 500 asked for"* ]]
	sed 's/kn: 1e5 Pa/kn: 1e-3 Pa/' "$T/box.yaml" > "$T/soft.yaml"
	run --separate-stderr demshot -s "$T/soft.yaml"
	[ "$status" -eq 3 ]
	[[ $stderr == *"cannot stop a body"* ]]
}

@test "bodies: a shot stream, --forces or --checkpoint with a bodies scene is a usage error" {
	usage_error demshot -s "$T/box.yaml" /dev/null
	usage_error demshot -s "$T/box.yaml" --forces "$T/f"
	usage_error demshot -s "$T/box.yaml" --checkpoint "$T/c"
}
