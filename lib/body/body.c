/* body.c - rigid 2D bodies and walls with the Feng-Owen contact (Han 2004,
 * Ch. 4).  See body.h. */
#include "body/body.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact/law.h"
#include "contact/model.h"
#include "core/consts.h"
#include "core/cost.h"

/* ---- shapes ------------------------------------------------------------ */

static const char *const kind_names[] = {"superquadric", "polygon", "disk", NULL};

const char *dem_shape_kind_name(int kind)
{
	return kind >= 0 && kind <= DEM_SHAPE_DISK ? kind_names[kind] : "?";
}

int dem_shape_kind_parse(const char *name)
{
	for (int k = 0; kind_names[k]; k++)
		if (strcmp(kind_names[k], name) == 0)
			return k;
	return -1;
}

/* the polygon's mass properties, the polygon moved to put its centroid at 0 */
static void shape_finish(dem_shape_t *s)
{
	dem_area_props_t pr;
	dem_polygon_props(s->nv, (const double (*)[2])s->v, &pr);
	s->A = pr.A, s->J = pr.J, s->r = 0;
	for (int i = 0; i < s->nv; i++) {
		s->v[i][0] -= pr.c[0], s->v[i][1] -= pr.c[1];
		s->r = fmax(s->r, hypot(s->v[i][0], s->v[i][1]));
	}
}

int dem_shape_init(dem_shape_t *s, int kind, double a, double b, double m, double tau,
                   dem_error_t *e)
{
	memset(s, 0, sizeof *s);
	s->kind = kind;
	if (!(a > 0) || !isfinite(a))
		return dem_error_set(e, DEM_EINPUT, "shape: a = %g: expected a size > 0", a);
	switch (kind) {
	case DEM_SHAPE_SUPERQUADRIC: {
		int n = dem_superquadric_polygon(a, b, m, tau, 0, NULL);
		if (n < 0)
			return dem_error_set(e, DEM_EINPUT, "superquadric a = %g, b = %g, m = %g, "
			                     "tau = %g: expected a, b, tau > 0 and m >= 1", a, b, m, tau);
		if (!(s->v = malloc((size_t)n * sizeof *s->v)))
			return dem_error_nomem(e, "superquadric");
		s->nv = dem_superquadric_polygon(a, b, m, tau, n, s->v);
		s->a = a, s->b = b, s->m = m;
		shape_finish(s);
		return DEM_OK;
	}
	case DEM_SHAPE_POLYGON: {
		if (!(m >= 3 && m <= 64 && m == floor(m)))
			return dem_error_set(e, DEM_EINPUT, "polygon: %g sides: expected a whole "
			                     "number from 3 to 64", m);
		int n = (int)m;
		if (!(s->v = malloc((size_t)n * sizeof *s->v)))
			return dem_error_nomem(e, "polygon");
		/* one side flat at the bottom; b > 0 stretches it along y
		 * (the points on the ellipse of semi-axes a, b) */
		if (!(b > 0) || !isfinite(b))
			b = a;
		dem_polygon_regular(n, a, b, s->v);
		s->nv = n;
		s->a = a, s->b = b, s->m = m;
		shape_finish(s);
		return DEM_OK;
	}
	case DEM_SHAPE_DISK:
		s->a = s->b = s->r = a;
		s->A = DEM_PI * a * a;
		s->J = 0.5 * DEM_PI * a * a * a * a;
		return DEM_OK;
	default:
		return dem_error_set(e, DEM_EINPUT, "shape: unknown kind %d", kind);
	}
}

void dem_shape_free(dem_shape_t *s)
{
	free(s->v);
	s->v = NULL;
	s->nv = 0;
}

/* ---- the run's workspace ------------------------------------------------- */

struct geo {
	double S;       /* overlap area */
	double Fn;      /* elastic normal force, |F| = W'(S) bw */
	double n[2];    /* unit normal on body i (the contactor) */
	double c[2];    /* reference contact point */
	double W;       /* W(S) */
};

typedef void (*pair_fn)(dem_de_t *de, uint32_t i, uint32_t j, double *ut);

struct dem_de_ws {
	dem_boxes_t boxes;
	size_t boxcap;
	dem_pairs_t pairs;
	dem_detect_ws_t *dws;
	dem_detect_opts_t dopt;
	size_t *voff;           /* body i's placed polygon: pool[voff[i]] */
	size_t sized;           /* the bodies voff and pool were sized for */
	double (*pool)[2];
	size_t poolcap;
	int maxnv;              /* the largest polygon, walls' 4 included */
	double (*ov)[2], (*work)[2];   /* an overlap's points and the clip's copies */
	unsigned char *side;
	/* friction: the tangential displacement of each pair of the last step,
	 * pairs sorted; the current step's, in the order of pairs */
	dem_pair_t *hp;
	double *hu, *ut;
	size_t hn, hcap, ucap;
	pair_fn kernel;
};

