#!/bin/sh
# tests/fuzz/run.sh SECONDS TARGET... - make fuzz: AFL++ on each reader of
# the toolkit for SECONDS (tests/fuzz/fuzz.c names the targets), one after
# the other on one core.
#
#  - builds the library and the harness with afl-cc under AddressSanitizer
#    and UBSan (AFL_USE_ASAN, AFL_USE_UBSAN) into build/rel-afl, so that a
#    memory error or undefined behaviour is a crash;
#  - seeds each run with tests/fuzz/corpus/TARGET (small valid inputs, and
#    every input an earlier run found to crash);
#  - copies each crash and hang found into tests/fuzz/corpus/TARGET as
#    crash-TARGET-N / hang-TARGET-N (make check replays the corpus: fix the
#    reader, keep the input);
#  - writes tests/fuzz/REPORT.md from afl-fuzz's fuzzer_stats.
# The runs go to build/fuzz/TARGET.  Installs afl++ when missing (as root).
set -eu
secs=$1
shift
top=$(pwd)
[ -f tests/fuzz/fuzz.c ] || { echo "fuzz: run from the top of the source tree" >&2; exit 2; }
if ! command -v afl-fuzz > /dev/null; then
	if [ "$(id -u)" -ne 0 ]; then
		echo "fuzz: AFL++ is not installed (as root: apt-get install afl++)" >&2
		exit 4
	fi
	DEBIAN_FRONTEND=noninteractive apt-get install -y -q afl++ > /dev/null
fi
# the instrumented build (the Makefile puts CC=afl-cc in build/rel-afl)
AFL_USE_ASAN=1 AFL_USE_UBSAN=1 AFL_QUIET=1 make --no-print-directory CC=afl-cc \
	OPT='-O1 -g -fno-omit-frame-pointer' build/rel-afl/tests/fuzz-readers > build/fuzz-build.log 2>&1 ||
	{ tail -20 build/fuzz-build.log >&2; exit 1; }
harness=$top/build/rel-afl/tests/fuzz-readers
# afl-fuzz's checks of the machine: no core dumps piped to a handler, no
# CPU frequency governor to complain of; ASan's own options as AFL wants
export AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_SKIP_CPUFREQ=1 AFL_NO_UI=1
export AFL_NO_AFFINITY=1
for t in "$@"; do
	out=build/fuzz/$t
	rm -rf "$out"
	mkdir -p "$out"
	echo "fuzz: $t for $secs s"
	afl-fuzz -i "tests/fuzz/corpus/$t" -o "$out" -V "$secs" -m none -t 2000 \
		-- "$harness" "$t" @@ > "$out/afl.log" 2>&1 ||
		{ echo "fuzz: afl-fuzz $t failed:" >&2; tail -20 "$out/afl.log" >&2; exit 1; }
	n=0
	for kind in crash hang; do
		dir=crashes
		[ "$kind" = hang ] && dir=hangs
		for f in "$out"/default/$dir/id:*; do
			[ -f "$f" ] || continue
			n=$((n + 1))
			cp "$f" "tests/fuzz/corpus/$t/$kind-$t-$(basename "$f" | cut -d, -f1 | tr -dc '0-9')"
		done
	done
	[ "$n" -eq 0 ] || echo "fuzz: $t: $n inputs kept in tests/fuzz/corpus/$t"
done
sh tests/fuzz/report.sh "$secs" "$@" > tests/fuzz/REPORT.md.tmp && mv -f tests/fuzz/REPORT.md.tmp tests/fuzz/REPORT.md
cat tests/fuzz/REPORT.md
