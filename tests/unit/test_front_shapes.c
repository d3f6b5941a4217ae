/* test_front_shapes.c - the advancing front packing of polygons and
 * ellipses (Han 2004, Ch. 5.3-5.4) and its geometry (lib/pack/locus).
 *
 * References:
 *   - the checker itself (exact2d.h): Wang-Wang-Kim's cubic against a
 *     dense sampling of the two boundaries on random pairs clearly apart
 *     or clearly overlapping, at aspect ratios 1 to 5 and 1 to 1000;
 *     touching circles, and touching ellipses built in closed form at
 *     aspect ratios 1 to 1000, shrunk or grown by 1e-9;
 *   - Minkowski sums: rectangles give the rectangle of summed sides; a
 *     triangle plus itself turned through 180 degrees is a hexagon of six
 *     times its area; a point and a segment; random pairs: at most
 *     na + nb points, and every sum of two points inside or on the sum;
 *   - Perram-Wertheim: for two circles F = d^2 / (r1 + r2)^2, for two
 *     ellipses scaled by sqrt(F) the sampled boundaries touch; the locus of
 *     a circle round a circle is the circle of radius r1 + r2; Newton on
 *     two circle loci against the circle-circle intersection; Newton's
 *     step count when it fails (0 from a singular start or a first step
 *     of more than a radian, worked by hand; maxit at the limit);
 *   - packings: no two bodies overlap by the independent exact tests
 *     (exact2d.h: separating axes for polygons, WWK for ellipses, each
 *     allowing 1e-9 of the size), on every pair whose bounding boxes meet
 *     (D-cell, checked against brute force in test_detect); every body
 *     inside the rectangle (its points, or its extents, to 1e-9); open,
 *     closed and gravity forms, an L-shaped polygon; 10^5 bodies of each
 *     shape with aspect ratios 1 to 5 (fewer under the sanitizers);
 *   - gravity (Fig. 5.9) with a body's true contact on a wall: a body in a
 *     bottom corner has its lowest point (closed form) on the side wall's
 *     side of its centre;
 *   - translation: a rectangle moved by 2^20 (1, -1) gives the bodies at
 *     the origin moved, within 1e-6 of the size;
 *   - polygon areas in the statistics against a b (m/2) sin(2 pi/m).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/polygon.h"
#include "core/rng.h"
#include "detect/detect.h"
#include "pack/front.h"
#include "pack/locus.h"

#include "exact2d.h"
#include "slow.h"

#define EPS 1e-9
/* The rounding of coordinates that front.h allows as overlap besides:
 * 64 ulps of their magnitude (at most 8.5e-12 at 600 from the origin). */
#define ROUNDING (64 * DBL_EPSILON)

/* ---- the checker and the geometry ------------------------------------- */

/* the least of |x|^T Q x - 1 over n points of ellipse 1's boundary,
 * against ellipse 2 (Q its inverse shape matrix) */
static double sample_min(double x1, double y1, double a1, double b1, double t1, double x2,
			 double y2, double a2, double b2, double t2, int n)
{
	double c2 = cos(t2), s2 = sin(t2), c1 = cos(t1), s1 = sin(t1), best = HUGE_VAL;
	for (int k = 0; k < n; k++) {
		double p = 2 * X2_PI * k / n, u = a1 * cos(p), w = b1 * sin(p);
		double x = x1 + c1 * u - s1 * w - x2, y = y1 + s1 * u + c1 * w - y2;
		double lx = c2 * x + s2 * y, ly = -s2 * x + c2 * y;
		best = fmin(best, lx * lx / (a2 * a2) + ly * ly / (b2 * b2) - 1);
	}
	return best;
}

static void test_wwk_against_sampling(void **state)
{
	(void)state;
	gsl_rng *g = dem_rng_derive(11, 0);
	int apart = 0, over = 0;
	for (int t = 0; t < 3000; t++) {
		double a1 = 0.2 + gsl_rng_uniform(g), b1 = a1 / (1 + 4 * gsl_rng_uniform(g));
		double a2 = 0.2 + gsl_rng_uniform(g), b2 = a2 / (1 + 4 * gsl_rng_uniform(g));
		double t1 = 7 * gsl_rng_uniform(g), t2 = 7 * gsl_rng_uniform(g);
		double x2 = 100 + 3 * gsl_rng_uniform(g), y2 = -50 + 3 * gsl_rng_uniform(g);
		double x1 = 100 + 3 * gsl_rng_uniform(g), y1 = -50 + 3 * gsl_rng_uniform(g);
		double m12 = sample_min(x1, y1, a1, b1, t1, x2, y2, a2, b2, t2, 4000);
		double m21 = sample_min(x2, y2, a2, b2, t2, x1, y1, a1, b1, t1, 4000);
		/* one centre inside the other: overlap whatever the boundaries */
		double dc = sample_min(x1, y1, 1e-9, 1e-9, 0, x2, y2, a2, b2, t2, 1);
		int wwk = x2_wwk_overlap(x1, y1, a1, b1, t1, x2, y2, a2, b2, t2, 0);
		if (fmin(m12, m21) < -0.02 || dc < 0) {
			assert_true(wwk);
			over++;
		} else if (fmin(m12, m21) > 0.02) {
			if (wwk)
				fail_msg("pair %d: sampled apart (%g), WWK says overlap", t, fmin(m12, m21));
			apart++;
		}
	}
	/* touching circles are not an overlap at any eps >= 0, and circles
	 * a 1e-6 into each other are one */
	assert_false(x2_wwk_overlap(0, 0, 1, 1, 0, 3, 0, 2, 2, 0, 1e-9));
	assert_true(x2_wwk_overlap(0, 0, 1, 1, 0, 3 - 1e-6, 0, 2, 2, 0, 1e-9));
	assert_true(apart > 300 && over > 300);
	gsl_rng_free(g);
}

