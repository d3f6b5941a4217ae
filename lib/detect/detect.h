/* detect.h - contact detection (global search) between axis-aligned boxes.
 *
 * Thesis Ch. 2.  Every object is reduced to its axis-aligned bounding box
 * (Ch. 2.2); boxes are closed, so boxes that touch on a face, an edge or a
 * corner overlap.  Every algorithm returns the same set of pairs (i < j, each
 * pair once) as brute force; the order of pairs is each algorithm's own and
 * deterministic: dem_pairs_sort() gives the canonical (i, j) order.
 */
#ifndef DEM_DETECT_DETECT_H
#define DEM_DETECT_DETECT_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

#define DEM_MAXDIM 3

/* N boxes in structure-of-arrays form: lo[d][i] <= hi[d][i] for d < dim.
 * The arrays are owned by whoever filled them (see dem_boxes_alloc). */
typedef struct dem_boxes {
	int dim;                  /* 2 or 3 (1 also works) */
	size_t n;
	double *lo[DEM_MAXDIM];
	double *hi[DEM_MAXDIM];
} dem_boxes_t;

/* One contact pair: i < j, indices into the box set. */
typedef struct dem_pair {
	uint32_t i, j;
} dem_pair_t;

/* A growable list of pairs. */
typedef struct dem_pairs {
	dem_pair_t *p;
	size_t n, cap;
	int nomem;                /* set when a push failed for lack of memory */
} dem_pairs_t;

typedef enum dem_detect_algo {
	DEM_DETECT_DCELL,         /* dynamic cell, Ch. 2.4.3, Box 2.1 (default) */
	DEM_DETECT_NBS,           /* no binary search, Ch. 2.4.2 (2D only) */
	DEM_DETECT_SCELL,         /* static cell, Ch. 2.4.1 */
	DEM_DETECT_ADT,           /* alternating digital tree, Ch. 2.3.2 */
	DEM_DETECT_ASDT,          /* augmented spatial digital tree, Ch. 2.3.3 */
	DEM_DETECT_BRUTE          /* all N(N-1)/2 pairs */
} dem_detect_algo_t;

/* A workspace: the buffers of a detection kept from one call to the next,
 * so a time loop that detects every step neither allocates nor touches
 * fresh pages after the first step (STYLE.md 10).  Opaque; one workspace
 * serves one detection at a time. */
typedef struct dem_detect_ws dem_detect_ws_t;

typedef struct dem_detect_opts {
	dem_detect_algo_t algo;
	/* Cell size of the cell methods, per axis.  0 means: cell_factor times
	 * the mean box extent (the Ch. 2.5 rule). */
	double cell[DEM_MAXDIM];
	/* Multiplier of the mean box extent; 0 means the default, 3 in 2D
	 * (the Ch. 2.5 rule) and 2 in 3D (measured optimum; Ch. 2.5 found
	 * about 5 for its implementation). */
	double cell_factor;
	/* Periodic axes: bit d set means axis d is periodic with period
	 * period_hi[d] - period_lo[d] (minimum image: every box must be shorter
	 * than half the period along that axis). */
	unsigned periodic;
	double period_lo[DEM_MAXDIM], period_hi[DEM_MAXDIM];
	/* Buffers to reuse (see dem_detect_ws_new); NULL: allocate and free
	 * them within each call. */
	struct dem_detect_ws *ws;
} dem_detect_opts_t;

/* Counters of one detection run, for the cost line. */
typedef struct dem_detect_stats {
	size_t checks;            /* box/box overlap tests performed */
	size_t cells[DEM_MAXDIM]; /* cells per axis (cell methods) */
	double cell[DEM_MAXDIM];  /* cell size used per axis (cell methods) */
	size_t ghosts;            /* periodic images added */
} dem_detect_stats_t;

/* Defaults: D-cell, Ch. 2.5 cell rule, no periodic axes, no workspace. */
void dem_detect_opts_init(dem_detect_opts_t *o);

/* A new, empty workspace (NULL without memory); it grows to what the
 * largest detection run with it needed and keeps that until freed.
 * dem_detect_ws_free(NULL) does nothing. */
