/* quad4.h - the 4-node bilinear quadrilateral of the 2D analyses (Ch. 7.4:
 * plane strain; Ch. 7.5.1: the axisymmetric reference of a single impact),
 * with the same integration choices as hex8.h: one point with the
 * hourglass control of Flanagan & Belytschko (1981), or 2x2 Gauss points
 * with or without the mean dilatation (B-bar) of Hughes (1980).
 *
 * Two kinematic modes (dem_quad4_mode_t):
 *   PLANE   plane strain in the x-y plane, thickness t: the out-of-plane
 *           strain (zz) is zero; forces and masses are those of a slab t
 *           thick;
 *   AXISYM  x = r >= 0, y = z (the axis is x = 0): the out-of-plane strain
 *           is the hoop strain u_r / r; forces, masses and volumes are
 *           those of the FULL ring (2 pi r per unit of length, not per
 *           radian), so that a nodal force is the whole force on the ring
 *           of that node, the force a rigid shot on the axis feels.
 * Every kernel sees one measure w of the out-of-plane extent: w = t, or
 * w = 2 pi r (at the point where the integrand is taken); the element's
 * volume is int w dA.
 *
 * Node order: counter-clockwise in the x-y plane; in natural coordinates
 * (xi, eta) the nodes are 0 (-,-), 1 (+,-), 2 (+,+), 3 (-,+), the bottom
 * face of hex8's node order.  Element arrays are packed component-major:
 * x[0..3] the x (r) coordinates of nodes 0-3, x[4..7] the y (z);
 * velocities, displacements and nodal forces likewise.  Velocity gradients
 * are 2x2, row-major (L[2 i + j] = dv_i/dx_j).
 *
 * Stresses are always the full 3D Voigt 6-vectors of material.h (xx, yy,
 * zz, xy, yz, zx; zz the out-of-plane or hoop stress), so that the J2
 * material of the 3D element (dem_mat_update, the batched update,
 * dem_mat_update_tangent, every hardening and rate law) serves unchanged:
 * a driver builds the 6-component rate of deformation with
 * dem_quad4_strain_rate (zz from the element, yz = zx = 0) and a spin
 * whose only component is W_xy.  In plane strain sigma_zz is carried as a
 * stress like the others (it is nu (sig_xx + sig_yy) while elastic) but
 * does no work.  The yz and zx stresses stay zero.
 *
 * Internal forces are, as in hex8.h, the forces the element needs to hold
 * its stress: M a = f_ext - f_int, and f_int . v is the rate of internal
 * (stress + hourglass) work of the slab or the whole ring.  No function
 * allocates memory.
 *
 * Near the axis.  A node on the axis (r = 0) is allowed; no kernel
 * divides by a nodal radius.  The one-point element takes its hoop strain
 * rate from the centre, v_r(0) / r(0) with r(0) the mean of the nodal
 * radii (> 0 in any element of positive area with r >= 0 at its nodes),
 * so its hoop force on node I is sigma_zz A pi / 2, free of r; the Gauss
 * points of the 2x2 rule lie inside the element, at r > 0.  A node at
 * r < 0 is an error (DEM_QUAD4_INVERTED): a driver holds u_r = 0 on the
 * axis.
 */
#ifndef DEM_FE_QUAD4_H
#define DEM_FE_QUAD4_H

#include "fe/material.h"

/* Return codes (a driver maps a non-zero one to DEM_ENUMERIC with the
 * element's number). */
enum {
	DEM_QUAD4_OK = 0,
	DEM_QUAD4_INVERTED = 1  /* non-positive area or Jacobian determinant at
				 * a point of the rule, a NaN coordinate, or
				 * (AXISYM) a node at r < 0 */
};

typedef enum dem_quad4_mode {
	DEM_QUAD4_PLANE = 0,   /* plane strain, thickness t */
	DEM_QUAD4_AXISYM = 1   /* axisymmetric about x = 0, full ring */
} dem_quad4_mode_t;

/* Natural coordinates of the nodes (+1 or -1). */
extern const double dem_quad4_node_xi[4], dem_quad4_node_eta[4];

/* The 6-component rate of deformation (engineering shears, yz = zx = 0)
 * and spin (W_xy, 0, 0), the arguments of dem_mat_update or
 * dem_mat_update_batch, from an in-plane velocity gradient L and the
 * out-of-plane normal rate zz. */
void dem_quad4_strain_rate(const double L[4], double zz, double d[6], double w[3]);

/* ---- One-point integration (Flanagan & Belytschko 1981) ---------------- */

