/* contact-bench.c - what each contact effect costs per evaluation of the
 * contact kernel (issue 5, item 5): the kernels of lib/contact/model.h,
 * picked once per scene by the effects it asks for, timed on a stream of
 * sphere/facet contacts with varying overlap, normal and sliding velocity.
 *
 *   contact-bench [-n N] [-r REPS]     a row per configuration (TSV)
 *
 * Configurations: the Hertz-type law (m = 1.5) alone; with friction
 * mu = 0.2; with friction written as mu = 0; with viscous damping
 * (xi = 0.05); with hysteresis; and friction plus damping.  The figure is
 * the median over REPS timings of N kernel calls, in ns per call; the
 * checksum of the forces shows the calls are not optimised away and that
 * friction absent and mu = 0 compute the same forces. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "contact/law.h"
#include "contact/model.h"

static double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

#define NK 1024   /* distinct contacts, cycled */

int main(int argc, char **argv)
{
	long n = 20000000;
	int reps = 7;
	for (int i = 1; i + 1 < argc; i += 2) {
		if (!strcmp(argv[i], "-n"))
			n = atol(argv[i + 1]);
		else if (!strcmp(argv[i], "-r"))
			reps = atoi(argv[i + 1]);
	}
	if (n <= 0 || reps <= 0 || reps > 99) {
		fprintf(stderr, "usage: contact-bench [-n N] [-r REPS]\n");
		return 2;
	}
	/* Ch. 8.6: aluminium E = 72 GPa, shot radius 0.7 mm, alpha 2 */
	const double E = 72e9, R = 0.7e-3;
	static dem_contact_kin_t kin[NK];
	unsigned s = 12345;
	for (int k = 0; k < NK; k++) {
		double u[6];
		for (int j = 0; j < 6; j++) {
			s = s * 1103515245u + 12345u;
			u[j] = (s >> 8) / 16777216.0;
		}
		double th = 0.3 * u[0], ph = 6.283185307179586 * u[1];
		dem_contact_kin_t *c = &kin[k];
		memset(c, 0, sizeof *c);
		c->delta = 1e-6 + 20e-6 * u[2];
		c->gamma = 0.1 + 0.9 * u[3];
		c->n[0] = sin(th) * cos(ph), c->n[1] = sin(th) * sin(ph), c->n[2] = cos(th);
		c->vrel[0] = 20 * (u[4] - 0.5), c->vrel[1] = 20 * (u[5] - 0.5), c->vrel[2] = -30 * u[2];
		c->r[0] = -R * c->n[0], c->r[1] = -R * c->n[1], c->r[2] = -R * c->n[2];
		c->wn = 100 * (u[0] - 0.5);
		c->meff = 1e-6;
		c->dt = 5e-9;
	}
	struct { const char *name; int damping, friction; double mu; } cfg[] = {
		{ "law only", DEM_DAMP_NONE, 0, 0 },
		{ "friction mu 0.2", DEM_DAMP_NONE, 1, 0.2 },
		{ "friction mu 0", DEM_DAMP_NONE, 1, 0 },
		{ "viscous damping", DEM_DAMP_VISCOUS, 0, 0 },
		{ "hysteresis", DEM_DAMP_HYSTERESIS, 0, 0 },
		{ "friction + viscous", DEM_DAMP_VISCOUS, 1, 0.2 },
	};
	printf("config\tns_per_call\tmin\tmax\tchecksum\n");
	for (size_t c = 0; c < sizeof cfg / sizeof *cfg; c++) {
		dem_contact_param_t p;
		memset(&p, 0, sizeof p);
		dem_error_t e = { 0 };
		if (dem_law_init(&p.law, 2, E, 1.5, &e)) {
			fprintf(stderr, "contact-bench: %s\n", e.msg);
			return 1;
		}
		p.damping = cfg[c].damping;
		p.xi = 0.05;
		p.unload = dem_hyst_unload_ratio(0.8, 1.5);
		p.friction = cfg[c].friction;
		p.mu = cfg[c].mu;
		p.partial = DEM_PARTIAL_AREA;
		dem_contact_model_t cm;
		if (dem_contact_model_init(&cm, &p, &e)) {
			fprintf(stderr, "contact-bench: %s\n", e.msg);
			return 1;
		}
		double kn = dem_law_kn(&p.law, R), t[99], sum = 0;
		for (int k = 0; k < NK; k++)
			kin[k].kn = kn;
		static dem_contact_state_t st[NK];
		for (int r = 0; r < reps; r++) {
			for (int k = 0; k < NK; k++)
				dem_contact_state_reset(&st[k]);
			double t0 = now(), acc = 0;
			for (long i = 0; i < n; i++) {
				dem_contact_out_t o;
				int k = (int)(i & (NK - 1));
				cm.kernel(&cm, &kin[k], &st[k], &o);
				acc += o.F[0] + o.F[1] + o.F[2];
			}
			t[r] = (now() - t0) / n * 1e9;
			sum = acc;
		}
		qsort(t, (size_t)reps, sizeof *t, cmp);
		printf("%s\t%.2f\t%.2f\t%.2f\t%.9g\n", cfg[c].name, t[reps / 2], t[0], t[reps - 1], sum);
	}
	return 0;
}
