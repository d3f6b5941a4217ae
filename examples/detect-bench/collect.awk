# collect.awk - one row per cost file (OUT/runs/RUN/KEY.EXT.cost, plan.awk):
# the set-up, parsed from the file's path, and the medians of its cost lines
# (demdetect's `key=value` fields), and the checksum of the demdetect that made
# them.  Each cost line is one process (`--repeat`): detect_s is its first,
# cold call, detect_warm_s the median of its later, warm calls; the row has the
# median, min and max over the runs of each.  Usage: awk -f collect.awk FILE...

function median(a, n,    i, j, t)
{
	for (i = 2; i <= n; i++) {      # insertion sort: n is at most a handful
		t = a[i]
		for (j = i - 1; j >= 1 && a[j] > t; j--)
			a[j + 1] = a[j]
		a[j + 1] = t
	}
	return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}

function lo(a, n,    i, x) { x = a[1]; for (i = 2; i <= n; i++) if (a[i] < x) x = a[i]; return x }
function hi(a, n,    i, x) { x = a[1]; for (i = 2; i <= n; i++) if (a[i] > x) x = a[i]; return x }

function flush(    np, p, run, name, ext, algo, cell, nk, k, asp, dlo, dhi, wlo, whi)
{
	if (runs == 0)
		return
	np = split(file, p, "/")
	run = p[np - 1]
	name = p[np]
	sub(/\.cost$/, "", name)
	ext = name ~ /\.bin\.gz$/ ? "bin.gz" : name ~ /\.txt$/ ? "txt" : "bin"
	sub(/\.(bin\.gz|bin|txt)$/, "", name)
	algo = run; cell = "def"
	if (run ~ /-c/) {
		algo = substr(run, 1, index(run, "-c") - 1)
		cell = substr(run, index(run, "-c") + 2)
	}
	nk = split(name, k, "-")
	asp = nk >= 6 ? substr(k[6], 2) : "-"
	dlo = lo(det, runs); dhi = hi(det, runs)
	wlo = lo(warm, runs); whi = hi(warm, runs)
	printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t%.6g\t%.6g\t%.6g\t%.0f\t%.6g\t%.6g\t%s\t%.6g\t%.6g\t%.6g\t%s\n",
	    algo, cell, substr(k[1], 2), substr(k[2], 2), k[3], substr(k[4], 4),
	    substr(k[5], 4), asp, ext, runs, median(det, runs), median(rd, runs),
	    median(rss, runs), pairs, dlo, dhi, binary,
	    median(warm, runs), wlo, whi, repeat
	runs = 0; binary = "-"; repeat = "-"
}

BEGIN {
	print "# algo\tcell\tdim\tn\tlaw\trho\tlam\taspect\tfmt\truns\tdetect_s\tread_s\trss_mb\tpairs\tdetect_min\tdetect_max\tbinary\twarm_s\twarm_min\twarm_max\trepeat"
	repeat = "-"
}

FNR == 1 { flush(); file = FILENAME; binary = "-"; repeat = "-" }

/^# binary / { binary = $3 }

/^# repeat / { repeat = $3 }

/: cost: / {
	runs++
	split("", v)
	for (i = 3; i <= NF; i++) {
		eq = index($i, "=")
		v[substr($i, 1, eq - 1)] = substr($i, eq + 1)
	}
	det[runs] = v["detect_s"] + 0; rd[runs] = v["read_s"] + 0; rss[runs] = v["rss_mb"] + 0
	# a cost file from before --repeat has no warm time: take the cold one
	warm[runs] = ("detect_warm_s" in v) ? v["detect_warm_s"] + 0 : v["detect_s"] + 0
	pairs = v["pairs"]
}

END { flush() }
