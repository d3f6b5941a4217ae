/* shotset.c - the shots of a pass against the block's top surface.  See
 * shotset.h. */
#include "shot/shotset.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/facet.h"
#include "contact/sphere.h"
#include "contact/vec3.h"
#include "core/consts.h"
#include "core/cost.h"
#include "detect/detect.h"

/* A sphere/facet candidate's result at this step, for the scatter. */
typedef struct pair_out {
	dem_facet_geom_t g;       /* geometry at x_n (when touch) */
	double Fnode[3][3];
	double K;                 /* the pair's stiffness gamma K_L (Box 3.1), for the nodes' step */
	int touch;
} pair_out_t;

typedef void (*integrate_fn)(dem_shotset_t *S, double h, double dt);

struct dem_shotset {
	const dem_mesh_t *mesh;
	const double *node_mass;
	dem_contact_model_t cm;
	dem_shotset_opts_t o;
	integrate_fn integrate;

	/* surface */
	size_t nf, ntop;
	uint32_t (*fnode)[3];     /* facet nodes, anticlockwise from above */
	double *fmass;            /* facet masses */
	double *Knode;            /* contact stiffness summed on each node this step (zero between) */
	uint32_t *top;            /* surface nodes */
	double *xtop;             /* their coordinates at the last build */
	/* what a shot out of contact must reach to touch the block: the box
	 * of the top surface grown by the buffer it may have moved since,
	 * down to the base; of the undeformed mesh (ref) and at the last
	 * build (at) */
	double ref_lo[3], ref_hi[3], at_lo[3], at_hi[3];

	/* shots */
	size_t ns, scap;
	dem_shot_body_t *b;
	double *xshot;            /* centres at the last build */
	double (*T)[3];           /* torques on the shots at this step */
	double dt_prev;

	/* sphere/facet candidates, per shot (CSR), facets increasing */
	size_t *off, *off_old;
	uint32_t *cf, *cf_old;
	dem_contact_state_t *cs, *cs_old;
	pair_out_t *po;
	size_t ncand, ccap;       /* all five candidate arrays have ccap */

	/* sphere/sphere candidates (s1 < s2), increasing */
	uint32_t (*sp)[2], (*sp_old)[2];
	dem_contact_state_t *ss, *ss_old;
	size_t nsp, nsp_old, spcap;   /* all four pair arrays have spcap */

	/* detection */
	dem_boxes_t boxes;
	size_t boxcap;
	dem_pairs_t pairs;
	dem_detect_ws_t *ws;
	int built;

	double dt_next;
	int prepared;             /* geometry of this step done by dem_shotset_prepare */
	dem_shotset_stats_t st;
};

/* ---- set-up ------------------------------------------------------------- */

static void integrate_translation(dem_shotset_t *S, double h, double dt)
{
	for (size_t s = 0; s < S->ns; s++) {
		dem_shot_body_t *b = &S->b[s];
		double a = h / b->M;
		for (int i = 0; i < 3; i++) {
			b->v[i] += b->F[i] * a;
			b->x[i] += b->v[i] * dt;
		}
	}
}

/* With friction: the torques of the contacts turn the shot too (Eq. 7.2
 * for the rotation, I = 2/5 M R^2 of a solid sphere). */
static void integrate_spin(dem_shotset_t *S, double h, double dt)
{
	for (size_t s = 0; s < S->ns; s++) {
		dem_shot_body_t *b = &S->b[s];
		double a = h / b->M, ai = h / (0.4 * b->M * b->R * b->R);
		for (int i = 0; i < 3; i++) {
			b->v[i] += b->F[i] * a;
			b->w[i] += S->T[s][i] * ai;
			b->x[i] += b->v[i] * dt;
		}
	}
}

/* The box lo..hi of the top surface nodes at x (S->top), grown by the
 * buffer, down to the block's base. */
static void top_box(const dem_shotset_t *S, const double *x, double lo[3], double hi[3])
{
	lo[0] = lo[1] = HUGE_VAL;
	lo[2] = S->mesh->gz[0];
	hi[0] = hi[1] = hi[2] = -HUGE_VAL;
	for (size_t k = 0; k < S->ntop; k++) {
		const double *p = x + 3 * (size_t)S->top[k];
		for (int i = 0; i < 3; i++) {
			if (i < 2)
				lo[i] = fmin(lo[i], p[i] - S->o.buffer);
			hi[i] = fmax(hi[i], p[i] + S->o.buffer);
		}
	}
}

