#!/usr/bin/env bats
# Command-line tests of demdetect.  The programs come from PATH (tests/run.sh
# puts bin/, or the sanitizer build, first).  References: Han 2004, Ch. 2
# (every algorithm returns the pairs of brute force; closed boxes), the
# common interface and exit codes of DESIGN.md, dem-streams(5), and small
# hand-written streams whose pairs are known by construction.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
}

# A text particle stream of dimension $1 from the rows on stdin, with the
# extra header lines given as further arguments; the trailer counts the rows.
particles() {
	local dim=$1 cols='x:f64:m y:f64:m r:f64:m'
	shift
	[ "$dim" -eq 3 ] && cols='x:f64:m y:f64:m z:f64:m r:f64:m'
	printf '# dem particles 1\n# dim %s\n# columns %s\n# format text\n' "$dim" "$cols"
	for l in "$@"; do printf '%s\n' "$l"; done
	printf '# data\n'
	awk '{ print } END { print "# end " NR }'
}

# The same for a boxes stream.
boxes() {
	local dim=$1 cols='xlo:f64:m ylo:f64:m xhi:f64:m yhi:f64:m'
	shift
	[ "$dim" -eq 3 ] && cols='xlo:f64:m ylo:f64:m zlo:f64:m xhi:f64:m yhi:f64:m zhi:f64:m'
	printf '# dem boxes 1\n# dim %s\n# columns %s\n# format text\n' "$dim" "$cols"
	for l in "$@"; do printf '%s\n' "$l"; done
	printf '# data\n'
	awk '{ print } END { print "# end " NR }'
}

# Random boxes with small integer corners (many exact touches, some boxes
# of zero size): boxes_random DIM N SEED
boxes_random() {
	awk -v dim="$1" -v n="$2" -v seed="$3" 'BEGIN {
		srand(seed)
		for (i = 0; i < n; i++) {
			lo = ""; hi = ""
			for (d = 0; d < dim; d++) {
				a = int(rand() * 24); w = int(rand() * 3)
				lo = lo (d ? " " : "") a; hi = hi " " a + w
			}
			print lo hi
		}
	}' | boxes "$1"
}

# The pair rows of a pair stream (no header, no trailer).
pairrows() {
	grep -v '^#' "$@"
}

# Bad input: exit 1, nothing on stdout, one line on stderr that starts with
# "demdetect: $2" (the stream and the line or row); and with -o FILE, no
# FILE and no temporary file.  bad_input FILE WHERE [OPTION...]
bad_input() {
	local f=$1 where=$2
	shift 2
	run --separate-stderr demdetect "$@" "$f"
	echo "\$ demdetect $* $f  -> status $status, stderr:"
	printf '  %s\n' "${stderr_lines[@]}"
	[ "$status" -eq 1 ] || return 1
	[ -z "$output" ] || return 1
	[ "${#stderr_lines[@]}" -eq 1 ] || return 1
	[[ ${stderr_lines[0]} == "demdetect: $where"* ]] || return 1
	mkdir -p "$T/o"
	run demdetect "$@" -o "$T/o/pairs" "$f"
	[ "$status" -eq 1 ] || return 1
	[ -z "$(ls -A "$T/o")" ] || { echo "left: $(ls -A "$T/o")"; return 1; }
}

@test "demdetect --help: usage and every option on stdout, nothing on stderr, exit 0" {
	run --separate-stderr demdetect --help
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	[[ ${lines[0]} == "Usage: demdetect "* ]]
	for o in algorithm count shape cell cell-size buffer periodic scene output binary gzip seed accuracy dump-scene verbose quiet help version; do
		echo "$output" | grep -q -- "--$o" || { echo "--$o missing"; false; }
	done
}

@test "demdetect --version: 'demdetect (dem toolkit) X.Y.Z' on stdout, exit 0" {
	run --separate-stderr demdetect --version
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	[[ $output =~ ^demdetect\ \(dem\ toolkit\)\ [0-9]+\.[0-9]+\.[0-9]+$ ]]
}

@test "demdetect: unknown options and missing arguments are usage errors (exit 2, one line + Try)" {
	usage_error demdetect --bogus
	[[ ${stderr_lines[0]} == *"'--bogus'"* ]]
	usage_error demdetect -Y
	[[ ${stderr_lines[0]} == *"-Y"* ]]
	usage_error demdetect --cell
	[[ ${stderr_lines[0]} == *"--cell"* ]]
	usage_error demdetect -c -a
	[[ ${stderr_lines[0]} == *"-a"* ]]
}

@test "demdetect: -c with -o, -b or -z, and two inputs, are usage errors" {
	usage_error demdetect -c -o "$T/x" /dev/null
	usage_error demdetect -c -b /dev/null
	usage_error demdetect -c -z /dev/null
	usage_error demdetect a.txt b.txt
	[[ ${stderr_lines[0]} == *b.txt* ]]
	[ ! -e "$T/x" ]
}

@test "demdetect: bad --seed and --accuracy values are usage errors" {
	usage_error demdetect --seed x /dev/null
	[[ ${stderr_lines[0]} == *--seed* ]]
	usage_error demdetect --accuracy best /dev/null
	[[ ${stderr_lines[0]} == *--accuracy* ]]
}

