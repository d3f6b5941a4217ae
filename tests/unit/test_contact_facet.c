/* test_contact_facet.c - unit tests of lib/contact/facet.c and sphere.c:
 * sphere/facet geometry with partial contact (Han 2004, Eqs. 3.13-3.22)
 * and sphere/sphere geometry.
 *
 * References: the overlap area S_p and centroid G of a circle and a
 * triangle against brute force (the area integrated by 40000 vertical
 * slices, each slice the intersection of two intervals), for random
 * configurations and for the edge cases (centre outside the facet, circle
 * covering the facet, circle tangent to an edge line from either side,
 * through a vertex, centre on an edge or a vertex); the facets of a flat
 * tiled surface must share the full contact exactly (sum of gamma = 1, by
 * area and by volume) wherever the sphere is, so the normal force is
 * continuous as the sphere slides across edges and vertices; statics of
 * the nodal distribution (sum and moment).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/facet.h"
#include "contact/model.h"
#include "contact/sphere.h"
#include "core/consts.h"

static double urand(unsigned long *s)  /* [0, 1) */
{
	*s = *s * 6364136223846793005ul + 1442695040888963407ul;
	return (*s >> 11) * (1.0 / 9007199254740992.0);
}

/* Brute force: slices x = const of the disk (centre 0, radius r) and of the
 * triangle; midpoint rule over [max(-r, xmin), min(r, xmax)]. */
static void brute(const double x[3], const double y[3], double r, double *S, double *Gx, double *Gy)
{
	double xl = fmax(-r, fmin(x[0], fmin(x[1], x[2])));
	double xr = fmin(r, fmax(x[0], fmax(x[1], x[2])));
	double s = 0, mx = 0, my = 0;
	const int N = 40000;
	if (xr > xl) {
		double h = (xr - xl) / N;
		for (int k = 0; k < N; k++) {
			double xs = xl + (k + 0.5) * h;
			double lo = HUGE_VAL, hi = -HUGE_VAL;
			for (int i = 0; i < 3; i++) {
				int j = (i + 1) % 3;
				double a = x[i], b = x[j];
				if ((xs - a) * (xs - b) > 0 || a == b)
					continue;
				double yy = y[i] + (y[j] - y[i]) * (xs - a) / (b - a);
				lo = fmin(lo, yy), hi = fmax(hi, yy);
			}
			double c = sqrt(fmax(0, r * r - xs * xs));
			lo = fmax(lo, -c), hi = fmin(hi, c);
			if (hi > lo) {
				double L = (hi - lo) * h;
				s += L, mx += xs * L, my += 0.5 * (lo + hi) * L;
			}
		}
	}
	*S = s;
	*Gx = s > 0 ? mx / s : 0;
	*Gy = s > 0 ? my / s : 0;
}

static void make_ccw(double x[3], double y[3])
{
	if ((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]) < 0) {
		double t = x[1]; x[1] = x[2]; x[2] = t;
		t = y[1]; y[1] = y[2]; y[2] = t;
	}
}

/* check one configuration; returns the area error relative to pi r^2 */
static double check_config(const double x[3], const double y[3], double r)
{
	double S, Mx, My, J, Sb, Gx, Gy;
	dem_circle_triangle(x, y, r, &S, &Mx, &My, &J);
	brute(x, y, r, &Sb, &Gx, &Gy);
	double ref = DEM_PI * r * r, err = fabs(S - Sb) / ref;
	if (err > 2e-6)
		fail_msg("area %.12g, brute force %.12g (r %g; triangle %g %g, %g %g, %g %g)",
		         S, Sb, r, x[0], y[0], x[1], y[1], x[2], y[2]);
	if (Sb > 1e-3 * ref) {
		double ex = Mx / S - Gx, ey = My / S - Gy;
		if (hypot(ex, ey) > 1e-5 * r)
			fail_msg("centroid (%g, %g), brute force (%g, %g)", Mx / S, My / S, Gx, Gy);
	}
	return err;
}