int dem_de_init(dem_de_t *de, const dem_de_param_t *p, int nshape, dem_shape_t *shape,
                dem_error_t *e)
{
	memset(de, 0, sizeof *de);
	de->p = *p;
	de->nshape = nshape;
	de->shape = shape;
	if (!(p->kn > 0) || !isfinite(p->kn))
		return dem_error_set(e, DEM_EINPUT, "contact: kn = %g: expected > 0", p->kn);
	if (p->law == DEM_W_POWER && !(p->p >= 1 && isfinite(p->p)))
		return dem_error_set(e, DEM_EINPUT, "contact: power exponent %g: expected >= 1", p->p);
	if (!(p->density > 0) || !isfinite(p->density))
		return dem_error_set(e, DEM_EINPUT, "bodies: density %g: expected > 0", p->density);
	if (p->friction && !(p->mu >= 0 && isfinite(p->mu)))
		return dem_error_set(e, DEM_EINPUT, "contact: friction %g: expected >= 0", p->mu);
	if (p->damping && !(p->xi >= 0 && p->xi < 1))
		return dem_error_set(e, DEM_EINPUT, "contact: damping ratio %g: expected in [0, 1)",
		                     p->xi);
	if (!(p->lambda > 0 && p->lambda <= 1))
		return dem_error_set(e, DEM_EINPUT, "time step factor %g: expected in (0, 1]",
		                     p->lambda);
	if (de->p.friction && !(de->p.kt_ratio > 0))
		de->p.kt_ratio = DEM_CONTACT_KT_RATIO;
	if (nshape < 1)
		return dem_error_set(e, DEM_EINPUT, "bodies: no shape");
	int disks = 0, maxnv = 4;
	for (int s = 0; s < nshape; s++) {
		disks += shape[s].kind == DEM_SHAPE_DISK;
		if (shape[s].nv > maxnv)
			maxnv = shape[s].nv;
	}
	if (disks && disks != nshape)
		return dem_error_set(e, DEM_EINPUT, "bodies: disks and polygons in one run are "
		                     "not supported (a disk meets only disks and walls)");
	if (!(de->ws = calloc(1, sizeof *de->ws)))
		return dem_error_nomem(e, "bodies");
	struct dem_de_ws *ws = de->ws;
	ws->maxnv = maxnv;
	ws->ov = malloc(4 * (size_t)maxnv * sizeof *ws->ov);
	ws->work = malloc(4 * (size_t)maxnv * sizeof *ws->work);
	ws->side = malloc(4 * (size_t)maxnv);
	ws->dws = dem_detect_ws_new();
	dem_pairs_init(&ws->pairs);
	if (!ws->ov || !ws->work || !ws->side || !ws->dws)
		return dem_error_nomem(e, "bodies");
	dem_detect_opts_init(&ws->dopt);
	ws->dopt.algo = p->algo;
	ws->dopt.cell_factor = p->cell_factor;
	ws->dopt.ws = ws->dws;
	return DEM_OK;
}

void dem_de_free(dem_de_t *de)
{
	struct dem_de_ws *ws = de->ws;
	free(de->sh);
	free(de->mass);
	free(de->inertia);
	free(de->x);
	free(de->y);
	free(de->th);
	free(de->vx);
	free(de->vy);
	free(de->w);
	free(de->fx);
	free(de->fy);
	free(de->mz);
	free(de->wall);
	if (ws) {
		dem_boxes_free(&ws->boxes);
		dem_pairs_free(&ws->pairs);
		dem_detect_ws_free(ws->dws);
		free(ws->voff);
		free(ws->pool);
		free(ws->ov);
		free(ws->work);
		free(ws->side);
		free(ws->hp);
		free(ws->hu);
		free(ws->ut);
		free(ws);
	}
	memset(de, 0, sizeof *de);
}

static int grow_bodies(dem_de_t *de, dem_error_t *e)
{
	size_t cap = de->cap ? 2 * de->cap : 64;
	double **arr[] = {&de->mass, &de->inertia, &de->x, &de->y, &de->th, &de->vx,
	                  &de->vy, &de->w, &de->fx, &de->fy, &de->mz};
	for (size_t k = 0; k < sizeof arr / sizeof *arr; k++) {
		double *q = realloc(*arr[k], cap * sizeof *q);
		if (!q)
			return dem_error_nomem(e, "bodies");
		*arr[k] = q;
	}
	uint32_t *sh = realloc(de->sh, cap * sizeof *sh);
	if (!sh)
		return dem_error_nomem(e, "bodies");
	de->sh = sh;
	de->cap = cap;
	return DEM_OK;
}