/* The checker at aspect ratios 1 to 1000 (log-uniform), against the
 * sampled boundaries (n points a boundary, enough that two samples are
 * closer than a tenth of the thinner semi-axis): the cubic's coefficients
 * spread as the square of the ratio there, and the checker must still
 * call every pair clearly apart apart and every pair clearly overlapping
 * an overlap; and pairs touching by construction, shrunk or grown by
 * 1e-9, apart or overlapping. */
static void test_wwk_thin(void **state)
{
	(void)state;
	gsl_rng *g = dem_rng_derive(12, 0);
	int apart = 0, over = 0, thin = 0;
	int ntry = SLOW_CASES(2000, 400);
	for (int t = 0; t < ntry; t++) {
		double al1 = pow(1000, gsl_rng_uniform(g)), al2 = pow(1000, gsl_rng_uniform(g));
		double a1 = 0.5 + gsl_rng_uniform(g), b1 = a1 / al1;
		double a2 = 0.5 + gsl_rng_uniform(g), b2 = a2 / al2;
		double t1 = 7 * gsl_rng_uniform(g), t2 = 7 * gsl_rng_uniform(g);
		double x1 = 10 + 2 * gsl_rng_uniform(g), y1 = -5 + 2 * gsl_rng_uniform(g);
		double x2 = 10 + 2 * gsl_rng_uniform(g), y2 = -5 + 2 * gsl_rng_uniform(g);
		int n = (int)(20 * X2_PI * fmax(a1, a2) / fmin(b1, b2)) + 1000;
		double m12 = sample_min(x1, y1, a1, b1, t1, x2, y2, a2, b2, t2, n);
		double m21 = sample_min(x2, y2, a2, b2, t2, x1, y1, a1, b1, t1, n);
		double dc = sample_min(x1, y1, 1e-9, 1e-9, 0, x2, y2, a2, b2, t2, 1);
		int wwk = x2_wwk_overlap(x1, y1, a1, b1, t1, x2, y2, a2, b2, t2, 0);
		thin += fmax(al1, al2) >= 50;
		if (fmin(m12, m21) < -0.02 || dc < 0) {
			if (!wwk)
				fail_msg("pair %d (aspect %.0f, %.0f): sampled overlap (%g), WWK says apart",
					 t, al1, al2, fmin(m12, m21));
			over++;
		} else if (fmin(m12, m21) > 0.02) {
			if (wwk)
				fail_msg("pair %d (aspect %.0f, %.0f): sampled apart (%g), WWK says overlap",
					 t, al1, al2, fmin(m12, m21));
			apart++;
		}
	}
	print_message("# thin ellipses: %d pairs, %d apart, %d overlapping, %d with an aspect "
		      "ratio of 50 or more\n", ntry, apart, over, thin);
	assert_true(apart > ntry / 10 && over > ntry / 10 && thin > ntry / 3);
	/* touching pairs in closed form, as the packings' are: ellipse 2's
	 * support point in a direction -n put on ellipse 1's in n (the
	 * support point of R diag(a^2, b^2) R^T = M in n is M n / sqrt(n^T
	 * M n)); shrunk by 1e-9 they are apart, grown by 1e-9 they overlap */
	for (int t = 0; t < 5000; t++) {
		double al1 = pow(1000, gsl_rng_uniform(g)), al2 = pow(1000, gsl_rng_uniform(g));
		double e[2][3], sp[2][2], u = 2 * X2_PI * gsl_rng_uniform(g);
		for (int k = 0; k < 2; k++) {
			e[k][0] = 0.5 + gsl_rng_uniform(g);
			e[k][1] = e[k][0] / (k ? al2 : al1);
			e[k][2] = 7 * gsl_rng_uniform(g);
			double c = cos(e[k][2]), sn = sin(e[k][2]), a2 = e[k][0] * e[k][0], b2 = e[k][1] * e[k][1];
			double n0 = k ? -cos(u) : cos(u), n1 = k ? -sin(u) : sin(u);
			double mx = (a2 * c * c + b2 * sn * sn) * n0 + (a2 - b2) * c * sn * n1;
			double my = (a2 - b2) * c * sn * n0 + (a2 * sn * sn + b2 * c * c) * n1;
			double h = sqrt(n0 * mx + n1 * my);
			sp[k][0] = mx / h, sp[k][1] = my / h;
		}
		double x1 = 10 + 2 * gsl_rng_uniform(g), y1 = -5 + 2 * gsl_rng_uniform(g);
		double x2 = x1 + sp[0][0] - sp[1][0], y2 = y1 + sp[0][1] - sp[1][1];
		for (int sg = -1; sg <= 1; sg += 2)
			if (x2_wwk_overlap(x1, y1, e[0][0], e[0][1], e[0][2], x2, y2, e[1][0], e[1][1],
					   e[1][2], sg * 1e-9) != (sg < 0))
				fail_msg("touching pair %d (aspect %.0f, %.0f) %s by 1e-9: WWK says %s", t,
					 al1, al2, sg > 0 ? "shrunk" : "grown", sg > 0 ? "overlap" : "apart");
	}
	gsl_rng_free(g);
}

