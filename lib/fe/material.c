/* material.c - isotropic elasticity and J2 plasticity (see material.h).
 *
 * The return mapping is the radial return of Wilkins (1964) in the form of
 * Simo & Taylor (1985): the trial stress is scaled back to the yield surface
 * along the deviatoric direction, which is exact for J2 with isotropic
 * hardening.  The scalar consistency equation
 *
 *     q_trial - 3 G dg = sigma_f(ep_n + dg, dg/dt)
 *
 * is solved exactly: segment by segment for the piecewise linear curve (the
 * solution is linear on each segment), by a safeguarded Newton iteration
 * when the flow stress depends on the rate.
 *
 * Rate dependence.  The thesis gives for each alloy of Table 7.2 a "strain
 * rate exponent" m (Ch. 7.6) measured in compression at constant strain
 * rates, i.e. sigma ~ rate^m, without a reference rate.  We use
 *     sigma_f(ep, rate) = sigma_y(ep) * max(rate / rate_ref, 1)^m
 * with rate the effective plastic strain rate dg/dt of the increment
 * (equal to the imposed strain rate in a steady uniaxial test, which is
 * how m was measured), and rate_ref = 1/s unless the scene says otherwise:
 * the quasi-static curve is taken as the curve at 1/s and the flow stress
 * never drops below it.  Solving for the rate implicitly (rather than using
 * the total strain rate of the step) keeps the update consistent, and the
 * max(., 1) keeps the law free of the infinite slope of rate^m at rate 0.
 */
#include "fe/material.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fe/simd.h"

int dem_mat_init(dem_mat_t *m, const dem_mat_param_t *p, dem_error_t *e)
{
	memset(m, 0, sizeof *m);
	if (!(p->E > 0) || !isfinite(p->E))
		return dem_error_set(e, DEM_EINPUT, "material: Young's modulus must be positive, got %g", p->E);
	if (!(p->nu > -1 && p->nu < 0.5))
		return dem_error_set(e, DEM_EINPUT, "material: Poisson's ratio must be in (-1, 0.5), got %g", p->nu);
	if (!(p->rho >= 0) || !isfinite(p->rho))
		return dem_error_set(e, DEM_EINPUT, "material: density must be >= 0, got %g", p->rho);
	if (!(p->H >= 0) || !isfinite(p->H))
		return dem_error_set(e, DEM_EINPUT, "material: hardening modulus must be >= 0, got %g", p->H);
	if (!(p->sy0 >= 0) || !isfinite(p->sy0))
		return dem_error_set(e, DEM_EINPUT, "material: yield stress must be >= 0, got %g", p->sy0);
	if (p->nhard < 0 || (p->nhard > 0 && (!p->hard_ep || !p->hard_sy)))
		return dem_error_set(e, DEM_EINPUT, "material: hardening table missing");
	if (!(p->rate_m >= 0 && p->rate_m < 1))
		return dem_error_set(e, DEM_EINPUT, "material: rate exponent must be in [0, 1), got %g", p->rate_m);
	if (!(p->rate_ref >= 0) || !isfinite(p->rate_ref))
		return dem_error_set(e, DEM_EINPUT, "material: reference strain rate must be positive, got %g", p->rate_ref);

	m->E = p->E;
	m->nu = p->nu;
	m->rho = p->rho;
	m->G = p->E / (2 * (1 + p->nu));
	m->K = p->E / (3 * (1 - 2 * p->nu));
	m->lam = m->K - 2 * m->G / 3;
	m->wave = p->rho > 0 ? sqrt((m->K + 4 * m->G / 3) / p->rho) : 0;

	int n = p->nhard > 0 ? p->nhard : (p->sy0 > 0 ? 1 : 0);
	if (n == 0) {
		if (p->rate_m > 0)
			return dem_error_set(e, DEM_EINPUT, "material: a rate exponent needs a yield stress");
		return DEM_OK;  /* elastic */
	}
	for (int k = 0; p->nhard > 0 && k < n; k++) {
		if (!isfinite(p->hard_ep[k]) || !isfinite(p->hard_sy[k]))
			return dem_error_set(e, DEM_EINPUT, "material: hardening table point %d is not finite", k + 1);
		if (k == 0 && p->hard_ep[0] != 0)
			return dem_error_set(e, DEM_EINPUT, "material: hardening table must start at plastic strain 0, got %g", p->hard_ep[0]);
		if (k == 0 && !(p->hard_sy[0] > 0))
			return dem_error_set(e, DEM_EINPUT, "material: hardening table: initial flow stress must be positive, got %g", p->hard_sy[0]);
		if (k > 0 && !(p->hard_ep[k] > p->hard_ep[k - 1]))
			return dem_error_set(e, DEM_EINPUT, "material: hardening table point %d: plastic strains must increase", k + 1);
		if (k > 0 && !(p->hard_sy[k] >= p->hard_sy[k - 1]))
			return dem_error_set(e, DEM_EINPUT, "material: hardening table point %d: flow stress must not decrease (softening is not supported)", k + 1);
	}
	m->hep = malloc(3 * (size_t)n * sizeof *m->hep);
	if (!m->hep)
		return dem_error_nomem(e, "hardening table");
	m->hsy = m->hep + n;
	m->hsl = m->hsy + n;
	m->nhard = n;
	if (p->nhard > 0) {
		for (int k = 0; k < n; k++) {
			m->hep[k] = p->hard_ep[k];
			m->hsy[k] = p->hard_sy[k];
		}
		for (int k = 0; k + 1 < n; k++)
			m->hsl[k] = (m->hsy[k + 1] - m->hsy[k]) / (m->hep[k + 1] - m->hep[k]);
		/* beyond the last point: the last slope (a one-point table: H) */
		m->hsl[n - 1] = n > 1 ? m->hsl[n - 2] : p->H;
	} else {
		m->hep[0] = 0;
		m->hsy[0] = p->sy0;
		m->hsl[0] = p->H;
	}
	if (n == 1)
		m->tratio = m->hsl[0] > 0 ? m->hsl[0] / (3 * m->G + m->hsl[0]) : 0;
	m->flags = DEM_MAT_PLASTIC;
	if (p->rate_m > 0) {
		m->flags |= DEM_MAT_RATE;
		m->rate_m = p->rate_m;
		m->rate_ref = p->rate_ref > 0 ? p->rate_ref : 1.0;
	}
	return DEM_OK;
}

