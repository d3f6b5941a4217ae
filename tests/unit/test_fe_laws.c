/* test_fe_laws.c - unit tests of the hardening and rate laws of
 * lib/fe/material.c beyond the piecewise linear curve: Voce, Johnson-Cook
 * (with its thermal factor), Cowper-Symonds and Johnson-Cook rate laws,
 * and the combined isotropic + nonlinear kinematic model (Armstrong-
 * Frederick / Chaboche back-stresses).
 *
 * References, all closed forms of the continuous laws:
 * - the monotonic uniaxial curve sigma = sigma_y(ep) + sum C_i/gamma_i
 *   (1 - exp(-gamma_i ep)), with eps = sigma/E + ep;
 * - the stabilised loop of symmetric strain cycling with one or more
 *   back-stresses and a constant yield stress (Lemaitre & Chaboche,
 *   Mechanics of Solid Materials, 1990, Ch. 5):
 *   sigma_max = sigma_y + sum C_i/gamma_i tanh(gamma_i Delta eps_p / 2),
 *   2 eps_a = 2 sigma_max / E + Delta eps_p; its dissipated energy, the
 *   integral of sigma d eps_p around the loop;
 * - ratcheting under stress cycling between s_min and s_max with one
 *   back-stress (same source): the plastic strain gained per cycle,
 *   (1/gamma) ln[((C/gamma)^2 - (s_min + sigma_y)^2) /
 *   ((C/gamma)^2 - (s_max - sigma_y)^2)]; none with gamma = 0 (Prager's
 *   linear kinematic hardening shakes down to a closed loop);
 * - the rate laws in steady uniaxial flow, where the effective plastic
 *   strain rate is the imposed one, across a jump of the rate;
 * - a central finite difference of the update for the algorithmic tangent;
 * - the scalar update for the batched one (bit for bit).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fe/material.h"

#define MPA 1e6
#define GPA 1e9
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static double rel(double a, double b)
{
	return fabs(a - b) / fmax(fabs(b), 1e-300);
}

static void init(dem_mat_t *m, const dem_mat_param_t *p)
{
	dem_error_t e = { 0 };
	int rc = dem_mat_init(m, p, &e);
	if (rc)
		fprintf(stderr, "# %s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
}

/* The monotonic uniaxial curve of the rate-independent combined law. */
static double mono(const dem_mat_param_t *p, double ep)
{
	double sy;
	switch (p->law) {
	case DEM_LAW_VOCE:
		sy = p->sy0 + p->voce_Q * (1 - exp(-p->voce_b * ep)) + p->H * ep;
		break;
	case DEM_LAW_JC: {
		double th = 1;
		if (p->T > p->T_ref)
			th = 1 - pow((p->T - p->T_ref) / (p->T_melt - p->T_ref), p->mt);
		sy = (p->jc_A + p->jc_B * pow(ep, p->jc_n)) * th;
		break;
	}
	default:
		sy = p->sy0 + p->H * ep;
		break;
	}
	for (int i = 0; i < p->nkin; i++)
		sy += p->kin_gamma[i] > 0 ? p->kin_C[i] / p->kin_gamma[i] * (1 - exp(-p->kin_gamma[i] * ep))
					  : p->kin_C[i] * ep;
	return sy;
}

/* Parameter sets of the tests (not material data: shapes of the laws). */
static const dem_mat_param_t P_VOCE = {
	.E = 72 * GPA, .nu = 0.33, .rho = 2800, .law = DEM_LAW_VOCE,
	.sy0 = 400 * MPA, .voce_Q = 150 * MPA, .voce_b = 25, .H = 200 * MPA
};
static const dem_mat_param_t P_JC = {
	.E = 73 * GPA, .nu = 0.33, .rho = 2780, .law = DEM_LAW_JC,
	.jc_A = 369 * MPA, .jc_B = 684 * MPA, .jc_n = 0.73,
	.T = 400, .T_ref = 293, .T_melt = 775, .mt = 1.7
};
static const dem_mat_param_t P_KIN = {   /* Voce + two back-stresses */
	.E = 200 * GPA, .nu = 0.3, .rho = 7800, .law = DEM_LAW_VOCE,
	.sy0 = 300 * MPA, .voce_Q = 80 * MPA, .voce_b = 8,
	.nkin = 2, .kin_C = { 60 * GPA, 4 * GPA }, .kin_gamma = { 600, 20 }
};
static const dem_mat_param_t P_PRAGER = {   /* linear kinematic, gamma 0 */
	.E = 200 * GPA, .nu = 0.3, .rho = 7800, .law = DEM_LAW_LINEAR,
	.sy0 = 300 * MPA, .nkin = 1, .kin_C = { 10 * GPA }, .kin_gamma = { 0 }
};

