/* test_fe_explicit.c - unit tests of lib/fe/explicit.c: the explicit
 * dynamics of the finite element block (issue 4, acceptance items 1-5).
 *
 * References, per test:
 *  - patch test (Irons; Belytschko, Liu & Moran, "Nonlinear finite elements
 *    for continua and structures", 2000, Ch. 8.4): a linear velocity field
 *    on a distorted mesh, imposed on the boundary and given as the initial
 *    velocity inside, is an exact solution of the discrete equations: the
 *    strain and stress stay uniform and the interior nodes feel no force;
 *  - 1D wave: a step load on a laterally constrained bar travels at the
 *    dilatational speed c = sqrt(E (1-nu) / ((1+nu)(1-2nu) rho)) with the
 *    particle velocity p / (rho c) behind its front;
 *  - uniaxial stress: the flow stress of Table 7.1 (thesis-data.yaml,
 *    hardening_table_7_1) at every table point, elastic unloading at slope
 *    E, and the rate law sigma = sigma_y(ep) (rate)^m of material.h with
 *    m of Table 7.2;
 *  - energy: conservation without damping; with C = alpha M the mechanical
 *    energy of free vibration decays like exp(-alpha t);
 *  - inverted element: DEM_ENUMERIC naming the element, no NaN left.
 * Materials: the steel of Ch. 7.4 (E 210 GPa, nu 0.3, Table 7.1; the
 * density 7800 kg/m^3 is not given by the thesis) and the aluminium of
 * Ch. 7.5 (E 68 GPa, yield 157 MPa, linear hardening 120 MPa; nu 0.33 and
 * density 2700 kg/m^3 assumed).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe/explicit.h"
#include "fe/hex8.h"
#include "fe/material.h"
#include "fe/mesh.h"

#define GPA 1e9
#define MPA 1e6

/* Table 7.1: effective plastic strain -> flow stress (N/mm^2) */
static const double T71_EP[8] = { 0.0, 0.0017, 0.0039, 0.0079, 0.0153, 0.0288, 0.0533, 0.0975 };
static const double T71_SY[8] = { 349.793, 605.419, 645.896, 689.08, 735.152, 784.303, 836.741, 892.684 };

static double urand(unsigned long *s)
{
	*s = *s * 6364136223846793005ul + 1442695040888963407ul;
	return ((*s >> 11) * (1.0 / 9007199254740992.0)) * 2 - 1;
}

