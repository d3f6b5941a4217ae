# scene.sh - sourced by run.sh and pair.sh: the lengths of the model
# and scene CX CY,
# the scene of examples/coverage (bash).  The model's settings, from the
# environment: THREADS (demshot's, 1), PER_D (elements per D, 5), AREA_D
# (the impact area's side in D, 8), D (the shot's diameter, 0.28 mm).
threads=${THREADS:-1}
per_d=${PER_D:-5}
area_d=${AREA_D:-8}
d=${D:-0.28}
# lengths in mm from D: shot radius, element, impact area, block side,
# block depth, fine depth, profile margin (0.75 D: at least the footprint
# radius, 0.56 D measured at D/5), pass time (us, 2 D / v)
read -r r h area side thick fdepth margin ptime <<< "$(awk -v d="$d" -v n="$per_d" -v k="$area_d" 'BEGIN {
	printf "%.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g\n",
		d / 2, d / n, k * d, (k + 0.4) * d, 1.5 * d, 0.6 * d, 0.75 * d, 2 * d / 50 * 1e3 }')"

# scene CX CY: the scene with the impact area centred at (CX, CY) mm (the
# block stays centred on 0)
scene() {
	echo "# scene of examples/coverage, written by run.sh: the model of"
	echo "# examples/verification (Han 2004, Ch. 7.5-7.6), D = $d mm, area ${area_d}D."
	echo
	cat "$here/../verification/Al5052.yaml"
	cat <<EOS

pack:
  method: shots
  area: [$area mm, $area mm]
  center: [$1 mm, $2 mm]

shot:
  radius: $r mm
  speed: 50 m/s
  angle: 90 deg
  density: 7800 kg/m^3

block:
  size: [$side mm, $side mm, $thick mm]
  element: $h mm
  fine: [$area mm, $area mm]
  fine_depth: $fdepth mm
  ratio: 1.3

contact:
  m: 1.5
  alpha: 2

run:
  damping: 0.05
  pass_time: $ptime us

# the plastic coverage (demprofile's default threshold, 0.002) over the
# area less 0.75 D at each edge
profile:
  margin: $margin mm
EOS
}