long dem_de_add_body(dem_de_t *de, int s, double x, double y, double th, double vx,
                     double vy, double w, dem_error_t *e)
{
	if (s < 0 || s >= de->nshape) {
		dem_error_set(e, DEM_EINPUT, "body: shape %d of %d", s, de->nshape);
		return -1;
	}
	if (de->n == de->cap && grow_bodies(de, e))
		return -1;
	size_t i = de->n++;
	const dem_shape_t *sh = &de->shape[s];
	de->sh[i] = (uint32_t)s;
	de->mass[i] = de->p.density * sh->A;
	de->inertia[i] = de->p.density * sh->J;
	de->x[i] = x, de->y[i] = y, de->th[i] = th;
	de->vx[i] = vx, de->vy[i] = vy, de->w[i] = w;
	de->fx[i] = de->fy[i] = de->mz[i] = 0;
	return (long)i;
}

long dem_de_add_wall(dem_de_t *de, const double A[2], const double B[2], double thickness,
                     dem_error_t *e)
{
	double dx = B[0] - A[0], dy = B[1] - A[1], L = hypot(dx, dy);
	if (!(L > 0) || !(thickness > 0) || !isfinite(L) || !isfinite(thickness)) {
		dem_error_set(e, DEM_EINPUT, "wall (%g, %g) -> (%g, %g), thickness %g: expected "
		              "two distinct points and a thickness > 0", A[0], A[1], B[0], B[1],
		              thickness);
		return -1;
	}
	if (de->nw == de->wcap) {
		size_t cap = de->wcap ? 2 * de->wcap : 8;
		double (*q)[4][2] = realloc(de->wall, cap * sizeof *q);
		if (!q) {
			dem_error_nomem(e, "walls");
			return -1;
		}
		de->wall = q, de->wcap = cap;
	}
	/* the left normal nL; the wall's inside is on the right of A -> B */
	double nx = -dy / L * thickness, ny = dx / L * thickness;
	double (*q)[2] = de->wall[de->nw];
	q[0][0] = B[0], q[0][1] = B[1];
	q[1][0] = A[0], q[1][1] = A[1];
	q[2][0] = A[0] - nx, q[2][1] = A[1] - ny;
	q[3][0] = B[0] - nx, q[3][1] = B[1] - ny;
	return (long)de->nw++;
}

/* ---- contact geometry ---------------------------------------------------- */

/* Body i (the contactor, P) against body j, or wall j - n (Q, held). */
static int geo_poly(dem_de_t *de, uint32_t i, uint32_t j, struct geo *g)
{
	struct dem_de_ws *ws = de->ws;
	const dem_shape_t *si = &de->shape[de->sh[i]];
	const double (*P)[2] = (const double (*)[2])ws->pool[ws->voff[i]];
	const double (*Q)[2];
	int nq;
	if (j < de->n) {
		Q = (const double (*)[2])ws->pool[ws->voff[j]];
		nq = de->shape[de->sh[j]].nv;
	} else {
		Q = (const double (*)[2])de->wall[j - de->n];
		nq = 4;
	}
	dem_overlap_t o;
	dem_poly_contact_t k;
	double xp[2] = {de->x[i], de->y[i]};
	/* the bounding-box clip, then the linear algorithm (Ch. 4.3) */
	if (!dem_polygon_chase(si->nv, P, nq, Q, 1, ws->ov, ws->side, ws->work, &o) ||
	    !dem_polygon_contact(&o, (const double (*)[2])ws->ov, ws->side, xp, de->p.law,
	                         de->p.kn, de->p.p, &k))
		return 0;
	g->S = k.S, g->Fn = k.Fn, g->W = k.W;
	g->n[0] = k.n[0], g->n[1] = k.n[1];
	g->c[0] = k.c[0], g->c[1] = k.c[1];
	return 1;
}

/* The circular segment of radius r cut at distance h from the centre:
 * area and chord. */
static void segment(double r, double h, double *S, double *bw)
{
	double q = sqrt(fmax(r * r - h * h, 0));
	*S = r * r * acos(fmax(-1, fmin(1, h / r))) - h * q;
	*bw = 2 * q;
}

/* The circle (centre c, radius r) against the convex polygon Q[nq]
 * (anticlockwise): the overlap area S, and grad S for the circle moving,
 * the sum over the arcs of the circle inside Q, each from h (where it
 * enters) to g (where it leaves), of (dy, -dx) with (dx, dy) = g - h (the
 * flux of a move through the arc: Eqs. 4.19-4.21, 4.31 with arcs for P's
 * edges).  Returns the number of such arcs (0: apart, or one inside the
 * other, where S does not change with a small move). */
