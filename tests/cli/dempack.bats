#!/usr/bin/env bats
# Command-line tests of dempack (random method).  The programs come from
# PATH (tests/run.sh puts bin/, or the sanitizer build, first).  References:
# the common interface and exit codes of DESIGN.md, the stream format of
# dem-streams(5), the radius laws of lib/core/radius.h (Han 2004, Ch. 2.5).

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
}

# Rows of a text stream (lines that are not header or trailer).
rows() {
	grep -vc '^#' "$1"
}

# The packing density of a text particle stream of dimension $2: the sum
# of the areas (volumes) over the domain of its '# domain' line.
density() {
	awk -v dim="$2" '
		/^# domain / { V = 1; for (d = 0; d < dim; d++) V *= $(3 + dim + d) - $(3 + d) }
		/^#/ { next }
		{ r = $(dim + 1); s += dim == 2 ? 3.141592653589793 * r * r : 4 / 3 * 3.141592653589793 * r * r * r }
		END { printf "%.17g\n", s / V }' "$1"
}

# Is |a - b| <= tol |b| ?
close_to() {
	awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= tol * (b < 0 ? -b : b)) }'
}

@test "dempack --help: usage and every option on stdout, nothing on stderr, exit 0" {
	run --separate-stderr dempack --help
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	[[ ${lines[0]} == "Usage: dempack random "* ]]
	for o in dim number density law rmin lambda aspect scene output binary gzip seed accuracy dump-scene verbose quiet help version; do
		echo "$output" | grep -q -- "--$o" || { echo "--$o missing"; false; }
	done
}

@test "dempack --version: 'dempack (dem toolkit) X.Y.Z' on stdout, exit 0" {
	run --separate-stderr dempack --version
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	[[ $output =~ ^dempack\ \(dem\ toolkit\)\ [0-9]+\.[0-9]+\.[0-9]+$ ]]
}

@test "dempack: an unknown option is a usage error (exit 2, one line + Try, no stdout)" {
	usage_error dempack --bogus random
	[[ ${stderr_lines[0]} == *"'--bogus'"* ]]
	usage_error dempack -Y random
	[[ ${stderr_lines[0]} == *"-Y"* ]]
}

@test "dempack: a missing option argument is a usage error" {
	usage_error dempack --dump-scene --seed
	[[ ${stderr_lines[0]} == *"--seed"* ]]
}

@test "dempack: a missing or unknown method is a usage error" {
	usage_error dempack -n 10
	usage_error dempack front -n 10
	[[ ${stderr_lines[0]} == *front* ]]
	usage_error dempack random extra
}

@test "dempack: a usage message names the bad option even when it follows the method" {
	# getopt moves the method word; the message must still name the option
	usage_error dempack random --bogus
	[[ ${stderr_lines[0]} == *"'--bogus'"* ]]
	usage_error dempack random -n
	[[ ${stderr_lines[0]} == *"'-n'"* ]]
}

@test "dempack: bad --seed and --accuracy values are usage errors naming the option" {
	for args in "--seed x" "--seed -1" "--seed 4294967296" "--accuracy best"; do
		# shellcheck disable=SC2086
		usage_error dempack random -n 5 $args
		[[ ${stderr_lines[0]} == *"${args%% *}"* ]]
	done
}

@test "dempack: bad method option values are usage errors naming the option" {
	# exit 2 and "Try" (DESIGN.md: 2 = usage), like --seed; nothing on stdout
	fails=0
	while IFS='|' read -r opt val; do
		if ! usage_error dempack random -n 5 "$opt" "$val" ||
		   [[ ${stderr_lines[0]} != *"$opt"* ]]; then
			echo "  ^ not a usage error naming $opt"
			fails=$((fails + 1))
		fi
	done <<-'EOF'
	--dim|4
	--dim|two
	--number|abc
	--number|-1
	--density|0
	--density|1.5
	--law|gauss
	--rmin|0
	--rmin|-1 mm
	--rmin|1 kg
	--lambda|0.5
	--aspect|1:0
	--aspect|1:2:3
	EOF
	[ "$fails" -eq 0 ]
}

@test "dempack: an option given many times: the last value wins" {
	# shellcheck disable=SC2046
	run --separate-stderr dempack random $(printf -- '-n 1 %.0s' $(seq 20)) -n 5 --seed 1
	echo "$status: $stderr"
	[ "$status" -eq 0 ]
	[ "$(echo "$output" | grep -vc '^#')" -eq 5 ]
}

@test "dempack random: N rows of x y r in 2D and x y z r in 3D, header as in dem-streams(5)" {
	dempack random -n 137 --seed 1 > "$T/p2" 2>/dev/null
	dempack random --dim 3 -n 59 --seed 1 > "$T/p3" 2>/dev/null
	[ "$(head -n 1 "$T/p2")" = "# dem particles 1" ]
	grep -qx '# dim 2' "$T/p2"
	grep -qx '# columns x:f64:m y:f64:m r:f64:m' "$T/p2"
	grep -qx '# format text' "$T/p2"
	grep -qx '# data' "$T/p2"
	grep -qx '# dim 3' "$T/p3"
	grep -qx '# columns x:f64:m y:f64:m z:f64:m r:f64:m' "$T/p3"
	[ "$(rows "$T/p2")" -eq 137 ]
	[ "$(rows "$T/p3")" -eq 59 ]
	[ "$(tail -n 1 "$T/p2")" = "# end 137" ]
	[ "$(tail -n 1 "$T/p3")" = "# end 59" ]
	awk '!/^#/ && NF != 3 { exit 1 }' "$T/p2"
	awk '!/^#/ && NF != 4 { exit 1 }' "$T/p3"
}

