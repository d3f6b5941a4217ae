#include "pack/shots.h"

#include <gsl/gsl_randist.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/consts.h"
#include "core/fmt.h"
#include "core/rng.h"

const char *const dem_shots_pattern_names[] = {"grid", "random", NULL};

/* ---- coverage raster ---------------------------------------------------- */

#define MAX_CELLS (1L << 27)    /* 128 MB of flags: a cell far too fine */

struct dem_coverage {
	long n[2];
	double lo[2], h[2];
	unsigned char *mark;
	size_t covered;
};

int dem_coverage_new(dem_coverage_t **c, const double *lo, const double *hi,
		     double cell, dem_error_t *e)
{
	long n[2];

	*c = NULL;
	if (!(cell > 0) || !isfinite(cell))
		return dem_error_set(e, DEM_EINPUT, "coverage raster: cell %g is not a positive length", cell);
	for (int d = 0; d < 2; d++) {
		double len = hi[d] - lo[d];
		if (!(len > 0) || !isfinite(len))
			return dem_error_set(e, DEM_EINPUT, "coverage raster: empty area on axis %d", d);
		double k = ceil(len / cell * (1 - 1e-12));
		if (k > (double)MAX_CELLS)
			k = (double)MAX_CELLS + 1;
		n[d] = k < 1 ? 1 : (long)k;
	}
	if ((double)n[0] * (double)n[1] > (double)MAX_CELLS)
		return dem_error_set(e, DEM_EINPUT, "coverage raster: %ld x %ld cells of %g m is more "
				     "than %ld; the dimple radius is too small for the area",
				     n[0], n[1], cell, MAX_CELLS);
	dem_coverage_t *r = calloc(1, sizeof *r);
	if (!r || !(r->mark = calloc((size_t)(n[0] * n[1]), 1))) {
		free(r);
		return dem_error_nomem(e, "coverage raster");
	}
	for (int d = 0; d < 2; d++) {
		r->n[d] = n[d];
		r->lo[d] = lo[d];
		r->h[d] = (hi[d] - lo[d]) / (double)n[d];
	}
	*c = r;
	return DEM_OK;
}

void dem_coverage_free(dem_coverage_t *c)
{
	if (c)
		free(c->mark);
	free(c);
}

void dem_coverage_clear(dem_coverage_t *c)
{
	for (long k = 0; k < c->n[0] * c->n[1]; k++)
		c->mark[k] = 0;
	c->covered = 0;
}

static long wrap_index(long i, long n)
{
	i %= n;
	return i < 0 ? i + n : i;
}

/* Row by row over the cell centres inside the disk; indices wrap, so an
 * impact near an edge marks the opposite edge as its periodic image
 * would.  A flag per cell keeps overlapping images from counting twice. */
void dem_coverage_add(dem_coverage_t *c, double x, double y, double a)
{
	if (!(a > 0) || !isfinite(a) || !isfinite(x) || !isfinite(y))
		return;
	double fx = (x - c->lo[0]) / c->h[0] - 0.5, fy = (y - c->lo[1]) / c->h[1] - 0.5;
	long j0 = (long)ceil(fy - a / c->h[1]), j1 = (long)floor(fy + a / c->h[1]);
	for (long j = j0; j <= j1; j++) {
		double dy = ((double)j - fy) * c->h[1], rem = a * a - dy * dy;
		if (rem < 0)
			continue;
		double half = sqrt(rem) / c->h[0];
		long i0 = (long)ceil(fx - half), i1 = (long)floor(fx + half);
		unsigned char *row = c->mark + wrap_index(j, c->n[1]) * c->n[0];
		for (long i = i0; i <= i1; i++) {
			unsigned char *m = row + wrap_index(i, c->n[0]);
			if (!*m) {
				*m = 1;
				c->covered++;
			}
		}
	}
}

double dem_coverage_fraction(const dem_coverage_t *c)
{
	return (double)c->covered / ((double)c->n[0] * (double)c->n[1]);
}

int dem_coverage_measure(const double *lo, const double *hi, double a,
			 size_t n, const double *x, const double *y,
			 double *fraction, dem_error_t *e)
{
	dem_coverage_t *c;
	int rc = dem_coverage_new(&c, lo, hi, a / DEM_COVERAGE_CELLS, e);
	if (rc)
		return rc;
	for (size_t i = 0; i < n; i++)
		dem_coverage_add(c, x[i], y[i], a);
	*fraction = dem_coverage_fraction(c);
	dem_coverage_free(c);
	return DEM_OK;
}

