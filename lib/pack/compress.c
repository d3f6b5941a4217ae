/* compress.c - sphere packing by geometric compression (Ch. 6); see
 * compress.h for the method and the domain. */
#include "pack/compress.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/consts.h"
#include "detect/detect.h"

#define NONE UINT32_MAX

/* Overlap accepted after the relaxation, relative to the smaller radius:
 * rounding only (the contract is 1e-9). */
#define ACCEPT 1e-10

static int converged(double pc, double pp, double tol);

static int cmp_zi(const void *a, const void *b);

const char *const dem_compress_phase_names[] = {
	"init", "global", "shake", "relax", "refill", NULL
};

/* How the spheres move in one iteration. */
enum mode { GLOBAL, SHAKE, RANDOM };

struct zi {
	double z;
	uint32_t i;
};

typedef struct pk {
	const dem_compress_spec_t *s;
	const dem_domain_t *dom;
	gsl_rng *rng;
	dem_error_t *e;
	double vol, volsum, r3sum, rmax, rmin, bumin, bumax;
	struct timespec t0;
	dem_compress_stats_t st;

	size_t n, cap;
	double *x[3], *r, *bu, *v[3], *u[3], *f[3], *im, *xb[3];
	unsigned char *mprev, *mnow, *isact;
	struct zi *ord;

	/* neighbour lists (CSR) from one detection */
	size_t *off;
	uint32_t *adj;
	size_t adjcap;
	dem_boxes_t box;
	size_t boxcap;
	dem_pairs_t pairs;
	dem_detect_ws_t *ws;
	dem_detect_opts_t dopt;

	/* uniform grid of cell 2 Rmax for insertion and dropping */
	double h;
	size_t gn[3];
	uint32_t *head, *next;

	/* relaxation: active spheres, pairs with one at least */
	double zfreeze, zadd;   /* relax above zfreeze; lowest refilled */
	uint32_t *act;
	size_t nact, npair;
} pk_t;

void dem_domain_box(dem_domain_t *d, const double lo[3], const double hi[3])
{
	memset(d, 0, sizeof *d);
	for (int k = 0; k < 3; k++) {
		d->lo[k] = lo[k];
		d->hi[k] = hi[k];
	}
}

void dem_domain_cylinder(dem_domain_t *d, double cx, double cy, double R,
			 double z0, double z1)
{
	double lo[3] = {cx - R, cy - R, z0}, hi[3] = {cx + R, cy + R, z1};
	dem_domain_box(d, lo, hi);
	d->cylinder = 1;
	d->axis[0] = cx;
	d->axis[1] = cy;
	d->radius = R;
}

void dem_compress_spec_init(dem_compress_spec_t *s)
{
	memset(s, 0, sizeof *s);
	s->init_density = 0.3;
	s->tol = 1e-3;
	s->nshake = 5;
	s->beta = 0.5;
	s->max_iter = 200;
	s->max_loops = 20;
	s->max_batches = 100;
	s->buffer = 1;
	s->nroll = 20;
	s->relax = 1;
	s->relax_overlap = 0.1;
	s->relax_ftol = 1e-3;
	s->relax_iter = 20000;
	s->relax_depth = 5;
	s->relax_batch = 0.01;
	s->relax_dt = 0.3;
	s->relax_skin = 0.5;
}

static double now(const pk_t *p)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)(t.tv_sec - p->t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - p->t0.tv_nsec);
}

/* ---- walls --------------------------------------------------------------- */

/* Smallest clearance of a sphere (centre c, radius r) to the walls: >= 0
 * inside. */
static double wall_gap(const dem_domain_t *d, const double *c, double r)
{
	double g = HUGE_VAL;
	for (int k = 0; k < 3; k++) {
		g = fmin(g, c[k] - r - d->lo[k]);
		g = fmin(g, d->hi[k] - r - c[k]);
	}
	if (d->cylinder) {
		double qx = c[0] - d->axis[0], qy = c[1] - d->axis[1];
		g = fmin(g, d->radius - r - sqrt(qx * qx + qy * qy));
	}
	for (size_t k = 0; k < d->nplane; k++) {
		const dem_plane_t *pl = &d->plane[k];
		g = fmin(g, pl->n[0] * c[0] + pl->n[1] * c[1] + pl->n[2] * c[2] - pl->d - r);
	}
	return g;
}

/* Furthest distance t >= 0 a sphere at c can move along unit v before it
 * touches a wall ("check with domain boundary", Box 6.1): ray against each
 * plane offset by r, and against the cylinder of radius R - r. */
static double wall_limit(const dem_domain_t *d, const double *c, double r,
			 const double *v)
{
	double t = HUGE_VAL;
	for (int k = 0; k < 3; k++) {
		if (v[k] < 0)
			t = fmin(t, (c[k] - r - d->lo[k]) / -v[k]);
		else if (v[k] > 0)
			t = fmin(t, (d->hi[k] - r - c[k]) / v[k]);
	}
	if (d->cylinder) {
		/* |q + t w|^2 = (R - r)^2, the larger root (q is inside) */
		double qx = c[0] - d->axis[0], qy = c[1] - d->axis[1];
		double a = v[0] * v[0] + v[1] * v[1];
		if (a > 0) {
			double b = qx * v[0] + qy * v[1];
			double rr = d->radius - r;
			double cc = qx * qx + qy * qy - rr * rr;
			double disc = fmax(0, b * b - a * cc);
			double sq = sqrt(disc);
			double tc = b > 0 ? -cc / (b + sq) : (sq - b) / a;
			t = fmin(t, tc);
		}
	}
	for (size_t k = 0; k < d->nplane; k++) {
		const dem_plane_t *pl = &d->plane[k];
		double nv = pl->n[0] * v[0] + pl->n[1] * v[1] + pl->n[2] * v[2];
		if (nv < 0) {
			double gap = pl->n[0] * c[0] + pl->n[1] * c[1] + pl->n[2] * c[2] - pl->d - r;
			t = fmin(t, gap / -nv);
		}
	}
	return t > 0 ? t : 0;
}

/* Eq. 6.1 in 3D: distance along unit v at which a sphere at c meets the
 * sphere of radius s = Rc + Rt about q; HUGE_VAL if it never does.  The
 * root is taken in the cancellation-free form. */
static inline double pair_limit(const double *c, const double *q, double s,
				const double *v)
{
	double px = c[0] - q[0], py = c[1] - q[1], pz = c[2] - q[2];
	double b = px * v[0] + py * v[1] + pz * v[2];
	if (b >= 0)
		return HUGE_VAL;        /* moving apart */
	double cc = px * px + py * py + pz * pz - s * s;
	double disc = b * b - cc;
	if (disc <= 0)
		return HUGE_VAL;        /* passes by */
	double t = cc / (sqrt(disc) - b);
	return t > 0 ? t : 0;
}

