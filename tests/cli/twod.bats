#!/usr/bin/env bats
# Command-line tests of demshot on a 2D scene (dim: 2, issue 18): a small
# plane-strain block of steel struck by one disk from a shot stream written
# by hand (dem-streams(5)), and its axisymmetric twin struck by a sphere on
# the axis.  References: the energy balance of the central difference
# method (explicit2d.h: |balance| / scale small); the state stream read by
# demprofile unchanged (a 3D grid one element thick); the exit codes of
# DESIGN.md with file:line:col for a bad scene.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	cat > "$T/plane.yaml" <<'YAML'
dim: 2
material:
  E: 210 GPa
  nu: 0.3
  rho: 7800 kg/m^3
  yield: 350 MPa
  hardening: 1 GPa
block:
  mode: plane
  size: [4 mm, 2 mm]
  thickness: 1 mm
  element: 0.1 mm
  fine: 1.5 mm
  fine_depth: 0.6 mm
  ratio: 1.3
run:
  damping: 0.3
  pass_time: 40 us
YAML
	sed 's/mode: plane/mode: axisym/; /thickness:/d' "$T/plane.yaml" > "$T/axisym.yaml"
	# one shot of 0.5 mm at 10 m/s straight down on x = 0 (y and vy unused)
	cat > "$T/shot.txt" <<'TXT'
# dem shots 1
# dim 3
# columns pass:u32:- t:f64:s x:f64:m y:f64:m r:f64:m vx:f64:m/s vy:f64:m/s vz:f64:m/s
# format text
# data
0 0 0 0 0.0005 0 0 -10
# end 1
TXT
}

@test "twod: a plane-strain block under one disk runs end to end; demprofile reads its state stream" {
	run --separate-stderr bash -c "demshot -s '$T/plane.yaml' --forces '$T/f.txt' '$T/shot.txt' | tee '$T/p.state' | demprofile; echo \"\${PIPESTATUS[*]}\""
	echo "$stderr"
	[ "${lines[-1]}" = "0 0 0" ]
	grep -q '^demshot: 2D plane strain block of 300 elements (25 x 12)' <<< "$stderr"
	grep -q 'effects: .*2D plane strain.*shots: contact law m=1.5 (2D), partial area, disk/disk' <<< "$stderr"
	# the block's energy balance, relative to its scale
	[[ $stderr =~ demshot:\ cost:\ .*energy_error=([0-9.e+-]+) ]]
	awk -v e="${BASH_REMATCH[1]}" 'BEGIN { exit !(e < 1e-4) }'
	# the state stream: a 3D grid one element thick, marked 2D
	gzip -dc "$T/p.state" | grep -a -m1 '^# grid' | grep -qx '# grid 25 1 12'
	gzip -dc "$T/p.state" | grep -a -m1 '^# twod' | grep -qx '# twod mode=plane thickness=0.001'
	grep -qx '# average layers area=stream' <<< "$output"
	# the profile: 12 element layers, compressive near the surface
	[ "$(sed '$d' <<< "$output" | grep -vc '^#')" -eq 12 ]
	grep -v '^#' <<< "$output" | head -1 | awk '{ exit !($3 < 0) }'
	# the history: the disk pushed up (fz > 0, N on the 1 mm slab), fy zero
	grep -v '^#' "$T/f.txt" | awk '$8 > m { m = $8 } $7 != 0 || $8 < 0 { bad++ }
		END { exit !(bad == 0 && m > 10 && m < 1e5) }'
}

@test "twod: an axisymmetric block under a sphere on the axis runs; a shot off the axis is refused" {
	run --separate-stderr demshot -s "$T/axisym.yaml" -o "$T/a.state" "$T/shot.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q '^demshot: 2D axisymmetric block of' <<< "$stderr"
	grep -q 'one sphere on the axis' <<< "$stderr"
	gzip -dc "$T/a.state" | grep -a -m1 '^# twod' | grep -qx '# twod mode=axisym'
	# no impact area in the shot stream: the whole top face, the disk of
	# the block's radius (x from -4 to 4 mm), all of the layer in y
	gzip -dc "$T/a.state" | grep -a -m1 '^# area' | awk '{ exit !($3 == -0.004 && $4 == -5e-05 && $5 == 0.004 && $6 == 5e-05) }'
	# demprofile averages it by ring (demprofile(1)); the plane one not
	demprofile "$T/a.state" 2>/dev/null | grep -qx '# average layers area=stream weight=ring'
	sed 's/^0 0 0 0 0.0005 0 0 -10$/0 0 0.0001 0 0.0005 0 0 -10/' "$T/shot.txt" > "$T/off.txt"
	run --separate-stderr demshot -s "$T/axisym.yaml" -o "$T/b.state" "$T/off.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q 'an axisymmetric shot moves on the axis' <<< "$stderr"
	[ ! -e "$T/b.state" ]
}

@test "twod: bad 2D scenes exit 1 with file:line:col and no output" {
	bad() {  # bad SED-SCRIPT MESSAGE
		sed "$1" "$T/plane.yaml" > "$T/bad.yaml"
		run --separate-stderr demshot -s "$T/bad.yaml" -o "$T/bad.state" "$T/shot.txt"
		echo "$1 -> $status: $stderr"
		[ "$status" -eq 1 ] && [ -z "$output" ] && [ ! -e "$T/bad.state" ] &&
			[[ $stderr == *"$2"* ]]
	}
	bad 's/^dim: 2/dim: 4/' 'bad.yaml:1:6: dim: 4 is out of range'
	bad 's/size: \[4 mm, 2 mm\]/size: [4 mm, 2 mm, 1 mm]/' 'bad.yaml:10:9: block.size: expected 2 lengths'
	bad 's/mode: plane/mode: planar/' 'bad.yaml:9:9: block.mode: expected one of plane, axisym'
	bad 's/^run:/block2:/' "bad.yaml:16:1: unknown section 'block2'"
	bad '$a load:\n  pressure: 1 GPa' 'load: a 2D block (dim: 2) takes shots only'
	bad '$a contact:\n  partial: volume' 'contact.partial: expected one of area, width'
	bad 's/fine: 1.5 mm/fine: 5 mm/' 'block.fine: the fine region'
}
