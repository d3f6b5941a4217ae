/* explicit.h - explicit dynamics of the finite element workpiece (Ch. 1.2.4,
 * 7.3): the block of hex8 elements of mesh.h, made of the J2 material of
 * material.h, integrated in time by the central difference method with a
 * lumped mass matrix.  demshot adds the shots' contact forces at every step
 * (Eq. 7.1: M u'' + C u' + F_in = F_ex + F_im).
 *
 * The step (Eqs. 1.2-1.9).  The state at the start of step n is the time
 * t_n, the coordinates x_n, the half-step velocities v_{n-1/2} (at the very
 * start: the initial velocities v_0) and the internal forces F_in(x_n).  A
 * step of length dt_{n+1}:
 *   1. external forces at t_n on x_n: the pressure loads (their time
 *      histories) and the caller's load hook (contact: dem_fe_set_load);
 *   2. velocities (Eq. 1.6 with C = alpha M, for the variable step of
 *      Eq. 1.5; the first step is Eq. 1.9):
 *        v_{n+1/2} = [(2 - alpha dt_n) v_{n-1/2} + 2 dt_{n+1/2} M^-1 F]
 *                    / (2 + alpha dt_{n+1}),  F = F_ex - F_in;
 *      a constrained degree of freedom (mesh->fix) keeps the velocity it
 *      has in dem_fe_velocity(): zero unless the caller prescribes one;
 *      periodic ties (mesh->tie): each tied set of nodes is one set of
 *      degrees of freedom, its master's: the slaves' masses and forces
 *      are the master's, and after this step a slave takes the master's
 *      velocity and its position plus the reference offset (the period);
 *      dem_fe_mass() gives a slave the mass of its set;
 *   3. coordinates x_{n+1} = x_n + dt_{n+1} v_{n+1/2} (Eq. 1.7);
 *   4. the elements on x_{n+1} (large strain) or on the reference
 *      coordinates (small strain): rate of deformation from v_{n+1/2},
 *      stress update, hourglass resistance, F_in(x_{n+1}) (Eq. 1.8).
 *
 * Elements.  DEM_FE_1PT (default): one-point integration with the
 * hourglass control of Flanagan & Belytschko (1981), four elements at a
 * time in SIMD lanes (hex8.h batch kernels).  DEM_FE_FULL: 2x2x2 Gauss
 * integration with the mean dilatation (B-bar, Hughes 1980) against
 * volumetric locking in plastic flow; element by element, dearer.
 *
 * Strain.  Small strain: the geometry stays the reference one, strains are
 * B(X) u.  Large strain (updated Lagrangian): rates of deformation and
 * internal forces on the current coordinates, the stress rotated with the
 * Jaumann rate (dem_mat_update_batch does it); the total strain reported
 * is the rate of deformation integrated in time and rotated the same way
 * (for coaxial stretching, the logarithmic strain).
 * Small strain drops the quadratic part 1/2 H^T H (H = grad u) of the
 * strain, which the elastic strain must dominate: it is fit only while
 * |H|^2 / 2 << sigma_y / E (a rigid rotation theta stresses it by
 * D (cos theta - 1)).  A shot that leaves plastic strains beyond a few
 * percent is not such a case: on the single shot of Ch. 7.5 the residual
 * sxx peaks at -107 MPa in small strain, -179 MPa in large; the two agree
 * (1 %) at 5 m/s, where 1/2 H^T H is 0.1 of the yield strain
 * (examples/cost/STRAIN.md).
 *
 * Damping.  Global mass-proportional damping C = alpha M (Eq. 1.1), alpha
 * in 1/s.  Ch. 7.5 applies "a global damping of 0.05 to all degrees of
 * freedom to damp out the kinetic energy" without defining the number; we
 * read it as a damping ratio xi = 0.05 of critical in the block's lowest
 * mode, alpha = 2 xi omega_1 (mass-proportional damping gives mode i the
 * ratio alpha / (2 omega_i): 5 % in the lowest mode, less above).  For a
 * block of thickness H fixed at the bottom with roller sides the lowest mode
 * is the quarter-wave shear mode through the thickness, omega_1 = pi c_s /
 * (2 H), c_s = sqrt(G / rho); dem_fe_damping_alpha() gives that alpha.  In
 * free vibration the mechanical energy then decays on average like
 * exp(-alpha t) (the damping power is 2 alpha times the kinetic energy,
 * which is half the energy on average).
 *
 * Time step.  The stable step is dt_factor (default 0.9, LS-DYNA's TSSFAC)
 * times the least element step dem_hex8_dt_crit() (l / c, l = volume over
 * the largest face area).  For a uniform mesh of cubes the exact stability
 * limit of the assembled lumped-mass system is 0.94-0.95 times that value
 * (1-point, B-bar and full, nu = 0.33); 0.9 keeps below it.  In large strain
 * each element's estimate follows its current shape (the ratio of its
 * volume to its largest mid-section area, calibrated to dem_hex8_dt_crit at
 * the start) and the step adapts at every cycle.
 *
 * Energies (at t_n, one step behind the state; dem_fe_energy): kinetic
 * 1/2 v_{n-1/2} M v_{n+1/2}, the form the central difference conserves
 * exactly for a linear undamped system at a constant step (1/2 v_n M v_n
 * with the mid-step velocity of Eq. 1.3 swings by tens of percent when
 * modes near the stability limit are excited); at the start v_{-1/2} =
 * v_0 - dt/2 M^-1 F_0, the velocity from which Eq. 1.9 is a central
 * difference step, so that a load acting at t = 0 makes the initial kinetic
 * energy 1/2 v_0 M v_0 - (dt/2)^2 F_0 M^-1 F_0 / 2 (the energy the
 * half-step start misses: 7 % of the work in a coarse sudden-load test);
 * internal (the stress work, by
 * the trapezoidal rule per element; elastic + plastic), plastic (the part
 * dissipated by plastic flow), hourglass (work of the hourglass forces),
 * damping (work against C v) and external (work of the pressure loads, of
 * the load hook and of the reactions of constrained degrees of freedom
 * that move, trapezoidal rule).  balance = kinetic + internal + hourglass
 * + damping - external - initial kinetic: zero for an exact integration.
 *
 * Threads.  The element loop runs over slabs of element layers (along z)
 * in two phases, even slabs then odd slabs: slabs of one phase share no
 * node, so each thread adds its forces to the nodes directly, and the
 * order of the additions at every node is fixed.  The slabs do not depend
 * on the number of threads, nor does any sum (partial sums over fixed
 * chunks, added in order): results are bitwise identical for any number
 * of threads.
 *
 * Ranks (issue 22; lib/par/par.h, MPI with `make MPI=1`).  With a group
 * of P ranks in opts.par, every rank holds the whole mesh and every node
 * and element array (replicated data: the memory is not distributed), but
 * runs only its own contiguous range of the slabs above, ranks bottom to
 * top, and updates only the nodes its elements touch.  After the element
 * loop each rank adds its neighbours' internal forces on the node plane
 * it shares with each (dem_par_halo_sum, the lower rank's part first: both
 * ranks hold the same bits); then one gather brings every rank's record:
 * its slabs' element sums (added in slab order, as one rank does), its
 * nodes' sums (kinetic energy, work; added in rank order) and, from the
 * top rank, the
 * coordinates and velocities of the top surface (z = gz[nz]).  Time step,
 * energies and failures are then the same on every rank, and the load
 * hook and dem_fe_coords()/dem_fe_velocity() see the top surface current
 * on every rank: a hook that reads only the top surface
 * (lib/shot/shotset.c) runs the same on every rank, its forces on other
 * ranks' nodes dropped.  Two messages a step to each neighbour and one
 * gather, whatever the mesh.  Why slabs along z: they are the
 * slabs of the threads already (contiguous element and node ranges, a
 * shared plane is one contiguous range of nodes), the top surface, where
 * the shots act, is then on one rank only, and the hook stays serial code;
 * the price is that P cannot exceed the number of slabs (min(nz, 32), or
 * nz when P > 32) and that the interface is a whole x-y plane.  One rank
 * gives the serial result to the bit; more ranks differ by the order of
 * the additions on the shared planes (round-off).  Other nodes and
 * elements hold stale values on a rank: dem_fe_sync() gathers everything
 * on every rank before the state is read (displacements, fields,
 * checkpoint).  Pressures on faces that are not top-surface faces, in
 * large strain, need coordinates a rank may not hold: refused.  Periodic
 * ties must tie nodes of one plane (the x and y sides).
 *
 * A failed step (inverted element) returns DEM_ENUMERIC naming the element,
 * its grid indices and the time; the state keeps finite values (the blocks
 * with a bad element keep their previous element state) and further steps
 * fail with the same error.
 */
