/* explicit2d.c - explicit dynamics of the 2D finite element block (see
 * explicit2d.h).
 *
 * Layout.  Node data are arrays of 2 doubles per node (x, v, internal and
 * external forces).  Element state, element by element: the one-point rule
 * keeps sig[6], ep, the back-stresses kin[nh] and the hourglass stiffness
 * state Qs[2] per element; the 2x2 rule keeps them per Gauss point
 * (sig[24], ep[4], kin[4 nh]).  Large strain adds the integrated strain
 * eps[6] per element.  One thread, elements in mesh order: every sum is
 * taken in a fixed order.
 */
#include "fe/explicit2d.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/cost.h"
#include "fe/cdiff.h"
#include "fe/ckpt.h"

typedef struct pload2 {
	size_t ns, nt;
	uint32_t *seg;
	double *t, *p;
} pload2_t;

struct dem_fe2 {
	const dem_mesh2_t *mesh;
	const dem_mat_t *mat;
	dem_fe2_opts_t o;
	dem_mat_update_fn upd;
	size_t nn, ne;
	int npt;              /* material points per element: 1 or 4 */
	int nh;               /* dem_mat_nhist */
	int hg;               /* hourglass control on */
	double *x, *v, *fi, *fx, *mass;
	uint8_t *fix;         /* mesh->fix, plus DEM_FIX_X on the axis (AXISYM) */
	size_t naxis;
	uint32_t *axis;       /* the nodes on the axis (AXISYM) */
	/* element state */
	double *sig, *ep, *kin, *Qs, *eps;
	/* loads */
	pload2_t *pl;
	int npl;
	dem_fe_load_fn hook;
	void *hctx;
	int ext;              /* external forces this step */
	/* time */
	double t, dt_prev, dt_stable;
	long steps;
	/* energies */
	dem_cd_work_t w;
	dem_fe_energy_t en;
	/* failure */
	int failed;
	dem_error_t fail;
	/* counters */
	double cycles, nplastic, elem_s, node_s;
};

void dem_fe2_opts_default(dem_fe2_opts_t *o)
{
	memset(o, 0, sizeof *o);
	o->mode = DEM_QUAD4_PLANE;
	o->thick = 1;
	o->rule = DEM_FE_1PT;
	o->dt_factor = 0.9;
	o->hg_stiff = 0.1;
	o->hg_tangent = 1;
}

double dem_fe2_damping_alpha(const dem_mat_t *m, double xi, double H)
{
	/* the quarter-wave shear mode through the thickness is the 3D block's
	 * (explicit.h): the same alpha */
	return dem_fe_damping_alpha(m, xi, H);
}

/* ---- Set-up --------------------------------------------------------------- */

void dem_fe2_free(dem_fe2_t *fe)
{
	if (!fe)
		return;
	free(fe->x), free(fe->v), free(fe->fi), free(fe->fx), free(fe->mass);
	free(fe->fix), free(fe->axis);
	free(fe->sig), free(fe->ep), free(fe->kin), free(fe->Qs), free(fe->eps);
	for (int i = 0; i < fe->npl; i++)
		free(fe->pl[i].seg), free(fe->pl[i].t), free(fe->pl[i].p);
	free(fe->pl);
	free(fe);
}

/* the coordinates of element el from the node array xs (2 per node) */
static inline void gather(const dem_fe2_t *fe, const double *xs, size_t el, double xe[8])
{
	const uint32_t *q = fe->mesh->quad + 4 * el;
	for (int I = 0; I < 4; I++) {
		xe[I] = xs[2 * (size_t)q[I]];
		xe[4 + I] = xs[2 * (size_t)q[I] + 1];
	}
}

/* ", i, j = I, J" of element el on a structured mesh (mesh2.h), "" on
 * one without grid indices (nx = 0: the disk of dem_mesh2_disk) */
static const char *elem_ij(const dem_mesh2_t *m, size_t el, char buf[48])
{
	buf[0] = 0;
	if (m->nx > 0)
		snprintf(buf, 48, " (i, j = %d, %d)", (int)(el % (size_t)m->nx), (int)(el / (size_t)m->nx));
	return buf;
}

/* the least stable step of the elements at the coordinates xs; 0 and
 * *bad = 1 + the first bad element when one is degenerate */
static double dt_min(const dem_fe2_t *fe, const double *xs, size_t *bad)
{
	double dtm = INFINITY;
	*bad = 0;
	for (size_t el = 0; el < fe->ne; el++) {
		double xe[8], d;
		gather(fe, xs, el, xe);
		if (dem_quad4_dt_crit(xe, fe->o.mode, fe->mat->wave, &d)) {
			*bad = el + 1;
			return 0;
		}
		dtm = d < dtm ? d : dtm;
	}
	return dtm;
}

