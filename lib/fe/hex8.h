/* hex8.h - the one 8-node hexahedron of the toolkit, for the explicit stage
 * (demshot: one-point integration with hourglass control, or full 2x2x2
 * integration) and the implicit stage (demform: element stiffness and
 * internal force, with incompatible modes against bending locking).
 *
 * Node order: the usual one.  In natural coordinates (xi, eta, zeta) the
 * nodes are 0 (-,-,-), 1 (+,-,-), 2 (+,+,-), 3 (-,+,-), 4 (-,-,+),
 * 5 (+,-,+), 6 (+,+,+), 7 (-,+,+): 0-3 the bottom face counter-clockwise seen
 * from +zeta, 4-7 the top face above them.
 *
 * Element arrays are packed per element, component-major: x[0..7] the x
 * coordinates of nodes 0-7, x[8..15] the y, x[16..23] the z; velocities,
 * displacements and nodal forces likewise.  A driver gathers them from its
 * structure-of-arrays node data and scatters the forces back.  Stresses and
 * strains are Voigt vectors as in material.h (xx, yy, zz, xy, yz, zx,
 * engineering shear strains).  No function allocates memory.
 *
 * Internal forces are the forces the element needs to hold its stress: the
 * equation of motion reads M a = f_ext - f_int, and f_int . v is the rate of
 * internal (stress + hourglass) work.
 *
 * The kernels work in the modal (Walsh) basis of the trilinear element:
 * x(xi) = sum_k a_k Lambda_k(xi) with Lambda = 1, xi, eta, zeta, eta zeta,
 * zeta xi, xi eta, xi eta zeta; the coefficients a_k of a nodal field come
 * from a 24-addition butterfly, and the volume, its gradient (Flanagan &
 * Belytschko's uniform gradient), the Jacobians at any point and the
 * hourglass base vectors are all short expressions in them.
 */
#ifndef DEM_FE_HEX8_H
#define DEM_FE_HEX8_H

#include "fe/material.h"

/* Return codes of the element functions (a driver maps a non-zero code to
 * DEM_ENUMERIC with the element's number). */
enum {
	DEM_HEX8_OK = 0,
	DEM_HEX8_INVERTED = 1,  /* non-positive Jacobian determinant or volume */
	DEM_HEX8_NOCONV = 2     /* local (incompatible-mode) iteration failed */
};

/* Natural coordinates of the nodes (+1 or -1). */
extern const double dem_hex8_node_xi[8], dem_hex8_node_eta[8], dem_hex8_node_zeta[8];

/* ---- One-point integration (Flanagan & Belytschko 1981) ---------------- */

/* Work space of one element for one cycle of the explicit loop. */
typedef struct dem_hex8_1pt {
	double a[8][3];  /* modal coefficients of the coordinates */
	double c[8][3];  /* c_k = dV/da_k: b_I = dV/dx_I = 1/8 sum_k Lambda_k(I) c_k */
	double vol;      /* exact volume of the trilinear element */
	double L[9];     /* velocity gradient dv_i/dx_j, row-major (dem_hex8_1pt_rate) */
	double q[12];    /* hourglass velocities q[3 alpha + i], FB's normalised basis */
} dem_hex8_1pt_t;

/* Geometry at coordinates x: volume and uniform gradient.  Returns
 * DEM_HEX8_INVERTED when the volume or the Jacobian determinant at the
 * centre is not positive (or not a number); the work space is then unfit
 * for the other calls. */
int dem_hex8_1pt_geom(const double x[24], dem_hex8_1pt_t *g);

/* Velocity gradient L = (1/V) sum_I v_I (x) b_I (the mean over the element)
 * and the hourglass velocities q_alpha = sum_I v_I gamma_alpha,I. */
void dem_hex8_1pt_rate(dem_hex8_1pt_t *g, const double v[24]);

/* Rate of deformation (engineering shears) and spin w = (W_xy, W_yz, W_zx)
 * from a velocity gradient. */
void dem_hex8_strain_rate(const double L[9], double d[6], double w[3]);

/* Nodal internal forces f (overwritten) from the element stress sig and the
 * generalised hourglass forces Q[12] (conjugate to q; NULL for none):
 * f_I = sig b_I + sum_alpha Q_alpha gamma_alpha,I with b_I = dV/dx_I, so
 * that f . v = V sig : d + Q . q. */
