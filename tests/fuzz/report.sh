#!/bin/sh
# tests/fuzz/report.sh SECONDS TARGET... - tests/fuzz/REPORT.md from the
# fuzzer_stats of the runs in build/fuzz/TARGET (tests/fuzz/run.sh).
set -eu
secs=$1
shift
stat() { sed -n "s/^$2 *: //p" "build/fuzz/$1/default/fuzzer_stats"; }
echo "# Fuzzing the readers (AFL++)"
echo
start=$(stat "$1" start_time)
echo "Written by \`make fuzz FUZZ_TIME=$secs\` (tests/fuzz/run.sh), runs from $(date -d "@$start" '+%F %H:%M')"
echo "($(nproc) cores, one run at a time on one core; AFL++ $(stat "$1" afl_version | sed 's/^++//'),"
echo "the harness tests/fuzz/fuzz.c built by afl-cc with AddressSanitizer and"
echo "UBSan, so that a memory error or undefined behaviour counts as a crash)."
echo "Seeds: tests/fuzz/corpus/TARGET; what crashes is kept there and replayed by"
echo "\`make check\`."
echo
echo "| reader | run s | executions | per s | corpus (found) | edges found / total | crashes | hangs |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for t in "$@"; do
	echo "| $t | $(stat "$t" run_time) | $(stat "$t" execs_done) | $(stat "$t" execs_per_sec) | $(stat "$t" corpus_count) ($(stat "$t" corpus_found)) | $(stat "$t" edges_found) / $(stat "$t" total_edges) | $(stat "$t" saved_crashes) | $(stat "$t" saved_hangs) |"
done
