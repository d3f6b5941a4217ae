/* test_fe_mesh.c - unit tests of lib/fe/mesh.c (graded axes, box meshes,
 * face constraints) and lib/fe/fescene.c (the material section).
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
#include <unistd.h>

#include "fe/fescene.h"
#include "fe/hex8.h"
#include "mesh/mesh.h"

/* A uniform axis: fine region = whole box. */
static void test_axis_uniform(void **state)
{
	dem_axis_t a = {0, 1, 0, 1, 0.1, 1.3, 0};
	dem_error_t e = {0};
	double *g;
	int n, i;

	(void)state;
	assert_int_equal(dem_axis_grid(&a, &g, &n, &e), DEM_OK);
	assert_int_equal(n, 10);
	for (i = 0; i <= n; i++)
		assert_true(fabs(g[i] - 0.1 * i) < 1e-15);
	free(g);
}

/* The Ch. 7.5 block axis: 8 mm, fine 5.6 mm centred, 0.05 mm elements,
 * ratio 1.2 outside: the fine spacing is exact, the sides grow by the ratio
 * (after the common scale), and the ends are exact. */
static void test_axis_graded(void **state)
{
	dem_axis_t a = {-4e-3, 4e-3, -2.8e-3, 2.8e-3, 5e-5, 1.2, 0};
	dem_error_t e = {0};
	double *g;
	int n, i, nf = 0;

	(void)state;
	assert_int_equal(dem_axis_grid(&a, &g, &n, &e), DEM_OK);
	assert_true(g[0] == -4e-3 && g[n] == 4e-3);
	for (i = 0; i < n; i++) {
		double h = g[i + 1] - g[i];

		assert_true(h > 0);
		if (g[i] >= -2.8e-3 - 1e-12 && g[i + 1] <= 2.8e-3 + 1e-12) {
			assert_true(fabs(h - 5e-5) < 1e-12);
			nf++;
		}
	}
	assert_int_equal(nf, 112);
	/* symmetric, and growing by 1.2 outward on the upper side */
	for (i = 0; i <= n; i++)
		assert_true(fabs(g[i] + g[n - i]) < 1e-15);
	for (i = 0; i + 2 <= n; i++)
		if (g[i] >= 2.8e-3 - 1e-12)
			assert_true(fabs((g[i + 2] - g[i + 1]) / (g[i + 1] - g[i])
					 - 1.2) < 1e-12);
	free(g);
}

/* Grading from a bare point (the plate's layers toward the peened face):
 * the first element is h, then h r, h r^2, ... scaled; a cap is honoured. */
static void test_axis_from_point(void **state)
{
	dem_axis_t a = {-4e-3, 0, 0, 0, 1e-4, 1.5, 1e-3};
	dem_error_t e = {0};
	double *g, hmaxseen = 0;
	int n, i;

	(void)state;
	assert_int_equal(dem_axis_grid(&a, &g, &n, &e), DEM_OK);
	assert_true(g[0] == -4e-3 && g[n] == 0);
	for (i = 0; i < n; i++) {
		double h = g[i + 1] - g[i];

		if (h > hmaxseen)
			hmaxseen = h;
		if (i + 1 < n)  /* thinner toward the top */
			assert_true(g[i + 2] - g[i + 1] <= h * (1 + 1e-12));
	}
	/* the common scale keeps sizes within a factor of sqrt(r) of the spec */
	assert_true(hmaxseen <= 1e-3 * 1.3);
	assert_true(g[n] - g[n - 1] > 1e-4 / 1.3 && g[n] - g[n - 1] < 1e-4 * 1.3);
	free(g);
}

static void test_axis_errors(void **state)
{
	dem_axis_t bad[] = {
		{1, 0, 0, 0, 0.1, 1, 0},        /* empty interval */
		{0, 1, -0.5, 0.5, 0.1, 1, 0},   /* fine region outside */
		{0, 1, 0, 1, 0, 1, 0},          /* zero size */
		{0, 1, 0, 1, 0.1, 0.9, 0},      /* ratio < 1 */
		{0, 1, 0, 1, 0.1, 1.2, 0.05},   /* hmax < h */
		{0, 1, 0, 1, NAN, 1.2, 0},
	};
	dem_error_t e = {0};
	double *g;
	int n;
	size_t i;

	(void)state;
	for (i = 0; i < sizeof bad / sizeof *bad; i++) {
		assert_int_equal(dem_axis_grid(&bad[i], &g, &n, &e), DEM_EINPUT);
		assert_null(g);
		assert_true(strncmp(e.msg, "mesh axis:", 10) == 0);
	}
}

/* Box mesh: counts, numbering, positive volumes summing to the box,
 * constraints by face. */
