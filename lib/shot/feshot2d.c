/* feshot2d.c - a finite element shot against the top edge of a plane
 * strain block.  See feshot2d.h. */
#include "shot/feshot2d.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "contact/law.h"
#include "contact/node2d.h"
#include "core/cost.h"

/* A surface: its nodes (slaves of one pass) with their tributary lengths
 * and masses, and its segments (masters of the other pass, the outside on
 * their left) with their masses. */
typedef struct surf {
	size_t nn, ns;
	uint32_t *node;           /* nn nodes */
	double *trib;             /* tributary length per node (reference) */
	uint32_t *seg;            /* 2 nodes per segment */
	double *smass;            /* segment masses */
	double dmax;              /* a node counts as touching up to this depth: the
				   * shortest segment */
	dem_contact_state_t *st;  /* per node, as a slave */
} surf_t;

struct dem_feshot2d {
	const dem_mesh2_t *block;
	const double *bmass;
	dem_feshot2d_opts_t o;
	dem_contact_model_t cm;   /* the linear kernel with the scene's damping */
	double coef;              /* the scene's law: alpha E (law.h, dim 2, m = 3/2) */
	double xi;                /* its damping ratio, 0 without */
	double thick;

	surf_t top;               /* the block's top edge */
	/* the current shot */
	int have;
	dem_mesh2_t mesh;
	dem_mat_t mat;
	int have_mat;
	dem_fe2_t *fe;
	surf_t rim;
	double R, kw, M, dt_pen;
	double *fs;               /* contact forces on the shot's nodes this step */
	dem_shot_body_t body;
	double epen;
	double contact_s, model_s;
};

static void surf_free(surf_t *s)
{
	free(s->node), free(s->trib), free(s->seg), free(s->smass), free(s->st);
	memset(s, 0, sizeof *s);
}

static int surf_alloc(surf_t *s, size_t nn, size_t ns)
{
	s->nn = nn, s->ns = ns;
	s->node = malloc(nn * sizeof *s->node);
	s->trib = calloc(nn, sizeof *s->trib);
	s->seg = malloc(2 * ns * sizeof *s->seg);
	s->smass = malloc(ns * sizeof *s->smass);
	s->st = calloc(nn, sizeof *s->st);
	return s->node && s->trib && s->seg && s->smass && s->st ? 0 : -1;
}

/* Tributary lengths (half of each segment to its two nodes; pos maps a
 * mesh node to its place in s->node), segment masses (a node's mass over
 * the segments it ends, as shotset2d.c's) and dmax, from X and mass. */
static void surf_measure(surf_t *s, const double *X, const double *mass, const size_t *pos)
{
	s->dmax = HUGE_VAL;
	unsigned deg[2];
	for (size_t k = 0; k < s->ns; k++) {
		const uint32_t *q = s->seg + 2 * k;
		double L = hypot(X[2 * q[1]] - X[2 * q[0]], X[2 * q[1] + 1] - X[2 * q[0] + 1]);
		s->trib[pos[q[0]]] += 0.5 * L;
		s->trib[pos[q[1]]] += 0.5 * L;
		s->dmax = fmin(s->dmax, L);
	}
	for (size_t k = 0; k < s->ns; k++) {
		const uint32_t *q = s->seg + 2 * k;
		for (int a = 0; a < 2; a++) {
			deg[a] = 0;
			for (size_t l = 0; l < 2 * s->ns; l++)
				deg[a] += s->seg[l] == q[a];
		}
		s->smass[k] = mass[q[0]] / deg[0] + mass[q[1]] / deg[1];
	}
}

