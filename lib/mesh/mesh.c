/* mesh.c - structured hexahedral meshes of a box (see mesh.h). */
#include "mesh/mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Element sizes of one graded side of length len: the sizes h0 r^k capped
 * at hmax, as many as make their sum closest to len (in ratio), scaled to
 * sum to len exactly.  Writes up to cap sizes into s (s may be NULL to
 * count); returns the count, or -1 if more than cap are needed. */
static long side_sizes(double len, double h0, double r, double hmax,
		       double *s, long cap)
{
	double sum = 0, prev = 0, size = h0, scale;
	long n = 0, i;

	if (len <= 0)
		return 0;
	while (sum < len) {
		if (n >= cap && s)
			return -1;
		prev = sum;
		if (s)
			s[n] = size;
		sum += size;
		n++;
		size *= r;
		if (hmax > 0 && size > hmax)
			size = hmax;
		if (n > 100000000L)
			return -1;
	}
	/* n sizes overshoot (sum >= len); n - 1 fall short (prev < len):
	 * keep the count whose scale factor is nearer to 1 */
	if (n > 1 && len / prev < sum / len)
		n--, sum = prev;
	if (s) {
		scale = len / sum;
		for (i = 0; i < n; i++)
			s[i] *= scale;
	}
	return n;
}

int dem_axis_grid(const dem_axis_t *a, double **g, int *n, dem_error_t *e)
{
	double wfine = a->fine_hi - a->fine_lo, h0, *below = NULL, *above = NULL;
	double *grid;
	long nf = 0, nb, na, i, k;

	*g = NULL;
	*n = 0;
	if (!(isfinite(a->lo) && isfinite(a->hi) && a->lo < a->hi))
		return dem_error_set(e, DEM_EINPUT, "mesh axis: [%g, %g] is not an "
				     "interval", a->lo, a->hi);
	if (!(a->fine_lo >= a->lo && a->fine_hi <= a->hi && wfine >= 0))
		return dem_error_set(e, DEM_EINPUT, "mesh axis: fine region "
				     "[%g, %g] is not inside [%g, %g]", a->fine_lo,
				     a->fine_hi, a->lo, a->hi);
	if (!(a->h > 0) || !isfinite(a->h))
		return dem_error_set(e, DEM_EINPUT, "mesh axis: element size %g "
				     "is not positive", a->h);
	if (!(a->ratio >= 1) || !isfinite(a->ratio))
		return dem_error_set(e, DEM_EINPUT, "mesh axis: grading ratio %g "
				     "is less than 1", a->ratio);
	if (a->hmax != 0 && !(a->hmax >= a->h))
		return dem_error_set(e, DEM_EINPUT, "mesh axis: largest element "
				     "%g is smaller than the element size %g",
				     a->hmax, a->h);
	if ((a->hi - a->lo) / a->h > 1e8)
		return dem_error_set(e, DEM_EINPUT, "mesh axis: element size %g "
				     "gives too many elements over %g", a->h,
				     a->hi - a->lo);
	if (wfine > 0) {
		nf = lround(wfine / a->h);
		if (nf < 1)
			nf = 1;
	}
	/* outside a fine region the first element already grows by r; from a
	 * bare grading point it starts at h */
	h0 = nf > 0 ? a->h * a->ratio : a->h;
	if (a->hmax > 0 && h0 > a->hmax)
		h0 = a->hmax;
	nb = side_sizes(a->fine_lo - a->lo, h0, a->ratio, a->hmax, NULL, 0);
	na = side_sizes(a->hi - a->fine_hi, h0, a->ratio, a->hmax, NULL, 0);
	if (nb < 0 || na < 0 || nf + nb + na > 100000000L)
		return dem_error_set(e, DEM_EINPUT, "mesh axis: too many elements");
	grid = malloc((size_t)(nf + nb + na + 1) * sizeof *grid);
	below = malloc((size_t)(nb + 1) * sizeof *below);
	above = malloc((size_t)(na + 1) * sizeof *above);
	if (!grid || !below || !above) {
		free(grid), free(below), free(above);
		return dem_error_nomem(e, "mesh axis");
	}
	side_sizes(a->fine_lo - a->lo, h0, a->ratio, a->hmax, below, nb + 1);
	side_sizes(a->hi - a->fine_hi, h0, a->ratio, a->hmax, above, na + 1);
	/* from lo: the below sizes in reverse (largest first), then the fine
	 * region, then the above sizes; the region ends are set exactly */
	k = 0;
	grid[k++] = a->lo;
	for (i = nb - 1; i >= 0; i--, k++)
		grid[k] = grid[k - 1] + below[i];
	if (nb > 0)
		grid[k - 1] = a->fine_lo;
	for (i = 1; i <= nf; i++, k++)
		grid[k] = i == nf ? a->fine_hi
			: a->fine_lo + wfine * (double)i / (double)nf;
	for (i = 0; i < na; i++, k++)
		grid[k] = grid[k - 1] + above[i];
	grid[k - 1] = a->hi;
	free(below);
	free(above);
	*g = grid;
	*n = (int)(k - 1);
	return DEM_OK;
}

void dem_mesh_free(dem_mesh_t *m)
{
	free(m->gx), free(m->gy), free(m->gz);
	free(m->X), free(m->hex), free(m->fix), free(m->tie);
	memset(m, 0, sizeof *m);
}

int dem_mesh_axes(const dem_axis_t *ax, int na, double **g, int *n, dem_error_t *e)
{
	static const char name[] = "xyz";
	int a;

	for (a = 0; a < na; a++)
		g[a] = NULL;
	for (a = 0; a < na; a++) {
		if (dem_axis_grid(&ax[a], &g[a], &n[a], e) != DEM_OK) {
			char msg[sizeof e->msg];

			/* name the axis: "mesh x axis: ..." */
			snprintf(msg, sizeof msg, "mesh %c axis:%s", name[a],
				 e->msg + strlen("mesh axis:"));
			memcpy(e->msg, msg, sizeof msg);
			for (int b = 0; b < na; b++)
				free(g[b]), g[b] = NULL;
			return e->code;
		}
	}
	return DEM_OK;
}