@test "dempack random: header records provenance, seed, method and domain" {
	dempack random -n 20 --seed 42 --law nrd --lambda 3 --density 0.4 > "$T/p" 2>/dev/null
	grep -qx '# prog dempack [0-9.]* seed=42 args: random -n 20 --seed 42 --law nrd --lambda 3 --density 0.4' "$T/p"
	grep -qx '# seed 42' "$T/p"
	grep -qx '# method random law=nrd rmin=1 lambda=3 density=0.4' "$T/p"
	grep -qE '^# domain 0 0 [0-9.e+-]+ [0-9.e+-]+$' "$T/p"
}

@test "dempack random: every centre lies in the domain of the '# domain' line (2D and 3D)" {
	dempack random -n 500 --seed 3 --aspect 3:1 > "$T/p2" 2>/dev/null
	dempack random --dim 3 -n 500 --seed 3 --aspect 1:2:3 > "$T/p3" 2>/dev/null
	awk '/^# domain/ { X = $5; Y = $6 } /^#/ { next }
	     $1 < 0 || $1 > X || $2 < 0 || $2 > Y { bad++ } END { exit bad > 0 }' "$T/p2"
	awk '/^# domain/ { X = $6; Y = $7; Z = $8 } /^#/ { next }
	     $1 < 0 || $1 > X || $2 < 0 || $2 > Y || $3 < 0 || $3 > Z { bad++ } END { exit bad > 0 }' "$T/p3"
}

@test "dempack random: --aspect sets the domain's side ratios" {
	dempack random -n 100 --seed 3 --aspect 3:1 > "$T/p2" 2>/dev/null
	dempack random --dim 3 -n 100 --seed 3 --aspect 1:2:3 > "$T/p3" 2>/dev/null
	d2=$(grep '^# domain' "$T/p2")
	d3=$(grep '^# domain' "$T/p3")
	set -- $d2
	close_to "$5" "$(awk -v y="$6" 'BEGIN { printf "%.17g", 3 * y }')" 1e-12
	set -- $d3
	close_to "$7" "$(awk -v x="$6" 'BEGIN { printf "%.17g", 2 * x }')" 1e-12
	close_to "$8" "$(awk -v x="$6" 'BEGIN { printf "%.17g", 3 * x }')" 1e-12
}

@test "dempack random: the same --seed gives identical output, other seeds differ" {
	dempack random -n 300 --lambda 5 --seed 7 > "$T/a" 2>/dev/null
	dempack random -n 300 --lambda 5 --seed 7 > "$T/b" 2>/dev/null
	dempack random -n 300 --lambda 5 --seed 8 > "$T/c" 2>/dev/null
	cmp "$T/a" "$T/b"
	! cmp -s <(grep -v '^#' "$T/a") <(grep -v '^#' "$T/c")
	# and in 3D, binary
	dempack random --dim 3 -n 300 --seed 7 -b > "$T/a" 2>/dev/null
	dempack random --dim 3 -n 300 --seed 7 -b > "$T/b" 2>/dev/null
	cmp "$T/a" "$T/b"
}

@test "dempack random: without --seed a seed is drawn, written, and reproduces the run" {
	dempack random -n 50 > "$T/a" 2>/dev/null
	seed=$(sed -n 's/^# seed //p' "$T/a")
	[[ $seed =~ ^[0-9]+$ ]]
	grep -q "^# prog dempack .* seed=$seed args: random -n 50\$" "$T/a"
	dempack random -n 50 --seed "$seed" > "$T/b" 2>/dev/null
	cmp <(grep -v '^# prog' "$T/a") <(grep -v '^# prog' "$T/b")
}

@test "dempack random: the density of the '# domain' box is the target to 1e-9, 2D, every law" {
	for law in mono urd nrd lnrd; do
		for rho in 0.05 0.6 1; do
			dempack random -n 700 --law "$law" --lambda 10 --rmin '0.3 mm' \
				--density "$rho" --aspect 2:1 --seed 5 > "$T/p" 2>/dev/null
			got=$(density "$T/p" 2)
			echo "law $law rho $rho: $got"
			close_to "$got" "$rho" 1e-9
		done
	done
}

@test "dempack random: the density of the '# domain' box is the target to 1e-9, 3D, every law" {
	for law in mono urd nrd lnrd; do
		for rho in 0.1 0.37; do
			dempack random --dim 3 -n 700 --law "$law" --lambda 4 --density "$rho" \
				--aspect 1:2:1 --seed 6 > "$T/p" 2>/dev/null
			got=$(density "$T/p" 3)
			echo "law $law rho $rho: $got"
			close_to "$got" "$rho" 1e-9
		done
	done
}

@test "dempack random: radii lie in [rmin, lambda rmin] for every law; mono gives rmin" {
	for dim in 2 3; do
		for law in mono urd nrd lnrd; do
			dempack random --dim "$dim" -n 2000 --law "$law" --rmin 0.5 --lambda 8 --seed 9 > "$T/p" 2>/dev/null
			read -r lo hi < <(awk -v c=$((dim + 1)) '!/^#/ { r = $c; if (n++ == 0 || r < lo) lo = r; if (r > hi) hi = r }
				END { printf "%.17g %.17g\n", lo, hi }' "$T/p")
			echo "dim $dim $law: [$lo, $hi]"
			awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo >= 0.5 && hi <= 4) }'
			if [ "$law" = mono ]; then
				[ "$lo" = 0.5 ] && [ "$hi" = 0.5 ]
			else
				# the laws spread the radii over the range
				awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo < 1 && hi > 3) }'
			fi
		done
	done
}

