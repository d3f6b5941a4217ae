#!/bin/sh
# pass-speed.sh OUT BASE RUNS [SAME] - the Ch. 8.6 pass (pass86.yaml, 16
# shots on the offset grid, frictionless, 2 threads) by this tree's demshot
# and by the demshot of the git revision BASE, in turn, RUNS times each,
# and the same pass on an elastic block (pass86.yaml without its yield and
# hardening: the elastic cycle, the floor of the element loop).  Issue 17,
# item 3: a ratio measured in one run, not two figures from two days.
# SAME (optional): a later revision whose pass gives this tree's results
# (the steps the same), run on the plastic block in the same turns: the
# speed-up of the changes that leave the results alone, apart from those
# that change them (speed-report.sh says which is which).
#
# Each run is made at real-time priority (chrt -f 50, when this user may:
# root) so that other work on the machine waits while it runs, the same
# for every build; SPEED_RT=0 in the environment runs them at normal
# priority.  OUT/prio.txt says which.
#
# Each revision is built from `git archive REV` into OUT/base-REV (its
# bin/demshot); nothing of this tree is touched.  Rows into OUT/speed.tsv:
#   build config run wall_s element_loop_s node_loop_s contact_s steps
#   ns_per_elem_cycle load
# (build: base, same or new) and each run's state stream as
# OUT/BUILD-CONFIG.state (the last run's), from which speed-report.sh
# compares the residual profiles.
set -eu
out=$1 base=$2 runs=$3 same=${4:-}
top=$(cd ../.. && pwd)
. ../lib.sh
mkdir -p "$out"

# build_rev REV: the demshot of REV into OUT/base-REV (once per revision);
# prints the short revision
build_rev() {
	r=$(git -C "$top" rev-parse --short "$1")
	if [ ! -x "$out/base-$r/bin/demshot" ]; then
		echo "pass-speed: building demshot of $r into $out/base-$r" >&2
		rm -rf "$out/base-$r"
		mkdir -p "$out/base-$r"
		git -C "$top" archive "$r" | tar -x -C "$out/base-$r"
		make -C "$out/base-$r" -j2 bin/demshot > "$out/base-$r.build.log" 2>&1 ||
			{ tail -20 "$out/base-$r.build.log" >&2; exit 1; }
	fi
	echo "$r"
}
prio=
if [ "${SPEED_RT:-1}" != 0 ] && chrt -f 50 true 2> /dev/null; then
	prio="chrt -f 50"
fi
echo "${prio:-normal}" > "$out/prio.txt"
rev=$(build_rev "$base")
echo "$rev" > "$out/base.txt"
rm -f "$out/same.txt" "$out/same-plastic.state"
if [ -n "$same" ]; then
	srev=$(build_rev "$same")
	echo "$srev" > "$out/same.txt"
fi

"$top"/bin/dempack shots --grid 4 --passes 1 --area 5.6mm:5.6mm --speed 46.5 \
	--shot-radius 0.7mm --seed 1 > "$out/shots.txt" 2> /dev/null
cp pass86.yaml "$out/plastic.yaml"
grep -v '^  \(yield\|hardening\):' pass86.yaml > "$out/elastic.yaml"
grep -q '^  yield:' "$out/elastic.yaml" && { echo "pass-speed: elastic.yaml still yields" >&2; exit 1; }

printf 'build\tconfig\trun\twall_s\telement_loop_s\tnode_loop_s\tcontact_s\tsteps\tns_per_elem_cycle\tload\n' > "$out/speed.tsv"
r=1
while [ "$r" -le "$runs" ]; do
	for config in plastic elastic; do
		# in turn, so that the load of the moment falls on both alike
		for build in base same new; do
			prog=$top/bin/demshot
			case $build in
			base) prog=$out/base-$rev/bin/demshot ;;
			same) [ -n "$same" ] && [ "$config" = plastic ] || continue
			      prog=$out/base-$srev/bin/demshot ;;
			esac
			echo "pass-speed: run $r of $runs: $build $config" >&2
			load=$(loadavg)
			$prio "$prog" -s "$out/$config.yaml" --threads 2 -o "$out/$build-$config.state" \
				"$out/shots.txt" 2> "$out/$build-$config.log"
			printf '%s\t%s\t%s\t%s\t%s\n' "$build" "$config" "$r" \
				"$(cost_field "$out/$build-$config.log" wall_s element_loop_s node_loop_s contact_s steps ns_per_elem_cycle)" \
				"$load" >> "$out/speed.tsv"
		done
	done
	r=$((r + 1))
done
