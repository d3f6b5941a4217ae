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
#define DEM_MAT_KIN     4u  /* kinematic hardening: back-stresses (implies PLASTIC) */
#define DEM_MAT_GENERAL 8u  /* the general return (Voce, Johnson-Cook, Cowper-Symonds,
			     * Johnson-Cook rate, back-stresses), not the closed
			     * forms of the piecewise linear curve */

/* Isotropic hardening laws (dem_mat_param_t.law).  sigma_y(ep) is the
 * rate-independent flow stress at the effective plastic strain ep:
 *   LINEAR  sy0 + H ep
 *   TABLE   piecewise linear through (hard_ep, hard_sy), the last slope on
 *   VOCE    sy0 + Q (1 - exp(-b ep)) + H ep          (Voce 1948)
 *   JC      (A + B ep^n) (1 - T*^mt)                 (Johnson & Cook 1983),
 *           T* = (T - T_ref) / (T_melt - T_ref), 0 at or below T_ref */
typedef enum dem_mat_law {
	DEM_LAW_AUTO = 0,     /* LINEAR with a yield stress, TABLE with a table */
	DEM_LAW_LINEAR, DEM_LAW_TABLE, DEM_LAW_VOCE, DEM_LAW_JC
} dem_mat_law_t;

/* Rate laws: the flow stress is sigma_y(ep) R(rate), rate the effective
 * plastic strain rate of the increment (Delta ep / dt), R >= 1:
 *   POWER   max(rate / ref, 1)^m                       (the m of Table 7.2)
 *   CS      1 + (rate / D)^(1/p)                       (Cowper & Symonds 1957)
 *   JC      1 + C ln(max(rate / ref, 1))               (Johnson & Cook 1983) */
typedef enum dem_mat_rate_law {
	DEM_RATE_NONE = 0, DEM_RATE_POWER, DEM_RATE_CS, DEM_RATE_JC
} dem_mat_rate_law_t;

/* Back-stresses of the combined isotropic + nonlinear kinematic model
 * (Armstrong & Frederick 1966; Chaboche 1986): the yield function is
 * sqrt(3/2) |s - sum alpha_i| - sigma_y(ep) R, and each back-stress
 * evolves as d alpha_i = 2/3 C_i d eps_p - gamma_i alpha_i d ep. */
#define DEM_MAT_NKIN 3

/* What a scene gives.  Zero fields are "absent". */
typedef struct dem_mat_param {
	double E, nu;        /* Young's modulus (Pa), Poisson's ratio */
	double rho;          /* density (kg/m^3); may be 0 for statics */
	dem_mat_law_t law;   /* isotropic hardening law */
	/* LINEAR and VOCE: the initial yield stress sy0 and the linear term
	 * H (Pa, >= 0), the plastic modulus d(sigma_y)/d(ep), not the
	 * tangent modulus of the stress-strain curve.  sy0 == 0 with no
	 * table: elastic. */
	double sy0;
	double H;
	int nhard;           /* TABLE: length; 0: no table */
	const double *hard_ep;  /* effective plastic strains, hard_ep[0] == 0, increasing */
	const double *hard_sy;  /* flow stresses (Pa), non-decreasing */
	double voce_Q, voce_b;  /* VOCE: saturation stress (Pa, >= 0), rate b (> 0) */
	/* JC: A (Pa, > 0), B (Pa, >= 0), n in (0, 1]; thermal softening when
	 * T > 0: temperatures in K with T_ref < T_melt, exponent mt > 0 */
	double jc_A, jc_B, jc_n;
	double T, T_ref, T_melt, mt;
	/* rate law */
	dem_mat_rate_law_t rate_law;
	double rate_m;       /* POWER: exponent in (0, 1) */
	double rate_ref;     /* POWER, JC: reference rate (1/s), required */
	double cs_D, cs_p;   /* CS: D (1/s) > 0, p > 0 */
	double jc_C;         /* JC rate: C > 0 */
	/* back-stresses: nkin in [0, DEM_MAT_NKIN], C_i (Pa) > 0, gamma_i >= 0 */
	int nkin;
	double kin_C[DEM_MAT_NKIN], kin_gamma[DEM_MAT_NKIN];
} dem_mat_param_t;

/* A material ready for the loops.  Read its fields, do not write them;
 * initialise with dem_mat_init() and release with dem_mat_free(). */
