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

#include "core/error.h"
#include "detect/algo.h"
#include "detect/boxes.h"

typedef enum dem_detect_algo {
	DEM_DETECT_DCELL,         /* dynamic cell, Ch. 2.4.3, Box 2.1 (default) */
	DEM_DETECT_NBS,           /* no binary search, Ch. 2.4.2 (2D only) */
	DEM_DETECT_SCELL,         /* static cell, Ch. 2.4.1 */
	DEM_DETECT_ADT,           /* alternating digital tree, Ch. 2.3.2 */
	DEM_DETECT_ASDT,          /* augmented spatial digital tree, Ch. 2.3.3 */
	DEM_DETECT_BRUTE          /* all N(N-1)/2 pairs */
} dem_detect_algo_t;

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

/* Defaults: D-cell, Ch. 2.5 cell rule, no periodic axes, no workspace. */
void dem_detect_opts_init(dem_detect_opts_t *o);

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

#endif
