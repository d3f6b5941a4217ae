/* test_fe_explicit2d.c - unit tests of lib/fe/explicit2d.c, the 2D explicit
 * engine (issue 18), and of lib/mesh/mesh2.c, its structured mesh.
 *
 * References, per test:
 *  - rigid motion: a uniform velocity field is an exact, stress-free
 *    solution (any rule, small and large strain, both modes);
 *  - patch test in uniaxial strain: a velocity linear in y, prescribed at
 *    the top and given as the initial velocity inside, stays linear; the
 *    stress is uniform, sigma_yy = E_oed eps_yy, E_oed = lambda + 2G,
 *    sigma_xx = sigma_zz = lambda eps_yy (small strain; in large strain the
 *    hypoelastic law gives the same with the logarithmic strain);
 *  - energy: an elastic block set in motion keeps kinetic + internal +
 *    hourglass energy (undamped), and with C = alpha M the damping work is
 *    the loss (the balance of explicit.h stays small);
 *  - wave: a pressure step on a bar in uniaxial strain (plane strain,
 *    rollers) arrives at x at x / c_p, c_p = sqrt((lambda + 2G) / rho),
 *    with the particle velocity p / (rho c_p) behind the front;
 *  - Lame: a thick-walled cylinder (axisymmetric, ends on rollers: plane
 *    strain) under internal pressure p, damped to rest:
 *    u_r = (1 + nu) p a^2 / (E (b^2 - a^2)) ((1 - 2 nu) r + b^2 / r);
 *  - axis: a solid cylinder on the axis under a uniform end pressure p,
 *    damped to rest: sigma_zz = -p, sigma_rr = sigma_tt = 0,
 *    u_r = nu p r / E, u_r = 0 held exactly on the axis;
 *  - 2D impact: a rigid disk dropped on an elastic block through
 *    contact/disk.h (see the test's comment for the closed form).
 * Material: the steel of Ch. 7.4 (E 210 GPa, nu 0.3), elastic, density
 * 7800 kg/m^3 (assumed).
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

#include "contact/disk.h"
#include "contact/law.h"
#include "contact/model.h"
#include "fe/explicit2d.h"
#include "fe/material.h"
#include "mesh/mesh2.h"
#include "slow.h"

#define GPA 1e9
#define MPA 1e6
#define PI 3.14159265358979323846

static void steel(dem_mat_t *m)
{
	dem_mat_param_t p = { .E = 210 * GPA, .nu = 0.3, .rho = 7800 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

/* A uniform nx x ny mesh of [x0, x0 + lx] x [y0, y0 + ly]. */
static void rect(dem_mesh2_t *m, int nx, int ny, double x0, double y0, double lx, double ly)
{
	dem_axis_t ax[2] = { { x0, x0 + lx, x0, x0 + lx, lx / nx, 1, 0 },
			     { y0, y0 + ly, y0, y0 + ly, ly / ny, 1, 0 } };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mesh2_rect(m, ax, &e), DEM_OK);
	assert_int_equal(m->nx, nx);
	assert_int_equal(m->ny, ny);
}