@test "dempack random: nrd and lnrd centre where radius.h says (mean, median)" {
	# nrd: mean (rmin + rmax)/2 = 4.5; lnrd: median exp((ln 1 + ln 8)/2) = sqrt(8)
	dempack random -n 4000 --law nrd --lambda 8 --seed 2 > "$T/n" 2>/dev/null
	dempack random -n 4001 --law lnrd --lambda 8 --seed 2 > "$T/l" 2>/dev/null
	mean=$(awk '!/^#/ { s += $3; n++ } END { printf "%.17g", s / n }' "$T/n")
	median=$(grep -v '^#' "$T/l" | cut -d' ' -f3 | sort -g | sed -n 2001p)
	echo "nrd mean $mean, lnrd median $median"
	close_to "$mean" 4.5 0.01
	close_to "$median" 2.8284271247461903 0.03
}

@test "dempack random: --rmin '2 mm' gives radii of 0.002 m" {
	dempack random -n 10 --law mono --rmin '2 mm' --seed 1 > "$T/p" 2>/dev/null
	[ "$(grep -v '^#' "$T/p" | cut -d' ' -f3 | sort -u)" = 0.002 ]
	grep -q '^# method random law=mono rmin=0.002 ' "$T/p"
	dempack random -n 10 --law urd --lambda 2 --rmin '2 mm' --seed 1 > "$T/p" 2>/dev/null
	awk '!/^#/ && ($3 < 0.002 || $3 > 0.004) { exit 1 }' "$T/p"
}

@test "dempack random -b: text header, one block of records holding the text values, trailer" {
	dempack random -n 800 --lambda 4 --seed 11 > "$T/t" 2>/dev/null
	dempack random -n 800 --lambda 4 --seed 11 -b > "$T/b" 2>/dev/null
	cmp <(grep -v '^# prog' "$T/t" | sed '/^# data/q' | sed 's/^# format text$/# format binary/') \
	    <(head -c "$(grep -abx '# data' "$T/b" | cut -d: -f1)" "$T/b" | grep -av '^# prog'; echo '# data')
	# after "# data": count 800, 800 records of 3 f64, count 0, "# end 800"
	h=$(($(grep -abx '# data' "$T/b" | cut -d: -f1) + 7))
	[ "$(wc -c < "$T/b")" -eq $((h + 4 + 800 * 24 + 4 + 10)) ]
	[ "$(od -An -tu4 -j "$h" -N 4 "$T/b" | tr -d ' ')" = 800 ]
	[ "$(od -An -tu4 -j $((h + 4 + 800 * 24)) -N 4 "$T/b" | tr -d ' ')" = 0 ]
	[ "$(tail -c 10 "$T/b")" = "# end 800" ]
	# the records are the text rows, bit for bit (the text is exact)
	paste -d' ' <(grep -v '^#' "$T/t") <(od -An -v -tf8 -w24 -j $((h + 4)) -N $((800 * 24)) "$T/b") |
		awk 'NF != 6 || $1 != $4 || $2 != $5 || $3 != $6 { bad++ } END { exit bad > 0 || NR != 800 }'
}

@test "dempack random -b: demdetect reads it back to the same pairs as the text" {
	dempack random -n 800 --lambda 4 --seed 11 > "$T/t" 2>/dev/null
	dempack random -n 800 --lambda 4 --seed 11 -b > "$T/b" 2>/dev/null
	nt=$(demdetect -c "$T/t" 2>/dev/null)
	[ "$nt" -gt 0 ]
	[ "$(demdetect -c "$T/b" 2>/dev/null)" = "$nt" ]
	cmp <(demdetect "$T/t" 2>/dev/null | grep -v '^# prog') <(demdetect "$T/b" 2>/dev/null | grep -v '^# prog')
}

@test "dempack random -z and -z -b: gzip data that demdetect reads to the same pairs as text" {
	dempack random --dim 3 -n 800 --seed 12 > "$T/t" 2>/dev/null
	dempack random --dim 3 -n 800 --seed 12 -z > "$T/z" 2>/dev/null
	dempack random --dim 3 -n 800 --seed 12 -z -b > "$T/zb" 2>/dev/null
	[ "$(head -c 2 "$T/z" | od -An -tx1 | tr -d ' ')" = 1f8b ]
	[ "$(head -c 2 "$T/zb" | od -An -tx1 | tr -d ' ')" = 1f8b ]
	# the text stream is the gzip stream uncompressed, apart from the args
	cmp <(grep -v '^# prog' "$T/t") <(gzip -dc "$T/z" | grep -v '^# prog')
	nt=$(demdetect -c "$T/t" 2>/dev/null)
	[ "$nt" -gt 0 ]
	[ "$(demdetect -c "$T/z" 2>/dev/null)" = "$nt" ]
	[ "$(demdetect -c "$T/zb" 2>/dev/null)" = "$nt" ]
}