/* ---- storage ------------------------------------------------------------- */

static int grow(pk_t *p, size_t need)
{
	if (need <= p->cap)
		return DEM_OK;
	size_t cap = p->cap ? p->cap : 1024;
	while (cap < need)
		cap *= 2;
	double **dv[] = {&p->x[0], &p->x[1], &p->x[2], &p->r, &p->bu,
			 &p->v[0], &p->v[1], &p->v[2], &p->u[0], &p->u[1], &p->u[2],
			 &p->f[0], &p->f[1], &p->f[2], &p->im, &p->xb[0], &p->xb[1], &p->xb[2]};
	for (size_t k = 0; k < sizeof dv / sizeof *dv; k++) {
		double *q = realloc(*dv[k], cap * sizeof *q);
		if (!q)
			return dem_error_nomem(p->e, "sphere arrays");
		*dv[k] = q;
	}
	unsigned char *m1 = realloc(p->mprev, cap), *m2;
	if (m1)
		p->mprev = m1;
	m2 = realloc(p->mnow, cap);
	if (m2)
		p->mnow = m2;
	struct zi *o = realloc(p->ord, cap * sizeof *o);
	if (o)
		p->ord = o;
	size_t *off = realloc(p->off, (cap + 1) * sizeof *off);
	if (off)
		p->off = off;
	uint32_t *nx = realloc(p->next, cap * sizeof *nx);
	if (nx)
		p->next = nx;
	uint32_t *ac = realloc(p->act, cap * sizeof *ac);
	if (ac)
		p->act = ac;
	unsigned char *ia = realloc(p->isact, cap);
	if (ia)
		p->isact = ia;
	if (!m1 || !m2 || !o || !off || !nx || !ac || !ia)
		return dem_error_nomem(p->e, "sphere arrays");
	p->cap = cap;
	return DEM_OK;
}

static double sphere_volume(double r)
{
	return 4.0 / 3.0 * DEM_PI * r * r * r;
}

static void add_sphere(pk_t *p, const double *c, double r)
{
	size_t i = p->n++;
	for (int k = 0; k < 3; k++)
		p->x[k][i] = c[k];
	p->r[i] = r;
	p->im[i] = pow(p->rmin / r, 3);    /* 1 / m, m = (r / Rmin)^3 */
	p->bu[i] = p->bumax;
	p->mprev[i] = 1;
	p->volsum += sphere_volume(r);
	p->r3sum += r * r * r;
}

/* Eq. 6.7 with heights (Eq. 6.5) measured up from the floor, so P_e > 0 and
 * falls as the packing settles; Eq. 6.8 uses only the ratio. */
static double energy(const pk_t *p)
{
	double lo = p->dom->lo[2], s = 0;
	for (size_t i = 0; i < p->n; i++) {
		double r = p->r[i];
		s += (p->x[2][i] - lo) * r * r * r;     /* Eq. 6.6 */
	}
	return s;
}

/* ---- uniform grid for insertion --------------------------------------------- */

static size_t cell_of(const pk_t *p, int k, double x)
{
	double f = floor((x - p->dom->lo[k]) / p->h);
	if (f < 0)
		return 0;
	if (f >= (double)p->gn[k])
		return p->gn[k] - 1;
	return (size_t)f;
}

static void grid_add(pk_t *p, size_t i)
{
	size_t c = (cell_of(p, 2, p->x[2][i]) * p->gn[1] + cell_of(p, 1, p->x[1][i])) * p->gn[0]
		   + cell_of(p, 0, p->x[0][i]);
	p->next[i] = p->head[c];
	p->head[c] = (uint32_t)i;
}

static void grid_build(pk_t *p)
{
	size_t nc = p->gn[0] * p->gn[1] * p->gn[2];
	for (size_t c = 0; c < nc; c++)
		p->head[c] = NONE;
	for (size_t i = 0; i < p->n; i++)
		grid_add(p, i);
}

/* Does a sphere at c of radius r overlap any placed sphere? */
static int grid_overlaps(const pk_t *p, const double *c, double r)
{
	size_t a[3], b[3];
	for (int k = 0; k < 3; k++) {
		a[k] = cell_of(p, k, c[k] - r - p->rmax);
		b[k] = cell_of(p, k, c[k] + r + p->rmax);
	}
	for (size_t z = a[2]; z <= b[2]; z++)
		for (size_t y = a[1]; y <= b[1]; y++)
			for (size_t x = a[0]; x <= b[0]; x++)
				for (uint32_t j = p->head[(z * p->gn[1] + y) * p->gn[0] + x];
				     j != NONE; j = p->next[j]) {
					double dx = c[0] - p->x[0][j], dy = c[1] - p->x[1][j];
					double dz = c[2] - p->x[2][j], s = r + p->r[j];
					if (dx * dx + dy * dy + dz * dz < s * s)
						return 1;
				}
	return 0;
}

/* Drop a sphere from c straight down (-z) to its first contact with a
 * sphere or a wall: Box 6.3, exactly, through the grid column above and
 * below it, scanned top-down and stopped once no lower cell can hold a
 * nearer obstacle. */
static double grid_drop(const pk_t *p, const double *c, double r)
{
	static const double down[3] = {0, 0, -1};
	double t = wall_limit(p->dom, c, r, down);
	size_t a[2], b[2];
	for (int k = 0; k < 2; k++) {
		a[k] = cell_of(p, k, c[k] - r - p->rmax);
		b[k] = cell_of(p, k, c[k] + r + p->rmax);
	}
	for (size_t z = cell_of(p, 2, c[2]) + 1; z-- > 0;) {
		/* any sphere at or below cell z stops the centre under
		 * lo + (z + 2) h */
		if (c[2] - t >= p->dom->lo[2] + (double)(z + 2) * p->h)
			break;
		for (size_t y = a[1]; y <= b[1]; y++)
			for (size_t x = a[0]; x <= b[0]; x++)
				for (uint32_t j = p->head[(z * p->gn[1] + y) * p->gn[0] + x];
				     j != NONE; j = p->next[j]) {
					double q[3] = {p->x[0][j], p->x[1][j], p->x[2][j]};
					t = fmin(t, pair_limit(c, q, r + p->r[j], down));
				}
	}
	return t;
}

/* Furthest move of a free sphere at c along unit v, at most maxd, against
 * the grid's spheres and the walls (Eqs. 6.1-6.3 for one sphere). */