static void test_sat(void **state)
{
	(void)state;
	double P[4][2], Q[4][2];
	x2_polygon(0, 0, 1, 1, 0, 4, P);        /* a square of circumradius 1 */
	x2_polygon(sqrt(2), 0, 1, 1, 0, 4, Q);  /* side by side, touching */
	assert_false(x2_sat_overlap(4, (const double (*)[2])P, 4, (const double (*)[2])Q, 1e-12));
	x2_polygon(sqrt(2) - 1e-6, 0, 1, 1, 0, 4, Q);
	assert_true(x2_sat_overlap(4, (const double (*)[2])P, 4, (const double (*)[2])Q, 1e-9));
	/* corner to corner across a diagonal gap the axes of the edges see */
	x2_polygon(sqrt(2) * 0.99, sqrt(2) * 0.99, 1, 1, X2_PI / 4, 4, Q);
	assert_false(x2_sat_overlap(4, (const double (*)[2])P, 4, (const double (*)[2])Q, 0));
}

static double area(int n, const double (*v)[2])
{
	double a = 0;
	for (int i = 0; i < n; i++)
		a += v[i][0] * v[(i + 1) % n][1] - v[i][1] * v[(i + 1) % n][0];
	return a / 2;
}

static void test_minkowski(void **state)
{
	(void)state;
	double A[4][2] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}}, B[4][2] = {{-1, -3}, {0, -3}, {0, 0}, {-1, 0}};
	double S[16][2], pa[16][2];
	int n = dem_minkowski(4, (const double (*)[2])A, 4, (const double (*)[2])B, S, pa);
	assert_int_equal(n, 4);     /* parallel edges merge */
	assert_true(fabs(area(n, (const double (*)[2])S) - 3 * 4) < 1e-12);
	assert_true(fabs(dem_convex_depth(n, (const double (*)[2])S, (double[2]){0.5, -1}) - 1.5) < 1e-12);
	double T[3][2] = {{0, 0}, {3, 0.5}, {1, 2}}, N[3][2];
	for (int k = 0; k < 3; k++)
		N[k][0] = -T[k][0], N[k][1] = -T[k][1];
	n = dem_minkowski(3, (const double (*)[2])T, 3, (const double (*)[2])N, S, NULL);
	assert_int_equal(n, 6);
	assert_true(fabs(area(n, (const double (*)[2])S) - 6 * area(3, (const double (*)[2])T)) < 1e-12);
	/* a point and a segment */
	double O[1][2] = {{5, 5}}, G[2][2] = {{0, 0}, {1, 1}};
	n = dem_minkowski(1, (const double (*)[2])O, 3, (const double (*)[2])T, S, pa);
	assert_int_equal(n, 3);
	assert_true(fabs(area(n, (const double (*)[2])S) - area(3, (const double (*)[2])T)) < 1e-12);
	assert_true(pa[1][0] == 5 && pa[1][1] == 5);
	n = dem_minkowski(2, (const double (*)[2])G, 3, (const double (*)[2])T, S, NULL);
	assert_int_equal(n, 5);
	/* a random pair: the sum's points are sums of points, its area the
	 * brute-force hull's (the largest-area check: every pairwise sum
	 * lies inside or on it) */
	gsl_rng *g = dem_rng_derive(3, 0);
	for (int t = 0; t < 200; t++) {
		double P[7][2], Q[5][2];
		x2_polygon(0, 0, 1 + gsl_rng_uniform(g), 0.5, 7 * gsl_rng_uniform(g), 7, P);
		x2_polygon(1, 2, 0.3 + gsl_rng_uniform(g), 0.2, 7 * gsl_rng_uniform(g), 5, Q);
		n = dem_minkowski(7, (const double (*)[2])P, 5, (const double (*)[2])Q, S, NULL);
		assert_true(n <= 12 && n >= 5);
		for (int i = 0; i < 7; i++)
			for (int j = 0; j < 5; j++) {
				double q[2] = {P[i][0] + Q[j][0], P[i][1] + Q[j][1]};
				assert_true(dem_convex_depth(n, (const double (*)[2])S, q) > -1e-12);
			}
	}
	gsl_rng_free(g);
}

