/* exact2d.h - exact overlap tests of convex polygons and ellipses, written
 * apart from the packer (lib/pack) to check its packings: nothing here
 * calls the library's geometry.
 *
 *   polygons  the separating axis test: two convex polygons are apart
 *             when the projections on the normal of one of their edges
 *             do not overlap;
 *   ellipses  Wang, Wang and Kim's algebraic condition in its 2D form
 *             (Choi, Wang, Liu and Kim 2006): with X^T A X <= 0 and
 *             X^T B X <= 0 the ellipses in homogeneous coordinates, the
 *             cubic f(l) = det(l A - B) has two distinct positive roots
 *             exactly when the ellipses are apart (a positive double root
 *             when they touch from outside).
 * A tolerance eps lets bodies touch: each body is shrunk by the factor
 * 1 - eps about its centre (ellipses), or eps times the smaller size is
 * allowed as overlap along every axis (polygons), before the test.
 * The polygon of a body is the body stream's shape 1 (dem-streams(5)):
 * m points (a cos p, b sin p), p = -pi/2 + pi/m + 2 pi k/m, turned by
 * theta about the centre.
 */
#ifndef DEM_TESTS_EXACT2D_H
#define DEM_TESTS_EXACT2D_H

#include <math.h>

#include <gsl/gsl_poly.h>

#define X2_PI 3.14159265358979323846

static void x2_polygon(double x, double y, double a, double b, double th, int m,
		       double (*v)[2])
{
	double c = cos(th), s = sin(th);
	for (int k = 0; k < m; k++) {
		double p = -X2_PI / 2 + X2_PI / m + 2 * X2_PI * k / m;
		double u = a * cos(p), w = b * sin(p);
		v[k][0] = x + c * u - s * w;
		v[k][1] = y + s * u + c * w;
	}
}

/* The projections of v[n] on (nx, ny). */
static void x2_project(int n, const double (*v)[2], double nx, double ny, double *lo, double *hi)
{
	*lo = HUGE_VAL;
	*hi = -HUGE_VAL;
	for (int k = 0; k < n; k++) {
		double t = nx * v[k][0] + ny * v[k][1];
		*lo = fmin(*lo, t);
		*hi = fmax(*hi, t);
	}
}

/* 1 when the convex polygons P and Q overlap by more than tol (a length)
 * on every edge normal. */
static int x2_sat_overlap(int n, const double (*P)[2], int m, const double (*Q)[2], double tol)
{
	for (int side = 0; side < 2; side++) {
		const double (*E)[2] = side ? Q : P;
		int ne = side ? m : n;
		for (int k = 0; k < ne; k++) {
			double ex = E[(k + 1) % ne][0] - E[k][0], ey = E[(k + 1) % ne][1] - E[k][1];
			double l = hypot(ex, ey), lo1, hi1, lo2, hi2;
			x2_project(n, P, ey / l, -ex / l, &lo1, &hi1);
			x2_project(m, Q, ey / l, -ex / l, &lo2, &hi2);
			if (hi1 <= lo2 + tol || hi2 <= lo1 + tol)
				return 0;
		}
	}
	return 1;
}

/* The homogeneous matrix of the ellipse (centre (x, y) in units of s,
 * semi-axes a, b, rotation th): X^T A X < 0 inside. */
static void x2_conic(double x, double y, double a, double b, double th, double A[3][3])
{
	double c = cos(th), s = sin(th), ia = 1 / (a * a), ib = 1 / (b * b);
	double q00 = c * c * ia + s * s * ib, q01 = c * s * (ia - ib), q11 = s * s * ia + c * c * ib;
	double qx = q00 * x + q01 * y, qy = q01 * x + q11 * y;
	A[0][0] = q00, A[0][1] = q01, A[0][2] = -qx;
	A[1][0] = q01, A[1][1] = q11, A[1][2] = -qy;
	A[2][0] = -qx, A[2][1] = -qy, A[2][2] = x * qx + y * qy - 1;
}

static double x2_det3(double M[3][3])
{
	return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
	       M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
	       M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

/* f(l) = det(l A + B) */
static double x2_pencil(double A[3][3], double B[3][3], double l)
{
	double M[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			M[i][j] = l * A[i][j] + B[i][j];
	return x2_det3(M);
}

/* 1 when ellipses 1 and 2, each shrunk by 1 - eps, are not apart (WWK). */
static int x2_wwk_overlap(double x1, double y1, double a1, double b1, double t1, double x2,
			  double y2, double a2, double b2, double t2, double eps)
{
	/* ellipse 1 at the origin, lengths in units of its size: the test
	 * does not change, the rounding does */
	double s = sqrt(a1 * b1), k = 1 - eps, A[3][3], B[3][3];
	x2_conic(0, 0, k * a1 / s, k * b1 / s, t1, A);
	x2_conic((x2 - x1) / s, (y2 - y1) / s, k * a2 / s, k * b2 / s, t2, B);
	/* the cubic through its values at -1, 0, 1, 2 */
	double fm = x2_pencil(A, B, -1), f0 = x2_pencil(A, B, 0);
	double f1 = x2_pencil(A, B, 1), f2 = x2_pencil(A, B, 2);
	double c0 = f0;
	double c2 = (f1 + fm) / 2 - f0;
	/* f(l) = c3 l^3 + c2 l^2 + c1 l + c0: f(1) - f(-1) = 2 (c3 + c1),
	 * f(2) = 8 c3 + 4 c2 + 2 c1 + c0 */
	double s31 = (f1 - fm) / 2;            /* c3 + c1 */
	double c3 = (f2 - 4 * c2 - c0 - 2 * s31) / 6;
	double c1 = s31 - c3;
	double r[3];
	int nr = gsl_poly_solve_cubic(c2 / c3, c1 / c3, c0 / c3, &r[0], &r[1], &r[2]);
	int pos = 0;
	double prev = -1;
	for (int i = 0; i < nr; i++)    /* in ascending order */
		if (r[i] > 0 && !(prev > 0 && r[i] - prev <= 1e-12 * r[i])) {
			pos++;
			prev = r[i];
		}
	return pos < 2;
}

#endif