static double grid_move(const pk_t *p, const double *c, double r,
			const double *v, double maxd)
{
	double t = fmin(maxd, wall_limit(p->dom, c, r, v));
	size_t a[3], b[3];
	for (int k = 0; k < 3; k++) {
		double e = c[k] + t * v[k];
		a[k] = cell_of(p, k, fmin(c[k], e) - r - p->rmax);
		b[k] = cell_of(p, k, fmax(c[k], e) + r + p->rmax);
	}
	for (size_t z = a[2]; z <= b[2]; z++)
		for (size_t y = a[1]; y <= b[1]; y++)
			for (size_t x = a[0]; x <= b[0]; x++)
				for (uint32_t j = p->head[(z * p->gn[1] + y) * p->gn[0] + x];
				     j != NONE; j = p->next[j]) {
					double q[3] = {p->x[0][j], p->x[1][j], p->x[2][j]};
					t = fmin(t, pair_limit(c, q, r + p->r[j], v));
				}
	return t;
}

/* One direction of the cone of Eq. 6.9 (random) or normal to -z (shake). */
static void cone(gsl_rng *g, double beta, int shake, double *v)
{
	double th = 2 * DEM_PI * gsl_rng_uniform(g);
	double a = 0, b = 1;
	if (!shake) {
		a = gsl_rng_uniform(g);
		b = beta * gsl_rng_uniform(g);
	}
	double len = sqrt(a * a + b * b);
	if (len > 1e-12) {
		v[0] = b * cos(th) / len;
		v[1] = b * sin(th) / len;
		v[2] = -a / len;
	} else {
		v[0] = v[1] = 0;
		v[2] = -1;
	}
}

/* Drop a new sphere and let it settle: the compression algorithm applied
 * to this single sphere (Ch. 6.2.2), a fall along -z followed by nroll
 * short moves in the cone of Eq. 6.9 with a wider cone (beta-bar 2), each
 * followed by a fall, so the sphere slides off its first support. */
static void settle_one(pk_t *p, double *c, double r)
{
	c[2] -= grid_drop(p, c, r);
	for (int k = 0; k < p->s->nroll; k++) {
		double v[3];
		cone(p->rng, 2, 0, v);
		double t = grid_move(p, c, r, v, p->rmax);
		for (int d = 0; d < 3; d++)
			c[d] += t * v[d];
		c[2] -= grid_drop(p, c, r);
	}
}

/* A uniform point of the box shrunk by r, inside every wall. */
static int draw_inside(pk_t *p, double r, double *c, double ztop)
{
	const dem_domain_t *d = p->dom;
	for (int k = 0; k < 2; k++)
		c[k] = d->lo[k] + r + gsl_rng_uniform(p->rng) * (d->hi[k] - d->lo[k] - 2 * r);
	c[2] = ztop < HUGE_VAL ? ztop
		: d->lo[2] + r + gsl_rng_uniform(p->rng) * (d->hi[2] - d->lo[2] - 2 * r);
	return wall_gap(d, c, r) >= 0;
}

static size_t max_reject(const pk_t *p)
{
	if (p->s->max_reject)
		return p->s->max_reject;
	const dem_domain_t *d = p->dom;
	double rm = 0.5 * (p->rmin + p->rmax);
	double a = (d->hi[0] - d->lo[0]) * (d->hi[1] - d->lo[1]) / (4 * rm * rm);
	return a > 50 ? (size_t)a : 50;
}

static int full(const pk_t *p)
{
	return p->s->max_n && p->n >= p->s->max_n;
}

/* Initial loose packing (Fig. 6.3a): spheres placed uniformly at random
 * without overlap until the fill fraction init_density, or M_r rejections
 * in a row.  A rejected sphere keeps its radius so the sizes follow the
 * law. */
static int initial(pk_t *p)
{
	double r = dem_radius_draw(&p->s->law, p->rng), c[3];
	size_t miss = 0, lim = 20 * max_reject(p);
	grid_build(p);
	while (p->volsum < p->s->init_density * p->vol && !full(p) && miss < lim) {
		if (!draw_inside(p, r, c, HUGE_VAL) || grid_overlaps(p, c, r)) {
			miss++;
			continue;
		}
		miss = 0;
		if (grow(p, p->n + 1))
			return p->e->code;
		add_sphere(p, c, r);
		grid_add(p, p->n - 1);
		r = dem_radius_draw(&p->s->law, p->rng);
	}
	return DEM_OK;
}

/* Box 6.3: spheres generated on the lid and dropped until M_r of them
 * overlapped where they were generated.  Returns the number added via
 * *added. */
static int refill(pk_t *p, size_t *added)
{
	size_t nr = 0, out = 0, mr = max_reject(p), n0 = p->n;
	double r = dem_radius_draw(&p->s->law, p->rng), c[3];
	grid_build(p);
	while (nr < mr && !full(p)) {
		if (!draw_inside(p, r, c, p->dom->hi[2] - r)) {
			if (++out > 100 * mr)   /* no lid left for this size */
				break;
			continue;
		}
		if (grid_overlaps(p, c, r)) {
			nr++;
			continue;
		}
		settle_one(p, c, r);
		p->zadd = fmin(p->zadd, c[2]);
		if (grow(p, p->n + 1))
			return p->e->code;
		add_sphere(p, c, r);
		grid_add(p, p->n - 1);
		r = dem_radius_draw(&p->s->law, p->rng);
	}
	*added = p->n - n0;
	return DEM_OK;
}

/* ---- compression ------------------------------------------------------------ */

static int cmp_zi(const void *a, const void *b)
{
	const struct zi *u = a, *w = b;
	if (u->z != w->z)
		return u->z < w->z ? -1 : 1;
	return (u->i > w->i) - (u->i < w->i);
}

/* Directions of one iteration: -z (global), normal to -z (shaking), or in
 * the cone of Eq. 6.9, v_l = alpha v_g + beta v_n, normalised. */
static void directions(pk_t *p, enum mode m)
{
	for (size_t i = 0; i < p->n; i++) {
		double v[3] = {0, 0, -1};
		if (m != GLOBAL)
			cone(p->rng, p->s->beta, m == SHAKE, v);
		for (int k = 0; k < 3; k++)
			p->v[k][i] = v[k];
	}
}

/* Box 6.1, "assign a bounding box with buffer zone" and "perform contact
 * detection": each box is the sphere's, stretched by its buffer b_u along
 * its own direction only (Ch. 6.2.3); the pairs become CSR lists. */