static void test_mesh_box(void **state)
{
	dem_axis_t ax[3] = {
		{-4e-3, 4e-3, -1e-3, 1e-3, 2.5e-4, 1.3, 0},
		{-4e-3, 4e-3, -1e-3, 1e-3, 2.5e-4, 1.3, 0},
		{-4e-3, 0, -1e-3, 0, 2.5e-4, 1.4, 0},
	};
	dem_bc_t bc[6] = {DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL,
			  DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE};
	dem_mesh_t m;
	dem_error_t e = {0};
	double vol = 0, x[24];
	size_t el, p;
	int i, j, k;

	(void)state;
	assert_int_equal(dem_mesh_box(&m, ax, &e), DEM_OK);
	assert_int_equal(m.nn, (size_t)(m.nx + 1) * (m.ny + 1) * (m.nz + 1));
	assert_int_equal(m.ne, (size_t)m.nx * m.ny * m.nz);
	for (el = 0; el < m.ne; el++) {
		dem_hex8_1pt_t g;

		dem_mesh_gather(&m, el, NULL, x);
		assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
		vol += g.vol;
	}
	assert_true(fabs(vol - 8e-3 * 8e-3 * 4e-3) < 1e-12 * 2.56e-7 * 1e3);
	/* element (i,j,k) spans grid lines i..i+1 etc, node 6 is (+,+,+) */
	el = dem_mesh_elem(&m, 2, 3, 1);
	dem_mesh_gather(&m, el, NULL, x);
	assert_true(x[0] == m.gx[2] && x[8] == m.gy[3] && x[16] == m.gz[1]);
	assert_true(x[6] == m.gx[3] && x[14] == m.gy[4] && x[22] == m.gz[2]);
	/* constraints */
	dem_mesh_set_bc(&m, bc);
	for (k = 0; k <= m.nz; k++)
		for (j = 0; j <= m.ny; j++)
			for (i = 0; i <= m.nx; i++) {
				unsigned want = 0;

				if (k == 0)
					want = 7;
				if (i == 0 || i == m.nx)
					want |= DEM_FIX_X;
				if (j == 0 || j == m.ny)
					want |= DEM_FIX_Y;
				p = dem_mesh_node(&m, i, j, k);
				assert_int_equal(m.fix[p], want);
			}
	/* displaced gather */
	{
		double *u = calloc(3 * m.nn, sizeof *u);

		assert_non_null(u);
		u[3 * m.hex[8 * el + 6] + 2] = 1e-5;
		dem_mesh_gather(&m, el, u, x);
		assert_true(x[22] == m.gz[2] + 1e-5);
		free(u);
	}
	dem_mesh_free(&m);
}

/* Write text to a scene file and load it. */
static dem_scene_t *scene(const char *text)
{
	char path[] = "/tmp/dem-test-mesh-XXXXXX";
	int fd = mkstemp(path);
	dem_scene_t *s = NULL;
	dem_error_t e = {0};
	FILE *f;

	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
	assert_int_equal(dem_scene_load(&s, path, &e), DEM_OK);
	unlink(path);
	return s;
}

static void test_material_scene(void **state)
{
	dem_scene_t *s;
	dem_mat_t m;
	dem_error_t e = {0};

	(void)state;
	/* Table 7.1 as a table */
	s = scene("material:\n  E: 210 GPa\n  nu: 0.3\n  rho: 7800 kg/m^3\n"
		  "  table:\n    strain: [0, 0.0017, 0.0039]\n"
		  "    stress: [349.793 MPa, 605.419 MPa, 645.896 MPa]\n");
	assert_int_equal(dem_scene_material(s, 1, &m, &e), DEM_OK);
	assert_int_equal(m.flags, DEM_MAT_PLASTIC);
	assert_true(fabs(dem_mat_flow_stress(&m, 0.0017, 0) - 605.419e6) < 1e-3);
	assert_true(fabs(m.E - 210e9) < 1);
	dem_mat_free(&m);
	dem_scene_free(s);
	dem_error_clear(&e);
	/* elastic: no yield; no density needed for statics */
	s = scene("material:\n  E: 72 GPa\n  nu: 0.33\n");
	assert_int_equal(dem_scene_material(s, 0, &m, &e), DEM_OK);
	assert_int_equal(m.flags, 0);
	dem_mat_free(&m);
	assert_int_equal(dem_scene_material(s, 1, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "material.rho"));
	dem_scene_free(s);
	dem_error_clear(&e);
	/* rate dependence (Table 7.2, Al 5052) */
	s = scene("material:\n  E: 69.3 GPa\n  nu: 0.31\n  rho: 2680 kg/m^3\n"
		  "  yield: 148 MPa\n  hardening: 194 GPa\n"
		  "  rate: {law: power, m: 0.0455, ref: 1 1/s}\n");
	assert_int_equal(dem_scene_material(s, 1, &m, &e), DEM_OK);
	assert_int_equal(m.flags, DEM_MAT_PLASTIC | DEM_MAT_RATE);
	assert_true(fabs(dem_mat_flow_stress(&m, 0, 1e4) / 148e6
			 - pow(1e4, 0.0455)) < 1e-12);
	dem_mat_free(&m);
	dem_scene_free(s);
	dem_error_clear(&e);
	/* errors: table lengths differ (names the stress key with its line) */
	s = scene("material:\n  E: 210 GPa\n  nu: 0.3\n"
		  "  table:\n    strain: [0, 0.0017]\n    stress: [349.793 MPa]\n");
	assert_int_equal(dem_scene_material(s, 0, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, ":6:"));
	assert_non_null(strstr(e.msg, "one per strain"));
	dem_scene_free(s);
	dem_error_clear(&e);
	s = scene("material:\n  E: 210 GPa\n  nu: 0.3\n  hardening: 1 GPa\n");
	assert_int_equal(dem_scene_material(s, 0, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "without a yield"));
	dem_scene_free(s);
	dem_error_clear(&e);
	s = scene("material:\n  E: 210 GPa\n  nu: 0.7\n");
	assert_int_equal(dem_scene_material(s, 0, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, ":3:"));
	dem_scene_free(s);
	dem_error_clear(&e);
}