static int circle_polygon(const double c[2], double r, int nq, const double (*Q)[2], double *S,
                          double grad[2])
{
	double ang[2 * 64 + 2];   /* the circle's crossings of Q's edges (2 an edge at most) */
	int na = 0;
	double area = 0;
	grad[0] = grad[1] = 0;
	/* the area: sum over Q's edges of the signed area of the circle within
	 * the triangle (c, q_k, q_k+1), the edge cut at its crossings */
	for (int k = 0; k < nq; k++) {
		const double *A = Q[k], *B = Q[k + 1 == nq ? 0 : k + 1];
		double ax = A[0] - c[0], ay = A[1] - c[1], dx = B[0] - A[0], dy = B[1] - A[1];
		double a2 = dx * dx + dy * dy, b = ax * dx + ay * dy, cc = ax * ax + ay * ay - r * r;
		double disc = b * b - a2 * cc, t[4] = {0, 0, 0, 1};
		int nt = 1;
		if (a2 > 0 && disc > 0) {
			double q = sqrt(disc);
			double t1 = (-b - q) / a2, t2 = (-b + q) / a2;
			if (t1 > 0 && t1 < 1) {
				t[nt++] = t1;
				ang[na++] = atan2(ay + t1 * dy, ax + t1 * dx);
			}
			if (t2 > 0 && t2 < 1) {
				t[nt++] = t2;
				ang[na++] = atan2(ay + t2 * dy, ax + t2 * dx);
			}
		}
		t[nt++] = 1;
		for (int m = 0; m + 1 < nt; m++) {
			double px = ax + t[m] * dx, py = ay + t[m] * dy;
			double qx = ax + t[m + 1] * dx, qy = ay + t[m + 1] * dy;
			double mx = 0.5 * (px + qx), my = 0.5 * (py + qy);
			double cr = px * qy - py * qx;
			if (mx * mx + my * my < r * r)
				area += 0.5 * cr;       /* the piece inside the circle: its triangle */
			else
				area += 0.5 * r * r * atan2(cr, px * qx + py * qy);   /* a sector */
		}
	}
	*S = area;
	if (na < 2)
		return 0;
	/* the arcs between consecutive crossings whose middle lies in Q */
	for (int k = 1; k < na; k++)
		for (int m = k; m > 0 && ang[m] < ang[m - 1]; m--) {
			double tt = ang[m];
			ang[m] = ang[m - 1], ang[m - 1] = tt;
		}
	int arcs = 0;
	for (int k = 0; k < na; k++) {
		double a0 = ang[k], a1 = k + 1 < na ? ang[k + 1] : ang[0] + 2 * DEM_PI;
		if (!(a1 > a0))
			continue;
		double am = 0.5 * (a0 + a1), mx = c[0] + r * cos(am), my = c[1] + r * sin(am);
		int in = 1;
		for (int q = 0; q < nq && in; q++) {
			const double *A = Q[q], *B = Q[q + 1 == nq ? 0 : q + 1];
			in = (B[0] - A[0]) * (my - A[1]) - (B[1] - A[1]) * (mx - A[0]) > 0;
		}
		if (!in)
			continue;
		double gx = r * (cos(a1) - cos(a0)), gy = r * (sin(a1) - sin(a0));   /* g - h */
		grad[0] += gy, grad[1] -= gx;
		arcs++;
	}
	return arcs;
}

/* Disk i against disk j (their lens) or wall j - n (the circle against the
 * wall's rectangle, circle_polygon).  Moving i by u changes S by -bw (u . n),
 * so F = W'(S) bw n (Eqs. 4.11-4.13 with the exact circles), through the
 * centre: at the middle of the chord (the lens), or on the line of action
 * at the chord's distance from the centre for a chord of length bw. */
static int geo_disk(dem_de_t *de, uint32_t i, uint32_t j, struct geo *g)
{
	double ri = de->shape[de->sh[i]].a, S, bw;
	if (j < de->n) {
		double rj = de->shape[de->sh[j]].a;
		double dx = de->x[i] - de->x[j], dy = de->y[i] - de->y[j], d = hypot(dx, dy);
		if (d >= ri + rj || d <= fabs(ri - rj))
			return 0;   /* apart, or one inside the other (no force, as polygons) */
		double d1 = (d * d + ri * ri - rj * rj) / (2 * d), Si, Sj, b;
		segment(ri, d1, &Si, &bw);
		segment(rj, d - d1, &Sj, &b);
		S = Si + Sj;
		g->n[0] = dx / d, g->n[1] = dy / d;
		g->c[0] = de->x[i] - d1 * g->n[0], g->c[1] = de->y[i] - d1 * g->n[1];
	} else {
		double xc[2] = {de->x[i], de->y[i]}, grad[2];
		if (!circle_polygon(xc, ri, 4, (const double (*)[2])de->wall[j - de->n], &S, grad))
			return 0;
		bw = hypot(grad[0], grad[1]);
		if (!(bw > 0))
			return 0;
		g->n[0] = -grad[0] / bw, g->n[1] = -grad[1] / bw;
		/* the chord's middle: towards the wall, or beyond the centre when
		 * more than half the disk is in */
		double h = sqrt(fmax(ri * ri - 0.25 * bw * bw, 0));
		if (S > 0.5 * DEM_PI * ri * ri)
			h = -h;
		g->c[0] = xc[0] - h * g->n[0], g->c[1] = xc[1] - h * g->n[1];
	}
	if (!(S > 0) || !(bw > 0))
		return 0;
	g->S = S;
	g->W = dem_wlaw_energy(de->p.law, de->p.kn, de->p.p, S);
	g->Fn = dem_wlaw_slope(de->p.law, de->p.kn, de->p.p, S) * bw;
	return 1;
}