int dem_fe2_create(dem_fe2_t **out, const dem_mesh2_t *mesh, const dem_mat_t *mat,
		   const dem_fe2_opts_t *o, dem_error_t *e)
{
	*out = NULL;
	if (o->mode != DEM_QUAD4_PLANE && o->mode != DEM_QUAD4_AXISYM)
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: unknown mode %d", (int)o->mode);
	if (o->mode == DEM_QUAD4_PLANE && (!(o->thick > 0) || !isfinite(o->thick)))
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: thickness must be > 0, got %g", o->thick);
	if (o->rule != DEM_FE_1PT && o->rule != DEM_FE_FULL)
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: unknown integration rule %d", (int)o->rule);
	if (!(o->dt_factor > 0 && o->dt_factor <= 1))
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: time step factor must be in (0, 1], got %g",
				     o->dt_factor);
	if (!(o->damping >= 0) || !isfinite(o->damping))
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: damping must be >= 0, got %g", o->damping);
	if (!(o->hg_stiff >= 0) || !(o->hg_visc >= 0) || !isfinite(o->hg_stiff + o->hg_visc))
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: hourglass coefficients must be >= 0");
	if (!(mat->rho > 0))
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: the material needs a density");
	if (mesh->ne == 0 || mesh->nx < 0 || mesh->ny < 0)
		return dem_error_set(e, DEM_EINPUT, "explicit 2D: empty mesh");
	if (o->mode == DEM_QUAD4_AXISYM)
		for (size_t n = 0; n < mesh->nn; n++)
			if (!(mesh->X[2 * n] >= 0))
				return dem_error_set(e, DEM_EINPUT, "explicit 2D: node %zu lies at r = %g < 0 "
						     "(axisymmetric: x is the radius)", n, mesh->X[2 * n]);

	dem_fe2_t *fe = calloc(1, sizeof *fe);
	if (!fe)
		return dem_error_nomem(e, "explicit 2D model");
	fe->mesh = mesh;
	fe->mat = mat;
	fe->o = *o;
	fe->upd = dem_mat_update_select(mat);
	fe->nn = mesh->nn;
	fe->ne = mesh->ne;
	fe->npt = o->rule == DEM_FE_FULL ? 4 : 1;
	fe->nh = dem_mat_nhist(mat);
	fe->hg = o->rule == DEM_FE_1PT && (o->hg_stiff > 0 || o->hg_visc > 0);
	size_t nn = fe->nn, ne = fe->ne, np = ne * (size_t)fe->npt;

	fe->x = malloc(2 * nn * sizeof *fe->x);
	fe->v = calloc(2 * nn, sizeof *fe->v);
	fe->fi = calloc(2 * nn, sizeof *fe->fi);
	fe->fx = calloc(2 * nn, sizeof *fe->fx);
	fe->mass = calloc(nn, sizeof *fe->mass);
	fe->fix = malloc(nn);
	fe->sig = calloc(6 * np, sizeof *fe->sig);
	fe->ep = calloc(np, sizeof *fe->ep);
	if (fe->nh)
		fe->kin = calloc((size_t)fe->nh * np, sizeof *fe->kin);
	if (fe->hg)
		fe->Qs = calloc(2 * ne, sizeof *fe->Qs);
	if (o->large)
		fe->eps = calloc(6 * ne, sizeof *fe->eps);
	if (!fe->x || !fe->v || !fe->fi || !fe->fx || !fe->mass || !fe->fix || !fe->sig || !fe->ep ||
	    (fe->nh && !fe->kin) || (fe->hg && !fe->Qs) || (o->large && !fe->eps))
		goto nomem;
	memcpy(fe->x, mesh->X, 2 * nn * sizeof *fe->x);
	memcpy(fe->fix, mesh->fix, nn);
	if (o->mode == DEM_QUAD4_AXISYM) {
		for (size_t n = 0; n < nn; n++)
			fe->naxis += mesh->X[2 * n] == 0;
		if (fe->naxis && !(fe->axis = malloc(fe->naxis * sizeof *fe->axis)))
			goto nomem;
		for (size_t n = 0, k = 0; n < nn; n++)
			if (mesh->X[2 * n] == 0) {
				fe->axis[k++] = (uint32_t)n;
				fe->fix[n] |= DEM_FIX_X;
			}
	}

	/* masses and the stable step */
	for (size_t el = 0; el < ne; el++) {
		double xe[8], me[4];
		gather(fe, mesh->X, el, xe);
		if (dem_quad4_lumped_mass(xe, o->mode, o->thick, mat->rho, me)) {
			char ij[48];
			dem_error_set(e, DEM_EINPUT, "explicit 2D: element %zu%s of the mesh is inverted "
				      "or degenerate", el, elem_ij(mesh, el, ij));
			dem_fe2_free(fe);
			return DEM_EINPUT;
		}
		for (int I = 0; I < 4; I++)
			fe->mass[mesh->quad[4 * el + I]] += me[I];
	}
	size_t bad;
	fe->dt_stable = o->dt_factor * dt_min(fe, mesh->X, &bad);
	if (bad) {
		size_t el = bad - 1;
		char ij[48];
		dem_error_set(e, DEM_EINPUT, "explicit 2D: element %zu%s of the mesh is inverted or "
			      "degenerate", el, elem_ij(mesh, el, ij));
		dem_fe2_free(fe);
		return DEM_EINPUT;
	}
	*out = fe;
	return DEM_OK;