static int facets_build(dem_shotset_t *S, dem_error_t *e)
{
	const dem_mesh_t *m = S->mesh;
	int nx = m->nx, ny = m->ny, nz = m->nz;
	size_t nf = 2 * (size_t)nx * (size_t)ny;
	size_t ntop = (size_t)(nx + 1) * (size_t)(ny + 1);
	unsigned *deg = calloc(m->nn, sizeof *deg);

	S->fnode = malloc(nf * sizeof *S->fnode);
	S->fmass = malloc(nf * sizeof *S->fmass);
	S->top = malloc(ntop * sizeof *S->top);
	S->xtop = malloc(3 * ntop * sizeof *S->xtop);
	if (!deg || !S->fnode || !S->fmass || !S->top || !S->xtop) {
		free(deg);
		return dem_error_nomem(e, "shot surface");
	}
	size_t f = 0;
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++) {
			uint32_t q[4] = {
				(uint32_t)dem_mesh_node(m, i, j, nz),
				(uint32_t)dem_mesh_node(m, i + 1, j, nz),
				(uint32_t)dem_mesh_node(m, i + 1, j + 1, nz),
				(uint32_t)dem_mesh_node(m, i, j + 1, nz) };
			/* alternate the diagonal: (0 1 2)(0 2 3) or (0 1 3)(1 2 3) */
			static const int t[2][2][3] = { { { 0, 1, 2 }, { 0, 2, 3 } },
							{ { 0, 1, 3 }, { 1, 2, 3 } } };
			int p = (i + j) & 1;
			for (int k = 0; k < 2; k++, f++)
				for (int a = 0; a < 3; a++) {
					S->fnode[f][a] = q[t[p][k][a]];
					deg[S->fnode[f][a]]++;
				}
		}
	for (f = 0; f < nf; f++) {
		double mf = 0;
		for (int a = 0; a < 3; a++)
			mf += S->node_mass[S->fnode[f][a]] / deg[S->fnode[f][a]];
		S->fmass[f] = mf;
	}
	size_t n = 0;
	for (int j = 0; j <= ny; j++)
		for (int i = 0; i <= nx; i++)
			S->top[n++] = (uint32_t)dem_mesh_node(m, i, j, nz);
	S->nf = nf;
	S->ntop = ntop;
	top_box(S, m->X, S->ref_lo, S->ref_hi);
	free(deg);
	return DEM_OK;
}

int dem_shotset_create(dem_shotset_t **Sp, const dem_mesh_t *mesh, const double *node_mass,
		       const dem_contact_model_t *cm, const dem_shotset_opts_t *o,
		       dem_error_t *e)
{
	*Sp = NULL;
	if (!(o->rho > 0) || !isfinite(o->rho))
		return dem_error_set(e, DEM_EINPUT, "shot density must be > 0 (got %g)", o->rho);
	if (!(o->buffer > 0) || !isfinite(o->buffer))
		return dem_error_set(e, DEM_EINPUT, "candidate buffer must be > 0 (got %g m)", o->buffer);
	if (!(o->gap >= 0) || !isfinite(o->gap))
		return dem_error_set(e, DEM_EINPUT, "start gap must be >= 0 (got %g m)", o->gap);
	if (!(o->lambda > 0 && o->lambda <= 1))
		return dem_error_set(e, DEM_EINPUT, "time step factor lambda must be in (0, 1] (got %g)", o->lambda);
	if (mesh->nx < 1 || mesh->ny < 1)
		return dem_error_set(e, DEM_EINPUT, "the block has no top surface");
	dem_shotset_t *S = calloc(1, sizeof *S);
	if (!S)
		return dem_error_nomem(e, "shots");
	S->mesh = mesh;
	S->node_mass = node_mass;
	S->cm = *cm;
	S->o = *o;
	S->integrate = cm->p.friction ? integrate_spin : integrate_translation;
	S->dt_next = HUGE_VAL;
	dem_pairs_init(&S->pairs);
	S->ws = dem_detect_ws_new();
	S->off = calloc(1, sizeof *S->off);
	S->off_old = calloc(1, sizeof *S->off_old);
	S->Knode = calloc(mesh->nn, sizeof *S->Knode);
	if (!S->ws || !S->off || !S->off_old || !S->Knode || facets_build(S, e)) {
		dem_shotset_free(S);
		return e->code ? e->code : dem_error_nomem(e, "shots");
	}
	*Sp = S;
	return DEM_OK;
}

void dem_shotset_free(dem_shotset_t *S)
{
	if (!S)
		return;
	free(S->fnode), free(S->fmass), free(S->Knode), free(S->top), free(S->xtop);
	free(S->b), free(S->xshot), free(S->T);
	free(S->off), free(S->off_old), free(S->cf), free(S->cf_old);
	free(S->cs), free(S->cs_old), free(S->po);
	free(S->sp), free(S->sp_old), free(S->ss), free(S->ss_old);
	dem_boxes_free(&S->boxes);
	dem_pairs_free(&S->pairs);
	dem_detect_ws_free(S->ws);
	free(S);
}

/* ---- a pass ------------------------------------------------------------ */