static int neighbours(pk_t *p)
{
	if (p->boxcap < p->n) {
		dem_boxes_free(&p->box);
		if (dem_boxes_alloc(&p->box, 3, p->cap) != DEM_OK)
			return dem_error_nomem(p->e, "bounding boxes");
		p->boxcap = p->cap;
	}
	p->box.n = p->n;
	for (int k = 0; k < 3; k++) {
		double *lo = p->box.lo[k], *hi = p->box.hi[k];
		const double *x = p->x[k], *v = p->v[k];
		for (size_t i = 0; i < p->n; i++) {
			double s = v[i] * p->bu[i];
			lo[i] = x[i] - p->r[i] + (s < 0 ? s : 0);
			hi[i] = x[i] + p->r[i] + (s > 0 ? s : 0);
		}
	}
	p->pairs.n = 0;
	int rc = dem_detect(&p->box, &p->dopt, &p->pairs, NULL, p->e);
	if (rc)
		return rc;
	if (p->pairs.nomem)
		return dem_error_nomem(p->e, "neighbour pairs");
	p->st.detections++;
	p->st.pairs += p->pairs.n;
	size_t m = 2 * p->pairs.n;
	if (m > p->adjcap) {
		uint32_t *a = realloc(p->adj, m * sizeof *a);
		if (!a)
			return dem_error_nomem(p->e, "neighbour lists");
		p->adj = a;
		p->adjcap = m;
	}
	size_t *off = p->off;
	memset(off, 0, (p->n + 1) * sizeof *off);
	for (size_t k = 0; k < p->pairs.n; k++) {
		off[p->pairs.p[k].i + 1]++;
		off[p->pairs.p[k].j + 1]++;
	}
	for (size_t i = 0; i < p->n; i++)
		off[i + 1] += off[i];
	/* fill each list from its end: off[i + 1] runs down to the start of
	 * list i, then the starts shift down one place */
	for (size_t k = 0; k < p->pairs.n; k++) {
		uint32_t i = p->pairs.p[k].i, j = p->pairs.p[k].j;
		p->adj[--off[i + 1]] = j;
		p->adj[--off[j + 1]] = i;
	}
	for (size_t i = 0; i < p->n; i++)
		off[i] = off[i + 1];
	off[p->n] = m;
	return DEM_OK;
}

/* One iteration of Box 6.1 along the directions of mode m: neighbours
 * found once, then each sphere, bottom-up (Ch. 6.2.3), moved by
 * d_i = min(d_j) (Eqs. 6.1, 6.2), capped by its buffer (Eq. 6.3) and the
 * walls, to X_i + d_i v (Eq. 6.4).  With mobility set, a sphere that did
 * not move last time is skipped unless a neighbour has moved since. */
static int iterate(pk_t *p, enum mode m, int mobility)
{
	directions(p, m);
	int rc = neighbours(p);
	if (rc)
		return rc;
	for (size_t i = 0; i < p->n; i++) {
		p->ord[i].z = p->x[2][i];
		p->ord[i].i = (uint32_t)i;
	}
	qsort(p->ord, p->n, sizeof *p->ord, cmp_zi);
	memset(p->mnow, 0, p->n);
	double still = 1e-6 * p->rmin;
	for (size_t k = 0; k < p->n; k++) {
		uint32_t i = p->ord[k].i;
		const uint32_t *nb = p->adj + p->off[i], *ne = p->adj + p->off[i + 1];
		if (mobility && !p->mprev[i]) {
			int wake = 0;
			for (const uint32_t *q = nb; q < ne && !wake; q++)
				wake = p->mprev[*q] | p->mnow[*q];
			if (!wake)
				continue;
		}
		double c[3] = {p->x[0][i], p->x[1][i], p->x[2][i]};
		double v[3] = {p->v[0][i], p->v[1][i], p->v[2][i]};
		double ri = p->r[i];
		double t = fmin(p->bu[i], wall_limit(p->dom, c, ri, v));
		for (const uint32_t *q = nb; q < ne; q++) {
			uint32_t j = *q;
			double cj[3] = {p->x[0][j], p->x[1][j], p->x[2][j]};
			t = fmin(t, pair_limit(c, cj, ri + p->r[j], v));
		}
		for (int d = 0; d < 3; d++)
			p->x[d][i] = c[d] + t * v[d];
		/* adaptive buffer: grow when the buffer was the limit, else
		 * follow the distance moved (Ch. 6.2.3) */
		double bu = t >= p->bu[i] ? 2 * p->bu[i] : 2 * t;
		p->bu[i] = fmin(p->bumax, fmax(p->bumin, bu));
		p->mnow[i] = t > still;
	}
	if (mobility) {
		unsigned char *tmp = p->mprev;
		p->mprev = p->mnow;
		p->mnow = tmp;
	}
	p->st.iters++;
	return DEM_OK;
}

static int converged(double pc, double pp, double tol)
{
	return pp == 0 || fabs(pc / pp - 1) <= tol;     /* Eq. 6.8 */
}

/* Repeat iterations of mode m until Eq. 6.8 holds or max_iter. */
static int settle(pk_t *p, enum mode m, int *iters)
{
	double pc = energy(p), pp;
	if (m == GLOBAL)
		memset(p->mprev, 1, p->n);
	int it = 0;
	do {
		pp = pc;
		int rc = iterate(p, m, m == GLOBAL && it > 0);
		if (rc)
			return rc;
		pc = energy(p);
		it++;
	} while (!converged(pc, pp, p->s->tol) && it < p->s->max_iter);
	*iters += it;
	return DEM_OK;
}

/* ---- relaxation under gravity (beyond the thesis) ------------------------- */

/* Move a sphere at c back inside every wall (projection onto each wall in
 * turn; the domain is convex, so a few rounds settle a small violation),
 * leaving the clearance margin. */
static void wall_project(const dem_domain_t *d, double *c, double r, double margin)
{
	double rr = r + margin;
	for (int round = 0; round < 4; round++) {
		for (int k = 0; k < 3; k++) {
			if (c[k] < d->lo[k] + rr)
				c[k] = d->lo[k] + rr;
			if (c[k] > d->hi[k] - rr)
				c[k] = d->hi[k] - rr;
		}
		if (d->cylinder) {
			double qx = c[0] - d->axis[0], qy = c[1] - d->axis[1];
			double q = sqrt(qx * qx + qy * qy), lim = d->radius - rr;
			if (q > lim) {
				c[0] = d->axis[0] + qx * lim / q;
				c[1] = d->axis[1] + qy * lim / q;
			}
		}
		int ok = 1;
		for (size_t k = 0; k < d->nplane; k++) {
			const dem_plane_t *pl = &d->plane[k];
			double g = pl->n[0] * c[0] + pl->n[1] * c[1] + pl->n[2] * c[2] - pl->d - rr;
			if (g < 0) {
				for (int m = 0; m < 3; m++)
					c[m] -= g * pl->n[m];
				ok = 0;
			}
		}
		if (ok)
			break;
	}
}

