/* algo.h - the contact detection algorithms of Ch. 2, each on its own:
 * what the front end (detect.h) dispatches to.
 */
#ifndef DEM_DETECT_ALGO_H
#define DEM_DETECT_ALGO_H

#include "detect/boxes.h"

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

#endif
