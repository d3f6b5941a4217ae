#!/usr/bin/env bats
# Command-line tests of demshot (the explicit stage, loaded by pressure
# pulses).  References: the static uniaxial-strain solution of a laterally
# confined column under a uniform pressure p (sigma_zz = -p, sigma_xx =
# sigma_yy = -p nu / (1 - nu)); energy conservation of the central
# difference method; the exit codes of DESIGN.md.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	cat > "$T/col.yaml" <<'YAML'
material:
  E: 68 GPa
  nu: 0.3
  rho: 2700 kg/m^3
block:
  size: [0.8 mm, 0.8 mm, 1 mm]
  element: 0.2 mm
load:
  pressure: 100 MPa
run:
  end: 10 us
  damping: 1
YAML
	cat > "$T/pulse.yaml" <<'YAML'
material:
  E: 68 GPa
  nu: 0.3
  rho: 2700 kg/m^3
  yield: 157 MPa
  hardening: 120 MPa
block:
  size: [2 mm, 2 mm, 1 mm]
  element: 0.1 mm
  fine: [1 mm, 1 mm]
  fine_depth: 0.4 mm
  ratio: 1.3
load:
  pressure: 1 GPa
  area: [0.4 mm, 0.4 mm]
  times: [0, 0.1 us, 0.3 us, 0.4 us]
  factors: [0, 1, 1, 0]
run:
  end: 1 us
  frames: 2
YAML
}

@test "demshot: a confined column under a step pressure settles to the static uniaxial-strain stress" {
	run --separate-stderr bash -c "demshot -s '$T/col.yaml' | demprofile; echo \"\${PIPESTATUS[*]}\""
	echo "$stderr"
	[ "${lines[-1]}" = "0 0" ]
	# every layer: sxx = syy = -p nu/(1-nu) = -42857142.857 Pa, szz = -1e8 Pa, to 1e-6
	grep -v '^#' <<< "$output" | sed '$d' | awk '
		function bad(v, w) { d = v - w; if (d < 0) d = -d; return d > 1e-6 * (w < 0 ? -w : w) }
		{ n++; if (bad($3, -42857142.857142857) || bad($4, -42857142.857142857) || bad($5, -1e8)) { print "layer", n, $0; exit 1 } }
		END { if (n != 5) { print "layers:", n; exit 1 } }'
}

@test "demshot: the state stream has the requested frames at their times, readable by demprofile" {
	run --separate-stderr demshot -s "$T/pulse.yaml" -q -o "$T/p.state" --vtu "$T/p.vtu"
	echo "$stderr"
	[ "$status" -eq 0 ]
	[ -z "$output" ]
	[ -s "$T/p.state" ]
	grep -q '<Piece NumberOfPoints="2312" NumberOfCells="1792">' "$T/p.vtu"
	# gzip-compressed binary with the header of a state stream
	gzip -dc "$T/p.state" | head -1 | grep -qx '# dem state 1'
	gzip -dc "$T/p.state" | grep -a -m1 '^# area' | grep -q -- '-0.0002.* 0.0002'
	run --separate-stderr demprofile -v --pass all "$T/p.state"
	[ "$status" -eq 0 ]
	# one pass (1), profiled from its last frame
	[ "$(grep -v '^#' <<< "$output" | cut -d' ' -f1 | sort -u)" = 1 ]
	# the cost line: steps, cycles, energy error
	[[ ${stderr_lines[-1]} == "demprofile: cost: "* ]]
	run --separate-stderr demshot -s "$T/pulse.yaml" -o "$T/q.state"
	[[ ${stderr_lines[-1]} =~ ^demshot:\ cost:\ wall_s=.*\ steps=[0-9]+\ elements=1792\ elem_cycles=[0-9]+\ ns_per_elem_cycle=[0-9.]+\ energy_error= ]]
	grep -q "effects: J2 plasticity (linear hardening), large strain, one-point" <<< "$stderr"
}

