#!/usr/bin/env bats
# make installcheck: the installed toolkit as a user meets it (tests/run.sh
# puts only the installed bin/ and the system's folders on PATH; the folders
# are the build's, DEM_TEST_DIRS, under DEM_TEST_DESTDIR when staged).
# Checked: every program of cmd/ runs from the installed bin/; the library
# is read from the installed data directory, and DEM_DATA overrides it;
# man finds the pages from PATH alone; a program of one's own builds with
# pkg-config on the installed dem.pc and counts the pairs demdetect counts.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	D=${DEM_TEST_DESTDIR:-}
}

# the toolkit's version, from the Makefile
pkg_version() { sed -n 's/^VERSION *:= *//p' "$ROOT/Makefile"; }

@test "installed: every program of cmd/ runs from the installed bin/" {
	for c in "$ROOT"/cmd/*.c; do
		p=$(basename "$c" .c)
		[ "$(command -v "$p")" = "$D$bindir/$p" ]
		[ "$("$p" --version)" = "$p (dem toolkit) $(pkg_version)" ]
	done
}

@test "installed: use: reads the installed library, and DEM_DATA overrides where" {
	printf 'material: {use: Al7050-T7651}\nshot: {use: S550}\n' > "$T/s.yaml"
	run --separate-stderr dempack -s "$T/s.yaml" shots --dump-scene
	echo "$stderr"
	[ "$status" -eq 0 ]
	grep -qx '  radius: 0.0006985 m' <<< "$output"
	# another data directory: looked for there only
	mkdir -p "$T/data/materials"
	sed 's/^E: .*/E: 1 GPa/' "$D$pkgdatadir/materials/Al7050-T7651.yaml" > "$T/data/materials/Al7050-T7651.yaml"
	run --separate-stderr env DEM_DATA="$T/data" demform -s "$T/s.yaml" --dump-scene
	echo "$stderr"
	[ "$status" -eq 1 ]
	[[ $stderr == *"no S550.yaml in $T/data/shots (from DEM_DATA)"* ]]
	printf 'material: {use: Al7050-T7651}\n' > "$T/m.yaml"
	run --separate-stderr env DEM_DATA="$T/data" demform -s "$T/m.yaml" --dump-scene
	[ "$status" -eq 0 ]
	grep -qx '  E: 1000000000 Pa' <<< "$output"
}

@test "installed: man finds every page by PATH alone" {
	for src in "$ROOT"/man/man1/*.1 "$ROOT"/man/man5/*.5; do
		name=$(basename "$src")
		run env -u MANPATH man -w "${name##*.}" "${name%.*}"
		echo "$name: $output"
		[ "$status" -eq 0 ]
		[ "$output" = "$(man_page "${name%.*}" "${name##*.}")" ]
	done
}

@test "installed: a program of one's own builds with pkg-config and counts the pairs demdetect counts" {
	export PKG_CONFIG_PATH="$D$pkgconfigdir${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
	[ -z "$D" ] || export PKG_CONFIG_SYSROOT_DIR="$D"
	pkg-config --exists --print-errors dem
	# the dem.pc of this install, not another one on pkg-config's path
	[ "$(pkg-config --variable=includedir dem)" = "$D$includedir" ]
	[ "$(pkg-config --modversion dem)" = "$(pkg_version)" ]
	cd "$T"
	# shellcheck disable=SC2046
	${DEM_TEST_CC:-cc} -std=c11 -Wall -Wextra -Werror "$ROOT/tests/install/pairs.c" \
		$(pkg-config --cflags --libs dem) -o pairs
	pairs_agree ./pairs
}
