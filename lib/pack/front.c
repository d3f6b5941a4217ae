/* front.c - the advancing front packing of disks (Han 2004, Ch. 5.2).
 *
 * Objects.  Walls and disks share one index space: walls are objects
 * 0 .. nw-1 (lines: a point and a unit inward normal, "disks of infinite
 * radius", Ch. 5.2.2), disks follow in the order they were made.  Per-object
 * data are structure-of-arrays.
 *
 * Orientation.  A front segment a -> b takes its new disk on its LEFT and
 * has the filled region on its right.  The open form then reads as in the
 * thesis (left wall -> bottom -> right wall, disks above); the closed front
 * runs clockwise, the mirror image of Fig. 5.4, whose front is
 * anticlockwise with new disks on the right.  Angles of Fig. 5.7 are
 * measured clockwise to match.
 *
 * The front is a doubly linked list through next[]/prev[] (a disk is on the
 * front at most once, so the object index is the node): circular in the
 * closed form, from the left wall (head) to the right wall (tail) in the
 * open form.  live[a] says whether the segment a -> next[a] may still be
 * chosen as active; nlive counts the live segments.
 *
 * Overlaps.  Every candidate is checked against every placed disk near it
 * through a uniform grid (cells as wide as the largest disk, so the 3 x 3
 * block around the candidate's cell holds every disk it can touch), and
 * against the walls.  The front check of Fig. 5.5 / Fig. 5.7 is then only a
 * classification of the overlapping disks that are on the front: the walks
 * forward from m and backward from p stop as soon as all of them are
 * placed, or at the check limit, the 180-degree rule or the list's ends.
 * A candidate that overlaps nothing the walks could place -- a disk behind
 * the front (in a hole left by cases (b)-(d)), or a front disk beyond the
 * check limit -- is never accepted: its segment is given up and the front
 * moves on.  So no accepted disk overlaps another, whatever the check
 * limit.
 *
 * Progress (nothing can run forever).  In one attempt each intermediate
 * step of cases (b)-(d) moves c back or n on over at least one front node,
 * and the walks never pass each other, so an attempt takes at most as many
 * steps as the front has nodes.  Each pass of the main loop then either
 *   1. places a disk: finitely many fit, as disks never overlap and all
 *      lie within a bounded distance of the domain (each is reached from a
 *      live segment, which has an end inside, in at most front-size steps
 *      of a few radii);
 *   2. kills a live segment (a failure without gravity): live segments are
 *      only born when a disk is placed, two at a time;
 *   3. (gravity) tags a live segment as refused for the current radius
 *      (unstable seat, or a failure): at most once per segment and radius;
 *      when every live segment is tagged the radius is dropped, and after
 *      MAXDROPS drops in a row the packing stops.
 * The search for the next live segment walks at most once round the front.
 */
#include "pack/front.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "contact/polygon.h"
#include "core/consts.h"
#include "pack/locus.h"

const char *const dem_front_form_names[] = {"closed", "open", NULL};
const char *const dem_front_shape_names[] = {"disk", "polygon", "ellipse", NULL};

enum { NIL = -1, OFF = -2 };    /* link at an open end; node not on the front */

/* Overlap allowed between accepted disks, relative to the smaller radius:
 * touching disks computed in floating point (the hexagonal lattice is all
 * contacts) must not count as overlapping. */
#define TOUCH 1e-10
/* ... and, far from the origin, the rounding of the coordinates, which
 * there is the larger: a coordinate of magnitude |x| is stored to half an
 * ulp, at most DBL_EPSILON |x| / 2, and a new centre is a few operations
 * from stored ones; 64 ulps leave room for those (at 10^6 radii from the
 * origin 1.4e-8 of a radius, still far below any real overlap). */
#define ROUND (64 * DBL_EPSILON)
/* Radii in a row that no live segment could take stably (gravity) before
 * the packing is taken as complete. */
#define MAXDROPS 16
/* Largest grid, in cells (4 bytes each). */
#define MAXCELLS (1L << 28)
/* Most sides of a polygon; its locus has at most twice as many points. */
#define MAXSIDES 64
/* Ellipses: the levels of the outer bounds of the loci (Ch. 5.4), and
 * Newton's steps at each. */
#define NLEVEL 3
static const int levels[NLEVEL] = {16, 64, 256};
#define NEWTON_MAXIT 30
/* Crossings of two loci kept, at most. */
#define MAXCROSS 16

enum { PLACED, FAIL, UNSTABLE_FWD, UNSTABLE_BWD };

struct wall {
	double qx, qy;          /* a point of the line */
	double nx, ny;          /* unit normal into the domain */
	double ex, ey;          /* polygon edge: from (qx, qy) to (ex, ey) */
	int seg;                /* 1: a segment (polygon edge), 0: a line */
	int pq, pe;             /* the reflex-vertex objects at its two ends,
				 * NIL at a convex vertex */
};

struct packer {
	const dem_front_spec_t *s;
	int closed, gravity;
	long limit;             /* forward/backward check length */
	dem_front_stats_t *st;

	int nw;                 /* walls: objects 0 .. nw-1 */
	int nfix;               /* walls and reflex vertices (disks of radius 0,
				 * objects nw .. nfix-1); disks from nfix on */
	struct wall *w;
	double lo[2], hi[2];    /* the domain's bounding box */
	double *poly;           /* polygon vertices, anticlockwise; NULL: rectangle */
	int npoly;
	double area;            /* of the domain */
	int n, cap;             /* objects so far, room */
	double *x, *y, *r;
	int *prev, *next;       /* front links (OFF: not on the front) */
	unsigned char *live;    /* segment a -> next[a] may be chosen */
	uint32_t *hit;          /* == serial: overlaps the current candidate */
	uint32_t *tag;          /* == radial: segment refused this radius (gravity) */
	int *cnext;             /* next disk in the same grid cell */
	int *sup;               /* the two supports of each disk (gravity) */

	double gx, gy, ginv;    /* grid origin, 1 / cell size */
	int gnx, gny;
	int *cell;              /* first disk of each cell, NIL if none */

	int fhead, ftail;       /* open form: the walls at the ends */
	int fsize, nlive;       /* nodes on the front, live segments */
	double ox, oy;          /* closed form: point O of Fig. 5.7 */
	uint32_t serial, radial;

	int *ov;                /* objects overlapping the current candidate */
	int nov, ovcap;

	/* polygons and ellipses (shape != DEM_FRONT_DISK): r[] is then each
	 * body's bounding radius, and */
	dem_front_shape_t shape;
	int m;                  /* polygon sides */
	double unit[MAXSIDES][2];  /* the unit m-gon, flat side down */
	double unit_area;       /* its area */
	double *ea, *eb, *ec, *es;  /* semi-axes, cos and sin of the rotation */
	double rb;              /* the largest bounding radius */
	struct {                /* the body being placed */
		double a, b, c, s, r, size;
		double mat[3];          /* ellipse: its shape matrix */
		double v[MAXSIDES][2];  /* polygon: its points about the centre */
	} W;
	double cpx[2];          /* x of the contacts with c and n found by the
				 * last tangent (gravity) */
	double (*buf)[2];       /* room for the loci: 4 x (2 MAXSIDES + levels) */
};

/* ---- storage ---------------------------------------------------------- */

static int grow(void **a, size_t n, size_t size)
{
	void *q = realloc(*a, n * size);
	if (!q)
		return -1;
	*a = q;
	return 0;
}

static int reserve(struct packer *p, int need)
{
	if (need <= p->cap)
		return 0;
	size_t cap = p->cap ? (size_t)p->cap : 64;
	while (cap < (size_t)need)
		cap *= 2;
	if (cap > INT_MAX)
		cap = INT_MAX;
	if (grow((void **)&p->x, cap, sizeof *p->x) ||
	    grow((void **)&p->y, cap, sizeof *p->y) ||
	    grow((void **)&p->r, cap, sizeof *p->r) ||
	    grow((void **)&p->prev, cap, sizeof *p->prev) ||
	    grow((void **)&p->next, cap, sizeof *p->next) ||
	    grow((void **)&p->live, cap, sizeof *p->live) ||
	    grow((void **)&p->hit, cap, sizeof *p->hit) ||
	    grow((void **)&p->tag, cap, sizeof *p->tag) ||
	    grow((void **)&p->cnext, cap, sizeof *p->cnext) ||
	    (p->gravity && grow((void **)&p->sup, 2 * cap, sizeof *p->sup)) ||
	    (p->shape && (grow((void **)&p->ea, cap, sizeof *p->ea) ||
			  grow((void **)&p->eb, cap, sizeof *p->eb) ||
			  grow((void **)&p->ec, cap, sizeof *p->ec) ||
			  grow((void **)&p->es, cap, sizeof *p->es))))
		return -1;
	p->cap = (int)cap;
	return 0;
}

static void release(struct packer *p)
{
	free(p->x);
	free(p->y);
	free(p->r);
	free(p->prev);
	free(p->next);
	free(p->live);
	free(p->hit);
	free(p->tag);
	free(p->cnext);
	free(p->sup);
	free(p->cell);
	free(p->ov);
	free(p->w);
	free(p->poly);
	free(p->ea);
	free(p->eb);
	free(p->ec);
	free(p->es);
	free(p->buf);
}

/* ---- grid ------------------------------------------------------------- */

/* Cell index along one axis, clamped to the grid: clamping keeps two
 * points less than a cell apart in the same or adjacent cells, so a disk
 * that strays beyond the grid is still found, only less quickly. */
static int cell_of(double v, double v0, double inv, int nc)
{
	double t = (v - v0) * inv;
	if (!(t >= 0))
		return 0;
	if (t >= nc)
		return nc - 1;
	return (int)t;
}

