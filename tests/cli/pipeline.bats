#!/usr/bin/env bats
# Pipelines of the programs, as DESIGN.md means them to be used, checked
# against independent brute-force counts written in awk over the text
# stream; and the whole pipeline under valgrind.

bats_require_minimum_version 1.5.0

setup() {
	T=$BATS_TEST_TMPDIR
}

# Brute force in awk over a text particle stream of dimension dim: prints
# the number of pairs of overlapping closed boxes and the number of pairs of
# really overlapping disks/spheres (r_i + r_j - d > 0), with the minimum
# image along the axes of per ("x", "xy", ...; period from '# domain').
brute() {
	awk -v dim="$1" -v per="${3:-}" '
		BEGIN { n = 0 }
		/^# domain / { for (d = 0; d < dim; d++) L[d] = $(3 + dim + d) - $(3 + d) }
		/^#/ { next }
		{ for (d = 0; d <= dim; d++) v[n, d] = $(d + 1) + 0; n++ }
		END {
			for (d = 0; d < dim; d++) P[d] = index(per, substr("xyz", d + 1, 1)) > 0
			for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) {
				s = v[i, dim] + v[j, dim]; dd = 0; box = 1
				for (d = 0; d < dim; d++) {
					x = v[j, d] - v[i, d]
					if (P[d]) { while (x > L[d] / 2) x -= L[d]; while (x < -L[d] / 2) x += L[d] }
					if ((x < 0 ? -x : x) > s) box = 0
					dd += x * x
				}
				nbox += box
				if (s * s > dd) nshape++
			}
			print nbox + 0, nshape + 0
		}' "$2"
}

@test "pipeline: dempack -b | demdetect -c counts the pairs of the text stream, both exit 0" {
	run --separate-stderr bash -c 'dempack random -n 20000 --lambda 10 --seed 1 -b | demdetect -c; echo "${PIPESTATUS[*]}"'
	[ "$status" -eq 0 ]
	[ "${lines[1]}" = "0 0" ]
	n=${lines[0]}
	[[ $n =~ ^[0-9]+$ ]] && [ "$n" -gt 0 ]
	dempack random -n 20000 --lambda 10 --seed 1 > "$T/p" 2>/dev/null
	[ "$(demdetect -c "$T/p" 2>/dev/null)" -eq "$n" ]
	# both cost lines on stderr
	[ "$(grep -c ': cost: ' <<< "$stderr")" -eq 2 ]
}

@test "pipeline: dempack -z | demdetect gives the pair stream of the text, with both provenance lines" {
	dempack random --dim 3 -n 3000 --lambda 3 --seed 2 -z 2>/dev/null | demdetect > "$T/z" 2>/dev/null
	dempack random --dim 3 -n 3000 --lambda 3 --seed 2 2>/dev/null | demdetect > "$T/t" 2>/dev/null
	[ "$(grep -vc '^#' "$T/t")" -gt 0 ]
	cmp <(grep -v '^# prog dempack' "$T/t") <(grep -v '^# prog dempack' "$T/z")
	grep -q '^# prog dempack .* seed=2 args: random --dim 3 -n 3000 --lambda 3 --seed 2 -z$' "$T/z"
	grep -q '^# prog demdetect .* args:$' "$T/z"
}

@test "pipeline: dempack -b -z | demdetect -b -z -o FILE: the trailer counts the pairs of -c" {
	dempack random -n 5000 --seed 3 -b -z 2>/dev/null | demdetect -b -z -o "$T/q.gz" 2>/dev/null
	n=$(dempack random -n 5000 --seed 3 2>/dev/null | demdetect -c 2>/dev/null)
	[ "$n" -gt 0 ]
	[ "$(gzip -dc "$T/q.gz" | tail -c 20 | grep -ao '# end [0-9]*$')" = "# end $n" ]
}

@test "pipeline: dempack | demdetect -c equals the awk brute-force count of box pairs (2D, 3D)" {
	dempack random -n 400 --lambda 5 --seed 4 > "$T/p2" 2>/dev/null
	dempack random --dim 3 -n 400 --lambda 5 --seed 4 > "$T/p3" 2>/dev/null
	read -r box2 _ < <(brute 2 "$T/p2")
	read -r box3 _ < <(brute 3 "$T/p3")
	echo "awk: $box2 $box3"
	[ "$box2" -gt 0 ] && [ "$box3" -gt 0 ]
	[ "$(demdetect -c < "$T/p2" 2>/dev/null)" -eq "$box2" ]
	[ "$(demdetect -c < "$T/p3" 2>/dev/null)" -eq "$box3" ]
}

