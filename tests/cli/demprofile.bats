#!/usr/bin/env bats
# Command-line tests of demprofile.  References: Han 2004, Ch. 8.4 (profiles
# are averages over the elements of the impacted region at each depth);
# demprofile(1) for the region, margins, bins, passes and tables; the exit
# codes of DESIGN.md.  The state streams are synthetic, written by awk, with
# values known per layer and column, so every average is known exactly.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
}

# state_stream NX NY NZ H PASSES [UZ]: a text state stream of a uniform block
# of NX x NY x NZ elements of size H (m), x and y centred on 0, top face
# z = 0.  Frame of pass p (1..PASSES), element (i, j, k), kd = NZ-1-k its
# layer counted from the top:
#   sxx = -1e6 (10 kd + p), syy = 1000 i, szz = -1e6 kd, sxy = syz = szx = 0
#   exx = -1e-4 (kd + 1), eyy = 1e-5 j, ezz = exy = eyz = ezx = 0
#   ep  = 0.001 (NZ - kd) p
# node displacement uz = UZ (default 0) on the top face, 0 elsewhere.
state_stream() {
	awk -v nx="$1" -v ny="$2" -v nz="$3" -v h="$4" -v np="$5" -v uz="${6:-0}" -v extra="${7:-}" 'BEGIN {
	OFS = " "
	print "# dem state 1"
	print "# dim 3"
	printf "# columns rec:u32:- id:u32:-"
	for (s = 0; s < 13; s++) printf " v%d:f64:-", s
	print ""
	print "# format text"
	print "# record node 1 per=4 x:m y:m z:m"
	print "# record hex 2 per=1 n0:- n1:- n2:- n3:- n4:- n5:- n6:- n7:-"
	print "# record frame 3 per=1 time:s nodes:- elements:-"
	print "# record disp 4 per=4 ux:m uy:m uz:m"
	print "# record elem 5 per=1 sxx:Pa syy:Pa szz:Pa sxy:Pa syz:Pa szx:Pa exx:- eyy:- ezz:- exy:- eyz:- ezx:- ep:-"
	nn = (nx + 1) * (ny + 1) * (nz + 1); ne = nx * ny * nz
	print "# nodes " nn
	print "# elements " ne
	print "# grid " nx " " ny " " nz
	if (extra != "") print extra
	print "# data"
	rows = 0
	for (n = 0; n < nn; n++) {
		i = n % (nx + 1); j = int(n / (nx + 1)) % (ny + 1); k = int(n / ((nx + 1) * (ny + 1)))
		X[3 * n] = (i - nx / 2) * h; X[3 * n + 1] = (j - ny / 2) * h; X[3 * n + 2] = (k - nz) * h
	}
	for (n = 0; n < nn; n += 4) {
		line = "1 " n
		for (q = 0; q < 12; q++) line = line " " (n + int(q / 3) < nn ? X[3 * n + q] : 0)
		print line " 0"; rows++
	}
	for (e = 0; e < ne; e++) {
		i = e % nx; j = int(e / nx) % ny; k = int(e / (nx * ny))
		n0 = i + (nx + 1) * (j + (ny + 1) * k); dj = nx + 1; dk = (nx + 1) * (ny + 1)
		print 2, e, n0, n0 + 1, n0 + 1 + dj, n0 + dj, n0 + dk, n0 + 1 + dk, n0 + 1 + dj + dk, n0 + dj + dk, 0, 0, 0, 0, 0
		rows++
	}
	for (p = 1; p <= np; p++) {
		print 3, p, p * 1e-4, nn, ne, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0; rows++
		for (n = 0; n < nn; n += 4) {
			line = "4 " n
			for (q = 0; q < 4; q++) {
				m = n + q; k = int(m / ((nx + 1) * (ny + 1)))
				line = line " 0 0 " (m < nn && k == nz ? uz : 0)
			}
			print line " 0"; rows++
		}
		for (e = 0; e < ne; e++) {
			i = e % nx; j = int(e / nx) % ny; k = int(e / (nx * ny)); kd = nz - 1 - k
			print 5, e, -1e6 * (10 * kd + p), 1000 * i, -1e6 * kd, 0, 0, 0, -1e-4 * (kd + 1), 1e-5 * j, 0, 0, 0, 0, 0.001 * (nz - kd) * p
			rows++
		}
	}
	print "# end " rows
	}'
}

