/* profile.h - the profile stream: residual fields against depth (Ch. 8.4).
 *
 * demprofile writes it, demform reads it.  One stream holds the profiles
 * of one or more passes; kind "profile", version 1; columns
 *
 *   pass:u32  depth:f64:m
 *   sxx syy szz sxy syz szx:f64:Pa        mean stress
 *   exx eyy ezz exy eyz ezx:f64           mean total strain (engineering shears)
 *   ep:f64                                mean effective plastic strain
 *   sd_sxx ... sd_ezx sd_ep:f64           their standard deviations (same units)
 *   n:u32                                 samples averaged
 *
 * Rows are grouped by pass (increasing), depth increasing within a pass;
 * depth is measured from the peened surface of the undeformed block into
 * the material (>= 0).  See dem-streams(5).
 */
#ifndef DEM_IO_PROFILE_H
#define DEM_IO_PROFILE_H

#include <stddef.h>

#include "core/error.h"
#include "io/stream.h"
#include "mesh/mesh.h"

/* One pass's profile, in SI units. */
typedef struct dem_profile {
	int pass;
	size_t n;         /* depth points */
	double *depth;    /* n, strictly increasing, >= 0 */
	double *sig;      /* 6 per point */
	double *eps;      /* 6 per point */
	double *ep;       /* 1 per point */
	double *sd;       /* 13 per point: sd of sig (6), eps (6), ep */
	unsigned *count;  /* samples per point */
	int plane;        /* 1: of a 2D plane-strain block (the stream's "# twod
			   * mode=plane" line, which demprofile passes on from
			   * demshot's state stream): syy is the stress of the
			   * constraint eps_yy = 0, not a stress of its own */
} dem_profile_t;

/* Read the profile of the given pass (pass < 0: the last one in the
 * stream) from path ("-" or NULL: stdin; gzip read transparently).  Errors
 * name the stream and row: DEM_EINPUT for a bad stream or a missing pass,
 * DEM_EIO for an unreadable file. */
int dem_profile_read(const char *path, int pass, dem_profile_t *p,
		     dem_error_t *e);

/* Every pass of the stream: *np profiles in *ps (free each, then free(*ps)). */
int dem_profile_read_all(const char *path, dem_profile_t **ps, int *np,
			 dem_error_t *e);

void dem_profile_free(dem_profile_t *p);

/* Fields at a depth by linear interpolation between the points; above the
 * first point the first point's values, below the last the last's.  Any
 * output pointer may be NULL. */
void dem_profile_eval(const dem_profile_t *p, double depth, double sig[6],
		      double eps[6], double *ep);

/* ---- writing (demprofile) ------------------------------------------------ */

/* Initialise h as a profile stream's header: kind, version and the columns
 * above, in that order.  The caller adds its metadata lines, opens a
 * dem_writer on it, writes each pass with dem_profile_write (passes
 * increasing) and closes the writer. */
void dem_profile_header(dem_header_t *h);
/* Room for n depth points (zeroed), pass 0; DEM_EIO without memory. */
int dem_profile_alloc(dem_profile_t *p, size_t n, dem_error_t *e);
/* Write p's rows (one per depth point).  Refuses (DEM_EINPUT) depths not
 * strictly increasing or negative, and values that are not finite. */
int dem_profile_write(dem_writer_t *w, const dem_profile_t *p, dem_error_t *e);

/* ---- profiles and surface metrics of a state frame (demprofile) --------- */

/* What to average and how.  The region is a rectangle of the x-y plane; an
 * element is in it when its centroid (reference coordinates) is, bounds
 * included.  Depth is measured from the top face of the block (its highest
 * reference z) down. */
typedef struct dem_profile_opts {
	double lo[2], hi[2];    /* the region */
	double bin;             /* > 0: depth bins [k bin, (k+1) bin); 0: element layers */
	double threshold;       /* surface: indentation (m) that counts as dimpled */
	double ep_threshold;    /* surface: effective plastic strain that counts
				 * as covered (the plastic share) */
	int axisym;             /* an axisymmetric block (demshot's "# twod
				 * mode=axisym"): x is the radius r, each
				 * element and face stands for the ring it
				 * sweeps about the axis x = 0, and every
				 * average weights it by that ring */
} dem_profile_opts_t;

/* One frame's profile: for each element layer (structured mesh only) or
 * depth bin holding at least one element of the region, the volume-
 * weighted mean and standard deviation of the 13 fields over those
 * elements, and their number.  In axisymmetry (o->axisym) an element's
 * volume is that of its ring, 2 pi r_c A for its section A and centroid
 * radius |r_c| (Pappus): for the rectangles of a grid, the exact integral
 * of 2 pi r over the section, so a field held constant on each element is
 * averaged exactly over the solid of revolution.  A layer's depth is its centroid's; a bin's
 * is the volume-weighted mean depth of its elements' centroids.  When the
 * elements of a point all hold the same value the mean is that value
 * exactly and the spread 0.  p is allocated here (dem_profile_free);
 * p->pass is 0.  DEM_EINPUT when no element is in the region, or for
 * layers without a grid. */
int dem_profile_compute(const dem_mesh_t *m, const double *sig,
			const double *eps, const double *ep,
			const dem_profile_opts_t *o, dem_profile_t *p,
			dem_error_t *e);

/* Surface metrics of a frame, over the top faces of the region's top-layer
 * elements (structured mesh only).  The indentation of a top node is -uz;
 * each node stands for a quarter of each region face around it (the
 * trapezoidal rule).  The plastic share counts each top face whole, by its
 * element's effective plastic strain ep (ep NULL: 0).
 *
 * In axisymmetry (o->axisym) a top face [r0, r1] stands for its ring,
 * pi |r1^2 - r0^2| (shared among the faces of its grid row in y by their
 * widths); each of its nodes for the integral of its linear shape function
 * over the ring, the nodes at r0 (2 r0 + r1) / (3 (r0 + r1)) of it and
 * those at r1 (r0 + 2 r1) / (3 (r0 + r1)), half each to the two nodes of
 * one radius.  A patch is cut (not a whole dimple) only where it reaches
 * the region's edge in r away from the axis: the y sides of the layer and
 * the axis are no edges. */
typedef struct dem_surface {
	double area;            /* top area of the region, m^2 */
	double indented;        /* share of it indented deeper than the threshold */
	double plastic;         /* share of it on top-layer elements whose ep
				 * exceeds ep_threshold: the FE counterpart of a
				 * dimpled area (coverage) */
	double depth_max;       /* deepest indentation, m (0 if none) */
	double depth_mean;      /* mean of the whole dimples' deepest points, m */
	double radius;          /* mean of their equivalent radii sqrt(A / pi), m */
	double ra;              /* roughness Ra: mean |uz - mean uz|, m */
	size_t dimples;         /* whole dimples: patches of indented nodes (joined
				 * along grid lines) that do not reach the region's edge */
	size_t patches;         /* every indented patch, cut ones included */
} dem_surface_t;

int dem_surface_compute(const dem_mesh_t *m, const double *u, const double *ep,
			const dem_profile_opts_t *o, dem_surface_t *s,
			dem_error_t *e);

#endif
