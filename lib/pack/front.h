/* front.h - dense random packing of disks by an advancing front (Han 2004,
 * Ch. 5.2), in a rectangle.
 *
 * Every new disk touches the two disks (or walls) of the current active
 * segment of the front, so each placement is locally as dense as it can be
 * (Fig. 5.5).  Two forms:
 *
 *   closed  the front starts as three touching disks at the centre of the
 *           domain and grows outwards in every direction (Ch. 5.2.1); at
 *           the end the disks not wholly inside the rectangle are culled.
 *           Equal disks give the hexagonal lattice.
 *   open    the walls are disks of infinite radius; the front is an open
 *           list from the left wall to the right wall and the disks are
 *           laid in layers from the bottom (Ch. 5.2.2), the top being an
 *           open lid; the disks crossing the lid are culled.  Optionally
 *           each disk must rest stably under gravity (Ch. 5.2.3, Fig. 5.9);
 *           a disk whose support is culled is culled too, so every disk
 *           emitted rests on emitted disks or walls.
 *
 * Guarantees: no two disks emitted overlap by more than 1e-10 of the
 * smaller radius, and every disk emitted lies inside the rectangle (to the
 * same relative tolerance).  Overlap checks go through a uniform grid of
 * cells as wide as the largest disk, so the cost is O(N) for N disks; the
 * forward/backward front check can be limited to k segments (Ch. 5.2.4).
 * Memory is O(N): all disks are kept until the culling at the end.
 *
 * The walls are held as lines (a point and an inward normal), and a disk
 * touching a wall is found as a disk touching a line, so a polygonal
 * boundary can later enter as more walls.
 */
#ifndef DEM_PACK_FRONT_H
#define DEM_PACK_FRONT_H

#include <stddef.h>

#include <gsl/gsl_rng.h>

#include "core/error.h"
#include "core/radius.h"

typedef enum dem_front_form {
	DEM_FRONT_CLOSED, DEM_FRONT_OPEN
} dem_front_form_t;

/* NULL-terminated names in enum order: "closed", "open". */
extern const char *const dem_front_form_names[];

typedef struct dem_front_spec {
	dem_front_form_t form;
	double lo[2], hi[2];    /* the rectangle [lo0, hi0] x [lo1, hi1] */
	dem_radius_law_t law;   /* radii drawn in turn, each kept until placed */
	int check_limit;        /* 0: no limit; k > 0: the forward and the
				 * backward front check look at most k disks
				 * each way (Ch. 5.2.4) */
	int gravity;            /* open form only: the Fig. 5.9 stability rule,
				 * gravity along -y */
} dem_front_spec_t;

typedef struct dem_front_stats {
	size_t placed;          /* disks generated, before culling */
	size_t kept;            /* disks wholly inside the rectangle (emitted) */
	double area;            /* total area of the kept disks */
	double density;         /* area over the rectangle's area */
	size_t attempts;        /* candidate positions computed */
	size_t cases[3];        /* intermediate segments, Fig. 5.5 (b), (c), (d) */
	size_t failed;          /* segments given up: the candidate overlaps a
				 * disk the front check cannot place (behind
				 * the front, or beyond the check limit), or
				 * no disk fits the gap; under gravity given
				 * up for the current radius only */
	size_t unstable;        /* candidates refused by the gravity rule */
	size_t dropped;         /* radii that no segment could seat stably;
				 * 16 in a row end the packing */
	size_t front_max;       /* the largest front, in disks and walls */
} dem_front_stats_t;

/* Called for each kept disk in the order of generation: centre x[2],
 * radius r.  Nonzero stops the emission and is returned. */
typedef int (*dem_front_emit_fn)(void *ctx, const double *x, double r);

/* Pack the rectangle of s, drawing radii from rng, then emit the kept
 * disks.  st (may be NULL) is complete before the first call of emit, so a
 * writer can put the density in its header.  Returns DEM_OK; DEM_EINPUT
 * for a bad spec (empty rectangle, radii not 0 < rmin <= rmax, gravity
 * with the closed form, a negative check limit); DEM_EIO when memory runs
 * out or the rectangle holds too many disks (more than 2^31 - 1); or
 * emit's nonzero value. */
int dem_pack_front(const dem_front_spec_t *s, gsl_rng *rng,
		   dem_front_emit_fn emit, void *ctx, dem_front_stats_t *st,
		   dem_error_t *e);

#endif
