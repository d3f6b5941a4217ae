/* law.h - normal contact laws, energy loss parameters and the contact
 * time step of Han (2004), Ch. 3.3, 3.5 and 3.7.
 *
 * Every normal law is the power law of Eq. 3.45,
 *
 *     F_n = k_n delta^m,   k_n = coef R^(2-m),   coef = alpha E,
 *
 * with the dimensionless penalty alpha: m = 1 linear (Hooke), 1.5 Hertz,
 * 2 the 3D Winkler model, any m in [1, 4] a power law.  The classic Hertz
 * law (Eqs. 3.28-3.29) is the same form with coef = 4/3 E*, m = 3/2, so the
 * DE law can be checked against the Hertz solution.
 *
 * The radius exponent.  Eq. 3.45 writes R^(m-1), which is a force only for
 * m = 3/2 in 3D (E R^(m-1) delta^m has the units of Pa m^(2m-1)); for m = 1
 * it is a force per unit length (the thesis's plane-strain Ch. 7.4) and
 * for m = 2 a force times a length, so that with a dimensionless alpha the
 * law would change with the unit of length (in SI the linear law came out
 * 1000 times stiffer than the thesis's in mm).  For spheres we use R^(2-m),
 * the exponent that makes alpha dimensionless for every m: the same as
 * Eq. 3.45 for the Hertz law, k_n = alpha E R for the linear law (the
 * stiffness of the 3D Hooke law of the DEM literature), alpha E for m = 2.  R is the sphere radius
 * for sphere/facet contact and the relative radius R1 R2 / (R1 + R2) for
 * sphere/sphere contact.  A driver computes k_n once per sphere
 * (dem_law_kn) and keeps it.
 *
 * Two dimensions (Ch. 3.2.1, 3.3, Table 3.1).  The same law object with
 * dim = 2 is a disk's law per unit thickness: F in N/m, M in kg/m, and the
 * radius exponent that keeps alpha dimensionless is then R^(1-m) (E
 * R^(1-m) delta^m is Pa m = N/m for every m).  For m = 1 this is Eq. 3.45
 * as printed, F = alpha E delta.  For m = 3/2 the thesis's R^(1/2) makes
 * E R^(1/2) delta^(3/2) a force, not a force per length, so its alpha is
 * silently per unit length (per mm, the unit of Ch. 7.4): the thesis's 2D
 * Hertz law in mm equals ours with alpha = alpha_thesis (R / 1 mm)^(2m-2),
 * 20 alpha_thesis for the 20 mm disk of Ch. 7.4 (dem_law_alpha_thesis2d).
 * The
 * three 2D laws of Ch. 3.3 in this one form:
 *   linear         F = alpha E delta                          (Eq. 3.25)
 *   generalised Hertz (Poritsky), rigid disk on an elastic segment:
 *                  F = beta E b^2 / R ~ 2 beta E delta         (Eqs. 3.30-3.32)
 *                  i.e. m = 1, alpha = 2 beta(nu)             (Eq. 3.43)
 *   Winkler        F = k_w S ~ 4/3 sqrt(2R) k_w delta^(3/2)   (Eqs. 3.34, 3.39)
 *                  i.e. m = 3/2, alpha = 4 sqrt(2) k_w R / (3 E)
 *                  for a foundation stiffness k_w (Pa/m)
 * (the closed forms b^2 / R and S hold for any overlap; the power forms
 * are their small-overlap limits, Eq. 3.1, to relative order delta/R).
 * dim = 0 counts as 3, so a zero-initialised law is a 3D one.
 *
 * The time step (Box 3.1, Eqs. 3.80-3.83): dt = lambda 2 sqrt(M / K_L(u))
 * with the secant stiffness K_L(u) = k_n (u_max^m - u^m) / (u_max - u) and
 * u_max the overlap at which the kinetic energy is used up (Eq. 3.81).
 * lambda defaults to 0.2 (Eq. 3.84); above 0.3 the exit velocity of the
 * rigid-sphere/wall test can exceed the impact velocity, above 0.5 the
 * scheme diverges (Fig. 3.15), so dem_dt_lambda_check warns and refuses.
 */
