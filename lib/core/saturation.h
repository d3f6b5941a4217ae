/* saturation.h - the Almen saturation curve: arc height H against exposure
 * t (passes, time), its saturation point and the intensity (SAE J443).
 *
 * SAE J443 defines the saturation point as the exposure T at which
 * doubling the exposure raises the arc height by 10 %, H(2T) = 1.1 H(T);
 * the intensity is H(T).  Two readings of it:
 *
 *  - dem_sat_fit: a curve fitted by nonlinear least squares (GSL's
 *    gsl_multifit_nlinear, trust region with Levenberg-Marquardt steps),
 *    in the forms of the curve solver that SAE J2597 describes:
 *      DEM_SAT_EXP2  H(t) = a (1 - exp(-b t))          (two parameters)
 *      DEM_SAT_EXP3  H(t) = a (1 - exp(-b t^c))        (three parameters)
 *    and T solved on the curve: for EXP2, exp(-b T) = 0.1, T = ln 10 / b,
 *    H(T) = 0.9 a; for EXP3, u = exp(-b T^c) solves 1 - u^(2^c) =
 *    1.1 (1 - u) in (0, 1) (a root exists when 2^c > 1.1, i.e. c > 0.1375;
 *    none otherwise: the curve rises too slowly ever to saturate).
 *  - dem_sat_points: the rule on the measured points themselves, the
 *    earliest measured t with 2t measured too and H(2t) <= 1.1 H(t).
 *
 * Exposures and heights in any units (the fit is scale-free; a and H in
 * the heights' unit, T and b in the exposures').
 */
#ifndef DEM_CORE_SATURATION_H
#define DEM_CORE_SATURATION_H

#include <stddef.h>

#include "core/error.h"

typedef enum dem_sat_form { DEM_SAT_EXP2 = 0, DEM_SAT_EXP3 = 1 } dem_sat_form_t;

/* The names of the forms, "exp2" and "exp3", NULL-terminated. */
extern const char *const dem_sat_form_names[];

typedef struct dem_sat_fit {
	dem_sat_form_t form;
	double a, b, c;          /* H(t) = a (1 - exp(-b t^c)); c = 1 for EXP2 */
	double rms;              /* root mean square of the residuals */
	int iterations;          /* of the solver (EXP3: after the EXP2 start) */
	int saturates;           /* 1: T and H found; 0: no saturation point */
	double T, H;             /* the saturation point and H(T) */
} dem_sat_fit_t;

/* Fit the n points (t[i], h[i]) in the given form.  Exposures must be
 * positive, finite and increasing, heights finite.  Refused (DEM_EINPUT,
 * with the reason in e): fewer than 4 points; points that never rise (no
 * point higher than an earlier one, or no positive height): no saturation
 * curve can be read from them.  DEM_ENUMERIC when the solver fails;
 * DEM_EIO without memory. */
int dem_sat_fit(size_t n, const double *t, const double *h, dem_sat_form_t form,
		dem_sat_fit_t *fit, dem_error_t *e);

/* H(t) of a fitted curve. */
double dem_sat_eval(const dem_sat_fit_t *fit, double t);

/* The J443 rule on the points (exposures increasing): the earliest t[i]
 * with h[i] > 0 and a t[j] = 2 t[i] (to 1e-6 relative) such that h[j] <=
 * 1.1 h[i].  Returns 1 and sets *T = t[i], *H = h[i], *ratio = h[j] / h[i];
 * 0 when no point qualifies. */
int dem_sat_points(size_t n, const double *t, const double *h, double *T, double *H,
		   double *ratio);

#endif