@test "dempack -o FILE: the complete stream in FILE, nothing on stdout, no temporary file left" {
	mkdir "$T/d"
	run --separate-stderr dempack random -n 100 --seed 1 -o "$T/d/p.txt"
	[ "$status" -eq 0 ]
	[ -z "$output" ]
	[ "$(ls "$T/d")" = p.txt ]
	dempack random -n 100 --seed 1 > "$T/ref" 2>/dev/null
	cmp <(grep -v '^# prog' "$T/ref") <(grep -v '^# prog' "$T/d/p.txt")
	[ "$(stat -c %a "$T/d/p.txt")" = 644 ]
}

@test "dempack -o FILE: on bad input no FILE is created and no temporary file is left" {
	mkdir "$T/d"
	run dempack random -n 100 --density 2 -o "$T/d/p.txt"
	[ "$status" -ne 0 ]
	[ -z "$(ls -A "$T/d")" ]
}

@test "dempack -o FILE: a write failure midway leaves no FILE, no temporary file, old FILE intact (exit 4)" {
	mkdir "$T/d"
	echo old > "$T/d/p.txt"
	# a file size limit of 8 blocks makes the write fail after a few kB
	run --separate-stderr bash -c "trap '' XFSZ; ulimit -f 8; dempack random -n 100000 --seed 1 -o '$T/d/p.txt'"
	echo "$stderr"
	[ "$status" -eq 4 ]
	[[ $stderr == *"dempack: $T/d/p.txt: "* ]]
	[ "$(ls -A "$T/d")" = p.txt ]
	[ "$(cat "$T/d/p.txt")" = old ]
}

@test "dempack -o into a missing folder: exit 4, message names the file" {
	run --separate-stderr dempack random -n 10 -o "$T/none/p.txt"
	[ "$status" -eq 4 ]
	[[ $stderr == "dempack: $T/none/p.txt: No such file or directory"* ]]
}

@test "dempack: a write error on standard output is exit 4 with a message" {
	[ -w /dev/full ] || skip "no /dev/full"
	run --separate-stderr bash -c 'dempack random -n 50000 --seed 1 > /dev/full'
	[ "$status" -eq 4 ]
	[[ $stderr == *"dempack: stdout: No space left on device"* ]]
}

@test "dempack --dump-scene: the resolved pack section, every default, on stdout" {
	run --separate-stderr dempack --dump-scene
	[ "$status" -eq 0 ]
	[ -z "$stderr" ]
	expected='pack:
  method: random
  dim: 2
  n: 1000
  density: 0.6
  radius:
    law: urd
    min: 1 m
    lambda: 1
  aspect: [1, 1]'
	[ "$output" = "$expected" ]
}

@test "dempack --dump-scene: its output loads with -s and gives the same stream" {
	for dim in 2 3; do
		dempack random --dim "$dim" -n 300 --law lnrd --lambda 3 --rmin '0.7 mm' \
			--density 0.45 --dump-scene > "$T/s.yaml"
		grep -q 'min: 0.0007 m' "$T/s.yaml"
		dempack random --dim "$dim" -n 300 --law lnrd --lambda 3 --rmin '0.7 mm' \
			--density 0.45 --seed 4 > "$T/a" 2>/dev/null
		dempack random -s "$T/s.yaml" --seed 4 > "$T/b" 2>/dev/null
		cmp <(grep -v '^# prog' "$T/a") <(grep -v '^# prog' "$T/b")
	done
	# options still override the scene
	dempack random -s "$T/s.yaml" -n 7 --seed 4 > "$T/c" 2>/dev/null
	[ "$(rows "$T/c")" -eq 7 ]
}

@test "dempack -n 0: a valid empty stream" {
	run --separate-stderr dempack random -n 0 --seed 1
	[ "$status" -eq 0 ]
	[ "${lines[-1]}" = "# end 0" ]
	[ "$(echo "$output" | grep -vc '^#')" -eq 0 ]
}

@test "dempack: the cost line is the last line of stderr: wall_s cpu_s rss_mb pack_s objects" {
	run --separate-stderr dempack random -n 123 --seed 1
	[ "$status" -eq 0 ]
	[[ ${stderr_lines[-1]} =~ ^dempack:\ cost:\ wall_s=[0-9.]+\ cpu_s=[0-9.]+\ rss_mb=[0-9.]+\ pack_s=[0-9.]+\ objects=123$ ]]
	# also with -q and with -o
	run --separate-stderr dempack random -n 5 --seed 1 -q -o "$T/p"
	[ "$status" -eq 0 ]
	[[ ${stderr_lines[-1]} == "dempack: cost: wall_s="*" objects=5" ]]
}

# ---- dempack shots (Han 2004, Ch. 7.1.3 and 8.6; dem-streams(5) "shots") ----