int dem_mesh_box(dem_mesh_t *m, const dem_axis_t ax[3], dem_error_t *e)
{
	double *g[3];
	int n[3];

	memset(m, 0, sizeof *m);
	if (dem_mesh_axes(ax, 3, g, n, e) != DEM_OK)
		return e->code;
	return dem_mesh_grid(m, g, n, e);
}

int dem_mesh_grid(dem_mesh_t *m, double *g[3], const int n[3], dem_error_t *e)
{
	int i, j, k;
	size_t nn, ne, p;

	memset(m, 0, sizeof *m);
	nn = (size_t)(n[0] + 1) * (size_t)(n[1] + 1) * (size_t)(n[2] + 1);
	ne = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
	if (nn > UINT32_MAX) {
		free(g[0]), free(g[1]), free(g[2]);
		return dem_error_set(e, DEM_EINPUT, "mesh: %zu nodes are more than "
				     "a mesh can number (%u)", nn, UINT32_MAX);
	}
	m->nx = n[0], m->ny = n[1], m->nz = n[2];
	m->gx = g[0], m->gy = g[1], m->gz = g[2];
	m->nn = nn, m->ne = ne;
	m->X = malloc(3 * nn * sizeof *m->X);
	m->hex = malloc(8 * ne * sizeof *m->hex);
	m->fix = calloc(nn, sizeof *m->fix);
	if (!m->X || !m->hex || !m->fix) {
		dem_mesh_free(m);
		return dem_error_nomem(e, "mesh");
	}
	for (k = 0, p = 0; k <= m->nz; k++)
		for (j = 0; j <= m->ny; j++)
			for (i = 0; i <= m->nx; i++, p++) {
				m->X[3 * p] = m->gx[i];
				m->X[3 * p + 1] = m->gy[j];
				m->X[3 * p + 2] = m->gz[k];
			}
	for (k = 0, p = 0; k < m->nz; k++)
		for (j = 0; j < m->ny; j++)
			for (i = 0; i < m->nx; i++, p++) {
				uint32_t *h = m->hex + 8 * p;
				int c;

				for (c = 0; c < 2; c++) {
					h[4 * c + 0] = (uint32_t)dem_mesh_node(m, i, j, k + c);
					h[4 * c + 1] = (uint32_t)dem_mesh_node(m, i + 1, j, k + c);
					h[4 * c + 2] = (uint32_t)dem_mesh_node(m, i + 1, j + 1, k + c);
					h[4 * c + 3] = (uint32_t)dem_mesh_node(m, i, j + 1, k + c);
				}
			}
	return DEM_OK;
}

void dem_mesh_set_bc(dem_mesh_t *m, const dem_bc_t bc[6])
{
	static const uint8_t normal[3] = {DEM_FIX_X, DEM_FIX_Y, DEM_FIX_Z};
	const uint8_t all = DEM_FIX_X | DEM_FIX_Y | DEM_FIX_Z;
	int i, j, k, f;

	memset(m->fix, 0, m->nn);
	for (k = 0; k <= m->nz; k++)
		for (j = 0; j <= m->ny; j++)
			for (i = 0; i <= m->nx; i++) {
				/* the faces this node lies on */
				int on[6] = {i == 0, i == m->nx, j == 0, j == m->ny,
					     k == 0, k == m->nz};
				uint8_t b = 0;

				for (f = 0; f < 6; f++) {
					if (!on[f] || bc[f] == DEM_BC_FREE ||
					    bc[f] == DEM_BC_PERIODIC)
						continue;
					b |= bc[f] == DEM_BC_FIXED ? all : normal[f / 2];
				}
				m->fix[dem_mesh_node(m, i, j, k)] = b;
			}
}

int dem_mesh_set_periodic(dem_mesh_t *m, int px, int py, dem_error_t *e)
{
	size_t n = 0;
	int i, j, k;

	free(m->tie);
	m->tie = NULL;
	m->ntie = 0;
	if (!px && !py)
		return DEM_OK;
	/* at most one face of nodes per pair, the corner line counted twice */
	m->tie = malloc(2 * (size_t)(m->nz + 1) *
			((size_t)(m->nx + 1) + (size_t)(m->ny + 1)) * sizeof *m->tie);
	if (!m->tie)
		return dem_error_nomem(e, "periodic ties");
	for (k = 0; k <= m->nz; k++)
		for (j = 0; j <= m->ny; j++)
			for (i = 0; i <= m->nx; i++) {
				/* the master straight away, not through another
				 * slave: (nx, ny) goes to (0, 0) */
				int im = px && i == m->nx ? 0 : i;
				int jm = py && j == m->ny ? 0 : j;

				if (im == i && jm == j)
					continue;
				m->tie[2 * n] = (uint32_t)dem_mesh_node(m, i, j, k);
				m->tie[2 * n + 1] = (uint32_t)dem_mesh_node(m, im, jm, k);
				n++;
			}
	m->ntie = n;
	return DEM_OK;
}

void dem_mesh_gather(const dem_mesh_t *m, size_t el, const double *u, double x[24])
{
	const uint32_t *h = m->hex + 8 * el;
	int I, c;

	for (I = 0; I < 8; I++)
		for (c = 0; c < 3; c++)
			x[8 * c + I] = m->X[3 * (size_t)h[I] + c]
				+ (u ? u[3 * (size_t)h[I] + c] : 0);
}
