/* fe-bench.c - time per element-cycle of the explicit finite element loop
 * (lib/fe/explicit.h): issue 4, item 6.  See README.md.
 *
 *   fe-bench [-n NX,NY,NZ] [-s STEPS] [-r REPS] [-w WARMUP] [-t THREADS,...]
 *            [-c CONFIG,...]
 *
 * The block: NX x NY x NZ elements (default 50 x 50 x 40 = 100 000) of
 * 0.1 mm, the aluminium of Ch. 7.5 (E 68 GPa, nu 0.33 assumed, 2700
 * kg/m^3; plastic: yield 157 MPa, hardening 120 MPa).  Motion: homogeneous
 * isochoric compression at 10^4 /s (top face driven, bottom on rollers,
 * every node starting on the field), so every element yields after about
 * 15 steps and keeps flowing: the plastic runs time the return mapping in
 * every element, the elastic runs the elastic path.  A configuration is
 * rule (1pt: one point + hourglass, full: 2x2x2 B-bar), strain (small,
 * large), material (elastic, plastic); each is run on each thread count:
 * WARMUP untimed steps, then REPS timings of STEPS steps each, and the
 * median of the REPS times per element-cycle is reported (also the
 * fastest and slowest, to judge the noise), and the median process CPU
 * time per element-cycle (all threads, spinning at barriers included:
 * with one thread, the cost free of what other processes on the machine
 * take from the wall clock).  Writes one TSV row per
 * configuration and thread count on stdout.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fe/material.h"
#include "fe-block.h"

static void die(const char *msg)
{
	fprintf(stderr, "fe-bench: %s\n", msg);
	exit(1);
}

int main(int argc, char **argv)
{
	int n[3] = { 50, 50, 40 }, steps = 20, reps = 5, warm = 20;
	int thr[8] = { 1, 2 }, nthr = 2;
	const char *only = NULL;
	int c;
	while ((c = getopt(argc, argv, "n:s:r:w:t:c:h")) != -1) {
		switch (c) {
		case 'n':
			if (sscanf(optarg, "%d,%d,%d", &n[0], &n[1], &n[2]) != 3 || n[0] < 1 || n[1] < 1 || n[2] < 1)
				die("-n wants NX,NY,NZ");
			break;
		case 's':
			steps = atoi(optarg);
			break;
		case 'r':
			reps = atoi(optarg);
			break;
		case 'w':
			warm = atoi(optarg);
			break;
		case 't': {
			char *s = optarg;
			nthr = 0;
			while (*s && nthr < 8) {
				thr[nthr++] = (int)strtol(s, &s, 10);
				if (*s == ',')
					s++;
			}
			break;
		}
		case 'c':
			only = optarg;
			break;
		default:
			fprintf(stderr, "usage: fe-bench [-n NX,NY,NZ] [-s STEPS] [-r REPS] [-w WARMUP] "
				"[-t THREADS,...] [-c CONFIG,...]\n");
			return c == 'h' ? 0 : 2;
		}
	}
	if (steps < 1 || reps < 1 || warm < 0 || reps > 99)
		die("bad -s, -r or -w");

	dem_mesh_t m;
	double len[3];
	dem_error_t e = { 0 };
	if (fe_block_mesh(n, &m, len, &e))
		die(e.msg);

	dem_mat_param_t pe = { .E = 68e9, .nu = 0.33, .rho = 2700 }, pp = pe;
	pp.sy0 = 157e6;
	pp.H = 120e6;
	dem_mat_t mat[2];
	if (dem_mat_init(&mat[0], &pe, &e) || dem_mat_init(&mat[1], &pp, &e))
		die(e.msg);

	static const char *rname[2] = { "1pt", "full" }, *sname[2] = { "small", "large" },
			  *mname[2] = { "elastic", "plastic" };
	printf("config\trule\tstrain\tmaterial\tthreads\tne\tsteps\treps\tns_median\tns_min\tns_max"
	       "\tcpu_ns_median\tplastic_frac\telem_share\n");
	for (int rule = 0; rule < 2; rule++)
		for (int large = 0; large < 2; large++)
			for (int pl = 0; pl < 2; pl++) {
				char name[64];
				snprintf(name, sizeof name, "%s-%s-%s", rname[rule], sname[large], mname[pl]);
				if (only && !strstr(only, name))
					continue;
				for (int ti = 0; ti < nthr; ti++) {
					dem_fe_opts_t o;
					dem_fe_opts_default(&o);
					o.rule = rule ? DEM_FE_FULL : DEM_FE_1PT;
					o.large = large;
					o.threads = thr[ti];
					dem_fe_t *fe;
					if (dem_fe_create(&fe, &m, &mat[pl], &o, &e))
						die(e.msg);
					fe_block_motion(fe, &m, len);
					fe_block_time_t r;
					if (fe_block_time(fe, m.ne, rule ? 8 : 1, warm, steps, reps, &r, &e))
						die(e.msg);
					printf("%s\t%s\t%s\t%s\t%d\t%zu\t%d\t%d\t%.1f\t%.1f\t%.1f\t%.1f\t%.3f\t%.3f\n", name,
					       rname[rule], sname[large], mname[pl], thr[ti], m.ne, steps, reps, r.med,
					       r.min, r.max, r.cpu, r.plastic, r.elem_share);
					fflush(stdout);
					dem_fe_free(fe);
				}
			}
	dem_mat_free(&mat[0]);
	dem_mat_free(&mat[1]);
	dem_mesh_free(&m);
	return 0;
}