# The rows of a profile stream, without header and trailer.
rows() {
	grep -v '^#' "$@"
}

# Column NAME of the profile stream rows on stdin (by its position in the
# '# columns' line of file $1).
col() {
	awk -v name="$2" '/^# columns/ { for (i = 3; i <= NF; i++) { split($i, a, ":"); c[a[1]] = i - 2 } next }
		/^#/ { next } { print $(c[name]) }' "$1"
}

# Is every line of stdin within REL (relative) of X?  near X REL
near() {
	awk -v x="$1" -v rel="$2" '{ d = $1 - x; if (d < 0) d = -d; if (d > rel * (x < 0 ? -x : x)) { print "got " $1 ", expected " x; bad = 1 } }
		END { exit bad }'
}

# Bad input: exit 1, no trailer on stdout (nothing at all when the fault
# comes before the first pass is complete; the profile is streamed), one
# message line naming demprofile and $2; with -o FILE and the tables, no
# file left.  bad_input FILE WHAT [OPTION...]
bad_input() {
	local f=$1 what=$2
	shift 2
	run --separate-stderr demprofile "$@" "$f"
	echo "\$ demprofile $* $f  -> status $status, stderr:"
	printf '  %s\n' "${stderr_lines[@]}"
	[ "$status" -eq 1 ] || return 1
	! grep -q '^# end' <<< "$output" || return 1
	[ "${#stderr_lines[@]}" -eq 1 ] || return 1
	[[ ${stderr_lines[0]} == "demprofile: "*"$what"* ]] || return 1
	mkdir -p "$T/o"
	run demprofile "$@" -o "$T/o/p" --surface "$T/o/s" --saturation "$T/o/t" "$f"
	[ "$status" -eq 1 ] || return 1
	[ -z "$(ls -A "$T/o")" ] || { echo "left: $(ls -A "$T/o")"; return 1; }
}

@test "demprofile --help and --version: stdout, exit 0" {
	run --separate-stderr demprofile --help
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	[[ ${lines[0]} == "Usage: demprofile "* ]]
	for o in pass area margin bins bin-size threshold plastic-threshold field surface saturation scene output binary gzip dump-scene verbose; do
		echo "$output" | grep -q -- "--$o" || { echo "--$o missing"; false; }
	done
	run --separate-stderr demprofile --version
	[ "$status" -eq 0 ]
	[[ $output =~ ^demprofile\ \(dem\ toolkit\)\ [0-9]+\.[0-9]+\.[0-9]+$ ]]
}

@test "demprofile: known layer values come back exactly, depth from the top face, counts, zero spread" {
	state_stream 4 4 3 1e-4 2 > "$T/a.state"
	demprofile "$T/a.state" > "$T/p" 2> "$T/err"
	head -n 1 "$T/p" | grep -qx '# dem profile 1'
	tail -n 1 "$T/p" | grep -qx '# end 6'
	tail -n 1 "$T/err" | grep -q '^demprofile: cost: wall_s=.* frames=2 passes=2 points=6'
	# pass p, layer kd from the top at depth (kd + 1/2) 0.1 mm
	paste <(col "$T/p" pass) <(col "$T/p" depth) <(col "$T/p" sxx) <(col "$T/p" szz) <(col "$T/p" exx) \
	      <(col "$T/p" ep) <(col "$T/p" sd_sxx) <(col "$T/p" n) > "$T/got"
	cat > "$T/want" <<-'END'
	1	5e-05	-1000000	0	-0.0001	0.003	0	16
	1	0.00015000000000000001	-11000000	-1000000	-0.0002	0.002	0	16
	1	0.00025	-21000000	-2000000	-0.0003	0.001	0	16
	2	5e-05	-2000000	0	-0.0001	0.006	0	16
	2	0.00015000000000000001	-12000000	-1000000	-0.0002	0.004	0	16
	2	0.00025	-22000000	-2000000	-0.0003	0.002	0	16
	END
	diff "$T/want" "$T/got"
}

