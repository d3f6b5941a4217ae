/* test_fe_periodic.c - unit tests of the periodic side ties of lib/fe
 * (mesh.c dem_mesh_set_periodic, explicit.c; issue 23).
 *
 * References, per test:
 *  - the ties: counted and checked node by node against the rule of
 *    mesh.h (xmax to xmin, ymax to ymin, the corner line to (0, 0), no
 *    master a slave);
 *  - translation: a block with periodic sides on a uniform mesh is
 *    invariant under a shift by whole elements, wrapped around the period.
 *    The same pressure pulse on a patch inside the block, and on the patch
 *    shifted across the (xmax, ymax) corner so that it straddles both tied
 *    pairs, must give the same displacements at the shifted nodes (up to
 *    the order of floating-point sums).  With roller sides instead the
 *    shifted patch sits at a wall and gives a different field: the test
 *    checks that too, so it can tell ties from no ties;
 *  - the tied nodes: every slave has its master's velocity and its
 *    position plus the period, exactly, after every step;
 *  - energy: the balance of explicit.h stays within 1 % of its largest
 *    term (a slave's mass counted twice, or its reaction, would break it).
 * Material: the aluminium of Ch. 7.5 (E 68 GPa, yield 157 MPa, linear
 * hardening 120 MPa; nu 0.33 and density 2700 kg/m^3 assumed), large
 * strain, a pulse strong enough to yield.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe/explicit.h"
#include "fe/material.h"
#include "mesh/mesh.h"

#define NX 8
#define NY 8
#define NZ 4
#define HE 0.25e-3   /* element side */
#define SHIFT 5     /* elements, along x and y: the patch 2..3 goes to 7..0 */

