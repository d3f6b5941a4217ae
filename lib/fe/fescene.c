/* fescene.c - the material section of a scene (see fescene.h). */
#include "fe/fescene.h"

#include <math.h>
#include <stdlib.h>

/* The hardening table: two sequences of one length. */
static int read_table(dem_scene_t *s, dem_mat_param_t *p, double **ep,
		      double **sy, dem_error_t *e)
{
	int n = dem_scene_length(s, "material.table.strain");
	int ns = dem_scene_length(s, "material.table.stress");

	if (n < 1)
		return dem_scene_error(s, "material.table.strain", e,
				       "expected a list of effective plastic "
				       "strains");
	if (ns != n)
		return dem_scene_error(s, "material.table.stress", e,
				       "expected a list of %d flow stresses, "
				       "one per strain", n);
	*ep = malloc((size_t)n * sizeof **ep);
	*sy = malloc((size_t)n * sizeof **sy);
	if (!*ep || !*sy)
		return dem_error_nomem(e, "material table");
	if (dem_scene_vector(s, "material.table.strain", DEM_DIM_NONE, n, NULL,
			     0, HUGE_VAL, *ep, e) ||
	    dem_scene_vector(s, "material.table.stress", DEM_DIM_PRESSURE, n,
			     NULL, DEM_SCENE_GT0, HUGE_VAL, *sy, e))
		return e->code;
	p->nhard = n;
	p->hard_ep = *ep;
	p->hard_sy = *sy;
	return DEM_OK;
}

int dem_scene_material(dem_scene_t *s, int need_rho, dem_mat_t *m,
		       dem_error_t *e)
{
	dem_mat_param_t p = {0};
	double *ep = NULL, *sy = NULL;
	int rc;

	p.E = p.nu = p.rho = p.rate_m = NAN;
	if ((rc = dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE, NAN,
				     DEM_SCENE_GT0, HUGE_VAL, &p.E, e)) ||
	    (rc = dem_scene_quantity(s, "material.nu", DEM_DIM_NONE, NAN,
				     -1, 0.5, &p.nu, e)) ||
	    (rc = dem_scene_quantity(s, "material.rho", DEM_DIM_DENSITY,
				     need_rho ? NAN : 0, need_rho ? DEM_SCENE_GT0 : 0,
				     HUGE_VAL, &p.rho, e)))
		return rc;
	if (isnan(p.E))
		return dem_scene_error(s, "material.E", e, "missing: the "
				       "material needs Young's modulus");
	if (isnan(p.nu))
		return dem_scene_error(s, "material.nu", e, "missing: the "
				       "material needs Poisson's ratio");
	if (isnan(p.rho))
		return dem_scene_error(s, "material.rho", e, "missing: the "
				       "explicit stage needs the density");
	if (dem_scene_has(s, "material.table")) {
		if (dem_scene_has(s, "material.yield") ||
		    dem_scene_has(s, "material.hardening")) {
			rc = dem_scene_error(s, "material.table", e, "give either "
					     "a hardening table or yield and "
					     "hardening, not both");
			goto out;
		}
		if ((rc = read_table(s, &p, &ep, &sy, e)))
			goto out;
	} else {
		p.sy0 = NAN;
		if ((rc = dem_scene_quantity(s, "material.yield", DEM_DIM_PRESSURE,
					     NAN, DEM_SCENE_GT0, HUGE_VAL, &p.sy0,
					     e)))
			goto out;
		if (isnan(p.sy0)) {
			p.sy0 = 0;  /* elastic */
			if (dem_scene_has(s, "material.hardening")) {
				rc = dem_scene_error(s, "material.hardening", e,
						     "hardening without a "
						     "yield stress");
				goto out;
			}
		} else if ((rc = dem_scene_quantity(s, "material.hardening",
						    DEM_DIM_PRESSURE, 0, 0,
						    HUGE_VAL, &p.H, e)))
			goto out;
	}
	if ((rc = dem_scene_quantity(s, "material.rate_exponent", DEM_DIM_NONE,
				     NAN, DEM_SCENE_GT0, 1, &p.rate_m, e)))
		goto out;
	if (isnan(p.rate_m)) {
		p.rate_m = 0;
	} else {
		if (p.sy0 == 0 && p.nhard == 0) {
			rc = dem_scene_error(s, "material.rate_exponent", e,
					     "rate dependence needs a yield "
					     "stress or a hardening table");
			goto out;
		}
		if ((rc = dem_scene_quantity(s, "material.rate_ref", DEM_DIM_RATE,
					     1, DEM_SCENE_GT0, HUGE_VAL,
					     &p.rate_ref, e)))
			goto out;
	}
	rc = dem_mat_init(m, &p, e);
out:
	free(ep);
	free(sy);
	return rc;
}