int dem_feshot2d_create(dem_feshot2d_t **Fp, const dem_mesh2_t *block, const double *block_mass,
			const dem_contact_model_t *cm, const dem_feshot2d_opts_t *o, dem_error_t *e)
{
	*Fp = NULL;
	if (!(o->element > 0) || !isfinite(o->element))
		return dem_error_set(e, DEM_EINPUT, "FE shot: element size must be > 0 (got %g m)", o->element);
	if (!(o->E > 0) || !(o->rho > 0) || !isfinite(o->E) || !isfinite(o->rho))
		return dem_error_set(e, DEM_EINPUT, "FE shot: modulus and density must be > 0");
	if (o->fe.mode != DEM_QUAD4_PLANE)
		return dem_error_set(e, DEM_EINPUT, "FE shot: plane strain only (an axisymmetric block "
				     "takes rigid shots)");
	if (cm->p.law.dim != 2 || cm->p.law.m != DEM_LAW_M_HERTZ)
		return dem_error_set(e, DEM_EINPUT, "FE shot: the penalty is the Winkler form of the 2D "
				     "law of m = 1.5 (feshot2d.h); got a %dD law of m = %g",
				     cm->p.law.dim == 2 ? 2 : 3, cm->p.law.m);
	if (cm->p.friction || cm->p.damping == DEM_DAMP_HYSTERESIS)
		return dem_error_set(e, DEM_EINPUT, "FE shot: no %s with an FE shot (Ch. 7.4 has none)",
				     cm->p.friction ? "friction" : "hysteresis");
	dem_feshot2d_t *F = calloc(1, sizeof *F);
	if (!F)
		return dem_error_nomem(e, "FE shot");
	F->block = block;
	F->bmass = block_mass;
	F->o = *o;
	F->o.fe.damping = 0;
	F->coef = cm->p.law.coef;
	F->xi = cm->p.damping == DEM_DAMP_VISCOUS ? cm->p.xi : 0;
	F->thick = o->fe.thick;
	/* the kernel of model.h with the linear law (the pair's k_n given per
	 * pair) and the scene's damping */
	dem_contact_param_t p = { .damping = cm->p.damping, .xi = cm->p.xi, .sepfix = DEM_SEPFIX_OFF };
	size_t nt = dem_mesh2_top_segments(block, -HUGE_VAL, HUGE_VAL, NULL);
	size_t *pos = calloc(block->nn, sizeof *pos);
	if (!pos || surf_alloc(&F->top, (size_t)block->nx + 1, nt)) {
		free(pos);
		dem_feshot2d_free(F);
		return dem_error_nomem(e, "FE shot");
	}
	if (dem_law_init_dim(&p.law, 1, 1, DEM_LAW_M_LINEAR, 2, e) ||
	    dem_contact_model_init(&F->cm, &p, e)) {
		free(pos);
		dem_feshot2d_free(F);
		return e->code;
	}
	dem_mesh2_top_segments(block, -HUGE_VAL, HUGE_VAL, F->top.seg);
	for (int i = 0; i <= block->nx; i++) {
		F->top.node[i] = (uint32_t)dem_mesh2_node(block, i, block->ny);
		pos[F->top.node[i]] = (size_t)i;
	}
	surf_measure(&F->top, block->X, block_mass, pos);
	free(pos);
	*Fp = F;
	return DEM_OK;
}

static void shot_drop(dem_feshot2d_t *F)
{
	dem_fe2_free(F->fe);
	F->fe = NULL;
	dem_mesh2_free(&F->mesh);
	if (F->have_mat)
		dem_mat_free(&F->mat);
	F->have_mat = 0;
	surf_free(&F->rim);
	free(F->fs);
	F->fs = NULL;
	F->have = 0;
}

void dem_feshot2d_free(dem_feshot2d_t *F)
{
	if (!F)
		return;
	shot_drop(F);
	surf_free(&F->top);
	free(F);
}

/* the largest l / m of a surface's nodes */
static double surf_lm(const surf_t *s, const double *mass)
{
	double r = 0;
	for (size_t i = 0; i < s->nn; i++)
		r = fmax(r, s->trib[i] / mass[s->node[i]]);
	return r;
}

/* the shot's model hook: the contact forces found in the block's hook */
static int shot_load(void *ctx, double t, double dt, const double *x, const double *v, double *f,
		     dem_error_t *e)
{
	const dem_feshot2d_t *F = ctx;
	(void)t, (void)dt, (void)x, (void)v, (void)e;
	memcpy(f, F->fs, 2 * F->mesh.nn * sizeof *f);
	return DEM_OK;
}

static void summary(dem_feshot2d_t *F)
{
	const double *x = dem_fe2_coords(F->fe), *v = dem_fe2_velocity(F->fe), *m = dem_fe2_mass(F->fe);
	double sx[2] = { 0, 0 }, sv[2] = { 0, 0 };
	for (size_t n = 0; n < F->mesh.nn; n++)
		for (int c = 0; c < 2; c++)
			sx[c] += m[n] * x[2 * n + c], sv[c] += m[n] * v[2 * n + c];
	for (int c = 0; c < 2; c++)
		F->body.x[c] = sx[c] / F->M, F->body.v[c] = sv[c] / F->M;
}

