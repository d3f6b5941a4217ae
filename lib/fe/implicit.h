/* implicit.h - the implicit static stage of peen forming (Ch. 8.5): a
 * plate of hexahedra given the residual profiles of peening as initial
 * conditions, brought to equilibrium by Newton-Raphson.
 *
 * A dem_form_t holds the plate (a structured mesh from mesh.h, thickness
 * along z, the peened face on top), the material, the displacements and
 * the element histories (Gauss point stresses, effective plastic strains,
 * incompatible-mode amplitudes), and the sparse linear system: a symmetric
 * CSC matrix whose pattern comes once from the structured mesh, factorised
 * by CHOLMOD (supernodal; analysed once per set of constraints, factorised
 * at every Newton iteration).
 *
 * A job is one or more steps (Ch. 8.5.3).  Each step maps its profiles onto
 * the Gauss points by depth below the face they were peened on
 * (dem_form_profile: linear interpolation, Ch. 8.5.1), sets its constraints,
 * and solves (dem_form_step).  The step's initial stresses sbar enter
 * through the pseudo-load factor lambda of Eqs. 8.6-8.9: each increment adds
 * dlambda sbar to the converged stresses and Newton restores equilibrium,
 *   int B^T sigma_n dV = 0,  sigma_n = sigma_{n-1}* + dlambda sbar + d(dsigma),
 * an increment that fails to converge being cut back (halved) from the last
 * converged state.  Small strain (dem_hex8_static) or large strain (total
 * Lagrangian, dem_hex8_large).  No external loads: the residual is -f_int.
 */
#ifndef DEM_FE_IMPLICIT_H
#define DEM_FE_IMPLICIT_H

#include <stddef.h>

#include "core/error.h"
#include "fe/hex8.h"
#include "io/profile.h"
#include "mesh/mesh.h"

typedef struct dem_form dem_form_t;

/* The plate: size L x W x h centred on x, y, z in [-h, 0] (top face z = 0
 * peened).  In-plane elements of about dxy; nz layers whose thickness grows
 * geometrically by `grade` per layer away from the peened face(s) (both
 * faces when two_sided: layers symmetric about the mid-plane). */
typedef struct dem_plate {
	double L, W, h;
	double dxy;
	int nz;
	double grade;
	int two_sided;
} dem_plate_t;

/* Build the plate's mesh (dem_mesh_free it). */
int dem_plate_mesh(const dem_plate_t *p, dem_mesh_t *mesh, dem_error_t *e);

/* How a profile initialises the plate (Ch. 8.5.1): the stress with the
 * effective plastic strain, or the total strain with it.  With the strain,
 * the profile's strain is imposed as an initial (eigen)strain: the plate is
 * held undeformed, which takes the stress -D eps. */
typedef enum dem_form_init { DEM_FORM_SIGMA = 0, DEM_FORM_STRAIN = 1 } dem_form_init_t;

/* Where a profile goes: the face it was peened on and a rectangle of it
 * (Gauss points with x0 <= x <= x1 and y0 <= y <= y1; use +-HUGE_VAL for the
 * whole face). */
typedef struct dem_form_region {
	int bottom;              /* 0: top face z = 0; 1: bottom face z = -h */
	double x0, x1, y0, y1;
} dem_form_region_t;

/* Solution controls. */
typedef struct dem_form_opts {
	int large;               /* geometric nonlinearity (total Lagrangian) */
	dem_hex8_rule_t rule;    /* DEM_HEX8_EAS (default), _FULL; _BBAR small strain only */
	double tol;              /* converged when |R| <= tol |F| (F: the step's
				  * equivalent load, Eq. 8.5, or the largest of the
				  * job's steps if larger); default 1e-8 */
	int maxit;               /* Newton iterations per increment before a cut-back (12) */
	int ninc;                /* initial increments of lambda (1) */
	int maxcut;              /* successive cut-backs allowed for one increment (10);
				  * a cut increment doubles again after each one
				  * that converges in fewer than maxit iterations */
	/* Called after every Newton iteration (may be NULL). */
	void (*log)(void *ctx, int step, int inc, double lambda, int iter,
		    double rnorm, double rrel, double dunorm);
	void *ctx;
} dem_form_opts_t;

void dem_form_opts_default(dem_form_opts_t *o);

/* What a step (and the job so far) cost and reached. */
typedef struct dem_form_stats {
	int increments, cutbacks, iterations, factorisations;
	double rnorm, rrel;      /* residual of the last converged iteration (N, relative) */
	double fnorm;            /* |F| of the step (N) */
	double assemble_s, factor_s, solve_s;
	double lambda;           /* reached load factor (1 on success) */
	size_t neq;              /* equations (free dofs) */
	double lnz, flops;       /* nonzeros of the factor, flops of one factorisation */
} dem_form_stats_t;

/* Create a plate model on mesh (borrowed; it must outlive f) of material m
 * (borrowed).  DEM_EIO when out of memory. */
int dem_form_create(dem_form_t **f, const dem_mesh_t *mesh, const dem_mat_t *m,
		    dem_error_t *e);
