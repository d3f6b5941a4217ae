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
#include "mesh/mesh.h"

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
			      .hard_ep = T71_EP, .hard_sy = sy, .rate_m = rate_m, .rate_ref = 1 };
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

static int all_finite(const double *a, size_t n)
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
	dem_fe_t *c = model(&m, &mat, DEM_FE_1PT, 1, 0);
	uint32_t *q;
	assert_int_equal(face_quads(&m, DEM_XMIN, &q), 1);
	double th[1] = { 0 }, ph[1] = { 500 * MPA };
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_add_pressure(a, 1, q, 1, th, ph, &e), DEM_OK);
	hook_ctx_t hc = { q, 500 * MPA, 0, 0 }, hc2 = hc;
	dem_fe_set_load(b, hook, &hc);
	/* c: the same hook, promised to load the face's nodes alone (the node
	 * loop then reads and clears the external forces there only) */
	size_t n0 = q[0], n1 = q[0];
	for (int i = 0; i < 4; i++)
		n0 = q[i] < n0 ? q[i] : n0, n1 = q[i] > n1 ? q[i] : n1;
	dem_fe_set_load(c, hook, &hc2);
	dem_fe_set_load_nodes(c, n0, n1 + 1);
	assert_true(n1 + 1 < m.nn); /* nodes past the range: their chunks unloaded */
	for (int it = 0; it < 50; it++) {
		step(a, 0);
		step(b, 0);
		step(c, 0);
	}
	assert_int_equal(hc.calls, 50);
	assert_memory_equal(dem_fe_velocity(a), dem_fe_velocity(b), 3 * m.nn * sizeof(double));
	assert_memory_equal(dem_fe_coords(a), dem_fe_coords(b), 3 * m.nn * sizeof(double));
	assert_memory_equal(dem_fe_velocity(b), dem_fe_velocity(c), 3 * m.nn * sizeof(double));
	assert_memory_equal(dem_fe_coords(b), dem_fe_coords(c), 3 * m.nn * sizeof(double));
	dem_fe_free(c);
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

/* ---- 3. Uniaxial stress ------------------------------------------------------ */

/* The flow stress of Table 7.1 at ep (linear interpolation, the last slope
 * beyond the last point), Pa. */
static double t71(double ep)
{
	int k = 0;
	while (k < 6 && ep >= T71_EP[k + 1])
		k++;
	return MPA * (T71_SY[k] + (T71_SY[k + 1] - T71_SY[k]) / (T71_EP[k + 1] - T71_EP[k]) * (ep - T71_EP[k]));
}

typedef struct uni {
	int n;            /* samples (steps) */
	double *ep, *sxx, *exx, *rate;   /* element 0: ep, sigma_xx, eps_xx, plastic rate */
	double worst;     /* largest |sigma_xx / flow - 1| over plastic steps */
	double lateral;   /* largest |other stress| / |sigma_xx| once plastic */
	double spread;    /* largest difference between elements / sigma_xx, once plastic */
} uni_t;

/* A box with symmetry rollers on x = 0, y = 0, z = 0 and the x = L face
 * pulled at the strain rate `rate` (velocity ramped up over `ramp` steps)
 * to the nominal strain emax, then pushed back by eback.  Damping: Ch. 7.5's
 * 5 % of the lowest mode (dem_fe_damping_alpha), which removes the ringing
 * of the start.  Records element 0 at every step; with flow != NULL checks
 * sigma_xx against flow(ep) at every plastic step of every element. */
