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

# ---- checkpoints (issue 18, item 2) ----------------------------------------
# Reference: the uninterrupted run.  A 2D run stopped after a pass's
# checkpoint (DEMSHOT_STOP_AFTER: SIGKILL from inside; or SIGTERM from
# outside while a later pass runs) and resumed must write the same state
# stream, decoded, byte for byte apart from its provenance line (the
# arguments differ), and the same force history.

# three passes of the plane block: two disks a pass (disk/disk contact,
# oblique), Coulomb friction and contact damping, so that the checkpoint
# must carry the shots' and the block's whole state
twod_passes() {
	cp "$T/plane.yaml" "$T/fr.yaml"
	printf 'contact:\n  friction: 0.3\n  damping: 0.1\n' >> "$T/fr.yaml"
	sed '/^0 0 0 0/,$d' "$T/shot.txt" > "$T/s6.txt"
	cat >> "$T/s6.txt" <<'TXT'
0 0 0 0 0.0005 0 0 -10
0 0 0.0004 0 0.0003 -2 0 -10
1 0 0.0002 0 0.0005 0 0 -10
1 1e-6 0.0002 0 0.0005 0 0 -10
2 0 -0.0002 0 0.0005 3 0 -10
2 0 0.0005 0 0.0004 -3 0 -8
# end 6
TXT
	# the axisymmetric block: one sphere a pass on the axis
	sed '/^0 0 0 0/,$d' "$T/shot.txt" > "$T/a3.txt"
	cat >> "$T/a3.txt" <<'TXT'
0 0 0 0 0.0005 0 0 -10
1 0 0 0 0.0004 0 0 -12
2 0 0 0 0.0005 0 0 -10
# end 3
TXT
}

# same_run A B: the decoded state streams A.state and B.state are equal
# but for their '# prog' line, and so are the force histories A.txt, B.txt
same_run() {
	cmp <(gzip -dc "$T/$1.state" | grep -av '^# prog') <(gzip -dc "$T/$2.state" | grep -av '^# prog')
	cmp <(grep -v '^# prog' "$T/$1.txt") <(grep -v '^# prog' "$T/$2.txt")
}

@test "twod: a 2D run killed after pass 2 and resumed writes the uninterrupted run's streams bit for bit" {
	twod_passes
	for c in "fr.yaml s6.txt" "axisym.yaml a3.txt"; do
		set -- $c
		rm -f "$T"/ck* "$T"/[ab].state "$T"/[ab].txt
		demshot -s "$T/$1" -q --forces "$T/a.txt" -o "$T/a.state" "$T/$2"
		run --separate-stderr env DEMSHOT_STOP_AFTER=2 demshot -s "$T/$1" -q --forces "$T/b.txt" \
			--checkpoint "$T/ck" -o "$T/b.state" "$T/$2"
		[ "$status" -eq 137 ]
		[ -s "$T/ck" ] && [ ! -e "$T/b.state" ] && [ ! -e "$T/b.txt" ]
		run --separate-stderr demshot -s "$T/$1" --forces "$T/b.txt" --checkpoint "$T/ck" --resume \
			-o "$T/b.state" "$T/$2"
		echo "$1: $stderr"
		[ "$status" -eq 0 ]
		grep -q "resuming after pass 1 (2 passes done)" <<< "$stderr"
		[[ ${stderr_lines[-1]} =~ resumed_after=2 ]]
		same_run a b
		[ ! -e "$T/ck" ]
		# the frames differ from pass to pass: the comparison sees them
		[ "$(demprofile --pass all "$T/b.state" | grep -v '^#' | cut -d' ' -f1 | sort -u | wc -l)" -eq 3 ]
	done
	# a plane-strain checkpoint is not the axisymmetric scene's
	rm -f "$T/b.state"
	run --separate-stderr env DEMSHOT_STOP_AFTER=1 demshot -s "$T/fr.yaml" -q --checkpoint "$T/ck" \
		-o "$T/b.state" "$T/s6.txt"
	[ "$status" -eq 137 ]
	run --separate-stderr demshot -s "$T/axisym.yaml" -q --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/a3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "ck: the checkpoint is of another scene" <<< "$stderr"
	[ ! -e "$T/b.state" ]
}

@test "twod: a 2D run stopped by SIGTERM during a pass resumes from its last checkpoint to the same streams" {
	twod_passes
	# passes of 100 us each (about half a second here), so that the
	# signal finds the run in its second or third pass
	sed 's/pass_time: 40 us/pass_time: 100 us\n  steady: 1e-30/' "$T/fr.yaml" > "$T/long.yaml"
	demshot -s "$T/long.yaml" -q --forces "$T/a.txt" -o "$T/a.state" "$T/s6.txt"
	demshot -s "$T/long.yaml" -q --forces "$T/b.txt" --checkpoint "$T/ck" -o "$T/b.state" "$T/s6.txt" &
	pid=$!
	for _ in $(seq 400); do
		[ -e "$T/ck" ] && break
		sleep 0.02
	done
	[ -e "$T/ck" ]
	kill -s TERM "$pid"
	st=0
	wait "$pid" || st=$?
	echo "SIGTERM: exit $st"
	[ "$st" -gt 128 ] || [ "$st" -eq 0 ]
	if [ "$st" -ne 0 ]; then
		[ -z "$(find "$T" -maxdepth 1 -name '*.tmp.*')" ]
		[ -s "$T/ck" ] && [ ! -e "$T/b.state" ]
		run --separate-stderr demshot -s "$T/long.yaml" --forces "$T/b.txt" --checkpoint "$T/ck" \
			--resume -o "$T/b.state" "$T/s6.txt"
		echo "$stderr"
		[ "$status" -eq 0 ]
		grep -q "resuming after pass" <<< "$stderr"
	fi
	same_run a b
}

@test "twod: demshot | demprofile | demform on a plane-strain block forms a plane-strain strip (kappa_y 0)" {
	cat > "$T/strip.yaml" <<-EOF
	material: {E: 210 GPa, nu: 0.3}
	plate: {size: [40 mm, 4 mm, 2 mm], element: 2 mm, layers: 12}
	EOF
	run --separate-stderr bash -c "demshot -s '$T/plane.yaml' -q '$T/shot.txt' | demprofile | demform -s '$T/strip.yaml'"
	echo "$output"; echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q 'plane strain along y (the profile is of a 2D plane-strain block)' <<< "$stderr"
	echo "$output" > "$T/sum"
	[ "$(value plane_strain "$T/sum")" = true ]
	awk -v x="$(value curvature_x "$T/sum")" -v y="$(value curvature_y "$T/sum")" \
		'BEGIN { exit !(x != 0 && y < 1e-9 * (x > 0 ? x : -x) && y > -1e-9 * (x > 0 ? x : -x)) }'
}