#ifndef DEM_CONTACT_LAW_H
#define DEM_CONTACT_LAW_H

#include <stddef.h>

#include "core/error.h"

/* Named exponents of Table 3.1. */
#define DEM_LAW_M_LINEAR  1.0
#define DEM_LAW_M_HERTZ   1.5
#define DEM_LAW_M_WINKLER 2.0

typedef struct dem_law {
	double m;     /* exponent of the overlap, in [1, 4] */
	double coef;  /* k_n = coef R^(dim-1-m): alpha E (Eq. 3.45) or 4/3 E* (Eq. 3.28) */
	int dim;      /* 3 (or 0): spheres, F in N; 2: disks, F per unit thickness (N/m) */
} dem_law_t;

/* Eq. 3.45 in 3D: F = alpha E R^(2-m) delta^m (see above).  alpha > 0 dimensionless, E > 0
 * (Pa), 1 <= m <= 4.  DEM_EINPUT with a message when out of range. */
int dem_law_init(dem_law_t *law, double alpha, double E, double m, dem_error_t *e);

/* The same in dim = 2 or 3 dimensions: in 2D F = alpha E R^(1-m) delta^m
 * per unit thickness (above).  DEM_EINPUT for another dim. */
int dem_law_init_dim(dem_law_t *law, double alpha, double E, double m, int dim, dem_error_t *e);

/* The generalised Hertz law of a rigid disk on an elastic segment
 * (Poritsky; Eqs. 3.30-3.32): beta(nu) of Eq. 3.31,
 *   beta = pi/4 [1 + (k4/k3)^2] / (2 (1 - nu^2)),  k4/k3 = pi (1 - 2nu) / (2 (1 - nu))
 * (the thesis prints a factor E inside beta as well; k_n = beta E must be
 * a modulus, so beta is the number), and the 2D law m = 1, alpha = 2 beta
 * (Eq. 3.43): F = 2 beta E delta, the small-overlap limit of beta E b^2/R.
 * nu in (-1, 0.5]. */
double dem_law_ghertz2d_beta(double nu);
int dem_law_ghertz2d(dem_law_t *law, double E, double nu, dem_error_t *e);

/* The 2D Winkler law (Eqs. 3.33-3.39) on a foundation of stiffness k_w
 * (traction per unit overlap, Pa/m) for a disk of radius R: the alpha of
 * the 2D law m = 3/2 with the same small-overlap force,
 * 4 sqrt(2) k_w R / (3 E). */
double dem_law_winkler2d_alpha(double kw, double E, double R);

/* The thesis writes its 2D laws with R^(m-1), in mm and N (Ch. 7.4): the
 * alpha of our 2D law (R^(1-m)) that gives the thesis's force for its
 * alpha_t and a disk of radius R (in m): alpha_t (R / 1 mm)^(2m-2), i.e.
 * alpha_t for m = 1, alpha_t R / (1 mm) for m = 3/2. */
double dem_law_alpha_thesis2d(double alpha_t, double m, double R);

/* The classic Hertz law of a rigid sphere on an elastic half-space
 * (Eqs. 3.27-3.29): k_n = 4/3 E/(1 - nu^2) sqrt(R), m = 3/2. */
int dem_law_hertz(dem_law_t *law, double E, double nu, dem_error_t *e);

/* E* of two elastic bodies, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (Eq. 3.28);
 * E2 = INFINITY for a rigid partner. */
double dem_law_estar(double E1, double nu1, double E2, double nu2);

/* Relative radius R1 R2 / (R1 + R2) of two spheres (Eq. 3.28). */
double dem_law_reff(double R1, double R2);

/* k_n = coef R^(2-m) in 3D, coef R^(1-m) in 2D (no pow() for m = 1, 1.5, 2). */
double dem_law_kn(const dem_law_t *law, double R);

/* F_n = k_n delta^m (0 for delta <= 0) and the tangent stiffness
 * K_n = m k_n delta^(m-1) (Eq. 3.72). */
double dem_law_force(const dem_law_t *law, double kn, double delta);
double dem_law_stiffness(const dem_law_t *law, double kn, double delta);

