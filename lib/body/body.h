/* body.h - rigid 2D bodies (superquadrics, polygons, disks) and fixed walls,
 * integrated in time with the Feng-Owen energy-based contact (Han 2004,
 * Ch. 4; the polygon geometry is lib/contact/polygon).
 *
 * Shapes.  A shape is given in its body frame, centroid at the origin:
 *   superquadric  |x/a|^m + |y/b|^m <= 1 (Eq. 4.1), sampled into its
 *                 inscribed polygon by Box 4.1 with tolerance tau; the
 *                 body IS that polygon (its area and inertia are the
 *                 polygon's, so the dynamics and the contact geometry
 *                 agree);
 *   polygon       the regular polygon of m sides (3 <= m <= 64) with
 *                 circumradius a, one side flat at the bottom at theta = 0;
 *                 with b > 0 (b != a) stretched along y to b: its points
 *                 (a cos p, b sin p) on the ellipse of semi-axes a, b;
 *   disk          the circle of radius a, in contact exactly: the overlap
 *                 of two disks is their lens, of a disk and a wall the
 *                 circle's part inside the wall's rectangle (its ends
 *                 included).
 * Bodies are 2D: mass and moment of inertia are per unit thickness
 * (density times area, density times the polar moment of area).
 *
 * Walls.  A wall is the segment A -> B with the bodies on its left, made a
 * fixed convex polygon (the rectangle of the given thickness behind the
 * segment), so that a body meets it through the same polygon contact as
 * another body; a disk meets the same rectangle exactly.
 *
 * Contact (Ch. 4.4).  The energy W(S) of Table 4.2 on the overlap area S
 * gives the elastic force F = -dW/dx (Eqs. 4.10-4.13) at the reference
 * contact point c, the middle of the contact line (Eq. 4.27): minus it at
 * c on the other body, so momentum and angular momentum are kept.  The
 * effects a run asks for add to it:
 *   damping   a viscous normal force -C v_n with C = 2 xi sqrt(M K)
 *             (the form of Eqs. 3.70, 3.75-3.76; M the pair's equivalent
 *             mass, K the secant stiffness below); repulsive only (the
 *             normal force never pulls);
 *   friction  Coulomb (Eq. 3.48): a tangential spring k_t = kt_ratio K
 *             on the tangential displacement accumulated while the pair
 *             is in contact, capped at mu times the normal force (the 2D
 *             form of Eqs. 3.57-3.62, the displacement kept as its
 *             component along the current tangent);
 *   gravity   a constant acceleration g.
 * The step is assembled from the effects present (DESIGN.md): the pair
 * kernel for the combination is chosen once, and no effect is tested in
 * the pair loop.  An absent effect and the same effect at zero (mu = 0,
 * xi = 0, g = 0) give the same motion.
 *
 * Time integration: velocity Verlet (kick, drift, forces, kick), which for
 * the conservative forces is the central difference scheme of Box 3.1
 * with velocities at whole steps, symplectic in (x, y, theta): a body
 * under the elastic contact alone keeps its energy bounded.  The
 * velocity-dependent forces see the half-step velocity.
 *
 * Time step (Box 3.1, Eqs. 3.80-3.83): dt = lambda 2 sqrt(M / K) with K
 * the secant stiffness F(u_max) / u_max of the law for the shape pushed
 * into a flat wall, u_max the depth at which W(S) = M v0^2 / 2, and M the
 * equivalent mass of two such bodies struck at their bounding radius r,
 * 1 / (2 (1/m + r^2/I)); the largest K over the shape's orientations (each
 * side flat on the wall, and 360 angles between).  A flat side meets the
 * wall all at once, so K depends on v0: v0 is the largest approach speed
 * the run expects (demshot: twice the free-fall speed over the scene's
 * height).  For the linear law and a side of length L flat on the wall,
 * K = 2 kn^2 L^2 / (M v0^2); a right-angled corner, K = 2 kn.
 *
 * Candidates: the bounding boxes of the bodies and walls, through the
 * library's detectors (lib/detect), every step; the pairs are sorted so
 * that the friction state of a pair carries from one step to the next.
 */
#ifndef DEM_BODY_BODY_H
#define DEM_BODY_BODY_H

#include <stddef.h>
#include <stdint.h>

#include "contact/polygon.h"
#include "core/error.h"
#include "detect/detect.h"

typedef enum dem_shape_kind {
	DEM_SHAPE_SUPERQUADRIC = 0,
	DEM_SHAPE_POLYGON = 1,
	DEM_SHAPE_DISK = 2
} dem_shape_kind_t;

/* Name <-> kind ("superquadric", "polygon", "disk"); -1 for another name. */
const char *dem_shape_kind_name(int kind);
int dem_shape_kind_parse(const char *name);

typedef struct dem_shape {
	int kind;
	double a, b, m;   /* superquadric: a, b, m; polygon: a (circumradius), m sides, b (a if
	                     none given: regular);
	                     disk: a (radius), b = a, m = 0 */
	int nv;           /* points of the polygon (0 for a disk) */
	double (*v)[2];   /* the polygon, anticlockwise, centroid at 0 (owned) */
	double A, J;      /* area and polar moment of area about the centroid */
	double r;         /* bounding radius about the centroid */
} dem_shape_t;

