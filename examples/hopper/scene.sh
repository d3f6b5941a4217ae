#!/bin/sh
# scene.sh SHAPE COUNT END FRAMES - the hopper's scene for one shape on
# stdout: base.yaml with the bodies section and the run's length.
#
# The shapes of Ch. 4.5: superquadrics with a = 4.5, b = 3.5 mm and
# m = 2, 5, 15; triangles and squares, which the thesis does not size:
# here equilateral and of the area of the m = 2 superquadric, pi a b =
# 49.48 mm^2 (circumradius sqrt(4 A / (3 sqrt 3)) = 6.172 mm and
# sqrt(A / 2) = 4.974 mm); and, for the cost of the shape, disks of that
# area (radius sqrt(a b) = 3.969 mm).
set -e
shape=$1 count=$2 end=$3 frames=$4
here=$(dirname "$0")
echo "bodies:"
case $shape in
sq2|sq5|sq15)
	printf '  shape: superquadric\n  a: 4.5 mm\n  b: 3.5 mm\n  m: %s\n' "${shape#sq}" ;;
tri)	printf '  shape: polygon\n  sides: 3\n  a: 6.172 mm\n' ;;
square)	printf '  shape: polygon\n  sides: 4\n  a: 4.974 mm\n' ;;
disk)	printf '  shape: disk\n  a: 3.969 mm\n' ;;
*)	echo "scene.sh: unknown shape '$shape'" >&2; exit 2 ;;
esac
# the bodies on a lattice above the funnel, each turned at random
printf '  count: %s\n  region: [-58 mm, 65 mm, 58 mm, 435 mm]\n' "$count"
# base.yaml ends with its run section
cat "$here/base.yaml"
printf '  end: %s\n  frames: %s\n' "$end" "$frames"
