/* nbs.c - NBS (no binary search) contact detection, Ch. 2.4.2, after
 * Munjiza and Andrews (1998); 2D only (the dispatcher refuses 3D).
 *
 * Each box is mapped to the cell (ix, iy) of its lower corner.  No nx * ny
 * array exists: a singly linked list per row Y[iy] holds the boxes of that
 * row, and the boxes of one row at a time are spread into singly linked
 * lists per column X[ix].  Memory is O(N + nx + ny) whatever the spatial
 * distribution, and for boxes of similar size time is O(N).
 *
 * The original method takes a cell as large as the largest object and
 * checks each object against the 5 cells of its own and the previous row
 * (own, left; and the three below).  Generalised here to any cell and any
 * size ratio, as an exact method: with S[d] the largest number of cell
 * faces a box crosses along d, a box j overlapping box i has its lower
 * corner cell within cell(lo_i) - S and cell(hi_i) on each axis (cells
 * of lower and upper corners come from one monotone function, so this is
 * exact).  A pair is tested from the box in the earlier row, or in the same
 * row from the box in the earlier column (same cell: the smaller index).
 * So the rows are taken in order; row q is spread into X lists, and the
 * boxes of rows q - S[1] .. q whose upper corner reaches row q scan its
 * columns cell(lo) - S[0] .. cell(hi) (in row q itself, from their own
 * column on).  When that column range is longer than row q's box list,
 * the list itself is walked instead, which bounds the work for very
 * unequal sizes by that of brute force within the reach.
 */
#include "detect/algo.h"

#include <math.h>
#include <stdlib.h>

#define NONE UINT32_MAX

typedef struct axis {
	double org, inv;
	uint32_t n;
	double cell;
} axis_t;

static inline uint32_t cell_of(const axis_t *a, double x)
{
	double t = (x - a->org) * a->inv;

	if (!(t > 0))                   /* also NaN */
		return 0;
	if (t >= (double)(a->n - 1))
		return a->n - 1;
	return (uint32_t)t;
}

/* Cells along one axis over the lower corners.  At most cap cells: finer
 * ones would only lengthen the column scans, and the lists stay
 * O(N + nx + ny). */
static void axis_setup(axis_t *a, const double *lo, size_t n, double cell,
		       double cap)
{
	double l = HUGE_VAL, h = -HUGE_VAL, c = cell > 0 ? cell : 1;

	for (size_t i = 0; i < n; i++) {
		l = fmin(l, lo[i]);
		h = fmax(h, lo[i]);
	}
	double span = h - l, cnt = span > 0 ? floor(span / c) + 1 : 1;
	if (cnt > cap) {
		c = span / (cap - 1);   /* cap cells just cover the corners */
		cnt = floor(span / c) + 1;
		if (cnt > cap)
			cnt = cap;
	}
	a->org = l;
	a->n = (uint32_t)cnt;
	a->inv = a->n > 1 ? 1 / c : 0;
	a->cell = c;
}

/* What the lists need of a box, in one record: its list links, the column
 * of its lower corner and the row of its upper corner, and its box. */
typedef struct ent {
	double lo[2], hi[2];
	uint32_t cx, hy;
	uint32_t xnext, ynext;
} ent_t;

static inline int overlap2(const ent_t *p, const ent_t *q)
{
	return (p->lo[0] <= q->hi[0]) & (q->lo[0] <= p->hi[0]) &
	       (p->lo[1] <= q->hi[1]) & (q->lo[1] <= p->hi[1]);
}

/* Box i against the boxes of row q (X lists xhead, Y list from yq, count
 * boxes) whose columns lie in lo .. hi; in i's own row (same), only those
 * after i.  Returns the number of box tests. */
static size_t scan(const ent_t *e, uint32_t i, uint32_t lo, uint32_t hi,
		   int same, const uint32_t *xhead, uint32_t yq, size_t count,
		   dem_pairs_t *out)
{
	const ent_t *p = &e[i];
	const uint32_t ci = p->cx;
	size_t checks = 0;

	if ((size_t)(hi - lo) + 1 > count) {
		/* more columns than boxes: walk the row list instead */
		for (uint32_t j = yq; j != NONE; j = e[j].ynext) {
			const ent_t *t = &e[j];
			if (t->cx < lo || t->cx > hi ||
			    (same && t->cx == ci && j <= i))
				continue;
			checks++;
			if (overlap2(p, t))
				dem_pairs_push(out, i, j);
		}
		return checks;
	}
	for (uint32_t x = lo; x <= hi; x++)
		for (uint32_t j = xhead[x]; j != NONE; j = e[j].xnext) {
			if (same && x == ci && j <= i)
				continue;
			checks++;
			if (overlap2(p, &e[j]))
				dem_pairs_push(out, i, j);
		}
	return checks;
}