/* ---- shots ----------------------------------------------------------------- */

void dem_shots_velocity(double speed, double angle, double azimuth, double *v)
{
	/* sin(pi/2 - angle), not cos(angle): a normal impact (angle the
	 * double nearest pi/2) then has no tangential part at all, where
	 * cos would leave 6e-17 of the speed */
	double t = speed * sin(DEM_PI / 2 - angle);
	v[0] = t * cos(azimuth);
	v[1] = t * sin(azimuth);
	v[2] = -speed * sin(angle);
}

/* Fig. 8.4 shows 32 offset layouts but gives no numbers, so the offsets are
 * our choice: the R2 sequence (Roberts 2018) is a low-discrepancy sequence
 * in the unit square whose every prefix spreads evenly, so each further
 * pass lands in the largest gaps the passes before it left, and coverage
 * grows as evenly as a regular layout can make it for any number of passes.
 * Starting at 0.5 puts pass 0 on the cell centres. */
void dem_shots_grid_offset(unsigned long p, double *o)
{
	const double g = DEM_SHOTS_PLASTIC;
	const double alpha[2] = {1 / g, 1 / (g * g)};
	for (int d = 0; d < 2; d++) {
		double u = 0.5 + (double)p * alpha[d];
		o[d] = u - floor(u) - 0.5;
	}
}

/* Densest packing of equal disks in the plane: pi / (2 sqrt 3). */
#define HEX_DENSITY 0.90689968211710892
/* Random sequential addition: tries per shot, then fresh starts per pass. */
#define TRIES 1000
#define RESTARTS 50

struct gen {
	const dem_shots_spec_t *s;
	gsl_rng *rr, *rx, *rv;          /* radii, positions, speeds: apart, so
					 * each is replayed alone */
	size_t cap;                     /* shots of a whole pass */
	dem_shot_t *pass;
	double len[2];
	/* random: a bucket grid of the pass, cells at least the largest
	 * separation, so neighbours lie in the 3 x 3 block around a cell */
	long nb[2];
	long *head, *next;
};

static void gen_free(struct gen *g)
{
	gsl_rng_free(g->rr);
	gsl_rng_free(g->rx);
	gsl_rng_free(g->rv);
	free(g->pass);
	free(g->head);
	free(g->next);
}

static int gen_init(struct gen *g, const dem_shots_spec_t *s, unsigned long seed,
		    dem_error_t *e)
{
	*g = (struct gen){.s = s};
	g->cap = s->pattern == DEM_SHOTS_GRID ? (size_t)s->grid * (size_t)s->grid : (size_t)s->per_pass;
	for (int d = 0; d < 2; d++)
		g->len[d] = s->hi[d] - s->lo[d];
	g->rr = dem_rng_derive(seed, 0);
	g->rx = dem_rng_derive(seed, 1);
	g->rv = dem_rng_derive(seed, 2);
	g->pass = malloc(g->cap * sizeof *g->pass);
	if (!g->rr || !g->rx || !g->rv || !g->pass)
		goto nomem;
	if (s->pattern == DEM_SHOTS_RANDOM && s->separation > 0) {
		double reach = s->separation * 2 * s->law.rmax;
		for (int d = 0; d < 2; d++) {
			double k = floor(g->len[d] / reach);
			g->nb[d] = k < 3 ? 1 : k > 1024 ? 1024 : (long)k;
		}
		g->head = malloc((size_t)(g->nb[0] * g->nb[1]) * sizeof *g->head);
		g->next = malloc(g->cap * sizeof *g->next);
		if (!g->head || !g->next)
			goto nomem;
	}
	return DEM_OK;
nomem:
	gen_free(g);
	*g = (struct gen){0};
	return dem_error_nomem(e, "shot pass");
}

static long bucket_of(const struct gen *g, const double *x, long *b)
{
	for (int d = 0; d < 2; d++) {
		long k = (long)((x[d] - g->s->lo[d]) / g->len[d] * (double)g->nb[d]);
		b[d] = k < 0 ? 0 : k >= g->nb[d] ? g->nb[d] - 1 : k;
	}
	return b[1] * g->nb[0] + b[0];
}

/* Is x at least separation (r + r_j) from every shot placed so far, by the
 * periodic (minimum image) distance? */