/* ---- Energy loss parameters (Ch. 3.5) ----------------------------------- */

/* Hysteretic model (Eqs. 3.63-3.67): the unloading stiffness ratio
 * k'_n / k_n that gives the coefficient of restitution rho in (0, 1]:
 * rho = (k_n / k'_n)^(1/(2m)), so k'_n / k_n = rho^(-2m).  And back. */
double dem_hyst_unload_ratio(double rho, double m);
double dem_hyst_restitution(double unload_ratio, double m);

/* Viscous damping of the linear law (Eq. 3.71): restitution of the damping
 * ratio xi in [0, 1) when the dash-pot may pull, and its inverse. */
double dem_visc_restitution_linear(double xi);
double dem_visc_xi_linear(double rho);

/* Equivalent mass of a sphere (M) against a facet whose nodes carry the
 * masses summing to Mf (Eq. 3.75): M Mf / (M + Mf); Mf = INFINITY for a
 * rigid facet gives M. */
double dem_contact_meff(double M, double Mf);

/* ---- Time step (Ch. 3.7, Box 3.1) --------------------------------------- */

#define DEM_DT_LAMBDA_DEFAULT 0.2  /* Eq. 3.84: 0.1 to 0.3 */
#define DEM_DT_LAMBDA_WARN    0.3  /* above: energy gain possible (Fig. 3.15b) */
#define DEM_DT_LAMBDA_MAX     0.5  /* above: divergence (Fig. 3.15a) */

/* Eq. 3.81: u_max = ((m+1) M v0^2 / (2 k_n))^(1/(m+1)). */
double dem_dt_umax(double m, double kn, double M, double v0);

/* The same from the current state (overlap u >= 0, normal speed v): the
 * overlap at which the energy k_n u^(m+1)/(m+1) + M v^2/2 is all stored.
 * Equals Eq. 3.81 at u = 0 and stays valid through the contact, so a
 * driver needs no impact speed in its contact state. */
double dem_dt_umax_state(double m, double kn, double M, double u, double v);

/* Eq. 3.80: secant stiffness k_n (u_max^m - u^m)/(u_max - u) for u >= 0
 * (u < 0 counts as 0; past u_max, after an overshoot, the secant is the
 * stiffer one beyond u_max); the tangent m k_n u_max^(m-1) at u = u_max. */
double dem_dt_secant(double m, double kn, double umax, double u);

/* Eqs. 3.82-3.83: lambda 2 sqrt(M / K); HUGE_VAL when K <= 0. */
double dem_dt_step(double lambda, double M, double K);

/* Outcome of dem_dt_lambda_check. */
typedef enum dem_lambda_status {
	DEM_LAMBDA_OK = 0,      /* 0 < lambda <= 0.3 */
	DEM_LAMBDA_WARN = 1,    /* 0.3 < lambda <= 0.5: run, print the message */
	DEM_LAMBDA_FORCED = 2,  /* 0.5 < lambda <= 1 and forced: run, print it */
	DEM_LAMBDA_REFUSED = 3, /* 0.5 < lambda <= 1, not forced: stop (usage error) */
	DEM_LAMBDA_INVALID = 4  /* not a number in (0, 1]: stop */
} dem_lambda_status_t;

/* Check the time step factor.  For every status but OK, writes a message
 * (without program name) to msg[len] that the caller prints as a warning or
 * as the error. */
dem_lambda_status_t dem_dt_lambda_check(double lambda, int force, char *msg, size_t len);

/* The rigid-sphere/rigid-wall test of Box 3.1: central differences with
 * dt_n = lambda dt_cr(u_n) (Eqs. 3.80-3.83, u_max by Eq. 3.81), u(0) = 0,
 * impact speed v0, until the sphere leaves.  Returns v_exit / v0 (NaN only
 * for bad arguments); steps and the largest overlap (NULL for none).  The
 * thesis scheme; dem_contact_wall_test (model.h) runs the same through a
 * contact model, with the separation correction that removes the energy
 * this scheme makes or loses. */
double dem_dt_wall_test(double m, double kn, double M, double v0, double lambda,
                        long *steps, double *umax_reached);

#endif
