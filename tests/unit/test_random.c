/* test_random.c - the radius laws of Ch. 2.5 and the random test sets:
 * bounds, moments against their closed forms, reproducibility from the
 * seed, and the exact packing density. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include "core/consts.h"
#include "core/radius.h"
#include "core/rng.h"
#include "pack/random.h"

enum { N = 200000 };

struct moments {
	double mean, sd, min, max;
};

static struct moments sample(dem_radius_kind_t k, double a, double b, int logs)
{
	dem_radius_law_t law = {k, a, b};
	gsl_rng *r = dem_rng_derive(5, 0);
	double s = 0, s2 = 0, lo = HUGE_VAL, hi = -HUGE_VAL;
	for (int i = 0; i < N; i++) {
		double x = dem_radius_draw(&law, r);
		lo = fmin(lo, x);
		hi = fmax(hi, x);
		if (logs)
			x = log(x);
		s += x;
		s2 += x * x;
	}
	gsl_rng_free(r);
	double m = s / N;
	return (struct moments){m, sqrt(s2 / N - m * m), lo, hi};
}

/* sd of a normal truncated at +-3 sd, relative to the untruncated sd */
static double trunc3(void)
{
	double z = 3, p = gsl_cdf_ugaussian_P(z) - gsl_cdf_ugaussian_P(-z);
	return sqrt(1 - 2 * z * gsl_ran_ugaussian_pdf(z) / p);
}

/* mono: every radius is Rmin. */
static void test_mono(void **state)
{
	(void)state;
	struct moments m = sample(DEM_RADIUS_MONO, 0.5, 5, 0);
	assert_true(m.min == 0.5 && m.max == 0.5);
}

/* URD on [1, 10]: mean 5.5, sd 9/sqrt(12), within 5 standard errors. */
static void test_urd(void **state)
{
	(void)state;
	struct moments m = sample(DEM_RADIUS_URD, 1, 10, 0);
	double sd = 9 / sqrt(12.0);
	assert_true(m.min >= 1 && m.max <= 10);
	assert_true(fabs(m.mean - 5.5) < 5 * sd / sqrt(N));
	assert_true(fabs(m.sd - sd) < 0.01 * sd);
}

/* NRD on [1, 10]: mean 5.5, sd (10-1)/6 reduced by the truncation at 3 sd. */
static void test_nrd(void **state)
{
	(void)state;
	struct moments m = sample(DEM_RADIUS_NRD, 1, 10, 0);
	double sd = 1.5 * trunc3();
	assert_true(m.min >= 1 && m.max <= 10);
	assert_true(fabs(m.mean - 5.5) < 5 * sd / sqrt(N));
	assert_true(fabs(m.sd - sd) < 0.01 * sd);
}

/* LNRD on [1, 100]: ln R has mean ln 10 and sd ln(100)/6 (truncated). */
static void test_lnrd(void **state)
{
	(void)state;
	struct moments m = sample(DEM_RADIUS_LNRD, 1, 100, 1);
	double sd = log(100.0) / 6 * trunc3();
	assert_true(m.min >= 1 && m.max <= 100);
	assert_true(fabs(m.mean - log(10.0)) < 5 * sd / sqrt(N));
	assert_true(fabs(m.sd - sd) < 0.01 * sd);
}

/* lambda = 1 collapses every law to mono. */
static void test_lambda_one(void **state)
{
	(void)state;
	for (int k = 0; k < 4; k++) {
		struct moments m = sample((dem_radius_kind_t)k, 2, 2, 0);
		assert_true(m.min == 2 && m.max == 2);
	}
}

struct acc {
	int dim;
	size_t n;
	double vol, hi[3];
	int outside;
	double first[4];
};

static int collect(void *ctx, const double *x, double r)
{
	struct acc *a = ctx;
	if (a->n == 0) {
		for (int d = 0; d < a->dim; d++)
			a->first[d] = x[d];
		a->first[3] = r;
	}
	a->n++;
	a->vol += a->dim == 2 ? DEM_PI * r * r : 4.0 / 3.0 * DEM_PI * r * r * r;
	for (int d = 0; d < a->dim; d++)
		a->outside += x[d] < 0 || x[d] > a->hi[d];
	return 0;
}

/* The domain is sized so the density of the radii drawn is exactly the
 * target; centres lie in the domain; the same seed gives the same set. */
static void test_density(void **state)
{
	(void)state;
	for (int dim = 2; dim <= 3; dim++)
		for (int law = 0; law < 4; law++) {
			dem_random_spec_t s = {dim, 5000, 0.37, {(dem_radius_kind_t)law, 0.1, 1.0}, {2, 1, 0.5}};
			dem_error_t e = {0};
			struct acc a = {.dim = dim}, b = {.dim = dim};
			assert_int_equal(dem_pack_random_domain(&s, 11, a.hi, &e), 0);
			double box = 1;
			for (int d = 0; d < dim; d++)
				box *= a.hi[d];
			assert_true(fabs(a.hi[0] / a.hi[1] - 2) < 1e-12);
			assert_int_equal(dem_pack_random(&s, 11, a.hi, collect, &a, &e), 0);
			assert_int_equal(a.n, 5000);
			assert_int_equal(a.outside, 0);
			assert_true(fabs(a.vol / box - 0.37) < 1e-12);
			for (int d = 0; d < 3; d++)
				b.hi[d] = a.hi[d];
			assert_int_equal(dem_pack_random(&s, 11, a.hi, collect, &b, &e), 0);
			assert_memory_equal(a.first, b.first, sizeof a.first);
			struct acc c = {.dim = dim};
			for (int d = 0; d < 3; d++)
				c.hi[d] = a.hi[d];
			assert_int_equal(dem_pack_random(&s, 12, a.hi, collect, &c, &e), 0);
			assert_memory_not_equal(a.first, c.first, sizeof a.first);
		}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_mono),
		cmocka_unit_test(test_urd),
		cmocka_unit_test(test_nrd),
		cmocka_unit_test(test_lnrd),
		cmocka_unit_test(test_lambda_one),
		cmocka_unit_test(test_density),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