static void test_ellipse_geometry(void **state)
{
	(void)state;
	double m1[3], m2[3], d[2] = {3, 4};
	dem_ellipse_matrix(1, 1, 1, 0, m1);
	dem_ellipse_matrix(2, 2, 0, 1, m2);
	/* circles: F = d^2 / (r1 + r2)^2 */
	assert_true(fabs(dem_ellipse_pw(m1, m2, d, HUGE_VAL, NULL) - 25.0 / 9) < 1e-12);
	/* the same for ellipses scaled: F scales as 1 / s^2, and equals 1
	 * where the sampled boundaries touch (the packer's criterion) */
	dem_ellipse_matrix(2, 0.5, cos(0.3), sin(0.3), m1);
	dem_ellipse_matrix(1.5, 0.4, cos(1.1), sin(1.1), m2);
	double F = dem_ellipse_pw(m1, m2, d, HUGE_VAL, NULL), s = sqrt(F);
	double lo = sample_min(0, 0, 2 * s, 0.5 * s, 0.3, 3, 4, 1.5 * s, 0.4 * s, 1.1, 200000);
	assert_true(fabs(lo) < 1e-6);
	assert_true(x2_wwk_overlap(0, 0, 2 * s, 0.5 * s, 0.3, 3, 4, 1.5 * s, 0.4 * s, 1.1, -1e-7));
	assert_false(x2_wwk_overlap(0, 0, 2 * s, 0.5 * s, 0.3, 3, 4, 1.5 * s, 0.4 * s, 1.1, 1e-7));
	/* the locus of a circle round a circle, and Newton on two of them
	 * against their intersection */
	dem_locus_t A = {0}, B = {0};
	dem_ellipse_matrix(1, 1, 1, 0, A.m1);
	dem_ellipse_matrix(0.5, 0.5, 1, 0, A.m2);
	B = A;
	B.c[0] = 2;
	double x[2];
	dem_locus_eval(&A, 0.7, x, NULL);
	assert_true(fabs(hypot(x[0], x[1]) - 1.5) < 1e-14);
	double u = 1.0, v = 2.0;
	assert_true(dem_locus_meet(&A, &B, &u, &v, 1e-14, 30, NULL) >= 0);
	dem_locus_eval(&A, u, x, NULL);
	assert_true(fabs(x[0] - 1) < 1e-13 && fabs(x[1] - sqrt(1.5 * 1.5 - 1)) < 1e-13);
	/* the outer bound lies outside the locus: every point of it */
	double V[16][2];
	dem_locus_outer(&A, 16, V);
	for (int k = 0; k < 16; k++)
		assert_true(hypot(V[k][0], V[k][1]) >= 1.5 - 1e-14);
}

/* ---- packings --------------------------------------------------------- */

struct bodies {
	size_t n, cap;
	dem_front_body_t *b;
};

static int keep(void *ctx, const dem_front_body_t *b)
{
	struct bodies *s = ctx;
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 1024;
		s->b = realloc(s->b, s->cap * sizeof *s->b);
		assert_non_null(s->b);
	}
	s->b[s->n++] = *b;
	return 0;
}

static dem_front_spec_t spec(dem_front_shape_t shape, dem_front_form_t form, double w,
			     double rmin, double lambda, double amax)
{
	dem_front_spec_t s;
	memset(&s, 0, sizeof s);
	s.form = form;
	s.hi[0] = w;
	s.hi[1] = w;
	s.shape = shape;
	s.sides = 6;
	s.law = (dem_radius_law_t){DEM_RADIUS_URD, rmin, rmin * lambda};
	s.ratio = (dem_radius_law_t){DEM_RADIUS_URD, 1, amax};
	return s;
}

static void pack(const dem_front_spec_t *s, unsigned long seed, struct bodies *out,
		 dem_front_stats_t *st)
{
	gsl_rng *g = dem_rng_derive(seed, 0);
	dem_error_t e;
	dem_error_clear(&e);
	memset(out, 0, sizeof *out);
	int rc = dem_pack_front_bodies(s, g, keep, out, st, &e);
	if (rc)
		fail_msg("dem_pack_front_bodies: %d: %s", rc, e.msg);
	gsl_rng_free(g);
}

/* Whether the ellipse (centre c, semi-axes a, b, angle th) lies inside the
 * polygon v[nd] (any simple polygon, convex or not): its centre inside by
 * the crossing rule and no edge nearer than 1 - tol to the centre in the
 * frame where the ellipse is the unit circle (the affine map keeps
 * segments; the ellipse is connected and holds its centre, so it cannot
 * reach outside without meeting an edge). */
static int ellipse_in_polygon(const double c[2], double a, double b, double th,
			      const double *v, int nd, double tol)
{
	int in = 0;
	for (int i = 0, j = nd - 1; i < nd; j = i++)
		if ((v[2 * i + 1] > c[1]) != (v[2 * j + 1] > c[1]) &&
		    c[0] < v[2 * j] + (c[1] - v[2 * j + 1]) * (v[2 * i] - v[2 * j]) /
				       (v[2 * i + 1] - v[2 * j + 1]))
			in = !in;
	if (!in)
		return 0;
	double cs = cos(th), sn = sin(th);
	for (int i = 0; i < nd; i++) {
		double p[2][2];
		for (int k = 0; k < 2; k++) {
			const double *q = v + 2 * ((i + k) % nd);
			double dx = q[0] - c[0], dy = q[1] - c[1];
			p[k][0] = (cs * dx + sn * dy) / a;
			p[k][1] = (-sn * dx + cs * dy) / b;
		}
		double ex = p[1][0] - p[0][0], ey = p[1][1] - p[0][1];
		double t = -(p[0][0] * ex + p[0][1] * ey) / (ex * ex + ey * ey);
		t = t < 0 ? 0 : t > 1 ? 1 : t;
		if (hypot(p[0][0] + t * ex, p[0][1] + t * ey) < 1 - tol)
			return 0;
	}
	return 1;
}

/* ellipse_in_polygon, the check the packings are held to, on the L's
 * reflex corner and its edges */