nomem:
	dem_fe2_free(fe);
	return dem_error_nomem(e, "explicit 2D model");
}

/* ---- Loads ---------------------------------------------------------------- */

int dem_fe2_add_pressure(dem_fe2_t *fe, size_t nseg, const uint32_t *seg, size_t nt,
			 const double *t, const double *p, dem_error_t *e)
{
	if (dem_cd_table_check(nt, t, p, e))
		return e->code;
	for (size_t s = 0; s < 2 * nseg; s++)
		if (seg[s] >= fe->nn)
			return dem_error_set(e, DEM_EINPUT, "pressure: segment %zu names node %u of %zu",
					     s / 2, seg[s], fe->nn);
	pload2_t *pl = realloc(fe->pl, (size_t)(fe->npl + 1) * sizeof *pl);
	if (!pl)
		return dem_error_nomem(e, "pressure load");
	fe->pl = pl;
	pl = &fe->pl[fe->npl];
	memset(pl, 0, sizeof *pl);
	pl->seg = malloc((2 * nseg + 1) * sizeof *pl->seg);
	pl->t = malloc(nt * sizeof *pl->t);
	pl->p = malloc(nt * sizeof *pl->p);
	if (!pl->seg || !pl->t || !pl->p) {
		free(pl->seg), free(pl->t), free(pl->p);
		return dem_error_nomem(e, "pressure load");
	}
	memcpy(pl->seg, seg, 2 * nseg * sizeof *seg);
	memcpy(pl->t, t, nt * sizeof *t);
	memcpy(pl->p, p, nt * sizeof *p);
	pl->ns = nseg;
	pl->nt = nt;
	fe->npl++;
	return DEM_OK;
}

void dem_fe2_set_load(dem_fe2_t *fe, dem_fe2_load_fn fn, void *ctx)
{
	fe->hook = fn;
	fe->hctx = ctx;
}

static void apply_pressure(dem_fe2_t *fe, const pload2_t *pl, double t)
{
	double p = dem_cd_history(pl->nt, pl->t, pl->p, t);
	if (p == 0)
		return;
	const double *x = fe->o.large ? fe->x : fe->mesh->X;
	int axi = fe->o.mode == DEM_QUAD4_AXISYM;
	const double two_pi = 6.28318530717958647693;
	for (size_t s = 0; s < pl->ns; s++) {
		size_t a = pl->seg[2 * s], b = pl->seg[2 * s + 1];
		double tx = x[2 * b] - x[2 * a], ty = x[2 * b + 1] - x[2 * a + 1];
		/* p L times the inward unit normal (t_y, -t_x)/L: p (t_y, -t_x);
		 * times the out-of-plane measure shared by the shape functions */
		double wa, wb;
		if (axi && fe->o.rule == DEM_FE_1PT) {
			/* the one-point element's own rule: the ring at the
			 * segment's middle (explicit2d.h) */
			wa = wb = 0.25 * two_pi * (x[2 * a] + x[2 * b]);
		} else if (axi) {
			double ra = x[2 * a], rb = x[2 * b];
			wa = two_pi * (2 * ra + rb) / 6;
			wb = two_pi * (ra + 2 * rb) / 6;
		} else {
			wa = wb = 0.5 * fe->o.thick;
		}
		fe->fx[2 * a] += wa * p * ty;
		fe->fx[2 * a + 1] -= wa * p * tx;
		fe->fx[2 * b] += wb * p * ty;
		fe->fx[2 * b + 1] -= wb * p * tx;
	}
}

