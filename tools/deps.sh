#!/bin/sh
# deps.sh [PACKAGE...] - install the Debian packages the toolkit needs, and
# the PACKAGEs named (CI: lintian), or say how.  debhelper is for the
# Debian package (make deb, dpkg-buildpackage); OpenMPI for the MPI build
# (make MPI=1), which make check then tests too.
# Quick when everything is there: one dpkg-query call.
pkgs="build-essential pkg-config man-db libgsl-dev libyaml-dev zlib1g-dev libsuitesparse-dev libopenblas0-pthread libcmocka-dev bats parallel gnuplot-nox valgrind debhelper libopenmpi-dev openmpi-bin $*"
missing=""
for p in $pkgs; do
	st=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)
	case "$st" in
	*" installed") ;;
	*) missing="$missing $p" ;;
	esac
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
	echo "deps: installing:$missing"
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq && apt-get install -y -qq --no-install-recommends $missing >/dev/null || {
		echo "deps: apt-get install failed" >&2; exit 4; }
else
	echo "deps: missing packages:$missing" >&2
	echo "deps: run as root:  apt-get update && apt-get install -y$missing" >&2
	exit 4
fi