static void test_circle_triangle_random(void **state)
{
	(void)state;
	unsigned long s = 12345;
	double worst = 0;
	int outside = 0, covering = 0;
	for (int t = 0; t < 300; t++) {
		double x[3], y[3];
		for (int i = 0; i < 3; i++)
			x[i] = 2 * urand(&s) - 1, y[i] = 2 * urand(&s) - 1;
		make_ccw(x, y);
		double cx = 3 * urand(&s) - 1.5, cy = 3 * urand(&s) - 1.5, r = 0.05 + 2.5 * urand(&s);
		double X[3], Y[3];
		for (int i = 0; i < 3; i++)
			X[i] = x[i] - cx, Y[i] = y[i] - cy;
		/* count the cases covered: centre outside, circle covering the facet */
		double d0 = X[0] * Y[1] - X[1] * Y[0], d1 = X[1] * Y[2] - X[2] * Y[1], d2 = X[2] * Y[0] - X[0] * Y[2];
		if (d0 < 0 || d1 < 0 || d2 < 0)
			outside++;
		if (hypot(X[0], Y[0]) < r && hypot(X[1], Y[1]) < r && hypot(X[2], Y[2]) < r)
			covering++;
		worst = fmax(worst, check_config(X, Y, r));
	}
	assert_true(outside > 100);
	assert_true(covering > 20);
	print_message("circle/triangle: 300 random cases (%d centre outside, %d covering), worst area error %.2e pi r^2\n",
	              outside, covering, worst);
}

static void test_circle_triangle_edges(void **state)
{
	(void)state;
	double x[3] = { -0.6, 0.8, 0.1 }, y[3] = { -0.4, -0.4, 0.9 };
	/* tangent to the line of edge 0 (y = -0.4) from inside and outside */
	for (int side = -1; side <= 1; side += 2) {
		double r = 0.3, cy = -0.4 + side * r, X[3], Y[3];
		for (int i = 0; i < 3; i++)
			X[i] = x[i] - 0.1, Y[i] = y[i] - cy;
		check_config(X, Y, r);
		/* and just across the tangency */
		for (int i = 0; i < 3; i++)
			Y[i] = y[i] - (cy - side * 1e-9);
		check_config(X, Y, r);
	}
	/* circle through a vertex, centre on an edge, centre at a vertex,
	 * circle inside, circle covering */
	double cases[][3] = {
		{ -0.6 + 0.5, -0.4, 0.5 }, { 0.1, -0.4, 0.3 }, { 0.8, -0.4, 0.4 },
		{ 0.1, 0.0, 0.05 }, { 0.1, 0.0, 5.0 }, { 0.1, -0.4 + 0.3 + 1e-12, 0.3 },
		{ 3, 3, 0.5 }, { -0.6, -0.4, 1e-3 }
	};
	for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
		double X[3], Y[3];
		for (int i = 0; i < 3; i++)
			X[i] = x[i] - cases[c][0], Y[i] = y[i] - cases[c][1];
		check_config(X, Y, cases[c][2]);
	}
}

/* a random rotation applied to the 2D set-up: dem_facet_geom must agree
 * with the 2D result, G on the plane, area coordinates summing to 1 */