static void grid_insert(struct packer *p, int i)
{
	int k = cell_of(p->y[i], p->gy, p->ginv, p->gny) * p->gnx +
		cell_of(p->x[i], p->gx, p->ginv, p->gnx);
	p->cnext[i] = p->cell[k];
	p->cell[k] = i;
}

/* Distance from (px, py) to the segment of a polygon wall: a disk near a
 * wall's end is held by the segment, not by the infinite line. */
static double seg_dist(const struct wall *w, double px, double py)
{
	double dx = w->ex - w->qx, dy = w->ey - w->qy;
	double t = ((px - w->qx) * dx + (py - w->qy) * dy) / (dx * dx + dy * dy);
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return hypot(px - (w->qx + t * dx), py - (w->qy + t * dy));
}

/* Crossing number test (even-odd rule) of (x, y) in the n-gon v. */
static int in_polygon(const double *v, int n, double x, double y)
{
	int in = 0;
	for (int i = 0, j = n - 1; i < n; j = i++) {
		double xi = v[2 * i], yi = v[2 * i + 1], xj = v[2 * j], yj = v[2 * j + 1];
		if ((yi > y) != (yj > y) && x < xj + (y - yj) * (xi - xj) / (yi - yj))
			in = !in;
	}
	return in;
}

static int ov_push(struct packer *p, int j)
{
	if (p->nov == p->ovcap) {
		int cap = p->ovcap ? 2 * p->ovcap : 32;
		if (grow((void **)&p->ov, (size_t)cap, sizeof *p->ov))
			return -1;
		p->ovcap = cap;
	}
	p->ov[p->nov++] = j;
	p->hit[j] = p->serial;
	return 0;
}

/* The overlap allowed at (px, py) between bodies whose smaller size is
 * size: TOUCH of it, and ROUND of the coordinates' magnitude. */
static double slack(double size, double px, double py)
{
	return TOUCH * size + ROUND * fmax(fabs(px), fabs(py));
}

/* ---- polygons and ellipses (Ch. 5.3-5.4) ------------------------------ */

/* Room in buf: two loci of LOCMAX points and their parts, then scratch. */
#define LOCMAX 256
#define BUFPTS (4 * LOCMAX + 6 * MAXSIDES)

enum { LOC_LINE, LOC_POLY, LOC_CURVE };

/* The locus of the body being placed round one object: a line n . y = d
 * (a wall), a convex polygon (polygons: the Minkowski sum; ellipses: the
 * outer bound of the curve L, K points an angle du apart). */
struct loc {
	int kind, obj;
	double n[2], d;
	int nv;
	double (*v)[2];         /* the polygon (absolute) */
	double (*pa)[2];        /* polygons: each point's part from the object */
	double du;
	dem_locus_t L;          /* ellipses: the exact locus for Newton */
};

/* A crossing of two loci: the point, and for a polygon the edge and the
 * fraction along it. */
struct cross {
	double x[2];
	int ia, ib;
	double sa, sb;
};

static double body_size(const struct packer *p, int j)
{
	return sqrt(p->ea[j] * p->eb[j]);
}

/* The points of the polygon of semi-axes a, b turned by (c, s), about its
 * centre: the unit m-gon stretched, then turned. */
static void body_polygon(const struct packer *p, double a, double b, double c, double s,
			 double (*v)[2])
{
	for (int k = 0; k < p->m; k++) {
		double x = a * p->unit[k][0], y = b * p->unit[k][1];
		v[k][0] = c * x - s * y;
		v[k][1] = s * x + c * y;
	}
}

/* The support function of the body being placed in the unit direction
 * (dx, dy), and (sp, may be NULL) a support point about its centre. */
static double w_support(const struct packer *p, double dx, double dy, double sp[2])
{
	if (p->shape == DEM_FRONT_ELLIPSE) {
		double n[2] = {dx, dy};
		return dem_ellipse_support(p->W.mat, n, sp);
	}
	int best = 0;
	double h = -HUGE_VAL;
	for (int k = 0; k < p->m; k++) {
		double t = dx * p->W.v[k][0] + dy * p->W.v[k][1];
		if (t > h) {
			h = t;
			best = k;
		}
	}
	if (sp) {
		sp[0] = p->W.v[best][0];
		sp[1] = p->W.v[best][1];
	}
	return h;
}

/* Where the body placed at (px, py) touches the line of wall k. */
static void wall_touch(const struct packer *p, int k, double px, double py, double *tx, double *ty)
{
	double sp[2];
	w_support(p, -p->w[k].nx, -p->w[k].ny, sp);
	*tx = px + sp[0];
	*ty = py + sp[1];
}

/* -W: the body being placed turned through 180 degrees (still
 * anticlockwise), into v. */
static void w_negated(const struct packer *p, double (*v)[2])
{
	for (int k = 0; k < p->m; k++) {
		v[k][0] = -p->W.v[k][0];
		v[k][1] = -p->W.v[k][1];
	}
}

/* Does the body being placed, at (px, py), overlap body or reflex vertex
 * j by more than slack() of the smaller size?  (Its bounding circle meets
 * j's.) */
static int shape_overlap(struct packer *p, int j, double px, double py)
{
	double dx = px - p->x[j], dy = py - p->y[j];
	if (p->shape == DEM_FRONT_ELLIPSE) {
		/* the factor both would be scaled by to touch: the slack
		 * relative to the size */
		double f = 1 - slack(p->W.size, px, py) / p->W.size;
		double lim = f * f;
		const double *m = p->W.mat;
		if (j < p->nfix) {      /* the vertex inside the ellipse */
			double det = m[0] * m[2] - m[1] * m[1];
			double q = (m[2] * dx * dx - 2 * m[1] * dx * dy + m[0] * dy * dy) / det;
			return q < lim;
		}
		/* the inscribed circles overlap: so do the ellipses */
		if (hypot(dx, dy) < f * (p->W.b + p->eb[j]))
			return 1;
		double mj[3], d[2] = {dx, dy};
		dem_ellipse_matrix(p->ea[j], p->eb[j], p->ec[j], p->es[j], mj);
		return dem_ellipse_pw(mj, m, d, lim, &p->st->overlap_evals) < lim;
	}
	double q[2] = {dx, dy};
	if (j < p->nfix) {      /* the vertex inside W, deeper than the slack */
		q[0] = -dx, q[1] = -dy;
		return dem_convex_depth(p->m, (const double (*)[2])p->W.v, q) > slack(p->W.size, px, py);
	}
	double (*P)[2] = p->buf + 4 * LOCMAX, (*N)[2] = P + MAXSIDES, (*S)[2] = N + MAXSIDES;
	body_polygon(p, p->ea[j], p->eb[j], p->ec[j], p->es[j], P);
	w_negated(p, N);
	int ns = dem_minkowski(p->m, (const double (*)[2])P, p->m, (const double (*)[2])N, S, NULL);
	return dem_convex_depth(ns, (const double (*)[2])S, q) >
	       slack(fmin(p->W.size, body_size(p, j)), px, py);
}

/* Does the body being placed, at (px, py), cross wall k by more than tol
 * (a length)?  A rectangle's wall is a line, a polygon's edge a segment. */
static int shape_wall_overlap(struct packer *p, int k, double px, double py, double tol)
{
	const struct wall *w = &p->w[k];
	if (!w->seg)
		return (px - w->qx) * w->nx + (py - w->qy) * w->ny - w_support(p, -w->nx, -w->ny, NULL) < -tol;
	if (p->shape == DEM_FRONT_ELLIPSE) {
		/* the segment in the frame where the ellipse is the unit
		 * circle; there a depth tol is at least tol / a */
		double u[2][2], c = p->W.c, s = p->W.s;
		const double e[2][2] = {{w->qx - px, w->qy - py}, {w->ex - px, w->ey - py}};
		for (int i = 0; i < 2; i++) {
			u[i][0] = (c * e[i][0] + s * e[i][1]) / p->W.a;
			u[i][1] = (-s * e[i][0] + c * e[i][1]) / p->W.b;
		}
		double dx = u[1][0] - u[0][0], dy = u[1][1] - u[0][1];
		double t = -(u[0][0] * dx + u[0][1] * dy) / (dx * dx + dy * dy);
		t = t < 0 ? 0 : t > 1 ? 1 : t;
		return hypot(u[0][0] + t * dx, u[0][1] + t * dy) < 1 - tol / p->W.a;
	}
	double (*G)[2] = p->buf + 4 * LOCMAX, (*N)[2] = G + MAXSIDES, (*S)[2] = N + MAXSIDES;
	G[0][0] = w->qx, G[0][1] = w->qy, G[1][0] = w->ex, G[1][1] = w->ey;
	w_negated(p, N);
	int ns = dem_minkowski(2, (const double (*)[2])G, p->m, (const double (*)[2])N, S, NULL);
	double q[2] = {px, py};
	return dem_convex_depth(ns, (const double (*)[2])S, q) > tol;
}

/* The locus of the body being placed round object k (K: the ellipses'
 * level), its points in v and pa (room for LOCMAX each). */
