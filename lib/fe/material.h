/* material.h - the one J2 material of the toolkit: isotropic elasticity,
 * von Mises plasticity by radial return with isotropic hardening (linear, or
 * piecewise linear from a table such as Table 7.1), and an optional power law
 * for the rate dependence of the flow stress (exponent m of Table 7.2).
 *
 * Shared by the explicit stage (demshot, Ch. 7.3) and the implicit stage
 * (demform, Ch. 8.5): the explicit loop calls only a stress update; the
 * implicit Newton calls the update with the algorithmic (consistent) tangent.
 *
 * Conventions.  Stresses and strains are Voigt 6-vectors in the order
 * xx, yy, zz, xy, yz, zx; strains carry engineering shears (gamma_xy =
 * 2 eps_xy), stresses the tensor components.  SI units throughout.  The
 * effective plastic strain ep is the usual sqrt(2/3 eps_p : eps_p) measure,
 * so that in uniaxial stress it equals the axial plastic strain.
 *
 * Effects (DESIGN.md, "simulate only what the scene calls for"): plasticity
 * is on when a yield stress or a hardening table is given; rate dependence
 * when a rate exponent m > 0 is given.  dem_mat_update_select() hands the
 * driver the cheapest update that covers the effects present, chosen once
 * before the loop; an elastic or rate-independent material never executes
 * the branches of the richer models.
 */
#ifndef DEM_FE_MATERIAL_H
#define DEM_FE_MATERIAL_H

#include "core/error.h"

/* dem_mat_t.flags */
#define DEM_MAT_PLASTIC 1u  /* J2 plasticity */
#define DEM_MAT_RATE    2u  /* rate-dependent flow stress (implies PLASTIC) */

/* What a scene gives.  Zero fields are "absent". */
typedef struct dem_mat_param {
	double E, nu;        /* Young's modulus (Pa), Poisson's ratio */
	double rho;          /* density (kg/m^3); may be 0 for statics */
	/* Plasticity: either a yield stress with a linear hardening modulus,
	 * or a table.  H is the plastic modulus d(sigma_y)/d(ep), not the
	 * tangent modulus of the stress-strain curve. */
	double sy0;          /* initial yield stress (Pa); 0: no plasticity */
	double H;            /* linear hardening modulus (Pa), >= 0 */
	int nhard;           /* table length; 0: no table */
	const double *hard_ep;  /* effective plastic strains, hard_ep[0] == 0, increasing */
	const double *hard_sy;  /* flow stresses (Pa), non-decreasing */
	/* Rate dependence: sigma_f = sigma_y(ep) * max(rate/rate_ref, 1)^m */
	double rate_m;       /* exponent m (Table 7.2); 0: rate independent */
	double rate_ref;     /* reference rate (1/s); 0: the default 1/s */
} dem_mat_param_t;

/* A material ready for the loops.  Read its fields, do not write them;
 * initialise with dem_mat_init() and release with dem_mat_free(). */
typedef struct dem_mat {
	double E, nu, rho;
	double K, G, lam;    /* bulk modulus, shear modulus, Lame's lambda */
	double wave;         /* dilatational wave speed sqrt((K + 4G/3)/rho), 0 if rho == 0 */
	unsigned flags;      /* DEM_MAT_PLASTIC, DEM_MAT_RATE */
	/* Hardening curve as nhard knots (hep, hsy) and the slope hsl[k] of
	 * the segment that starts at knot k; the last slope extends the curve
	 * beyond the last knot.  Linear hardening is the one-knot case. */
	int nhard;
	double *hep, *hsy, *hsl;
	/* One knot (linear hardening, slope H = hsl[0]): the tangent shear
	 * ratio H / (3G + H) of dem_mat_tangent_ratio(), computed once */
	double tratio;
	double rate_m, rate_ref;
} dem_mat_t;

/* Validate the parameters and build the material.  On error returns
 * DEM_EINPUT with a message naming the bad parameter; m is then empty
 * (dem_mat_free() on it is harmless). */
int dem_mat_init(dem_mat_t *m, const dem_mat_param_t *p, dem_error_t *e);
void dem_mat_free(dem_mat_t *m);

/* Flow stress sigma_y(ep) * max(rate/rate_ref, 1)^m (the rate factor only
 * when the material has DEM_MAT_RATE). */
double dem_mat_flow_stress(const dem_mat_t *m, double ep, double rate);