int dem_shotset_begin(dem_shotset_t *S, size_t n, const dem_shot_t *sh, const double *x,
		      dem_error_t *e)
{
	const dem_mesh_t *m = S->mesh;
	double z0 = m->gz[m->nz];

	if (n > S->scap) {
		dem_shot_body_t *b = realloc(S->b, n * sizeof *b);
		if (b)
			S->b = b;
		double *xs = realloc(S->xshot, 3 * n * sizeof *xs);
		if (xs)
			S->xshot = xs;
		size_t *off = realloc(S->off, (n + 1) * sizeof *off);
		if (off)
			S->off = off;
		size_t *oo = realloc(S->off_old, (n + 1) * sizeof *oo);
		if (oo)
			S->off_old = oo;
		double (*T)[3] = realloc(S->T, n * sizeof *T);
		if (T)
			S->T = T;
		if (!b || !xs || !off || !oo || !T)
			return dem_error_nomem(e, "shots");
		S->scap = n;
	}
	S->ns = 0;
	S->built = 0;
	S->ncand = 0;
	S->nsp = 0;
	S->dt_prev = 0;
	memset(S->off, 0, (n + 1) * sizeof *S->off);
	for (size_t i = 0; i < n; i++) {
		const dem_shot_t *r = &sh[i];
		double sp = sqrt(r->v[0] * r->v[0] + r->v[1] * r->v[1] + r->v[2] * r->v[2]);
		if (!(r->r > 0) || !isfinite(r->r))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: radius must be > 0 (got %g m)",
					     i, r->pass, r->r);
		if (!(r->v[2] < 0) || !isfinite(sp))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: velocity must point down "
					     "into the block (vz < 0; got %g m/s)", i, r->pass, r->v[2]);
		if (!(r->t >= 0) || !isfinite(r->t))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: start time must be >= 0 "
					     "(got %g s)", i, r->pass, r->t);
		dem_shot_body_t *b = &S->b[i];
		memset(b, 0, sizeof *b);
		b->R = r->r;
		b->M = S->o.rho * 4.0 / 3.0 * DEM_PI * r->r * r->r * r->r;
		b->kn = dem_law_kn(&S->cm.p.law, r->r);
		b->pass = r->pass;
		b->dt = HUGE_VAL;
		double u[3] = { r->v[0] / sp, r->v[1] / sp, r->v[2] / sp };
		/* the highest surface node within R of the impact point */
		double zmax = -HUGE_VAL;
		for (size_t k = 0; k < S->ntop; k++) {
			const double *p = x + 3 * (size_t)S->top[k];
			double dx = p[0] - r->x[0], dy = p[1] - r->x[1];
			if (dx * dx + dy * dy <= r->r * r->r && p[2] > zmax)
				zmax = p[2];
		}
		if (zmax == -HUGE_VAL)
			zmax = z0;
		double s = (zmax + S->o.gap - z0) / -u[2] + r->t * sp;
		double c[3] = { r->x[0] - s * u[0], r->x[1] - s * u[1], z0 + r->r - s * u[2] };
		/* no overlap with the shots placed before: back along the line */
		for (size_t it = 0; it <= i; it++) {
			int moved = 0;
			for (size_t j = 0; j < i; j++) {
				const dem_shot_body_t *q = &S->b[j];
				double d[3] = { c[0] - q->x[0], c[1] - q->x[1], c[2] - q->x[2] };
				double RR = b->R + q->R, dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
				if (dd >= RR * RR * (1 - 1e-12))
					continue;
				double du = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];  /* back by s: |d - s u| = RR */
				double back = du + sqrt(du * du - dd + RR * RR);
				for (int a = 0; a < 3; a++)
					c[a] -= back * u[a];
				moved = 1;
			}
			if (!moved)
				break;
		}
		memcpy(b->x, c, sizeof c);
		memcpy(b->v, r->v, sizeof b->v);
		S->ns++;
	}
	S->dt_next = HUGE_VAL;
	S->prepared = 0;
	return DEM_OK;
}

/* ---- candidates --------------------------------------------------------- */

static int cmp_u32(const void *a, const void *b)
{
	uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
	return (x > y) - (x < y);
}

static int cmp_pair(const void *a, const void *b)
{
	const uint32_t *x = a, *y = b;
	if (x[0] != y[0])
		return (x[0] > y[0]) - (x[0] < y[0]);
	return (x[1] > y[1]) - (x[1] < y[1]);
}

static int need_rebuild(const dem_shotset_t *S, const double *x)
{
	if (!S->built)
		return 1;
	double lim = 0.25 * S->o.buffer * S->o.buffer;   /* (buffer / 2)^2 */
	for (size_t s = 0; s < S->ns; s++) {
		const double *p = S->b[s].x, *q = S->xshot + 3 * s;
		double d0 = p[0] - q[0], d1 = p[1] - q[1], d2 = p[2] - q[2];
		if (d0 * d0 + d1 * d1 + d2 * d2 > lim)
			return 1;
	}
	for (size_t k = 0; k < S->ntop; k++) {
		const double *p = x + 3 * (size_t)S->top[k], *q = S->xtop + 3 * k;
		double d0 = p[0] - q[0], d1 = p[1] - q[1], d2 = p[2] - q[2];
		if (d0 * d0 + d1 * d1 + d2 * d2 > lim)
			return 1;
	}
	return 0;
}

static int grow1(void **p, size_t n, size_t size)
{
	void *q = realloc(*p, n * size);
	if (!q)
		return -1;
	*p = q;
	return 0;
}

/* The candidate arrays, current and old, all to one capacity. */
static int grow_cand(dem_shotset_t *S, size_t need)
{
	if (need <= S->ccap)
		return 0;
	size_t c = S->ccap ? S->ccap : 256;
	while (c < need)
		c *= 2;
	if (grow1((void **)&S->cf, c, sizeof *S->cf) || grow1((void **)&S->cf_old, c, sizeof *S->cf_old) ||
	    grow1((void **)&S->cs, c, sizeof *S->cs) || grow1((void **)&S->cs_old, c, sizeof *S->cs_old) ||
	    grow1((void **)&S->po, c, sizeof *S->po))
		return -1;
	S->ccap = c;
	return 0;
}

