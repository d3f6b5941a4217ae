/* test_fe_implicit.c - unit tests of lib/fe/implicit.c (the implicit forming
 * stage, Ch. 8.5) and lib/fe/hex8_large.c (its large-strain element).
 *
 * References: the closed form of DESIGN.md for a free plate with an
 * equi-biaxial initial stress s(z) (curvature -12 (1-nu) int s z dz /
 * (E h^3), membrane strain -(1-nu) int s dz / (E h), stress s + E/(1-nu)
 * (eps0 + kappa z)), integrated exactly over the piecewise-linear profile;
 * the mesh counts of Ch. 8.6 (4500 elements, 5456 nodes); the quadratic
 * convergence of Newton's method with the consistent tangent; finite
 * differences of the internal force for the large-strain tangent; the
 * small-strain element at zero displacement; rigid rotations that must not
 * strain the large-strain element; for the J2 plate whose unpeened face
 * yields, a layered plate (plane-stress layers under Kirchhoff strains,
 * the 1D return of the equi-biaxial state) solved alongside.
 *
 * The profile of the tests is a made-up shot-peening shape (compressive
 * surface, deeper peak, zero at 0.6 mm; Fig. 8.5 of the thesis has the
 * same shape); it is no datum, the closed form is the reference.  The
 * material is Al 7050-T7651 of Ch. 8.6 (E 72 GPa, yield 450 MPa, hardening
 * 120 MPa) with nu = 0.33; for the unpeened face that yields, 316 stainless
 * steel of Table 7.2 with a strain-hardened profile made up for it.
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

#include "fe/hex8_large.h"
#include "fe/implicit.h"

#define MM 1e-3
#define MPA 1e6
#define E_AL 72e9
#define NU_AL 0.33


/* ---- The test profile ----------------------------------------------------------- */

#define NP 6
static const double P_DEPTH[NP] = { 0, 0.1 * MM, 0.2 * MM, 0.35 * MM, 0.5 * MM, 0.6 * MM };
static const double P_SIG[NP] = { -300 * MPA, -400 * MPA, -350 * MPA, -150 * MPA, 30 * MPA, 0 };
static const double P_EP[NP] = { 0.05, 0.0375, 0.025, 0.0125, 0, 0 };

typedef struct prof {
	dem_profile_t p;
	double depth[NP], sig[6 * NP], eps[6 * NP], ep[NP];
} prof_t;

/* The equi-biaxial profile scaled by s (sxx = syy); with strain: the
 * eigenstrain whose stress -D eps is that profile: exx = eyy = -(1-nu) s/E
 * and ezz = 2 nu s / E (so that szz = 0). */
static void make_profile(prof_t *q, double s, int strain)
{
	memset(q, 0, sizeof *q);
	for (int k = 0; k < NP; k++) {
		q->depth[k] = P_DEPTH[k];
		if (strain) {
			q->eps[6 * k] = q->eps[6 * k + 1] = -(1 - NU_AL) * s * P_SIG[k] / E_AL;
			q->eps[6 * k + 2] = 2 * NU_AL * s * P_SIG[k] / E_AL;
		} else {
			q->sig[6 * k] = q->sig[6 * k + 1] = s * P_SIG[k];
		}
		q->ep[k] = P_EP[k];
	}
	q->p.n = NP;
	q->p.depth = q->depth;
	q->p.sig = q->sig;
	q->p.eps = q->eps;
	q->p.ep = q->ep;
}

/* int s dd and int s (h/2 - d) dd over the thickness h (d the depth), exact
 * for the piecewise-linear profile (Simpson on each segment). */
static void profile_moments(double s, double h, double *I0, double *I1)
{
	*I0 = *I1 = 0;
	for (int k = 0; k + 1 < NP; k++) {
		double a = P_DEPTH[k], b = P_DEPTH[k + 1];
		for (int g = 0; g < 3; g++) {
			double t = 0.5 * g, d = a + t * (b - a), w = (b - a) * (g == 1 ? 4 : 1) / 6.0;
			double v = s * (P_SIG[k] + t * (P_SIG[k + 1] - P_SIG[k]));
			*I0 += w * v;
			*I1 += w * v * (h / 2 - d);
		}
	}
}

/* DESIGN.md: the free plate's curvature and membrane strain. */
static void closed_form(double s, double h, double *kappa, double *eps0)
{
	double I0, I1;
	profile_moments(s, h, &I0, &I1);
	*kappa = -12 * (1 - NU_AL) * I1 / (E_AL * h * h * h);
	*eps0 = -(1 - NU_AL) * I0 / (E_AL * h);
}

static double profile_at(double s, double d)
{
	if (d >= P_DEPTH[NP - 1])
		return s * P_SIG[NP - 1];
	int k = 0;
	while (P_DEPTH[k + 1] < d)
		k++;
	double t = (d - P_DEPTH[k]) / (P_DEPTH[k + 1] - P_DEPTH[k]);
	return s * (P_SIG[k] + t * (P_SIG[k + 1] - P_SIG[k]));
}

/* ---- A plate job ----------------------------------------------------------------- */

typedef struct job {
	dem_mesh_t mesh;
	dem_mat_t mat;
	dem_form_t *f;
	dem_form_stats_t st;
	dem_form_opts_t o;
	/* the Newton log of the last step */
	int nlog;
	double r[200];
	int inc[200], it[200];
} job_t;

static void logger(void *ctx, int step, int inc, double lambda, int iter, double rn,
		   double rrel, double dun)
{
	job_t *j = ctx;
	(void)step, (void)lambda, (void)rrel, (void)dun;
	if (j->nlog < 200) {
		j->r[j->nlog] = rn;
		j->inc[j->nlog] = inc;
		j->it[j->nlog] = iter;
		j->nlog++;
	}
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "  step %d inc %d lambda %.4g it %d |R| %.3e rel %.3e |du| %.3e\n",
			step, inc, lambda, iter, rn, rrel, dun);
}

