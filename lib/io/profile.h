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

#endif
