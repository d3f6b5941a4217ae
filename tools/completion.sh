#!/bin/sh
# completion.sh PROG - print the bash completion of the program PROG (a
# path), made from what 'PROG --help' prints: the help is printed from the
# program's option table (dem_cli_help), so the completion is that table's
# and is made again whenever the program is (make), it cannot drift.
#
# Read from the help:
#   "Usage: PROG VERB [OPTION]..." / "  or:  PROG VERB ..."  the verbs, the
#       first word after PROG when it is not "[...]": completed when no verb
#       is there yet; with no verbs, an operand ("[FILE]") is a file name;
#   "  -x, --long ARG", "      --long ARG", "      --long[=ARG]"  the
#       options, as tests/cli/man.bats reads them: an upper-case word right
#       after the option is its argument.  The argument of an option whose
#       argument is FILE is completed as a file name; other arguments are
#       left alone (nothing is offered).
# The script uses bash's compgen only (bash-completion's helpers are not
# needed).
set -eu
[ $# -eq 1 ] || { echo "usage: completion.sh PROG" >&2; exit 2; }
prog=$1
name=$(basename "$prog")
case $name in
*[!A-Za-z0-9_]*) echo "completion.sh: $name: not a name for a shell function" >&2; exit 2 ;;
esac
help=$("$prog" --help) || { echo "completion.sh: $prog --help failed" >&2; exit 1; }
printf '%s\n' "$help" | awk -v name="$name" '
function add(list, w) { return list == "" ? w : list "|" w }
# the usage lines: verbs, and whether an operand is a file
$1 == "Usage:" && $2 == name || $1 == "or:" && $2 == name {
	if ($3 !~ /^\[/ && $3 != "")
		verbs = verbs " " $3
	else if ($0 ~ /\]\.\.\. \[[A-Z]+\]/)
		operand = 1
	next
}
/^ +(-[[:alnum:]], )?--[[:alnum:]][[:alnum:]-]*/ {
	line = $0
	sub(/^ +/, "", line)
	short = ""
	if (line ~ /^-[[:alnum:]], /) {
		short = substr(line, 1, 2)
		line = substr(line, 5)
	}
	match(line, /^--[[:alnum:]][[:alnum:]-]*/)
	long = substr(line, 1, RLENGTH)
	rest = substr(line, RLENGTH + 1)
	words = words " " (short != "" ? short " " : "") long
	if (rest ~ /^\[=/) {                    # an optional argument: --long=ARG only
		optional = add(optional, long)
	} else if (match(rest, /^ [A-Z][][A-Z:]*( |$)/)) {
		arg = substr(rest, 2, RLENGTH - 1)
		sub(/ $/, "", arg)
		both = (short != "" ? short "|" : "") long
		if (arg == "FILE")
			file = add(file, both)
		else
			other = add(other, both)
	}
}
END {
	if (words == "") {
		print "completion.sh: " name ": no options in its --help" > "/dev/stderr"
		exit 1
	}
	sub(/^ /, "", words)
	sub(/^ /, "", verbs)
	none = "__dem_none__"
	printf "# bash completion for %s, made by tools/completion.sh from\n", name
	printf "# \"%s --help\" (the program'"'"'s option table); do not edit.\n", name
	printf "_dem_%s()\n{\n", name
	print "\tlocal i=$COMP_CWORD cur=${COMP_WORDS[COMP_CWORD]} prev= eq= j w"
	print "\tCOMPREPLY=()"
	print "\t# \"--opt=VALUE\" comes as three words, \"--opt\", \"=\" and VALUE"
	print "\tif [[ $cur == = ]]; then"
	print "\t\tcur= prev=${COMP_WORDS[i-1]} eq=1"
	print "\telif ((i > 1)) && [[ ${COMP_WORDS[i-1]} == = ]]; then"
	print "\t\tprev=${COMP_WORDS[i-2]} eq=1"
	print "\telif ((i > 0)); then"
	print "\t\tprev=${COMP_WORDS[i-1]}"
	print "\tfi"
	print "\tcase $prev in"
	printf "\t%s)\n", file == "" ? none : file
	print "\t\tmapfile -t COMPREPLY < <(compgen -f -- \"$cur\")"
	print "\t\treturn ;;"
	printf "\t%s)\n", other == "" ? none : other
	print "\t\treturn ;;"
	printf "\t%s)\n", optional == "" ? none : optional
	print "\t\t[[ -z $eq ]] || return ;;"
	print "\tesac"
	print "\tif [[ $cur == -* ]]; then"
	printf "\t\tmapfile -t COMPREPLY < <(compgen -W \"%s\" -- \"$cur\")\n", words
	print "\t\treturn"
	print "\tfi"
	if (verbs != "") {
		print "\t# a verb, unless one is there already (option arguments skipped)"
		print "\tfor ((j = 1; j < i; j++)); do"
		print "\t\tw=${COMP_WORDS[j]}"
		print "\t\tcase $w in"
		printf "\t\t%s)\n", file == "" && other == "" ? none : (file == "" ? other : (other == "" ? file : file "|" other))
		print "\t\t\tj=$((j + 1))"
		print "\t\t\t[[ ${COMP_WORDS[j]:-} != = ]] || j=$((j + 1))"
		print "\t\t\t# \"1mm:2mm\" comes as three words too"
		print "\t\t\twhile [[ ${COMP_WORDS[j+1]:-} == : ]]; do j=$((j + 2)); done ;;"
		print "\t\t-*) ;;"
		print "\t\t*) return ;;"
		print "\t\tesac"
		print "\tdone"
		printf "\tmapfile -t COMPREPLY < <(compgen -W \"%s\" -- \"$cur\")\n", verbs
	} else if (operand) {
		print "\tmapfile -t COMPREPLY < <(compgen -f -- \"$cur\")"
	}
	print "}"
	printf "complete -o filenames -F _dem_%s %s\n", name, name
}'
