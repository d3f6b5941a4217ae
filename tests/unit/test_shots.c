/* test_shots.c - shot streams for peening (lib/pack/shots.h).
 *
 * References:
 *   - the Ch. 8.6 layout (Han 2004; thesis-data.yaml peen_forming): 4 x 4
 *     shots of 1.4 mm per pass, 32 passes, over 5.6 x 5.6 mm, so 512
 *     impacts, 16 a pass, pass 0 at the cell centres;
 *   - the R2 offsets (Roberts 2018) computed here from their definition,
 *     and their spread: after 32 passes no point of a cell is farther than
 *     0.35 cell from an impact (the design's bound), and in fact within
 *     1.5 times the covering radius of the best possible arrangement of 32
 *     points, the hexagonal lattice, sqrt(2 / (3 sqrt 3 32)) = 0.110;
 *   - the velocity from speed, angle and azimuth by the closed form;
 *   - speed scatter: mean and sd of a normal cut at 3 sd;
 *   - coverage: SAE J2277 100 % = 98 % of the area dimpled, C % = C/100
 *     times the impacts of 100 %; for independent uniform impacts the
 *     Avrami (Poisson) law 1 - exp(-n pi a^2 / A) gives the count at 98 %,
 *     n = -ln(0.02) A / (pi a^2);
 *   - the raster: one dimple covers pi a^2 / A of the area, wherever it
 *     lies, the area being periodic.
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

#include "core/consts.h"
#include "pack/shots.h"

struct set {
	size_t n, cap;
	dem_shot_t *s;
};

static int collect(void *ctx, const dem_shot_t *sh)
{
	struct set *c = ctx;
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 1024;
		c->s = realloc(c->s, c->cap * sizeof *c->s);
		assert_non_null(c->s);
	}
	c->s[c->n++] = *sh;
	return 0;
}

/* The Ch. 8.6 job: S550 (r = 0.7 mm) at 46.5 m/s, normal, 5.6 mm square. */
static dem_shots_spec_t ch86(void)
{
	return (dem_shots_spec_t){
		.pattern = DEM_SHOTS_GRID, .lo = {-0.0028, -0.0028}, .hi = {0.0028, 0.0028},
		.grid = 4, .passes = 32, .per_pass = 8, .separation = 1,
		.law = {DEM_RADIUS_MONO, 0.0007, 0.0007}, .speed = 46.5, .angle = DEM_PI / 2,
	};
}

static dem_shots_spec_t random_spec(double coverage, double a)
{
	dem_shots_spec_t s = ch86();
	s.pattern = DEM_SHOTS_RANDOM;
	s.coverage = coverage;
	s.dimple_radius = a;
	return s;
}

static struct set shots_of(const dem_shots_spec_t *s, unsigned long seed, dem_shots_plan_t *plan)
{
	struct set c = {0};
	dem_error_t e = {0};
	assert_int_equal(dem_shots_plan(s, seed, plan, &e), DEM_OK);
	assert_int_equal(dem_pack_shots(s, seed, plan, collect, &c, &e), DEM_OK);
	assert_int_equal(c.n, plan->shots);
	return c;
}

/* periodic (minimum image) distance in an area of sides len */
static double torus_dist(const double *a, const double *b, const double *len)
{
	double d2 = 0;
	for (int d = 0; d < 2; d++) {
		double dx = a[d] - b[d];
		dx -= len[d] * round(dx / len[d]);
		d2 += dx * dx;
	}
	return sqrt(d2);
}

/* Ch. 8.6: 4 x 4 shots, 32 passes -> 512 impacts, 16 in each pass, passes
 * in order, every impact inside the area, radius and velocity as asked. */
static void test_grid_counts(void **state)
{
	(void)state;
	dem_shots_spec_t s = ch86();
	dem_shots_plan_t p;
	struct set c = shots_of(&s, 1, &p);
	assert_int_equal(p.shots, 512);
	assert_int_equal(p.passes, 32);
	assert_int_equal(p.per_pass, 16);
	assert_true(isnan(p.covered));
	for (size_t i = 0; i < c.n; i++) {
		const dem_shot_t *sh = &c.s[i];
		assert_int_equal(sh->pass, i / 16);
		assert_true(sh->t == 0);
		for (int d = 0; d < 2; d++)
			assert_true(sh->x[d] >= s.lo[d] && sh->x[d] < s.hi[d]);
		assert_true(sh->r == 0.0007);
		assert_true(sh->v[0] == 0 && sh->v[1] == 0 && sh->v[2] == -46.5);
	}
	free(c.s);
}