/* ---- the pair kernels ---------------------------------------------------- */

/* The force of a contact on i at g->c (minus it on j), with damping and
 * friction when the kernel was made with them (constants at compile time). */
static inline void apply(dem_de_t *de, uint32_t i, uint32_t j, const struct geo *g,
                         double *ut, const int damping, const int friction)
{
	int body = j < de->n;
	double Fn = g->Fn, Ft = 0;
	double tx = -g->n[1], ty = g->n[0];
	double rix = g->c[0] - de->x[i], riy = g->c[1] - de->y[i];
	double rjx = 0, rjy = 0;
	double vx = 0, vy = 0;
	if (damping || friction) {
		/* velocity of i's material point at c minus j's */
		vx = de->vx[i] - de->w[i] * riy;
		vy = de->vy[i] + de->w[i] * rix;
		if (body) {
			rjx = g->c[0] - de->x[j], rjy = g->c[1] - de->y[j];
			vx -= de->vx[j] - de->w[j] * rjy;
			vy -= de->vy[j] + de->w[j] * rjx;
		}
	}
	if (damping) {
		double M = body ? dem_contact_meff(de->mass[i], de->mass[j]) : de->mass[i];
		double vn = vx * g->n[0] + vy * g->n[1];
		/* Eqs. 3.70, 3.75-3.76 with the secant K; repulsive only */
		Fn = fmax(0, Fn - 2 * de->p.xi * sqrt(M * de->K) * vn);
	}
	if (friction) {
		/* Eq. 3.48: the trial force of the tangential spring, capped */
		double kt = de->p.kt_ratio * de->K, cap = de->p.mu * Fn;
		*ut += (vx * tx + vy * ty) * de->dt;
		Ft = -kt * *ut;
		if (fabs(Ft) > cap) {
			Ft = Ft > 0 ? cap : -cap;
			*ut = -Ft / kt;
		}
	}
	double Fx = Fn * g->n[0] + Ft * tx, Fy = Fn * g->n[1] + Ft * ty;
	de->fx[i] += Fx, de->fy[i] += Fy;
	de->mz[i] += rix * Fy - riy * Fx;
	if (body) {
		if (!(damping || friction))
			rjx = g->c[0] - de->x[j], rjy = g->c[1] - de->y[j];
		de->fx[j] -= Fx, de->fy[j] -= Fy;
		de->mz[j] -= rjx * Fy - rjy * Fx;
	}
	de->W += g->W;
	de->ncontact++;
	double s = g->S / de->shape[de->sh[i]].A;
	de->st.overlap_max = s > de->st.overlap_max ? s : de->st.overlap_max;
}

#define KERNEL(name, GEO, D, F)                                                  \
	static void name(dem_de_t *de, uint32_t i, uint32_t j, double *ut)       \
	{                                                                        \
		struct geo g;                                                    \
		if (GEO(de, i, j, &g))                                           \
			apply(de, i, j, &g, ut, D, F);                           \
		else                                                             \
			*ut = 0;                                                 \
	}
KERNEL(poly_e, geo_poly, 0, 0)
KERNEL(poly_d, geo_poly, 1, 0)
KERNEL(poly_f, geo_poly, 0, 1)
KERNEL(poly_df, geo_poly, 1, 1)
KERNEL(disk_e, geo_disk, 0, 0)
KERNEL(disk_d, geo_disk, 1, 0)
KERNEL(disk_f, geo_disk, 0, 1)
KERNEL(disk_df, geo_disk, 1, 1)

static const pair_fn kernels[2][4] = {
	{poly_e, poly_d, poly_f, poly_df},
	{disk_e, disk_d, disk_f, disk_df},
};

/* ---- forces -------------------------------------------------------------- */