static int grow_sp(dem_shotset_t *S, size_t need)
{
	if (need <= S->spcap)
		return 0;
	size_t c = S->spcap ? S->spcap : 16;
	while (c < need)
		c *= 2;
	if (grow1((void **)&S->sp, c, sizeof *S->sp) || grow1((void **)&S->sp_old, c, sizeof *S->sp_old) ||
	    grow1((void **)&S->ss, c, sizeof *S->ss) || grow1((void **)&S->ss_old, c, sizeof *S->ss_old))
		return -1;
	S->spcap = c;
	return 0;
}

/* The D-cell over the facets and the shots, each box enlarged by half the
 * buffer; the states of pairs found again are kept. */
static int rebuild(dem_shotset_t *S, const double *x, dem_error_t *e)
{
	double t0 = dem_wall(), hb = 0.5 * S->o.buffer;
	size_t nf = S->nf, ns = S->ns, n = nf + ns;
	int rc;

	if (n > S->boxcap) {
		dem_boxes_free(&S->boxes);
		if (dem_boxes_alloc(&S->boxes, 3, n))
			return dem_error_nomem(e, "shot candidates");
		S->boxcap = n;
	}
	S->boxes.n = n;
	for (size_t f = 0; f < nf; f++)
		for (int d = 0; d < 3; d++) {
			double a = x[3 * (size_t)S->fnode[f][0] + d];
			double b = x[3 * (size_t)S->fnode[f][1] + d];
			double c = x[3 * (size_t)S->fnode[f][2] + d];
			S->boxes.lo[d][f] = fmin(a, fmin(b, c)) - hb;
			S->boxes.hi[d][f] = fmax(a, fmax(b, c)) + hb;
		}
	for (size_t s = 0; s < ns; s++)
		for (int d = 0; d < 3; d++) {
			S->boxes.lo[d][nf + s] = S->b[s].x[d] - S->b[s].R - hb;
			S->boxes.hi[d][nf + s] = S->b[s].x[d] + S->b[s].R + hb;
		}
	dem_detect_opts_t o;
	dem_detect_opts_init(&o);
	o.algo = DEM_DETECT_DCELL;
	o.ws = S->ws;
	S->pairs.n = 0;
	if ((rc = dem_detect(&S->boxes, &o, &S->pairs, NULL, e)))
		return rc;
	if (S->pairs.nomem)
		return dem_error_nomem(e, "shot candidates");

	/* room for the new lists beside the old ones (whose states carry
	 * over), then swap */
	size_t nc = 0, nsp = 0;
	for (size_t k = 0; k < S->pairs.n; k++) {
		uint32_t i = S->pairs.p[k].i, j = S->pairs.p[k].j;
		nc += i < nf && j >= nf;
		nsp += i >= nf;
	}
	if (grow_cand(S, nc) || grow_sp(S, nsp))
		return dem_error_nomem(e, "shot candidates");
	{
		void *t;
		t = S->cf, S->cf = S->cf_old, S->cf_old = t;
		t = S->cs, S->cs = S->cs_old, S->cs_old = t;
		t = S->off, S->off = S->off_old, S->off_old = t;
		t = S->sp, S->sp = S->sp_old, S->sp_old = t;
		t = S->ss, S->ss = S->ss_old, S->ss_old = t;
		S->nsp_old = S->nsp;
	}
	int had = S->built;
	/* count per shot, fill (off[s + 1] runs as the cursor) */
	memset(S->off, 0, (ns + 1) * sizeof *S->off);
	for (size_t k = 0; k < S->pairs.n; k++) {
		uint32_t i = S->pairs.p[k].i, j = S->pairs.p[k].j;
		if (i < nf && j >= nf)
			S->off[j - nf + 1]++;
	}
	for (size_t s = 0; s < ns; s++)
		S->off[s + 1] += S->off[s];
	nsp = 0;
	for (size_t k = 0; k < S->pairs.n; k++) {
		uint32_t i = S->pairs.p[k].i, j = S->pairs.p[k].j;
		if (i < nf && j >= nf)
			S->cf[S->off[j - nf]++] = i;
		else if (i >= nf) {
			S->sp[nsp][0] = i - (uint32_t)nf;
			S->sp[nsp][1] = j - (uint32_t)nf;
			nsp++;
		}
	}
	for (size_t s = ns; s > 0; s--)
		S->off[s] = S->off[s - 1];
	S->off[0] = 0;
	/* facets increasing per shot; states carried over by merge */
	for (size_t s = 0; s < ns; s++) {
		size_t a = S->off[s], b = S->off[s + 1];
		if (b - a > 1)
			qsort(S->cf + a, b - a, sizeof *S->cf, cmp_u32);
		size_t p = had ? S->off_old[s] : 0, pe = had ? S->off_old[s + 1] : 0;
		for (size_t k = a; k < b; k++) {
			while (p < pe && S->cf_old[p] < S->cf[k])
				p++;
			if (p < pe && S->cf_old[p] == S->cf[k])
				S->cs[k] = S->cs_old[p];
			else
				dem_contact_state_reset(&S->cs[k]);
		}
	}
	if (nsp > 1)    /* qsort wants a pointer even for nothing (UBSan) */
		qsort(S->sp, nsp, sizeof *S->sp, cmp_pair);
	{
		size_t p = 0, pe = had ? S->nsp_old : 0;
		for (size_t k = 0; k < nsp; k++) {
			while (p < pe && cmp_pair(S->sp_old[p], S->sp[k]) < 0)
				p++;
			if (p < pe && cmp_pair(S->sp_old[p], S->sp[k]) == 0)
				S->ss[k] = S->ss_old[p];
			else
				dem_contact_state_reset(&S->ss[k]);
		}
	}
	S->ncand = nc;
	S->nsp = nsp;
	for (size_t s = 0; s < ns; s++)
		memcpy(S->xshot + 3 * s, S->b[s].x, sizeof S->b[s].x);
	for (size_t k = 0; k < S->ntop; k++)
		memcpy(S->xtop + 3 * k, x + 3 * (size_t)S->top[k], 3 * sizeof *x);
	top_box(S, x, S->at_lo, S->at_hi);
	S->built = 1;
	S->st.rebuilds++;
	S->st.detect_s += dem_wall() - t0;
	return DEM_OK;
}