@test "dempack shots: the Ch. 8.6 layout gives 512 rows, 16 in each of 32 passes, inside the area" {
	run --separate-stderr dempack shots --grid 4 --passes 32 --area 5.6mm:5.6mm \
		--shot-radius 0.7mm --speed 46.5 --seed 1
	[ "$status" -eq 0 ]
	echo "$output" > "$T/s"
	[ "${lines[0]}" = "# dem shots 1" ]
	grep -qx '# columns pass:u32:- t:f64:s x:f64:m y:f64:m r:f64:m vx:f64:m/s vy:f64:m/s vz:f64:m/s' "$T/s"
	grep -qx '# method shots pattern=grid grid=4 passes=32 per_pass=16' "$T/s"
	grep -qx '# area -0.0028 -0.0028 0.0028 0.0028' "$T/s"
	[ "$(rows "$T/s")" -eq 512 ]
	[ "${lines[-1]}" = "# end 512" ]
	# 16 rows per pass 0..31; inside the area; r 0.7 mm; v = (0, 0, -46.5)
	awk '!/^#/ { n[$1]++; if ($3 < -0.0028 || $3 >= 0.0028 || $4 < -0.0028 || $4 >= 0.0028) bad++
	             if ($5 != 0.0007 || $6 != 0 || $7 != 0 || $8 != -46.5 || $2 != 0) bad++ }
	     END { for (p = 0; p < 32; p++) if (n[p] != 16) bad++; exit bad > 0 }' "$T/s"
	[[ ${stderr_lines[-1]} =~ ^dempack:\ cost:\ wall_s=[0-9.]+\ cpu_s=[0-9.]+\ rss_mb=[0-9.]+\ pack_s=[0-9.]+\ shots=512\ passes=32$ ]]
}

@test "dempack shots: --angle 60deg gives v = speed (cos 60, 0, -sin 60)" {
	dempack shots --grid 1 --passes 1 --angle 60deg --speed 10 --seed 1 > "$T/s" 2>/dev/null
	awk '!/^#/ { d = $6 - 5; e = $8 + 8.660254037844386; exit !(d * d < 1e-24 && e * e < 1e-24 && $7 == 0) }' "$T/s"
}