static void test_facet_geom_3d(void **state)
{
	(void)state;
	unsigned long s = 99;
	int partial = 0;
	for (int t = 0; t < 200; t++) {
		double a = 2 * DEM_PI * urand(&s), bb = DEM_PI * urand(&s), c = 2 * DEM_PI * urand(&s);
		/* rotation matrix from three angles (z-x-z) */
		double ca = cos(a), sa = sin(a), cb = cos(bb), sb = sin(bb), cc = cos(c), sc = sin(c);
		double Q[3][3] = {
			{ ca * cc - sa * cb * sc, -ca * sc - sa * cb * cc, sa * sb },
			{ sa * cc + ca * cb * sc, -sa * sc + ca * cb * cc, -ca * sb },
			{ sb * sc, sb * cc, cb }
		};
		double x[3], y[3];
		for (int i = 0; i < 3; i++)
			x[i] = 2 * urand(&s) - 1, y[i] = 2 * urand(&s) - 1;
		make_ccw(x, y);
		double R = 1 + urand(&s), delta = 0.3 * urand(&s) * R;
		double cx = 2 * urand(&s) - 1, cy = 2 * urand(&s) - 1;
		double X[3][3], O[3], off[3] = { urand(&s), urand(&s), urand(&s) };
		for (int i = 0; i < 3; i++) {
			double p[3] = { x[i], y[i], 0 };
			for (int k = 0; k < 3; k++)
				X[i][k] = off[k] + Q[k][0] * p[0] + Q[k][1] * p[1] + Q[k][2] * p[2];
		}
		double o[3] = { cx, cy, R - delta };
		for (int k = 0; k < 3; k++)
			O[k] = off[k] + Q[k][0] * o[0] + Q[k][1] * o[1] + Q[k][2] * o[2];
		double b = sqrt(delta * (2 * R - delta));
		double xs[3], ys[3], S, Mx, My, J;
		for (int i = 0; i < 3; i++)
			xs[i] = x[i] - cx, ys[i] = y[i] - cy;
		dem_circle_triangle(xs, ys, b, &S, &Mx, &My, &J);
		dem_facet_geom_t g;
		int in = dem_facet_geom(O, R, (const double (*)[3])X, DEM_PARTIAL_AREA, &g);
		if (S < 1e-12 * b * b) {
			assert_int_equal(in, 0);
			continue;
		}
		assert_int_equal(in, 1);
		partial += !g.full;
		assert_true(fabs(g.Sp - S) <= 1e-12 * DEM_PI * b * b);
		assert_true(fabs(g.gamma - S / (DEM_PI * b * b)) < 1e-12);
		assert_true(fabs(g.delta - delta) < 1e-12);
		/* G back in the 2D frame */
		double gl[3];
		for (int k = 0; k < 3; k++)
			gl[k] = g.G[k] - off[k];
		double g2[3] = { 0, 0, 0 };
		for (int k = 0; k < 3; k++)
			for (int i = 0; i < 3; i++)
				g2[k] += Q[i][k] * gl[i];
		assert_true(fabs(g2[0] - (cx + Mx / S)) < 1e-10);
		assert_true(fabs(g2[1] - (cy + My / S)) < 1e-10);
		assert_true(fabs(g2[2]) < 1e-10);
		/* area coordinates: sum 1, inside, reproduce G */
		assert_true(fabs(g.N[0] + g.N[1] + g.N[2] - 1) < 1e-12);
		for (int k = 0; k < 3; k++) {
			assert_true(g.N[k] > -1e-9);
			double p = g.N[0] * X[0][k] + g.N[1] * X[1][k] + g.N[2] * X[2][k];
			assert_true(fabs(p - g.G[k]) < 1e-10);
		}
		/* sphere behind the facet: no contact */
		double Ob[3];
		for (int k = 0; k < 3; k++)
			Ob[k] = 2 * g.G[k] - O[k];
		assert_int_equal(dem_facet_geom(Ob, R, (const double (*)[3])X, DEM_PARTIAL_AREA, &g), 0);
	}
	assert_true(partial > 50);
}

/* A flat surface z = 0 of nq x nq square quads of side h around the origin,
 * each split into 2 facets (diagonals alternating). */
#define NQ 10
typedef struct tiled {
	int nf;
	double X[2 * NQ * NQ][3][3];
} tiled_t;