void dem_mat_free(dem_mat_t *m)
{
	free(m->hep);
	m->hep = m->hsy = m->hsl = NULL;
	m->nhard = 0;
}

/* The segment k of the hardening curve that holds ep: hep[k] <= ep <
 * hep[k+1], or the last one.  Tables are short (Table 7.1 has 8 points), so
 * a forward scan beats a bisection. */
static inline int segment(const dem_mat_t *m, double ep)
{
	int k = 0;
	while (k + 1 < m->nhard && ep >= m->hep[k + 1])
		k++;
	return k;
}

static inline double yield_on(const dem_mat_t *m, int k, double ep)
{
	return m->hsy[k] + m->hsl[k] * (ep - m->hep[k]);
}

double dem_mat_hardening_slope(const dem_mat_t *m, double ep)
{
	return m->nhard ? m->hsl[segment(m, ep)] : 0;
}

/* Rate factor max(rate/rate_ref, 1)^m and its derivative with respect to
 * the rate. */
static inline double rate_factor(const dem_mat_t *m, double rate, double *dfac)
{
	double r = rate / m->rate_ref;
	if (!(r > 1)) {
		*dfac = 0;
		return 1;
	}
	double f = exp(m->rate_m * log(r));
	*dfac = m->rate_m * f / rate;
	return f;
}

double dem_mat_flow_stress(const dem_mat_t *m, double ep, double rate)
{
	if (!m->nhard)
		return INFINITY;
	double sy = yield_on(m, segment(m, ep), ep);
	if (m->flags & DEM_MAT_RATE) {
		double d;
		sy *= rate_factor(m, rate, &d);
	}
	return sy;
}