#ifndef DEM_FE_EXPLICIT_H
#define DEM_FE_EXPLICIT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "core/error.h"
#include "fe/material.h"
#include "mesh/mesh.h"
#include "par/par.h"

typedef enum dem_fe_rule {
	DEM_FE_1PT = 0,   /* one point + Flanagan-Belytschko hourglass control */
	DEM_FE_FULL = 1   /* 2x2x2 Gauss with B-bar */
} dem_fe_rule_t;

typedef struct dem_fe_opts {
	dem_fe_rule_t rule;
	int large;          /* 0: small strain; 1: updated Lagrangian (Jaumann) */
	double dt_factor;   /* safety factor on the stable step, in (0, 1] */
	double damping;     /* alpha of C = alpha M (1/s), >= 0 */
	double hg_stiff;    /* kappa of the stiffness form of the hourglass control */
	double hg_visc;     /* kappa of the viscous form */
	int hg_tangent;     /* 1: in an element that flows plastically, the
			     * stiffness form grows on that step with the
			     * tangent shear ratio H / (3G + H) of J2 (beyond
			     * Flanagan & Belytschko, who scale it by the
			     * elastic modulus: then an element flowing under
			     * a shot stores elastic hourglass stress that its
			     * plastic flow cannot, and the surface of a single
			     * impact ends in tension); 0: the elastic modulus */
	int threads;        /* OpenMP threads; 0: OpenMP's default for meshes of
			     * 20000 elements or more, 1 for smaller ones (a
			     * step of a small mesh is shorter than the cost of
			     * waking threads, and on a busy machine a thread
			     * descheduled at a barrier stalls the others) */
	dem_par_t *par;     /* the ranks that share the model (see "Ranks"
			     * above); NULL: this process alone */
} dem_fe_opts_t;