void dem_form_free(dem_form_t *f);

/* Add a profile to the next step's initial conditions over region r, scaled
 * by `scale`: its stress (or, for DEM_FORM_STRAIN, -D eps) joins the step's
 * sbar; the effective plastic strain of the history is raised to the
 * profile's where that is larger.  Profiles of one step add up. */
int dem_form_profile(dem_form_t *f, const dem_profile_t *p, const dem_form_region_t *r,
		     dem_form_init_t mode, double scale, dem_error_t *e);

/* Constraints of the next step: the six faces' conditions (mesh.h; NULL:
 * all free) and, when minimal is set, the 6 rigid-body modes removed at
 * three nodes of the mid-plane (the centre: x y z; the centre of the +x
 * edge: y z; the centre of the +y edge: z), which leaves a free plate free. */
void dem_form_constrain(dem_form_t *f, const dem_bc_t bc[6], int minimal);

/* Plane strain along y for the next step (call after dem_form_constrain):
 * u_y held at zero at every node, so eps_yy = 0 and the plate bends about
 * y only, as the plane-strain strip of a 2D block does.  The profile's
 * syy is then the stress of that constraint, carried by its reactions:
 * it bends nothing.  With uniform profiles the curvature is
 * kappa_x = -12 int sxx z dz / (E' h^3), E' = E / (1 - nu^2) (z from the
 * mid-plane). */
void dem_form_plane_strain(dem_form_t *f);

/* Threads of the static stage: n > 0 sets the OpenMP threads of the
 * assembly and, when the BLAS under CHOLMOD is OpenBLAS (found at run time
 * by its openblas_set_num_threads), its threads too; n <= 0 changes
 * nothing.  Returns the BLAS's threads after the call (1 for a sequential
 * OpenBLAS), 0 when the BLAS is not OpenBLAS (its threads unknown). */
int dem_form_threads(int n);

/* Solve one step: lambda from 0 to 1 in o->ninc increments, cut back on
 * divergence.  st accumulates (zero it before the first step).  Returns
 * DEM_OK, or DEM_ENUMERIC when the step cannot be completed (the model
 * keeps the last converged state, st->lambda says how far it got). */
int dem_form_step(dem_form_t *f, const dem_form_opts_t *o, dem_form_stats_t *st,
		  dem_error_t *e);

/* ---- Results ---------------------------------------------------------- */

/* Displacements, 3 per node (x, y, z), of the last converged state. */
const double *dem_form_disp(const dem_form_t *f);

/* Histories of the last converged state (one per element). */
const dem_hex8_hist_t *dem_form_hist(const dem_form_t *f);

/* Out-of-plane results of the mid-surface, whose deflection w is the mean
 * of the top and bottom faces' (free of the change of thickness).
 * Curvatures k = -d2w/dx2 etc. fitted by least squares to
 *   w = a + b x + c y - (kx x^2 + ky y^2 + 2 kxy x y)/2
 * over the nodes with |x| <= fx L/2 and |y| <= fy W/2 (fx, fy in (0, 1];
 * x, y of the reference configuration in small strain, of the deformed one
 * in large strain), positive when the top (peened) face is convex.  Arc
 * height over a chord of length c along x (axis 0) or y (axis 1) through
 * the centre: the centre's w less the mean of the w at the chord's ends
 * (interpolated along the centre line); maximum deflection: max w - min w. */
typedef struct dem_form_shape {
	double kx, ky, kxy;
	double arc;              /* over the chord */
	double wmax;             /* max - min of w */
} dem_form_shape_t;

int dem_form_shape(const dem_form_t *f, double chord, int axis, double fx, double fy,
		   dem_form_shape_t *s, dem_error_t *e);

/* What an Almen gauge (SAE J442) reads on the plate: the plate rests with
 * the face opposite the peened one (the bottom, z = -h) on four balls at
 * the corners of an lx x ly rectangle centred on the plate's centre (sides
 * along x and y), and the indicator touches that face at the centre.
 * *height is the distance of the face's centre from the plane of the four
 * contacts (their least-squares plane, exact when they are coplanar),
 * along its normal; positive when the peened face is convex.  For
 * w = -(kx x^2 + ky y^2)/2 it is kx lx^2/8 + ky ly^2/8.  The balls are
 * points at fixed x, y (reference coordinates, also in large strain): a
 * ball of radius r touches a face of slope s a little off its centre,
 * which lowers the reading by about r s^2 / 2 (not modelled).  DEM_EINPUT
 * when the rectangle is not on the plate. */
int dem_form_gauge(const dem_form_t *f, double lx, double ly, double *height,
		   dem_error_t *e);

/* The stress through the thickness at the plate centre: the Gauss points of
 * the elements around (0, 0) averaged at each Gauss depth (2 per layer);
 * *n (<= 2 nz) points, depth below the top face, stress (6, Pa; S in large
 * strain, equal to Cauchy to the order of the strain at the centre, where
 * the plate does not rotate) and ep.  Arrays of 2 nz entries. */
void dem_form_centre_profile(const dem_form_t *f, int *n, double *depth, double *sig,
			     double *ep);

#endif
