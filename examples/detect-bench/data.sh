#!/bin/sh
# data.sh DEMPACK FILE - make the data set FILE with `dempack random`, once.
#
# FILE is DIR/KEY.EXT: KEY is d<dim>-n<N>-<law>-rho<density>-lam<lambda>[-a<AXxAY>]
# (plan.awk) and EXT the format: bin (binary), bin.gz (gzip-compressed binary)
# or txt (text).  The seed is fixed, so every machine times the same objects.
set -eu
dempack=$1 file=$2
name=${file##*/}
case $name in
*.bin.gz) fmt="-b -z" key=${name%.bin.gz} ;;
*.bin)    fmt="-b"    key=${name%.bin} ;;
*.txt)    fmt=""      key=${name%.txt} ;;
*) echo "data.sh: $file: expected a .bin, .bin.gz or .txt name" >&2; exit 2 ;;
esac
set -f        # split the key at "-" into the positional parameters, no globbing
IFS=-
# shellcheck disable=SC2086
set -- $key
unset IFS
[ $# -ge 5 ] || { echo "data.sh: $key: expected d<dim>-n<N>-<law>-rho<R>-lam<L>[-a<aspect>]" >&2; exit 2; }
aspect=
[ $# -ge 6 ] && aspect="--aspect $(echo "${6#a}" | tr x :)"
mkdir -p "$(dirname "$file")"
err=$(mktemp)
trap 'rm -f "$err"' EXIT
# shellcheck disable=SC2086 # fmt and aspect are option lists
if ! "$dempack" random -q --seed 1 --dim "${1#d}" -n "${2#n}" --law "$3" \
	--density "${4#rho}" --lambda "${5#lam}" $aspect $fmt -o "$file" 2>"$err"; then
	cat "$err" >&2    # only dempack's errors: its cost line is of no use here
	exit 1
fi