@test "demshot: an elastic pulse without damping keeps the energy balance within 1 %" {
	sed -e '/yield/d' -e '/hardening/d' "$T/pulse.yaml" > "$T/el.yaml"
	run --separate-stderr demshot -s "$T/el.yaml" --end 2us -o "$T/el.state"
	[ "$status" -eq 0 ]
	err=$(sed -n 's/.*energy_error=\([0-9.e+-]*\).*/\1/p' <<< "${stderr_lines[-1]}")
	echo "energy error $err"
	awk -v e="$err" 'BEGIN { exit !(e < 1e-2) }'
}

@test "demshot: results do not depend on the number of threads" {
	demshot -s "$T/pulse.yaml" -q --threads 1 | demprofile | grep -v '^#' > "$T/one"
	demshot -s "$T/pulse.yaml" -q --threads 2 | demprofile | grep -v '^#' > "$T/two"
	[ -s "$T/one" ]
	cmp "$T/one" "$T/two"
}

@test "demshot: full integration and small strain run and are named in the effects" {
	run --separate-stderr demshot -s "$T/pulse.yaml" --rule full --strain small -o "$T/f.state"
	[ "$status" -eq 0 ]
	grep -q "small strain, full 2x2x2 B-bar integration" <<< "$stderr"
	run --separate-stderr demshot -s "$T/pulse.yaml" --accuracy fine --dump-scene
	[ "$status" -eq 0 ]
	grep -q "rule: full" <<< "$output"
	grep -q "end: 1e-06 s" <<< "$output"
}

@test "demshot: an inverted element stops the run with exit 3, naming element and time, and leaves no file" {
	# a huge pressure on a soft elastic block crushes the loaded elements
	sed -e '/yield/d' -e '/hardening/d' -e 's/pressure: 1 GPa/pressure: 1000 GPa/' "$T/pulse.yaml" > "$T/crush.yaml"
	run --separate-stderr demshot -s "$T/crush.yaml" --end 5us -o "$T/crush.state"
	echo "$stderr"
	[ "$status" -eq 3 ]
	[[ ${stderr_lines[-1]} == "demshot: "*"element "*"t = "* ]] || [[ ${stderr_lines[-1]} == "demshot: "*"element"*"time"* ]]
	[ ! -e "$T/crush.state" ]
	# on stdout the stream is cut before its trailer: demprofile refuses it
	run --separate-stderr bash -c "demshot -s '$T/crush.yaml' --end 5us -q | demprofile; echo \"\${PIPESTATUS[*]}\""
	[ "${lines[-1]}" = "3 1" ]
}

@test "demshot: a misspelt section is reported first, where it is, not as missing keys" {
	# the block section spelt 'blokc': without the check at load the first
	# message was 'block.size: missing'
	sed 's/^block:/blokc:/' "$T/pulse.yaml" > "$T/blokc.yaml"
	run --separate-stderr demshot -s "$T/blokc.yaml"
	echo "$stderr"
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[ "$(grep -c . <<< "$stderr")" -eq 1 ]
	[[ $stderr == "demshot: $T/blokc.yaml:7:1: unknown section 'blokc' (did you mean 'block'?); known sections: "* ]]
	[[ $stderr != *missing* ]]
	# the same for every program that reads a scene
	for p in dempack demdetect demprofile demform; do
		run --separate-stderr "$p" -s "$T/blokc.yaml" --dump-scene
		[ "$status" -eq 1 ]
		[[ $stderr == "$p: $T/blokc.yaml:7:1: unknown section 'blokc'"* ]]
	done
}

@test "demshot: scene errors are bad input naming the key and its place" {
	sed '/end:/d' "$T/pulse.yaml" > "$T/noend.yaml"
	run --separate-stderr demshot -s "$T/noend.yaml"
	[ "$status" -eq 1 ]
	[[ $stderr == *"run.end"*"missing"* ]]
	sed 's/element: 0.1 mm/elemnt: 0.1 mm/' "$T/pulse.yaml" > "$T/typo.yaml"
	run --separate-stderr demshot -s "$T/typo.yaml"
	[ "$status" -eq 1 ]
	[[ $stderr == *"block.element: missing"* ]]
	sed 's/frames: 2/frames: 2\n  framez: 3/' "$T/pulse.yaml" > "$T/typo2.yaml"
	run --separate-stderr demshot -s "$T/typo2.yaml"
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == *"typo2.yaml:21:3: unknown key 'run.framez'"* ]]
	printf 'load:\n  pressure: 1 GPa\n  area: [0.01 mm, 0.01 mm]\n  center: [0.1 mm, 0.1 mm]\n' > "$T/tinyload"
	sed '/^load:/,/factors/d' "$T/pulse.yaml" | cat - "$T/tinyload" > "$T/tiny.yaml"
	run --separate-stderr demshot -s "$T/tiny.yaml"
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == *"no face of the top"* ]]
}

