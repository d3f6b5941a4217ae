/* law.c - normal contact laws and the contact time step (Han 2004, Ch. 3.3,
 * 3.5, 3.7).  See law.h. */
#include "contact/law.h"

#include <math.h>
#include <stdio.h>

#include "core/consts.h"

/* delta^m without pow() for the three exponents of Table 3.1 */
static double powm(double m, double x)
{
	if (m == 1.0)
		return x;
	if (m == 1.5)
		return x * sqrt(x);
	if (m == 2.0)
		return x * x;
	return pow(x, m);
}

int dem_law_init(dem_law_t *law, double alpha, double E, double m, dem_error_t *e)
{
	return dem_law_init_dim(law, alpha, E, m, 3, e);
}

int dem_law_init_dim(dem_law_t *law, double alpha, double E, double m, int dim, dem_error_t *e)
{
	if (dim != 2 && dim != 3)
		return dem_error_set(e, DEM_EINPUT, "contact law: dimension %d: expected 2 or 3", dim);
	if (!(alpha > 0) || !isfinite(alpha))
		return dem_error_set(e, DEM_EINPUT, "contact law: penalty alpha = %g: expected a finite number > 0 (Eq. 3.45)", alpha);
	if (!(E > 0) || !isfinite(E))
		return dem_error_set(e, DEM_EINPUT, "contact law: Young's modulus E = %g: expected a finite number > 0", E);
	if (!(m >= 1 && m <= 4))
		return dem_error_set(e, DEM_EINPUT, "contact law: exponent m = %g: expected 1 <= m <= 4 (1 linear, 1.5 Hertz, 2 Winkler)", m);
	law->m = m;
	law->coef = alpha * E;
	law->dim = dim;
	return DEM_OK;
}

double dem_law_ghertz2d_beta(double nu)
{
	double r = DEM_PI * (1 - 2 * nu) / (2 * (1 - nu));  /* k4/k3, rigid disk (G2 infinite) */
	return DEM_PI / 4 * (1 + r * r) / (2 * (1 - nu * nu));  /* Eq. 3.31 */
}

int dem_law_ghertz2d(dem_law_t *law, double E, double nu, dem_error_t *e)
{
	if (!(nu > -1 && nu <= 0.5))
		return dem_error_set(e, DEM_EINPUT, "generalised Hertz 2D law: Poisson's ratio nu = %g: "
		                     "expected -1 < nu <= 0.5", nu);
	return dem_law_init_dim(law, 2 * dem_law_ghertz2d_beta(nu), E, 1, 2, e);  /* Eq. 3.43 */
}

double dem_law_winkler2d_alpha(double kw, double E, double R)
{
	return 4 * sqrt(2.0) * kw * R / (3 * E);  /* Eq. 3.39 in the form of Eq. 3.45 */
}

double dem_law_alpha_thesis2d(double alpha_t, double m, double R)
{
	return alpha_t * pow(R / 1e-3, 2 * m - 2);
}

int dem_law_hertz(dem_law_t *law, double E, double nu, dem_error_t *e)
{
	if (!(E > 0) || !isfinite(E))
		return dem_error_set(e, DEM_EINPUT, "Hertz law: Young's modulus E = %g: expected a finite number > 0", E);
	if (!(nu > -1 && nu < 0.5))
		return dem_error_set(e, DEM_EINPUT, "Hertz law: Poisson's ratio nu = %g: expected -1 < nu < 0.5", nu);
	law->m = 1.5;
	law->coef = 4.0 / 3.0 * E / (1 - nu * nu);  /* Eq. 3.29 */
	law->dim = 3;
	return DEM_OK;
}

double dem_law_estar(double E1, double nu1, double E2, double nu2)
{
	double c = (1 - nu1 * nu1) / E1;
	if (isfinite(E2))
		c += (1 - nu2 * nu2) / E2;
	return 1 / c;
}

double dem_law_reff(double R1, double R2)
{
	return R1 * R2 / (R1 + R2);
}

double dem_law_kn(const dem_law_t *law, double R)
{
	double m = law->m;
	if (law->dim == 2) {  /* R^(1-m): a force per unit thickness */
		if (m == 1.0)
			return law->coef;
		if (m == 1.5)
			return law->coef / sqrt(R);
		if (m == 2.0)
			return law->coef / R;
		return law->coef * pow(R, 1 - m);
	}
	if (m == 1.0)
		return law->coef * R;
	if (m == 1.5)
		return law->coef * sqrt(R);
	if (m == 2.0)
		return law->coef;
	return law->coef * pow(R, 2 - m);
}

double dem_law_force(const dem_law_t *law, double kn, double delta)
{
	return delta > 0 ? kn * powm(law->m, delta) : 0;
}