void dem_hex8_1pt_force(const dem_hex8_1pt_t *g, const double sig[6],
			const double Q[12], double f[24]);

/* Hourglass resistance of Flanagan & Belytschko (1981): in their normalised
 * basis the stiffness form has the modal stiffness
 *     ks = kappa_s (lambda + 2 mu) (b . b) / (3 V)
 * and the viscous form the modal damping
 *     cv = kappa_v rho c sqrt((b . b) / 3),
 * with c the dilatational wave speed and b . b = sum_I |dV/dx_I|^2.
 * kappa 0.05-0.15 is usual; either may be zero. */
void dem_hex8_hg_coef(const dem_hex8_1pt_t *g, const dem_mat_t *m,
		      double kappa_s, double kappa_v, double *ks, double *cv);

/* Update the element's hourglass state Qs[12] (stiffness form:
 * Qs += ks dt q) and write the generalised forces Q = Qs + cv q.  Returns
 * the hourglass power Q . q (W).  Qs is not rotated with the element: as
 * in Flanagan & Belytschko, the stiffness form assumes small rotations
 * between the cycles that build it up. */
double dem_hex8_hg_resist(const dem_hex8_1pt_t *g, double ks, double cv,
			  double dt, double Qs[12], double Q[12]);

/* Expanded forms, for tests and stiffness matrices: the uniform gradient
 * B[24] (B_I = b_I / V, component-major as x) and the four normalised
 * hourglass vectors gam[8 alpha + I] (Flanagan & Belytschko's gamma, scaled
 * by 1/sqrt(8)). */
void dem_hex8_1pt_grad(const dem_hex8_1pt_t *g, double B[24]);
void dem_hex8_1pt_gamma(const dem_hex8_1pt_t *g, double gam[32]);

/* One-point stiffness V B^T D B plus the hourglass stiffness
 * ks sum_alpha gamma_alpha gamma_alpha^T (for each direction), 24x24,
 * row-major, dofs component-major like x (dof 8 i + I).  Returns a
 * dem_hex8_1pt_geom() code. */
int dem_hex8_1pt_stiffness(const double x[24], const double D[36], double ks,
			   double K[576]);

/* ---- One-point integration, batched for the explicit loop ------------- */

/* The same kernels for DEM_HEX8_NB elements at once, laid out with the
 * element innermost so that each operation runs across the batch in SIMD
 * lanes: a batch array is double[n][NB] passed as a flat pointer, entry
 * [k][e] at k * NB + e (x, v, f: k = 8 i + I for component i of node I;
 * sig: k = 0..5; Q, Qs: k = 3 alpha + i).  A driver keeps its element state
 * in the same blocked layout (blocks of NB elements: sig[6][NB], ep[NB],
 * Qs[12][NB]) and for each block gathers x and v, calls _kin, then
 * dem_mat_update_batch(m, dt, b.d[0], b.w[0], sig, ep, wp), then _hg and
 * _force, and scatters f.  A short last block is padded with copies of a
 * valid element (whose forces are dropped).  Results equal the scalar
 * kernels' to round-off (the test checks 1e-13).  On x86-64 with GCC the
 * batch functions are also compiled for AVX2 and chosen at load time. */
#define DEM_HEX8_NB DEM_MAT_NB

typedef struct dem_hex8_batch {
	double a[8][3][DEM_HEX8_NB];  /* modal coefficients a1..a7 of x */
	double c[8][3][DEM_HEX8_NB];  /* volume gradient modes c1..c6 */
	double vol[DEM_HEX8_NB];
	double bb[DEM_HEX8_NB];       /* b . b = sum_I |dV/dx_I|^2 */
	double L[9][DEM_HEX8_NB];     /* velocity gradients */
	double d[6][DEM_HEX8_NB];     /* rates of deformation (engineering shears) */
	double w[3][DEM_HEX8_NB];     /* spins W_xy, W_yz, W_zx */
	double q[12][DEM_HEX8_NB];    /* hourglass velocities */
} dem_hex8_batch_t;