/* Defaults: DEM_FE_1PT, small strain, dt_factor 0.9, no damping,
 * hg_stiff 0.1 (Flanagan & Belytschko recommend 0.05-0.15; the stiffness
 * form resists the static hourglass modes that a residual stress field
 * would otherwise leave free), hg_visc 0, hg_tangent 1, threads 0. */
void dem_fe_opts_default(dem_fe_opts_t *o);

/* alpha = 2 xi omega_1 with omega_1 = pi c_s / (2 H) (see above), for a
 * damping ratio xi (Ch. 7.5: 0.05) and a block of thickness H. */
double dem_fe_damping_alpha(const dem_mat_t *m, double xi, double H);

typedef struct dem_fe dem_fe_t;

/* Build the model of a mesh (constraints from mesh->fix) and a material
 * (needs rho > 0).  Both are borrowed: they must outlive the model and not
 * change.  Starts at t = 0 at rest, stress-free.  DEM_EINPUT for a bad
 * option or a degenerate element of the mesh, DEM_EIO when out of memory. */
int dem_fe_create(dem_fe_t **fe, const dem_mesh_t *mesh, const dem_mat_t *mat,
		  const dem_fe_opts_t *o, dem_error_t *e);
void dem_fe_free(dem_fe_t *fe);

/* ---- Loads ----------------------------------------------------------- */

/* A pressure p(t) (Pa, positive pushing into the body) on a set of
 * quadrilateral faces quad[4 q + 0..3] (node numbers, counter-clockwise
 * seen from outside), p(t) piecewise linear through (t[i], p[i]), i < nt,
 * t non-decreasing (a repeated time is a jump), constant beyond the ends.
 * Each node of a face takes a quarter of p times the face's area vector
 * (current coordinates in large strain).  The arrays are copied; several
 * sets may be added.  DEM_EINPUT for a bad node number or time table. */
int dem_fe_add_pressure(dem_fe_t *fe, size_t nquad, const uint32_t *quad,
			size_t nt, const double *t, const double *p, dem_error_t *e);

/* The faces of the top surface (z = gz[nz]) whose centres lie in the
 * rectangle [x0, x1] x [y0, y1], oriented for dem_fe_add_pressure: writes
 * 4 node numbers per face to quad (unless NULL) and returns the count. */
size_t dem_fe_top_quads(const dem_mesh_t *m, double x0, double x1, double y0,
			double y1, uint32_t *quad);

/* The hook for contact forces (part 2): called at the start of each step
 * with the time t_n, the step dt about to be taken, the current
 * coordinates x (3 per node, x_n), the latest velocities v (v_{n-1/2}) and
 * the force array f (3 per node, zero on entry) to which it adds its nodal
 * forces.  Non-zero return: the step stops before changing anything and
 * returns that code (the hook fills e).  NULL fn: no hook. */
typedef int (*dem_fe_load_fn)(void *ctx, double t, double dt, const double *x,
			      const double *v, double *f, dem_error_t *e);
void dem_fe_set_load(dem_fe_t *fe, dem_fe_load_fn fn, void *ctx);

