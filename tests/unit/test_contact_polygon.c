/* test_contact_polygon.c - unit tests of lib/contact/polygon.c: the
 * superquadric's polygon (Box 4.1), polygon properties, the overlap of two
 * convex polygons by the linear algorithm with and without the clip of
 * Ch. 4.3.2 and by full Sutherland-Hodgman clipping, and the Feng-Owen
 * contact geometry (Han 2004, Ch. 4.2-4.4).
 *
 * References: the superquadric's equation (every point on the curve),
 * the exact area and polar moment of the superquadric (Dirichlet
 * integrals; pi a b and pi a b (a^2 + b^2)/4 for the ellipse), closed forms
 * for rectangles and triangles; each degenerate case of the overlap
 * (shared point, point on an edge, collinear edges, identical polygons,
 * one inside the other, contact without area, disjoint, nearly parallel
 * edges) against its area and centroid worked by hand; the two methods
 * against each other on 10^4 random pairs of each kind (superquadrics,
 * triangles, squares, integer-grid polygons) to 1e-12 of the size scale;
 * the force and moment of the contact against finite differences of
 * W(S) with S from the reference overlap.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/polygon.h"
#include "core/consts.h"
#include "polygen.h"

#define MAXV 2048

/* the three methods on one pair: chase with clip, chase without, clip */
typedef struct three {
	dem_overlap_t o[3];
	double v[3][2 * MAXV][2];
	unsigned char side[3][2 * MAXV];
	double work[4 * MAXV][2];
} three_t;

static three_t T;  /* too big for the stack */

static void overlap3(int n, const double (*P)[2], int m, const double (*Q)[2])
{
	dem_polygon_chase(n, P, m, Q, 1, T.v[0], T.side[0], T.work, &T.o[0]);
	dem_polygon_chase(n, P, m, Q, 0, T.v[1], T.side[1], T.work, &T.o[1]);
	dem_polygon_clip(n, P, m, Q, T.v[2], T.side[2], T.work, &T.o[2]);
	for (int k = 0; k < 3; k++)
		assert_true(T.o[k].nv <= n + m);
}

/* all three methods give area S and centroid (cx, cy) to tol */
static void expect3(int n, const double (*P)[2], int m, const double (*Q)[2], double S,
                    double cx, double cy, double tol, const char *what)
{
	overlap3(n, P, m, Q);
	for (int k = 0; k < 3; k++) {
		const dem_overlap_t *o = &T.o[k];
		if (fabs(o->S - S) > tol || (S > 0 && (fabs(o->c[0] - cx) > tol || fabs(o->c[1] - cy) > tol))) {
			fprintf(stderr, "%s: method %d: S %.17g (%.17g) c %.17g %.17g (%.17g %.17g)\n", what, k,
			        o->S, S, o->c[0], o->c[1], cx, cy);
			fail();
		}
		if (S == 0)
			assert_int_equal(o->nv, 0);
	}
}

#define EXPECT(P, Q, S, cx, cy, what)                                                    \
	expect3((int)(sizeof P / sizeof *P), (const double (*)[2])P, (int)(sizeof Q / sizeof *Q), \
	        (const double (*)[2])Q, S, cx, cy, 1e-14, what)

/* ---- superquadric --------------------------------------------------------- */

