/* model.c - contact model kernels: normal law, energy loss, friction
 * (Han 2004, Ch. 3.3-3.6).  See model.h.
 *
 * One generic kernel is written once with the law exponent, the energy
 * loss and friction as compile-time constants; the 24 combinations are
 * instantiated below and dem_contact_model_init picks one.  The compiler
 * drops the branches of the absent effects.
 */
#include "contact/model.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/vec3.h"

enum { LAW_1, LAW_15, LAW_2, LAW_GEN };

static inline __attribute__((always_inline)) double lawpow(int law, double m, double x)
{
	switch (law) {
	case LAW_1: return x;
	case LAW_15: return x * sqrt(x);
	case LAW_2: return x * x;
	default: return pow(x, m);
	}
}

void dem_contact_state_reset(dem_contact_state_t *s)
{
	memset(s, 0, sizeof *s);
}

/* Eqs. 3.57-3.62.  Deviation: Eq. 3.62 writes the new force along the
 * current sliding direction n_t; we keep the direction of the trial force
 * (the usual return mapping), which is what the elasto-plastic model of
 * Fig. 3.10 describes: on a reversal the force unloads along k_t instead of
 * flipping at once. */
static inline __attribute__((always_inline)) void
friction(dem_contact_state_t *s, const double n[3], const double vrel[3], double wn,
         double dt, double kt, double mu, double Fn, double Ft[3])
{
	double f[3] = { s->Ft[0], s->Ft[1], s->Ft[2] };
	double f2 = v3_dot(f, f);
	if (f2 > 0) {
		/* co-rotation T_r: the smallest rotation taking the old normal to
		 * the new one (Rodrigues, k = n_old x n, c = n_old . n), then the
		 * component along n removed and the length restored, so that
		 * |F_tR| = |F_t| and F_tR . n = 0 */
		double k[3], kf[3], c = v3_dot(s->n, n);
		if (c > -0.5) {
			v3_cross(s->n, n, k);
			v3_cross(k, f, kf);
			double kk = v3_dot(k, f) / (1 + c);
			for (int i = 0; i < 3; i++)
				f[i] = c * f[i] + kf[i] + k[i] * kk;
		}
		double fn = v3_dot(f, n);
		for (int i = 0; i < 3; i++)
			f[i] -= fn * n[i];
		double l2 = v3_dot(f, f);
		if (l2 > 0) {
			double sc = sqrt(f2 / l2);
			for (int i = 0; i < 3; i++)
				f[i] *= sc;
		}
		/* Eq. 3.59: rotation about n by the relative normal spin */
		double th = wn * dt;
		if (th != 0) {
			double nf[3], co = cos(th), si = sin(th);
			v3_cross(n, f, nf);
			for (int i = 0; i < 3; i++)
				f[i] = co * f[i] + si * nf[i];
		}
	}
	/* Eqs. 3.58, 3.60: trial force from the tangential sliding increment */
	double vn = v3_dot(vrel, n);
	for (int i = 0; i < 3; i++)
		f[i] -= kt * (vrel[i] - vn * n[i]) * dt;
	/* Eqs. 3.61-3.62: return to the Coulomb cone */
	double lim = mu * Fn, l2 = v3_dot(f, f);
	if (l2 > lim * lim) {
		double sc = l2 > 0 ? lim / sqrt(l2) : 0;
		for (int i = 0; i < 3; i++)
			f[i] *= sc;
	}
	for (int i = 0; i < 3; i++) {
		Ft[i] = s->Ft[i] = f[i];
		s->n[i] = n[i];
	}
}

void dem_friction_step(dem_contact_state_t *s, const double n[3], const double vrel[3],
                       double wn, double dt, double kt, double mu, double Fn, double Ft[3])
{
	friction(s, n, vrel, wn, dt, kt, mu, Fn, Ft);
}

