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

/* The hardening laws and rate laws as a scene names them, each with the
 * block of keys it reads (NULL: at the section's level); index + 1 is the
 * dem_mat_law_t / dem_mat_rate_law_t. */
static const char *const law_names[] = {"linear", "table", "voce", "johnson-cook", NULL};
static const char *const law_block[] = {NULL, "material.table", "material.voce",
					"material.johnson-cook"};
static const char *const rate_names[] = {"power", "cowper-symonds", "johnson-cook", NULL};

/* A quantity the law needs: absent is an error naming the law. */
static int need(dem_scene_t *s, const char *key, dem_dim_t dim, double min,
		double max, double *out, const char *what, dem_error_t *e)
{
	int rc;

	*out = NAN;
	if ((rc = dem_scene_quantity(s, key, dim, NAN, min, max, out, e)))
		return rc;
	if (isnan(*out)) {
		/* point at the block that lacks it, where the scene has one */
		char parent[128];
		const char *dot;

		snprintf(parent, sizeof parent, "%s", key);
		while ((dot = strrchr(parent, '.')) && !dem_scene_has(s, parent))
			parent[dot - parent] = '\0';
		if (dot && strcmp(parent, key) != 0)
			return dem_scene_error(s, parent, e, "missing %s: %s",
					       key + strlen(parent) + 1, what);
		return dem_scene_error(s, key, e, "missing: %s", what);
	}
	return DEM_OK;
}

/* The law of the section: material.law, or the one its keys imply. */
static int read_law(dem_scene_t *s, dem_mat_law_t *law, dem_error_t *e)
{
	int v, def = -1, rc;

	if (dem_scene_has(s, "material.table"))
		def = DEM_LAW_TABLE - 1;
	else if (dem_scene_has(s, "material.voce"))
		def = DEM_LAW_VOCE - 1;
	else if (dem_scene_has(s, "material.johnson-cook"))
		def = DEM_LAW_JC - 1;
	else if (dem_scene_has(s, "material.yield"))
		def = DEM_LAW_LINEAR - 1;
	if (def < 0 && !dem_scene_has(s, "material.law")) {
		*law = DEM_LAW_AUTO;   /* elastic */
		return DEM_OK;
	}
	if ((rc = dem_scene_choice(s, "material.law", law_names, def < 0 ? 0 : def, &v, e)))
		return rc;
	*law = (dem_mat_law_t)(v + 1);
	/* another law's block is a mistake, not a key to ignore */
	for (int k = 0; k < 4; k++)
		if (k != v && law_block[k] && dem_scene_has(s, law_block[k]))
			return dem_scene_error(s, law_block[k], e, "given, but the "
					       "hardening law is %s", law_names[v]);
	return DEM_OK;
}

static int read_kinematic(dem_scene_t *s, dem_mat_param_t *p, dem_error_t *e)
{
	int n = dem_scene_length(s, "material.kinematic.C");
	int ng = dem_scene_length(s, "material.kinematic.gamma");
	int rc;

	if (n < 1 || n > DEM_MAT_NKIN)
		return dem_scene_error(s, "material.kinematic.C", e, "expected a "
				       "list of 1 to %d back-stress moduli "
				       "(pressures)", DEM_MAT_NKIN);
	if (ng != n)
		return dem_scene_error(s, "material.kinematic.gamma", e, "expected "
				       "a list of %d recall constants, one per "
				       "modulus", n);
	if ((rc = dem_scene_vector(s, "material.kinematic.C", DEM_DIM_PRESSURE, n,
				   NULL, DEM_SCENE_GT0, HUGE_VAL, p->kin_C, e)) ||
	    (rc = dem_scene_vector(s, "material.kinematic.gamma", DEM_DIM_NONE, n,
				   NULL, 0, HUGE_VAL, p->kin_gamma, e)))
		return rc;
	p->nkin = n;
	return DEM_OK;
}

