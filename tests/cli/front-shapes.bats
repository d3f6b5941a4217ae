#!/usr/bin/env bats
# Command-line tests of dempack front --shape polygon|ellipse (Han 2004,
# Ch. 5.3-5.4).  References: the body stream of dem-streams(5) (its
# columns, shape codes and trailer), the size and aspect laws of
# dempack(1) (a b = r^2 with r in [rmin, rmax], a / b in [ratio-min,
# ratio-max]), the exit codes of DESIGN.md.  That no two bodies overlap is
# checked exactly in tests/unit/test_front_shapes.c.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
}

# Every row of body stream $1: shape $2, m $3, sizes in [$4, $5], ratios
# in [$6, $7] (to 1e-12), centre inside [0, $8]^2; the trailer counts the
# rows.  Prints the number of rows.
check_bodies() {
	awk -v sh="$2" -v m="$3" -v r0="$4" -v r1="$5" -v a0="$6" -v a1="$7" -v w="$8" '
	/^# end / { end = $3; next }
	/^#/ { next }
	{ n++
	  if ($4 != sh || $7 != m) { print "row " n ": shape " $4 " m " $7; bad = 1 }
	  r = sqrt($5 * $6); q = $5 / $6
	  if (r < r0 * (1 - 1e-12) || r > r1 * (1 + 1e-12)) { print "row " n ": size " r; bad = 1 }
	  if (q < a0 * (1 - 1e-12) || q > a1 * (1 + 1e-12)) { print "row " n ": ratio " q; bad = 1 }
	  if ($8 < 0 || $8 > w || $9 < 0 || $9 > w) { print "row " n ": centre outside"; bad = 1 }
	  if ($11 != 0 || $12 != 0 || $13 != 0) { print "row " n ": moving"; bad = 1 }
	}
	END { if (end != n || n == 0) { print "trailer " end ", rows " n; bad = 1 }
	      if (bad) exit 1; print n }' "$1"
}

@test "dempack front --shape polygon: a body stream of stretched m-gons with the laws' sizes and ratios" {
	dempack front --shape polygon --sides 5 --ratio-min 1.5 --ratio-max 4 --domain 0:0:10:10 \
		--rmin 0.2 --lambda 2 --seed 3 -q >"$T/p"
	head -1 "$T/p" | grep -qx '# dem bodies 1'
	grep -q '^# bodies shape=polygon sides=5 ratio_law=urd ratio_min=1.5 ratio_max=4$' "$T/p"
	[ "$(grep -c '^# wall ' "$T/p")" -eq 4 ]
	n=$(check_bodies "$T/p" 1 5 0.2 0.4 1.5 4 10)
	[ "$n" -gt 200 ]
	# the density of the header: the polygons' area over the square's
	awk '/^# density/ { d = $3 } /^#/ { next }
	     { s += $5 * $6 * 2.5 * sin(2 * 3.14159265358979 / 5) }
	     END { if ((s / 100 - d) ^ 2 > 1e-16 || d < 0.4) exit 1 }' "$T/p"
}

@test "dempack front --shape ellipse: closed, open and gravity forms; Newton's counts in the cost line" {
	for f in "--form closed" "--form open" "--gravity"; do
		run --separate-stderr dempack front --shape ellipse --ratio-max 5 --domain 0:0:12:12 \
			--rmin 0.2 --lambda 2 --seed 2 $f
		[ "$status" -eq 0 ]
		printf '%s\n' "$output" >"$T/e"
		n=$(check_bodies "$T/e" 0 2 0.2 0.4 1 5 12)
		[ "$n" -gt 100 ]
		cost=${stderr_lines[-1]}
		[[ $cost == "dempack: cost: "*" newton="*" newton_steps="*" newton_refused="*" fallbacks="* ]]
	done
}

@test "dempack front: the shape keys in a scene give the options' bodies; the same seed the same stream" {
	printf 'pack:\n  method: front\n  shape: polygon\n  sides: 4\n  domain: [0, 0, 8 m, 8 m]\n  radius: {min: 0.25 m, lambda: 1.5}\n  ratio: {law: mono, min: 2}\n' >"$T/s.yaml"
	dempack front -s "$T/s.yaml" --seed 4 -q | grep -v '^# prog' >"$T/a"
	dempack front --shape polygon --sides 4 --domain 0:0:8:8 --rmin 0.25 --lambda 1.5 \
		--ratio-law mono --ratio-min 2 --seed 4 -q | grep -v '^# prog' >"$T/b"
	cmp "$T/a" "$T/b"
	check_bodies "$T/a" 1 4 0.25 0.375 2 2 8
	# a polygon domain: the walls are its edges, anticlockwise
	dempack front --shape ellipse --ratio-max 2 --polygon 0:0:0:4:4:4:4:0 --rmin 0.2 --seed 1 -q >"$T/c"
	grep -q '^# wall 4 0 4 4 ' "$T/c"
	check_bodies "$T/c" 0 2 0.2 0.2 1 2 4
}

@test "dempack front --shape: bad shapes, sides and ratios are refused without output" {
	usage_error dempack front --sides 5
	usage_error dempack front --shape ellipse --sides 5
	usage_error dempack front --ratio-max 2
	for a in "--shape cube" "--shape polygon --sides 2" "--shape polygon --sides 65" \
		 "--shape ellipse --ratio-min 0.5" "--shape ellipse --ratio-min 3 --ratio-max 2"; do
		# a bad value given on the command line is a usage error
		run --separate-stderr dempack front $a -o "$T/x"
		[ "$status" -eq 2 ]
		[ ! -e "$T/x" ]
		[[ ${stderr_lines[0]} == "dempack: "* ]]
	done
	printf 'pack:\n  method: front\n  shape: ellipse\n  ratio:\n    min: 3\n    max: 2\n' >"$T/s.yaml"
	run --separate-stderr dempack front -s "$T/s.yaml" -o "$T/x"
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == "dempack: $T/s.yaml:6:"*"pack.ratio.max"* ]]
	# --vtk draws disks: with --shape typed, a usage error; with the
	# shape from the scene, a bad input
	usage_error dempack front --shape ellipse --vtk "$T/v.vtk" -o "$T/x"
	[[ ${stderr_lines[0]} == *"--vtk: disks only"* ]]
	[ ! -e "$T/x" ] && [ ! -e "$T/v.vtk" ]
	dempack front --shape disk --vtk "$T/v.vtk" --rmin 0.1 -q -o "$T/x"
	[ -s "$T/v.vtk" ] && [ -s "$T/x" ]
	rm -f "$T/x" "$T/v.vtk"
	printf 'pack:\n  method: front\n  shape: ellipse\n' >"$T/e.yaml"
	run --separate-stderr dempack front -s "$T/e.yaml" --vtk "$T/v.vtk" -o "$T/x"
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == *"--vtk: disks only"* ]]
	[ ! -e "$T/x" ] && [ ! -e "$T/v.vtk" ]
}