static void make_tiled(tiled_t *t, double h)
{
	t->nf = 0;
	for (int i = 0; i < NQ; i++)
		for (int j = 0; j < NQ; j++) {
			double x0 = (i - NQ / 2) * h, y0 = (j - NQ / 2) * h;
			double P[4][3] = { { x0, y0, 0 }, { x0 + h, y0, 0 }, { x0 + h, y0 + h, 0 }, { x0, y0 + h, 0 } };
			int tri[2][3];
			if ((i + j) % 2) {
				int a[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
				memcpy(tri, a, sizeof tri);
			} else {
				int a[2][3] = { { 0, 1, 3 }, { 1, 2, 3 } };
				memcpy(tri, a, sizeof tri);
			}
			for (int f = 0; f < 2; f++, t->nf++)
				for (int k = 0; k < 3; k++)
					memcpy(t->X[t->nf][k], P[tri[f][k]], sizeof P[0]);
		}
}

static tiled_t tiles;

/* Slide a sphere across edges and vertices: sum of gamma = 1, summed force
 * continuous and equal to the full contact within the tilt of the O-G
 * directions (at most delta/R), nodal forces in balance. */
static void slide(double b_over_h, int scheme, double *worst_gamma, double *worst_step)
{
	const double R = 1, delta = 1e-3, h = sqrt(delta * (2 * R - delta)) / b_over_h;
	make_tiled(&tiles, h);
	dem_law_t law;
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_init(&law, 1, 1e9, 1.5, &e), DEM_OK);
	dem_contact_param_t p = { .law = law, .partial = scheme };
	dem_contact_model_t cm;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_OK);
	double Ffull = dem_law_force(&law, dem_law_kn(&law, R), delta);
	/* paths: along a grid line (through vertices), along a diagonal, generic */
	double paths[3][4] = { { -1.5, 0, 1.5, 0 }, { -1.5, -1.5, 1.5, 1.5 }, { -1.3, -0.4, 1.1, 1.45 } };
	double prev = -1;
	for (int q = 0; q < 3; q++) {
		prev = -1;
		for (int k = 0; k <= 1500; k++) {
			double t = k / 1500.0;
			dem_sphere_t s = { .R = R, .kn = dem_law_kn(&law, R) };
			s.x[0] = h * (paths[q][0] + t * (paths[q][2] - paths[q][0]));
			s.x[1] = h * (paths[q][1] + t * (paths[q][3] - paths[q][1]));
			s.x[2] = R - delta;
			double gs = 0, F[3] = { 0, 0, 0 }, Fn[3] = { 0, 0, 0 }, Mn[3] = { 0, 0, 0 }, MG[3] = { 0, 0, 0 };
			for (int f = 0; f < tiles.nf; f++) {
				dem_contact_state_t st;
				dem_contact_state_reset(&st);
				dem_facet_out_t o;
				if (!dem_contact_sphere_facet(&cm, &s, (const double (*)[3])tiles.X[f], NULL, 1, 1e-9, &st, &o))
					continue;
				gs += o.g.gamma;
				for (int i = 0; i < 3; i++)
					F[i] += o.c.F[i];
				/* statics: node forces sum to -F and have its moment at G */
				double mg[3], fneg[3] = { -o.c.F[0], -o.c.F[1], -o.c.F[2] };
				mg[0] = o.g.G[1] * fneg[2] - o.g.G[2] * fneg[1];
				mg[1] = o.g.G[2] * fneg[0] - o.g.G[0] * fneg[2];
				mg[2] = o.g.G[0] * fneg[1] - o.g.G[1] * fneg[0];
				for (int a = 0; a < 3; a++) {
					const double *X = tiles.X[f][a], *P = o.Fnode[a];
					for (int i = 0; i < 3; i++)
						Fn[i] += P[i];
					Mn[0] += X[1] * P[2] - X[2] * P[1];
					Mn[1] += X[2] * P[0] - X[0] * P[2];
					Mn[2] += X[0] * P[1] - X[1] * P[0];
				}
				for (int i = 0; i < 3; i++)
					MG[i] += mg[i];
			}
			*worst_gamma = fmax(*worst_gamma, fabs(gs - 1));
			assert_true(fabs(gs - 1) < 1e-9);
			for (int i = 0; i < 3; i++) {
				assert_true(fabs(Fn[i] + F[i]) < 1e-9 * Ffull);
				/* the potential's forces act along the lines to O, not at G */
				if (scheme != DEM_PARTIAL_POTENTIAL)
					assert_true(fabs(Mn[i] - MG[i]) < 1e-9 * Ffull * h * NQ);
			}
			/* the normal force: full contact within delta/R (the O-G tilt);
			 * the potential's is the law's, to its quadrature */
			double tol = scheme == DEM_PARTIAL_POTENTIAL ? 1e-6 : delta / R;
			assert_true(fabs(F[2] - Ffull) <= tol * Ffull);
			assert_true(hypot(F[0], F[1]) <= tol * Ffull);
			if (prev > 0)
				*worst_step = fmax(*worst_step, fabs(F[2] - prev) / prev);
			prev = F[2];
		}
	}
	assert_true(*worst_step < 0.05);
}

