/* shotset2d.c - the shots of a pass against the top edge of a 2D block.
 * See shotset2d.h. */
#include "shot/shotset2d.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "contact/disk.h"
#include "contact/sphere.h"
#include "core/consts.h"
#include "core/cost.h"

/* One shot/segment pair at this step. */
typedef struct pair2 {
	dem_seg_geom_t g;         /* geometry at x_n (when touch) */
	double Fnode[2][2];       /* forces on the segment's nodes */
	double K;                 /* the pair's stiffness gamma K_L, for the nodes' step */
	int touch;
} pair2_t;

struct dem_shotset2d {
	const dem_mesh2_t *mesh;
	const double *node_mass;
	dem_contact_model_t cm;
	dem_shotset2d_opts_t o;
	int axisym;

	size_t nseg;
	uint32_t *seg;            /* 2 nodes per top segment, left to right */
	double *smass;            /* segment masses */
	double *Knode;            /* contact stiffness summed per node this step */
	double lo[2], hi[2];      /* box of the top edge at the last prepare, down to the base */

	size_t ns, scap;
	dem_shot_body_t *b;
	pair2_t *po;              /* ns x nseg */
	dem_contact_state_t *cs;  /* ns x nseg */
	dem_contact_state_t *ss;  /* disk/disk pairs, ns x ns (i < j used) */
	double *T;                /* torques about z at this step */
	double dt_prev;
	int prepared;
	dem_shotset_stats_t st;
	dem_feshot2d_t *F;        /* FE shots, or NULL */
};

/* ---- set-up ------------------------------------------------------------- */

int dem_shotset2d_create(dem_shotset2d_t **Sp, const dem_mesh2_t *mesh, const double *node_mass,
			 const dem_contact_model_t *cm, const dem_shotset2d_opts_t *o,
			 dem_error_t *e)
{
	*Sp = NULL;
	int axi = o->mode == DEM_QUAD4_AXISYM;
	if (o->mode != DEM_QUAD4_PLANE && !axi)
		return dem_error_set(e, DEM_EINPUT, "2D shots: unknown mode %d", (int)o->mode);
	if (!(o->rho > 0) || !isfinite(o->rho))
		return dem_error_set(e, DEM_EINPUT, "shot density must be > 0 (got %g)", o->rho);
	if (!axi && (!(o->thick > 0) || !isfinite(o->thick)))
		return dem_error_set(e, DEM_EINPUT, "thickness must be > 0 (got %g m)", o->thick);
	if (!(o->gap >= 0) || !isfinite(o->gap))
		return dem_error_set(e, DEM_EINPUT, "start gap must be >= 0 (got %g m)", o->gap);
	if (!(o->lambda > 0 && o->lambda <= 1))
		return dem_error_set(e, DEM_EINPUT, "lambda must be in (0, 1] (got %g)", o->lambda);
	int dim = cm->p.law.dim == 2 ? 2 : 3;
	if (dim != (axi ? 3 : 2))
		return dem_error_set(e, DEM_EINPUT, "2D shots: a %dD contact law for %s shots "
				     "(expected %dD)", dim, axi ? "axisymmetric" : "plane strain",
				     axi ? 3 : 2);
	dem_shotset2d_t *S = calloc(1, sizeof *S);
	if (!S)
		return dem_error_nomem(e, "shots");
	S->mesh = mesh;
	S->node_mass = node_mass;
	S->cm = *cm;
	S->o = *o;
	S->o.fe = NULL;
	S->axisym = axi;
	if (o->fe && dem_feshot2d_create(&S->F, mesh, node_mass, cm, o->fe, e)) {
		dem_shotset2d_free(S);
		return e->code;
	}
	S->nseg = dem_mesh2_top_segments(mesh, -HUGE_VAL, HUGE_VAL, NULL);
	S->seg = malloc(2 * S->nseg * sizeof *S->seg);
	S->smass = malloc(S->nseg * sizeof *S->smass);
	S->Knode = calloc(mesh->nn, sizeof *S->Knode);
	unsigned *deg = calloc(mesh->nn, sizeof *deg);
	if (!S->seg || !S->smass || !S->Knode || !deg) {
		free(deg);
		dem_shotset2d_free(S);
		return dem_error_nomem(e, "shot surface");
	}
	dem_mesh2_top_segments(mesh, -HUGE_VAL, HUGE_VAL, S->seg);
	for (size_t k = 0; k < 2 * S->nseg; k++)
		deg[S->seg[k]]++;
	for (size_t k = 0; k < S->nseg; k++)
		S->smass[k] = node_mass[S->seg[2 * k]] / deg[S->seg[2 * k]] +
			      node_mass[S->seg[2 * k + 1]] / deg[S->seg[2 * k + 1]];
	free(deg);
	*Sp = S;
	return DEM_OK;
}

