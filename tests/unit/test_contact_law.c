/* test_contact_law.c - unit tests of lib/contact/law.c: the normal laws of
 * Eq. 3.45 and the contact time step of Box 3.1 (Han 2004, Ch. 3.3, 3.7).
 *
 * References: Table 3.1 and Eqs. 3.28-3.29 (Hertz coefficient); Eq. 3.81
 * (u_max by energy); Fig. 3.15 and the text of Ch. 3.7.2 (the exit
 * velocity of the rigid-sphere/wall test is independent of M, k_n and v0;
 * exact for the linear law at lambda = 1/sqrt(2); the Winkler law m = 2
 * dissipates for lambda < 0.48; divergence above 0.5); and, for the linear
 * law, the discrete energy of central differences: v_{n+1/2}^2 +
 * omega^2 u_n u_{n+1} is conserved while in contact, so the exit speed is
 * v0 / sqrt(1 - 4 lambda^2 s (1 - s)), s the fraction of the last step still
 * in contact: at most v0 / sqrt(1 - lambda^2), exactly v0 when the discrete
 * half period pi / (Omega dt) is a whole number of steps, cos(Omega dt) =
 * 1 - 2 lambda^2, i.e. lambda = sin(pi / (2 N)).
 *
 * The separation correction (model.h, beyond the thesis) against: the
 * energy balance of central differences (after the correction the elastic
 * laws leave the wall at v0: ratio 1 to rounding, whatever lambda and the
 * step rule); the closed-form restitution of the hysteretic model,
 * Eq. 3.67, reached for the largest overlap the steps reached, rho_r^2 =
 * 1 - (1 - rho^2) (u_reached / u_max)^(m+1) with u_max of Eq. 3.81; and,
 * with viscous damping, an independent tally of the discrete work of the
 * elastic and the damping parts of the force: the correction takes the
 * first and leaves the second.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/law.h"
#include "contact/model.h"
#include "core/consts.h"

static void test_law_forms(void **state)
{
	(void)state;
	dem_law_t l, h;
	dem_error_t e = { 0 };
	/* Eq. 3.45 */
	assert_int_equal(dem_law_init(&l, 2.5, 68e9, 1.5, &e), DEM_OK);
	assert_true(fabs(dem_law_kn(&l, 4e-4) - 2.5 * 68e9 * 0.02) < 1e-6);
	assert_true(fabs(dem_law_force(&l, 10, 4.0) - 80) < 1e-12);
	assert_true(fabs(dem_law_stiffness(&l, 10, 4.0) - 30) < 1e-12);
	assert_true(dem_law_force(&l, 10, -1) == 0);
	/* R^(2-m): a force for every m (N = Pa m^(2-m) m^m) */
	assert_int_equal(dem_law_init(&l, 1, 1, 2, &e), DEM_OK);
	assert_true(fabs(dem_law_kn(&l, 3) - 1) < 1e-15);
	assert_int_equal(dem_law_init(&l, 1, 1, 1, &e), DEM_OK);
	assert_true(fabs(dem_law_kn(&l, 3) - 3) < 1e-15);
	assert_int_equal(dem_law_init(&l, 1, 1, 2.5, &e), DEM_OK);
	assert_true(fabs(dem_law_kn(&l, 4) - 0.5) < 1e-12);
	/* the force does not depend on the unit of length: R and delta in
	 * mm with E in N/mm^2 give the same newtons as in SI */
	for (double m = 1; m <= 2.5; m += 0.5) {
		dem_law_t si, mm;
		assert_int_equal(dem_law_init(&si, 2.5, 68e9, m, &e), DEM_OK);
		assert_int_equal(dem_law_init(&mm, 2.5, 68e3, m, &e), DEM_OK);
		double fsi = dem_law_force(&si, dem_law_kn(&si, 0.5e-3), 1e-6);
		double fmm = dem_law_force(&mm, dem_law_kn(&mm, 0.5), 1e-3);
		assert_true(fabs(fsi - fmm) < 1e-12 * fsi);
	}
	assert_true(fabs(dem_law_force(&l, 1, 4) - 32) < 1e-12);
	/* Hertz (Eq. 3.29) is Eq. 3.45 with alpha = 4 / (3 (1 - nu^2)) */
	assert_int_equal(dem_law_hertz(&h, 68e9, 0.33, &e), DEM_OK);
	assert_int_equal(dem_law_init(&l, 4 / (3 * (1 - 0.33 * 0.33)), 68e9, 1.5, &e), DEM_OK);
	assert_true(fabs(dem_law_kn(&h, 5e-4) - dem_law_kn(&l, 5e-4)) < 1e-9 * dem_law_kn(&h, 5e-4));
	assert_true(fabs(dem_law_estar(68e9, 0.33, INFINITY, 0.3) - 68e9 / (1 - 0.33 * 0.33)) < 1);
	assert_true(fabs(dem_law_estar(1, 0, 1, 0) - 0.5) < 1e-15);
	/* bad input is refused with a message */
	assert_int_equal(dem_law_init(&l, 0, 68e9, 1.5, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "alpha"));
	dem_error_clear(&e);
	assert_int_equal(dem_law_init(&l, 1, 68e9, 0.5, &e), DEM_EINPUT);
	dem_error_clear(&e);
	assert_int_equal(dem_law_init(&l, 1, NAN, 1, &e), DEM_EINPUT);
	dem_error_clear(&e);
	assert_int_equal(dem_law_hertz(&h, 68e9, 0.5, &e), DEM_EINPUT);
}