@test "demprofile: the region: profile.area and profile.center of the scene, then the stream's '# area', then the block" {
	state_stream 4 4 3 1e-4 1 0 '# area -1e-4 -1e-4 1e-4 1e-4' > "$T/a.state"
	# the stream's area less 10 %: x, y in [-0.08, 0.08] mm: columns i = 1, 2
	demprofile "$T/a.state" > "$T/p" 2>/dev/null
	grep -qx '# average layers area=stream' "$T/p"
	[ "$(col "$T/p" n | sort -u)" = 4 ]
	[ "$(col "$T/p" syy | sort -u)" = 1500 ]
	# the scene's: 0.2 mm square centred at x = 0.1 mm, no margin: i = 2, 3
	printf 'profile:\n  area: [0.2 mm, 0.2 mm]\n  center: [0.1 mm, 0 mm]\n  margin: 0 mm\n' > "$T/s.yaml"
	demprofile -s "$T/s.yaml" "$T/a.state" > "$T/p" 2>/dev/null
	grep -qx '# average layers area=scene' "$T/p"
	grep -q '^# region 0 -0.0001[0-9]* 0.0002[0-9]* 0.0001' "$T/p"
	[ "$(col "$T/p" n | sort -u)" = 4 ]
	[ "$(col "$T/p" syy | sort -u)" = 2500 ]
	col "$T/p" eyy | near 1.5e-5 1e-12
	# no area anywhere: the whole top face less 10 % keeps all 16 columns
	state_stream 4 4 3 1e-4 1 > "$T/b.state"
	demprofile "$T/b.state" > "$T/p" 2>/dev/null
	grep -qx '# average layers area=block' "$T/p"
	[ "$(col "$T/p" n | sort -u)" = 16 ]
}

@test "demprofile --margin and --area: fewer columns, the mean of those left" {
	state_stream 6 6 2 1e-4 1 > "$T/a.state"
	# block x in [-0.3, 0.3] mm; a margin of 0.1 mm leaves centroids
	# -0.15 .. 0.15: i = 1..4, mean i = 2.5
	demprofile --margin 0.1mm "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" n | sort -u)" = 16 ]
	[ "$(col "$T/p" syy | sort -u)" = 2500 ]
	# a margin of 0.2 mm: i = 2, 3
	demprofile --margin 0.2mm "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" n | sort -u)" = 4 ]
	[ "$(col "$T/p" syy | sort -u)" = 2500 ]
	# an area 0.4 x 0.2 mm, no margin: i = 1..4, j = 2, 3
	demprofile --area 0.4mm:0.2mm --margin 0 "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" n | sort -u)" = 8 ]
	# a margin that leaves nothing: bad input, no output
	bad_input "$T/a.state" "a margin of 0.0003 m leaves nothing" --margin 0.3mm
}

