/* locus.c - Minkowski sums, ellipses and loci for the advancing front of
 * polygons and ellipses (locus.h; Han 2004, Ch. 5.3-5.4). */
#include "pack/locus.h"

#include <math.h>
#include <stddef.h>

#include "core/consts.h"

/* A monotone stand-in for the angle of (dx, dy) in [0, 2 pi): the
 * "diamond angle" in [0, 4), cheaper than atan2 and enough to merge two
 * sequences of edge directions. */
static double pangle(double dx, double dy)
{
	if (dy >= 0)
		return dx >= 0 ? dy / (dx + dy) : 1 - dx / (dy - dx);
	return dx < 0 ? 2 - dy / (-dx - dy) : 3 + dx / (dx - dy);
}

/* The lowest point (then the leftmost): from it the edge directions of a
 * convex anticlockwise polygon increase through [0, 2 pi) without
 * wrapping. */
static int lowest(int n, const double (*P)[2])
{
	int k = 0;
	for (int i = 1; i < n; i++)
		if (P[i][1] < P[k][1] || (P[i][1] == P[k][1] && P[i][0] < P[k][0]))
			k = i;
	return k;
}

int dem_minkowski(int na, const double (*A)[2], int nb, const double (*B)[2],
		  double (*S)[2], double (*sa)[2])
{
	int ia = lowest(na, A), ib = lowest(nb, B), i = 0, j = 0, k = 0;

	/* a point has no edges: the sum is the other polygon moved */
	if (na == 1)
		i = na;
	if (nb == 1)
		j = nb;
	if (i == na && j == nb) {
		S[0][0] = A[ia][0] + B[ib][0];
		S[0][1] = A[ia][1] + B[ib][1];
		if (sa)
			sa[0][0] = A[ia][0], sa[0][1] = A[ia][1];
		return 1;
	}
	/* merge the edges of A and B by direction (each polygon's edges
	 * turn anticlockwise through less than 2 pi from its lowest point) */
	while (i < na || j < nb) {
		const double *a = A[(ia + i) % na], *b = B[(ib + j) % nb];
		S[k][0] = a[0] + b[0];
		S[k][1] = a[1] + b[1];
		if (sa)
			sa[k][0] = a[0], sa[k][1] = a[1];
		k++;
		int ai = 0, bj = 0;
		if (i == na)
			bj = 1;
		else if (j == nb)
			ai = 1;
		else {
			const double *a1 = A[(ia + i + 1) % na], *b1 = B[(ib + j + 1) % nb];
			double pa = pangle(a1[0] - a[0], a1[1] - a[1]);
			double pb = pangle(b1[0] - b[0], b1[1] - b[1]);
			ai = pa <= pb;
			bj = pb <= pa;
		}
		i += ai;
		j += bj;
	}
	return k;
}

double dem_convex_depth(int n, const double (*S)[2], const double x[2])
{
	double d = HUGE_VAL;
	for (int i = 0; i < n; i++) {
		const double *a = S[i], *b = S[(i + 1) % n];
		double ex = b[0] - a[0], ey = b[1] - a[1], l = hypot(ex, ey);
		if (!(l > 0))
			continue;
		double s = (ex * (x[1] - a[1]) - ey * (x[0] - a[0])) / l;
		if (s < d)
			d = s;
	}
	return d;
}

void dem_ellipse_matrix(double a, double b, double c, double s, double m[3])
{
	double a2 = a * a, b2 = b * b;
	m[0] = a2 * c * c + b2 * s * s;
	m[1] = (a2 - b2) * c * s;
	m[2] = a2 * s * s + b2 * c * c;
}

double dem_ellipse_support(const double m[3], const double n[2], double sp[2])
{
	double mx = m[0] * n[0] + m[1] * n[1], my = m[1] * n[0] + m[2] * n[1];
	double h = sqrt(n[0] * mx + n[1] * my);
	if (sp) {
		sp[0] = h > 0 ? mx / h : 0;
		sp[1] = h > 0 ? my / h : 0;
	}
	return h;
}

/* f(l) = l (1 - l) d^T C^-1 d, C = (1 - l) A + l B, and its slope
 * (1 - 2l) d^T w - l (1 - l) w^T (B - A) w with w = C^-1 d. */
static double pw_eval(const double *A, const double *B, const double *d, double l, double *g)
{
	double p = (1 - l) * A[0] + l * B[0], q = (1 - l) * A[1] + l * B[1];
	double r = (1 - l) * A[2] + l * B[2], det = p * r - q * q;
	double w0 = (r * d[0] - q * d[1]) / det, w1 = (p * d[1] - q * d[0]) / det;
	double dw = d[0] * w0 + d[1] * w1;
	double wdw = (B[0] - A[0]) * w0 * w0 + 2 * (B[1] - A[1]) * w0 * w1 + (B[2] - A[2]) * w1 * w1;
	*g = (1 - 2 * l) * dw - l * (1 - l) * wdw;
	return l * (1 - l) * dw;
}

