/* saturation.c - the saturation curve's fit and saturation point
 * (saturation.h). */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_vector.h>

#include "core/saturation.h"

const char *const dem_sat_form_names[] = {"exp2", "exp3", NULL};

/* The points scaled to the last exposure and the highest height, so that
 * the parameters are of order 1 whatever the units. */
struct pts {
	size_t n;
	const double *tau, *y;
	int np;                  /* 2 or 3 parameters */
};

/* Parameters x = (ln A, ln B, ln C) (C = 1 with two): positive by
 * construction.  Residuals r_i = A (1 - exp(-B tau_i^C)) - y_i. */
static void unpack(const gsl_vector *x, int np, double *A, double *B, double *C)
{
	*A = exp(gsl_vector_get(x, 0));
	*B = exp(gsl_vector_get(x, 1));
	*C = np == 3 ? exp(gsl_vector_get(x, 2)) : 1;
}

static int resid(const gsl_vector *x, void *data, gsl_vector *f)
{
	const struct pts *p = data;
	double A, B, C;
	unpack(x, p->np, &A, &B, &C);
	for (size_t i = 0; i < p->n; i++)
		gsl_vector_set(f, i, -A * expm1(-B * pow(p->tau[i], C)) - p->y[i]);
	return GSL_SUCCESS;
}

static int jac(const gsl_vector *x, void *data, gsl_matrix *J)
{
	const struct pts *p = data;
	double A, B, C;
	unpack(x, p->np, &A, &B, &C);
	for (size_t i = 0; i < p->n; i++) {
		double tc = pow(p->tau[i], C), E = exp(-B * tc);
		gsl_matrix_set(J, i, 0, -A * expm1(-B * tc));      /* d/d ln A */
		gsl_matrix_set(J, i, 1, A * E * B * tc);            /* d/d ln B */
		if (p->np == 3)                                     /* d/d ln C */
			gsl_matrix_set(J, i, 2, A * E * B * tc * log(p->tau[i]) * C);
	}
	return GSL_SUCCESS;
}

/* Least squares from x (updated in place); *iter the solver's iterations. */
static int solve(struct pts *p, gsl_vector *x, int *iter, double *chi2)
{
	gsl_multifit_nlinear_fdf fdf = {0};
	fdf.f = resid;
	fdf.df = jac;
	fdf.fvv = NULL;
	fdf.n = p->n;
	fdf.p = (size_t)p->np;
	fdf.params = p;
	gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
	gsl_multifit_nlinear_workspace *w =
		gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, p->n, (size_t)p->np);
	if (!w)
		return GSL_ENOMEM;
	int info, rc = gsl_multifit_nlinear_init(x, &fdf, w);
	if (!rc)
		rc = gsl_multifit_nlinear_driver(500, 1e-12, 1e-12, 0, NULL, NULL, &info, w);
	/* no further progress at the minimum is convergence too; GSL reports
	 * it as GSL_EMAXITER with info GSL_ENOPROG when the start is already
	 * there (exact points from a good start) */
	if (rc == GSL_ENOPROG || (rc == GSL_EMAXITER && info == GSL_ENOPROG))
		rc = GSL_SUCCESS;
	if (!rc) {
		gsl_vector_memcpy(x, gsl_multifit_nlinear_position(w));
		gsl_vector *f = gsl_multifit_nlinear_residual(w);
		double s = 0;
		for (size_t i = 0; i < p->n; i++)
			s += gsl_vector_get(f, i) * gsl_vector_get(f, i);
		*chi2 = s;
		*iter = (int)gsl_multifit_nlinear_niter(w);
	}
	gsl_multifit_nlinear_free(w);
	return rc;
}

/* g(eps) = 1 - u^m - 1.1 (1 - u) with u = 1 - eps, written without
 * cancellation near eps = 0. */
static double ratio_gap(double eps, void *m)
{
	return -expm1(*(double *)m * log1p(-eps)) - 1.1 * eps;
}

/* The saturation point of a(1 - exp(-b t^c)): u = exp(-b T^c) with
 * 1 - u^(2^c) = 1.1 (1 - u); H(T) = a (1 - u).  0 when there is none. */
static int saturation_point(dem_sat_fit_t *f)
{
	double eps;
	if (f->form == DEM_SAT_EXP2) {
		eps = 0.9;      /* u = 0.1 exactly: 1 - u^2 = (1 - u)(1 + u) */
	} else {
		double m = pow(2, f->c);
		/* g(1) = -0.1; g > 0 near 0 when m > 1.1 (g ~ (m - 1.1) eps) */
		double lo = 1e-9;
		if (!(m > 1.1) || !(ratio_gap(lo, &m) > 0))
			return 0;
		gsl_function F = {ratio_gap, &m};
		gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
		if (!s)
			return -1;
		double hi = 1;
		int st = gsl_root_fsolver_set(s, &F, lo, hi);
		for (int k = 0; k < 200 && !st; k++) {
			if ((st = gsl_root_fsolver_iterate(s)))
				break;
			lo = gsl_root_fsolver_x_lower(s);
			hi = gsl_root_fsolver_x_upper(s);
			if (gsl_root_test_interval(lo, hi, 0, 1e-14) == GSL_SUCCESS)
				break;
		}
		eps = gsl_root_fsolver_root(s);
		gsl_root_fsolver_free(s);
		if (st)
			return -1;
	}
	/* -ln u = b T^c */
	f->T = pow(-log1p(-eps) / f->b, 1 / f->c);
	f->H = f->a * eps;
	return 1;
}