static void make_locus(const struct packer *p, int k, int K, struct loc *L, double (*v)[2],
		       double (*pa)[2])
{
	L->obj = k;
	L->v = v;
	L->pa = pa;
	memset(&L->L, 0, sizeof L->L);
	if (k < p->nw) {
		const struct wall *w = &p->w[k];
		double h = w_support(p, -w->nx, -w->ny, NULL);
		L->kind = LOC_LINE;
		L->n[0] = w->nx, L->n[1] = w->ny;
		L->d = w->qx * w->nx + w->qy * w->ny + h;
		L->L.line = 1;
		L->L.c[0] = w->qx + h * w->nx, L->L.c[1] = w->qy + h * w->ny;
		L->L.t[0] = -w->ny, L->L.t[1] = w->nx;
		return;
	}
	if (p->shape == DEM_FRONT_ELLIPSE) {
		L->kind = LOC_CURVE;
		L->L.c[0] = p->x[k], L->L.c[1] = p->y[k];
		if (k >= p->nfix)
			dem_ellipse_matrix(p->ea[k], p->eb[k], p->ec[k], p->es[k], L->L.m1);
		memcpy(L->L.m2, p->W.mat, sizeof L->L.m2);
		L->nv = K;
		L->du = 2 * DEM_PI / K;
		dem_locus_outer(&L->L, K, v);
		return;
	}
	L->kind = LOC_POLY;
	double (*N)[2] = p->buf + 4 * LOCMAX, (*P)[2] = N + MAXSIDES;
	w_negated(p, N);
	if (k < p->nfix) {      /* a reflex vertex: -W about it */
		double o[1][2] = {{0, 0}};
		L->nv = dem_minkowski(1, (const double (*)[2])o, p->m, (const double (*)[2])N, v, pa);
	} else {
		body_polygon(p, p->ea[k], p->eb[k], p->ec[k], p->es[k], P);
		L->nv = dem_minkowski(p->m, (const double (*)[2])P, p->m, (const double (*)[2])N, v, pa);
	}
	for (int i = 0; i < L->nv; i++)
		v[i][0] += p->x[k], v[i][1] += p->y[k];
}

/* The crossings of a line (n . y = d) with the polygon L; each edge
 * counts its first point, not its last.  side: which of ia/ib is the
 * polygon's edge. */
static int cross_line_poly(const double n[2], double d, const struct loc *L, int side,
			   struct cross *out, int k)
{
	for (int i = 0; i < L->nv && k < MAXCROSS; i++) {
		const double *a = L->v[i], *b = L->v[(i + 1) % L->nv];
		double s0 = n[0] * a[0] + n[1] * a[1] - d, s1 = n[0] * b[0] + n[1] * b[1] - d;
		if (!((s0 <= 0 && s1 > 0) || (s0 > 0 && s1 <= 0)))
			continue;
		double t = s0 / (s0 - s1);
		struct cross *c = &out[k++];
		c->x[0] = a[0] + t * (b[0] - a[0]);
		c->x[1] = a[1] + t * (b[1] - a[1]);
		c->ia = side ? -1 : i, c->sa = t;
		c->ib = side ? i : -1, c->sb = t;
	}
	return k;
}

/* The crossings of the loci A and B (at most MAXCROSS). */
static int cross_loci(const struct loc *A, const struct loc *B, struct cross *out)
{
	if (A->kind == LOC_LINE && B->kind == LOC_LINE) {
		double det = A->n[0] * B->n[1] - A->n[1] * B->n[0];
		if (fabs(det) < 1e-12)
			return 0;
		out[0].x[0] = (A->d * B->n[1] - B->d * A->n[1]) / det;
		out[0].x[1] = (A->n[0] * B->d - B->n[0] * A->d) / det;
		out[0].ia = out[0].ib = -1;
		return 1;
	}
	if (A->kind == LOC_LINE)
		return cross_line_poly(A->n, A->d, B, 1, out, 0);
	if (B->kind == LOC_LINE)
		return cross_line_poly(B->n, B->d, A, 0, out, 0);
	/* two convex polygons: every pair of edges whose boxes meet */
	double blo[2] = {HUGE_VAL, HUGE_VAL}, bhi[2] = {-HUGE_VAL, -HUGE_VAL};
	for (int j = 0; j < B->nv; j++)
		for (int d = 0; d < 2; d++) {
			blo[d] = fmin(blo[d], B->v[j][d]);
			bhi[d] = fmax(bhi[d], B->v[j][d]);
		}
	int k = 0;
	for (int i = 0; i < A->nv && k < MAXCROSS; i++) {
		const double *a0 = A->v[i], *a1 = A->v[(i + 1) % A->nv];
		if (fmax(a0[0], a1[0]) < blo[0] || fmin(a0[0], a1[0]) > bhi[0] ||
		    fmax(a0[1], a1[1]) < blo[1] || fmin(a0[1], a1[1]) > bhi[1])
			continue;
		double rx = a1[0] - a0[0], ry = a1[1] - a0[1];
		for (int j = 0; j < B->nv && k < MAXCROSS; j++) {
			const double *b0 = B->v[j], *b1 = B->v[(j + 1) % B->nv];
			if (fmax(a0[0], a1[0]) < fmin(b0[0], b1[0]) || fmin(a0[0], a1[0]) > fmax(b0[0], b1[0]) ||
			    fmax(a0[1], a1[1]) < fmin(b0[1], b1[1]) || fmin(a0[1], a1[1]) > fmax(b0[1], b1[1]))
				continue;
			double sx = b1[0] - b0[0], sy = b1[1] - b0[1];
			double den = rx * sy - ry * sx;
			if (den == 0)
				continue;
			double qx = b0[0] - a0[0], qy = b0[1] - a0[1];
			double t = (qx * sy - qy * sx) / den, u = (qx * ry - qy * rx) / den;
			if (!(t >= 0 && t < 1 && u >= 0 && u < 1))
				continue;
			struct cross *c = &out[k++];
			c->x[0] = a0[0] + t * rx;
			c->x[1] = a0[1] + t * ry;
			c->ia = i, c->sa = t, c->ib = j, c->sb = u;
		}
	}
	return k;
}

/* The x of the contact with a body's locus at a crossing on its edge i at
 * fraction s (polygons). */
static double contact_poly(const struct packer *p, const struct loc *L, int i, double s)
{
	const double *a = L->pa[i], *b = L->pa[(i + 1) % L->nv];
	return p->x[L->obj] + a[0] + s * (b[0] - a[0]);
}

/* ... and on an ellipse's curve at the normal angle u. */
static double contact_curve(const struct packer *p, const struct loc *L, double u)
{
	double n[2] = {cos(u), sin(u)}, sp[2] = {0, 0};
	if (L->obj >= p->nfix)
		dem_ellipse_support(L->L.m1, n, sp);
	return p->x[L->obj] + sp[0];
}

/* The Newton start on locus L from a crossing on its edge i at s. */
static double start_param(const struct loc *L, int i, double s, const double x[2])
{
	if (L->kind == LOC_LINE)
		return (x[0] - L->L.c[0]) * L->L.t[0] + (x[1] - L->L.c[1]) * L->L.t[1];
	return (i + 0.5 + s) * L->du;
}

/* The centre of the body being placed touching objects a and b, on the
 * left of a -> b (Fig. 5.14(b), Fig. 5.16(b)): of the crossings of the
 * two loci, the one furthest to the left of the direction from a to b
 * (from a wall, its normal; to a wall, minus its normal).  Returns 0 when
 * the loci do not cross.  Sets cpx, the contacts' x (gravity). */
static int shape_tangent(struct packer *p, int a, int b, double *px, double *py)
{
	struct loc A, B;
	struct cross c[MAXCROSS];
	double dir[2];
	if (a < p->nw)
		dir[0] = p->w[a].nx, dir[1] = p->w[a].ny;
	else if (b < p->nw)
		dir[0] = -p->w[b].nx, dir[1] = -p->w[b].ny;
	else
		dir[0] = p->x[b] - p->x[a], dir[1] = p->y[b] - p->y[a];
	int nlev = p->shape == DEM_FRONT_ELLIPSE ? NLEVEL : 1;
	for (int lev = 0; lev < nlev; lev++) {
		make_locus(p, a, levels[lev], &A, p->buf, p->buf + LOCMAX);
		make_locus(p, b, levels[lev], &B, p->buf + 2 * LOCMAX, p->buf + 3 * LOCMAX);
		int nc = cross_loci(&A, &B, c), best = -1;
		double sbest = -HUGE_VAL;
		for (int k = 0; k < nc; k++) {
			double sc = dir[0] * c[k].x[1] - dir[1] * c[k].x[0];
			if (sc > sbest) {
				sbest = sc;
				best = k;
			}
		}
		if (best < 0)
			return 0;       /* the (outer bounds of the) loci do not cross */
		const struct cross *x0 = &c[best];
		if (p->shape == DEM_FRONT_POLYGON || (A.kind == LOC_LINE && B.kind == LOC_LINE)) {
			*px = x0->x[0];
			*py = x0->x[1];
			p->cpx[0] = A.kind == LOC_POLY ? contact_poly(p, &A, x0->ia, x0->sa) : *px;
			p->cpx[1] = B.kind == LOC_POLY ? contact_poly(p, &B, x0->ib, x0->sb) : *px;
			return 1;
		}
		/* ellipses: Newton from the crossing of the outer bounds */
		double u = start_param(&A, x0->ia, x0->sa, x0->x);
		double v = start_param(&B, x0->ib, x0->sb, x0->x);
		double tol = 1e-13 * p->W.size + 8 * DBL_EPSILON * (fabs(x0->x[0]) + fabs(x0->x[1]));
		p->st->newton++;
		int steps;
		int ok = dem_locus_meet(&A.L, &B.L, &u, &v, tol, NEWTON_MAXIT, &steps) >= 0;
		double x[2];
		p->st->newton_iters += (size_t)steps;   /* converged or not */
		if (ok) {
			dem_locus_eval(&A.L, u, x, NULL);
			double d0 = hypot(x[0] - x0->x[0], x[1] - x0->x[1]);
			ok = d0 <= p->W.r;
			for (int k = 0; k < nc && ok; k++)
				if (k != best && hypot(x[0] - c[k].x[0], x[1] - c[k].x[1]) < d0)
					ok = 0;
		}
		if (ok) {
			*px = x[0];
			*py = x[1];
			p->cpx[0] = A.kind == LOC_CURVE ? contact_curve(p, &A, u) : *px;
			p->cpx[1] = B.kind == LOC_CURVE ? contact_curve(p, &B, v) : *px;
			return 1;
		}
		p->st->newton_failed++;
		if (lev == nlev - 1) {
			/* fall-back: the crossing of the outer bounds, outside
			 * both loci, so overlapping neither */
			p->st->fallbacks++;
			*px = x0->x[0];
			*py = x0->x[1];
			u = start_param(&A, x0->ia, x0->sa, x0->x);
			v = start_param(&B, x0->ib, x0->sb, x0->x);
			p->cpx[0] = A.kind == LOC_CURVE ? contact_curve(p, &A, u) : *px;
			p->cpx[1] = B.kind == LOC_CURVE ? contact_curve(p, &B, v) : *px;
			return 1;
		}
	}
	return 0;
}

