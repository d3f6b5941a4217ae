/* boxes.h - the types the contact detectors share: boxes, pair lists,
 * workspaces and counters.
 *
 * The front end (detect.h) and every algorithm (algo.h) build on this
 * header; neither includes the other's, so the detection folder has no
 * loop: boxes.c below, the algorithms on it, detect.c on top.
 */
#ifndef DEM_DETECT_BOXES_H
#define DEM_DETECT_BOXES_H

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

/* A workspace: the buffers of a detection kept from one call to the next,
 * so a time loop that detects every step neither allocates nor touches
 * fresh pages after the first step (STYLE.md 10).  Opaque; one workspace
 * serves one detection at a time. */
typedef struct dem_detect_ws dem_detect_ws_t;

/* Counters of one detection run, for the cost line. */
typedef struct dem_detect_stats {
	size_t checks;            /* box/box overlap tests performed */
	size_t cells[DEM_MAXDIM]; /* cells per axis (cell methods) */
	double cell[DEM_MAXDIM];  /* cell size used per axis (cell methods) */
	size_t ghosts;            /* periodic images added */
} dem_detect_stats_t;

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