static void test_superquadric_polygon(void **state)
{
	(void)state;
	static double v[1 << 16][2];
	const double ms[] = { 1, 2, 3, 5, 15, 40 };
	for (size_t im = 0; im < sizeof ms / sizeof *ms; im++) {
		double a = 4.5, b = 3.5, m = ms[im];
		int need = dem_superquadric_polygon(a, b, m, 1e-3, 0, NULL);
		assert_true(need >= 4 && need % 4 == 0 && need <= 1 << 16);
		int n = dem_superquadric_polygon(a, b, m, 1e-3, need, v);
		assert_int_equal(n, need);
		assert_true(v[0][0] == a && v[0][1] == 0);
		assert_true(v[n / 4][0] == 0 && v[n / 4][1] == b);
		for (int i = 0; i < n; i++) {
			/* on the curve (Eq. 4.1), convex and anticlockwise, mirrored */
			double f = pow(fabs(v[i][0] / a), m) + pow(fabs(v[i][1] / b), m);
			assert_true(fabs(f - 1) < 1e-12);
			int j = (i + 1) % n, k = (i + 2) % n;
			double o = (v[j][0] - v[i][0]) * (v[k][1] - v[i][1]) -
			           (v[j][1] - v[i][1]) * (v[k][0] - v[i][0]);
			assert_true(o > 0 || (m == 1 && o == 0));
			int ii = (n - i) % n;  /* the point mirrored about the x axis */
			assert_true(v[ii][0] == v[i][0] && v[ii][1] == -v[i][1]);
		}
	}
	/* the rhombus m = 1 is flat at once: 4 points */
	assert_int_equal(dem_superquadric_polygon(1, 2, 1, 1e-6, 0, NULL), 4);
	/* bad parameters */
	assert_int_equal(dem_superquadric_polygon(0, 1, 2, 1e-3, 0, NULL), -1);
	assert_int_equal(dem_superquadric_polygon(1, 1, 0.5, 1e-3, 0, NULL), -1);
	assert_int_equal(dem_superquadric_polygon(1, 1, 2, 0, 0, NULL), -1);
	assert_int_equal(dem_superquadric_polygon(1, 1, NAN, 1e-3, 0, NULL), -1);
}

/* The inscribed polygon's area and polar moment converge to the exact
 * superquadric's as tau falls, always from below: about as tau^2 (an edge
 * of length l on a curvature k is flat for l k / 8 < tau, so there are
 * some 1/tau edges, each cutting off a sliver of about l^3 k / 12).
 * For m > 2 the parametrisation of Eq. 4.3 runs infinitely fast at the
 * axes, where the middle point then understates the distance (Eq. 4.5's
 * stand-in for Eq. 4.4): the error falls more slowly, about as tau^1.5
 * for m = 5 and 15 (2.5e-6 and 2.2e-5 at tau = 1e-4, against 6.8e-8 for
 * the ellipse). */
static void test_superquadric_convergence(void **state)
{
	(void)state;
	static double v[1 << 16][2];
	const double ms[] = { 2, 5, 15 };
	for (size_t im = 0; im < sizeof ms / sizeof *ms; im++) {
		double a = 4.5, b = 3.5, m = ms[im];
		dem_area_props_t ex, p;
		dem_superquadric_props(a, b, m, &ex);
		if (m == 2) {
			assert_true(fabs(ex.A - DEM_PI * a * b) < 1e-13 * ex.A);
			assert_true(fabs(ex.J - DEM_PI * a * b * (a * a + b * b) / 4) < 1e-13 * ex.J);
		}
		double prev = HUGE_VAL;
		for (double tau = 1e-1; tau >= 1e-4 * 0.99; tau /= 10) {
			int n = dem_superquadric_polygon(a, b, m, tau, 1 << 16, v);
			assert_true(n > 0 && n <= 1 << 16);
			dem_polygon_props(n, (const double (*)[2])v, &p);
			double eA = (ex.A - p.A) / ex.A, eJ = (ex.J - p.J) / ex.J;
			if (getenv("TEST_VERBOSE"))
				fprintf(stderr, "m %g tau %g n %d eA %.3g eJ %.3g\n", m, tau, n, eA, eJ);
			assert_true(eA > 0 && eJ > 0);
			assert_true(eA < (m == 2 ? 10 * tau * tau : 30 * pow(tau, 1.5)));
			assert_true(eA < prev / 5);
			assert_true(fabs(p.c[0]) < 1e-14 * a && fabs(p.c[1]) < 1e-14 * b);
			prev = eA;
		}
		assert_true(prev < (m == 2 ? 1e-7 : 3e-5));
	}
}

