/* setup.c - a DE-only run from its scene (setup.h). */
#include "body/setup.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/law.h"
#include "contact/model.h"
#include "core/cli.h"
#include "core/consts.h"

const char *const dem_de_sections[] = {"bodies", "walls", "contact", "run", "detect", NULL};

static int read_shape(dem_scene_t *s, int accuracy, dem_shape_t *sh, dem_error_t *e)
{
	static const char *const kinds[] = {"superquadric", "polygon", "disk", NULL};
	int kind;
	long sides = 4;
	double a = NAN, b, m = 2, tau;
	if (dem_scene_choice(s, "bodies.shape", kinds, DEM_SHAPE_SUPERQUADRIC, &kind, e) ||
	    dem_scene_quantity(s, "bodies.a", DEM_DIM_LENGTH, NAN, DEM_SCENE_GT0, HUGE_VAL, &a, e))
		return e->code;
	if (isnan(a))
		return dem_scene_error(s, "bodies.a", e, "missing: the bodies' size (e.g. 4.5 mm: "
		                       "half-axis, circumradius or radius)");
	switch (kind) {
	case DEM_SHAPE_SUPERQUADRIC:
		/* Box 4.1's tolerance: the accuracy knob of the shape */
		tau = accuracy == DEM_ACCURACY_FINE ? 1e-3 : accuracy == DEM_ACCURACY_COARSE ? 3e-2 : 1e-2;
		if (dem_scene_quantity(s, "bodies.b", DEM_DIM_LENGTH, a, DEM_SCENE_GT0, HUGE_VAL, &b, e) ||
		    dem_scene_quantity(s, "bodies.m", DEM_DIM_NONE, 2, 1, 1e6, &m, e) ||
		    dem_scene_quantity(s, "bodies.tau", DEM_DIM_NONE, tau, DEM_SCENE_GT0, 0.5, &tau, e))
			return e->code;
		return dem_shape_init(sh, kind, a, b, m, tau, e);
	case DEM_SHAPE_POLYGON:
		if (dem_scene_int(s, "bodies.sides", 4, 3, 64, &sides, e))
			return e->code;
		return dem_shape_init(sh, kind, a, a, (double)sides, 0, e);
	default:
		return dem_shape_init(sh, kind, a, a, 0, 0, e);
	}
}

static int read_contact(dem_scene_t *s, int accuracy, dem_de_param_t *p, dem_error_t *e)
{
	static const char *const laws[] = {"linear", "hertz", "power", NULL};
	static const char *const algos[] = {"dcell", "nbs", "scell", "adt", "asdt", "brute", NULL};
	/* W (J/m, per unit thickness) over S^k: Pa for the linear law, Pa/m
	 * for the Hertz-type law; the power law's in SI units, a bare number */
	static const dem_dim_t kn_dim[] = {{-1, 1, -2, 0, 0}, {-2, 1, -2, 0, 0}, {0, 0, 0, 0, 0}};
	int law, algo;
	double kn = NAN;
	if (dem_scene_choice(s, "contact.law", laws, 0, &law, e) ||
	    dem_scene_quantity(s, "contact.kn", kn_dim[law], NAN, DEM_SCENE_GT0, HUGE_VAL, &kn, e))
		return e->code;
	if (isnan(kn))
		return dem_scene_error(s, "contact.kn", e, "missing: the penalty k_n of W(S) "
		                       "(Table 4.2; e.g. 1e7 Pa for the linear law)");
	p->law = law == 0 ? DEM_W_LINEAR : law == 1 ? DEM_W_HERTZ : DEM_W_POWER;
	p->kn = kn;
	if (p->law == DEM_W_POWER &&
	    dem_scene_quantity(s, "contact.m", DEM_DIM_NONE, 2, 1, 10, &p->p, e))
		return e->code;
	/* the effects the scene names (DESIGN.md) */
	if ((p->friction = dem_scene_has(s, "contact.friction")) &&
	    (dem_scene_quantity(s, "contact.friction", DEM_DIM_NONE, 0, 0, HUGE_VAL, &p->mu, e) ||
	     dem_scene_quantity(s, "contact.kt_ratio", DEM_DIM_NONE, DEM_CONTACT_KT_RATIO,
	                        DEM_SCENE_GT0, HUGE_VAL, &p->kt_ratio, e)))
		return e->code;
	if ((p->damping = dem_scene_has(s, "contact.damping")) &&
	    dem_scene_quantity(s, "contact.damping", DEM_DIM_NONE, 0, 0, 0.999999, &p->xi, e))
		return e->code;
	if ((p->gravity = dem_scene_has(s, "run.gravity")) &&
	    dem_scene_vector(s, "run.gravity", DEM_DIM_ACCEL, 2, NULL, -HUGE_VAL, HUGE_VAL, p->g, e))
		return e->code;
	if (dem_scene_quantity(s, "run.lambda", DEM_DIM_NONE,
	                       accuracy == DEM_ACCURACY_FINE ? 0.1 :
	                       accuracy == DEM_ACCURACY_COARSE ? 0.3 : DEM_DT_LAMBDA_DEFAULT,
	                       DEM_SCENE_GT0, 1, &p->lambda, e) ||
	    dem_scene_choice(s, "detect.algorithm", algos, 0, &algo, e) ||
	    dem_scene_quantity(s, "detect.cell_factor", DEM_DIM_NONE, 0, 0, 1e6, &p->cell_factor, e))
		return e->code;
	p->algo = (dem_detect_algo_t)dem_detect_algo_parse(algos[algo]);
	return DEM_OK;
}

