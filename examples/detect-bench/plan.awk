# plan.awk - print the timings the report needs, as cost-file names, one a line:
#
#     OUT/runs/RUN/KEY.EXT.cost
#
# RUN is the algorithm, with "-cF" for cell factor F (dcell-c1.5); KEY names the
# data set, d<dim>-n<N>-<law>-rho<density>-lam<lambda>[-a<aspect>] (data.sh);
# EXT is its format: bin, txt or bin.gz.
#
# Input: tables.tsv.  Variables (-v): out; tables, "all" or the tables to run
# ("2.1 2.3"); n1m n2m n5m, the object counts standing in for the thesis's 1M,
# 2M and 5M (empty: skip those rows); factors, the cell factors of the sweep;
# sweep2 and sweep3, its 2D and 3D cases as density:lambda; io, 1 for the I/O runs.

function key(dim, n, law, rho, lam, asp)
{
	return "d" dim "-n" n "-" law "-rho" rho "-lam" lam (asp == "-" ? "" : "-a" asp)
}

function cost(run, k, ext)
{
	return out "/runs/" run "/" k "." ext ".cost"
}

BEGIN {
	FS = "\t"
	N["1m"] = n1m; N["2m"] = n2m; N["5m"] = n5m
	nt = split(tables, t, " ")
	for (i = 1; i <= nt; i++)
		want[t[i]] = 1
}

/^#/ || NF < 9 { next }

(tables == "all" || ($1 in want)) && N[$2] != "" {
	print cost($8, key($3, N[$2], $4, $5, $6, $7), "bin")
}

END {
	nf = split(factors, f, " ")
	for (d = 2; d <= 3 && n1m != ""; d++) {
		nc = split(d == 2 ? sweep2 : sweep3, c, " ")
		for (i = 1; i <= nc; i++) {
			split(c[i], rl, ":")
			for (j = 1; j <= nf; j++)
				print cost("dcell-c" f[j], key(d, n1m, "urd", rl[1], rl[2], "-"), "bin")
		}
	}
	if (io && n1m != "") {
		# the same 1M disks as text and as gzip-compressed binary, and a
		# tiny set for the process's own memory (the baseline of rss_mb)
		k = key(2, n1m, "urd", "0.6", "1", "-")
		print cost("dcell", k, "bin")
		print cost("dcell", k, "txt")
		print cost("dcell", k, "bin.gz")
		print cost("dcell", key(3, n1m, "urd", "0.6", "1", "-"), "bin")
		print cost("dcell", key(2, 1000, "urd", "0.6", "1", "-"), "bin")
	}
}