/* Pass 0 sits at the centres of the 4 x 4 cells of 1.4 mm, row by row. */
static void test_grid_pass0_centres(void **state)
{
	(void)state;
	dem_shots_spec_t s = ch86();
	dem_shots_plan_t p;
	struct set c = shots_of(&s, 1, &p);
	for (int j = 0; j < 4; j++)
		for (int i = 0; i < 4; i++) {
			const dem_shot_t *sh = &c.s[4 * j + i];
			assert_true(fabs(sh->x[0] - (-0.0028 + (i + 0.5) * 0.0014)) < 1e-15);
			assert_true(fabs(sh->x[1] - (-0.0028 + (j + 0.5) * 0.0014)) < 1e-15);
		}
	free(c.s);
}

/* The offsets follow their definition (R2, Roberts 2018), are distinct,
 * and every pass is the pass-0 lattice shifted by its offset (wrapped).
 * The union of the 32 passes leaves no point of the area farther than
 * 0.35 cell from an impact, and within 1.5x of the hexagonal optimum. */
static void test_grid_offsets(void **state)
{
	(void)state;
	const double g = 1.32471795724474602596, cell = 0.0014;
	double o[32][2], len[2] = {0.0056, 0.0056};
	for (unsigned long p = 0; p < 32; p++) {
		dem_shots_grid_offset(p, o[p]);
		double u = 0.5 + (double)p / g, v = 0.5 + (double)p / (g * g);
		assert_true(fabs(o[p][0] - (u - floor(u) - 0.5)) < 1e-12);
		assert_true(fabs(o[p][1] - (v - floor(v) - 0.5)) < 1e-12);
		assert_true(o[p][0] >= -0.5 && o[p][0] < 0.5 && o[p][1] >= -0.5 && o[p][1] < 0.5);
		for (unsigned long q = 0; q < p; q++) {
			double one[2] = {1, 1};
			assert_true(torus_dist(o[p], o[q], one) > 0.05);
		}
	}
	assert_true(o[0][0] == 0 && o[0][1] == 0);

	dem_shots_spec_t s = ch86();
	dem_shots_plan_t p;
	struct set c = shots_of(&s, 1, &p);
	for (size_t i = 0; i < c.n; i++) {
		const dem_shot_t *sh = &c.s[i];
		size_t k = i % 16;
		double want[2] = {-0.0028 + ((double)(k % 4) + 0.5 + o[sh->pass][0]) * cell,
				  -0.0028 + ((double)(k / 4) + 0.5 + o[sh->pass][1]) * cell};
		assert_true(torus_dist(sh->x, want, len) < 1e-12);
	}

	double worst = 0;
	enum { M = 112 };       /* 28 samples per cell and axis */
	for (int j = 0; j < M; j++)
		for (int i = 0; i < M; i++) {
			double x[2] = {-0.0028 + (i + 0.5) * 0.0056 / M, -0.0028 + (j + 0.5) * 0.0056 / M};
			double best = HUGE_VAL;
			for (size_t k = 0; k < c.n; k++)
				best = fmin(best, torus_dist(x, c.s[k].x, len));
			worst = fmax(worst, best);
		}
	double hex = sqrt(2 / (3 * sqrt(3.0) * 32));
	print_message("  farthest point from the 512 impacts: %.4f cell (hexagonal optimum %.4f)\n",
		      worst / cell, hex);
	assert_true(worst / cell <= 0.35);
	assert_true(worst / cell <= 1.5 * hex);
	free(c.s);
}