static void job_init_plate(job_t *j, const dem_plate_t *pl, const dem_mat_param_t *mp)
{
	dem_error_t e = { 0 };
	memset(j, 0, sizeof *j);
	assert_int_equal(dem_plate_mesh(pl, &j->mesh, &e), DEM_OK);
	assert_int_equal(dem_mat_init(&j->mat, mp, &e), DEM_OK);
	assert_int_equal(dem_form_create(&j->f, &j->mesh, &j->mat, &e), DEM_OK);
	dem_form_opts_default(&j->o);
	j->o.log = logger;
	j->o.ctx = j;
}

static void job_init(job_t *j, double L, double W, double h, double dxy, int nz,
		     double grade, double yield)
{
	dem_plate_t pl = { L, W, h, dxy, nz, grade, 0 };
	dem_mat_param_t mp = { .E = E_AL, .nu = NU_AL, .sy0 = yield, .H = yield > 0 ? 120 * MPA : 0 };
	job_init_plate(j, &pl, &mp);
}

static void job_free(job_t *j)
{
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "job: %zu elements, %d iterations, %.2f s assembly, %.2f s factor\n",
			j->mesh.ne, j->st.iterations, j->st.assemble_s, j->st.factor_s);
	dem_form_free(j->f);
	dem_mat_free(&j->mat);
	dem_mesh_free(&j->mesh);
}

static const dem_form_region_t TOP = { 0, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL };

/* Apply the test profile (scale s) on the top face, free plate, solve. */
static int job_solve(job_t *j, double s, int strain, dem_error_t *e)
{
	prof_t q;
	make_profile(&q, s, strain);
	assert_int_equal(dem_form_profile(j->f, &q.p, &TOP, strain ? DEM_FORM_STRAIN : DEM_FORM_SIGMA,
					  1, e), DEM_OK);
	dem_form_constrain(j->f, NULL, 1);
	j->nlog = 0;
	return dem_form_step(j->f, &j->o, &j->st, e);
}

static dem_form_shape_t job_shape(job_t *j)
{
	dem_form_shape_t sh;
	dem_error_t e = { 0 };
	double L = j->mesh.gx[j->mesh.nx] - j->mesh.gx[0];
	assert_int_equal(dem_form_shape(j->f, L, 0, 1, 1, &sh, &e), DEM_OK);
	return sh;
}

/* Largest difference of the centre sxx from the closed form, relative to
 * the profile's peak. */
static double stress_error(job_t *j, double s, double h)
{
	double kap, e0, dep[400], sig[2400], ep[400], err = 0;
	int n;
	closed_form(s, h, &kap, &e0);
	dem_form_centre_profile(j->f, &n, dep, sig, ep);
	assert_int_equal(n, 2 * j->mesh.nz);
	for (int i = 0; i < n; i++) {
		double ref = profile_at(s, dep[i]) + E_AL / (1 - NU_AL) * (e0 + kap * (h / 2 - dep[i]));
		err = fmax(err, fabs(sig[6 * i] - ref));
		err = fmax(err, fabs(sig[6 * i + 1] - ref));
		err = fmax(err, fabs(sig[6 * i + 2]));   /* plane stress */
	}
	return err / (400 * MPA * fabs(s));
}

/* ---- Mesh ------------------------------------------------------------------------- */

/* Ch. 8.6: 5 x 5 mm in plane, 15 layers: 4500 elements, 5456 nodes;
 * layers graded by the ratio, top one thinnest. */
static void test_plate_mesh(void **state)
{
	(void)state;
	dem_plate_t pl = { 150 * MM, 50 * MM, 4 * MM, 5 * MM, 15, 1.2, 0 };
	dem_mesh_t m;
	dem_error_t e = { 0 };
	assert_int_equal(dem_plate_mesh(&pl, &m, &e), DEM_OK);
	assert_int_equal(m.ne, 4500);
	assert_int_equal(m.nn, 5456);
	assert_true(fabs(m.gz[15]) < 1e-15 && fabs(m.gz[0] + 4 * MM) < 1e-15);
	assert_true(fabs(m.gx[0] + 75 * MM) < 1e-15 && fabs(m.gy[10] - 25 * MM) < 1e-15);
	for (int k = 0; k + 2 <= 15; k++) {
		double t0 = m.gz[k + 1] - m.gz[k], t1 = m.gz[k + 2] - m.gz[k + 1];
		assert_true(fabs(t0 / t1 - 1.2) < 1e-9);
	}
	/* sum of t0 1.2^k over 15 layers is 4 mm */
	double t0 = 4 * MM * 0.2 / (pow(1.2, 15) - 1);
	assert_true(fabs(m.gz[15] - m.gz[14] - t0) < 1e-12);
	dem_mesh_free(&m);

	pl.two_sided = 1;
	pl.nz = 10;
	assert_int_equal(dem_plate_mesh(&pl, &m, &e), DEM_OK);
	for (int k = 0; k <= 10; k++)
		assert_true(fabs(m.gz[k] + m.gz[10 - k] + 4 * MM) < 1e-12);
	assert_true(m.gz[1] - m.gz[0] < m.gz[5] - m.gz[4]);
	dem_mesh_free(&m);
}

/* ---- Acceptance 2: the free plate against the closed form ---------------------------- */

/* The Ch. 8.6 strip and mesh: curvature within 3 %, both directions, and
 * the arc height over the length within 3 % of kappa L^2 / 8; stress at the
 * centre within 3 % of the profile's peak of the closed form; converged in
 * one Newton iteration (the elastic problem is linear). */
static void test_free_plate_ch86(void **state)
{
	(void)state;
	job_t j;
	dem_error_t e = { 0 };
	job_init(&j, 150 * MM, 50 * MM, 4 * MM, 5 * MM, 15, 1.2, 0);
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
	double kap, e0;
	closed_form(1, 4 * MM, &kap, &e0);
	dem_form_shape_t sh = job_shape(&j);
	assert_true(kap > 0);
	assert_true(fabs(sh.kx / kap - 1) < 0.03);
	assert_true(fabs(sh.ky / kap - 1) < 0.03);
	assert_true(fabs(sh.kxy) < 1e-6 * kap);
	double L = 150 * MM;
	assert_true(fabs(sh.arc / (kap * L * L / 8) - 1) < 0.03);
	assert_true(stress_error(&j, 1, 4 * MM) < 0.03);
	assert_int_equal(j.st.iterations, 1);
	assert_true(j.st.rrel < 1e-8);
	job_free(&j);
}