static void test_tiled_surface(void **state)
{
	(void)state;
	double ratios[3] = { 2.5, 0.8, 0.3 };  /* contact radius over facet size */
	static const char *const name[] = { "potential", "area", "volume" };
	for (int sc = 0; sc < 3; sc++)
		for (int r = 0; r < 3; r++) {
			double wg = 0, ws = 0;
			slide(ratios[r], sc, &wg, &ws);
			print_message("tiled surface, b/h = %.1f, %s: |sum gamma - 1| <= %.1e, largest force step %.1e\n",
			              ratios[r], name[sc], wg, ws);
		}
}

/* Volume scheme against a direct numerical integral of the paraboloidal
 * cap over the overlap, and gamma = 1 for a facet covering the circle. */
static void test_volume_scheme(void **state)
{
	(void)state;
	const double R = 1, delta = 0.01, b = sqrt(delta * (2 * R - delta));
	double X[3][3] = { { -0.05, -0.2, 0 }, { 0.3, -0.05, 0 }, { -0.1, 0.25, 0 } };
	for (int c = 0; c < 3; c++) {
		/* centre inside the facet near a vertex, near an edge, outside */
		double cs[3][2] = { { 0.0, -0.1 }, { 0.05, 0.05 }, { 0.25, 0.15 } };
		double O[3] = { cs[c][0], cs[c][1], R - delta };
		dem_facet_geom_t g;
		assert_int_equal(dem_facet_geom(O, R, (const double (*)[3])X, DEM_PARTIAL_VOLUME, &g), 1);
		/* grid integral of delta (1 - r^2/b^2) over the circle inside the facet */
		double V = 0, Vx = 0, Vy = 0, hh = b / 1000;
		for (double x = O[0] - b + hh / 2; x < O[0] + b; x += hh)
			for (double y = O[1] - b + hh / 2; y < O[1] + b; y += hh) {
				double r2 = (x - O[0]) * (x - O[0]) + (y - O[1]) * (y - O[1]);
				if (r2 >= b * b)
					continue;
				int inside = 1;
				for (int i = 0; i < 3; i++) {
					int j = (i + 1) % 3;
					if ((X[j][0] - X[i][0]) * (y - X[i][1]) - (X[j][1] - X[i][1]) * (x - X[i][0]) < 0)
						inside = 0;
				}
				if (inside) {
					double dv = delta * (1 - r2 / (b * b)) * hh * hh;
					V += dv, Vx += x * dv, Vy += y * dv;
				}
			}
		double gref = V / (DEM_PI / 2 * b * b * delta);
		assert_true(fabs(g.gamma - gref) < 2e-3);
		/* G: the centroid of that volume */
		assert_true(hypot(g.G[0] - Vx / V, g.G[1] - Vy / V) < 1e-3 * b);
	}
	double big[3][3] = { { -5, -5, 0 }, { 5, -5, 0 }, { 0, 5, 0 } };
	double O[3] = { 0.3, 0.1, R - delta };
	dem_facet_geom_t g;
	assert_int_equal(dem_facet_geom(O, R, (const double (*)[3])big, DEM_PARTIAL_VOLUME, &g), 1);
	assert_true(g.full && g.gamma == 1);
}

/* The nearest point of a triangle against brute force: the triangle
 * sampled on a barycentric grid of 400 x 400 (the grid's nearest sample is
 * within h/sqrt(2) of the true point, h the grid's spacing along the
 * longest edge, so the distances agree to that), for random points in
 * front, behind, beside the edges and the vertices, and for degenerate
 * triangles (two vertices equal, three collinear). */
