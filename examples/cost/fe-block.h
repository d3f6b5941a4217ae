/* fe-block.h - the test block and the timing loop shared by the element
 * loop benchmarks (examples/cost/fe-bench.c, examples/materials/law-bench.c).
 *
 * The block: NX x NY x NZ elements of 0.1 mm, bottom on rollers, top
 * driven in z, sides free; the motion: homogeneous isochoric compression
 * at 10^4 /s with every node starting on the field, so that a plastic
 * material yields after a few steps and keeps flowing.  Static functions
 * in a header: the benchmarks are single files built against lib/libdem.a
 * (also the libdem of an older commit, examples/materials/baseline.sh), so
 * this uses only the library's public API.
 */
#ifndef FE_BLOCK_H
#define FE_BLOCK_H

#include <stdio.h>
#include <stdlib.h>

#include "core/cost.h"
#include "fe/explicit.h"
#include "fe/mesh.h"

#define FE_BLOCK_H_SIZE 1e-4    /* element size (m) */
#define FE_BLOCK_RATE   1e4     /* compression rate (1/s) */

/* The block of n[3] elements; len receives its sides.  Returns 0, or
 * -1 with e set. */
static int fe_block_mesh(const int n[3], dem_mesh_t *m, double len[3], dem_error_t *e)
{
	dem_axis_t ax[3];
	for (int a = 0; a < 3; a++) {
		len[a] = n[a] * FE_BLOCK_H_SIZE;
		double lo = a < 2 ? -len[a] / 2 : -len[a];
		ax[a] = (dem_axis_t){ lo, lo + len[a], lo, lo + len[a], FE_BLOCK_H_SIZE, 1, 0 };
	}
	if (dem_mesh_box(m, ax, e))
		return -1;
	dem_bc_t bc[6] = { DEM_BC_FREE, DEM_BC_FREE, DEM_BC_FREE, DEM_BC_FREE, DEM_BC_NORMAL, DEM_BC_NORMAL };
	dem_mesh_set_bc(m, bc);
	return 0;
}

/* Every node on the isochoric compression field. */
static void fe_block_motion(dem_fe_t *fe, const dem_mesh_t *m, const double len[3])
{
	double *v = dem_fe_velocity(fe);
	for (size_t i = 0; i < m->nn; i++) {
		const double *X = m->X + 3 * i;
		v[3 * i] = 0.5 * FE_BLOCK_RATE * X[0];
		v[3 * i + 1] = 0.5 * FE_BLOCK_RATE * X[1];
		v[3 * i + 2] = -FE_BLOCK_RATE * (X[2] + len[2]);
	}
}

static int fe_block_cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double fe_block_median(const double *t, int n)
{
	return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

/* The timings of a model: warm untimed steps, then reps timings of steps
 * steps.  Fills the median, fastest and slowest wall ns per element-cycle,
 * the median CPU ns, the share of the material points that flowed (npt
 * points per element) and the element loop's share of the step.  Returns 0, or -1 with e set. */
typedef struct fe_block_time {
	double med, min, max, cpu, plastic, elem_share;
} fe_block_time_t;

static int fe_block_time(dem_fe_t *fe, size_t ne, int npt, int warm, int steps, int reps,
			 fe_block_time_t *r, dem_error_t *e)
{
	double t[100], tc[100];
	if (reps > 100)
		reps = 100;
	for (int s = 0; s < warm; s++)
		if (dem_fe_step(fe, 0, e))
			return -1;
	dem_fe_stats_t s0, s1;
	dem_fe_stats(fe, &s0);
	for (int k = 0; k < reps; k++) {
		double w0 = dem_wall(), c0 = dem_cpu();
		for (int s = 0; s < steps; s++)
			if (dem_fe_step(fe, 0, e))
				return -1;
		double ec = (double)steps * (double)ne;
		t[k] = (dem_wall() - w0) / ec * 1e9;
		tc[k] = (dem_cpu() - c0) / ec * 1e9;
	}
	dem_fe_stats(fe, &s1);
	qsort(t, (size_t)reps, sizeof *t, fe_block_cmp);
	qsort(tc, (size_t)reps, sizeof *tc, fe_block_cmp);
	r->med = fe_block_median(t, reps);
	r->min = t[0];
	r->max = t[reps - 1];
	r->cpu = fe_block_median(tc, reps);
	r->plastic = (s1.plastic_updates - s0.plastic_updates) / ((s1.elem_cycles - s0.elem_cycles) * npt);
	double el = s1.elem_s - s0.elem_s;
	r->elem_share = el / (el + (s1.node_s - s0.node_s));
	return 0;
}

#endif
