/* test_shotset2d.c - unit tests of lib/shot/shotset2d.c, the shots of a
 * 2D block (issue 18).
 *
 * References, per test:
 *  - plane drop: a rigid disk (R = 0.25 mm, 0.2 m/s, steel) dropped
 *    through the shot set on an elastic plane-strain block (the mesh of
 *    test_fe_explicit2d.c's test_drop, 10 elements on the contact half
 *    width), the thesis's 2D Hertz law (Eq. 3.45, m = 3/2, law.h's
 *    dem_law_alpha_thesis2d): peak force and contact time within 5 % of
 *    the closed-form impact of that law on a rigid surface,
 *    d = (5 M v^2 / (4 k))^(2/5), F = k d^(3/2), t_c = 2.94327 d / v;
 *    the same with a slab 1 mm thick (forces and masses of the slab: the
 *    force per thickness the same to 1e-9); the block's energy balance
 *    small, the shot's lost kinetic energy the block's external work;
 *  - axisymmetric drop: a rigid sphere on the axis with a soft 3D power
 *    law (1/20 of the classic Hertz stiffness, so the block's own
 *    compliance is a small part of the approach) on an elastic
 *    axisymmetric block: peak force and contact time within 5 % of the
 *    same closed form for that law (M the sphere's), rebound 0.9 v to v;
 *  - refusals: a shot off the axis, two shots in an axisymmetric pass, a
 *    law of the wrong dimension.
 * Material: steel (E 210 GPa, nu 0.3, 7800 kg/m^3), elastic.
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

#include "contact/law.h"
#include "contact/model.h"
#include "fe/explicit2d.h"
#include "fe/material.h"
#include "mesh/mesh2.h"
#include "shot/shotset2d.h"
#include "slow.h"

#define PI 3.14159265358979323846

static void steel(dem_mat_t *m)
{
	dem_mat_param_t p = { .E = 210e9, .nu = 0.3, .rho = 7800 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

typedef struct drop_res {
	double Fmax, t_on, t_off, v_end, ext, ebal, ke0, ke1;
} drop_res_t;

/* Drop one shot (radius R, speed v0, touching at t = 0) on the block m
 * through the shot set with law; F per the slab (PLANE) or whole. */
static void drop(const dem_mesh2_t *m, const dem_mat_t *mat, dem_quad4_mode_t mode, double thick,
		 const dem_law_t *law, double R, double v0, double tmax, drop_res_t *r)
{
	dem_error_t e = { 0 };
	dem_fe2_opts_t fo;
	dem_fe2_opts_default(&fo);
	fo.mode = mode;
	fo.thick = thick;
	dem_fe2_t *fe;
	assert_int_equal(dem_fe2_create(&fe, m, mat, &fo, &e), DEM_OK);
	dem_contact_model_t cm;
	dem_contact_param_t cp = { .law = *law, .partial = DEM_PARTIAL_AREA };
	assert_int_equal(dem_contact_model_init(&cm, &cp, &e), DEM_OK);
	dem_shotset2d_opts_t so = { .mode = mode, .thick = thick, .rho = 7800, .lambda = 0.2, .gap = 0 };
	dem_shotset2d_t *S;
	assert_int_equal(dem_shotset2d_create(&S, m, dem_fe2_mass(fe), &cm, &so, &e), DEM_OK);
	dem_shot_t sh = { .pass = 0, .r = R, .v = { 0, 0, -v0 } };
	assert_int_equal(dem_shotset2d_begin(S, 1, &sh, dem_fe2_coords(fe), &e), DEM_OK);
	dem_fe2_set_load(fe, dem_shotset2d_hook, S);
	memset(r, 0, sizeof *r);
	r->t_on = -1;
	r->ke0 = dem_shotset2d_kinetic(S);
	const dem_shot_body_t *b = dem_shotset2d_body(S, 0);
	while (dem_fe2_time(fe) < tmax) {
		double dt, t = dem_fe2_time(fe);
		assert_int_equal(dem_shotset2d_prepare(S, dem_fe2_coords(fe), dem_fe2_velocity(fe),
						       dem_fe2_dt(fe), &dt, &e), DEM_OK);
		int rc = dem_fe2_step(fe, dt, &e);
		if (rc)
			printf("# %s\n", e.msg);
	memset(&e, 0, sizeof e);
		assert_int_equal(rc, DEM_OK);
		if (b->contacts > 0) {
			if (r->t_on < 0)
				r->t_on = t;
			r->t_off = t + dt;
			r->Fmax = fmax(r->Fmax, b->F[1]);
		}
		if (dem_shotset2d_done(S))
			break;
	}
	assert_true(dem_shotset2d_done(S));
	r->v_end = b->v[1];
	r->ke1 = dem_shotset2d_kinetic(S);
	dem_fe_energy_t en;
	dem_fe2_energy(fe, &en);
	r->ext = en.external;
	r->ebal = en.scale > 0 ? fabs(en.balance) / en.scale : 0;
	dem_shotset2d_free(S);
	dem_fe2_free(fe);
}