void dem_shotset2d_free(dem_shotset2d_t *S)
{
	if (!S)
		return;
	free(S->seg), free(S->smass), free(S->Knode);
	free(S->b), free(S->po), free(S->cs), free(S->ss), free(S->T);
	dem_feshot2d_free(S->F);
	free(S);
}

/* The box of the top edge at x, down to the base. */
static void top_box(dem_shotset2d_t *S, const double *x)
{
	S->lo[0] = S->lo[1] = HUGE_VAL;
	S->hi[0] = S->hi[1] = -HUGE_VAL;
	for (size_t k = 0; k < 2 * S->nseg; k++) {
		const double *p = x + 2 * (size_t)S->seg[k];
		for (int i = 0; i < 2; i++)
			S->lo[i] = fmin(S->lo[i], p[i]), S->hi[i] = fmax(S->hi[i], p[i]);
	}
	S->lo[1] = S->mesh->gy[0];
}

int dem_shotset2d_begin(dem_shotset2d_t *S, size_t n, const dem_shot_t *sh, const double *x,
			dem_error_t *e)
{
	const double y0 = S->mesh->gy[S->mesh->ny];
	if (S->axisym && n > 1)
		return dem_error_set(e, DEM_EINPUT, "pass %lu: %zu shots; an axisymmetric block "
				     "takes one shot per pass (on the axis)", sh[0].pass, n);
	if (S->F && n > 1)
		return dem_error_set(e, DEM_EINPUT, "pass %lu: %zu shots; FE shots come one per "
				     "pass", sh[0].pass, n);
	if (n > S->scap) {
		dem_shot_body_t *b = realloc(S->b, n * sizeof *b);
		if (b)
			S->b = b;
		pair2_t *po = realloc(S->po, n * S->nseg * sizeof *po);
		if (po)
			S->po = po;
		dem_contact_state_t *cs = realloc(S->cs, n * S->nseg * sizeof *cs);
		if (cs)
			S->cs = cs;
		dem_contact_state_t *ss = realloc(S->ss, n * n * sizeof *ss);
		if (ss)
			S->ss = ss;
		double *T = realloc(S->T, n * sizeof *T);
		if (T)
			S->T = T;
		if (!b || !po || !cs || !ss || !T)
			return dem_error_nomem(e, "shots");
		S->scap = n;
	}
	S->ns = 0;
	S->dt_prev = 0;
	S->prepared = 0;
	for (size_t k = 0; k < n * S->nseg; k++)
		dem_contact_state_reset(&S->cs[k]), S->po[k].touch = 0;
	for (size_t k = 0; k < n * n; k++)
		dem_contact_state_reset(&S->ss[k]);
	for (size_t i = 0; i < n; i++) {
		const dem_shot_t *r = &sh[i];
		double vx = r->v[0], vy = r->v[2], sp = hypot(vx, vy);
		if (!(r->r > 0) || !isfinite(r->r))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: radius must be > 0 (got %g m)",
					     i, r->pass, r->r);
		if (!(vy < 0) || !isfinite(sp))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: velocity must point down "
					     "into the block (vz < 0; got %g m/s)", i, r->pass, vy);
		if (!(r->t >= 0) || !isfinite(r->t))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: start time must be >= 0 "
					     "(got %g s)", i, r->pass, r->t);
		if (S->axisym && (r->x[0] != 0 || vx != 0))
			return dem_error_set(e, DEM_EINPUT, "shot %zu of pass %lu: an axisymmetric shot "
					     "moves on the axis (x = 0 and vx = 0; got x %g m, vx %g m/s)",
					     i, r->pass, r->x[0], vx);
		dem_shot_body_t *b = &S->b[i];
		memset(b, 0, sizeof *b);
		b->R = r->r;
		if (S->axisym) {
			b->M = S->o.rho * 4.0 / 3.0 * DEM_PI * r->r * r->r * r->r;
			b->kn = dem_law_kn(&S->cm.p.law, r->r);
		} else {
			b->M = S->o.rho * DEM_PI * r->r * r->r * S->o.thick;
			b->kn = dem_law_kn(&S->cm.p.law, r->r) * S->o.thick;
		}
		b->pass = r->pass;
		b->dt = HUGE_VAL;
		double u[2] = { vx / sp, vy / sp };
		/* the highest top node within R of the impact point */
		double ymax = -HUGE_VAL;
		for (size_t k = 0; k < 2 * S->nseg; k++) {
			const double *p = x + 2 * (size_t)S->seg[k];
			if (fabs(p[0] - r->x[0]) <= r->r && p[1] > ymax)
				ymax = p[1];
		}
		if (ymax == -HUGE_VAL)
			ymax = y0;
		double s = (ymax + S->o.gap - y0) / -u[1] + r->t * sp;
		double c[2] = { r->x[0] - s * u[0], y0 + r->r - s * u[1] };
		/* no overlap with the shots placed before: back along the line */
		for (size_t it = 0; it <= i; it++) {
			int moved = 0;
			for (size_t j = 0; j < i; j++) {
				const dem_shot_body_t *q = &S->b[j];
				double d[2] = { c[0] - q->x[0], c[1] - q->x[1] };
				double RR = b->R + q->R, dd = d[0] * d[0] + d[1] * d[1];
				if (dd >= RR * RR * (1 - 1e-12))
					continue;
				double du = d[0] * u[0] + d[1] * u[1];
				double back = du + sqrt(du * du - dd + RR * RR);
				c[0] -= back * u[0], c[1] -= back * u[1];
				moved = 1;
			}
			if (!moved)
				break;
		}
		b->x[0] = c[0], b->x[1] = c[1];
		b->v[0] = vx, b->v[1] = vy;
		if (S->F) {
			/* the FE disk where the rigid one would be */
			double v2[2] = { vx, vy };
			if (dem_feshot2d_begin(S->F, r->r, c, v2, e))
				return e->code;
			unsigned long pass = b->pass;
			dem_feshot2d_body(S->F, b);
			b->pass = pass;
		}
		S->ns++;
	}
	top_box(S, x);
	return DEM_OK;
}