/* A fine mesh (2.5 mm in plane, 30 layers; on a 50 x 50 mm plate, the
 * closed form not depending on the size): curvature within 1 %, stress
 * within 1 %. */
static void test_free_plate_fine(void **state)
{
	(void)state;
	job_t j;
	dem_error_t e = { 0 };
	job_init(&j, 50 * MM, 50 * MM, 4 * MM, 2.5 * MM, 30, 1.1, 0);
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
	double kap, e0;
	closed_form(1, 4 * MM, &kap, &e0);
	dem_form_shape_t sh = job_shape(&j);
	assert_true(fabs(sh.kx / kap - 1) < 0.01);
	assert_true(fabs(sh.ky / kap - 1) < 0.01);
	assert_true(stress_error(&j, 1, 4 * MM) < 0.01);
	job_free(&j);
}

/* No locking: the plain 2x2x2 element on the Ch. 8.6 mesh (thin layers,
 * 5 mm in plane) misses the curvature by far (28 % measured); the
 * incompatible modes do not (the test above).  This is what makes the EAS element necessary. */
static void test_full_integration_locks(void **state)
{
	(void)state;
	job_t j;
	dem_error_t e = { 0 };
	job_init(&j, 150 * MM, 50 * MM, 4 * MM, 5 * MM, 15, 1.2, 0);
	j.o.rule = DEM_HEX8_FULL;
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
	double kap, e0;
	closed_form(1, 4 * MM, &kap, &e0);
	dem_form_shape_t sh = job_shape(&j);
	/* more than three times the 3 % the EAS element is allowed */
	assert_true(sh.kx < 0.9 * kap);
	job_free(&j);
}

/* The (eps, ep) initial condition: the eigenstrain whose stress -D eps is
 * the profile gives the same plate as the stress profile. */
static void test_strain_initial_condition(void **state)
{
	(void)state;
	job_t j;
	dem_error_t e = { 0 };
	job_init(&j, 50 * MM, 20 * MM, 4 * MM, 5 * MM, 15, 1.2, 0);
	assert_int_equal(job_solve(&j, 1, 1, &e), DEM_OK);
	dem_form_shape_t a = job_shape(&j);
	job_free(&j);
	job_init(&j, 50 * MM, 20 * MM, 4 * MM, 5 * MM, 15, 1.2, 0);
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
	dem_form_shape_t b = job_shape(&j);
	job_free(&j);
	assert_true(b.kx > 0);
	assert_true(fabs(a.kx / b.kx - 1) < 1e-8);
	assert_true(fabs(a.ky / b.ky - 1) < 1e-8);
}

/* ---- hex8_large ----------------------------------------------------------------------- */

static void box_element(double X[24], double a, double b, double c)
{
	for (int I = 0; I < 8; I++) {
		X[I] = 0.5 * a * (1 + dem_hex8_node_xi[I]);
		X[8 + I] = 0.5 * b * (1 + dem_hex8_node_eta[I]);
		X[16 + I] = 0.5 * c * (1 + dem_hex8_node_zeta[I]);
	}
}

/* At zero displacement and zero stress the large-strain element is the
 * small-strain one (both EAS); with an initial stress only the geometric
 * stiffness differs, and it is symmetric. */
static void test_large_matches_small(void **state)
{
	(void)state;
	job_t j;
	job_init(&j, 10 * MM, 10 * MM, 1 * MM, 5 * MM, 1, 1, 0);
	double X[24], z[24] = { 0 }, f1[24], f2[24], K1[576], K2[576];
	box_element(X, 5 * MM, 4 * MM, 0.1 * MM);
	dem_hex8_hist_t hn = { 0 }, h1 = { 0 }, h2 = { 0 };
	/* a small displacement: the tangents agree to its order */
	double du[24];
	for (int i = 0; i < 24; i++)
		du[i] = 1e-12 * sin(1.3 * i);
	assert_int_equal(dem_hex8_static(&j.mat, DEM_HEX8_EAS, X, du, &hn, &h1, f1, K1, NULL), 0);
	assert_int_equal(dem_hex8_large(&j.mat, 1, X, z, du, &hn, &h2, f2, K2, NULL), 0);
	double kmax = 0, fmax_ = 0;
	for (int i = 0; i < 576; i++)
		kmax = fmax(kmax, fabs(K1[i]));
	for (int i = 0; i < 24; i++)
		fmax_ = fmax(fmax_, fabs(f1[i]));
	double dk = 0;
	for (int i = 0; i < 576; i++)
		dk = fmax(dk, fabs(K1[i] - K2[i]));
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "dk %g of %g\n", dk, kmax);
	assert_true(dk < 1e-7 * kmax);
	for (int i = 0; i < 24; i++)
		assert_true(fabs(f1[i] - f2[i]) < 1e-6 * fmax_);
	for (int p = 0; p < 8; p++)
		hn.sig[6 * p] = hn.sig[6 * p + 1] = -300 * MPA;
	assert_int_equal(dem_hex8_large(&j.mat, 1, X, z, z, &hn, &h2, f2, K2, NULL), 0);
	for (int a = 0; a < 24; a++)
		for (int b = 0; b < a; b++)
			assert_true(fabs(K2[24 * a + b] - K2[24 * b + a]) < 1e-10 * kmax);
	job_free(&j);
}

/* The tangent is the derivative of the internal force (central
 * differences) at a stressed, rotated and strained state; J2 loading. */
