#!/bin/sh
# liggghts-in.sh PACKING MU DUMP - the LIGGGHTS input script (on stdout) of
# the pour that `make peers` puts beside `dempack compress`: as many spheres
# as PACKING (a dempack compress text stream) holds, of its radius (one size:
# law mono), poured into its box under gravity.
#
# The floor and the four side walls are the box's ('# box' in PACKING's
# header); the top stays open and the domain reaches above the box, since a
# pour needs room above the bed: the spheres are inserted at once, without
# overlap, at a volume fraction of 0.3 in a column over the box's floor
# area, then fall and settle (a rain pour).  Hertz contacts with Coulomb
# friction MU (tangential history) between spheres and with the walls;
# restitution 0.5; glass density 2500 kg/m^3 with a softened Young's modulus
# of 5 MPa (Poisson 0.3), so the time step stays affordable while the
# overlaps stay near 0.1 % of the radius at rest (the bed's weight is tiny
# at this scale); time step 0.2 Rayleigh times.  The run goes on in chunks
# of 2000 steps until the kinetic energy is below that of every sphere
# moving at 1e-2 sqrt(g d), at most 100 chunks, then writes the spheres to
# DUMP (a LIGGGHTS custom dump: id x y z radius).  The stop test and the
# insertion fraction are ours, chosen for a settled bed, not LIGGGHTS's.
set -eu
packing=$1 mu=$2 dump=$3
awk -v mu="$mu" -v dump="$dump" '
/^# box / { x0 = $3; y0 = $4; z0 = $5; x1 = $6; y1 = $7; z1 = $8; next }
/^#/ { next }
NF >= 4 { n++; if (r == "") r = $4; else if ($4 != r) mono = "no" }
END {
	if (n == 0 || x1 == "") { print "liggghts-in.sh: " FILENAME ": no spheres or no # box line" > "/dev/stderr"; exit 1 }
	if (mono == "no") { print "liggghts-in.sh: spheres of one size only (dempack compress --law mono)" > "/dev/stderr"; exit 1 }
	pi = atan2(0, -1)
	rho = 2500; E = 5e6; nu = 0.3; en = 0.5; g = 9.81
	vol = n * 4 / 3 * pi * r ^ 3
	area = (x1 - x0) * (y1 - y0)
	col = vol / (area * 0.3)              # the column the spheres start in
	ztop = z0 + col + 2 * r
	G = E / (2 * (1 + nu))
	dt = 0.2 * pi * r * sqrt(rho / G) / (0.1631 * nu + 0.8766)
	m = rho * 4 / 3 * pi * r ^ 3
	vstop = 1e-2 * sqrt(g * 2 * r)
	kestop = n * 0.5 * m * vstop ^ 2
	print "# LIGGGHTS pour written by liggghts-in.sh from " FILENAME "; do not edit"
	printf "# %d spheres of radius %g m into the box %g %g %g %g %g %g (open top), friction %g\n", n, r, x0, y0, z0, x1, y1, z1, mu
	print "atom_style granular"
	print "atom_modify map array"
	print "boundary f f f"
	print "newton off"
	print "communicate single vel yes"
	print "units si"
	printf "region domain block %.9g %.9g %.9g %.9g %.9g %.9g units box\n", x0, x1, y0, y1, z0, ztop
	print "create_box 1 domain"
	printf "neighbor %.9g bin\n", 0.4 * r
	print "neigh_modify delay 0"
	printf "fix m1 all property/global youngsModulus peratomtype %g\n", E
	printf "fix m2 all property/global poissonsRatio peratomtype %g\n", nu
	printf "fix m3 all property/global coefficientRestitution peratomtypepair 1 %g\n", en
	printf "fix m4 all property/global coefficientFriction peratomtypepair 1 %g\n", mu
	print "pair_style gran model hertz tangential history"
	print "pair_coeff * *"
	printf "timestep %.6g\n", dt
	printf "fix gravi all gravity %g vector 0.0 0.0 -1.0\n", g
	printf "fix wx0 all wall/gran model hertz tangential history primitive type 1 xplane %.9g\n", x0
	printf "fix wx1 all wall/gran model hertz tangential history primitive type 1 xplane %.9g\n", x1
	printf "fix wy0 all wall/gran model hertz tangential history primitive type 1 yplane %.9g\n", y0
	printf "fix wy1 all wall/gran model hertz tangential history primitive type 1 yplane %.9g\n", y1
	printf "fix wz0 all wall/gran model hertz tangential history primitive type 1 zplane %.9g\n", z0
	printf "fix pts all particletemplate/sphere 15485863 atom_type 1 volume_limit 1e-20 density constant %g radius constant %.9g\n", rho, r
	print "fix pdd all particledistribution/discrete 15485867 1 pts 1.0"
	printf "region column block %.9g %.9g %.9g %.9g %.9g %.9g units box volume_limit 1e-20\n", x0, x1, y0, y1, z0, z0 + col
	printf "fix ins all insert/pack seed 32452843 distributiontemplate pdd maxattempt 1000 insert_every once overlapcheck yes all_in yes vel constant 0 0 0 region column particles_in_region %d ntry_mc 10000\n", n
	print "fix integr all nve/sphere"
	print "thermo_style custom step atoms ke cpu"
	print "thermo 2000"
	print "thermo_modify lost ignore norm no"
	print "compute_modify thermo_temp dynamic yes"
	print "run 1"
	print "variable ke equal ke"
	print "variable chunk loop 100"
	print "label settle"
	print "run 2000"
	printf "if \"${ke} < %.6g\" then \"jump SELF settled\"\n", kestop
	print "next chunk"
	print "jump SELF settle"
	print "label settled"
	printf "dump bed all custom 1 %s id x y z radius\n", dump
	print "run 0"
}' "$packing"
