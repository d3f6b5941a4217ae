# Helpers of the install tests (load helpers): those of tests/cli, the
# folders make install uses (DEM_TEST_DIRS from the Makefile: prefix,
# bindir, libdir, includedir, mandir, pkgdatadir, pkgconfigdir,
# bashcompdir), and the check of a program built on libdem.

load ../cli/helpers

for kv in ${DEM_TEST_DIRS:?run through make check or make installcheck}; do
	declare -g "$kv"
done

# pairs_agree PROG: PROG, built from tests/install/pairs.c, counts the pairs
# demdetect -c counts, on a 2D text stream and a gzip-compressed binary 3D
# one (in BATS_TEST_TMPDIR)
pairs_agree() {
	local d=$BATS_TEST_TMPDIR p n
	dempack random -n 3000 --seed 1 2> /dev/null > "$d/p2"
	dempack random --dim 3 -n 3000 --seed 2 -b 2> /dev/null | gzip > "$d/p3"
	for p in p2 p3; do
		n=$("$1" "$d/$p")
		echo "$p: pairs.c $n, demdetect $(demdetect -c "$d/$p" 2> /dev/null)"
		[ "$n" -gt 100 ] && [ "$n" = "$(demdetect -c "$d/$p" 2> /dev/null)" ] || return 1
	done
}