static void test_large_tangent_fd(void **state)
{
	(void)state;
	job_t j;
	job_init(&j, 10 * MM, 10 * MM, 1 * MM, 5 * MM, 1, 1, 450 * MPA);
	double X[24], un[24], du[24], f0[24], K[576];
	box_element(X, 5 * MM, 4 * MM, 0.2 * MM);
	dem_hex8_hist_t hn = { 0 }, h = { 0 };
	for (int p = 0; p < 8; p++)
		hn.sig[6 * p] = hn.sig[6 * p + 1] = -440 * MPA;
	/* a rotation of 0.2 rad about y and a little strain */
	double c = cos(0.2), s = sin(0.2);
	for (int I = 0; I < 8; I++) {
		double x = X[I], zz = X[16 + I];
		un[I] = c * x + s * zz - x;
		un[8 + I] = 0;
		un[16 + I] = -s * x + c * zz - zz;
	}
	for (int i = 0; i < 24; i++)
		du[i] = 2e-6 * cos(0.7 * i);
	assert_int_equal(dem_hex8_large(&j.mat, 1, X, un, du, &hn, &h, f0, K, NULL), 0);
	int plastic = 0;
	for (int p = 0; p < 8; p++)
		plastic |= h.ep[p] > 0;
	assert_true(plastic);
	double kmax = 0, err = 0;
	for (int b = 0; b < 24; b++) {
		double d = 1e-10, fp[24], fm[24], dp[24], dm[24];
		memcpy(dp, du, sizeof dp);
		memcpy(dm, du, sizeof dm);
		dp[b] += d;
		dm[b] -= d;
		dem_hex8_hist_t hp = h, hm = h;
		assert_int_equal(dem_hex8_large(&j.mat, 1, X, un, dp, &hn, &hp, fp, NULL, NULL), 0);
		assert_int_equal(dem_hex8_large(&j.mat, 1, X, un, dm, &hn, &hm, fm, NULL, NULL), 0);
		for (int a = 0; a < 24; a++) {
			err = fmax(err, fabs((fp[a] - fm[a]) / (2 * d) - K[24 * a + b]));
			kmax = fmax(kmax, fabs(K[24 * a + b]));
		}
	}
	assert_true(err < 1e-5 * kmax);
	job_free(&j);
}

/* A rigid rotation of a stress-free element strains nothing (Green-Lagrange
 * strain is objective): zero force; the small-strain element would see
 * strains of order theta^2. */
static void test_large_rigid_rotation(void **state)
{
	(void)state;
	job_t j;
	job_init(&j, 10 * MM, 10 * MM, 1 * MM, 5 * MM, 1, 1, 0);
	double X[24], z[24] = { 0 }, u[24], f[24], K[576];
	box_element(X, 5 * MM, 4 * MM, 0.2 * MM);
	double c = cos(0.7), s = sin(0.7);
	for (int I = 0; I < 8; I++) {
		double x = X[I], y = X[8 + I];
		u[I] = c * x - s * y - x;
		u[8 + I] = s * x + c * y - y;
		u[16 + I] = 0;
	}
	dem_hex8_hist_t hn = { 0 }, h = { 0 };
	assert_int_equal(dem_hex8_large(&j.mat, 1, X, z, u, &hn, &h, f, K, NULL), 0);
	/* scale: the force of a 1e-3 strain */
	double ref = E_AL * 1e-3 * 4 * MM * 0.2 * MM;
	for (int i = 0; i < 24; i++)
		assert_true(fabs(f[i]) < 1e-9 * ref);
	job_free(&j);
}

/* ---- Acceptance 3 and 4: Newton, plasticity, cut-back, large strain ----------------- */

/* Relative residuals of increment inc (the log's numbering), for the
 * convergence order; r[0] is the residual of the increment's load. */
static int increment_residuals(const job_t *j, int inc, double *r, int max)
{
	int n = 0;
	for (int k = 0; k < j->nlog && n < max; k++)
		if (j->inc[k] == inc)
			r[n++] = j->r[k];
	for (int k = n - 1; k >= 0; k--)
		r[k] /= r[0];
	return n;
}

/* Quadratic convergence in increment inc: for the iterations in the
 * asymptotic range (residual at most 1e-2 of the increment's first, the
 * next above the round-off floor, a fraction of the first), r_{k+1} <= 100
 * r_k^2 and r_{k+1} <= 0.01 r_k; a linear rate of 0.1 fails the second. */
static void assert_quadratic_inc(const job_t *j, int inc, double floor)
{
	double r[64];
	int n = increment_residuals(j, inc, r, 64), checked = 0;
	for (int k = 0; k + 1 < n; k++)
		if (r[k] <= 1e-2 && r[k + 1] >= floor) {
			assert_true(r[k + 1] <= 100 * r[k] * r[k]);
			assert_true(r[k + 1] <= 0.01 * r[k]);
			checked++;
		}
	assert_true(checked >= 1);
}

/* The same in the last increment, the floor about 1e-10 of its first
 * residual in the tests that use it. */
static void assert_quadratic(const job_t *j)
{
	assert_quadratic_inc(j, j->inc[j->nlog - 1], 1e-10);
}

/* Ch. 8.5.1: the mapped profile may violate the yield condition.  The
 * 4 mm strip of Al 7050 (yield 450 MPa, hardening 120 MPa) given 1.5 times
 * the test profile (peak 600 MPa): the redistribution relieves the layer
 * by about 130 MPa, not enough, so the last of 4 load increments yields.
 * Newton with the consistent tangent converges quadratically; the final
 * stresses are on or inside the yield surface; the plate differs from the
 * elastic one.  (Here the unpeened face does not yield: by the closed form
 * it receives at most a third of the peened layer's stress, and without
 * hardening a layer inside the yield surface cannot make it yield; with a
 * strain-hardened layer it can: test_j2_unpeened_face.) */
