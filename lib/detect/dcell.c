/* dcell.c - the dynamic cell (D-cell) contact detection of Ch. 2.4.3.
 *
 * Every box is mapped to the cell of its lower corner (Box 2.1).  A box
 * carries one "migrated" bit per axis: bit d is set once it has left, along
 * d, the cell where its lower corner lies (types 01, 10 and 11 of Ch.
 * 2.4.3).  Two boxes are tested in a cell only when no bit is set in both,
 * which is the rule of Fig. 2.8 (00 against every type, 01 against 10)
 * written for any dimension: a pair is then tested in exactly one cell, the
 * one holding the componentwise maximum of the two lower corners.
 *
 * The grid is implicit: the boxes are radix-sorted by cell (slab, row,
 * column), so nothing is stored per empty cell and memory is O(N) whatever
 * the cell count.  Two sweeps make the tests of Fig. 2.8:
 *
 * - The near sweep, for the usual sets, where no box crosses more than one
 *   cell face along any axis.  The boxes that migrate into a cell T then
 *   come only from the cells T - dA, dA a 0/1 vector, and the tests in T are
 *   those between the boxes of T - dA and of T - dB with dA & dB = 0, each
 *   box reaching T along the axes of its vector.  Walking the non-empty
 *   cells A in order, with one cursor per row of neighbour cells, reaches
 *   every such pair of source cells in place in the sorted array: the
 *   migration lists are never built (dcell_impl.h, sweep_near).
 * - The list sweep of Box 2.1 for the other sets: slab, row and cell lists
 *   with the migrants merged in, as in the thesis.
 *
 * The buffers come from a workspace (dem_detect_ws_t), so a time loop that
 * detects every step reuses them.  The instantiations for 1, 2 and 3
 * dimensions come from dcell_impl.h.
 */
#include "detect/algo.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Workspace slots (dem_detect_ws_get). */
enum {
	WS_RAW,         /* boxes in input order, then the cells' group starts
			 * (near sweep) or cell coordinates (list sweep) */
	WS_ENT,         /* boxes in cell order; before, the radix sort's
			 * second buffer */
	WS_KEY,         /* sort keys */
	WS_CELL,        /* the indices of the non-empty cells (near sweep) */
	WS_LIST         /* the lists of the list sweep */
};

/* The grid: origin, inverse cell size and cell count per axis.  Cell
 * indices of lower and upper corners come from the same monotone function,
 * so lo_j <= hi_i implies cell(lo_j) <= cell(hi_i) exactly, and migration is
 * decided on integers without rounding trouble. */
typedef struct grid {
	double org[DEM_MAXDIM], inv[DEM_MAXDIM];
	double top[DEM_MAXDIM];         /* n - 1, the last cell */
	uint32_t n[DEM_MAXDIM];
	int kb;                         /* bits of a sort key: cell, group */
} grid_t;

static inline uint32_t cell_of(const grid_t *g, int d, double x)
{
	double t = (x - g->org[d]) * g->inv[d];
	t = t > 0 ? t : 0;              /* also maps NaN to 0 */
	t = t < g->top[d] ? t : g->top[d];
	return (uint32_t)t;
}

/* The smallest and largest of x[0 .. n - 1] (NaNs ignored); two chains of
 * each, so the comparisons do not all wait on one another. */
static void span_of(const double *x, size_t n, double *lo, double *hi)
{
	double l0 = HUGE_VAL, l1 = HUGE_VAL, h0 = -HUGE_VAL, h1 = -HUGE_VAL;
	size_t i = 0;

	for (; i + 2 <= n; i += 2) {
		l0 = x[i] < l0 ? x[i] : l0;
		h0 = x[i] > h0 ? x[i] : h0;
		l1 = x[i + 1] < l1 ? x[i + 1] : l1;
		h1 = x[i + 1] > h1 ? x[i + 1] : h1;
	}
	for (; i < n; i++) {
		l0 = x[i] < l0 ? x[i] : l0;
		h0 = x[i] > h0 ? x[i] : h0;
	}
	*lo = l0 < l1 ? l0 : l1;
	*hi = h0 > h1 ? h0 : h1;
}

/* Per-axis cell counts are capped so the linear index fits 60 bits and the
 * cell count never exceeds a few times N: a smaller cell than that buys
 * nothing, since most cells would be empty. */
static void grid_setup(grid_t *g, const dem_boxes_t *b, const double *cell,
		       dem_detect_stats_t *st)
{
	double cap = 4.0 * (double)b->n + 1;
	uint64_t cells = 1;

	if (cap > (double)(1u << 20))
		cap = (double)(1u << 20);
	for (int d = 0; d < b->dim; d++) {
		double lo, hi;
		span_of(b->lo[d], b->n, &lo, &hi);
		double span = hi - lo, c = cell[d];
		double n = span > 0 && c > 0 ? floor(span / c) + 1 : 1;
		if (n > cap)
			n = cap;
		g->org[d] = lo;
		g->n[d] = (uint32_t)n;
		g->top[d] = n - 1;
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
		cells *= g->n[d];
	}
	int bits = 0;
	while (bits < 64 && (cells - 1) >> bits)
		bits++;
	g->kb = bits + b->dim;
}