/* ---- the step ----------------------------------------------------------- */

/* The ring's geometry (AXISYM): disk.h's chord on the segment's line,
 * then gamma the ring's surface within the sphere over pi b^2 and P the
 * chord's ring-weighted middle (shotset2d.h).  0: no contact. */
static int ring_geom(const double O[2], double R, const double A[2], const double B[2],
		     dem_seg_geom_t *g)
{
	if (!dem_segment_geom(O, R, A, B, DEM_PARTIAL_WIDTH, g))
		return 0;
	double L = hypot(B[0] - A[0], B[1] - A[1]);
	double t[2] = { (B[0] - A[0]) / L, (B[1] - A[1]) / L }, nf[2] = { -t[1], t[0] };
	double C[2] = { O[0] - g->d * nf[0], O[1] - g->d * nf[1] };
	double sc = (C[0] - A[0]) * t[0] + (C[1] - A[1]) * t[1];
	double x0 = g->x0, x1 = g->x1;
	/* int r dx and int x r dx over [x0, x1], r = C_r + x t_r */
	double m0 = C[0] * (x1 - x0) + t[0] * (x1 * x1 - x0 * x0) / 2;
	double m1 = C[0] * (x1 * x1 - x0 * x0) / 2 + t[0] * (x1 * x1 * x1 - x0 * x0 * x0) / 3;
	if (!(m0 > 0) || !(g->b > 0))
		return 0;
	double xp = m1 / m0;
	g->gamma = 2 * m0 / (g->b * g->b);
	for (int i = 0; i < 2; i++)
		g->P[i] = g->G[i] = C[i] + xp * t[i];
	double on[2] = { O[0] - g->P[0], O[1] - g->P[1] }, l = hypot(on[0], on[1]);
	if (!(l > 0))
		return 0;
	g->n[0] = on[0] / l, g->n[1] = on[1] / l;
	g->xi = (sc + xp) / L;
	return 1;
}

