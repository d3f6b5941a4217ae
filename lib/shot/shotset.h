/* shotset.h - the discrete element side of the peening run (Han 2004,
 * Ch. 7.3 and 7.5): the shots of a pass as rigid spheres hitting the top
 * surface of the finite element block.
 *
 * Surface.  Each quad of the block's top face (z = gz[nz]) is split into
 * two 3-node facets (Ch. 7.5), the diagonal alternating with the parity of
 * i + j so the facets of a dimple have no preferred direction.  The nodes
 * run anticlockwise seen from above: the facet normal points out of the
 * block, as lib/contact/facet.h wants.
 *
 * Step.  dem_shotset_hook is the load hook of lib/fe/explicit (Eq. 7.1:
 * F_im); at every step, with the block's coordinates x_n and velocities
 * v_{n-1/2}:
 *   1. candidates (Ch. 2.4.3): the D-cell of lib/detect over the facets'
 *      and shots' boxes, each enlarged by half the buffer; rebuilt only
 *      when a shot or a surface node has moved more than half the buffer
 *      since the last build, so every pair that can touch before the next
 *      build is in the list;
 *   2. sphere/facet contact of every candidate (facet.h: full and partial
 *      contact, the force through the centroid G, to the nodes by area
 *      coordinates) and sphere/sphere contact between shots (sphere.h),
 *      through the contact model's kernel (model.h: the effects the scene
 *      asked for, composed once);
 *   3. the shots' central difference step (Eq. 7.2 and Box 3.1):
 *      v_{n+1/2} = v_{n-1/2} + F/M (dt_n + dt_{n+1})/2, x_{n+1} = x_n +
 *      dt_{n+1} v_{n+1/2}; with friction also the spin w (I = 2/5 M R^2).
 *   The facets' forces go to the block's nodes (the opposite of the
 *   shots').  Shots of a pass are processed in parallel, the nodal forces
 *   added afterwards in a fixed order: results do not depend on threads.
 *
 * Masses and the time step.  A facet's mass is its share of the surface
 * nodes' lumped masses (each node's mass over the number of facets it
 * belongs to).  A pair with partial contact factor gamma is the spring
 * gamma K between the shot M and the facet's mass m_f: it has the equivalent
 * mass mu = M m_f / (M + m_f) (Eq. 3.75) on the stiffness gamma K, i.e.
 * mu / gamma on K; the kernel gets mu / gamma for its viscous damping
 * (Eq. 3.76 then gives gamma times the critical damping of that spring) and
 * the time step (Box 3.1, Eqs. 3.80-3.83) is lambda 2 sqrt((mu / gamma) /
 * K_L) for the pair.  On a fine mesh gamma / m_f is about one over the mass
 * of the whole contact area, so this is the step of the shot against the
 * surface it presses on.  A shot touching nothing but within its reach of
 * a facet in one step is limited as a contact just starting on the
 * lightest such facet with gamma = 1 (a first contact lies inside one
 * facet), so no contact begins with a step too long for it.  The surface
 * nodes limit the step as well: each touching pair's stiffness gamma K_L
 * goes to its facet's nodes by the area coordinates of G, and a node of
 * mass m carrying K in all allows lambda 2 sqrt(m / K) (where the 4-8
 * facets around a node all press on it, the pairs' own limit was up to
 * twice too long).
 * dem_shotset_prepare gives the smallest limit over the shots and shot
 * pairs, for the coordinates of the coming step.
 *
 * Energy.  The partial contact forces of the thesis (gamma F(delta) along
 * G -> O, area or volume factor) do not derive from a potential, so the
 * run does not conserve energy exactly:
 * on the Ch. 7.5 shot with the area factor the total stays within
 * 1e-5 of the input for alpha 0.5-10 (tests/unit/test_shot_impact.c); on
 * a soft block with a quasi-static impact the area factor pumps energy
 * for alpha about 5-10 and is stable again at 30; the volume factor is
 * stable there but gains 3 % on the Ch. 7.5 shot at alpha 0.5.  The
 * potential scheme (contact/facet.h, the default) derives them from an
 * energy: within 1e-3 of the input on the Ch. 7.5 shot for alpha 0.5-10
 * with both laws, 1e-5 on the soft block for alpha 2-30.
 */
#ifndef DEM_SHOT_SHOTSET_H
#define DEM_SHOT_SHOTSET_H

#include <stddef.h>

#include "contact/model.h"
#include "core/error.h"
#include "mesh/mesh.h"
#include "pack/shots.h"

typedef struct dem_shotset_opts {
	double rho;      /* shot density, kg/m^3, > 0 */
	double lambda;   /* Box 3.1 factor in (0, 1] (checked by the caller) */
	double buffer;   /* candidate buffer, m, > 0 */
	double gap;      /* a new shot's lowest point starts this far above the
			  * highest surface node under it, m, >= 0 */
	int threads;     /* 0: OpenMP's default; 1: serial */
} dem_shotset_opts_t;