@test "demprofile --bins and --bin-size: volume-weighted means over the bins, mean depth of their elements" {
	state_stream 4 4 3 1e-4 1 > "$T/a.state"
	# one bin: every element; depth 0.15 mm, sxx -1e6 (10 x 1 + 1)
	demprofile --bins 1 "$T/a.state" > "$T/p" 2>/dev/null
	grep -qE '^# average bins size=(0.0003|0.00029999)' "$T/p"
	[ "$(rows "$T/p" | wc -l)" -eq 1 ]
	[ "$(col "$T/p" n)" = 48 ]
	col "$T/p" depth | near 1.5e-4 1e-12
	col "$T/p" sxx | near -11e6 1e-12
	# 0.2 mm bins: layers at 0.05 and 0.15 mm, then the one at 0.25 mm
	demprofile --bin-size 0.2mm "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" n | tr '\n' ' ')" = "32 16 " ]
	[ "$(col "$T/p" depth | head -n 1)" = 0.0001 ]
	col "$T/p" sxx | head -n 1 | near -6e6 1e-12
	col "$T/p" sxx | tail -n 1 | near -21e6 1e-12
	# the spread of the first bin: sxx -1e6 and -11e6, equal volumes: 5e6
	[ "$(col "$T/p" sd_sxx | head -n 1)" = 5000000 ]
	usage_error demprofile --bins 2 --bin-size 1mm "$T/a.state"
	[[ ${stderr_lines[0]} == *"--bins and --bin-size"* ]]
}

@test "demprofile: an axisymmetric stream ('# twod mode=axisym') is averaged by ring: x the radius, weight r" {
	# 8 x 1 x 3 elements of 0.1 mm, x from -0.4 to 0.4 mm; the region x in
	# [0, 0.4] mm: columns i = 4..7 at radii r = 0.05, 0.15, 0.25, 0.35 mm,
	# syy = 1000 i.  Each column stands for a ring of volume 2 pi r h^2
	# (Pappus), so the mean is sum(1000 i r) / sum(r) = 1000 * 4.9 / 0.8 =
	# 6125 Pa, where the plane mean (every column alike) is 5500.
	state_stream 8 1 3 1e-4 1 0 '# twod mode=axisym' > "$T/a.state"
	state_stream 8 1 3 1e-4 1 0 '# twod mode=plane thickness=0.0001' > "$T/p.state"
	printf 'profile:\n  area: [0.4 mm, 0.2 mm]\n  center: [0.2 mm, 0 mm]\n  margin: 0 mm\n' > "$T/s.yaml"
	demprofile -s "$T/s.yaml" --surface "$T/as" "$T/a.state" > "$T/a" 2>/dev/null
	demprofile -s "$T/s.yaml" --surface "$T/ps" "$T/p.state" > "$T/p" 2>/dev/null
	grep -qx '# average layers area=scene weight=ring' "$T/a"
	grep -qx '# average layers area=scene' "$T/p"
	grep -qx '# twod mode=axisym' "$T/a"
	[ "$(col "$T/a" n | sort -u)" = 4 ]
	col "$T/a" syy | near 6125 1e-12
	[ "$(col "$T/p" syy | sort -u)" = 5500 ]
	# a field constant over each layer keeps its value; depth bins weigh alike
	col "$T/a" sxx | paste -sd' ' | grep -qx -- '-1000000 -11000000 -21000000'
	demprofile -s "$T/s.yaml" --bins 1 "$T/a.state" 2>/dev/null > "$T/b"
	grep -q '^# average bins size=.* area=scene weight=ring$' "$T/b"
	col "$T/b" syy | near 6125 1e-12
	# the top face of the region is the disk r < 0.4 mm: pi (0.4 mm)^2,
	# against the strip's 0.4 x 0.1 mm (the table's column 10, area)
	grep -v '^#' "$T/as" | awk '{ print $10 }' | near 5.026548245743669e-07 1e-12
	grep -v '^#' "$T/ps" | awk '{ print $10 }' | near 4e-08 1e-12
	# -v says so
	demprofile -v -s "$T/s.yaml" "$T/a.state" 2>&1 > /dev/null | grep -q 'axisymmetric (x the radius): weighted by ring'
}