double dem_mat_mises(const double s[6])
{
	double p = (s[0] + s[1] + s[2]) / 3;
	double a = s[0] - p, b = s[1] - p, c = s[2] - p;
	return sqrt(1.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

/* Trial stress of an elastic increment: sig += D deps. */
static inline void elastic_add(const dem_mat_t *m, const double d[6], double s[6])
{
	double lev = m->lam * (d[0] + d[1] + d[2]);
	double g2 = 2 * m->G;
	s[0] += lev + g2 * d[0];
	s[1] += lev + g2 * d[1];
	s[2] += lev + g2 * d[2];
	s[3] += m->G * d[3];
	s[4] += m->G * d[4];
	s[5] += m->G * d[5];
}

int dem_mat_update_elastic(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *wp)
{
	(void)dt;
	(void)ep;
	elastic_add(m, deps, sig);
	*wp = 0;
	return 0;
}

/* Rate-independent return: the plastic multiplier dg (increment of ep)
 * with q - 3 G dg = sigma_y(ep + dg), found on the segment where it lies.
 * Each segment gives the closed form of linear hardening; when the end
 * point falls past the segment's end, the next segment is tried, so the
 * curve is followed exactly over any number of knots.  *hslope receives
 * the slope of the final segment (for the tangent). */
static double return_map(const dem_mat_t *m, double ep, double q, double *hslope)
{
	double G3 = 3 * m->G;
	int k = segment(m, ep);
	for (;;) {
		double dg = (q - yield_on(m, k, ep)) / (G3 + m->hsl[k]);
		if (k + 1 >= m->nhard || ep + dg < m->hep[k + 1]) {
			*hslope = m->hsl[k];
			return dg;
		}
		k++;
	}
}

/* Rate-dependent return: g(dg) = q - 3 G dg - sigma_y(ep + dg) R(dg/dt) = 0.
 * g is continuous and strictly decreasing (slope <= -3G), g(0) > 0, and at
 * the rate-independent solution dg0 it is <= 0 because R >= 1; so the root
 * is bracketed in (0, dg0] and a Newton iteration kept inside the bracket
 * (bisection when a step leaves it) converges.  *hslope receives
 * -g'(dg) - 3 G, the slope of the flow stress along the return. */
static double return_map_rate(const dem_mat_t *m, double ep, double q, double dt,
			      double *hslope)
{
	double G3 = 3 * m->G;
	double h0;
	double hi = return_map(m, ep, q, &h0);
	double dR;
	double R = rate_factor(m, hi / dt, &dR);
	if (R == 1) {           /* slower than rate_ref: the static curve */
		*hslope = h0;
		return hi;
	}
	double lo = 0, x = hi, hs = h0;
	for (int it = 0; it < 100; it++) {
		int k = segment(m, ep + x);
		double sy = yield_on(m, k, ep + x);
		R = rate_factor(m, x / dt, &dR);
		double g = q - G3 * x - sy * R;
		hs = m->hsl[k] * R + sy * dR / dt;
		if (g > 0)
			lo = x;
		else
			hi = x;
		if (fabs(g) <= 1e-13 * q || hi - lo <= 1e-15 * hi)
			break;
		double xn = x + g / (G3 + hs);
		x = (xn > lo && xn < hi) ? xn : 0.5 * (lo + hi);
	}
	*hslope = hs;
	return x;
}

/* Deviatoric split of a trial stress: s[0..5], pressure p, and 3/2 s:s. */
static inline double split(const double sig[6], double s[6], double *p)
{
	*p = (sig[0] + sig[1] + sig[2]) / 3;
	s[0] = sig[0] - *p;
	s[1] = sig[1] - *p;
	s[2] = sig[2] - *p;
	s[3] = sig[3];
	s[4] = sig[4];
	s[5] = sig[5];
	return 1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) +
	       3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
}

/* Radial return to the flow stress: sig = p 1 + beta s with
 * beta = 1 - 3 G dg / q (Simo & Taylor 1985). */
static inline void scale_back(double sig[6], const double s[6], double p, double beta)
{
	sig[0] = p + beta * s[0];
	sig[1] = p + beta * s[1];
	sig[2] = p + beta * s[2];
	sig[3] = beta * s[3];
	sig[4] = beta * s[4];
	sig[5] = beta * s[5];
}

int dem_mat_update_j2(const dem_mat_t *m, const double deps[6], double dt,
		      double sig[6], double *ep, double *wp)
{
	(void)dt;
	elastic_add(m, deps, sig);
	double s[6], p;
	double q2 = split(sig, s, &p);
	int k = segment(m, *ep);
	double sy = yield_on(m, k, *ep);
	if (q2 <= sy * sy) {    /* elastic: no square root needed */
		*wp = 0;
		return 0;
	}
	double q = sqrt(q2), hs;
	double dg = return_map(m, *ep, q, &hs);
	double qn = q - 3 * m->G * dg;
	scale_back(sig, s, p, qn / q);
	*ep += dg;
	*wp = dg * qn;
	return 1;
}

int dem_mat_update_j2_rate(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *wp)
{
	if (!(dt > 0))
		return dem_mat_update_j2(m, deps, dt, sig, ep, wp);
	elastic_add(m, deps, sig);
	double s[6], p;
	double q2 = split(sig, s, &p);
	/* R >= 1, so the static curve is the lowest the flow stress can be:
	 * below it the increment is elastic whatever the rate */
	double sy = yield_on(m, segment(m, *ep), *ep);
	if (q2 <= sy * sy) {
		*wp = 0;
		return 0;
	}
	double q = sqrt(q2), hs;
	double dg = return_map_rate(m, *ep, q, dt, &hs);
	double qn = q - 3 * m->G * dg;
	scale_back(sig, s, p, qn / q);
	*ep += dg;
	*wp = dg * qn;
	return 1;
}

/* The batched update is in the hot loop of the explicit stage: compiled
 * at -O3 (without contracting to fused multiply-adds, which would break
 * its bitwise agreement with the scalar update). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("O3")
#endif

/* ---- Batched update ------------------------------------------------------ */

/* One lane per material point over a vector of NB doubles (simd.h). */

SIMD_CLONES
unsigned dem_mat_update_batch(const dem_mat_t *m, double dt,
			      const double *restrict d, const double *restrict w,
			      double *restrict sig, double *restrict ep,
			      double *restrict wp)
{
	vec s[6], e[6];
	for (int k = 0; k < 6; k++) {
		VLOAD(s[k], sig + k * NB);
		VLOAD(e[k], d + k * NB);
		e[k] *= dt;
	}
	if (w) {   /* Jaumann rotation, as dem_mat_jaumann */
		vec a, b, c;
		VLOAD(a, w);
		VLOAD(b, w + NB);
		VLOAD(c, w + 2 * NB);
		a *= dt;
		b *= dt;
		c *= dt;
		vec sxx = s[0], syy = s[1], szz = s[2], sxy = s[3], syz = s[4], szx = s[5];
		s[0] += 2 * (a * sxy - c * szx);
		s[1] += 2 * (b * syz - a * sxy);
		s[2] += 2 * (c * szx - b * syz);
		s[3] += a * (syy - sxx) - c * syz + b * szx;
		s[4] += b * (szz - syy) - a * szx + c * sxy;
		s[5] += c * (sxx - szz) - b * sxy + a * syz;
	}
	/* elastic predictor */
	vec lev = m->lam * (e[0] + e[1] + e[2]);
	double g2 = 2 * m->G;
	s[0] += lev + g2 * e[0];
	s[1] += lev + g2 * e[1];
	s[2] += lev + g2 * e[2];
	s[3] += m->G * e[3];
	s[4] += m->G * e[4];
	s[5] += m->G * e[5];
	for (int k = 0; k < 6; k++)
		VSTORE(sig + k * NB, s[k]);
	const vec zero = { 0 };
	VSTORE(wp, zero);
	if (!(m->flags & DEM_MAT_PLASTIC))
		return 0;
	/* yield check against the static curve (the rate factor is >= 1) */
	vec p = (s[0] + s[1] + s[2]) / 3;
	vec a[6] = { s[0] - p, s[1] - p, s[2] - p, s[3], s[4], s[5] };
	vec q2 = 1.5 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) +
		 3 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]);
	vec sy, hs, e0;
	VLOAD(e0, ep);
	double enext[NB];
	if (m->nhard == 1) {
		sy = m->hsy[0] + m->hsl[0] * e0;
		hs = zero + m->hsl[0];
	} else {
		double t[NB], h[NB];
		for (int l = 0; l < NB; l++) {
			int k = segment(m, ep[l]);
			t[l] = yield_on(m, k, ep[l]);
			h[l] = m->hsl[k];
			enext[l] = k + 1 < m->nhard ? m->hep[k + 1] : INFINITY;
		}
		VLOAD(sy, t);
		VLOAD(hs, h);
	}
	lvec yield = q2 > sy * sy;
	unsigned mask = 0;
	for (int l = 0; l < NB; l++)
		if (yield[l])
			mask |= 1u << l;
	if (!mask)
		return 0;
	unsigned mask_todo = mask;
	if (!(m->flags & DEM_MAT_RATE)) {
		/* the closed-form return of the current hardening segment across
		 * the lanes, the same operations as dem_mat_update_j2; a lane
		 * whose plastic strain runs past the segment's end is redone
		 * below (rare: the step crosses a table point) */
		double qt[NB];
		for (int l = 0; l < NB; l++)
			qt[l] = yield[l] ? sqrt(q2[l]) : 1;
		vec q, G3 = zero + 3 * m->G;
		VLOAD(q, qt);
		vec dg = (q - sy) / (G3 + hs);
		dg = (vec)(yield & (lvec)dg);
		unsigned redo = 0;
		if (m->nhard > 1)
			for (int l = 0; l < NB; l++)
				if (yield[l] && !(ep[l] + dg[l] < enext[l]))
					redo |= 1u << l;
		vec qn = q - G3 * dg, beta = qn / q;
		for (int k = 0; k < 6; k++) {
			vec sn = k < 3 ? p + beta * a[k] : beta * a[k];
			vec sk = (vec)((yield & (lvec)sn) | (~yield & (lvec)s[k]));
			VSTORE(sig + k * NB, sk);
		}
		vec w0 = dg * qn;
		e0 += dg;
		/* lanes to redo get back their trial state */
		for (int l = 0; l < NB; l++)
			if (redo >> l & 1) {
				e0[l] = ep[l];
				w0[l] = 0;
				for (int k = 0; k < 6; k++)
					sig[k * NB + l] = s[k][l];
			}
		VSTORE(ep, e0);
		VSTORE(wp, w0);
		if (!redo)
			return mask;
		mask_todo = redo;
	}
	/* the return mapping, lane by lane, only where needed */
	for (int l = 0; mask_todo >> l; l++) {
		if (!(mask_todo >> l & 1))
			continue;
		double st[6], dev[6], pr;
		for (int k = 0; k < 6; k++)
			st[k] = sig[k * NB + l];
		double qq = sqrt(split(st, dev, &pr)), hl;
		double dg = (m->flags & DEM_MAT_RATE) && dt > 0
			? return_map_rate(m, ep[l], qq, dt, &hl)
			: return_map(m, ep[l], qq, &hl);
		double qn = qq - 3 * m->G * dg;
		scale_back(st, dev, pr, qn / qq);
		for (int k = 0; k < 6; k++)
			sig[k * NB + l] = st[k];
		ep[l] += dg;
		wp[l] = dg * qn;
	}
	return mask;
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
#endif

