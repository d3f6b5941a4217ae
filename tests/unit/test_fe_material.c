/* test_fe_material.c - unit tests of lib/fe/material.c: isotropic
 * elasticity and J2 plasticity with isotropic hardening and rate dependence.
 *
 * References: Hooke's law; the uniaxial closed form of linear hardening;
 * the hardening curve of Table 7.1 (Han 2004, Ch. 7.4, via thesis-data.yaml,
 * hardening_table_7_1), which the uniaxial response must reproduce; the
 * Table 7.2 rate exponents with the power law documented in material.c; and
 * a central finite-difference derivative of the stress update for the
 * consistent tangent of Simo & Taylor (1985).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/consts.h"
#include "fe/material.h"

#define MPA 1e6
#define GPA 1e9
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Table 7.1: effective plastic strain -> flow stress (N/mm^2) */
static const double t71_ep[] = { 0.0, 0.0017, 0.0039, 0.0079, 0.0153, 0.0288, 0.0533, 0.0975 };
static const double t71_sy[] = { 349.793, 605.419, 645.896, 689.08, 735.152, 784.303, 836.741, 892.684 };

/* Ch. 7.4 workpiece with the Table 7.1 curve: E = 2.1e5 N/mm^2, nu = 0.3. */
static void make_t71(dem_mat_t *m, double *ep, double *sy)
{
	for (size_t k = 0; k < COUNT(t71_ep); k++) {
		ep[k] = t71_ep[k];
		sy[k] = t71_sy[k] * MPA;
	}
	dem_mat_param_t p = { .E = 2.1e5 * MPA, .nu = 0.3, .rho = 7800,
			      .nhard = (int)COUNT(t71_ep), .hard_ep = ep, .hard_sy = sy };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

static void make_linear(dem_mat_t *m, double E, double nu, double sy0, double H, double rate_m)
{
	dem_mat_param_t p = { .E = E, .nu = nu, .rho = 2700, .sy0 = sy0, .H = H, .rate_m = rate_m,
			      .rate_law = rate_m > 0 ? DEM_RATE_POWER : DEM_RATE_NONE, .rate_ref = 1 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

static double rel(double a, double b)
{
	return fabs(a - b) / fmax(fabs(b), 1e-300);
}

/* Hooke's law: the update of an elastic material is D deps with
 * D = lambda 1(x)1 + 2 mu I (engineering shears: mu on the shear diagonal);
 * the uniaxial driver recovers E and nu. */
static void test_elastic(void **state)
{
	(void)state;
	dem_mat_t m;
	dem_mat_param_t p = { .E = 200 * GPA, .nu = 0.25, .rho = 7800 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(&m, &p, &e), DEM_OK);
	assert_true(dem_mat_update_select(&m) == dem_mat_update_elastic);
	assert_true(rel(m.G, 80 * GPA) < 1e-15);
	assert_true(rel(m.K, 200 * GPA / 1.5) < 1e-15);
	assert_true(rel(m.wave, sqrt((m.K + 4 * m.G / 3) / 7800)) < 1e-15);

	double d[6] = { 1e-3, -2e-4, 3e-4, 5e-4, -1e-4, 2e-4 }, s[6] = { 0 }, ep = 0, wp = 1;
	assert_int_equal(dem_mat_update(&m, d, 1e-6, s, &ep, NULL, &wp), 0);
	double tr = d[0] + d[1] + d[2];
	for (int i = 0; i < 3; i++)
		assert_true(rel(s[i], m.lam * tr + 2 * m.G * d[i]) < 1e-14);
	for (int i = 3; i < 6; i++)
		assert_true(rel(s[i], m.G * d[i]) < 1e-14);
	assert_true(wp == 0 && ep == 0);

	double eps[6] = { 0 }, sig[6] = { 0 };
	ep = 0;
	assert_int_equal(dem_mat_uniaxial(&m, 1e-3, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(rel(sig[0] / eps[0], 200 * GPA) < 1e-12);
	assert_true(rel(-eps[1] / eps[0], 0.25) < 1e-12);
	assert_true(fabs(sig[1]) < 1e-6 && fabs(sig[2]) < 1e-6);
	/* no yield stress: elastic at any stress */
	assert_int_equal(dem_mat_uniaxial(&m, 0.5, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(ep == 0);
	dem_mat_free(&m);
}

/* Bad parameters are refused with a message. */
static void test_invalid(void **state)
{
	(void)state;
	dem_mat_t m;
	dem_error_t e;
	static const double ep_bad0[] = { 0.01, 0.02 }, sy_ok[] = { 100e6, 120e6 };
	static const double ep_ok[] = { 0, 0.02 }, sy_down[] = { 100e6, 90e6 };
	const dem_mat_param_t bad[] = {
		{ .E = -1, .nu = 0.3 },
		{ .E = 1e9, .nu = 0.5 },
		{ .E = 1e9, .nu = 0.3, .rho = -1 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .H = -1 },
		{ .E = 1e9, .nu = 0.3, .nhard = 2, .hard_ep = ep_bad0, .hard_sy = sy_ok },
		{ .E = 1e9, .nu = 0.3, .nhard = 2, .hard_ep = ep_ok, .hard_sy = sy_down },
		{ .E = 1e9, .nu = 0.3, .rate_m = 0.05 },   /* rate without yield */
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .rate_m = 1.5, .rate_ref = 1 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .rate_m = 0.05 },   /* no reference rate */
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .rate_law = DEM_RATE_JC, .jc_C = 0.01 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .rate_law = DEM_RATE_CS, .cs_D = 100 },
		{ .E = 1e9, .nu = 0.3, .law = DEM_LAW_VOCE, .sy0 = 1e6, .voce_Q = 1e6 },  /* no b */
		{ .E = 1e9, .nu = 0.3, .law = DEM_LAW_JC, .jc_A = 1e6, .jc_B = 1e6 },     /* no n */
		{ .E = 1e9, .nu = 0.3, .law = DEM_LAW_JC, .jc_A = 1e6, .jc_n = 0.5, .T = 300,
		  .T_ref = 293, .T_melt = 280, .mt = 1 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .nkin = 4 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .nkin = 1, .kin_C = { 0 } },
		{ .E = 1e9, .nu = 0.3, .nkin = 1, .kin_C = { 1e9 } },   /* back-stress, elastic */
	};
	for (size_t i = 0; i < COUNT(bad); i++) {
		dem_error_clear(&e);
		assert_int_equal(dem_mat_init(&m, &bad[i], &e), DEM_EINPUT);
		assert_true(strncmp(e.msg, "material: ", 10) == 0);
		dem_mat_free(&m);
	}
}

/* Uniaxial stress with the Table 7.1 curve.  The total strain that puts the
 * effective plastic strain exactly on table point k is ep_k + sy_k / E; the
 * driver is taken there in steps (some landing on the knots, some crossing
 * several segments at once) and the axial stress must be the table's flow
 * stress to round-off (the acceptance asks 0.5 %). */
static void test_table71_uniaxial(void **state)
{
	(void)state;
	double hep[8], hsy[8];
	dem_mat_t m;
	make_t71(&m, hep, hsy);
	assert_true(dem_mat_update_select(&m) == dem_mat_update_j2);
	double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0;
	/* first yield */
	assert_int_equal(dem_mat_uniaxial(&m, hsy[0] / m.E, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(rel(sig[0], hsy[0]) < 1e-12);
	assert_true(ep == 0);
	for (int k = 1; k < 8; k++) {
		double target = hep[k] + hsy[k] / m.E;
		int nstep = k % 2 ? 7 : 1;   /* odd knots in steps, even ones in one jump */
		double e0 = eps[0];
		for (int s = 1; s <= nstep; s++) {
			double want = e0 + (target - e0) * s / nstep;
			assert_int_equal(dem_mat_uniaxial(&m, want - eps[0], 0, eps, sig, &ep, NULL), DEM_OK);
			/* consistency on the curve at every step */
			assert_true(rel(sig[0], dem_mat_flow_stress(&m, ep, 0)) < 1e-12);
		}
		assert_true(rel(sig[0], hsy[k]) < 1e-11);
		assert_true(fabs(ep - hep[k]) < 1e-12);
	}
	/* beyond the last point the last slope continues */
	double slope = (hsy[7] - hsy[6]) / (hep[7] - hep[6]);
	assert_int_equal(dem_mat_uniaxial(&m, 0.05, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(rel(sig[0], hsy[7] + slope * (ep - hep[7])) < 1e-12);
	assert_true(rel(eps[0], ep + sig[0] / m.E) < 1e-12);

	/* one large increment from the virgin state across all segments */
	double eps2[6] = { 0 }, sig2[6] = { 0 }, ep2 = 0;
	double target = hep[6] + hsy[6] / m.E;
	assert_int_equal(dem_mat_uniaxial(&m, target, 0, eps2, sig2, &ep2, NULL), DEM_OK);
	assert_true(rel(sig2[0], hsy[6]) < 1e-11);
	assert_true(fabs(ep2 - hep[6]) < 1e-12);
	dem_mat_free(&m);
}

/* Unloading is elastic with slope E; reloading in compression yields at the
 * current (isotropically hardened) flow stress. */
static void test_unloading(void **state)
{
	(void)state;
	double hep[8], hsy[8];
	dem_mat_t m;
	make_t71(&m, hep, hsy);
	double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0;
	for (int i = 0; i < 40; i++)
		assert_int_equal(dem_mat_uniaxial(&m, 5e-4, 0, eps, sig, &ep, NULL), DEM_OK);
	double s0 = sig[0], e0 = eps[0], ep0 = ep;
	assert_true(ep0 > 0.01);
	double de = -1e-3;
	assert_int_equal(dem_mat_uniaxial(&m, de, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(rel((sig[0] - s0) / (eps[0] - e0), m.E) < 1e-10);
	assert_true(ep == ep0);
	/* down to reverse yield at -sigma_y(ep0) */
	double rev = -dem_mat_flow_stress(&m, ep0, 0);
	assert_int_equal(dem_mat_uniaxial(&m, (rev - sig[0]) / m.E * (1 - 1e-9), 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(ep == ep0);
	assert_int_equal(dem_mat_uniaxial(&m, -1e-3, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(ep > ep0);
	assert_true(rel(sig[0], -dem_mat_flow_stress(&m, ep, 0)) < 1e-12);
	dem_mat_free(&m);
}

/* Linear hardening, uniaxial stress: with the plastic modulus H,
 *     sigma = sy + E H / (E + H) (eps - sy / E)   for eps > sy / E
 * (eps = sigma/E + ep and sigma = sy + H ep).  Materials: Ch. 7.5
 * aluminium (68 GPa, 157 MPa, 120 MPa; nu = 0.33 assumed) and Al 5052 of
 * Table 7.2 (69.3 GPa, nu 0.31, 148 MPa, H = 194 GPa).  The plastic work
 * of the steps sums to int sigma dep = sy ep + H ep^2 / 2 to the order of
 * the step. */
static void test_linear_hardening(void **state)
{
	(void)state;
	static const double par[][4] = {
		{ 68 * GPA, 0.33, 157 * MPA, 120 * MPA },
		{ 69.3 * GPA, 0.31, 148 * MPA, 194 * GPA },
	};
	for (size_t c = 0; c < COUNT(par); c++) {
		double E = par[c][0], sy = par[c][2], H = par[c][3];
		dem_mat_t m;
		make_linear(&m, E, par[c][1], sy, H, 0);
		double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0, W = 0;
		double ey = sy / E;
		for (int i = 1; i <= 400; i++) {
			double ep0 = ep;
			assert_int_equal(dem_mat_uniaxial(&m, 10 * ey / 400, 0, eps, sig, &ep, NULL), DEM_OK);
			double want = eps[0] <= ey ? E * eps[0] : sy + E * H / (E + H) * (eps[0] - ey);
			assert_true(rel(sig[0], want) < 1e-11);
			W += (ep - ep0) * sig[0];   /* dep sigma_f, as the update counts it */
		}
		double Wexact = sy * ep + H * ep * ep / 2;
		assert_true(rel(W, Wexact) < 2e-2);
		dem_mat_free(&m);
	}
}

/* The plastic work returned by the update is dep * sigma_f (backward
 * Euler): summed over a fine loading it converges to sy ep + H ep^2 / 2. */
static void test_plastic_work(void **state)
{
	(void)state;
	dem_mat_t m;
	double E = 68 * GPA, sy = 157 * MPA, H = 2 * GPA;
	make_linear(&m, E, 0.33, sy, H, 0);
	/* isochoric deviatoric strain path: plane of pure shear, loaded in
	 * equal steps well past yield */
	double sig[6] = { 0 }, ep = 0, W = 0, wp;
	int n = 4000;
	for (int i = 0; i < n; i++) {
		double d[6] = { 0, 0, 0, 4e-2 / n, 0, 0 };
		dem_mat_update(&m, d, 0, sig, &ep, NULL, &wp);
		W += wp;
	}
	assert_true(ep > 0.01);
	assert_true(rel(W, sy * ep + H * ep * ep / 2) < 1e-3);
	/* and in pure shear the flow stress is sqrt(3) tau */
	assert_true(rel(sqrt(3) * sig[3], sy + H * ep) < 1e-12);
	dem_mat_free(&m);
}

/* Rate dependence, sigma_f = sigma_y(ep) max(rate/rate_ref, 1)^m with the
 * effective plastic strain rate, rate_ref = 1/s here (material.c).  In steady
 * uniaxial flow of a perfectly plastic material the plastic rate equals the
 * imposed rate, so the flow stress is sy (rate)^m; with hardening the law
 * holds at every step with the rate dep/dt of that step. */
static void test_rate(void **state)
{
	(void)state;
	double E = 69.3 * GPA, sy = 148 * MPA, m_al = 0.0455;  /* Al 5052, Table 7.2 */
	dem_mat_t m;
	make_linear(&m, E, 0.31, sy, 0, m_al);
	assert_true(dem_mat_update_select(&m) == dem_mat_update_j2_rate);
	assert_true(m.rate_ref == 1.0);
	static const double rates[] = { 0.1, 1, 10, 1e3, 1e5 };
	for (size_t r = 0; r < COUNT(rates); r++) {
		double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0;
		double de = 2e-4, dt = de / rates[r];
		for (int i = 0; i < 200; i++)
			assert_int_equal(dem_mat_uniaxial(&m, de, dt, eps, sig, &ep, NULL), DEM_OK);
		double want = sy * fmax(pow(rates[r], m_al), 1);
		assert_true(rel(sig[0], want) < 1e-10);
	}
	dem_mat_free(&m);

	/* hardening and rate: the law at every step */
	double hep[8], hsy[8];
	for (int k = 0; k < 8; k++) {
		hep[k] = t71_ep[k];
		hsy[k] = t71_sy[k] * MPA;
	}
	dem_mat_param_t p = { .E = 2.1e5 * MPA, .nu = 0.3, .nhard = 8, .hard_ep = hep, .hard_sy = hsy,
			      .rate_law = DEM_RATE_POWER, .rate_m = 0.0303, .rate_ref = 10 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(&m, &p, &e), DEM_OK);
	double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0;
	int nplastic = 0;
	for (int i = 0; i < 300; i++) {
		double ep0 = ep, dt = 1e-7;
		assert_int_equal(dem_mat_uniaxial(&m, 5e-4, dt, eps, sig, &ep, NULL), DEM_OK);
		if (ep > ep0) {
			double rate = (ep - ep0) / dt;
			double want = dem_mat_flow_stress(&m, ep, 0) * pow(fmax(rate / 10, 1), 0.0303);
			assert_true(rel(sig[0], want) < 1e-11);
			assert_true(rel(sig[0], dem_mat_flow_stress(&m, ep, rate)) < 1e-11);
			nplastic++;
		}
	}
	assert_true(nplastic > 250);
	assert_true(ep > hep[7]);
	dem_mat_free(&m);
}

/* An absent effect and the same effect at zero agree: rate_m = 0 is the
 * rate-independent material (bit for bit), and so is a rate-dependent
 * material in a static increment (dt <= 0). */
static void test_absent_equals_zero(void **state)
{
	(void)state;
	dem_mat_t a, b;
	make_linear(&a, 200 * GPA, 0.3, 300 * MPA, 1 * GPA, 0);
	make_linear(&b, 200 * GPA, 0.3, 300 * MPA, 1 * GPA, 0.02);
	double d[6] = { 3e-3, -1e-3, -1e-3, 2e-3, 1e-3, -5e-4 };
	double sa[6] = { 0 }, sb[6] = { 0 }, ea = 0, eb = 0, wa, wb;
	assert_int_equal(dem_mat_update(&a, d, 1e-6, sa, &ea, NULL, &wa), 1);
	assert_int_equal(dem_mat_update(&b, d, 0, sb, &eb, NULL, &wb), 1);
	assert_memory_equal(sa, sb, sizeof sa);
	assert_true(ea == eb && wa == wb);
	dem_mat_free(&a);
	dem_mat_free(&b);
}

/* Central finite-difference derivative of the stress update. */
static void fd_tangent(const dem_mat_t *m, const double s0[6], double ep0,
		       const double d0[6], double dt, double h, double Dfd[36])
{
	for (int j = 0; j < 6; j++) {
		double sp[6], sm[6], dp[6], dm[6], e1 = ep0, e2 = ep0, w;
		memcpy(sp, s0, sizeof sp);
		memcpy(sm, s0, sizeof sm);
		memcpy(dp, d0, sizeof dp);
		memcpy(dm, d0, sizeof dm);
		dp[j] += h;
		dm[j] -= h;
		dem_mat_update(m, dp, dt, sp, &e1, NULL, &w);
		dem_mat_update(m, dm, dt, sm, &e2, NULL, &w);
		for (int i = 0; i < 6; i++)
			Dfd[6 * i + j] = (sp[i] - sm[i]) / (2 * h);
	}
}

static double tangent_error(const dem_mat_t *m, const double s0[6], double ep0,
			    const double d0[6], double dt, int *plastic)
{
	double s[6], ep = ep0, w, D[36], Dfd[36];
	memcpy(s, s0, sizeof s);
	*plastic = dem_mat_update_tangent(m, d0, dt, s, &ep, NULL, &w, D);
	/* the update with the tangent agrees with the plain update */
	double s2[6], ep2 = ep0;
	memcpy(s2, s0, sizeof s2);
	dem_mat_update(m, d0, dt, s2, &ep2, NULL, &w);
	for (int i = 0; i < 6; i++)
		assert_true(fabs(s[i] - s2[i]) <= 1e-12 * dem_mat_mises(s2) + 1e-6);
	fd_tangent(m, s0, ep0, d0, dt, 1e-9, Dfd);
	double err = 0, big = 0;
	for (int i = 0; i < 36; i++) {
		err = fmax(err, fabs(D[i] - Dfd[i]));
		big = fmax(big, fabs(D[i]));
		assert_true(fabs(D[i] - D[6 * (i % 6) + i / 6]) <= 1e-12 * big + 1e-3);  /* symmetric */
	}
	return err / big;
}

/* The algorithmic tangent is the derivative of the update: it matches a
 * central finite difference to 1e-6 (relative to its largest entry) in an
 * elastic state, in plastic states on one segment of the Table 7.1 curve,
 * with linear hardening, perfect plasticity and rate dependence. */
static void test_tangent_fd(void **state)
{
	(void)state;
	double hep[8], hsy[8];
	dem_mat_t mats[4];
	make_t71(&mats[0], hep, hsy);
	make_linear(&mats[1], 68 * GPA, 0.33, 157 * MPA, 120 * MPA, 0);
	make_linear(&mats[2], 200 * GPA, 0.3, 300 * MPA, 0, 0);
	make_linear(&mats[3], 69.3 * GPA, 0.31, 148 * MPA, 194 * GPA, 0.0455);
	/* a general (non-proportional) pre-stress and increment */
	static const double dir[6] = { 1.0, -0.3, -0.5, 0.8, 0.2, -0.4 };
	for (int k = 0; k < 4; k++) {
		dem_mat_t *m = &mats[k];
		double sy0 = dem_mat_flow_stress(m, 0, 0);
		double s0[6] = { 0.3 * sy0, -0.1 * sy0, 0.05 * sy0, 0.1 * sy0, 0, -0.05 * sy0 };
		double ep0 = k == 0 ? 0.02 : 0.005;   /* inside segment 4 of Table 7.1 */
		double ey = dem_mat_flow_stress(m, ep0, 0) / m->E;
		/* elastic: a small increment */
		double d[6];
		for (int i = 0; i < 6; i++)
			d[i] = 0.01 * ey * dir[i];
		int plastic;
		double err = tangent_error(m, s0, ep0, d, 1e-6, &plastic);
		printf("# material %d: elastic tangent vs finite difference: %.1e\n", k, err);
		assert_int_equal(plastic, 0);
		assert_true(err < 1e-6);
		/* plastic: an increment well past yield */
		for (int i = 0; i < 6; i++)
			d[i] = 2 * ey * dir[i];
		err = tangent_error(m, s0, ep0, d, 1e-6, &plastic);
		printf("# material %d: plastic tangent vs finite difference: %.1e\n", k, err);
		assert_int_equal(plastic, 1);
		assert_true(err < 1e-6);
		dem_mat_free(m);
	}
}

/* The batched update (explicit loop) gives bit for bit the results of the
 * scalar one, dem_mat_jaumann followed by dem_mat_update with deps = d dt,
 * lane by lane: for an elastic material, linear hardening, the Table 7.1
 * curve (with steps that cross table points, redone lane by lane) and rate
 * dependence, with a mix of elastic and plastic lanes, and with or without
 * the spin. */
static void test_batch_update(void **state)
{
	(void)state;
	enum { NB = DEM_MAT_NB };
	double hep[8], hsy[8];
	dem_mat_t mats[4];
	dem_mat_param_t pe = { .E = 72 * GPA, .nu = 0.33, .rho = 2800 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(&mats[0], &pe, &e), DEM_OK);
	make_linear(&mats[1], 72 * GPA, 0.33, 450 * MPA, 120 * MPA, 0);
	make_t71(&mats[2], hep, hsy);
	make_linear(&mats[3], 69.3 * GPA, 0.31, 148 * MPA, 194 * GPA, 0.0455);
	unsigned long seed = 1;
	int nplastic = 0, ncross = 0;
	for (int k = 0; k < 4; k++) {
		const dem_mat_t *m = &mats[k];
		double sy = k ? dem_mat_flow_stress(m, 0, 0) : 300 * MPA;
		double sig[6][NB], ep[NB] = { 0 }, ss[NB][6], es[NB] = { 0 };
		for (int l = 0; l < NB; l++)
			for (int c = 0; c < 6; c++)
				ss[l][c] = sig[c][l] = 0;
		for (int step = 0; step < 200; step++) {
			double d[6][NB], w[3][NB], wp[NB], dt = 1e-7;
			for (int l = 0; l < NB; l++) {
				/* lanes 0-1 load steadily, 2-3 wander (and unload) */
				for (int c = 0; c < 6; c++) {
					seed = seed * 6364136223846793005ul + 1442695040888963407ul;
					double r = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
					d[c][l] = (l < 2 ? (c == 0 ? 1.0 : c < 3 ? -0.4 : 0.1) + 0.3 * r : 4 * r) *
						  0.05 * sy / m->E / dt;
				}
				for (int c = 0; c < 3; c++)
					w[c][l] = (l - 1.5) * 1e3 * (c + 1);
			}
			int spin = step % 3 != 0;
			unsigned mask = dem_mat_update_batch(m, dt, d[0], spin ? w[0] : NULL, sig[0], ep, NULL, wp, NULL);
			for (int l = 0; l < NB; l++) {
				double dd[6], ww[3] = { w[0][l], w[1][l], w[2][l] }, wps;
				double ep0 = es[l];
				for (int c = 0; c < 6; c++)
					dd[c] = d[c][l] * dt;
				if (spin)
					dem_mat_jaumann(ss[l], ww, dt);
				int pl = dem_mat_update(m, dd, dt, ss[l], &es[l], NULL, &wps);
				assert_int_equal(pl, (int)(mask >> l & 1));
				for (int c = 0; c < 6; c++)
					assert_true(memcmp(&sig[c][l], &ss[l][c], sizeof(double)) == 0);
				assert_true(memcmp(&ep[l], &es[l], sizeof(double)) == 0);
				assert_true(memcmp(&wp[l], &wps, sizeof(double)) == 0);
				nplastic += pl;
				if (k == 2 && pl) {
					int crossed = 0;
					for (int t = 1; t < 8; t++)
						crossed |= ep0 < hep[t] && es[l] >= hep[t];
					ncross += crossed;
				}
			}
		}
		dem_mat_free(&mats[k]);
	}
	assert_true(nplastic > 500);
	assert_true(ncross >= 5);
}

/* Jaumann rotation: a body spinning at omega about z carries its stress
 * round; after a quarter turn in many small steps sigma_xx has become
 * sigma_yy (first-order update: error O(dt)). */
static void test_jaumann(void **state)
{
	(void)state;
	double s[6] = { 100, 0, 0, 0, 0, 0 };
	/* v = omega x r about z: L = [[0, -w], [w, 0]], W_xy = -w */
	double omega = 1, w[3] = { -omega, 0, 0 };
	int n = 20000;
	double dt = DEM_PI / 2 / n;
	for (int i = 0; i < n; i++)
		dem_mat_jaumann(s, w, dt);
	assert_true(fabs(s[0]) < 0.05 && fabs(s[1] - 100) < 0.05);
	assert_true(fabs(s[2]) < 1e-12 && fabs(s[4]) < 1e-12 && fabs(s[5]) < 1e-12);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_elastic),
		cmocka_unit_test(test_invalid),
		cmocka_unit_test(test_table71_uniaxial),
		cmocka_unit_test(test_unloading),
		cmocka_unit_test(test_linear_hardening),
		cmocka_unit_test(test_plastic_work),
		cmocka_unit_test(test_rate),
		cmocka_unit_test(test_absent_equals_zero),
		cmocka_unit_test(test_tangent_fd),
		cmocka_unit_test(test_batch_update),
		cmocka_unit_test(test_jaumann),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