static inline __attribute__((always_inline)) void
kernel(const dem_contact_model_t *cm, const dem_contact_kin_t *k, dem_contact_state_t *s,
       dem_contact_out_t *o, const int law, const int damp, const int fric)
{
	const double m = cm->m, d = k->delta, kn = k->kn, g = k->gamma;
	const double dm = lawpow(law, m, d);  /* delta^m */
	double F;
	o->bc = kn, o->bg0 = 0;
	if (damp == DEM_DAMP_HYSTERESIS) {
		/* Eqs. 3.63-3.64: loading on k_n delta^m; below the largest
		 * overlap, the steeper k'_n (delta - delta_0)^m, zero below delta_0 */
		if (d >= s->dmax) {
			s->dmax = d;
			F = kn * dm;
		} else {
			double x = d - s->dmax * cm->shift;
			F = x > 0 ? kn * cm->p.unload * lawpow(law, m, x) : 0;
			o->bc = kn * cm->p.unload, o->bg0 = s->dmax * cm->shift;
		}
	} else {
		F = kn * dm;
	}
	o->Fe = F * g;  /* the elastic part, for the separation correction */
	/* tangent stiffness K_n = m k_n delta^(m-1) (Eq. 3.72) */
	double Kn = 0;
	if (damp == DEM_DAMP_VISCOUS || fric)
		Kn = law == LAW_1 ? kn : m * kn * dm / d;
	const double vn = v3_dot(k->vrel, k->n);  /* < 0 while approaching */
	if (damp == DEM_DAMP_VISCOUS) {
		/* Eqs. 3.70, 3.75-3.76: C_n = 2 xi sqrt(K_n M); repulsive only */
		F -= 2 * cm->p.xi * sqrt(Kn * k->meff) * vn;
		if (F < 0)
			F = 0;
	}
	F *= g;  /* Eq. 3.9 */
	o->Fn = F;
	for (int i = 0; i < 3; i++)
		o->F[i] = F * k->n[i];
	if (fric) {
		double Ft[3];
		friction(s, k->n, k->vrel, k->wn, k->dt, cm->kt_ratio * g * Kn, cm->p.mu, F, Ft);
		for (int i = 0; i < 3; i++)
			o->F[i] += Ft[i];
		/* the normal force passes through the centre: only F_t turns */
		v3_cross(k->r, Ft, o->T);
		o->Ft = v3_norm(Ft);
	} else {
		o->T[0] = o->T[1] = o->T[2] = 0;
		o->Ft = 0;
	}
}

#define KERNEL(L, D, F) \
	static void kernel_##L##_##D##_##F(const dem_contact_model_t *cm, const dem_contact_kin_t *k, \
	                                   dem_contact_state_t *s, dem_contact_out_t *o) \
	{ kernel(cm, k, s, o, L, D, F); }
#define KERNELS_D(L, D) KERNEL(L, D, 0) KERNEL(L, D, 1)
#define KERNELS(L) KERNELS_D(L, 0) KERNELS_D(L, 1) KERNELS_D(L, 2)
KERNELS(LAW_1)
KERNELS(LAW_15)
KERNELS(LAW_2)
KERNELS(LAW_GEN)

#define ROW_D(L, D) { kernel_##L##_##D##_0, kernel_##L##_##D##_1 }
#define ROW(L) { ROW_D(L, 0), ROW_D(L, 1), ROW_D(L, 2) }
static const dem_contact_kernel_fn kernels[4][3][2] = {
	ROW(LAW_1), ROW(LAW_15), ROW(LAW_2), ROW(LAW_GEN)
};

