/* mesh2.c - quadrilateral meshes of a rectangle and of a disk (see
 * mesh2.h). */
#include "mesh/mesh2.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/consts.h"

/* The node and element arrays of nn nodes and ne elements (fix zero);
 * on failure the mesh freed. */
static int mesh2_alloc(dem_mesh2_t *m, size_t nn, size_t ne, const char *what, dem_error_t *e)
{
	m->nn = nn, m->ne = ne;
	m->X = malloc(2 * nn * sizeof *m->X);
	m->quad = malloc(4 * ne * sizeof *m->quad);
	m->fix = calloc(nn, sizeof *m->fix);
	if (!m->X || !m->quad || !m->fix) {
		dem_mesh2_free(m);
		return dem_error_nomem(e, what);
	}
	return DEM_OK;
}

int dem_mesh2_rect(dem_mesh2_t *m, const dem_axis_t ax[2], dem_error_t *e)
{
	double *g[2];
	int n[2];

	memset(m, 0, sizeof *m);
	if (dem_mesh_axes(ax, 2, g, n, e) != DEM_OK)
		return e->code;
	size_t nn = (size_t)(n[0] + 1) * (size_t)(n[1] + 1), ne = (size_t)n[0] * (size_t)n[1];
	m->nx = n[0], m->ny = n[1];
	m->gx = g[0], m->gy = g[1];
	if (nn > UINT32_MAX) {
		dem_mesh2_free(m);
		return dem_error_set(e, DEM_EINPUT, "mesh: %zu nodes are more than a mesh can number (%u)",
				     nn, UINT32_MAX);
	}
	if (mesh2_alloc(m, nn, ne, "mesh", e))
		return e->code;
	for (int j = 0; j <= m->ny; j++)
		for (int i = 0; i <= m->nx; i++) {
			size_t p = dem_mesh2_node(m, i, j);
			m->X[2 * p] = m->gx[i];
			m->X[2 * p + 1] = m->gy[j];
		}
	for (int j = 0; j < m->ny; j++)
		for (int i = 0; i < m->nx; i++) {
			uint32_t *q = m->quad + 4 * dem_mesh2_elem(m, i, j);
			q[0] = (uint32_t)dem_mesh2_node(m, i, j);
			q[1] = (uint32_t)dem_mesh2_node(m, i + 1, j);
			q[2] = (uint32_t)dem_mesh2_node(m, i + 1, j + 1);
			q[3] = (uint32_t)dem_mesh2_node(m, i, j + 1);
		}
	return DEM_OK;
}

void dem_mesh2_free(dem_mesh2_t *m)
{
	free(m->gx), free(m->gy);
	free(m->X), free(m->quad), free(m->fix);
	memset(m, 0, sizeof *m);
}

void dem_mesh2_set_bc(dem_mesh2_t *m, const dem_bc_t bc[4])
{
	static const uint8_t normal[2] = { DEM_FIX_X, DEM_FIX_Y };
	const uint8_t all = DEM_FIX_X | DEM_FIX_Y;

	for (int j = 0; j <= m->ny; j++)
		for (int i = 0; i <= m->nx; i++) {
			int on[4] = { i == 0, i == m->nx, j == 0, j == m->ny };
			uint8_t b = 0;
			for (int f = 0; f < 4; f++) {
				if (!on[f] || bc[f] == DEM_BC_FREE || bc[f] == DEM_BC_PERIODIC)
					continue;
				b |= bc[f] == DEM_BC_FIXED ? all : normal[f / 2];
			}
			m->fix[dem_mesh2_node(m, i, j)] = b;
		}
}

void dem_mesh2_gather(const dem_mesh2_t *m, size_t el, const double *u, double x[8])
{
	const uint32_t *q = m->quad + 4 * el;
	for (int I = 0; I < 4; I++)
		for (int c = 0; c < 2; c++)
			x[4 * c + I] = m->X[2 * (size_t)q[I] + c] + (u ? u[2 * (size_t)q[I] + c] : 0);
}

size_t dem_mesh2_top_segments(const dem_mesh2_t *m, double x0, double x1, uint32_t *seg)
{
	size_t n = 0;
	for (int i = 0; i < m->nx; i++) {
		double xc = 0.5 * (m->gx[i] + m->gx[i + 1]);
		if (xc < x0 || xc > x1)
			continue;
		if (seg) {
			seg[2 * n] = (uint32_t)dem_mesh2_node(m, i, m->ny);
			seg[2 * n + 1] = (uint32_t)dem_mesh2_node(m, i + 1, m->ny);
		}
		n++;
	}
	return n;
}

int dem_mesh2_extrude(const dem_mesh2_t *m2, double w, dem_mesh_t *m, dem_error_t *e)
{
	double *g[3];
	int n[3] = { m2->nx, 1, m2->ny };

	g[0] = malloc(((size_t)n[0] + 1) * sizeof *g[0]);
	g[1] = malloc(2 * sizeof *g[1]);
	g[2] = malloc(((size_t)n[2] + 1) * sizeof *g[2]);
	if (!g[0] || !g[1] || !g[2]) {
		free(g[0]), free(g[1]), free(g[2]);
		memset(m, 0, sizeof *m);
		return dem_error_nomem(e, "mesh");
	}
	memcpy(g[0], m2->gx, ((size_t)n[0] + 1) * sizeof *g[0]);
	memcpy(g[2], m2->gy, ((size_t)n[2] + 1) * sizeof *g[2]);
	g[1][0] = -w / 2, g[1][1] = w / 2;
	return dem_mesh_grid(m, g, n, e);
}

static void lift6(const double *a, double *b)
{
	b[0] = a[0], b[1] = a[2], b[2] = a[1];
	b[3] = 0, b[4] = 0, b[5] = a[3];
}

