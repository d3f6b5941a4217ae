#!/usr/bin/env bats
# The man pages agree with --help (STYLE.md: "make check fails when the man
# page and --help disagree on the options") and render without warnings.
# Every program of cmd/ is checked; it runs from PATH (bin/, or the
# sanitizer build, first), its page is man/man1/PROG.1 (with make
# installcheck, the installed program and page: MANDIR, helpers.bash).

bats_require_minimum_version 1.5.0
load helpers

setup() {
	PROGS=()
	for c in "$ROOT"/cmd/*.c; do
		PROGS+=("$(basename "$c" .c)")
	done
}

# The options of PROG --help, one per line, as they are shown there:
# "-n, --number N", "--shape[=TOL]", "--dump-scene".
help_options() {
	"$1" --help | grep -oE '^ +(-[[:alnum:]], )?--[[:alnum:]][[:alnum:]-]*(\[=[A-Z][A-Z:]*\]| [A-Z][][A-Z:]*)?' |
		sed 's/^ *//'
}

# The tags of the OPTIONS section of a man page, rendered, one per line,
# in the same form.
man_options() {
	LC_ALL=C MANWIDTH=200 man -l "$1" 2>/dev/null |
		awk '/^[A-Z]/ { on = ($0 == "OPTIONS") } on && /^       -/' |
		sed -E 's/^ +//; s/  +.*//'
}

@test "man: every program of cmd/ is on PATH and has its page man/man1/PROG.1" {
	[ "${#PROGS[@]}" -ge 2 ]
	for p in "${PROGS[@]}"; do
		command -v "$p"
		[ -f "$(man_page "$p" 1)" ] || { echo "no $MANDIR/man1/$p.1"; false; }
	done
}

@test "man: every long option of --help appears in the man page as \\-\\-name" {
	for p in "${PROGS[@]}"; do
		page=$(man_page "$p" 1)
		opts=$("$p" --help | grep -oE '^ +(-[[:alnum:]], )?--[[:alnum:]][[:alnum:]-]*' | sed 's/.*--//')
		[ -n "$opts" ]
		for o in $opts; do
			esc=${o//-/\\\\-}
			zcat -f "$page" | grep -qE -- "(\\\\-\\\\-|--)($o|$esc)([^[:alnum:]\\\\-]|\\\\[^-]|\$)" ||
				{ echo "$p: --$o is not in $page"; false; }
		done
	done
}

@test "man: every option the OPTIONS section lists is in --help, with the same letter and argument" {
	for p in "${PROGS[@]}"; do
		help_options "$p" | sort > "$BATS_TEST_TMPDIR/help"
		man_options "$(man_page "$p" 1)" | sort > "$BATS_TEST_TMPDIR/man"
		echo "$p: --help (<) against man OPTIONS (>):"
		[ -s "$BATS_TEST_TMPDIR/man" ]
		diff "$BATS_TEST_TMPDIR/help" "$BATS_TEST_TMPDIR/man"
	done
}

@test "man: the pages render with man -l without warnings" {
	for src in "$ROOT"/man/man1/*.1 "$ROOT"/man/man5/*.5; do
		name=$(basename "$src")
		page=$(man_page "${name%.*}" "${name##*.}")
		run --separate-stderr env MANWIDTH=80 man --warnings -l "$page"
		echo "$page: $stderr"
		[ "$status" -eq 0 ]
		[ -z "$stderr" ]
		[ -n "$output" ]
	done
}

@test "man: each page has the sections the toolkit's pages carry" {
	for p in "${PROGS[@]}"; do
		page=$(man_page "$p" 1)
		for s in NAME SYNOPSIS DESCRIPTION OPTIONS "EXIT STATUS" EXAMPLES "SEE ALSO"; do
			zcat -f "$page" | grep -qx "\\.SH \"\\?$s\"\\?" || { echo "$p: no $s section"; false; }
		done
		zcat -f "$page" | grep -q "^$p \\\\- "
	done
	zcat -f "$(man_page dem-streams 5)" | grep -qx '\.SH NAME'
}