/* ---- the step ----------------------------------------------------------- */

/* Whether a shot (centre O, velocity vs, radius R) whose enlarged sphere
 * meets the box of the facet X (node velocities V, NULL: at rest) but does
 * not touch it may touch it within the step dt: its surface is nearer to
 * the triangle than twice the shot's speed plus the fastest facet node's,
 * times dt.  The distance is the triangle's, not its plane's: the planes
 * of a dimple's tilted facets cut a shot rising out of it long after the
 * last touch, and held the whole block at the contact step for the rest of
 * the pass.  The speeds are whole, not their closing parts along the line
 * to O: a surface springing back after the shot leaves it moves with the
 * shot at first (no closing speed) and then overtakes it within one long
 * step (the linear law at alpha 5 gained 30 % of the energy so).  A centre
 * behind the plane within R (no touch by dem_facet_geom, yet closer than
 * R) counts as near. */
static int facet_near(const double O[3], double vs, double R, const double X[3][3],
		      const double (*V)[3], double dt)
{
	double q[3];
	double d = sqrt(dem_triangle_closest(O, X, q)), gap = d - R;
	if (!(gap > 0))
		return 1;
	double w = 0;  /* the fastest node */
	for (int k = 0; V && k < 3; k++)
		w = fmax(w, v3_norm(V[k]));
	return gap < 2 * (vs + w) * dt;
}

/* Geometry of shot s against its candidate facets at x: which touch (po),
 * and its step limit (Box 3.1 per touching pair; for a shot that touches
 * nothing but may within reach, the step against the lightest facet in
 * reach with gamma = 1, the start of a contact).  A facet is in reach when
 * the sphere enlarged by reach meets its box and the shot may reach the
 * triangle itself within the step (facet_near): the box alone kept a shot
 * rising out of its dimple at the contact step for the rest of the pass
 * (the dimple's tilted facets have tall boxes, and their planes cut the
 * shot). */
static void shot_geometry(dem_shotset_t *S, size_t s, const double *x, const double *v,
			  double dt_max, double reach)
{
	dem_shot_body_t *b = &S->b[s];
	double R = b->R, R2 = R * R, Rr2 = (R + reach) * (R + reach), dtmin = HUGE_VAL;
	double sp = v3_norm(b->v);
	double mnear = HUGE_VAL;
	int nc = 0;

	for (size_t k = S->off[s]; k < S->off[s + 1]; k++) {
		const uint32_t *fn = S->fnode[S->cf[k]];
		double X[3][3], d2 = 0;
		pair_out_t *po = &S->po[k];
		for (int a = 0; a < 3; a++)
			for (int i = 0; i < 3; i++)
				X[a][i] = x[3 * (size_t)fn[a] + i];
		/* sphere against the facet's box: most candidates end here */
		for (int i = 0; i < 3; i++) {
			double lo = fmin(X[0][i], fmin(X[1][i], X[2][i]));
			double hi = fmax(X[0][i], fmax(X[1][i], X[2][i]));
			double c = b->x[i], q = c < lo ? lo - c : c > hi ? c - hi : 0;
			d2 += q * q;
		}
		po->touch = 0;
		if (d2 >= Rr2)
			continue;
		if (d2 >= R2 || !dem_facet_geom(b->x, R, (const double (*)[3])X, S->cm.p.partial, &po->g)) {
			double V[3][3];
			if (v)
				for (int a = 0; a < 3; a++)
					for (int i = 0; i < 3; i++)
						V[a][i] = v[3 * (size_t)fn[a] + i];
			if (facet_near(b->x, sp, R, (const double (*)[3])X, v ? (const double (*)[3])V : NULL,
				       dt_max))
				mnear = fmin(mnear, S->fmass[S->cf[k]]);
			continue;
		}
		po->touch = 1;
		nc++;
		double mass = dem_contact_meff(b->M, S->fmass[S->cf[k]]) / po->g.gamma;
		double vn = -(b->v[0] * po->g.n[0] + b->v[1] * po->g.n[1] + b->v[2] * po->g.n[2]);
		double K = dem_contact_secant(&S->cm, b->kn, mass, po->g.delta, vn);
		po->K = po->g.gamma * K;
		dtmin = fmin(dtmin, dem_dt_step(S->o.lambda, mass, K));
	}
	if (nc == 0 && mnear < HUGE_VAL) {
		dtmin = dem_contact_dt(&S->cm, b->kn, dem_contact_meff(b->M, mnear), 0, sp, S->o.lambda);
	}
	b->dt = dtmin;
}