int dem_sat_fit(size_t n, const double *t, const double *h, dem_sat_form_t form,
		dem_sat_fit_t *fit, dem_error_t *e)
{
	if (n < 4)
		return dem_error_set(e, DEM_EINPUT, "saturation curve: %zu point%s: at least 4 are "
				     "needed", n, n == 1 ? "" : "s");
	double hmax = -HUGE_VAL, lowest = HUGE_VAL;
	int rises = 0;
	for (size_t i = 0; i < n; i++) {
		if (!(isfinite(t[i]) && t[i] > 0 && isfinite(h[i])))
			return dem_error_set(e, DEM_EINPUT, "saturation curve: point %zu (%g, %g): "
					     "expected a positive exposure and a finite height",
					     i + 1, t[i], h[i]);
		if (i > 0 && !(t[i] > t[i - 1]))
			return dem_error_set(e, DEM_EINPUT, "saturation curve: point %zu: exposure "
					     "%g after %g: exposures must increase", i + 1, t[i],
					     t[i - 1]);
		rises |= h[i] > lowest;
		lowest = fmin(lowest, h[i]);
		hmax = fmax(hmax, h[i]);
	}
	if (!rises || !(hmax > 0))
		return dem_error_set(e, DEM_EINPUT, "saturation curve: the %zu points never rise "
				     "(no height above an earlier one%s): no saturation point can be "
				     "read", n, hmax > 0 ? "" : ", none positive");

	double *tau = malloc(2 * n * sizeof *tau);
	if (!tau)
		return dem_error_nomem(e, "saturation curve");
	double *y = tau + n, tmax = t[n - 1];
	for (size_t i = 0; i < n; i++) {
		tau[i] = t[i] / tmax;
		y[i] = h[i] / hmax;
	}
	/* Start: A = 1 and B from the first point at half height or more,
	 * A (1 - exp(-B tau)) = y there. */
	size_t k = 0;
	while (k + 1 < n && y[k] < 0.5)
		k++;
	double B0 = -log1p(-fmin(fmax(y[k], 0.05), 0.95)) / tau[k];
	struct pts p = {n, tau, y, 2};
	double xs[3] = {0, log(B0), 0}, chi2 = 0;
	gsl_vector_view xv = gsl_vector_view_array(xs, 2);
	int it2 = 0, it3 = 0;
	int rc = solve(&p, &xv.vector, &it2, &chi2);
	if (!rc && form == DEM_SAT_EXP3) {
		/* the three-parameter curve from the two-parameter one (c = 1) */
		p.np = 3;
		xs[2] = 0;
		xv = gsl_vector_view_array(xs, 3);
		rc = solve(&p, &xv.vector, &it3, &chi2);
	}
	free(tau);
	if (rc == GSL_ENOMEM)
		return dem_error_nomem(e, "saturation curve fit");
	if (rc || !isfinite(xs[0] + xs[1] + xs[2]))
		return dem_error_set(e, DEM_ENUMERIC, "saturation curve: the %s fit did not "
				     "converge (%s)", dem_sat_form_names[form], gsl_strerror(rc));
	fit->form = form;
	fit->a = exp(xs[0]) * hmax;
	fit->c = form == DEM_SAT_EXP3 ? exp(xs[2]) : 1;
	fit->b = exp(xs[1]) / pow(tmax, fit->c);
	fit->rms = hmax * sqrt(chi2 / (double)n);
	fit->iterations = it2 + it3;
	fit->T = fit->H = 0;
	int s = saturation_point(fit);
	if (s < 0)
		return dem_error_set(e, DEM_ENUMERIC, "saturation curve: no root of "
				     "H(2T) = 1.1 H(T) found for c = %g", fit->c);
	fit->saturates = s;
	return DEM_OK;
}

double dem_sat_eval(const dem_sat_fit_t *f, double t)
{
	return -f->a * expm1(-f->b * pow(t, f->c));
}

int dem_sat_points(size_t n, const double *t, const double *h, double *T, double *H,
		   double *ratio)
{
	for (size_t i = 0; i < n; i++) {
		if (!(h[i] > 0))
			continue;
		for (size_t j = i + 1; j < n; j++)
			if (fabs(t[j] - 2 * t[i]) <= 1e-6 * t[j] && h[j] <= 1.1 * h[i]) {
				*T = t[i];
				*H = h[i];
				*ratio = h[j] / h[i];
				return 1;
			}
	}
	return 0;
}
