/* compress.h - random sphere packing by geometric compression (Ch. 6).
 *
 * No forces: spheres are moved, one at a time and with their neighbours held
 * still, along a direction until they touch a neighbour or a wall (Eqs.
 * 6.1-6.4).  The whole method (Box 6.4) is
 *
 *   initial loose packing: random non-overlapping insertion (Fig. 6.3a);
 *   DO {
 *     global compression along -z until the potential energy settles
 *       (Box 6.1, Eqs. 6.5-6.8);
 *     DO { N_s shakes (moves normal to -z); random compression with a
 *          cone of directions (Eq. 6.9) } while the energy still falls
 *       (Box 6.2);
 *     relaxation under gravity (beyond the thesis, on unless relax = 0):
 *       the spheres above a frozen depth settle as frictionless soft
 *       spheres, overlap springs plus Eq. 6.7 minimised by FIRE (Bitzek
 *       et al. 2006); the weight is taken off, FIRE and projection
 *       sweeps remove every overlap (the packing expands upwards), and
 *       Box 6.1 closes the gaps; the result is kept only if Eq. 6.7 fell;
 *   } while a new batch dropped from the lid (Box 6.3) added spheres.
 *
 * The thesis's stages move each sphere to its first contact with the others
 * held still, which leaves arches (the thesis reached 0.5289 in the Ch. 6.3
 * cylinder, this code 0.505); frictionless spheres settled together slide
 * past one another and reach random close packing (Silbert et al. 2002,
 * Phys. Rev. E 65, 031304): 0.62 in that cylinder.
 *
 * Neighbours come from the library's contact detection (D-cell) over the
 * spheres' boxes extended by a buffer zone along each sphere's own moving
 * direction (Ch. 6.2.3); the buffer adapts to the distance a sphere last
 * moved.  Spheres are processed bottom-up, and in global compression a
 * sphere is skipped while neither it nor a neighbour moves (mobility).
 *
 * The domain is the box [lo, hi], optionally cut by a circular cylinder with
 * its axis along z (an exact curved wall) and by half-spaces n.x >= d with
 * unit inward normals n (a convex polyhedron; [lo, hi] is then its bounding
 * box).  Compression is along -z; the lid is the face z = hi[2].
 *
 * Invariant after every stage: no two spheres overlap and none crosses a
 * wall (up to rounding and the relaxation's accepted 1e-10 of the smaller
 * radius; the contract is 1e-9).
 */
#ifndef DEM_PACK_COMPRESS_H
#define DEM_PACK_COMPRESS_H

#include <stddef.h>

#include <gsl/gsl_rng.h>

#include "core/error.h"
#include "core/radius.h"

/* The half-space n.x >= d, n a unit inward normal. */
typedef struct dem_plane {
	double n[3];
	double d;
} dem_plane_t;

typedef struct dem_domain {
	double lo[3], hi[3];      /* box walls; hi[2] is the lid */
	int cylinder;             /* nonzero: also inside the cylinder below */
	double axis[2], radius;   /* cylinder axis (x, y) and radius */
	size_t nplane;            /* extra half-spaces (owned by the caller) */
	const dem_plane_t *plane;
	double volume;            /* 0: computed (exact for box and cylinder,
				     a 200^3 midpoint estimate with planes) */
} dem_domain_t;

/* A box; a cylinder of radius R on axis (cx, cy) from z0 to z1. */
void dem_domain_box(dem_domain_t *d, const double lo[3], const double hi[3]);
void dem_domain_cylinder(dem_domain_t *d, double cx, double cy, double R,
			 double z0, double z1);

/* Phases reported after each stage. */
typedef enum dem_compress_phase {
	DEM_COMPRESS_INIT,        /* loose initial packing placed */
	DEM_COMPRESS_GLOBAL,      /* global compression converged (Box 6.1) */
	DEM_COMPRESS_SHAKE,       /* shaking + random compression (Box 6.2) */
	DEM_COMPRESS_RELAX,       /* relaxation under gravity, then Box 6.1 */
	DEM_COMPRESS_REFILL       /* a batch dropped from the lid (Box 6.3) */
} dem_compress_phase_t;