/* Monotonic uniaxial tension of each law to 20 % strain in steps of
 * different sizes (one step crossing the yield point, some large): the
 * stress is the closed-form curve at the reached plastic strain, and the
 * plastic strain is the strain less sigma/E, to 1e-9. */
static void test_monotonic(void **state)
{
	(void)state;
	const dem_mat_param_t *sets[] = { &P_VOCE, &P_JC, &P_KIN, &P_PRAGER };
	for (size_t k = 0; k < COUNT(sets); k++) {
		dem_mat_t m;
		init(&m, sets[k]);
		assert_true(m.flags & DEM_MAT_GENERAL);
		assert_int_equal(!!(m.flags & DEM_MAT_KIN), sets[k]->nkin > 0);
		double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0, kin[18] = { 0 }, worst = 0;
		double de = 2e-4;
		int n = 0;
		while (eps[0] < 0.2) {
			double d = n % 7 == 3 ? 25 * de : de;   /* now and then a large step */
			assert_int_equal(dem_mat_uniaxial(&m, d, 0, eps, sig, &ep, kin), DEM_OK);
			if (ep > 0) {
				worst = fmax(worst, rel(sig[0], mono(sets[k], ep)));
				worst = fmax(worst, fabs(eps[0] - sig[0] / m.E - ep) / eps[0]);
			}
			n++;
		}
		printf("# law %zu: monotonic curve, worst relative error %.1e over %d steps, ep %.4f\n",
		       k, worst, n, ep);
		assert_true(ep > 0.15);
		assert_true(worst < 1e-9);
		dem_mat_free(&m);
	}
}

/* Symmetric strain cycling at +-eps_a with a constant yield stress and
 * two back-stresses: after the transient the loop is the analytic one
 * (peak stress within 1e-6), and the energy dissipated over a cycle, the
 * sum of the plastic work of the steps, is the loop's integral of sigma
 * d eps_p (within 1 %: the steps' work is taken at their end stress). */
static void test_cyclic_loop(void **state)
{
	(void)state;
	dem_mat_param_t p = P_KIN;
	p.law = DEM_LAW_LINEAR;   /* constant yield stress */
	p.voce_Q = p.voce_b = 0;
	dem_mat_t m;
	init(&m, &p);
	double ea = 0.01;
	/* the analytic loop: plastic strain range x from
	 * 2 ea = 2 smax(x) / E + x, by bisection */
	double lo = 0, hi = 2 * ea, smax = 0;
	for (int it = 0; it < 200; it++) {
		double x = 0.5 * (lo + hi);
		smax = p.sy0;
		for (int i = 0; i < p.nkin; i++)
			smax += p.kin_C[i] / p.kin_gamma[i] * tanh(p.kin_gamma[i] * x / 2);
		if (2 * smax / p.E + x > 2 * ea)
			hi = x;
		else
			lo = x;
	}
	double dep = 0.5 * (lo + hi);
	/* dissipated energy of the loop: twice the half cycle's integral of
	 * (sy + X) dp with X from -Xm to Xm along the exponential */
	double wloop = 2 * p.sy0 * dep;
	for (int i = 0; i < p.nkin; i++) {
		double C = p.kin_C[i], g = p.kin_gamma[i], Xm = C / g * tanh(g * dep / 2);
		wloop += 2 * (C / g * dep + (-Xm - C / g) * (1 - exp(-g * dep)) / g);
	}

	double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0, kin[18] = { 0 };
	int nstep = 400;                     /* per quarter cycle */
	double de = ea / nstep, peak = 0, trough = 0, wcyc = 0;
	for (int cyc = 0; cyc < 20; cyc++) {
		/* 0 -> +ea -> -ea -> 0 */
		for (int s = 0; s < 4 * nstep; s++) {
			double d = s < nstep ? de : s < 3 * nstep ? -de : de;
			assert_int_equal(dem_mat_uniaxial(&m, d, 0, eps, sig, &ep, kin), DEM_OK);
			if (s == nstep - 1)
				peak = sig[0];
			if (s == 3 * nstep - 1)
				trough = sig[0];
		}
	}
	/* one more cycle: the plastic work of each step, sig : Delta eps_p
	 * (uniaxial stress: sig_xx times the axial plastic strain) */
	{
		double e2[6], s2[6], p2 = ep, k2[18], W = 0;
		memcpy(e2, eps, sizeof e2);
		memcpy(s2, sig, sizeof s2);
		memcpy(k2, kin, sizeof k2);
		for (int s = 0; s < 4 * nstep; s++) {
			double d = s < nstep ? de : s < 3 * nstep ? -de : de;
			double ep_axial0 = e2[0] - s2[0] / m.E;
			assert_int_equal(dem_mat_uniaxial(&m, d, 0, e2, s2, &p2, k2), DEM_OK);
			double ep_axial1 = e2[0] - s2[0] / m.E;
			W += s2[0] * (ep_axial1 - ep_axial0);   /* backward Euler: end stress */
		}
		wcyc = W;
	}
	printf("# cyclic loop: peak %.6f MPa, trough %.6f MPa, analytic %.6f MPa; "
	       "dissipation %.4f MJ/m^3 against %.4f\n", peak / MPA, trough / MPA, smax / MPA,
	       wcyc / 1e6, wloop / 1e6);
	assert_true(rel(peak, smax) < 1e-6);
	assert_true(rel(-trough, smax) < 1e-6);
	assert_true(rel(wcyc, wloop) < 0.01);
	dem_mat_free(&m);
}