/* Is the body being placed, at (px, py), wholly inside the domain, to
 * tol (a length)? */
static int shape_inside(struct packer *p, double px, double py, double tol)
{
	if (p->poly) {
		if (!in_polygon(p->poly, p->npoly, px, py))
			return 0;
		for (int k = 0; k < p->nw; k++)
			if (shape_wall_overlap(p, k, px, py, tol))
				return 0;
		return 1;
	}
	const dem_front_spec_t *s = p->s;
	for (int d = 0; d < 2; d++) {
		double v = d ? py : px;
		double hlo = w_support(p, d ? 0 : -1, d ? -1 : 0, NULL);
		double hhi = w_support(p, d ? 0 : 1, d ? 1 : 0, NULL);
		if (v - hlo < s->lo[d] - tol || v + hhi > s->hi[d] + tol)
			return 0;
	}
	return 1;
}

/* Make the body of semi-axes a, b turned by (c, s) the one being placed. */
static void set_w(struct packer *p, double a, double b, double c, double s)
{
	p->W.a = a, p->W.b = b, p->W.c = c, p->W.s = s;
	p->W.size = sqrt(a * b);
	if (p->shape == DEM_FRONT_ELLIPSE) {
		dem_ellipse_matrix(a, b, c, s, p->W.mat);
		p->W.r = a;
	} else {
		body_polygon(p, a, b, c, s, p->W.v);
		p->W.r = 0;
		for (int k = 0; k < p->m; k++)
			p->W.r = fmax(p->W.r, hypot(p->W.v[k][0], p->W.v[k][1]));
	}
}

/* Collect into ov every object that the disk (px, py, r) overlaps; return
 * how many of them are on the front, or -1 without memory. */
static int collect(struct packer *p, double px, double py, double r)
{
	int ix = cell_of(px, p->gx, p->ginv, p->gnx);
	int iy = cell_of(py, p->gy, p->ginv, p->gny);
	int onfront = 0;
	double round = slack(0, px, py);

	if (++p->serial == 0) {         /* wrapped: stale marks could match */
		memset(p->hit, 0, (size_t)p->n * sizeof *p->hit);
		p->serial = 1;
	}
	p->nov = 0;
	for (int cy = iy > 0 ? iy - 1 : 0; cy <= iy + 1 && cy < p->gny; cy++)
		for (int cx = ix > 0 ? ix - 1 : 0; cx <= ix + 1 && cx < p->gnx; cx++)
			for (int j = p->cell[cy * p->gnx + cx]; j != NIL; j = p->cnext[j]) {
				double dx = px - p->x[j], dy = py - p->y[j];
				double rj = p->r[j];
				/* a reflex vertex (rj = 0) takes the disk's own
				 * tolerance, so a disk touching it is no overlap */
				double d = r + rj - TOUCH * (rj > 0 && rj < r ? rj : r) - round;
				if (p->shape ? dx * dx + dy * dy < (r + rj) * (r + rj) &&
					       shape_overlap(p, j, px, py)
					     : dx * dx + dy * dy < d * d) {
					if (ov_push(p, j))
						return -1;
					onfront += p->next[j] != OFF;
				}
			}
	for (int k = 0; k < p->nw; k++) {
		const struct wall *w = &p->w[k];
		if (p->shape ? shape_wall_overlap(p, k, px, py, slack(p->W.size, px, py))
		    : w->seg ? seg_dist(w, px, py) < r * (1 - TOUCH) - round
			     : (px - w->qx) * w->nx + (py - w->qy) * w->ny < r * (1 - TOUCH) - round) {
			if (ov_push(p, k))
				return -1;
			onfront += p->next[k] != OFF;
		}
	}
	return onfront;
}

/* ---- geometry --------------------------------------------------------- */

/* The centre of a disk of radius r touching objects a and b, on the left
 * of a -> b (Fig. 5.5, step 1).  Returns 0 when there is none (the two are
 * too far apart, or two parallel walls). */
static int tangent(struct packer *p, int a, int b, double r,
		   double *px, double *py)
{
	if (p->shape)
		return shape_tangent(p, a, b, px, py);
	if (a >= p->nw && b >= p->nw) {
		/* two circles of radii ra + r and rb + r about the centres */
		double dx = p->x[b] - p->x[a], dy = p->y[b] - p->y[a];
		double d2 = dx * dx + dy * dy, d = sqrt(d2);
		double da = p->r[a] + r, db = p->r[b] + r;
		if (!(d > 0) || d > da + db)
			return 0;
		double t = (da * da - db * db + d2) / (2 * d);
		double h2 = da * da - t * t;
		if (h2 < 0) {
			if (h2 < -1e-12 * da * da)
				return 0;
			h2 = 0;         /* rounding: the gap is exactly 2r */
		}
		double h = sqrt(h2);
		*px = p->x[a] + (t * dx - h * dy) / d;
		*py = p->y[a] + (t * dy + h * dx) / d;
		return 1;
	}
	if (a < p->nw && b < p->nw) {
		/* a corner: where the two lines moved inwards by r cross */
		const struct wall *u = &p->w[a], *v = &p->w[b];
		double det = u->nx * v->ny - u->ny * v->nx;
		if (fabs(det) < 1e-12)
			return 0;
		double cu = r + u->qx * u->nx + u->qy * u->ny;
		double cv = r + v->qx * v->nx + v->qy * v->ny;
		*px = (cu * v->ny - cv * u->ny) / det;
		*py = (u->nx * cv - v->nx * cu) / det;
		return 1;
	}
	/* a wall and a disk: the line moved inwards by r against the circle of
	 * radius rd + r.  In the frame (normal n, tangent tv) the normal
	 * coordinate is the wall's plus r, so an axis-parallel wall gives the
	 * centre's distance from it rounded only once. */
	int k = a < p->nw ? a : b, d = a < p->nw ? b : a;
	const struct wall *w = &p->w[k];
	/* tangent direction: left of (disk -> wall) = left of -n, or left of
	 * (wall -> disk) = left of n */
	double tx = a < p->nw ? -w->ny : w->ny, ty = a < p->nw ? w->nx : -w->nx;
	double s = (p->x[d] - w->qx) * w->nx + (p->y[d] - w->qy) * w->ny;
	double dn = r - s, dd = p->r[d] + r;
	double t2 = dd * dd - dn * dn;
	if (t2 < 0) {
		if (t2 < -1e-12 * dd * dd)
			return 0;
		t2 = 0;
	}
	double cn = w->qx * w->nx + w->qy * w->ny + r;
	double ct = p->x[d] * tx + p->y[d] * ty + sqrt(t2);
	*px = cn * w->nx + ct * tx;
	*py = cn * w->ny + ct * ty;
	return 1;
}

/* Is object i's centre outside the region still to be filled?  Closed
 * form: outside the rectangle (Ch. 5.2.1, segment deactivation); open
 * form: above the lid (Ch. 5.2.2). */
static int outside(const struct packer *p, int i)
{
	const dem_front_spec_t *s = p->s;
	if (p->poly)    /* the reflex vertices count as inside */
		return i >= p->nfix && !in_polygon(p->poly, p->npoly, p->x[i], p->y[i]);
	if (!p->closed)
		return p->y[i] > s->hi[1];
	return p->x[i] < s->lo[0] || p->x[i] > s->hi[0] ||
	       p->y[i] < s->lo[1] || p->y[i] > s->hi[1];
}

/* A segment is deactivated when both its disks lie outside; a wall end
 * follows the other end; a corner (two walls) stays live. */
static int seg_live(const struct packer *p, int a, int b)
{
	if (a < p->nw && b < p->nw)
		return 1;
	if (a < p->nw)
		return !outside(p, b);
	if (b < p->nw)
		return !outside(p, a);
	return !(outside(p, a) && outside(p, b));
}

/* Signed angle D_s O D_t of Fig. 5.7(a), positive clockwise (our front's
 * sense of travel). */
static double angle(const struct packer *p, int s, int t)
{
	double ax = p->x[s] - p->ox, ay = p->y[s] - p->oy;
	double bx = p->x[t] - p->ox, by = p->y[t] - p->oy;
	return atan2(-(ax * by - ay * bx), ax * bx + ay * by);
}

/* ---- the front -------------------------------------------------------- */

/* Make a -> b a segment of the front (a new segment: it is live unless
 * both ends lie outside, and untried). */
static void link(struct packer *p, int a, int b)
{
	p->nlive -= p->live[a];
	p->next[a] = b;
	p->prev[b] = a;
	p->live[a] = (unsigned char)seg_live(p, a, b);
	p->nlive += p->live[a];
	p->tag[a] = 0;
}