/* the n > 0 lengths of key, a whole number of groups of per (else an
 * error expecting form), into *c (the caller frees it; NULL on failure) */
static int read_lengths(dem_scene_t *s, const char *key, int n, int per, const char *form,
                        double **c, dem_error_t *e)
{
	*c = NULL;
	if (n < per || n % per)
		return dem_scene_error(s, key, e, "expected %s", form);
	if (!(*c = malloc((size_t)n * sizeof **c)))
		return dem_error_nomem(e, key);
	return dem_scene_vector(s, key, DEM_DIM_LENGTH, n, NULL, -HUGE_VAL, HUGE_VAL, *c, e);
}

/* the bodies at their centres or on the lattice of the region */
static int place_bodies(dem_scene_t *s, gsl_rng *rng, const dem_shape_t *sh, dem_de_t *de,
                        dem_error_t *e)
{
	static const double zero[2] = {0, 0};
	double v[2], spin, angle = NAN, region[4];
	long count = 0;
	int nat = dem_scene_length(s, "bodies.at");
	if (dem_scene_vector(s, "bodies.velocity", DEM_DIM_VELOCITY, 2, zero, -HUGE_VAL,
	                     HUGE_VAL, v, e) ||
	    dem_scene_quantity(s, "bodies.spin", (dem_dim_t){0, 0, -1, 1, 0}, 0, -HUGE_VAL,
	                       HUGE_VAL, &spin, e) ||
	    dem_scene_quantity(s, "bodies.angle", DEM_DIM_ANGLE, NAN, -HUGE_VAL, HUGE_VAL, &angle, e))
		return e->code;
	if (nat >= 0 && dem_scene_has(s, "bodies.count"))
		return dem_scene_error(s, "bodies.count", e, "give the bodies by at (centres) or "
		                       "by count and region, not both");
	if (nat >= 0) {
		double *c;
		int rc = read_lengths(s, "bodies.at", nat, 2, "x, y pairs of centres "
		                      "([x1, y1, x2, y2, ...] mm)", &c, e);
		for (int k = 0; !rc && k < nat / 2; k++) {
			double th = isnan(angle) ? 2 * DEM_PI * gsl_rng_uniform(rng) : angle;
			if (dem_de_add_body(de, 0, c[2 * k], c[2 * k + 1], th, v[0], v[1], spin, e) < 0)
				rc = e->code;
		}
		free(c);
		return rc;
	}
	if (dem_scene_int(s, "bodies.count", 0, 0, 10000000, &count, e) ||
	    dem_scene_vector(s, "bodies.region", DEM_DIM_LENGTH, 4, NULL, -HUGE_VAL, HUGE_VAL,
	                     region, e))
		return e->code;
	if (count == 0)
		return dem_scene_error(s, "bodies.count", e, "missing: the bodies' centres "
		                       "(bodies.at) or their number (bodies.count) and region");
	if (!dem_scene_has(s, "bodies.region"))
		return dem_scene_error(s, "bodies.region", e, "missing: the rectangle [x0, y0, x1, "
		                       "y1] the %ld bodies fill", count);
	double sp = 2.2 * sh->r, w = region[2] - region[0], h = region[3] - region[1];
	long nx = w > 0 ? (long)floor(w / sp) : 0, ny = h > 0 ? (long)floor(h / sp) : 0;
	if (nx < 1 || nx * ny < count)
		return dem_scene_error(s, "bodies.region", e, "room for %ld bodies on the lattice "
		                       "of %g m: %ld asked for", nx * (ny > 0 ? ny : 0), sp, count);
	double x0 = region[0] + 0.5 * (w - (double)nx * sp) + 0.5 * sp;
	for (long k = 0; k < count; k++) {
		double th = isnan(angle) ? 2 * DEM_PI * gsl_rng_uniform(rng) : angle;
		if (dem_de_add_body(de, 0, x0 + (double)(k % nx) * sp,
		                    region[1] + 0.5 * sp + (double)(k / nx) * sp, th, v[0], v[1],
		                    spin, e) < 0)
			return e->code;
	}
	return DEM_OK;
}