/* Uniaxial stress target: the strain step that takes sig_xx from the
 * state (eps, sig, ep, kin) to s, by bisection on the step (the state is
 * left at the end of that step). */
static void stress_to(const dem_mat_t *m, double s, double eps[6], double sig[6],
		      double *ep, double *kin)
{
	double e1[6], s1[6], p1, k1[18];
	double sg = s > sig[0] ? 1 : -1, lo = 0, hi = 1e-4;
	for (;;) {   /* a step long enough, by doubling */
		memcpy(e1, eps, sizeof e1);
		memcpy(s1, sig, sizeof s1);
		memcpy(k1, kin, sizeof k1);
		p1 = *ep;
		assert_int_equal(dem_mat_uniaxial(m, sg * hi, 0, e1, s1, &p1, k1), DEM_OK);
		if (sg * (s1[0] - s) >= 0)
			break;
		lo = hi;
		hi *= 2;
		assert_true(hi < 1);
	}
	if (sg < 0) {
		double t = lo;
		lo = -hi;
		hi = -t;
	}
	for (int it = 0; it < 200; it++) {
		double d = 0.5 * (lo + hi);
		memcpy(e1, eps, sizeof e1);
		memcpy(s1, sig, sizeof s1);
		memcpy(k1, kin, sizeof k1);
		p1 = *ep;
		assert_int_equal(dem_mat_uniaxial(m, d, 0, e1, s1, &p1, k1), DEM_OK);
		if (s1[0] > s)
			hi = d;
		else
			lo = d;
	}
	memcpy(eps, e1, sizeof e1);
	memcpy(sig, s1, sizeof s1);
	memcpy(kin, k1, sizeof k1);
	*ep = p1;
}

/* Stress cycling between s_min and s_max with a mean stress: one
 * Armstrong-Frederick back-stress ratchets by the closed-form strain per
 * cycle; Prager's linear rule (gamma = 0) shakes down to a closed loop. */