static void test_j2_plate(void **state)
{
	(void)state;
	job_t j;
	dem_error_t e = { 0 };
	job_init(&j, 150 * MM, 50 * MM, 4 * MM, 10 * MM, 8, 1.3, 450 * MPA);
	j.o.ninc = 4;
	assert_int_equal(job_solve(&j, 1.5, 0, &e), DEM_OK);
	assert_int_equal(j.st.increments, 4);
	assert_quadratic(&j);
	assert_true(j.st.rrel <= j.o.tol);
	const dem_hex8_hist_t *h = dem_form_hist(j.f);
	double dep = 0;
	prof_t q;
	make_profile(&q, 1, 0);
	for (size_t el = 0; el < j.mesh.ne; el++)
		for (int p = 0; p < 8; p++) {
			double X[24], xg[24], ep0;
			dem_mesh_gather(&j.mesh, el, NULL, X);
			dem_hex8_gauss_points(X, xg);
			dem_profile_eval(&q.p, -xg[16 + p], NULL, NULL, &ep0);
			dep = fmax(dep, h[el].ep[p] - ep0);
			double sf = dem_mat_flow_stress(&j.mat, h[el].ep[p], 0);
			assert_true(dem_mat_mises(h[el].sig + 6 * p) <= sf * (1 + 1e-6));
		}
	assert_true(dep > 1e-4);  /* it yielded */
	job_free(&j);

	/* the elastic plate's stresses go beyond the flow stress */
	job_init(&j, 150 * MM, 50 * MM, 4 * MM, 10 * MM, 8, 1.3, 0);
	assert_int_equal(job_solve(&j, 1.5, 0, &e), DEM_OK);
	double mises = 0;
	h = dem_form_hist(j.f);
	for (size_t el = 0; el < j.mesh.ne; el++)
		for (int p = 0; p < 8; p++)
			mises = fmax(mises, dem_mat_mises(h[el].sig + 6 * p));
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "elastic centre mises %g\n", mises);
	assert_true(mises > 1.02 * (450 + 120 * 0.05) * MPA);
	job_free(&j);
}

/* ---- Acceptance 3: the unpeened face yields (Ch. 8.5 remark) ---------------------- */

/* Without hardening the unpeened face of a free plate cannot yield: a thin
 * slice of stress s at depth t changes the bottom stress by s (2 - 6 t/h)
 * dt / h (the closed form), so a layer bounded by the yield stress gives
 * the bottom at most a third of it (a uniform layer of depth h/3).  A
 * peened layer is strain hardened, though, and the unpeened face is virgin:
 * the face yields when the layer's flow stress is above three times the
 * initial yield stress.
 *
 * The material: 316 stainless steel of Table 7.2 (Ch. 7.6; compression
 * tests): E 193 GPa, nu 0.328, yield 366 MPa, work hardening 2430 MPa
 * (linear; rate dependence left out of the static stage).  Three times the
 * yield stress needs ep = 0.30; Table 7.1's curve (349.8 MPa rising to
 * 892.7 MPa at 0.0975) stays below 2.6 times its yield stress and could not
 * do it.  The profile (made up; equi-biaxial): ep falls linearly from 0.5
 * at the surface to 0 at 0.5 mm; the compressive layer, 0.25 mm deep, is on
 * its hardened flow surface, sxx = syy = -(366 MPa + 2430 MPa ep), from
 * -1581 MPa at the surface to -973.5 MPa at 0.25 mm; the stress returns to
 * zero at 0.28 mm (inside the flow surface there) and stays zero below.
 * The plate: 0.75 mm thick (the layer a third of it), 6 x 6 mm, free. */
#define E_SS 193e9
#define NU_SS 0.328
#define SY_SS (366 * MPA)
#define H_SS (2430 * MPA)
#define SS_H (0.75 * MM)

static void make_hardened(prof_t *q)
{
	static const double dep[4] = { 0, 0.25 * MM, 0.28 * MM, 0.5 * MM };
	memset(q, 0, sizeof *q);
	for (int k = 0; k < 4; k++) {
		q->depth[k] = dep[k];
		q->ep[k] = 0.5 * (1 - dep[k] / (0.5 * MM));
		if (k < 2)
			q->sig[6 * k] = q->sig[6 * k + 1] = -(SY_SS + H_SS * q->ep[k]);
	}
	q->p.n = 4;
	q->p.depth = q->depth;
	q->p.sig = q->sig;
	q->p.eps = q->eps;
	q->p.ep = q->ep;
}

/* The closed form for the elastic plate: sxx at depth t,
 * s(t) - I0/h - 12 I1 (h/2 - t) / h^3 with I0 = int s dd and
 * I1 = int s (h/2 - d) dd (Simpson, exact per segment); the curvature. */
static double hardened_elastic_stress(const prof_t *q, double h, double t, double *kappa)
{
	double I0 = 0, I1 = 0;
	for (size_t k = 0; k + 1 < q->p.n; k++) {
		double a = q->depth[k], b = q->depth[k + 1];
		for (int g = 0; g < 3; g++) {
			double u = 0.5 * g, d = a + u * (b - a), w = (b - a) * (g == 1 ? 4 : 1) / 6.0;
			double v = q->sig[6 * k] + u * (q->sig[6 * (k + 1)] - q->sig[6 * k]);
			I0 += w * v;
			I1 += w * v * (h / 2 - d);
		}
	}
	double sig[6];
	dem_profile_eval(&q->p, t, sig, NULL, NULL);
	*kappa = -12 * (1 - NU_SS) * I1 / (E_SS * h * h * h);
	return sig[0] - I0 / h - 12 * I1 * (h / 2 - t) / (h * h * h);
}

/* Brute force for the J2 plate: the plate as a stack of n plane-stress
 * layers under equi-biaxial in-plane strain a + kappa (h/2 - t) (Kirchhoff),
 * each with the 1D form of the J2 return for an equi-biaxial state
 * (s = E/(1-nu) (e - e_p), |s| <= sy(ep), ep = 2 |e_p|), the same load
 * increments, Newton on (a, kappa) for zero force and moment.  Returns the
 * curvature and the ep of the layer at depth tb. */