/* The relaxation moves only the active spheres, those above p->zfreeze
 * (the mobility of Ch. 6.2.3: deep spheres under a jammed packing do not
 * move); the others are fixed obstacles.  Neighbour pairs: D-cell over the
 * boxes, grown by skin/2 on every side, of the spheres that can touch an
 * active one, so the list holds every contact while no sphere moves more
 * than skin/2 from where it was at the build (the Verlet list rule); pairs
 * of two fixed spheres are dropped.  Spheres within skin of a wall are
 * flagged (mnow) for the wall terms. */
static int relax_pairs(pk_t *p, double skin)
{
	double zlow = HUGE_VAL;
	p->nact = 0;
	for (size_t i = 0; i < p->n; i++)
		if (p->isact[i]) {
			p->act[p->nact++] = (uint32_t)i;
			zlow = fmin(zlow, p->x[2][i]);
		}
	double zcut = zlow - 2 * p->rmax - skin;
	size_t m = 0;
	for (size_t i = 0; i < p->n; i++)
		if (p->x[2][i] > zcut)
			p->ord[m++].i = (uint32_t)i;   /* in the box set */
	if (p->boxcap < p->n) {
		dem_boxes_free(&p->box);
		if (dem_boxes_alloc(&p->box, 3, p->cap) != DEM_OK)
			return dem_error_nomem(p->e, "bounding boxes");
		p->boxcap = p->cap;
	}
	p->box.n = m;
	for (size_t b = 0; b < m; b++) {
		uint32_t i = p->ord[b].i;
		double h = p->r[i] + 0.5 * skin;
		for (int k = 0; k < 3; k++) {
			p->box.lo[k][b] = p->x[k][i] - h;
			p->box.hi[k][b] = p->x[k][i] + h;
			p->v[k][i] = p->x[k][i];        /* where the list was built */
		}
		double c[3] = {p->x[0][i], p->x[1][i], p->x[2][i]};
		p->mnow[i] = wall_gap(p->dom, c, p->r[i]) < skin;
	}
	p->pairs.n = 0;
	int rc = dem_detect(&p->box, &p->dopt, &p->pairs, NULL, p->e);
	if (rc)
		return rc;
	if (p->pairs.nomem)
		return dem_error_nomem(p->e, "neighbour pairs");
	p->st.detections++;
	p->st.pairs += p->pairs.n;
	if (p->adjcap < 2 * p->pairs.n) {
		uint32_t *a = realloc(p->adj, 2 * p->pairs.n * sizeof *a);
		if (!a)
			return dem_error_nomem(p->e, "neighbour lists");
		p->adj = a;
		p->adjcap = 2 * p->pairs.n;
	}
	size_t q = 0;
	for (size_t k = 0; k < p->pairs.n; k++) {
		uint32_t i = p->ord[p->pairs.p[k].i].i, j = p->ord[p->pairs.p[k].j].i;
		if (!p->isact[i] && !p->isact[j])
			continue;
		p->adj[2 * q] = i;
		p->adj[2 * q + 1] = j;
		q++;
	}
	p->npair = q;
	return DEM_OK;
}

static int active(const pk_t *p, uint32_t i)
{
	return p->isact[i];
}

static void put(pk_t *p, uint32_t i, double *c, double margin)
{
	if (p->mnow[i])
		wall_project(p->dom, c, p->r[i], margin);
	p->x[0][i] = c[0];
	p->x[1][i] = c[1];
	p->x[2][i] = c[2];
}

/* One Gauss-Seidel sweep over the pair list: each overlapping pair (closer
 * than the radii plus margin) pushed apart along its centre line, the
 * shares in inverse proportion to the masses (r^3; a fixed sphere does not
 * move), each moved sphere put back inside the walls.  Returns the deepest
 * overlap met, relative to the smaller radius. */
static double relax_sweep(pk_t *p, double margin)
{
	double worst = 0;
	const uint32_t *a = p->adj;
	const double *x = p->x[0], *y = p->x[1], *z = p->x[2], *r = p->r;
	for (size_t k = 0; k < p->npair; k++) {
		uint32_t i = a[2 * k], j = a[2 * k + 1];
		double dx = x[j] - x[i], dy = y[j] - y[i], dz = z[j] - z[i];
		double s = r[i] + r[j] + margin, d2 = dx * dx + dy * dy + dz * dz;
		if (d2 >= s * s)
			continue;
		double d = sqrt(d2), ov = s - d;
		worst = fmax(worst, (ov - margin) / fmin(r[i], r[j]));
		if (d == 0) {
			dz = d = 1;
		}
		double wi = active(p, i) ? r[j] * r[j] * r[j] : 0;
		double wj = active(p, j) ? r[i] * r[i] * r[i] : 0;
		if (wi + wj == 0)
			continue;
		double fi = ov * wi / ((wi + wj) * d), fj = ov * wj / ((wi + wj) * d);
		double ci[3] = {x[i] - fi * dx, y[i] - fi * dy, z[i] - fi * dz};
		double cj[3] = {x[j] + fj * dx, y[j] + fj * dy, z[j] + fj * dz};
		if (wi > 0)
			put(p, i, ci, margin);
		if (wj > 0)
			put(p, j, cj, margin);
	}
	return worst;
}

/* Contact forces of the soft relaxation: a linear spring of stiffness k on
 * every overlap between spheres or with a wall, and the weight m g along
 * -z (g = 0: none), m = (r / Rmin)^3.  Returns the deepest overlap,
 * relative to the smaller radius. */
