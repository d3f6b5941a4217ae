#!/bin/sh
# deb.sh OUTDIR - build the Debian packages (dpkg-buildpackage -us -uc -b)
# from the files git tracks in this tree (or would: new files not ignored),
# in a temporary copy so that the tree's own build is left alone, then
# check them with lintian when it is installed (CI installs it:
# tools/deps.sh lintian).  The .deb files, the .changes, the build's log
# and lintian's report go to OUTDIR.  DEB_BUILD_OPTIONS is
# dpkg-buildpackage's, e.g. "nocheck parallel=2" (CI: the tests have run).
# Exit status: 1 when the build fails or lintian reports an error.
set -eu
[ $# -eq 1 ] || { echo "usage: deb.sh OUTDIR" >&2; exit 2; }
out=$1
top=$(cd "$(dirname "$0")/.." && pwd)
ver=$(sed -n '1s/^dem (\([^)]*\)).*/\1/p' "$top/debian/changelog")
mkver=$(sed -n 's/^VERSION *:= *//p' "$top/Makefile")
if [ "$ver" != "$mkver" ]; then
	echo "deb.sh: debian/changelog is at $ver, the Makefile's VERSION at $mkver" >&2
	exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
src=$tmp/dem-$ver
mkdir "$src"
# the files git tracks, or would (not ignored), as they are in the tree
git -C "$top" ls-files -z --cached --others --exclude-standard |
	tar -C "$top" --null -T - --ignore-failed-read -cf - 2> /dev/null | tar -C "$src" -xf -
echo "deb: dpkg-buildpackage -us -uc -b in $src (DEB_BUILD_OPTIONS=${DEB_BUILD_OPTIONS:-})"
if ! (cd "$src" && dpkg-buildpackage -us -uc -b) > "$tmp/build.log" 2>&1; then
	tail -40 "$tmp/build.log" >&2
	echo "deb: the package build failed" >&2
	exit 1
fi
mkdir -p "$out"
for f in "$tmp"/*.deb "$tmp"/*.ddeb "$tmp"/*.changes "$tmp"/*.buildinfo; do
	[ ! -f "$f" ] || cp "$f" "$out"/
done
cp "$tmp/build.log" "$out/build.log"
ls "$out"/*.deb
if command -v lintian > /dev/null; then
	rc=0
	lintian --fail-on error --display-info "$tmp"/*.changes > "$out/lintian.txt" 2>&1 || rc=$?
	cat "$out/lintian.txt"
	echo "deb: lintian: $(grep -c '^E: ' "$out/lintian.txt") errors," \
		"$(grep -c '^W: ' "$out/lintian.txt") warnings, $(grep -c '^I: ' "$out/lintian.txt") notes"
	[ "$rc" -eq 0 ] || { echo "deb: lintian failed (status $rc)" >&2; exit 1; }
else
	echo "deb: lintian is not installed: the packages were not checked"
fi