static void uniaxial(const dem_mesh_t *m, const dem_mat_t *mat, dem_fe_rule_t rule, int large,
		     double rate, int ramp, double emax, double eback, double (*flow)(double, double),
		     uni_t *r)
{
	double L = m->gx[m->nx] - m->gx[0];
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FREE, DEM_BC_NORMAL, DEM_BC_FREE };
	dem_mesh_set_bc((dem_mesh_t *)m, bc);
	dem_fe_t *fe = model(m, mat, rule, large, dem_fe_damping_alpha(mat, 0.05, L));
	double dt = dem_fe_dt(fe), V = rate * L;
	int nload = (int)ceil(emax / (rate * dt)), nback = (int)ceil(eback / (rate * dt));
	int ntot = nload + ramp / 2 + nback;
	r->ep = malloc((size_t)ntot * sizeof(double));
	r->sxx = malloc((size_t)ntot * sizeof(double));
	r->exx = malloc((size_t)ntot * sizeof(double));
	r->rate = malloc((size_t)ntot * sizeof(double));
	double *sig = malloc(6 * m->ne * sizeof *sig), *eps = malloc(6 * m->ne * sizeof *eps);
	double *ep = malloc(m->ne * sizeof *ep);
	r->n = 0;
	r->worst = r->lateral = r->spread = 0;
	double epprev = 0;
	for (int it = 0; it < ntot; it++) {
		double vx = it < nload + ramp / 2 ? V * fmin(1, (it + 0.5) / ramp) : -V;
		double *v = dem_fe_velocity(fe);
		for (int k = 0; k <= m->nz; k++)
			for (int j = 0; j <= m->ny; j++)
				v[3 * dem_mesh_node(m, m->nx, j, k)] = vx;
		step(fe, dt);
		dem_fe_fields(fe, sig, eps, ep);
		r->ep[r->n] = ep[0];
		r->sxx[r->n] = sig[0];
		r->exx[r->n] = eps[0];
		r->rate[r->n] = (ep[0] - epprev) / dt;
		epprev = ep[0];
		r->n++;
		for (size_t el = 0; el < m->ne; el++) {
			const double *s = sig + 6 * el;
			if (!(ep[el] > 0) || !flow || vx < 0)
				continue;
			r->spread = fmax(r->spread, fabs(s[0] - sig[0]) / fabs(sig[0]));
			r->worst = fmax(r->worst, fabs(s[0] / flow(ep[el], r->rate[r->n - 1]) - 1));
			for (int k = 1; k < 6; k++)
				r->lateral = fmax(r->lateral, fabs(s[k] / s[0]));
		}
	}
	free(sig), free(eps), free(ep);
	dem_fe_free(fe);
}

static void uni_free(uni_t *r)
{
	free(r->ep), free(r->sxx), free(r->exx), free(r->rate);
}

static double flow_t71(double ep, double rate)
{
	(void)rate;
	return t71(ep);
}

/* sigma_xx where ep first reaches e (linear interpolation between steps) */
static double stress_at(const uni_t *r, double e)
{
	for (int i = 1; i < r->n; i++)
		if (r->ep[i] >= e && r->ep[i] > r->ep[i - 1]) {
			if (r->ep[i - 1] <= 0)
				return r->sxx[i];   /* first yield: the first plastic step */
			double w = (e - r->ep[i - 1]) / (r->ep[i] - r->ep[i - 1]);
			return r->sxx[i - 1] + w * (r->sxx[i] - r->sxx[i - 1]);
		}
	return NAN;
}