static void test_polygon_props(void **state)
{
	(void)state;
	/* rectangle w x h far from the origin: A = w h, J = A (w^2 + h^2)/12 */
	const double w = 3, h = 2, x0 = 1e6, y0 = -2e6;
	double r[4][2] = { { x0, y0 }, { x0 + w, y0 }, { x0 + w, y0 + h }, { x0, y0 + h } };
	dem_area_props_t p;
	dem_polygon_props(4, (const double (*)[2])r, &p);
	assert_true(fabs(p.A - w * h) < 1e-12);
	assert_true(fabs(p.c[0] - (x0 + w / 2)) < 1e-9 && fabs(p.c[1] - (y0 + h / 2)) < 1e-9);
	assert_true(fabs(p.J - w * h * (w * w + h * h) / 12) < 1e-9);
	/* clockwise: the area negative */
	double cw[4][2] = { { 0, 0 }, { 0, 1 }, { 1, 1 }, { 1, 0 } };
	dem_polygon_props(4, (const double (*)[2])cw, &p);
	assert_true(p.A == -1);
	/* a right triangle with legs a, b: J = A (a^2 + b^2)/18 about its centroid */
	double t[3][2] = { { 0, 0 }, { 3, 0 }, { 0, 4 } };
	dem_polygon_props(3, (const double (*)[2])t, &p);
	assert_true(fabs(p.A - 6) < 1e-15 && fabs(p.c[0] - 1) < 1e-15 && fabs(p.c[1] - 4.0 / 3) < 1e-15);
	assert_true(fabs(p.J - 6 * 25.0 / 18) < 1e-13);
	/* placing keeps A and J and moves the centroid */
	double u[3][2], x[2] = { 5, -7 };
	dem_polygon_place(3, (const double (*)[2])t, x, 0.7, u);
	dem_area_props_t q;
	dem_polygon_props(3, (const double (*)[2])u, &q);
	assert_true(fabs(q.A - p.A) < 1e-13 && fabs(q.J - p.J) < 1e-12);
	double cx = 5 + cos(0.7) * p.c[0] - sin(0.7) * p.c[1];
	double cy = -7 + sin(0.7) * p.c[0] + cos(0.7) * p.c[1];
	assert_true(fabs(q.c[0] - cx) < 1e-13 && fabs(q.c[1] - cy) < 1e-13);
}

/* ---- degenerate overlaps ------------------------------------------------ */

static const double SQ2[4][2] = { { 0, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 } };  /* [0, 2]^2 */

static void test_shared_vertex(void **state)
{
	(void)state;
	/* corner to corner: no area */
	const double Q1[4][2] = { { 2, 2 }, { 4, 2 }, { 4, 4 }, { 2, 4 } };
	EXPECT(SQ2, Q1, 0, 0, 0, "corner to corner");
	/* a triangle from P's corner (0, 0) into it: the square less two
	 * triangles of area 1, S = 2, centroid (7/6, 7/6) */
	const double Q2[3][2] = { { 0, 0 }, { 4, 2 }, { 2, 4 } };
	EXPECT(SQ2, Q2, 2, 7.0 / 6, 7.0 / 6, "shared corner");
	EXPECT(Q2, SQ2, 2, 7.0 / 6, 7.0 / 6, "shared corner, swapped");
	/* a triangle on two of P's corners (and so along its edge), its apex
	 * outside: the triangle's area 3 less the tip above y = 2 (height 1,
	 * base 2/3, area 1/3, centroid at y = 2 + 1/3) */
	const double Q3[3][2] = { { 0, 0 }, { 2, 0 }, { 1, 3 } };
	double S3 = 3 - 1.0 / 3;
	double cy3 = (3 * 1.0 - (1.0 / 3) * (2 + 1.0 / 3)) / S3;
	EXPECT(SQ2, Q3, S3, 1, cy3, "two shared corners and a shared edge");
}

