/* Unit tests of the explicit model's checkpoint (dem_fe_save, dem_fe_load).
 *
 * Reference: the uninterrupted run.  A model saved after n steps and loaded
 * into a fresh model of the same mesh, material and options continues bit
 * for bit as the one that was saved (coordinates, velocities, element
 * fields, energies), for every element rule and strain measure, with
 * plasticity, damping, hourglass control and a pressure load; a checkpoint
 * of another mesh, other options or another material is refused, and so is
 * a truncated or corrupt one.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe/explicit.h"
#include "fe/material.h"
#include "mesh/mesh.h"

static void alu(dem_mat_t *m, double sy0)
{
	dem_mat_param_t p = { .E = 68e9, .nu = 0.33, .rho = 2700, .sy0 = sy0, .H = 120e6 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

static void box(dem_mesh_t *m, int nx, int ny, int nz)
{
	double len[3] = { 1e-3, 1e-3, 0.5e-3 };
	int n[3] = { nx, ny, nz };
	dem_axis_t ax[3];
	for (int a = 0; a < 3; a++)
		ax[a] = (dem_axis_t){ 0, len[a], 0, len[a], len[a] / n[a], 1, 0 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mesh_box(m, ax, &e), DEM_OK);
}

/* A model with a pressure pulse of 1.5 GPa on the middle of the top. */
static dem_fe_t *model(const dem_mesh_t *m, const dem_mat_t *mat, dem_fe_rule_t rule, int large)
{
	static const double t[3] = { 0, 20e-9, 60e-9 }, p[3] = { 0, 1.5e9, 0 };
	dem_fe_opts_t o;
	dem_fe_opts_default(&o);
	o.rule = rule;
	o.large = large;
	o.damping = 1e6;
	dem_fe_t *fe;
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_create(&fe, m, mat, &o, &e), DEM_OK);
	size_t nq = dem_fe_top_quads(m, 0.3e-3, 0.7e-3, 0.3e-3, 0.7e-3, NULL);
	uint32_t *q = malloc(4 * nq * sizeof *q);
	assert_non_null(q);
	dem_fe_top_quads(m, 0.3e-3, 0.7e-3, 0.3e-3, 0.7e-3, q);
	assert_int_equal(dem_fe_add_pressure(fe, nq, q, 3, t, p, &e), DEM_OK);
	free(q);
	return fe;
}

/* n steps, the step varying as in a contact run (cut below the stable one) */
static void steps(dem_fe_t *fe, int k0, int n)
{
	dem_error_t e = { 0 };
	for (int k = k0; k < k0 + n; k++)
		assert_int_equal(dem_fe_step(fe, dem_fe_dt(fe) * (0.6 + 0.4 * (k % 3) / 2.0), &e), DEM_OK);
}

static void snapshot(const dem_fe_t *fe, const dem_mesh_t *m, double *buf)
{
	dem_fe_displacements(fe, buf);
	memcpy(buf + 3 * m->nn, dem_fe_velocity((dem_fe_t *)fe), 3 * m->nn * sizeof *buf);
	dem_fe_fields(fe, buf + 6 * m->nn, buf + 6 * m->nn + 6 * m->ne, buf + 6 * m->nn + 12 * m->ne);
}

/* The combined law: Voce with two back-stresses and a rate law, whose
 * back-stresses are state the checkpoint must carry. */