static int read_rate(dem_scene_t *s, dem_mat_param_t *p, dem_error_t *e)
{
	int v, rc;

	if (!dem_scene_has(s, "material.rate.law"))
		return dem_scene_error(s, "material.rate", e, "missing: the rate "
				       "law (law: power, cowper-symonds or "
				       "johnson-cook)");
	if ((rc = dem_scene_choice(s, "material.rate.law", rate_names, 0, &v, e)))
		return rc;
	p->rate_law = (dem_mat_rate_law_t)(v + 1);
	switch (p->rate_law) {
	case DEM_RATE_POWER:
		if ((rc = need(s, "material.rate.m", DEM_DIM_NONE, DEM_SCENE_GT0, 1,
			       &p->rate_m, "the power law's exponent m", e)))
			return rc;
		if (!(p->rate_m < 1))
			return dem_scene_error(s, "material.rate.m", e, "expected "
					       "an exponent below 1");
		break;
	case DEM_RATE_CS:
		if ((rc = need(s, "material.rate.D", DEM_DIM_RATE, DEM_SCENE_GT0,
			       HUGE_VAL, &p->cs_D, "the Cowper-Symonds rate D", e)) ||
		    (rc = need(s, "material.rate.p", DEM_DIM_NONE, DEM_SCENE_GT0,
			       HUGE_VAL, &p->cs_p, "the Cowper-Symonds exponent p", e)))
			return rc;
		return DEM_OK;
	default:
		if ((rc = need(s, "material.rate.C", DEM_DIM_NONE, DEM_SCENE_GT0,
			       HUGE_VAL, &p->jc_C, "the Johnson-Cook rate constant C", e)))
			return rc;
		break;
	}
	/* power and Johnson-Cook: the reference rate is part of the law,
	 * never a hidden default */
	return need(s, "material.rate.ref", DEM_DIM_RATE, DEM_SCENE_GT0, HUGE_VAL,
		    &p->rate_ref, "the reference strain rate of the law", e);
}

/* The Johnson-Cook thermal term: T_ref, T_melt and m together, T (the
 * part's temperature) defaulting to T_ref, i.e. no softening. */
static int read_thermal(dem_scene_t *s, dem_mat_param_t *p, dem_error_t *e)
{
	static const char *const keys[] = {"material.johnson-cook.T_ref",
		"material.johnson-cook.T_melt", "material.johnson-cook.m"};
	int have = 0, rc;

	for (int k = 0; k < 3; k++)
		have += dem_scene_has(s, keys[k]);
	if (have == 0) {
		if (dem_scene_has(s, "material.johnson-cook.T"))
			return dem_scene_error(s, "material.johnson-cook.T", e,
					       "a temperature needs the thermal "
					       "term: T_ref, T_melt and m");
		return DEM_OK;
	}
	if ((rc = need(s, keys[0], DEM_DIM_TEMPERATURE, DEM_SCENE_GT0, HUGE_VAL,
		       &p->T_ref, "the reference temperature of the thermal term", e)) ||
	    (rc = need(s, keys[1], DEM_DIM_TEMPERATURE, DEM_SCENE_GT0, HUGE_VAL,
		       &p->T_melt, "the melting temperature of the thermal term", e)) ||
	    (rc = need(s, keys[2], DEM_DIM_NONE, DEM_SCENE_GT0, HUGE_VAL, &p->mt,
		       "the thermal exponent m", e)) ||
	    (rc = dem_scene_quantity(s, "material.johnson-cook.T", DEM_DIM_TEMPERATURE,
				     p->T_ref, DEM_SCENE_GT0, HUGE_VAL, &p->T, e)))
		return rc;
	if (!(p->T_melt > p->T_ref))
		return dem_scene_error(s, keys[1], e, "expected above T_ref (%g K)", p->T_ref);
	if (!(p->T < p->T_melt))
		return dem_scene_error(s, "material.johnson-cook.T", e, "expected "
				       "below T_melt (%g K)", p->T_melt);
	return DEM_OK;
}