/* The step limit of the surface nodes: each touching pair's stiffness
 * gamma K_L goes to its facet's nodes by the area coordinates of G, as its
 * force does, and a node carrying K in all gets lambda 2 sqrt(m / K)
 * (Box 3.1).  The pairs' own limit (mass m_f / gamma) assumes the force
 * spread over the facet's three nodes; where the facets around one node
 * all press on it (a shot landing on a vertex: 4 to 8 facets, each gamma
 * 1/8 or so, G near the node) it was up to twice too long, and the linear
 * law gained energy at first touch.  Serial, in shot and pair order; the
 * sums are zeroed as they are read. */
static double nodes_dt(dem_shotset_t *S)
{
	size_t n = S->off[S->ns];
	for (size_t k = 0; k < n; k++)
		if (S->po[k].touch)
			for (int a = 0; a < 3; a++)
				S->Knode[S->fnode[S->cf[k]][a]] += S->po[k].K * S->po[k].g.N[a];
	/* each node's sum once: read, then zeroed for the next step */
	double dt = HUGE_VAL;
	for (size_t k = 0; k < n; k++)
		if (S->po[k].touch)
			for (int a = 0; a < 3; a++) {
				uint32_t m = S->fnode[S->cf[k]][a];
				if (S->Knode[m] > 0)
					dt = fmin(dt, dem_dt_step(S->o.lambda, S->node_mass[m], S->Knode[m]));
				S->Knode[m] = 0;
			}
	return dt;
}

/* Forces of shot s's touching pairs (geometry from shot_geometry): its
 * force F, torque T, normal and tangential sums, the facets' nodal forces
 * (in po). */
static void shot_forces(dem_shotset_t *S, size_t s, const double *v, double dt, double T[3])
{
	dem_shot_body_t *b = &S->b[s];
	int nc = 0;

	for (int i = 0; i < 3; i++)
		b->F[i] = 0, T[i] = 0;
	b->Fn = b->Ft = 0;
	for (size_t k = S->off[s]; k < S->off[s + 1]; k++) {
		pair_out_t *po = &S->po[k];
		if (!po->touch) {
			dem_contact_state_reset(&S->cs[k]);
			continue;
		}
		/* as dem_contact_sphere_facet, on the geometry already found */
		const uint32_t *fn = S->fnode[S->cf[k]];
		const dem_facet_geom_t *g = &po->g;
		dem_contact_kin_t kin;
		dem_contact_out_t o;
		double wr[3];
		for (int i = 0; i < 3; i++)
			kin.r[i] = g->G[i] - b->x[i];
		wr[0] = b->w[1] * kin.r[2] - b->w[2] * kin.r[1];
		wr[1] = b->w[2] * kin.r[0] - b->w[0] * kin.r[2];
		wr[2] = b->w[0] * kin.r[1] - b->w[1] * kin.r[0];
		for (int i = 0; i < 3; i++) {
			double vt = g->N[0] * v[3 * (size_t)fn[0] + i] + g->N[1] * v[3 * (size_t)fn[1] + i] +
				    g->N[2] * v[3 * (size_t)fn[2] + i];
			kin.vrel[i] = b->v[i] + wr[i] - vt;  /* Eqs. 3.54-3.56 */
			kin.n[i] = g->n[i];
		}
		kin.delta = g->delta;
		kin.gamma = g->gamma;
		kin.wn = b->w[0] * g->n[0] + b->w[1] * g->n[1] + b->w[2] * g->n[2];
		kin.kn = b->kn;
		kin.meff = dem_contact_meff(b->M, S->fmass[S->cf[k]]) / g->gamma;
		kin.dt = dt;
		S->cm.kernel(&S->cm, &kin, &S->cs[k], &o);
		double F[3];
		dem_facet_forces(g, &o, S->cm.m, F, po->Fnode, NULL);
		for (int i = 0; i < 3; i++)
			b->F[i] += F[i], T[i] += o.T[i];
		b->Fn += o.Fn;
		b->Ft += o.Ft;
		nc++;
	}
	b->contacts = nc;
}

