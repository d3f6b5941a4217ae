# examples/lib.sh - small shell helpers shared by the example scripts (POSIX
# sh; source it: . ../lib.sh).  No side effect on sourcing.

# state_rows FILE - the md5 of the decoded rows of a (gzip) state stream,
# its header (which holds the provenance) left out: two runs that must give
# the same results compare equal.
state_rows() {
	_off=$(gzip -dc "$1" | grep -abo -m1 '^# data' | cut -d: -f1)
	gzip -dc "$1" | tail -c +$((_off + 1)) | md5sum | cut -c1-32
}

# cost_field FILE KEY... - the values of KEY=VALUE in the last cost line
# (": cost: ") of FILE (a program's standard error), tab-separated, "-" for
# a key the line does not have.
cost_field() {
	_f=$1
	shift
	grep ': cost: ' "$_f" | tail -n 1 | awk -v keys="$*" '{
		for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
		n = split(keys, k, " ")
		for (j = 1; j <= n; j++) printf "%s%s", (j > 1 ? "\t" : ""), ((k[j] in v) ? v[k[j]] : "-")
		print "" }'
}

# median - the median of the numbers on standard input, one a line (the
# mean of the middle two for an even count); nothing for no input.
median() {
	sort -g | awk '{ v[++n] = $1 } END { if (n) print (n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2) }'
}

# loadavg - the 1-minute load average.
loadavg() {
	cut -d' ' -f1 /proc/loadavg
}
