/* node2d.h - node-to-segment contact in two dimensions: the geometry of a
 * node of one mesh against a boundary segment of another, for the penalty
 * contact of two finite element bodies (shot/feshot2d.h, the FE shot of
 * Ch. 7.4).
 *
 * The segment A -> B has the outside of its body on its left, as disk.h
 * has it: its unit normal nf = (-t_y, t_x), t = (B - A) / L, points out of
 * the body.  A node P is behind the segment (in its body) by the
 * penetration g = -(P - A) . nf > 0, and its foot on the segment is
 * C = (1 - xi) A + xi B, xi = (P - A) . t / L.  It touches the segment when
 * 0 < g < dmax and -tol <= xi <= 1 + tol; xi is then clamped to [0, 1].
 * dmax keeps a node away from the segments on the far side of a thin or
 * curved body (a node behind a segment by more than dmax is no contact);
 * tol closes the gap that a convex corner of the segment chain leaves
 * between the feet of its two segments (a node just outside both ranges,
 * behind both lines, within tol L of the corner).
 *
 * Of several segments a node touches, the driver keeps the one with the
 * least penetration (the surface the node crossed last).  The force on the
 * node is along nf; the segment gets its opposite shared as (1 - xi) on A
 * and xi on B, which keeps force and moment about every point to O(g)
 * (the force acts at C, which lies on A B).
 */
#ifndef DEM_CONTACT_NODE2D_H
#define DEM_CONTACT_NODE2D_H

typedef struct dem_node_seg {
	double g;      /* penetration > 0 */
	double xi;     /* the foot C = (1 - xi) A + xi B, xi in [0, 1] */
	double n[2];   /* the segment's outward unit normal nf */
	double L;      /* the segment's length */
} dem_node_seg_t;

/* Whether node P touches the segment A -> B (above): 1 and out filled, or
 * 0. */
int dem_node_segment(const double P[2], const double A[2], const double B[2], double dmax, double tol,
		     dem_node_seg_t *out);

#endif
