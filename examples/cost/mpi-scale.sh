#!/bin/sh
# mpi-scale.sh OUT MPIBIN REPS - demshot on MPI (issue 22, acceptance 2):
# strong and weak scaling on 1-2 ranks, the bytes a rank sends a step, and
# the agreement of each run with the serial one.  One shot of Ch. 8.6
# (S550, 0.7 mm radius, 46.5 m/s) on a block of uniform 0.1 mm cubes,
# 4.8 x 4.8 mm, each pass run to 10 us (--steady 1e-9: the same steps in
# every run):
#   S  2.4 mm deep (48 x 48 x 24 = 55 296 elements): the serial demshot on
#      1 and 2 OpenMP threads, then 1, 2 and 4 ranks of one thread each
#      (4 oversubscribed on 2 cores: its bytes and agreement, not its time)
#   W  1.2 mm deep (48 x 48 x 12): 1 rank; with S on 2 ranks, the weak
#      scaling (the same layers per rank: z-slabs scale in depth)
#   C  the Ch. 8.6 sample model (pass86.yaml), a few steps: its mesh for
#      the model's projection
# mpirun runs with --bind-to none: on a machine shared with other jobs a
# rank bound to a core another process holds waits there, and with it the
# other rank at the next exchange.
# A row per run in OUT/mpi.tsv (the least wall time of REPS runs, the cost
# line's figures of that run); the profiles' largest relative difference
# from the serial run of the same block (demprofile, every column of every
# row, over the largest magnitude of the columns of its unit: profdiff.awk).
# Then the Ch. 7.5 cases CH75 (examples/ch75/run.sh, unchanged, its demshot
# the serial one or mpirun -np N of the MPI one): OUT/mpi-ch75.tsv, the
# profile's largest relative difference from the serial run and the wall
# time.
set -e
out=$1 mbin=$2 reps=${3:-2}
ch75=${CH75:-single-0.1-2-0.2-75-full multi-0.2-2-none-90-full}
bin=../../bin
. ../lib.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
cat > "$out/shot.txt" <<'TXT'
# dem shots 1
# dim 3
# columns pass:u32:- t:f64:s x:f64:m y:f64:m r:f64:m vx:f64:m/s vy:f64:m/s vz:f64:m/s
# format text
# data
0 0 0 0 0.0007 0 0 -46.5
# end 1
TXT
# Al 7050-T7651 of Ch. 8.6 (thesis-data.yaml, peen_forming; rho and nu
# textbook), as pass86.yaml
block() {
	cat <<YAML
material:
  E: 72 GPa
  nu: 0.33
  rho: 2830 kg/m^3
  yield: 450 MPa
  hardening: 120 MPa
block:
  size: [4.8 mm, 4.8 mm, $1 mm]
  element: 0.1 mm
shot:
  density: 7800 kg/m^3
contact:
  alpha: 2
run:
  damping: 0.05
YAML
}
rm -f "$out"/*.ref.prof
block 2.4 > "$out/S.yaml"
block 1.2 > "$out/W.yaml"
cp pass86.yaml "$out/C.yaml"

printf 'run\tblock\tranks\tthreads\tnx\tny\tnz\telements\tsteps\twall_s\trun_s\telement_loop_s\tnode_loop_s\texchange_s\tcontact_s\tdetect_s\tbytes_per_step\tprofile_diff\tload\n' > "$out/mpi.tsv"
# run NAME BLOCK RANKS THREADS [PASS_TIME]: RANKS 0 is the serial demshot
run() {
	name=$1 blk=$2 np=$3 thr=$4 pt=${5:-10us}
	best=
	for r in $(seq "$reps"); do
		echo "mpi-scale: $name, run $r" >&2
		load=$(loadavg)
		if [ "$np" -eq 0 ]; then
			"$bin"/demshot -s "$out/$blk.yaml" --threads "$thr" --pass-time "$pt" --steady 1e-9 \
				-o "$out/$name.state" "$out/shot.txt" 2> "$out/$name.log.tmp"
		else
			timeout 3600 mpirun -np "$np" --oversubscribe --bind-to none "$mbin"/demshot -s "$out/$blk.yaml" \
				--threads "$thr" --pass-time "$pt" --steady 1e-9 -o "$out/$name.state" \
				"$out/shot.txt" 2> "$out/$name.log.tmp"
		fi
		w=$(cost_field "$out/$name.log.tmp" wall_s)
		if [ -z "$best" ] || awk -v a="$w" -v b="$best" 'BEGIN { exit !(a < b) }'; then
			best=$w
			mv "$out/$name.log.tmp" "$out/$name.log"
			echo "$load" > "$out/$name.load"
		fi
	done
	rm -f "$out/$name.log.tmp"
	"$bin"/demprofile -s "$out/$blk.yaml" -q --pass all -o "$out/$name.prof" "$out/$name.state"
	ref=$out/$blk.ref.prof   # the block's first run, serial (below)
	[ -s "$ref" ] || cp "$out/$name.prof" "$ref"
	diff=$(awk -f profdiff.awk "$ref" "$out/$name.prof" || :)
	dims=$(sed -n 's/.*block of \([0-9]*\) elements (\([0-9]*\) x \([0-9]*\) x \([0-9]*\)).*/\2\t\3\t\4/p' "$out/$name.log")
	printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$blk" "$np" "$thr" "$dims" \
		"$(cost_field "$out/$name.log" elements steps wall_s run_s element_loop_s node_loop_s exchange_s contact_s detect_s bytes_per_step)" \
		"$diff" "$(cat "$out/$name.load")" >> "$out/mpi.tsv"
}
# the serial references first (their profiles are the others' reference)
run S-serial-t1 S 0 1
run S-serial-t2 S 0 2
run S-np1 S 1 1
run S-np2 S 2 1
run S-np4 S 4 1
run W-serial-t1 W 0 1
run W-np1 W 1 1
# the Ch. 8.6 model: its mesh and the bytes of 2 ranks on it, a few steps
reps=1
run C-serial C 0 1 0.2us
run C-np2 C 2 1 0.2us

# ---- Ch. 7.5 (acceptance 1: one Ch. 7.5 case) --------------------------
printf 'case\tranks\twall_s\tprofile_diff\tload\n' > "$out/mpi-ch75.tsv"
top=$(cd ../.. && pwd)
for np in 0 1 2 4; do
	b=$out/ch75-bin-$np
	mkdir -p "$b"
	for p in dempack demprofile; do ln -sf "$top/bin/$p" "$b/$p"; done
	if [ "$np" -eq 0 ]; then
		ln -sf "$top/bin/demshot" "$b/demshot"
	else
		rm -f "$b/demshot"
		printf '#!/bin/sh\nexec timeout 3600 mpirun -np %s --oversubscribe --bind-to none %s/demshot "$@"\n' \
			"$np" "$(cd "$mbin" && pwd)" > "$b/demshot"
		chmod +x "$b/demshot"
	fi
	for c in $ch75; do
		echo "mpi-scale: Ch. 7.5 $c, ranks $np" >&2
		load=$(loadavg)
		t0=$(date +%s.%N)
		BIN=$b THREADS=1 sh ../ch75/run.sh "$out/ch75-$np" "$c"
		t1=$(date +%s.%N)
		d=$(awk -f profdiff.awk "$out/ch75-0/$c.prof" "$out/ch75-$np/$c.prof" || :)
		printf '%s\t%s\t%.2f\t%s\t%s\n' "$c" "$np" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" \
			"$d" "$load" >> "$out/mpi-ch75.tsv"
	done
done