dem_mat_update_fn dem_mat_update_select(const dem_mat_t *m)
{
	if (m->flags & DEM_MAT_RATE)
		return dem_mat_update_j2_rate;
	if (m->flags & DEM_MAT_PLASTIC)
		return dem_mat_update_j2;
	return dem_mat_update_elastic;
}

int dem_mat_update(const dem_mat_t *m, const double deps[6], double dt,
		   double sig[6], double *ep, double *wp)
{
	return dem_mat_update_select(m)(m, deps, dt, sig, ep, wp);
}

void dem_mat_elastic_stiffness(const dem_mat_t *m, double D[36])
{
	memset(D, 0, 36 * sizeof *D);
	double a = m->lam + 2 * m->G;
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++)
			D[6 * i + j] = i == j ? a : m->lam;
		D[6 * (i + 3) + i + 3] = m->G;
	}
}

int dem_mat_update_tangent(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *wp, double D[36])
{
	dem_mat_elastic_stiffness(m, D);
	elastic_add(m, deps, sig);
	if (!(m->flags & DEM_MAT_PLASTIC)) {
		*wp = 0;
		return 0;
	}
	double s[6], p;
	double q2 = split(sig, s, &p);
	double sy = yield_on(m, segment(m, *ep), *ep);
	if (q2 <= sy * sy) {
		*wp = 0;
		return 0;
	}
	double q = sqrt(q2), hs;
	double dg = (m->flags & DEM_MAT_RATE) && dt > 0
		? return_map_rate(m, *ep, q, dt, &hs)
		: return_map(m, *ep, q, &hs);
	double G = m->G, G3 = 3 * G;
	double qn = q - G3 * dg;
	scale_back(sig, s, p, qn / q);
	*ep += dg;
	*wp = dg * qn;

	/* Simo & Taylor (1985), consistent tangent of the radial return:
	 *   D = K 1(x)1 + 2G beta I_dev - 2G gbar n(x)n,
	 *   beta = 1 - 3G dg/q_trial,  gbar = 3G/(3G + H') - 3G dg/q_trial,
	 * n = s/|s| the unit flow direction, H' the slope of the flow stress
	 * along the return (hardening, and rate when present).  In Voigt form
	 * with engineering shears I_dev has 1/2 on the shear diagonal and the
	 * n(x)n block is n_i n_j with n in tensor components. */
	double beta = 1 - G3 * dg / q;
	double gbar = G3 / (G3 + hs) - G3 * dg / q;
	double snorm = sqrt(2 * q2 / 3);   /* |s| */
	double n[6];
	for (int i = 0; i < 6; i++)
		n[i] = s[i] / snorm;
	double K = m->K;
	for (int i = 0; i < 6; i++)
		for (int j = 0; j < 6; j++) {
			double idev;
			if (i < 3 && j < 3)
				idev = (i == j ? 1.0 : 0.0) - 1.0 / 3;
			else
				idev = i == j ? 0.5 : 0.0;
			D[6 * i + j] = (i < 3 && j < 3 ? K : 0) + 2 * G * beta * idev -
				       2 * G * gbar * n[i] * n[j];
		}
	return 1;
}