/* ---- Node loop ------------------------------------------------------------ */


static void node_loop(dem_fe2_t *fe, const dem_cd_coef_t *c, double sum[DEM_CD_N])
{
	const uint8_t *fix = fe->fix;
	double *restrict x = fe->x, *restrict v = fe->v, *restrict fi = fe->fi;
	double *restrict fx = fe->fx;
	const double *restrict mass = fe->mass;
	const int ext = fe->ext;
	double T = 0, wxa = 0, wxb = 0, wda = 0, wdb = 0;
	for (size_t n = 0; n < fe->nn; n++) {
		double m = mass[n], rm = c->cf / m;
		unsigned fb = fix[n];
		for (int k = 0; k < 2; k++) {
			size_t d = 2 * n + k;
			double fext = ext ? fx[d] : 0;
			double F = fext - fi[d];
			double vm = v[d];
			int fixed = fb >> k & 1;
			double vp = fixed ? vm : (c->co * vm + rm * F) * c->rden;
			double vn = c->w1 * vp + c->w0 * vm;
			double dua = c->dtp * vm, dub = c->dt * vp;
			double fd = c->alpha * m * vn;
			/* on a constrained dof the loads' force includes the
			 * reaction (explicit.c) */
			double fa = fixed ? m * (vp - vm) * c->rdth + fd + fi[d] : fext;
			T += m * (c->k0 * vm + c->k1 * vp) * vp;
			wda += fd * dua;
			wdb += fd * dub;
			wxa += fa * dua;
			wxb += fa * dub;
			v[d] = vp;
			x[d] += dub;
			fi[d] = 0;
			fx[d] = 0;
		}
	}
	sum[DEM_CD_T] = 0.5 * T;
	sum[DEM_CD_WXA] = 0.5 * wxa;
	sum[DEM_CD_WXB] = 0.5 * wxb;
	sum[DEM_CD_WDA] = 0.5 * wda;
	sum[DEM_CD_WDB] = 0.5 * wdb;
}

/* ---- Element loops ---------------------------------------------------------- */

typedef struct esum {
	double eint, epl, ehg, npl;
	double dt;       /* least step estimate of the new shapes (large strain) */
	size_t bad;      /* 1 + first bad element, 0 if none */
} esum_t;

/* Jaumann rotation of a strain with engineering shears by the in-plane
 * spin: a = W_xy dt (dem_mat_jaumann's rotation on eps_ij = gamma_ij / 2,
 * with W_yz = W_zx = 0) */
static inline void rotate_strain2(double e[6], double a)
{
	double e0 = e[0], e1 = e[1], g3 = e[3];
	e[0] += a * g3;
	e[1] -= a * g3;
	e[3] += 2 * a * (e1 - e0);
}

/* rotate the stress and the back-stresses of one point by the spin w */
static inline void rotate_point(int nh, const double w[3], double dt, double *s, double *kin)
{
	dem_mat_jaumann(s, w, dt);
	for (int k = 0; k < nh; k += 6)
		dem_mat_jaumann(kin + k, w, dt);
}

static inline void scatter(dem_fe2_t *fe, size_t el, const double f[8])
{
	const uint32_t *q = fe->mesh->quad + 4 * el;
	for (int I = 0; I < 4; I++) {
		fe->fi[2 * (size_t)q[I]] += f[I];
		fe->fi[2 * (size_t)q[I] + 1] += f[4 + I];
	}
}