/* Take the nodes a .. b (following next) off the front. */
static void unlink_range(struct packer *p, int a, int b)
{
	for (int d = a;;) {
		int nx = p->next[d];
		p->nlive -= p->live[d];
		p->live[d] = 0;
		p->next[d] = p->prev[d] = OFF;
		p->fsize--;
		if (d == b)
			break;
		d = nx;
	}
}

static void kill(struct packer *p, int a)
{
	p->nlive -= p->live[a];
	p->live[a] = 0;
}

/* A new disk object (not yet on the front); -1 without room. */
static int add_disk(struct packer *p, double x, double y, double r)
{
	if (p->n == INT_MAX || reserve(p, p->n + 1))
		return -1;
	int i = p->n++;
	p->x[i] = x;
	p->y[i] = y;
	p->r[i] = r;
	if (p->shape) {
		p->ea[i] = p->W.a;
		p->eb[i] = p->W.b;
		p->ec[i] = p->W.c;
		p->es[i] = p->W.s;
	}
	p->prev[i] = p->next[i] = OFF;
	p->live[i] = 0;
	p->hit[i] = 0;
	p->tag[i] = 0;
	if (p->gravity)
		p->sup[2 * i] = p->sup[2 * i + 1] = NIL;
	grid_insert(p, i);
	p->st->placed++;
	return i;
}

/* The overlapping objects on the front, placed relative to the active
 * segment c -> n: *j the first one met going forward from m (a subsequent
 * disk), *u the first met going backward from p (a preceding disk), NIL if
 * none; *js, *us how many steps the walks took to meet them.  Closed form:
 * a disk is subsequent while the angle accumulated from c stays within 180
 * degrees, preceding while the angle accumulated backwards does (Fig.
 * 5.7(b)); the two walks share none of the room nodes of the front (all
 * but c and n).  Open form: the list's order decides, no angles needed
 * (Ch. 5.2.2).  Both walks stop at the check limit, and as soon as every
 * overlapping front object has been met (in either walk), which keeps
 * them short. */
static void classify(const struct packer *p, int c, int n, long room,
		     int onfront, int *pu, int *pj, long *us, long *js)
{
	int u = NIL, j = NIL, found = 0;
	int f = p->next[n], fp = n, b = p->prev[c], bp = c;
	int fdone = 0, bdone = 0;
	long kf = 0, kb = 0;
	double af = p->closed ? angle(p, c, n) : 0, ab = 0;

	while (!(fdone && bdone) && found < onfront) {
		if (!fdone) {
			if (f < 0 || kf >= p->limit || room <= 0)
				fdone = 1;
			else if (p->closed && (af += angle(p, fp, f)) > DEM_PI)
				fdone = 1;
			else {
				kf++;
				room--;
				if (p->hit[f] == p->serial) {
					found++;
					if (j == NIL) {
						j = f;
						*js = kf;
					}
				}
				fp = f;
				f = p->next[f];
			}
		}
		if (!bdone && found < onfront) {
			if (b < 0 || kb >= p->limit || room <= 0)
				bdone = 1;
			else if (p->closed && (ab += angle(p, b, bp)) > DEM_PI)
				bdone = 1;
			else {
				kb++;
				room--;
				if (p->hit[b] == p->serial) {
					found++;
					if (u == NIL) {
						u = b;
						*us = kb;
					}
				}
				bp = b;
				b = p->prev[b];
			}
		}
	}
	*pu = u;
	*pj = j;
}

/* Where object k (h: 0 the segment's start, 1 its end) holds up the body
 * centred at (px, py): the x of the contact.  A disk: on a wall the foot
 * of the perpendicular from the centre, on a disk its centre (the same
 * vertical order as the contact point, Fig. 5.9).  A polygon or an
 * ellipse: where it really touches, its support point towards the wall
 * (not below its centre unless the wall's normal is one of its axes), or
 * the contact the last tangent found on a body. */
static double support_x(const struct packer *p, int k, int h, double px, double py)
{
	if (k < p->nw) {
		const struct wall *w = &p->w[k];
		double tx, ty;
		if (p->shape) {
			wall_touch(p, k, px, py, &tx, &ty);
			return tx;
		}
		return px - ((px - w->qx) * w->nx + (py - w->qy) * w->ny) * w->nx;
	}
	return p->shape ? p->cpx[h] : p->x[k];
}

/* Fig. 5.9: the disk rests on c and n when the vertical through its centre
 * meets the segment between their support points.  The disk lies left of
 * c -> n, so with c's point left of n's it is above the segment and the
 * two contact forces are compressive.  Otherwise say on which side gravity
 * misses, so the front can move that way (downhill). */
static int stability(const struct packer *p, int c, int n, double px, double py)
{
	double a = support_x(p, c, 0, px, py), b = support_x(p, n, 1, px, py);
	if (px < a)
		return UNSTABLE_BWD;
	if (px > b)
		return UNSTABLE_FWD;
	return PLACED;
}

/* Place a disk of radius r on the active segment *c -> *n: Steps 1 and 2
 * of Ch. 5.2.1 with the four cases of Fig. 5.5.  The intermediate
 * segments of cases (b)-(d) are tentative: the front is left as it was
 * until a disk is placed, and only then are the nodes between the final
 * c and n taken off it.  So a candidate refused at the end (no room, an
 * overlap the front check cannot place, or -- gravity -- an unstable seat)
 * costs nothing: no bridge over a pocket that stays empty, no real contact
 * hidden behind the front.  On return *c -> *n is the segment last tried
 * and, when PLACED, *i the new disk.  -1 without memory, -2 for a
 * candidate not finite (check_spec's ranges should make that impossible). */
static int attempt(struct packer *p, int *pc, int *pn, double r, int *pi)
{
	int c = *pc, n = *pn, res;
	/* room nodes of the closed front: all but c and n, less the nodes
	 * dropped tentatively */
	long room = p->closed ? p->fsize - 2 : LONG_MAX;

	for (;;) {
		double px, py;
		p->st->attempts++;
		if (!tangent(p, c, n, r, &px, &py) ||
		    (p->poly && !in_polygon(p->poly, p->npoly, px, py))) {
			/* (a polygon: a centre outside is behind a wall, from
			 * the corner of two walls that are not neighbours) */
			res = FAIL;
			break;
		}
		if (!(isfinite(px) && isfinite(py)))
			return -2;      /* a NaN would pass every overlap test */
		if (p->poly) {
			/* a disk touching a wall's line beyond a reflex end
			 * touches no wall: go on from that vertex instead, a
			 * disk of radius 0 next on the front */
			int k = c < p->nw ? c : n < p->nw ? n : NIL, v = NIL;
			if (k != NIL) {
				const struct wall *w = &p->w[k];
				double tx = px, ty = py;        /* where it touches */
				if (p->shape)
					wall_touch(p, k, px, py, &tx, &ty);
				double t = (tx - w->qx) * (w->ex - w->qx) + (ty - w->qy) * (w->ey - w->qy);
				double l2 = (w->ex - w->qx) * (w->ex - w->qx) + (w->ey - w->qy) * (w->ey - w->qy);
				v = t < 0 ? w->pq : t > l2 ? w->pe : NIL;
			}
			if (v != NIL) {
				if (k == n && p->next[n] == v)
					n = v;
				else if (k == c && p->prev[c] == v)
					c = v;
				else {
					res = FAIL;
					break;
				}
				continue;
			}
		}
		int onfront = collect(p, px, py, r);
		if (onfront < 0)
			return -1;
		if (p->nov == 0) {
			/* Fig. 5.5(a): no overlap */
			if (p->gravity && (res = stability(p, c, n, px, py)) != PLACED) {
				p->st->unstable++;
				break;
			}
			int i = add_disk(p, px, py, r);
			if (i < 0)
				return -1;
			if (p->gravity) {
				p->sup[2 * i] = c;
				p->sup[2 * i + 1] = n;
			}
			/* commit: the nodes between c and n enclose holes */
			if (p->next[c] != n)
				unlink_range(p, p->next[c], p->prev[n]);
			link(p, c, i);
			link(p, i, n);
			p->fsize++;
			if ((size_t)p->fsize > p->st->front_max)
				p->st->front_max = (size_t)p->fsize;
			*pi = i;
			res = PLACED;
			break;
		}
		int u, j;
		long us = 0, js = 0;
		classify(p, c, n, room, onfront, &u, &j, &us, &js);
		if (u == NIL && j == NIL) {
			/* the overlap is with a disk behind the front or beyond
			 * the check limit: no intermediate segment can be built
			 * from it, so this segment is given up */
			res = FAIL;
			break;
		}
		/* Fig. 5.5(b): drop n .. k, the js nodes before j;
		 * Fig. 5.5(c): drop v .. c, the us nodes after u;
		 * Fig. 5.5(d): both.  The dropped part of the front and the
		 * intermediate segment u -> j enclose a hole left unfilled. */
		if (j != NIL) {
			n = j;
			room -= js;
		}
		if (u != NIL) {
			c = u;
			room -= us;
		}
		p->st->cases[j != NIL && u != NIL ? 2 : j != NIL ? 0 : 1]++;
	}
	*pc = c;
	*pn = n;
	return res;
}

/* The next segment at or after node a that may take the current disk:
 * live, and (gravity) not yet refused for this radius.  NIL when none
 * (then every live segment has refused it).  Walks round the front at
 * most once. */
static int find_segment(const struct packer *p, int a)
{
	for (int k = 0; k <= p->fsize; k++) {
		if (p->next[a] >= 0 && p->live[a] &&
		    !(p->gravity && p->tag[a] == p->radial))
			return a;
		a = p->next[a];
		if (a < 0)
			a = p->fhead;   /* open form: past the right wall */
	}
	return NIL;
}