/* Make a shape (tau: the superquadric's sampling tolerance, else unused).
 * DEM_EINPUT for bad parameters, DEM_EIO without memory. */
int dem_shape_init(dem_shape_t *s, int kind, double a, double b, double m, double tau,
                   dem_error_t *e);
void dem_shape_free(dem_shape_t *s);

/* What a run simulates (zero-initialise, then fill). */
typedef struct dem_de_param {
	dem_wlaw_t law;     /* W(S) of Table 4.2 */
	double kn, p;       /* penalty (Pa: energy per unit thickness over area); power exponent */
	double density;     /* kg/m^3 (mass per unit thickness = density x area) */
	int friction;       /* 0 absent */
	double mu, kt_ratio;/* Coulomb coefficient; k_t / K (0: DEM_CONTACT_KT_RATIO) */
	int damping;        /* 0 absent */
	double xi;          /* damping ratio in [0, 1) */
	int gravity;        /* 0 absent */
	double g[2];        /* m/s^2 */
	double lambda;      /* time step factor (Box 3.1) */
	double v0;          /* largest approach speed expected, for the time step */
	dem_detect_algo_t algo;
	double cell_factor; /* 0: the detector's default */
} dem_de_param_t;

/* Counters of a run, summed over its steps. */
typedef struct dem_de_stats {
	uint64_t candidates;   /* pairs of overlapping boxes (body/body and body/wall) */
	uint64_t contacts;     /* of them, pairs in contact (S > 0) */
	double overlap_max;    /* the largest overlap area over the area of body i */
	double detect_s, contact_s, move_s;  /* CPU seconds by phase (process time: the machine may be shared) */
} dem_de_stats_t;

struct dem_de_ws;

/* A run: bodies (structure of arrays), walls, parameters, workspace. */
typedef struct dem_de {
	dem_de_param_t p;
	int nshape;
	dem_shape_t *shape;     /* the caller's table, kept until dem_de_free */
	size_t n, cap;          /* bodies */
	uint32_t *sh;           /* shape of body i */
	double *mass, *inertia;
	double *x, *y, *th;     /* centroid, rotation (rad) */
	double *vx, *vy, *w;    /* velocities (m/s, rad/s) */
	double *fx, *fy, *mz;   /* force and moment about the centroid, last evaluation */
	size_t nw, wcap;        /* walls */
	double (*wall)[4][2];   /* each a rectangle: B, A, A - t nL, B - t nL */
	double t, dt;           /* time, step */
	long steps;
	double K;               /* secant stiffness of the time step (N/m per unit thickness) */
	double W;               /* contact energy W(S) summed at the last evaluation */
	size_t ncontact;        /* pairs in contact at the last evaluation */
	dem_de_stats_t st;
	struct dem_de_ws *ws;
} dem_de_t;

/* A new run with the shapes (the caller's, which must outlive it).
 * DEM_EINPUT for bad parameters, DEM_EIO without memory. */
int dem_de_init(dem_de_t *de, const dem_de_param_t *p, int nshape, dem_shape_t *shape,
                dem_error_t *e);
void dem_de_free(dem_de_t *de);

/* Add a body of shape s at centroid (x, y), rotation th, with velocities
 * (vx, vy, w).  Returns its index, or -1 without memory (e filled). */
long dem_de_add_body(dem_de_t *de, int s, double x, double y, double th, double vx,
                     double vy, double w, dem_error_t *e);

/* Add the wall A -> B (bodies on its left) of the given thickness > 0.
 * Returns its index, or -1 (e filled: a zero-length segment, no memory). */
long dem_de_add_wall(dem_de_t *de, const double A[2], const double B[2], double thickness,
                     dem_error_t *e);

/* The secant stiffness (Eq. 3.80 at u = 0) of shape s at rotation th
 * pushed into a flat wall below it, for mass M and speed v0 (above), and
 * the depth u_max reached.  DEM_ENUMERIC when W(S) cannot take the energy
 * before the shape is wholly in the wall. */
int dem_shape_secant(const dem_shape_t *s, double th, const dem_de_param_t *p, double M,
                     double v0, double *K, double *umax, dem_error_t *e);

/* The time step and K of the run (above); at least one body. */
int dem_de_timestep(dem_de_t *de, dem_error_t *e);

/* Compute the time step (dem_de_timestep) and the forces at the start.
 * Call after the bodies and walls are in. */
int dem_de_start(dem_de_t *de, dem_error_t *e);

/* One step of dt.  DEM_ENUMERIC when a body's state is no longer finite,
 * DEM_EIO without memory. */
int dem_de_step(dem_de_t *de, dem_error_t *e);

/* Kinetic, gravitational (-m g.x) and contact energy (de->W) of the bodies
 * now (velocities at whole steps). */
double dem_de_energy(const dem_de_t *de);

/* The body's outline in the world (its polygon placed at its pose): at
 * most cap points written to v; returns the number of points (a disk:
 * 0). */
int dem_de_outline(const dem_de_t *de, size_t i, int cap, double (*v)[2]);

#endif