/* One shot as the run sees it. */
typedef struct dem_shot_body {
	double x[3], v[3], w[3];  /* centre, velocity, spin */
	double R, M;              /* radius, mass */
	double kn;                /* k_n against a facet (dem_law_kn) */
	double F[3];              /* contact force on the shot at the last step */
	double Fn, Ft;            /* sums over its contacts of |F_n|, |F_t| */
	double dt;                /* its step limit found at the last step */
	unsigned long pass;       /* the stream's pass */
	int contacts;             /* facets and shots touching at the last step */
} dem_shot_body_t;

/* Of the n shots b in DIM dimensions (2: x and y up; 3: x, y and z up),
 * those that keep a pass going: touching at the last step (*touching) and
 * those out of contact not moving up on a straight path that meets the box
 * lo..hi of the block's top surface grown by their radius (*coming); the
 * pointers may be NULL.  Shared by the 3D and 2D shot sets. */
size_t dem_shot_holding(const dem_shot_body_t *b, size_t n, int dim, const double *lo,
			const double *hi, size_t *touching, size_t *coming);

typedef struct dem_shotset_stats {
	long steps;               /* hook calls */
	long rebuilds;            /* candidate lists built */
	double candidates;        /* sphere/facet candidate pairs examined, summed over steps */
	double contacts;          /* sphere/facet pairs in contact, summed over steps */
	double sphere_contacts;   /* sphere/sphere pairs in contact, summed */
	double detect_s, contact_s, integrate_s;  /* wall seconds */
	double sepfix_J;          /* energy the separation correction took from shot
				   * pairs (J; < 0: gave back) */
} dem_shotset_stats_t;

typedef struct dem_shotset dem_shotset_t;

/* The shots' side of a block: mesh and its lumped nodal masses (borrowed,
 * must outlive the set), a contact model (copied).  DEM_EINPUT for a bad
 * option, DEM_EIO without memory. */
int dem_shotset_create(dem_shotset_t **S, const dem_mesh_t *mesh, const double *node_mass,
		       const dem_contact_model_t *cm, const dem_shotset_opts_t *o,
		       dem_error_t *e);
void dem_shotset_free(dem_shotset_t *S);

/* Start a pass: drop the shots of the last pass and place these n (shot
 * stream rows).  Shot i aims at its impact point: its centre is put on the
 * line through (x, y, R) along its velocity, back from that point so that
 * its lowest point is gap above the highest surface node within R of the
 * impact point (x: the block's current coordinates), and further back by
 * v t for a start time t; if it overlaps a shot placed before it, it moves
 * back along its line until it only touches it.  DEM_EINPUT for a shot with
 * a bad radius or no downward speed. */
int dem_shotset_begin(dem_shotset_t *S, size_t n, const dem_shot_t *shots, const double *x,
		      dem_error_t *e);

/* Before each step, with the block's coordinates x_n that the step's hook
 * will see and its velocities v (v_{n-1/2}; NULL: at rest): find the
 * contacts and give the step, dt_max (the block's stable step) or less if
 * a contact needs it (Box 3.1; a shot that may reach a facet within
 * dt_max is treated as starting a contact with it: its sphere enlarged by
 * 2 |v_shot| dt_max meets the facet's box, and the triangle itself comes
 * nearer to the sphere than twice the shot's speed plus the facet's
 * fastest node's, times dt_max).  The hook then reuses this geometry.  Errors of the
 * candidate search (DEM_EIO without memory). */
int dem_shotset_prepare(dem_shotset_t *S, const double *x, const double *v, double dt_max,
			double *dt, dem_error_t *e);

/* The load hook (dem_fe_load_fn); ctx is the dem_shotset_t.  Without a
 * dem_shotset_prepare for this step it finds the geometry itself (and the
 * step dt is not checked against the contacts). */
int dem_shotset_hook(void *ctx, double t, double dt, const double *x, const double *v,
		     double *f, dem_error_t *e);
/* The nodes the hook loads: [*n0, *n1), the top plane's (for
 * dem_fe_set_load_nodes). */
void dem_shotset_nodes(const dem_shotset_t *S, size_t *n0, size_t *n1);

/* 1 when every shot has left: no contact at the last step, and moving
 * away from the block (upward) or on a straight path that never meets the
 * box of the block's top surface (a shot gone past its side, or one sent
 * down beside it by another shot); or no shots. */
int dem_shotset_done(const dem_shotset_t *S);
/* The shots that keep the pass going (dem_shotset_done is 1 when there is
 * none): those touching the block at the last step (touching) and those
 * out of contact moving down on a path that meets the box of its top
 * surface (coming); either pointer may be NULL. */
size_t dem_shotset_holding(const dem_shotset_t *S, size_t *touching, size_t *coming);

size_t dem_shotset_count(const dem_shotset_t *S);
const dem_shot_body_t *dem_shotset_body(const dem_shotset_t *S, size_t i);

/* Kinetic energy of the shots (translation and spin), J. */
double dem_shotset_kinetic(const dem_shotset_t *S);

/* Number of facets of the surface. */
size_t dem_shotset_facets(const dem_shotset_t *S);

void dem_shotset_stats(const dem_shotset_t *S, dem_shotset_stats_t *s);

#endif
