#!/usr/bin/env bats
# Command-line tests of demfit.  References: the closed form of the
# two-parameter curve (T = ln 10 / b, H(T) = 0.9 a); H(2T) = 1.1 H(T) on the
# fitted three-parameter curve; the J443 rule on the points by hand; the
# exit codes of DESIGN.md.  The curves are written by awk from made-up
# parameters (heights of an A strip, exposures in passes).

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	# passes, a made-up coverage column, H = 0.3 mm (1 - exp(-0.3 n))
	awk 'BEGIN { print "# passes coverage:- arc_height:mm"
		split("1 2 3 4 6 8 12 16", n, " ")
		for (i = 1; i <= 8; i++) printf "%d 0.%d %.12g\n", n[i], i, 0.3 * (1 - exp(-0.3 * n[i])) }' > "$T/exp2"
	# H = 0.3 mm (1 - exp(-0.15 n^1.4)), in m, two columns
	awk 'BEGIN { split("1 2 3 4 6 8 12 16 24 32", n, " ")
		for (i = 1; i <= 10; i++) printf "%d %.12g\n", n[i], 3e-4 * (1 - exp(-0.15 * n[i] ^ 1.4)) }' > "$T/exp3"
}


@test "demfit --help and --version: stdout, exit 0" {
	run --separate-stderr demfit --help
	[ "$status" -eq 0 ]
	[[ ${lines[0]} == "Usage: demfit "* ]]
	[ -z "$stderr" ]
	run --separate-stderr demfit --version
	[ "$status" -eq 0 ]
	[[ $output =~ ^demfit\ \(dem\ toolkit\)\ [0-9]+\.[0-9]+\.[0-9]+$ ]]
}

@test "demfit: exact two-parameter points give T = ln 10 / b and H = 0.9 a (m and inches); the rule on the points brackets T" {
	demfit --unit mm --columns 1:3 "$T/exp2" > "$T/fit" 2> "$T/err"
	[ "$(value points "$T/fit")" -eq 8 ]
	rel_close "$(value exp2_a "$T/fit")" 3e-4 1e-6
	rel_close "$(value exp2_T "$T/fit")" "$(awk 'BEGIN { printf "%.12g", log(10) / 0.3 }')" 1e-6
	rel_close "$(value exp2_H "$T/fit")" 2.7e-4 1e-6
	rel_close "$(value exp2_H_mm "$T/fit")" 0.27 1e-6
	rel_close "$(value exp2_H_in "$T/fit")" "$(awk 'BEGIN { printf "%.12g", 2.7e-4 / 0.0254 }')" 1e-5
	[ "$(value exp2_intensity "$T/fit")" = 0.0106A ]
	[ "$(value exp2_extrapolated "$T/fit")" -eq 0 ]
	# the three-parameter fit of the same points finds c = 1
	rel_close "$(value exp3_c "$T/fit")" 1 1e-5
	# the rule: H(16)/H(8) = 1.0907 <= 1.1 first (H(12) has no 24)
	[ "$(value points_T "$T/fit")" = 8 ]
	rel_close "$(value points_ratio "$T/fit")" "$(awk 'BEGIN { printf "%.12g", (1 - exp(-4.8)) / (1 - exp(-2.4)) }')" 1e-5
	tail -n 1 "$T/err" | grep -q '^demfit: cost: wall_s=.* points=8 iterations_exp2=[0-9]* iterations_exp3=[0-9]*$'
}

@test "demfit --form exp3: the fitted curve doubles to 1.1 at T; --strip names the strip; -o writes the same atomically" {
	demfit --form exp3 --strip N "$T/exp3" > "$T/fit" 2>/dev/null
	! grep -q '^exp2_' "$T/fit"
	rel_close "$(value exp3_c "$T/fit")" 1.4 1e-5
	a=$(value exp3_a "$T/fit") b=$(value exp3_b "$T/fit") c=$(value exp3_c "$T/fit") t=$(value exp3_T "$T/fit")
	awk -v a="$a" -v b="$b" -v c="$c" -v t="$t" 'BEGIN {
		r = (1 - exp(-b * (2 * t) ^ c)) / (1 - exp(-b * t ^ c)); exit !(r > 1.1 - 1e-9 && r < 1.1 + 1e-9) }'
	[[ $(value exp3_intensity "$T/fit") == *N ]]
	demfit --form exp3 --strip N -o "$T/out" "$T/exp3" 2>/dev/null
	cmp "$T/fit" "$T/out"
}

@test "demfit: fewer than 4 points, points that never rise, a malformed row: exit 1, a clear message, no output" {
	head -n 4 "$T/exp2" > "$T/three"
	run --separate-stderr demfit --columns 1:3 -o "$T/o" "$T/three"
	[ "$status" -eq 1 ]
	[ "$stderr" = "demfit: $T/three: saturation curve: 3 points: at least 4 are needed" ]
	[ ! -e "$T/o" ]
	printf '1 0.3\n2 0.28\n4 0.2\n8 0.1\n' > "$T/fall"
	run --separate-stderr demfit -o "$T/o" "$T/fall"
	[ "$status" -eq 1 ]
	[[ $stderr == "demfit: $T/fall: saturation curve: the 4 points never rise"* ]]
	[ ! -e "$T/o" ]
	printf '1 0.1\n2 x\n' > "$T/bad"
	run --separate-stderr demfit "$T/bad"
	[ "$status" -eq 1 ]
	[ "$stderr" = "demfit: $T/bad:2: column 2: 'x' is not a finite number" ]
	[ -z "$output" ]
	printf '1 0.1\n2\n' > "$T/short"
	run --separate-stderr demfit "$T/short"
	[ "$status" -eq 1 ]
	[[ $stderr == *"short:2: 1 column, expected at least 2" ]]
	run --separate-stderr demfit "$T/missing"
	[ "$status" -eq 4 ]
}

@test "demfit: a curve that jumps to its plateau: exp3 does not converge, reported beside exp2 (exit 0); asked alone, exit 3 and no output" {
	printf '1 0.05\n2 0.3\n4 0.28\n8 0.31\n16 0.29\n' > "$T/jump"
	run --separate-stderr demfit "$T/jump"
	[ "$status" -eq 0 ]
	[ "$(value exp2_converged <(echo "$output"))" -eq 1 ]
	[ "$(value exp3_converged <(echo "$output"))" -eq 0 ]
	! grep -q '^exp3_a:' <<< "$output"
	[ "${stderr_lines[0]}" = "demfit: $T/jump: saturation curve: the exp3 fit did not converge (exceeded max number of iterations)" ]
	run --separate-stderr demfit --form exp3 -o "$T/o" "$T/jump"
	[ "$status" -eq 3 ]
	[ ! -e "$T/o" ]
}

@test "demfit: usage errors" {
	usage_error demfit --form exp4 "$T/exp2"
	usage_error demfit --columns 2:2 "$T/exp2"
	usage_error demfit --unit s "$T/exp2"
	usage_error demfit --strip B "$T/exp2"
	usage_error demfit -s scene.yaml "$T/exp2"
	usage_error demfit -z "$T/exp2"
	usage_error demfit a b
}