/* The hardening laws as a scene names them: each law's keys reach the
 * material (checked through its flow stress against the law's closed
 * form), and a law that is unknown, a key it needs that is missing, a
 * block of another law, or the old rate keys are refused with the
 * position of the fault. */
static void test_material_laws_scene(void **state)
{
	dem_scene_t *s;
	dem_mat_t m;
	dem_error_t e = { 0 };
	(void)state;
	/* Johnson-Cook with its thermal factor, in kelvin, and its rate law */
	s = scene("material:\n  E: 73 GPa\n  nu: 0.33\n  rho: 2780 kg/m^3\n"
		  "  johnson-cook: {A: 369 MPa, B: 684 MPa, n: 0.73, T: 400 K,\n"
		  "                 T_ref: 293 K, T_melt: 775 K, m: 1.7}\n"
		  "  rate: {law: johnson-cook, C: 0.0083, ref: 1 1/s}\n");
	assert_int_equal(dem_scene_material(s, 1, &m, &e), DEM_OK);
	assert_int_equal(m.law, DEM_LAW_JC);
	double th = 1 - pow((400.0 - 293) / (775 - 293), 1.7);
	double want = (369e6 + 684e6 * pow(0.1, 0.73)) * th * (1 + 0.0083 * log(1e3));
	assert_true(fabs(dem_mat_flow_stress(&m, 0.1, 1e3) / want - 1) < 1e-12);
	dem_mat_free(&m);
	dem_scene_free(s);
	/* Voce with two back-stresses and Cowper-Symonds */
	s = scene("material:\n  E: 72 GPa\n  nu: 0.33\n  rho: 2830 kg/m^3\n"
		  "  law: voce\n  yield: 400 MPa\n  hardening: 50 MPa\n"
		  "  voce: {Q: 100 MPa, b: 20}\n"
		  "  kinematic: {C: [40 GPa, 2 GPa], gamma: [400, 10]}\n"
		  "  rate: {law: cowper-symonds, D: 6500 1/s, p: 4}\n");
	assert_int_equal(dem_scene_material(s, 1, &m, &e), DEM_OK);
	assert_int_equal(m.flags, DEM_MAT_PLASTIC | DEM_MAT_RATE | DEM_MAT_KIN | DEM_MAT_GENERAL);
	assert_int_equal(dem_mat_nhist(&m), 12);
	want = (400e6 + 100e6 * (1 - exp(-2.0)) + 50e6 * 0.1) * (1 + pow(1e4 / 6500, 0.25));
	assert_true(fabs(dem_mat_flow_stress(&m, 0.1, 1e4) / want - 1) < 1e-12);
	dem_mat_free(&m);
	dem_scene_free(s);
	/* refusals, each with file:line:col and what was expected */
	static const struct {
		const char *body, *where, *what;
	} bad[] = {
		{ "  law: vocee\n  yield: 1 MPa\n", ":4:8:", "voce" },
		{ "  law: voce\n  yield: 1 MPa\n  voce: {Q: 1 MPa}\n", ":6:", "missing b" },
		{ "  johnson-cook: {A: 1 MPa, B: 1 MPa}\n", ":4:", "missing n" },
		{ "  yield: 1 MPa\n  voce: {Q: 1 MPa, b: 2}\n  law: linear\n", ":5:", "law is linear" },
		{ "  yield: 1 MPa\n  rate: {m: 0.05, ref: 1 1/s}\n", ":5:", "rate law" },
		{ "  yield: 1 MPa\n  rate: {law: power, m: 0.05}\n", ":5:", "missing ref" },
		{ "  yield: 1 MPa\n  rate: {law: wrong}\n", ":5:", "cowper-symonds" },
		{ "  yield: 1 MPa\n  rate_exponent: 0.05\n", ":5:", "rate: {law: power" },
		{ "  yield: 1 MPa\n  kinematic: {C: [1 GPa, 2 GPa], gamma: [1]}\n", ":5:", "one per modulus" },
		{ "  kinematic: {C: [1 GPa], gamma: [1]}\n", ":4:", "need a yield" },
		{ "  johnson-cook: {A: 1 MPa, B: 1 MPa, n: 0.5, T: 300 K}\n", ":4:", "T_ref" },
		{ "  johnson-cook: {A: 1 MPa, B: 1 MPa, n: 0.5, T: 300 m, T_ref: 293 K, T_melt: 800 K, m: 1}\n",
		  ":4:", "temperature" },
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		char text[512];
		snprintf(text, sizeof text, "material:\n  E: 210 GPa\n  nu: 0.3\n%s", bad[i].body);
		s = scene(text);
		dem_error_clear(&e);
		assert_int_equal(dem_scene_material(s, 0, &m, &e), DEM_EINPUT);
		if (!strstr(e.msg, bad[i].where) || !strstr(e.msg, bad[i].what))
			fprintf(stderr, "# case %zu: %s\n", i, e.msg);
		assert_non_null(strstr(e.msg, bad[i].where));
		assert_non_null(strstr(e.msg, bad[i].what));
		dem_mat_free(&m);
		dem_scene_free(s);
	}
}