void dem_mesh2_lift(const dem_mesh2_t *m2, const double *u2, const double *sig2,
		    const double *eps2, const double *ep2, double *u, double *sig,
		    double *eps, double *ep)
{
	size_t row = (size_t)m2->nx + 1;
	for (int k = 0; u2 && k <= m2->ny; k++)
		for (int i = 0; i <= m2->nx; i++) {
			size_t p = dem_mesh2_node(m2, i, k);
			for (int j = 0; j < 2; j++) {
				double *q = u + 3 * ((size_t)i + row * ((size_t)j + 2 * (size_t)k));
				q[0] = u2[2 * p], q[1] = 0, q[2] = u2[2 * p + 1];
			}
		}
	for (size_t el = 0; el < m2->ne; el++) {
		if (sig2)
			lift6(sig2 + 6 * el, sig + 6 * el);
		if (eps2)
			lift6(eps2 + 6 * el, eps + 6 * el);
		if (ep2)
			ep[el] = ep2[el];
	}
}

/* ---- the disk (O-grid) --------------------------------------------------- */

/* Node number of ring j (0: the core's boundary .. m: the rim), block k,
 * position i = 0..n along the block (i = n is the next block's 0). */
static size_t ring_node(int n, int m, int j, int k, int i)
{
	if (i == n)
		k = (k + 1) % 4, i = 0;
	return (size_t)(m - j) * 4 * (size_t)n + (size_t)k * (size_t)n + (size_t)i;
}

/* Node number of the core's grid point (p, q), 0..n each, from (-a, -a). */
static size_t core_node(int n, int m, int p, int q)
{
	if (p == n)
		return ring_node(n, m, 0, 0, q);
	if (q == n)
		return ring_node(n, m, 0, 1, n - p);
	if (p == 0)
		return ring_node(n, m, 0, 2, n - q);
	if (q == 0)
		return ring_node(n, m, 0, 3, p);
	return 4 * (size_t)n * ((size_t)m + 1) + (size_t)(p - 1) + (size_t)(n - 1) * (size_t)(q - 1);
}

int dem_mesh2_disk(dem_mesh2_t *m, double R, double h, const double c[2], size_t *nrim,
		   dem_error_t *e)
{
	memset(m, 0, sizeof *m);
	if (!(R > 0) || !(h > 0) || !isfinite(R) || !isfinite(h))
		return dem_error_set(e, DEM_EINPUT, "disk mesh: radius and element size must be > 0 "
				     "(got %g m, %g m)", R, h);
	const double a = 0.5 * R;
	double fn = ceil(DEM_PI * R / (2 * h));
	if (!(fn * fn * 4 < 1e7))
		return dem_error_set(e, DEM_EINPUT, "disk mesh: an element of %g m in a disk of "
				     "radius %g m makes too many elements", h, R);
	int n = (int)fn, nm = (int)fmax(1, round((R - a) / h));
	size_t nn = 4 * (size_t)n * ((size_t)nm + 1) + (size_t)(n - 1) * (size_t)(n - 1);
	size_t ne = 4 * (size_t)n * (size_t)nm + (size_t)n * (size_t)n;
	if (mesh2_alloc(m, nn, ne, "disk mesh", e))
		return e->code;
	/* the blocks: block k is block 0 turned by k quarter turns */
	static const double rot[4][4] = { { 1, 0, 0, 1 }, { 0, -1, 1, 0 }, { -1, 0, 0, -1 },
					  { 0, 1, -1, 0 } };
	for (int j = 0; j <= nm; j++)
		for (int k = 0; k < 4; k++)
			for (int i = 0; i < n; i++) {
				double th = -DEM_PI / 4 + DEM_PI / 2 * i / n, s = (double)j / nm;
				double p[2] = { a + s * (R * cos(th) - a),
						-a + 2 * a * i / n + s * (R * sin(th) + a - 2 * a * i / n) };
				if (j == nm)  /* on the circle to rounding */
					p[0] = R * cos(th), p[1] = R * sin(th);
				const double *r = rot[k];
				double *X = m->X + 2 * ring_node(n, nm, j, k, i);
				X[0] = c[0] + r[0] * p[0] + r[1] * p[1];
				X[1] = c[1] + r[2] * p[0] + r[3] * p[1];
			}
	for (int q = 1; q < n; q++)
		for (int p = 1; p < n; p++) {
			double *X = m->X + 2 * core_node(n, nm, p, q);
			X[0] = c[0] - a + 2 * a * p / n;
			X[1] = c[1] - a + 2 * a * q / n;
		}
	uint32_t *qd = m->quad;
	for (int j = 0; j < nm; j++)
		for (int k = 0; k < 4; k++)
			for (int i = 0; i < n; i++, qd += 4) {
				/* counter-clockwise: out along the ray, then on round */
				qd[0] = (uint32_t)ring_node(n, nm, j, k, i);
				qd[1] = (uint32_t)ring_node(n, nm, j + 1, k, i);
				qd[2] = (uint32_t)ring_node(n, nm, j + 1, k, i + 1);
				qd[3] = (uint32_t)ring_node(n, nm, j, k, i + 1);
			}
	for (int q = 0; q < n; q++)
		for (int p = 0; p < n; p++, qd += 4) {
			qd[0] = (uint32_t)core_node(n, nm, p, q);
			qd[1] = (uint32_t)core_node(n, nm, p + 1, q);
			qd[2] = (uint32_t)core_node(n, nm, p + 1, q + 1);
			qd[3] = (uint32_t)core_node(n, nm, p, q + 1);
		}
	if (nrim)
		*nrim = 4 * (size_t)n;
	return DEM_OK;
}