static void uniaxial_case(int nx, int ny, int nz, dem_fe_rule_t rule, int large)
{
	static const double lo[3] = { 0, 0, 0 };
	const double h = 1e-3;
	double len[3] = { nx * h, ny * h, nz * h };
	dem_mesh_t m;
	dem_mat_t mat;
	steel(&mat, 0);
	box(&m, nx, ny, nz, lo, len);
	/* strain rate: the load past ep = 0.0975 (also in log strain) in about 45000 steps */
	uni_t r;
	uniaxial(&m, &mat, rule, large, 17, 400, 0.115, 0.003, flow_t71, &r);
	printf("# uniaxial %dx%dx%d rule %d large %d: worst |sxx/flow - 1| %.2e, lateral %.2e, "
	       "spread %.2e\n", nx, ny, nz, rule, large, r.worst, r.lateral, r.spread);
	for (int k = 0; k < 8; k++) {
		double sk = stress_at(&r, T71_EP[k]);
		printf("#   ep %.4f: sxx %.3f MPa, table %.3f MPa (%+.3f %%)\n", T71_EP[k], sk / MPA, T71_SY[k],
		       100 * (sk / (T71_SY[k] * MPA) - 1));
		/* at the first yield ep is already one step's flow past 0 */
		double ref = k == 0 ? t71(r.ep[0] > 0 ? r.ep[0] : 0) : T71_SY[k] * MPA;
		if (k == 0)
			for (int i = 0; i < r.n; i++)
				if (r.ep[i] > 0) {
					ref = t71(r.ep[i]);
					break;
				}
		assert_true(fabs(sk / ref - 1) <= 0.005);
	}
	assert_true(r.worst <= 0.005);
	assert_true(r.lateral <= 0.005);
	assert_true(r.spread <= 0.005);
	/* unloading: ep frozen, slope E */
	int i1 = r.n - 1, i0 = i1;
	while (i0 > 0 && r.exx[i0 - 1] > r.exx[i0])
		i0--;
	i0 += 2;   /* past the reversal */
	double slope = (r.sxx[i1] - r.sxx[i0]) / (r.exx[i1] - r.exx[i0]);
	printf("#   unloading: slope %.4g GPa (E %.4g GPa), ep %.6g -> %.6g\n", slope / GPA, mat.E / GPA,
	       r.ep[i0 - 2], r.ep[i1]);
	assert_true(fabs(r.ep[i1] - r.ep[i0 - 2]) <= 1e-12 * r.ep[i1]);   /* frozen (round-off of the Gauss average) */
	assert_true(fabs(slope / mat.E - 1) <= 0.005);
	uni_free(&r);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

static void test_uniaxial_table(void **state)
{
	(void)state;
	uniaxial_case(1, 1, 1, DEM_FE_1PT, 0);
	uniaxial_case(1, 1, 1, DEM_FE_FULL, 1);
	uniaxial_case(3, 2, 2, DEM_FE_1PT, 1);
}

/* Rate dependence: the Table 7.1 curve with the exponent m = 0.0455 of
 * Table 7.2 (Al 5052), pulled at 10/s and 1000/s.  The law of material.h:
 * sigma = sigma_y(ep) (rate / 1 s^-1)^m with the plastic strain rate; at a
 * given ep the two flow stresses differ by the factor 100^m (the plastic
 * rate equals the imposed rate to within the elastic share, < 2 % here,
 * i.e. < 0.1 % in stress). */
static double flow_rate(double ep, double rate)
{
	return t71(ep) * pow(fmax(rate, 1), 0.0455);
}

static void test_uniaxial_rate(void **state)
{
	(void)state;
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 1e-3, 1e-3, 1e-3 };
	const double m = 0.0455;
	dem_mesh_t msh;
	dem_mat_t mat;
	steel(&mat, m);
	box(&msh, 1, 1, 1, lo, len);
	uni_t slow, fast;
	uniaxial(&msh, &mat, DEM_FE_1PT, 0, 10, 400, 0.05, 0, NULL, &slow);
	uniaxial(&msh, &mat, DEM_FE_1PT, 0, 1000, 20, 0.05, 0, NULL, &fast);
	/* the law through the driver, with the measured plastic rate */
	double worst = 0;
	uni_t *rr[2] = { &slow, &fast };
	for (int c = 0; c < 2; c++)
		for (int i = 0; i < rr[c]->n; i++)
			if (rr[c]->ep[i] > 0.005)
				worst = fmax(worst, fabs(rr[c]->sxx[i] / flow_rate(rr[c]->ep[i], rr[c]->rate[i]) - 1));
	printf("# rate law: worst |sxx/flow(ep, rate) - 1| %.2e\n", worst);
	assert_true(worst <= 0.005);
	static const double eps_at[3] = { 0.01, 0.02, 0.04 };
	for (int k = 0; k < 3; k++) {
		double r = stress_at(&fast, eps_at[k]) / stress_at(&slow, eps_at[k]);
		double rs = stress_at(&slow, eps_at[k]) / t71(eps_at[k]);
		printf("#   ep %.2f: sigma(1000/s) / sigma(10/s) = %.5f, 100^m = %.5f; sigma(10/s) / table "
		       "= %.5f, 10^m = %.5f\n", eps_at[k], r, pow(100, m), rs, pow(10, m));
		assert_true(fabs(r / pow(100, m) - 1) <= 0.005);
		assert_true(fabs(rs / pow(10, m) - 1) <= 0.005);
	}
	uni_free(&slow);
	uni_free(&fast);
	dem_mesh_free(&msh);
	dem_mat_free(&mat);
}