static void test_vertex_on_edge(void **state)
{
	(void)state;
	/* Q's corner (1, 0) on P's bottom edge, Q into P: S = 3,
	 * centroid (1, 11/9) */
	const double Q1[3][2] = { { 1, 0 }, { 3, 2 }, { -1, 2 } };
	EXPECT(SQ2, Q1, 3, 1, 11.0 / 9, "corner on an edge");
	EXPECT(Q1, SQ2, 3, 1, 11.0 / 9, "corner on an edge, swapped");
	/* Q's edge through P's corner (2, 2), Q outside: one point in common */
	const double Q2[3][2] = { { 1, 3 }, { 3, 1 }, { 3, 3 } };
	EXPECT(SQ2, Q2, 0, 0, 0, "edge through a corner");
	EXPECT(Q2, SQ2, 0, 0, 0, "edge through a corner, swapped");
	/* Q's corner on P's edge from outside: one point in common */
	const double Q3[3][2] = { { 1, 2 }, { 2, 3 }, { 0, 3 } };
	EXPECT(SQ2, Q3, 0, 0, 0, "corner touching an edge");
}

static void test_collinear_edges(void **state)
{
	(void)state;
	/* the same direction, overlapping: [1, 2] x [0, 2] */
	const double Q1[4][2] = { { 1, 0 }, { 3, 0 }, { 3, 2 }, { 1, 2 } };
	EXPECT(SQ2, Q1, 2, 1.5, 1, "two collinear edge pairs");
	/* one collinear pair, with collinear points on P's edges */
	const double P5[8][2] = { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 2, 2 }, { 1, 2 }, { 0, 2 }, { 0, 1 } };
	const double Q2[3][2] = { { 1, 0 }, { 3, 0 }, { 1, 2 } };
	/* the triangle's part in the square: [1, 2] x [0, 2] less the corner
	 * above x + y = 3 (area 1/2, centroid (5/3, 5/3)); its long edge
	 * passes through two of P's points */
	double S2 = 1.5, cx2 = (2 * 1.5 - 0.5 * (5.0 / 3)) / S2, cy2 = (2 * 1.0 - 0.5 * (5.0 / 3)) / S2;
	EXPECT(P5, Q2, S2, cx2, cy2, "collinear bottom edges, collinear points");
	EXPECT(Q2, P5, S2, cx2, cy2, "collinear bottom edges, swapped");
	/* opposite directions: the squares side by side, touching along x = 2 */
	const double Q3[4][2] = { { 2, 1 }, { 3, 1 }, { 3, 3 }, { 2, 3 } };
	EXPECT(SQ2, Q3, 0, 0, 0, "touching along an edge");
	/* stacked, the whole edge shared */
	const double Q4[4][2] = { { 0, 2 }, { 2, 2 }, { 2, 4 }, { 0, 4 } };
	EXPECT(SQ2, Q4, 0, 0, 0, "a whole edge shared");
}

static void test_identical(void **state)
{
	(void)state;
	EXPECT(SQ2, SQ2, 4, 1, 1, "identical squares");
	static double v[4096][2];
	int n = dem_superquadric_polygon(4.5, 3.5, 5, 1e-3, 4096, v);
	double x[2] = { 0.3, -0.2 };
	dem_polygon_place(n, (const double (*)[2])v, x, 0.4, v);
	dem_area_props_t p;
	dem_polygon_props(n, (const double (*)[2])v, &p);
	expect3(n, (const double (*)[2])v, n, (const double (*)[2])v, p.A, p.c[0], p.c[1],
	        1e-12 * p.A, "identical superquadrics");
}

