/* scell.c - static cell (S-cell) contact detection, Ch. 2.4.1, generalised
 * to boxes of any size.
 *
 * The space spanned by the lower corners is divided into nx * ny (* nz)
 * cells held in one static array, and every box is mapped to the cell of its
 * lower corner.  The thesis maps disks by their centres and searches the 8
 * (4 by symmetry) neighbouring cells, which is exact only when no box is
 * larger than a cell.  Here the reach is measured in cells instead: with
 * span[d] the largest number of cell faces any box crosses along d, a box j
 * overlapping box i has its lower-corner cell between cell(lo_i) - span and
 * cell(hi_i) on every axis, whatever the sizes.  Corner cells come from one
 * monotone function of the coordinate, so this holds exactly, without
 * rounding margins: lo_j <= hi_i gives cell(lo_j) <= cell(hi_i), and
 * hi_j >= lo_i gives cell(lo_j) >= cell(hi_j) - span >= cell(lo_i) - span.
 *
 * The symmetry that halves the 8 neighbours to 4 in the thesis becomes: a
 * pair is tested only from the box that comes first in cell order (cells in
 * linear order, boxes of one cell in input order), so each box scans only the
 * cells of its reach that do not precede its own.  Each pair is tested once.
 *
 * Memory: the cell array is capped at about 4N cells (the cell is enlarged
 * when the requested one would need more), plus a sorted copy of the boxes,
 * so O(N) in all.  Time is O(N) for boxes of similar size and degrades with
 * the size ratio, as the thesis says of this method: one huge box makes
 * every box scan most of the grid.
 */
#include "detect/algo.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The grid; axes at or above dim have one cell, so the scan below can be
 * written once for 1, 2 and 3 dimensions. */
typedef struct sgrid {
	double org[DEM_MAXDIM], inv[DEM_MAXDIM];
	size_t n[DEM_MAXDIM];
} sgrid_t;

/* Cell of coordinate x along d: floor((x - org) / cell) clamped to the grid.
 * Monotone in x, which is all the exactness argument above needs. */
static inline size_t cell_of(const sgrid_t *g, int d, double x)
{
	double t = (x - g->org[d]) * g->inv[d];

	if (!(t > 0))                   /* also NaN */
		return 0;
	if (t >= (double)(g->n[d] - 1))
		return g->n[d] - 1;
	return (size_t)t;
}

/* Choose the cell counts: the requested cell size, enlarged by a common
 * factor on the subdivided axes until the total count is at most cap.  A
 * finer grid than a few cells per box would only add empty cells to scan. */
static void grid_setup(sgrid_t *g, const dem_boxes_t *b, const double *cell,
		       double cap, double *used)
{
	double lo[DEM_MAXDIM], span[DEM_MAXDIM], c[DEM_MAXDIM], cnt[DEM_MAXDIM];

	for (int d = 0; d < DEM_MAXDIM; d++) {
		g->org[d] = 0;
		g->inv[d] = 0;
		g->n[d] = 1;
		used[d] = 0;
	}
	for (int d = 0; d < b->dim; d++) {
		double l = HUGE_VAL, h = -HUGE_VAL;
		for (size_t i = 0; i < b->n; i++) {
			l = fmin(l, b->lo[d][i]);
			h = fmax(h, b->lo[d][i]);
		}
		lo[d] = l;
		span[d] = h - l;
		c[d] = cell[d] > 0 ? cell[d] : 1;
	}
	for (;;) {
		double prod = 1;
		int split = 0;
		for (int d = 0; d < b->dim; d++) {
			/* 2^40 keeps the product finite for absurd cells */
			cnt[d] = span[d] > 0 ?
				 fmin(floor(span[d] / c[d]) + 1, 0x1p40) : 1;
			prod *= cnt[d];
			split += cnt[d] > 1;
		}
		if (prod <= cap || split == 0)
			break;
		/* at least 1/16 larger each round, so the loop ends */
		double f = fmax(pow(prod / cap, 1.0 / split), 1.0625);
		for (int d = 0; d < b->dim; d++)
			if (cnt[d] > 1)
				c[d] *= f;
	}
	for (int d = 0; d < b->dim; d++) {
		g->org[d] = lo[d];
		g->n[d] = (size_t)cnt[d];
		g->inv[d] = g->n[d] > 1 ? 1 / c[d] : 0;
		used[d] = c[d];
	}
}

/* Box p (sorted position) against the boxes of the cells in its reach
 * that do not precede its own cell in linear order (z, then y, then x);
 * in its own cell, the boxes after p.  co holds the sorted boxes, lo then
 * hi, 2 dim doubles each.  Returns the number of box tests. */