static void test_ellipse_in_polygon(void **state)
{
	(void)state;
	const double L[12] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
	const double pi = acos(-1);
	assert_true(ellipse_in_polygon((double[2]){0.5, 0.5}, 0.4, 0.2, 0, L, 6, EPS));
	/* centre in the notch */
	assert_false(ellipse_in_polygon((double[2]){1.2, 1.2}, 0.1, 0.05, 0, L, 6, EPS));
	/* along the diagonal into the notch, or across it past the corner */
	assert_false(ellipse_in_polygon((double[2]){0.9, 0.9}, 0.3, 0.05, pi / 4, L, 6, EPS));
	assert_true(ellipse_in_polygon((double[2]){0.9, 0.9}, 0.3, 0.05, -pi / 4, L, 6, EPS));
	/* touching the edge x = 0, and a hundredth beyond it */
	assert_true(ellipse_in_polygon((double[2]){0.3, 0.5}, 0.3, 0.1, 0, L, 6, EPS));
	assert_false(ellipse_in_polygon((double[2]){0.29, 0.5}, 0.3, 0.1, 0, L, 6, EPS));
	/* the same ellipse turned upright fits */
	assert_true(ellipse_in_polygon((double[2]){0.29, 0.5}, 0.3, 0.1, pi / 2, L, 6, EPS));
}


/* Newton's count (dem_locus_meet's steps, summed into the packer's
 * newton_iters) is the steps taken, also when the solve fails, not the
 * limit: a singular start (two parallel lines) fails before any step, a
 * limit of maxit ends after maxit steps, a converged solve reports the
 * steps it returns. */
static void test_newton_count(void **state)
{
	(void)state;
	dem_locus_t P = {0}, Q = {0};
	P.line = Q.line = 1;
	P.t[0] = Q.t[0] = 1;
	Q.c[1] = 1;                     /* y = 0 and y = 1: never meet */
	double u = 0, v = 0;
	int steps = -5;
	assert_int_equal(dem_locus_meet(&P, &Q, &u, &v, 1e-14, 30, &steps), -1);
	assert_int_equal(steps, 0);
	/* two circles' loci (radius 1.5 about 0 and about (2, 0)) meet at
	 * (1, sqrt(1.25)): from a start a radian off, one step is not enough
	 * for 1e-14, and maxit = 1 stops after it */
	dem_locus_t A = {0}, B;
	dem_ellipse_matrix(1, 1, 1, 0, A.m1);
	dem_ellipse_matrix(0.5, 0.5, 1, 0, A.m2);
	B = A;
	B.c[0] = 2;
	u = 1.0, v = 2.0;
	steps = -5;
	assert_int_equal(dem_locus_meet(&A, &B, &u, &v, 1e-14, 1, &steps), -1);
	assert_int_equal(steps, 1);
	u = 1.0, v = 2.0;
	int it = dem_locus_meet(&A, &B, &u, &v, 1e-14, 30, &steps);
	assert_true(it > 1);
	assert_int_equal(steps, it);
	/* a step of more than a radian is refused before it is taken: from
	 * (u, v) = (4, 2) the first Newton step is (-0.947, 2.516) (by hand:
	 * the 2 x 2 system [A'(u), -B'(v)] (du, dv) = B(v) - A(u)) */
	u = 4.0, v = 2.0;
	assert_int_equal(dem_locus_meet(&A, &B, &u, &v, 1e-14, 30, &steps), -1);
	assert_int_equal(steps, 0);
}

/* Every pair whose bounding boxes meet, by the independent tests; every
 * body inside the rectangle (polygon: its points; ellipse: its extents),
 * or for a polygon domain dom[nd] every point inside it by the crossing
 * rule and no reflex point inside a body (polygons), every ellipse inside
 * it by ellipse_in_polygon. */