static void test_inside(void **state)
{
	(void)state;
	const double Q1[3][2] = { { 0.5, 0.5 }, { 1.5, 0.5 }, { 0.5, 1.5 } };
	EXPECT(SQ2, Q1, 0.5, 5.0 / 6, 5.0 / 6, "triangle inside the square");
	EXPECT(Q1, SQ2, 0.5, 5.0 / 6, 5.0 / 6, "square round the triangle");
	/* inside, one corner shared */
	const double Q2[3][2] = { { 0, 0 }, { 1, 0.5 }, { 0.5, 1 } };
	EXPECT(SQ2, Q2, 0.375, 0.5, 0.5, "inside with a shared corner");
	EXPECT(Q2, SQ2, 0.375, 0.5, 0.5, "inside with a shared corner, swapped");
	/* inside, touching an edge along a stretch */
	const double Q3[3][2] = { { 0.5, 0 }, { 1.5, 0 }, { 1, 1 } };
	EXPECT(SQ2, Q3, 0.5, 1, 1.0 / 3, "inside along an edge");
	EXPECT(Q3, SQ2, 0.5, 1, 1.0 / 3, "inside along an edge, swapped");
}

static void test_disjoint(void **state)
{
	(void)state;
	const double Q1[3][2] = { { 5, 5 }, { 6, 5 }, { 5, 6 } };
	EXPECT(SQ2, Q1, 0, 0, 0, "far apart");
	/* the boxes overlap, the polygons do not */
	const double P2[3][2] = { { 0, 0 }, { 2, 0 }, { 0, 2 } };
	const double Q2[3][2] = { { 2, 1.5 }, { 2, 2 }, { 1.5, 2 } };
	EXPECT(P2, Q2, 0, 0, 0, "boxes overlapping");
	EXPECT(Q2, P2, 0, 0, 0, "boxes overlapping, swapped");
	/* parallel edges facing each other a little apart */
	const double Q3[4][2] = { { 0, 2.5 }, { 2, 2.5 }, { 2, 3 }, { 0, 3 } };
	EXPECT(SQ2, Q3, 0, 0, 0, "parallel, apart");
}

static void test_nearly_parallel(void **state)
{
	(void)state;
	for (double d = 1e-3; d >= 1e-15; d /= 100) {
		/* Q's bottom edge tilted by d across P's top edge y = 2: the
		 * overlap is the thin triangle (0.5, 2-d) (1, 2) (0.5, 2) */
		const double Q[4][2] = { { 0.5, 2 - d }, { 1.5, 2 + d }, { 1.5, 3 }, { 0.5, 3 } };
		/* d as the coordinates hold it, below and above y = 2 */
		double d1 = 2 - (2 - d), d2 = (2 + d) - 2, xc = 0.5 + d1 / (d1 + d2);
		double S = 0.5 * d1 * (xc - 0.5), cx = (0.5 + xc + 0.5) / 3, cy = (2 - d1 + 2 + 2) / 3;
		overlap3(4, SQ2, 4, Q);
		for (int k = 0; k < 3; k++) {
			assert_true(fabs(T.o[k].S - S) < 1e-9 * S);
			assert_true(fabs(T.o[k].c[0] - cx) < 1e-9 && fabs(T.o[k].c[1] - cy) < 1e-12);
		}
		/* nearly parallel and overlapping along the whole width: a
		 * trapezoid of width 1, height 0.5 - d/2 on average */
		const double R[4][2] = { { 0.5, 1.5 }, { 1.5, 1.5 + d }, { 1.5, 3 }, { 0.5, 3 } };
		overlap3(4, SQ2, 4, R);
		double dr = (1.5 + d) - 1.5;
		for (int k = 0; k < 3; k++)
			assert_true(fabs(T.o[k].S - (0.5 - dr / 2)) < 1e-15);
	}
}

/* ---- random pairs: the methods agree ------------------------------------- */

static double P_[MAXV][2], Q_[MAXV][2];

/* N pairs of the kinds (kp, kq); returns the largest difference of area
 * (relative to L^2) and of centroid (relative to L, for overlaps above
 * 1e-6 L^2: the centroid of a tiny sliver between nearly parallel edges
 * moves with the round-off of its points), L the smaller polygon's size,
 * of the chase with and without the clip against the reference */
