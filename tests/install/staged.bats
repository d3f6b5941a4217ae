#!/usr/bin/env bats
# make install and make uninstall of this build (make check), staged under
# a temporary DESTDIR with the build's own folders (DEM_TEST_DIRS; make
# installcheck runs the installed programs).  Checked: the files installed
# are the programs of cmd/, the man pages, the library of share/, the
# examples' scenes, libdem.a with its public headers, dem.pc and a
# completion a program, each in its GNU folder under DESTDIR and nothing
# elsewhere; a program of one's own builds with pkg-config on the staged
# files and counts the pairs demdetect counts; a place that is not a
# regular file is refused and left alone; uninstall removes every file, and
# the folders that install made when they were not staged.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
}

# stage DESTDIR [VAR=VALUE...]: make install into DESTDIR, or fail
stage() {
	local d=$1
	shift
	make -s -C "$ROOT" --no-print-directory install DESTDIR="$d" "$@" > "$T/install.log" 2>&1 ||
		{ cat "$T/install.log"; return 1; }
}

# the files make install should make, one a line, sorted
expected() {
	local f n
	for f in "$ROOT"/cmd/*.c; do n=${f##*/}; echo "$bindir/${n%.c}"; echo "$bashcompdir/${n%.c}"; done
	for f in "$ROOT"/man/man1/*.1; do echo "$mandir/man1/${f##*/}"; done
	for f in "$ROOT"/man/man5/*.5; do echo "$mandir/man5/${f##*/}"; done
	echo "$pkgdatadir/README.md"
	for f in "$ROOT"/share/materials/*.yaml; do echo "$pkgdatadir/materials/${f##*/}"; done
	for f in "$ROOT"/share/shots/*.yaml; do echo "$pkgdatadir/shots/${f##*/}"; done
	for f in "$ROOT"/examples/*/*.yaml "$ROOT"/examples/verification/laws-mat/*.yaml; do
		echo "$pkgdatadir/scenes/${f#"$ROOT"/examples/}"
	done
	echo "$libdir/libdem.a"
	echo "$pkgconfigdir/dem.pc"
	for f in "$ROOT"/lib/*/*.h; do
		case $f in */vec3.h | */dcell_impl.h | */dcell_sweep.h | */tree_impl.h | */simd.h | */fe/ckpt.h | */fe/cdiff.h | */mesh/hex.h) ;;
		*) echo "$includedir/dem/${f#"$ROOT"/lib/}" ;;
		esac
	done
}

@test "install: every file in its folder under DESTDIR, and nothing else" {
	stage "$T/stage"
	(cd "$T/stage" && find . ! -type d | sed 's/^\.//' | sort) > "$T/got"
	expected | sort > "$T/want"
	diff "$T/want" "$T/got"
	[ "$(wc -l < "$T/got")" -ge 80 ]
	# modes: the programs 755, the rest 644; no list of made folders
	[ -z "$(cd "$T/stage" && find . -type f ! -perm 644 ! -path ".$bindir/*")" ]
	[ -z "$(cd "$T/stage" && find ".$bindir" -type f ! -perm 755)" ]
	[ ! -e "$T/stage$pkgdatadir/.made-dirs" ]
	# the programs are this build's: the same bytes
	for f in "$T/stage$bindir"/*; do
		cmp "$f" "$(command -v "${f##*/}")"
	done
	# dem.pc names the folders
	grep -qx "includedir=$includedir" "$T/stage$pkgconfigdir/dem.pc"
	grep -qx "libdir=$libdir" "$T/stage$pkgconfigdir/dem.pc"
}

# pc OPTION...: pkg-config OPTION... dem, on the staged dem.pc
pc() { PKG_CONFIG_PATH="$T/stage$pkgconfigdir" PKG_CONFIG_SYSROOT_DIR="$T/stage" pkg-config "$@" dem; }

# cc_dem ARGS...: the compiler of the build, as strict as the build
cc_dem() {
	local san=
	[ "${DEM_SANITIZE:-}" != 1 ] || san="-fsanitize=address,undefined"
	${DEM_TEST_CC:-cc} -std=c11 -Wall -Wextra -Werror $san "$@"
}

