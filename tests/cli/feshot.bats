#!/usr/bin/env bats
# Command-line tests of demshot's FE shot (shot.model: fe, issue 18,
# Ch. 7.4): twod.bats's small plane-strain block struck by one disk of
# 0.5 mm at 10 m/s, the disk meshed as an elastic FE shot (E_s = 100 E).
# References: the energy balance of the block (explicit2d.h: |balance| /
# scale small); the shot's element count (mesh2.h); the force history's rows (the shot pushed up, fy zero,
# fn the resultant's magnitude, ft zero: no friction); the state stream
# read by demprofile; the exit codes of DESIGN.md for what an FE shot
# refuses (dem-scene(5), demshot(1)).

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	cat > "$T/fe.yaml" <<'YAML'
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
shot:
  model: fe
  element: 0.1 mm
contact:
  damping: 0.3
run:
  damping: 0.3
  pass_time: 40 us
YAML
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

@test "feshot: a plane-strain block under one FE shot runs end to end; the force history and the profile" {
	run --separate-stderr bash -c "demshot -s '$T/fe.yaml' --forces '$T/f.txt' '$T/shot.txt' | tee '$T/p.state' | demprofile; echo \"\${PIPESTATUS[*]}\""
	echo "$stderr"
	[ "${lines[-1]}" = "0 0 0" ]
	grep -q 'shots: FE disks (E_s = 100 E, element 0.0001 m), node-to-segment penalty' <<< "$stderr"
	# the shot's O-grid: n = 8 a quarter, m = 3 (mesh2.h): 4 n m + n^2
	grep -q 'demshot: cost: .* shot_elements=160 ' <<< "$stderr"
	[[ $stderr =~ demshot:\ cost:\ .*energy_error=([0-9.e+-]+) ]]
	awk -v e="${BASH_REMATCH[1]}" 'BEGIN { exit !(e < 1e-4) }'
	# the history: the shot pushed up (fz > 0), fy and ft zero, fn = |F|
	grep -v '^#' "$T/f.txt" | awk '$8 > m { m = $8 }
		$7 != 0 || $5 != 0 || ($4 - sqrt($6 * $6 + $8 * $8)) ^ 2 > 1e-12 * $4 * $4 { bad++ }
		END { exit !(NR > 10 && bad == 0 && m > 10 && m < 1e5) }'
	# the profile: the 12 element layers (the contact, about 0.06 mm wide,
	# is less than an element here: its physics is test_feshot2d's)
	[ "$(sed '$d' <<< "$output" | grep -vc '^#')" -eq 12 ]
}

@test "feshot: what an FE shot refuses exits 1 with the key and no output" {
	bad() {  # bad SED-SCRIPT MESSAGE
		sed "$1" "$T/fe.yaml" > "$T/bad.yaml"
		run --separate-stderr demshot -s "$T/bad.yaml" -o "$T/bad.state" "$T/shot.txt"
		echo "$1 -> $status: $stderr"
		[ "$status" -eq 1 ] && [ -z "$output" ] && [ ! -e "$T/bad.state" ] &&
			[[ $stderr == *"$2"* ]]
	}
	bad 's/model: fe/model: soft/' 'bad.yaml:17:10: shot.model: expected one of rigid, fe'
	bad 's/mode: plane/mode: axisym/; /thickness:/d' 'shot.model: FE shots need a plane strain block'
	bad 's/^contact:/contact:\n  m: 1/' 'bad.yaml:20:6: contact.m: an FE shot'"'"'s penalty is the Winkler form'
	bad 's/^contact:/contact:\n  law: hertz/' 'bad.yaml:20:8: contact.law: an FE shot'"'"'s penalty'
	bad 's/^contact:/contact:\n  friction: 0.1/' 'bad.yaml:20:13: contact.friction: no friction with an FE shot'
	bad '/^shot:/,/^contact:/s/element: 0.1 mm/element: -1 mm/' 'bad.yaml:18:12: shot.element: -1 mm'
}
