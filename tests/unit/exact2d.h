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
 *             cubic f(l) = det(l A + B) has two distinct positive roots
 *             exactly when the ellipses are apart (a positive double root
 *             when they touch from outside), so exactly when f > 0 at one
 *             of its positive critical points; f's sign there is taken
 *             from a form that stays accurate at aspect ratios to 1000
 *             (x2_sign), not from the roots of the cubic.
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

/* The determinant of the matrix whose column j is A's when bit j of mask
 * is set, else B's: f's coefficients are sums of these. */
static double x2_mixed(double A[3][3], double B[3][3], int mask)
{
	double M[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			M[i][j] = mask >> j & 1 ? A[i][j] : B[i][j];
	return x2_det3(M);
}

/* The ellipse of semi-axes a, b along the unit axes u and v = u turned
 * by 90 degrees: its shape matrix M = a^2 u u^T + b^2 v v^T and the
 * adjugate adj(M) = b^2 u u^T + a^2 v v^T (M's inverse times a^2 b^2).
 * x2_adj(e, w) = w^T adj(M) w: a sum of two positive terms. */
struct x2_ell {
	double a, b, u[2];
};

static double x2_adj(const struct x2_ell *e, const double w[2])
{
	double wu = w[0] * e->u[0] + w[1] * e->u[1], wv = -w[0] * e->u[1] + w[1] * e->u[0];
	return e->b * e->b * wu * wu + e->a * e->a * wv * wv;
}

/* u^T M u for the ellipse e: also a sum of two positive terms. */
static double x2_form(const struct x2_ell *e, const double w[2])
{
	double wu = w[0] * e->u[0] + w[1] * e->u[1], wv = -w[0] * e->u[1] + w[1] * e->u[0];
	return e->a * e->a * wu * wu + e->b * e->b * wv * wv;
}

/* The sign of f(l) = det(l A + B), l > 0, by the Schur complement of the
 * homogeneous block: f(l) = det(l Q1 + Q2) (d^T (M2 + M1 / l)^-1 d - 1 - l)
 * with Q = M^-1 and d the centre of 2 from 1, and det(l Q1 + Q2) > 0.
 * With t = 1 / l, (M2 + t M1)^-1 = adj(M2 + t M1) / det(M2 + t M1), where
 * adj is linear and det(M2 + t M1) = det M2 + t^2 det M1 + t X, X = the
 * trace of adj(M2) M1 = b2^2 u2^T M1 u2 + a2^2 v2^T M1 v2: every term a
 * sum of positive ones, so the value is accurate to a few ulps of 1 + l
 * whatever the aspect ratios; the homogeneous determinant, whose entries
 * spread as their squares, is not. */
static double x2_sign(const struct x2_ell *e1, const struct x2_ell *e2, const double d[2], double l)
{
	double t = 1 / l, v2[2] = {-e2->u[1], e2->u[0]};
	double X = e2->b * e2->b * x2_form(e1, e2->u) + e2->a * e2->a * x2_form(e1, v2);
	double det = e2->a * e2->a * e2->b * e2->b + t * t * e1->a * e1->a * e1->b * e1->b + t * X;
	return (x2_adj(e2, d) + t * x2_adj(e1, d)) / det - (1 + l);
}

/* 1 when ellipses 1 and 2, each shrunk by 1 - eps, are not apart (WWK).
 * f(0) = det B < 0 and f(l) -> -inf (det A < 0), so f has two positive
 * roots, distinct exactly when the ellipses are apart, or none: they are
 * apart exactly when f > 0 somewhere on l > 0, so at one of its critical
 * points (the roots of the quadratic f').  There f's sign is taken from
 * x2_sign, not from the roots of the cubic: at aspect ratios of 50 and
 * more the coefficients spread as the ratios squared, and a cubic
 * solver's discriminant, cancelling, turns the two close positive roots
 * of bodies that touch into a complex pair (a false overlap; 263 of 1306
 * pairs clearly apart at ratio 1000 in a sampling, by interpolated
 * coefficients and gsl_poly_solve_cubic). */
static int x2_wwk_overlap(double x1, double y1, double a1, double b1, double t1, double x2,
			  double y2, double a2, double b2, double t2, double eps)
{
	/* ellipse 1 at the origin, lengths in units of its size: the test
	 * does not change, the rounding does */
	double s = sqrt(a1 * b1), k = 1 - eps, A[3][3], B[3][3];
	double d[2] = {(x2 - x1) / s, (y2 - y1) / s};
	struct x2_ell e1 = {k * a1 / s, k * b1 / s, {cos(t1), sin(t1)}};
	struct x2_ell e2 = {k * a2 / s, k * b2 / s, {cos(t2), sin(t2)}};
	x2_conic(0, 0, e1.a, e1.b, t1, A);
	x2_conic(d[0], d[1], e2.a, e2.b, t2, B);
	/* f(l) = c3 l^3 + c2 l^2 + c1 l + c0, each coefficient a sum of
	 * mixed determinants */
	double c3 = x2_mixed(A, B, 7);
	double c2 = x2_mixed(A, B, 3) + x2_mixed(A, B, 5) + x2_mixed(A, B, 6);
	double c1 = x2_mixed(A, B, 1) + x2_mixed(A, B, 2) + x2_mixed(A, B, 4);
	/* f'(l) = 3 c3 l^2 + 2 c2 l + c1 = 0, by the stable quadratic formula */
	double qa = 3 * c3, qb = 2 * c2, qc = c1, disc = qb * qb - 4 * qa * qc;
	if (!(disc >= 0))
		return 1;       /* f decreasing: no positive root */
	double q = -0.5 * (qb + copysign(sqrt(disc), qb)), l[2] = {q / qa, q != 0 ? qc / q : 0};
	for (int i = 0; i < 2; i++)
		if (l[i] > 0 && x2_sign(&e1, &e2, d, l[i]) > 0)
			return 0;
	return 1;
}

#endif