@test "demshot: periodic sides run; a periodic side without its partner, or a periodic bottom, is bad input" {
	printf '  bc: {xmin: periodic, xmax: periodic, ymin: periodic, ymax: periodic}\n' > "$T/bc"
	sed '/^  ratio:/r '"$T/bc" "$T/pulse.yaml" > "$T/per.yaml"
	run --separate-stderr demshot -s "$T/per.yaml" -o "$T/per.state"
	echo "$stderr"
	[ "$status" -eq 0 ]
	[ -s "$T/per.state" ]
	sed 's/xmax: periodic/xmax: normal/' "$T/per.yaml" > "$T/half.yaml"
	run --separate-stderr demshot -s "$T/half.yaml" -o "$T/half.state"
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == *"block.bc.xmin: periodic needs block.bc.xmax periodic too"* ]]
	[ ! -e "$T/half.state" ]
	sed 's/ymax: periodic}/ymax: periodic, bottom: periodic}/' "$T/per.yaml" > "$T/bot.yaml"
	run --separate-stderr demshot -s "$T/bot.yaml"
	[ "$status" -eq 1 ]
	[[ $stderr == *"block.bc.bottom: the bottom cannot be periodic"* ]]
}

@test "demshot: usage errors exit 2" {
	usage_error demshot -s "$T/pulse.yaml" --rule twopoint
	usage_error demshot -s "$T/pulse.yaml" --threads 0
	usage_error demshot -s "$T/pulse.yaml" shots1 shots2
	usage_error demshot -s "$T/pulse.yaml" --lambda 0.6 "$T/none"
	usage_error demshot --bogus
}

@test "valgrind: demshot | demprofile run clean" {
	[ "${DEM_SANITIZE:-}" != 1 ] || skip "sanitizer build: ASan and valgrind do not mix"
	command -v valgrind >/dev/null || skip "valgrind is not installed"
	vg="valgrind -q --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite"
	run --separate-stderr bash -c "$vg demshot -s '$T/col.yaml' --end 1us --threads 1 -q | $vg demprofile; echo \"\${PIPESTATUS[*]}\""
	echo "$stderr"
	[ "${lines[-1]}" = "0 0" ]
}

# ---- the peening run (shots) ----------------------------------------------
# The Ch. 7.5 single shot (examples/ch75/scene.yaml: 0.5 mm radius, 19 m/s,
# aluminium E 68 GPa, yield 157 MPa, hardening 120 MPa; thesis-data.yaml) on
# a coarse block 2 x 2 x 1 mm of 0.1 mm elements (fine region 0.4 mm deep),
# passes of at most 20 us.

CH75=$SCENES/ch75

# scene_set SCENE KEY=VALUE...: SCENE with the keys set (scene.sh)
scene_set() {
	sh "$ROOT/examples/ch75/scene.sh" "$@"
}

shot_scene() {
	scene_set "$CH75/scene.yaml" "block.size=[2 mm, 2 mm, 1 mm]" "block.element=0.1 mm" \
		"block.fine_depth=0.4 mm" "run.pass_time=20 us" > "$T/shot.yaml"
	dempack -s "$T/shot.yaml" shots --grid 1 --passes 2 --area 0.2mm:0.2mm --seed 1 > "$T/s2.txt"
	dempack -s "$T/shot.yaml" shots --grid 2 --passes 1 --area 1mm:1mm --angle 60deg --shot-radius 0.25mm --seed 1 > "$T/s4.txt"
}