@test "demprofile --pass N|last|all: the passes written; a missing pass is bad input" {
	state_stream 2 2 2 1e-4 3 > "$T/a.state"
	demprofile "$T/a.state" 2>/dev/null | col /dev/stdin pass > "$T/all" || true
	demprofile "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" pass | uniq | tr '\n' ' ')" = "1 2 3 " ]
	demprofile --pass 2 "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" pass | uniq | tr '\n' ' ')" = "2 " ]
	[ "$(col "$T/p" sxx | head -n 1)" = -2000000 ]
	demprofile --pass last "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" pass | uniq | tr '\n' ' ')" = "3 " ]
	demprofile --pass all "$T/a.state" > "$T/p" 2>/dev/null
	[ "$(rows "$T/p" | wc -l)" -eq 6 ]
	bad_input "$T/a.state" "no pass 7 in the state stream (3 passes, 1 to 3)" --pass 7
	usage_error demprofile --pass -1 "$T/a.state"
	[[ ${stderr_lines[0]} == *--pass* ]]
	usage_error demprofile --pass first "$T/a.state"
	[[ ${stderr_lines[0]} == *--pass* ]]
}

@test "demprofile: several frames of a pass: the last one is the pass's profile" {
	state_stream 2 2 2 1e-4 2 > "$T/a.state"
	# renumber pass 2 as pass 1: two frames of pass 1, the second with p = 2 values
	awk '$1 == 3 && $2 == 2 { $2 = 1 } { print }' "$T/a.state" > "$T/b.state"
	demprofile "$T/b.state" > "$T/p" 2>/dev/null
	[ "$(col "$T/p" pass | uniq | tr '\n' ' ')" = "1 " ]
	[ "$(col "$T/p" sxx | head -n 1)" = -2000000 ]
	# passes that decrease are bad input
	awk '$1 == 3 && $2 == 2 { $2 = 0 } { print }' "$T/a.state" > "$T/c.state"
	bad_input "$T/c.state" "a frame of pass 0 after pass 1"
}

@test "demprofile --surface: indented share, dimples, Ra, plastic coverage of the top face; --threshold, --plastic-threshold" {
	# the whole top face sunk by 2 um: indented, one patch cut by the edge,
	# Ra 0; the top layer's ep is 0.002 (state_stream), not above the
	# default threshold 0.002: plastic coverage 0
	state_stream 4 4 2 1e-4 1 -2e-6 > "$T/a.state"
	demprofile --surface "$T/s" "$T/a.state" > /dev/null 2>&1
	grep -qx '# pass time:s indented:- depth_max:m depth_mean:m radius:m ra:m dimples:- patches:- area:m^2 plastic:-' "$T/s"
	grep -q '^# region .* threshold 9.9999999999999995e-07 m, plastic threshold 0.002$' "$T/s"
	[ "$(grep -v '^#' "$T/s")" = "1 0.0001 1 2e-06 0 0 0 0 1 1.6000000000000003e-07 0" ]
	demprofile --surface "$T/s" --threshold 3um --plastic-threshold 0.0015 "$T/a.state" > /dev/null 2>&1
	[ "$(grep -v '^#' "$T/s" | cut -d' ' -f3,8,9,11)" = "0 0 0 1" ]
	# -v: the metrics on stderr
	run --separate-stderr demprofile -v "$T/a.state"
	[[ $stderr == *"pass 1 (t = 0.0001 s): 2 depth points; plastic coverage 0, indented 1,"* ]]
	# a threshold out of [0, 1]: a usage error naming the key; in a scene, bad input
	usage_error demprofile --plastic-threshold 2 "$T/a.state"
	[[ ${stderr_lines[0]} == *"profile.plastic_threshold"* ]]
	printf 'profile: {plastic_threshold: -0.1}\n' > "$T/bad.yaml"
	bad_input "$T/a.state" "plastic_threshold" -s "$T/bad.yaml"
}