/* the impact of F = k d^(3/2) on a rigid surface (Hertz's closed form) */
static void closed(double k, double M, double v0, double *d, double *F, double *tc)
{
	*d = pow(5 * M * v0 * v0 / (4 * k), 0.4);
	*F = k * pow(*d, 1.5);
	*tc = 2.94327 * *d / v0;
}

static void test_plane_drop(void **state)
{
	(void)state;
	const double R = 0.25e-3, v0 = 0.2;
	int nb = SLOW_CASES(10, 4);
	dem_mat_t mat;
	steel(&mat);
	double nu = mat.nu, at = 4 / (3 * (1 - nu * nu));
	dem_law_t law;
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_init_dim(&law, dem_law_alpha_thesis2d(at, 1.5, R), mat.E, 1.5, 2, &e), DEM_OK);
	double k = dem_law_kn(&law, R), M = 7800 * PI * R * R, d, Fc, tc;
	closed(k, M, v0, &d, &Fc, &tc);
	double b = sqrt(2 * R * d), h = b / nb, W = 40 * b, H = 20 * b;
	dem_axis_t ax[2] = { { -W / 2, W / 2, -2 * b, 2 * b, h, 1.25, 0 }, { -H, 0, -2 * b, 0, h, 1.25, 0 } };
	dem_mesh2_t m;
	assert_int_equal(dem_mesh2_rect(&m, ax, &e), DEM_OK);
	dem_bc_t bc[4] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh2_set_bc(&m, bc);
	drop_res_t r1, r2;
	drop(&m, &mat, DEM_QUAD4_PLANE, 1, &law, R, v0, 3 * tc, &r1);
	drop(&m, &mat, DEM_QUAD4_PLANE, 1e-3, &law, R, v0, 3 * tc, &r2);
	double ef = r1.Fmax / Fc - 1, et = (r1.t_off - r1.t_on) / tc - 1;
	printf("# plane drop b/h %d: closed form F %.5g N/m, t_c %.5g us; shot set F %.5g N/m (%+.2f %%), "
	       "t_c %.5g us (%+.2f %%), rebound %.4f v0; block energy balance %.2g, shot's loss / block's "
	       "external work %.6f; slab 1 mm: F/t %.6g N/m\n", nb, Fc, tc * 1e6, r1.Fmax, 100 * ef,
	       (r1.t_off - r1.t_on) * 1e6, 100 * et, r1.v_end / v0, r1.ebal, (r1.ke0 - r1.ke1) / r1.ext,
	       r2.Fmax / 1e-3);
	assert_true(fabs(ef) <= 0.05);
	assert_true(fabs(et) <= 0.05);
	assert_true(r1.v_end > 0.9 * v0 && r1.v_end <= v0);
	assert_true(r1.ebal < 1e-3);
	assert_true(fabs((r1.ke0 - r1.ke1) / r1.ext - 1) < 1e-2);
	assert_true(fabs(r2.Fmax / 1e-3 / r1.Fmax - 1) < 1e-9);
	assert_true(fabs((r2.t_off - r2.t_on) / (r1.t_off - r1.t_on) - 1) < 1e-9);
	dem_mesh2_free(&m);
	dem_mat_free(&mat);
}

