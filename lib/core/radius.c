#include "core/radius.h"

#include <gsl/gsl_randist.h>
#include <math.h>

const char *const dem_radius_names[] = {"mono", "urd", "nrd", "lnrd", NULL};

/* Truncation by rejection: +-3 sd covers 99.7 %, so few draws are lost. */
double dem_radius_draw(const dem_radius_law_t *law, gsl_rng *r)
{
	double a = law->rmin, b = law->rmax, x;

	if (!(b > a))
		return a;
	switch (law->kind) {
	case DEM_RADIUS_URD:
		return a + (b - a) * gsl_rng_uniform(r);
	case DEM_RADIUS_NRD:
		do
			x = 0.5 * (a + b) + gsl_ran_gaussian_ziggurat(r, (b - a) / 6);
		while (x < a || x > b);
		return x;
	case DEM_RADIUS_LNRD: {
		double la = log(a), lb = log(b);
		do
			x = exp(0.5 * (la + lb) + gsl_ran_gaussian_ziggurat(r, (lb - la) / 6));
		while (x < a || x > b);
		return x;
	}
	default:
		return a;
	}
}