static double forces(pk_t *p, double k, double g)
{
	const uint32_t *a = p->adj;
	const double *x = p->x[0], *y = p->x[1], *z = p->x[2], *r = p->r;
	double *fx = p->f[0], *fy = p->f[1], *fz = p->f[2], worst = 0;
	const dem_domain_t *d = p->dom;
	for (size_t q = 0; q < p->nact; q++) {
		uint32_t i = p->act[q];
		double m = r[i] / p->rmin;
		fx[i] = fy[i] = 0;
		fz[i] = -g * m * m * m;
	}
	for (size_t q = 0; q < p->npair; q++) {
		uint32_t i = a[2 * q], j = a[2 * q + 1];
		double dx = x[j] - x[i], dy = y[j] - y[i], dz = z[j] - z[i];
		double s = r[i] + r[j], d2 = dx * dx + dy * dy + dz * dz;
		if (d2 >= s * s || d2 == 0)
			continue;
		double dd = sqrt(d2), ov = s - dd, f = k * ov / dd;
		if (ov > worst * r[i] || ov > worst * r[j])
			worst = ov / (r[i] < r[j] ? r[i] : r[j]);
		/* a fixed sphere's force is computed and never used */
		fx[i] -= f * dx; fy[i] -= f * dy; fz[i] -= f * dz;
		fx[j] += f * dx; fy[j] += f * dy; fz[j] += f * dz;
	}
	for (size_t q = 0; q < p->nact; q++) {
		uint32_t i = p->act[q];
		if (!p->mnow[i])
			continue;       /* far from every wall */
		double c[3] = {x[i], y[i], z[i]}, *fc[3] = {&fx[i], &fy[i], &fz[i]};
		for (int e = 0; e < 3; e++) {
			double lo = r[i] - (c[e] - d->lo[e]), hi = r[i] - (d->hi[e] - c[e]);
			if (lo > 0)
				*fc[e] += k * lo;
			if (hi > 0)
				*fc[e] -= k * hi;
			worst = fmax(worst, fmax(lo, hi) / r[i]);
		}
		if (d->cylinder) {
			double qx = c[0] - d->axis[0], qy = c[1] - d->axis[1];
			double qq = sqrt(qx * qx + qy * qy), ov = qq + r[i] - d->radius;
			if (ov > 0 && qq > 0) {
				fx[i] -= k * ov * qx / qq;
				fy[i] -= k * ov * qy / qq;
				worst = fmax(worst, ov / r[i]);
			}
		}
		for (size_t e = 0; e < d->nplane; e++) {
			const dem_plane_t *pl = &d->plane[e];
			double ov = r[i] - (pl->n[0] * c[0] + pl->n[1] * c[1] + pl->n[2] * c[2] - pl->d);
			if (ov > 0) {
				for (int m = 0; m < 3; m++)
					*fc[m] += k * ov * pl->n[m];
				worst = fmax(worst, ov / r[i]);
			}
		}
	}
	return worst;
}

/* Eq. 6.7 over the active spheres. */
static double active_energy(const pk_t *p)
{
	double s = 0;
	for (size_t q = 0; q < p->nact; q++) {
		uint32_t i = p->act[q];
		double r = p->r[i];
		s += (p->x[2][i] - p->dom->lo[2]) * r * r * r;
	}
	return s;
}

/* FIRE minimisation (Bitzek et al. 2006, with the parameters of their
 * paper) of the soft energy over the active spheres.  With gravity g > 0
 * it stops when the mean fall of the active spheres over `window` steps is
 * below ftol Rmin (the energy test of Eq. 6.8 in another form); with g = 0
 * when no overlap is deeper than otol of the smaller radius. */
static int fire(pk_t *p, double k, double g, double ftol, double otol,
		int maxsteps, double skin, int *steps)
{
	const double finc = 1.1, fdec = 0.5, a0 = 0.1, fa = 0.99;
	const int nmin = 5, window = 100;
	double t0 = sqrt(1 / k);        /* m = 1 for Rmin */
	double dt = 0.05 * t0, dtmax = p->s->relax_dt * t0, alpha = a0;
	for (size_t q = 0; q < p->nact; q++)
		for (int d = 0; d < 3; d++)
			p->u[d][p->act[q]] = 0;
	double r3 = 0;
	for (size_t q = 0; q < p->nact; q++)
		r3 += pow(p->r[p->act[q]], 3);
	int rc, since = 0, s;
	double worst = forces(p, k, g), pe = active_energy(p);
	for (s = 0; s < maxsteps; s++) {
		if (g == 0 && worst <= otol)
			break;
		if (g > 0 && s > 0 && s % window == 0) {
			double pn = active_energy(p);
			if (pe - pn < ftol * p->rmin * r3)
				break;
			pe = pn;
		}
		double fv = 0, ff = 0, vv = 0;
		for (size_t q = 0; q < p->nact; q++) {
			uint32_t i = p->act[q];
			double f0 = p->f[0][i], f1 = p->f[1][i], f2 = p->f[2][i];
			double u0 = p->u[0][i], u1 = p->u[1][i], u2 = p->u[2][i];
			fv += f0 * u0 + f1 * u1 + f2 * u2;
			ff += f0 * f0 + f1 * f1 + f2 * f2;
			vv += u0 * u0 + u1 * u1 + u2 * u2;
		}
		double mix = 0, keep = 0;
		if (fv > 0) {
			mix = alpha * sqrt(vv / (ff > 1e-300 ? ff : 1e-300));
			keep = 1 - alpha;
			if (++since > nmin) {
				dt = dt * finc < dtmax ? dt * finc : dtmax;
				alpha *= fa;
			}
		} else {        /* uphill: stop, restart slowly */
			since = 0;
			dt *= fdec;
			alpha = a0;
		}
		/* v <- (1 - a) v + a |v| F/|F|; then semi-implicit Euler; the
		 * largest move since the list build along the way */
		double far = 0;
		for (size_t q = 0; q < p->nact; q++) {
			uint32_t i = p->act[q];
			double im = p->im[i], w = 0;
			for (int d = 0; d < 3; d++) {
				double u = keep * p->u[d][i] + mix * p->f[d][i] + dt * im * p->f[d][i];
				double x = p->x[d][i] + dt * u;
				p->u[d][i] = u;
				p->x[d][i] = x;
				w += (x - p->v[d][i]) * (x - p->v[d][i]);
			}
			far = w > far ? w : far;
		}
		if (far > 0.0625 * skin * skin && (rc = relax_pairs(p, skin)))
			return rc;
		worst = forces(p, k, g);
	}
	*steps += s;
	p->st.steps += (size_t)s;
	return DEM_OK;
}

/* Renumber the spheres in cell order (cells of the insertion grid, x
 * fastest), so neighbours sit close in memory during the relaxation. */
static void reorder(pk_t *p)
{
	for (size_t i = 0; i < p->n; i++) {
		size_t c = (cell_of(p, 2, p->x[2][i]) * p->gn[1] + cell_of(p, 1, p->x[1][i]))
			   * p->gn[0] + cell_of(p, 0, p->x[0][i]);
		p->ord[i].z = (double)c;
		p->ord[i].i = (uint32_t)i;
	}
	qsort(p->ord, p->n, sizeof *p->ord, cmp_zi);
	double *a[] = {p->x[0], p->x[1], p->x[2], p->r, p->im, p->bu};
	double *tmp = p->f[0];
	for (size_t k = 0; k < sizeof a / sizeof *a; k++) {
		for (size_t i = 0; i < p->n; i++)
			tmp[i] = a[k][p->ord[i].i];
		memcpy(a[k], tmp, p->n * sizeof *tmp);
	}
}

/* The last resort when the sweeps leave an overlap (rare: seen where a
 * plane meets the cylinder in a wedge): the upper sphere of every pair still overlapping, and any sphere
 * across a wall, is taken out, so the packing stays valid; counted in
 * stats.removed. */
