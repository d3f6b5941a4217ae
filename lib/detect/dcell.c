/* dcell.c - the dynamic cell (D-cell) contact detection of Ch. 2.4.3.
 *
 * Every box is mapped to the cell of its lower corner (Box 2.1).  Cells are
 * visited slab by slab (z), row by row (y), cell by cell (x); a box whose
 * upper corner reaches past the current slab, row or cell migrates into the
 * following ones.  A box carries one "migrated" bit per axis: bit d is set
 * once it has left the cell where its lower corner lies along d.  Two boxes
 * are tested in a cell only when no bit is set in both, which is the thesis's
 * rule (00 against everything, 01 against 10) written for any dimension: a
 * pair is then tested in exactly one cell, the one holding the componentwise
 * maximum of the two lower corners.
 *
 * Only the migrating boxes move between cells, so the cost is O(N) plus the
 * migrations; nothing is stored per empty cell (the cell grid is implicit
 * in a radix sort of the boxes by cell), so memory is O(N) whatever the cell
 * count.  The instantiations for 2 and 3 dimensions come from
 * dcell_impl.h.
 */
#include "detect/detect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* An item of a slab, row or cell list: a box (index into the sorted box
 * array) and its migrated bits. */
typedef struct item {
	uint32_t e;
	uint32_t m;
} item_t;

/* Sort key of one box: its cell's linear index, and the box index. */
typedef struct keyed {
	uint64_t key;
	uint32_t idx;
} keyed_t;

/* LSD radix sort of n keyed records by key (bits of key < 2^bits), stable,
 * 11 bits a pass; the result ends in *a (buffers may be swapped). */
static void radix_sort(keyed_t **a, keyed_t **tmp, size_t n, int bits)
{
	enum { R = 11, B = 1 << R };
	size_t count[B];

	for (int shift = 0; shift < bits; shift += R) {
		keyed_t *src = *a, *dst = *tmp;
		memset(count, 0, sizeof count);
		for (size_t i = 0; i < n; i++)
			count[(src[i].key >> shift) & (B - 1)]++;
		size_t sum = 0;
		for (size_t k = 0; k < B; k++) {
			size_t c = count[k];
			count[k] = sum;
			sum += c;
		}
		for (size_t i = 0; i < n; i++)
			dst[count[(src[i].key >> shift) & (B - 1)]++] = src[i];
		*a = dst;
		*tmp = src;
	}
}

/* The grid: origin, inverse cell size and cell count per axis.  Cell
 * indices of lower and upper corners come from the same monotone function,
 * so lo_j <= hi_i implies cell(lo_j) <= cell(hi_i) exactly, and migration can
 * be decided on integers without rounding trouble. */
typedef struct grid {
	double org[DEM_MAXDIM], inv[DEM_MAXDIM];
	uint32_t n[DEM_MAXDIM];
	int bits;                       /* bits of the linear cell index */
} grid_t;

static inline uint32_t cell_of(const grid_t *g, int d, double x)
{
	double t = (x - g->org[d]) * g->inv[d];
	if (!(t > 0))                   /* also catches NaN */
		return 0;
	if (t >= g->n[d])
		return g->n[d] - 1;
	return (uint32_t)t;
}

/* Per-axis cell counts are capped so the linear index fits 60 bits and the
 * cell count never exceeds a few times N: a smaller cell than that buys
 * nothing, since most cells would be empty. */
static void grid_setup(grid_t *g, const dem_boxes_t *b, const double *cell,
		       dem_detect_stats_t *st)
{
	int bits = 0;
	double cap = 4.0 * (double)b->n + 1;

	if (cap > (double)(1u << 20))
		cap = (double)(1u << 20);
	for (int d = 0; d < b->dim; d++) {
		double lo = HUGE_VAL, hi = -HUGE_VAL;
		for (size_t i = 0; i < b->n; i++) {
			if (b->lo[d][i] < lo)
				lo = b->lo[d][i];
			if (b->lo[d][i] > hi)
				hi = b->lo[d][i];
		}
		double span = hi - lo, c = cell[d];
		double n = span > 0 && c > 0 ? floor(span / c) + 1 : 1;
		if (n > cap)
			n = cap;
		g->org[d] = lo;
		g->n[d] = (uint32_t)n;
		if (n <= 1)
			g->inv[d] = 0;
		else if (n < cap || floor(span / c) + 1 <= cap)
			g->inv[d] = 1 / c;
		else    /* capped: n cells just span the lower corners */
			g->inv[d] = (n - 0.5) / span;
		if (st) {
			st->cells[d] = g->n[d];
			st->cell[d] = n > 1 ? 1 / g->inv[d] : span;
		}
		int nb = 0;
		while ((1ull << nb) < g->n[d])
			nb++;
		bits += nb;
	}
	g->bits = bits;
}

#define DIM 2
#include "detect/dcell_impl.h"
#undef DIM
#define DIM 3
#include "detect/dcell_impl.h"
#undef DIM
#define DIM 1
#include "detect/dcell_impl.h"
#undef DIM

int dem_detect_dcell(const dem_boxes_t *b, const double *cell,
		     dem_pairs_t *out, dem_detect_stats_t *st)
{
	if (b->n < 2)
		return DEM_OK;
	grid_t g;
	grid_setup(&g, b, cell, st);
	switch (b->dim) {
	case 1:
		return dcell_run1(b, &g, out, st);
	case 2:
		return dcell_run2(b, &g, out, st);
	default:
		return dcell_run3(b, &g, out, st);
	}
}