static void test_energy_loss_params(void **state)
{
	(void)state;
	for (double m = 1; m <= 2; m += 0.5) {
		double r = dem_hyst_unload_ratio(0.7, m);
		assert_true(fabs(dem_hyst_restitution(r, m) - 0.7) < 1e-12);
		assert_true(fabs(pow(1 / r, 1 / (2 * m)) - 0.7) < 1e-12);  /* Eq. 3.67 */
	}
	assert_true(fabs(dem_visc_restitution_linear(0) - 1) < 1e-15);
	assert_true(fabs(dem_visc_xi_linear(dem_visc_restitution_linear(0.3)) - 0.3) < 1e-12);
	assert_true(fabs(dem_contact_meff(2, 2) - 1) < 1e-15);
	assert_true(dem_contact_meff(2, INFINITY) == 2);
}

static void test_dt_functions(void **state)
{
	(void)state;
	/* Eq. 3.81 stores the kinetic energy: k u^(m+1)/(m+1) = M v^2/2 */
	for (double m = 1; m <= 2; m += 0.5) {
		double u = dem_dt_umax(m, 3, 2, 5);
		assert_true(fabs(3 * pow(u, m + 1) / (m + 1) - 25) < 1e-9);
		/* from a state part way through, the same u_max */
		double uu = 0.4 * u, v = sqrt((25 - 3 * pow(uu, m + 1) / (m + 1)) * 2 / 2);
		assert_true(fabs(dem_dt_umax_state(m, 3, 2, uu, v) - u) < 1e-12 * u);
		/* Eq. 3.80: secant, tangent at the top */
		assert_true(fabs(dem_dt_secant(m, 3, u, 0) - 3 * pow(u, m - 1)) < 1e-12 * pow(u, m - 1) * 3);
		assert_true(fabs(dem_dt_secant(m, 3, u, u) - 3 * m * pow(u, m - 1)) < 1e-12 * pow(u, m - 1) * 3 * m);
		double s = dem_dt_secant(m, 3, u, 0.5 * u);
		assert_true(fabs(s - 3 * (pow(u, m) - pow(0.5 * u, m)) / (0.5 * u)) < 1e-12 * s);
	}
	assert_true(fabs(dem_dt_step(0.2, 4, 1) - 0.8) < 1e-15);
	assert_true(dem_dt_step(0.2, 4, 0) == HUGE_VAL);
}