dem_detect_ws_t *dem_detect_ws_new(void);
void dem_detect_ws_free(dem_detect_ws_t *ws);

/* For the algorithms: buffer number slot (< DEM_DETECT_WS_SLOTS) of the
 * workspace, at least bytes long; its contents are undefined (a buffer
 * that has to grow is replaced, not copied).  NULL without memory. */
#define DEM_DETECT_WS_SLOTS 8
void *dem_detect_ws_get(dem_detect_ws_t *ws, int slot, size_t bytes);

/* Name <-> algorithm ("dcell", "nbs", "scell", "adt", "asdt", "brute").
 * dem_detect_algo_parse returns -1 for an unknown name. */
const char *dem_detect_algo_name(dem_detect_algo_t a);
int dem_detect_algo_parse(const char *name);

/* Find every overlapping pair of b and append it to out (which is not
 * cleared).  Returns DEM_OK, or an error code with e filled: DEM_EINPUT for a
 * box set the options cannot handle (NBS in 3D, a box longer than half a
 * period, more than 2^32-1 boxes), DEM_EIO when memory runs out.  stats may
 * be NULL. */
/* stats (reset first) receives the counters of this call. */
int dem_detect(const dem_boxes_t *b, const dem_detect_opts_t *o,
	       dem_pairs_t *out, dem_detect_stats_t *stats, dem_error_t *e);

/* The algorithms themselves, without periodic images; each appends the
 * pairs of b to out.  cell[] is the resolved cell size per axis (ignored by
 * the tree and brute-force methods).  They return DEM_OK, or DEM_EIO when
 * memory runs out (out->nomem may also be set). */
int dem_detect_dcell(const dem_boxes_t *b, const double *cell,
		     dem_pairs_t *out, dem_detect_stats_t *st);
/* The same with a workspace (NULL: a temporary one). */
int dem_detect_dcell_ws(const dem_boxes_t *b, const double *cell,
			dem_detect_ws_t *ws, dem_pairs_t *out,
			dem_detect_stats_t *st);
int dem_detect_nbs(const dem_boxes_t *b, const double *cell,
		   dem_pairs_t *out, dem_detect_stats_t *st);
int dem_detect_scell(const dem_boxes_t *b, const double *cell,
		     dem_pairs_t *out, dem_detect_stats_t *st);
int dem_detect_adt(const dem_boxes_t *b, dem_pairs_t *out,
		   dem_detect_stats_t *st);
int dem_detect_asdt(const dem_boxes_t *b, dem_pairs_t *out,
		    dem_detect_stats_t *st);
int dem_detect_brute(const dem_boxes_t *b, dem_pairs_t *out,
		     dem_detect_stats_t *st);

/* Boxes: allocate arrays for n boxes of dimension dim (one block), free. */
int dem_boxes_alloc(dem_boxes_t *b, int dim, size_t n);
void dem_boxes_free(dem_boxes_t *b);

/* Closed-box overlap test of boxes i and j. */
static inline int dem_boxes_overlap(const dem_boxes_t *b, size_t i, size_t j)
{
	for (int d = 0; d < b->dim; d++)
		if (b->lo[d][i] > b->hi[d][j] || b->lo[d][j] > b->hi[d][i])
			return 0;
	return 1;
}

/* Pairs. */
void dem_pairs_init(dem_pairs_t *p);
void dem_pairs_free(dem_pairs_t *p);
int dem_pairs_grow(dem_pairs_t *p);     /* slow path of dem_pairs_push */
/* Append (i, j), stored as (min, max). */
static inline void dem_pairs_push(dem_pairs_t *p, uint32_t i, uint32_t j)
{
	if (p->n == p->cap && dem_pairs_grow(p) != 0)
		return;
	dem_pair_t *q = &p->p[p->n++];
	q->i = i < j ? i : j;
	q->j = i < j ? j : i;
}
/* Sort into (i, j) order (radix sort, O(n)); returns DEM_EIO without memory. */
int dem_pairs_sort(dem_pairs_t *p);

#endif