static int clear_of(const struct gen *g, const double *x, double r)
{
	long b[2];
	bucket_of(g, x, b);
	long span[2] = {g->nb[0] < 3 ? 0 : 1, g->nb[1] < 3 ? 0 : 1};
	for (long dj = -span[1]; dj <= span[1]; dj++)
		for (long di = -span[0]; di <= span[0]; di++) {
			long k = wrap_index(b[1] + dj, g->nb[1]) * g->nb[0] + wrap_index(b[0] + di, g->nb[0]);
			for (long i = g->head[k]; i >= 0; i = g->next[i]) {
				const dem_shot_t *o = &g->pass[i];
				double dmin = g->s->separation * (r + o->r), d2 = 0;
				for (int d = 0; d < 2; d++) {
					double dx = x[d] - o->x[d];
					dx -= g->len[d] * round(dx / g->len[d]);
					d2 += dx * dx;
				}
				if (d2 < dmin * dmin)
					return 0;
			}
		}
	return 1;
}

/* Random sequential addition: each shot tries uniform points until one is
 * clear of the shots before it; a pass that jams starts afresh. */
static int place_random(struct gen *g, dem_error_t *e)
{
	const dem_shots_spec_t *s = g->s;
	size_t placed = 0, best = 0;

	for (int start = 0; start < RESTARTS; start++) {
		if (g->head)
			for (long k = 0; k < g->nb[0] * g->nb[1]; k++)
				g->head[k] = -1;
		for (placed = 0; placed < g->cap; placed++) {
			dem_shot_t *sh = &g->pass[placed];
			int ok = 0;
			for (int t = 0; t < TRIES && !ok; t++) {
				for (int d = 0; d < 2; d++)
					sh->x[d] = s->lo[d] + g->len[d] * gsl_rng_uniform(g->rx);
				ok = !g->head || clear_of(g, sh->x, sh->r);
			}
			if (!ok)
				break;
			if (g->head) {
				long b[2], k = bucket_of(g, sh->x, b);
				g->next[placed] = g->head[k];
				g->head[k] = (long)placed;
			}
		}
		if (placed == g->cap)
			return DEM_OK;
		if (placed > best)
			best = placed;
	}
	char r[32], a[32], b[32];
	dem_fmt_double(r, s->law.rmin);
	dem_fmt_double(a, g->len[0]);
	dem_fmt_double(b, g->len[1]);
	return dem_error_set(e, DEM_EINPUT, "random pattern: cannot place per_pass %ld shots of "
			     "radius %s m at least %g (r_i + r_j) apart in the %s x %s m area (placed "
			     "%zu at best, %d fresh starts of %d tries a shot); lower per_pass or "
			     "separation, or enlarge the area",
			     s->per_pass, r, s->separation, a, b, best, RESTARTS, TRIES);
}

/* Fill g->pass with pass p: radii, speeds and velocities, then positions. */
static int gen_pass(struct gen *g, unsigned long p, dem_error_t *e)
{
	const dem_shots_spec_t *s = g->s;

	for (size_t i = 0; i < g->cap; i++) {
		dem_shot_t *sh = &g->pass[i];
		double speed = s->speed, z;
		sh->pass = p;
		sh->t = 0;      /* every shot of a pass starts together (Ch. 8.6) */
		sh->r = dem_radius_draw(&s->law, g->rr);
		if (s->speed_scatter > 0) {
			do
				z = gsl_ran_gaussian_ziggurat(g->rv, 1);
			while (fabs(z) > 3);
			speed *= 1 + s->speed_scatter * z;
		}
		dem_shots_velocity(speed, s->angle, s->azimuth, sh->v);
	}
	if (s->pattern == DEM_SHOTS_RANDOM)
		return place_random(g, e);

	double o[2];
	dem_shots_grid_offset(p, o);
	for (int j = 0, k = 0; j < s->grid; j++)
		for (int i = 0; i < s->grid; i++, k++) {
			int ij[2] = {i, j};
			for (int d = 0; d < 2; d++) {
				/* the shifted lattice, wrapped back into the area */
				double u = (ij[d] + 0.5 + o[d]) / s->grid;
				u -= floor(u);
				double x = s->lo[d] + u * g->len[d];
				g->pass[k].x[d] = x < s->hi[d] ? x : s->lo[d];
			}
		}
	return DEM_OK;
}

enum { STOP = INT_MIN };     /* a visitor's clean early end; no DEM_E* code */

