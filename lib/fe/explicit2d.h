/* explicit2d.h - explicit dynamics of a 2D finite element workpiece
 * (Ch. 7.4: plane strain; Ch. 7.5.1: axisymmetric): the quad4 elements of
 * quad4.h on a structured mesh (mesh/mesh2.h), made of the J2 material of
 * material.h, integrated in time by the central difference method with a
 * lumped mass matrix.  The 2D twin of explicit.h, with the same step, the
 * same options and the same energies; a driver adds the contact forces of
 * disks (contact/disk.h) through the load hook (Eq. 7.1).
 *
 * Modes (quad4.h).  PLANE: plane strain, a slab of thickness t; masses,
 * forces and energies are those of the slab (t = 1 m gives them per metre,
 * the unit of a 2D contact law, law.h dim = 2).  AXISYM: x = r >= 0,
 * y = z; masses, forces and energies are those of the full ring (2 pi r),
 * so a nodal force is the whole force on its ring and the force a rigid
 * shot on the axis feels.  A node on the axis (reference r = 0) has u_r = 0
 * held whatever mesh->fix says: its radial velocity is set to zero before
 * every step, and a radial velocity given there is dropped.
 *
 * The step (explicit.h, Eqs. 1.2-1.9).  The state at the start of step n
 * is t_n, x_n, the half-step velocities v_{n-1/2} (at the very start v_0)
 * and F_in(x_n).  A step of length dt_{n+1}:
 *   1. external forces at t_n on x_n: the pressure loads and the load hook;
 *   2. velocities (Eq. 1.6 with C = alpha M, variable step Eq. 1.5, the
 *      first step Eq. 1.9):
 *        v_{n+1/2} = [(2 - alpha dt_n) v_{n-1/2} + 2 dt_{n+1/2} M^-1 F]
 *                    / (2 + alpha dt_{n+1}),  F = F_ex - F_in;
 *      a constrained degree of freedom (mesh->fix) keeps the velocity it
 *      has in dem_fe2_velocity(): zero unless the caller prescribes one;
 *   3. coordinates x_{n+1} = x_n + dt_{n+1} v_{n+1/2} (Eq. 1.7);
 *   4. the elements on x_{n+1} (large strain) or on the reference
 *      coordinates (small strain): rate of deformation from v_{n+1/2}
 *      (dem_quad4_strain_rate: the out-of-plane rate zero in plane strain,
 *      the hoop rate u_r / r in axisymmetry), stress update, hourglass
 *      resistance, F_in(x_{n+1}) (Eq. 1.8).
 *
 * Elements.  DEM_FE_1PT: one point with the hourglass control of Flanagan
 * & Belytschko (1981), kappa matched to hex8's (dem_quad4_hg_coef), and
 * with hg_tangent the stiffness form's loading increments scaled by the
 * tangent shear ratio in elements that flow, as explicit.c does.
 * DEM_FE_FULL: 2x2 Gauss points with the mean dilatation (B-bar).  Element
 * by element, one thread: the order of every sum is fixed, results are
 * reproducible bit for bit.
 *
 * Strain.  As explicit.h: small strain keeps the reference geometry
 * (strains B(X) u); large strain (updated Lagrangian) takes rates and
 * forces on the current coordinates and rotates the stress (and the
 * back-stresses) with the Jaumann rate of the in-plane spin W_xy
 * (dem_mat_jaumann), and the reported strain is the rate of deformation
 * integrated and rotated the same way.
 *
 * Damping.  C = alpha M, alpha in 1/s; dem_fe2_damping_alpha is the 2D
 * reading of dem_fe_damping_alpha: a damping ratio xi in the lowest mode of
 * a block of thickness H fixed at the bottom with roller sides, the
 * quarter-wave shear mode through the thickness, omega_1 = pi c_s / (2 H),
 * the same in plane strain and (for a block wide against H) axisymmetry:
 * alpha = 2 xi omega_1.
 *
 * Time step.  dt_factor (default 0.9) times the least element step
 * dem_quad4_dt_crit (A / longest edge over the dilatational speed; for
 * AXISYM with the hoop margin near the axis: quad4.h measures the free
 * meshes' limits against it).  In large strain it is taken again from
 * every element's current shape after each step.
 *
 * Energies (at t_n, one step behind the state; dem_fe2_energy), the forms
 * of explicit.h: kinetic 1/2 v_{n-1/2} M v_{n+1/2} (at the start with
 * v_{-1/2} = v_0 - dt/2 M^-1 F_0), internal (stress work by the
 * trapezoidal rule per element or Gauss point; elastic + plastic), plastic,
 * hourglass (the stiffness form by the trapezoidal rule, plus the viscous
 * form), damping (work against C v) and external (pressure loads, the load
 * hook, the reactions of constrained degrees of freedom that move;
 * trapezoidal).  balance = kinetic + internal + hourglass + damping -
 * external - kinetic(0).  In plane strain sigma_zz is carried but does no
 * work (quad4.h).
 *
 * A failed step (inverted element, a node driven to r < 0) returns
 * DEM_ENUMERIC naming the element, its grid indices and the time; the
 * elements that failed keep their previous state, everything stays finite,
 * and further steps fail with the same error.
 */