static void test_ratchet(void **state)
{
	(void)state;
	dem_mat_param_t p = {
		.E = 200 * GPA, .nu = 0.3, .rho = 7800, .law = DEM_LAW_LINEAR,
		.sy0 = 200 * MPA, .nkin = 1, .kin_C = { 50 * GPA }, .kin_gamma = { 250 }
	};
	double smin = -150 * MPA, smax = 350 * MPA, cg = p.kin_C[0] / p.kin_gamma[0];
	double xb = smin + p.sy0, xt = smax - p.sy0;
	double want = log((cg * cg - xb * xb) / (cg * cg - xt * xt)) / p.kin_gamma[0];
	for (int lin = 0; lin < 2; lin++) {
		if (lin) {
			p.kin_gamma[0] = 0;
			p.kin_C[0] = 5 * GPA;
			want = 0;
		}
		dem_mat_t m;
		init(&m, &p);
		double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0, kin[18] = { 0 }, last = 0, per = 0;
		for (int cyc = 0; cyc < 6; cyc++) {
			/* in steps of 5 MPa up, then down: each step stress-controlled */
			for (double s = sig[0]; s < smax - 1; ) {
				s = fmin(s + 5 * MPA, smax);
				stress_to(&m, s, eps, sig, &ep, kin);
			}
			for (double s = sig[0]; s > smin + 1; ) {
				s = fmax(s - 5 * MPA, smin);
				stress_to(&m, s, eps, sig, &ep, kin);
			}
			double epx = eps[0] - sig[0] / m.E;
			if (cyc > 0)
				per = epx - last;
			last = epx;
		}
		printf("# ratchet (gamma %g): %.6e per cycle, closed form %.6e\n",
		       p.kin_gamma[0], per, want);
		if (lin)
			assert_true(fabs(per) < 1e-10);
		else
			assert_true(rel(per, want) < 1e-6);
		dem_mat_free(&m);
	}
}

/* Rate laws in steady uniaxial flow with a constant yield stress: the
 * plastic strain rate is the imposed rate, so the flow stress is sy
 * R(rate); after a jump of the rate by 100 the stress is sy R(new rate)
 * once the transient of the jump is through (100 steps of 1e-4 here). */
static void test_rate_jump(void **state)
{
	(void)state;
	dem_mat_param_t cs = { .E = 200 * GPA, .nu = 0.3, .rho = 7800, .law = DEM_LAW_LINEAR,
			       .sy0 = 300 * MPA, .rate_law = DEM_RATE_CS, .cs_D = 40.4, .cs_p = 5 };
	dem_mat_param_t jc = { .E = 73 * GPA, .nu = 0.33, .rho = 2780, .law = DEM_LAW_LINEAR,
			       .sy0 = 369 * MPA, .rate_law = DEM_RATE_JC, .jc_C = 0.0083,
			       .rate_ref = 1 };
	dem_mat_param_t jcv = jc;   /* with Voce hardening: the law at every step */
	jcv.law = DEM_LAW_VOCE;
	jcv.voce_Q = 100 * MPA;
	jcv.voce_b = 10;
	const dem_mat_param_t *sets[] = { &cs, &jc, &jcv };
	for (size_t k = 0; k < COUNT(sets); k++) {
		dem_mat_t m;
		init(&m, sets[k]);
		assert_true(m.flags & DEM_MAT_RATE);
		double r1 = 1e2, r2 = 1e4, de = 1e-4;
		double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0, worst = 0;
		for (int i = 0; i < 600; i++) {
			double r = i < 300 ? r1 : r2, ep0 = ep;
			assert_int_equal(dem_mat_uniaxial(&m, de, de / r, eps, sig, &ep, NULL), DEM_OK);
			double rate = (ep - ep0) / (de / r);
			if ((i >= 200 && i < 300) || i >= 500) {
				/* steady: the plastic rate is the imposed one */
				double R = sets[k]->rate_law == DEM_RATE_CS
					   ? 1 + pow(r / sets[k]->cs_D, 1 / sets[k]->cs_p)
					   : 1 + sets[k]->jc_C * log(r / sets[k]->rate_ref);
				double sy = dem_mat_flow_stress(&m, ep, 0);
				if (k < 2)
					worst = fmax(worst, rel(sig[0], sy * R));
				assert_true(rel(rate, r) < 1e-3 || k == 2);
			}
			/* at every plastic step the law holds with the step's rate */
			if (ep > ep0)
				worst = fmax(worst, rel(sig[0], dem_mat_flow_stress(&m, ep, rate)));
		}
		printf("# rate law %zu: worst relative error %.1e\n", k, worst);
		assert_true(worst < 1e-6);
		dem_mat_free(&m);
	}
}