static inline __attribute__((always_inline)) void elem_1pt(dem_fe2_t *fe, double dt, esum_t *es,
							   const int large, const int hg)
{
	const dem_mat_t *m = fe->mat;
	const double *xs = large ? fe->x : fe->mesh->X;
	dem_mat_update_fn upd = fe->upd;
	int nh = fe->nh;
	double kaps = fe->o.hg_stiff, kapv = fe->o.hg_visc;
	double eint = 0, epl = 0, ehg = 0, npl = 0, dtm = INFINITY;
	size_t bad = 0;
	for (size_t el = 0; el < fe->ne; el++) {
		double xe[8], ve[8], f[8];
		dem_quad4_1pt_t g;
		gather(fe, xs, el, xe);
		gather(fe, fe->v, el, ve);
		if (dem_quad4_1pt_geom(xe, fe->o.mode, fe->o.thick, &g)) {
			if (!bad)
				bad = el + 1;
			continue;
		}
		dem_quad4_1pt_rate(&g, ve);
		double d[6], w[3], de[6], s0[6], wp = 0;
		dem_quad4_strain_rate(g.L, g.zz, d, w);
		double *s = fe->sig + 6 * el, *kin = nh ? fe->kin + (size_t)nh * el : NULL;
		memcpy(s0, s, sizeof s0);
		if (large)
			rotate_point(nh, w, dt, s, kin);
		for (int k = 0; k < 6; k++)
			de[k] = d[k] * dt;
		int pl = upd(m, de, dt, s, fe->ep + el, kin, &wp);
		double dE = 0;
		for (int k = 0; k < 6; k++)
			dE += (s0[k] + s[k]) * d[k];
		eint += 0.5 * dt * g.vol * dE;
		epl += g.vol * wp;
		npl += pl;
		double Q[2];
		if (hg) {
			double ks, cv, *qs = fe->Qs + 2 * el, qo = 0, qn = 0, P = 0;
			dem_quad4_hg_coef(&g, m, kaps, kapv, &ks, &cv);
			/* in an element that flows, an increment that loads the
			 * stiffness form grows by the tangent shear ratio, one that
			 * unloads it by the full stiffness (explicit.c) */
			double r = pl && fe->o.hg_tangent ? dem_mat_tangent_ratio(m, fe->ep[el]) : 1;
			for (int i = 0; i < 2; i++) {
				double inc = ks * dt * g.q[i];
				qo += qs[i] * g.q[i];
				if (qs[i] * inc > 0)
					inc *= r;
				qs[i] += inc;
				Q[i] = qs[i] + cv * g.q[i];
				qn += qs[i] * g.q[i];
				P += Q[i] * g.q[i];
			}
			/* the stiffness form's work by the trapezoidal rule */
			ehg += dt * (P - 0.5 * (qn - qo));
		}
		dem_quad4_1pt_force(&g, s, hg ? Q : NULL, f);
		scatter(fe, el, f);
		if (large) {
			double *ee = fe->eps + 6 * el, dte;
			rotate_strain2(ee, w[0] * dt);
			for (int k = 0; k < 6; k++)
				ee[k] += de[k];
			if (dem_quad4_dt_crit(xe, fe->o.mode, m->wave, &dte) == DEM_QUAD4_OK && dte < dtm)
				dtm = dte;
		}
	}
	es->eint = eint, es->epl = epl, es->ehg = ehg, es->npl = npl;
	es->dt = dtm;
	es->bad = bad;
}

static inline __attribute__((always_inline)) void elem_full(dem_fe2_t *fe, double dt, esum_t *es,
							    const int large)
{
	const dem_mat_t *m = fe->mat;
	const double *xs = large ? fe->x : fe->mesh->X;
	dem_mat_update_fn upd = fe->upd;
	int nh = fe->nh;
	double eint = 0, epl = 0, npl = 0, dtm = INFINITY;
	size_t bad = 0;
	for (size_t el = 0; el < fe->ne; el++) {
		double xe[8], ve[8], f[8];
		dem_quad4_full_t g;
		gather(fe, xs, el, xe);
		gather(fe, fe->v, el, ve);
		if (dem_quad4_full_geom(xe, fe->o.mode, fe->o.thick, &g)) {
			if (!bad)
				bad = el + 1;
			continue;
		}
		dem_quad4_full_rate(&g, ve, 1);
		double *sg = fe->sig + 24 * el, *ep = fe->ep + 4 * el;
		double dm[6] = { 0 }, wm = 0;
		for (int p = 0; p < 4; p++) {
			double d[6], w[3], de[6], s0[6], wp = 0, dE = 0;
			double *s = sg + 6 * p, *kin = nh ? fe->kin + (size_t)nh * (4 * el + (size_t)p) : NULL;
			dem_quad4_strain_rate(g.L[p], g.zz[p], d, w);
			memcpy(s0, s, sizeof s0);
			if (large)
				rotate_point(nh, w, dt, s, kin);
			for (int k = 0; k < 6; k++)
				de[k] = d[k] * dt;
			npl += upd(m, de, dt, s, ep + p, kin, &wp);
			for (int k = 0; k < 6; k++) {
				dE += (s0[k] + s[k]) * d[k];
				dm[k] += g.wdet[p] * d[k];
			}
			wm += g.wdet[p] * w[0];
			eint += 0.5 * dt * g.wdet[p] * dE;
			epl += g.wdet[p] * wp;
		}
		dem_quad4_full_force(&g, sg, 1, f);
		scatter(fe, el, f);
		if (large) {
			double rv = 1 / g.vol, *ee = fe->eps + 6 * el, dte;
			rotate_strain2(ee, dt * rv * wm);
			for (int k = 0; k < 6; k++)
				ee[k] += dt * rv * dm[k];
			if (dem_quad4_dt_crit(xe, fe->o.mode, m->wave, &dte) == DEM_QUAD4_OK && dte < dtm)
				dtm = dte;
		}
	}
	es->eint = eint, es->epl = epl, es->ehg = 0, es->npl = npl;
	es->dt = dtm;
	es->bad = bad;
}