static int ws_size(dem_de_t *de, dem_error_t *e)
{
	struct dem_de_ws *ws = de->ws;
	size_t nb = de->n + de->nw, need = 0;
	if (ws->boxes.n == nb && ws->sized == de->n)
		return DEM_OK;          /* no body or wall added since the last step */
	if (ws->boxcap < nb) {
		dem_boxes_free(&ws->boxes);
		if (dem_boxes_alloc(&ws->boxes, 2, nb))
			return dem_error_nomem(e, "bodies");
		ws->boxcap = nb;
		size_t *voff = realloc(ws->voff, (de->n + 1) * sizeof *voff);
		if (!voff)
			return dem_error_nomem(e, "bodies");
		ws->voff = voff;
	}
	ws->boxes.n = nb;
	for (size_t i = 0; i < de->n; i++) {
		ws->voff[i] = need;
		need += (size_t)de->shape[de->sh[i]].nv;
	}
	if (ws->poolcap < need) {
		double (*q)[2] = realloc(ws->pool, need * sizeof *q);
		if (!q)
			return dem_error_nomem(e, "bodies");
		ws->pool = q, ws->poolcap = need;
	}
	ws->sized = de->n;
	return DEM_OK;
}

/* merge the last step's tangential displacements into the new sorted pairs */
static int carry_friction(struct dem_de_ws *ws, dem_error_t *e)
{
	size_t n = ws->pairs.n, k = 0;
	if (ws->ucap < n) {
		double *u = realloc(ws->ut, n * sizeof *u);
		if (!u)
			return dem_error_nomem(e, "friction");
		ws->ut = u, ws->ucap = n;
	}
	for (size_t q = 0; q < n; q++) {
		const dem_pair_t *p = &ws->pairs.p[q];
		while (k < ws->hn && (ws->hp[k].i < p->i ||
		                      (ws->hp[k].i == p->i && ws->hp[k].j < p->j)))
			k++;
		ws->ut[q] = k < ws->hn && ws->hp[k].i == p->i && ws->hp[k].j == p->j ? ws->hu[k] : 0;
	}
	return DEM_OK;
}

static int keep_friction(struct dem_de_ws *ws, dem_error_t *e)
{
	size_t n = ws->pairs.n;
	if (ws->hcap < n) {
		dem_pair_t *p = realloc(ws->hp, n * sizeof *p);
		if (p)
			ws->hp = p;
		double *u = realloc(ws->hu, n * sizeof *u);
		if (u)
			ws->hu = u;
		if (!p || !u)
			return dem_error_nomem(e, "friction");
		ws->hcap = n;
	}
	if (n) {
		memcpy(ws->hp, ws->pairs.p, n * sizeof *ws->hp);
		memcpy(ws->hu, ws->ut, n * sizeof *ws->hu);
	}
	ws->hn = n;
	return DEM_OK;
}

static int forces(dem_de_t *de, dem_error_t *e)
{
	struct dem_de_ws *ws = de->ws;
	dem_boxes_t *b = &ws->boxes;
	double t0 = dem_cpu();
	if (ws_size(de, e))
		return e->code;
	/* the bodies placed, their boxes; the walls' */
	for (size_t i = 0; i < de->n; i++) {
		const dem_shape_t *s = &de->shape[de->sh[i]];
		double xc[2] = {de->x[i], de->y[i]};
		if (s->nv == 0) {
			b->lo[0][i] = xc[0] - s->r, b->hi[0][i] = xc[0] + s->r;
			b->lo[1][i] = xc[1] - s->r, b->hi[1][i] = xc[1] + s->r;
			continue;
		}
		double (*v)[2] = ws->pool + ws->voff[i];
		dem_polygon_place(s->nv, (const double (*)[2])s->v, xc, de->th[i], v);
		double lx = v[0][0], hx = lx, ly = v[0][1], hy = ly;
		for (int k = 1; k < s->nv; k++) {
			/* not fmin/fmax: a libm call each at -O2 */
			lx = v[k][0] < lx ? v[k][0] : lx, hx = v[k][0] > hx ? v[k][0] : hx;
			ly = v[k][1] < ly ? v[k][1] : ly, hy = v[k][1] > hy ? v[k][1] : hy;
		}
		b->lo[0][i] = lx, b->hi[0][i] = hx, b->lo[1][i] = ly, b->hi[1][i] = hy;
	}
	for (size_t k = 0; k < de->nw; k++) {
		const double (*q)[2] = (const double (*)[2])de->wall[k];
		size_t i = de->n + k;
		b->lo[0][i] = fmin(fmin(q[0][0], q[1][0]), fmin(q[2][0], q[3][0]));
		b->hi[0][i] = fmax(fmax(q[0][0], q[1][0]), fmax(q[2][0], q[3][0]));
		b->lo[1][i] = fmin(fmin(q[0][1], q[1][1]), fmin(q[2][1], q[3][1]));
		b->hi[1][i] = fmax(fmax(q[0][1], q[1][1]), fmax(q[2][1], q[3][1]));
	}
	ws->pairs.n = 0;
	if (dem_detect(b, &ws->dopt, &ws->pairs, NULL, e))
		return e->code;
	if (ws->pairs.nomem)
		return dem_error_nomem(e, "contact pairs");
	if (de->p.friction) {
		if (dem_pairs_sort(&ws->pairs))
			return dem_error_nomem(e, "contact pairs");
		if (carry_friction(ws, e))
			return e->code;
	}
	double t1 = dem_cpu();
	de->st.detect_s += t1 - t0;
	/* the body forces, then the contacts */
	for (size_t i = 0; i < de->n; i++) {
		de->fx[i] = de->p.gravity ? de->mass[i] * de->p.g[0] : 0;
		de->fy[i] = de->p.gravity ? de->mass[i] * de->p.g[1] : 0;
		de->mz[i] = 0;
	}
	de->W = 0;
	de->ncontact = 0;
	double scratch = 0;
	size_t cand = 0;
	for (size_t q = 0; q < ws->pairs.n; q++) {
		const dem_pair_t *p = &ws->pairs.p[q];
		if (p->i >= de->n)
			continue;               /* wall against wall */
		cand++;
		ws->kernel(de, p->i, p->j, de->p.friction ? &ws->ut[q] : &scratch);
	}
	de->st.candidates += cand;
	de->st.contacts += de->ncontact;
	if (de->p.friction && keep_friction(ws, e))
		return e->code;
	de->st.contact_s += dem_cpu() - t1;
	return DEM_OK;
}