static void check(const dem_front_spec_t *s, const struct bodies *B, const char *label)
{
	dem_boxes_t bx;
	dem_detect_opts_t o;
	dem_pairs_t pr;
	dem_error_t e;
	int m = s->sides;
	double (*V)[2] = malloc(B->n * (size_t)m * sizeof *V);
	assert_non_null(V);
	assert_int_equal(dem_boxes_alloc(&bx, 2, B->n), DEM_OK);
	for (size_t i = 0; i < B->n; i++) {
		const dem_front_body_t *b = &B->b[i];
		double h = b->a * (1 + 1e-6);
		bx.lo[0][i] = b->x[0] - h, bx.hi[0][i] = b->x[0] + h;
		bx.lo[1][i] = b->x[1] - h, bx.hi[1][i] = b->x[1] + h;
		double size = sqrt(b->a * b->b), tol = EPS * size;
		if (s->shape == DEM_FRONT_POLYGON) {
			x2_polygon(b->x[0], b->x[1], b->a, b->b, b->theta, m, V + i * m);
			for (int k = 0; k < m && !s->polygon; k++)
				for (int d = 0; d < 2; d++)
					if (V[i * m + k][d] < s->lo[d] - tol || V[i * m + k][d] > s->hi[d] + tol)
						fail_msg("%s: body %zu sticks out", label, i);
		} else if (!s->polygon) {
			double c = cos(b->theta), sn = sin(b->theta);
			double ex = sqrt(b->a * b->a * c * c + b->b * b->b * sn * sn);
			double ey = sqrt(b->a * b->a * sn * sn + b->b * b->b * c * c);
			if (b->x[0] - ex < s->lo[0] - tol || b->x[0] + ex > s->hi[0] + tol ||
			    b->x[1] - ey < s->lo[1] - tol || b->x[1] + ey > s->hi[1] + tol)
				fail_msg("%s: ellipse %zu sticks out", label, i);
		} else if (!ellipse_in_polygon(b->x, b->a, b->b, b->theta, s->polygon, s->npolygon, EPS))
			fail_msg("%s: ellipse %zu not inside the polygon", label, i);
		if (s->polygon && s->shape == DEM_FRONT_POLYGON)
			for (int k = 0; k < m; k++) {
				/* crossing rule, then every vertex of the
				 * domain not inside the body */
				int in = 0;
				const double *v = s->polygon, *q = V[i * m + k];
				int nd = s->npolygon;
				for (int a = 0, z = nd - 1; a < nd; z = a++)
					if ((v[2 * a + 1] > q[1]) != (v[2 * z + 1] > q[1]) &&
					    q[0] < v[2 * z] + (q[1] - v[2 * z + 1]) * (v[2 * a] - v[2 * z]) /
							   (v[2 * a + 1] - v[2 * z + 1]))
						in = !in;
				if (!in) {
					/* on an edge to the tolerance counts as in */
					double dmin = HUGE_VAL;
					for (int a = 0; a < nd; a++) {
						const double *p0 = v + 2 * a, *p1 = v + 2 * ((a + 1) % nd);
						double dx = p1[0] - p0[0], dy = p1[1] - p0[1];
						double t = ((q[0] - p0[0]) * dx + (q[1] - p0[1]) * dy) / (dx * dx + dy * dy);
						t = t < 0 ? 0 : t > 1 ? 1 : t;
						dmin = fmin(dmin, hypot(q[0] - p0[0] - t * dx, q[1] - p0[1] - t * dy));
					}
					if (dmin > tol)
						fail_msg("%s: body %zu point %d outside the polygon", label, i, k);
				}
				for (int a = 0; a < nd; a++) {
					double P1[1][2] = {{v[2 * a], v[2 * a + 1]}};
					/* a point as a polygon of one: SAT on the
					 * body's axes */
					int inside = 1;
					for (int j = 0; j < m && inside; j++) {
						const double *e0 = V[i * m + j], *e1 = V[i * m + (j + 1) % m];
						double cr = (e1[0] - e0[0]) * (P1[0][1] - e0[1]) -
							    (e1[1] - e0[1]) * (P1[0][0] - e0[0]);
						if (cr <= tol * hypot(e1[0] - e0[0], e1[1] - e0[1]))
							inside = 0;
					}
					if (inside)
						fail_msg("%s: a vertex of the domain inside body %zu", label, i);
				}
			}
	}
	dem_detect_opts_init(&o);
	o.algo = DEM_DETECT_DCELL;
	dem_error_clear(&e);
	dem_pairs_init(&pr);
	assert_int_equal(dem_detect(&bx, &o, &pr, NULL, &e), DEM_OK);
	for (size_t k = 0; k < pr.n; k++) {
		size_t i = pr.p[k].i, j = pr.p[k].j;
		const dem_front_body_t *p = &B->b[i], *q = &B->b[j];
		int ov;
		/* front.h: EPS of the smaller size, and far from the origin
		 * the rounding of the coordinates, 64 ulps of their magnitude */
		double size = fmin(sqrt(p->a * p->b), sqrt(q->a * q->b));
		double far = ROUNDING * fmax(fmax(fabs(p->x[0]), fabs(p->x[1])),
					     fmax(fabs(q->x[0]), fabs(q->x[1])));
		if (s->shape == DEM_FRONT_POLYGON)
			ov = x2_sat_overlap(m, (const double (*)[2])(V + i * m), m,
					    (const double (*)[2])(V + j * m), EPS * size + far);
		else
			ov = x2_wwk_overlap(p->x[0], p->x[1], p->a, p->b, p->theta, q->x[0], q->x[1],
					    q->a, q->b, q->theta, EPS + far / size);
		if (ov)
			fail_msg("%s: bodies %zu and %zu overlap", label, i, j);
	}
	dem_pairs_free(&pr);
	dem_boxes_free(&bx);
	free(V);
}

static void report(const char *label, const struct bodies *B, const dem_front_stats_t *st)
{
	fprintf(stderr, "# %s: %zu bodies, density %.4f, failed %zu, newton %zu "
		"(%zu steps, %zu refused), fall-backs %zu\n", label, B->n, st->density, st->failed,
		st->newton, st->newton_iters, st->newton_failed, st->fallbacks);
}

static void test_forms(void **state)
{
	(void)state;
	for (int sh = DEM_FRONT_POLYGON; sh <= DEM_FRONT_ELLIPSE; sh++)
		for (int f = 0; f < 3; f++) {
			dem_front_spec_t s = spec((dem_front_shape_t)sh, f == 0 ? DEM_FRONT_CLOSED : DEM_FRONT_OPEN,
						  20, 0.3, 2, 3);
			s.gravity = f == 2;
			struct bodies B;
			dem_front_stats_t st;
			char label[64];
			snprintf(label, sizeof label, "%s %s%s", dem_front_shape_names[sh],
				 dem_front_form_names[s.form], s.gravity ? " gravity" : "");
			pack(&s, 5, &B, &st);
			report(label, &B, &st);
			assert_true(B.n > 200);
			assert_true(st.density > 0.45 && st.density < 0.91);
			check(&s, &B, label);
			/* reproducible from the seed */
			struct bodies C;
			dem_front_stats_t st2;
			pack(&s, 5, &C, &st2);
			assert_int_equal(C.n, B.n);
			assert_memory_equal(C.b, B.b, B.n * sizeof *B.b);
			free(C.b);
			free(B.b);
		}
}