#ifndef DEM_FE_EXPLICIT2D_H
#define DEM_FE_EXPLICIT2D_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "core/error.h"
#include "fe/explicit.h"
#include "fe/material.h"
#include "fe/quad4.h"
#include "mesh/mesh2.h"

typedef struct dem_fe2_opts {
	dem_quad4_mode_t mode;  /* DEM_QUAD4_PLANE or DEM_QUAD4_AXISYM */
	double thick;       /* PLANE: the thickness t (m), > 0; ignored for AXISYM */
	dem_fe_rule_t rule; /* DEM_FE_1PT or DEM_FE_FULL (2x2 with B-bar) */
	int large;          /* 0: small strain; 1: updated Lagrangian (Jaumann) */
	double dt_factor;   /* safety factor on the stable step, in (0, 1] */
	double damping;     /* alpha of C = alpha M (1/s), >= 0 */
	double hg_stiff;    /* kappa of the stiffness form of the hourglass control */
	double hg_visc;     /* kappa of the viscous form */
	int hg_tangent;     /* 1: the stiffness form grows by the tangent shear
			     * ratio in elements that flow (explicit.h) */
} dem_fe2_opts_t;

/* Defaults: PLANE with t = 1 m, DEM_FE_1PT, small strain, dt_factor 0.9,
 * no damping, hg_stiff 0.1, hg_visc 0, hg_tangent 1 (explicit.h's). */
void dem_fe2_opts_default(dem_fe2_opts_t *o);

/* alpha = 2 xi omega_1, omega_1 = pi c_s / (2 H) (see above). */
double dem_fe2_damping_alpha(const dem_mat_t *m, double xi, double H);

typedef struct dem_fe2 dem_fe2_t;

/* Build the model of a mesh (constraints from mesh->fix, plus u_r = 0 on
 * the axis for AXISYM) and a material (needs rho > 0).  The mesh may be
 * one without grid lines (nx = 0: mesh2.h's disk, the FE shot of
 * shot/feshot2d.h); its elements are then named by number alone.  Both are borrowed:
 * they must outlive the model and not change.  Starts at t = 0 at rest,
 * stress-free.  DEM_EINPUT for a bad option, a degenerate element or (for
 * AXISYM) a node at r < 0; DEM_EIO when out of memory. */
int dem_fe2_create(dem_fe2_t **fe, const dem_mesh2_t *mesh, const dem_mat_t *mat,
		   const dem_fe2_opts_t *o, dem_error_t *e);
void dem_fe2_free(dem_fe2_t *fe);

/* ---- Loads ----------------------------------------------------------- */

/* A pressure p(t) (Pa, positive pushing into the body) on a set of
 * boundary segments seg[2 s + 0..1] (node numbers A, B, the outside on the
 * left of A -> B as contact/disk.h has it: dem_mesh2_top_segments), p(t)
 * piecewise linear through (t[i], p[i]) as dem_fe_add_pressure's.  The
 * nodal forces are p L w / 2 on each node in plane strain (w = t); in
 * axisymmetry, with the 2x2 rule the consistent ones, p L 2 pi (2 r_A +
 * r_B) / 6 on A and p L 2 pi (r_A + 2 r_B) / 6 on B (the ring's area
 * weighted by the shape functions), and with the one-point rule p L 2 pi
 * r_m / 2 on each, r_m the segment's middle: the one-point element
 * integrates its internal forces with the ring 2 pi r0 of its centre, and
 * against those forces only this load makes a uniform stress an exact
 * static state (at a node on the axis the consistent load is 2/3 of what
 * the element's uniform sigma_zz pushes back with); along the inward
 * normal (current coordinates in large strain).  Copied; several sets may be added.  DEM_EINPUT for a
 * bad node number or time table. */