/* Step limits of the shot pairs touching or within reach. */
static void pairs_dt(dem_shotset_t *S, double dt_max)
{
	for (size_t k = 0; k < S->nsp; k++) {
		dem_shot_body_t *b1 = &S->b[S->sp[k][0]], *b2 = &S->b[S->sp[k][1]];
		double d[3], w[3];
		for (int i = 0; i < 3; i++)
			d[i] = b2->x[i] - b1->x[i], w[i] = b2->v[i] - b1->v[i];
		double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
		double sp = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
		double delta = b1->R + b2->R - dist;
		if (delta < -2 * sp * dt_max || dist == 0)
			continue;
		double vn = -(d[0] * w[0] + d[1] * w[1] + d[2] * w[2]) / dist;
		double kn = dem_law_kn(&S->cm.p.law, dem_law_reff(b1->R, b2->R));
		double dts = dem_contact_dt(&S->cm, kn, dem_contact_meff(b1->M, b2->M), delta,
					    delta > 0 ? vn : sp, S->o.lambda);
		b1->dt = fmin(b1->dt, dts);
		b2->dt = fmin(b2->dt, dts);
	}
}

static int nthreads(const dem_shotset_t *S)
{
	int nthr = S->o.threads;
#ifdef _OPENMP
	if (nthr <= 0)
		nthr = omp_get_max_threads();
#endif
	if (S->ncand < 256 || S->ns < 2)
		nthr = 1;
	return nthr;
}

/* Geometry of every shot at x, and the step limit. */
static int geometry(dem_shotset_t *S, const double *x, const double *v, double dt_max,
		    dem_error_t *e)
{
	int rc;
	if (need_rebuild(S, x) && (rc = rebuild(S, x, e)))
		return rc;
	double t0 = dem_wall();
	int nthr = nthreads(S);
	(void)nthr;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthr) if (nthr > 1)
	for (size_t s = 0; s < S->ns; s++) {
		const double *vs = S->b[s].v;
		double sp = sqrt(vs[0] * vs[0] + vs[1] * vs[1] + vs[2] * vs[2]);
		shot_geometry(S, s, x, v, dt_max, 2 * sp * dt_max);
	}
	pairs_dt(S, dt_max);
	S->dt_next = nodes_dt(S);
	for (size_t s = 0; s < S->ns; s++)
		S->dt_next = fmin(S->dt_next, S->b[s].dt);
	S->st.contact_s += dem_wall() - t0;
	return DEM_OK;
}

int dem_shotset_prepare(dem_shotset_t *S, const double *x, const double *v, double dt_max, double *dt,
			dem_error_t *e)
{
	int rc;
	*dt = dt_max;
	S->prepared = 0;
	if (S->ns == 0)
		return DEM_OK;
	if ((rc = geometry(S, x, v, dt_max, e)))
		return rc;
	S->prepared = 1;
	*dt = fmin(dt_max, S->dt_next);
	return DEM_OK;
}

int dem_shotset_hook(void *ctx, double t, double dt, const double *x, const double *v,
		     double *f, dem_error_t *e)
{
	dem_shotset_t *S = ctx;
	size_t ns = S->ns;
	int rc;
	(void)t;

	if (ns == 0)
		return DEM_OK;
	if (!S->prepared && (rc = geometry(S, x, v, dt, e)))
		return rc;
	S->prepared = 0;
	double t0 = dem_wall();
	double (*T)[3] = S->T;
	int nthr = nthreads(S);
	(void)nthr;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthr) if (nthr > 1)
	for (size_t s = 0; s < ns; s++)
		shot_forces(S, s, v, dt, T[s]);
	double ncont = 0;
	for (size_t s = 0; s < ns; s++)
		ncont += S->b[s].contacts;
	/* sphere/sphere (Eq. 3.8 in 3D), in order */
	double spc = 0, h = 0.5 * (S->dt_prev + dt);
	for (size_t k = 0; k < S->nsp; k++) {
		dem_shot_body_t *b1 = &S->b[S->sp[k][0]], *b2 = &S->b[S->sp[k][1]];
		dem_sphere_t s1 = { .R = b1->R, .kn = b1->kn }, s2 = { .R = b2->R, .kn = b2->kn };
		memcpy(s1.x, b1->x, sizeof s1.x), memcpy(s1.v, b1->v, sizeof s1.v), memcpy(s1.w, b1->w, sizeof s1.w);
		memcpy(s2.x, b2->x, sizeof s2.x), memcpy(s2.v, b2->v, sizeof s2.v), memcpy(s2.w, b2->w, sizeof s2.w);
		double kn = dem_law_kn(&S->cm.p.law, dem_law_reff(b1->R, b2->R));
		double meff = dem_contact_meff(b1->M, b2->M);
		dem_pair_out_t o;
		/* the separation correction (contact/model.h): the pair's work
		 * tally is recorded while in contact, and closed, from the
		 * state as it was, on the first step apart */
		const int fix = S->cm.sepfix;
		dem_contact_state_t keep;
		double w[3];
		if (fix)
			keep = S->ss[k];
		for (int i = 0; i < 3; i++)
			w[i] = b2->v[i] - b1->v[i];
		if (!dem_contact_sphere_sphere(&S->cm, &s1, &s2, kn, meff, dt, &S->ss[k], &o)) {
			double d[3], J[3], l = 0;
			if (!fix)
				continue;
			for (int i = 0; i < 3; i++)
				d[i] = b2->x[i] - b1->x[i], l += d[i] * d[i];
			if (!(l > 0))
				continue;
			l = sqrt(l);
			for (int i = 0; i < 3; i++)
				d[i] /= l;
			S->st.sepfix_J += dem_sepfix_release(&S->cm, &keep, kn, meff, d, w, J);
			for (int i = 0; i < 3; i++) {
				b2->F[i] += J[i] / h;
				b1->F[i] -= J[i] / h;
			}
			continue;
		}
		if (fix)
			dem_sepfix_record(&S->ss[k], o.n, w, o.c.Fe, h);
		spc++;
		double *T1 = T[S->sp[k][0]], *T2 = T[S->sp[k][1]];
		for (int i = 0; i < 3; i++) {
			b2->F[i] += o.c.F[i];
			b1->F[i] -= o.c.F[i];
			T2[i] += o.c.T[i];
			T1[i] += o.T1[i];
		}
		b1->Fn += o.c.Fn, b2->Fn += o.c.Fn;
		b1->Ft += o.c.Ft, b2->Ft += o.c.Ft;
		b1->contacts++, b2->contacts++;
	}
	/* the facets' forces on the block, in a fixed order */
	for (size_t k = 0; k < S->ncand; k++) {
		const pair_out_t *po = &S->po[k];
		if (!po->touch)
			continue;
		const uint32_t *fn = S->fnode[S->cf[k]];
		for (int a = 0; a < 3; a++)
			for (int i = 0; i < 3; i++)
				f[3 * (size_t)fn[a] + i] += po->Fnode[a][i];
	}
	double t1 = dem_wall();
	/* the shots' central difference step */
	S->integrate(S, 0.5 * (S->dt_prev + dt), dt);
	S->dt_prev = dt;
	double t2 = dem_wall();
	S->st.steps++;
	S->st.candidates += (double)S->ncand;
	S->st.contacts += ncont;
	S->st.sphere_contacts += spc;
	S->st.contact_s += t1 - t0;
	S->st.integrate_s += t2 - t1;
	return DEM_OK;
}

