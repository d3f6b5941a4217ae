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
	# no contact.partial: the potential scheme, the default (issue 18), in
	# the effects and the time lines
	grep -q 'effects: .*2D plane strain.*shots: contact law m=1.5 (2D), partial potential, disk/disk' <<< "$stderr"
	grep -q '^demshot: time: .*contact (law m=1.5 (2D), partial potential)' <<< "$stderr"
	demshot -s "$T/plane.yaml" --dump-scene | grep -qx '  partial: potential'
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

@test "twod: contact.partial area and width are taken in plane strain, named in the log, and keep the block's energy balance" {
	for p in area width; do
		printf 'contact:\n  partial: %s\n' "$p" | cat "$T/plane.yaml" - > "$T/$p.yaml"
		run --separate-stderr demshot -s "$T/$p.yaml" -o "$T/$p.state" "$T/shot.txt"
		echo "$p: $stderr"
		[ "$status" -eq 0 ]
		grep -q "effects: .*2D plane strain.*shots: contact law m=1.5 (2D), partial $p, disk/disk" <<< "$stderr"
		[[ $stderr =~ demshot:\ cost:\ .*energy_error=([0-9.e+-]+) ]]
		awk -v e="${BASH_REMATCH[1]}" 'BEGIN { exit !(e < 1e-4) }'
		[ -s "$T/$p.state" ]
	done
}

@test "twod: an axisymmetric block under a sphere on the axis runs; a shot off the axis is refused" {
	run --separate-stderr demshot -s "$T/axisym.yaml" -o "$T/a.state" "$T/shot.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q '^demshot: 2D axisymmetric block of' <<< "$stderr"
	grep -q 'one sphere on the axis' <<< "$stderr"
	# its one scheme, the ring's (shotset2d.h), named area; not a key there
	grep -q 'effects: .*2D axisymmetric.*shots: contact law m=1.5, partial area, one sphere' <<< "$stderr"
	[ "$(demshot -s "$T/axisym.yaml" --dump-scene | grep -c 'partial:')" -eq 0 ]
	printf 'contact:\n  partial: potential\n' | cat "$T/axisym.yaml" - > "$T/ap.yaml"
	run --separate-stderr demshot -s "$T/ap.yaml" -o "$T/ap.state" "$T/shot.txt"
	[ "$status" -eq 1 ] && [ ! -e "$T/ap.state" ]
	grep -q "ap.yaml:19:3: unknown key 'contact.partial'" <<< "$stderr"
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
	bad '$a contact:\n  partial: volume' 'contact.partial: expected one of potential, area, width'
	bad 's/fine: 1.5 mm/fine: 5 mm/' 'block.fine: the fine region'
}

# force_sums HISTORY: the disk's impact from a force history (one shot):
# "first last peak J negative fxmax" - the first and last times with a
# normal force (s), the peak fz and the impulse int fz dt (trapezoids over
# the rows, one a step while in contact), the rows with a negative or
# non-finite fz, the largest |fx| (N).
force_sums() {
	awk '!/^#/ { F = $8
		if (F !~ /^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$/ || F < 0) bad++
		if (F > 0) { if (t0 == "") t0 = $3; t1 = $3 }
		if (F > pk) pk = F
		if (n++) J += 0.5 * (F + Fp) * ($3 - tp)
		tp = $3; Fp = F; x = $6 < 0 ? -$6 : $6; if (x > fx) fx = x }
		END { print t0, t1, pk, J, bad + 0, fx + 0 }' "$1"
}

@test "twod: a disk on a soft penalty and an elastic block bounces as the spring-mass of its law (closed form)" {
	# Elastic block, no damping, the linear law at alpha 0.01 and the
	# Hertz-form law (m = 3/2) at alpha 0.05 of E (per unit length,
	# law.h), disk R = 0.5 mm, 7800 kg/m^3 (mu = rho pi R^2 per unit
	# length), 10 m/s.  On a rigid block the law alone gives, for
	# F = k delta^m: delta_max from k delta^(m+1) / (m+1) = mu v^2 / 2,
	# contact time 2 I delta_max / v with I = pi/2 (m = 1: pi sqrt(mu/k))
	# and 1.4716 (m = 3/2, B(2/5, 1/2) 2/5), peak k delta_max^m, impulse
	# 2 mu v.  The block's compliance, a strip load about 0.26 mm wide on
	# 2 mm of steel, (2 / (pi E')) ln(2 mm / 0.13 mm) ~ 1.6 / E, is 1.6 %
	# of the penalty's 1/(0.01 E): duration and peak within 3 %, the
	# rebound e = J / (mu v) - 1 within 3 % of 1 (the energy left ringing
	# in the block is of that order at most).
	sed 's/^  yield:.*//; s/^  hardening:.*//; s/^  damping: 0.3//; s/pass_time: 40 us/pass_time: 20 us\n  steady: 1e-9/' \
		"$T/plane.yaml" > "$T/el.yaml"
	for law in "1 0.01 1.5708" "1.5 0.05 1.4716"; do
		read -r m alpha I <<< "$law"
		printf 'contact:\n  law: power\n  m: %s\n  alpha: %s\n' "$m" "$alpha" >> "$T/el.yaml"
		run --separate-stderr demshot -s "$T/el.yaml" --forces "$T/f.txt" -o "$T/el.state" "$T/shot.txt"
		echo "m $m: $stderr"
		[ "$status" -eq 0 ]
		grep -q 'effects: elasticity, 2D plane strain' <<< "$stderr"
		read -r t0 t1 pk J bad fx <<< "$(force_sums "$T/f.txt")"
		echo "m $m: contact $t0 to $t1 s, peak $pk N, J $J N s, bad rows $bad"
		[ "$bad" -eq 0 ]
		awk -v m="$m" -v a="$alpha" -v I="$I" -v t0="$t0" -v t1="$t1" -v pk="$pk" -v J="$J" 'BEGIN {
			pi = 3.141592653589793; R = 0.0005; v = 10; th = 0.001
			mu = 7800 * pi * R * R; k = a * 210e9 * R^(1 - m)
			d = ((m + 1) * mu * v * v / (2 * k))^(1 / (m + 1))
			T = 2 * I * d / v; F = k * d^m * th; e = J / (mu * th * v) - 1
			printf "duration %g us (closed form %g), peak %g N (%g), e %g\n", (t1 - t0) * 1e6, T * 1e6, pk, F, e
			r1 = (t1 - t0) / T - 1; r2 = pk / F - 1
			exit !(r1 < 0.03 && r1 > -0.03 && r2 < 0.03 && r2 > -0.03 && e > 0.97 && e <= 1.0001) }'
		sed -i '/^contact:/,$d' "$T/el.yaml"
	done
}