static void alu_kin(dem_mat_t *m)
{
	dem_mat_param_t p = { .E = 68e9, .nu = 0.33, .rho = 2700, .law = DEM_LAW_VOCE,
			      .sy0 = 157e6, .voce_Q = 60e6, .voce_b = 20, .nkin = 2,
			      .kin_C = { 20e9, 1e9 }, .kin_gamma = { 300, 10 },
			      .rate_law = DEM_RATE_JC, .jc_C = 0.01, .rate_ref = 1 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
	assert_int_equal(dem_mat_nhist(m), 12);
}

static void resume_case(dem_fe_rule_t rule, int large, int kin)
{
	dem_mesh_t m = { 0 };
	dem_mat_t mat = { 0 };
	dem_error_t e = { 0 };
	box(&m, 6, 6, 3);
	if (kin)
		alu_kin(&mat);
	else
		alu(&mat, 157e6);
	size_t n = 6 * m.nn + 13 * m.ne;
	double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
	assert_non_null(a);
	assert_non_null(b);

	dem_fe_t *A = model(&m, &mat, rule, large);
	steps(A, 0, 40);
	FILE *f = tmpfile();
	assert_non_null(f);
	assert_int_equal(dem_fe_save(A, f, &e), DEM_OK);
	steps(A, 40, 60);
	snapshot(A, &m, a);

	dem_fe_t *B = model(&m, &mat, rule, large);
	rewind(f);
	assert_int_equal(dem_fe_load(B, f, &e), DEM_OK);
	assert_int_equal(dem_fe_steps(B), 40);
	steps(B, 40, 60);
	snapshot(B, &m, b);
	assert_int_equal(dem_fe_steps(B), 100);
	assert_true(dem_fe_time(A) == dem_fe_time(B));
	assert_true(dem_fe_dt(A) == dem_fe_dt(B));
	assert_memory_equal(a, b, n * sizeof *a);
	dem_fe_energy_t ea, eb;
	dem_fe_energy(A, &ea);
	dem_fe_energy(B, &eb);
	assert_memory_equal(&ea, &eb, sizeof ea);
	/* the pulse did something: plastic work */
	assert_true(ea.plastic > 0);

	fclose(f);
	dem_fe_free(A);
	dem_fe_free(B);
	free(a);
	free(b);
	dem_mat_free(&mat);
	dem_mesh_free(&m);
}

static void test_resume_1pt_small(void **state)
{
	(void)state;
	resume_case(DEM_FE_1PT, 0, 0);
}

static void test_resume_1pt_large(void **state)
{
	(void)state;
	resume_case(DEM_FE_1PT, 1, 0);
}

static void test_resume_full_small(void **state)
{
	(void)state;
	resume_case(DEM_FE_FULL, 0, 0);
}

static void test_resume_full_large(void **state)
{
	(void)state;
	resume_case(DEM_FE_FULL, 1, 0);
}

/* With back-stresses: the checkpoint carries them (a resumed run that
 * started them from zero would part from the straight one). */
static void test_resume_kin(void **state)
{
	(void)state;
	resume_case(DEM_FE_1PT, 1, 1);
	resume_case(DEM_FE_FULL, 1, 1);
}

/* The checkpoint of model A loaded into B: the error code and message. */
static int load_into(dem_fe_t *A, dem_fe_t *B, long cut, long flip, dem_error_t *e)
{
	FILE *f = tmpfile();
	assert_non_null(f);
	assert_int_equal(dem_fe_save(A, f, e), DEM_OK);
	long size = ftell(f);
	assert_true(size > 0);
	char *buf = malloc((size_t)size);
	assert_non_null(buf);
	rewind(f);
	assert_int_equal(fread(buf, 1, (size_t)size, f), (size_t)size);
	fclose(f);
	if (flip >= 0)
		buf[flip < size ? flip : size - 3] ^= 0x10;   /* past the end: in the CRC */
	if (cut >= size)
		cut = size - 1;
	f = tmpfile();
	assert_non_null(f);
	fwrite(buf, 1, (size_t)(cut >= 0 ? cut : size), f);
	rewind(f);
	free(buf);
	memset(e, 0, sizeof *e);
	int rc = dem_fe_load(B, f, e);
	fclose(f);
	return rc;
}

static void test_refused(void **state)
{
	(void)state;
	dem_mesh_t m = { 0 }, m2 = { 0 }, m3 = { 0 };
	dem_mat_t mat = { 0 }, mat2 = { 0 };
	dem_error_t e = { 0 };
	box(&m, 4, 4, 2);
	box(&m2, 4, 4, 3);
	box(&m3, 4, 4, 2);
	m3.X[0] += 1e-9;          /* same sizes, one node moved */
	alu(&mat, 157e6);
	alu(&mat2, 200e6);
	dem_fe_t *A = model(&m, &mat, DEM_FE_1PT, 1);
	steps(A, 0, 5);

	dem_fe_t *B = model(&m, &mat, DEM_FE_1PT, 1);
	assert_int_equal(load_into(A, B, -1, -1, &e), DEM_OK);
	dem_fe_free(B);

	B = model(&m2, &mat, DEM_FE_1PT, 1);
	assert_int_equal(load_into(A, B, -1, -1, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "of a mesh of 4 x 4 x 2 elements"));
	dem_fe_free(B);

	B = model(&m3, &mat, DEM_FE_1PT, 1);
	assert_int_equal(load_into(A, B, -1, -1, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "another mesh"));
	dem_fe_free(B);

	B = model(&m, &mat, DEM_FE_1PT, 0);
	assert_int_equal(load_into(A, B, -1, -1, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "other run options"));
	dem_fe_free(B);

	B = model(&m, &mat2, DEM_FE_1PT, 1);
	assert_int_equal(load_into(A, B, -1, -1, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "another material"));
	dem_fe_free(B);

	/* truncated anywhere, or one bit flipped in the data or the CRC */
	B = model(&m, &mat, DEM_FE_1PT, 1);
	long cuts[] = { 0, 7, 100, 5000, 1L << 30 };
	for (size_t i = 0; i < sizeof cuts / sizeof *cuts; i++) {
		assert_int_equal(load_into(A, B, cuts[i], -1, &e), DEM_EINPUT);
		assert_non_null(strstr(e.msg, "truncated"));
	}
	long flips[] = { 200, 1000, 3000, 1L << 30 };
	for (size_t i = 0; i < sizeof flips / sizeof *flips; i++) {
		assert_int_equal(load_into(A, B, -1, flips[i], &e), DEM_EINPUT);
		assert_non_null(strstr(e.msg, "corrupt"));
	}
	dem_fe_free(B);
	dem_fe_free(A);
	dem_mat_free(&mat);
	dem_mat_free(&mat2);
	dem_mesh_free(&m);
	dem_mesh_free(&m2);
	dem_mesh_free(&m3);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_resume_1pt_small),
		cmocka_unit_test(test_resume_1pt_large),
		cmocka_unit_test(test_resume_full_small),
		cmocka_unit_test(test_resume_full_large),
		cmocka_unit_test(test_resume_kin),
		cmocka_unit_test(test_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