double dem_ellipse_pw(const double ma[3], const double mb[3], const double d[2], double stop,
		      long *evals)
{
	/* the maximum of a function with one maximum on [0, 1]: bisection on
	 * the sign of its slope, stopping once a value reaches stop */
	double lo = 0, hi = 1, best = 0;
	long k = 0;
	while (hi - lo > 1e-14) {
		double l = 0.5 * (lo + hi), g;
		double f = pw_eval(ma, mb, d, l, &g);
		k++;
		if (f > best)
			best = f;
		if (best >= stop || g == 0)
			break;
		if (g > 0)
			lo = l;
		else
			hi = l;
	}
	if (evals)
		*evals += k;
	return best;
}

static int zero(const double m[3])
{
	return m[0] == 0 && m[1] == 0 && m[2] == 0;
}

/* The support point of M in the direction n and its derivative along the
 * circle of directions (t = dn/du). */
static void support_du(const double m[3], const double n[2], const double t[2], double s[2],
		       double ds[2])
{
	double mn0 = m[0] * n[0] + m[1] * n[1], mn1 = m[1] * n[0] + m[2] * n[1];
	double mt0 = m[0] * t[0] + m[1] * t[1], mt1 = m[1] * t[0] + m[2] * t[1];
	double h = sqrt(n[0] * mn0 + n[1] * mn1), ntm = n[0] * mt0 + n[1] * mt1;
	s[0] = mn0 / h;
	s[1] = mn1 / h;
	ds[0] = mt0 / h - mn0 * ntm / (h * h * h);
	ds[1] = mt1 / h - mn1 * ntm / (h * h * h);
}

void dem_locus_eval(const dem_locus_t *L, double u, double x[2], double dx[2])
{
	if (L->line) {
		x[0] = L->c[0] + u * L->t[0];
		x[1] = L->c[1] + u * L->t[1];
		if (dx)
			dx[0] = L->t[0], dx[1] = L->t[1];
		return;
	}
	double n[2] = {cos(u), sin(u)}, t[2] = {-n[1], n[0]}, s[2], ds[2];
	x[0] = L->c[0];
	x[1] = L->c[1];
	double d0 = 0, d1 = 0;
	if (!zero(L->m1)) {
		support_du(L->m1, n, t, s, ds);
		x[0] += s[0], x[1] += s[1], d0 += ds[0], d1 += ds[1];
	}
	support_du(L->m2, n, t, s, ds);
	x[0] += s[0], x[1] += s[1], d0 += ds[0], d1 += ds[1];
	if (dx)
		dx[0] = d0, dx[1] = d1;
}

void dem_locus_outer(const dem_locus_t *L, int K, double (*v)[2])
{
	double du = 2 * DEM_PI / K, n0[2], d0, x[2];
	dem_locus_eval(L, 0, x, NULL);
	n0[0] = 1, n0[1] = 0;
	d0 = x[0];
	double nf[2] = {n0[0], n0[1]}, df = d0;   /* the first line, for the last vertex */
	for (int k = 0; k < K; k++) {
		double n1[2], d1;
		if (k + 1 < K) {
			double u = du * (k + 1);
			n1[0] = cos(u), n1[1] = sin(u);
			dem_locus_eval(L, u, x, NULL);
			d1 = n1[0] * x[0] + n1[1] * x[1];
		} else {
			n1[0] = nf[0], n1[1] = nf[1], d1 = df;
		}
		double det = n0[0] * n1[1] - n0[1] * n1[0];
		v[k][0] = (d0 * n1[1] - d1 * n0[1]) / det;
		v[k][1] = (n0[0] * d1 - n1[0] * d0) / det;
		n0[0] = n1[0], n0[1] = n1[1], d0 = d1;
	}
}

int dem_locus_meet(const dem_locus_t *A, const dem_locus_t *B, double *u, double *v,
		   double tol, int maxit, int *steps)
{
	int it, conv = 0;
	for (it = 0; it <= maxit; it++) {
		double a[2], da[2], b[2], db[2];
		dem_locus_eval(A, *u, a, da);
		dem_locus_eval(B, *v, b, db);
		double g0 = a[0] - b[0], g1 = a[1] - b[1];
		if (!(isfinite(g0) && isfinite(g1)))
			break;
		if (hypot(g0, g1) <= tol) {
			conv = 1;
			break;
		}
		if (it == maxit)
			break;
		/* [da, -db] (du, dv) = -g */
		double det = -da[0] * db[1] + db[0] * da[1];
		if (!(fabs(det) > 0))
			break;
		double du = (g0 * db[1] - g1 * db[0]) / det;
		double dv = (da[1] * g0 - da[0] * g1) / det;
		/* a step of more than a radian on a curve leaves the
		 * neighbourhood the bounds gave: not converging */
		if (!(fabs(du) < 1 || A->line) || !(fabs(dv) < 1 || B->line))
			break;
		*u += du;
		*v += dv;
	}
	if (steps)
		*steps = it;
	return conv ? it : -1;
}