@test "install: a program of one's own builds with pkg-config on the headers and libdem.a, and counts the pairs demdetect counts" {
	stage "$T/stage"
	pc --exists --print-errors
	# shellcheck disable=SC2046
	cc_dem "$ROOT/tests/install/pairs.c" $(pc --cflags --libs) -o "$T/pairs"
	pairs_agree "$T/pairs"
	# a truncated stream: the reader's error, not a count
	head -c 300 "$T/p2" > "$T/cut"
	run --separate-stderr "$T/pairs" "$T/cut"
	[ "$status" -eq 1 ]
	[[ $stderr == "pairs: $T/cut:"*"truncated"* ]]
	# each installed header compiles on its own
	for h in $(cd "$T/stage$includedir/dem" && find . -name '*.h' | sed 's|^\./||'); do
		printf '#include <%s>\nint main(void) { return 0; }\n' "$h" > "$T/h.c"
		# shellcheck disable=SC2046
		cc_dem -c "$T/h.c" $(pc --cflags) -o "$T/h.o" || { echo "$h does not compile alone"; false; }
	done
}

@test "install: a place that is not a regular file is refused and left alone, and nothing is installed" {
	mkdir -p "$T/stage$bindir/dempack" "$T/stage$mandir/man1"
	ln -s "$T/target" "$T/stage$mandir/man1/demshot.1"
	echo keep > "$T/target"
	run stage "$T/stage"
	echo "$output"
	[ "$status" -ne 0 ]
	grep -q "install.sh: $T/stage$bindir/dempack is there and is not a regular file; not replaced" <<< "$output"
	grep -q "install.sh: $T/stage$mandir/man1/demshot.1 is there and is not a regular file; not replaced" <<< "$output"
	[ -d "$T/stage$bindir/dempack" ]
	[ -L "$T/stage$mandir/man1/demshot.1" ]
	[ "$(cat "$T/target")" = keep ]
	[ -z "$(find "$T/stage" -type f)" ]
}

@test "uninstall: every installed file goes, then the toolkit's own folders" {
	stage "$T/stage"
	echo mine > "$T/stage$bindir/other"
	run make -s -C "$ROOT" --no-print-directory uninstall DESTDIR="$T/stage"
	echo "$output"
	[ "$status" -eq 0 ]
	[ "$(cd "$T/stage" && find . ! -type d)" = "./${bindir#/}/other" ]
	[ ! -e "$T/stage$pkgdatadir" ]
	[ ! -e "$T/stage$includedir/dem" ]
	# a second uninstall finds nothing to do
	run make -s -C "$ROOT" --no-print-directory uninstall DESTDIR="$T/stage"
	[ "$status" -eq 0 ]
	[ -z "$output" ]
}

@test "install.sh: without DESTDIR, uninstall removes the folders install made and no other" {
	# the script on a small plan of its own, so that nothing is built
	mkdir -p "$T/p/share/man" "$T/p/bin"
	touch "$T/p/share/man/theirs"
	(cd "$T/p" && find . | sort) > "$T/before"
	export INSTALL_PLAN="755 $T/p/bin $ROOT/tools/install.sh
644 $T/p/share/man/man1 $ROOT/man/man1/dempack.1 $ROOT/man/man1/demshot.1
644 $T/p/share/dem/materials $ROOT/share/materials/Al5052.yaml
644 $T/p/lib/pkgconfig $ROOT/lib/dem.pc.in"
	sh "$ROOT/tools/install.sh" install "" "$T/p/share/dem"
	[ -x "$T/p/bin/install.sh" ]
	[ -f "$T/p/share/dem/materials/Al5052.yaml" ]
	# again over the first: the same files, the list of folders kept
	sh "$ROOT/tools/install.sh" install "" "$T/p/share/dem"
	sort "$T/p/share/dem/.made-dirs" > "$T/made"
	printf '%s\n' "$T/p/lib" "$T/p/lib/pkgconfig" "$T/p/share/dem" "$T/p/share/dem/materials" \
		"$T/p/share/man/man1" | sort | diff - "$T/made"
	sh "$ROOT/tools/install.sh" uninstall "" "$T/p/share/dem"
	(cd "$T/p" && find . | sort) | diff "$T/before" -
}