static double brute_closest(const double O[3], const double X[3][3])
{
	const int N = 400;
	double best = HUGE_VAL;
	for (int i = 0; i <= N; i++)
		for (int j = 0; i + j <= N; j++) {
			double s = (double)i / N, t = (double)j / N, d2 = 0;
			for (int k = 0; k < 3; k++) {
				double p = X[0][k] + s * (X[1][k] - X[0][k]) + t * (X[2][k] - X[0][k]);
				d2 += (O[k] - p) * (O[k] - p);
			}
			best = fmin(best, d2);
		}
	return sqrt(best);
}

static void test_triangle_closest(void **state)
{
	(void)state;
	unsigned long s = 777;
	double worst = 0;
	int inside = 0, edge = 0, vertex = 0;
	for (int t = 0; t < 400; t++) {
		double X[3][3], O[3], q[3];
		for (int a = 0; a < 3; a++)
			for (int i = 0; i < 3; i++)
				X[a][i] = 2 * urand(&s) - 1;
		if (t % 40 == 38)        /* two vertices equal */
			memcpy(X[2], X[1], sizeof X[1]);
		else if (t % 40 == 39)   /* collinear */
			for (int i = 0; i < 3; i++)
				X[2][i] = X[0][i] + 0.3 * (X[1][i] - X[0][i]);
		/* O: a point of the triangle's plane at area coordinates in
		 * [-0.5, 1.5] (inside, beside an edge, beyond a vertex), moved by up
		 * to 0.5 along each axis */
		double bs = 2 * urand(&s) - 0.5, bt = 2 * urand(&s) - 0.5, off = 2 * urand(&s) - 1;
		for (int i = 0; i < 3; i++)
			O[i] = X[0][i] + bs * (X[1][i] - X[0][i]) + bt * (X[2][i] - X[0][i]) + 0.5 * off * (2 * urand(&s) - 1);
		double d = sqrt(dem_triangle_closest(O, X, q));
		/* q lies on the triangle: its area coordinates are in [0, 1] */
		double h = 0;
		for (int a = 0; a < 3; a++) {
			double e = 0;
			for (int i = 0; i < 3; i++)
				e += (X[(a + 1) % 3][i] - X[a][i]) * (X[(a + 1) % 3][i] - X[a][i]);
			h = fmax(h, sqrt(e) / 400);
		}
		double dq = 0;
		for (int i = 0; i < 3; i++)
			dq += (O[i] - q[i]) * (O[i] - q[i]);
		assert_true(fabs(sqrt(dq) - d) <= 1e-12 * (1 + d));
		double db = brute_closest(O, X);
		/* never farther than a sample (brute >= true), within the grid */
		if (d > db + 1e-12 || db - d > h)
			fail_msg("case %d: distance %.12g, brute force %.12g (h %.3g)", t, d, db, h);
		worst = fmax(worst, (db - d) / h);
		/* where q fell: interior, an edge or a vertex */
		int at_vertex = 0;
		for (int a = 0; a < 3; a++) {
			double e = 0;
			for (int i = 0; i < 3; i++)
				e += (q[i] - X[a][i]) * (q[i] - X[a][i]);
			at_vertex |= e < 1e-24;
		}
		double n[3], e1[3], e2[3], w[3];
		for (int i = 0; i < 3; i++)
			e1[i] = X[1][i] - X[0][i], e2[i] = X[2][i] - X[0][i], w[i] = O[i] - q[i];
		n[0] = e1[1] * e2[2] - e1[2] * e2[1];
		n[1] = e1[2] * e2[0] - e1[0] * e2[2];
		n[2] = e1[0] * e2[1] - e1[1] * e2[0];
		double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		double c = nn > 0 ? fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / (nn * d) : 0;
		if (at_vertex)
			vertex++;
		else if (c > 1 - 1e-9)
			inside++;
		else
			edge++;
	}
	print_message("triangle nearest point: 400 cases (%d interior, %d edge, %d vertex), "
	              "brute force within %.2f grid spacings\n", inside, edge, vertex, worst);
	assert_true(inside > 20 && edge > 20 && vertex > 20);
}