static double new_radius(struct packer *p, gsl_rng *rng)
{
	if (++p->radial == 0) {         /* wrapped: stale tags could match */
		memset(p->tag, 0, (size_t)p->n * sizeof *p->tag);
		p->radial = 1;
	}
	double r = dem_radius_draw(&p->s->law, rng);
	if (!p->shape)
		return r;
	/* a body: its aspect ratio and rotation drawn after its size */
	double al = p->s->ratio.rmin > 0 ? dem_radius_draw(&p->s->ratio, rng) : 1;
	double th = gsl_rng_uniform(rng) * (p->shape == DEM_FRONT_ELLIPSE ? DEM_PI : 2 * DEM_PI);
	set_w(p, r * sqrt(al), r / sqrt(al), cos(th), sin(th));
	return p->W.r;
}

/* ---- the two initial fronts ------------------------------------------- */

/* Ch. 5.2.1: three touching disks about the centre of the domain; the
 * front D1 -> D2 -> D3 -> D1 (clockwise here); O their centroid. */
static int start_closed(struct packer *p, gsl_rng *rng, int *seg)
{
	const dem_front_spec_t *s = p->s;
	int d1, d2, d3;
	double x3, y3;
	if (p->shape) {
		/* D2 touching D1 on its right: the ray from D1's centre
		 * leaves D1's locus once (it is convex), found by bisection */
		double r1 = new_radius(p, rng);
		if ((d1 = add_disk(p, 0, 0, r1)) < 0)
			return -1;
		double r2 = new_radius(p, rng), lo = 0, hi = r1 + r2;
		for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; k++) {
			double mid = 0.5 * (lo + hi);
			if (shape_overlap(p, d1, mid, 0))
				lo = mid;
			else
				hi = mid;
		}
		if ((d2 = add_disk(p, hi, 0, r2)) < 0)
			return -1;
		double r3 = new_radius(p, rng);
		if (!tangent(p, d2, d1, r3, &x3, &y3) || (d3 = add_disk(p, x3, y3, r3)) < 0)
			return -1;
	} else {
		double r1 = new_radius(p, rng), r2 = new_radius(p, rng), r3 = new_radius(p, rng);
		d1 = add_disk(p, 0, 0, r1);
		if (d1 < 0 || (d2 = add_disk(p, r1 + r2, 0, r2)) < 0)
			return -1;
		tangent(p, d2, d1, r3, &x3, &y3);       /* below D1 -> D2 */
		if ((d3 = add_disk(p, x3, y3, r3)) < 0)
			return -1;
	}
	/* move the triangle's centroid to the centre; the grid is rebuilt */
	double cx = (p->x[d1] + p->x[d2] + p->x[d3]) / 3;
	double cy = (p->y[d1] + p->y[d2] + p->y[d3]) / 3;
	double mx = 0.5 * (s->lo[0] + s->hi[0]), my = 0.5 * (s->lo[1] + s->hi[1]);
	for (int i = 0; i < p->gnx * p->gny; i++)
		p->cell[i] = NIL;
	for (int i = d1; i <= d3; i++) {
		p->x[i] += mx - cx;
		p->y[i] += my - cy;
		grid_insert(p, i);
	}
	p->ox = mx;
	p->oy = my;
	link(p, d1, d2);
	link(p, d2, d3);
	link(p, d3, d1);
	p->fsize = 3;
	p->st->front_max = 3;
	*seg = d1;
	return 0;
}

/* Ch. 5.2.2: the walls B_l -> B_b -> B_r as an open front; the first
 * active segment is the bottom-left corner. */
static void start_open(struct packer *p, int *seg)
{
	const dem_front_spec_t *s = p->s;
	p->w[0] = (struct wall){s->lo[0], s->lo[1], 1, 0, 0, 0, 0, NIL, NIL};   /* B_l */
	p->w[1] = (struct wall){s->lo[0], s->lo[1], 0, 1, 0, 0, 0, NIL, NIL};   /* B_b */
	p->w[2] = (struct wall){s->hi[0], s->lo[1], -1, 0, 0, 0, 0, NIL, NIL};  /* B_r */
	p->nw = p->nfix = p->n = 3;
	for (int k = 0; k < 3; k++) {
		p->x[k] = p->y[k] = 0;
		p->r[k] = HUGE_VAL;
		p->live[k] = 0;
		p->hit[k] = p->tag[k] = 0;
		p->cnext[k] = NIL;
	}
	p->prev[0] = NIL;
	p->next[2] = NIL;
	link(p, 0, 1);
	link(p, 1, 2);
	p->fhead = 0;
	p->ftail = 2;
	p->fsize = 3;
	p->st->front_max = 3;
	*seg = 0;
}

/* Ch. 5.2.2 in a polygon (Ch. 5.2.4, Figs. 5.12-5.13): every edge is a
 * wall; the lid is the edge whose midpoint is highest, and the front is
 * the open chain of the other edges in anticlockwise order, from the one
 * after the lid (head) to the one before it (tail), as B_l -> B_b -> B_r
 * runs for the rectangle.  Each reflex vertex is an object of radius 0,
 * on the grid (so every candidate is checked against it as a point) and,
 * when inside the chain, on the front between its two edges: a corner of
 * two lines would there be a disk touching neither segment.  The first
 * active segment is the corner at the start of the lowest edge.  -1
 * without memory. */
static int start_polygon(struct packer *p, int *seg)
{
	const double *v = p->poly;
	int nv = p->npoly, lid = 0, low = 0;

	/* the walls are objects 0 .. nv-1: room for them first (the first
	 * reservation counts disks only, and may hold fewer) */
	if (reserve(p, nv))
		return -1;
	for (int k = 0; k < nv; k++) {
		int k1 = (k + 1) % nv;
		double ax = v[2 * k], ay = v[2 * k + 1], bx = v[2 * k1], by = v[2 * k1 + 1];
		double dx = bx - ax, dy = by - ay, len = hypot(dx, dy);
		/* anticlockwise: the inside is on the left */
		p->w[k] = (struct wall){ax, ay, -dy / len, dx / len, bx, by, 1, NIL, NIL};
		double my = ay + by, ly = v[2 * lid + 1] + v[2 * ((lid + 1) % nv) + 1];
		double wy = v[2 * low + 1] + v[2 * ((low + 1) % nv) + 1];
		if (my > ly)
			lid = k;
		if (my < wy || (my == wy && ax + bx < v[2 * low] + v[2 * ((low + 1) % nv)]))
			low = k;
	}
	p->nw = p->n = nv;
	for (int k = 0; k < nv; k++) {
		p->x[k] = p->y[k] = 0;
		p->r[k] = HUGE_VAL;
		p->live[k] = 0;
		p->hit[k] = p->tag[k] = 0;
		p->cnext[k] = NIL;
		p->prev[k] = p->next[k] = OFF;
	}
	/* reflex vertices: vertex[k] is the start of edge k; point[k] its
	 * object or NIL */
	int *point = malloc((size_t)nv * sizeof *point);
	if (!point)
		return -1;
	for (int k = 0; k < nv; k++) {
		const struct wall *a = &p->w[(k + nv - 1) % nv], *b = &p->w[k];
		/* turning right at vertex k: the edge normals cross negatively */
		point[k] = NIL;
		if (a->nx * b->ny - a->ny * b->nx < 0) {
			int i = add_disk(p, v[2 * k], v[2 * k + 1], 0);
			if (i < 0) {
				free(point);
				return -1;
			}
			point[k] = i;
			p->w[k].pq = i;
			p->w[(k + nv - 1) % nv].pe = i;
		}
	}
	p->nfix = p->n;
	p->st->placed = 0;
	/* the chain head .. tail, with the reflex vertices inside it */
	int head = (lid + 1) % nv, tail = (lid + nv - 1) % nv, prev = head;
	p->prev[head] = NIL;
	p->fsize = 1;
	for (int k = (head + 1) % nv; k != lid; k = (k + 1) % nv) {
		if (point[k] != NIL) {
			link(p, prev, point[k]);
			prev = point[k];
			p->fsize++;
		}
		link(p, prev, k);
		prev = k;
		p->fsize++;
	}
	p->next[tail] = NIL;
	p->fhead = head;
	p->ftail = tail;
	p->st->front_max = (size_t)p->fsize;
	*seg = low == head ? head : p->prev[low];
	free(point);
	return 0;
}

/* ---- the advance ------------------------------------------------------ */

static int advance(struct packer *p, gsl_rng *rng, int seg)
{
	double r = new_radius(p, rng);
	int drops = 0;

	while (p->nlive > 0) {
		int a = find_segment(p, seg);
		if (a == NIL) {
			/* gravity: no live segment holds this disk stably */
			p->st->dropped++;
			if (++drops >= MAXDROPS)
				break;
			r = new_radius(p, rng);
			continue;
		}
		int c = a, n = p->next[a], i = NIL;
		int res = attempt(p, &c, &n, r, &i);
		/* c -> n: the final (maybe intermediate) segment; a: the one
		 * chosen, which a refusal marks */
		switch (res) {
		case PLACED:
			drops = 0;
			r = new_radius(p, rng);
			/* closed: the segment after the new ones, so the front
			 * grows round evenly (Fig. 5.4); open: on along the
			 * layer, and back to the left wall once the layer meets
			 * the right wall (Ch. 5.2.2) */
			seg = p->closed ? n : n == p->ftail ? p->fhead : i;
			break;
		case FAIL:
			/* without gravity a segment given up stays dead; under
			 * gravity the seat is sought radius by radius, so it is
			 * only refused for this one (a smaller disk may fit
			 * where this one met a disk it could not resolve, and
			 * a dead valley would leave the front stranded) */
			if (p->gravity)
				p->tag[a] = p->radial;
			else
				kill(p, a);
			p->st->failed++;
			seg = a;
			break;
		case UNSTABLE_FWD:      /* Ch. 5.2.3: gravity misses beyond n, */
			p->tag[a] = p->radial;  /* try the subsequent segment */
			seg = n;
			break;
		case UNSTABLE_BWD:      /* ... before c: the preceding one */
			p->tag[a] = p->radial;
			seg = p->prev[c] >= 0 ? p->prev[c] : c;
			break;
		default:
			return res;     /* -1 without memory, -2 not finite */
		}
	}
	return 0;
}

