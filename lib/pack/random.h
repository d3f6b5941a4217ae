/* random.h - random test sets of Ch. 2.5: N disks or spheres placed
 * uniformly at random in a box sized so that the packing density (sum of
 * object areas or volumes over the domain) is the target; overlaps allowed. */
#ifndef DEM_PACK_RANDOM_H
#define DEM_PACK_RANDOM_H

#include <stddef.h>

#include "core/error.h"
#include "core/radius.h"

typedef struct dem_random_spec {
	int dim;                        /* 2 or 3 */
	size_t n;
	double density;                 /* (0, 1]: object volume over domain volume */
	dem_radius_law_t law;
	double aspect[3];               /* domain side ratios (scaled to the volume) */
} dem_random_spec_t;

/* Called for each object: centre x[dim], radius r.  Nonzero stops the
 * generation and is returned. */
typedef int (*dem_random_emit_fn)(void *ctx, const double *x, double r);

/* The domain [0, hi] that gives the exact target density for the radii this
 * seed draws (the first pass over the radii). */
int dem_pack_random_domain(const dem_random_spec_t *s, unsigned long seed,
			   double *hi, dem_error_t *e);

/* Emit the objects in the domain [0, hi]: the same radii again (drawn from
 * the same seed), with uniform positions.  Memory is O(1) whatever N. */
int dem_pack_random(const dem_random_spec_t *s, unsigned long seed,
		    const double *hi, dem_random_emit_fn emit, void *ctx,
		    dem_error_t *e);

#endif