@test "demprofile --saturation: surface and peak values per pass, gnuplot-ready" {
	state_stream 4 4 3 1e-4 2 > "$T/a.state"
	demprofile --saturation "$T/t" -o /dev/null "$T/a.state" 2>/dev/null
	grep -qx '# pass surface:Pa peak:Pa peak_depth:m zero_depth:m ep_surface:- ep_max:-' "$T/t"
	[ "$(grep -v '^#' "$T/t" | tr '\n' ';')" = "1 -1000000 -21000000 0.00025 0 0.003 0.003;2 -2000000 -22000000 0.00025 0 0.006 0.006;" ]
	demprofile --saturation "$T/t" --field ep -o /dev/null "$T/a.state" 2>/dev/null
	grep -q '^# demprofile saturation table: ep (-)' "$T/t"
	[ "$(grep -v '^#' "$T/t" | head -n 1)" = "1 0.003 0.003 5e-05 0 0.003 0.003" ]
	usage_error demprofile --field sxz "$T/a.state"
	[[ ${stderr_lines[0]} == *"--field"*"got 'sxz'"* ]]
}

@test "demprofile: gzip input, -b and -z outputs hold the same profile" {
	state_stream 3 3 2 1e-4 2 > "$T/a.state"
	demprofile "$T/a.state" > "$T/p" 2>/dev/null
	gzip -c "$T/a.state" > "$T/a.state.gz"
	demprofile < "$T/a.state.gz" > "$T/p2" 2>/dev/null
	diff <(rows "$T/p") <(rows "$T/p2")
	demprofile -b -z -o "$T/p3" "$T/a.state" 2>/dev/null
	[ "$(head -c 2 "$T/p3" | od -An -tx1 | tr -d ' ')" = 1f8b ]
	demprofile --pass 2 -o "$T/p4" "$T/a.state" 2>/dev/null
	[ -s "$T/p4" ]
}

@test "demprofile: bad streams are bad input (exit 1), nothing on stdout, no file left" {
	state_stream 2 2 2 1e-4 2 > "$T/a.state"
	head -n -1 "$T/a.state" > "$T/cut.state"
	bad_input "$T/cut.state" "truncated stream"
	# cut inside the first frame, with a trailer that counts the rows left
	head -n 30 "$T/a.state" | awk '{ print } !/^#/ { n++ } END { print "# end " n }' > "$T/cut2.state"
	bad_input "$T/cut2.state" "truncated state: the stream ends before the disp row of pass 1: node"
	printf 'hello\n' > "$T/x"
	bad_input "$T/x" "not a dem stream"
	printf '# dem shots 1\n# columns pass:u32:-\n# format text\n# data\n# end 0\n' > "$T/shots"
	bad_input "$T/shots" "a shots stream; expected a state stream"
	: > "$T/empty"
	bad_input "$T/empty" "empty input"
	grep -v '^[345] ' "$T/a.state" | sed 's/^# end .*/# end 15/' > "$T/mesh.state"
	bad_input "$T/mesh.state" "no frame"
	bad_input "$T/none" "No such file"
	state_stream 2 2 2 1e-4 1 0 '# area 1 2 3' > "$T/area.state"
	bad_input "$T/area.state" "'# area 1 2 3': expected XLO YLO XHI YHI"
}

@test "demprofile: usage errors: unknown option, two inputs, bad --pass; exit 2" {
	usage_error demprofile --bogus
	usage_error demprofile a b
	[[ ${stderr_lines[0]} == *"'b'"* ]]
	usage_error demprofile --pass
}

@test "demprofile: scene errors name the key (exit 1); --dump-scene prints the profile section" {
	printf 'profile:\n  bins: 3\n  bin_size: 1 mm\n' > "$T/s.yaml"
	run --separate-stderr demprofile -s "$T/s.yaml" /dev/null
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == *"s.yaml:3:"*"profile.bin_size"* ]]
	printf 'profile:\n  thresh: 1 um\n' > "$T/s.yaml"
	run --separate-stderr demprofile -s "$T/s.yaml" /dev/null
	[ "$status" -eq 1 ]
	[[ ${stderr_lines[0]} == *"thresh"* ]]
	run --separate-stderr demprofile --dump-scene --threshold 2um
	[ "$status" -eq 0 ]
	[[ $output == *"profile:"* ]]
	[[ $output == *"threshold: 2e-06 m"* ]]
}