double dem_law_stiffness(const dem_law_t *law, double kn, double delta)
{
	double m = law->m;
	if (m == 1.0)
		return kn;
	if (!(delta > 0))
		return 0;
	return m * kn * powm(m - 1, delta);
}

/* ---- Energy loss -------------------------------------------------------- */

double dem_hyst_unload_ratio(double rho, double m)
{
	return pow(rho, -2 * m);  /* Eq. 3.67 */
}

double dem_hyst_restitution(double unload_ratio, double m)
{
	return pow(1 / unload_ratio, 1 / (2 * m));
}

double dem_visc_restitution_linear(double xi)
{
	return exp(-DEM_PI * xi / sqrt(1 - xi * xi));  /* Eq. 3.71 */
}

double dem_visc_xi_linear(double rho)
{
	double l = log(rho);
	return -l / sqrt(DEM_PI * DEM_PI + l * l);
}

double dem_contact_meff(double M, double Mf)
{
	if (!isfinite(Mf))
		return M;
	return M * Mf / (M + Mf);
}

/* ---- Time step ---------------------------------------------------------- */

double dem_dt_umax(double m, double kn, double M, double v0)
{
	return pow((m + 1) * M * v0 * v0 / (2 * kn), 1 / (m + 1));  /* Eq. 3.81 */
}

double dem_dt_umax_state(double m, double kn, double M, double u, double v)
{
	double w = u > 0 ? powm(m, u) * u : 0;  /* u^(m+1) */
	return pow(w + (m + 1) * M * v * v / (2 * kn), 1 / (m + 1));
}

double dem_dt_secant(double m, double kn, double umax, double u)
{
	if (m == 1.0)
		return kn;
	if (!(umax > 0))
		return 0;
	if (u < 0)
		u = 0;
	double h = umax - u;
	/* near u_max the secant is the tangent; the quotient would cancel */
	if (fabs(h) <= 1e-6 * umax)
		return m * kn * powm(m - 1, umax);
	return kn * (powm(m, umax) - powm(m, u)) / h;  /* Eq. 3.80 */
}

double dem_dt_step(double lambda, double M, double K)
{
	if (!(K > 0))
		return HUGE_VAL;
	return lambda * 2 * sqrt(M / K);  /* Eqs. 3.82-3.83 */
}

dem_lambda_status_t dem_dt_lambda_check(double lambda, int force, char *msg, size_t len)
{
	if (!(lambda > 0 && lambda <= 1)) {
		snprintf(msg, len, "time step factor lambda = %g: expected a number in (0, 1], "
		         "0.1 to 0.3 recommended (Han 2004, Eq. 3.84)", lambda);
		return DEM_LAMBDA_INVALID;
	}
	if (lambda > DEM_DT_LAMBDA_MAX) {
		if (force) {
			snprintf(msg, len, "time step factor lambda = %g is above 0.5 (forced): the contact "
			         "time step diverges, the shots gain energy (Han 2004, Fig. 3.15)", lambda);
			return DEM_LAMBDA_FORCED;
		}
		snprintf(msg, len, "time step factor lambda = %g is above 0.5, where the contact time "
		         "step diverges (Han 2004, Fig. 3.15): use 0.1 to 0.3, or force it", lambda);
		return DEM_LAMBDA_REFUSED;
	}
	if (lambda > DEM_DT_LAMBDA_WARN) {
		snprintf(msg, len, "time step factor lambda = %g is above 0.3: contacts may gain energy "
		         "(Han 2004, Fig. 3.15); 0.1 to 0.3 recommended", lambda);
		return DEM_LAMBDA_WARN;
	}
	return DEM_LAMBDA_OK;
}

double dem_dt_wall_test(double m, double kn, double M, double v0, double lambda,
                        long *steps, double *umax_reached)
{
	if (!(m >= 1 && kn > 0 && M > 0 && v0 > 0 && lambda > 0))
		return NAN;
	double umax = dem_dt_umax(m, kn, M, v0);
	/* Box 3.1: u_n, v_{n-1/2}, dt_{n-1}; u > 0 is the overlap */
	double u = 0, v = v0, dtp = 0, umx = 0;
	long n = 0;
	for (;;) {
		double a = -(u > 0 ? kn * powm(m, u) : 0) / M;
		double dt = lambda * 2 * sqrt(M / dem_dt_secant(m, kn, umax, u));
		v += a * (dtp + dt) / 2;
		u += v * dt;
		dtp = dt;
		n++;
		if (u > umx)
			umx = u;
		if (u < 0 && v < 0)
			break;  /* separated: no further contact (Ch. 3.7) */
		if (n > 100000000L)
			return NAN;
	}
	if (steps)
		*steps = n;
	if (umax_reached)
		*umax_reached = umx;
	return -v / v0;
}
