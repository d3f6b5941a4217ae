/* facet.h - sphere/facet contact for 3-node facets (Han 2004, Ch. 3.2.2).
 *
 * The facet's nodes X1, X2, X3 run anticlockwise seen from the side the
 * sphere is on: the facet normal (X2 - X1) x (X3 - X1) points toward the
 * sphere (outward from the solid).  With d the distance of the sphere's
 * centre O from the facet's plane, the full contact overlap is
 * delta = R - d and the contact circle on the plane has its centre C (the
 * projection of O) and radius b = sqrt(delta (2R - delta)) (Eq. 3.13).
 *
 * Partial contact (Eqs. 3.15-3.22).  S_p, the area of the circle inside the
 * facet, and its centroid G come from signed per-edge pieces: for each edge
 * the circle's part in the wedge from C over that edge, signed positive
 * when C lies left of the edge.  Summed, they give Eqs. 3.20-3.21 without
 * the case split (for C inside the facet the wedges fill the circle, for C
 * outside their signed angles cancel); each piece is exact (triangles and
 * circular sectors), so S_p and G are exact.  Then either
 *   area:   gamma = S_p / (pi b^2)                     (Eqs. 3.15, 3.17)
 *   volume: gamma = V_p / V_f with V_f = pi/2 b^2 delta (Eq. 3.13) and V_p
 *           the volume over S_p of the same paraboloidal cap,
 *           delta (1 - r^2/b^2), integrated exactly (r the distance to C);
 *           G is then the centroid of that volume, projected on the plane.
 *           Eq. 3.22 (V_p = S_p delta' at G) is this integral's one-point
 *           rule; it is good for small S_p only (a facet covering the whole
 *           circle would get gamma = 2), the exact integral gives gamma = 1
 *           there and sums to 1 over a flat tiled surface.
 * The force acts along G -> O (n, pointing to the sphere) and goes to the
 * facet's nodes by the area coordinates N of G.  (With the volume factor,
 * the thesis keeps G the centroid of the area; but then the facets of a
 * flat surface push the sphere sideways, sum V_i (G_i - C) != 0, so we
 * take the volume's centroid, for which the sum vanishes.)
 *
 * Neither force derives from a potential (beyond the thesis).  A sphere
 * pressed into a dimpled, deforming surface can then gain energy without
 * bound: on a soft block under a large slow sphere the area factor with
 * m = 1.5 did for alpha 2 to 10, whatever the step.  The third scheme,
 * potential (the default), spreads the law over the surface as an energy per unit area
 * that depends only on a surface point's distance q from O:
 *     Phi = int over the facet of w(q) dA,  w(q) = F(R - q) / (2 pi q)
 * (F the law's branch, zero for q >= R).  On a flat surface at distance d
 * this integrates to U(R - d), the law's energy (pi int_{d^2}^{R^2} w ds
 * with s = q^2, differentiated in d, gives F back), so a tiled plane gives
 * the law exactly, and each facet's share is local: a point's energy
 * depends on where it is, not on the facet's plane extended to C (taking
 * gamma U(delta) for Phi instead makes the tilt of a small facet far from
 * C cost the sphere's whole force times that distance: far too stiff for
 * the step, it blew up the soft block).  The elastic forces are minus the
 * gradient of Phi with respect to O and to each node, exact integrals
 * over the area inside the circle (the integrand vanishes on the circle,
 * so the moving rim adds nothing):
 *     on the sphere  F_O = int 2 w'(s) (y - O) dA
 *     on node a      F_a = -int [w grad N_a + N_a 2 w'(s) (y - O)] dA
 * (w' = dw/ds; grad N_a the in-plane gradient of the area coordinate,
 * from the facet's stretch).  They sum to zero with zero moment, do the
 * work Phi loses, and each point pushes along the line to O, like a
 * pressure on the sphere.  In full contact they are the thesis's force (F
 * n through C, to the nodes by area coordinates).  The integrals are
 * closed on the circle's sectors and 1D quadrature along the chords (see
 * facet.c), so the scheme costs more only in partial contact.  Damping and
 * friction act at G, as in the area scheme, with gamma by area.  It is the
 * default (DEM_PARTIAL_POTENTIAL = 0).
 */
#ifndef DEM_CONTACT_FACET_H
#define DEM_CONTACT_FACET_H

#include "contact/model.h"