int dem_fe2_add_pressure(dem_fe2_t *fe, size_t nseg, const uint32_t *seg, size_t nt,
			 const double *t, const double *p, dem_error_t *e);

/* The hook for contact forces: as dem_fe_load_fn with 2 components per
 * node (x, v, f: x and y interleaved; f zero on entry, forces of the slab
 * or the whole ring, like the nodal masses).  Non-zero return: the step
 * stops before changing anything and returns that code. */
typedef dem_fe_load_fn dem_fe2_load_fn;
void dem_fe2_set_load(dem_fe2_t *fe, dem_fe2_load_fn fn, void *ctx);

/* ---- Time stepping ----------------------------------------------------- */

/* The stable step for the current shape (dt_factor included). */
double dem_fe2_dt(const dem_fe2_t *fe);

/* Advance one step of length dt (dt <= 0: dem_fe2_dt()).  DEM_ENUMERIC for
 * an inverted or degenerate element, or an error of the load hook. */
int dem_fe2_step(dem_fe2_t *fe, double dt, dem_error_t *e);

/* ---- State ------------------------------------------------------------- */

double dem_fe2_time(const dem_fe2_t *fe);
long dem_fe2_steps(const dem_fe2_t *fe);

/* Current coordinates, 2 per node (x, y interleaved). */
const double *dem_fe2_coords(const dem_fe2_t *fe);

/* The velocities, 2 per node: v_{n-1/2} after n steps, v_0 before the
 * first.  Writable: initial velocities before the first step, or the
 * velocity of a constrained degree of freedom for the next step (a
 * prescribed motion); not the radial one on the axis (held at zero). */
double *dem_fe2_velocity(dem_fe2_t *fe);

/* Lumped nodal masses (kg): of the slab, or of the ring. */
const double *dem_fe2_mass(const dem_fe2_t *fe);

/* Node displacements u = x - X, 2 per node. */
void dem_fe2_displacements(const dem_fe2_t *fe, double *u);

/* Element fields, element-numbered as the mesh; any pointer may be NULL:
 * sig (6 per element, Voigt xx, yy, zz, xy, yz, zx, Pa; zz out of plane or
 * hoop), eps (6, engineering shears), ep (1).  For DEM_FE_FULL, volume
 * averages over the Gauss points.  Small strain: eps = B(X) u (zz 0 in
 * plane strain, u_r / r at the centre in axisymmetry); large strain: the
 * integrated, rotated rate of deformation. */
void dem_fe2_fields(const dem_fe2_t *fe, double *sig, double *eps, double *ep);

/* Energies (explicit.h's record and meaning). */
void dem_fe2_energy(const dem_fe2_t *fe, dem_fe_energy_t *en);

/* Work counters (explicit.h's record; node_s and elem_s wall clock). */
void dem_fe2_stats(const dem_fe2_t *fe, dem_fe_stats_t *s);

/* Checkpoint: as dem_fe_save / dem_fe_load (explicit.h), the whole
 * time-stepping state, for a model made by dem_fe2_create from the same
 * mesh, material and options; stepping then continues bit for bit as the
 * model that was saved.  Loads (pressures, the hook) are not state: give
 * them again.  Its own magic: a 3D checkpoint is refused, and the other
 * way round.  DEM_EINPUT for a checkpoint of another mesh, material or
 * options, or a truncated or corrupt one; DEM_EIO for a write error.
 * After a failed load the model's state is undefined: free it. */
int dem_fe2_save(const dem_fe2_t *fe, FILE *f, dem_error_t *e);
int dem_fe2_load(dem_fe2_t *fe, FILE *f, dem_error_t *e);

#endif