void dem_mat_jaumann(double sig[6], const double w[3], double dt)
{
	/* W = [[0, w0, -w2], [-w0, 0, w1], [w2, -w1, 0]];
	 * sig += (W sig + (W sig)^T) dt, which equals (W sig - sig W) dt */
	double sxx = sig[0], syy = sig[1], szz = sig[2];
	double sxy = sig[3], syz = sig[4], szx = sig[5];
	double a = w[0] * dt, b = w[1] * dt, c = w[2] * dt;
	sig[0] += 2 * (a * sxy - c * szx);
	sig[1] += 2 * (b * syz - a * sxy);
	sig[2] += 2 * (c * szx - b * syz);
	sig[3] += a * (syy - sxx) - c * syz + b * szx;
	sig[4] += b * (szz - syy) - a * szx + c * sxy;
	sig[5] += c * (sxx - szz) - b * sxy + a * syz;
}

/* Solve the 2x2 system A x = r. */
static int solve2(const double A[4], const double r[2], double x[2])
{
	double det = A[0] * A[3] - A[1] * A[2];
	if (!(fabs(det) > 0))
		return -1;
	x[0] = (A[3] * r[0] - A[1] * r[1]) / det;
	x[1] = (A[0] * r[1] - A[2] * r[0]) / det;
	return 0;
}