@test "demdetect: bad detection option values are usage errors naming the option" {
	# exit 2 and "Try" (DESIGN.md: 2 = usage), like --seed; nothing on stdout
	fails=0
	while IFS='|' read -r opt val; do
		if ! usage_error demdetect "$opt" ${val:+"$val"} /dev/null ||
		   [[ ${stderr_lines[0]} != *"${opt%%=*}"* ]]; then
			echo "  ^ not a usage error naming $opt"
			fails=$((fails + 1))
		fi
	done <<-'EOF'
	--algorithm|quick
	--cell|-1
	--cell|x
	--cell-size|-1 mm
	--cell-size|1 s
	--buffer|-1
	--buffer|1 kg
	--periodic|q
	--shape=2|
	--shape=x|
	EOF
	[ "$fails" -eq 0 ]
}

@test "demdetect: a usage message names the bad option even when it follows the input" {
	usage_error demdetect in.txt --cell
	[[ ${stderr_lines[0]} == *"'--cell'"* ]]
	usage_error demdetect in.txt --bogus
	[[ ${stderr_lines[0]} == *"'--bogus'"* ]]
}

@test "demdetect: an option given many times: no overflow, the last value wins" {
	dempack random -n 200 --seed 1 > "$T/p" 2>/dev/null
	want=$(demdetect --buffer 5 -c "$T/p" 2>/dev/null)
	# shellcheck disable=SC2046
	run --separate-stderr demdetect $(printf -- '--buffer 0 %.0s' $(seq 20)) --buffer 5 -c "$T/p"
	echo "$status $output ($want wanted) $stderr"
	[ "$status" -eq 0 ]
	[ "$output" = "$want" ]
	want=$(demdetect --shape -c "$T/p" 2>/dev/null)
	# shellcheck disable=SC2046
	run --separate-stderr demdetect $(printf -- '--shape %.0s' $(seq 20)) -c "$T/p"
	echo "$status $output ($want wanted) $stderr"
	[ "$status" -eq 0 ]
	[ "$output" = "$want" ]
}

@test "demdetect: every algorithm gives the pair stream of brute force, 2D random disks" {
	for set in "urd 1 0.6" "urd 10 0.6" "urd 100 0.3" "nrd 10 0.8" "lnrd 10 0.1" "mono 1 1"; do
		read -r law lambda rho <<< "$set"
		dempack random -n 1500 --law "$law" --lambda "$lambda" --density "$rho" --aspect 2:1 --seed 21 -b > "$T/p" 2>/dev/null
		demdetect -a brute "$T/p" 2>/dev/null | pairrows > "$T/ref"
		[ -s "$T/ref" ]
		for a in dcell nbs scell adt asdt; do
			demdetect -a "$a" "$T/p" 2>/dev/null | pairrows > "$T/got"
			diff -q "$T/ref" "$T/got" || { echo "$a differs on $set"; false; }
		done
	done
}

@test "demdetect: every algorithm gives the pair stream of brute force, 3D random spheres" {
	for set in "urd 1 0.6" "urd 10 0.3" "nrd 5 0.8" "lnrd 20 0.1"; do
		read -r law lambda rho <<< "$set"
		dempack random --dim 3 -n 1500 --law "$law" --lambda "$lambda" --density "$rho" --aspect 1:2:1 --seed 22 -b > "$T/p" 2>/dev/null
		demdetect -a brute "$T/p" 2>/dev/null | pairrows > "$T/ref"
		[ -s "$T/ref" ]
		for a in dcell scell adt asdt; do
			demdetect -a "$a" "$T/p" 2>/dev/null | pairrows > "$T/got"
			diff -q "$T/ref" "$T/got" || { echo "$a differs on $set"; false; }
		done
	done
}

@test "demdetect: every algorithm gives the pairs of brute force on touching and zero-size boxes" {
	for dim in 2 3; do
		for seed in 1 2; do
			boxes_random "$dim" 500 "$seed" > "$T/b"
			demdetect -a brute "$T/b" 2>/dev/null | pairrows > "$T/ref"
			[ -s "$T/ref" ]
			for a in dcell nbs scell adt asdt; do
				[ "$dim" -eq 3 ] && [ "$a" = nbs ] && continue
				demdetect -a "$a" "$T/b" 2>/dev/null | pairrows > "$T/got"
				diff -q "$T/ref" "$T/got" || { echo "$a differs, dim $dim seed $seed"; false; }
			done
		done
	done
}

@test "demdetect: the cell size changes no pair (--cell, --cell-size, dcell nbs scell)" {
	dempack random -n 1000 --lambda 20 --seed 23 -b > "$T/p" 2>/dev/null
	demdetect -a brute "$T/p" 2>/dev/null | pairrows > "$T/ref"
	for a in dcell nbs scell; do
		for c in "--cell 0.1" "--cell 1" "--cell 7" "--cell 1000" "--cell-size 0.01" "--cell-size 3" "--cell-size 1e4"; do
			# shellcheck disable=SC2086
			demdetect -a "$a" $c "$T/p" 2>/dev/null | pairrows > "$T/got"
			diff -q "$T/ref" "$T/got" || { echo "$a $c differs"; false; }
		done
	done
}

