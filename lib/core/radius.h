/* radius.h - the radius laws of Ch. 2.5 between Rmin and Rmax = lambda Rmin:
 *   mono  every radius Rmin;
 *   urd   uniform on [Rmin, Rmax];
 *   nrd   normal, mean (Rmin+Rmax)/2, sd (Rmax-Rmin)/6, truncated to
 *         [Rmin, Rmax] (the thesis's sigma = (R - Rmin)/3);
 *   lnrd  log-normal: ln R normal with mean (ln Rmin + ln Rmax)/2 and sd
 *         (ln Rmax - ln Rmin)/6, truncated to [Rmin, Rmax] (the thesis
 *         names the law without its parameters; this is the NRD rule in
 *         ln R). */
#ifndef DEM_CORE_RADIUS_H
#define DEM_CORE_RADIUS_H

#include <gsl/gsl_rng.h>

typedef enum dem_radius_kind {
	DEM_RADIUS_MONO, DEM_RADIUS_URD, DEM_RADIUS_NRD, DEM_RADIUS_LNRD
} dem_radius_kind_t;

typedef struct dem_radius_law {
	dem_radius_kind_t kind;
	double rmin, rmax;
} dem_radius_law_t;

/* NULL-terminated names in enum order: "mono", "urd", "nrd", "lnrd". */
extern const char *const dem_radius_names[];

double dem_radius_draw(const dem_radius_law_t *law, gsl_rng *r);

#endif
