/* fescene.c - the material section of a scene (see fescene.h). */
#include "fe/fescene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

int dem_scene_block(dem_scene_t *s, dem_mesh_t *m, dem_error_t *e)
{
	static const char *const bcs[] = {"free", "fixed", "normal",
		"periodic", NULL};
	static const char *const face_key[6] = {
		"block.bc.xmin", "block.bc.xmax", "block.bc.ymin",
		"block.bc.ymax", "block.bc.bottom", "block.bc.top"
	};
	static const int face_def[6] = {DEM_BC_NORMAL, DEM_BC_NORMAL,
		DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE};
	double size[3] = {NAN, NAN, NAN}, fine[2], h = NAN, depth, ratio, hmax;
	dem_axis_t ax[3];
	dem_bc_t bc[6];
	int a, f, rc;

	if ((rc = dem_scene_vector(s, "block.size", DEM_DIM_LENGTH, 3, NULL,
				   DEM_SCENE_GT0, HUGE_VAL, size, e)) ||
	    (rc = dem_scene_quantity(s, "block.element", DEM_DIM_LENGTH, NAN,
				     DEM_SCENE_GT0, HUGE_VAL, &h, e)))
		return rc;
	if (isnan(size[0]))
		return dem_scene_error(s, "block.size", e, "missing: the block "
				       "needs its size [x, y, thickness]");
	if (isnan(h))
		return dem_scene_error(s, "block.element", e, "missing: the "
				       "block needs the element size under the "
				       "impact area");
	if ((rc = dem_scene_vector(s, "block.fine", DEM_DIM_LENGTH, 2, size,
				   DEM_SCENE_GT0, HUGE_VAL, fine, e)) ||
	    (rc = dem_scene_quantity(s, "block.fine_depth", DEM_DIM_LENGTH,
				     size[2], DEM_SCENE_GT0, HUGE_VAL, &depth,
				     e)) ||
	    (rc = dem_scene_quantity(s, "block.ratio", DEM_DIM_NONE, 1.2, 1,
				     10, &ratio, e)) ||
	    (rc = dem_scene_quantity(s, "block.max_element", DEM_DIM_LENGTH, 0,
				     0, HUGE_VAL, &hmax, e)))
		return rc;
	for (a = 0; a < 2; a++)
		if (fine[a] > size[a])
			return dem_scene_error(s, "block.fine", e, "the fine "
					       "region (%g m along %c) is larger "
					       "than the block (%g m)", fine[a],
					       "xy"[a], size[a]);
	if (depth > size[2])
		return dem_scene_error(s, "block.fine_depth", e, "%g m is deeper "
				       "than the block (%g m)", depth, size[2]);
	if (hmax != 0 && hmax < h)
		return dem_scene_error(s, "block.max_element", e, "%g m is "
				       "smaller than the element size (%g m)",
				       hmax, h);
	for (a = 0; a < 2; a++)
		ax[a] = (dem_axis_t){-size[a] / 2, size[a] / 2, -fine[a] / 2,
				     fine[a] / 2, h, ratio, hmax};
	ax[2] = (dem_axis_t){-size[2], 0, -depth, 0, h, ratio, hmax};
	for (f = 0; f < 6; f++) {
		int v;

		if ((rc = dem_scene_choice(s, face_key[f], bcs, face_def[f], &v,
					   e)))
			return rc;
		bc[f] = (dem_bc_t)v;
	}
	/* a periodic side needs its partner periodic too; the top and bottom
	 * have none */
	for (f = 0; f < 6; f++) {
		int p = f ^ 1;

		if (bc[f] != DEM_BC_PERIODIC)
			continue;
		if (f >= DEM_ZMIN)
			return dem_scene_error(s, face_key[f], e, "the %s "
					       "cannot be periodic (only the "
					       "x and y side pairs)",
					       f == DEM_ZMIN ? "bottom" : "top");
		if (bc[p] != DEM_BC_PERIODIC)
			return dem_scene_error(s, face_key[f], e, "periodic "
					       "needs %s periodic too",
					       face_key[p]);
	}
	if (dem_mesh_box(m, ax, e)) {
		char msg[sizeof e->msg];

		memcpy(msg, e->msg, sizeof msg);
		dem_error_clear(e);
		return dem_scene_error(s, "block", e, "%s", msg);
	}
	dem_mesh_set_bc(m, bc);
	if ((rc = dem_mesh_set_periodic(m, bc[DEM_XMIN] == DEM_BC_PERIODIC,
					bc[DEM_YMIN] == DEM_BC_PERIODIC, e))) {
		dem_mesh_free(m);
		return rc;
	}
	return DEM_OK;
}