/* Distance from O to the segment A B, and the unit direction from O to
 * the segment's nearest point in u (NULL: not wanted; 0 0 at distance 0). */
static double seg_dist(const double O[2], const double A[2], const double B[2], double u[2])
{
	double ab[2] = { B[0] - A[0], B[1] - A[1] }, ao[2] = { O[0] - A[0], O[1] - A[1] };
	double l2 = ab[0] * ab[0] + ab[1] * ab[1];
	double s = l2 > 0 ? (ao[0] * ab[0] + ao[1] * ab[1]) / l2 : 0;
	s = s < 0 ? 0 : s > 1 ? 1 : s;
	double q[2] = { s * ab[0] - ao[0], s * ab[1] - ao[1] }, l = hypot(q[0], q[1]);
	if (u)
		u[0] = l > 0 ? q[0] / l : 0, u[1] = l > 0 ? q[1] / l : 0;
	return l;
}

/* AXISYM: the step limit of the ring of segment k (A B) that does not
 * touch sphere b yet, at distance gap (u: the unit direction from the
 * sphere's centre to the segment's nearest point), but may within a step
 * dt at the approach speed vrel.  A ring's force gamma k_n delta^m is no
 * power law of the overlap: a ring first touched inside its segment (a
 * dent's flank, the chord's end) has gamma = 2 int r dx / b^2 about
 * 4 r / b, b = sqrt(2 R delta), so its force grows as delta^(m - 1/2):
 * for the linear law as sqrt(delta), from zero at a slope without bound
 * (for m 1.5 linearly).  The first step's overlap is then no small part
 * of the contact, and the limit at gamma 1 that the law gives before
 * contact lets the step's own overlap store energy the pair never paid
 * for (issue 18: a light ring near the axis bouncing off the sphere).
 * The limit of Box 3.1 with the pair's secant over the overlap delta1 =
 * vrel dt - gap that one step can make (the ring's force from 0 to delta1
 * over delta1: gamma(delta1) times the law's secant, as shot_geometry
 * takes it once they touch), for the pair and for its two nodes as
 * nodes_dt; a smaller step makes a smaller delta1 and a larger gamma, so
 * it is taken again down to a step that holds (dt returned as is when
 * it does). */
static double ring_approach_dt(const dem_shotset2d_t *S, const dem_shot_body_t *b, size_t k,
			       const double *x, double vrel, double gap, const double u[2], double dt)
{
	const uint32_t *sn = S->seg + 2 * k;
	const double *A = x + 2 * (size_t)sn[0], *B = x + 2 * (size_t)sn[1];
	if (!(gap > 0))
		return dt;
	for (int it = 0; it < 64; it++) {
		double d1 = vrel * dt - gap;
		if (!(d1 > 0))
			return dt;
		/* the sphere moved toward the segment's nearest point to overlap d1 */
		double O1[2] = { b->x[0] + (gap + d1) * u[0], b->x[1] + (gap + d1) * u[1] };
		dem_seg_geom_t g;
		if (!ring_geom(O1, b->R, A, B, &g))
			return dt;
		double mass = dem_contact_meff(b->M, S->smass[k]) / g.gamma;
		double K = dem_contact_secant(&S->cm, b->kn, mass, 0, vrel);
		double dtn = dem_dt_step(S->o.lambda, mass, K);
		dtn = fmin(dtn, dem_dt_step(S->o.lambda, S->node_mass[sn[0]], g.gamma * K * (1 - g.xi)));
		dtn = fmin(dtn, dem_dt_step(S->o.lambda, S->node_mass[sn[1]], g.gamma * K * g.xi));
		if (dtn >= dt)
			return dt;
		dt = dtn;
	}
	return dt;
}