static void test_lambda_check(void **state)
{
	(void)state;
	char msg[256];
	assert_int_equal(dem_dt_lambda_check(DEM_DT_LAMBDA_DEFAULT, 0, msg, sizeof msg), DEM_LAMBDA_OK);
	assert_int_equal(dem_dt_lambda_check(0.3, 0, msg, sizeof msg), DEM_LAMBDA_OK);
	assert_int_equal(dem_dt_lambda_check(0.35, 0, msg, sizeof msg), DEM_LAMBDA_WARN);
	assert_non_null(strstr(msg, "0.35"));
	assert_int_equal(dem_dt_lambda_check(0.5, 0, msg, sizeof msg), DEM_LAMBDA_WARN);
	assert_int_equal(dem_dt_lambda_check(0.6, 0, msg, sizeof msg), DEM_LAMBDA_REFUSED);
	assert_non_null(strstr(msg, "force"));
	assert_int_equal(dem_dt_lambda_check(0.6, 1, msg, sizeof msg), DEM_LAMBDA_FORCED);
	assert_int_equal(dem_dt_lambda_check(0, 1, msg, sizeof msg), DEM_LAMBDA_INVALID);
	assert_int_equal(dem_dt_lambda_check(-0.1, 0, msg, sizeof msg), DEM_LAMBDA_INVALID);
	assert_int_equal(dem_dt_lambda_check(1.5, 1, msg, sizeof msg), DEM_LAMBDA_INVALID);
	assert_int_equal(dem_dt_lambda_check(NAN, 1, msg, sizeof msg), DEM_LAMBDA_INVALID);
}

/* Box 3.1 sweep over (0, 0.3]: 300 values of lambda per law. */
static void test_box31_sweep(void **state)
{
	(void)state;
	const double ms[3] = { 1, 1.5, 2 };
	for (int j = 0; j < 3; j++) {
		double m = ms[j], worst = 0, wl = 0;
		for (int i = 1; i <= 300; i++) {
			double lambda = 0.3 * i / 300, umx;
			long steps;
			double r = dem_dt_wall_test(m, 1, 1, 1, lambda, &steps, &umx);
			assert_true(isfinite(r));
			if (r > worst)
				worst = r, wl = lambda;
			/* the linear law's bound, from its discrete energy */
			assert_true(r <= 1 / sqrt(1 - lambda * lambda) * (1 + 1e-12));
			/* the overshoot of u_max stays small (Eq. 3.81) */
			assert_true(umx <= dem_dt_umax(m, 1, 1, 1) * (1 + lambda * lambda));
			if (m == 2)
				assert_true(r <= 1 + 1e-3);  /* the criterion */
			/* and where the linear bound guarantees it, for every law */
			if (1 / sqrt(1 - lambda * lambda) <= 1 + 1e-3)
				assert_true(r <= 1 + 1e-3);
		}
		print_message("Box 3.1, m = %.1f: largest v_exit/v0 over lambda in (0, 0.3]: %.5f at %.3f\n",
		              m, worst, wl);
	}
	/* Winkler: dissipative for lambda < 0.48 (Ch. 3.7.2) */
	for (int i = 1; i < 48; i++)
		assert_true(dem_dt_wall_test(2, 1, 1, 1, 0.01 * i, NULL, NULL) <= 1 + 1e-12);
	/* linear: the exact points lambda = sin(pi/(2N)), 1/sqrt(2) among them */
	for (int N = 2; N <= 40; N++) {
		double r = dem_dt_wall_test(1, 1, 1, 1, sin(DEM_PI / (2 * N)), NULL, NULL);
		assert_true(fabs(r - 1) < 1e-9);
	}
	/* independent of M, k_n and v0 (Ch. 3.7.2) */
	for (int j = 0; j < 3; j++) {
		double a = dem_dt_wall_test(ms[j], 1, 1, 1, 0.237, NULL, NULL);
		double b = dem_dt_wall_test(ms[j], 3e9, 4e-6, 150, 0.237, NULL, NULL);
		assert_true(fabs(a - b) < 1e-9);
	}
	/* above 0.5 energy is gained: at lambda = 1 every law diverges */
	for (int j = 0; j < 3; j++)
		assert_true(dem_dt_wall_test(ms[j], 1, 1, 1, 1.0, NULL, NULL) > 2);
}