/* A promise of the hook set last: it adds forces to nodes n0 <= n < n1
 * alone (dem_fe_set_load: any node).  The node loop then reads and clears
 * the external forces of that range alone, plus the pressure loads' nodes:
 * a force the hook adds outside it would be neither applied nor cleared.
 * (The shot contact loads the top plane of nodes, the last of the mesh's
 * numbering: the node loop's traffic of the external forces goes.) */
void dem_fe_set_load_nodes(dem_fe_t *fe, size_t n0, size_t n1);

/* ---- Time stepping ----------------------------------------------------- */

/* The stable step for the current shape (dt_factor included). */
double dem_fe_dt(const dem_fe_t *fe);

/* Advance one step of length dt (dt <= 0: dem_fe_dt()).  DEM_ENUMERIC for
 * an inverted or degenerate element, or an error of the load hook. */
int dem_fe_step(dem_fe_t *fe, double dt, dem_error_t *e);

/* ---- State ------------------------------------------------------------- */

/* With several ranks (opts.par): every rank gets every rank's nodes and
 * elements, so that everything below reads the whole current state.  Does
 * not change the run that follows.  Collective; nothing with one rank. */
void dem_fe_sync(dem_fe_t *fe);

/* The bytes this rank sent in the last step: its halo planes and its
 * record in the gather (the top surface, on the top rank), for the
 * communication model of examples/cost; 0 with one rank. */
double dem_fe_comm_bytes(const dem_fe_t *fe);

double dem_fe_time(const dem_fe_t *fe);
long dem_fe_steps(const dem_fe_t *fe);

/* Current coordinates, 3 per node (x, y, z interleaved). */
const double *dem_fe_coords(const dem_fe_t *fe);

/* The velocities, 3 per node: v_{n-1/2} after n steps, v_0 before the
 * first.  Writable: set initial velocities before the first step, or the
 * velocity of a constrained degree of freedom (mesh->fix) for the next
 * step (a prescribed motion). */
double *dem_fe_velocity(dem_fe_t *fe);

/* Lumped nodal masses (kg), one per node (of a periodic slave or master:
 * the mass of its tied set). */
const double *dem_fe_mass(const dem_fe_t *fe);

/* Node displacements u = x - X, 3 per node. */
void dem_fe_displacements(const dem_fe_t *fe, double *u);

/* Element fields, element-numbered as the mesh; any pointer may be NULL:
 * sig (6 per element, Pa), eps (6, engineering shears), ep (1, effective
 * plastic strain).  For DEM_FE_FULL, volume averages over the Gauss
 * points.  Small strain: eps = B(X) u; large strain: the integrated,
 * rotated rate of deformation. */
void dem_fe_fields(const dem_fe_t *fe, double *sig, double *eps, double *ep);

typedef struct dem_fe_energy {
	double t;           /* time of the values: t_n after n + 1 steps */
	double kinetic, internal, plastic, hourglass, damping, external;
	double balance;     /* kinetic + internal + hourglass + damping - external - kinetic(0) */
	double scale;       /* largest magnitude of the terms, for a relative error */
} dem_fe_energy_t;

void dem_fe_energy(const dem_fe_t *fe, dem_fe_energy_t *en);

/* Work counters: steps, element updates (cycles), plastic element (or
 * Gauss point) updates, and the seconds spent in the element and node
 * loops (wall clock), and in the exchanges between ranks. */
typedef struct dem_fe_stats {
	long steps;
	double elem_cycles, plastic_updates;
	double elem_s, node_s;
	double comm_s;      /* with several ranks: in the exchanges (waits included) */
} dem_fe_stats_t;

void dem_fe_stats(const dem_fe_t *fe, dem_fe_stats_t *s);

/* Checkpoint.  dem_fe_save writes the whole time-stepping state of the
 * model (coordinates, velocities, internal forces, element stresses,
 * plastic strains, hourglass and strain state, time, step sizes, energy
 * sums and work counters) to f at its current position; dem_fe_load reads
 * it back into a model made by dem_fe_create from the same mesh, material
 * and options, after which stepping continues bit for bit as the model
 * that was saved.  Loads (pressures, the hook) are not state: give them
 * again.  The block starts with a header (magic, version, mesh sizes, the
 * options and checksums of the mesh and material) and ends with a CRC-32
 * of everything; native byte order (a checkpoint is for the machine that
 * wrote it).  DEM_EINPUT for a checkpoint of another mesh, material or
 * options, or a truncated or corrupt one (the message says which);
 * DEM_EIO for a write error.  After a failed load the model's state is
 * undefined: free it. */
int dem_fe_save(const dem_fe_t *fe, FILE *f, dem_error_t *e);
int dem_fe_load(dem_fe_t *fe, FILE *f, dem_error_t *e);

#endif