@test "pipeline: dempack | demdetect --shape -c is > 0 and equals the awk count of overlapping disks" {
	for set in "2 urd 1" "2 urd 10" "2 lnrd 4" "3 urd 1" "3 nrd 5"; do
		read -r dim law lambda <<< "$set"
		dempack random --dim "$dim" -n 400 --law "$law" --lambda "$lambda" --seed 5 > "$T/p" 2>/dev/null
		read -r box shape < <(brute "$dim" "$T/p")
		got=$(dempack random --dim "$dim" -n 400 --law "$law" --lambda "$lambda" --seed 5 2>/dev/null | demdetect --shape -c 2>/dev/null)
		echo "$set: awk $shape of $box box pairs, demdetect $got"
		[ "$shape" -gt 0 ]
		[ "$shape" -lt "$box" ]
		[ "$got" -eq "$shape" ]
	done
}

@test "pipeline: dempack | demdetect --periodic --shape equals the awk minimum-image count" {
	for set in "2 x" "2 xy" "3 z" "3 xyz"; do
		read -r dim per <<< "$set"
		dempack random --dim "$dim" -n 400 --lambda 2 --seed 6 > "$T/p" 2>/dev/null
		read -r box shape < <(brute "$dim" "$T/p" "$per")
		read -r box0 _ < <(brute "$dim" "$T/p")
		echo "$set: awk $box box pairs ($box0 without wrapping), $shape overlapping"
		[ "$box" -gt "$box0" ]
		[ "$(demdetect --periodic "$per" -c < "$T/p" 2>/dev/null)" -eq "$box" ]
		[ "$(demdetect --periodic "$per" --shape -c < "$T/p" 2>/dev/null)" -eq "$shape" ]
	done
}

@test "pipeline: a failing dempack gives demdetect no stream: exit 1, nothing on stdout" {
	# dempack refuses the bad option value (usage, 2); demdetect sees no stream (1)
	run --separate-stderr bash -c 'dempack random -n 100 --density 2 | demdetect; echo "${PIPESTATUS[*]}"'
	[ "${lines[0]}" = "2 1" ]
	[ "${#lines[@]}" -eq 1 ]
	[[ $stderr == *"demdetect: stdin: empty input"* ]]
}

@test "pipeline: a stream cut on its way (head -c) is refused by demdetect as truncated" {
	for fmt in "" "-b" "-z"; do
		run --separate-stderr bash -c "dempack random -n 20000 --seed 7 $fmt 2>/dev/null | head -c 100000 | demdetect -c"
		echo "format '$fmt': $status $output / $stderr"
		[ "$status" -eq 1 ]
		[ -z "$output" ]
		[[ $stderr == "demdetect: stdin"* ]]
	done
}

@test "pipeline: -o to a FIFO or /dev/null writes through it and leaves it what it was" {
	# the outputs are written atomically (a temporary renamed into place),
	# but a path that is not a regular file is written in place: renamed
	# over, /dev/null became a regular file when run as root
	mkfifo "$T/p"
	timeout 20 cat "$T/p" > "$T/got" &   # (bounded: the old code never opened the FIFO)
	dempack random -n 100 --seed 1 -o "$T/p"
	wait
	[ -p "$T/p" ]
	dempack random -n 100 --seed 1 > "$T/want"
	cmp <(grep -v "^# prog" "$T/got") <(grep -v "^# prog" "$T/want")   # the provenance line holds the arguments
	[ -z "$(ls "$T" | grep tmp)" ]
	dempack random -n 100 --seed 1 -o /dev/null
	dempack random -n 100 --seed 1 | demdetect -o /dev/null
	[ -c /dev/null ]
}

@test "valgrind: dempack | demdetect run clean (no invalid access, no definite leak)" {
	[ "${DEM_SANITIZE:-}" != 1 ] || skip "sanitizer build: ASan and valgrind do not mix"
	command -v valgrind >/dev/null || skip "valgrind is not installed"
	vg="valgrind -q --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite"
	run --separate-stderr bash -c "$vg dempack random -n 300 --lambda 3 --seed 8 -b |
		$vg demdetect --shape --periodic xy -a dcell; echo \"\${PIPESTATUS[*]}\""
	echo "$stderr"
	[ "${lines[-1]}" = "0 0" ]
	[ "$(grep -vc '^#' <<< "$output")" -gt 1 ]
	# the other output forms, algorithms and the error paths
	$vg dempack random --dim 3 -n 200 --seed 8 -z -o "$T/p3" 2>"$T/err" || { cat "$T/err"; false; }
	$vg demdetect -a asdt -c "$T/p3" >/dev/null 2>"$T/err" || { cat "$T/err"; false; }
	$vg demdetect -a scell -b -o "$T/q" "$T/p3" 2>"$T/err" || { cat "$T/err"; false; }
	head -c 3000 "$T/p3" > "$T/cut"
	run $vg demdetect -a nbs "$T/cut"
	[ "$status" -eq 1 ]
	run $vg dempack random --bogus
	[ "$status" -eq 2 ]
}