@test "twod: the Ch. 7.4 shot, linear law at alpha 0.5 and 5: a bounce that the physics allows, a compressive layer" {
	# The scene of examples/twod (Han 2004, Ch. 7.4) with the thesis's
	# linear law (m = 1, k_n = alpha E), to 60 us (the contact lasts about
	# 40 us, README.md).  Checked from the force history: every normal
	# force finite and >= 0, fx zero to rounding (a centred disk on a
	# symmetric mesh); the impulse between m v and 2 m v (0 < e < 1: the
	# disk comes back, slower: the block keeps the plastic work); the
	# contact over before 60 us and longer than the bound of the yield-
	# limited contact, T >= (3 m v / (4 p sqrt(2 R v)))^(2/3) with
	# p = (2 + pi)/sqrt(3) sigma_max (the disk moves at most v T, so the
	# contact is at most 2 sqrt(2 R v T) wide, under at most the plane-
	# strain punch pressure at the largest flow stress of Table 7.1,
	# 892.684 MPa); the softer penalty touching longer (Ch. 7.4.1: alpha
	# 0.5 gives "a longer impact interval").  From the profile: sxx
	# compressive somewhere 1 to 4 mm under the disk (plastic indentation).
	printf '%s\n' '# dem shots 1' '# dim 3' \
		'# columns pass:u32:- t:f64:s x:f64:m y:f64:m r:f64:m vx:f64:m/s vy:f64:m/s vz:f64:m/s' \
		'# format text' '# data' '0 0 0 0 0.02 0 0 -12.2' '# end 1' > "$T/disk.txt"
	for a in 0.5 5; do
		sh "$ROOT/examples/ch75/scene.sh" "$SCENES/twod/scene.yaml" contact.m=1 "contact.alpha=$a" \
			'run.pass_time=60 us' > "$T/s$a.yaml"
		run --separate-stderr demshot -s "$T/s$a.yaml" --forces "$T/f$a.txt" -o "$T/s$a.state" "$T/disk.txt"
		echo "alpha $a: $stderr"
		[ "$status" -eq 0 ]
		read -r t0 t1 pk J bad fx <<< "$(force_sums "$T/f$a.txt")"
		echo "alpha $a: contact $t0 to $t1 s, peak $pk N, J $J N s, bad rows $bad, |fx| <= $fx N"
		[ "$bad" -eq 0 ]
		awk -v t0="$t0" -v t1="$t1" -v pk="$pk" -v J="$J" -v fx="$fx" 'BEGIN {
			pi = 3.141592653589793; R = 0.02; v = 12.2; th = 0.001
			mv = 7800 * pi * R * R * th * v; p = (2 + pi) / sqrt(3) * 892.684e6 * th
			tb = (3 * mv / (4 * p * sqrt(2 * R * v)))^(2 / 3)
			printf "e %g, duration %g us, bound %g us\n", J / mv - 1, (t1 - t0) * 1e6, tb * 1e6
			exit !(J > mv && J < 2 * mv && t1 < 59e-6 && t1 - t0 > tb && fx < 1e-6 * pk) }'
		echo "$t1 $t0" > "$T/d$a"
		run demprofile -q --area 1mm:1mm --margin 0 "$T/s$a.state"
		[ "$status" -eq 0 ]
		grep -v '^#' <<< "$output" | awk '$2 > 0.001 && $2 < 0.004 && $3 < 0 { c++ } END { exit !c }'
	done
	awk 'NR == FNR { d05 = $1 - $2; next } { exit !(d05 > $1 - $2) }' "$T/d0.5" "$T/d5"
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
