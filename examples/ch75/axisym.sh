#!/bin/sh
# axisym.sh OUT NAME [SECTION.KEY=VALUE]... - one axisymmetric run of the
# Ch. 7.5 single impact (Ch. 7.5.1, Figs. 7.14-7.15), NAME =
# axisym-H-ALPHA[-TAG] (e.g. axisym-0.05-5):
#
#   H      element size in the impact area, mm (the 3D run's: 0.05 = d/20)
#   ALPHA  penalty k_n = alpha E (Ch. 7.5.1 takes k_n = 5E for both models)
#   TAG    a variant's name; the keys given after NAME are set in its scene
#          (scene.sh), after the model's own (axisym-checks.sh)
#
# The model is scene.yaml made 2D with scene.sh (one statement of the data):
# dim: 2, block.mode axisym, the cylinder r <= 4 mm (the 3D block's sides are
# 4 mm from the impact; their rollers become the outer rim's, u_r = 0),
# 0.9 mm thick, the fine region the 3D one's half-width (0.5 mm) from the
# axis, 0.6 mm deep, graded by the same 1.3 outside; bottom fixed, top
# free; the material, shot, damping and alpha of scene.yaml.  The shot is
# the 3D run's shot stream (one shot at x = y = 0, on the axis).
#
# Writes OUT/NAME.{yaml,shots,state,log,forces}.  The profiles are taken by
# axisym-report.sh (over the disks it compares).
set -e
out=$1 name=$2
shift 2
IFS=- read -r model h alpha tag <<EOF
$name
EOF
[ "$model" = axisym ] && [ -n "$alpha" ] || { echo "axisym.sh: $name: expected axisym-H-ALPHA" >&2; exit 2; }
bin=${BIN:-../../bin}
here=$(dirname "$0")
mkdir -p "$out"
"$bin"/dempack -s "$here/scene.yaml" shots --grid 1 --passes 1 --area 0.2mm:0.2mm \
	--angle 90deg --seed 1 > "$out/$name.shots" 2> /dev/null
{
	echo "dim: 2"
	sh "$here/scene.sh" "$here/scene.yaml" "block.element=$h mm" 'block.size=[4 mm, 0.9 mm]' \
		'block.fine=0.5 mm' 'block.mode=axisym' \
		'block.bc={xmax: normal, bottom: fixed, top: free}' "contact.alpha=$alpha" "$@"
} > "$out/$name.yaml"
"$bin"/demshot -s "$out/$name.yaml" --rule full -v --forces "$out/$name.forces" \
	-o "$out/$name.state" "$out/$name.shots" 2> "$out/$name.log"
grep '^demshot: cost' "$out/$name.log"