static void test_sphere_sphere(void **state)
{
	(void)state;
	dem_law_t law;
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_init(&law, 2, 1e9, 1.5, &e), DEM_OK);
	dem_contact_param_t p = { .law = law };
	dem_contact_model_t cm;
	assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_OK);
	dem_sphere_t a = { .x = { 0, 0, 0 }, .R = 1 }, b = { .x = { 0.6, 0.8, 0 }, .R = 0.5 };
	/* distance 1: overlap 0.5 */
	double kn = dem_law_kn(&law, dem_law_reff(1, 0.5));
	assert_true(fabs(kn - 2e9 * sqrt(1.0 / 3)) < 1e-6 * kn);
	dem_contact_state_t st;
				dem_contact_state_reset(&st);
	dem_pair_out_t o;
	assert_int_equal(dem_contact_sphere_sphere(&cm, &a, &b, kn, 1, 1e-9, &st, &o), 1);
	assert_true(fabs(o.delta - 0.5) < 1e-12);
	assert_true(fabs(o.n[0] - 0.6) < 1e-12 && fabs(o.n[1] - 0.8) < 1e-12);
	/* C: half way through the overlap, 0.75 from the first centre */
	assert_true(fabs(o.C[0] - 0.45) < 1e-12 && fabs(o.C[1] - 0.6) < 1e-12);
	double F = kn * pow(0.5, 1.5);
	assert_true(fabs(o.c.Fn - F) < 1e-9 * F);
	assert_true(fabs(o.c.F[0] - 0.6 * F) < 1e-9 * F);
	/* apart: no contact, state reset */
	b.x[0] = 2;
	st.dmax = 1;
	assert_int_equal(dem_contact_sphere_sphere(&cm, &a, &b, kn, 1, 1e-9, &st, &o), 0);
	assert_true(st.dmax == 0);
}

/* The potential scheme (facet.h): the elastic forces on the sphere and on
 * the three nodes are minus the gradient of Phi = gamma U(delta), against
 * central differences of Phi itself, for random partial contacts of a
 * tilted facet (the circle across one edge, two, a vertex; the centre
 * inside and outside the facet); the four forces sum to zero with zero
 * moment; in full contact they are the area scheme's.  The kernel is the
 * power law alone (model.h), so o.F = o.Fe n and Phi = gamma k delta^(m+1)
 * / (m + 1). */
static double potential_phi(const dem_contact_model_t *cm, const double O[3], double R,
                            const double X[3][3])
{
	dem_sphere_t sp = { .R = R, .kn = dem_law_kn(&cm->p.law, R) };
	memcpy(sp.x, O, sizeof sp.x);
	dem_contact_state_t st = { 0 };
	dem_facet_out_t out;
	if (!dem_contact_sphere_facet(cm, &sp, X, NULL, 1, 1e-3, &st, &out))
		return 0;
	double F[3], Fn[3][3], Phi;
	dem_facet_forces(&out.g, &out.c, cm->m, F, Fn, &Phi);
	return Phi;
}

