/* law-bench.c - time per element-cycle of the explicit element loop for
 * each hardening and rate law of lib/fe/material.c (issue 16: the cost of
 * each law).  See README.md.
 *
 *   law-bench [-n NX,NY,NZ] [-s STEPS] [-r REPS] [-w WARMUP] [-t THREADS]
 *             [-c CONFIG,...]
 *
 * The block, its motion and the timing loop are examples/cost/fe-block.h's,
 * shared with fe-bench.c: NX x NY x NZ elements (default 40 x 40 x 25 =
 * 40 000) of 0.1 mm, homogeneous
 * isochoric compression at 10^4 /s, so that every element yields after a
 * few steps and keeps flowing: each plastic law is timed where its return
 * runs in every element at every step (the worst case; in a peening run a
 * few per cent of the elements flow at a time).  The elastic constants are
 * those of Al 7050 (Ch. 8.6: E 72 GPa; nu 0.33, rho 2830 kg/m^3); the
 * parameters of each law are shapes for timing, not material data.
 * For each law, one-point (hourglass) and full (2x2x2 B-bar) integration,
 * large strain: WARMUP untimed steps, then REPS timings of STEPS steps;
 * one TSV row per configuration with the median, fastest and slowest ns per
 * element-cycle, the median CPU ns, and the share of plastic points.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fe/material.h"
#include "fe-block.h"     /* examples/cost: the block and the timing loop */

static void die(const char *msg)
{
	fprintf(stderr, "law-bench: %s\n", msg);
	exit(1);
}

/* Table 7.1 of the thesis (flow stress in MPa against ep) */
static const double T71_EP[8] = { 0.0, 0.0017, 0.0039, 0.0079, 0.0153, 0.0288, 0.0533, 0.0975 };
static const double T71_SY[8] = { 349.793, 605.419, 645.896, 689.08, 735.152, 784.303, 836.741, 892.684 };

struct law {
	const char *name;
	dem_mat_param_t p;
};

int main(int argc, char **argv)
{
	int n[3] = { 40, 40, 25 }, steps = 20, reps = 5, warm = 20, thr = 1;
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
		case 't':
			thr = atoi(optarg);
			break;
		case 'c':
			only = optarg;
			break;
		default:
			fprintf(stderr, "usage: law-bench [-n NX,NY,NZ] [-s STEPS] [-r REPS] [-w WARMUP] "
				"[-t THREADS] [-c CONFIG,...]\n");
			return c == 'h' ? 0 : 2;
		}
	}
	if (steps < 1 || reps < 1 || warm < 0 || reps > 99 || thr < 1)
		die("bad -s, -r, -w or -t");

	static double sy71[8];
	for (int i = 0; i < 8; i++)
		sy71[i] = T71_SY[i] * 1e6;
	const dem_mat_param_t el = { .E = 72e9, .nu = 0.33, .rho = 2830 };
	struct law laws[12];
	int nl = 0;
	for (int i = 0; i < 12; i++)
		laws[i].p = el;
	laws[nl++].name = "elastic";
	laws[nl].name = "linear";
	laws[nl].p.sy0 = 450e6, laws[nl++].p.H = 120e6;
	laws[nl].name = "table";
	laws[nl].p.nhard = 8, laws[nl].p.hard_ep = T71_EP, laws[nl++].p.hard_sy = sy71;
	laws[nl].name = "linear+power";
	laws[nl].p.sy0 = 450e6, laws[nl].p.H = 120e6, laws[nl].p.rate_law = DEM_RATE_POWER;
	laws[nl].p.rate_m = 0.0455, laws[nl++].p.rate_ref = 1;
	laws[nl].name = "voce";
	laws[nl].p.law = DEM_LAW_VOCE, laws[nl].p.sy0 = 450e6, laws[nl].p.voce_Q = 100e6;
	laws[nl++].p.voce_b = 20;
	laws[nl].name = "johnson-cook";
	laws[nl].p.law = DEM_LAW_JC, laws[nl].p.jc_A = 450e6, laws[nl].p.jc_B = 300e6;
	laws[nl++].p.jc_n = 0.5;
	laws[nl] = laws[nl - 1];
	laws[nl].name = "johnson-cook+jc-rate";
	laws[nl].p.rate_law = DEM_RATE_JC, laws[nl].p.jc_C = 0.01, laws[nl++].p.rate_ref = 1;
	laws[nl] = laws[nl - 1];
	laws[nl].name = "johnson-cook+cowper-symonds";
	laws[nl].p.rate_law = DEM_RATE_CS, laws[nl].p.cs_D = 6500, laws[nl++].p.cs_p = 4;
	laws[nl].name = "linear+1kin";
	laws[nl].p.sy0 = 450e6, laws[nl].p.nkin = 1, laws[nl].p.kin_C[0] = 20e9;
	laws[nl++].p.kin_gamma[0] = 200;
	laws[nl] = laws[4];
	laws[nl].name = "voce+3kin";
	laws[nl].p.nkin = 3;
	laws[nl].p.kin_C[0] = 50e9, laws[nl].p.kin_gamma[0] = 1000;
	laws[nl].p.kin_C[1] = 10e9, laws[nl].p.kin_gamma[1] = 100;
	laws[nl].p.kin_C[2] = 1e9, laws[nl++].p.kin_gamma[2] = 10;
	laws[nl] = laws[nl - 1];
	laws[nl].name = "voce+3kin+jc-rate";
	laws[nl].p.rate_law = DEM_RATE_JC, laws[nl].p.jc_C = 0.01, laws[nl++].p.rate_ref = 1;

	dem_mesh_t m;
	double len[3];
	dem_error_t e = { 0 };
	if (fe_block_mesh(n, &m, len, &e))
		die(e.msg);

	static const char *rname[2] = { "1pt", "full" };
	printf("law\trule\tthreads\tne\tsteps\treps\tns_median\tns_min\tns_max\tcpu_ns_median\tplastic_frac\n");
	for (int rule = 0; rule < 2; rule++)
		for (int k = 0; k < nl; k++) {
			char name[80];
			snprintf(name, sizeof name, "%s/%s", laws[k].name, rname[rule]);
			if (only && !strstr(only, name))
				continue;
			dem_mat_t mat;
			if (dem_mat_init(&mat, &laws[k].p, &e))
				die(e.msg);
			dem_fe_opts_t o;
			dem_fe_opts_default(&o);
			o.rule = rule ? DEM_FE_FULL : DEM_FE_1PT;
			o.large = 1;
			o.threads = thr;
			dem_fe_t *fe;
			if (dem_fe_create(&fe, &m, &mat, &o, &e))
				die(e.msg);
			fe_block_motion(fe, &m, len);
			fe_block_time_t r;
			if (fe_block_time(fe, m.ne, rule ? 8 : 1, warm, steps, reps, &r, &e))
				die(e.msg);
			printf("%s\t%s\t%d\t%zu\t%d\t%d\t%.1f\t%.1f\t%.1f\t%.1f\t%.3f\n", laws[k].name,
			       rname[rule], thr, m.ne, steps, reps, r.med, r.min, r.max, r.cpu, r.plastic);
			fflush(stdout);
			dem_fe_free(fe);
			dem_mat_free(&mat);
		}
	dem_mesh_free(&m);
	return 0;
}