/* v = speed (cos a cos az, cos a sin az, -sin a). */
static void test_velocity(void **state)
{
	(void)state;
	double v[3], sp = 46.5;
	dem_shots_velocity(sp, DEM_PI / 2, 0, v);
	assert_true(v[0] == 0 && v[1] == 0 && v[2] == -sp);
	dem_shots_velocity(sp, DEM_PI / 2, 1.0, v);
	assert_true(v[0] == 0 && v[1] == 0 && v[2] == -sp);
	dem_shots_velocity(sp, DEM_PI / 3, 0, v);
	assert_true(fabs(v[0] - sp / 2) < 1e-12 * sp && v[1] == 0);
	assert_true(fabs(v[2] + sp * sqrt(3.0) / 2) < 1e-12 * sp);
	dem_shots_velocity(sp, DEM_PI / 3, DEM_PI / 2, v);
	assert_true(fabs(v[0]) < 1e-12 * sp && fabs(v[1] - sp / 2) < 1e-12 * sp);
	dem_shots_velocity(sp, DEM_PI / 6, DEM_PI / 4, v);
	assert_true(fabs(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - sp) < 1e-12 * sp);
	assert_true(fabs(v[0] - v[1]) < 1e-12 * sp && fabs(v[2] + sp / 2) < 1e-12 * sp);
}

/* Speeds scattered by 10 %: mean 46.5 within 5 standard errors, sd 10 %
 * of it reduced by the cut at 3 sd (factor 0.98658), within 1 %; none
 * beyond 3 sd; the direction unchanged (angle 60 deg). */
static void test_speed_scatter(void **state)
{
	(void)state;
	dem_shots_spec_t s = ch86();
	s.speed_scatter = 0.1;
	s.angle = DEM_PI / 3;
	s.grid = 20;
	s.passes = 500;         /* 200000 shots */
	dem_shots_plan_t p;
	struct set c = shots_of(&s, 7, &p);
	double sum = 0, sum2 = 0;
	for (size_t i = 0; i < c.n; i++) {
		const double *v = c.s[i].v;
		double u = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
		assert_true(fabs(u / 46.5 - 1) <= 0.3 + 1e-12);
		assert_true(fabs(-v[2] / u - sqrt(3.0) / 2) < 1e-12);
		sum += u;
		sum2 += u * u;
	}
	double n = (double)c.n, mean = sum / n, sd = sqrt(sum2 / n - mean * mean);
	double want = 4.65 * 0.98658;
	assert_true(fabs(mean - 46.5) < 5 * want / sqrt(n));
	assert_true(fabs(sd - want) < 0.01 * want);
	free(c.s);
}

/* Random up to 100 % and 200 %: the stream covers at least 98 % (and the
 * coverage measured again from the rows agrees with the plan); 200 % has
 * exactly twice the impacts of 100 %, whole passes but the last; the
 * header's passes count them. */
static void test_random_coverage(void **state)
{
	(void)state;
	size_t n100 = 0;
	for (int k = 0; k < 3; k++) {
		double target[3] = {100, 200, 50};
		dem_shots_spec_t s = random_spec(target[k], 0.0004);
		dem_shots_plan_t p;
		struct set c = shots_of(&s, 11, &p);
		double *x = malloc(c.n * sizeof *x), *y = malloc(c.n * sizeof *y), f;
		dem_error_t e = {0};
		assert_non_null(x);
		assert_non_null(y);
		for (size_t i = 0; i < c.n; i++) {
			x[i] = c.s[i].x[0];
			y[i] = c.s[i].x[1];
			assert_int_equal(c.s[i].pass, i / 8);
		}
		assert_int_equal(dem_coverage_measure(s.lo, s.hi, 0.0004, c.n, x, y, &f, &e), DEM_OK);
		assert_true(f == p.covered);
		if (k == 0)
			n100 = p.impacts_100;
		assert_int_equal(p.impacts_100, n100);      /* the same seed finds the same 100 % */
		assert_int_equal(p.shots, (size_t)ceil(target[k] / 100 * (double)n100));
		assert_int_equal(p.passes, (p.shots + 7) / 8);
		print_message("  %g %%: %zu impacts (100 %% at %zu), covered %.5f\n",
			      target[k], p.shots, n100, p.covered);
		if (target[k] >= 100)
			assert_true(p.covered >= DEM_COVERAGE_FULL);
		else    /* Avrami: 1 - 0.02^(C/100) = 0.859, or more when a pass spreads */
			assert_true(p.covered > 0.75 && p.covered < DEM_COVERAGE_FULL);
		if (target[k] == 200)
			assert_true(p.covered >= 0.995);    /* Avrami: 1 - 0.02^2 */
		free(x);
		free(y);
		free(c.s);
	}
}