static void test_axisym_drop(void **state)
{
	(void)state;
	const double R = 0.25e-3, v0 = 0.2;
	int nb = SLOW_CASES(10, 4);
	dem_mat_t mat;
	steel(&mat);
	dem_law_t law;
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_hertz(&law, mat.E, mat.nu, &e), DEM_OK);
	law.coef /= 20;
	double k = dem_law_kn(&law, R), M = 7800 * 4.0 / 3 * PI * R * R * R, d, Fc, tc;
	closed(k, M, v0, &d, &Fc, &tc);
	double b = sqrt(R * d), h = b / nb, W = 20 * b, H = 20 * b;
	dem_axis_t ax[2] = { { 0, W, 0, 2 * b, h, 1.25, 0 }, { -H, 0, -2 * b, 0, h, 1.25, 0 } };
	dem_mesh2_t m;
	assert_int_equal(dem_mesh2_rect(&m, ax, &e), DEM_OK);
	dem_bc_t bc[4] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh2_set_bc(&m, bc);
	drop_res_t r;
	drop(&m, &mat, DEM_QUAD4_AXISYM, 1, &law, R, v0, 3 * tc, &r);
	double ef = r.Fmax / Fc - 1, et = (r.t_off - r.t_on) / tc - 1;
	printf("# axisym drop b/h %d: closed form F %.5g N, t_c %.5g us; shot set F %.5g N (%+.2f %%), "
	       "t_c %.5g us (%+.2f %%), rebound %.4f v0; block energy balance %.2g, shot's loss / block's "
	       "external work %.6f\n", nb, Fc, tc * 1e6, r.Fmax, 100 * ef, (r.t_off - r.t_on) * 1e6,
	       100 * et, r.v_end / v0, r.ebal, (r.ke0 - r.ke1) / r.ext);
	assert_true(fabs(ef) <= 0.05);
	assert_true(fabs(et) <= 0.05);
	assert_true(r.v_end > 0.9 * v0 && r.v_end <= v0);
	dem_mesh2_free(&m);
	dem_mat_free(&mat);
}

static void test_refused(void **state)
{
	(void)state;
	dem_mat_t mat;
	steel(&mat);
	dem_error_t e = { 0 };
	dem_mesh2_t m;
	dem_axis_t ax[2] = { { 0, 1e-3, 0, 1e-3, 1e-4, 1, 0 }, { -1e-3, 0, -1e-3, 0, 1e-4, 1, 0 } };
	assert_int_equal(dem_mesh2_rect(&m, ax, &e), DEM_OK);
	double *mass = calloc(m.nn, sizeof *mass);
	for (size_t i = 0; i < m.nn; i++)
		mass[i] = 1e-6;
	dem_law_t l2, l3;
	assert_int_equal(dem_law_init_dim(&l2, 1, mat.E, 1.5, 2, &e), DEM_OK);
	assert_int_equal(dem_law_hertz(&l3, mat.E, mat.nu, &e), DEM_OK);
	dem_contact_model_t c2, c3;
	assert_int_equal(dem_contact_model_init(&c2, &(dem_contact_param_t){ .law = l2 }, &e), DEM_OK);
	assert_int_equal(dem_contact_model_init(&c3, &(dem_contact_param_t){ .law = l3 }, &e), DEM_OK);
	dem_shotset2d_opts_t so = { .mode = DEM_QUAD4_AXISYM, .thick = 1, .rho = 7800, .lambda = 0.2 };
	dem_shotset2d_t *S;
	assert_int_equal(dem_shotset2d_create(&S, &m, mass, &c2, &so, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	memset(&e, 0, sizeof e);
	so.mode = DEM_QUAD4_PLANE;
	assert_int_equal(dem_shotset2d_create(&S, &m, mass, &c3, &so, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	memset(&e, 0, sizeof e);
	so.mode = DEM_QUAD4_AXISYM;
	assert_int_equal(dem_shotset2d_create(&S, &m, mass, &c3, &so, &e), DEM_OK);
	dem_shot_t sh[2] = { { .r = 1e-4, .x = { 1e-4, 0 }, .v = { 0, 0, -1 } },
			     { .r = 1e-4, .v = { 0, 0, -1 } } };
	assert_int_equal(dem_shotset2d_begin(S, 1, sh, m.X, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	memset(&e, 0, sizeof e);
	assert_int_equal(dem_shotset2d_begin(S, 2, sh + 1, m.X, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	memset(&e, 0, sizeof e);
	assert_int_equal(dem_shotset2d_begin(S, 1, sh + 1, m.X, &e), DEM_OK);
	dem_shotset2d_free(S);
	free(mass);
	dem_mesh2_free(&m);
	dem_mat_free(&mat);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_plane_drop),
		cmocka_unit_test(test_axisym_drop),
		cmocka_unit_test(test_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