int dem_feshot2d_begin(dem_feshot2d_t *F, double R, const double c[2], const double v[2],
		       dem_error_t *e)
{
	shot_drop(F);
	if (!(R > 0) || !isfinite(R))
		return dem_error_set(e, DEM_EINPUT, "FE shot: radius must be > 0 (got %g m)", R);
	size_t nrim;
	dem_mat_param_t mp = { .E = F->o.E, .nu = F->o.nu, .rho = F->o.rho };
	if (dem_mesh2_disk(&F->mesh, R, F->o.element, c, &nrim, e) || dem_mat_init(&F->mat, &mp, e))
		return e->code;
	F->have_mat = 1;
	if (dem_fe2_create(&F->fe, &F->mesh, &F->mat, &F->o.fe, e))
		return e->code;
	F->fs = calloc(2 * F->mesh.nn, sizeof *F->fs);
	size_t *pos = malloc(nrim * sizeof *pos);
	if (!F->fs || !pos || surf_alloc(&F->rim, nrim, nrim)) {
		free(pos);
		return dem_error_nomem(e, "FE shot");
	}
	/* the rim: nodes 0 .. nrim-1 counter-clockwise, segments (k+1, k) with
	 * the outside on their left (mesh2.h) */
	for (size_t k = 0; k < nrim; k++) {
		F->rim.node[k] = (uint32_t)k;
		pos[k] = k;
		F->rim.seg[2 * k] = (uint32_t)((k + 1) % nrim);
		F->rim.seg[2 * k + 1] = (uint32_t)k;
	}
	const double *ms = dem_fe2_mass(F->fe);
	surf_measure(&F->rim, F->mesh.X, ms, pos);
	free(pos);
	double *vs = dem_fe2_velocity(F->fe);
	F->M = 0;
	for (size_t n = 0; n < F->mesh.nn; n++) {
		vs[2 * n] = v[0], vs[2 * n + 1] = v[1];
		F->M += ms[n];
	}
	dem_fe2_set_load(F->fe, shot_load, F);
	F->R = R;
	/* the foundation of the scene's law (dem_law_winkler2d_alpha inverted) */
	F->kw = F->coef / dem_law_winkler2d_alpha(1, 1, R);
	double w2 = F->kw * F->thick * (surf_lm(&F->top, F->bmass) + surf_lm(&F->rim, ms));
	F->dt_pen = F->o.fe.dt_factor * 2 / sqrt(w2) * (sqrt(1 + F->xi * F->xi) - F->xi);
	memset(&F->body, 0, sizeof F->body);
	F->body.R = R;
	F->body.M = F->M;
	F->body.dt = HUGE_VAL;
	summary(F);
	F->epen = 0;
	F->have = 1;
	return DEM_OK;
}

double dem_feshot2d_dt(const dem_feshot2d_t *F)
{
	return F->have ? fmin(dem_fe2_dt(F->fe), F->dt_pen) : HUGE_VAL;
}

/* One pass: the slaves of surface s (coordinates xs, velocities vs,
 * masses ms, forces into fsl) against the segments of surface m (xm, vm,
 * fm).  Adds the force on the shot (sign: +1 when the slaves are the
 * shot's, -1 when the segments are) to Fshot; returns the pairs. */