/* Central finite-difference derivative of the update from a state. */
static void fd_tangent(const dem_mat_t *m, const double s0[6], double ep0, const double *k0,
		       const double d0[6], double dt, double h, double Dfd[36])
{
	for (int j = 0; j < 6; j++) {
		double sp[6], sm[6], dp[6], dm[6], e1 = ep0, e2 = ep0, w, kp[18], km[18];
		memcpy(sp, s0, sizeof sp);
		memcpy(sm, s0, sizeof sm);
		memcpy(dp, d0, sizeof dp);
		memcpy(dm, d0, sizeof dm);
		memcpy(kp, k0, sizeof kp);
		memcpy(km, k0, sizeof km);
		dp[j] += h;
		dm[j] -= h;
		dem_mat_update(m, dp, dt, sp, &e1, kp, &w);
		dem_mat_update(m, dm, dt, sm, &e2, km, &w);
		for (int i = 0; i < 6; i++)
			Dfd[6 * i + j] = (sp[i] - sm[i]) / (2 * h);
	}
}

/* The algorithmic tangent is the derivative of the update (central finite
 * difference, to 1e-6 of its largest entry) for every law and rate law,
 * from a non-proportional pre-stressed state with back-stresses; with
 * back-stresses whose recall is on it is not symmetric, without it is. */
static void test_tangent(void **state)
{
	(void)state;
	dem_mat_param_t jcr = P_JC;
	jcr.rate_law = DEM_RATE_JC;
	jcr.jc_C = 0.014;
	jcr.rate_ref = 1;
	dem_mat_param_t kcs = P_KIN;
	kcs.rate_law = DEM_RATE_CS;
	kcs.cs_D = 40.4;
	kcs.cs_p = 5;
	const dem_mat_param_t *sets[] = { &P_VOCE, &P_JC, &jcr, &P_KIN, &kcs, &P_PRAGER };
	static const double dir[6] = { 1.0, -0.3, -0.5, 0.8, 0.2, -0.4 };
	for (size_t k = 0; k < COUNT(sets); k++) {
		dem_mat_t m;
		init(&m, sets[k]);
		double sy = dem_mat_flow_stress(&m, 0.01, 0), ey = sy / m.E;
		double s0[6] = { 0.3 * sy, -0.1 * sy, 0.05 * sy, 0.1 * sy, 0, -0.05 * sy };
		double k0[18] = { 0 };
		for (int i = 0; i < m.nkin; i++)   /* back-stresses not along the flow */
			for (int c = 0; c < 6; c++)
				k0[6 * i + c] = (i + 1) * 0.05 * sy * (c < 3 ? (c == 0 ? 1 : -0.5) : 0.3 * (c - 3));
		double d[6];
		for (int i = 0; i < 6; i++)
			d[i] = 3 * ey * dir[i];
		double s[6], ep = 0.01, w, D[36], Dfd[36], kk[18];
		memcpy(s, s0, sizeof s);
		memcpy(kk, k0, sizeof kk);
		int plastic = dem_mat_update_tangent(&m, d, 1e-6, s, &ep, kk, &w, D);
		assert_int_equal(plastic, 1);
		assert_true(w > 0);
		/* the same state as the plain update */
		double s2[6], ep2 = 0.01, k2[18];
		memcpy(s2, s0, sizeof s2);
		memcpy(k2, k0, sizeof k2);
		dem_mat_update(&m, d, 1e-6, s2, &ep2, k2, &w);
		assert_memory_equal(s, s2, sizeof s);
		assert_true(ep == ep2);
		fd_tangent(&m, s0, 0.01, k0, d, 1e-6, 1e-10, Dfd);
		double err = 0, big = 0, asym = 0;
		for (int i = 0; i < 36; i++) {
			err = fmax(err, fabs(D[i] - Dfd[i]));
			big = fmax(big, fabs(D[i]));
			asym = fmax(asym, fabs(D[i] - D[6 * (i % 6) + i / 6]));
		}
		printf("# law set %zu: tangent against finite difference %.1e, asymmetry %.1e\n",
		       k, err / big, asym / big);
		assert_true(err / big < 1e-6);
		int recall = 0;
		for (int i = 0; i < m.nkin; i++)
			recall |= m.kin_gamma[i] > 0;
		if (recall)
			assert_true(asym / big > 1e-6);
		else
			assert_true(asym / big < 1e-12);
		dem_mat_free(&m);
	}
}

