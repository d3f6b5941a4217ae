#!/bin/sh
# summary.sh OUT SHOWN DEMFORM SCENE - the demo's closing lines, from the
# files of the run in OUT (SHOWN: how to name OUT to the user):
#   the residual profile of the last pass (saturation table of demprofile),
#   the strip's curvatures and, as a check, the arc height kappa L^2 / 8 of
#   the closed form of a free elastic plate: kappa = 12/h^3 int e z dz, z
#   from the mid-plane, e = -(sxx - nu (syy + szz))/E the in-plane strain
#   the profile's stress leaves when released (DESIGN.md's formula for an
#   equi-biaxial s without szz: e = -(1 - nu) s / E), the profile mapped by
#   depth as demform maps it (linear between points, constant beyond),
#   the wall time of each stage (the cost lines), and last the arc height.
set -eu
out=$1 shown=$2 demform=$3 scene=$4

sat=$out/saturation.txt form=$out/form.txt prof=$out/profile.txt
for f in "$sat" "$form" "$prof"; do
	[ -s "$f" ] || { echo "summary.sh: $f: missing" >&2; exit 1; }
done

# the last pass's row of the saturation table (sxx)
awk '!/^#/ { l = $0 } END {
	if (l == "") { print "summary.sh: empty saturation table" > "/dev/stderr"; exit 1 }
	split(l, v, " ")
	printf "profile (pass %d): sxx %.0f MPa at the surface, peak %.0f MPa at %.2f mm, compressive to %.2f mm; plastic strain %.3f at the surface\n",
		v[1], v[2] / 1e6, v[3] / 1e6, v[4] * 1e3, v[5] * 1e3, v[6] }' "$sat"

# E, nu and the plate from the resolved scene (SI)
set -- $("$demform" -s "$scene" --dump-scene | awk '
	/^[^ ]/ { sec = $1 }
	sec == "material:" && $1 == "E:" { E = $2 } sec == "material:" && $1 == "nu:" { nu = $2 }
	sec == "plate:" && $1 == "size:" { gsub(/[][,]/, ""); L = $2; h = $6 }
	sec == "form:" && /^  pass:/ { pass = $2 }
	END { print E, nu, L, h, pass }')
E=$1 nu=$2 L=$3 h=$4 pass=$5
# form.pass -1 (the default): demform forms with the last pass
[ "$pass" != -1 ] || pass=$(awk '!/^#/ { p = $1 } END { print p }' "$sat")

closed=$(awk -v E="$E" -v nu="$nu" -v L="$L" -v h="$h" -v pass="$pass" '
	!/^#/ && $1 == pass {
		# the profile released in the free plate: its eigenstrain along x
		n++; d[n] = $2; ex[n] = -($3 - nu * ($4 + $5)) / E
	}
	END {
		if (n == 0) { print "summary.sh: pass " pass " not in the profile" > "/dev/stderr"; exit 1 }
		N = 4000; I = 0
		for (k = 0; k < N; k++) {
			dep = (k + 0.5) * h / N
			if (dep <= d[1]) v = ex[1]
			else if (dep >= d[n]) v = ex[n]
			else for (j = 1; j < n; j++) if (dep <= d[j + 1]) { v = ex[j] + (ex[j + 1] - ex[j]) * (dep - d[j]) / (d[j + 1] - d[j]); break }
			I += v * (h / 2 - dep) * h / N
		}
		kappa = 12 * I / h ^ 3
		printf "%.3f mm (curvature %.3f 1/m)", kappa * L * L / 8 * 1e3, kappa
	}' "$prof")

awk -v closed="$closed" '
	{ v[$1] = $2 }
	END {
		printf "strip: curvature %.3f 1/m along, %.3f 1/m across; check, the closed form of a free elastic plate: %s\n",
			v["curvature_x:"], v["curvature_y:"], closed
	}' "$form"

# the stage times, from the cost lines kept in the logs
line=
for p in dempack demshot demprofile demform; do
	t=$(sed -n "s/^$p: cost: wall_s=\([0-9.]*\).*/\1/p" "$out/$p.log" 2>/dev/null | tail -n 1)
	line="$line${line:+, }$p ${t:-?} s"
done
echo "wall time: $line"

awk -v shown="$shown" '
	{ v[$1] = $2 }
	END {
		if (!("arc_height:" in v)) { print "summary.sh: no arc_height in the summary" > "/dev/stderr"; exit 1 }
		printf "arc height: %.3f mm (over the %g mm span); plots: %s/*.png\n",
			v["arc_height:"] * 1e3, v["chord:"] * 1e3, shown
	}' "$form"