static void agree(unsigned long seed, int N, int kp, int kq, double tau, double *dS, double *dc)
{
	unsigned long s = seed;
	*dS = *dc = 0;
	int hits = 0;
	for (int it = 0; it < N; it++) {
		int n = pg_poly(&s, kp, tau, MAXV, P_), m = pg_poly(&s, kq, tau, MAXV, Q_);
		assert_true(n <= MAXV && m <= MAXV);
		overlap3(n, (const double (*)[2])P_, m, (const double (*)[2])Q_);
		double L = fmin(pg_size(n, (const double (*)[2])P_), pg_size(m, (const double (*)[2])Q_));
		const dem_overlap_t *r = &T.o[2];
		hits += r->S > 0;
		for (int k = 0; k < 2; k++) {
			const dem_overlap_t *o = &T.o[k];
			double e = fabs(o->S - r->S) / (L * L);
			if (e > *dS)
				*dS = e;
			if (fmin(o->S, r->S) > 1e-6 * L * L) {
				double ec = hypot(o->c[0] - r->c[0], o->c[1] - r->c[1]) / L;
				if (ec > *dc)
					*dc = ec;
			}
			if (e > 1e-12) {
				fprintf(stderr, "pair %d (kinds %d %d, clip %d): S %.17g ref %.17g\n", it, kp, kq,
				        1 - k, o->S, r->S);
				fail();
			}
		}
	}
	/* the generator overlaps often enough to test something */
	assert_true(hits > N / 4);
}

static void test_random_pairs(void **state)
{
	(void)state;
	static const int kinds[][2] = { { POLY_SQ, POLY_SQ }, { POLY_TRI, POLY_TRI },
	                                { POLY_SQUARE, POLY_SQUARE }, { POLY_SQ, POLY_TRI },
	                                { POLY_TRI, POLY_SQUARE }, { POLY_GRID, POLY_GRID } };
	for (size_t k = 0; k < sizeof kinds / sizeof *kinds; k++) {
		double dS, dc;
		int N = kinds[k][0] == POLY_SQ ? 2000 : 2500;
		agree(1000 + k, N, kinds[k][0], kinds[k][1], 1e-2, &dS, &dc);
		if (getenv("TEST_VERBOSE"))
			fprintf(stderr, "kinds %d %d: max dS %.3g dc %.3g\n", kinds[k][0], kinds[k][1], dS, dc);
		assert_true(dS <= 1e-12 && dc <= 1e-12);
	}
}

/* ---- contact ------------------------------------------------------------- */

/* S of the body v0 placed at (x, theta) against Q, by the reference */
static double S_at(int n, const double (*v0)[2], const double x[2], double th, int m,
                   const double (*Q)[2])
{
	static double w[MAXV][2];
	dem_polygon_place(n, v0, x, th, w);
	dem_overlap_t o;
	dem_polygon_clip(n, (const double (*)[2])w, m, Q, T.v[2], T.side[2], T.work, &o);
	return o.S;
}

/* A square's corner into a square's edge: S = d^2 (a corner of 90 degrees
 * turned 45 degrees, depth d), the contact line on Q's edge, of width 2 d,
 * the normal straight up, c under the corner. */
