#!/bin/sh
# shot-run.sh OUT NAME - one demshot run of the accuracy study on the single
# shot of Ch. 7.5, NAME = H-RULE-LAMBDA-PARTIAL-STRAIN-EFFECT, e.g.
# 0.1-one_point-0.2-area-large-none (the base case):
#
#   H        element size in the impact area, mm (0.2 = d/5, 0.1 = d/10,
#            0.05 = d/20 for the 1 mm shot)
#   RULE     one_point or full (demshot --rule)
#   LAMBDA   contact time step factor (demshot --lambda; --force above 0.5)
#   PARTIAL  partial contact factor (contact.partial: area, volume, ...)
#   STRAIN   large or small (demshot --strain)
#   EFFECT   none, or one effect switched on or off against the base:
#            friction   contact.friction 0.2 (Ch. 7.5.3's range 0-0.5)
#            friction0  contact.friction 0 (must give the results of none)
#            cdamping   contact.damping 0.1 (viscous contact damping,
#                       Eqs. 3.70-3.76; ratio chosen here)
#            unload     contact.unload 2 (hysteresis, Eqs. 3.63-3.67;
#                       chosen here: restitution 2^(-1/3) = 0.79)
#            rate       material.rate: power law, m 0.0455, ref 1/s (the
#                       aluminium of Table 7.2, Al5052)
#            undamped   no global damping (run.damping left out)
#
# The model is that of examples/ch75/run.sh (single): Ch. 7.5
# (thesis-data.yaml, shot_peening_3d), steel shot of radius 0.5 mm at 19 m/s
# on an 8 x 8 x 0.9 mm aluminium block (E 68 GPa, yield 157 MPa, linear
# hardening 120 MPa), global damping 0.05, penalty alpha 2; nu 0.33, rho
# 2700 kg/m^3, shot density 7800 kg/m^3, the 1 x 1 mm fine region 0.6 mm
# deep and the growth 1.3 are ch75's choices.  One thread.
#
# A run shorter than SHORT seconds (default 10) is repeated until REPS runs
# (default 3); the results are the same bit for bit, the times differ.
# Writes OUT/NAME.{yaml,state,log,prof} and OUT/NAME.row: name, h, rule,
# lambda, partial, strain, effect, elements, steps, runs, median wall s,
# median cpu s, min and max wall s, load average before the first run, the
# energy balance error, whether every repeat gave the same state rows.
# The profile is the residual stress averaged over the central 0.4 x 0.4 mm
# (2 x 2 elements at d/5, 8 x 8 at d/20: the same area for every H).
set -e
out=$1 name=$2
here=$(dirname "$0")
. "$here/../lib.sh"
IFS=- read -r h rule lambda partial strain effect <<EOF
$name
EOF
[ -n "$effect" ] || { echo "shot-run.sh: $name: expected H-RULE-LAMBDA-PARTIAL-STRAIN-EFFECT" >&2; exit 2; }
bin=${BIN:-../../bin}
reps=${REPS:-3}
short=${SHORT:-10}
mkdir -p "$out"
shots=$out/shot.shots
[ -s "$shots" ] || "$bin"/dempack shots --grid 1 --passes 1 --area 0.2mm:0.2mm --speed 19 \
	--shot-radius 0.5mm --seed 1 -o "$shots" 2> /dev/null
mat= con= damp="  damping: 0.05"
case $effect in
none) ;;
friction) con="  friction: 0.2" ;;
friction0) con="  friction: 0" ;;
cdamping) con="  damping: 0.1" ;;
unload) con="  unload: 2" ;;
rate) mat="  rate: {law: power, m: 0.0455, ref: 1 1/s}" ;;
undamped) damp= ;;
*) echo "shot-run.sh: $name: unknown effect '$effect'" >&2; exit 2 ;;
esac
cat > "$out/$name.yaml" <<EOF
material:
  E: 68 GPa
  nu: 0.33
  rho: 2700 kg/m^3
  yield: 157 MPa
  hardening: 120 MPa
$mat
block:
  size: [8 mm, 8 mm, 0.9 mm]
  element: $h mm
  fine: [1 mm, 1 mm]
  fine_depth: 0.6 mm
  ratio: 1.3
shot:
  density: 7800 kg/m^3
contact:
  alpha: 2
  partial: $partial
$con
run:
$damp
EOF
force=
awk -v l="$lambda" 'BEGIN { exit !(l > 0.5) }' && force=--force
load=$(loadavg)
: > "$out/$name.times"
i=0 same=yes
while :; do
	i=$((i + 1))
	"$bin"/demshot -s "$out/$name.yaml" -v --threads 1 --rule "$rule" --strain "$strain" \
		--lambda "$lambda" $force -o "$out/$name.state.new" "$shots" 2> "$out/$name.log"
	cost_field "$out/$name.log" wall_s cpu_s >> "$out/$name.times"
	if [ "$i" -gt 1 ] && [ "$(state_rows "$out/$name.state.new")" != "$(state_rows "$out/$name.state")" ]; then
		same=no
	fi
	mv "$out/$name.state.new" "$out/$name.state"
	wall=$(cost_field "$out/$name.log" wall_s)
	[ "$i" -lt "$reps" ] && awk -v w="$wall" -v s="$short" 'BEGIN { exit !(w < s) }' || break
done
"$bin"/demprofile -q --area 0.4mm:0.4mm --margin 0 -o "$out/$name.prof" "$out/$name.state" 2> "$out/$name.plog"
set -- $(cost_field "$out/$name.log" elements steps energy_error)
wmed=$(cut -f1 "$out/$name.times" | median)
cmed=$(cut -f2 "$out/$name.times" | median)
wmin=$(cut -f1 "$out/$name.times" | sort -g | head -n 1)
wmax=$(cut -f1 "$out/$name.times" | sort -g | tail -n 1)
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$h" "$rule" "$lambda" \
	"$partial" "$strain" "$effect" "$1" "$2" "$i" "$wmed" "$cmed" "$wmin" "$wmax" "$load" "$3" "$same" \
	> "$out/$name.row"
cat "$out/$name.row"