static double strip_j2(const prof_t *q, double h, int ninc, int plastic, double tb, double *ep_tb)
{
	enum { N = 3000 };
	static double sb[N], s[N], ep[N], sn[N], epn[N];
	double Ep = E_SS / (1 - NU_SS), w = h / N, kap = 0;
	for (int i = 0; i < N; i++) {
		double sig[6];
		dem_profile_eval(&q->p, (i + 0.5) * w, sig, NULL, &ep[i]);
		sb[i] = sig[0];
		s[i] = 0;
	}
	for (int inc = 0; inc < ninc; inc++) {
		for (int i = 0; i < N; i++) {
			sn[i] = s[i] + sb[i] / ninc;
			epn[i] = ep[i];
		}
		double da = 0, dk = 0;
		for (int it = 0; it < 50; it++) {
			double F = 0, M = 0, Kaa = 0, Kak = 0, Kkk = 0;
			for (int i = 0; i < N; i++) {
				double z = h / 2 - (i + 0.5) * w, st = sn[i] + Ep * (da + dk * z), D = Ep;
				double f = fabs(st) - (SY_SS + H_SS * epn[i]);
				ep[i] = epn[i];
				if (plastic && f > 0) {
					double dp = f / (Ep + 2 * H_SS);
					st -= copysign(Ep * dp, st);
					ep[i] += 2 * dp;
					D = Ep * 2 * H_SS / (Ep + 2 * H_SS);
				}
				s[i] = st;
				F += w * st;
				M += w * st * z;
				Kaa += w * D;
				Kak += w * D * z;
				Kkk += w * D * z * z;
			}
			if (hypot(F, M / h) <= 1e-10 * SY_SS * h)
				break;
			double det = Kaa * Kkk - Kak * Kak;
			da -= (Kkk * F - Kak * M) / det;
			dk -= (Kaa * M - Kak * F) / det;
		}
		kap += dk;
	}
	int i = (int)(tb / w);
	*ep_tb = ep[i < N ? i : N - 1];
	return kap;
}

/* The curvature fitted over the central 2 x 2 mm, where the plate's
 * free edges do not reach. */
static double centre_curvature(job_t *j)
{
	dem_form_shape_t sh;
	dem_error_t e = { 0 };
	double L = j->mesh.gx[j->mesh.nx] - j->mesh.gx[0];
	assert_int_equal(dem_form_shape(j->f, L, 0, 2 * MM / L, 2 * MM / L, &sh, &e), DEM_OK);
	return sh.kx;
}

/* The hardened profile on the thin SS316 plate, 4 load increments.
 * Predicted before solving: the elastic plate's bottom face is at
 * -457.9 MPa (closed form; 1.25 times the initial yield stress), so the
 * face yields from lambda = 0.80 on, in the last increment.
 *
 * The mesh: in-plane elements of 0.5 mm, less than the thickness.  With
 * elements wider than the plate is thick (1-2 mm) the free edges, where
 * the layer ends, leave an element-to-element ringing of the bottom stress
 * (30 % at the edge, shrinking by a factor 0.5-0.7 per element inwards,
 * measured); with 0.5 mm it stays within 1 mm of the edges.  The claims
 * are for the central 2 x 2 mm.  12 layers, thinnest (0.04 mm) at both
 * faces.
 *
 * Asserted: the elastic plate's bottom stress (deepest Gauss point, centre)
 * and curvature within 2 % of the closed form (0.2 % and 0.6 % measured);
 * with J2, the increments up to lambda = 0.5 are elastic (one iteration,
 * to the round-off floor), those after the face's first yield take more
 * and converge quadratically; every bottom Gauss point of the centre
 * yielded (ep up from 0); its ep within 10 % of the layered plate's
 * (0.2 % measured); above the two bottom layers nothing yielded at the
 * centre (the layer is relieved, the tension below it is inside the
 * hardened flow surface); every stress is within the flow surface; the
 * curvature exceeds the elastic one by the layered plate's margin (0.92 %)
 * within 20 % (0.86 % measured; on a 5 mm plate the edge zones take it to
 * 0.75 %, on a 10 mm plate it is 0.88 %). */
