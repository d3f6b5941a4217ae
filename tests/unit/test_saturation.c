/* test_saturation.c - unit tests of lib/core/saturation.c (the saturation
 * curve's fit, its saturation point, the J443 rule on the points).
 *
 * References: the closed forms of the curves (EXP2: T = ln 10 / b,
 * H(T) = 0.9 a; EXP3: H(2T) = 1.1 H(T) evaluated on the curve); points
 * drawn from known curves, exactly or with 1 % Gaussian noise (sd 1 % of
 * each height, fixed seeds), the noise's effect on T and H(T) predicted by
 * linearised least squares (the derivatives of the fit's T and H to each
 * point, by central differences, times the noise); the J443 rule's
 * definition.  The curves are made up (heights of an Almen A strip, 0.3
 * mm at saturation; exposures in passes).
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

#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "core/saturation.h"

#define NT 10
static const double T10[NT] = { 1, 2, 3, 4, 6, 8, 12, 16, 24, 32 };

struct curve {
	dem_sat_form_t form;
	double a, b, c;
};

static const struct curve C2 = { DEM_SAT_EXP2, 0.3, 0.3, 1 };
static const struct curve C3 = { DEM_SAT_EXP3, 0.3, 0.15, 1.4 };

static double curve_at(const struct curve *k, double t)
{
	return k->a * (1 - exp(-k->b * pow(t, k->c)));
}

static void fit_ok(size_t n, const double *t, const double *h, dem_sat_form_t form,
		   dem_sat_fit_t *f)
{
	dem_error_t e = { 0 };
	int rc = dem_sat_fit(n, t, h, form, f, &e);
	if (rc)
		fprintf(stderr, "dem_sat_fit: %s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
}

/* Exact points: the fit returns the curve, its T and H(T) to 1e-6; the
 * saturation point satisfies the definition on the curve. */
static void test_exact(void **state)
{
	(void)state;
	const struct curve *cs[2] = { &C2, &C3 };
	for (int k = 0; k < 2; k++) {
		double h[NT];
		for (int i = 0; i < NT; i++)
			h[i] = curve_at(cs[k], T10[i]);
		dem_sat_fit_t f;
		fit_ok(NT, T10, h, cs[k]->form, &f);
		assert_true(fabs(f.a / cs[k]->a - 1) < 1e-6);
		assert_true(fabs(f.b / cs[k]->b - 1) < 1e-6);
		assert_true(fabs(f.c / cs[k]->c - 1) < 1e-6);
		assert_true(f.rms < 1e-9);
		assert_int_equal(f.saturates, 1);
		assert_true(fabs(dem_sat_eval(&f, 2 * f.T) / dem_sat_eval(&f, f.T) - 1.1) < 1e-9);
		assert_true(fabs(dem_sat_eval(&f, f.T) / f.H - 1) < 1e-12);
		if (cs[k]->form == DEM_SAT_EXP2) {
			assert_true(fabs(f.T / (log(10) / C2.b) - 1) < 1e-6);
			assert_true(fabs(f.H / (0.9 * C2.a) - 1) < 1e-6);
		}
		if (getenv("TEST_VERBOSE"))
			fprintf(stderr, "%s exact: a %.9g b %.9g c %.9g T %.9g H %.9g (%d iterations)\n",
				dem_sat_form_names[k], f.a, f.b, f.c, f.T, f.H, f.iterations);
	}
}

/* 1 % noise, 200 seeds per form: over the seeds, T and H(T) are recovered
 * within 1 % on the mean (no bias), and their scatter is the noise's, as
 * linearised least squares predicts it (within 25 %): the misses of single
 * fits are the data's, not the fitter's.  H(T) has an rms error under
 * 1 %; T, set by the rate b, scatters more (1.3 % for EXP2, 1.8 % for EXP3
 * predicted with these 10 points), so a single fit misses it by more than
 * 1 % about half the time. */