/* The batched update gives bit for bit the scalar one (the Jaumann
 * rotation of the stress and of each back-stress, then the update) lane
 * by lane, for the general laws, with a mix of elastic and plastic lanes,
 * with and without spin, and with and without the record of the static
 * flow stress (syc), which then holds sigma_y(ep) of each lane that has been
 * through the general return and never more than it. */
static void test_batch(void **state)
{
	(void)state;
	enum { NB = DEM_MAT_NB };
	dem_mat_param_t kr = P_KIN;
	kr.rate_law = DEM_RATE_JC;
	kr.jc_C = 0.01;
	kr.rate_ref = 1;
	dem_mat_param_t jcs = P_JC;
	jcs.rate_law = DEM_RATE_CS;
	jcs.cs_D = 6500;
	jcs.cs_p = 4;
	const dem_mat_param_t *sets[] = { &P_VOCE, &kr, &jcs, &P_PRAGER };
	unsigned long seed = 7;
	int nplastic = 0, nrec = 0;
	for (size_t kr2 = 0; kr2 < 2 * COUNT(sets); kr2++) {
		const size_t k = kr2 / 2;
		const int rec = kr2 % 2;
		dem_mat_t m;
		init(&m, sets[k]);
		int nh = dem_mat_nhist(&m);
		assert_int_equal(nh, 6 * sets[k]->nkin);
		double syc[NB];
		for (int l = 0; l < NB; l++)
			syc[l] = m.sy_floor;
		double sy = dem_mat_flow_stress(&m, 0, 0);
		double sig[6][NB] = { { 0 } }, ep[NB] = { 0 }, kin[18][NB] = { { 0 } };
		double ss[NB][6] = { { 0 } }, es[NB] = { 0 }, ks[NB][18] = { { 0 } };
		for (int step = 0; step < 200; step++) {
			double d[6][NB], w[3][NB], wp[NB], dt = 1e-7;
			for (int l = 0; l < NB; l++) {
				for (int c = 0; c < 6; c++) {
					seed = seed * 6364136223846793005ul + 1442695040888963407ul;
					double r = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
					d[c][l] = (l < 2 ? (c == 0 ? 1.0 : c < 3 ? -0.4 : 0.1) + 0.3 * r : 4 * r) *
						  0.05 * sy / m.E / dt;
				}
				for (int c = 0; c < 3; c++)
					w[c][l] = (l - 1.5) * 1e3 * (c + 1);
			}
			int spin = step % 3 != 0;
			unsigned mask = dem_mat_update_batch(&m, dt, d[0], spin ? w[0] : NULL, sig[0], ep,
							     nh ? kin[0] : NULL, wp, rec ? syc : NULL);
			for (int l = 0; l < NB; l++) {
				double dd[6], ww[3] = { w[0][l], w[1][l], w[2][l] }, wps;
				for (int c = 0; c < 6; c++)
					dd[c] = d[c][l] * dt;
				if (spin) {
					dem_mat_jaumann(ss[l], ww, dt);
					for (int i = 0; i < nh / 6; i++)
						dem_mat_jaumann(ks[l] + 6 * i, ww, dt);
				}
				int pl = dem_mat_update(&m, dd, dt, ss[l], &es[l], nh ? ks[l] : NULL, &wps);
				assert_int_equal(pl, (int)(mask >> l & 1));
				for (int c = 0; c < 6; c++)
					assert_true(memcmp(&sig[c][l], &ss[l][c], sizeof(double)) == 0);
				for (int c = 0; c < nh; c++)
					assert_true(memcmp(&kin[c][l], &ks[l][c], sizeof(double)) == 0);
				assert_true(memcmp(&ep[l], &es[l], sizeof(double)) == 0);
				if (pl)
					assert_true(memcmp(&wp[l], &wps, sizeof(double)) == 0);
				nplastic += pl;
				if (rec) {
					double fl = dem_mat_flow_stress(&m, es[l], 0);
					assert_true(syc[l] >= m.sy_floor && syc[l] <= fl);
					if (!nh && pl)   /* just through the return */
						assert_true(syc[l] == fl);
					nrec += !nh && syc[l] > m.sy_floor;
				}
			}
		}
		dem_mat_free(&m);
	}
	assert_true(nplastic > 1000);
	assert_true(nrec > 100);
}