int dem_scene_material(dem_scene_t *s, int need_rho, dem_mat_t *m,
		       dem_error_t *e)
{
	dem_mat_param_t p = {0};
	double *ep = NULL, *sy = NULL;
	int rc;

	p.E = p.nu = p.rho = NAN;
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
	if (dem_scene_has(s, "material.rate_exponent") ||
	    dem_scene_has(s, "material.rate_ref"))
		return dem_scene_error(s, dem_scene_has(s, "material.rate_exponent")
				       ? "material.rate_exponent" : "material.rate_ref", e,
				       "replaced by rate: {law: power, m: M, ref: RATE} "
				       "(the reference rate is now required)");
	if ((rc = read_law(s, &p.law, e)))
		return rc;
	switch (p.law) {
	case DEM_LAW_TABLE:
		if (dem_scene_has(s, "material.yield") ||
		    dem_scene_has(s, "material.hardening")) {
			rc = dem_scene_error(s, "material.table", e, "give either "
					     "a hardening table or yield and "
					     "hardening, not both");
			goto out;
		}
		if ((rc = read_table(s, &p, &ep, &sy, e)))
			goto out;
		break;
	case DEM_LAW_LINEAR:
	case DEM_LAW_VOCE:
		if ((rc = need(s, "material.yield", DEM_DIM_PRESSURE, DEM_SCENE_GT0,
			       HUGE_VAL, &p.sy0, "the initial yield stress", e)) ||
		    (rc = dem_scene_quantity(s, "material.hardening", DEM_DIM_PRESSURE,
					     0, 0, HUGE_VAL, &p.H, e)))
			goto out;
		if (p.law == DEM_LAW_VOCE &&
		    ((rc = need(s, "material.voce.Q", DEM_DIM_PRESSURE, 0, HUGE_VAL,
				&p.voce_Q, "the Voce saturation stress Q", e)) ||
		     (rc = need(s, "material.voce.b", DEM_DIM_NONE, DEM_SCENE_GT0,
				HUGE_VAL, &p.voce_b, "the Voce rate b", e))))
			goto out;
		break;
	case DEM_LAW_JC:
		if (dem_scene_has(s, "material.yield") ||
		    dem_scene_has(s, "material.hardening")) {
			rc = dem_scene_error(s, dem_scene_has(s, "material.yield") ?
					     "material.yield" : "material.hardening", e,
					     "the Johnson-Cook law takes its yield "
					     "stress from johnson-cook.A");
			goto out;
		}
		if ((rc = need(s, "material.johnson-cook.A", DEM_DIM_PRESSURE,
			       DEM_SCENE_GT0, HUGE_VAL, &p.jc_A,
			       "the Johnson-Cook yield stress A", e)) ||
		    (rc = need(s, "material.johnson-cook.B", DEM_DIM_PRESSURE, 0,
			       HUGE_VAL, &p.jc_B, "the Johnson-Cook hardening B", e)) ||
		    (rc = need(s, "material.johnson-cook.n", DEM_DIM_NONE,
			       DEM_SCENE_GT0, 2, &p.jc_n,
			       "the Johnson-Cook exponent n", e)) ||
		    (rc = read_thermal(s, &p, e)))
			goto out;
		break;
	default:   /* elastic */
		if (dem_scene_has(s, "material.hardening")) {
			rc = dem_scene_error(s, "material.hardening", e,
					     "hardening without a yield stress");
			goto out;
		}
		break;
	}
	if (dem_scene_has(s, "material.kinematic") &&
	    ((rc = p.law == DEM_LAW_AUTO
		   ? dem_scene_error(s, "material.kinematic", e, "back-stresses "
				     "need a yield stress or a hardening law")
		   : read_kinematic(s, &p, e))))
		goto out;
	if (dem_scene_has(s, "material.rate") &&
	    ((rc = p.law == DEM_LAW_AUTO
		   ? dem_scene_error(s, "material.rate", e, "rate dependence "
				     "needs a yield stress or a hardening law")
		   : read_rate(s, &p, e))))
		goto out;
	rc = dem_mat_init(m, &p, e);
out:
	free(ep);
	free(sy);
	return rc;
}

/* The grading keys against the block, for the 3D and the 2D block: the
 * fine depth within the thickness, the largest element not below the
 * fine one. */