/* Geometry of shot s against every segment at x, and its step limit. */
static void shot_geometry(dem_shotset2d_t *S, size_t s, const double *x, const double *v,
			  double dt_max)
{
	dem_shot_body_t *b = &S->b[s];
	double R = b->R, sp = hypot(b->v[0], b->v[1]), reach = 2 * sp * dt_max;
	double dtmin = HUGE_VAL, mnear = HUGE_VAL, dtnear = dt_max;
	int nc = 0;

	for (size_t k = 0; k < S->nseg; k++) {
		pair2_t *po = &S->po[s * S->nseg + k];
		size_t a = S->seg[2 * k], c = S->seg[2 * k + 1];
		const double *A = x + 2 * a, *B = x + 2 * c;
		po->touch = 0;
		/* the disk grown by its reach against the segment's box */
		double d2 = 0;
		for (int i = 0; i < 2; i++) {
			double lo = fmin(A[i], B[i]), hi = fmax(A[i], B[i]), q = b->x[i];
			q = q < lo ? lo - q : q > hi ? q - hi : 0;
			d2 += q * q;
		}
		if (d2 >= (R + reach) * (R + reach))
			continue;
		int touch = d2 < R * R &&
			    (S->axisym ? ring_geom(b->x, R, A, B, &po->g)
				       : dem_segment_geom(b->x, R, A, B, S->cm.p.partial, &po->g));
		if (!touch) {
			double w = v ? fmax(hypot(v[2 * a], v[2 * a + 1]), hypot(v[2 * c], v[2 * c + 1])) : 0;
			double u[2], gap = seg_dist(b->x, A, B, u) - R;
			if (!(gap > 0) || gap < 2 * (sp + w) * dt_max)
				mnear = fmin(mnear, S->smass[k]);
			if (S->axisym)
				dtnear = ring_approach_dt(S, b, k, x, sp + w, gap, u, dtnear);
			continue;
		}
		po->touch = 1;
		nc++;
		double mass = dem_contact_meff(b->M, S->smass[k]) / po->g.gamma;
		double vn = -(b->v[0] * po->g.n[0] + b->v[1] * po->g.n[1]);
		double K = dem_contact_secant(&S->cm, b->kn, mass, po->g.delta, vn);
		po->K = po->g.gamma * K;
		dtmin = fmin(dtmin, dem_dt_step(S->o.lambda, mass, K));
	}
	if (nc == 0 && mnear < HUGE_VAL)
		dtmin = dem_contact_dt(&S->cm, b->kn, dem_contact_meff(b->M, mnear), 0, sp, S->o.lambda);
	if (dtnear < dt_max)
		dtmin = fmin(dtmin, dtnear);
	b->dt = dtmin;
}

/* The surface nodes' limit: each node of mass m carrying K of its pairs
 * (shared by (1 - xi), xi) allows lambda 2 sqrt(m / K) (Box 3.1). */
static double nodes_dt(dem_shotset2d_t *S)
{
	size_t n = S->ns * S->nseg;
	double dt = HUGE_VAL;
	for (size_t k = 0; k < n; k++)
		if (S->po[k].touch) {
			const uint32_t *sn = S->seg + 2 * (k % S->nseg);
			S->Knode[sn[0]] += S->po[k].K * (1 - S->po[k].g.xi);
			S->Knode[sn[1]] += S->po[k].K * S->po[k].g.xi;
		}
	for (size_t k = 0; k < n; k++)
		if (S->po[k].touch)
			for (int a = 0; a < 2; a++) {
				uint32_t m = S->seg[2 * (k % S->nseg) + a];
				if (S->Knode[m] > 0)
					dt = fmin(dt, dem_dt_step(S->o.lambda, S->node_mass[m], S->Knode[m]));
				S->Knode[m] = 0;
			}
	return dt;
}