static void model(dem_contact_model_t *cm, const dem_contact_param_t *p)
{
	dem_error_t e = { 0 };
	if (dem_contact_model_init(cm, p, &e))
		fail_msg("%s", e.msg);
}

static void wall(const dem_contact_model_t *cm, double kn, double M, double v0, double lambda, int step,
                 dem_wall_run_t *r)
{
	dem_error_t e = { 0 };
	if (dem_contact_wall_test(cm, kn, M, v0, lambda, step, r, &e))
		fail_msg("%s", e.msg);
}

/* lambda over (0, 0.3]: 300 evenly spaced, then 300 scattered by the golden
 * ratio (no common grid with the first, no simple fractions) */
#define NSWEEP 600
static double sweep_lambda(int i)
{
	if (i < 300)
		return 0.3 * (i + 1) / 300;
	double f = fmod((i - 299) * 0.6180339887498949, 1.0);
	return 0.3 * (f > 1e-3 ? f : 1e-3);
}

/* Box 3.1 with the separation correction: the criterion
 * |v_exit/v0 - 1| <= 1e-3 for every lambda in (0, 0.3], m = 1, 1.5, 2, with
 * the thesis' step (u_max of the impact) and the drivers' (from the state). */
static void test_sepfix_sweep(void **state)
{
	(void)state;
	const double ms[3] = { 1, 1.5, 2 };
	for (int j = 0; j < 3; j++) {
		dem_contact_param_t p = { .law = { .m = ms[j], .coef = 1 } };
		dem_contact_model_t cm, off;
		model(&cm, &p);
		p.sepfix = DEM_SEPFIX_OFF;
		model(&off, &p);
		assert_true(cm.sepfix && !off.sepfix);
		for (int step = 0; step < 2; step++) {
			double hi0 = 0, lo0 = 2, dev = 0;
			for (int i = 0; i < NSWEEP; i++) {
				double lambda = sweep_lambda(i);
				dem_wall_run_t r, ro;
				/* k_n, M, v0 of a shot (they do not matter, Ch. 3.7.2) */
				wall(&cm, 3e8, 4e-6, 60, lambda, step, &r);
				wall(&off, 3e8, 4e-6, 60, lambda, step, &ro);
				/* the criterion, both ways */
				assert_true(r.ratio <= 1 + 1e-3 && r.ratio >= 1 - 1e-3);
				/* and much more: the energy balance is exact */
				assert_true(fabs(r.ratio - 1) < 1e-9);
				/* the correction acts at separation only: the same run */
				assert_true(r.ratio0 == ro.ratio && ro.dE == 0 && r.steps == ro.steps);
				/* it took the energy the thesis scheme made */
				double gain = 0.5 * 4e-6 * 60 * 60 * (r.ratio0 * r.ratio0 - 1);
				assert_true(fabs(r.dE - gain) <= 1e-9 * 0.5 * 4e-6 * 60 * 60);
				if (step == DEM_WALL_STEP_IMPACT)  /* the same scheme as dem_dt_wall_test */
					assert_true(r.ratio0 == dem_dt_wall_test(ms[j], 3e8, 4e-6, 60, lambda, NULL, NULL));
				hi0 = fmax(hi0, r.ratio0), lo0 = fmin(lo0, r.ratio0);
				dev = fmax(dev, fabs(r.ratio - 1));
			}
			print_message("Box 3.1, m = %.1f, %s step, lambda in (0, 0.3]: v_exit/v0 %.5f to %.5f (thesis "
			              "scheme), corrected within 1 +- %.1e\n", ms[j],
			              step == DEM_WALL_STEP_IMPACT ? "impact" : "state", lo0, hi0, dev);
		}
	}
	/* the sweep can see the failure: without the correction the linear law
	 * breaks the criterion at lambda = 0.3 (1.025) */
	dem_contact_param_t p = { .law = { .m = 1, .coef = 1 }, .sepfix = DEM_SEPFIX_OFF };
	dem_contact_model_t off;
	model(&off, &p);
	dem_wall_run_t r;
	wall(&off, 1, 1, 1, 0.3, DEM_WALL_STEP_IMPACT, &r);
	assert_true(r.ratio > 1 + 1e-3 && r.ratio == r.ratio0);
	/* bad arguments */
	dem_error_t e = { 0 };
	assert_int_equal(dem_contact_wall_test(&off, 1, 1, 0, 0.2, 0, &r, &e), DEM_EINPUT);
	dem_error_clear(&e);
	assert_int_equal(dem_contact_wall_test(&off, 1, 1, 1, 0.2, 7, &r, &e), DEM_EINPUT);
	dem_error_clear(&e);
	p.sepfix = 5;
	assert_int_equal(dem_contact_model_init(&off, &p, &e), DEM_EINPUT);
}