/* Hardening slope d(sigma_y)/d(ep) of the rate-independent curve at ep
 * (the slope of the segment to the right of ep). */
double dem_mat_hardening_slope(const dem_mat_t *m, double ep);

/* Tangent shear ratio H / (3G + H) of J2 flow at ep, H the hardening slope
 * there (0 when H is 0): the shear stiffness along the flow over the
 * elastic one (the explicit stage scales its hourglass stiffness by it in
 * elements that flow).  Read from the material for linear hardening. */
static inline double dem_mat_tangent_ratio(const dem_mat_t *m, double ep)
{
	if (m->nhard == 1)
		return m->tratio;
	double H = dem_mat_hardening_slope(m, ep);
	return H > 0 ? H / (3 * m->G + H) : 0;
}

/* Stress update for a strain increment deps over the time dt:
 * sig (in: at the start, out: at the end), ep likewise; *wp receives the
 * plastic work per unit volume of the increment (Delta ep * sigma_f at the
 * end of the step, consistent with the backward Euler return).  dt only
 * matters for a rate-dependent material; dt <= 0 means a static increment
 * (no rate effect).  Returns 1 if the increment was plastic, else 0. */
typedef int (*dem_mat_update_fn)(const dem_mat_t *m, const double deps[6],
				 double dt, double sig[6], double *ep, double *wp);

int dem_mat_update_elastic(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *wp);
int dem_mat_update_j2(const dem_mat_t *m, const double deps[6], double dt,
		      double sig[6], double *ep, double *wp);
int dem_mat_update_j2_rate(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *wp);

/* The cheapest of the three for m's effects: choose it once, before the loop. */
dem_mat_update_fn dem_mat_update_select(const dem_mat_t *m);

/* The update of m's kind (a dispatch on m->flags: for tests and cold code). */
int dem_mat_update(const dem_mat_t *m, const double deps[6], double dt,
		   double sig[6], double *ep, double *wp);

/* Batched update for the explicit loop: DEM_MAT_NB material points with
 * the point innermost (component k of point p at sig[k * DEM_MAT_NB + p]), e.g. one lane
 * per element of a block of one-point hexahedra; the arrays are
 * double[n][DEM_MAT_NB] passed flat (entry [k][p] at k * DEM_MAT_NB + p).
 * Applies the Jaumann
 * rotation by the spins w (rates; NULL for small strain), then the strain
 * increment d dt (d: rates of deformation, engineering shears), then the
 * return to the flow stress: the elastic predictor and the yield check run
 * across the lanes in SIMD registers, the return mapping only for the lanes
 * that yield.  The material's effects are tested once per call, not per
 * point.  wp receives the plastic work per unit volume; returns a bit mask
 * of the plastic lanes. */
#define DEM_MAT_NB 4

unsigned dem_mat_update_batch(const dem_mat_t *m, double dt,
			      const double *restrict d, const double *restrict w,
			      double *restrict sig, double *restrict ep,
			      double *restrict wp);

/* Elastic stiffness D (6x6, row-major) mapping engineering strains to stress. */
void dem_mat_elastic_stiffness(const dem_mat_t *m, double D[36]);

/* Stress update as dem_mat_update(), plus the algorithmic tangent
 * D = d(sig_new)/d(deps) (6x6, row-major, symmetric) of Simo & Taylor (1985)
 * for the implicit Newton; the elastic D for an elastic increment. */
int dem_mat_update_tangent(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *wp, double D[36]);

/* Jaumann rotation of the stress for the large-strain explicit loop:
 * sig += (W sig - sig W) dt, with the spin W = (L - L^T)/2 given by its
 * three components w = (W_xy, W_yz, W_zx). */
void dem_mat_jaumann(double sig[6], const double w[3], double dt);

/* Von Mises equivalent stress sqrt(3/2 s:s). */
double dem_mat_mises(const double sig[6]);

/* Uniaxial-stress driver (tests, calibration): a material point with
 * total strain eps[6], stress sig[6] and plastic strain *ep is strained by
 * deps11 along x in the time dt, with the lateral strains found by Newton
 * iteration on the consistent tangent so that every stress but sig_xx stays
 * zero.  Updates eps, sig, ep; returns DEM_OK, or DEM_ENUMERIC if the
 * lateral iteration fails to converge. */
int dem_mat_uniaxial(const dem_mat_t *m, double deps11, double dt,
		     double eps[6], double sig[6], double *ep);

#endif