static size_t scan(const sgrid_t *g, int dim, const size_t *span,
		   const uint32_t *start, const double *co, const uint32_t *id,
		   size_t p, dem_pairs_t *out)
{
	const size_t s = 2 * (size_t)dim;
	const double *bp = co + p * s;
	size_t own[DEM_MAXDIM] = {0, 0, 0}, lo[DEM_MAXDIM] = {0, 0, 0},
	       hi[DEM_MAXDIM] = {0, 0, 0}, checks = 0;

	for (int d = 0; d < dim; d++) {
		own[d] = cell_of(g, d, bp[d]);
		lo[d] = own[d] > span[d] ? own[d] - span[d] : 0;
		hi[d] = cell_of(g, d, bp[dim + d]);
	}
	for (size_t z = own[2]; z <= hi[2]; z++) {
		int z0 = z == own[2];
		for (size_t y = z0 ? own[1] : lo[1]; y <= hi[1]; y++) {
			int y0 = z0 && y == own[1];
			size_t row = (z * g->n[1] + y) * g->n[0];
			for (size_t x = y0 ? own[0] : lo[0]; x <= hi[0]; x++) {
				size_t c = row + x;
				size_t k0 = y0 && x == own[0] ? p + 1 : start[c];
				checks += start[c + 1] - k0;
				for (size_t k = k0; k < start[c + 1]; k++) {
					const double *bk = co + k * s;
					int hit = 1;
					for (int d = 0; d < dim; d++)
						hit &= (bp[d] <= bk[dim + d]) &
						       (bk[d] <= bp[dim + d]);
					if (hit)
						dem_pairs_push(out, id[p], id[k]);
				}
			}
		}
	}
	return checks;
}

int dem_detect_scell(const dem_boxes_t *b, const double *cell,
		     dem_pairs_t *out, dem_detect_stats_t *st)
{
	const size_t n = b->n;
	const int dim = b->dim;
	sgrid_t g;
	double used[DEM_MAXDIM];

	if (n < 2)
		return DEM_OK;
	grid_setup(&g, b, cell, 4.0 * (double)n, used);
	if (st)
		for (int d = 0; d < dim; d++) {
			st->cells[d] = g.n[d];
			st->cell[d] = used[d];
		}

	const size_t nc = g.n[0] * g.n[1] * g.n[2];
	uint32_t *start = calloc(nc + 1, sizeof *start);
	uint32_t *id = malloc(n * sizeof *id);
	double *co = malloc(2 * (size_t)dim * n * sizeof *co);
	int rc = DEM_EIO;

	if (!start || !id || !co)
		goto done;

	/* The cell array: counting sort of the boxes by lower-corner cell,
	 * input order kept within a cell; span[d] is the reach in cells. */
	size_t span[DEM_MAXDIM] = {0, 0, 0};
	for (size_t i = 0; i < n; i++) {
		size_t lin = 0;
		for (int d = dim - 1; d >= 0; d--) {
			size_t cl = cell_of(&g, d, b->lo[d][i]);
			size_t ch = cell_of(&g, d, b->hi[d][i]);
			if (ch - cl > span[d])
				span[d] = ch - cl;
			lin = lin * g.n[d] + cl;
		}
		start[lin + 1]++;
	}
	for (size_t c = 0; c < nc; c++)
		start[c + 1] += start[c];
	/* place with start[c] as a cursor, then shift the cursors back */
	for (size_t i = 0; i < n; i++) {
		size_t lin = 0;
		for (int d = dim - 1; d >= 0; d--)
			lin = lin * g.n[d] + cell_of(&g, d, b->lo[d][i]);
		id[start[lin]++] = (uint32_t)i;
	}
	memmove(start + 1, start, nc * sizeof *start);
	start[0] = 0;

	/* Sorted copy, box by box: lo[0..dim), hi[0..dim), so the scan of a
	 * cell reads contiguous memory. */
	const size_t s = 2 * (size_t)dim;
	for (size_t k = 0; k < n; k++)
		for (int d = 0; d < dim; d++) {
			co[k * s + d] = b->lo[d][id[k]];
			co[k * s + dim + d] = b->hi[d][id[k]];
		}

	size_t checks = 0;
	for (size_t p = 0; p < n; p++) {
		checks += scan(&g, dim, span, start, co, id, p, out);
		if (out->nomem)
			goto done;
	}
	if (st)
		st->checks += checks;
	rc = DEM_OK;
done:
	free(start);
	free(id);
	free(co);
	return rc;
}