/* Sort keys come packed, (cell << dim | group) << 32 | box index, when that
 * fits 64 bits (one word to move a pass), else as a pair. */
typedef struct keyed {
	uint64_t key;
	uint32_t idx;
} keyed_t;

/* The passes of the radix sorts for kb key bits: as few as cover them
 * with digits of at most 11 bits (2048 counts, which stay in L1). */
static int sort_passes(int kb)
{
	return (kb + 10) / 11;
}

/* LSD radix sort of packed keys by bits 32 .. 32 + kb - 1 (kb <= 32), in
 * sort_passes(kb) passes of equal digits, the counts of every pass from one
 * read.  Returns the buffer that holds the result (a or tmp). */
static uint64_t *sort_packed(uint64_t *a, uint64_t *tmp, size_t n, int kb)
{
	enum { MAXR = 11, MAXP = 3 };
	static_assert(MAXR * MAXP >= 32, "three passes cover 32 bits");
	uint32_t count[MAXP][1 << MAXR];
	int passes = sort_passes(kb);
	if (passes == 0)
		return a;
	int r = (kb + passes - 1) / passes;
	uint32_t mask = (1u << r) - 1;

	memset(count, 0, sizeof count);
	for (size_t i = 0; i < n; i++) {
		uint64_t k = a[i] >> 32;
		for (int p = 0; p < passes; p++)
			count[p][(k >> (p * r)) & mask]++;
	}
	for (int p = 0; p < passes; p++) {
		uint32_t sum = 0;
		for (uint32_t k = 0; k <= mask; k++) {
			uint32_t c = count[p][k];
			count[p][k] = sum;
			sum += c;
		}
	}
	for (int p = 0; p < passes; p++) {
		uint32_t *c = count[p];
		int shift = 32 + p * r;
		for (size_t i = 0; i < n; i++)
			tmp[c[(a[i] >> shift) & mask]++] = a[i];
		uint64_t *t = a;
		a = tmp;
		tmp = t;
	}
	return a;
}

/* LSD radix sort of keyed records by key (bits of key < 2^kb), stable,
 * 11 bits a pass (sort_passes(kb) passes); returns the buffer that holds
 * the result (a or tmp). */
static keyed_t *sort_wide(keyed_t *a, keyed_t *tmp, size_t n, int kb)
{
	enum { R = 11, B = 1 << R };
	size_t count[B];

	for (int shift = 0; shift < kb; shift += R) {
		memset(count, 0, sizeof count);
		for (size_t i = 0; i < n; i++)
			count[(a[i].key >> shift) & (B - 1)]++;
		size_t sum = 0;
		for (size_t k = 0; k < B; k++) {
			size_t c = count[k];
			count[k] = sum;
			sum += c;
		}
		for (size_t i = 0; i < n; i++)
			tmp[count[(a[i].key >> shift) & (B - 1)]++] = a[i];
		keyed_t *t = a;
		a = tmp;
		tmp = t;
	}
	return a;
}

/* The sorted keys, whichever form they took. */
typedef struct sorted {
	const uint64_t *pk;     /* packed, or NULL */
	const keyed_t *wk;      /* else these */
} sorted_t;

static inline uint64_t sorted_key(const sorted_t *s, size_t k)
{
	return s->pk ? s->pk[k] >> 32 : s->wk[k].key;
}

static inline uint32_t sorted_idx(const sorted_t *s, size_t k)
{
	return s->pk ? (uint32_t)s->pk[k] : s->wk[k].idx;
}

/* Make room for need more pairs. */
static inline int room(dem_pairs_t *out, size_t need)
{
	while (out->cap - out->n < need)
		if (dem_pairs_grow(out) != 0)
			return 0;
	return 1;
}

/* The tests write each pair as (box tested, box tested against); one pass
 * at the end puts the smaller index first. */
static void pairs_order(dem_pairs_t *out, size_t from)
{
	for (size_t k = from; k < out->n; k++) {
		uint32_t i = out->p[k].i, j = out->p[k].j;
		out->p[k].i = i < j ? i : j;
		out->p[k].j = i < j ? j : i;
	}
}

/* A set of boxes of a cell as runs of its groups: group b[r] up to (not
 * including) group e[r], for r < n. */
typedef struct runs {
	int n;
	unsigned char b[4], e[4];
} runs_t;

/* The runs of the groups whose boxes have all the bits of m, for every m,
 * given the order of the groups (group_f[g]: the migration bits of group g). */