static void test_noise(void **state)
{
	(void)state;
	const struct curve *cs[2] = { &C2, &C3 };
	gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
	assert_non_null(r);
	for (int k = 0; k < 2; k++) {
		double h[NT];
		for (int i = 0; i < NT; i++)
			h[i] = curve_at(cs[k], T10[i]);
		dem_sat_fit_t f0, fp, fm;
		fit_ok(NT, T10, h, cs[k]->form, &f0);
		/* predicted variances: sum over points of (dX/dh_i 0.01 h_i)^2 */
		double vT = 0, vH = 0;
		for (int i = 0; i < NT; i++) {
			double hp[NT], hm[NT], d = 1e-5 * h[i];
			memcpy(hp, h, sizeof h);
			memcpy(hm, h, sizeof h);
			hp[i] += d;
			hm[i] -= d;
			fit_ok(NT, T10, hp, cs[k]->form, &fp);
			fit_ok(NT, T10, hm, cs[k]->form, &fm);
			vT += pow((fp.T - fm.T) / (2 * d) * 0.01 * h[i], 2);
			vH += pow((fp.H - fm.H) / (2 * d) * 0.01 * h[i], 2);
		}
		double sdT = sqrt(vT) / f0.T, sdH = sqrt(vH) / f0.H;
		const int N = 200;
		double mT = 0, mH = 0, sT = 0, sH = 0;
		int within = 0;
		for (int s = 1; s <= N; s++) {
			gsl_rng_set(r, (unsigned long)s);
			double hn[NT];
			for (int i = 0; i < NT; i++)
				hn[i] = h[i] * (1 + 0.01 * gsl_ran_gaussian(r, 1));
			dem_sat_fit_t f;
			fit_ok(NT, T10, hn, cs[k]->form, &f);
			assert_int_equal(f.saturates, 1);
			double dT = f.T / f0.T - 1, dH = f.H / f0.H - 1;
			mT += dT / N;
			mH += dH / N;
			sT += dT * dT / N;
			sH += dH * dH / N;
			within += fabs(dT) < 0.01 && fabs(dH) < 0.01;
		}
		if (getenv("TEST_VERBOSE"))
			fprintf(stderr, "%s, 1 %% noise, %d seeds: mean error T %+.3f %% H %+.3f %%; "
				"rms T %.3f %% H %.3f %% (predicted %.3f %%, %.3f %%); both within 1 %%: "
				"%d\n", dem_sat_form_names[k], N, 100 * mT, 100 * mH, 100 * sqrt(sT),
				100 * sqrt(sH), 100 * sdT, 100 * sdH, within);
		assert_true(fabs(mT) < 0.01 && fabs(mH) < 0.01);
		assert_true(sqrt(sH) < 0.01);
		assert_true(sqrt(sT) > 0.75 * sdT && sqrt(sT) < 1.25 * sdT);
		assert_true(sqrt(sH) > 0.75 * sdH && sqrt(sH) < 1.25 * sdH);
	}
	gsl_rng_free(r);
}

static void refused(size_t n, const double *t, const double *h, const char *what)
{
	dem_error_t e = { 0 };
	dem_sat_fit_t f;
	for (int form = 0; form < 2; form++) {
		dem_error_clear(&e);
		assert_int_equal(dem_sat_fit(n, t, h, (dem_sat_form_t)form, &f, &e), DEM_EINPUT);
		if (!strstr(e.msg, what))
			fprintf(stderr, "message '%s' lacks '%s'\n", e.msg, what);
		assert_non_null(strstr(e.msg, what));
	}
}

/* Refused with a clear message: fewer than 4 points; points that never
 * rise (falling, flat, or rising but never positive); exposures that do
 * not increase or are not positive. */
static void test_refusals(void **state)
{
	(void)state;
	static const double t[] = { 1, 2, 4, 8, 16 };
	static const double h3[] = { 0.1, 0.2, 0.25 };
	refused(3, t, h3, "3 points: at least 4 are needed");
	static const double fall[] = { 0.3, 0.25, 0.2, 0.2, 0.1 };
	refused(5, t, fall, "never rise");
	static const double flat[] = { 0.2, 0.2, 0.2, 0.2, 0.2 };
	refused(5, t, flat, "never rise");
	static const double neg[] = { -0.4, -0.3, -0.2, -0.1, -0.05 };
	refused(5, t, neg, "none positive");
	static const double h5[] = { 0.1, 0.2, 0.25, 0.27, 0.28 };
	static const double tback[] = { 1, 2, 2, 8, 16 };
	refused(5, tback, h5, "exposures must increase");
	static const double tzero[] = { 0, 2, 4, 8, 16 };
	refused(5, tzero, h5, "positive exposure");
	/* one rise is enough to fit */
	static const double late[] = { 0.3, 0.2, 0.2, 0.25, 0.25 };
	dem_sat_fit_t f;
	dem_error_t e = { 0 };
	assert_int_equal(dem_sat_fit(5, t, late, DEM_SAT_EXP2, &f, &e), DEM_OK);
}