/* Generate whole passes and hand their first `limit` shots to visit, which
 * returns DEM_OK to go on, STOP to end early, or an error code.  A partial
 * last pass is still drawn whole, so any limit sees the same shots. */
static int run(const dem_shots_spec_t *s, unsigned long seed, size_t limit,
	       int (*visit)(void *, const dem_shot_t *), void *ctx, dem_error_t *e)
{
	struct gen g;
	size_t done = 0;
	int rc;

	if ((rc = gen_init(&g, s, seed, e)))
		return rc;
	for (unsigned long p = 0; done < limit && rc == DEM_OK; p++) {
		rc = gen_pass(&g, p, e);
		for (size_t i = 0; i < g.cap && done < limit && rc == DEM_OK; i++, done++)
			rc = visit(ctx, &g.pass[i]);
	}
	gen_free(&g);
	return rc == STOP ? DEM_OK : rc;
}

struct measure {
	dem_coverage_t *c;
	double a;
	size_t n, impacts_100;
	int stop_at_full;
};

static int measure_visit(void *ctx, const dem_shot_t *sh)
{
	struct measure *m = ctx;
	dem_coverage_add(m->c, sh->x[0], sh->x[1], m->a);
	m->n++;
	if (!m->impacts_100 && dem_coverage_fraction(m->c) >= DEM_COVERAGE_FULL) {
		m->impacts_100 = m->n;
		if (m->stop_at_full)
			return STOP;
	}
	return DEM_OK;
}

static int count_visit(void *ctx, const dem_shot_t *sh)
{
	(void)sh;
	((struct measure *)ctx)->n++;
	return DEM_OK;
}

static int check_spec(const dem_shots_spec_t *s, dem_error_t *e)
{
	for (int d = 0; d < 2; d++)
		if (!(s->hi[d] > s->lo[d]) || !isfinite(s->hi[d] - s->lo[d]))
			return dem_error_set(e, DEM_EINPUT, "shots: the area is empty or unbounded");
	if (!(s->law.rmin > 0) || !(s->law.rmax >= s->law.rmin) || !isfinite(s->law.rmax))
		return dem_error_set(e, DEM_EINPUT, "shots: the radii must be positive lengths");
	if (!(s->speed > 0) || !isfinite(s->speed) || !(s->speed_scatter >= 0) ||
	    !(s->speed_scatter < 1.0 / 3))
		return dem_error_set(e, DEM_EINPUT, "shots: the speed must be positive, its scatter in "
				     "[0, 1/3) so the speed cut at 3 sd stays positive");
	if (!(s->angle > 0) || !(s->angle <= DEM_PI / 2 + 1e-12) || !isfinite(s->azimuth))
		return dem_error_set(e, DEM_EINPUT, "shots: the angle to the surface must be in (0, 90] deg");
	if (!(s->dimple_radius >= 0) || !isfinite(s->dimple_radius))
		return dem_error_set(e, DEM_EINPUT, "shots: the dimple radius must be 0 or positive");
	if (s->pattern == DEM_SHOTS_GRID) {
		if (s->grid < 1 || s->passes < 1)
			return dem_error_set(e, DEM_EINPUT, "shots: grid and passes must be at least 1");
		return DEM_OK;
	}
	if (s->per_pass < 1 || !(s->separation >= 0) || !isfinite(s->separation) ||
	    !(s->coverage >= 0) || !isfinite(s->coverage))
		return dem_error_set(e, DEM_EINPUT, "shots: per_pass must be at least 1, separation "
				     "and coverage not negative");
	if (s->coverage > 0 && !(s->dimple_radius > 0))
		return dem_error_set(e, DEM_EINPUT, "shots: a coverage needs the dimple radius");
	if (s->coverage == 0 && s->passes < 1)
		return dem_error_set(e, DEM_EINPUT, "shots: passes must be at least 1");
	/* Shots at least sep (r_i + r_j) apart are disks of radius sep r that
	 * do not overlap; no arrangement holds more than the hexagonal one. */
	double area = (s->hi[0] - s->lo[0]) * (s->hi[1] - s->lo[1]);
	double need = (double)s->per_pass * DEM_PI * pow(s->separation * s->law.rmin, 2);
	if (need > HEX_DENSITY * area) {
		char r[32];
		dem_fmt_double(r, s->law.rmin);
		return dem_error_set(e, DEM_EINPUT, "random pattern: per_pass %ld shots of radius %s m "
				     "at least %g (r_i + r_j) apart cannot fit in the area even in "
				     "the densest (hexagonal) arrangement; lower per_pass or "
				     "separation, or enlarge the area",
				     s->per_pass, r, s->separation);
	}
	return DEM_OK;
}