typedef struct dem_mat {
	double E, nu, rho;
	double K, G, lam;    /* bulk modulus, shear modulus, Lame's lambda */
	double wave;         /* dilatational wave speed sqrt((K + 4G/3)/rho), 0 if rho == 0 */
	unsigned flags;      /* DEM_MAT_PLASTIC, _RATE, _KIN, _GENERAL */
	dem_mat_law_t law;   /* never AUTO once initialised (plastic materials) */
	/* LINEAR and TABLE: the curve as nhard knots (hep, hsy) and the slope
	 * hsl[k] of the segment that starts at knot k; the last slope extends
	 * the curve beyond the last knot.  Linear hardening is the one-knot
	 * case.  VOCE and JC: one knot, hsy[0] the initial yield stress. */
	int nhard;
	double *hep, *hsy, *hsl;
	/* One knot (linear hardening, slope H = hsl[0]): the tangent shear
	 * ratio H / (3G + H) of dem_mat_tangent_ratio(), computed once */
	double tratio;
	/* A lower bound of the static flow curve over ep >= 0 (0: none
	 * known): a trial stress below it is elastic whatever ep and the
	 * rate, which lets the batched update skip the general return */
	double sy_floor;
	double voce_Q, voce_b, voce_H;
	double jc_A, jc_B, jc_n;   /* thermal factor folded into A and B */
	dem_mat_rate_law_t rate_law;
	double rate_m, rate_ref, cs_D, cs_ip, jc_C;   /* cs_ip = 1/p */
	int nkin;            /* back-stresses, 6 Voigt components each */
	double kin_C[DEM_MAT_NKIN], kin_gamma[DEM_MAT_NKIN];
	/* The static stage's reading of a kinematic law (dem_mat_kin_as_iso):
	 * no back-stresses, the monotonic curve's kinematic part
	 * sum C_i/gamma_i (1 - exp(-gamma_i ep)) added to sigma_y */
	int kin_iso;
} dem_mat_t;

/* Doubles of history per material point beyond the stress and ep: the
 * back-stresses, 6 * nkin (0 for isotropic hardening).  Drivers keep them
 * per point and pass them to the updates (NULL when 0). */
static inline int dem_mat_nhist(const dem_mat_t *m)
{
	return m->flags & DEM_MAT_KIN ? 6 * m->nkin : 0;
}

/* Validate the parameters and build the material.  On error returns
 * DEM_EINPUT with a message naming the bad parameter; m is then empty
 * (dem_mat_free() on it is harmless). */
int dem_mat_init(dem_mat_t *m, const dem_mat_param_t *p, dem_error_t *e);
void dem_mat_free(dem_mat_t *m);

/* For the static stage (demform), whose initial state (a residual profile)
 * carries no back-stresses: a kinematic law is read as its monotonic
 * uniaxial curve, sigma_y(ep) + sum C_i/gamma_i (1 - exp(-gamma_i ep))
 * (C_i ep where gamma_i = 0), an isotropic law with no history beyond ep.
 * Nothing to do for an isotropic law. */
void dem_mat_kin_as_iso(dem_mat_t *m);

/* The name of the law as a scene writes it ("voce"), for logs. */
const char *dem_mat_law_name(const dem_mat_t *m);
const char *dem_mat_rate_name(const dem_mat_t *m);

/* Flow stress sigma_y(ep) R(rate) (the rate factor only when the material
 * has DEM_MAT_RATE); with back-stresses, the radius of the yield surface
 * (the monotonic curve adds the back-stresses to it). */
double dem_mat_flow_stress(const dem_mat_t *m, double ep, double rate);

/* Hardening slope d(sigma_y)/d(ep) of the rate-independent curve at ep
 * (the slope of the segment to the right of ep); with back-stresses, plus
 * their slope on the monotonic curve from a virgin state,
 * sum C_i exp(-gamma_i ep).  HUGE_VAL for Johnson-Cook with n < 1 at 0. */
double dem_mat_hardening_slope(const dem_mat_t *m, double ep);

/* Tangent shear ratio H / (3G + H) of J2 flow at ep, H the hardening slope
 * there (0 when H is 0): the shear stiffness along the flow over the
 * elastic one (the explicit stage scales its hourglass stiffness by it in
 * elements that flow).  Read from the material for linear hardening. */
static inline double dem_mat_tangent_ratio(const dem_mat_t *m, double ep)
{
	if (m->nhard == 1 && !(m->flags & DEM_MAT_GENERAL))
		return m->tratio;
	double H = dem_mat_hardening_slope(m, ep);
	return H > 0 ? (H < 1e300 ? H / (3 * m->G + H) : 1) : 0;
}

/* Stress update for a strain increment deps over the time dt:
 * sig (in: at the start, out: at the end), ep likewise, kin the
 * dem_mat_nhist(m) back-stress components likewise (alpha_i at
 * kin[6 i + k], Voigt order with tensor shears; NULL when there are none);
 * *wp receives the plastic work per unit volume of the increment,
 * sig_end : Delta eps_p (backward Euler).  dt only matters for a
 * rate-dependent material; dt <= 0 means a static increment (no rate
 * effect).  Returns 1 if the increment was plastic, else 0. */
