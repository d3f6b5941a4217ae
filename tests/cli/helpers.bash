# Helpers shared by the command-line tests (loaded with `load helpers`).

# A usage error: exit 2, nothing on stdout, one message line naming the
# program, then "Try 'prog --help' ..." (coreutils).  Returns 1 (with the
# details on stdout, which bats shows) when it is not one.
# usage_error PROG ARGS...
usage_error() {
	local prog=$1
	run --separate-stderr "$@"
	echo "\$ $*  -> status $status, stdout '$output', stderr:"
	printf '  %s\n' "${stderr_lines[@]}"
	[ "$status" -eq 2 ] || return 1
	[ -z "$output" ] || return 1
	[ "${#stderr_lines[@]}" -eq 2 ] || return 1
	[[ ${stderr_lines[0]} == "$prog: "* ]] || return 1
	[ "${stderr_lines[1]}" = "Try '$prog --help' for more information." ]
}