/* The block section: the Ch. 7.5 block and its default constraints. */
static void test_block_scene(void **state)
{
	dem_scene_t *s;
	dem_mesh_t m;
	dem_error_t e = {0};
	int i, nf = 0;

	(void)state;
	s = scene("block:\n  size: [8 mm, 8 mm, 4 mm]\n  element: 0.25 mm\n"
		  "  fine: [2 mm, 2 mm]\n  fine_depth: 1 mm\n  ratio: 1.3\n");
	assert_int_equal(dem_scene_block(s, &m, &e), DEM_OK);
	assert_true(fabs(m.gx[0] + 4e-3) < 1e-18 && fabs(m.gx[m.nx] - 4e-3) < 1e-18);
	assert_true(m.gz[m.nz] == 0 && fabs(m.gz[0] + 4e-3) < 1e-18);
	for (i = 0; i < m.nx; i++)
		nf += fabs(m.gx[i + 1] - m.gx[i] - 2.5e-4) < 1e-12;
	assert_int_equal(nf, 8);
	/* top layers are fine: 4 elements in the first mm */
	for (i = 0; i < 4; i++)
		assert_true(fabs(m.gz[m.nz - i] - m.gz[m.nz - i - 1] - 2.5e-4) < 1e-12);
	/* bottom fixed, sides normal, top free */
	assert_int_equal(m.fix[dem_mesh_node(&m, 1, 1, 0)], 7);
	assert_int_equal(m.fix[dem_mesh_node(&m, 0, 1, 1)], DEM_FIX_X);
	assert_int_equal(m.fix[dem_mesh_node(&m, 1, m.ny, 1)], DEM_FIX_Y);
	assert_int_equal(m.fix[dem_mesh_node(&m, 1, 1, m.nz)], 0);
	assert_int_equal(m.fix[dem_mesh_node(&m, 0, 0, m.nz)], DEM_FIX_X | DEM_FIX_Y);
	dem_mesh_free(&m);
	dem_scene_free(s);
	/* errors name the key and its place */
	s = scene("block:\n  size: [8 mm, 8 mm, 4 mm]\n  element: 0.25 mm\n"
		  "  fine: [9 mm, 2 mm]\n");
	assert_int_equal(dem_scene_block(s, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, ":4:"));
	assert_non_null(strstr(e.msg, "larger than the block"));
	dem_scene_free(s);
	dem_error_clear(&e);
	s = scene("block:\n  size: [8 mm, 8 mm, 4 mm]\n  element: 0.25 mm\n"
		  "  bc:\n    top: glued\n");
	assert_int_equal(dem_scene_block(s, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "block.bc.top"));
	dem_scene_free(s);
	dem_error_clear(&e);
	s = scene("block:\n  element: 0.25 mm\n");
	assert_int_equal(dem_scene_block(s, &m, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "block.size"));
	dem_scene_free(s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_axis_uniform),
		cmocka_unit_test(test_axis_graded),
		cmocka_unit_test(test_axis_from_point),
		cmocka_unit_test(test_axis_errors),
		cmocka_unit_test(test_mesh_box),
		cmocka_unit_test(test_material_scene),
		cmocka_unit_test(test_material_laws_scene),
		cmocka_unit_test(test_block_scene),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