/* The pieces of the correction on hand-computed numbers: the tally (half
 * steps), the exact work of the hysteresis loop, the impulse, and its
 * limits (no reversal, nothing when not separating). */
static void test_sepfix_pieces(void **state)
{
	(void)state;
	dem_contact_param_t p = { .law = { .m = 1.5, .coef = 1 } };
	dem_contact_model_t cm;
	model(&cm, &p);
	dem_contact_state_t s;
	dem_contact_state_reset(&s);
	const double n[3] = { 0, 0, 1 }, w1[3] = { 5, 0, -2 }, w2[3] = { 5, 1, -1 }, w3[3] = { 0, 0, 3 };
	/* F_e = 3 with h = 0.5 at w1, then F_e = 4 with h = 0.25 at w2 */
	dem_sepfix_record(&s, n, w1, 3, 0.5);
	assert_true(fabs(s.W - 0.5 * 1.5 * -2) < 1e-15 && s.P[2] == 1.5);
	dem_sepfix_record(&s, n, w2, 4, 0.25);
	assert_true(fabs(s.W - (-1.5 + 0.5 * (1.5 * -1 + 1 * -1))) < 1e-15 && s.P[2] == 1);
	/* closed with w3: W_h = -2.75 + 1.5 = -1.25; power law: E = W_h */
	assert_true(fabs(dem_sepfix_error(&cm, &s, 7, w3) + 1.25) < 1e-15);
	double J[3];
	/* meff = 2: w_n' = sqrt(9 + 1.25) */
	double got = dem_sepfix_release(&cm, &s, 7, 2, n, w3, J);
	assert_true(fabs(got + 1.25) < 1e-14);
	assert_true(J[0] == 0 && J[1] == 0 && fabs(J[2] - 2 * (sqrt(10.25) - 3)) < 1e-14);
	/* more energy made than the normal motion has: stopped, not reversed */
	s.W = 20, s.P[2] = 0;
	got = dem_sepfix_release(&cm, &s, 7, 2, n, w3, J);
	assert_true(fabs(J[2] + 6) < 1e-14 && fabs(got - 9) < 1e-14);
	/* not separating: nothing */
	const double w4[3] = { 1, 0, -0.5 };
	assert_true(dem_sepfix_release(&cm, &s, 7, 2, n, w4, J) == 0 && J[2] == 0);
	/* hysteresis: the exact work is minus the loop at dmax */
	p.damping = DEM_DAMP_HYSTERESIS;
	p.unload = 4;
	model(&cm, &p);
	dem_contact_state_reset(&s);
	s.dmax = 0.5;
	double D = 7 * pow(0.5, 2.5) / 2.5 * (1 - pow(0.25, 1 / 1.5));
	assert_true(fabs(dem_sepfix_error(&cm, &s, 7, w3) - D) < 1e-14);
	s.W = -D;
	assert_true(fabs(dem_sepfix_error(&cm, &s, 7, w3)) < 1e-14);
	/* a fresh state: nothing to do */
	dem_contact_state_reset(&s);
	assert_true(dem_sepfix_release(&cm, &s, 7, 2, n, w3, J) == 0 && J[2] == 0);
}

