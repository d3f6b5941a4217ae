#!/bin/sh
# pass-bench.sh OUT - one pass of the Ch. 8.6 sample model (pass86.yaml) per
# configuration, on 2 threads; a row per run in OUT/pass.tsv from each
# run's cost line.  Configurations: the scene as it is; with friction
# (mu = 0.2); friction written as mu = 0; a deeper fine region (0.5 mm,
# growth 1.3: 333 396 elements).
set -e
out=$1
bin=../../bin
mkdir -p "$out"
"$bin"/dempack shots --grid 4 --passes 1 --area 5.6mm:5.6mm --speed 46.5 \
	--shot-radius 0.7mm --seed 1 > "$out/shots.txt" 2> /dev/null
sed 's/^  alpha: 2$/  alpha: 2\n  friction: 0.2/' pass86.yaml > "$out/friction.yaml"
sed 's/^  alpha: 2$/  alpha: 2\n  friction: 0/' pass86.yaml > "$out/mu0.yaml"
sed -e 's/fine_depth: 0.3 mm/fine_depth: 0.5 mm/' -e 's/ratio: 2.5/ratio: 1.3/' pass86.yaml > "$out/deep.yaml"
printf 'config\telements\tsteps\twall_s\trun_s\telement_loop_s\tnode_loop_s\tcontact_s\tdetect_s\tcontacts\tns_per_elem_cycle\tns_per_contact\tsim_us\tload\n' > "$out/pass.tsv"
for c in frictionless:pass86.yaml friction:"$out/friction.yaml" mu0:"$out/mu0.yaml" deep:"$out/deep.yaml"; do
	name=${c%%:*} scene=${c#*:}
	echo "pass-bench: $name" >&2
	load=$(cut -d' ' -f1 /proc/loadavg)
	"$bin"/demshot -s "$scene" --threads 2 -v -o "$out/$name.state" "$out/shots.txt" 2> "$out/$name.log"
	awk -v name="$name" -v load="$load" '
		/ pass 0 done at t = / { t = $(NF - 1) * 1e6 }
		/: cost: / { for (i = 3; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
		END { printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%.2f\t%s\n", name, v["elements"],
		      v["steps"], v["wall_s"], v["run_s"], v["element_loop_s"], v["node_loop_s"], v["contact_s"],
		      v["detect_s"], v["contacts"], v["ns_per_elem_cycle"], v["ns_per_contact"], t, load }' \
		"$out/$name.log" >> "$out/pass.tsv"
done