/* ---- 4. Energy ----------------------------------------------------------------- */

/* The block of Ch. 7.5 in miniature: 4 x 4 x 2 mm of the aluminium
 * (elastic here), 0.25 mm elements, bottom fixed, sides on rollers, top
 * free; 100 MPa on the central 2 x 2 mm of the top (8 x 8 elements) from
 * t = 0 to 2 us, then free vibration to 30 us.  Returns the energies at
 * every step.  (With 4 x 4 elements under the patch the hourglass energy
 * peaks at 5.3 % of the internal energy, 3.4 % on average: the resolution
 * of the load, not the time integration, sets that ratio.) */
typedef struct erun {
	int n;
	dem_fe_energy_t *en;
	double tr;
} erun_t;

static void energy_run(dem_fe_rule_t rule, int large, double alpha, erun_t *r)
{
	static const double lo[3] = { -2e-3, -2e-3, -2e-3 }, len[3] = { 4e-3, 4e-3, 2e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, 0);
	box(&m, 16, 16, 8, lo, len);
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh_set_bc(&m, bc);
	dem_fe_t *fe = model(&m, &mat, rule, large, alpha);
	size_t nq = dem_fe_top_quads(&m, -1e-3, 1e-3, -1e-3, 1e-3, NULL);
	assert_int_equal(nq, 64);
	uint32_t *q = malloc(4 * nq * sizeof *q);
	dem_fe_top_quads(&m, -1e-3, 1e-3, -1e-3, 1e-3, q);
	r->tr = 2e-6;
	double th[3] = { 0, r->tr, r->tr }, ph[3] = { 100 * MPA, 100 * MPA, 0 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_add_pressure(fe, nq, q, 3, th, ph, &e), DEM_OK);
	int cap = 4096;
	r->en = malloc((size_t)cap * sizeof *r->en);
	r->n = 0;
	while (dem_fe_time(fe) < 30e-6 && r->n < cap) {
		step(fe, 0);
		dem_fe_energy(fe, &r->en[r->n++]);
	}
	free(q);
	dem_fe_free(fe);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

static double emech(const dem_fe_energy_t *en)
{
	return en->kinetic + en->internal + en->hourglass;
}

static void energy_case(dem_fe_rule_t rule, int large, int damped)
{
	erun_t r;
	energy_run(rule, large, 0, &r);
	/* the first sample after the load is gone */
	int i0 = 0;
	while (r.en[i0].t <= r.tr)
		i0++;
	double e0 = emech(&r.en[i0]), dev = 0, bal = 0, hg = 0;
	for (int i = 0; i < r.n; i++) {
		if (r.en[i].scale > 0)
			bal = fmax(bal, fabs(r.en[i].balance) / r.en[i].scale);
		if (i >= i0)
			dev = fmax(dev, fabs(emech(&r.en[i]) / e0 - 1));
		if (i >= 5)
			hg = fmax(hg, r.en[i].hourglass / r.en[i].internal);
	}
	printf("# energy rule %d large %d: %d steps, E after unloading %.4g mJ, drift %.2e, "
	       "balance %.2e, hourglass/internal %.2e\n", rule, large, r.n, e0 * 1e3, dev, bal, hg);
	assert_true(r.en[r.n - 1].t > 25e-6);
	assert_true(dev <= 0.01);
	assert_true(bal <= 0.01);
	assert_true(hg <= 0.05);
	free(r.en);
	if (!damped)
		return;

	/* with damping C = alpha M, alpha (30 us - 2 us) = 1 */
	double alpha = 1 / 28e-6;
	energy_run(rule, large, alpha, &r);
	i0 = 0;
	while (r.en[i0].t <= r.tr)
		i0++;
	bal = 0;
	for (int i = 0; i < r.n; i++)
		if (r.en[i].scale > 0)
			bal = fmax(bal, fabs(r.en[i].balance) / r.en[i].scale);
	const dem_fe_energy_t *a = &r.en[i0], *b = &r.en[r.n - 1];
	double ratio = emech(b) / emech(a), expect = exp(-alpha * (b->t - a->t));
	printf("# damped: E(%.3g us) / E(%.3g us) = %.4f, exp(-alpha dt) = %.4f; damping work %.4g mJ, "
	       "balance %.2e\n", b->t * 1e6, a->t * 1e6, ratio, expect, b->damping * 1e3, bal);
	assert_true(fabs(ratio / expect - 1) <= 0.1);
	assert_true(bal <= 0.01);
	free(r.en);
}

static void test_energy(void **state)
{
	(void)state;
	energy_case(DEM_FE_1PT, 0, 1);
	energy_case(DEM_FE_1PT, 1, 1);
	energy_case(DEM_FE_FULL, 1, 0);
}

/* ---- 5. Inverted element -------------------------------------------------------- */

/* A 2x2x2 block (large strain) whose top centre node is driven down at
 * 2000 m/s at a fixed time step: the four elements around it collapse
 * within a few steps.  The
 * step returns DEM_ENUMERIC naming the first of them, element 4 at grid
 * (0, 0, 1), and the time; nothing in the state is NaN and the next step
 * fails the same way. */
static void inverted_case(dem_fe_rule_t rule)
{
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 2e-3, 2e-3, 2e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, 1);
	box(&m, 2, 2, 2, lo, len);
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh_set_bc(&m, bc);
	size_t nc = dem_mesh_node(&m, 1, 1, 2);
	m.fix[nc] = DEM_FIX_Z;     /* prescribed velocity */
	dem_fe_t *fe = model(&m, &mat, rule, 1, 0);
	dem_fe_velocity(fe)[3 * nc + 2] = -2000;
	dem_error_t e = { 0 };
	int rc = DEM_OK, it;
	/* at a fixed step: the adaptive one shrinks with the elements */
	double dt = dem_fe_dt(fe);
	for (it = 0; it < 100 && rc == DEM_OK; it++)
		rc = dem_fe_step(fe, dt, &e);
	printf("# inverted rule %d after %d steps: %s\n", rule, it, e.msg);
	assert_int_equal(rc, DEM_ENUMERIC);
	assert_non_null(strstr(e.msg, "element 4 (i, j, k = 0, 0, 1)"));
	char tbuf[64];
	snprintf(tbuf, sizeof tbuf, "t = %.9g s", dem_fe_time(fe));
	assert_non_null(strstr(e.msg, tbuf));
	double *sig = malloc(6 * m.ne * sizeof *sig), *eps = malloc(6 * m.ne * sizeof *eps);
	double *ep = malloc(m.ne * sizeof *ep), *u = malloc(3 * m.nn * sizeof *u);
	dem_fe_fields(fe, sig, eps, ep);
	dem_fe_displacements(fe, u);
	dem_fe_energy_t en;
	dem_fe_energy(fe, &en);
	assert_true(all_finite(sig, 6 * m.ne) && all_finite(eps, 6 * m.ne) && all_finite(ep, m.ne));
	assert_true(all_finite(u, 3 * m.nn) && all_finite(dem_fe_velocity(fe), 3 * m.nn));
	assert_true(all_finite(&en.kinetic, 7));
	dem_error_t e2 = { 0 };
	assert_int_equal(dem_fe_step(fe, 0, &e2), DEM_ENUMERIC);
	assert_string_equal(e.msg, e2.msg);
	free(sig), free(eps), free(ep), free(u);
	dem_fe_free(fe);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

static void test_inverted(void **state)
{
	(void)state;
	inverted_case(DEM_FE_1PT);
	inverted_case(DEM_FE_FULL);
	/* a mesh with an inverted element is refused */
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 2e-3, 1e-3, 1e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, 0);
	box(&m, 2, 1, 1, lo, len);
	m.X[3 * dem_mesh_node(&m, 1, 1, 1) + 2] = -2e-3;   /* through the bottom */
	dem_fe_opts_t o;
	dem_fe_opts_default(&o);
	dem_fe_t *fe;
	dem_error_t e = { 0 };
	assert_int_equal(dem_fe_create(&fe, &m, &mat, &o, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "element 0 (i, j, k = 0, 0, 0)"));
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

/* ---- Threads and time step ------------------------------------------------------- */

/* The same run on 1, 2 and 3 threads gives the same bits: a plastic block
 * (large strain) under a pressure patch, 40 steps.  The block is thin (8
 * layers), so its slabs are bands of rows in four colours. */
static void test_threads(void **state)
{
	(void)state;
	static const double lo[3] = { -2e-3, -2e-3, -2e-3 }, len[3] = { 4e-3, 4e-3, 2e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, 1);
	box(&m, 16, 16, 8, lo, len);
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh_set_bc(&m, bc);
	size_t nq = dem_fe_top_quads(&m, -1e-3, 1e-3, -1e-3, 1e-3, NULL);
	uint32_t *q = malloc(4 * nq * sizeof *q);
	dem_fe_top_quads(&m, -1e-3, 1e-3, -1e-3, 1e-3, q);
	double th[1] = { 0 }, ph[1] = { 600 * MPA };
	dem_fe_t *fe[3];
	double *sig[3];
	dem_fe_energy_t en[3];
	for (int r = 0; r < 3; r++) {
		dem_fe_opts_t o;
		dem_fe_opts_default(&o);
		o.large = 1;
		o.threads = r + 1;
		dem_error_t e = { 0 };
		assert_int_equal(dem_fe_create(&fe[r], &m, &mat, &o, &e), DEM_OK);
		assert_int_equal(dem_fe_add_pressure(fe[r], nq, q, 1, th, ph, &e), DEM_OK);
		for (int it = 0; it < 40; it++)
			step(fe[r], 0);
		sig[r] = malloc(6 * m.ne * sizeof(double));
		dem_fe_fields(fe[r], sig[r], NULL, NULL);
		dem_fe_energy(fe[r], &en[r]);
	}
	dem_fe_stats_t st;
	dem_fe_stats(fe[0], &st);
	printf("# threads: %.0f plastic updates in %ld steps\n", st.plastic_updates, st.steps);
	assert_true(st.plastic_updates > 0);
	assert_memory_equal(dem_fe_coords(fe[0]), dem_fe_coords(fe[1]), 3 * m.nn * sizeof(double));
	assert_memory_equal(dem_fe_velocity(fe[0]), dem_fe_velocity(fe[1]), 3 * m.nn * sizeof(double));
	assert_memory_equal(sig[0], sig[1], 6 * m.ne * sizeof(double));
	assert_memory_equal(&en[0], &en[1], sizeof en[0]);
	assert_memory_equal(dem_fe_coords(fe[0]), dem_fe_coords(fe[2]), 3 * m.nn * sizeof(double));
	assert_memory_equal(sig[0], sig[2], 6 * m.ne * sizeof(double));
	assert_memory_equal(&en[0], &en[2], sizeof en[0]);
	for (int r = 0; r < 3; r++) {
		free(sig[r]);
		dem_fe_free(fe[r]);
	}
	free(q);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

/* In large strain the stable step follows the shape: a cube squeezed to
 * 60 % of its height (prescribed top velocity) has the step
 * 0.9 dem_hex8_dt_crit of its current shape (exact for a box); in small
 * strain the step does not change. */
static void test_dt_follows_shape(void **state)
{
	(void)state;
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 1e-3, 1e-3, 1e-3 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, 0);
	box(&m, 1, 1, 1, lo, len);
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_FREE, DEM_BC_NORMAL, DEM_BC_FREE, DEM_BC_NORMAL, DEM_BC_NORMAL };
	dem_mesh_set_bc(&m, bc);
	for (int large = 0; large < 2; large++) {
		dem_fe_t *fe = model(&m, &mat, DEM_FE_1PT, large, 0);
		double dt0 = dem_fe_dt(fe);
		while (dem_fe_coords(fe)[3 * dem_mesh_node(&m, 0, 0, 1) + 2] > 0.6e-3) {
			double *v = dem_fe_velocity(fe);
			for (int j = 0; j <= 1; j++)
				for (int i = 0; i <= 1; i++)
					v[3 * dem_mesh_node(&m, i, j, 1) + 2] = -20;
			step(fe, 0);
		}
		double xe[24], dtc;
		const double *x = dem_fe_coords(fe);
		for (int I = 0; I < 8; I++)
			for (int c = 0; c < 3; c++)
				xe[8 * c + I] = x[3 * m.hex[I] + c];
		assert_int_equal(dem_hex8_dt_crit(xe, mat.wave, &dtc), DEM_HEX8_OK);
		printf("# dt large %d: start %.4g ns, now %.4g ns, 0.9 dt_crit(current) %.4g ns\n", large,
		       dt0 * 1e9, dem_fe_dt(fe) * 1e9, 0.9 * dtc * 1e9);
		if (large)
			assert_true(fabs(dem_fe_dt(fe) / (0.9 * dtc) - 1) < 1e-3);
		else
			assert_true(dem_fe_dt(fe) == dt0);
		dem_fe_free(fe);
	}
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

/* ---- Small against large strain -------------------------------------------- */

/* One element (0.1 mm cube, every node prescribed) moved through the
 * homogeneous motion x(t) = F(t) X, the velocity of every node dF/dt X
 * at the mid-step value of F; returns the element's stress and plastic
 * strain.  mode 0: F = I + s G, s from 0 to smax at a constant rate;
 * mode 1: F = R(theta), a rigid rotation about y from 0 to smax rad. */
static void homog(dem_fe_rule_t rule, int large, int plastic, int mode, const double G[9], double smax,
		  double sig[6], double *ep)
{
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 1e-4, 1e-4, 1e-4 };
	dem_mesh_t m;
	dem_mat_t mat;
	alu(&mat, plastic);
	box(&m, 1, 1, 1, lo, len);
	for (size_t n = 0; n < m.nn; n++)
		m.fix[n] = DEM_FIX_X | DEM_FIX_Y | DEM_FIX_Z;
	dem_fe_t *fe = model(&m, &mat, rule, large, 0);
	double dt = dem_fe_dt(fe);
	const int N = 2000;
	double rate = smax / (N * dt);
	for (int it = 0; it < N; it++) {
		double *v = dem_fe_velocity(fe), a = smax * (it + 0.5) / N;
		for (size_t n = 0; n < m.nn; n++) {
			const double *X = m.X + 3 * n;
			if (mode == 0)
				for (int c = 0; c < 3; c++)
					v[3 * n + c] = rate * (G[3 * c] * X[0] + G[3 * c + 1] * X[1] + G[3 * c + 2] * X[2]);
			else {
				/* x = cos a X + sin a Z, z = -sin a X + cos a Z */
				v[3 * n] = rate * (-sin(a) * X[0] + cos(a) * X[2]);
				v[3 * n + 1] = 0;
				v[3 * n + 2] = rate * (-cos(a) * X[0] - sin(a) * X[2]);
			}
		}
		step(fe, dt);
	}
	dem_fe_fields(fe, sig, NULL, ep);
	dem_fe_free(fe);
	dem_mesh_free(&m);
	dem_mat_free(&mat);
}