/* ---- time step ----------------------------------------------------------- */

/* S and bw of shape s turned by th, pushed to depth d into the flat wall
 * below it; the polygon clipped by the reference method */
static int halfplane(const dem_shape_t *s, const double (*v)[2], double lo, double hi,
                     double d, double (*buf)[2], unsigned char *side, double (*work)[2],
                     double *S, double *bw)
{
	if (s->nv == 0) {
		segment(s->r, s->r - d, S, bw);
		return DEM_OK;
	}
	double R = 2 * s->r, top = lo + d;
	double Q[4][2] = {{-R, lo - R}, {R, lo - R}, {R, top}, {-R, top}};
	dem_overlap_t o;
	dem_poly_contact_t k;
	double xp[2] = {0, 0};
	(void)hi;
	*S = 0, *bw = 0;
	if (dem_polygon_clip(s->nv, v, 4, (const double (*)[2])Q, buf, side, work, &o) &&
	    dem_polygon_contact(&o, (const double (*)[2])buf, side, xp, DEM_W_LINEAR, 1, 1, &k))
		*S = k.S, *bw = k.bw;
	return DEM_OK;
}

int dem_shape_secant(const dem_shape_t *s, double th, const dem_de_param_t *p, double M,
                     double v0, double *K, double *umax, dem_error_t *e)
{
	int n = s->nv;
	double (*v)[2] = NULL, (*buf)[2] = NULL, (*work)[2] = NULL;
	unsigned char *side = NULL;
	double lo = -s->r, hi = s->r;
	if (n) {
		v = malloc((size_t)n * sizeof *v);
		buf = malloc(2 * (size_t)(n + 4) * sizeof *buf);
		work = malloc(2 * (size_t)(n + 4) * sizeof *work);
		side = malloc(2 * (size_t)(n + 4));
		if (!v || !buf || !work || !side) {
			free(v), free(buf), free(work), free(side);
			return dem_error_nomem(e, "time step");
		}
		double zero[2] = {0, 0};
		dem_polygon_place(n, (const double (*)[2])s->v, zero, th, v);
		lo = hi = v[0][1];
		for (int k = 1; k < n; k++)
			lo = fmin(lo, v[k][1]), hi = fmax(hi, v[k][1]);
	}
	double E0 = 0.5 * M * v0 * v0, S, bw, a = 0, b = hi - lo;
	halfplane(s, (const double (*)[2])v, lo, hi, b * (1 - 1e-9), buf, side, work, &S, &bw);
	int rc = DEM_OK;
	if (!(dem_wlaw_energy(p->law, p->kn, p->p, S) > E0)) {
		rc = dem_error_set(e, DEM_ENUMERIC, "time step: the contact law (kn = %g) cannot "
		                   "stop a body of mass %g at %g m/s before it is wholly in the "
		                   "wall: raise kn", p->kn, M, v0);
	} else {
		/* W(S(u)) = E0 by bisection (S grows with the depth) */
		for (int it = 0; it < 64 && b - a > 1e-14 * (hi - lo); it++) {
			double c = 0.5 * (a + b);
			halfplane(s, (const double (*)[2])v, lo, hi, c, buf, side, work, &S, &bw);
			if (dem_wlaw_energy(p->law, p->kn, p->p, S) < E0)
				a = c;
			else
				b = c;
		}
		halfplane(s, (const double (*)[2])v, lo, hi, b, buf, side, work, &S, &bw);
		*umax = b;
		*K = dem_wlaw_slope(p->law, p->kn, p->p, S) * bw / b;
	}
	free(v), free(buf), free(work), free(side);
	return rc;
}

