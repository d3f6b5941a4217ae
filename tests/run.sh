#!/bin/sh
# Run every unit test (cmocka, TAP output) and every command-line test
# (bats, TAP output), then print the one summary line "N passed, N failed".
#   tests/run.sh TESTDIR BINDIR SANITIZE BATS...
# TESTDIR empty: no unit tests.  BATS: the bats files and folders to run.
# DEM_DATA is unset: the programs find their library as they do for a
# user, in the source tree or where they were installed to.  With
# DEM_TEST_INSTALLED=1 (make installcheck) PATH is BINDIR and the system's
# folders only, and every program of cmd/ must be there; a staged install
# (DEM_TEST_DESTDIR) has its library found through DEM_DATA.
# DEM_TEST_JOBS (default: the number of cores) test programs run at once:
# the unit tests by xargs -P, the bats files by bats --jobs when GNU
# parallel is installed (make deps installs it; bats needs it for --jobs),
# one file at a time each (--no-parallelize-within-files: a file's tests
# may share what its setup_file made).  Every test writes under its own
# temporary folder, so the order they run in does not matter.
# DEM_TEST_MPITESTS: the unit test programs built on MPI, run under mpirun
# (below); DEM_TEST_MPIBIN, the programs built on MPI, is for the bats
# files (tests/cli/mpi.bats).
testdir=$1 bindir=$2 sanitize=$3
shift 3
unset DEM_DATA
if [ "${DEM_TEST_INSTALLED:-}" = 1 ]; then
	for c in cmd/*.c; do
		p=$(basename "$c" .c)
		[ -x "$bindir/$p" ] || { echo "installcheck: no $bindir/$p (make install first)" >&2; exit 4; }
	done
	path="$bindir:/usr/bin:/bin"
	[ -z "${DEM_TEST_DESTDIR:-}" ] || export DEM_DATA="$DEM_TEST_DATA"
else
	path="$bindir:$PATH"
fi
log=$(mktemp -d) || exit 4
trap 'rm -rf "$log"' EXIT
jobs=${DEM_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
case $jobs in ''|*[!0-9]*|0) echo "tests: DEM_TEST_JOBS: a positive number, not '$jobs'" >&2; exit 2 ;; esac
status=0
export CMOCKA_MESSAGE_OUTPUT=TAP
# each unit test program: its TAP into LOG/NAME.tap, stderr into
# LOG/NAME.err, and LOG/NAME.failed when it exits non-zero
units=
for t in ${testdir:+"$testdir"/test_*}; do
	[ -x "$t" ] && units="$units $t"
done
if [ -n "$units" ]; then
	printf '%s\n' $units | LOG=$log xargs -P "$jobs" -n 1 sh -c \
		'n=$(basename "$1"); "$1" > "$LOG/$n.tap" 2> "$LOG/$n.err" || : > "$LOG/$n.failed"' unit
fi
for t in $units; do
	name=$(basename "$t")
	if [ -e "$log/$name.failed" ]; then
		status=1
		echo "unit: $name: FAILED" >&2
		grep -v '^ok ' "$log/$name.tap" | head -40 >&2
		head -40 "$log/$name.err" >&2
	fi
done
# the MPI unit tests (DEM_TEST_MPITESTS, make check's when
# mpicc is installed) under mpirun on 2 and 4 ranks, 4 oversubscribed (one
# rank is the plain build's run of the same test: the one-rank code path);
# rank 0 writes the TAP, a failure on any rank fails the run
if [ -n "${DEM_TEST_MPITESTS:-}" ] && command -v mpirun > /dev/null; then
	if [ "$(id -u)" = 0 ]; then
		export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
	fi
	for t in $DEM_TEST_MPITESTS; do
		for np in 2 4; do
			name=mpi-np$np-$(basename "$t")
			if ! timeout 300 mpirun -np $np --oversubscribe "$t" > "$log/$name.tap" 2> "$log/$name.err"; then
				status=1
				echo "unit: $name: FAILED" >&2
				grep -v '^ok ' "$log/$name.tap" | head -40 >&2
				head -40 "$log/$name.err" >&2
			fi
		done
	done
fi
# the readers' fuzzing harness over its corpus (tests/fuzz: the seeds and
# every input a fuzz run found to crash): no input may crash a reader
fz=${testdir:+$testdir/fuzz-readers}
if [ -n "$fz" ] && [ -x "$fz" ]; then
	k=0
	: > "$log/fuzz.tap"
	for d in tests/fuzz/corpus/*/; do
		t=$(basename "$d")
		k=$((k + 1))
		if "$fz" "$t" "$d"* > /dev/null 2> "$log/fuzz-$t.err"; then
			echo "ok $k fuzz corpus: $t ($(ls "$d" | wc -l) inputs)" >> "$log/fuzz.tap"
		else
			status=1
			echo "not ok $k fuzz corpus: $t" >> "$log/fuzz.tap"
			echo "fuzz: $t: FAILED" >&2
			head -40 "$log/fuzz-$t.err" >&2
		fi
	done
fi
if [ $# -gt 0 ]; then
	# bats by its full name: PATH may not have it
	bats=$(command -v bats) || { echo "cli: bats is not installed" >&2; exit 4; }
	par=
	if [ "$jobs" -gt 1 ] && command -v parallel > /dev/null; then
		par="--jobs $jobs --no-parallelize-within-files"
	fi
	if ! PATH="$path" DEM_SANITIZE="$sanitize" "$bats" --tap $par "$@" > "$log/cli.tap" 2>"$log/cli.err"; then
		status=1
		echo "cli: FAILED" >&2
		grep -A12 '^not ok' "$log/cli.tap" >&2
		tail -20 "$log/cli.err" >&2
	fi
fi
# skipped tests (cmocka: "not ok N # SKIP name", bats: "ok N name # skip
# reason") are the documented known failures: neither passed nor failed
all=$(cat "$log"/*.tap 2>/dev/null)
skip=$(printf '%s\n' "$all" | grep -ci '^\(not \)\{0,1\}ok .*# skip')
pass=$(printf '%s\n' "$all" | grep '^ok ' | grep -vic '# skip')
fail=$(printf '%s\n' "$all" | grep '^not ok ' | grep -vic '# skip')
[ "$skip" -eq 0 ] || echo "$skip skipped (each says why in the test: a known failure with its figures, or not run in this build)"
# a test program that died before reporting counts as a failure too
if [ "$status" -ne 0 ] && [ "$fail" -eq 0 ]; then fail=1; fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