static void steel(dem_mat_t *m, double rate_m)
{
	static double sy[8];
	for (int i = 0; i < 8; i++)
		sy[i] = T71_SY[i] * MPA;
	dem_mat_param_t p = { .E = 210 * GPA, .nu = 0.3, .rho = 7800, .nhard = 8,
			      .hard_ep = T71_EP, .hard_sy = sy, .rate_m = rate_m };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

static void alu(dem_mat_t *m, int plastic)
{
	dem_mat_param_t p = { .E = 68 * GPA, .nu = 0.33, .rho = 2700 };
	if (plastic) {
		p.sy0 = 157 * MPA;
		p.H = 120 * MPA;
	}
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

/* A uniform box mesh [x0, x0 + lx] x [y0, y0 + ly] x [z0, z0 + lz]. */
static void box(dem_mesh_t *m, int nx, int ny, int nz, const double lo[3], const double len[3])
{
	int n[3] = { nx, ny, nz };
	dem_axis_t ax[3];
	for (int a = 0; a < 3; a++)
		ax[a] = (dem_axis_t){ lo[a], lo[a] + len[a], lo[a], lo[a] + len[a], len[a] / n[a], 1, 0 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mesh_box(m, ax, &e), DEM_OK);
	assert_int_equal(m->nx, nx);
	assert_int_equal(m->ny, ny);
	assert_int_equal(m->nz, nz);
}

static dem_fe_t *model(const dem_mesh_t *m, const dem_mat_t *mat, dem_fe_rule_t rule, int large,
		       double damping)
{
	dem_fe_opts_t o;
	dem_fe_opts_default(&o);
	o.rule = rule;
	o.large = large;
	o.damping = damping;
	dem_fe_t *fe;
	dem_error_t e = { 0 };
	int rc = dem_fe_create(&fe, m, mat, &o, &e);
	if (rc)
		fprintf(stderr, "%s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
	return fe;
}

static void step(dem_fe_t *fe, double dt)
{
	dem_error_t e = { 0 };
	int rc = dem_fe_step(fe, dt, &e);
	if (rc)
		fprintf(stderr, "%s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
}

/* The quadrilaterals of one box face (enum dem_face), oriented outward;
 * returns their count (malloc'ed in *q). */
static size_t face_quads(const dem_mesh_t *m, int face, uint32_t **q)
{
	static const int fn[6][4] = { { 0, 3, 7, 4 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 },
				      { 3, 2, 6, 7 }, { 0, 1, 2, 3 }, { 4, 5, 6, 7 } };
	int ax = face / 2, hi = face % 2;
	size_t n = 0;
	*q = malloc(4 * m->ne * sizeof **q);
	assert_non_null(*q);
	for (size_t el = 0; el < m->ne; el++) {
		int ijk[3] = { (int)(el % (size_t)m->nx), (int)(el / (size_t)m->nx % (size_t)m->ny),
			       (int)(el / ((size_t)m->nx * (size_t)m->ny)) };
		int nmax[3] = { m->nx, m->ny, m->nz };
		if (ijk[ax] != (hi ? nmax[ax] - 1 : 0))
			continue;
		uint32_t *p = *q + 4 * n++;
		for (int I = 0; I < 4; I++)
			p[I] = m->hex[8 * el + fn[face][I]];
		const double *X = m->X;
		double d1[3], d2[3];
		for (int c = 0; c < 3; c++) {
			d1[c] = X[3 * p[2] + c] - X[3 * p[0] + c];
			d2[c] = X[3 * p[3] + c] - X[3 * p[1] + c];
		}
		double A[3] = { d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
				d1[0] * d2[1] - d1[1] * d2[0] };
		if ((A[ax] > 0) != hi) {
			uint32_t t = p[1];
			p[1] = p[3];
			p[3] = t;
		}
	}
	return n;
}

__attribute__((unused)) static int all_finite(const double *a, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!isfinite(a[i]))
			return 0;
	return 1;
}

/* ---- 1. Patch test ------------------------------------------------------- */

/* A 4x4x4 mesh with its 27 interior nodes moved at random by up to 0.2 h;
 * the boundary nodes move with the linear velocity field v = A X
 * (prescribed), the interior ones start with it.  For every rule and
 * strain measure: the interior velocities never change (the internal
 * forces at interior nodes cancel) and every element has the same strain
 * and stress; in small strain these equal sym(A) t and D sym(A) t. */
static const double PA[9] = { 1.0e3, 2.0e2, -3.0e2, -1.0e2, -5.0e2, 4.0e2, 6.0e2, 1.5e2, 2.5e2 };

static void patch_case(dem_fe_rule_t rule, int large)
{
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 1e-3, 1e-3, 1e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, 0);
	box(&m, 4, 4, 4, lo, len);
	unsigned long s = 4242;
	double h = 0.25e-3;
	for (int k = 0; k <= 4; k++)
		for (int j = 0; j <= 4; j++)
			for (int i = 0; i <= 4; i++) {
				size_t n = dem_mesh_node(&m, i, j, k);
				int interior = i > 0 && i < 4 && j > 0 && j < 4 && k > 0 && k < 4;
				if (interior)
					for (int c = 0; c < 3; c++)
						m.X[3 * n + c] += 0.2 * h * urand(&s);
				m.fix[n] = interior ? 0 : DEM_FIX_X | DEM_FIX_Y | DEM_FIX_Z;
			}
	dem_fe_t *fe = model(&m, &mat, rule, large, 0);
	double *v = dem_fe_velocity(fe);
	for (size_t n = 0; n < m.nn; n++)
		for (int c = 0; c < 3; c++) {
			const double *X = m.X + 3 * n;
			v[3 * n + c] = PA[3 * c] * X[0] + PA[3 * c + 1] * X[1] + PA[3 * c + 2] * X[2];
		}
	double *v0 = malloc(3 * m.nn * sizeof *v0);
	memcpy(v0, v, 3 * m.nn * sizeof *v0);
	double dt = dem_fe_dt(fe);
	for (int it = 0; it < 20; it++)
		step(fe, dt);
	double dvmax = 0, vmax = 0;
	for (size_t n = 0; n < 3 * m.nn; n++) {
		dvmax = fmax(dvmax, fabs(v[n] - v0[n]));
		vmax = fmax(vmax, fabs(v0[n]));
	}
	/* a force imbalance f at a node would change its velocity by
	 * dt f / m per step; compare with the element force scale */
	double *sig = malloc(6 * m.ne * sizeof *sig), *eps = malloc(6 * m.ne * sizeof *eps);
	dem_fe_fields(fe, sig, eps, NULL);
	double smax = 0, emax = 0, sdev = 0, edev = 0;
	for (size_t el = 0; el < m.ne; el++)
		for (int k = 0; k < 6; k++) {
			smax = fmax(smax, fabs(sig[k]));
			emax = fmax(emax, fabs(eps[k]));
			sdev = fmax(sdev, fabs(sig[6 * el + k] - sig[k]));
			edev = fmax(edev, fabs(eps[6 * el + k] - eps[k]));
		}
	double mnode = mat.rho * h * h * h, fscale = smax * h * h;
	double fimb = dvmax * mnode / dt;
	printf("# patch rule %d large %d: force imbalance %.2e, stress spread %.2e, strain spread %.2e\n",
	       rule, large, fimb / fscale, sdev / smax, edev / emax);
	assert_true(fimb <= 1e-10 * fscale);
	assert_true(dvmax <= 1e-10 * vmax);
	assert_true(sdev <= 1e-10 * smax);
	assert_true(edev <= 1e-10 * emax);
	if (!large) {
		double t = dem_fe_time(fe);
		double ex[6] = { PA[0] * t, PA[4] * t, PA[8] * t, (PA[1] + PA[3]) * t,
				 (PA[5] + PA[7]) * t, (PA[6] + PA[2]) * t };
		double D[36], sx[6];
		dem_mat_elastic_stiffness(&mat, D);
		for (int r = 0; r < 6; r++) {
			sx[r] = 0;
			for (int c = 0; c < 6; c++)
				sx[r] += D[6 * r + c] * ex[c];
		}
		for (size_t el = 0; el < m.ne; el++)
			for (int k = 0; k < 6; k++) {
				assert_true(fabs(eps[6 * el + k] - ex[k]) <= 1e-10 * emax);
				assert_true(fabs(sig[6 * el + k] - sx[k]) <= 1e-10 * smax);
			}
	}
	free(sig), free(eps), free(v0);
	dem_fe_free(fe);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

static void test_patch(void **state)
{
	(void)state;
	patch_case(DEM_FE_1PT, 0);
	patch_case(DEM_FE_1PT, 1);
	patch_case(DEM_FE_FULL, 0);
	patch_case(DEM_FE_FULL, 1);
}


/* ---- 2. Wave in a bar ------------------------------------------------------ */

/* A bar of 100 cubes along x with roller faces at y and z (uniaxial
 * strain), a pressure step p0 on its x = 0 end at t = 0: the front reaches
 * x at t = x / c, c the dilatational speed, with the particle velocity
 * p0 / (rho c) behind it.  The arrival (the half-plateau crossing of the
 * velocity at a node plane, interpolated between the half steps) must be
 * within one element's transit h / c of x / c, at x = L/4 and 3L/4. */
static void bar_case(dem_fe_rule_t rule, int large)
{
	const int nx = 100;
	const double h = 1e-3, p0 = 100 * MPA;
	static const double lo[3] = { 0, 0, 0 };
	double len[3] = { nx * h, h, h };
	dem_mesh_t m;
	dem_mat_t mat;
	steel(&mat, 0);
	mat.flags = 0;   /* elastic */
	box(&m, nx, 1, 1, lo, len);
	dem_bc_t bc[6] = { DEM_BC_FREE, DEM_BC_FREE, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL };
	dem_mesh_set_bc(&m, bc);
	dem_fe_t *fe = model(&m, &mat, rule, large, 0);
	uint32_t *q;
	size_t nq = face_quads(&m, DEM_XMIN, &q);
	assert_int_equal(nq, 1);
	double th[1] = { 0 }, ph[1] = { p0 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_add_pressure(fe, nq, q, 1, th, ph, &e), DEM_OK);
	double c = sqrt(mat.E * (1 - mat.nu) / ((1 + mat.nu) * (1 - 2 * mat.nu) * mat.rho));
	double vstar = p0 / (mat.rho * c);
	int st[2] = { nx / 4, 3 * nx / 4 };
	double tarr[2] = { -1, -1 }, vprev[2] = { 0, 0 }, tprev = 0;
	const double *v;
	while (dem_fe_time(fe) < 0.9 * nx * h / c) {
		step(fe, 0);
		v = dem_fe_velocity(fe);
		double tv = dem_fe_time(fe) - 0.5 * dem_fe_dt(fe);   /* v_{n+1/2} */
		for (int s = 0; s < 2; s++) {
			double vs = 0;
			for (int j = 0; j <= 1; j++)
				for (int k = 0; k <= 1; k++)
					vs += 0.25 * v[3 * dem_mesh_node(&m, st[s], j, k)];
			if (tarr[s] < 0 && vs >= 0.5 * vstar)
				tarr[s] = tprev + (0.5 * vstar - vprev[s]) / (vs - vprev[s]) * (tv - tprev);
			vprev[s] = vs;
		}
		tprev = tv;
	}
	for (int s = 0; s < 2; s++) {
		double x = st[s] * h;
		printf("# bar rule %d large %d: x = %g mm arrival %.4g us, x/c %.4g us, h/c %.3g us\n",
		       rule, large, x * 1e3, tarr[s] * 1e6, x / c * 1e6, h / c * 1e6);
		assert_true(tarr[s] > 0);
		assert_true(fabs(tarr[s] - x / c) <= h / c);
	}
	/* behind the front the velocity rings about p0 / (rho c) (the
	 * discrete step front trails slowly decaying oscillations); its mean
	 * over the first half of the bar is p0 / (rho c) within 2 % */
	v = dem_fe_velocity(fe);
	double vp = 0;
	for (int i = 0; i <= nx / 2; i++)
		vp += v[3 * dem_mesh_node(&m, i, 0, 0)] / (nx / 2 + 1);
	printf("# bar plateau %.5g m/s, p0/(rho c) %.5g m/s\n", vp, vstar);
	assert_true(fabs(vp - vstar) <= 0.02 * vstar);
	free(q);
	dem_fe_free(fe);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

static void test_bar_wave(void **state)
{
	(void)state;
	bar_case(DEM_FE_1PT, 0);
	bar_case(DEM_FE_1PT, 1);
	bar_case(DEM_FE_FULL, 0);
	bar_case(DEM_FE_FULL, 1);
}

/* The load hook: adding the same nodal forces as a pressure load gives the
 * same motion, bit for bit; the hook sees the current coordinates and
 * time. */
typedef struct hook_ctx {
	const uint32_t *q;
	double p, tlast;
	int calls;
} hook_ctx_t;

static int hook(void *ctx, double t, double dt, const double *x, const double *v, double *f,
		dem_error_t *e)
{
	hook_ctx_t *h = ctx;
	(void)v;
	(void)e;
	assert_true(dt > 0);
	assert_true(h->calls == 0 || t > h->tlast);
	h->tlast = t;
	h->calls++;
	const uint32_t *n = h->q;
	double d1[3], d2[3];
	for (int c = 0; c < 3; c++) {
		d1[c] = x[3 * (size_t)n[2] + c] - x[3 * (size_t)n[0] + c];
		d2[c] = x[3 * (size_t)n[3] + c] - x[3 * (size_t)n[1] + c];
	}
	double s = -0.125 * h->p;
	double fq[3] = { s * (d1[1] * d2[2] - d1[2] * d2[1]), s * (d1[2] * d2[0] - d1[0] * d2[2]),
			 s * (d1[0] * d2[1] - d1[1] * d2[0]) };
	for (int I = 0; I < 4; I++)
		for (int c = 0; c < 3; c++)
			f[3 * (size_t)n[I] + c] += fq[c];
	return 0;
}

static int hook_fail(void *ctx, double t, double dt, const double *x, const double *v, double *f,
		     dem_error_t *e)
{
	(void)ctx, (void)t, (void)dt, (void)x, (void)v;
	f[0] = 1;
	return dem_error_set(e, DEM_ENUMERIC, "contact: shot 3 lost");
}

static void test_load_hook(void **state)
{
	(void)state;
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 10e-3, 1e-3, 1e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	steel(&mat, 0);
	box(&m, 10, 1, 1, lo, len);
	dem_fe_t *a = model(&m, &mat, DEM_FE_1PT, 1, 0), *b = model(&m, &mat, DEM_FE_1PT, 1, 0);
	uint32_t *q;
	assert_int_equal(face_quads(&m, DEM_XMIN, &q), 1);
	double th[1] = { 0 }, ph[1] = { 500 * MPA };
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_add_pressure(a, 1, q, 1, th, ph, &e), DEM_OK);
	hook_ctx_t hc = { q, 500 * MPA, 0, 0 };
	dem_fe_set_load(b, hook, &hc);
	for (int it = 0; it < 50; it++) {
		step(a, 0);
		step(b, 0);
	}
	assert_int_equal(hc.calls, 50);
	assert_memory_equal(dem_fe_velocity(a), dem_fe_velocity(b), 3 * m.nn * sizeof(double));
	assert_memory_equal(dem_fe_coords(a), dem_fe_coords(b), 3 * m.nn * sizeof(double));
	dem_fe_energy_t ea, eb;
	dem_fe_energy(a, &ea);
	dem_fe_energy(b, &eb);
	assert_true(ea.external > 0 && ea.external == eb.external);
	/* a failing hook stops the step before anything changes */
	double t = dem_fe_time(b);
	dem_fe_set_load(b, hook_fail, NULL);
	dem_error_clear(&e);
	assert_int_equal(dem_fe_step(b, 0, &e), DEM_ENUMERIC);
	assert_non_null(strstr(e.msg, "shot 3"));
	assert_true(dem_fe_time(b) == t);
	dem_fe_set_load(b, hook, &hc);
	step(a, 0);
	step(b, 0);
	assert_memory_equal(dem_fe_velocity(a), dem_fe_velocity(b), 3 * m.nn * sizeof(double));
	free(q);
	dem_fe_free(a);
	dem_fe_free(b);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_patch),
		cmocka_unit_test(test_bar_wave),
		cmocka_unit_test(test_load_hook),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