@test "demshot: shots from a stream, a frame per pass, the force history" {
	shot_scene
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/f.txt" -o "$T/s.state" "$T/s2.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q "shots: contact law m=1.5, partial potential, sphere/sphere (separation correction), lambda 0.2" <<< "$stderr"
	grep -q "time: elements .*%, contact (law m=1.5, partial potential) .*%" <<< "$stderr"
	[[ ${stderr_lines[-1]} =~ ^demshot:\ cost:\ .*\ passes=2\ .*contacts=[1-9] ]]
	# the frames carry the stream's passes 0 and 1, and its impact area
	[ "$(demprofile --pass all "$T/s.state" | grep -v '^#' | cut -d' ' -f1 | sort -u | tr '\n' ' ')" = "0 1 " ]
	gzip -dc "$T/s.state" | grep -a -m1 '^# area' | grep -q -- '-0.0001 -0.0001 0.0001 0.0001'
	# the history: rows while in contact, the normal force pushing the shot up
	head -1 "$T/f.txt" | grep -qx '# dem history 1'
	grep -q '^# columns pass:u32:- shot:u32:- t:f64:s fn:f64:N ft:f64:N fx:f64:N fy:f64:N fz:f64:N' "$T/f.txt"
	tail -1 "$T/f.txt" | grep -q '^# end [1-9]'
	grep -v '^#' "$T/f.txt" | awk '$4 < 0 || $8 < 0 { bad++ } $8 > m { m = $8 } END { exit !(bad == 0 && m > 10 && m < 1e4) }'
}

@test "demshot: friction absent and friction 0 give the same block; the log names the effects" {
	shot_scene
	scene_set "$T/shot.yaml" contact.friction=0 > "$T/mu0.yaml"
	scene_set "$T/shot.yaml" contact.friction=0.3 > "$T/mu3.yaml"
	run --separate-stderr demshot -s "$T/shot.yaml" -o "$T/a.state" "$T/s4.txt"
	[ "$status" -eq 0 ]
	run --separate-stderr demshot -s "$T/mu0.yaml" -o "$T/b.state" "$T/s4.txt"
	[ "$status" -eq 0 ]
	grep -q "contact law m=1.5, friction mu=0, partial potential" <<< "$stderr"
	run --separate-stderr demshot -s "$T/mu3.yaml" -o "$T/c.state" "$T/s4.txt"
	[ "$status" -eq 0 ]
	a=$(demprofile "$T/a.state" | grep -v '^#')
	b=$(demprofile "$T/b.state" | grep -v '^#')
	c=$(demprofile "$T/c.state" | grep -v '^#')
	[ "$a" = "$b" ]
	[ "$a" != "$c" ]
}

@test "demshot: the thesis's area partial contact scheme runs, is named in the log and changes the block" {
	shot_scene
	scene_set "$T/shot.yaml" contact.partial=area > "$T/area.yaml"
	run --separate-stderr demshot -s "$T/shot.yaml" -o "$T/p.state" "$T/s2.txt"
	[ "$status" -eq 0 ]
	grep -q "contact law m=1.5, partial potential" <<< "$stderr"
	run --separate-stderr demshot -s "$T/area.yaml" -o "$T/a.state" "$T/s2.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q "contact law m=1.5, partial area" <<< "$stderr"
	a=$(demprofile "$T/a.state" | grep -v '^#')
	p=$(demprofile "$T/p.state" | grep -v '^#')
	[ -n "$p" ]
	[ "$a" != "$p" ]
}

@test "demshot: lambda above 0.3 warns, above 0.5 is refused unless forced" {
	shot_scene
	run --separate-stderr demshot -s "$T/shot.yaml" --lambda 0.4 -q -o "$T/w.state" "$T/s2.txt"
	[ "$status" -eq 0 ]
	grep -q "warning" <<< "$stderr"
	run --separate-stderr demshot -s "$T/shot.yaml" --lambda 0.6 -o "$T/r.state" "$T/s2.txt"
	[ "$status" -eq 2 ]
	[ ! -e "$T/r.state" ]
	run --separate-stderr demshot -s "$T/shot.yaml" --lambda 0.6 --force -q -o "$T/r.state" --pass-time 2us "$T/s2.txt"
	[ "$status" -eq 0 ]
}

