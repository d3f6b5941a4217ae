#!/bin/sh
# scene.sh SCENE [SECTION.KEY=VALUE]... - print the scene SCENE with each
# key set to its value: the line "  KEY: ..." of SECTION is replaced, or
# "  KEY: VALUE" is added at the end of SECTION.  For scenes written as
# scene.yaml is: top-level sections, their keys two spaces in, one a line.
# The variants of the Ch. 7.5 model are made this way (run.sh and the
# tests in tests/cli), so the model is written out once:
#
#   sh scene.sh scene.yaml 'block.element=0.1 mm' contact.friction=0.2
#
# A SECTION the scene lacks is an error (exit 2, nothing printed); a KEY
# the program does not know is left to the program, which refuses it.
[ $# -ge 1 ] || { echo "usage: scene.sh SCENE [SECTION.KEY=VALUE]..." >&2; exit 2; }
awk '
BEGIN {
	for (i = 2; i < ARGC; i++) {
		eq = index(ARGV[i], "=")
		k = substr(ARGV[i], 1, eq - 1)
		if (eq == 0 || k !~ /^[A-Za-z_]+\.[A-Za-z_]+$/) {
			print "scene.sh: " ARGV[i] ": expected SECTION.KEY=VALUE" > "/dev/stderr"
			bad = 1
			exit 2
		}
		if (!(k in val))
			keys[++n] = k
		val[k] = substr(ARGV[i], eq + 1)
		ARGV[i] = ""
	}
}
# the keys of section s that its lines did not have
function add(s,   i) {
	for (i = 1; i <= n; i++)
		if (!(keys[i] in done) && index(keys[i], s ".") == 1) {
			line[++nl] = "  " substr(keys[i], length(s) + 2) ": " val[keys[i]]
			done[keys[i]] = 1
		}
}
/^[A-Za-z_]+:/ {
	add(sec)
	sec = substr($0, 1, index($0, ":") - 1)
	line[++nl] = $0
	next
}
sec != "" && /^  [A-Za-z_]+:/ {
	k = sec "." substr($1, 1, length($1) - 1)
	if (k in val) {
		line[++nl] = "  " substr($1, 1, length($1) - 1) ": " val[k]
		done[k] = 1
		next
	}
}
{ line[++nl] = $0 }
END {
	if (bad)
		exit 2
	add(sec)
	for (i = 1; i <= n; i++)
		if (!(keys[i] in done)) {
			print "scene.sh: " keys[i] ": no section \"" substr(keys[i], 1, index(keys[i], ".") - 1) "\" in " ARGV[1] > "/dev/stderr"
			exit 2
		}
	for (i = 1; i <= nl; i++)
		print line[i]
}' "$@"