static void drop_offenders(pk_t *p)
{
	unsigned char *out = p->mprev;
	memset(out, 0, p->n);
	for (size_t k = 0; k < p->npair; k++) {
		uint32_t i = p->adj[2 * k], j = p->adj[2 * k + 1];
		double dx = p->x[0][j] - p->x[0][i], dy = p->x[1][j] - p->x[1][i];
		double dz = p->x[2][j] - p->x[2][i], s = p->r[i] + p->r[j];
		double lim = s - ACCEPT * fmin(p->r[i], p->r[j]);
		if (dx * dx + dy * dy + dz * dz < lim * lim && !out[i] && !out[j])
			out[dz > 0 && active(p, j) ? j : active(p, i) ? i : j] = 1;
	}
	size_t m = 0;
	for (size_t i = 0; i < p->n; i++) {
		double c[3] = {p->x[0][i], p->x[1][i], p->x[2][i]}, r = p->r[i];
		if (out[i] || wall_gap(p->dom, c, r) < -ACCEPT * r) {
			p->volsum -= sphere_volume(r);
			p->r3sum -= r * r * r;
			p->st.removed++;
			continue;
		}
		for (int d = 0; d < 3; d++)
			p->x[d][m] = c[d];
		p->r[m] = r;
		p->im[m] = p->im[i];
		p->bu[m] = p->bu[i];
		m++;
	}
	p->n = m;
}

/* Relaxation (beyond the thesis): the active spheres settle under their
 * weight along the compression direction as frictionless soft spheres,
 * the energy of overlap springs plus Eq. 6.7 minimised by FIRE -- so they
 * slide past one another collectively, which the move-to-contact steps of
 * Boxes 6.1-6.2 cannot do (frictionless spheres settled so reach random
 * close packing: Silbert et al. 2002).  The spring is as stiff as makes the
 * deepest overlap about relax_overlap Rmin under the column's weight.  The
 * weight is then taken off and FIRE runs until no overlap is deeper than
 * 1e-6 of a radius, the packing expanding upwards into the free space;
 * Gauss-Seidel projection sweeps then leave a gap of 1e-12 Rmin at every
 * contact and wall. */
static int relax(pk_t *p, int *iters)
{
	double skin = p->s->relax_skin * p->rmin;
	reorder(p);
	/* the active set is fixed for the whole relaxation */
	for (size_t i = 0; i < p->n; i++)
		p->isact[i] = p->x[2][i] > p->zfreeze;
	for (int d = 0; d < 3; d++)
		memcpy(p->xb[d], p->x[d], p->n * sizeof *p->xb[d]);
	double pe0 = energy(p);
	size_t n0 = p->n;
	int rc = relax_pairs(p, skin);
	if (rc)
		return rc;
	double rm = 0.5 * (p->rmin + p->rmax), m = pow(rm / p->rmin, 3);
	double layers = (p->dom->hi[2] - p->dom->lo[2]) / (2 * rm);
	double k = layers * m / (p->s->relax_overlap * p->rmin);       /* g = 1 */
	int it = 0;
	if ((rc = fire(p, k, 1, p->s->relax_ftol, 0, p->s->relax_iter, skin, &it)))
		return rc;
	if ((rc = fire(p, k, 0, 0, 1e-6, p->s->relax_iter, skin, &it)))
		return rc;
	if ((rc = relax_pairs(p, skin)))
		return rc;
	for (size_t q = 0; q < p->nact; q++) {
		uint32_t i = p->act[q];
		double c[3] = {p->x[0][i], p->x[1][i], p->x[2][i]};
		put(p, i, c, 1e-12 * p->rmin);
	}
	double w = 1;
	for (int sw = 0; sw < 2000 && w > ACCEPT; sw++)
		w = relax_sweep(p, 1e-12 * p->rmin);
	if (w > ACCEPT)
		drop_offenders(p);
	/* kept only if it lowered Eq. 6.7: the expansion on unloading can
	 * outweigh a small settlement */
	if (p->n == n0 && energy(p) > pe0)
		for (int d = 0; d < 3; d++)
			memcpy(p->x[d], p->xb[d], p->n * sizeof *p->x[d]);
	*iters += it;
	return DEM_OK;
}

static int report(pk_t *p, dem_compress_phase_t ph, int batch, size_t added,
		  int iters)
{
	if (!p->s->stage)
		return 0;
	dem_compress_stage_t s = {
		.phase = ph, .batch = batch, .n = p->n, .added = added,
		.iters = iters, .density = p->volsum / p->vol,
		.pe = energy(p), .seconds = now(p),
		.x = {p->x[0], p->x[1], p->x[2]}, .r = p->r,
	};
	return p->s->stage(p->s->stage_ctx, &s);
}

/* Box 6.2: global compression, then rounds of shaking and random
 * compression until the energy stops falling. */
static int compress(pk_t *p, int batch, size_t added)
{
	int it = 0, rc = settle(p, GLOBAL, &it);
	if (rc || (rc = report(p, DEM_COMPRESS_GLOBAL, batch, 0, it)))
		return rc;
	it = 0;
	double pc = energy(p), pp;
	int loop = 0;
	do {
		pp = pc;
		for (int k = 0; k < p->s->nshake; k++, it++)
			if ((rc = iterate(p, SHAKE, 0)))
				return rc;
		if ((rc = settle(p, RANDOM, &it)))
			return rc;
		pc = energy(p);
	} while (!converged(pc, pp, p->s->tol) && ++loop < p->s->max_loops);
	if ((rc = report(p, DEM_COMPRESS_SHAKE, batch, 0, it)) || !p->s->relax
	    || (double)added < p->s->relax_batch * (double)p->n)
		return rc;
	it = 0;
	if ((rc = relax(p, &it)))
		return rc;
	if ((rc = settle(p, GLOBAL, &it)))
		return rc;
	return report(p, DEM_COMPRESS_RELAX, batch, 0, it);
}

/* ---- the whole ------------------------------------------------------------ */

static double domain_volume(const dem_domain_t *d)
{
	if (d->volume > 0)
		return d->volume;
	double w[3];
	for (int k = 0; k < 3; k++)
		w[k] = d->hi[k] - d->lo[k];
	if (!d->nplane)
		return d->cylinder ? DEM_PI * d->radius * d->radius * w[2]
				   : w[0] * w[1] * w[2];
	enum { M = 200 };
	size_t in = 0;
	for (int a = 0; a < M; a++)
		for (int b = 0; b < M; b++)
			for (int c = 0; c < M; c++) {
				double q[3] = {d->lo[0] + (a + 0.5) * w[0] / M,
					       d->lo[1] + (b + 0.5) * w[1] / M,
					       d->lo[2] + (c + 0.5) * w[2] / M};
				in += wall_gap(d, q, 0) >= 0;
			}
	return w[0] * w[1] * w[2] * (double)in / ((double)M * M * M);
}