/* The floor of the static curve that lets the batched update skip elastic
 * lanes (the initial yield) bounds sigma_y(ep) from below for every law,
 * Johnson-Cook's infinite initial slope and a kinematic law read as
 * isotropic included. */
static void test_floor(void **state)
{
	(void)state;
	double tep[] = { 0, 0.01, 0.05, 0.2 }, tsy[] = { 400 * MPA, 400 * MPA, 420 * MPA, 430 * MPA };
	dem_mat_param_t tab = {
		.E = 72 * GPA, .nu = 0.33, .rho = 2800, .law = DEM_LAW_TABLE,
		.nhard = 4, .hard_ep = tep, .hard_sy = tsy
	};
	const dem_mat_param_t *sets[] = { &P_VOCE, &P_JC, &P_KIN, &P_PRAGER, &tab, &P_KIN };
	for (size_t k = 0; k < COUNT(sets); k++) {
		dem_mat_t m;
		init(&m, sets[k]);
		if (k == COUNT(sets) - 1)
			dem_mat_kin_as_iso(&m);
		assert_true(m.sy_floor > 0);
		assert_true(rel(m.sy_floor, sets[k] == &tab ? tsy[0] : mono(sets[k], 0)) < 1e-15);
		for (double ep = 0; ep < 3; ep += 1e-3)
			assert_true(dem_mat_flow_stress(&m, ep, 0) >= m.sy_floor);
		dem_mat_free(&m);
	}
}

/* The static stage's reading of a kinematic law: no history beyond ep,
 * and the flow stress of the monotonic curve, so uniaxial tension of the
 * isotropic equivalent is the combined law's monotonic curve. */
static void test_kin_as_iso(void **state)
{
	(void)state;
	dem_mat_t m;
	init(&m, &P_KIN);
	assert_int_equal(dem_mat_nhist(&m), 12);
	dem_mat_kin_as_iso(&m);
	assert_int_equal(dem_mat_nhist(&m), 0);
	double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0;
	for (int i = 0; i < 300; i++)
		assert_int_equal(dem_mat_uniaxial(&m, 3e-4, 0, eps, sig, &ep, NULL), DEM_OK);
	assert_true(ep > 0.05);
	assert_true(rel(sig[0], mono(&P_KIN, ep)) < 1e-9);
	dem_mat_free(&m);
}

/* Parameters out of range are refused with a message naming them. */
static void test_refused(void **state)
{
	(void)state;
	const dem_mat_param_t bad[] = {
		{ .E = 1e9, .nu = 0.3, .law = DEM_LAW_VOCE, .sy0 = 1e6, .voce_Q = -1, .voce_b = 1 },
		{ .E = 1e9, .nu = 0.3, .law = DEM_LAW_JC, .jc_A = 1e6, .jc_B = 1e6, .jc_n = 3 },
		{ .E = 1e9, .nu = 0.3, .law = DEM_LAW_JC, .jc_A = 1e6, .jc_n = 0.5, .T = 900,
		  .T_ref = 293, .T_melt = 800, .mt = 1 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .rate_law = DEM_RATE_POWER, .rate_m = 0.1 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .rate_law = DEM_RATE_CS, .cs_D = 1, .cs_p = -1 },
		{ .E = 1e9, .nu = 0.3, .sy0 = 1e6, .nkin = 1, .kin_C = { 1e9 }, .kin_gamma = { -1 } },
	};
	static const char *const what[] = { "Voce", "Johnson-Cook n", "melting", "reference",
					    "Cowper-Symonds p", "recall" };
	for (size_t i = 0; i < COUNT(bad); i++) {
		dem_mat_t m;
		dem_error_t e = { 0 };
		assert_int_equal(dem_mat_init(&m, &bad[i], &e), DEM_EINPUT);
		assert_non_null(strstr(e.msg, what[i]));
		dem_mat_free(&m);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_monotonic),
		cmocka_unit_test(test_cyclic_loop),
		cmocka_unit_test(test_ratchet),
		cmocka_unit_test(test_rate_jump),
		cmocka_unit_test(test_tangent),
		cmocka_unit_test(test_batch),
		cmocka_unit_test(test_floor),
		cmocka_unit_test(test_kin_as_iso),
		cmocka_unit_test(test_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