static int one_pass(dem_feshot2d_t *F, surf_t *s, const double *xs, const double *vs,
		    const double *ms, double *fsl, const surf_t *m, const double *xm, const double *vm,
		    double *fm, double dt, double sign, double Fshot[2])
{
	double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
	const double dmax = m->dmax, tol = 1e-2;
	int np = 0;
	for (size_t k = 0; k < 2 * m->ns; k++)
		for (int c = 0; c < 2; c++) {
			double q = xm[2 * (size_t)m->seg[k] + c];
			lo[c] = fmin(lo[c], q - dmax), hi[c] = fmax(hi[c], q + dmax);
		}
	for (size_t i = 0; i < s->nn; i++) {
		size_t id = s->node[i];
		const double *P = xs + 2 * id;
		int best = -1;
		dem_node_seg_t g, gb = { 0 };
		if (P[0] >= lo[0] && P[0] <= hi[0] && P[1] >= lo[1] && P[1] <= hi[1])
			for (size_t k = 0; k < m->ns; k++) {
				const double *A = xm + 2 * (size_t)m->seg[2 * k], *B = xm + 2 * (size_t)m->seg[2 * k + 1];
				if (P[0] < fmin(A[0], B[0]) - dmax || P[0] > fmax(A[0], B[0]) + dmax ||
				    P[1] < fmin(A[1], B[1]) - dmax || P[1] > fmax(A[1], B[1]) + dmax)
					continue;
				if (dem_node_segment(P, A, B, dmax, tol, &g) && (best < 0 || g.g < gb.g))
					best = (int)k, gb = g;
			}
		if (best < 0) {
			dem_contact_state_reset(&s->st[i]);
			continue;
		}
		const uint32_t *q = m->seg + 2 * (size_t)best;
		double xi = gb.xi;
		dem_contact_kin_t kin;
		dem_contact_out_t o;
		for (int c = 0; c < 2; c++) {
			double vt = (1 - xi) * vm[2 * (size_t)q[0] + c] + xi * vm[2 * (size_t)q[1] + c];
			kin.vrel[c] = vs[2 * id + c] - vt;
			kin.n[c] = gb.n[c];
			kin.r[c] = 0;
		}
		kin.vrel[2] = kin.n[2] = kin.r[2] = 0;
		kin.delta = gb.g;
		kin.gamma = 1;
		kin.wn = 0;
		kin.kn = 0.5 * F->kw * s->trib[i] * F->thick;
		kin.meff = dem_contact_meff(ms[id], m->smass[best]);
		kin.dt = dt;
		F->cm.kernel(&F->cm, &kin, &s->st[i], &o);
		F->epen += 0.5 * kin.kn * gb.g * gb.g;
		for (int c = 0; c < 2; c++) {
			fsl[2 * id + c] += o.F[c];
			fm[2 * (size_t)q[0] + c] -= (1 - xi) * o.F[c];
			fm[2 * (size_t)q[1] + c] -= xi * o.F[c];
			Fshot[c] += sign * o.F[c];
		}
		np++;
	}
	return np;
}

int dem_feshot2d_hook(void *ctx, double t, double dt, const double *x, const double *v, double *f,
		      dem_error_t *e)
{
	dem_feshot2d_t *F = ctx;
	(void)t;
	if (!F->have)
		return DEM_OK;
	double t0 = dem_wall();
	const double *xs = dem_fe2_coords(F->fe), *ms = dem_fe2_mass(F->fe);
	const double *vs = dem_fe2_velocity(F->fe);
	double Fs[2] = { 0, 0 };
	memset(F->fs, 0, 2 * F->mesh.nn * sizeof *F->fs);
	F->epen = 0;
	int np = one_pass(F, &F->rim, xs, vs, ms, F->fs, &F->top, x, v, f, dt, 1, Fs);
	np += one_pass(F, &F->top, x, v, F->bmass, f, &F->rim, xs, vs, F->fs, dt, -1, Fs);
	double t1 = dem_wall();
	int rc = dem_fe2_step(F->fe, dt, e);
	F->contact_s += t1 - t0;
	F->model_s += dem_wall() - t1;
	if (rc) {
		dem_error_t w = *e;
		dem_error_clear(e);
		return dem_error_set(e, rc, "FE shot: %s", w.msg);
	}
	F->body.F[0] = Fs[0], F->body.F[1] = Fs[1], F->body.F[2] = 0;
	F->body.Fn = hypot(Fs[0], Fs[1]);
	F->body.Ft = 0;
	F->body.contacts = np;
	F->body.dt = dem_feshot2d_dt(F);
	summary(F);
	return DEM_OK;
}

void dem_feshot2d_body(const dem_feshot2d_t *F, dem_shot_body_t *b)
{
	*b = F->body;
}

const dem_fe2_t *dem_feshot2d_model(const dem_feshot2d_t *F)
{
	return F->have ? F->fe : NULL;
}

const dem_mesh2_t *dem_feshot2d_mesh(const dem_feshot2d_t *F)
{
	return &F->mesh;
}

double dem_feshot2d_kw(const dem_feshot2d_t *F)
{
	return F->kw;
}

double dem_feshot2d_kinetic(const dem_feshot2d_t *F)
{
	if (!F->have)
		return 0;
	const double *v = dem_fe2_velocity(F->fe), *m = dem_fe2_mass(F->fe);
	double k = 0;
	for (size_t n = 0; n < F->mesh.nn; n++)
		k += m[n] * (v[2 * n] * v[2 * n] + v[2 * n + 1] * v[2 * n + 1]);
	return 0.5 * k;
}

double dem_feshot2d_penalty_energy(const dem_feshot2d_t *F)
{
	return F->epen;
}

void dem_feshot2d_times(const dem_feshot2d_t *F, double *contact_s, double *model_s)
{
	*contact_s = F->contact_s;
	*model_s = F->model_s;
}