/* Independent uniform impacts (no separation) reach 98 % after
 * n = -ln(0.02) A / (pi a^2) on average (Avrami); the mean over 10 seeds is
 * within 10 %. */
static void test_random_avrami(void **state)
{
	(void)state;
	dem_shots_spec_t s = random_spec(100, 0.0004);
	s.separation = 0;
	double sum = 0, n = -log(0.02) * 0.0056 * 0.0056 / (DEM_PI * 0.0004 * 0.0004);
	for (unsigned long seed = 1; seed <= 10; seed++) {
		dem_shots_plan_t p;
		dem_error_t e = {0};
		assert_int_equal(dem_shots_plan(&s, seed, &p, &e), DEM_OK);
		sum += (double)p.impacts_100;
	}
	print_message("  impacts at 98 %%: mean %.1f, Avrami %.1f\n", sum / 10, n);
	assert_true(fabs(sum / 10 - n) < 0.10 * n);
}

/* The same seed gives the same stream, bit for bit; another seed another. */
static void test_random_seed(void **state)
{
	(void)state;
	dem_shots_spec_t s = random_spec(200, 0.0004);
	s.speed_scatter = 0.05;
	s.law = (dem_radius_law_t){DEM_RADIUS_URD, 0.0005, 0.0007};
	dem_shots_plan_t p1, p2, p3;
	struct set a = shots_of(&s, 3, &p1), b = shots_of(&s, 3, &p2), c = shots_of(&s, 4, &p3);
	assert_int_equal(a.n, b.n);
	assert_memory_equal(a.s, b.s, a.n * sizeof *a.s);
	assert_true(p1.covered == p2.covered);
	size_t same = 0;
	for (size_t i = 0; i < a.n && i < c.n; i++)
		same += a.s[i].x[0] == c.s[i].x[0];
	assert_int_equal(same, 0);
	for (size_t i = 0; i < a.n; i++)
		assert_true(a.s[i].r >= 0.0005 && a.s[i].r <= 0.0007);
	free(a.s);
	free(b.s);
	free(c.s);
}

/* Within a pass, centres are at least separation (r_i + r_j) apart by the
 * periodic distance: one diameter (the default), and two (the shots of a
 * pass then keep a diameter of clear surface between them). */
static void test_random_min_distance(void **state)
{
	(void)state;
	double len[2] = {0.0056, 0.0056};
	for (int k = 0; k < 2; k++) {
		dem_shots_spec_t s = random_spec(0, 0);
		s.passes = 200;
		s.separation = k ? 2 : 1;
		s.per_pass = k ? 2 : 8;
		s.law = (dem_radius_law_t){DEM_RADIUS_URD, 0.0005, 0.0007};
		dem_shots_plan_t p;
		struct set c = shots_of(&s, 5, &p);
		double closest = HUGE_VAL;
		for (size_t i = 0; i < c.n; i++)
			for (size_t j = i + 1; j < c.n && c.s[j].pass == c.s[i].pass; j++) {
				double d = torus_dist(c.s[i].x, c.s[j].x, len);
				assert_true(d >= s.separation * (c.s[i].r + c.s[j].r) * (1 - 1e-12));
				closest = fmin(closest, d / (c.s[i].r + c.s[j].r));
			}
		print_message("  separation %g: closest pair at %.3f (r_i + r_j)\n", s.separation, closest);
		free(c.s);
	}
}

/* Patterns that cannot be placed are clear errors, not endless loops:
 * 16 shots of 1.4 mm in 5.6 mm fit only as a lattice (random addition
 * jams near 55 % of the area), and 40 cannot fit at all; a coverage
 * without a dimple radius is refused. */
static void test_errors(void **state)
{
	(void)state;
	dem_shots_plan_t p;
	dem_error_t e = {0};
	dem_shots_spec_t s = random_spec(0, 0);
	s.per_pass = 16;
	assert_int_equal(dem_shots_plan(&s, 1, &p, &e), DEM_EINPUT);     /* found by the dry run */
	assert_non_null(strstr(e.msg, "per_pass 16"));
	dem_error_clear(&e);
	s.per_pass = 40;
	assert_int_equal(dem_shots_plan(&s, 1, &p, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "densest"));
	dem_error_clear(&e);
	s = random_spec(100, 0);
	assert_int_equal(dem_shots_plan(&s, 1, &p, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "dimple radius"));
	dem_error_clear(&e);
	s = ch86();
	s.angle = 0;
	assert_int_equal(dem_shots_plan(&s, 1, &p, &e), DEM_EINPUT);
}