static void alu(dem_mat_t *m)
{
	dem_mat_param_t p = { .E = 68e9, .nu = 0.33, .rho = 2700, .sy0 = 157e6, .H = 120e6 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

static void box(dem_mesh_t *m, int periodic)
{
	double len[3] = { NX * HE, NY * HE, NZ * HE };
	dem_axis_t ax[3];
	dem_error_t e = { 0 };
	for (int a = 0; a < 3; a++)
		ax[a] = (dem_axis_t){ 0, len[a], 0, len[a], HE, 1, 0 };
	assert_int_equal(dem_mesh_box(m, ax, &e), DEM_OK);
	dem_bc_t s = periodic ? DEM_BC_PERIODIC : DEM_BC_NORMAL;
	dem_bc_t bc[6] = { s, s, s, s, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh_set_bc(m, bc);
	assert_int_equal(dem_mesh_set_periodic(m, periodic, periodic, &e), DEM_OK);
}

static void test_ties(void **state)
{
	(void)state;
	dem_mesh_t m;
	box(&m, 1);
	/* per layer: ny + 1 nodes on xmax, nx on ymax less the corner */
	assert_int_equal(m.ntie, (size_t)(NZ + 1) * ((NY + 1) + NX));
	char *slave = calloc(m.nn, 1);
	for (size_t t = 0; t < m.ntie; t++)
		slave[m.tie[2 * t]] = 1;
	for (size_t t = 0; t < m.ntie; t++) {
		size_t s = m.tie[2 * t], ms = m.tie[2 * t + 1];
		int i = (int)(s % (NX + 1)), j = (int)(s / (NX + 1) % (NY + 1)), k = (int)(s / ((NX + 1) * (NY + 1)));
		assert_true(i == NX || j == NY);
		assert_int_equal(ms, dem_mesh_node(&m, i == NX ? 0 : i, j == NY ? 0 : j, k));
		assert_false(slave[ms]);
		/* the side faces constrain nothing */
		assert_int_equal(m.fix[s], k == 0 ? DEM_FIX_X | DEM_FIX_Y | DEM_FIX_Z : 0);
	}
	free(slave);
	dem_error_t e = { 0 };
	assert_int_equal(dem_mesh_set_periodic(&m, 0, 0, &e), DEM_OK);
	assert_int_equal(m.ntie, 0);
	assert_int_equal(dem_mesh_set_periodic(&m, 1, 0, &e), DEM_OK);
	assert_int_equal(m.ntie, (size_t)(NZ + 1) * (NY + 1));
	dem_mesh_free(&m);
}

/* Displacements after a pressure pulse (400 MPa for 1 us, then off, to
 * 4 us) on the top faces i in {i0, i0 + 1} mod NX, j likewise; checks the
 * ties and the energy balance on the way.  u: 3 per node. */
static void pulse(int periodic, int i0, int j0, double *u)
{
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat);
	box(&m, periodic);
	dem_fe_opts_t o;
	dem_fe_opts_default(&o);
	o.large = 1;
	o.threads = 1;
	dem_fe_t *fe;
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_create(&fe, &m, &mat, &o, &e), DEM_OK);
	uint32_t q[16];
	int n = 0;
	for (int a = 0; a < 2; a++)
		for (int b = 0; b < 2; b++) {
			int i = (i0 + a) % NX, j = (j0 + b) % NY;
			q[n++] = (uint32_t)dem_mesh_node(&m, i, j, NZ);
			q[n++] = (uint32_t)dem_mesh_node(&m, i + 1, j, NZ);
			q[n++] = (uint32_t)dem_mesh_node(&m, i + 1, j + 1, NZ);
			q[n++] = (uint32_t)dem_mesh_node(&m, i, j + 1, NZ);
		}
	double th[3] = { 0, 1e-6, 1e-6 }, ph[3] = { 400e6, 400e6, 0 };
	assert_int_equal(dem_fe_add_pressure(fe, 4, q, 3, th, ph, &e), DEM_OK);
	double bal = 0;
	while (dem_fe_time(fe) < 4e-6) {
		assert_int_equal(dem_fe_step(fe, 0, &e), DEM_OK);
		const double *x = dem_fe_coords(fe), *v = dem_fe_velocity(fe);
		for (size_t t = 0; t < m.ntie; t++) {
			size_t s = m.tie[2 * t], ms = m.tie[2 * t + 1];
			for (int c = 0; c < 3; c++) {
				assert_true(v[3 * s + c] == v[3 * ms + c]);
				assert_true(x[3 * s + c] == x[3 * ms + c] + (m.X[3 * s + c] - m.X[3 * ms + c]));
			}
		}
		dem_fe_energy_t en;
		dem_fe_energy(fe, &en);
		if (en.scale > 0)
			bal = fmax(bal, fabs(en.balance) / en.scale);
	}
	assert_true(bal <= 0.01);
	dem_fe_displacements(fe, u);
	dem_fe_free(fe);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

/* The largest difference between u of the patch at (2, 2) and u' of the
 * patch shifted by SHIFT, node (i, j, k) against ((i + SHIFT) mod N, ...),
 * over the largest |u|. */
static double shifted_diff(int periodic)
{
	size_t nn = (size_t)(NX + 1) * (NY + 1) * (NZ + 1);
	double *ua = malloc(3 * nn * sizeof *ua), *ub = malloc(3 * nn * sizeof *ub);
	pulse(periodic, 2, 2, ua);
	pulse(periodic, 2 + SHIFT, 2 + SHIFT, ub);
	double d = 0, umax = 0;
	for (int k = 0; k <= NZ; k++)
		for (int j = 0; j < NY; j++)
			for (int i = 0; i < NX; i++) {
				size_t a = (size_t)i + (NX + 1) * ((size_t)j + (NY + 1) * (size_t)k);
				size_t b = (size_t)((i + SHIFT) % NX) +
					   (NX + 1) * ((size_t)((j + SHIFT) % NY) + (NY + 1) * (size_t)k);
				for (int c = 0; c < 3; c++) {
					d = fmax(d, fabs(ua[3 * a + c] - ub[3 * b + c]));
					umax = fmax(umax, fabs(ua[3 * a + c]));
				}
			}
	free(ua);
	free(ub);
	printf("# periodic %d: largest |u| %.4g um, shifted difference %.3g of it\n", periodic,
	       umax * 1e6, d / umax);
	assert_true(umax > 1e-7);
	return d / umax;
}

static void test_translation(void **state)
{
	(void)state;
	assert_true(shifted_diff(1) <= 1e-9);
	/* roller sides: the shifted patch at the corner walls is another problem */
	assert_true(shifted_diff(0) >= 1e-2);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_ties),
		cmocka_unit_test(test_translation),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