/* k_n of a disk/disk pair (PLANE: the law times the thickness). */
static double pair_kn(const dem_shotset2d_t *S, const dem_shot_body_t *b1, const dem_shot_body_t *b2)
{
	return dem_law_kn(&S->cm.p.law, dem_law_reff(b1->R, b2->R)) * S->o.thick;
}

/* Step limits of the disk pairs touching or within reach (PLANE). */
static void pairs_dt(dem_shotset2d_t *S, double dt_max)
{
	for (size_t i = 0; i < S->ns; i++)
		for (size_t j = i + 1; j < S->ns; j++) {
			dem_shot_body_t *b1 = &S->b[i], *b2 = &S->b[j];
			double d[2] = { b2->x[0] - b1->x[0], b2->x[1] - b1->x[1] };
			double w[2] = { b2->v[0] - b1->v[0], b2->v[1] - b1->v[1] };
			double dist = hypot(d[0], d[1]), sp = hypot(w[0], w[1]);
			double delta = b1->R + b2->R - dist;
			if (delta < -2 * sp * dt_max || dist == 0)
				continue;
			double vn = -(d[0] * w[0] + d[1] * w[1]) / dist;
			double dts = dem_contact_dt(&S->cm, pair_kn(S, b1, b2), dem_contact_meff(b1->M, b2->M),
						    delta, delta > 0 ? vn : sp, S->o.lambda);
			b1->dt = fmin(b1->dt, dts);
			b2->dt = fmin(b2->dt, dts);
		}
}

static double geometry(dem_shotset2d_t *S, const double *x, const double *v, double dt_max)
{
	double t0 = dem_wall();
	for (size_t s = 0; s < S->ns; s++)
		shot_geometry(S, s, x, v, dt_max);
	if (!S->axisym)
		pairs_dt(S, dt_max);
	double dt = nodes_dt(S);
	for (size_t s = 0; s < S->ns; s++)
		dt = fmin(dt, S->b[s].dt);
	top_box(S, x);
	S->st.contact_s += dem_wall() - t0;
	return dt;
}

int dem_shotset2d_prepare(dem_shotset2d_t *S, const double *x, const double *v, double dt_max,
			  double *dt, dem_error_t *e)
{
	(void)e;
	*dt = dt_max;
	S->prepared = 0;
	if (S->ns == 0)
		return DEM_OK;
	if (S->F) {
		top_box(S, x);
		*dt = fmin(dt_max, dem_feshot2d_dt(S->F));
		return DEM_OK;
	}
	*dt = fmin(dt_max, geometry(S, x, v, dt_max));
	S->prepared = 1;
	return DEM_OK;
}

/* Forces of shot s's touching pairs: on the shot (F, torque about z in
 * *T) and on the segments' nodes (po). */