/* Hysteresis (Eqs. 3.63-3.67) with the correction: the exact work is minus
 * the loop closed at the largest overlap reached, so the sphere leaves
 * with the closed-form restitution for that overlap. */
static void test_sepfix_hysteresis(void **state)
{
	(void)state;
	const double ms[3] = { 1, 1.5, 2 }, rhos[3] = { 0.3, 0.6, 0.9 };
	for (int j = 0; j < 3; j++)
		for (int q = 0; q < 3; q++) {
			dem_contact_param_t p = { .law = { .m = ms[j], .coef = 1 }, .damping = DEM_DAMP_HYSTERESIS,
			                          .unload = dem_hyst_unload_ratio(rhos[q], ms[j]) };
			dem_contact_model_t cm;
			model(&cm, &p);
			/* largest |ratio / rho - 1| corrected, thesis scheme, and
			 * |u_reached / u_max - 1|, over (0, 0.3] and (0, 0.2] */
			double u0 = dem_dt_umax(ms[j], 1, 1, 1), wc[2] = { 0, 0 }, wt[2] = { 0, 0 }, wu[2] = { 0, 0 };
			for (int i = 0; i < NSWEEP; i += 3) {
				double lambda = sweep_lambda(i);
				dem_wall_run_t r;
				wall(&cm, 1, 1, 1, lambda, DEM_WALL_STEP_STATE, &r);
				double rr = sqrt(1 - (1 - rhos[q] * rhos[q]) * pow(r.umax / u0, ms[j] + 1));
				assert_true(fabs(r.ratio - rr) < 1e-9);
				for (int b = 0; b < (lambda <= 0.2 ? 2 : 1); b++) {
					wc[b] = fmax(wc[b], fabs(r.ratio / rhos[q] - 1));
					wt[b] = fmax(wt[b], fabs(r.ratio0 / rhos[q] - 1));
					wu[b] = fmax(wu[b], fabs(r.umax / u0 - 1));
				}
			}
			/* converges to Eq. 3.67 with the step */
			dem_wall_run_t r;
			wall(&cm, 1, 1, 1, 0.01, DEM_WALL_STEP_STATE, &r);
			assert_true(fabs(r.ratio / rhos[q] - 1) < 1e-3);
			print_message("hysteresis m = %.1f, rho %.1f: |restitution/rho - 1| up to %.4f corrected, %.4f thesis "
			              "scheme, reached overlap off by %.4f, for lambda in (0, 0.3]; %.4f, %.4f, %.4f in "
			              "(0, 0.2]\n", ms[j], rhos[q], wc[0], wt[0], wu[0], wc[1], wt[1], wu[1]);
		}
}

/* Viscous damping: the correction takes the discrete work of the elastic
 * part and leaves the damping's.  Box 3.1 with the kernel, integrated here
 * with its own tally of the two works: F h (v_{n-1/2} + v_{n+1/2}) / 2 per
 * part. */
