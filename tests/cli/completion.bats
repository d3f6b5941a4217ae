#!/usr/bin/env bats
# The bash completion of every program of cmd/ (tools/completion.sh, made
# from --help by make; with make installcheck the installed files, COMPDIR
# in helpers.bash).  Checked against the program's own --help: "-" offers
# exactly the options --help lists, short and long; an option whose
# argument is FILE completes file names, another argument nothing; the
# verbs of dempack come first; an operand FILE completes file names.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	T=$BATS_TEST_TMPDIR
	PROGS=()
	for c in "$ROOT"/cmd/*.c; do
		PROGS+=("$(basename "$c" .c)")
	done
}

# complete PROG WORD...: the completions of the last WORD of the command
# line "PROG WORD...", one a line, sorted (in bash, as bash-completion
# calls the function the file registers for PROG)
complete_words() {
	bash -c '
		. "$1" || exit 1
		shift
		spec=$(complete -p "$1") || exit 1
		fn=${spec#*-F }
		fn=${fn%% *}
		COMP_WORDS=("$@")
		COMP_CWORD=$(($# - 1))
		COMPREPLY=()
		"$fn" "$1" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
		printf "%s\n" "${COMPREPLY[@]}" | sort
	' complete "$COMPDIR/$1" "$@"
}

@test "completion: each program has its file, and '-' offers the options of its --help" {
	[ "${#PROGS[@]}" -ge 6 ]
	for p in "${PROGS[@]}"; do
		[ -f "$COMPDIR/$p" ] || { echo "no $COMPDIR/$p"; false; }
		"$p" --help | grep -oE '^ +(-[[:alnum:]], )?--[[:alnum:]][[:alnum:]-]*' |
			tr -d ',' | tr ' ' '\n' | grep . | sort > "$T/help"
		complete_words "$p" - > "$T/comp"
		echo "$p: --help (<) against the completion of '-' (>):"
		diff "$T/help" "$T/comp"
		[ "$(wc -l < "$T/comp")" -ge 11 ]
	done
}

@test "completion: option names, FILE arguments, other arguments, operands" {
	cd "$T"
	mkdir sub
	touch scene.yaml shots.txt 'a b.yaml'
	[ "$(complete_words demshot --sc)" = --scene ]
	[ "$(complete_words demdetect --sha)" = --shape ]
	# a FILE argument: file names, also after --opt= and with spaces
	[ "$(complete_words demshot -s sc)" = scene.yaml ]
	[ "$(complete_words demform --scene = sc)" = scene.yaml ]
	[ "$(complete_words demshot --vtu 'a ')" = 'a b.yaml' ]
	[ "$(complete_words demprofile -o s | tr '\n' ' ')" = "scene.yaml shots.txt sub " ]
	# another argument: nothing offered
	[ -z "$(complete_words demshot --end '')" ]
	[ -z "$(complete_words demdetect -a '')" ]
	[ -z "$(complete_words demdetect --shape = '')" ]
	# an operand: file names (demshot's SHOTS, demdetect's FILE)
	[ "$(complete_words demshot -s scene.yaml sh)" = shots.txt ]
	[ "$(complete_words demdetect --shape sh)" = shots.txt ]
}

@test "completion: dempack's verbs first, once" {
	verbs=$(dempack --help | awk '$1 == "Usage:" || $1 == "or:" { print $3 }' | sort)
	[ "$(echo "$verbs" | wc -l)" -eq 4 ]
	[ "$(complete_words dempack '')" = "$verbs" ]
	[ "$(complete_words dempack co)" = compress ]
	# after options and their arguments (1mm:1mm is three words to bash)
	[ "$(complete_words dempack --seed 1 -q --area 1mm : 1mm '')" = "$verbs" ]
	[ "$(complete_words dempack --scene = x.yaml s)" = shots ]
	# not after a verb
	[ -z "$(complete_words dempack shots '')" ]
	[ -z "$(complete_words dempack -s x.yaml front '')" ]
}