/* the loop chosen once per step: the effects are constants in each
 * instance */
static void elem_run(dem_fe2_t *fe, double dt, esum_t *es)
{
	if (fe->o.rule == DEM_FE_FULL) {
		if (fe->o.large)
			elem_full(fe, dt, es, 1);
		else
			elem_full(fe, dt, es, 0);
	} else if (fe->o.large) {
		if (fe->hg)
			elem_1pt(fe, dt, es, 1, 1);
		else
			elem_1pt(fe, dt, es, 1, 0);
	} else {
		if (fe->hg)
			elem_1pt(fe, dt, es, 0, 1);
		else
			elem_1pt(fe, dt, es, 0, 0);
	}
}

/* ---- The step -------------------------------------------------------------- */

int dem_fe2_step(dem_fe2_t *fe, double dt, dem_error_t *e)
{
	if (fe->failed)
		return dem_error_set(e, fe->fail.code, "%s", fe->fail.msg);
	if (!(dt > 0) || !isfinite(dt))
		dt = fe->dt_stable;
	double tn = fe->t;
	/* u_r = 0 on the axis */
	for (size_t k = 0; k < fe->naxis; k++)
		fe->v[2 * (size_t)fe->axis[k]] = 0;

	/* 1. external forces at t_n on x_n */
	fe->ext = fe->npl > 0 || fe->hook;
	if (fe->hook) {
		int rc = fe->hook(fe->hctx, tn, dt, fe->x, fe->v, fe->fx, e);
		if (rc) {
			memset(fe->fx, 0, 2 * fe->nn * sizeof *fe->fx);
			return rc;
		}
	}
	for (int i = 0; i < fe->npl; i++)
		apply_pressure(fe, &fe->pl[i], tn);

	/* 2-3. velocities and coordinates (Eqs. 1.6-1.7; Eq. 1.9 to start) */
	dem_cd_coef_t c;
	dem_cd_coef(&c, fe->steps, dt, fe->dt_prev, fe->o.damping);
	double w0 = dem_wall(), sum[DEM_CD_N];
	node_loop(fe, &c, sum);
	double w1 = dem_wall();

	/* energies at t_n */
	dem_cd_energy(&fe->w, fe->steps, tn, sum, &fe->en);

	/* 4. elements on x_{n+1} */
	esum_t es;
	elem_run(fe, dt, &es);
	double w2 = dem_wall();
	fe->node_s += w1 - w0;
	fe->elem_s += w2 - w1;
	fe->w.eint += es.eint;
	fe->w.epl += es.epl;
	fe->w.ehg += es.ehg;
	fe->nplastic += es.npl;
	fe->t = tn + dt;
	fe->dt_prev = dt;
	fe->steps++;
	fe->cycles += (double)fe->ne;
	if (es.bad) {
		size_t el = es.bad - 1;
		fe->failed = 1;
		char ij[48];
		dem_error_set(&fe->fail, DEM_ENUMERIC, "element %zu%s inverted or degenerate at t = "
			      "%.9g s (step %ld)", el, elem_ij(fe->mesh, el, ij), fe->t, fe->steps);
		return dem_error_set(e, DEM_ENUMERIC, "%s", fe->fail.msg);
	}
	if (fe->o.large)
		fe->dt_stable = fe->o.dt_factor * es.dt;
	return DEM_OK;
}

/* ---- State ------------------------------------------------------------------ */

double dem_fe2_dt(const dem_fe2_t *fe)
{
	return fe->dt_stable;
}

double dem_fe2_time(const dem_fe2_t *fe)
{
	return fe->t;
}

long dem_fe2_steps(const dem_fe2_t *fe)
{
	return fe->steps;
}

const double *dem_fe2_coords(const dem_fe2_t *fe)
{
	return fe->x;
}

double *dem_fe2_velocity(dem_fe2_t *fe)
{
	return fe->v;
}

const double *dem_fe2_mass(const dem_fe2_t *fe)
{
	return fe->mass;
}

void dem_fe2_displacements(const dem_fe2_t *fe, double *u)
{
	for (size_t i = 0; i < 2 * fe->nn; i++)
		u[i] = fe->x[i] - fe->mesh->X[i];
}