@test "dempack shots random: --coverage 200 reaches the target (98 % at 100 %, twice the impacts)" {
	run --separate-stderr dempack shots --pattern random --coverage 200 --dimple-radius 0.4mm --seed 1
	[ "$status" -eq 0 ]
	echo "$output" > "$T/s"
	line=$(grep '^# coverage ' "$T/s")
	echo "$line"
	[[ $line =~ ^#\ coverage\ target=200\ covered=([0-9.]+)\ impacts_100=([0-9]+)\ dimple_radius=0.0004$ ]]
	covered=${BASH_REMATCH[1]} n100=${BASH_REMATCH[2]}
	awk -v c="$covered" 'BEGIN { exit !(c >= 0.995) }'
	[ "$(rows "$T/s")" -eq $((2 * n100)) ]
	[[ ${stderr_lines[-1]} == "dempack: cost: "*" shots=$((2 * n100)) passes="*" coverage=0.99"* ]]
	# and 100 %: at least 98 % covered with n100 impacts
	dempack shots --pattern random --coverage 100 --dimple-radius 0.4mm --seed 1 > "$T/h" 2>/dev/null
	[ "$(rows "$T/h")" -eq "$n100" ]
	grep -qE '^# coverage target=100 covered=0\.98[0-9]* ' "$T/h"
}

@test "dempack shots random: the same seed gives the same stream, another seed another" {
	dempack shots --pattern random --passes 5 --seed 3 > "$T/a" 2>/dev/null
	dempack shots --pattern random --passes 5 --seed 3 > "$T/b" 2>/dev/null
	dempack shots --pattern random --passes 5 --seed 4 > "$T/c" 2>/dev/null
	[ "$(rows "$T/a")" -eq 40 ]
	cmp "$T/a" "$T/b"
	! cmp -s <(grep -v '^#' "$T/a") <(grep -v '^#' "$T/c")
}

@test "dempack shots random: a coverage without --dimple-radius is an error naming the key, no output" {
	run --separate-stderr dempack shots --pattern random --coverage 100 --seed 1
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[[ ${stderr_lines[0]} == "dempack: pack.dimple_radius: required with pack.coverage"* ]]
}

@test "dempack shots random: a pass that cannot hold the shots is an error, no output" {
	run --separate-stderr dempack shots --pattern random --per-pass 16 --passes 2 --seed 1
	[ "$status" -eq 1 ]
	[ -z "$output" ]
	[[ ${stderr_lines[0]} == "dempack: random pattern: cannot place per_pass 16 shots"* ]]
}

@test "dempack shots: options of other methods and patterns are usage errors, and vice versa" {
	usage_error dempack shots -n 5
	[[ ${stderr_lines[0]} == *"--number: not an option of method shots"* ]]
	usage_error dempack shots --law urd
	usage_error dempack random --grid 4
	[[ ${stderr_lines[0]} == *"--grid: not an option of method random"* ]]
	usage_error dempack front --coverage 100
	usage_error dempack shots --coverage 100 --dimple-radius 1mm
	[[ ${stderr_lines[0]} == *"--coverage: pack.coverage: not read with pack.pattern grid"* ]]
	usage_error dempack shots --pattern random --grid 3
	usage_error dempack shots --pattern random --coverage 100 --passes 3 --dimple-radius 1mm
	usage_error dempack shots --angle 100deg
	usage_error dempack shots --pattern hexagon
	usage_error dempack shots --area 5.6mm
}

@test "dempack shots --dump-scene: the pack and shot sections, every default; it loads back" {
	run --separate-stderr dempack shots --dump-scene
	[ "$status" -eq 0 ]
	expected='pack:
  method: shots
  pattern: grid
  area: [0.0056 m, 0.0056 m]
  center: [0 m, 0 m]
  grid: 4
  passes: 32
shot:
  radius: 0.0007 m
  law: mono
  lambda: 1
  speed: 46.5 m/s
  speed_scatter: 0
  angle: 1.5707963267948966 rad
  azimuth: 0 rad'
	[ "$output" = "$expected" ]
	dempack shots --pattern random --coverage 150 --dimple-radius 0.4mm --dump-scene > "$T/s.yaml"
	dempack shots -s "$T/s.yaml" --seed 2 > "$T/a" 2>/dev/null
	dempack shots --pattern random --coverage 150 --dimple-radius 0.4mm --seed 2 > "$T/b" 2>/dev/null
	cmp <(grep -v '^# prog' "$T/a") <(grep -v '^# prog' "$T/b")
}

# ---- front in a polygon, --vtk ------------------------------------------

# Every disk of the stream inside the polygon of its '# polygon' line:
# centre inside (crossing number), every edge at least r (1 - 1e-9) away.
inside_polygon() {
	awk '/^# polygon / { n = (NF - 2) / 2; for (i = 0; i < n; i++) { X[i] = $(3 + 2 * i); Y[i] = $(4 + 2 * i) } }
	     /^#/ { next }
	     { x = $1; y = $2; r = $3; c = 0
	       for (i = 0; i < n; i++) {
		 j = (i + n - 1) % n
		 if ((Y[i] > y) != (Y[j] > y) && x < X[j] + (y - Y[j]) * (X[i] - X[j]) / (Y[i] - Y[j])) c = !c
		 dx = X[i] - X[j]; dy = Y[i] - Y[j]
		 t = ((x - X[j]) * dx + (y - Y[j]) * dy) / (dx * dx + dy * dy); t = t < 0 ? 0 : t > 1 ? 1 : t
		 ex = x - X[j] - t * dx; ey = y - Y[j] - t * dy
		 if (sqrt(ex * ex + ey * ey) < r * (1 - 1e-9)) { print "edge", i, NR; bad++ }
	       }
	       if (!c) { print "outside", NR; bad++ } ; k++ }
	     END { if (bad || k == 0) exit 1 }' "$1"
}

@test "dempack front --polygon: an L and a hopper, with and without gravity, every disk inside, no overlap" {
	for g in "" --gravity; do
		dempack front --polygon 0:0:2:0:2:1:1:1:1:2:0:2 --rmin 0.02 --lambda 3 --seed 4 $g -q >"$T/l"
		grep -q '^# polygon 0 0 2 0 2 1 1 1 1 2 0 2$' "$T/l"
		! grep -q '^# domain' "$T/l"
		inside_polygon "$T/l"
		[ "$(demdetect -a brute --shape 1e-9 -c "$T/l" 2>/dev/null)" -eq 0 ]
		dempack front --polygon 0:10:4:2:4:0:6:0:6:2:10:10 --rmin 0.05 --lambda 4 --seed 4 $g -q >"$T/h"
		inside_polygon "$T/h"
		[ "$(demdetect -a brute --shape 1e-9 -c "$T/h" 2>/dev/null)" -eq 0 ]
		[ "$(rows "$T/h")" -gt 200 ]
	done
}

@test "dempack front: pack.polygon in the scene with units; clockwise the same disks" {
	printf 'pack:\n  method: front\n  polygon: [0 mm, 0 mm, 20 mm, 0 mm, 15 mm, 10 mm, 5 mm, 10 mm]\n  radius: {min: 0.2 mm, lambda: 2}\n' >"$T/s.yaml"
	dempack front -s "$T/s.yaml" --seed 2 -q >"$T/a"
	grep -q '^# polygon 0 0 0.02 0 0.015 0.01 0.005 0.01$' "$T/a"
	inside_polygon "$T/a"
	dempack front --polygon 5mm:10mm:15mm:10mm:20mm:0mm:0mm:0mm --rmin 0.2mm --lambda 2 --seed 2 -q >"$T/b"
	diff <(grep -v '^#' "$T/a") <(grep -v '^#' "$T/b")
}

@test "dempack front --polygon: bad polygons and the closed form are refused, no output" {
	for p in 0:0:1:0 0:0:1:1:1:0:0:1 0:0:1:1:2:2 0:0:1:0:2; do
		run --separate-stderr dempack front --polygon "$p" -o "$T/x"
		# a usage error on the command line (2), a scene value error (1)
		[ "$status" -eq 1 ] || [ "$status" -eq 2 ] || { echo "$p: $status $stderr"; false; }
		[[ "$stderr" == *polygon* ]]
		[ ! -e "$T/x" ]
	done
	run --separate-stderr dempack front --form closed --polygon 0:0:1:0:0:1 -o "$T/x"
	[ "$status" -eq 2 ]
	[[ "$stderr" == *"open form"* ]]
	[ ! -e "$T/x" ]
	usage_error dempack random --vtk "$T/v"
}

@test "dempack front --vtk: legacy VTK points with the stream's centres and radii" {
	dempack front --polygon 0:0:2:0:2:1:1:1:1:2:0:2 --rmin 0.05 --lambda 2 --seed 1 -q --vtk "$T/p.vtk" >"$T/p"
	n=$(rows "$T/p")
	head -1 "$T/p.vtk" | grep -q '^# vtk DataFile Version 3.0$'
	grep -q '^DATASET POLYDATA$' "$T/p.vtk"
	grep -q "^POINTS $n double\$" "$T/p.vtk"
	grep -q "^VERTICES $n $((2 * n))\$" "$T/p.vtk"
	grep -q "^POINT_DATA $n\$" "$T/p.vtk"
	grep -q '^SCALARS radius double 1$' "$T/p.vtk"
	# same values: points (x y 0) and radii, in order, against the stream
	awk -v n="$n" 'FNR == NR { if (!/^#/) { k++; X[k] = $1; Y[k] = $2; R[k] = $3 } next }
	     /^POINTS/ { m = 1; i = 0; next } /^VERTICES/ { m = 0 }
	     /^LOOKUP_TABLE/ { m = 2; i = 0; next }
	     m == 1 { i++; if ($1 != X[i] || $2 != Y[i] || $3 != 0) bad++ }
	     m == 2 { i++; if ($1 != R[i]) bad++ }
	     END { if (bad || i != n || k != n) { print bad, i, k; exit 1 } }' "$T/p" "$T/p.vtk"
	ls "$T" | { ! grep -q tmp; }
}

# dempack compress (Ch. 6).  Every sphere inside the walls of the stream's
# header (box, cylinder, planes), to 1e-9 of its radius.
inside_domain() {
	awk 'BEGIN { np = 0 }
	     /^# box / { b = 1; for (k = 0; k < 6; k++) B[k] = $(3 + k) }
	     /^# cylinder / { c = 1; cx = $3; cy = $4; R = $5; B[2] = $6; B[5] = $7 }
	     /^# plane / { N[np, 0] = $3; N[np, 1] = $4; N[np, 2] = $5; D[np] = $6; np++ }
	     /^#/ { next }
	     { x = $1; y = $2; z = $3; r = $4; t = 1e-9 * r; k++
	       if (b && (x - r < B[0] - t || y - r < B[1] - t || x + r > B[3] + t || y + r > B[4] + t)) bad++
	       if (z - r < B[2] - t || z + r > B[5] + t) bad++
	       if (c && sqrt((x - cx) ^ 2 + (y - cy) ^ 2) + r > R + t) bad++
	       for (p = 0; p < np; p++)
		 if (N[p, 0] * x + N[p, 1] * y + N[p, 2] * z - D[p] < r - t) bad++ }
	     END { if (bad || !k) { print "outside:", bad + 0, "of", k + 0; exit 1 } }' "$1"
}

# The density of a 3D stream in a box: sphere volume over the box's.
box_density() {
	awk '/^# box / { V = ($6 - $3) * ($7 - $4) * ($8 - $5) } /^#/ { next }
	     { s += 4 / 3 * 3.141592653589793 * $4 ^ 3 } END { printf "%.17g\n", s / V }' "$1"
}

@test "dempack compress: a box of URD spheres, no overlap (demdetect brute force), inside, the density in the header" {
	dempack compress --box 0:0:0:14:14:14 --rmin 0.5 --lambda 2 --seed 3 -q >"$T/p" 2>"$T/err"
	head -1 "$T/p" | grep -q '^# dem particles 1$'
	grep -q '^# dim 3$' "$T/p"
	grep -q '^# columns x:f64:m y:f64:m z:f64:m r:f64:m$' "$T/p"
	grep -q '^# method compress law=urd rmin=0.5 lambda=2 .*relax=true$' "$T/p"
	grep -q '^# box 0 0 0 14 14 14$' "$T/p"
	[ "$(rows "$T/p")" -gt 600 ]
	[ "$(demdetect -a brute --shape 1e-9 -c "$T/p" 2>/dev/null)" -eq 0 ]
	inside_domain "$T/p"
	rho=$(awk '/^# density / { print $3 }' "$T/p")
	close_to "$(box_density "$T/p")" "$rho" 1e-12
	# the core (a diameter from the walls) denser than the whole, and than
	# random loose packing, 0.555 (Onoda and Liniger 1990)
	core=$(awk '/^# density_core / { print $3 }' "$T/p")
	awk -v r="$rho" -v c="$core" 'BEGIN { exit !(c > r && c > 0.555) }'
	tail -1 "$T/err" | grep -q "^dempack: cost: wall_s=.* objects=$(rows "$T/p") density=.* density_core=.* relax_steps="
}

@test "dempack compress --no-relax: the thesis's stages alone, valid and looser" {
	dempack compress --box 0:0:0:12:12:12 --rmin 0.5 --lambda 2 --seed 5 -q >"$T/a"
	dempack compress --box 0:0:0:12:12:12 --rmin 0.5 --lambda 2 --seed 5 -q --no-relax >"$T/t"
	grep -q 'relax=false$' "$T/t"
	[ "$(demdetect -a brute --shape 1e-9 -c "$T/t" 2>/dev/null)" -eq 0 ]
	inside_domain "$T/t"
	awk -v a="$(box_density "$T/a")" -v t="$(box_density "$T/t")" 'BEGIN { exit !(a > t + 0.03) }'
}

@test "dempack compress: a cylinder cut by two planes, from the scene with units; the options give the same spheres" {
	printf 'pack:\n  method: compress\n  cylinder: [0 mm, 0 mm, 4 mm, 0 mm, 8 mm]\n  planes: [1, 0, 1, 2 mm, -1, 0, 0, -3 mm]\n  radius: {law: urd, min: 0.25 mm, lambda: 2}\n' >"$T/s.yaml"
	dempack compress -s "$T/s.yaml" --seed 2 -q >"$T/a"
	grep -q '^# cylinder 0 0 0.004 0 0.008$' "$T/a"
	[ "$(grep -c '^# plane ' "$T/a")" -eq 2 ]
	[ "$(rows "$T/a")" -gt 300 ]
	inside_domain "$T/a"
	[ "$(demdetect -a brute --shape 1e-9 -c "$T/a" 2>/dev/null)" -eq 0 ]
	dempack compress --cylinder 0:0:4mm:0:8mm --planes 1:0:1:2mm:-1:0:0:-3mm --rmin 0.25mm --lambda 2 --seed 2 -q >"$T/b"
	diff <(grep -v '^#' "$T/a") <(grep -v '^#' "$T/b")
}

@test "dempack compress: the same seed gives the same stream, another seed another" {
	dempack compress --box 0:0:0:10:10:10 --rmin 0.5 --seed 8 -q >"$T/a"
	dempack compress --box 0:0:0:10:10:10 --rmin 0.5 --seed 8 -q >"$T/b"
	dempack compress --box 0:0:0:10:10:10 --rmin 0.5 --seed 9 -q >"$T/c"
	diff <(grep -v '^# prog' "$T/a") <(grep -v '^# prog' "$T/b")
	! diff -q <(grep -v '^#' "$T/a") <(grep -v '^#' "$T/c") >/dev/null
}

@test "dempack compress --vtk --stages: VTK points of the stream, a stage table ending at the stream's density" {
	dempack compress --box 0:0:0:10:10:10 --rmin 0.5 --seed 1 -q --vtk "$T/p.vtk" --stages "$T/st" >"$T/p"
	n=$(rows "$T/p")
	grep -q "^POINTS $n double\$" "$T/p.vtk"
	grep -q "^POINT_DATA $n\$" "$T/p.vtk"
	grep -q '^# seconds	phase	batch	spheres	added	iterations	density$' "$T/st"
	awk -F'\t' '!/^#/ { k++; ph[$2]++ } END { exit !(k >= 4 && ph["init"] == 1 && ph["global"] && ph["shake"] && ph["relax"]) }' "$T/st"
	last=$(grep -v '^#' "$T/st" | tail -1 | cut -f 4)
	[ "$last" -eq "$n" ]
	ls "$T" | { ! grep -q tmp; }
}

@test "dempack compress: -v reports each stage on stderr; -q none" {
	run --separate-stderr dempack compress --box 0:0:0:8:8:8 --rmin 0.5 --seed 1 -v -o "$T/p"
	[ "$status" -eq 0 ]
	[[ "$stderr" == *"dempack: compress: global batch 0: "*" spheres"* ]]
	run --separate-stderr dempack compress --box 0:0:0:8:8:8 --rmin 0.5 --seed 1 -q -o "$T/p"
	[ "${#stderr_lines[@]}" -eq 1 ]
	[[ ${stderr_lines[0]} == "dempack: cost: "* ]]
}

@test "dempack compress: bad domains are refused naming the key, no output; other methods' options are usage errors" {
	for a in "--box 0:0:0:1:-1:1" "--cylinder 0:0:0:0:1" "--cylinder 0:0:1:1:0" "--planes 0:0:0:1" "--planes 1:0:0"; do
		run --separate-stderr dempack compress $a --rmin 0.1 -o "$T/x"
		[ "$status" -eq 1 ] || [ "$status" -eq 2 ] || { echo "$a: $status $stderr"; false; }
		[[ "$stderr" == *pack.* ]] || [[ "$stderr" == *--* ]]
		[ ! -e "$T/x" ]
	done
	# typed, a usage error (2); from the scene, bad input (1)
	run --separate-stderr dempack compress --box 0:0:0:1:1:1 --cylinder 0:0:1:0:1 -o "$T/x"
	[ "$status" -eq 2 ]
	[[ "$stderr" == *"pack.box"* ]]
	[ ! -e "$T/x" ]
	printf 'pack:\n  box: [0, 0, 0, 1, 1, 1]\n  cylinder: [0, 0, 1, 0, 1]\n' >"$T/s.yaml"
	run --separate-stderr dempack compress -s "$T/s.yaml" -o "$T/x"
	[ "$status" -eq 1 ]
	[[ "$stderr" == *"s.yaml:"*"pack.box"* ]]
	[ ! -e "$T/x" ]
	# a domain narrower than a sphere
	run --separate-stderr dempack compress --box 0:0:0:1:1:1 --rmin 1 -o "$T/x"
	[ "$status" -eq 1 ]
	[ ! -e "$T/x" ]
	usage_error dempack compress --density 0.5
	usage_error dempack random --no-relax
	usage_error dempack front --stages "$T/s"
	usage_error dempack shots --box 0:0:0:1:1:1
}

@test "dempack front: 1M disks (URD [0.5, 1], open form) with and without a check limit: no overlap by D-cell, all inside" {
	for k in 0 5; do
		run --separate-stderr bash -c "dempack front --domain 0:0:1500:1500 --rmin 0.5 --lambda 2 --seed 3 --check-limit $k -b -o '$T/f$k' &&
			demdetect -a dcell --shape 1e-9 -c '$T/f$k'"
		echo "$stderr"
		[ "$status" -eq 0 ]
		[ "$output" = 0 ]
		# close to a million disks, every one inside the square
		n=$(sed -n 's/.*objects=\([0-9]*\).*/\1/p' <<< "$stderr" | head -1)
		[ "$n" -gt 990000 ]
	done
	dempack front --domain 0:0:1500:1500 --rmin 0.5 --lambda 2 --seed 3 2>/dev/null |
		awk '!/^#/ { if ($1 - $3 < -1e-9 || $2 - $3 < -1e-9 || $1 + $3 > 1500 + 1e-9 || $2 + $3 > 1500 + 1e-9) bad++; n++ }
		     END { exit !(n > 990000 && !bad) }'
}
