# Helpers shared by the command-line tests (loaded with `load helpers`).

# Where the tests find the toolkit's files: in the source tree, or with
# make installcheck where they were installed (the Makefile's DEM_TEST_*):
# ROOT the source tree (the tests and the examples' scripts), SCENES the
# examples' scenes (examples/NAME/X.yaml or DATADIR/scenes/NAME/X.yaml),
# DATA the material and shot library, MANDIR the man pages, COMPDIR the
# bash completions.
ROOT=$(cd "$BATS_TEST_DIRNAME/../.." && pwd)
if [ -n "${DEM_TEST_DATA:-}" ]; then
	SCENES=$DEM_TEST_DATA/scenes
	DATA=$DEM_TEST_DATA
else
	SCENES=$ROOT/examples
	DATA=$ROOT/share
fi
MANDIR=${DEM_TEST_MANDIR:-$ROOT/man}
COMPDIR=${DEM_TEST_COMPDIR:-$ROOT/build/rel/completion}

# man_page NAME SECTION: the file of a man page under MANDIR, as make
# install leaves it or compressed (a Debian package's)
man_page() {
	local f=$MANDIR/man$2/$1.$2
	[ -f "$f" ] || [ ! -f "$f.gz" ] || f=$f.gz
	echo "$f"
}

# A usage error: exit 2, nothing on stdout, one message line naming the
# program, then "Try 'prog --help' ..." (coreutils).  Returns 1 (with the
# details on stdout, which bats shows) when it is not one.
# usage_error PROG ARGS...
usage_error() {
	local prog=$1
	run --separate-stderr "$@"
	echo "\$ $*  -> status $status, stdout '$output', stderr:"
	printf '  %s\n' "${stderr_lines[@]}"
	[ "$status" -eq 2 ] || return 1
	[ -z "$output" ] || return 1
	[ "${#stderr_lines[@]}" -eq 2 ] || return 1
	[[ ${stderr_lines[0]} == "$prog: "* ]] || return 1
	[ "${stderr_lines[1]}" = "Try '$prog --help' for more information." ]
}

# profile_stream SHAPE: a text profile stream with two passes of SHAPE.
profile_stream() {
	awk 'BEGIN {
		print "# dem profile 1"
		printf "# columns pass:u32:- depth:f64:m sxx:f64:Pa syy:f64:Pa szz:f64:Pa sxy:f64:Pa syz:f64:Pa szx:f64:Pa"
		printf " exx:f64:- eyy:f64:- ezz:f64:- exy:f64:- eyz:f64:- ezx:f64:- ep:f64:-"
		printf " sd_sxx:f64:Pa sd_syy:f64:Pa sd_szz:f64:Pa sd_sxy:f64:Pa sd_syz:f64:Pa sd_szx:f64:Pa"
		print " sd_exx:f64:- sd_eyy:f64:- sd_ezz:f64:- sd_exy:f64:- sd_eyz:f64:- sd_ezx:f64:- sd_ep:f64:- n:u32:-"
		print "# format text"
		print "# data"
	}
	{ d[NR] = $1 * 1e-3; s[NR] = $2 * 1e6; ep[NR] = $3 }
	END {
		for (p = 1; p <= 2; p++)
			for (k = 1; k <= NR; k++) {
				f = p == 1 ? 0.5 : 1
				printf "%d %.17g %.17g %.17g 0 0 0 0 0 0 0 0 0 0 %.17g", p, d[k], f * s[k], f * s[k], ep[k]
				for (c = 0; c < 13; c++) printf " 0"
				print " 10"
			}
		print "# end " 2 * NR
	}' "$1"
}

# value KEY FILE: the value of the first "KEY: value" line of FILE (the
# summaries of demform and demfit).
value() { awk -v k="$1:" '$1 == k { print $2; exit }' "$2"; }

# rel_close A B TOL: |A / B - 1| < TOL.
rel_close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { r = a / b - 1; exit !(r < t && r > -t) }'; }