@test "demshot: a stream that is not a shot stream is bad input, with no output" {
	shot_scene
	dempack random -n 3 --seed 1 > "$T/p.txt" 2>/dev/null || skip "dempack random needs a scene"
	run --separate-stderr demshot -s "$T/shot.yaml" -o "$T/x.state" "$T/p.txt"
	[ "$status" -eq 1 ]
	grep -q "expected a shot stream" <<< "$stderr"
	[ ! -e "$T/x.state" ]
	head -c 300 "$T/s2.txt" > "$T/cut.txt"
	run --separate-stderr demshot -s "$T/shot.yaml" -o "$T/x.state" "$T/cut.txt"
	[ "$status" -eq 1 ]
	[ ! -e "$T/x.state" ]
}

# ---- checkpoints ----------------------------------------------------------
# Reference: the uninterrupted run; a run killed after the checkpoint of
# pass 2 (DEMSHOT_STOP_AFTER, SIGKILL) and resumed must give the same
# frames and force rows bit for bit.

# the rows of a state stream, decoded, without its header (provenance)
state_rows() {
	local off
	off=$(gzip -dc "$1" | grep -abo -m1 '^# data' | cut -d: -f1)
	gzip -dc "$1" | tail -c +$((off + 1)) | md5sum
}

ckpt_setup() {
	shot_scene
	dempack -s "$T/shot.yaml" shots --grid 1 --passes 3 --area 0.4mm:0.4mm --seed 1 > "$T/s3.txt"
	demshot -s "$T/shot.yaml" -q --forces "$T/fa.txt" -o "$T/a.state" "$T/s3.txt" 2> "$T/a.log"
	run --separate-stderr env DEMSHOT_STOP_AFTER=2 demshot -s "$T/shot.yaml" -q --forces "$T/fb.txt" --checkpoint "$T/ck" -o "$T/b.state" "$T/s3.txt"
	[ "$status" -eq 137 ]
	[ -s "$T/ck" ] && [ -s "$T/ck.journal" ]
	[ ! -e "$T/b.state" ] && [ ! -e "$T/fb.txt" ]
}

@test "demshot: a run killed after pass 2 and resumed gives the frames of the uninterrupted run bit for bit" {
	ckpt_setup
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 0 ]
	grep -q "resuming after pass 1 (2 passes done)" <<< "$stderr"
	[[ ${stderr_lines[-1]} =~ passes=3 ]]
	# only the last pass was run again: fewer element updates than the whole run
	full=$(grep -o 'elem_cycles=[0-9]*' "$T/a.log" | cut -d= -f2)
	part=$(grep -o 'elem_cycles=[0-9]*' <<< "${stderr_lines[-1]}" | cut -d= -f2)
	echo "element updates: whole run $full, resumed $part"
	[ "$part" -gt 0 ] && [ $((3 * part)) -lt $((2 * full)) ]
	# the cost line: this process's time, and the whole run's with the
	# killed process's two passes (its checkpoint carries them)
	[[ ${stderr_lines[-1]} =~ resumed_after=2 ]]
	awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
	     END { print "wall", v["wall_s"], "total", v["total_wall_s"], "cpu", v["cpu_s"], "total", v["total_cpu_s"]
		   exit !(v["total_wall_s"] > v["wall_s"] && v["total_cpu_s"] > v["cpu_s"]) }' <<< "${stderr_lines[-1]}"
	[ "$(state_rows "$T/a.state")" = "$(state_rows "$T/b.state")" ]
	[ "$(demprofile --pass all "$T/a.state" | grep -v '^#')" = "$(demprofile --pass all "$T/b.state" | grep -v '^#')" ]
	cmp <(grep -v '^# prog' "$T/fa.txt") <(grep -v '^# prog' "$T/fb.txt")
	# a finished run removes its checkpoint
	[ ! -e "$T/ck" ] && [ ! -e "$T/ck.journal" ]
	# 3 frames, the first two copied from the journal
	[ "$(demprofile --pass all "$T/b.state" | grep -v '^#' | cut -d' ' -f1 | sort -u | wc -l)" -eq 3 ]
}