int dem_contact_model_init(dem_contact_model_t *cm, const dem_contact_param_t *p, dem_error_t *e)
{
	memset(cm, 0, sizeof *cm);
	double m = p->law.m;
	if (!(m >= 1 && m <= 4) || !(p->law.coef > 0) || !isfinite(p->law.coef))
		return dem_error_set(e, DEM_EINPUT, "contact model: no valid normal law (m = %g, coefficient %g)",
		                     m, p->law.coef);
	if (p->damping < DEM_DAMP_NONE || p->damping > DEM_DAMP_HYSTERESIS)
		return dem_error_set(e, DEM_EINPUT, "contact model: unknown energy loss model %d", p->damping);
	if (p->damping == DEM_DAMP_VISCOUS && !(p->xi >= 0 && p->xi < 1))
		return dem_error_set(e, DEM_EINPUT, "contact model: damping ratio xi = %g: expected 0 <= xi < 1", p->xi);
	if (p->damping == DEM_DAMP_HYSTERESIS && !(p->unload >= 1 && isfinite(p->unload)))
		return dem_error_set(e, DEM_EINPUT, "contact model: unloading stiffness ratio k'/k = %g: "
		                     "expected a finite number >= 1 (Eq. 3.63)", p->unload);
	if (p->friction && !(p->mu >= 0 && isfinite(p->mu)))
		return dem_error_set(e, DEM_EINPUT, "contact model: friction coefficient mu = %g: expected a finite number >= 0", p->mu);
	if (p->friction && !(p->kt_ratio >= 0 && isfinite(p->kt_ratio)))
		return dem_error_set(e, DEM_EINPUT, "contact model: tangential stiffness ratio %g: expected >= 0", p->kt_ratio);
	if (p->partial != DEM_PARTIAL_AREA && p->partial != DEM_PARTIAL_VOLUME &&
	    p->partial != DEM_PARTIAL_POTENTIAL && p->partial != DEM_PARTIAL_WIDTH)
		return dem_error_set(e, DEM_EINPUT, "contact model: unknown partial contact scheme %d", p->partial);
	cm->p = *p;
	cm->m = m;
	cm->kt_ratio = p->kt_ratio > 0 ? p->kt_ratio : DEM_CONTACT_KT_RATIO;
	cm->dt_factor = 1;
	if (p->damping == DEM_DAMP_HYSTERESIS) {
		cm->shift = 1 - pow(1 / p->unload, 1 / m);           /* Eq. 3.64 */
		cm->dt_factor = pow(p->unload, 1 / m);
		/* the loop: loading area k dmax^(m+1)/(m+1) minus the unloading
		 * area k' (dmax - delta_0)^(m+1)/(m+1) = (k/k')^(1/m) times it */
		cm->loop = cm->shift / (m + 1);
	}
	if (p->sepfix != DEM_SEPFIX_ON && p->sepfix != DEM_SEPFIX_OFF)
		return dem_error_set(e, DEM_EINPUT, "contact model: unknown separation correction setting %d", p->sepfix);
	cm->sepfix = p->sepfix == DEM_SEPFIX_ON;
	int law = m == 1.0 ? LAW_1 : m == 1.5 ? LAW_15 : m == 2.0 ? LAW_2 : LAW_GEN;
	cm->kernel = kernels[law][p->damping][p->friction ? 1 : 0];

	char *b = cm->effects;
	size_t n = sizeof cm->effects;
	int w = snprintf(b, n, "law m=%g%s", m, p->law.dim == 2 ? " (2D)" : "");
	if (p->damping == DEM_DAMP_VISCOUS)
		w += snprintf(b + w, n - w, ", viscous damping xi=%g", p->xi);
	else if (p->damping == DEM_DAMP_HYSTERESIS)
		w += snprintf(b + w, n - w, ", hysteresis k'/k=%g", p->unload);
	if (p->friction)
		w += snprintf(b + w, n - w, ", friction mu=%g", p->mu);
	static const char *const partial[] = { "potential", "area", "volume", "width" };
	snprintf(b + w, n - w, ", partial %s", partial[p->partial]);
	return DEM_OK;
}

double dem_contact_secant(const dem_contact_model_t *cm, double kn, double M, double delta,
                          double vn)
{
	double u = delta > 0 ? delta : 0;
	double umax = dem_dt_umax_state(cm->m, kn, M, u, vn);
	return dem_dt_secant(cm->m, kn, umax, u) * cm->dt_factor;
}

double dem_contact_dt(const dem_contact_model_t *cm, double kn, double M, double delta,
                      double vn, double lambda)
{
	return dem_dt_step(lambda, M, dem_contact_secant(cm, kn, M, delta, vn));
}

/* ---- Separation correction (beyond the thesis; see model.h) ------------ */

void dem_sepfix_record(dem_contact_state_t *s, const double n[3], const double w[3], double Fe,
                       double h)
{
	double P[3] = { Fe * h * n[0], Fe * h * n[1], Fe * h * n[2] };
	/* F h n . (w_{n-1/2} + w_{n+1/2}) / 2: the previous step's second half
	 * and this step's first half */
	s->W += 0.5 * (v3_dot(s->P, w) + v3_dot(P, w));
	for (int i = 0; i < 3; i++)
		s->P[i] = P[i];
}

