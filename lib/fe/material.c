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

static const char *const law_names[] = {
	[DEM_LAW_AUTO] = "elastic", [DEM_LAW_LINEAR] = "linear",
	[DEM_LAW_TABLE] = "table", [DEM_LAW_VOCE] = "voce",
	[DEM_LAW_JC] = "johnson-cook"
};
static const char *const rate_names[] = {
	[DEM_RATE_NONE] = "none", [DEM_RATE_POWER] = "power",
	[DEM_RATE_CS] = "cowper-symonds", [DEM_RATE_JC] = "johnson-cook"
};

const char *dem_mat_law_name(const dem_mat_t *m)
{
	return law_names[m->flags & DEM_MAT_PLASTIC ? m->law : DEM_LAW_AUTO];
}

const char *dem_mat_rate_name(const dem_mat_t *m)
{
	return rate_names[m->rate_law];
}

static int bad(dem_error_t *e, const char *what, double v, const char *range)
{
	return dem_error_set(e, DEM_EINPUT, "material: %s must be %s, got %g", what, range, v);
}

/* The isotropic law's own parameters; n and the knots are set by the caller. */
static int check_law(const dem_mat_param_t *p, dem_mat_law_t law, dem_error_t *e)
{
	switch (law) {
	case DEM_LAW_VOCE:
		if (!(p->sy0 > 0) || !isfinite(p->sy0))
			return bad(e, "the Voce law's yield stress", p->sy0, "positive");
		if (!(p->voce_Q >= 0) || !isfinite(p->voce_Q))
			return bad(e, "the Voce saturation stress Q", p->voce_Q, ">= 0");
		if (!(p->voce_b > 0) || !isfinite(p->voce_b))
			return bad(e, "the Voce rate b", p->voce_b, "positive");
		break;
	case DEM_LAW_JC:
		if (!(p->jc_A > 0) || !isfinite(p->jc_A))
			return bad(e, "the Johnson-Cook A", p->jc_A, "positive");
		if (!(p->jc_B >= 0) || !isfinite(p->jc_B))
			return bad(e, "the Johnson-Cook B", p->jc_B, ">= 0");
		if (!(p->jc_n > 0 && p->jc_n <= 2))
			return bad(e, "the Johnson-Cook n", p->jc_n, "in (0, 2]");
		if (p->T != 0) {
			if (!(p->T > 0) || !isfinite(p->T))
				return bad(e, "the temperature", p->T, "positive (K)");
			if (!(p->T_ref > 0 && p->T_melt > p->T_ref) || !isfinite(p->T_melt))
				return dem_error_set(e, DEM_EINPUT, "material: the Johnson-Cook thermal term needs "
						     "0 < T_ref < T_melt, got %g and %g K", p->T_ref, p->T_melt);
			if (!(p->T < p->T_melt))
				return dem_error_set(e, DEM_EINPUT, "material: temperature %g K is not below "
						     "the melting temperature %g K", p->T, p->T_melt);
			if (!(p->mt > 0) || !isfinite(p->mt))
				return bad(e, "the Johnson-Cook thermal exponent m", p->mt, "positive");
		}
		break;
	default:
		break;
	}
	return DEM_OK;
}

static int check_rate(const dem_mat_param_t *p, dem_mat_rate_law_t rl, dem_error_t *e)
{
	switch (rl) {
	case DEM_RATE_NONE:
		return DEM_OK;
	case DEM_RATE_POWER:
		if (!(p->rate_m > 0 && p->rate_m < 1))
			return bad(e, "the rate exponent", p->rate_m, "in (0, 1)");
		break;
	case DEM_RATE_CS:
		if (!(p->cs_D > 0) || !isfinite(p->cs_D))
			return bad(e, "the Cowper-Symonds D", p->cs_D, "positive (1/s)");
		if (!(p->cs_p > 0) || !isfinite(p->cs_p))
			return bad(e, "the Cowper-Symonds p", p->cs_p, "positive");
		return DEM_OK;
	case DEM_RATE_JC:
		if (!(p->jc_C > 0) || !isfinite(p->jc_C))
			return bad(e, "the Johnson-Cook rate constant C", p->jc_C, "positive");
		break;
	default:
		return dem_error_set(e, DEM_EINPUT, "material: unknown rate law %d", (int)rl);
	}
	/* power and Johnson-Cook: the reference rate is part of the law */
	if (!(p->rate_ref > 0) || !isfinite(p->rate_ref))
		return bad(e, "the reference strain rate", p->rate_ref, "positive (1/s)");
	return DEM_OK;
}

