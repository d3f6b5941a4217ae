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
	double coef;  /* k_n = coef R^(2-m): alpha E (Eq. 3.45) or 4/3 E* (Eq. 3.28) */
} dem_law_t;

/* Eq. 3.45 in 3D: F = alpha E R^(2-m) delta^m (see above).  alpha > 0 dimensionless, E > 0
 * (Pa), 1 <= m <= 4.  DEM_EINPUT with a message when out of range. */
int dem_law_init(dem_law_t *law, double alpha, double E, double m, dem_error_t *e);

/* The classic Hertz law of a rigid sphere on an elastic half-space
 * (Eqs. 3.27-3.29): k_n = 4/3 E/(1 - nu^2) sqrt(R), m = 3/2. */
int dem_law_hertz(dem_law_t *law, double E, double nu, dem_error_t *e);

/* E* of two elastic bodies, 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (Eq. 3.28);
 * E2 = INFINITY for a rigid partner. */
double dem_law_estar(double E1, double nu1, double E2, double nu2);

/* Relative radius R1 R2 / (R1 + R2) of two spheres (Eq. 3.28). */
double dem_law_reff(double R1, double R2);

/* k_n = coef R^(2-m) (no pow() for m = 1, 1.5, 2). */
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