typedef struct dem_quad4_1pt {
	dem_quad4_mode_t mode;
	double b[8];      /* b_I = dA/dx_I (component-major): the uniform
			   * gradient, A B_I */
	double area;      /* A, exact */
	double r0;        /* x at the centre, the mean of the nodal x */
	double w;         /* t, or 2 pi r0 */
	double vol;       /* w A: the one-point volume */
	double bb;        /* b . b = sum_I |b_I|^2 */
	double gam[4];    /* normalised hourglass vector gamma_I (1/2 of FB's) */
	double L[4];      /* velocity gradient (dem_quad4_1pt_rate) */
	double zz;        /* out-of-plane normal rate: 0, or v_r(0) / r0 */
	double q[2];      /* hourglass velocities q_i = sum_I v_iI gamma_I */
} dem_quad4_1pt_t;

/* Geometry at coordinates x: area, uniform gradient, hourglass vector.
 * t is the thickness (PLANE; ignored for AXISYM).  Returns
 * DEM_QUAD4_INVERTED when the area (so det J at the centre) or t is not
 * positive or not a number, or for AXISYM a node lies at r < 0; the work
 * space is then unfit for the other calls. */
int dem_quad4_1pt_geom(const double x[8], dem_quad4_mode_t mode, double t,
		       dem_quad4_1pt_t *g);

/* Velocity gradient L = (1/A) sum_I v_I (x) b_I, the out-of-plane rate zz
 * and the hourglass velocities q. */
void dem_quad4_1pt_rate(dem_quad4_1pt_t *g, const double v[8]);

/* Nodal internal forces f (overwritten) from the element stress sig and
 * the generalised hourglass forces Q[2] (NULL for none):
 * f_I = w sig b_I (+ sigma_zz A pi / 2 along r for AXISYM) + Q gamma_I,
 * so that f . v = V sig : d + Q . q. */
void dem_quad4_1pt_force(const dem_quad4_1pt_t *g, const double sig[6],
			 const double Q[2], double f[8]);

/* Hourglass resistance with hex8's parameters and meaning
 * (dem_hex8_hg_coef): kappa_s and kappa_v are the scene's hg_stiff and
 * hg_visc, and the coefficients are scaled so that a square element of
 * side h and thickness h resists an in-plane hourglass mode with exactly
 * the nodal forces of hex8's cube of side h (summed over its two faces)
 * under the same kappa:
 *     ks = kappa_s (lambda + 2 mu) w (b . b) / (2 A)
 *     cv = kappa_v rho c w sqrt(b . b)
 * (w = t or 2 pi r0; the test checks the match against hex8.c). */
void dem_quad4_hg_coef(const dem_quad4_1pt_t *g, const dem_mat_t *m,
		       double kappa_s, double kappa_v, double *ks, double *cv);

/* Update the stiffness-form state Qs[2] (Qs += ks dt q) and write
 * Q = Qs + cv q.  Returns the hourglass power Q . q (W).  As in hex8, Qs
 * is not rotated with the element. */
double dem_quad4_hg_resist(const dem_quad4_1pt_t *g, double ks, double cv,
			   double dt, double Qs[2], double Q[2]);

/* One-point stiffness V B^T D B (B the strain-displacement matrix at the
 * centre, with the hoop row 1 / (4 r0) for AXISYM) plus the hourglass
 * stiffness ks gamma gamma^T for each direction: 8x8, row-major, dofs
 * component-major like x (dof 4 i + I).  D is a 6x6 Voigt stiffness
 * (dem_mat_elastic_stiffness).  Returns a dem_quad4_1pt_geom() code. */
int dem_quad4_1pt_stiffness(const double x[8], dem_quad4_mode_t mode, double t,
			    const double D[36], double ks, double K[64]);

/* ---- Full 2x2 integration, explicit form ------------------------------- */

/* Gauss points at (+-1/sqrt 3)^2, numbered like the nodes. */
typedef struct dem_quad4_full {
	dem_quad4_mode_t mode;
	double vol;        /* int w dA (exact: the rule integrates it exactly) */
	double dN[4][8];   /* dN_I/dx_j at Gauss point p: dN[p][4 j + I] */
	double r[4];       /* x at the Gauss points */
	double wdet[4];    /* w(p) det J(p) (Gauss weights are 1) */
	double bv[8];      /* mean volumetric gradient (1/V) int (dN_I/dx + N_I/r
			    * for AXISYM, dN_I/dy) dV, for B-bar */
	double L[4][4];    /* velocity gradients at the Gauss points (_rate) */
	double zz[4];      /* out-of-plane normal rates at the Gauss points */
} dem_quad4_full_t;

