/* polygen.h - random convex polygons for the polygon tests (one
 * translation unit each: everything is static).
 *
 *   POLY_SQ    a superquadric (a, b in [0.5, 1.5), m in 2..15, tolerance
 *              tau), turned and moved
 *   POLY_TRI   a triangle: three points in [-1, 1)^2, turned and moved
 *   POLY_SQUARE a square of half side [0.5, 1.5), turned and moved
 *   POLY_GRID  the convex hull of 3 to 8 points of the 5 x 5 integer grid,
 *              with or without its collinear boundary points: shared
 *              points, points on edges and collinear edges in plenty
 * The moves keep the pairs overlapping often: centres in [-1, 1)^2.
 */
#ifndef DEM_TEST_POLYGEN_H
#define DEM_TEST_POLYGEN_H

#include <math.h>
#include <stdlib.h>

#include "contact/polygon.h"
#include "core/consts.h"

enum { POLY_SQ, POLY_TRI, POLY_SQUARE, POLY_GRID };

static double pg_urand(unsigned long *s)  /* [0, 1) */
{
	*s = *s * 6364136223846793005ul + 1442695040888963407ul;
	return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

static int pg_cmp(const void *a, const void *b)
{
	const double *p = a, *q = b;
	if (p[0] != q[0])
		return p[0] < q[0] ? -1 : 1;
	return p[1] < q[1] ? -1 : p[1] > q[1];
}

static double pg_orient(const double *o, const double *a, const double *b)
{
	return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* Andrew's monotone chain, anticlockwise; keep: collinear boundary points
 * stay (exact for the integer grid).  p is sorted in place; h: room for
 * 2 k points. */
static int pg_hull(int k, double (*p)[2], double (*h)[2], int keep)
{
	qsort(p, (size_t)k, sizeof *p, pg_cmp);
	int n = 0;
	for (int pass = 0; pass < 2; pass++) {
		int lo = n + 1;
		for (int j = pass; j < k; j++) {  /* the upper chain from the next to last */
			int i = pass ? k - 1 - j : j;
			if (j > 0 && p[i][0] == p[pass ? i + 1 : i - 1][0] &&
			    p[i][1] == p[pass ? i + 1 : i - 1][1])
				continue;
			while (n >= (pass ? lo : 2)) {
				double o = pg_orient(h[n - 2], h[n - 1], p[i]);
				if (keep ? o < 0 : o <= 0)
					n--;
				else
					break;
			}
			h[n][0] = p[i][0], h[n][1] = p[i][1], n++;
		}
	}
	return n - 1;
}

static double pg_area2(int n, const double (*v)[2])
{
	double a = 0;
	for (int i = 0; i < n; i++) {
		int j = i + 1 == n ? 0 : i + 1;
		a += v[i][0] * v[j][1] - v[j][0] * v[i][1];
	}
	return a;
}

/* One polygon of the kind into v (room: cap points); returns its points. */
static int pg_poly(unsigned long *s, int kind, double tau, int cap, double (*v)[2])
{
	double p[16][2], h[32][2];
	int n;
	switch (kind) {
	case POLY_GRID:
		do {
			int k = 3 + (int)(pg_urand(s) * 6);
			for (int i = 0; i < k; i++)
				p[i][0] = floor(pg_urand(s) * 5), p[i][1] = floor(pg_urand(s) * 5);
			n = pg_hull(k, p, h, pg_urand(s) < 0.5);
		} while (n < 3 || !(pg_area2(n, (const double (*)[2])h) > 0));
		for (int i = 0; i < n; i++)
			v[i][0] = h[i][0], v[i][1] = h[i][1];
		return n;
	case POLY_SQ: {
		double a = 0.5 + pg_urand(s), b = 0.5 + pg_urand(s), m = 2 + floor(pg_urand(s) * 14);
		n = dem_superquadric_polygon(a, b, m, tau, cap, v);
		break;
	}
	case POLY_TRI:
		do {
			for (int i = 0; i < 3; i++)
				p[i][0] = 2 * pg_urand(s) - 1, p[i][1] = 2 * pg_urand(s) - 1;
			n = pg_hull(3, p, h, 0);
		} while (n < 3);
		for (int i = 0; i < 3; i++)
			v[i][0] = h[i][0], v[i][1] = h[i][1];
		break;
	default: {
		double a = 0.5 + pg_urand(s);
		const double sq[4][2] = { { a, -a }, { a, a }, { -a, a }, { -a, -a } };
		n = 4;
		for (int i = 0; i < 4; i++)
			v[i][0] = sq[i][0], v[i][1] = sq[i][1];
		break;
	}
	}
	double x[2] = { 2 * pg_urand(s) - 1, 2 * pg_urand(s) - 1 };
	dem_polygon_place(n, (const double (*)[2])v, x, 2 * DEM_PI * pg_urand(s), v);
	return n;
}

/* the diagonal of v's bounding box: the size scale of the comparisons */
static double pg_size(int n, const double (*v)[2])
{
	double b[4] = { v[0][0], v[0][1], v[0][0], v[0][1] };
	for (int i = 1; i < n; i++) {
		b[0] = fmin(b[0], v[i][0]), b[1] = fmin(b[1], v[i][1]);
		b[2] = fmax(b[2], v[i][0]), b[3] = fmax(b[3], v[i][1]);
	}
	return hypot(b[2] - b[0], b[3] - b[1]);
}

#endif
