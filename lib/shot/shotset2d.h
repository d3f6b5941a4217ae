/* shotset2d.h - the shots of a pass against the top edge of a 2D block
 * (Han 2004, Ch. 7.4: plane strain; Ch. 7.5.1: the axisymmetric
 * reference of a single shot): the 2D twin of shotset.h, for the engine
 * of fe/explicit2d.h.
 *
 * Plane and shots.  The 2D block lies in the x-y plane of mesh2.h, its
 * top edge y = gy[ny] the peened surface.  A shot stream's row (pack/
 * shots.h) is read in the x-z plane of the 3D toolkit: the impact
 * abscissa is the row's x, the velocity (vx, vz); the row's y and vy are
 * not used.  So the 2D y is the stream's z, and a dempack shot stream with
 * azimuth 0 serves unchanged.  A body (dem_shot_body_t) keeps x, v and F
 * in the 2D plane (x[0], x[1]; the third component 0) and its spin in
 * w[2].
 *
 * Modes (quad4.h).
 *   PLANE   a shot is a rigid disk, the same thickness t as the slab: its
 *           mass rho pi R^2 t, its law the scene's at dim = 2 (a force per
 *           unit thickness, law.h) times t.  Forces, masses and energies
 *           are those of the slab t thick, as explicit2d.h's; divide by t
 *           for values per unit length.  Partial contact: the scheme of
 *           the model (disk.h: the potential scheme, demshot's default,
 *           or the overlap area or contact width factor, Eqs. 3.10, 3.11).
 *           Disks of a pass touching each other: disk/disk contact
 *           (sphere.h in the plane, Eq. 3.8), all pairs of the pass.
 *   AXISYM  a shot is a rigid sphere on the axis (x = r = 0), moving along
 *           it: its mass 4/3 pi R^3 rho, its law the scene's 3D one (a
 *           sphere on a surface).  The surface is the ring swept by each
 *           top segment; the sphere's section in the r-z plane cuts the
 *           segment's line in the chord [x0, x1] (disk.h's geometry), and
 *           the ring's share of the full contact is its surface within
 *           the sphere over the full contact's disc,
 *             gamma = int_{x0}^{x1} 2 pi r(x) dx / (pi b^2)
 *           (the 3D area factor, Eq. 3.15, read on a surface of
 *           revolution: the rings of a flat surface add up to 1), acting
 *           at the ring-weighted middle P of the chord along P -> O.  The
 *           force on the ring's nodes is the whole ring's (quad4.h AXISYM),
 *           both components; the sphere feels only its axial part (the
 *           radial parts cancel round the ring).  One shot per pass, no
 *           spin; its row must have x = 0 and vx = 0.
 *
 * Step.  As shotset.h: dem_shotset2d_prepare finds the contacts at x_n
 * and the step limit, the hook (dem_fe2_load_fn) gives the forces and
 * moves the shots by central differences (Eq. 7.2, Box 3.1).  No
 * candidate lists: the top edge has nx segments, and each shot is tested
 * against every one (box test first).  Each segment's mass is its share
 * of its two nodes' lumped masses (a node's over the number of top
 * segments it ends).  A touching pair with factor gamma is the spring
 * gamma K between the shot M and the segment's mass m_s (mass mu / gamma
 * on K, mu = M m_s / (M + m_s), Eq. 3.75) and limits the step to lambda 2
 * sqrt((mu / gamma) / K) (Box 3.1, Eqs. 3.80-3.83); a shot touching
 * nothing but able to reach a segment within the step (its distance to
 * the segment under twice its speed plus the segment's fastest node's,
 * times dt) is limited as a contact starting on the lightest such
 * segment; each surface node carrying the stiffness gamma K of its pairs
 * (shared as the force is, (1 - xi) and xi) limits the step to lambda 2
 * sqrt(m / K), as in 3D.
 *
 * A pass is over (dem_shotset2d_done) when no shot touches the block and
 * every shot moves up or on a straight path that misses the box of the
 * top edge.
 *
 * FE shots (opts.fe, PLANE only).  Each shot is instead a finite element
 * disk in penalty contact with the block (feshot2d.h: Ch. 7.4's FE
 * analysis), placed as a rigid one is; one shot per pass.  Its body
 * (dem_shotset2d_body) is the summary of feshot2d.h (centre of mass, mean
 * velocity, resultant contact force), the step the shot model's and the
 * penalty's (lambda is not used), and the pass ends as above on that
 * summary.
 */
#ifndef DEM_SHOT_SHOTSET2D_H
#define DEM_SHOT_SHOTSET2D_H

#include <stddef.h>