@test "demshot: with back-stresses (Voce + kinematic, a rate law) a killed run resumes to the same frames bit for bit" {
	shot_scene
	scene_set "$T/shot.yaml" "material.law=voce" "material.voce={Q: 60 MPa, b: 20}" \
		"material.kinematic={C: [20 GPa, 1 GPa], gamma: [300, 10]}" \
		"material.rate={law: johnson-cook, C: 0.01, ref: 1 1/s}" > "$T/kin.yaml"
	dempack -s "$T/kin.yaml" shots --grid 1 --passes 3 --area 0.4mm:0.4mm --seed 1 > "$T/s3.txt"
	demshot -s "$T/kin.yaml" --forces "$T/fa.txt" -o "$T/a.state" "$T/s3.txt" 2> "$T/a.log"
	grep -q "effects: J2 plasticity (voce hardening), 2 back-stresses, rate dependence (johnson-cook)" "$T/a.log"
	run --separate-stderr env DEMSHOT_STOP_AFTER=2 demshot -s "$T/kin.yaml" -q --forces "$T/fb.txt" --checkpoint "$T/ck" -o "$T/b.state" "$T/s3.txt"
	[ "$status" -eq 137 ]
	run --separate-stderr demshot -s "$T/kin.yaml" -q --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	[ "$status" -eq 0 ]
	[ "$(state_rows "$T/a.state")" = "$(state_rows "$T/b.state")" ]
	cmp <(grep -v '^# prog' "$T/fa.txt") <(grep -v '^# prog' "$T/fb.txt")
	# and the back-stresses matter: the same run without them differs
	demshot -s "$T/shot.yaml" -q -o "$T/c.state" "$T/s3.txt"
	[ "$(state_rows "$T/a.state")" != "$(state_rows "$T/c.state")" ]
}

@test "demshot: a checkpoint of another scene or shot stream is refused with exit 1 and no output" {
	ckpt_setup
	scene_set "$T/shot.yaml" "run.pass_time=21 us" > "$T/other.yaml"
	run --separate-stderr demshot -s "$T/other.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "ck: the checkpoint is of another scene" <<< "$stderr"
	[ ! -e "$T/b.state" ]
	# the same stream but for the impact point of pass 1
	sed "s/^1 0 -9/1 0 -8/" "$T/s3.txt" > "$T/t3.txt"
	cmp -s "$T/s3.txt" "$T/t3.txt" && false
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/t3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "is of another shot stream" <<< "$stderr"
	run --separate-stderr demshot -s "$T/shot.yaml" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	[ "$status" -eq 1 ]
	grep -q "written with --forces" <<< "$stderr"
	[ ! -e "$T/b.state" ]
}

@test "demshot: a truncated or corrupt checkpoint or journal is refused with exit 1" {
	ckpt_setup
	cp "$T/ck" "$T/ck.good"
	cp "$T/ck.journal" "$T/j.good"
	n=$(stat -c %s "$T/ck")
	head -c $((n - 100)) "$T/ck.good" > "$T/ck"
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "checkpoint: truncated" <<< "$stderr"
	# one byte flipped in the middle of the model
	cp "$T/ck.good" "$T/ck"
	printf '\xff' | dd of="$T/ck" bs=1 seek=$((n / 2)) conv=notrunc 2> /dev/null
	cmp -s "$T/ck" "$T/ck.good" && false
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "checkpoint: corrupt (checksum mismatch)" <<< "$stderr"
	# a journal cut short
	cp "$T/ck.good" "$T/ck"
	head -c 1000 "$T/j.good" > "$T/ck.journal"
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "truncated journal" <<< "$stderr"
	[ ! -e "$T/b.state" ] && [ ! -e "$T/fb.txt" ]
	# an older demshot's checkpoint (version 1: no time spent in it)
	cp "$T/ck.good" "$T/ck"
	printf '\x01' | dd of="$T/ck" bs=1 seek=8 conv=notrunc 2> /dev/null
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 1 ]
	grep -q "an older demshot's: run it again without --resume" <<< "$stderr"
	# not a checkpoint at all
	cp "$T/s3.txt" "$T/ck"
	run --separate-stderr demshot -s "$T/shot.yaml" --forces "$T/fb.txt" --checkpoint "$T/ck" --resume -o "$T/b.state" "$T/s3.txt"
	[ "$status" -eq 1 ]
	grep -q "not a demshot checkpoint" <<< "$stderr"
}