static int read_walls(dem_scene_t *s, const dem_shape_t *sh, dem_de_t *de, dem_error_t *e)
{
	int n = dem_scene_length(s, "walls.segments");
	double t;
	if (dem_scene_quantity(s, "walls.thickness", DEM_DIM_LENGTH, 2 * sh->r, DEM_SCENE_GT0,
	                       HUGE_VAL, &t, e))
		return e->code;
	if (n < 0)
		return DEM_OK;
	double *c;
	int rc = read_lengths(s, "walls.segments", n, 4, "ax, ay, bx, by for each wall (the "
	                      "bodies on the left of A -> B)", &c, e);
	for (int k = 0; !rc && k < n / 4; k++)
		if (dem_de_add_wall(de, c + 4 * k, c + 4 * k + 2, t, e) < 0) {
			/* the library's reason, placed in the scene */
			char why[sizeof e->msg];
			snprintf(why, sizeof why, "%s", e->msg);
			dem_error_clear(e);
			rc = dem_scene_error(s, "walls.segments", e, "wall %d: %s", k + 1, why);
		}
	free(c);
	return rc;
}

/* Box 3.1's v0: the largest approach speed the run expects, by default
 * twice the larger of the free-fall speed over the scene's height and the
 * bodies' initial speed */
static int read_speed(dem_scene_t *s, dem_de_t *de, dem_error_t *e)
{
	double lo = HUGE_VAL, hi = -HUGE_VAL, v = 0;
	for (size_t i = 0; i < de->n; i++) {
		double r = de->shape[de->sh[i]].r;
		lo = fmin(lo, de->y[i] - r), hi = fmax(hi, de->y[i] + r);
		v = fmax(v, hypot(de->vx[i], de->vy[i]) + fabs(de->w[i]) * r);
	}
	for (size_t k = 0; k < de->nw; k++)
		for (int q = 0; q < 4; q++)
			lo = fmin(lo, de->wall[k][q][1]), hi = fmax(hi, de->wall[k][q][1]);
	if (de->p.gravity)
		v = fmax(v, sqrt(2 * hypot(de->p.g[0], de->p.g[1]) * (hi - lo)));
	if (dem_scene_quantity(s, "run.speed", DEM_DIM_VELOCITY, 2 * v, DEM_SCENE_GT0, HUGE_VAL,
	                       &de->p.v0, e))
		return e->code;
	if (!(de->p.v0 > 0))
		return dem_scene_error(s, "run.speed", e, "missing: nothing moves the bodies; give "
		                       "the largest approach speed expected, for the time step");
	return DEM_OK;
}

int dem_de_setup_read(dem_scene_t *s, int accuracy, gsl_rng *rng, dem_de_setup_t *su,
                      dem_de_t *de, dem_error_t *e)
{
	dem_de_param_t p;
	memset(su, 0, sizeof *su);
	memset(de, 0, sizeof *de);
	memset(&p, 0, sizeof p);
	int rc;
	if ((rc = read_shape(s, accuracy, &su->shape, e)) ||
	    (rc = dem_scene_quantity(s, "bodies.density", DEM_DIM_DENSITY, 2500, DEM_SCENE_GT0,
	                             HUGE_VAL, &p.density, e)) ||
	    (rc = read_contact(s, accuracy, &p, e)) ||
	    (rc = dem_scene_quantity(s, "run.end", DEM_DIM_TIME, NAN, DEM_SCENE_GT0, HUGE_VAL,
	                             &su->end, e)) ||
	    (rc = dem_scene_int(s, "run.frames", 1, 1, 100000, &su->frames, e)))
		goto fail;
	if (isnan(su->end)) {
		rc = dem_scene_error(s, "run.end", e, "missing: how long to run (e.g. 1 s)");
		goto fail;
	}
	if ((rc = dem_de_init(de, &p, 1, &su->shape, e)) ||
	    (rc = place_bodies(s, rng, &su->shape, de, e)) ||
	    (rc = read_walls(s, &su->shape, de, e)) ||
	    (rc = read_speed(s, de, e)))
		goto fail;
	return DEM_OK;
fail:
	dem_de_setup_free(su, de);
	return rc;
}

void dem_de_setup_free(dem_de_setup_t *su, dem_de_t *de)
{
	dem_de_free(de);
	dem_shape_free(&su->shape);
}

const char *dem_de_effects(const dem_de_t *de, char *buf, size_t len)
{
	size_t w = 0;
	buf[0] = '\0';
	if (de->p.gravity)
		w += (size_t)snprintf(buf + w, len - w, "gravity (%g, %g) m/s^2", de->p.g[0],
		                      de->p.g[1]);
	if (de->p.friction && w < len)
		w += (size_t)snprintf(buf + w, len - w, "%sfriction mu=%g", w ? ", " : "", de->p.mu);
	if (de->p.damping && w < len)
		w += (size_t)snprintf(buf + w, len - w, "%sviscous damping xi=%g", w ? ", " : "",
		                      de->p.xi);
	if (w == 0)
		snprintf(buf, len, "none");
	return buf;
}