static void test_sides_and_polygon_domain(void **state)
{
	(void)state;
	static const double L[12] = {0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20};
	for (int m = 3; m <= 8; m++) {
		for (int g = 0; g < 2; g++) {
			dem_front_spec_t s = spec(DEM_FRONT_POLYGON, DEM_FRONT_OPEN, 20, 0.4, 1.5, 2);
			s.sides = m;
			s.polygon = L;
			s.npolygon = 6;
			s.gravity = g;
			struct bodies B;
			dem_front_stats_t st;
			char label[64];
			snprintf(label, sizeof label, "L, %d sides%s", m, g ? ", gravity" : "");
			pack(&s, 7, &B, &st);
			assert_true(B.n > 100);
			check(&s, &B, label);
			free(B.b);
		}
	}
	/* ellipses in the L: no overlap, each inside (ellipse_in_polygon) */
	dem_front_spec_t s = spec(DEM_FRONT_ELLIPSE, DEM_FRONT_OPEN, 20, 0.4, 1.5, 4);
	s.polygon = L;
	s.npolygon = 6;
	struct bodies B;
	dem_front_stats_t st;
	pack(&s, 7, &B, &st);
	assert_true(B.n > 100);
	check(&s, &B, "ellipses in the L");
	free(B.b);
}

static void test_refused(void **state)
{
	(void)state;
	struct bodies B = {0};
	dem_error_t e;
	gsl_rng *g = dem_rng_derive(1, 0);
	dem_front_spec_t s = spec(DEM_FRONT_POLYGON, DEM_FRONT_OPEN, 10, 0.3, 1, 2);
	s.sides = 2;
	dem_error_clear(&e);
	assert_int_equal(dem_pack_front_bodies(&s, g, keep, &B, NULL, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "sides"));
	s = spec(DEM_FRONT_ELLIPSE, DEM_FRONT_OPEN, 10, 0.3, 1, 2);
	s.ratio.rmin = 0.5;
	dem_error_clear(&e);
	assert_int_equal(dem_pack_front_bodies(&s, g, keep, &B, NULL, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "aspect"));
	assert_int_equal(B.n, 0);
	gsl_rng_free(g);
}

/* The lowest point (lx, ly) of a body and its extent in x [xlo, xhi]:
 * the ellipse (a, b, theta) in closed form, with A = R diag(a^2, b^2) R^T
 * its support point in the direction -y is -A e_y / sqrt(A11) and its
 * half-width sqrt(A00); the polygon by its vertices. */
static void body_bottom(const dem_front_body_t *b, int shape, int m, double *lx, double *ly,
			double *xlo, double *xhi)
{
	if (shape == DEM_FRONT_ELLIPSE) {
		double c = cos(b->theta), s = sin(b->theta), a2 = b->a * b->a, b2 = b->b * b->b;
		double a00 = a2 * c * c + b2 * s * s, a01 = (a2 - b2) * c * s, a11 = a2 * s * s + b2 * c * c;
		*lx = b->x[0] - a01 / sqrt(a11);
		*ly = b->x[1] - sqrt(a11);
		*xlo = b->x[0] - sqrt(a00);
		*xhi = b->x[0] + sqrt(a00);
		return;
	}
	double V[64][2];
	x2_polygon(b->x[0], b->x[1], b->a, b->b, b->theta, m, V);
	*lx = V[0][0], *ly = V[0][1], *xlo = *xhi = V[0][0];
	for (int k = 1; k < m; k++) {
		if (V[k][1] < *ly)
			*lx = V[k][0], *ly = V[k][1];
		*xlo = fmin(*xlo, V[k][0]);
		*xhi = fmax(*xhi, V[k][0]);
	}
}

/* The gravity rule (Fig. 5.9) with the true contact on a wall: a body in
 * a bottom corner rests on the side wall and the floor, and is stable
 * only when the vertical through its centre meets the segment between
 * the two contacts.  The floor contact is the body's lowest point, not the
 * foot of the perpendicular from its centre (that holds for disks only).
 * So a body touching the left wall and the floor has its lowest point at
 * or right of its centre, and one touching the right wall at or left of
 * it; a tilted ellipse or polygon breaks this half the time when the
 * rule takes the foot. */
static void test_gravity_wall_contact(void **state)
{
	(void)state;
	int corners = 0;
	for (int sh = DEM_FRONT_POLYGON; sh <= DEM_FRONT_ELLIPSE; sh++)
		for (unsigned long seed = 1; seed <= 30; seed++) {
			dem_front_spec_t s = spec((dem_front_shape_t)sh, DEM_FRONT_OPEN, 4, 0.3, 1.5, 3);
			s.gravity = 1;
			struct bodies B;
			dem_front_stats_t st;
			pack(&s, seed, &B, &st);
			for (size_t i = 0; i < B.n; i++) {
				const dem_front_body_t *b = &B.b[i];
				double size = sqrt(b->a * b->b), touch = 1e-6 * size, lx, ly, xlo, xhi;
				body_bottom(b, sh, s.sides, &lx, &ly, &xlo, &xhi);
				if (ly - s.lo[1] > touch)
					continue;
				int left = xlo - s.lo[0] < touch, right = s.hi[0] - xhi < touch;
				if ((left && lx < b->x[0] - EPS * size) || (right && lx > b->x[0] + EPS * size))
					fail_msg("%s %zu (seed %lu) in the %s corner: its lowest point at x = %.9g, "
						 "its centre at %.9g", dem_front_shape_names[sh], i, seed,
						 left ? "left" : "right", lx, b->x[0]);
				corners += left + right;
			}
			free(B.b);
		}
	/* most packings fill both corners */
	assert_true(corners >= 60);
}