static void test_sepfix_viscous(void **state)
{
	(void)state;
	const double ms[2] = { 1, 1.5 }, lambdas[4] = { 0.05, 0.137, 0.2, 0.3 };
	for (int j = 0; j < 2; j++)
		for (double xi = 0.05; xi < 0.7; xi += 0.2)
			for (int l = 0; l < 4; l++) {
				dem_contact_param_t p = { .law = { .m = ms[j], .coef = 1 }, .damping = DEM_DAMP_VISCOUS,
				                          .xi = xi };
				dem_contact_model_t cm;
				model(&cm, &p);
				double u = 0, v = 1, dtp = 0, We = 0, Wd = 0;
				for (int n = 0; n < 100000; n++) {
					double dt = dem_contact_dt(&cm, 1, 1, u, v, lambdas[l]), h = (dtp + dt) / 2;
					double F = 0, Fe = 0;
					if (u > 0) {
						dem_contact_kin_t k = { .delta = u, .gamma = 1, .n = { 0, 0, 1 },
						                        .vrel = { 0, 0, -v }, .kn = 1, .meff = 1, .dt = dt };
						dem_contact_state_t st = { 0 };
						dem_contact_out_t o;
						cm.kernel(&cm, &k, &st, &o);
						F = o.Fn, Fe = o.Fe;
					}
					double v1 = v - F * h;
					/* power on the sphere: force F along +z, velocity -v */
					We += Fe * h * -(v + v1) / 2;
					Wd += (F - Fe) * h * -(v + v1) / 2;
					v = v1;
					u += v * dt;
					dtp = dt;
					if (u < 0 && v < 0)
						break;
				}
				dem_wall_run_t r;
				wall(&cm, 1, 1, 1, lambdas[l], DEM_WALL_STEP_STATE, &r);
				assert_true(fabs(r.ratio0 + v) < 1e-12);  /* the same integration */
				assert_true(fabs(r.dE - We) < 1e-12);      /* the elastic error, all of it */
				assert_true(fabs(0.5 * r.ratio * r.ratio - (0.5 + Wd)) < 1e-12);  /* the damping's work, kept */
				assert_true(Wd < 0);
				if (ms[j] == 1 && lambdas[l] == 0.2) {
					/* for the record: the restitution of a dash-pot that may not pull
					 * (test_contact_impact.c) */
					double c = sqrt(1 - xi * xi), wt = DEM_PI - atan2(2 * xi * c, 1 - 2 * xi * xi);
					double rho = exp(-xi / c * wt) * (-cos(wt) + xi / c * sin(wt));
					print_message("viscous, linear, xi %.2f, lambda 0.2: restitution %.4f thesis scheme, "
					              "%.4f corrected, exact %.4f\n", xi, r.ratio0, r.ratio, rho);
				}
			}
}

/* The time step of a model: Box 3.1 secant, stiffer with hysteresis. */
static void test_model_dt(void **state)
{
	(void)state;
	dem_contact_param_t p = { .law = { .m = 1.5, .coef = 1 } };
	dem_contact_model_t cm;
	dem_error_t e = { 0 };
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_OK);
	double u = dem_dt_umax(1.5, 2, 3, 4);
	double dt = dem_contact_dt(&cm, 2, 3, 0, 4, 0.2);
	assert_true(fabs(dt - 0.2 * 2 * sqrt(3 / (2 * sqrt(u)))) < 1e-12 * dt);
	assert_true(dem_contact_dt(&cm, 2, 3, 0, 0, 0.2) == HUGE_VAL);
	p.damping = DEM_DAMP_HYSTERESIS;
	p.unload = 4;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_OK);
	double dth = dem_contact_dt(&cm, 2, 3, 0, 4, 0.2);
	assert_true(fabs(dth - dt / sqrt(pow(4, 1 / 1.5))) < 1e-12 * dt);
	/* bad parameters */
	p.unload = 0.5;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_EINPUT);
	dem_error_clear(&e);
	p.damping = DEM_DAMP_VISCOUS;
	p.xi = 1;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_EINPUT);
	dem_error_clear(&e);
	p.xi = 0.1;
	p.friction = 1;
	p.mu = -1;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_EINPUT);
	dem_error_clear(&e);
	p.mu = 0.2;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_OK);
	assert_non_null(strstr(cm.effects, "friction mu=0.2"));
	assert_non_null(strstr(cm.effects, "viscous"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_law_forms),
		cmocka_unit_test(test_energy_loss_params),
		cmocka_unit_test(test_dt_functions),
		cmocka_unit_test(test_lambda_check),
		cmocka_unit_test(test_box31_sweep),
		cmocka_unit_test(test_model_dt),
		cmocka_unit_test(test_sepfix_pieces),
		cmocka_unit_test(test_sepfix_sweep),
		cmocka_unit_test(test_sepfix_hysteresis),
		cmocka_unit_test(test_sepfix_viscous),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