/* Geometry and rates of a batch (dem_hex8_1pt_geom + _rate).  Returns a bit
 * mask of the elements that are inverted or degenerate (bit e for element
 * e), 0 when all are sound. */
unsigned dem_hex8_batch_kin(dem_hex8_batch_t *restrict b,
			    const double *restrict x, const double *restrict v);

/* Flanagan-Belytschko hourglass resistance of a batch (dem_hex8_hg_coef +
 * dem_hex8_hg_resist): updates the stiffness-form state Qs, writes the
 * generalised forces Q and the hourglass power P of each element.  kscale:
 * NULL, or a factor per element on this step's increment of the stiffness
 * form (the explicit driver's tangent ratio for elements that flow). */
void dem_hex8_batch_hg(const dem_hex8_batch_t *restrict b, const dem_mat_t *m,
		       double kappa_s, double kappa_v, double dt, const double *kscale,
		       double *restrict Qs, double *restrict Q, double *restrict P);

/* Nodal internal forces of a batch (dem_hex8_1pt_force); Q may be NULL. */
void dem_hex8_batch_force(const dem_hex8_batch_t *restrict b,
			  const double *restrict sig, const double *restrict Q,
			  double *restrict f);

/* ---- Full 2x2x2 integration, explicit form ----------------------------- */

/* Gauss points at (+-1/sqrt 3)^3, numbered like the nodes. */
typedef struct dem_hex8_full {
	double a[8][3];     /* modal coefficients of the coordinates */
	double c[8][3];     /* volume gradient modes (for the mean dilatation) */
	double vol;
	double Jinv[8][9];  /* inverse Jacobian d xi_i / d x_j at each Gauss point */
	double wdet[8];     /* weight x det J */
	double L[8][9];     /* velocity gradients at the Gauss points (_rate) */
} dem_hex8_full_t;

/* Returns DEM_HEX8_INVERTED when det J <= 0 at a Gauss point or the centre. */
int dem_hex8_full_geom(const double x[24], dem_hex8_full_t *g);

/* Velocity gradients at the Gauss points.  bbar != 0: the mean dilatation
 * of Hughes (1980), the trace of each L replaced by the element mean (the
 * one-point value), which keeps the isochoric plastic flow of J2 free of
 * volumetric locking. */
void dem_hex8_full_rate(dem_hex8_full_t *g, const double v[24], int bbar);

/* Nodal internal forces from the Gauss point stresses sig[6 p + k], with
 * the same bbar choice as the rate. */
void dem_hex8_full_force(const dem_hex8_full_t *g, const double sig[48],
			 int bbar, double f[24]);

/* ---- Implicit (static, small strain) ----------------------------------- */

typedef enum dem_hex8_rule {
	DEM_HEX8_FULL = 0,  /* 2x2x2 Gauss, plain displacement element */
	DEM_HEX8_BBAR = 1,  /* 2x2x2 with the mean dilatation (Hughes 1980) */
	DEM_HEX8_EAS = 2    /* 2x2x2 with nine incompatible modes: Wilson's modes
			     * 1 - xi^2, 1 - eta^2, 1 - zeta^2 for each
			     * displacement component, with the Jacobian of the
			     * centre and the det J0 / det J scaling that makes them
			     * pass the patch test (Taylor, Beresford & Wilson
			     * 1976; the Q1/E9 enhanced strain element of Simo &
			     * Rifai 1990).  Exact in pure bending of rectangular
			     * elements; no locking in thin layers. */
} dem_hex8_rule_t;

/* Converged state of one element (the history): Gauss point stresses,
 * effective plastic strains, incompatible-mode amplitudes (EAS only). */
typedef struct dem_hex8_hist {
	double sig[48];
	double ep[8];
	double alpha[9];
} dem_hex8_hist_t;

/* Internal force and tangent stiffness of an element with reference
 * coordinates X for the displacement increment du since the converged
 * state hn.  h receives the state at the end of the increment; h->alpha is
 * read as the starting guess of the local iteration for the incompatible
 * modes (pass the previous iterate, or hn->alpha) and returns converged, so
 * that the modes are condensed exactly for any material.  fint[24]
 * = int B^T sig dV, K[576] the condensed consistent tangent (row-major;
 * NULL to skip), *wp the plastic work of the increment over the element
 * (J; NULL to skip);
 * fint and K use the component-major dof order of x (dof 8 i + I).  Initial
 * stresses (Ch. 8.5) are simply hn->sig: with du = 0 the assembled -fint is
 * the equivalent load of Eq. 8.4, and lambda hn->sig that of Eq. 8.9.
 * Returns DEM_HEX8_OK, DEM_HEX8_INVERTED or DEM_HEX8_NOCONV. */