/* A three-parameter curve too slow ever to saturate (2^c <= 1.1): no T. */
static void test_no_saturation(void **state)
{
	(void)state;
	struct curve slow = { DEM_SAT_EXP3, 0.3, 0.5, 0.12 };
	double h[NT];
	for (int i = 0; i < NT; i++)
		h[i] = curve_at(&slow, T10[i]);
	dem_sat_fit_t f;
	fit_ok(NT, T10, h, DEM_SAT_EXP3, &f);
	assert_true(fabs(f.c / slow.c - 1) < 1e-4);
	assert_int_equal(f.saturates, 0);
}

/* The J443 rule on the points agrees with the fit where it finds a point:
 * on exact points at doubling exposures (1, 2, 4, ... 64) the ratio
 * H(2t)/H(t) falls with t, so the rule's point is the first measured
 * exposure at or after the fit's T (T_pts / 2 < T <= T_pts), and its height
 * lies between H(T) and H(2T) = 1.1 H(T).  Several rates and shapes. */
static void test_points_rule(void **state)
{
	(void)state;
	static const double td[7] = { 1, 2, 4, 8, 16, 32, 64 };
	const struct curve cs[] = {
		{ DEM_SAT_EXP2, 0.3, 0.1, 1 }, { DEM_SAT_EXP2, 0.3, 0.3, 1 },
		{ DEM_SAT_EXP2, 0.3, 1.0, 1 }, { DEM_SAT_EXP3, 0.3, 0.3, 0.7 },
		{ DEM_SAT_EXP3, 0.3, 0.05, 1.5 },
	};
	int found = 0;
	for (size_t k = 0; k < sizeof cs / sizeof cs[0]; k++) {
		double h[7], T, H, ratio;
		for (int i = 0; i < 7; i++)
			h[i] = curve_at(&cs[k], td[i]);
		dem_sat_fit_t f;
		fit_ok(7, td, h, cs[k].form, &f);
		if (!dem_sat_points(7, td, h, &T, &H, &ratio))
			continue;
		found++;
		if (getenv("TEST_VERBOSE"))
			fprintf(stderr, "%s a %g b %g c %g: fit T %.4g H %.5g; points T %g H %.5g "
				"(ratio %.4f)\n", dem_sat_form_names[cs[k].form], cs[k].a, cs[k].b,
				cs[k].c, f.T, f.H, T, H, ratio);
		assert_true(ratio <= 1.1);
		assert_true(T / 2 < f.T && f.T <= T * (1 + 1e-9));
		assert_true(H >= f.H * (1 - 1e-9) && H <= 1.1 * f.H * (1 + 1e-9));
	}
	assert_int_equal(found, (int)(sizeof cs / sizeof cs[0]));
	/* no t with 2t measured and a 10 % rise at most: none */
	static const double t4[] = { 1, 2, 4, 8 };
	static const double rising[] = { 0.1, 0.2, 0.3, 0.4 };
	double T, H, ratio;
	assert_int_equal(dem_sat_points(4, t4, rising, &T, &H, &ratio), 0);
	static const double t3[] = { 1, 3, 5, 7 };
	static const double flat[] = { 0.3, 0.3, 0.3, 0.3 };
	assert_int_equal(dem_sat_points(4, t3, flat, &T, &H, &ratio), 0);
}

int main(void)
{
	gsl_set_error_handler_off();
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_exact),
		cmocka_unit_test(test_noise),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_no_saturation),
		cmocka_unit_test(test_points_rule),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