static void test_potential_gradient(void **state)
{
	(void)state;
	unsigned long seed = 7;
	const double R = 1, ms[] = { 1, 1.5, 2 };
	int partial = 0, full = 0;
	double worst = 0, worst_sum = 0, worst_mom = 0;
	for (int c = 0; c < 600; c++) {
		double m = ms[c % 3];
		dem_contact_param_t p = { 0 };
		dem_error_t e = { 0 };
		assert_int_equal(dem_law_init(&p.law, 2, 1, m, &e), DEM_OK);
		p.partial = DEM_PARTIAL_POTENTIAL;
		dem_contact_model_t cm;
		assert_int_equal(dem_contact_model_init(&cm, &p, &e), DEM_OK);
		/* a facet of size about the contact circle's, tilted at random */
		/* facets from a tenth of the contact circle's radius to twice it */
		double X[3][3], O[3], sz = c % 2 ? 0.6 : 0.06;
		for (int a = 0; a < 3; a++)
			for (int i = 0; i < 3; i++)
				X[a][i] = sz * (urand(&seed) - 0.5) + (i == 2 ? 0 : 0.5 * sz * ((a == 1) * (i == 0) + (a == 2) * (i == 1)));
		double e1[3], e2[3], nf[3];
		for (int i = 0; i < 3; i++)
			e1[i] = X[1][i] - X[0][i], e2[i] = X[2][i] - X[0][i];
		nf[0] = e1[1] * e2[2] - e1[2] * e2[1];
		nf[1] = e1[2] * e2[0] - e1[0] * e2[2];
		nf[2] = e1[0] * e2[1] - e1[1] * e2[0];
		double ln = sqrt(nf[0] * nf[0] + nf[1] * nf[1] + nf[2] * nf[2]);
		double d = R * (1 - 0.02 - 0.1 * urand(&seed));  /* delta 0.02-0.12 R: b 0.2-0.5 R */
		for (int i = 0; i < 3; i++)
			O[i] = (X[0][i] + X[1][i] + X[2][i]) / 3 + d * nf[i] / ln + 1.0 * (urand(&seed) - 0.5) * (i < 2);
		dem_sphere_t sp = { .R = R, .kn = dem_law_kn(&p.law, R) };
		memcpy(sp.x, O, sizeof O);
		dem_contact_state_t st = { 0 };
		dem_facet_out_t out;
		if (!dem_contact_sphere_facet(&cm, &sp, (const double (*)[3])X, NULL, 1, 1e-3, &st, &out))
			continue;
		if (out.g.full) {
			/* the area scheme's forces */
			full++;
			for (int i = 0; i < 3; i++)
				assert_true(fabs(out.c.F[i] - out.c.Fe * out.g.n[i]) <= 1e-14 * out.c.Fe);
			continue;
		}
		partial++;
		/* central differences of Phi, step 1e-6 R */
		const double hh = 1e-6 * sz;
		double Fs = fabs(out.c.Fe) + 1e-300, sum[3] = { 0 }, mom[3] = { 0 };
		for (int body = 0; body < 4; body++) {
			const double *f = body == 0 ? out.c.F : out.Fnode[body - 1];
			const double *at = body == 0 ? O : X[body - 1];
			for (int i = 0; i < 3; i++) {
				double Op[3], Xp[3][3];
				memcpy(Op, O, sizeof O);
				memcpy(Xp, X, sizeof X);
				double *q = body == 0 ? &Op[i] : &Xp[body - 1][i];
				*q += hh;
				double up = potential_phi(&cm, Op, R, (const double (*)[3])Xp);
				*q -= 2 * hh;
				double dn = potential_phi(&cm, Op, R, (const double (*)[3])Xp);
				double fd = -(up - dn) / (2 * hh);
				worst = fmax(worst, fabs(f[i] - fd) / Fs);
				sum[i] += f[i];
			}
			mom[0] += at[1] * f[2] - at[2] * f[1];
			mom[1] += at[2] * f[0] - at[0] * f[2];
			mom[2] += at[0] * f[1] - at[1] * f[0];
		}
		for (int i = 0; i < 3; i++) {
			worst_sum = fmax(worst_sum, fabs(sum[i]) / Fs);
			worst_mom = fmax(worst_mom, fabs(mom[i]) / (Fs * R));
		}
	}
	printf("# potential: %d partial, %d full contacts; force - FD gradient <= %.2g Fe, "
	       "sum <= %.2g Fe, moment <= %.2g Fe R\n", partial, full, worst, worst_sum, worst_mom);
	assert_true(partial > 200);
	assert_true(worst < 1e-5);
	assert_true(worst_sum < 1e-11);
	assert_true(worst_mom < 1e-11);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_circle_triangle_random),
		cmocka_unit_test(test_circle_triangle_edges),
		cmocka_unit_test(test_facet_geom_3d),
		cmocka_unit_test(test_tiled_surface),
		cmocka_unit_test(test_volume_scheme),
		cmocka_unit_test(test_triangle_closest),
		cmocka_unit_test(test_sphere_sphere),
		cmocka_unit_test(test_potential_gradient),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
