#!/bin/sh
# ccx-inp.sh DEMFORM SCENE PROFILE - the CalculiX input (.inp, on stdout) of
# the job `demform -s SCENE PROFILE` runs: the same plate, mesh, material,
# supports and initial stress, for `make peers`.
#
# - Mesh: demform's (dem_plate_mesh): nx = round(L / element) by
#   ny = round(W / element) elements in plane, centred on x = y = 0, and
#   `layers` layers in z in [-h, 0] whose thickness grows by `grading` per
#   layer away from the peened face z = 0.  Node (i, j, k) is number
#   1 + i + (nx+1)(j + (ny+1)k), element (i, j, k) 1 + i + nx(j + ny k);
#   C3D8I (eight-node brick with incompatible modes, as demform's Q1/E9),
#   nodes in the order of both codes: the bottom face counter-clockwise seen
#   from above, then the top face.
# - Material: isotropic elastic, E and nu of the scene.  demform's J2 material
#   stays elastic in this job (the profile is inside the yield surface and
#   the plate is free: one Newton iteration), so the problem is the same.
# - Supports: demform's minimal ones, which leave the plate free: node
#   (nx/2, ny/2, nz/2) in x, y, z; (nx, ny/2, nz/2) in y, z; (nx/2, ny, nz/2) in z.
# - Initial stress (*INITIAL CONDITIONS, TYPE=STRESS): at each of the 8
#   integration points (2 x 2 x 2 Gauss; points 1-4 on the lower Gauss
#   plane, 5-8 on the upper one), the profile's stress at the point's depth
#   below z = 0, interpolated linearly between the profile's points (the
#   first point's values above it, the last's below it), as demform does;
#   the last pass of the profile.
# - Output: the displacements of the nodes the arc height needs (set NARC:
#   top and bottom nodes at the centre and at the chord's ends, y = 0), in
#   the .dat file; ccx-arc.sh computes the arc height as demform does.
#
# Lengths in m, stresses in Pa (the dem streams' SI units).  Needs an even
# nx and ny (the centre and the chord's ends are then nodes) and the chord
# along x over the whole length (demform's default).
set -eu
demform=$1 scene=$2 profile=$3
"$demform" -s "$scene" --dump-scene | awk -v prof="$profile" -v scene="$scene" '
function num(s) { sub(/\[/, "", s); sub(/,$/, "", s); return s + 0 }
/^[a-z]/ { sec = $1; sub(/:$/, "", sec); next }
{ key = sec "." $1; sub(/:$/, "", key) }
key == "material.E"  { E = num($2) }
key == "material.nu" { nu = num($2) }
key == "plate.size"  { L = num($2); W = num($4); h = num($6) }
key == "plate.element" { dxy = num($2) }
key == "plate.layers"  { nz = num($2) }
key == "plate.grading" { g = num($2) }
key == "plate.two_sided" { two = $2 }
key == "form.strain" { strain = $2 }
key == "form.init"   { init = $2 }
key == "form.chord"  { chord = num($2) }
key == "form.chord_axis" { axis = $2 }
function die(msg) { print "ccx-inp.sh: " msg > "/dev/stderr"; bad = 1; exit 1 }
function round(x) { return int(x + 0.5) }
function node(i, j, k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k) }
# the profile stress component c at depth d (linear, held beyond the ends)
function sig(c, d,    p) {
	if (d <= pd[1]) return ps[c, 1]
	for (p = 2; p <= np; p++)
		if (d <= pd[p])
			return ps[c, p - 1] + (ps[c, p] - ps[c, p - 1]) * (d - pd[p - 1]) / (pd[p] - pd[p - 1])
	return ps[c, np]
}
END {
	if (bad) exit 1
	if (two != "false" || strain != "small" || init != "stress")
		die("only one-sided plates, small strain and init: stress are written")
	if (axis != "x" || chord < L * (1 - 1e-12))
		die("the chord must run along x over the whole length")
	nx = round(L / dxy); ny = round(W / dxy)
	if (nx < 2 || ny < 2 || nx % 2 || ny % 2)
		die("nx = " nx " and ny = " ny " must be even")
	# the profile: columns by name from the header, rows of the last pass
	while ((getline line < prof) > 0) {
		if (line ~ /^# columns /) {
			nc = split(line, cols, " ")
			for (i = 3; i <= nc; i++) { split(cols[i], cv, ":"); col[cv[1]] = i - 2 }
			continue
		}
		if (line ~ /^#/ || line ~ /^[ \t]*$/) continue
		nf = split(line, v, " ")
		if (v[col["pass"]] + 0 != lastpass) { lastpass = v[col["pass"]] + 0; np = 0 }
		np++
		pd[np] = v[col["depth"]]
		ps[1, np] = v[col["sxx"]]; ps[2, np] = v[col["syy"]]; ps[3, np] = v[col["szz"]]
		ps[4, np] = v[col["sxy"]]; ps[5, np] = v[col["szx"]]; ps[6, np] = v[col["syz"]]
	}
	close(prof)
	if (np < 1) die(prof ": no profile rows")
	# the layers: thickness t0 g^k from the top, scaled to h
	sum = 0
	for (k = 0; k < nz; k++) { t[k] = g ^ k; sum += t[k] }
	gz[nz] = 0
	for (k = 0; k < nz; k++) gz[nz - 1 - k] = gz[nz - k] - h * t[k] / sum
	gz[0] = -h
	print "*HEADING"
	printf "form-bench peer: demform job %s, %d x %d x %d C3D8I, free, initial stress from %s\n", \
	    scene, nx, ny, nz, prof
	print "*NODE, NSET=NALL"
	for (k = 0; k <= nz; k++)
		for (j = 0; j <= ny; j++)
			for (i = 0; i <= nx; i++)
				printf "%d, %.13g, %.13g, %.13g\n", node(i, j, k), -L / 2 + L * i / nx, -W / 2 + W * j / ny, gz[k]
	print "*ELEMENT, TYPE=C3D8I, ELSET=EALL"
	for (k = 0; k < nz; k++)
		for (j = 0; j < ny; j++)
			for (i = 0; i < nx; i++)
				printf "%d, %d, %d, %d, %d, %d, %d, %d, %d\n", 1 + i + nx * (j + ny * k), \
				    node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k), \
				    node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)
	print "*NSET, NSET=NARC"
	printf "%d, %d, %d, %d, %d, %d\n", node(nx / 2, ny / 2, 0), node(nx / 2, ny / 2, nz), \
	    node(0, ny / 2, 0), node(0, ny / 2, nz), node(nx, ny / 2, 0), node(nx, ny / 2, nz)
	print "*MATERIAL, NAME=PLATE"
	print "*ELASTIC"
	printf "%.13g, %.13g\n", E, nu
	print "*SOLID SECTION, ELSET=EALL, MATERIAL=PLATE"
	print "*BOUNDARY"
	kc = int(nz / 2)
	printf "%d, 1, 3\n", node(nx / 2, ny / 2, kc)
	printf "%d, 2, 3\n", node(nx, ny / 2, kc)
	printf "%d, 3, 3\n", node(nx / 2, ny, kc)
	print "*INITIAL CONDITIONS, TYPE=STRESS"
	a = 1 / sqrt(3)
	for (k = 0; k < nz; k++) {
		zm = (gz[k] + gz[k + 1]) / 2; hz = (gz[k + 1] - gz[k]) / 2
		for (q = 0; q < 2; q++) {       # the lower, then the upper Gauss plane
			d = -(zm + (q ? a : -a) * hz)
			s[q] = sprintf("%.13g, %.13g, %.13g, %.13g, %.13g, %.13g",
			    sig(1, d), sig(2, d), sig(3, d), sig(4, d), sig(5, d), sig(6, d))
		}
		for (j = 0; j < ny; j++)
			for (i = 0; i < nx; i++) {
				el = 1 + i + nx * (j + ny * k)
				for (ip = 1; ip <= 8; ip++)
					printf "%d, %d, %s\n", el, ip, s[(ip > 4) ? 1 : 0]
			}
	}
	print "*STEP"
	print "*STATIC"
	print "*NODE PRINT, NSET=NARC"
	print "U"
	print "*END STEP"
}'