int dem_detect_nbs(const dem_boxes_t *b, const double *cell,
		   dem_pairs_t *out, dem_detect_stats_t *st)
{
	const size_t n = b->n;
	axis_t ax, ay;

	if (n < 2)
		return DEM_OK;
	/* per axis at most 4N + 1 cells, and indices below NONE */
	double cap = fmin(4.0 * (double)n + 1, (double)(NONE - 1));
	axis_setup(&ax, b->lo[0], n, cell[0], cap);
	axis_setup(&ay, b->lo[1], n, cell[1], cap);
	if (st) {
		st->cells[0] = ax.n;
		st->cells[1] = ay.n;
		st->cell[0] = ax.cell;
		st->cell[1] = ay.cell;
	}

	ent_t *e = malloc(n * sizeof *e);
	uint32_t *yhead = malloc(ay.n * sizeof *yhead);
	uint32_t *xhead = malloc(ax.n * sizeof *xhead);
	uint32_t *rows = malloc(ay.n * sizeof *rows);       /* non-empty rows */
	int rc = DEM_EIO;

	if (!e || !yhead || !xhead || !rows)
		goto done;
	for (uint32_t k = 0; k < ay.n; k++)
		yhead[k] = NONE;
	for (uint32_t k = 0; k < ax.n; k++)
		xhead[k] = NONE;

	/* Y lists, boxes pushed in input order (as in Fig. 2.7); S is the
	 * reach in cells. */
	uint32_t sx = 0, sy = 0;
	for (size_t k = 0; k < n; k++) {
		ent_t *p = &e[k];
		for (int d = 0; d < 2; d++) {
			p->lo[d] = b->lo[d][k];
			p->hi[d] = b->hi[d][k];
		}
		uint32_t x1 = cell_of(&ax, p->hi[0]), y0 = cell_of(&ay, p->lo[1]);
		p->cx = cell_of(&ax, p->lo[0]);
		p->hy = cell_of(&ay, p->hi[1]);
		if (x1 - p->cx > sx)
			sx = x1 - p->cx;
		if (p->hy - y0 > sy)
			sy = p->hy - y0;
		p->ynext = yhead[y0];
		yhead[y0] = (uint32_t)k;
	}
	size_t nrows = 0;
	for (uint32_t k = 0; k < ay.n; k++)
		if (yhead[k] != NONE)
			rows[nrows++] = k;

	size_t checks = 0;
	for (size_t qi = 0; qi < nrows; qi++) {
		const uint32_t q = rows[qi];
		size_t count = 0;

		/* spread row q into its X lists */
		for (uint32_t j = yhead[q]; j != NONE; j = e[j].ynext) {
			e[j].xnext = xhead[e[j].cx];
			xhead[e[j].cx] = j;
			count++;
		}
		/* the boxes of rows q - S[1] .. q that reach row q test
		 * themselves against it */
		for (size_t ri = qi + 1; ri-- > 0 && q - rows[ri] <= sy;) {
			const int same = ri == qi;
			for (uint32_t i = yhead[rows[ri]]; i != NONE; i = e[i].ynext) {
				if (e[i].hy < q)
					continue;
				uint32_t ci = e[i].cx;
				uint32_t lo = same ? ci : ci > sx ? ci - sx : 0;
				uint32_t hi = cell_of(&ax, e[i].hi[0]);
				checks += scan(e, i, lo, hi, same, xhead, yhead[q],
					       count, out);
			}
		}
		/* clear the X lists through the row's own boxes: O(row), not
		 * O(nx) */
		for (uint32_t j = yhead[q]; j != NONE; j = e[j].ynext)
			xhead[e[j].cx] = NONE;
		if (out->nomem)
			goto done;
	}
	if (st)
		st->checks += checks;
	rc = DEM_OK;
done:
	free(e);
	free(yhead);
	free(xhead);
	free(rows);
	return rc;
}