static void test_j2_unpeened_face(void **state)
{
	(void)state;
	const int ninc = 4;
	dem_plate_t pl = { 6 * MM, 6 * MM, SS_H, 0.5 * MM, 12, 1.15, 1 };
	dem_mat_param_t mp = { .E = E_SS, .nu = NU_SS };
	prof_t q;
	make_hardened(&q);
	dem_error_t e = { 0 };
	job_t j;
	double dep[400], sig[2400], ep[400];
	int n;

	/* elastic: the closed form at the deepest Gauss point */
	job_init_plate(&j, &pl, &mp);
	assert_int_equal(dem_form_profile(j.f, &q.p, &TOP, DEM_FORM_SIGMA, 1, &e), DEM_OK);
	dem_form_constrain(j.f, NULL, 1);
	assert_int_equal(dem_form_step(j.f, &j.o, &j.st, &e), DEM_OK);
	dem_form_centre_profile(j.f, &n, dep, sig, ep);
	double tb = dep[n - 1], kap_cf;
	double sb_cf = hardened_elastic_stress(&q, SS_H, tb, &kap_cf);
	double sb_el = sig[6 * (n - 1)], kap_el = centre_curvature(&j);
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "elastic: bottom at %.4f mm: sxx %.2f MPa (closed form %.2f, face %.2f); "
			"kappa %.5f (closed form %.5f) 1/m\n", tb / MM, sb_el / MPA, sb_cf / MPA,
			hardened_elastic_stress(&q, SS_H, SS_H, &kap_cf) / MPA, kap_el, kap_cf);
	assert_true(fabs(sb_el / sb_cf - 1) < 0.02);
	assert_true(fabs(sig[6 * (n - 1) + 1] / sb_cf - 1) < 0.02);
	assert_true(fabs(kap_el / kap_cf - 1) < 0.02);
	/* the prediction: the face at 1.25 times the initial yield stress */
	assert_true(fabs(hardened_elastic_stress(&q, SS_H, SS_H, &kap_cf) / (-1.25 * SY_SS) - 1) < 0.01);
	job_free(&j);

	/* J2 */
	mp.sy0 = SY_SS;
	mp.H = H_SS;
	job_init_plate(&j, &pl, &mp);
	j.o.ninc = ninc;
	assert_int_equal(dem_form_profile(j.f, &q.p, &TOP, DEM_FORM_SIGMA, 1, &e), DEM_OK);
	dem_form_constrain(j.f, NULL, 1);
	assert_int_equal(dem_form_step(j.f, &j.o, &j.st, &e), DEM_OK);
	assert_int_equal(j.st.increments, ninc);
	assert_int_equal(j.st.cutbacks, 0);
	double lam_y = SY_SS / fabs(sb_el), floor = 0;
	for (int inc = 1; inc <= ninc; inc++) {
		double r[64];
		int nr = increment_residuals(&j, inc, r, 64);
		if (getenv("TEST_VERBOSE")) {
			fprintf(stderr, "increment %d (lambda %.3f):", inc, (double)inc / ninc);
			for (int k = 0; k < nr; k++)
				fprintf(stderr, " %.2e", r[k]);
			fprintf(stderr, "\n");
		}
		if (2 * inc <= ninc) {
			/* linear: solved in one iteration, to the round-off floor */
			assert_int_equal(nr, 2);
			floor = fmax(floor, 10 * r[1]);
		} else if (inc > ninc * lam_y * 1.02) {
			assert_true(nr >= 3);
			assert_quadratic_inc(&j, inc, floor);
		}
	}
	const dem_hex8_hist_t *h = dem_form_hist(j.f);
	double zb = j.mesh.gz[0] + 0.5 * (j.mesh.gz[1] - j.mesh.gz[0]), epmin = HUGE_VAL;
	int nbottom = 0;
	for (size_t el = 0; el < j.mesh.ne; el++) {
		double X[24], xg[24];
		dem_mesh_gather(&j.mesh, el, NULL, X);
		dem_hex8_gauss_points(X, xg);
		for (int p = 0; p < 8; p++) {
			double sf = dem_mat_flow_stress(&j.mat, h[el].ep[p], 0), ep0;
			assert_true(dem_mat_mises(h[el].sig + 6 * p) <= sf * (1 + 1e-6));
			dem_profile_eval(&q.p, -xg[16 + p], NULL, NULL, &ep0);
			if (fabs(xg[p]) > 1 * MM || fabs(xg[8 + p]) > 1 * MM)
				continue;
			/* elastic above the two bottom layers (0.09 mm; the
			 * layered plate yields to 0.04 mm above the face) */
			if (xg[16 + p] > j.mesh.gz[2])
				assert_true(h[el].ep[p] == ep0);
			if (xg[16 + p] < zb) {
				epmin = fmin(epmin, h[el].ep[p]);
				nbottom++;
			}
		}
	}
	dem_form_centre_profile(j.f, &n, dep, sig, ep);
	double ep_ref, ep_el;
	double kap_ref = strip_j2(&q, SS_H, ninc, 1, dep[n - 1], &ep_ref);
	double kap_ref_el = strip_j2(&q, SS_H, ninc, 0, dep[n - 1], &ep_el);
	double kap = centre_curvature(&j);
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "J2: %d bottom points, ep >= %.3g; centre bottom ep %.3g (layered %.3g), "
			"sxx %.2f MPa; kappa %.5f / elastic %.5f = %.5f (layered %.5f)\n", nbottom, epmin,
			ep[n - 1], ep_ref, sig[6 * (n - 1)] / MPA, kap, kap_el, kap / kap_el,
			kap_ref / kap_ref_el);
	assert_int_equal(nbottom, 4 * 4 * 4);
	assert_true(epmin > 0);
	assert_true(fabs(ep[n - 1] / ep_ref - 1) < 0.1);
	double dk = kap / kap_el - 1, dk_ref = kap_ref / kap_ref_el - 1;
	/* the layered plate's own check: elastic, the closed form */
	assert_true(fabs(kap_ref_el / kap_cf - 1) < 1e-3);
	assert_true(dk_ref > 0.005);
	assert_true(fabs(dk / dk_ref - 1) < 0.2);
	job_free(&j);
}

/* A forced divergence: allowed only 4 Newton iterations, the large-strain
 * increment that needs 7 is cut back, and the smaller increments reach
 * lambda = 1 and the same (elastic, path-independent) solution. */
static void test_cutback(void **state)
{
	(void)state;
	job_t j;
	dem_error_t e = { 0 };
	job_init(&j, 150 * MM, 50 * MM, 2 * MM, 10 * MM, 8, 1.2, 0);
	j.o.large = 1;
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
	assert_int_equal(j.st.cutbacks, 0);
	assert_true(j.st.iterations > 3);
	dem_form_shape_t ref = job_shape(&j);
	job_free(&j);

	job_init(&j, 150 * MM, 50 * MM, 2 * MM, 10 * MM, 8, 1.2, 0);
	j.o.large = 1;
	j.o.maxit = 4;
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
	assert_true(j.st.cutbacks >= 1);
	assert_true(j.st.increments >= 2);
	assert_true(j.st.lambda == 1);
	dem_form_shape_t sh = job_shape(&j);
	assert_true(fabs(sh.kx / ref.kx - 1) < 1e-6);
	assert_true(fabs(sh.arc / ref.arc - 1) < 1e-6);
	job_free(&j);

	/* no iteration at all allowed: every cut-back fails, the step reports
	 * DEM_ENUMERIC and keeps the last converged (undeformed) state */
	job_init(&j, 50 * MM, 20 * MM, 2 * MM, 10 * MM, 4, 1.2, 0);
	j.o.maxit = 1;
	j.o.large = 1;
	j.o.maxcut = 2;
	assert_int_equal(job_solve(&j, 1, 0, &e), DEM_ENUMERIC);
	assert_true(strstr(e.msg, "cut-backs") != NULL);
	assert_true(j.st.lambda < 1);
	job_free(&j);
}

/* Small and large strain: the 4 mm strip of Ch. 8.6 (arc height a quarter
 * of the thickness) agrees within 1 % (0.13 % measured); a 2 mm strip (arc
 * height about twice the thickness) differs by more than 2 % (3.1 %), and its large-strain
 * solution is in equilibrium: a further step without loads starts with a
 * residual below the tolerance and takes no iteration.  Newton converges
 * quadratically in both large-strain solutions. */