/* ---- queries ------------------------------------------------------------ */

void dem_shotset_nodes(const dem_shotset_t *S, size_t *n0, size_t *n1)
{
	size_t lo = SIZE_MAX, hi = 0;
	for (size_t k = 0; k < S->ntop; k++) {
		lo = S->top[k] < lo ? S->top[k] : lo;
		hi = S->top[k] + (size_t)1 > hi ? S->top[k] + (size_t)1 : hi;
	}
	*n0 = lo <= hi ? lo : 0;
	*n1 = hi;
}

/* Whether the straight path of shot b (no contact: it flies freely) never
 * meets the box lo..hi enlarged by its radius, in dim dimensions. */
static int path_misses(const dem_shot_body_t *b, int dim, const double *lo, const double *hi)
{
	double t0 = 0, t1 = HUGE_VAL;
	for (int i = 0; i < dim; i++) {
		double a = lo[i] - b->R, c = hi[i] + b->R, x = b->x[i], v = b->v[i];
		if (v == 0) {
			if (x < a || x > c)
				return 1;
			continue;
		}
		double ta = (a - x) / v, tc = (c - x) / v;
		t0 = fmax(t0, fmin(ta, tc));
		t1 = fmin(t1, fmax(ta, tc));
	}
	return t0 > t1;
}

size_t dem_shot_holding(const dem_shot_body_t *b, size_t n, int dim, const double *lo,
			const double *hi, size_t *touching, size_t *coming)
{
	size_t nt = 0, nc = 0;

	for (size_t s = 0; s < n; s++) {
		if (b[s].contacts > 0)
			nt++;
		else if (!(b[s].v[dim - 1] > 0) && !path_misses(&b[s], dim, lo, hi))
			nc++;
	}
	if (touching)
		*touching = nt;
	if (coming)
		*coming = nc;
	return nt + nc;
}

size_t dem_shotset_holding(const dem_shotset_t *S, size_t *touching, size_t *coming)
{
	return dem_shot_holding(S->b, S->ns, 3, S->built ? S->at_lo : S->ref_lo,
				S->built ? S->at_hi : S->ref_hi, touching, coming);
}

int dem_shotset_done(const dem_shotset_t *S)
{
	return dem_shotset_holding(S, NULL, NULL) == 0;
}

size_t dem_shotset_count(const dem_shotset_t *S)
{
	return S->ns;
}

const dem_shot_body_t *dem_shotset_body(const dem_shotset_t *S, size_t i)
{
	return &S->b[i];
}

double dem_shotset_kinetic(const dem_shotset_t *S)
{
	double k = 0;
	for (size_t s = 0; s < S->ns; s++) {
		const dem_shot_body_t *b = &S->b[s];
		double I = 0.4 * b->M * b->R * b->R;
		k += 0.5 * b->M * (b->v[0] * b->v[0] + b->v[1] * b->v[1] + b->v[2] * b->v[2]);
		k += 0.5 * I * (b->w[0] * b->w[0] + b->w[1] * b->w[1] + b->w[2] * b->w[2]);
	}
	return k;
}

size_t dem_shotset_facets(const dem_shotset_t *S)
{
	return S->nf;
}

void dem_shotset_stats(const dem_shotset_t *S, dem_shotset_stats_t *s)
{
	*s = S->st;
}