static double maxdiff(const double a[6], const double b[6], double *scale)
{
	double d = 0, s = 0;
	for (int k = 0; k < 6; k++) {
		d = fmax(d, fabs(a[k] - b[k]));
		s = fmax(s, fabs(a[k]));
	}
	*scale = s;
	return d;
}

/* The two strain measures must agree to first order in the strain and
 * differ, as the theory says, where the geometrically linear one is known
 * to fail (Belytschko, Liu & Moran 2000, Ch. 2.4: a rigid rotation).
 *  1. A homogeneous motion F = I + s G (stretch, shear and spin), elastic:
 *     the stresses of the two differ by O(s) relative (the difference
 *     of the linear strain and the integrated rate of deformation, and the
 *     rotation of the stress); measured 0.62 s for this G, both rules, at
 *     every s from 1e-4 to 1e-2: the test asks for <= s and for the
 *     difference to fall in proportion to s (ratio 100 +- 5 % over two
 *     decades).  The same motion with J2 plasticity (the aluminium of
 *     Ch. 7.5) to s = 0.01 (ep 0.007): within 2 s of each other.
 *  2. A rigid rotation by theta = 0.03 rad: large strain keeps the block
 *     stress-free (below 1e-3 of the next figure); small strain gives the
 *     stress of its own theory exactly, D eps with eps_xx = eps_zz =
 *     cos theta - 1 (-68 MPa here; at 0.3 rad the spurious strain
 *     theta^2 / 2 = 0.045 is 20 times the yield strain of that aluminium).
 *     That term is what separates the two on the Ch. 7.5 shot (see
 *     examples/cost/STRAIN.md): not a defect of the small strain path. */