typedef int (*dem_mat_update_fn)(const dem_mat_t *m, const double deps[6],
				 double dt, double sig[6], double *ep,
				 double *kin, double *wp);

int dem_mat_update_elastic(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *kin, double *wp);
int dem_mat_update_j2(const dem_mat_t *m, const double deps[6], double dt,
		      double sig[6], double *ep, double *kin, double *wp);
int dem_mat_update_j2_rate(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *kin, double *wp);
/* Any law, rate law and back-stresses: the return of the combined model
 * (see material.c), a scalar equation in Delta ep solved by a safeguarded
 * Newton iteration. */
int dem_mat_update_general(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *kin, double *wp);

/* The cheapest of these for m's effects: choose it once, before the loop. */
dem_mat_update_fn dem_mat_update_select(const dem_mat_t *m);

/* The update of m's kind (a dispatch on m->flags: for tests and cold code). */
int dem_mat_update(const dem_mat_t *m, const double deps[6], double dt,
		   double sig[6], double *ep, double *kin, double *wp);

/* Batched update for the explicit loop: DEM_MAT_NB material points with
 * the point innermost (component k of point p at sig[k * DEM_MAT_NB + p]), e.g. one lane
 * per element of a block of one-point hexahedra; the arrays are
 * double[n][DEM_MAT_NB] passed flat (entry [k][p] at k * DEM_MAT_NB + p),
 * the back-stresses kin as double[6 nkin][DEM_MAT_NB] (NULL when none).
 * Applies the Jaumann rotation by the spins w (rates; NULL for small
 * strain) to the stress and the back-stresses, then the strain increment
 * d dt (d: rates of deformation, engineering shears), then the return to
 * the flow stress: the elastic predictor and the yield check of the
 * piecewise linear curve run across the lanes in SIMD registers, the
 * return mapping only for the lanes that yield (the general return lane by
 * lane).  The material's effects are tested once per call, not per
 * point.  wp receives the plastic work per unit volume; returns a bit mask
 * of the plastic lanes.  Each lane's result is bit for bit that of
 * dem_mat_jaumann (on the stress and each back-stress) and dem_mat_update
 * with deps = d dt.
 *
 * syc (NULL: none) is a record of each point's static flow stress
 * sigma_y(ep), kept by the caller beside ep (double[DEM_MAT_NB]): for a law
 * without a closed-form return (DEM_MAT_GENERAL) and without back-stresses,
 * a lane whose trial stress lies below its record is elastic without the
 * general return, and each lane that goes through the return gets its
 * record updated.  Start it at m->sy_floor (never above sigma_y(ep)) and
 * reset it there whenever ep changes other than through this call; the
 * results are the same bit for bit with or without it. */
#define DEM_MAT_NB 4

unsigned dem_mat_update_batch(const dem_mat_t *m, double dt,
			      const double *restrict d, const double *restrict w,
			      double *restrict sig, double *restrict ep,
			      double *restrict kin, double *restrict wp,
			      double *restrict syc);

/* Elastic stiffness D (6x6, row-major) mapping engineering strains to stress. */
void dem_mat_elastic_stiffness(const dem_mat_t *m, double D[36]);

/* Stress update as dem_mat_update(), plus the algorithmic tangent
 * D = d(sig_new)/d(deps) (6x6, row-major) of the return (Simo & Taylor
 * 1985 for isotropic hardening) for the implicit Newton; the elastic D for
 * an elastic increment.  D is symmetric except with back-stresses whose
 * recall term (gamma_i > 0) makes the exact tangent unsymmetric. */
int dem_mat_update_tangent(const dem_mat_t *m, const double deps[6], double dt,
			   double sig[6], double *ep, double *kin, double *wp,
			   double D[36]);

/* Jaumann rotation of the stress for the large-strain explicit loop:
 * sig += (W sig - sig W) dt, with the spin W = (L - L^T)/2 given by its
 * three components w = (W_xy, W_yz, W_zx). */
void dem_mat_jaumann(double sig[6], const double w[3], double dt);

/* Von Mises equivalent stress sqrt(3/2 s:s). */
double dem_mat_mises(const double sig[6]);

/* Uniaxial-stress driver (tests, calibration): a material point with
 * total strain eps[6], stress sig[6], plastic strain *ep and back-stresses
 * kin (NULL when none) is strained by deps11 along x in the time dt, with
 * the lateral strains found by Newton iteration on the consistent tangent
 * so that every stress but sig_xx stays zero.  Updates eps, sig, ep, kin;
 * returns DEM_OK, or DEM_ENUMERIC if the lateral iteration fails to
 * converge. */
int dem_mat_uniaxial(const dem_mat_t *m, double deps11, double dt,
		     double eps[6], double sig[6], double *ep, double *kin);

#endif
