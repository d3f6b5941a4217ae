/* feshot2d.h - a finite element shot against the top edge of a plane
 * strain block (Han 2004, Ch. 7.4: the FE analysis the rigid DE disk is
 * compared with): the disk meshed with quadrilaterals (the O-grid of
 * mesh2.h's dem_mesh2_disk), an elastic body of its own (a second model of
 * fe/explicit2d.h, its own material: Ch. 7.4 takes E_s = 100 E to stand
 * for a rigid shot), in penalty contact with the block.
 *
 * Contact: node to segment (contact/node2d.h), both ways.  The shot's rim
 * nodes against the block's top segments, and the block's top nodes
 * against the shot's rim segments, each pass with half the penalty, so
 * that where both surfaces touch the pressure is the penalty's and
 * neither surface's nodes can pass through the other's segments (the
 * thesis used node to node, whose force history it found oscillating;
 * one pass alone lets the other surface's nodes into the gaps between the
 * slave nodes, by the chords' sagitta, h^2 / 8R, as much as the
 * penetration itself for h = 1 mm, R = 20 mm).
 *
 * The penalty, and its units.  A touching node of tributary length l
 * (half its two surface segments, in the reference state) carries the
 * normal force (1/2) k_w g l t (g the penetration, t the slab's thickness):
 * the pressure k_w g, a Winkler foundation of stiffness k_w (Pa/m) between
 * the surfaces.  A rigid disk pressed by delta into such a layer on a
 * rigid flat meets F = k_w S, S = 4/3 sqrt(2R) delta^(3/2) to small delta
 * (Eqs. 3.34-3.39), the 2D power law of m = 3/2.  So k_w is taken from the
 * scene's 2D law (law.h, dim 2: F = alpha E R^(-1/2) delta^(3/2) per unit
 * thickness) as the foundation that gives that law, dem_law_winkler2d_alpha
 * inverted: k_w = 3 alpha E / (4 sqrt(2) R).  alpha stays dimensionless and
 * the same number as the DE disk's, and the FE shot and the DE disk meet
 * the same force for the same overlap: their difference is the shot's
 * elasticity and its facets.  For Ch. 7.4's alpha_t = 2.5 (the thesis's
 * Hertz alpha, per mm; alpha = 50 here for R = 20 mm) k_w = 1.33 E per
 * mm; the thesis's node-to-node spring k_n = alpha_t E per node (per unit
 * thickness) at a node spacing h is the foundation alpha_t E / h, the same
 * at h = 1.9 mm (its spacing is not given).  Only the law m = 3/2 has this
 * form; another m is refused.  Damping (the scene's contact damping, Eqs. 3.70-3.76): each
 * touching node the dash-pot 2 xi sqrt(K m_eff) on its normal velocity
 * relative to the segment's foot, K its spring, m_eff of the node and the
 * segment's share of mass (Eq. 3.75), repulsive only: the contact kernel
 * of model.h with the linear law.  No friction (Ch. 7.4 has none).
 *
 * Step.  The block's load hook (dem_fe2_load_fn) takes the contact forces
 * at t_n on both bodies (x_n of both), adds the block's, and advances the
 * shot's model by the same dt with its own; the two models so step in
 * lockstep.  The step (dem_feshot2d_dt) is the shot model's stable one
 * (E_s = 100 E: a tenth of the block's for elements of the same size)
 * and the penalty's: each surface node carries about k_w l t, of its own
 * pass and its share of the other, so a pair of nodes is the spring k_w t
 * (l_b + l_s) / 2 between masses m_b and m_s, and the step is kept below
 * dt_factor 2 / omega (sqrt(1 + xi^2) - xi), omega^2 = k_w t (l_b / m_b +
 * l_s / m_s), the largest ratios of each surface.
 *
 * The shot's summary (dem_shot_body_t): x and v its centre of mass and
 * mean velocity, F the resultant contact force on it at t_n, Fn its
 * magnitude (no friction: all normal), contacts the node pairs touching.
 */
#ifndef DEM_SHOT_FESHOT2D_H
#define DEM_SHOT_FESHOT2D_H

#include <stddef.h>

#include "contact/model.h"
#include "core/error.h"
#include "fe/explicit2d.h"
#include "mesh/mesh2.h"
#include "shot/shotset.h"

typedef struct dem_feshot2d_opts {
	double element;        /* the O-grid's element size h at the rim (m), > 0 */
	double E, nu, rho;     /* the shot's elastic material (Pa, -, kg/m^3) */
	dem_fe2_opts_t fe;     /* the shot model's options (PLANE, the slab's
				* thickness; damping is not used: 0) */
} dem_feshot2d_opts_t;

typedef struct dem_feshot2d dem_feshot2d_t;

/* The FE shot's side of a block: the block's mesh and lumped masses
 * (borrowed, as dem_shotset2d_create's), the scene's contact model (its
 * 2D law m = 3/2 gives the penalty, its viscous damping the contact's;
 * copied).  DEM_EINPUT for a bad option, a law not 2D or not m = 3/2,
 * friction or hysteresis; DEM_EIO without memory. */
int dem_feshot2d_create(dem_feshot2d_t **F, const dem_mesh2_t *block, const double *block_mass,
			const dem_contact_model_t *cm, const dem_feshot2d_opts_t *o, dem_error_t *e);
void dem_feshot2d_free(dem_feshot2d_t *F);

/* A new shot of radius R, centre c, velocity v (2 each), at rest inside
 * and stress-free: its mesh, model and contact sets (the previous shot's
 * dropped).  DEM_EINPUT for a bad radius or mesh. */
int dem_feshot2d_begin(dem_feshot2d_t *F, double R, const double c[2], const double v[2],
		       dem_error_t *e);

/* The step limit (above): the shot model's stable step and the
 * penalty's; HUGE_VAL before the first shot. */
double dem_feshot2d_dt(const dem_feshot2d_t *F);

/* The block's load hook (ctx: the dem_feshot2d_t): contact forces at x_n,
 * the block's added to f, then the shot's model one step of dt. */
int dem_feshot2d_hook(void *ctx, double t, double dt, const double *x, const double *v, double *f,
		      dem_error_t *e);

/* The summary at the last step (above); before the first, the shot as
 * placed. */
void dem_feshot2d_body(const dem_feshot2d_t *F, dem_shot_body_t *b);

/* The shot's model (NULL before the first shot), its mesh, and the
 * penalty stiffness k_w (Pa/m) of the current shot. */
const dem_fe2_t *dem_feshot2d_model(const dem_feshot2d_t *F);
const dem_mesh2_t *dem_feshot2d_mesh(const dem_feshot2d_t *F);
double dem_feshot2d_kw(const dem_feshot2d_t *F);

/* The shot's kinetic energy, 1/2 sum m v_{n-1/2}^2 (J, of the slab). */
double dem_feshot2d_kinetic(const dem_feshot2d_t *F);

/* The penalty's energy at the last step, sum 1/2 K g^2 (J). */
double dem_feshot2d_penalty_energy(const dem_feshot2d_t *F);

/* Wall seconds spent in the contact and in the shot model's steps. */
void dem_feshot2d_times(const dem_feshot2d_t *F, double *contact_s, double *model_s);

#endif