void dem_fe2_fields(const dem_fe2_t *fe, double *sig, double *eps, double *ep)
{
	const dem_mesh2_t *m = fe->mesh;
	int full = fe->o.rule == DEM_FE_FULL;
	for (size_t el = 0; el < fe->ne; el++) {
		if (!full) {
			if (sig)
				memcpy(sig + 6 * el, fe->sig + 6 * el, 6 * sizeof *sig);
			if (ep)
				ep[el] = fe->ep[el];
		} else if (sig || ep) {
			/* volume averages over the Gauss points */
			double xe[8], s6[6] = { 0 }, e1 = 0, wsum = 0;
			dem_quad4_full_t g;
			gather(fe, fe->o.large ? fe->x : m->X, el, xe);
			int ok = !dem_quad4_full_geom(xe, fe->o.mode, fe->o.thick, &g);
			for (int p = 0; p < 4; p++) {
				double w = ok ? g.wdet[p] : 1;
				wsum += w;
				for (int k = 0; k < 6; k++)
					s6[k] += w * fe->sig[24 * el + 6 * (size_t)p + k];
				e1 += w * fe->ep[4 * el + (size_t)p];
			}
			for (int k = 0; k < 6 && sig; k++)
				sig[6 * el + k] = s6[k] / wsum;
			if (ep)
				ep[el] = e1 / wsum;
		}
		if (!eps)
			continue;
		if (fe->o.large) {
			memcpy(eps + 6 * el, fe->eps + 6 * el, 6 * sizeof *eps);
		} else {
			/* B(X) u: the mean displacement gradient (and the hoop
			 * strain at the centre) */
			double xe[8], ue[8], w[3];
			dem_quad4_1pt_t g;
			gather(fe, m->X, el, xe);
			for (int I = 0; I < 4; I++) {
				size_t n = m->quad[4 * el + I];
				ue[I] = fe->x[2 * n] - m->X[2 * n];
				ue[4 + I] = fe->x[2 * n + 1] - m->X[2 * n + 1];
			}
			dem_quad4_1pt_geom(xe, fe->o.mode, fe->o.thick, &g);
			dem_quad4_1pt_rate(&g, ue);
			dem_quad4_strain_rate(g.L, g.zz, eps + 6 * el, w);
		}
	}
}

void dem_fe2_energy(const dem_fe2_t *fe, dem_fe_energy_t *en)
{
	*en = fe->en;
}

void dem_fe2_stats(const dem_fe2_t *fe, dem_fe_stats_t *s)
{
	s->steps = fe->steps;
	s->elem_cycles = fe->cycles;
	s->plastic_updates = fe->nplastic;
	s->elem_s = fe->elem_s;
	s->node_s = fe->node_s;
}

/* ---- Checkpoint ------------------------------------------------------------- */

/* Everything dem_fe2_step reads that it wrote before (explicit.c's rule:
 * a field added to struct dem_fe2 that carries over from step to step
 * needs its line here, and CKPT_VERSION raised). */
#define CKPT_VERSION 1
#define CKPT_MAXITEM 32

static int ckpt_items(const dem_fe2_t *cfe, dem_ckpt_item_t *it)
{
	dem_fe2_t *fe = (dem_fe2_t *)cfe;  /* saved from, or loaded into */
	size_t nn = fe->nn, ne = fe->ne, np = ne * (size_t)fe->npt, d = sizeof(double);
	int n = 0;
#define ITEM(nm, ptr, sz) (it[n++] = (dem_ckpt_item_t){ nm, ptr, sz })
	ITEM("x", fe->x, 2 * nn * d);
	ITEM("v", fe->v, 2 * nn * d);
	ITEM("fi", fe->fi, 2 * nn * d);
	ITEM("sig", fe->sig, 6 * np * d);
	ITEM("ep", fe->ep, np * d);
	if (fe->kin)
		ITEM("kin", fe->kin, (size_t)fe->nh * np * d);
	if (fe->Qs)
		ITEM("Qs", fe->Qs, 2 * ne * d);
	if (fe->eps)
		ITEM("eps", fe->eps, 6 * ne * d);
	ITEM("t", &fe->t, d);
	ITEM("dt_prev", &fe->dt_prev, d);
	ITEM("dt_stable", &fe->dt_stable, d);
	ITEM("steps", &fe->steps, sizeof fe->steps);
	ITEM("T0", &fe->w.T0, d);
	ITEM("wx_acc", &fe->w.wx_acc, d);
	ITEM("wd_acc", &fe->w.wd_acc, d);
	ITEM("eint", &fe->w.eint, d);
	ITEM("epl", &fe->w.epl, d);
	ITEM("ehg", &fe->w.ehg, d);
	ITEM("en", &fe->en, sizeof fe->en);
	ITEM("cycles", &fe->cycles, d);
	ITEM("nplastic", &fe->nplastic, d);
	ITEM("elem_s", &fe->elem_s, d);
	ITEM("node_s", &fe->node_s, d);
#undef ITEM
	return n;
}

