#!/bin/sh
# case.sh OUT NAME MATERIAL SPEED - one case of the sweep: the demo scene
# (examples/demo/scene.yaml) with the material MATERIAL of share/materials and
# the shot speed SPEED (m/s), through the whole pipeline (dempack shots,
# demshot, demprofile, demform) into OUT/NAME/, and one row of results on
# standard output: NAME MATERIAL SPEED arc_height_mm peak_MPa wall_s ranks.
#
# demshot runs on MPI when NP > 1 (environment): $LAUNCH (default
# "mpirun -np $NP") of $MPIBIN/demshot (default: ../../build/rel-mpi/bin, from
# `make MPI=1`); under Slurm, LAUNCH=srun takes the job's tasks.  PASSES
# overrides the scene's passes (make quick: 1).  BIN: the serial programs.
set -eu
out=$1 name=$2 mat=$3 speed=$4
here=$(cd "$(dirname "$0")" && pwd)
bin=${BIN:-$here/../../bin}
np=${NP:-1}
dir=$out/$name
mkdir -p "$dir"

# the scene: the demo's, its material replaced by the library's, its speed
# and (PASSES) its passes set
awk -v mat="$mat" -v speed="$speed" -v passes="${PASSES:-}" '
	/^material:/ { print "material:"; print "  use: " mat; skip = 1; next }
	skip && /^[ \t]/ { next }
	{ skip = 0 }
	/^  speed:/ { print "  speed: " speed " m/s"; next }
	/^  passes:/ && passes != "" { print "  passes: " passes; next }
	{ print }' "$here/../demo/scene.yaml" > "$dir/scene.yaml"
grep -q "^  use: $mat\$" "$dir/scene.yaml" || { echo "case.sh: $name: no material line written" >&2; exit 1; }

"$bin/dempack" -s "$dir/scene.yaml" shots --seed 1 -o "$dir/shots.txt" 2> "$dir/dempack.log"
start=$(date +%s.%N)
if [ "$np" -gt 1 ]; then
	mpibin=${MPIBIN:-$here/../../build/rel-mpi/bin}
	launch=${LAUNCH:-mpirun -np $np}
	$launch "$mpibin/demshot" -s "$dir/scene.yaml" -o "$dir/peen.state" "$dir/shots.txt" 2> "$dir/demshot.log"
else
	"$bin/demshot" -s "$dir/scene.yaml" -o "$dir/peen.state" "$dir/shots.txt" 2> "$dir/demshot.log"
fi
wall=$(echo "$start $(date +%s.%N)" | awk '{ printf "%.1f", $2 - $1 }')
"$bin/demprofile" -s "$dir/scene.yaml" -o "$dir/profile.txt" "$dir/peen.state" 2> "$dir/demprofile.log"
"$bin/demform" -s "$dir/scene.yaml" -o "$dir/form.txt" "$dir/profile.txt" 2> "$dir/demform.log"
arc=$(awk '$1 == "arc_height:" { printf "%.4f", $2 * 1000 }' "$dir/form.txt")
# the most compressive sxx of the last pass's profile, MPa
peak=$(awk '/^#/ { next } { last = $1 } { row[NR] = $0 }
	END { for (i in row) { split(row[i], f, " "); if (f[1] == last && (m == "" || f[3] < m)) m = f[3] }
	      printf "%.1f", m / 1e6 }' "$dir/profile.txt")
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$mat" "$speed" "$arc" "$peak" "$wall" "$np"