/* Returns DEM_QUAD4_INVERTED when det J <= 0 at a Gauss point or the
 * centre (or NaN), or for AXISYM a node lies at r < 0. */
int dem_quad4_full_geom(const double x[8], dem_quad4_mode_t mode, double t,
			dem_quad4_full_t *g);

/* Velocity gradients and out-of-plane rates at the Gauss points.
 * bbar != 0: the mean dilatation, each point's volumetric rate
 * (L_xx + L_yy + zz) replaced by the element mean, the difference spread
 * equally over the three normal rates (so in plane strain zz is then not
 * zero at a point, only on the element's mean: Hughes 1980). */
void dem_quad4_full_rate(dem_quad4_full_t *g, const double v[8], int bbar);

/* Nodal internal forces from the Gauss point stresses sig[6 p + k], with
 * the same bbar choice as the rate. */
void dem_quad4_full_force(const dem_quad4_full_t *g, const double sig[24],
			  int bbar, double f[8]);

/* ---- Implicit (static, small strain) ----------------------------------- */

typedef enum dem_quad4_rule {
	DEM_QUAD4_FULL = 0,  /* 2x2 Gauss, plain displacement element */
	DEM_QUAD4_BBAR = 1   /* 2x2 with the mean dilatation */
} dem_quad4_rule_t;

/* Converged state of an element: Gauss point stresses and effective
 * plastic strains. */
typedef struct dem_quad4_hist {
	double sig[24];
	double ep[4];
} dem_quad4_hist_t;

/* Internal force fint[8] = int B^T sig dV and consistent tangent K[64]
 * (row-major, dof 4 i + I; NULL to skip) of an element with reference
 * coordinates X for the displacement increment du from the converged
 * state hn; h receives the state at the end of the increment, *wp (NULL
 * to skip) the plastic work of the increment over the element (J).  The
 * stress update is dem_mat_update_tangent at each Gauss point (an
 * isotropic law: no back-stresses, as dem_hex8_static).  Returns
 * DEM_QUAD4_OK or DEM_QUAD4_INVERTED. */
int dem_quad4_static(const dem_mat_t *m, dem_quad4_mode_t mode, double t,
		     dem_quad4_rule_t rule, const double X[8], const double du[8],
		     const dem_quad4_hist_t *hn, dem_quad4_hist_t *h,
		     double fint[8], double K[64], double *wp);

/* ---- Helpers ------------------------------------------------------------ */

/* Coordinates of the 4 Gauss points (component-major, as x). */
void dem_quad4_gauss_points(const double x[8], double xg[8]);

/* Lumped (row-sum) nodal masses rho int N_I w dA, exact (2x2 Gauss
 * integrates N r det J exactly): for AXISYM the consistent radial
 * weighting, so a node on the axis gets the mass of its share of the ring,
 * not zero.  Returns a dem_quad4_full_geom() code (masses 0 then). */
int dem_quad4_lumped_mass(const double x[8], dem_quad4_mode_t mode, double t,
			  double rho, double mass[4]);

/* Critical time step dt = l / c with hex8's characteristic length in 2D,
 * l = A / (longest edge) (a square of side h: l = h, the crossing time of
 * the dilatational wave), and c the dilatational wave speed
 * sqrt((K + 4G/3)/rho) (the same in plane strain).  For AXISYM l is
 * further divided by sqrt(1 + s^2), s = 0.2 (r_max - r_min) / r0 (radial
 * extent over mean nodal radius), a margin for the hoop strain, which
 * stiffens the elements next to the axis (a mesh of squares there: 1.109
 * without it, 1.029 with it, at nu = 0.4999).  Like hex8's, the estimate
 * is the mesh's, not a bound of the single free element (whose highest
 * frequency it exceeds by 1.195 for a square at nu = 0.3): the test
 * measures dt omega_max / 2 of whole free meshes of squares, both modes,
 * on and off the axis, every rule: at most 1.011 at nu = 0.3 and 1.098 at
 * nu = 0.4999 (free edges and corners lift omega_max a little above the
 * 2 c / h of an unbounded mesh), stable under explicit.c's default
 * dt_factor 0.9.  Returns DEM_QUAD4_INVERTED (and *dt = 0) for a bad
 * element, c <= 0 or (AXISYM) a node at r < 0. */
int dem_quad4_dt_crit(const double x[8], dem_quad4_mode_t mode, double c, double *dt);

#endif