static void shot_forces(dem_shotset2d_t *S, size_t s, const double *v, double dt, double *T)
{
	dem_shot_body_t *b = &S->b[s];
	int nc = 0;

	b->F[0] = b->F[1] = b->F[2] = 0;
	b->Fn = b->Ft = 0;
	*T = 0;
	for (size_t k = 0; k < S->nseg; k++) {
		pair2_t *po = &S->po[s * S->nseg + k];
		dem_contact_state_t *cs = &S->cs[s * S->nseg + k];
		if (!po->touch) {
			dem_contact_state_reset(cs);
			continue;
		}
		/* as dem_contact_disk_segment, on the geometry found (the ring's
		 * in AXISYM) */
		const dem_seg_geom_t *g = &po->g;
		const uint32_t *sn = S->seg + 2 * k;
		dem_contact_kin_t kin;
		dem_contact_out_t o;
		double xi = g->xi;
		kin.r[0] = g->P[0] - b->x[0], kin.r[1] = g->P[1] - b->x[1], kin.r[2] = 0;
		double wr[2] = { -b->w[2] * kin.r[1], b->w[2] * kin.r[0] };
		for (int i = 0; i < 2; i++) {
			double vt = (1 - xi) * v[2 * (size_t)sn[0] + i] + xi * v[2 * (size_t)sn[1] + i];
			kin.vrel[i] = b->v[i] + wr[i] - vt;  /* Eqs. 3.54-3.56 */
			kin.n[i] = g->n[i];
		}
		kin.vrel[2] = kin.n[2] = 0;
		kin.delta = g->delta;
		kin.gamma = g->gamma;
		kin.wn = 0;
		kin.kn = b->kn;
		kin.meff = dem_contact_meff(b->M, S->smass[k]) / g->gamma;
		kin.dt = dt;
		S->cm.kernel(&S->cm, &kin, cs, &o);
		double F[2];
		dem_segment_forces(g, &o, S->cm.m, F, po->Fnode, NULL);
		for (int i = 0; i < 2; i++)
			b->F[i] += F[i];
		*T += o.T[2];
		b->Fn += o.Fn;
		b->Ft += o.Ft;
		nc++;
	}
	b->contacts = nc;
}

int dem_shotset2d_hook(void *ctx, double t, double dt, const double *x, const double *v,
		       double *f, dem_error_t *e)
{
	dem_shotset2d_t *S = ctx;
	(void)t, (void)e;
	if (S->ns == 0)
		return DEM_OK;
	if (S->F) {
		double c0, m0, c1, m1;
		dem_feshot2d_times(S->F, &c0, &m0);
		int rc = dem_feshot2d_hook(S->F, t, dt, x, v, f, e);
		if (rc)
			return rc;
		dem_feshot2d_times(S->F, &c1, &m1);
		unsigned long pass = S->b[0].pass;
		dem_feshot2d_body(S->F, &S->b[0]);
		S->b[0].pass = pass;
		S->st.steps++;
		S->st.candidates += (double)(S->nseg + dem_feshot2d_mesh(S->F)->nn);
		S->st.contacts += S->b[0].contacts;
		S->st.contact_s += c1 - c0;
		S->st.integrate_s += m1 - m0;
		return DEM_OK;
	}
	if (!S->prepared)
		geometry(S, x, v, dt);
	S->prepared = 0;
	double t0 = dem_wall(), ncont = 0, spc = 0;
	for (size_t s = 0; s < S->ns; s++) {
		shot_forces(S, s, v, dt, &S->T[s]);
		ncont += S->b[s].contacts;
	}
	/* disk/disk (Eq. 3.8), in order (PLANE) */
	for (size_t i = 0; !S->axisym && i < S->ns; i++)
		for (size_t j = i + 1; j < S->ns; j++) {
			dem_shot_body_t *b1 = &S->b[i], *b2 = &S->b[j];
			dem_sphere_t s1 = { .R = b1->R, .kn = b1->kn }, s2 = { .R = b2->R, .kn = b2->kn };
			for (int c = 0; c < 2; c++)
				s1.x[c] = b1->x[c], s1.v[c] = b1->v[c], s2.x[c] = b2->x[c], s2.v[c] = b2->v[c];
			s1.w[2] = b1->w[2], s2.w[2] = b2->w[2];
			dem_pair_out_t o;
			if (!dem_contact_sphere_sphere(&S->cm, &s1, &s2, pair_kn(S, b1, b2),
						       dem_contact_meff(b1->M, b2->M), dt,
						       &S->ss[i * S->ns + j], &o))
				continue;
			spc++;
			for (int c = 0; c < 2; c++)
				b2->F[c] += o.c.F[c], b1->F[c] -= o.c.F[c];
			S->T[j] += o.c.T[2], S->T[i] += o.T1[2];
			b1->Fn += o.c.Fn, b2->Fn += o.c.Fn;
			b1->Ft += o.c.Ft, b2->Ft += o.c.Ft;
			b1->contacts++, b2->contacts++;
		}
	/* the segments' forces on the block, in a fixed order */
	for (size_t k = 0; k < S->ns * S->nseg; k++) {
		const pair2_t *po = &S->po[k];
		if (!po->touch)
			continue;
		const uint32_t *sn = S->seg + 2 * (k % S->nseg);
		for (int a = 0; a < 2; a++)
			for (int i = 0; i < 2; i++)
				f[2 * (size_t)sn[a] + i] += po->Fnode[a][i];
	}
	double t1 = dem_wall();
	/* the shots' central difference step (Eq. 7.2, Box 3.1); a solid
	 * disk's I = M R^2 / 2; the sphere on the axis moves along it only */
	double h = 0.5 * (S->dt_prev + dt);
	for (size_t s = 0; s < S->ns; s++) {
		dem_shot_body_t *b = &S->b[s];
		double Tz = S->T[s];
		if (S->axisym) {
			b->F[0] = 0;
			b->v[1] += h * b->F[1] / b->M;
			b->x[1] += dt * b->v[1];
			continue;
		}
		for (int i = 0; i < 2; i++) {
			b->v[i] += h * b->F[i] / b->M;
			b->x[i] += dt * b->v[i];
		}
		b->w[2] += h * Tz / (0.5 * b->M * b->R * b->R);
	}
	S->dt_prev = dt;
	S->st.steps++;
	S->st.candidates += (double)(S->ns * S->nseg);
	S->st.contacts += ncont;
	S->st.sphere_contacts += spc;
	S->st.contact_s += t1 - t0;
	S->st.integrate_s += dem_wall() - t1;
	return DEM_OK;
}