double dem_sepfix_error(const dem_contact_model_t *cm, const dem_contact_state_t *s, double kn,
                        const double w[3])
{
	double Wh = s->W + 0.5 * v3_dot(s->P, w);
	double Wx = 0;  /* U(0) - U(0) for the power law */
	if (cm->p.damping == DEM_DAMP_HYSTERESIS && s->dmax > 0)
		Wx = -cm->loop * kn * pow(s->dmax, cm->m + 1);  /* the loop of Eqs. 3.63-3.64 */
	return Wh - Wx;
}

double dem_sepfix_release(const dem_contact_model_t *cm, const dem_contact_state_t *s, double kn,
                          double meff, const double n[3], const double w[3], double J[3])
{
	J[0] = J[1] = J[2] = 0;
	double E = dem_sepfix_error(cm, s, kn, w);
	double wn = v3_dot(n, w);
	if (!(wn > 0) || E == 0 || !isfinite(E) || !(meff > 0))
		return 0;
	double w2 = wn * wn - 2 * E / meff;
	double wn1 = w2 > 0 ? sqrt(w2) : 0;  /* never reversed */
	double j = meff * (wn1 - wn);
	for (int i = 0; i < 3; i++)
		J[i] = j * n[i];
	return 0.5 * meff * (wn * wn - wn1 * wn1);
}

/* ---- The rigid sphere/rigid wall test ---------------------------------- */

int dem_contact_wall_test(const dem_contact_model_t *cm, double kn, double M, double v0,
                          double lambda, int step, dem_wall_run_t *r, dem_error_t *e)
{
	memset(r, 0, sizeof *r);
	if (!(kn > 0 && M > 0 && v0 > 0 && lambda > 0) || !isfinite(kn) || !isfinite(M) || !isfinite(v0)
	    || (step != DEM_WALL_STEP_IMPACT && step != DEM_WALL_STEP_STATE))
		return dem_error_set(e, DEM_EINPUT, "wall test: expected k_n, M, v0, lambda > 0 and a step rule "
		                     "(got %g, %g, %g, %g, %d)", kn, M, v0, lambda, step);
	const double m = cm->m;
	const double umax = dem_dt_umax(m, kn, M, v0);  /* Eq. 3.81 */
	dem_contact_state_t st;
	dem_contact_state_reset(&st);
	/* Box 3.1: u_n, v_{n-1/2} (= du/dt), dt_{n-1}; the wall's normal n = +z
	 * points to the sphere, whose velocity is -v along it */
	double u = 0, v = v0, dtp = 0, t = 0;
	const double nz[3] = { 0, 0, 1 };
	for (long k = 0;; k++) {
		double dt = step == DEM_WALL_STEP_IMPACT
		            ? lambda * 2 * sqrt(M / (dem_dt_secant(m, kn, umax, u) * cm->dt_factor))
		            : dem_contact_dt(cm, kn, M, u, v, lambda);
		double h = (dtp + dt) / 2, F = 0;
		if (u > 0) {
			dem_contact_kin_t kin = { .delta = u, .gamma = 1, .n = { 0, 0, 1 }, .vrel = { 0, 0, -v },
			                          .kn = kn, .meff = M, .dt = dt };
			dem_contact_out_t o;
			cm->kernel(cm, &kin, &st, &o);
			F = o.Fn;
			if (cm->sepfix)
				dem_sepfix_record(&st, nz, kin.vrel, o.Fe, h);
		}
		r->Fmax = fmax(r->Fmax, F);
		double a = -F / M;
		v += a * (dtp + dt) / 2;
		double un = u + v * dt;
		r->steps++;
		if (un < 0 && v < 0) {
			/* left during this step: u is linear in it */
			r->tc = t + u / -v;
			break;
		}
		u = un;
		r->umax = fmax(r->umax, u);
		t += dt;
		dtp = dt;
		if (!isfinite(u) || !isfinite(v) || k > 100000000L)
			return dem_error_set(e, DEM_ENUMERIC, "wall test: the sphere did not leave (m = %g, lambda = %g)",
			                     m, lambda);
	}
	r->ratio0 = r->ratio = -v / v0;
	if (cm->sepfix) {
		double J[3], w[3] = { 0, 0, -v };
		r->dE = dem_sepfix_release(cm, &st, kn, M, nz, w, J);
		r->ratio = (-v + J[2] / M) / v0;
	}
	return DEM_OK;
}
