#!/bin/sh
# repro.sh DIR NAME - is case NAME (run.sh) reproducible from its seed?  At
# the quick resolution (PER_D=5, COVERAGE=50), four runs in DIR:
#
#   a  seed 1            b  seed 1 again: every output equal to a's, byte for byte
#   c  seed 2: the shots and the profiles differ from a's
#   d  seed 1, demshot --threads 1 (a: THREADS, default 2): the same rows
#      as a's (the headers differ: they record the option)
#
# Writes the verdicts as Markdown on stdout; exit status 1 when one fails.
set -e
dir=$1 name=$2
here=$(cd "$(dirname "$0")" && pwd)
threads=${THREADS:-2}
run() { # run SUBDIR SEED THREADS
	PER_D=5 COVERAGE=50 SEED=$2 THREADS=$3 "$here"/run.sh "$dir/$1" "$name" > /dev/null
}
rm -rf "$dir/a" "$dir/b" "$dir/c" "$dir/d"
run a 1 "$threads"
run b 1 "$threads"
run c 2 "$threads"
run d 1 1
outputs="scene.yaml shots.txt single.vtu single.surf single.sat single.prof profile.txt sxx.txt surface.txt"
fail=0
echo "Case $name at d/5 and 50 % coverage (PER_D=5, COVERAGE=50), run four times"
echo "($(date '+%F %H:%M')):"
echo
same=0 bytes=0
for f in $outputs; do
	if cmp -s "$dir/a/$name/$f" "$dir/b/$name/$f"; then
		same=$((same + 1)); bytes=$((bytes + $(wc -c < "$dir/a/$name/$f")))
	else
		echo "- FAILED: seed 1 twice: $f differs"; fail=1
	fi
done
echo "- seed 1 twice: $same of $(echo $outputs | wc -w) outputs identical byte for byte ($bytes bytes: $outputs)"
diff=
for f in shots.txt profile.txt; do
	cmp -s "$dir/a/$name/$f" "$dir/c/$name/$f" && { echo "- FAILED: seed 2: $f equal to seed 1's"; fail=1; } || diff="$diff $f"
done
echo "- seed 2: differs from seed 1 in$diff ($(awk '!/^#/' "$dir/a/$name/shots.txt" | wc -l) and $(awk '!/^#/' "$dir/c/$name/shots.txt" | wc -l) shots)"
n=0
for f in shots.txt single.surf single.sat profile.txt sxx.txt surface.txt; do
	if [ "$(grep -v '^#' "$dir/a/$name/$f" | cksum)" = "$(grep -v '^#' "$dir/d/$name/$f" | cksum)" ]; then
		n=$((n + 1))
	else
		echo "- FAILED: --threads 1 against $threads: the rows of $f differ"; fail=1
	fi
done
echo "- demshot --threads 1 against --threads $threads: the rows of $n of 6 outputs equal (shots.txt single.surf single.sat profile.txt sxx.txt surface.txt)"
echo
[ $fail = 0 ] && echo "Reproducible: yes." || echo "Reproducible: NO."
exit $fail