@test "demshot: --resume needs --checkpoint; --checkpoint needs shots" {
	usage_error demshot -s "$T/pulse.yaml" --resume
	usage_error demshot -s "$T/pulse.yaml" --checkpoint "$T/ck"
}

@test "demshot/dempack: one shot section serves both programs, each checks its own keys, a typo is refused by both" {
	cat > "$T/both.yaml" <<'YAML'
material: {E: 68 GPa, nu: 0.33, rho: 2700 kg/m^3, yield: 157 MPa, hardening: 120 MPa}
block: {size: [1 mm, 1 mm, 0.5 mm], element: 0.1 mm}
run: {pass_time: 1 us}
shot:
  radius: 0.25 mm
  speed: 19 m/s
  density: 7800 kg/m^3
YAML
	dempack -s "$T/both.yaml" shots --grid 1 --passes 1 > "$T/s1.txt" 2>/dev/null
	run --separate-stderr demshot -s "$T/both.yaml" -q -o "$T/b.state" "$T/s1.txt"
	[ "$status" -eq 0 ]
	grep -v '^#' "$T/s1.txt" | awk '{ exit !($5 == 0.00025 && $8 == -19) }'
	# a value of the other program's key is that program's to check
	sed 's/density: 7800 kg\/m^3/density: -1 kg\/m^3/' "$T/both.yaml" > "$T/neg.yaml"
	dempack -s "$T/neg.yaml" shots --grid 1 --passes 1 > /dev/null 2>&1
	run --separate-stderr demshot -s "$T/neg.yaml" -q -o "$T/n.state" "$T/s1.txt"
	[ "$status" -eq 1 ]
	grep -q "shot.density" <<< "$stderr"
	printf '  densty: 1\n' >> "$T/both.yaml"
	run --separate-stderr dempack -s "$T/both.yaml" shots --grid 1
	[ "$status" -eq 1 ]
	grep -q "unknown key 'shot.densty'" <<< "$stderr"
	run --separate-stderr demshot -s "$T/both.yaml" -q -o "$T/c.state" "$T/s1.txt"
	[ "$status" -eq 1 ]
	grep -q "unknown key 'shot.densty'" <<< "$stderr"
}

@test "demshot: stopped by SIGTERM or SIGHUP, it leaves no temporary file behind" {
	# (SIGINT is guarded too, but a background job of a script ignores it.)
	# demshot leaves a signal that it inherits ignored as it is (nohup's
	# SIGHUP), so env resets both to their default: the test then holds
	# under nohup too.
	shot_scene
	for sig in TERM HUP; do
		rm -f "$T"/k.state*
		env --default-signal=TERM,HUP demshot -s "$T/shot.yaml" -q --pass-time 2000us \
			-o "$T/k.state" "$T/s2.txt" 2> /dev/null &
		pid=$!
		# writing: a named temporary, or (O_TMPFILE, lib/core/afile.c) an
		# unnamed file open in $T, which /proc shows as $T/#INODE (deleted)
		writing() { ls "$T"/k.state.tmp.* > /dev/null 2>&1 || ls -l /proc/$pid/fd 2> /dev/null | grep -q "$T/#"; }
		for i in $(seq 100); do writing && break; sleep 0.05; done
		writing
		kill -$sig $pid
		st=0
		wait $pid || st=$?
		echo "$sig: status $st"
		[ "$st" -gt 128 ]
		[ -z "$(ls "$T"/k.state* 2> /dev/null)" ]
	done
}