@test "demdetect -a nbs on a 3D stream: refused, exit 1, nothing on stdout" {
	dempack random --dim 3 -n 50 --seed 1 > "$T/p" 2>/dev/null
	run --separate-stderr demdetect -a nbs "$T/p"
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[[ $stderr == *"demdetect: "*NBS*2D* ]]
}

@test "demdetect: closed boxes, touching on an edge, a corner or a face is a pair" {
	boxes 2 > "$T/b2" <<-'EOF'
	0 0 1 1
	1 0 2 1
	2 1 3 2
	0 2 1 3
	5 5 5 5
	5 5 6 6
	10 10 11 11
	EOF
	# 0-1 share an edge, 1-2 a corner, 4 (a point) is a corner of 5;
	# 3 is 1 away from 0, 6 is alone
	[ "$(demdetect "$T/b2" 2>/dev/null | pairrows)" = "0 1
1 2
4 5" ]
	boxes 3 > "$T/b3" <<-'EOF'
	0 0 0 1 1 1
	1 0 0 2 1 1
	1 1 1 2 2 2
	0 0 1.5 0.5 0.5 2
	EOF
	# 0-1 a face, 0-2 a corner, 1-2 an edge; 3 is above 0 with a gap
	for a in dcell scell adt asdt brute; do
		[ "$(demdetect -a "$a" "$T/b3" 2>/dev/null | pairrows)" = "0 1
0 2
1 2" ]
	done
}

@test "demdetect -c: only the number of pairs on stdout, the number the pair stream has" {
	dempack random -n 700 --lambda 3 --seed 24 > "$T/p" 2>/dev/null
	run --separate-stderr demdetect -c "$T/p"
	[ "$status" -eq 0 ]
	[ "${#lines[@]}" -eq 1 ]
	[[ $output =~ ^[0-9]+$ ]]
	[ "$output" -gt 0 ]
	[ "$(demdetect "$T/p" 2>/dev/null | pairrows | wc -l)" -eq "$output" ]
}

@test "demdetect: the pair stream: header, provenance kept, i < j, sorted, each pair once, trailer" {
	dempack random -n 700 --lambda 3 --seed 25 > "$T/p" 2>/dev/null
	demdetect -a asdt "$T/p" > "$T/q" 2>/dev/null
	[ "$(head -n 3 "$T/q")" = "# dem pairs 1
# columns i:u32:- j:u32:-
# format text" ]
	! grep -q '^# dim' "$T/q"
	grep -qx '# objects 700' "$T/q"
	# the metadata of the input, then demdetect's own provenance
	for l in "$(grep '^# prog dempack' "$T/p")" "$(grep '^# seed' "$T/p")" "$(grep '^# method' "$T/p")" "$(grep '^# domain' "$T/p")"; do
		grep -qxF "$l" "$T/q"
	done
	[ "$(grep '^# prog' "$T/q" | cut -d' ' -f3)" = "dempack
demdetect" ]
	grep -qx "# prog demdetect [0-9.]* args: -a asdt $T/p" "$T/q"
	n=$(pairrows "$T/q" | wc -l)
	[ "$n" -gt 0 ]
	[ "$(tail -n 1 "$T/q")" = "# end $n" ]
	pairrows "$T/q" | awk 'NF != 2 || $1 >= $2 || $2 >= 700 { exit 1 }'
	pairrows "$T/q" | sort -c -u -k1,1n -k2,2n
}

@test "demdetect: reads a file, '-' and standard input alike" {
	dempack random -n 300 --seed 26 -z > "$T/p" 2>/dev/null
	a=$(demdetect "$T/p" 2>/dev/null | pairrows)
	b=$(demdetect - < "$T/p" 2>/dev/null | pairrows)
	c=$(demdetect < "$T/p" 2>/dev/null | pairrows)
	[ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" = "$c" ]
}

@test "demdetect: columns are found by name, in any order; extra columns are ignored" {
	printf '# dem particles 1\n# dim 2\n# columns id:u32:- r:f64:m y:f64:m x:f64:m\n# format text\n# data\n7 1 0 0\n8 1 0 2\n9 1 0 5\n# end 3\n' > "$T/p"
	[ "$(demdetect "$T/p" 2>/dev/null | pairrows)" = "0 1" ]
}

@test "demdetect -o FILE, -b, -z: the same pairs in every output form" {
	dempack random -n 500 --seed 27 > "$T/p" 2>/dev/null
	demdetect "$T/p" 2>/dev/null > "$T/ref"
	mkdir "$T/d"
	demdetect -o "$T/d/t" "$T/p" 2>/dev/null
	demdetect -b -o "$T/d/b" "$T/p" 2>/dev/null
	demdetect -z -o "$T/d/z" "$T/p" 2>/dev/null
	[ "$(ls "$T/d" | tr '\n' ' ')" = "b t z " ]
	cmp <(grep -v '^# prog' "$T/ref") <(grep -v '^# prog' "$T/d/t")
	grep -aqx '# format binary' "$T/d/b"
	t=$(tail -n 1 "$T/ref")
	[ "$(tail -c $((${#t} + 1)) "$T/d/b")" = "$t" ]
	cmp <(grep -v '^# prog' "$T/ref") <(gzip -dc "$T/d/z" | grep -v '^# prog')
}

@test "demdetect --shape: of touching, overlapping and apart disks, keeps only the overlapping pair" {
	particles 2 > "$T/p" <<-'EOF'
	0 0 1
	2 0 1
	10 0 1
	11.5 0 1
	20 0 1
	23 0 1
	30 0 1
	31.8 1.8 1
	EOF
	# boxes: 0-1 touch, 2-3 overlap, 4-5 apart, 6-7 overlap at a corner
	[ "$(demdetect -c "$T/p" 2>/dev/null)" -eq 3 ]
	for a in dcell nbs scell adt asdt brute; do
		[ "$(demdetect -a "$a" --shape "$T/p" 2>/dev/null | pairrows)" = "2 3" ]
	done
	[ "$(demdetect --shape -c "$T/p" 2>/dev/null)" -eq 1 ]
}

@test "demdetect --shape=TOL: keeps pairs overlapping by more than TOL x the smaller radius" {
	particles 2 > "$T/p" <<-'EOF'
	0 0 1
	2 0 1
	10 0 1
	11.5 0 2
	EOF
	# overlaps: 0-1 exactly 0, 2-3 1.5 = 1.5 x the smaller radius 1
	[ "$(demdetect --shape=0 "$T/p" 2>/dev/null | pairrows)" = "2 3" ]
	[ "$(demdetect --shape=1 "$T/p" 2>/dev/null | pairrows)" = "2 3" ]
	[ -z "$(demdetect --shape=1 -c "$T/p" 2>/dev/null | grep -v '^1$')" ]
	[ "$(demdetect --shape=0.5 -c "$T/p" 2>/dev/null)" -eq 1 ]
	# negative: pairs that nearly touch count too (their boxes must overlap)
	[ "$(demdetect --shape=-0.01 "$T/p" 2>/dev/null | pairrows)" = "0 1
2 3" ]
	# the same from a scene
	printf 'detect:\n  shape: true\n  shape_tol: 1\n' > "$T/s.yaml"
	[ "$(demdetect -s "$T/s.yaml" -c "$T/p" 2>/dev/null)" -eq 1 ]
	printf 'detect:\n  shape: true\n  shape_tol: -0.5\n' > "$T/s.yaml"
	[ "$(demdetect -s "$T/s.yaml" -c "$T/p" 2>/dev/null)" -eq 2 ]
}

@test "demdetect --shape in 3D: spheres overlapping, touching and apart" {
	particles 3 > "$T/p" <<-'EOF'
	0 0 0 1
	1 1 1 1
	10 0 0 1
	10 1.2 1.2 0.5
	20 0 0 1
	20 0 3 2
	EOF
	# 0-1: distance sqrt 3 < 2; 2-3: 1.697 > 1.5 (box overlap only); 4-5 touch
	[ "$(demdetect -c "$T/p" 2>/dev/null)" -eq 3 ]
	for a in dcell scell adt asdt brute; do
		[ "$(demdetect -a "$a" --shape "$T/p" 2>/dev/null | pairrows)" = "0 1" ]
	done
}

@test "demdetect --shape on a boxes stream: refused, exit 1" {
	boxes 2 > "$T/b" <<< "0 0 1 1"
	run --separate-stderr demdetect --shape "$T/b"
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[[ $stderr == "demdetect: $T/b: "*shape* ]]
}

@test "demdetect --buffer B: enlarges each particle's box by B on every side" {
	particles 2 > "$T/p" <<-'EOF'
	0 0 1
	2.1 0 1
	EOF
	# the boxes are 0.1 apart: they touch with B = 0.05
	[ "$(demdetect -c "$T/p" 2>/dev/null)" -eq 0 ]
	[ "$(demdetect -c --buffer 0.04 "$T/p" 2>/dev/null)" -eq 0 ]
	[ "$(demdetect -c --buffer 0.05 "$T/p" 2>/dev/null)" -eq 1 ]
	[ "$(demdetect -c --buffer '60 mm' "$T/p" 2>/dev/null)" -eq 1 ]
	[ "$(demdetect -c --buffer '40 mm' "$T/p" 2>/dev/null)" -eq 0 ]
	# the shape test still uses the real radii
	[ "$(demdetect -c --buffer 1 --shape "$T/p" 2>/dev/null)" -eq 0 ]
	[ "$(demdetect -c --buffer 1 --shape=-0.09 "$T/p" 2>/dev/null)" -eq 0 ]
	[ "$(demdetect -c --buffer 1 --shape=-0.11 "$T/p" 2>/dev/null)" -eq 1 ]
}

@test "demdetect --periodic x: finds the pairs across the boundary, minimum image" {
	particles 2 '# domain 0 0 10 10' > "$T/p" <<-'EOF'
	0.5 5 1
	9.6 5 1
	4 5 1
	5.5 5 1
	0 8 1
	8 8 1
	0.25 1 0.5
	9.5 1 0.25
	EOF
	# without periodic: only 2-3 (4-5: boxes [-1,1] and [7,9])
	[ "$(demdetect "$T/p" 2>/dev/null | pairrows)" = "2 3" ]
	# along x: 0-1 (0.9 apart), 4-5 (boxes touch at 9 = -1), 6-7 (0.75 apart)
	for a in dcell nbs scell adt asdt brute; do
		[ "$(demdetect -a "$a" --periodic x "$T/p" 2>/dev/null | pairrows)" = "0 1
2 3
4 5
6 7" ]
	done
	# --shape with the minimum image: 4-5 and 6-7 only touch (exact in binary)
	[ "$(demdetect --periodic x --shape "$T/p" 2>/dev/null | pairrows)" = "0 1
2 3" ]
	# periodic along y only: none of them wrap
	[ "$(demdetect --periodic y "$T/p" 2>/dev/null | pairrows)" = "2 3" ]
}

@test "demdetect --periodic: objects outside the domain are wrapped; images counted in the cost line" {
	particles 2 '# domain -5 0 5 10' > "$T/p" <<-'EOF'
	-4.5 5 1
	14.4 5 1
	EOF
	# 14.4 wraps to 4.4 (two periods), 0.9 from -4.5 across the boundary
	run --separate-stderr demdetect --periodic x "$T/p"
	[ "$status" -eq 0 ]
	[ "$(echo "$output" | pairrows)" = "0 1" ]
	[[ ${stderr_lines[-1]} == *" images="[1-9]* ]]
}

@test "demdetect --periodic xy and xyz agree with brute force over every algorithm" {
	dempack random -n 1200 --lambda 3 --density 0.5 --aspect 2:1 --seed 28 -b > "$T/p2" 2>/dev/null
	dempack random --dim 3 -n 1200 --lambda 3 --density 0.5 --seed 28 -b > "$T/p3" 2>/dev/null
	demdetect -a brute --periodic xy "$T/p2" 2>/dev/null | pairrows > "$T/ref2"
	demdetect -a brute --periodic xyz "$T/p3" 2>/dev/null | pairrows > "$T/ref3"
	# wrapping adds pairs
	[ "$(wc -l < "$T/ref2")" -gt "$(demdetect -c "$T/p2" 2>/dev/null)" ]
	[ "$(wc -l < "$T/ref3")" -gt "$(demdetect -c "$T/p3" 2>/dev/null)" ]
	for a in dcell nbs scell adt asdt; do
		demdetect -a "$a" --periodic xy "$T/p2" 2>/dev/null | pairrows | diff -q "$T/ref2" -
		[ "$a" = nbs ] && continue
		demdetect -a "$a" --periodic xyz "$T/p3" 2>/dev/null | pairrows | diff -q "$T/ref3" -
	done
}

@test "demdetect --periodic without a '# domain' line: refused, exit 1, nothing on stdout" {
	particles 2 > "$T/p" <<< "0 0 1"
	run --separate-stderr demdetect --periodic x "$T/p"
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[[ $stderr == "demdetect: $T/p: "*domain* ]]
	mkdir "$T/o"
	run demdetect --periodic x -o "$T/o/q" "$T/p"
	[ "$status" -eq 1 ]
	[ -z "$(ls -A "$T/o")" ]
}

@test "demdetect --periodic: a box not shorter than half the period, or an axis not in the stream: exit 1" {
	particles 2 '# domain 0 0 10 10' > "$T/p" <<-'EOF'
	1 1 1
	5 5 2.5
	EOF
	run --separate-stderr demdetect --periodic y "$T/p"
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[[ $stderr == *"half the period"* ]]
	run --separate-stderr demdetect --periodic z "$T/p"
	[ "$status" -eq 1 ]
	[ -z "$output" ]
}

@test "demdetect: boxes streams in 2D and 3D give the brute-force count of awk" {
	for dim in 2 3; do
		boxes_random "$dim" 300 7 > "$T/b"
		want=$(awk -v dim="$dim" 'BEGIN { n = 0 } /^#/ { next } { for (k = 1; k <= 2 * dim; k++) b[n, k] = $k; n++ }
			END { for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) {
				ok = 1
				for (d = 1; d <= dim; d++) if (b[i, d] > b[j, d + dim] || b[j, d] > b[i, d + dim]) ok = 0
				c += ok }
			print c + 0 }' "$T/b")
		echo "dim $dim: awk $want"
		[ "$want" -gt 0 ]
		[ "$(demdetect -c "$T/b" 2>/dev/null)" -eq "$want" ]
	done
}

@test "demdetect: a box with xlo > xhi is bad input naming the line" {
	boxes 2 > "$T/b" <<-'EOF'
	0 0 1 1
	2 0 1 1
	EOF
	bad_input "$T/b" "$T/b:7: "
}

@test "demdetect: NaN, inf and a negative radius are bad input naming the line" {
	for row in "nan 0 1" "0 NAN 1" "inf 0 1" "0 0 -inf" "0 0 1e999" "0 0 -1"; do
		printf '0 0 1\n%s\n3 3 1\n' "$row" | particles 2 > "$T/p"
		bad_input "$T/p" "$T/p:7: "
	done
}

@test "demdetect: malformed rows (letters, too few, too many values) are bad input naming the line" {
	for row in "0 x 1" "0 0 1m" "0 0" "0" "0 0 1 1" "0,0,1"; do
		printf '0 0 1\n3 3 1\n%s\n' "$row" | particles 2 > "$T/p"
		bad_input "$T/p" "$T/p:8: "
	done
}

@test "demdetect: a text stream without its trailer is truncated, exit 1" {
	dempack random -n 50 --seed 1 2>/dev/null | head -n 30 > "$T/p"
	bad_input "$T/p" "$T/p:30: "
	[[ ${stderr_lines[0]} == *truncated* ]]
	# cut in the middle of a line
	dempack random -n 50 --seed 1 2>/dev/null | head -c 1500 > "$T/p"
	bad_input "$T/p" "$T/p:"
	# only the header
	dempack random -n 50 --seed 1 2>/dev/null | sed '/^# data/q' > "$T/p"
	bad_input "$T/p" "$T/p:9: "
	[[ ${stderr_lines[0]} == *truncated* ]]
	# cut inside the header
	dempack random -n 50 --seed 1 2>/dev/null | head -n 4 > "$T/p"
	bad_input "$T/p" "$T/p:4: "
	[[ ${stderr_lines[0]} == *truncated* ]]
}

@test "demdetect: a binary stream cut in the middle (head -c) is truncated, exit 1, naming a row" {
	dempack random -n 5000 --seed 2 -b > "$T/full" 2>/dev/null
	size=$(wc -c < "$T/full")
	for cut in $((size / 2)) $((size - 200)) $((size - 5)) 400; do
		head -c "$cut" "$T/full" > "$T/p"
		run --separate-stderr demdetect "$T/p"
		echo "cut at $cut: $stderr"
		[ "$status" -eq 1 ]
		[ -z "$output" ]
		[[ $stderr == "demdetect: $T/p"* ]]
	done
	head -c $((size / 2)) "$T/full" > "$T/p"
	bad_input "$T/p" "$T/p: row "
	[[ ${stderr_lines[0]} == *truncated* ]]
}

@test "demdetect: a binary stream cut in the middle names the row where it ends" {
	# 5000 records of 24 bytes in blocks of 4096: cut inside record 4500
	dempack random -n 5000 --seed 2 -b > "$T/full" 2>/dev/null
	h=$(($(grep -abx '# data' "$T/full" | cut -d: -f1) + 7))
	head -c $((h + 4 + 4096 * 24 + 4 + 403 * 24 + 10)) "$T/full" > "$T/p"
	run --separate-stderr demdetect "$T/p"
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == "demdetect: $T/p: row 4500: truncated"* ]]
}

@test "demdetect: a trailer whose count differs from the rows is bad input" {
	printf '0 0 1\n3 3 1\n' | particles 2 | sed 's/^# end 2$/# end 3/' > "$T/p"
	bad_input "$T/p" "$T/p:8: "
	printf '0 0 1\n3 3 1\n' | particles 2 | sed 's/^# end 2$/# end 1/' > "$T/p"
	bad_input "$T/p" "$T/p:8: "
	printf '0 0 1\n3 3 1\n' | particles 2 | sed 's/^# end 2$/# end two/' > "$T/p"
	bad_input "$T/p" "$T/p:8: "
	printf '0 0 1\n3 3 1\n' | particles 2 | sed 's/^# end 2$/# end 2\n0 0 1/' > "$T/p"
	bad_input "$T/p" "$T/p:9: "
}

@test "demdetect: a binary trailer whose count differs from the records is bad input" {
	dempack random -n 100 --seed 3 -b 2>/dev/null | sed 's/# end 100$/# end 99/' > "$T/p"
	bad_input "$T/p" "$T/p"
	[[ ${stderr_lines[0]} == *99* ]]
}

@test "demdetect: a pairs stream, an unknown kind, a non-dem file, empty input: bad input" {
	dempack random -n 100 --seed 3 2>/dev/null | demdetect 2>/dev/null > "$T/pairs"
	bad_input "$T/pairs" "$T/pairs: "
	[[ ${stderr_lines[0]} == *pairs* ]]
	dempack random -n 10 --seed 3 2>/dev/null | sed '1s/particles/grains/' > "$T/k"
	bad_input "$T/k" "$T/k:1: "
	[[ ${stderr_lines[0]} == *grains* ]]
	printf 'x y r\n0 0 1\n' > "$T/n"
	bad_input "$T/n" "$T/n:1: "
	[[ ${stderr_lines[0]} == *"not a dem stream"* ]]
	: > "$T/e"
	bad_input "$T/e" "$T/e: "
	# gzip magic, then garbage
	printf '\037\213garbage' > "$T/g"
	bad_input "$T/g" "$T/g: "
}

@test "demdetect: header faults are bad input: no columns, no format, bad type, missing column" {
	printf '# dem particles 1\n# dim 2\n# format text\n# data\n# end 0\n' > "$T/a"
	bad_input "$T/a" "$T/a:"
	printf '# dem particles 1\n# dim 2\n# columns x:f64:m y:f64:m r:f64:m\n# data\n# end 0\n' > "$T/b"
	bad_input "$T/b" "$T/b:"
	printf '# dem particles 1\n# dim 2\n# columns x:f32:m y:f64:m r:f64:m\n# format text\n# data\n# end 0\n' > "$T/c"
	bad_input "$T/c" "$T/c:3: "
	printf '# dem particles 1\n# dim 2\n# columns x:f64:m y:f64:m\n# format text\n# data\n# end 0\n' > "$T/d"
	bad_input "$T/d" "$T/d: "
	printf '# dem particles 1\n# dim 3\n# columns x:f64:m y:f64:m r:f64:m\n# format text\n# data\n# end 0\n' > "$T/e"
	bad_input "$T/e" "$T/e: "
	printf '# dem particles 1\n# columns x:f64:m y:f64:m r:f64:m\n# format text\n# data\n# end 0\n' > "$T/f"
	bad_input "$T/f" "$T/f: "
}

@test "demdetect: a stream of an unknown version is refused" {
	printf '0 0 1\n1 0 1\n' | particles 2 | sed '1s/ 1$/ 2/' > "$T/p"
	head -n 1 "$T/p" | grep -qx '# dem particles 2'
	bad_input "$T/p" "$T/p:1: "
}

@test "demdetect: lengths not in metres are converted or refused, never taken as metres" {
	# x and y in mm, r in m: the centres are 1 m apart, the disks overlap
	printf '# dem particles 1\n# dim 2\n# columns x:f64:mm y:f64:mm r:f64:m\n# format text\n# data\n0 0 1\n1000 0 1\n# end 2\n' > "$T/p"
	run --separate-stderr demdetect -c "$T/p"
	echo "status $status, stdout '$output', stderr '$stderr'"
	[ "$status" -eq 1 ] || [ "$output" = 1 ]
}

@test "demdetect: gzip of a truncated stream, and a cut gzip file, are truncated streams: exit 1" {
	dempack random -n 400 --seed 4 2>/dev/null | head -n 200 | gzip > "$T/t.gz"
	bad_input "$T/t.gz" "$T/t.gz:200: "
	[[ ${stderr_lines[0]} == *truncated* ]]
	dempack random -n 4000 --seed 4 -z > "$T/full.gz" 2>/dev/null
	head -c $(($(wc -c < "$T/full.gz") / 2)) "$T/full.gz" > "$T/cut.gz"
	bad_input "$T/cut.gz" "$T/cut.gz"
	dempack random -n 4000 --seed 4 -z -b > "$T/full.gz" 2>/dev/null
	head -c $(($(wc -c < "$T/full.gz") / 2)) "$T/full.gz" > "$T/cut.gz"
	bad_input "$T/cut.gz" "$T/cut.gz"
}

@test "demdetect: a binary NaN or negative radius is bad input naming the row" {
	# a hand-made binary stream: rows (0,0,1), (NaN,0,1) / (3,0,-1)
	for bad in '\000\000\000\000\000\000\370\177\000\000\000\000\000\000\000\000\000\000\000\000\000\000\360\077' \
	           '\000\000\000\000\000\000\010\100\000\000\000\000\000\000\000\000\000\000\000\000\000\000\360\277'; do
		{
			printf '# dem particles 1\n# dim 2\n# columns x:f64:m y:f64:m r:f64:m\n# format binary\n# data\n'
			printf '\002\000\000\000'
			printf '\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\360\077'
			printf "$bad"
			printf '\000\000\000\000# end 2\n'
		} > "$T/p"
		bad_input "$T/p" "$T/p: row 2: "
	done
	# and the same stream with good values is read
	{
		printf '# dem particles 1\n# dim 2\n# columns x:f64:m y:f64:m r:f64:m\n# format binary\n# data\n'
		printf '\002\000\000\000'
		printf '\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\360\077'
		printf '\000\000\000\000\000\000\000\100\000\000\000\000\000\000\000\000\000\000\000\000\000\000\360\077'
		printf '\000\000\000\000# end 2\n'
	} > "$T/p"
	[ "$(demdetect "$T/p" 2>/dev/null | pairrows)" = "0 1" ]
}

@test "demdetect: a missing input file is bad input; a write error on stdout is exit 4" {
	run --separate-stderr demdetect "$T/none"
	[ "$status" -eq 1 ]
	[ "$stderr" = "demdetect: $T/none: No such file or directory" ]
	[ -w /dev/full ] || skip "no /dev/full"
	dempack random -n 3000 --seed 5 > "$T/p" 2>/dev/null
	run --separate-stderr bash -c "demdetect '$T/p' > /dev/full"
	[ "$status" -eq 4 ]
	[[ $stderr == *"No space left on device"* ]]
}

@test "demdetect: the cost line is last on stderr, with the fields of each mode" {
	dempack random -n 400 --seed 6 > "$T/p" 2>/dev/null
	num='[0-9.]+'
	run --separate-stderr demdetect "$T/p"
	[[ ${stderr_lines[-1]} =~ ^demdetect:\ cost:\ wall_s=$num\ cpu_s=$num\ rss_mb=$num\ read_s=$num\ detect_s=$num\ sort_s=$num\ write_s=$num\ objects=400\ pairs=[0-9]+\ checks=[0-9]+$ ]]
	run --separate-stderr demdetect -c "$T/p"
	[[ ${stderr_lines[-1]} =~ ^demdetect:\ cost:\ wall_s=$num\ cpu_s=$num\ rss_mb=$num\ read_s=$num\ detect_s=$num\ objects=400\ pairs=$output\ checks=[0-9]+$ ]]
	n=$output
	run --separate-stderr demdetect -c --shape --periodic xy "$T/p"
	[[ ${stderr_lines[-1]} =~ ^demdetect:\ cost:\ wall_s=$num\ cpu_s=$num\ rss_mb=$num\ read_s=$num\ detect_s=$num\ shape_s=$num\ objects=400\ pairs=$output\ box_pairs=[0-9]+\ checks=[0-9]+\ images=[0-9]+$ ]]
	# box_pairs is the count without --shape, pairs the overlapping ones
	bp=$(echo "${stderr_lines[-1]}" | sed 's/.*box_pairs=\([0-9]*\).*/\1/')
	[ "$bp" -eq "$(demdetect -c --periodic xy "$T/p" 2>/dev/null)" ]
	[ "$output" -lt "$bp" ]
	# brute force checks every pair once
	run --separate-stderr demdetect -a brute -c "$T/p"
	[[ ${stderr_lines[-1]} == *" checks=79800" ]]
}

@test "demdetect --dump-scene: the resolved detect section, with options applied" {
	run --separate-stderr demdetect --dump-scene -a asdt --buffer '1 mm' --periodic xy --shape=0.1
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	[ "$output" = "detect:
  algorithm: asdt
  cell_factor: 0
  cell: 0 m
  buffer: 0.001 m
  periodic: xy
  shape: true
  shape_tol: 0.1" ]
	# and it loads back
	echo "$output" > "$T/s.yaml"
	run --separate-stderr demdetect -s "$T/s.yaml" --dump-scene
	[ "$status" -eq 0 ]
	grep -q 'shape_tol: 0.1' <<< "$output"
}

@test "demdetect: the examples of --help run as written" {
	cd "$T"
	dempack random -n 300 --seed 1 > packing.txt 2>/dev/null
	demdetect --help | sed -n '/^Examples:/,/^$/p' | grep '^  demdetect' | sed 's/#.*//' > ex.sh
	[ -s ex.sh ]
	while read -r line; do
		run --separate-stderr bash -c "$line"
		echo "\$ $line -> $status: $output / $stderr"
		[ "$status" -eq 0 ]
		[[ $output =~ ^[0-9]+$ ]]
	done < ex.sh
}

@test "demdetect --repeat N: same pairs as one call; the cost line adds detect_warm_s" {
	# The repeats reuse the workspace (warm buffers); the output is the
	# first call's, identical to a plain run, for 2D and 3D and periodic.
	dempack random -n 3000 --lambda 5 --seed 31 > "$T/p2" 2>/dev/null
	dempack random --dim 3 -n 3000 --lambda 5 --seed 32 > "$T/p3" 2>/dev/null
	for p in p2 p3; do
		demdetect "$T/$p" > "$T/one" 2>/dev/null
		run --separate-stderr demdetect --repeat 4 "$T/$p"
		[ "$status" -eq 0 ]
		diff <(grep -v '^# prog' "$T/one") <(printf '%s\n' "$output" | grep -v '^# prog')
		[[ ${stderr_lines[-1]} == *" detect_s="*" detect_warm_s="* ]]
		[ "$(demdetect --periodic xy --repeat 3 -c "$T/$p" 2>/dev/null)" -eq \
		  "$(demdetect --periodic xy -c "$T/$p" 2>/dev/null)" ]
	done
	usage_error demdetect --repeat 0 "$T/p2"
}

@test "demdetect: the AVX2 and the portable 3D sweep give the same pairs as brute force" {
	dempack random --dim 3 -n 20000 --density 0.6 --lambda 3 --seed 9 -b > "$T/s.bin" 2>/dev/null
	a=$(demdetect -c "$T/s.bin" 2>/dev/null)
	b=$(DEM_NO_AVX2=1 demdetect -c "$T/s.bin" 2>/dev/null)
	c=$(demdetect -a brute -c "$T/s.bin" 2>/dev/null)
	echo "avx2 $a portable $b brute $c"
	[ "$c" -gt 0 ] && [ "$a" = "$c" ] && [ "$b" = "$c" ]
	cmp <(demdetect "$T/s.bin" 2>/dev/null | grep -v '^# prog') <(DEM_NO_AVX2=1 demdetect "$T/s.bin" 2>/dev/null | grep -v '^# prog')
}