/* What the model was made from; zeroed before filling. */
typedef struct ckpt_head {
	char magic[8];
	uint32_t version, nitem;
	uint64_t nn, ne;
	int32_t nx, ny, mode, rule, large, hg, hg_tangent, pad;
	double thick, dt_factor, damping, hg_stiff, hg_visc;
	uint32_t mesh_crc, mat_crc;
} ckpt_head_t;

static const char ckpt_magic[8] = "DEMFE2ck";

static void ckpt_head(const dem_fe2_t *fe, ckpt_head_t *h)
{
	const dem_mesh2_t *m = fe->mesh;
	dem_ckpt_item_t it[CKPT_MAXITEM];
	memset(h, 0, sizeof *h);
	memcpy(h->magic, ckpt_magic, sizeof h->magic);
	h->version = CKPT_VERSION;
	h->nitem = (uint32_t)ckpt_items(fe, it);
	h->nn = fe->nn, h->ne = fe->ne;
	h->nx = m->nx, h->ny = m->ny;
	h->mode = (int32_t)fe->o.mode, h->rule = (int32_t)fe->o.rule, h->large = fe->o.large;
	h->hg = fe->hg, h->hg_tangent = fe->o.hg_tangent;
	h->thick = fe->o.mode == DEM_QUAD4_PLANE ? fe->o.thick : 0;
	h->dt_factor = fe->o.dt_factor, h->damping = fe->o.damping;
	h->hg_stiff = fe->o.hg_stiff, h->hg_visc = fe->o.hg_visc;
	uint32_t c = dem_ckpt_crc(0, m->X, 2 * m->nn * sizeof *m->X);
	c = dem_ckpt_crc(c, m->quad, 4 * m->ne * sizeof *m->quad);
	h->mesh_crc = dem_ckpt_crc(c, m->fix, m->nn);
	h->mat_crc = dem_ckpt_mat_crc(fe->mat);
}

int dem_fe2_save(const dem_fe2_t *fe, FILE *f, dem_error_t *e)
{
	ckpt_head_t h;
	dem_ckpt_item_t it[CKPT_MAXITEM];
	int n = ckpt_items(fe, it);
	ckpt_head(fe, &h);
	return dem_ckpt_write(f, &h, sizeof h, it, n, e);
}

int dem_fe2_load(dem_fe2_t *fe, FILE *f, dem_error_t *e)
{
	ckpt_head_t h, w;
	dem_ckpt_item_t it[CKPT_MAXITEM];
	int n = ckpt_items(fe, it);
	ckpt_head(fe, &w);
	if (dem_ckpt_read_head(f, &h, sizeof h, e))
		return e->code;
	if (memcmp(h.magic, ckpt_magic, sizeof h.magic))
		return dem_error_set(e, DEM_EINPUT, "checkpoint: not a 2D model checkpoint (bad magic)");
	if (h.version != w.version)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: model version %u, expected %u",
				     (unsigned)h.version, (unsigned)w.version);
	if (h.nn != w.nn || h.ne != w.ne || h.nx != w.nx || h.ny != w.ny)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of a mesh of %d x %d elements (%llu "
				     "nodes), this one is %d x %d (%zu nodes)", (int)h.nx, (int)h.ny,
				     (unsigned long long)h.nn, w.nx, w.ny, fe->nn);
	if (h.mesh_crc != w.mesh_crc)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of another mesh (same sizes, other "
				     "coordinates or constraints)");
	if (h.mode != w.mode || h.rule != w.rule || h.large != w.large || h.hg != w.hg ||
	    h.hg_tangent != w.hg_tangent || h.nitem != w.nitem || memcmp(&h.thick, &w.thick, 5 * sizeof(double)))
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of other run options (mode, thickness, "
				     "integration rule, strain, time step factor, damping or hourglass control)");
	if (h.mat_crc != w.mat_crc)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of another material");
	if (dem_ckpt_read_items(f, &h, sizeof h, it, n, e))
		return e->code;
	fe->failed = 0;
	return DEM_OK;
}
