#include "pack/random.h"

#include <math.h>

#include "core/consts.h"
#include "core/rng.h"

static double measure(int dim, double r)
{
	return dim == 2 ? DEM_PI * r * r : dim == 3 ? 4.0 / 3.0 * DEM_PI * r * r * r : 2 * r;
}

int dem_pack_random_domain(const dem_random_spec_t *s, unsigned long seed,
			   double *hi, dem_error_t *e)
{
	gsl_rng *rr = dem_rng_derive(seed, 0);
	double vol = 0, prod = 1;

	if (!rr)
		return dem_error_nomem(e, "random generator");
	for (size_t i = 0; i < s->n; i++)
		vol += measure(s->dim, dem_radius_draw(&s->law, rr));
	gsl_rng_free(rr);
	for (int d = 0; d < s->dim; d++)
		prod *= s->aspect[d];
	double scale = s->n ? pow(vol / s->density / prod, 1.0 / s->dim) : 0;
	for (int d = 0; d < s->dim; d++)
		hi[d] = scale * s->aspect[d];
	return DEM_OK;
}

int dem_pack_random(const dem_random_spec_t *s, unsigned long seed,
		    const double *hi, dem_random_emit_fn emit, void *ctx,
		    dem_error_t *e)
{
	gsl_rng *rr = dem_rng_derive(seed, 0), *rx = dem_rng_derive(seed, 1);
	int rc = DEM_OK;

	if (!rr || !rx) {
		rc = dem_error_nomem(e, "random generator");
	} else {
		for (size_t i = 0; i < s->n && rc == DEM_OK; i++) {
			double x[3], r = dem_radius_draw(&s->law, rr);
			for (int d = 0; d < s->dim; d++)
				x[d] = hi[d] * gsl_rng_uniform(rx);
			rc = emit(ctx, x, r);
		}
	}
	gsl_rng_free(rr);
	gsl_rng_free(rx);
	return rc;
}