static int check_grading(dem_scene_t *s, double depth, double thickness, double h,
			 double hmax, dem_error_t *e)
{
	if (depth > thickness)
		return dem_scene_error(s, "block.fine_depth", e, "%g m is deeper "
				       "than the block (%g m)", depth, thickness);
	if (hmax != 0 && hmax < h)
		return dem_scene_error(s, "block.max_element", e, "%g m is "
				       "smaller than the element size (%g m)",
				       hmax, h);
	return DEM_OK;
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
	if ((rc = check_grading(s, depth, size[2], h, hmax, e)))
		return rc;
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

int dem_scene_block2(dem_scene_t *s, dem_mesh2_t *m, int *axisym, double *thick,
		     dem_error_t *e)
{
	static const char *const bcs[] = {"free", "fixed", "normal", NULL};
	static const char *const modes[] = {"plane", "axisym", NULL};
	static const char *const edge_key[4] = {
		"block.bc.xmin", "block.bc.xmax", "block.bc.bottom", "block.bc.top"
	};
	static const int edge_def[4] = {DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED,
		DEM_BC_FREE};
	double size[2] = {NAN, NAN}, fine, h = NAN, depth, ratio, hmax;
	dem_bc_t bc[4];
	int rc;

	*thick = 0;
	if ((rc = dem_scene_choice(s, "block.mode", modes, 0, axisym, e)) ||
	    (!*axisym && (rc = dem_scene_quantity(s, "block.thickness", DEM_DIM_LENGTH,
						  1e-3, DEM_SCENE_GT0, HUGE_VAL, thick, e))) ||
	    (rc = dem_scene_vector(s, "block.size", DEM_DIM_LENGTH, 2, NULL,
				   DEM_SCENE_GT0, HUGE_VAL, size, e)) ||
	    (rc = dem_scene_quantity(s, "block.element", DEM_DIM_LENGTH, NAN,
				     DEM_SCENE_GT0, HUGE_VAL, &h, e)))
		return rc;
	if (isnan(size[0]))
		return dem_scene_error(s, "block.size", e, "missing: the 2D block "
				       "needs its size [width, thickness]");
	if (isnan(h))
		return dem_scene_error(s, "block.element", e, "missing: the "
				       "block needs the element size under the "
				       "impact area");
	if ((rc = dem_scene_quantity(s, "block.fine", DEM_DIM_LENGTH, size[0],
				     DEM_SCENE_GT0, HUGE_VAL, &fine, e)) ||
	    (rc = dem_scene_quantity(s, "block.fine_depth", DEM_DIM_LENGTH,
				     size[1], DEM_SCENE_GT0, HUGE_VAL, &depth, e)) ||
	    (rc = dem_scene_quantity(s, "block.ratio", DEM_DIM_NONE, 1.2, 1,
				     10, &ratio, e)) ||
	    (rc = dem_scene_quantity(s, "block.max_element", DEM_DIM_LENGTH, 0,
				     0, HUGE_VAL, &hmax, e)))
		return rc;
	if (fine > size[0])
		return dem_scene_error(s, "block.fine", e, "the fine region (%g m) "
				       "is wider than the block (%g m)", fine, size[0]);
	if ((rc = check_grading(s, depth, size[1], h, hmax, e)))
		return rc;
	for (int f = 0; f < 4; f++) {
		int v;

		if ((rc = dem_scene_choice(s, edge_key[f], bcs, edge_def[f], &v, e)))
			return rc;
		bc[f] = (dem_bc_t)v;
	}
	dem_axis_t ax[2] = {
		*axisym ? (dem_axis_t){0, size[0], 0, fine, h, ratio, hmax}
			: (dem_axis_t){-size[0] / 2, size[0] / 2, -fine / 2, fine / 2,
				       h, ratio, hmax},
		{-size[1], 0, -depth, 0, h, ratio, hmax}
	};
	if (dem_mesh2_rect(m, ax, e)) {
		char msg[sizeof e->msg];

		memcpy(msg, e->msg, sizeof msg);
		dem_error_clear(e);
		return dem_scene_error(s, "block", e, "%s", msg);
	}
	dem_mesh2_set_bc(m, bc);
	return DEM_OK;
}