/* ---- culling and output ----------------------------------------------- */

/* Wholly inside the rectangle, to TOUCH of the radius and the rounding of
 * the coordinates (a disk touching a wall sits at lo + r, rounded). */
static int inside(struct packer *p, int i)
{
	const dem_front_spec_t *s = p->s;
	double r = p->r[i];
	if (p->shape) {
		double big = fmax(fmax(fabs(p->lo[0]), fabs(p->hi[0])),
				  fmax(fabs(p->lo[1]), fabs(p->hi[1])));
		set_w(p, p->ea[i], p->eb[i], p->ec[i], p->es[i]);
		return shape_inside(p, p->x[i], p->y[i], TOUCH * p->W.size + 4 * DBL_EPSILON * (big + r));
	}
	if (p->poly) {
		/* the centre inside, every edge at least r away (to TOUCH and
		 * the rounding of coordinates of the bounding box's size) */
		double big = fmax(fmax(fabs(p->lo[0]), fabs(p->hi[0])),
				  fmax(fabs(p->lo[1]), fabs(p->hi[1])));
		double tol = TOUCH * r + 4 * DBL_EPSILON * (big + r);
		if (!in_polygon(p->poly, p->npoly, p->x[i], p->y[i]))
			return 0;
		for (int k = 0; k < p->nw; k++)
			if (seg_dist(&p->w[k], p->x[i], p->y[i]) < r - tol)
				return 0;
		return 1;
	}
	for (int d = 0; d < 2; d++) {
		double v = d ? p->y[i] : p->x[i];
		double tl = TOUCH * r + 2 * DBL_EPSILON * (fabs(s->lo[d]) + r);
		double th = TOUCH * r + 2 * DBL_EPSILON * (fabs(s->hi[d]) + r);
		if (v - r < s->lo[d] - tl || v + r > s->hi[d] + th)
			return 0;
	}
	return 1;
}

/* Do the closed segments a-b and c-d meet? */
static double orient(double ax, double ay, double bx, double by, double cx, double cy)
{
	return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static int on_seg(double ax, double ay, double bx, double by, double cx, double cy)
{
	return fmin(ax, bx) <= cx && cx <= fmax(ax, bx) && fmin(ay, by) <= cy && cy <= fmax(ay, by);
}

static int meet(const double *a, const double *b, const double *c, const double *d)
{
	double o1 = orient(a[0], a[1], b[0], b[1], c[0], c[1]);
	double o2 = orient(a[0], a[1], b[0], b[1], d[0], d[1]);
	double o3 = orient(c[0], c[1], d[0], d[1], a[0], a[1]);
	double o4 = orient(c[0], c[1], d[0], d[1], b[0], b[1]);
	if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) &&
	    ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
		return 1;
	return (o1 == 0 && on_seg(a[0], a[1], b[0], b[1], c[0], c[1])) ||
	       (o2 == 0 && on_seg(a[0], a[1], b[0], b[1], d[0], d[1])) ||
	       (o3 == 0 && on_seg(c[0], c[1], d[0], d[1], a[0], a[1])) ||
	       (o4 == 0 && on_seg(c[0], c[1], d[0], d[1], b[0], b[1]));
}

/* Twice the signed area of the n-gon v (x0 y0 x1 y1 ...; positive
 * anticlockwise), by the library's shoelace about the first vertex. */
static double twice_area(const double *v, int n)
{
	dem_area_props_t pr;
	dem_polygon_props(n, (const double (*)[2])v, &pr);
	return 2 * pr.A;
}

int dem_front_polygon_check(const double *v, int n, dem_error_t *e)
{
	double a2 = 0, size = 0;

	if (!v || n < 3)
		return dem_error_set(e, DEM_EINPUT, "a polygon needs at least 3 vertices (got %d)",
				     v ? n : 0);
	for (int i = 0; i < 2 * n; i++)
		if (!isfinite(v[i]))
			return dem_error_set(e, DEM_EINPUT, "polygon vertex %d is not finite", i / 2 + 1);
	/* the size and the area about the first vertex, so that they do not
	 * depend on where the polygon lies */
	for (int i = 0; i < 2 * n; i++)
		size = fmax(size, fabs(v[i] - v[i % 2]));
	for (int i = 0; i < n; i++) {
		const double *a = v + 2 * i, *b = v + 2 * ((i + 1) % n);
		if (a[0] == b[0] && a[1] == b[1])
			return dem_error_set(e, DEM_EINPUT, "polygon vertices %d and %d coincide",
					     i + 1, (i + 1) % n + 1);
	}
	a2 = twice_area(v, n);
	for (int i = 0; i < n; i++) {
		const double *a = v + 2 * i, *b = v + 2 * ((i + 1) % n);
		for (int j = i + 1; j < n; j++) {
			const double *c = v + 2 * j, *d = v + 2 * ((j + 1) % n);
			int bad;
			if (j == i + 1 || (i == 0 && j == n - 1)) {
				/* neighbours share a vertex: bad only when they
				 * fold back onto each other */
				const double *o = j == i + 1 ? b : a;   /* the shared vertex */
				const double *p = j == i + 1 ? a : b, *q = j == i + 1 ? d : c;
				bad = orient(o[0], o[1], p[0], p[1], q[0], q[1]) == 0 &&
				      (p[0] - o[0]) * (q[0] - o[0]) + (p[1] - o[1]) * (q[1] - o[1]) > 0;
			} else {
				bad = meet(a, b, c, d);
			}
			if (bad)
				return dem_error_set(e, DEM_EINPUT,
						     "polygon edges %d-%d and %d-%d intersect: not a simple polygon",
						     i + 1, (i + 1) % n + 1, j + 1, (j + 1) % n + 1);
		}
	}
	if (!(fabs(a2) > 1e-12 * size * size))
		return dem_error_set(e, DEM_EINPUT, "the polygon has zero area");
	return DEM_OK;
}

/* The lengths the packer may meet: lengths are squared (distances, radii,
 * areas) and an ellipse's shape matrix has the fourth power of its size
 * as determinant, so the semi-axes, and the coordinates with a few
 * bounding radii added, must keep those powers finite and normal (64 of
 * room for sums and products); an overflow gives infinities and NaNs, and
 * a NaN passes every "overlap > tol" test.  And the coordinates' rounding
 * (ROUND of their magnitude, allowed as overlap) must stay below 1e-3 of
 * the smallest semi-axis, or no disk could be placed to a meaning. */
static int check_range(const dem_front_spec_t *s, dem_error_t *e)
{
	int pw = s->shape == DEM_FRONT_ELLIPSE ? 4 : 2;
	double al = s->shape != DEM_FRONT_DISK && s->ratio.rmax > 1 ? sqrt(s->ratio.rmax) : 1;
	double big = s->law.rmax * al, small = s->law.rmin / al, mag = 0;
	double top = pow(DBL_MAX, 1.0 / pw) / 64, bottom = pow(DBL_MIN, 1.0 / pw) * 64;
	if (s->polygon)
		for (int i = 0; i < 2 * s->npolygon; i++)
			mag = fmax(mag, fabs(s->polygon[i]));
	else
		for (int d = 0; d < 2; d++)
			mag = fmax(mag, fmax(fabs(s->lo[d]), fabs(s->hi[d])));
	if (!(small >= bottom && big <= top && mag + 8 * big <= top))
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: lengths out of range: semi-axes %g to %g, coordinates "
				     "up to %g; expected semi-axes from %g and lengths up to %g (their %s "
				     "must stay finite and normal)", small, big, mag, bottom, top,
				     pw == 4 ? "fourth powers" : "squares");
	if (!(ROUND * mag <= 1e-3 * small))
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: coordinates out of range for the radii: at %g from "
				     "the origin they are rounded to %g, more than 1e-3 of the smallest "
				     "semi-axis %g", mag, ROUND * mag, small);
	return DEM_OK;
}