int dem_hex8_static(const dem_mat_t *m, dem_hex8_rule_t rule, const double X[24],
		    const double du[24], const dem_hex8_hist_t *hn,
		    dem_hex8_hist_t *h, double fint[24], double K[576], double *wp);

/* The last step of dem_hex8_static and dem_hex8_large: from the element
 * system of the pseudo-nodes (Kf, rows nd long; residual r; dofs 3 n + i,
 * the 3 incompatible modes last), with eas the static condensation of the
 * modes (K = Kuu - Kua Kaa^-1 Kau, f = r_u - Kua Kaa^-1 r_a, in place),
 * then fint and K[576] of the nodes in dof order 8 i + I.  Returns
 * DEM_HEX8_OK, or DEM_HEX8_NOCONV when Kaa is singular. */
int dem_hex8_condense(int eas, double *Kf, int nd, double *r, double fint[24],
		      double K[576]);

/* For the implicit elements built on this one (dem_hex8_static and
 * dem_hex8_large): the reference gradients at Gauss point p of g, b[0..7]
 * those of the 8 shape functions (J^-T grad_xi N_I) and, with eas, b[8..10]
 * those of the incompatible modes 1 - xi_m^2, mapped with the centre
 * Jacobian's inverse J0i and scaled by j0 / det J (its determinant over
 * the point's): the patch test holds. */
void dem_hex8_grads(const dem_hex8_full_t *g, int p, int eas, double j0,
		    const double J0i[9], double b[][3]);

/* The local iteration on the mode amplitudes alpha that makes their
 * residual r_a vanish, with backtracking (a plastic Gauss point switching
 * between loading and unloading can make the plain iteration cycle): per
 * iteration it (from 0, at most DEM_HEX8_MODES_MAXIT), after r_a,
 * dem_hex8_modes_check says DONE (converged: |r_a| negligible against the
 * element's stress resultant ref, in N, of an element of volume vol and
 * modulus E), HALVED (the step did not reduce |r_a|: alpha set back along
 * it, evaluate again) or NEWTON: the caller assembles K_aa and
 * dem_hex8_modes_newton solves K_aa dalpha = -r_a and sets alpha
 * (DEM_HEX8_NOCONV when K_aa is singular).  mi starts as { .step = 1 }. */
#define DEM_HEX8_MODES_MAXIT 60
enum { DEM_HEX8_MODES_DONE, DEM_HEX8_MODES_HALVED, DEM_HEX8_MODES_NEWTON };
typedef struct dem_hex8_modes {
	double rn, rprev, step, a0[9], da[9];
} dem_hex8_modes_t;
int dem_hex8_modes_check(dem_hex8_modes_t *mi, int it, const double ra[9],
			 double ref, double vol, double E, double alpha[9]);
int dem_hex8_modes_newton(dem_hex8_modes_t *mi, double Kaa[81], const double ra[9],
			  double alpha[9]);

/* ---- Helpers ------------------------------------------------------------ */

/* Coordinates of the 8 Gauss points (component-major, as x), for mapping
 * profiles onto them by depth (Ch. 8.5.1). */
void dem_hex8_gauss_points(const double x[24], double xg[24]);

/* Lumped (row-sum) nodal masses rho int N_I dV, exact for the trilinear
 * element; returns a dem_hex8_full_geom() code. */
int dem_hex8_lumped_mass(const double x[24], double rho, double mass[8]);

/* Critical time step of the element, dt = l / c with the characteristic
 * length l = V / (largest face area) and c the dilatational wave speed
 * sqrt((K + 4G/3)/rho).  Returns DEM_HEX8_INVERTED (and *dt = 0) for a bad
 * element. */
int dem_hex8_dt_crit(const double x[24], double c, double *dt);

#endif
