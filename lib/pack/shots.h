/* shots.h - the impacts of a peening job, pass by pass, and their coverage.
 *
 * A shot stream lists, per pass, every shot that strikes the surface z = 0
 * (the block below it): impact point (x, y), radius, velocity vector and
 * start time within the pass.  Every shot of a pass starts together, as the
 * 16 shots of each pass of Ch. 8.6 do, so t is 0 for now.  Two patterns:
 *
 *   grid    n x n shots per pass at the cell centres of the area's n x n
 *           grid, shifted in every pass by an offset inside one cell
 *           (Ch. 8.6, Fig. 8.4: 4 x 4 shots of 1.4 mm, 32 offset passes
 *           over 5.6 x 5.6 mm);
 *   random  per_pass shots per pass, uniform in the area and apart by at
 *           least separation (r_i + r_j), until a requested coverage.
 *
 * Coverage (Ch. 7.1.3) is measured on a raster of the area, periodic, so
 * the area stands for one tile of a larger peened surface and impacts
 * near an edge dimple the opposite edge too.  100 % coverage follows
 * SAE J2277: 98 % of the area dimpled; C % is C/100 times the number of
 * impacts that 100 % needed (the thesis: "multiples of the exposure time").
 *
 * Memory: one pass of shots plus the raster, whatever the number of passes.
 */
#ifndef DEM_PACK_SHOTS_H
#define DEM_PACK_SHOTS_H

#include <stddef.h>

#include "core/error.h"
#include "core/radius.h"

/* SAE J2277: "100 %" coverage is 98 % of the area dimpled. */
#define DEM_COVERAGE_FULL 0.98
/* Raster cells per dimple radius (the cell is at most a / 20). */
#define DEM_COVERAGE_CELLS 20
/* The plastic number, root of g^3 = g + 1 (Roberts 2018, the R2 sequence). */
#define DEM_SHOTS_PLASTIC 1.32471795724474602596

/* ---- coverage raster ---------------------------------------------------- */

typedef struct dem_coverage dem_coverage_t;

/* A periodic raster of the area [lo, hi] (2 values each) whose cells are
 * at most cell wide on each axis.  Refuses more than 2^27 cells (too fine a
 * cell for the area) with DEM_EINPUT. */
int dem_coverage_new(dem_coverage_t **c, const double *lo, const double *hi,
		     double cell, dem_error_t *e);
void dem_coverage_free(dem_coverage_t *c);
/* Forget every impact. */
void dem_coverage_clear(dem_coverage_t *c);
/* Mark the cells whose centre lies within a of (x, y), the area wrapped
 * periodically on both axes. */
void dem_coverage_add(dem_coverage_t *c, double x, double y, double a);
/* The fraction of cells marked so far, in [0, 1]. */
double dem_coverage_fraction(const dem_coverage_t *c);
/* The fraction of the area [lo, hi] within a of one of the n impacts
 * (x[i], y[i]), periodic, on a raster of cell a / DEM_COVERAGE_CELLS. */
int dem_coverage_measure(const double *lo, const double *hi, double a,
			 size_t n, const double *x, const double *y,
			 double *fraction, dem_error_t *e);

/* ---- shot streams -------------------------------------------------------- */

typedef enum dem_shots_pattern {
	DEM_SHOTS_GRID, DEM_SHOTS_RANDOM
} dem_shots_pattern_t;

/* NULL-terminated names in enum order: "grid", "random". */
extern const char *const dem_shots_pattern_names[];

typedef struct dem_shots_spec {
	dem_shots_pattern_t pattern;
	double lo[2], hi[2];            /* the impact area on z = 0 */
	int grid;                       /* grid: n, n x n shots per pass */
	long passes;                    /* grid; random when coverage is 0 */
	double coverage;                /* random: target, percent; 0: passes */
	long per_pass;                  /* random: shots per pass */
	double separation;              /* random: min distance / (r_i + r_j) */
	double dimple_radius;           /* coverage radius a; 0: not measured */
	dem_radius_law_t law;           /* shot radii */
	double speed;                   /* mean speed, m/s */
	double speed_scatter;           /* relative sd, normal cut at 3 sd */
	double angle;                   /* to the surface, rad, (0, pi/2] */
	double azimuth;                 /* of the tangential part, rad */
} dem_shots_spec_t;

typedef struct dem_shot {
	unsigned long pass;             /* from 0 */
	double t;                       /* start time within the pass, s */
	double x[2];                    /* impact point on z = 0 */
	double r;
	double v[3];                    /* velocity; v[2] < 0, towards the block */
} dem_shot_t;

/* What a spec gives for a seed, found by a dry run (nothing emitted). */
typedef struct dem_shots_plan {
	size_t shots;                   /* impacts written */
	size_t passes;                  /* passes begun (the last may be partial) */
	size_t per_pass;                /* shots of a whole pass */
	size_t impacts_100;             /* impacts to 98 % covered; 0 if never */
	double covered;                 /* fraction covered by all; NAN if a = 0 */
} dem_shots_plan_t;

/* Called for each shot in order; nonzero stops and is returned. */
typedef int (*dem_shots_emit_fn)(void *ctx, const dem_shot_t *s);

/* Check the spec (DEM_EINPUT naming what is wrong, e.g. a random pass that
 * cannot hold per_pass shots so far apart) and plan the stream by a dry run
 * (every random pass is drawn, so dem_pack_shots cannot fail on it later):
 * for random with a coverage, impacts_100 by adding impacts until 98 % is
 * covered, then shots = ceil(coverage / 100 impacts_100), the last pass
 * partial; with a dimple radius, the fraction all the shots cover. */
int dem_shots_plan(const dem_shots_spec_t *s, unsigned long seed,
		   dem_shots_plan_t *plan, dem_error_t *e);

/* Emit the plan's shots (the same as the dry run saw, drawn again from the
 * seed): pass by pass, rows of a pass in order. */
int dem_pack_shots(const dem_shots_spec_t *s, unsigned long seed,
		   const dem_shots_plan_t *plan, dem_shots_emit_fn emit,
		   void *ctx, dem_error_t *e);

/* The velocity of a shot of this speed arriving at angle to the surface,
 * its tangential part along azimuth in the surface plane:
 * speed (cos angle cos azimuth, cos angle sin azimuth, -sin angle). */
void dem_shots_velocity(double speed, double angle, double azimuth, double *v);

/* The offset of grid pass p in cell units, each in [-0.5, 0.5): 0 for
 * pass 0, then the R2 sequence frac(0.5 + p alpha) - 0.5 with
 * alpha = (1/g, 1/g^2), g the plastic number (Roberts 2018). */
void dem_shots_grid_offset(unsigned long p, double *o);

#endif
