/* front.h - dense random packing of disks by an advancing front (Han 2004,
 * Ch. 5.2), in a rectangle or (open form) any simple polygon.
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
 * smaller radius plus the rounding of their coordinates (64 ulps of their
 * magnitude, 64 DBL_EPSILON max(|x|, |y|): negligible near the origin,
 * the larger term some 10^6 radii from it), and every disk emitted lies
 * inside the rectangle (to 1e-10 of its radius and the same rounding).
 * So a packing of a domain moved far from the origin is the packing of
 * the domain at the origin, moved.  Overlap checks go through a uniform grid of
 * cells as wide as the largest disk, so the cost is O(N) for N disks; the
 * forward/backward front check can be limited to k segments (Ch. 5.2.4).
 * Memory is O(N): all disks are kept until the culling at the end.
 *
 * The walls are held as lines (a point and an inward normal), and a disk
 * touching a wall is found as a disk touching a line.
 *
 * Polygons and ellipses (Ch. 5.3-5.4): the same front, forms, domains and
 * gravity rule (a body's support on a wall is where it touches it, its
 * support point towards the wall, on a body the contact of the tangent
 * solve) with convex bodies placed by translation only, each drawn
 * with a size r (the radius law), an aspect ratio alpha >= 1 (a law of
 * the same kinds) and a uniform random rotation theta, with semi-axes
 * a = r sqrt(alpha), b = r / sqrt(alpha) (so a b = r^2):
 *   polygon  the m-gon with its points on the ellipse (a, b), a side flat
 *            at the bottom before the rotation: the regular polygon of
 *            circumradius r stretched (the body stream's shape 1);
 *   ellipse  the ellipse (a, b) (the body stream's shape 0 with m = 2).
 * A new body touching two front objects is where its loci round them
 * cross (lib/pack/locus.h): for polygons the Minkowski sums, exactly; for
 * ellipses the tangent-line polygons that bound the loci from outside
 * (16, 64 and 256 sides, the hierarchy), whose crossing starts Newton's
 * method on the curves.  Newton's root is taken when it converges within
 * the body's bounding radius of the start and nearer to it than to any
 * other crossing of the bounds; otherwise the next level is tried, and
 * after the last the crossing of the outer bounds itself is taken (a
 * fall-back: the body then touches neither exactly but overlaps neither,
 * as the bounds lie outside the loci).  Overlap: polygons by the depth of
 * the centre in the Minkowski sum (the tolerance t: 1e-10 of the smaller
 * size and the rounding of the coordinates, as for disks), ellipses by
 * the Perram-Wertheim function (overlap when below (1 - t / size)^2),
 * each after the bounding circles.
 *
 * Polygons (open form, Ch. 5.2.4, Figs. 5.12-5.13): every edge is a wall,
 * checked as a segment; the front starts as the chain of edges from the
 * one after the lid (the edge whose midpoint is highest) round to the one
 * before it, and the first active segment is the corner at the start of
 * the lowest edge.  A reflex vertex is a disk of radius 0 on the front
 * between its two edges, so a disk can rest against it but never poke
 * through.  A candidate whose centre is outside the polygon is refused,
 * so every disk placed lies wholly inside; the lid is a wall off the
 * front, which the packing fills up to but never touches.
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

typedef enum dem_front_shape {
	DEM_FRONT_DISK, DEM_FRONT_POLYGON, DEM_FRONT_ELLIPSE
} dem_front_shape_t;

/* NULL-terminated names in enum order: "disk", "polygon", "ellipse". */
extern const char *const dem_front_shape_names[];