int dem_shots_plan(const dem_shots_spec_t *s, unsigned long seed,
		   dem_shots_plan_t *plan, dem_error_t *e)
{
	struct measure m = {0};
	int rc;

	if ((rc = check_spec(s, e)))
		return rc;
	*plan = (dem_shots_plan_t){0};
	plan->per_pass = s->pattern == DEM_SHOTS_GRID ? (size_t)s->grid * (size_t)s->grid : (size_t)s->per_pass;
	plan->covered = NAN;
	if (s->pattern == DEM_SHOTS_RANDOM && s->coverage > 0) {
		plan->shots = 0;        /* known once 100 % is found */
	} else {
		if ((double)plan->per_pass * (double)s->passes > (double)SIZE_MAX / 2)
			return dem_error_set(e, DEM_EINPUT, "shots: too many shots");
		plan->shots = plan->per_pass * (size_t)s->passes;
	}
	if (s->dimple_radius > 0) {
		m.a = s->dimple_radius;
		if ((rc = dem_coverage_new(&m.c, s->lo, s->hi, m.a / DEM_COVERAGE_CELLS, e)))
			return rc;
	}
	if (s->pattern == DEM_SHOTS_RANDOM && s->coverage > 0) {
		/* Find 100 %: random impacts cover 1 - exp(-n pi a^2 / A) on
		 * average (Avrami), so 98 % takes about -ln 0.02 A / (pi a^2);
		 * twenty times that without reaching it means something is
		 * wrong, not unlucky. */
		double area = (s->hi[0] - s->lo[0]) * (s->hi[1] - s->lo[1]);
		double guess = -log(1 - DEM_COVERAGE_FULL) * area / (DEM_PI * m.a * m.a);
		size_t cap = (size_t)fmin(20 * guess + 1000, 1e9);
		m.stop_at_full = 1;
		if ((rc = run(s, seed, cap, measure_visit, &m, e)))
			goto out;
		if (!m.impacts_100) {
			rc = dem_error_set(e, DEM_ENUMERIC, "shots: %zu impacts did not cover 98 %% of the area",
					   cap);
			goto out;
		}
		plan->impacts_100 = m.impacts_100;
		double n = ceil(s->coverage / 100 * (double)m.impacts_100 - 1e-9);
		if (n > 1e12) {
			rc = dem_error_set(e, DEM_EINPUT, "shots: coverage %g %% needs too many shots",
					   s->coverage);
			goto out;
		}
		plan->shots = n < 1 ? 1 : (size_t)n;
		/* then measure what the stream itself covers */
		dem_coverage_clear(m.c);
		m.n = 0;
		m.stop_at_full = 0;
	}
	if (!m.c && s->pattern == DEM_SHOTS_RANDOM) {
		/* draw the passes once anyway: a pass that cannot be placed
		 * fails here, before any output */
		if ((rc = run(s, seed, plan->shots, count_visit, &m, e)))
			goto out;
	}
	if (m.c) {
		m.impacts_100 = 0;
		if ((rc = run(s, seed, plan->shots, measure_visit, &m, e)))
			goto out;
		plan->covered = dem_coverage_fraction(m.c);
		if (!plan->impacts_100)
			plan->impacts_100 = m.impacts_100;
	}
	plan->passes = plan->per_pass ? (plan->shots + plan->per_pass - 1) / plan->per_pass : 0;
out:
	dem_coverage_free(m.c);
	return rc;
}

struct emit_ctx {
	dem_shots_emit_fn emit;
	void *ctx;
};

static int emit_visit(void *ctx, const dem_shot_t *sh)
{
	struct emit_ctx *c = ctx;
	int rc = c->emit(c->ctx, sh);
	return rc == STOP ? DEM_EIO : rc;       /* STOP is ours alone */
}

int dem_pack_shots(const dem_shots_spec_t *s, unsigned long seed,
		   const dem_shots_plan_t *plan, dem_shots_emit_fn emit,
		   void *ctx, dem_error_t *e)
{
	struct emit_ctx c = {emit, ctx};
	int rc = check_spec(s, e);
	if (rc)
		return rc;
	return run(s, seed, plan->shots, emit_visit, &c, e);
}