#include "contact/model.h"
#include "core/error.h"
#include "fe/quad4.h"
#include "mesh/mesh2.h"
#include "pack/shots.h"
#include "shot/feshot2d.h"
#include "shot/shotset.h"

typedef struct dem_shotset2d_opts {
	dem_quad4_mode_t mode;  /* DEM_QUAD4_PLANE or DEM_QUAD4_AXISYM */
	double thick;    /* PLANE: the slab's thickness t (m), > 0 */
	double rho;      /* shot density, kg/m^3, > 0 */
	double lambda;   /* Box 3.1 factor in (0, 1] */
	double gap;      /* a new shot's lowest point starts this far above the
			  * highest top node under it, m, >= 0 */
	const dem_feshot2d_opts_t *fe;  /* NULL: rigid shots; else FE shots
					 * (above; copied) */
} dem_shotset2d_opts_t;

typedef struct dem_shotset2d dem_shotset2d_t;

/* The shots' side of a 2D block: mesh and lumped nodal masses (borrowed:
 * they must outlive the set; the masses of the slab or the ring, as
 * dem_fe2_mass gives them), a contact model (copied: PLANE a law at dim
 * 2, AXISYM a 3D one).  DEM_EINPUT for a bad option or a law of the wrong
 * dimension (or, for FE shots, what dem_feshot2d_create refuses), DEM_EIO
 * without memory. */
int dem_shotset2d_create(dem_shotset2d_t **S, const dem_mesh2_t *mesh, const double *node_mass,
			 const dem_contact_model_t *cm, const dem_shotset2d_opts_t *o,
			 dem_error_t *e);
void dem_shotset2d_free(dem_shotset2d_t *S);

/* Start a pass with these n shot stream rows (see above for the plane):
 * shot i's centre is put on the line through (x, R) along (vx, vz), back
 * so that its lowest point is gap above the highest top node within R of
 * x (x: the block's current coordinates, 2 per node), further back by
 * |v| t for a start time t, and back along its line until it no more
 * overlaps a shot placed before it.  DEM_EINPUT for a bad radius, no
 * downward speed, or (AXISYM, FE shots) a shot off the axis or a second
 * shot. */
int dem_shotset2d_begin(dem_shotset2d_t *S, size_t n, const dem_shot_t *shots, const double *x,
			dem_error_t *e);

/* Before each step (x_n and v_{n-1/2}, 2 per node; v NULL: at rest): the
 * contacts and the step, dt_max or less (above). */
int dem_shotset2d_prepare(dem_shotset2d_t *S, const double *x, const double *v, double dt_max,
			  double *dt, dem_error_t *e);

/* The load hook (dem_fe2_load_fn); ctx is the dem_shotset2d_t. */
int dem_shotset2d_hook(void *ctx, double t, double dt, const double *x, const double *v,
		       double *f, dem_error_t *e);

/* Drive shot i of the pass (a prescribed motion: a disk pressed to a
 * fixed indentation and rolled or slid along the surface, as a test or a
 * burnishing tool would): its centre x, velocity v (2D, the plane above)
 * and spin w about z are set now, before dem_shotset2d_prepare.  The next
 * step finds the contacts and the step limit on that motion and the
 * forces with that velocity, then moves the shot on as a free one; drive
 * it again before each step to hold it on its path.  DEM_EINPUT for i
 * beyond the pass, a value not finite, or (AXISYM) a motion off the axis
 * or a spin. */
int dem_shotset2d_drive(dem_shotset2d_t *S, size_t i, const double x[2], const double v[2],
			double w, dem_error_t *e);

int dem_shotset2d_done(const dem_shotset2d_t *S);
size_t dem_shotset2d_holding(const dem_shotset2d_t *S, size_t *touching, size_t *coming);
size_t dem_shotset2d_count(const dem_shotset2d_t *S);
const dem_shot_body_t *dem_shotset2d_body(const dem_shotset2d_t *S, size_t i);

/* Kinetic energy of the shots (translation and, PLANE, spin of a solid
 * disk; an FE shot's, dem_feshot2d_kinetic), J (of the slab in PLANE). */
double dem_shotset2d_kinetic(const dem_shotset2d_t *S);

/* The FE shots' side (feshot2d.h), NULL for rigid shots. */
const dem_feshot2d_t *dem_shotset2d_feshot(const dem_shotset2d_t *S);

/* Segments of the top edge. */
size_t dem_shotset2d_segments(const dem_shotset2d_t *S);

/* Counters as shotset.h's (no candidate rebuilds: rebuilds 0). */
void dem_shotset2d_stats(const dem_shotset2d_t *S, dem_shotset_stats_t *s);

#endif