static void test_small_large(void **state)
{
	(void)state;
	dem_error_t e = { 0 };
	double arc[2][2];
	for (int t = 0; t < 2; t++)
		for (int large = 0; large < 2; large++) {
			job_t j;
			double h = t ? 2 * MM : 4 * MM;
			job_init(&j, 150 * MM, 50 * MM, h, 10 * MM, 8, 1.3, 0);
			j.o.large = large;
			assert_int_equal(job_solve(&j, 1, 0, &e), DEM_OK);
			arc[t][large] = job_shape(&j).arc;
			if (large && t)
				assert_quadratic(&j);
			if (t && large) {
				int it = j.st.iterations;
				double fnorm = j.st.fnorm;
				dem_form_constrain(j.f, NULL, 1);
				j.nlog = 0;
				assert_int_equal(dem_form_step(j.f, &j.o, &j.st, &e), DEM_OK);
				assert_int_equal(j.st.iterations, it);
				assert_int_equal(j.nlog, 1);
				/* the residual of the formed plate, against its load */
				assert_true(j.r[0] <= j.o.tol * fnorm);
			}
			job_free(&j);
		}
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "arcs %g %g %g %g\n", arc[0][0], arc[0][1], arc[1][0], arc[1][1]);
	assert_true(fabs(arc[0][1] / arc[0][0] - 1) < 0.01);
	assert_true(fabs(arc[1][1] / arc[1][0] - 1) > 0.02);
}

/* ---- The Almen gauge (issue 25) ------------------------------------------------ */

/* The closed form of a free plate of material (E, nu) under the test
 * profile scaled by s, equi-biaxial (sxx = syy) or uniaxial (sxx only):
 * with M = int s z dz (z from the mid-plane), equi-biaxial
 * kx = ky = -12 (1-nu) M / (E h^3) (DESIGN.md); uniaxial, the moment
 * balances int sxx z = int syy z = 0 of the plane-stress plate give
 * kx = -12 M / (E h^3), ky = -nu kx. */
static void closed_form_mat(double E, double nu, double s, double h, int uniaxial,
			    double *kx, double *ky)
{
	double I0, I1;
	profile_moments(s, h, &I0, &I1);
	if (uniaxial) {
		*kx = -12 * I1 / (E * h * h * h);
		*ky = -nu * *kx;
	} else {
		*kx = *ky = -12 * (1 - nu) * I1 / (E * h * h * h);
	}
}

/* Solve the free plate (L x W x h, elements dxy, nz layers graded 1.2) of
 * (E, nu) under the test profile, equi-biaxial or uniaxial; read the gauge
 * on the lx x ly rectangle; check it against kx lx^2/8 + ky ly^2/8 of the
 * closed form and of the curvatures fitted to the solution, within tol. */
static void gauge_case(double L, double W, double h, double dxy, int nz, double E, double nu,
		       int uniaxial, double lx, double ly, double tol)
{
	job_t j;
	dem_error_t e = { 0 };
	dem_plate_t pl = { L, W, h, dxy, nz, 1.2, 0 };
	dem_mat_param_t mp = { .E = E, .nu = nu };
	job_init_plate(&j, &pl, &mp);
	prof_t q;
	make_profile(&q, 1, 0);
	if (uniaxial)
		for (int k = 0; k < NP; k++)
			q.sig[6 * k + 1] = 0;
	assert_int_equal(dem_form_profile(j.f, &q.p, &TOP, DEM_FORM_SIGMA, 1, &e), DEM_OK);
	dem_form_constrain(j.f, NULL, 1);
	assert_int_equal(dem_form_step(j.f, &j.o, &j.st, &e), DEM_OK);
	double kx, ky, g;
	closed_form_mat(E, nu, 1, h, uniaxial, &kx, &ky);
	assert_int_equal(dem_form_gauge(j.f, lx, ly, &g, &e), DEM_OK);
	double ref = kx * lx * lx / 8 + ky * ly * ly / 8;
	dem_form_shape_t sh = job_shape(&j);
	double fit = sh.kx * lx * lx / 8 + sh.ky * ly * ly / 8;
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "gauge %g x %g on %g x %g x %g: %.6g m; closed form %.6g (%+.3f %%), "
			"fitted curvatures %.6g (%+.3f %%); kx %.5g ky %.5g (closed %.5g %.5g)\n",
			lx, ly, L, W, h, g, ref, 100 * (g / ref - 1), fit, 100 * (g / fit - 1),
			sh.kx, sh.ky, kx, ky);
	assert_true(fabs(g / ref - 1) < tol);
	assert_true(fabs(g / fit - 1) < tol);
	/* a rectangle off the plate is refused */
	assert_int_equal(dem_form_gauge(j.f, 1.01 * L, ly, &g, &e), DEM_EINPUT);
	job_free(&j);
}

/* Acceptance 1 of issue 25, on the Almen A strip (76.2 x 19.05 x 1.295 mm,
 * steel: E 210 GPa, nu 0.3) with the J442 default rectangle (31.75 x
 * 15.875 mm): the reading is kx p^2/2 + ky q^2/2 (p, q the half-sides)
 * within 0.5 %. */
static void test_gauge_almen_strip(void **state)
{
	(void)state;
	gauge_case(76.2 * MM, 19.05 * MM, 1.295 * MM, 1.27 * MM, 12, 210e9, 0.3, 0,
		   31.75 * MM, 15.875 * MM, 0.005);
}

/* The same on a rectangular plate (60 x 40 x 2 mm, the aluminium of the
 * tests) with balls on a 40 x 20 mm rectangle; and under a uniaxial profile
 * (ky = -nu kx: the transverse term subtracts), which tells the two sides
 * of the rectangle apart. */
static void test_gauge_plate(void **state)
{
	(void)state;
	gauge_case(60 * MM, 40 * MM, 2 * MM, 2 * MM, 14, E_AL, NU_AL, 0, 40 * MM, 20 * MM, 0.005);
	gauge_case(60 * MM, 40 * MM, 2 * MM, 2 * MM, 14, E_AL, NU_AL, 1, 40 * MM, 20 * MM, 0.005);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_plate_mesh),
		cmocka_unit_test(test_free_plate_ch86),
		cmocka_unit_test(test_free_plate_fine),
		cmocka_unit_test(test_full_integration_locks),
		cmocka_unit_test(test_strain_initial_condition),
		cmocka_unit_test(test_large_matches_small),
		cmocka_unit_test(test_large_tangent_fd),
		cmocka_unit_test(test_large_rigid_rotation),
		cmocka_unit_test(test_j2_plate),
		cmocka_unit_test(test_j2_unpeened_face),
		cmocka_unit_test(test_cutback),
		cmocka_unit_test(test_small_large),
		cmocka_unit_test(test_gauge_almen_strip),
		cmocka_unit_test(test_gauge_plate),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
