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
} dem_facet_geom_t;

/* Overlap of the sphere (O, R) with the facet X[3][3]: returns 1 and fills g
 * when they overlap (0 < delta, the centre in front of the facet's plane,
 * S_p > 0), 0 otherwise.  scheme: DEM_PARTIAL_AREA or DEM_PARTIAL_VOLUME. */
int dem_facet_geom(const double O[3], double R, const double X[3][3], int scheme,
                   dem_facet_geom_t *g);

/* Area S and first moments (Mx, My) of the part of the circle (centre 0,
 * radius r) inside the triangle (x[i], y[i]), i = 0..2, anticlockwise, and
 * its polar moment J = integral of x^2 + y^2: exact.  For tests and for
 * other polygon users. */
void dem_circle_triangle(const double x[3], const double y[3], double r,
                         double *S, double *Mx, double *My, double *J);

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