static dem_fe2_t *model(const dem_mesh2_t *m, const dem_mat_t *mat, dem_quad4_mode_t mode,
			dem_fe_rule_t rule, int large, double alpha)
{
	dem_fe2_opts_t o;
	dem_fe2_opts_default(&o);
	o.mode = mode;
	o.rule = rule;
	o.large = large;
	o.damping = alpha;
	dem_fe2_t *fe;
	dem_error_t e = { 0 };
	int rc = dem_fe2_create(&fe, m, mat, &o, &e);
	if (rc)
		printf("# %s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
	return fe;
}

static void step(dem_fe2_t *fe, double dt)
{
	dem_error_t e = { 0 };
	int rc = dem_fe2_step(fe, dt, &e);
	if (rc)
		printf("# %s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
}

static __attribute__((unused)) int all_finite(const double *a, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!isfinite(a[i]))
			return 0;
	return 1;
}

/* ---- Mesh ---------------------------------------------------------------- */

/* The graded axes of mesh.h, the numbering and the edges' constraints. */
static void test_mesh2(void **state)
{
	(void)state;
	dem_axis_t ax[2] = { { -4e-3, 4e-3, -1e-3, 1e-3, 0.25e-3, 1.3, 1e-3 },
			     { 0, 2e-3, 1e-3, 2e-3, 0.25e-3, 1.3, 0 } };
	dem_mesh2_t m;
	dem_error_t e = { 0 };
	assert_int_equal(dem_mesh2_rect(&m, ax, &e), DEM_OK);
	/* the same grid lines as the 3D mesher's axes */
	for (int a = 0; a < 2; a++) {
		double *g;
		int n;
		assert_int_equal(dem_axis_grid(&ax[a], &g, &n, &e), DEM_OK);
		assert_int_equal(n, a ? m.ny : m.nx);
		for (int i = 0; i <= n; i++)
			assert_true(g[i] == (a ? m.gy : m.gx)[i]);
		free(g);
	}
	assert_int_equal(m.nn, (size_t)(m.nx + 1) * (m.ny + 1));
	/* counter-clockwise elements of positive area */
	for (size_t el = 0; el < m.ne; el++) {
		double x[8];
		dem_mesh2_gather(&m, el, NULL, x);
		double A = 0.5 * ((x[2] - x[0]) * (x[7] - x[5]) - (x[3] - x[1]) * (x[6] - x[4]));
		assert_true(A > 0);
	}
	dem_bc_t bc[4] = { DEM_BC_NORMAL, DEM_BC_FREE, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh2_set_bc(&m, bc);
	assert_int_equal(m.fix[dem_mesh2_node(&m, 0, 0)], DEM_FIX_X | DEM_FIX_Y);
	assert_int_equal(m.fix[dem_mesh2_node(&m, 0, 2)], DEM_FIX_X);
	assert_int_equal(m.fix[dem_mesh2_node(&m, m.nx, 0)], DEM_FIX_X | DEM_FIX_Y);
	assert_int_equal(m.fix[dem_mesh2_node(&m, m.nx, m.ny)], 0);
	/* top segments over the fine region, left to right */
	size_t ns = dem_mesh2_top_segments(&m, -1e-3, 1e-3, NULL);
	assert_int_equal(ns, 8);
	uint32_t seg[16];
	dem_mesh2_top_segments(&m, -1e-3, 1e-3, seg);
	for (size_t s = 0; s < ns; s++) {
		assert_true(m.X[2 * seg[2 * s + 1]] > m.X[2 * seg[2 * s]]);
		assert_true(m.X[2 * seg[2 * s] + 1] == 2e-3);
	}
	dem_mesh2_free(&m);
	/* a bad axis is named */
	ax[1].h = 0;
	assert_int_equal(dem_mesh2_rect(&m, ax, &e), DEM_EINPUT);
	assert_true(strncmp(e.msg, "mesh y axis:", 12) == 0);
}

/* ---- 1. Rigid motion and the patch test ------------------------------------ */

/* Shift the interior nodes of a mesh by up to 0.2 of an element (a
 * distorted patch). */
static void distort(dem_mesh2_t *m, double h)
{
	unsigned long s = 12345;
	for (int j = 1; j < m->ny; j++)
		for (int i = 1; i < m->nx; i++) {
			size_t n = dem_mesh2_node(m, i, j);
			for (int c = 0; c < 2; c++) {
				s = s * 6364136223846793005ul + 1442695040888963407ul;
				m->X[2 * n + c] += 0.2 * h * (((s >> 11) * (1.0 / 9007199254740992.0)) * 2 - 1);
			}
		}
}

/* A free distorted block moving at a uniform velocity: no stress, no
 * change of velocity, over 200 steps. */
static void rigid_case(dem_quad4_mode_t mode, dem_fe_rule_t rule, int large)
{
	const double h = 1e-3;
	dem_mesh2_t m;
	dem_mat_t mat;
	steel(&mat);
	rect(&m, 6, 4, mode == DEM_QUAD4_AXISYM ? 0 : -3e-3, 0, 6 * h, 4 * h);
	distort(&m, h);
	dem_fe2_t *fe = model(&m, &mat, mode, rule, large, 0);
	double *v = dem_fe2_velocity(fe);
	/* axisymmetric: only an axial translation is rigid */
	double v0[2] = { mode == DEM_QUAD4_AXISYM ? 0 : 3.0, -7.0 };
	for (size_t n = 0; n < m.nn; n++)
		v[2 * n] = v0[0], v[2 * n + 1] = v0[1];
	for (int it = 0; it < 200; it++)
		step(fe, 0);
	double *sig = malloc(6 * m.ne * sizeof *sig), smax = 0, dv = 0;
	dem_fe2_fields(fe, sig, NULL, NULL);
	for (size_t i = 0; i < 6 * m.ne; i++)
		smax = fmax(smax, fabs(sig[i]));
	for (size_t n = 0; n < m.nn; n++)
		for (int c = 0; c < 2; c++)
			dv = fmax(dv, fabs(v[2 * n + c] - v0[c]));
	/* the scale: the stress of a strain of one rounding error of the motion */
	double ref = mat.E * 1e-15 * 7 * dem_fe2_time(fe) / h;
	printf("# rigid mode %d rule %d large %d: max |sig| %.3g Pa (scale %.3g), max |dv| %.3g m/s\n",
	       mode, rule, large, smax, ref, dv);
	assert_true(smax <= 100 * ref);
	assert_true(dv <= 1e-12);
	free(sig);
	dem_fe2_free(fe);
	dem_mesh2_free(&m);
	dem_mat_free(&mat);
}

static void test_rigid(void **state)
{
	(void)state;
	for (int mode = 0; mode < 2; mode++)
		for (int rule = 0; rule < 2; rule++)
			for (int large = 0; large < 2; large++)
				rigid_case((dem_quad4_mode_t)mode, (dem_fe_rule_t)rule, large);
}

/* Uniaxial strain along y: the sides on rollers (in axisymmetry every
 * node held radially), the bottom on rollers, the top driven down at
 * v0, every node starting at the linear velocity -v0 Y / H.  The forces
 * of the uniform stress cancel at every free node, so every node keeps
 * its velocity (to rounding), and each element has sigma_yy = E_oed
 * eps_yy, sigma_xx = sigma_zz = lambda eps_yy, no shear (to rounding),
 * with eps_yy its strain (dem_fe2_fields).  Small strain: eps_yy = -v0 t
 * / H to rounding.  Large strain: the integrated rate, the logarithmic
 * strain ln(1 - v0 t / H) to the first-order error of the one-sided rate
 * (the rate of each step is taken on the shape at its end: 1e-3). */
static void patch_case(dem_quad4_mode_t mode, dem_fe_rule_t rule, int large)
{
	const double h = 1e-3, H = 6 * h, v0 = 5.0;
	dem_mesh2_t m;
	dem_mat_t mat;
	steel(&mat);
	int axi = mode == DEM_QUAD4_AXISYM;
	rect(&m, 4, 6, axi ? 0 : -2e-3, 0, 4 * h, H);
	dem_bc_t bc[4] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FREE };
	dem_mesh2_set_bc(&m, bc);
	if (axi) {
		/* no radial motion anywhere: uniaxial strain along the axis */
		for (size_t n = 0; n < m.nn; n++)
			m.fix[n] |= DEM_FIX_X;
	} else {
		distort(&m, h);
	}
	for (int i = 0; i <= m.nx; i++)
		m.fix[dem_mesh2_node(&m, i, m.ny)] |= DEM_FIX_Y;
	dem_fe2_t *fe = model(&m, &mat, mode, rule, large, 0);
	double *v = dem_fe2_velocity(fe);
	for (size_t n = 0; n < m.nn; n++)
		v[2 * n + 1] = -v0 * m.X[2 * n + 1] / H;
	for (int it = 0; it < 300; it++)
		step(fe, 0);
	double t = dem_fe2_time(fe);
	double eyy = large ? log(1 - v0 * t / H) : -v0 * t / H;
	double *sig = malloc(6 * m.ne * sizeof *sig), *eps = malloc(6 * m.ne * sizeof *eps);
	dem_fe2_fields(fe, sig, eps, NULL);
	double Eoed = mat.lam + 2 * mat.G, err = 0, eerr = 0, verr = 0;
	for (size_t el = 0; el < m.ne; el++) {
		const double *s = sig + 6 * el;
		double ey = eps[6 * el + 1];
		double want[6] = { mat.lam * ey, Eoed * ey, mat.lam * ey, 0, 0, 0 };
		for (int k = 0; k < 6; k++)
			err = fmax(err, fabs(s[k] - want[k]));
		eerr = fmax(eerr, fabs(ey - eyy));
	}
	for (size_t n = 0; n < m.nn; n++)
		verr = fmax(verr, fabs(v[2 * n + 1] + v0 * m.X[2 * n + 1] / H));
	printf("# patch mode %d rule %d large %d: eps_yy %.6g, sigma_yy %.6g MPa, stress error "
	       "%.3g Pa, strain error %.3g, velocity error %.3g m/s\n", mode, rule, large, eyy,
	       sig[1] * 1e-6, err, eerr, verr);
	assert_true(err <= 1e-9 * Eoed * fabs(eyy));
	assert_true(eerr <= (large ? 1e-3 : 1e-9) * fabs(eyy));
	assert_true(verr <= 1e-9 * v0);
	free(sig), free(eps);
	dem_fe2_free(fe);
	dem_mesh2_free(&m);
	dem_mat_free(&mat);
}

static void test_patch(void **state)
{
	(void)state;
	for (int mode = 0; mode < 2; mode++)
		for (int rule = 0; rule < 2; rule++)
			for (int large = 0; large < 2; large++)
				patch_case((dem_quad4_mode_t)mode, (dem_fe_rule_t)rule, large);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_mesh2),
		cmocka_unit_test(test_rigid),
		cmocka_unit_test(test_patch),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