typedef struct dem_facet_geom {
	double delta;  /* full contact overlap R - d */
	double b;      /* contact circle radius */
	double gamma;  /* partial contact factor, 1 in full contact */
	double Sp;     /* overlap area S_p */
	double G[3];   /* centroid of the overlap area (volume, by that scheme), on the plane */
	double n[3];   /* unit direction G -> O */
	double N[3];   /* area coordinates of G in the facet */
	int full;      /* 1: the circle lies inside the facet */
	/* the potential scheme in partial contact (pot = 1; else unset) */
	int pot;
	double R, d;              /* the sphere's radius, O's distance from the plane */
	double nf[3], u[3], w[3]; /* the facet's frame: normal, in-plane axes */
	double x[3], y[3];        /* the nodes in (u, w) relative to C */
	double A2;                /* twice the facet's area */
} dem_facet_geom_t;

/* Overlap of the sphere (O, R) with the facet X[3][3]: returns 1 and fills g
 * when they overlap (0 < delta, the centre in front of the facet's plane,
 * S_p > 0), 0 otherwise.  scheme: DEM_PARTIAL_AREA, _VOLUME or _POTENTIAL
 * (as _AREA, and in partial contact the derivatives of S_p as well). */
int dem_facet_geom(const double O[3], double R, const double X[3][3], int scheme,
                   dem_facet_geom_t *g);

/* Area S and first moments (Mx, My) of the part of the circle (centre 0,
 * radius r) inside the triangle (x[i], y[i]), i = 0..2, anticlockwise, and
 * its polar moment J = integral of x^2 + y^2: exact.  For tests and for
 * other polygon users. */
void dem_circle_triangle(const double x[3], const double y[3], double r,
                         double *S, double *Mx, double *My, double *J);

/* The point q of the triangle X[3][3] (edges and interior) nearest to O,
 * and its squared distance, returned.  Any orientation; a degenerate
 * triangle gives the nearest point of its edges. */
double dem_triangle_closest(const double O[3], const double X[3][3], double q[3]);

/* The forces of one pair from the kernel's output o (for the pair's
 * geometry g): on the sphere (F) and on the facet's nodes (Fnode; the sum
 * of all four is zero).  For the area and volume schemes, and in full
 * contact, o->F on the sphere and -N_a o->F on node a; with the potential
 * scheme in partial contact, the elastic part o->Fe n is replaced by the
 * gradient of Phi (above).  m: the law's exponent.  Phi, when not NULL,
 * gets the elastic energy: Phi above, or gamma times the branch's energy
 * at delta. */
void dem_facet_forces(const dem_facet_geom_t *g, const dem_contact_out_t *o, double m,
                      double F[3], double Fnode[3][3], double *Phi);

/* The integrals of the potential scheme over a plane region: w(q) =
 * F(R - q) / (2 pi q), F(g) = c g^m (g > 0; a branch of the law, R the
 * branch's radius, R - g0), q the distance of a point of the plane from O,
 * d > 0 O's distance from the plane; over the part of the convex polygon
 * (x, y), nv vertices anticlockwise in plane axes with C (O's foot) at the
 * origin, where q < R:
 *     A0 = int w dA (the energy Phi), B0 = int 2 w' dA, B1 = int 2 w' y dA,
 *     B2 = int 2 w' y y^T dA (xx, xy, yy)
 * (w' = dw/d(q^2), y the in-plane position).  The facet's triangle here;
 * the strip swept by a segment in disk.c. */
void dem_potential_polygon(double c, double m, double R, double d, const double *x,
                           const double *y, int nv, double *A0, double *B0, double B1[2],
                           double B2[3]);

/* A rigid sphere (the contactor). */
typedef struct dem_sphere {
	double x[3];  /* centre */
	double v[3];  /* velocity */
	double w[3];  /* angular velocity */
	double R;     /* radius */
	double kn;    /* k_n of its normal law against a facet: dem_law_kn(law, R) */
} dem_sphere_t;

/* The result of one sphere/facet pair at one step. */
typedef struct dem_facet_out {
	dem_facet_geom_t g;
	dem_contact_out_t c;  /* force and torque on the sphere */
	double Fnode[3][3];   /* forces on the facet's nodes (sum: -c.F) */
} dem_facet_out_t;

/* One sphere/facet pair at one step: geometry, then cm->kernel.  V: node
 * velocities (NULL for a rigid facet at rest); meff: the equivalent mass
 * (dem_contact_meff; the sphere's mass for a rigid facet).  Returns 1 in
 * contact (out filled), 0 otherwise (state reset, out untouched). */
int dem_contact_sphere_facet(const dem_contact_model_t *cm, const dem_sphere_t *s,
                             const double X[3][3], const double (*V)[3], double meff,
                             double dt, dem_contact_state_t *st, dem_facet_out_t *out);

#endif
