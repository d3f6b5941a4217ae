#!/bin/sh
# tests/fuzz/report.sh SECONDS TARGET... - tests/fuzz/REPORT.md (on
# standard output) from the fuzzer_stats of the runs in build/fuzz/TARGET
# (tests/fuzz/run.sh).  A reader not fuzzed this time keeps its row of the
# report before (tests/fuzz/REPORT.md), with the day it ran, so that
# `make fuzz FUZZ_TARGETS=bodies` adds a reader without losing the others.
set -eu
secs=$1
shift
old=tests/fuzz/REPORT.md
stat() { sed -n "s/^$2 *: //p" "build/fuzz/$1/default/fuzzer_stats"; }
echo "# Fuzzing the readers (AFL++)"
echo
echo "Written by \`make fuzz\` (tests/fuzz/run.sh; FUZZ_TIME=$secs s a reader this time):"
echo "one run at a time on one core of $(nproc); AFL++ $(stat "$1" afl_version | sed 's/^++//'),"
echo "the harness tests/fuzz/fuzz.c built by afl-cc with AddressSanitizer and"
echo "UBSan, so that a memory error or undefined behaviour counts as a crash."
echo "Seeds: tests/fuzz/corpus/TARGET; what crashes is kept there and replayed by"
echo "\`make check\`.  A row not run this time is kept from the report before."
echo
echo "| reader | started | run s | executions | per s | corpus (found) | edges found / total | crashes | hangs |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
for t in stream scene state profile bodies; do
	fresh=
	for a in "$@"; do [ "$a" = "$t" ] && fresh=1; done
	if [ -n "$fresh" ]; then
		echo "| $t | $(date -d "@$(stat "$t" start_time)" '+%F %H:%M') | $(stat "$t" run_time) | $(stat "$t" execs_done) | $(stat "$t" execs_per_sec) | $(stat "$t" corpus_count) ($(stat "$t" corpus_found)) | $(stat "$t" edges_found) / $(stat "$t" total_edges) | $(stat "$t" saved_crashes) | $(stat "$t" saved_hangs) |"
	elif [ -f "$old" ]; then
		# the row before; a report of the older layout (one start for
		# all, no column for it) gives its start line's date
		awk -v t="$t" '
			/runs from [0-9-]+ [0-9:]+/ { match($0, /[0-9]+-[0-9]+-[0-9]+ [0-9]+:[0-9]+/); d = substr($0, RSTART, RLENGTH) }
			/^\| reader \| started \|/ { dated = 1 }
			$0 ~ "^\\| " t " \\|" { if (dated) print; else { sub("^\\| " t " \\|", "| " t " | " d " |"); print } }' "$old"
	fi
done