static void test_contact_corner(void **state)
{
	(void)state;
	const double Qb[4][2] = { { -5, -5 }, { 5, -5 }, { 5, 0 }, { -5, 0 } };
	const double d = 0.1;
	/* P: a square of half diagonal 1 turned 45 degrees, its lowest corner at y = -d */
	double P[4][2] = { { 0, -d }, { 1, 1 - d }, { 0, 2 - d }, { -1, 1 - d } };
	dem_overlap_t o;
	dem_polygon_chase(4, (const double (*)[2])P, 4, Qb, 1, T.v[0], T.side[0], T.work, &o);
	assert_true(fabs(o.S - d * d) < 1e-15);
	double xp[2] = { 0, 1 - d };
	dem_poly_contact_t k;
	assert_int_equal(dem_polygon_contact(&o, (const double (*)[2])T.v[0], T.side[0], xp,
	                                     DEM_W_LINEAR, 2.0, 0, &k), 1);
	assert_int_equal(k.chains, 1);
	assert_true(fabs(k.bw - 2 * d) < 1e-15);
	assert_true(fabs(k.n[0]) < 1e-15 && fabs(k.n[1] - 1) < 1e-15);
	/* P enters Q at h = (-d, 0) and leaves at g = (d, 0) anticlockwise */
	assert_true(fabs(k.h[0] + d) < 1e-15 && fabs(k.h[1]) < 1e-15);
	assert_true(fabs(k.g[0] - d) < 1e-15 && fabs(k.g[1]) < 1e-15);
	assert_true(fabs(k.c[0]) < 1e-15 && fabs(k.c[1]) < 1e-15);
	assert_true(fabs(k.Fn - 2.0 * 2 * d) < 1e-15 && fabs(k.M) < 1e-15);
	/* Table 4.2 */
	assert_true(fabs(dem_wlaw_energy(DEM_W_HERTZ, 3, 0, 4) - 16) < 1e-15);
	assert_true(fabs(dem_wlaw_slope(DEM_W_HERTZ, 3, 0, 4) - 6) < 1e-15);
	assert_true(fabs(dem_wlaw_energy(DEM_W_POWER, 3, 3, 2) - 8) < 1e-15);
	assert_true(fabs(dem_wlaw_slope(DEM_W_POWER, 3, 3, 2) - 12) < 1e-15);
	assert_true(dem_wlaw_energy(DEM_W_LINEAR, 3, 0, -1) == 0);
	/* no overlap: no contact */
	P[0][1] = 0.5;
	dem_polygon_chase(4, (const double (*)[2])P, 4, Qb, 1, T.v[0], T.side[0], T.work, &o);
	assert_int_equal(dem_polygon_contact(&o, (const double (*)[2])T.v[0], T.side[0], xp,
	                                     DEM_W_LINEAR, 2.0, 0, &k), 0);
}

/* F = -dW/dxp and M = -dW/dtheta by central differences of W(S(x, theta))
 * (S by the reference overlap), for random bodies and the three laws;
 * both overlap methods' labels give the same force. */
