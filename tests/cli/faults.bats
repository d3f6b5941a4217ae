#!/usr/bin/env bats
# Faults (issue 21, item 2): demshot killed at random times and resumed; a
# full disk; a closed pipe downstream; SIGTERM.  References: the
# uninterrupted run (bit for bit) and the exit codes of DESIGN.md (4: I/O
# or resource failure; no half-written output file left behind).

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	# the Ch. 7.5 shot (examples/ch75) on a coarse 2 x 2 x 1 mm block, three
	# passes of one shot at the centre: about a second
	sh "$ROOT/examples/ch75/scene.sh" "$SCENES/ch75/scene.yaml" "block.size=[2 mm, 2 mm, 1 mm]" \
		"block.element=0.1 mm" "block.fine_depth=0.4 mm" "run.pass_time=20 us" > "$T/shot.yaml"
	dempack -s "$T/shot.yaml" shots --grid 1 --passes 3 --area 0.4mm:0.4mm --seed 1 > "$T/s3.txt" 2> /dev/null
}

teardown() {
	if [ -n "${MNT:-}" ] && mountpoint -q "$MNT"; then
		umount "$MNT"
	fi
}

# the rows of a state stream, decoded, without its header (provenance)
state_rows() {
	local off
	off=$(gzip -dc "$1" | grep -abo -m1 '^# data' | cut -d: -f1)
	gzip -dc "$1" | tail -c +$((off + 1)) | md5sum
}

# the uninterrupted run: a.state, fa.txt; its wall time in $T/tref
reference_run() {
	local t0 t1
	t0=$(date +%s%N)
	demshot -s "$T/shot.yaml" -q --forces "$T/fa.txt" -o "$T/a.state" "$T/s3.txt"
	t1=$(date +%s%N)
	echo $(((t1 - t0) / 1000000)) > "$T/tref"
}

# run_to_end: the checkpointed run in $T/b.state, fb.txt, resumed from
# its checkpoint when there is one, until it ends (status 0)
run_to_end() {
	local resume=
	[ -e "$T/ck" ] && resume=--resume
	demshot -s "$T/shot.yaml" -q --forces "$T/fb.txt" --checkpoint "$T/ck" $resume \
		-o "$T/b.state" "$T/s3.txt"
}

@test "faults: demshot killed (SIGKILL) at 20 random times and resumed ends with the uninterrupted run's frames bit for bit" {
	reference_run
	tref=$(cat "$T/tref")
	# kill times uniform over 1.1 times the reference run: before the first
	# checkpoint, within passes, while a checkpoint is written, after the
	# end; DEM_FAULT_SEED repeats a sequence
	seed=${DEM_FAULT_SEED:-$RANDOM}
	# 20 kills (issue 21); 5 under the sanitizers (make check SANITIZE=1),
	# which check the resume path's memory, not more of its timing
	n=20
	[ -z "${DEM_SANITIZE:-}" ] || n=5
	echo "seed $seed, reference run $tref ms, $n kills"
	ref_rows=$(state_rows "$T/a.state")
	ref_forces=$(grep -v '^# prog' "$T/fa.txt" | md5sum)
	resumed=0 fresh=0 finished=0
	# on a file system with O_TMPFILE (Linux's ext4, xfs, btrfs, tmpfs) the
	# outputs have no name until they are whole: a kill leaves no stray
	# NAME.tmp.XXXXXX (lib/core/afile.c); elsewhere strays are allowed
	unnamed=0
	case "$(stat -f -c %T "$T" 2> /dev/null)" in ext2/ext3 | ext4 | xfs | btrfs | tmpfs) unnamed=1 ;; esac
	for ms in $(awk -v s="$seed" -v t="$tref" -v n="$n" 'BEGIN { srand(s); for (i = 0; i < n; i++) printf "%d\n", rand() * 1.1 * t }'); do
		rm -f "$T"/ck* "$T"/b.state* "$T"/fb.txt*
		demshot -s "$T/shot.yaml" -q --forces "$T/fb.txt" --checkpoint "$T/ck" -o "$T/b.state" "$T/s3.txt" \
			2> "$T/killed.log" &
		pid=$!
		sleep "$(awk -v m="$ms" 'BEGIN { printf "%.3f", m / 1000 }')"
		kill -9 "$pid" 2> /dev/null || true
		st=0
		wait "$pid" || st=$?
		if [ "$st" -eq 0 ]; then
			finished=$((finished + 1))
		else
			[ "$st" -eq 137 ] || { echo "kill at $ms ms: exit $st"; return 1; }
			if [ -e "$T/ck" ]; then resumed=$((resumed + 1)); else fresh=$((fresh + 1)); fi
			[ "$unnamed" = 0 ] || [ -z "$(find "$T" -maxdepth 1 -name '*.tmp.*')" ] ||
				{ echo "kill at $ms ms: strays left:"; find "$T" -maxdepth 1 -name '*.tmp.*'; return 1; }
			run_to_end 2> "$T/resumed.log" || { echo "kill at $ms ms: the resumed run failed"; cat "$T/resumed.log"; return 1; }
		fi
		[ "$(state_rows "$T/b.state")" = "$ref_rows" ] || { echo "kill at $ms ms: the frames differ"; return 1; }
		[ "$(grep -v '^# prog' "$T/fb.txt" | md5sum)" = "$ref_forces" ] ||
			{ echo "kill at $ms ms: the force history differs"; return 1; }
		[ ! -e "$T/ck" ] && [ ! -e "$T/ck.journal" ]
	done
	echo "resumed from a checkpoint $resumed, started again $fresh, finished before the kill $finished"
	# the kills fell on both sides of the first checkpoint
	[ "$resumed" -gt 0 ]
}