int dem_mat_init(dem_mat_t *m, const dem_mat_param_t *p, dem_error_t *e)
{
	int rc;

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
	if (p->law < DEM_LAW_AUTO || p->law > DEM_LAW_JC)
		return dem_error_set(e, DEM_EINPUT, "material: unknown hardening law %d", (int)p->law);
	if (p->nkin < 0 || p->nkin > DEM_MAT_NKIN)
		return dem_error_set(e, DEM_EINPUT, "material: %d back-stresses, at most %d", p->nkin, DEM_MAT_NKIN);
	for (int i = 0; i < p->nkin; i++) {
		if (!(p->kin_C[i] > 0) || !isfinite(p->kin_C[i]))
			return bad(e, "a back-stress modulus C", p->kin_C[i], "positive");
		if (!(p->kin_gamma[i] >= 0) || !isfinite(p->kin_gamma[i]))
			return bad(e, "a back-stress recall gamma", p->kin_gamma[i], ">= 0");
	}

	m->E = p->E;
	m->nu = p->nu;
	m->rho = p->rho;
	m->G = p->E / (2 * (1 + p->nu));
	m->K = p->E / (3 * (1 - 2 * p->nu));
	m->lam = m->K - 2 * m->G / 3;
	m->wave = p->rho > 0 ? sqrt((m->K + 4 * m->G / 3) / p->rho) : 0;

	dem_mat_law_t law = p->law;
	if (law == DEM_LAW_AUTO)
		law = p->nhard > 0 ? DEM_LAW_TABLE : p->sy0 > 0 ? DEM_LAW_LINEAR : DEM_LAW_AUTO;
	if (law == DEM_LAW_LINEAR && !(p->sy0 > 0))
		return bad(e, "the yield stress", p->sy0, "positive");
	if (law == DEM_LAW_TABLE && p->nhard < 1)
		return dem_error_set(e, DEM_EINPUT, "material: the table law needs a hardening table");
	/* the old form of the power law: an exponent with no law named */
	dem_mat_rate_law_t rl = p->rate_law == DEM_RATE_NONE && p->rate_m > 0 ? DEM_RATE_POWER : p->rate_law;
	if (law == DEM_LAW_AUTO) {
		if (rl != DEM_RATE_NONE)
			return dem_error_set(e, DEM_EINPUT, "material: a rate law needs a yield stress");
		if (p->nkin > 0)
			return dem_error_set(e, DEM_EINPUT, "material: back-stresses need a yield stress");
		return DEM_OK;  /* elastic */
	}
	if ((rc = check_law(p, law, e)) || (rc = check_rate(p, rl, e)))
		return rc;

	int n = law == DEM_LAW_TABLE ? p->nhard : 1;
	for (int k = 0; law == DEM_LAW_TABLE && k < n; k++) {
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
	m->law = law;
	m->hep[0] = 0;
	switch (law) {
	case DEM_LAW_TABLE:
		for (int k = 0; k < n; k++) {
			m->hep[k] = p->hard_ep[k];
			m->hsy[k] = p->hard_sy[k];
		}
		for (int k = 0; k + 1 < n; k++)
			m->hsl[k] = (m->hsy[k + 1] - m->hsy[k]) / (m->hep[k + 1] - m->hep[k]);
		/* beyond the last point: the last slope (a one-point table: H) */
		m->hsl[n - 1] = n > 1 ? m->hsl[n - 2] : p->H;
		break;
	case DEM_LAW_VOCE:
		m->voce_Q = p->voce_Q;
		m->voce_b = p->voce_b;
		m->voce_H = p->H;
		m->hsy[0] = p->sy0;
		m->hsl[0] = p->voce_Q * p->voce_b + p->H;
		break;
	case DEM_LAW_JC: {
		/* a constant temperature scales the whole curve: fold the
		 * factor (1 - T*^m) into A and B (Johnson & Cook 1983) */
		double th = 1;
		if (p->T > p->T_ref)
			th = 1 - pow((p->T - p->T_ref) / (p->T_melt - p->T_ref), p->mt);
		m->jc_A = th * p->jc_A;
		m->jc_B = th * p->jc_B;
		m->jc_n = p->jc_n;
		m->hsy[0] = m->jc_A;
		m->hsl[0] = p->jc_n == 1 ? m->jc_B : 0;
		break;
	}
	default:   /* LINEAR */
		m->hsy[0] = p->sy0;
		m->hsl[0] = p->H;
		break;
	}
	if (n == 1)
		m->tratio = m->hsl[0] > 0 ? m->hsl[0] / (3 * m->G + m->hsl[0]) : 0;
	/* the floor of the static curve: its initial yield, every accepted
	 * curve being non-decreasing (H, Q, B >= 0; a falling table refused) */
	m->sy_floor = m->hsy[0];
	m->flags = DEM_MAT_PLASTIC;
	if (rl != DEM_RATE_NONE) {
		m->flags |= DEM_MAT_RATE;
		m->rate_law = rl;
		m->rate_m = p->rate_m;
		m->rate_ref = p->rate_ref;
		m->cs_D = p->cs_D;
		m->cs_ip = p->cs_p > 0 ? 1 / p->cs_p : 0;
		m->jc_C = p->jc_C;
	}
	m->nkin = p->nkin;
	for (int i = 0; i < p->nkin; i++) {
		m->kin_C[i] = p->kin_C[i];
		m->kin_gamma[i] = p->kin_gamma[i];
	}
	if (m->nkin)
		m->flags |= DEM_MAT_KIN;
	/* the closed forms of the piecewise linear curve (with the power
	 * rate law: its bracketed Newton) cover linear and table without
	 * back-stresses; everything else takes the general return */
	if (m->nkin || (law != DEM_LAW_LINEAR && law != DEM_LAW_TABLE) ||
	    (rl != DEM_RATE_NONE && rl != DEM_RATE_POWER))
		m->flags |= DEM_MAT_GENERAL;
	return DEM_OK;
}

void dem_mat_kin_as_iso(dem_mat_t *m)
{
	if (!(m->flags & DEM_MAT_KIN))
		return;
	m->flags &= ~DEM_MAT_KIN;
	m->kin_iso = 1;
	/* sum C_i/gamma_i (1 - exp(-gamma_i ep)) raises the curve (C_i > 0):
	 * the floor holds */
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

/* The rate-independent flow stress sigma_y(ep) of any law and its slope
 * *h; with dem_mat_kin_as_iso, plus the back-stresses' monotonic curve. */
static double iso_flow(const dem_mat_t *m, double ep, double *h)
{
	double sy;

	switch (m->law) {
	case DEM_LAW_VOCE: {
		double x = exp(-m->voce_b * ep);
		sy = m->hsy[0] + m->voce_Q * (1 - x) + m->voce_H * ep;
		*h = m->voce_Q * m->voce_b * x + m->voce_H;
		break;
	}
	case DEM_LAW_JC:
		if (ep > 0) {
			double b = m->jc_B * pow(ep, m->jc_n);
			sy = m->jc_A + b;
			*h = m->jc_n * b / ep;
		} else {
			sy = m->jc_A;
			*h = m->jc_n < 1 && m->jc_B > 0 ? HUGE_VAL : m->hsl[0];
		}
		break;
	default: {
		int k = segment(m, ep);
		sy = yield_on(m, k, ep);
		*h = m->hsl[k];
		break;
	}
	}
	if (m->kin_iso)
		for (int i = 0; i < m->nkin; i++) {
			double C = m->kin_C[i], g = m->kin_gamma[i];
			if (g > 0) {
				double x = exp(-g * ep);
				sy += C / g * (1 - x);
				*h += C * x;
			} else {
				sy += C * ep;
				*h += C;
			}
		}
	return sy;
}

double dem_mat_hardening_slope(const dem_mat_t *m, double ep)
{
	if (!m->nhard)
		return 0;
	double h;
	iso_flow(m, ep, &h);
	for (int i = 0; (m->flags & DEM_MAT_KIN) && i < m->nkin; i++)
		h += m->kin_C[i] * exp(-m->kin_gamma[i] * ep);
	return h;
}

/* Rate factor max(rate/rate_ref, 1)^m of the power law and its derivative
 * with respect to the rate. */
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

/* The rate factor R >= 1 of any rate law and dR/d(rate).  Below the
 * reference rate (power, Johnson-Cook) and at rate 0 (Cowper-Symonds) R is
 * 1 and its slope is taken as 0: the bracketed iterations below do not
 * need the infinite slope of (rate/D)^(1/p) at 0. */
static inline double rate_R(const dem_mat_t *m, double rate, double *dR)
{
	switch (m->rate_law) {
	case DEM_RATE_POWER:
		return rate_factor(m, rate, dR);
	case DEM_RATE_CS:
		if (rate > 0) {
			double y = pow(rate / m->cs_D, m->cs_ip);
			*dR = m->cs_ip * y / rate;
			return 1 + y;
		}
		break;
	case DEM_RATE_JC:
		if (rate > m->rate_ref) {
			*dR = m->jc_C / rate;
			return 1 + m->jc_C * log(rate / m->rate_ref);
		}
		break;
	default:
		break;
	}
	*dR = 0;
	return 1;
}

double dem_mat_flow_stress(const dem_mat_t *m, double ep, double rate)
{
	if (!m->nhard)
		return INFINITY;
	double h, sy = iso_flow(m, ep, &h);
	if (m->flags & DEM_MAT_RATE) {
		double d;
		sy *= rate_R(m, rate, &d);
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
			   double sig[6], double *ep, double *kin, double *wp)
{
	(void)dt;
	(void)ep;
	(void)kin;
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
		      double sig[6], double *ep, double *kin, double *wp)
{
	(void)dt;
	(void)kin;
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
			   double sig[6], double *ep, double *kin, double *wp)
{
	if (!(dt > 0))
		return dem_mat_update_j2(m, deps, dt, sig, ep, kin, wp);
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

/* ---- The general return ------------------------------------------------- */

/* Combined isotropic + nonlinear kinematic hardening with any isotropic
 * law and rate law.  Each back-stress follows the Armstrong-Frederick law
 * d a_i = sqrt(2/3) C_i N d ep - gamma_i a_i d ep (Chaboche 1986: several
 * such terms), integrated over the step with the flow direction N held at
 * its end value, which is exact when N does not change (radial loading,
 * uniaxial cycles):
 *
 *     a_i = th_i a_i,n + sqrt(2/3) k_i N,
 *     th_i = exp(-gamma_i x),  k_i = C_i (1 - th_i) / gamma_i  (C_i x if gamma_i = 0),
 *
 * x = Delta ep; the stress is s = s* - 2 G r x N with r = sqrt(3/2) and the
 * trial deviator s*.  Writing xi(x) = s* - sum th_i a_i,n, the relative
 * stress s - sum a_i is xi - (2 G r x + sqrt(2/3) sum k_i) N, so N =
 * xi / |xi| and the consistency condition is one scalar equation in x:
 *
 *     f(x) = r |xi(x)| - 3 G x - sum k_i(x) - sigma_y(ep + x) R(x / dt) = 0.
 *
 * f(0) > 0 (the trial state yields) and f < 0 at x = r (|s*| + sum |a_i|)
 * / (3 G), so a root is bracketed; a Newton iteration kept inside the
 * bracket (bisection when a step leaves it or the slope is not finite)
 * finds it.  Without back-stresses xi = s* and this is the radial return
 * with a nonlinear flow stress.  The back-stresses stay within their
 * saturation C_i / gamma_i, as the continuous law keeps them. */

#define SQ32 1.2247448713915890491   /* sqrt(3/2) */
#define SQ23 0.81649658092772603273  /* sqrt(2/3) */

/* Voigt vectors with tensor shears: a : b and |a| */
static inline double ddot(const double a[6], const double b[6])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] +
	       2 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

typedef struct gret {
	double x;                  /* Delta ep */
	double xn;                 /* |xi| at x */
	double n[6];               /* N */
	double th[DEM_MAT_NKIN];   /* th_i at x */
	double k[DEM_MAT_NKIN];    /* k_i at x */
	double hp;                 /* d(sigma_y R)/dx at x */
	double sy;                 /* sigma_y(ep + x), the static flow stress at x */
	double v[6];               /* d xi / dx = sum gamma_i th_i a_i,n */
	double ck;                 /* sum dk_i/dx = sum C_i th_i */
} gret_t;

/* f(x) and f'(x); fills g's fields at x */
static double gfun(const dem_mat_t *m, const double st[6], const double *a,
		   double ep, double dt, double x, gret_t *g, double *fp)
{
	const int nk = m->flags & DEM_MAT_KIN ? m->nkin : 0;
	double xi[6], ck = 0, ks = 0;

	memcpy(xi, st, sizeof xi);
	memset(g->v, 0, sizeof g->v);
	for (int i = 0; i < nk; i++) {
		double gm = m->kin_gamma[i], th = 1, k = m->kin_C[i] * x;
		if (gm > 0) {
			th = exp(-gm * x);
			k = -m->kin_C[i] * expm1(-gm * x) / gm;
		}
		g->th[i] = th;
		g->k[i] = k;
		ks += k;
		ck += m->kin_C[i] * th;
		for (int c = 0; c < 6; c++) {
			xi[c] -= th * a[6 * i + c];
			g->v[c] += gm * th * a[6 * i + c];
		}
	}
	double xn = sqrt(ddot(xi, xi));
	double h, sy = iso_flow(m, ep + x, &h), R = 1, dR = 0;
	if ((m->flags & DEM_MAT_RATE) && dt > 0)
		R = rate_R(m, x / dt, &dR);
	g->x = x;
	g->xn = xn;
	g->sy = sy;
	for (int c = 0; c < 6; c++)
		g->n[c] = xn > 0 ? xi[c] / xn : 0;
	g->hp = h * R + (dR != 0 ? sy * dR / dt : 0);
	g->ck = ck;
	*fp = SQ32 * ddot(g->n, g->v) - 3 * m->G - ck - g->hp;
	return SQ32 * xn - 3 * m->G * x - ks - sy * R;
}

/* The plastic part of the general update: sig holds the trial stress,
 * ep, a (the back-stresses) the start state.  Returns 1 and the end state
 * if the trial state yields, else 0 (sig, ep, a untouched); *g the solution
 * (for the tangent; of an elastic increment only g->sy, sigma_y(ep)). */
static int return_general(const dem_mat_t *m, double sig[6], double *ep,
			  double *a, double dt, double *wp, gret_t *g)
{
	const int nk = m->flags & DEM_MAT_KIN ? m->nkin : 0;
	double st[6], p;
	split(sig, st, &p);
	double rel[6], an = 0;
	memcpy(rel, st, sizeof rel);
	for (int i = 0; i < nk; i++) {
		for (int k = 0; k < 6; k++)
			rel[k] -= a[6 * i + k];
		an += sqrt(ddot(a + 6 * i, a + 6 * i));
	}
	double h0, sy0 = iso_flow(m, *ep, &h0);
	double q2 = 1.5 * ddot(rel, rel);
	/* R >= 1: below the static curve the increment is elastic whatever
	 * the rate */
	if (q2 <= sy0 * sy0) {
		*wp = 0;
		g->sy = sy0;
		return 0;
	}
	double f0 = sqrt(q2) - sy0;
	double lo = 0, hi = SQ32 * (sqrt(ddot(st, st)) + an) / (3 * m->G);
	double ctot = 0;
	for (int i = 0; i < nk; i++)
		ctot += m->kin_C[i];
	/* the first Newton step from 0 with the slopes at the start (the
	 * infinite slope of Johnson-Cook at ep = 0 left out) */
	double x = f0 / (3 * m->G + ctot + (h0 < HUGE_VAL ? h0 : 0)), fp = 0, f = 0;
	if (!(x < hi))
		x = 0.5 * hi;
	int done = 0;
	for (int it = 0; it < 100; it++) {
		f = gfun(m, st, a, *ep, dt, x, g, &fp);
		if (f > 0)
			lo = x;
		else
			hi = x;
		if (fabs(f) <= 1e-13 * sy0 || hi - lo <= 4e-16 * hi) {
			done = 1;
			break;
		}
		double xn = x - f / fp;
		x = isfinite(xn) && xn > lo && xn < hi ? xn : 0.5 * (lo + hi);
	}
	if (!done)
		f = gfun(m, st, a, *ep, dt, x, g, &fp);
	x = g->x;
	double c = 2 * m->G * SQ32 * x;
	double sn[6];
	for (int k = 0; k < 6; k++) {
		sn[k] = st[k] - c * g->n[k];
		sig[k] = sn[k] + (k < 3 ? p : 0);
	}
	for (int i = 0; i < nk; i++) {
		double th = g->th[i], b = SQ23 * g->k[i];
		for (int k = 0; k < 6; k++)
			a[6 * i + k] = th * a[6 * i + k] + b * g->n[k];
	}
	*ep += x;
	*wp = SQ32 * x * ddot(g->n, sn);
	return 1;
}

int dem_mat_update_general(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *kin, double *wp)
{
	gret_t g;
	elastic_add(m, deps, sig);
	return return_general(m, sig, ep, kin, dt, wp, &g);
}

/* The batched update is in the hot loop of the explicit stage: compiled
 * at -O3 (without contracting to fused multiply-adds, which would break
 * its bitwise agreement with the scalar update). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("O3")
#endif

/* ---- Batched update ------------------------------------------------------ */

/* The general return of a batch, lane by lane, after the elastic predictor:
 * the back-stresses turn with the spin (as dem_mat_jaumann) whether the
 * lane yields or not. */
static unsigned batch_general(const dem_mat_t *m, double dt, const double *restrict w,
			      double *restrict sig, double *restrict ep,
			      double *restrict kin, double *restrict wp,
			      double *restrict syc, unsigned todo)
{
	const int nh = dem_mat_nhist(m);
	unsigned mask = 0;
	for (int l = 0; l < NB; l++) {
		if (!(todo >> l & 1))
			continue;
		double st[6], a[6 * DEM_MAT_NKIN], wl;
		gret_t g;
		for (int k = 0; k < 6; k++)
			st[k] = sig[k * NB + l];
		for (int j = 0; j < nh; j++)
			a[j] = kin[j * NB + l];
		if (w && nh) {
			const double wl3[3] = { w[l], w[NB + l], w[2 * NB + l] };
			for (int i = 0; i < nh / 6; i++)
				dem_mat_jaumann(a + 6 * i, wl3, dt);
		}
		if (return_general(m, st, &ep[l], a, dt, &wl, &g)) {
			mask |= 1u << l;
			for (int k = 0; k < 6; k++)
				sig[k * NB + l] = st[k];
			wp[l] = wl;
		}
		for (int j = 0; j < nh; j++)
			kin[j * NB + l] = a[j];
		if (syc)   /* the static flow stress at the lane's end state */
			syc[l] = g.sy;
	}
	return mask;
}


/* One lane per material point over a vector of NB doubles (simd.h). */

SIMD_CLONES
unsigned dem_mat_update_batch(const dem_mat_t *m, double dt,
			      const double *restrict d, const double *restrict w,
			      double *restrict sig, double *restrict ep,
			      double *restrict kin, double *restrict wp,
			      double *restrict syc)
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
	/* the back-stresses turn in every lane, yielding or not */
	if (m->flags & DEM_MAT_KIN)
		return batch_general(m, dt, w, sig, ep, kin, wp, NULL, (1u << NB) - 1);
	/* yield check against the static curve (the rate factor is >= 1) */
	vec p = (s[0] + s[1] + s[2]) / 3;
	vec a[6] = { s[0] - p, s[1] - p, s[2] - p, s[3], s[4], s[5] };
	vec q2 = 1.5 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) +
		 3 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]);
	if (m->flags & DEM_MAT_GENERAL) {
		/* without back-stresses a lane below its static flow stress (syc,
		 * or the curve's floor when there is no record) is elastic: the
		 * general return (which would find it so) is left to the others.
		 * The bound is lowered by a relative 1e-12, far above the
		 * rounding by which this q2 and the return's differ, so that the
		 * result is the same bit for bit. */
		unsigned todo = 0;
		for (int l = 0; l < NB; l++) {
			double c = syc ? syc[l] : m->sy_floor;
			if (!(q2[l] <= c * c * (1 - 1e-12)))
				todo |= 1u << l;
		}
		return todo ? batch_general(m, dt, w, sig, ep, kin, wp, syc, todo) : 0;
	}
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
	if (m->flags & DEM_MAT_GENERAL)
		return dem_mat_update_general;
	if (m->flags & DEM_MAT_RATE)
		return dem_mat_update_j2_rate;
	if (m->flags & DEM_MAT_PLASTIC)
		return dem_mat_update_j2;
	return dem_mat_update_elastic;
}