int dem_de_timestep(dem_de_t *de, dem_error_t *e)
{
	if (de->n == 0)
		return dem_error_set(e, DEM_EINPUT, "bodies: none to run");
	if (!(de->p.v0 > 0) || !isfinite(de->p.v0))
		return dem_error_set(e, DEM_EINPUT, "time step: approach speed %g: expected > 0",
		                     de->p.v0);
	double dt = HUGE_VAL, Kmax = 0;
	for (int s = 0; s < de->nshape; s++) {
		const dem_shape_t *sh = &de->shape[s];
		size_t i;
		for (i = 0; i < de->n && de->sh[i] != (uint32_t)s; i++)
			;
		if (i == de->n)
			continue;           /* a shape no body has */
		double m = de->mass[i], I = de->inertia[i];
		double M = 0.5 / (1 / m + sh->r * sh->r / I), K = 0, Ki, u;
		int nth = sh->nv ? 360 + sh->nv : 1;
		for (int k = 0; k < nth; k++) {
			double th;
			if (k < 360 || !sh->nv) {
				th = 2 * DEM_PI * k / 360;
			} else {
				/* side q flat on the wall: its outward normal down */
				int q = k - 360, r = q + 1 == sh->nv ? 0 : q + 1;
				double ex = sh->v[r][0] - sh->v[q][0], ey = sh->v[r][1] - sh->v[q][1];
				th = -0.5 * DEM_PI - atan2(-ex, ey);
			}
			if (dem_shape_secant(sh, th, &de->p, M, de->p.v0, &Ki, &u, e))
				return e->code;
			K = fmax(K, Ki);
		}
		Kmax = fmax(Kmax, K);
		dt = fmin(dt, dem_dt_step(de->p.lambda, M, K));
	}
	de->dt = dt;
	de->K = Kmax;
	return DEM_OK;
}

/* ---- the run ------------------------------------------------------------- */

int dem_de_start(dem_de_t *de, dem_error_t *e)
{
	int disk = de->shape[0].kind == DEM_SHAPE_DISK;
	de->ws->kernel = kernels[disk][(de->p.damping ? 1 : 0) + (de->p.friction ? 2 : 0)];
	if (dem_de_timestep(de, e))
		return e->code;
	return forces(de, e);
}

/* v += F/m dt/2 */
static void kick(dem_de_t *de)
{
	double h = 0.5 * de->dt;
	for (size_t i = 0; i < de->n; i++) {
		de->vx[i] += h * de->fx[i] / de->mass[i];
		de->vy[i] += h * de->fy[i] / de->mass[i];
		de->w[i] += h * de->mz[i] / de->inertia[i];
	}
}

int dem_de_step(dem_de_t *de, dem_error_t *e)
{
	double t0 = dem_cpu();
	kick(de);
	int bad = 0;
	for (size_t i = 0; i < de->n; i++) {
		de->x[i] += de->dt * de->vx[i];
		de->y[i] += de->dt * de->vy[i];
		de->th[i] += de->dt * de->w[i];
		bad |= !isfinite(de->x[i] + de->y[i] + de->th[i]);
	}
	if (bad)
		for (size_t i = 0; i < de->n; i++)
			if (!isfinite(de->x[i] + de->y[i] + de->th[i]))
				return dem_error_set(e, DEM_ENUMERIC, "body %zu: position not finite "
				                     "at t = %g s (step %ld)", i, de->t, de->steps);
	de->st.move_s += dem_cpu() - t0;
	if (forces(de, e))
		return e->code;
	t0 = dem_cpu();
	kick(de);
	de->t += de->dt;
	de->steps++;
	de->st.move_s += dem_cpu() - t0;
	return DEM_OK;
}

double dem_de_energy(const dem_de_t *de)
{
	double E = de->W;
	for (size_t i = 0; i < de->n; i++) {
		E += 0.5 * de->mass[i] * (de->vx[i] * de->vx[i] + de->vy[i] * de->vy[i]) +
		     0.5 * de->inertia[i] * de->w[i] * de->w[i];
		if (de->p.gravity)
			E -= de->mass[i] * (de->p.g[0] * de->x[i] + de->p.g[1] * de->y[i]);
	}
	return E;
}

int dem_de_outline(const dem_de_t *de, size_t i, int cap, double (*v)[2])
{
	const dem_shape_t *s = &de->shape[de->sh[i]];
	if (s->nv <= cap) {
		double xc[2] = {de->x[i], de->y[i]};
		dem_polygon_place(s->nv, (const double (*)[2])s->v, xc, de->th[i], v);
	}
	return s->nv;
}