@test "faults: SIGTERM or SIGINT during a run leaves the last pass's checkpoint, and the run resumes from it" {
	reference_run
	for sig in TERM INT; do
		rm -f "$T"/ck* "$T"/b.state* "$T"/fb.txt*
		# stopped after pass 1's checkpoint (DEMSHOT_STOP_AFTER sends
		# SIGKILL: here the signal comes from outside, while pass 2 runs)
		demshot -s "$T/shot.yaml" -q --forces "$T/fb.txt" --checkpoint "$T/ck" -o "$T/b.state" "$T/s3.txt" &
		pid=$!
		for _ in $(seq 200); do
			[ -e "$T/ck" ] && break
			sleep 0.02
		done
		[ -e "$T/ck" ]
		kill -s "$sig" "$pid"
		st=0
		wait "$pid" || st=$?
		echo "SIG$sig: exit $st"
		[ "$st" -gt 128 ] || [ "$st" -eq 0 ]
		if [ "$st" -ne 0 ]; then
			# no temporary file left beside the outputs or the checkpoint
			[ -z "$(find "$T" -maxdepth 1 -name '*.tmp.*')" ]
			[ -s "$T/ck" ] && [ ! -e "$T/b.state" ]
			run --separate-stderr run_to_end
			[ "$status" -eq 0 ]
		fi
		[ "$(state_rows "$T/b.state")" = "$(state_rows "$T/a.state")" ]
	done
}

@test "faults: a closed pipe downstream ends every writer with exit 4 and a message, not a signal" {
	# each program's standard output into a reader that has gone
	run --separate-stderr bash -c "dempack random -n 200000 | head -c 10 > /dev/null; echo \${PIPESTATUS[0]}"
	echo "dempack: $output / $stderr"
	[ "${lines[-1]}" = 4 ]
	grep -q '^dempack: stdout: Broken pipe' <<< "$stderr"
	dempack random -n 200000 --seed 1 2> /dev/null > "$T/p.txt"
	run --separate-stderr bash -c "demdetect '$T/p.txt' | head -c 10 > /dev/null; echo \${PIPESTATUS[0]}"
	echo "demdetect: $output / $stderr"
	[ "${lines[-1]}" = 4 ]
	grep -q '^demdetect: stdout: Broken pipe' <<< "$stderr"
	run --separate-stderr bash -c "demshot -s '$T/shot.yaml' -q '$T/s3.txt' | head -c 10 > /dev/null; echo \${PIPESTATUS[0]}"
	echo "demshot: $output / $stderr"
	[ "${lines[-1]}" = 4 ]
	grep -q '^demshot: .*Broken pipe' <<< "$stderr"
}

@test "faults: a full device (/dev/full) as standard output gives exit 4 and a message" {
	run --separate-stderr bash -c "dempack random -n 100000 > /dev/full"
	[ "$status" -eq 4 ]
	grep -q '^dempack: stdout: No space left on device' <<< "$stderr"
	reference_run
	run --separate-stderr bash -c "demprofile --pass all '$T/a.state' > /dev/full"
	[ "$status" -eq 4 ]
	grep -q '^demprofile: .*No space left on device' <<< "$stderr"
}

@test "faults: a full disk (a 64 KiB tmpfs) gives exit 4, a message naming the file, and leaves nothing on it" {
	[ "$(id -u)" -eq 0 ] || skip "mounting a tmpfs needs root"
	MNT=$T/full
	mkdir "$MNT"
	mount -t tmpfs -o size=64k tmpfs "$MNT" 2> /dev/null || skip "cannot mount a tmpfs here"
	# a packing larger than the disk
	run --separate-stderr dempack random -n 100000 -o "$MNT/p.txt"
	echo "$stderr"
	[ "$status" -eq 4 ]
	grep -q "^dempack: $MNT/p.txt: No space left on device" <<< "$stderr"
	[ -z "$(ls -A "$MNT")" ]
	# demshot's state stream, and its checkpoint
	run --separate-stderr demshot -s "$T/shot.yaml" -q -o "$MNT/a.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 4 ]
	grep -q "$MNT/a.state" <<< "$stderr"
	[ -z "$(ls -A "$MNT")" ]
	run --separate-stderr demshot -s "$T/shot.yaml" -q --checkpoint "$MNT/ck" -o "$T/b.state" "$T/s3.txt"
	echo "$stderr"
	[ "$status" -eq 4 ]
	grep -q "$MNT/ck" <<< "$stderr"
	[ -z "$(ls -A "$MNT")" ] && [ ! -e "$T/b.state" ]
}