static void test_small_vs_large(void **state)
{
	(void)state;
	static const double G[9] = { 1.0, 0.3, -0.2, -0.1, -0.5, 0.4, 0.2, 0.15, 0.25 };
	for (int rule = DEM_FE_1PT; rule <= DEM_FE_FULL; rule++) {
		double s0[6], s1[6], ep0, ep1, sc, d[3];
		for (int i = 0; i < 3; i++) {
			double s = 1e-4 * pow(10, i);
			homog(rule, 0, 0, 0, G, s, s0, &ep0);
			homog(rule, 1, 0, 0, G, s, s1, &ep1);
			d[i] = maxdiff(s0, s1, &sc) / sc;
			printf("# small/large rule %d, elastic, s = %.0e: stress difference %.3e = %.3f s\n", rule, s,
			       d[i], d[i] / s);
			assert_true(d[i] <= s);
		}
		printf("# small/large rule %d: difference at s = 1e-2 over s = 1e-4: %.2f\n", rule, d[2] / d[0]);
		assert_true(fabs(d[2] / d[0] / 100 - 1) <= 0.05);
		homog(rule, 0, 1, 0, G, 1e-2, s0, &ep0);
		homog(rule, 1, 1, 0, G, 1e-2, s1, &ep1);
		double dp = maxdiff(s0, s1, &sc) / sc;
		printf("# small/large rule %d, plastic, s = 0.01: ep %.5f / %.5f, stress difference %.3e\n", rule,
		       ep0, ep1, dp);
		assert_true(ep0 > 0.005 && ep1 > 0.005);
		assert_true(dp <= 2e-2);
		assert_true(fabs(ep1 / ep0 - 1) <= 2e-2);

		const double th = 0.03;
		dem_mat_t mat;
		alu(&mat, 1);
		double D[36], ex[6] = { cos(th) - 1, 0, cos(th) - 1, 0, 0, 0 }, sx[6];
		dem_mat_elastic_stiffness(&mat, D);
		for (int r = 0; r < 6; r++) {
			sx[r] = 0;
			for (int c = 0; c < 6; c++)
				sx[r] += D[6 * r + c] * ex[c];
		}
		homog(rule, 0, 1, 1, NULL, th, s0, &ep0);
		homog(rule, 1, 1, 1, NULL, th, s1, &ep1);
		double ds = maxdiff(sx, s0, &sc), dl = fmax(fabs(s1[0]), fabs(s1[2]));
		for (int k = 0; k < 6; k++)
			dl = fmax(dl, fabs(s1[k]));
		printf("# rotation %.2f rad rule %d: small sxx %.3f szz %.3f MPa (linear theory %.3f), large "
		       "max |sig| %.2e MPa\n", th, rule, s0[0] / MPA, s0[2] / MPA, sx[0] / MPA, dl / MPA);
		assert_true(ds <= 1e-6 * sc);
		assert_true(ep0 == 0 && ep1 == 0);
		assert_true(dl <= 1e-3 * sc);
		dem_mat_free(&mat);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_patch),
		cmocka_unit_test(test_bar_wave),
		cmocka_unit_test(test_load_hook),
		cmocka_unit_test(test_uniaxial_table),
		cmocka_unit_test(test_uniaxial_rate),
		cmocka_unit_test(test_energy),
		cmocka_unit_test(test_inverted),
		cmocka_unit_test(test_threads),
		cmocka_unit_test(test_dt_follows_shape),
		cmocka_unit_test(test_small_vs_large),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