/* One dimple of radius a in the middle of a 1 x 1 area covers pi a^2; the
 * raster (cell a / 20, about 1257 cells in the disk) counts the cell
 * centres inside, which errs by a few cells along the rim: within 1 %.  At a corner, or at a point
 * outside the area, the periodic images cover the same fraction to the
 * cell (each quarter lands in another corner). */
static void test_coverage_raster(void **state)
{
	(void)state;
	const double lo[2] = {0, 0}, hi[2] = {1, 1}, a = 0.1, exact = DEM_PI * a * a;
	dem_coverage_t *c;
	dem_error_t e = {0};
	double x = 0.5, y = 0.5, f, fc;
	assert_int_equal(dem_coverage_measure(lo, hi, a, 1, &x, &y, &f, &e), DEM_OK);
	print_message("  one dimple: %.6f, pi a^2 %.6f\n", f, exact);
	assert_true(fabs(f - exact) < 0.01 * exact);

	assert_int_equal(dem_coverage_new(&c, lo, hi, a / DEM_COVERAGE_CELLS, &e), DEM_OK);
	assert_true(dem_coverage_fraction(c) == 0);
	dem_coverage_add(c, 0, 0, a);
	fc = dem_coverage_fraction(c);
	assert_true(fabs(fc - f) < 1e-12);
	dem_coverage_add(c, 1, 1, a);           /* the same point, periodically */
	assert_true(dem_coverage_fraction(c) == fc);
	dem_coverage_clear(c);
	dem_coverage_add(c, -0.95, 2.05, a);    /* (0.05, 0.05) wrapped */
	double fo = dem_coverage_fraction(c);
	assert_true(fabs(fo - exact) < 0.01 * exact);
	dem_coverage_clear(c);
	dem_coverage_add(c, 0.5, 0.5, 5);       /* larger than the area */
	assert_true(dem_coverage_fraction(c) == 1);
	dem_coverage_free(c);

	/* two touching dimples (no cell centre in both) cover twice one; a
	 * third on the first adds nothing */
	double xs[3] = {0.3, 0.5, 0.3}, ys[3] = {0.5, 0.5, 0.5}, f2;
	assert_int_equal(dem_coverage_measure(lo, hi, a, 3, xs, ys, &f2, &e), DEM_OK);
	assert_true(fabs(f2 - 2 * f) < 1e-12);

	const double tiny_hi[2] = {1, 1};
	assert_int_equal(dem_coverage_new(&c, lo, tiny_hi, 1e-6, &e), DEM_EINPUT);
	assert_null(c);
}

/* A grid job with a dimple radius reports the coverage its passes reach
 * and the impacts at which 98 % was first covered. */
static void test_grid_coverage(void **state)
{
	(void)state;
	dem_shots_spec_t s = ch86();
	s.dimple_radius = 0.0004;
	dem_shots_plan_t p;
	dem_error_t e = {0};
	assert_int_equal(dem_shots_plan(&s, 1, &p, &e), DEM_OK);
	print_message("  Ch. 8.6 grid, a = 0.4 mm: covered %.5f, 98 %% at impact %zu (pass %zu)\n",
		      p.covered, p.impacts_100, (p.impacts_100 + 15) / 16);
	assert_true(p.covered == 1);
	assert_true(p.impacts_100 > 0 && p.impacts_100 < 512);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_grid_counts),
		cmocka_unit_test(test_grid_pass0_centres),
		cmocka_unit_test(test_grid_offsets),
		cmocka_unit_test(test_velocity),
		cmocka_unit_test(test_speed_scatter),
		cmocka_unit_test(test_random_coverage),
		cmocka_unit_test(test_random_avrami),
		cmocka_unit_test(test_random_seed),
		cmocka_unit_test(test_random_min_distance),
		cmocka_unit_test(test_errors),
		cmocka_unit_test(test_coverage_raster),
		cmocka_unit_test(test_grid_coverage),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