extern const char *const dem_compress_phase_names[];

/* One stage: counters and a read-only view of the packing. */
typedef struct dem_compress_stage {
	dem_compress_phase_t phase;
	int batch;                /* 0 for the initial packing */
	size_t n;                 /* spheres now */
	size_t added;             /* spheres added by this stage */
	int iters;                /* compression iterations of this stage */
	double density;           /* sphere volume / domain volume */
	double pe;                /* Eq. 6.7, heights from the floor z = lo[2] */
	double seconds;           /* since the start */
	const double *x[3], *r;   /* centres and radii, n each */
} dem_compress_stage_t;

/* Nonzero stops the packing and is returned. */
typedef int (*dem_compress_stage_fn)(void *ctx, const dem_compress_stage_t *s);

typedef struct dem_compress_spec {
	dem_domain_t dom;
	dem_radius_law_t law;
	double init_density;      /* fill fraction of the loose start (0.3) */
	size_t max_n;             /* stop adding at this count (0: no limit) */
	double tol;               /* tau of Eq. 6.8 (1e-4) */
	int nshake;               /* N_s of Box 6.2 (5) */
	double beta;              /* beta-bar of Eq. 6.9, cone size (0.5) */
	int max_iter;             /* iterations per compression phase (200) */
	int max_loops;            /* rounds of the Box 6.2 loop (20) */
	int max_batches;          /* refill batches, Box 6.4 (100) */
	size_t max_reject;        /* M_r of Box 6.3 (0: lid area / (4 Rmean^2)) */
	double buffer;            /* largest buffer zone, in Rmax (1) */
	int nroll;                /* cone moves of a dropped sphere (20) */
	int relax;                /* nonzero: relax after each Box 6.2 (1) */
	double relax_overlap;     /* deepest overlap under the weight, in Rmin (0.01) */
	double relax_ftol;        /* settled: mean fall per 100 steps, in Rmin (1e-3) */
	int relax_iter;           /* FIRE steps per stage at most (20000) */
	double relax_dt;          /* largest FIRE step, in sqrt(m/k) of Rmin (0.2) */
	double relax_skin;        /* Verlet skin, in Rmin (1) */
	double relax_batch;       /* relax after a refill adding this share of
				     the spheres at least (0.01) */
	double relax_depth;       /* after a refill relax down to this many
				     diameters below the new spheres (5) */
	dem_compress_stage_fn stage;  /* may be NULL */
	void *stage_ctx;
} dem_compress_spec_t;

/* Called for each sphere at the end: centre x[3], radius r.  Nonzero stops
 * and is returned. */
typedef int (*dem_compress_emit_fn)(void *ctx, const double *x, double r);

typedef struct dem_compress_stats {
	size_t n;
	double density, pe, seconds;  /* density: sphere volume / domain volume */
	double ztop;              /* top of the highest sphere */
	double density_top;       /* over the domain below ztop (sampled) */
	double density_core;      /* over the domain one largest diameter
				     from every wall and below ztop (sampled) */
	int batches;              /* refill batches that added spheres */
	size_t iters;             /* compression iterations, all phases */
	size_t steps;             /* relaxation (FIRE) steps */
	size_t removed;           /* spheres taken out by the last resort of the
				     relaxation (rare; wedge corners) */
	size_t detections, pairs; /* detection runs, neighbour pairs found */
} dem_compress_stats_t;

/* Defaults as noted above; dom and law are left for the caller. */
void dem_compress_spec_init(dem_compress_spec_t *s);

/* Fill s->dom with spheres of radii from s->law using r (positions, radii,
 * directions all from r), then emit them (emit may be NULL).  stats may be
 * NULL; it is complete before the first emit.  Returns DEM_OK, DEM_EINPUT for a bad spec, DEM_EIO without memory,
 * or a nonzero value from a callback. */
int dem_pack_compress(const dem_compress_spec_t *s, gsl_rng *r,
		      dem_compress_emit_fn emit, void *ctx,
		      dem_compress_stats_t *stats, dem_error_t *e);

#endif