static int check_spec(const dem_compress_spec_t *s, dem_error_t *e)
{
	const dem_domain_t *d = &s->dom;
	const dem_radius_law_t *l = &s->law;
	if (!(l->rmin > 0) || !(l->rmax >= l->rmin))
		return dem_error_set(e, DEM_EINPUT, "radius law: need 0 < rmin <= rmax");
	for (int k = 0; k < 3; k++)
		if (!(d->hi[k] - d->lo[k] > 2 * l->rmax))
			return dem_error_set(e, DEM_EINPUT,
					     "domain: axis %d narrower than the largest sphere", k);
	if (d->cylinder && !(d->radius > l->rmax))
		return dem_error_set(e, DEM_EINPUT, "domain: cylinder narrower than the largest sphere");
	for (size_t k = 0; k < d->nplane; k++) {
		const double *n = d->plane[k].n;
		if (fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1) > 1e-9)
			return dem_error_set(e, DEM_EINPUT, "domain: plane %zu: normal not of unit length", k);
	}
	if (!(s->tol > 0) || s->nshake < 0 || !(s->beta >= 0) || s->max_iter < 1 || s->nroll < 0
	    || s->max_loops < 1 || s->max_batches < 0 || !(s->buffer > 0)
	    || !(s->init_density >= 0 && s->init_density < 1))
		return dem_error_set(e, DEM_EINPUT, "compression: bad accuracy settings");
	return DEM_OK;
}

static void release(pk_t *p)
{
	double *dv[] = {p->x[0], p->x[1], p->x[2], p->r, p->bu, p->v[0], p->v[1], p->v[2],
			p->u[0], p->u[1], p->u[2], p->f[0], p->f[1], p->f[2], p->im,
			p->xb[0], p->xb[1], p->xb[2]};
	for (size_t k = 0; k < sizeof dv / sizeof *dv; k++)
		free(dv[k]);
	free(p->mprev);
	free(p->mnow);
	free(p->ord);
	free(p->off);
	free(p->adj);
	free(p->head);
	free(p->next);
	free(p->act);
	free(p->isact);
	dem_boxes_free(&p->box);
	dem_pairs_free(&p->pairs);
	dem_detect_ws_free(p->ws);
}



/* The densities of the finished packing besides the whole domain's:
 * below the top of the packing (the highest sphere's top), and in its core
 * -- the points of the domain at least one largest diameter from every
 * wall and below the top less one diameter.  Points of a stratified
 * sample (one in each cube of side Rmin / 2, placed at random in it)
 * count as covered when inside a sphere. */
static void measure(pk_t *p)
{
	const dem_domain_t *d = p->dom;
	double ztop = d->lo[2], h = 0.5 * p->rmin, layer = 2 * p->rmax;
	for (size_t i = 0; i < p->n; i++)
		ztop = fmax(ztop, p->x[2][i] + p->r[i]);
	p->st.ztop = ztop;
	grid_build(p);
	size_t m[3], in[2] = {0, 0}, cov[2] = {0, 0};
	for (int k = 0; k < 3; k++)
		m[k] = (size_t)ceil((d->hi[k] - d->lo[k]) / h);
	for (size_t c = 0; c < m[2]; c++)
		for (size_t b = 0; b < m[1]; b++)
			for (size_t a = 0; a < m[0]; a++) {
				double q[3] = {d->lo[0] + ((double)a + gsl_rng_uniform(p->rng)) * h,
					       d->lo[1] + ((double)b + gsl_rng_uniform(p->rng)) * h,
					       d->lo[2] + ((double)c + gsl_rng_uniform(p->rng)) * h};
				if (q[2] > ztop)
					continue;
				double g = wall_gap(d, q, 0);
				if (g < 0)
					continue;
				int core = g >= layer && q[2] <= ztop - layer;
				int hit = grid_overlaps(p, q, 0);
				in[0]++;
				cov[0] += (size_t)hit;
				in[1] += (size_t)core;
				cov[1] += (size_t)(core && hit);
			}
	p->st.density_top = in[0] ? (double)cov[0] / (double)in[0] : 0;
	p->st.density_core = in[1] ? (double)cov[1] / (double)in[1] : 0;
}

static int run(pk_t *p)
{
	int rc = initial(p);
	if (rc || (rc = report(p, DEM_COMPRESS_INIT, 0, p->n, 0)))
		return rc;
	p->zfreeze = -HUGE_VAL;
	size_t added = p->n;
	for (int batch = 0;; batch++) {
		if ((rc = compress(p, batch, added)))
			return rc;
		if (batch >= p->s->max_batches || full(p))
			break;
		added = 0;
		p->zadd = HUGE_VAL;
		if ((rc = refill(p, &added)))
			return rc;
		if ((rc = report(p, DEM_COMPRESS_REFILL, batch + 1, added, 0)))
			return rc;
		if (!added)
			break;
		p->zfreeze = p->zadd - 2 * p->rmax * p->s->relax_depth;
		p->st.batches++;
	}
	return DEM_OK;
}

int dem_pack_compress(const dem_compress_spec_t *s, gsl_rng *r,
		      dem_compress_emit_fn emit, void *ctx,
		      dem_compress_stats_t *stats, dem_error_t *e)
{
	int rc = check_spec(s, e);
	if (rc)
		return rc;
	pk_t p = {.s = s, .dom = &s->dom, .rng = r, .e = e};
	clock_gettime(CLOCK_MONOTONIC, &p.t0);
	p.vol = domain_volume(&s->dom);
	p.rmin = s->law.rmin;
	p.rmax = s->law.kind == DEM_RADIUS_MONO ? s->law.rmin : s->law.rmax;
	p.bumax = s->buffer * p.rmax;
	p.bumin = 0.02 * p.rmin;
	p.h = 2 * p.rmax;
	size_t nc = 1;
	for (int k = 0; k < 3; k++) {
		p.gn[k] = (size_t)ceil((s->dom.hi[k] - s->dom.lo[k]) / p.h);
		nc *= p.gn[k];
	}
	dem_detect_opts_init(&p.dopt);
	p.ws = dem_detect_ws_new();
	p.dopt.ws = p.ws;
	p.head = malloc(nc * sizeof *p.head);
	if (!p.ws || !p.head)
		rc = dem_error_nomem(e, "packing grid");
	else
		rc = grow(&p, 1);
	if (!rc)
		rc = run(&p);
	if (!rc && p.n)
		measure(&p);
	p.st.n = p.n;
	p.st.density = p.volsum / p.vol;
	p.st.pe = energy(&p);
	p.st.seconds = now(&p);
	if (stats)      /* complete before the first emit, for a header */
		*stats = p.st;
	for (size_t i = 0; !rc && emit && i < p.n; i++) {
		double c[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
		rc = emit(ctx, c, p.r[i]);
	}
	release(&p);
	return rc;
}