int dem_mat_uniaxial(const dem_mat_t *m, double deps11, double dt,
		     double eps[6], double sig[6], double *ep)
{
	/* Unknown lateral strain increments; start from the elastic guess. */
	double d[6] = { deps11, -m->nu * deps11, -m->nu * deps11, 0, 0, 0 };
	double s1[6], ep1 = *ep, wp, D[36];
	for (int it = 0; it < 50; it++) {
		memcpy(s1, sig, sizeof s1);
		ep1 = *ep;
		dem_mat_update_tangent(m, d, dt, s1, &ep1, &wp, D);
		double scale = fabs(s1[0]) + m->E * 1e-12;
		if (fabs(s1[1]) <= 1e-13 * scale && fabs(s1[2]) <= 1e-13 * scale) {
			for (int i = 0; i < 6; i++)
				eps[i] += d[i];
			memcpy(sig, s1, sizeof s1);
			*ep = ep1;
			return DEM_OK;
		}
		/* lateral block of the tangent: d(sig_yy, sig_zz)/d(eps_yy, eps_zz) */
		double A[4] = { D[7], D[8], D[13], D[14] };
		double r[2] = { -s1[1], -s1[2] }, x[2];
		if (solve2(A, r, x))
			return DEM_ENUMERIC;
		d[1] += x[0];
		d[2] += x[1];
	}
	return DEM_ENUMERIC;
}