/* Translation, as test_far_from_origin in test_front.c: polygons and
 * ellipses in the rectangle moved by 2^20 (1, -1), about 10^6 sizes from
 * the origin, are the bodies at the origin moved, each centre within
 * 1e-6 of its size, with as many segments given up, and no overlap by the
 * exact tests. */
static void test_far_from_origin(void **state)
{
	(void)state;
	const double X = 1048576, Y = -1048576;
	for (int sh = DEM_FRONT_POLYGON; sh <= DEM_FRONT_ELLIPSE; sh++)
		for (int g = 0; g < 2; g++) {
			dem_front_spec_t s = spec((dem_front_shape_t)sh, DEM_FRONT_OPEN, 20, 0.5, 2, 3);
			s.gravity = g;
			struct bodies A, B;
			dem_front_stats_t sa, sb;
			char label[64];
			snprintf(label, sizeof label, "%s%s, moved by 2^20", dem_front_shape_names[sh],
				 g ? " gravity" : "");
			pack(&s, 4, &A, &sa);
			s.lo[0] += X, s.hi[0] += X, s.lo[1] += Y, s.hi[1] += Y;
			pack(&s, 4, &B, &sb);
			if (B.n != A.n || sb.failed != sa.failed)
				fail_msg("%s: %zu bodies (%zu failed), at the origin %zu (%zu)", label, B.n,
					 sb.failed, A.n, sa.failed);
			for (size_t i = 0; i < A.n; i++) {
				const dem_front_body_t *a = &A.b[i], *b = &B.b[i];
				double size = sqrt(a->a * a->b);
				assert_true(a->a == b->a && a->b == b->b && a->theta == b->theta);
				if (fabs(b->x[0] - X - a->x[0]) > 1e-6 * size ||
				    fabs(b->x[1] - Y - a->x[1]) > 1e-6 * size)
					fail_msg("%s: body %zu at (%.17g, %.17g), at the origin (%.17g, %.17g)",
						 label, i, b->x[0] - X, b->x[1] - Y, a->x[0], a->x[1]);
			}
			check(&s, &B, label);
			print_message("# %s: %zu bodies, the same as at the origin\n", label, B.n);
			free(A.b);
			free(B.b);
		}
}

/* The polygon bodies' area in the statistics: a b (m / 2) sin(2 pi / m)
 * each, the regular m-gon of circumradius 1 (area (m / 2) sin(2 pi / m))
 * stretched by a and b; and the library's polygon of the body stream's
 * shape 1 (dem_polygon_regular, which the packer and lib/body share) is
 * the checker's x2_polygon point for point. */
static void test_polygon_area(void **state)
{
	(void)state;
	for (int m = 3; m <= 64; m += m < 8 ? 1 : 28) {
		double V[64][2], W[64][2];
		dem_polygon_regular(m, 1.7, 0.6, V);
		x2_polygon(0, 0, 1.7, 0.6, 0, m, W);
		for (int k = 0; k < m; k++)
			assert_true(fabs(V[k][0] - W[k][0]) < 1e-15 && fabs(V[k][1] - W[k][1]) < 1e-15);
		dem_front_spec_t s = spec(DEM_FRONT_POLYGON, DEM_FRONT_OPEN, 8, 0.4, 1.5, 3);
		s.sides = m;
		struct bodies B;
		dem_front_stats_t st;
		pack(&s, 3, &B, &st);
		double a = 0;
		for (size_t i = 0; i < B.n; i++)
			a += B.b[i].a * B.b[i].b * 0.5 * m * sin(2 * X2_PI / m);
		assert_true(B.n > 20);
		assert_int_equal(st.kept, B.n);
		if (!(fabs(st.area - a) <= 1e-12 * a))
			fail_msg("%d sides: area %.17g, closed form %.17g", m, st.area, a);
		assert_true(fabs(st.density - a / 64) <= 1e-12 * st.density);
		free(B.b);
	}
}

/* 10^5 bodies a shape, aspect ratios 1 to 5 (issue 20, acceptance 1). */
static void test_large(void **state)
{
	(void)state;
	for (int sh = DEM_FRONT_POLYGON; sh <= DEM_FRONT_ELLIPSE; sh++) {
		/* URD sizes [0.5, 1]: about 0.3 bodies per unit area */
		double w = SLOW_CASES(580, 150);
		dem_front_spec_t s = spec((dem_front_shape_t)sh, DEM_FRONT_OPEN, w, 0.5, 2, 5);
		struct bodies B;
		dem_front_stats_t st;
		char label[64];
		snprintf(label, sizeof label, "%s, %g x %g", dem_front_shape_names[sh], w, w);
		pack(&s, 2, &B, &st);
		report(label, &B, &st);
		assert_true(B.n > (size_t)(0.2 * w * w));
		check(&s, &B, label);
		free(B.b);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_wwk_against_sampling),
		cmocka_unit_test(test_wwk_thin),
		cmocka_unit_test(test_sat),
		cmocka_unit_test(test_minkowski),
		cmocka_unit_test(test_ellipse_geometry),
		cmocka_unit_test(test_newton_count),
		cmocka_unit_test(test_ellipse_in_polygon),
		cmocka_unit_test(test_forms),
		cmocka_unit_test(test_sides_and_polygon_domain),
		cmocka_unit_test(test_refused),
		cmocka_unit_test(test_gravity_wall_contact),
		cmocka_unit_test(test_far_from_origin),
		cmocka_unit_test(test_polygon_area),
		cmocka_unit_test(test_large),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
