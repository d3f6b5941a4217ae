#!/bin/sh
# install.sh install|uninstall DESTDIR PKGDATADIR - make install and make
# uninstall, by the plan the Makefile exports in INSTALL_PLAN: one line a
# folder, "MODE FOLDER FILE...", each FILE going to DESTDIR/FOLDER under
# its own name (no spaces in the names: make has none either).
#
# install: copies each file to a temporary name beside its place, then
# renames it there, so that an installed file is never half written.  A
# place that holds anything but a regular file (a folder, a link, a
# device) is refused and left as it is, and then nothing is installed.
# Without DESTDIR the folders it had to make are listed in
# PKGDATADIR/.made-dirs, so that uninstall removes them again, and only
# them; a staged install (DESTDIR, for a package) keeps no such list.
# uninstall: removes each planned file (a regular file only), then the
# listed folders and the toolkit's own (PKGDATADIR, and .../include/dem)
# when they are empty.
set -euf
[ $# -eq 3 ] || { echo "usage: install.sh install|uninstall DESTDIR PKGDATADIR" >&2; exit 2; }
what=$1 dest=$2 pkgdatadir=$3
: "${INSTALL_PLAN:?install.sh: INSTALL_PLAN is not set (run it from make)}"
made=$dest$pkgdatadir/.made-dirs
tmp=$(mktemp -d) || exit 4
trap 'rm -rf "$tmp"' EXIT
# the planned lines, trimmed, the empty ones left out
printf '%s\n' "$INSTALL_PLAN" | awk 'NF >= 2 { $1 = $1; print }' > "$tmp/plan"

say() { printf 'install.sh: %s\n' "$*" >&2; }

# is_other PATH: PATH is there and is not a regular file
is_other() { [ -L "$1" ] || { [ -e "$1" ] && [ ! -f "$1" ]; }; }

# mkdirs DIR: make DIR and its missing parents, printing those it made
mkdirs() {
	d=$1 missing=
	while [ ! -d "$d" ]; do
		if is_other "$d"; then
			say "$d is there and is not a folder"
			return 1
		fi
		missing="$d
$missing"
		d=$(dirname "$d")
	done
	printf '%s' "$missing" | while IFS= read -r m; do
		[ -z "$m" ] || { mkdir -m 755 "$m" && printf '%s\n' "$m"; }
	done
}

do_install() {
	# everything is checked before anything is copied
	bad=0
	while read -r mode dir files; do
		for f in $files; do
			t=$dest$dir/${f##*/}
			if [ ! -f "$f" ]; then
				say "$f: not built (run make first)"
				bad=1
			elif is_other "$t"; then
				say "$t is there and is not a regular file; not replaced"
				bad=1
			fi
		done
	done < "$tmp/plan"
	[ "$bad" -eq 0 ] || exit 4
	: > "$tmp/made"
	while read -r mode dir files; do
		mkdirs "$dest$dir" >> "$tmp/made" || exit 4
		names=
		for f in $files; do
			t=$dest$dir/${f##*/}
			new=$(mktemp "$dest$dir/.install.XXXXXX") || exit 4
			if ! { cp "$f" "$new" && chmod "$mode" "$new" && mv -fT "$new" "$t"; }; then
				rm -f "$new"
				say "$t: not installed"
				exit 4
			fi
			names="$names ${f##*/}"
		done
		echo "$dest$dir:$names"
	done < "$tmp/plan"
	if [ -z "$dest" ]; then
		# an earlier install's folders stay on the list
		[ ! -f "$made" ] || cat "$made" >> "$tmp/made"
		sort -u "$tmp/made" > "$tmp/made.sorted"
		cp "$tmp/made.sorted" "$made"
	fi
}

do_uninstall() {
	while read -r mode dir files; do
		for f in $files; do
			t=$dest$dir/${f##*/}
			if is_other "$t"; then
				say "$t is not a regular file; left there"
			elif [ -e "$t" ]; then
				rm -f "$t" && echo "removed $t"
			fi
		done
		: "$mode"
	done < "$tmp/plan"
	# the toolkit's own folders, and those that install made
	awk -v p="$pkgdatadir" -v d="$dest" '
		index($2, p) == 1 { print d $2 }
		$2 ~ /\/include\/dem(\/|$)/ { x = $2; sub(/\/include\/dem\/.*/, "/include/dem", x); print d $2; print d x }
		END { print d p "/scenes"; print d p }' "$tmp/plan" > "$tmp/dirs"
	if [ -f "$made" ] && [ ! -L "$made" ]; then
		cat "$made" >> "$tmp/dirs"
		rm -f "$made"
	fi
	# deepest first: a folder's subfolders go before it
	sort -u "$tmp/dirs" | awk 'NF { print length($0) "\t" $0 }' | sort -rn | cut -f2- |
		while IFS= read -r d; do
			if [ -d "$d" ] && [ ! -L "$d" ] && rmdir "$d" 2>/dev/null; then
				echo "removed $d/"
			fi
		done
}

case $what in
install) do_install ;;
uninstall) do_uninstall ;;
*) echo "install.sh: $what: expected install or uninstall" >&2; exit 2 ;;
esac