static void test_contact_gradient(void **state)
{
	(void)state;
	static double v0[MAXV][2], w[MAXV][2], Q[MAXV][2];
	unsigned long s = 77;
	int tested = 0, multi = 0;
	for (int it = 0; it < 600; it++) {
		int kp = it % 3, kq = (it / 3) % 3;
		int n = pg_poly(&s, kp, 1e-2, MAXV, v0), m = pg_poly(&s, kq, 1e-2, MAXV, Q);
		/* the body in its own frame: about its centroid */
		dem_area_props_t pp;
		dem_polygon_props(n, (const double (*)[2])v0, &pp);
		for (int i = 0; i < n; i++)
			v0[i][0] -= pp.c[0], v0[i][1] -= pp.c[1];
		double x[2] = { 2 * pg_urand(&s) - 1, 2 * pg_urand(&s) - 1 }, th = 6 * pg_urand(&s);
		dem_polygon_place(n, (const double (*)[2])v0, x, th, w);
		dem_wlaw_t law = (dem_wlaw_t)((it / 9) % 3);
		double kn = 1e3, p = 2.5;
		dem_poly_contact_t kc[2];
		int in = 1;
		for (int meth = 0; meth < 2; meth++) {
			dem_overlap_t o;
			if (meth == 0)
				dem_polygon_chase(n, (const double (*)[2])w, m, (const double (*)[2])Q, 1,
				                  T.v[0], T.side[0], T.work, &o);
			else
				dem_polygon_clip(n, (const double (*)[2])w, m, (const double (*)[2])Q, T.v[0],
				                 T.side[0], T.work, &o);
			in &= dem_polygon_contact(&o, (const double (*)[2])T.v[0], T.side[0], x, law, kn,
			                          p, &kc[meth]);
		}
		if (!in)
			continue;
		dem_poly_contact_t *k = &kc[0];
		double L = fmin(pg_size(n, (const double (*)[2])w), pg_size(m, (const double (*)[2])Q));
		if (k->S < 1e-4 * L * L)
			continue;  /* a small overlap: the differences below would not resolve it */
		double h = 1e-6 * L, Fs = fmax(k->Fn, 1e-300);
		double dW[3];
		for (int c = 0; c < 3; c++) {
			double xa[2] = { x[0], x[1] }, xb[2] = { x[0], x[1] }, ta = th, tb = th;
			if (c < 2)
				xa[c] += h, xb[c] -= h;
			else
				ta += h / L, tb -= h / L;
			double Wa = dem_wlaw_energy(law, kn, p, S_at(n, (const double (*)[2])v0, xa, ta, m,
			                                             (const double (*)[2])Q));
			double Wb = dem_wlaw_energy(law, kn, p, S_at(n, (const double (*)[2])v0, xb, tb, m,
			                                             (const double (*)[2])Q));
			dW[c] = (Wa - Wb) / (c < 2 ? 2 * h : 2 * h / L);
		}
		double eF = hypot(k->F[0] + dW[0], k->F[1] + dW[1]) / Fs;
		double eM = fabs(k->M + dW[2]) / (Fs * L);
		/* the moment is that of F at c */
		double Mc = (k->c[0] - x[0]) * k->F[1] - (k->c[1] - x[1]) * k->F[0];
		double eC = fabs(Mc - k->M) / (Fs * L);
		double e2 = hypot(kc[1].F[0] - k->F[0], kc[1].F[1] - k->F[1]) / Fs;
		if (getenv("TEST_VERBOSE") || eF > 1e-5 || eM > 1e-5 || eC > 1e-12 || e2 > 1e-9) {
			fprintf(stderr, "it %d chains %d S %g: eF %.3g eM %.3g eC %.3g e2 %.3g\n", it,
			        k->chains, k->S, eF, eM, eC, e2);
			fprintf(stderr, " F %g %g FD %g %g M %g FD %g bw %g n %d m %d\n", k->F[0], k->F[1], -dW[0], -dW[1], k->M, -dW[2], k->bw, n, m);
			if (n < 10) for (int i = 0; i < n; i++) fprintf(stderr, " P %.17g %.17g\n", w[i][0], w[i][1]);
			if (m < 10) for (int i = 0; i < m; i++) fprintf(stderr, " Q %.17g %.17g\n", Q[i][0], Q[i][1]);
		}
		assert_true(eF < 1e-5 && eM < 1e-5 && eC < 1e-12 && e2 < 1e-9);
		/* the normal is a unit vector along F, pushing P out */
		assert_true(fabs(hypot(k->n[0], k->n[1]) - 1) < 1e-14);
		tested++;
		multi += k->chains > 1;
	}
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "contact: %d configurations, %d with several chains\n", tested, multi);
	assert_true(tested > 100 && multi > 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_superquadric_polygon),
		cmocka_unit_test(test_superquadric_convergence),
		cmocka_unit_test(test_polygon_props),
		cmocka_unit_test(test_shared_vertex),
		cmocka_unit_test(test_vertex_on_edge),
		cmocka_unit_test(test_collinear_edges),
		cmocka_unit_test(test_identical),
		cmocka_unit_test(test_inside),
		cmocka_unit_test(test_disjoint),
		cmocka_unit_test(test_nearly_parallel),
		cmocka_unit_test(test_random_pairs),
		cmocka_unit_test(test_contact_corner),
		cmocka_unit_test(test_contact_gradient),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