static void runs_setup(runs_t *r, const unsigned char *group_f, int ng)
{
	for (int m = 0; m < ng; m++) {
		r[m].n = 0;
		for (int g = 0; g < ng; g++) {
			if ((group_f[g] & m) != m)
				continue;
			if (r[m].n && r[m].e[r[m].n - 1] == g) {
				r[m].e[r[m].n - 1]++;
			} else {
				r[m].b[r[m].n] = (unsigned char)g;
				r[m].e[r[m].n++] = (unsigned char)(g + 1);
			}
		}
	}
}

/* A row of neighbour cells of the near sweep: the cells A + (vx, vy, vz),
 * vx = -1, 0, 1, for one (vy, vz) whose last nonzero component is +1, so
 * that of the source cells A, B = A + v and B, A = B - v only one pair is
 * met, from A.  The three cells are consecutive in the cell order, so one
 * cursor finds them.  Boxes of A take part when they reach the owner cell
 * T = max(A, B) along the axes where v = +1 (da), boxes of B along the axes
 * where v = -1 (db); vx adds x to one of them. */
typedef struct nrow {
	uint64_t delta;         /* linear index of A + (0, vy, vz) minus A's */
	int vy, vz;
	unsigned da, db;        /* their y and z bits */
} nrow_t;

#define NROW_MAX 4

/* The rows of neighbours for a grid of dim axes: (0, 1) in 2D; (1, 0),
 * (-1, 1), (0, 1), (1, 1) in 3D; none in 1D.  The index difference is taken
 * mod 2^64; it is positive for every row that is inside the grid. */
static int nrow_setup(const grid_t *g, int dim, nrow_t *t)
{
	int k = 0;

	for (int vz = 0; vz <= (dim > 2); vz++)
		for (int vy = -1; vy <= 1 && dim > 1; vy++) {
			if (!(vz == 1 || vy == 1))
				continue;       /* last nonzero must be +1 */
			uint64_t delta = (uint64_t)(int64_t)vy * g->n[0];
			if (vz)
				delta += (uint64_t)g->n[0] * g->n[1];
			unsigned da = (unsigned)(vy > 0) << 1 | (unsigned)vz << 2;
			t[k++] = (nrow_t){delta, vy, vz, da,
					  (unsigned)(vy < 0) << 1};
		}
	return k;
}

/* Where a row of neighbours' boxes begin for the boxes of A (s), and where
 * they end for a box of A that does not (e0) or does (e1) reach the next
 * cell along x. */
typedef struct span {
	uint32_t s, e0, e1;
	const nrow_t *row;
} span_t;

/* Where the cells of a row of tests lie from A's along an axis (see
 * axis_ok in dcell_impl.h). */
enum { AX_ANY, AX_ABOVE, AX_BELOW };

/* The 3D near sweep has an AVX2 twin (dcell_sweep.h), built with GCC on
 * x86-64 and chosen at run time when the processor has AVX2 (DEM_NO_AVX2
 * in the environment forces the portable one, for comparisons). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define DCELL_X86_AVX2 1
#include <immintrin.h>
static int have_avx2(void)
{
	static int have = -1;
	if (have < 0) {
		__builtin_cpu_init();
		have = __builtin_cpu_supports("avx2") && !getenv("DEM_NO_AVX2");
	}
	return have;
}
#else
#define DCELL_X86_AVX2 0
#endif

/* An item of a slab, row or cell list of the list sweep: a box (index into
 * the sorted box array) and its migrated bits. */
typedef struct item {
	uint32_t e;
	uint32_t m;
} item_t;

#define DIM 2
#include "detect/dcell_impl.h"
#undef DIM
#define DIM 3
#include "detect/dcell_impl.h"
#undef DIM
#define DIM 1
#include "detect/dcell_impl.h"
#undef DIM

int dem_detect_dcell_ws(const dem_boxes_t *b, const double *cell,
			dem_detect_ws_t *ws, dem_pairs_t *out,
			dem_detect_stats_t *st)
{
	dem_detect_ws_t *own = NULL;
	grid_t g;
	int rc;

	if (b->n < 2)
		return DEM_OK;
	grid_setup(&g, b, cell, st);
	if (!ws && !(ws = own = dem_detect_ws_new()))
		return DEM_EIO;
	switch (b->dim) {
	case 1:
		rc = dcell_run1(b, &g, ws, out, st);
		break;
	case 2:
		rc = dcell_run2(b, &g, ws, out, st);
		break;
	default:
		rc = dcell_run3(b, &g, ws, out, st);
		break;
	}
	dem_detect_ws_free(own);
	return rc;
}

int dem_detect_dcell(const dem_boxes_t *b, const double *cell,
		     dem_pairs_t *out, dem_detect_stats_t *st)
{
	return dem_detect_dcell_ws(b, cell, NULL, out, st);
}