static int check_spec(const dem_front_spec_t *s, dem_error_t *e)
{
	if (s->polygon) {
		if (s->form != DEM_FRONT_OPEN)
			return dem_error_set(e, DEM_EINPUT,
					     "advancing front: a polygon needs the open form (Ch. 5.2.2)");
		/* its own error first: e keeps the first message set on it */
		dem_error_t e2 = {0};
		if (dem_front_polygon_check(s->polygon, s->npolygon, &e2))
			return dem_error_set(e, DEM_EINPUT, "advancing front: %s", e2.msg);
	}
	for (int d = 0; d < 2 && !s->polygon; d++)
		if (!(isfinite(s->lo[d]) && isfinite(s->hi[d]) && s->lo[d] < s->hi[d]))
			return dem_error_set(e, DEM_EINPUT,
					     "advancing front: empty domain along %c: [%g, %g]",
					     "xy"[d], s->lo[d], s->hi[d]);
	if (!(s->law.rmin > 0 && isfinite(s->law.rmax) && s->law.rmax >= s->law.rmin))
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: radii must satisfy 0 < rmin <= rmax (got %g, %g)",
				     s->law.rmin, s->law.rmax);
	if (s->form != DEM_FRONT_CLOSED && s->form != DEM_FRONT_OPEN)
		return dem_error_set(e, DEM_EINPUT, "advancing front: unknown form %d", (int)s->form);
	if (s->gravity && s->form != DEM_FRONT_OPEN)
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: gravity needs the open form (Ch. 5.2.3)");
	if (s->check_limit < 0)
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: check limit %d is negative", s->check_limit);
	if (s->shape != DEM_FRONT_DISK && s->shape != DEM_FRONT_POLYGON &&
	    s->shape != DEM_FRONT_ELLIPSE)
		return dem_error_set(e, DEM_EINPUT, "advancing front: unknown shape %d", (int)s->shape);
	if (s->shape == DEM_FRONT_POLYGON && !(s->sides >= 3 && s->sides <= MAXSIDES))
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: a polygon of %d sides: expected 3 to %d",
				     s->sides, MAXSIDES);
	if (s->shape != DEM_FRONT_DISK && (s->ratio.rmin != 0 || s->ratio.rmax != 0) &&
	    !(s->ratio.rmin >= 1 && isfinite(s->ratio.rmax) && s->ratio.rmax >= s->ratio.rmin))
		return dem_error_set(e, DEM_EINPUT,
				     "advancing front: aspect ratios must satisfy 1 <= min <= max (got %g, %g)",
				     s->ratio.rmin, s->ratio.rmax);
	return check_range(s, e);
}

/* The grid covers the domain and a margin of two cells (disks of the
 * closed form, and the top layers of the open form, reach past it). */
static int make_grid(struct packer *p, dem_error_t *e)
{
	const dem_front_spec_t *s = p->s;
	double cs = 2 * (p->shape ? p->rb : s->law.rmax), m = 2 * cs;
	double nx = ceil((p->hi[0] - p->lo[0] + 2 * m) / cs);
	double ny = ceil((p->hi[1] - p->lo[1] + 2 * m) / cs);
	if (!(nx * ny <= (double)MAXCELLS))
		return dem_error_set(e, DEM_EIO,
				     "advancing front: the domain holds too many disks of radius %g "
				     "(%.3g grid cells; at most %ld)", cs / 2, nx * ny, MAXCELLS);
	p->gnx = (int)nx;
	p->gny = (int)ny;
	p->gx = p->lo[0] - m;
	p->gy = p->lo[1] - m;
	p->ginv = 1 / cs;
	p->cell = malloc((size_t)p->gnx * (size_t)p->gny * sizeof *p->cell);
	if (!p->cell)
		return dem_error_nomem(e, "advancing front grid");
	for (long i = 0; i < (long)p->gnx * p->gny; i++)
		p->cell[i] = NIL;
	return DEM_OK;
}

/* The domain: the rectangle's three walls, or the polygon turned
 * anticlockwise with room for its edges; the bounding box and the area.
 * -1 without memory. */
static int setup_domain(struct packer *p)
{
	const dem_front_spec_t *s = p->s;
	if (!s->polygon) {
		for (int d = 0; d < 2; d++) {
			p->lo[d] = s->lo[d];
			p->hi[d] = s->hi[d];
		}
		p->area = (s->hi[0] - s->lo[0]) * (s->hi[1] - s->lo[1]);
		p->w = malloc(3 * sizeof *p->w);
		return p->w ? 0 : -1;
	}
	int n = s->npolygon;
	double a2 = 0;
	p->poly = malloc(2 * (size_t)n * sizeof *p->poly);
	p->w = malloc((size_t)n * sizeof *p->w);
	if (!p->poly || !p->w)
		return -1;
	p->npoly = n;
	a2 = twice_area(s->polygon, n);
	p->lo[0] = p->lo[1] = HUGE_VAL;
	p->hi[0] = p->hi[1] = -HUGE_VAL;
	for (int i = 0; i < n; i++) {
		int k = a2 > 0 ? i : n - 1 - i;         /* anticlockwise */
		for (int d = 0; d < 2; d++) {
			double c = s->polygon[2 * k + d];
			p->poly[2 * i + d] = c;
			p->lo[d] = fmin(p->lo[d], c);
			p->hi[d] = fmax(p->hi[d], c);
		}
	}
	p->area = 0.5 * fabs(a2);
	return 0;
}

static double body_area(const struct packer *p, int i)
{
	if (!p->shape)
		return DEM_PI * p->r[i] * p->r[i];
	/* the unit m-gon stretched by a and b */
	double ab = p->ea[i] * p->eb[i];
	return p->shape == DEM_FRONT_ELLIPSE ? DEM_PI * ab : ab * p->unit_area;
}

static int pack(const dem_front_spec_t *s, gsl_rng *rng, dem_front_emit_fn emit,
		dem_front_body_fn emit_body, void *ctx, dem_front_stats_t *st, dem_error_t *e)
{
	struct packer pk = {0}, *p = &pk;
	dem_front_stats_t st0;
	int rc, seg;

	if (!st)
		st = &st0;
	memset(st, 0, sizeof *st);
	if ((rc = check_spec(s, e)))
		return rc;
	p->s = s;
	p->st = st;
	p->closed = s->form == DEM_FRONT_CLOSED;
	p->gravity = s->gravity;
	p->limit = s->check_limit > 0 ? s->check_limit : LONG_MAX;
	p->fhead = p->ftail = NIL;
	p->serial = p->radial = 0;
	p->shape = s->shape;
	if (p->shape) {
		p->m = s->sides;
		dem_area_props_t pr;
		dem_polygon_regular(p->m, 1, 1, p->unit);
		dem_polygon_props(p->m, (const double (*)[2])p->unit, &pr);
		p->unit_area = pr.A;
		p->rb = s->law.rmax * (s->ratio.rmin > 0 ? sqrt(s->ratio.rmax) : 1);
		if (!(p->buf = malloc(BUFPTS * sizeof *p->buf))) {
			rc = dem_error_nomem(e, "advancing front loci");
			goto out;
		}
	}
	if (setup_domain(p)) {
		rc = dem_error_nomem(e, "advancing front walls");
		goto out;
	}

	/* first reservation: the disks of mean square radius that fill the
	 * rectangle (URD's E[r^2]); arrays double beyond that */
	const dem_radius_law_t *L = &s->law;
	double r2 = (L->rmin * L->rmin + L->rmin * L->rmax + L->rmax * L->rmax) / 3;
	double est = p->area / (DEM_PI * r2);
	int want = est < 1 << 20 ? (int)(1.2 * est) + 64 : 1 << 20;
	if ((rc = make_grid(p, e)))
		goto out;
	if (reserve(p, want)) {
		rc = dem_error_nomem(e, "advancing front disks");
		goto out;
	}
	if (p->closed) {
		if (start_closed(p, rng, &seg)) {
			rc = dem_error_nomem(e, "advancing front disks");
			goto out;
		}
	} else if (p->poly) {
		if (start_polygon(p, &seg)) {
			rc = dem_error_nomem(e, "advancing front disks");
			goto out;
		}
	} else {
		start_open(p, &seg);
	}
	if ((rc = advance(p, rng, seg))) {
		rc = rc == -2
			? dem_error_set(e, DEM_ENUMERIC, "advancing front: a position not finite "
					"(after %zu bodies); the radii or the domain out of range?",
					st->placed)
			: p->n == INT_MAX
			? dem_error_set(e, DEM_EIO, "advancing front: more than %d disks", INT_MAX)
			: dem_error_nomem(e, "advancing front disks");
		goto out;
	}

	/* Cull (Fig. 5.6, Fig. 5.8(c)): keep the disks wholly inside.  Under
	 * gravity a disk whose support was culled goes too, so every kept
	 * disk still rests on kept disks or walls (supports come first in
	 * the order of generation).  live[] is free now and holds the flags. */
	unsigned char *keep = p->live;
	for (int i = p->nfix; i < p->n; i++) {
		int k = inside(p, i);
		if (k && p->gravity)
			for (int h = 0; h < 2; h++) {
				int q = p->sup[2 * i + h];
				if (q >= p->nfix && !keep[q])
					k = 0;
			}
		keep[i] = (unsigned char)k;
		if (k) {
			st->kept++;
			st->area += body_area(p, i);
		}
	}
	st->density = st->area / p->area;
	rc = DEM_OK;
	for (int i = p->nfix; i < p->n && rc == DEM_OK; i++)
		if (keep[i]) {
			double c[2] = {p->x[i], p->y[i]};
			if (emit)
				rc = emit(ctx, c, p->r[i]);
			else if (p->shape) {
				dem_front_body_t b = {{c[0], c[1]}, p->ea[i], p->eb[i],
						      atan2(p->es[i], p->ec[i])};
				rc = emit_body(ctx, &b);
			} else {
				dem_front_body_t b = {{c[0], c[1]}, p->r[i], p->r[i], 0};
				rc = emit_body(ctx, &b);
			}
		}
out:
	release(p);
	return rc;
}

int dem_pack_front(const dem_front_spec_t *s, gsl_rng *rng,
		   dem_front_emit_fn emit, void *ctx, dem_front_stats_t *st,
		   dem_error_t *e)
{
	if (s->shape != DEM_FRONT_DISK)
		return dem_error_set(e, DEM_EINPUT, "advancing front: %s bodies are written "
				     "by dem_pack_front_bodies", s->shape == DEM_FRONT_POLYGON ? "polygon" : "other");
	return pack(s, rng, emit, NULL, ctx, st, e);
}

int dem_pack_front_bodies(const dem_front_spec_t *s, gsl_rng *rng,
			  dem_front_body_fn emit, void *ctx, dem_front_stats_t *st,
			  dem_error_t *e)
{
	return pack(s, rng, NULL, emit, ctx, st, e);
}