typedef struct dem_front_spec {
	dem_front_form_t form;
	double lo[2], hi[2];    /* the rectangle [lo0, hi0] x [lo1, hi1] */
	dem_radius_law_t law;   /* radii drawn in turn, each kept until placed */
	int check_limit;        /* 0: no limit; k > 0: the forward and the
				 * backward front check look at most k disks
				 * each way (Ch. 5.2.4) */
	int gravity;            /* open form only: the Fig. 5.9 stability rule,
				 * gravity along -y */
	const double *polygon;  /* open form: npolygon vertices x0 y0 x1 y1 ...
				 * of a simple polygon, either orientation;
				 * NULL: the rectangle lo, hi (then ignored) */
	int npolygon;
	dem_front_shape_t shape;  /* DEM_FRONT_DISK (0) unless set */
	int sides;              /* polygon: 3 to 64 */
	dem_radius_law_t ratio; /* polygon, ellipse: the aspect ratio law,
				 * 1 <= rmin <= rmax; all zero: alpha = 1 */
} dem_front_spec_t;

typedef struct dem_front_stats {
	size_t placed;          /* disks generated, before culling */
	size_t kept;            /* disks wholly inside the rectangle (emitted) */
	double area;            /* total area of the kept disks */
	double density;         /* area over the domain's area */
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
	/* ellipses: the contact position by Newton's method */
	size_t newton;          /* solves started (one per level tried) */
	size_t newton_iters;    /* their steps, converged or not */
	size_t newton_failed;   /* solves refused (not converged, or the
				 * root outside the bounds' neighbourhood) */
	size_t fallbacks;       /* positions taken from the outer bounds
				 * after the last level's solve failed */
	long overlap_evals;     /* Perram-Wertheim evaluations */
} dem_front_stats_t;

/* A body placed (polygon or ellipse): centre, semi-axes, rotation (rad,
 * anticlockwise). */
typedef struct dem_front_body {
	double x[2];
	double a, b, theta;
} dem_front_body_t;

typedef int (*dem_front_body_fn)(void *ctx, const dem_front_body_t *b);

/* Called for each kept disk in the order of generation: centre x[2],
 * radius r.  Nonzero stops the emission and is returned. */
typedef int (*dem_front_emit_fn)(void *ctx, const double *x, double r);

/* Check that the n vertices v (x0 y0 x1 y1 ...) make a simple polygon: at
 * least 3 finite vertices, no edge of zero length, no two edges crossing
 * or touching except neighbours at their shared vertex, non-zero area.
 * Returns DEM_OK or DEM_EINPUT with a message naming the edges. */
int dem_front_polygon_check(const double *v, int n, dem_error_t *e);

/* Pack the rectangle (or polygon) of s, drawing radii from rng, then emit the kept
 * disks.  st (may be NULL) is complete before the first call of emit, so a
 * writer can put the density in its header.  Returns DEM_OK; DEM_EINPUT
 * for a bad spec (empty rectangle, bad polygon, a polygon or gravity
 * with the closed form, radii not 0 < rmin <= rmax, a negative check
 * limit; lengths out of range: semi-axes or coordinates whose squares --
 * ellipses: fourth powers -- would overflow or underflow, with 64 of
 * room, or coordinates so far from the origin that their rounding, 64
 * ulps, exceeds 1e-3 of the smallest semi-axis); DEM_ENUMERIC for a
 * position not finite (which those ranges exclude); DEM_EIO when memory runs
 * out or the rectangle holds too many disks (more than 2^31 - 1); or
 * emit's nonzero value. */
int dem_pack_front(const dem_front_spec_t *s, gsl_rng *rng,
		   dem_front_emit_fn emit, void *ctx, dem_front_stats_t *st,
		   dem_error_t *e);

/* The same for any shape: each kept body to emit (a disk with a = b = r,
 * theta = 0).  DEM_EINPUT also for a polygon of other than 3 to 64 sides
 * or an aspect ratio law not 1 <= rmin <= rmax. */
int dem_pack_front_bodies(const dem_front_spec_t *s, gsl_rng *rng,
			  dem_front_body_fn emit, void *ctx, dem_front_stats_t *st,
			  dem_error_t *e);

#endif