int dem_mat_update(const dem_mat_t *m, const double deps[6], double dt,
		   double sig[6], double *ep, double *kin, double *wp)
{
	return dem_mat_update_select(m)(m, deps, dt, sig, ep, kin, wp);
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

/* The algorithmic tangent of the general return (see return_general).
 * Differentiating f = 0 and the end state with respect to the strain,
 * with c = 2 G r x / |xi| and A = 3 G + sum C_i th_i + H' - r N : v
 * (H' = d(sigma_y R)/dx, v = d xi/dx):
 *
 *   D = K 1(x)1 + 2G (1 - c) I_dev + (2G c - 6 G^2 / A) N(x)N
 *       - (2 G c r / A) (v - (N : v) N)(x)N,
 *
 * which without back-stresses (v = 0) is the tangent of Simo & Taylor
 * (1985); the last term, from the recall of the back-stresses, is not
 * symmetric. */
static void tangent_general(const dem_mat_t *m, const gret_t *g, double D[36])
{
	double G = m->G, r = SQ32;
	double c = g->xn > 0 ? 2 * G * r * g->x / g->xn : 0;
	double nv = ddot(g->n, g->v);
	double A = 3 * G + g->ck + g->hp - r * nv;
	double b = 2 * G * c - 6 * G * G / A, t = 2 * G * c * r / A;
	double vp[6];
	for (int i = 0; i < 6; i++)
		vp[i] = g->v[i] - nv * g->n[i];
	for (int i = 0; i < 6; i++)
		for (int j = 0; j < 6; j++) {
			double idev;
			if (i < 3 && j < 3)
				idev = (i == j ? 1.0 : 0.0) - 1.0 / 3;
			else
				idev = i == j ? 0.5 : 0.0;
			D[6 * i + j] = (i < 3 && j < 3 ? m->K : 0) + 2 * G * (1 - c) * idev +
				       b * g->n[i] * g->n[j] - t * vp[i] * g->n[j];
		}
}

int dem_mat_update_tangent(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *kin, double *wp, double D[36])
{
	dem_mat_elastic_stiffness(m, D);
	elastic_add(m, deps, sig);
	if (!(m->flags & DEM_MAT_PLASTIC)) {
		*wp = 0;
		return 0;
	}
	if (m->flags & DEM_MAT_GENERAL) {
		gret_t g;
		if (!return_general(m, sig, ep, kin, dt, wp, &g))
			return 0;
		tangent_general(m, &g, D);
		return 1;
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
	double qn = q - 3 * m->G * dg;
	scale_back(sig, s, p, qn / q);
	*ep += dg;
	*wp = dg * qn;
	/* the tangent of Simo & Taylor (1985): tangent_general's without
	 * back-stresses, the flow direction that of the trial deviator and
	 * H' the slope of the flow stress along the return (hardening, and
	 * rate when present) */
	gret_t g = { .x = dg, .xn = sqrt(2 * q2 / 3), .hp = hs };
	for (int i = 0; i < 6; i++)
		g.n[i] = s[i] / g.xn;
	tangent_general(m, &g, D);
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
		     double eps[6], double sig[6], double *ep, double *kin)
{
	/* Unknown lateral strain increments; start from the elastic guess. */
	double d[6] = { deps11, -m->nu * deps11, -m->nu * deps11, 0, 0, 0 };
	double s1[6], ep1 = *ep, wp, D[36], a1[6 * DEM_MAT_NKIN];
	const int nh = dem_mat_nhist(m);
	for (int it = 0; it < 50; it++) {
		memcpy(s1, sig, sizeof s1);
		ep1 = *ep;
		if (nh)
			memcpy(a1, kin, (size_t)nh * sizeof *a1);
		dem_mat_update_tangent(m, d, dt, s1, &ep1, nh ? a1 : NULL, &wp, D);
		/* round-off of the lateral stresses: of the axial one, and
		 * of the back-stresses they are computed with */
		double scale = fabs(s1[0]) + m->E * 1e-12;
		for (int j = 0; j < nh; j++)
			scale += fabs(a1[j]);
		if (fabs(s1[1]) <= 1e-13 * scale && fabs(s1[2]) <= 1e-13 * scale) {
			for (int i = 0; i < 6; i++)
				eps[i] += d[i];
			memcpy(sig, s1, sizeof s1);
			*ep = ep1;
			if (nh)
				memcpy(kin, a1, (size_t)nh * sizeof *a1);
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