int dem_shotset2d_drive(dem_shotset2d_t *S, size_t i, const double x[2], const double v[2],
			double w, dem_error_t *e)
{
	if (i >= S->ns)
		return dem_error_set(e, DEM_EINPUT, "drive: shot %zu of a pass of %zu", i, S->ns);
	if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(w))
		return dem_error_set(e, DEM_EINPUT, "drive: shot %zu: a motion that is not finite", i);
	if (S->axisym && (x[0] != 0 || v[0] != 0 || w != 0))
		return dem_error_set(e, DEM_EINPUT, "drive: shot %zu: an axisymmetric shot moves on "
				     "the axis, without spin", i);
	dem_shot_body_t *b = &S->b[i];
	b->x[0] = x[0], b->x[1] = x[1];
	b->v[0] = v[0], b->v[1] = v[1];
	b->w[2] = w;
	S->prepared = 0;
	return DEM_OK;
}

/* ---- queries ------------------------------------------------------------ */

size_t dem_shotset2d_holding(const dem_shotset2d_t *S, size_t *touching, size_t *coming)
{
	return dem_shot_holding(S->b, S->ns, 2, S->lo, S->hi, touching, coming);
}

int dem_shotset2d_done(const dem_shotset2d_t *S)
{
	return dem_shotset2d_holding(S, NULL, NULL) == 0;
}

size_t dem_shotset2d_count(const dem_shotset2d_t *S)
{
	return S->ns;
}

const dem_shot_body_t *dem_shotset2d_body(const dem_shotset2d_t *S, size_t i)
{
	return &S->b[i];
}

double dem_shotset2d_kinetic(const dem_shotset2d_t *S)
{
	if (S->F)
		return S->ns ? dem_feshot2d_kinetic(S->F) : 0;
	double k = 0;
	for (size_t s = 0; s < S->ns; s++) {
		const dem_shot_body_t *b = &S->b[s];
		k += 0.5 * b->M * (b->v[0] * b->v[0] + b->v[1] * b->v[1]);
		k += 0.25 * b->M * b->R * b->R * b->w[2] * b->w[2];
	}
	return k;
}

const dem_feshot2d_t *dem_shotset2d_feshot(const dem_shotset2d_t *S)
{
	return S->F;
}

size_t dem_shotset2d_segments(const dem_shotset2d_t *S)
{
	return S->nseg;
}

void dem_shotset2d_stats(const dem_shotset2d_t *S, dem_shotset_stats_t *s)
{
	*s = S->st;
}
