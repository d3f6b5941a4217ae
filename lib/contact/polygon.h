/* polygon.h - convex polygons and 2D superquadrics: sampling, mass
 * properties, overlap of two polygons and the Feng-Owen contact geometry
 * (Han 2004, Ch. 4.2-4.4).
 *
 * A polygon is n >= 3 points double v[n][2], anticlockwise (the interior
 * on the left of each edge v[i] -> v[i+1]), convex; edge i runs from v[i]
 * to v[(i+1) % n].  Collinear or repeated consecutive points are allowed.
 * No function allocates: the caller passes the buffers, so a time loop can
 * reuse them.
 *
 * Superquadric (Eq. 4.1): |x/a|^m + |y/b|^m <= 1, a, b > 0, m >= 1 (convex;
 * m = 2 an ellipse, m -> infinity the box).  Its inscribed polygon comes
 * from the adaptive subdivision of Box 4.1 on the first quadrant with the
 * parametrisation x = a cos(t)^(2/m), y = b sin(t)^(2/m), t in [0, pi/2]
 * (Eq. 4.3 prints the exponent as m/2, which lies on the curve only for
 * m = 2).  A piece [t0, t1] is flat when the point at t2 = (t0 + t1)/2 lies
 * within tau |P0 P1| of the segment P0 P1 (Eqs. 4.4-4.6); otherwise P2 is a
 * vertex and both halves are refined.  The quarter, from (a, 0) to (0, b),
 * is mirrored into the other three, so the polygon is symmetric about both
 * axes, anticlockwise, starts at (a, 0) and has 4 k vertices.
 *
 * Overlap of two convex polygons P (n points) and Q (m points): the
 * intersection polygon (at most n + m points, anticlockwise, without
 * repeated consecutive points but possibly with collinear ones), its area
 * S and centroid, and for each of its edges
 * which polygon's boundary it lies on.  Two methods:
 *
 *   dem_polygon_chase   O'Rourke, Chien, Olson and Naddor's linear
 *                       algorithm (Box 4.2): one edge of each polygon,
 *                       advanced so that they chase each other round both
 *                       boundaries (O'Rourke et al.'s rule, which is Table
 *                       4.1 but for six cells where the turning direction
 *                       decides: polygon.c), at most 2 (n + m) steps to
 *                       the first crossing.  With clip = 1 it first applies
 *                       the modification of Ch. 4.3.2: the window W is the
 *                       overlap of the two bounding boxes (none: no
 *                       overlap), and each polygon is clipped against each
 *                       side of W in turn, Sutherland-Hodgman style, except
 *                       that an edge is never cut: only the points whose
 *                       two edges both lie strictly outside that side are
 *                       dropped (the run they formed is replaced by the
 *                       chord joining its ends, itself strictly outside).
 *                       The clipped polygon P' lies in P and
 *                       P' n W = P n W, so P' n Q' = P n Q exactly, and a
 *                       small overlap of two many-sided polygons leaves a
 *                       few edges each to chase.  A polygon with no point
 *                       inside one side of W does not overlap.
 *   dem_polygon_clip    the reference: P clipped by the half-plane of each
 *                       edge of Q in turn (full Sutherland-Hodgman), O(n m).
 *
 * Both give the same area and centroid to round-off, including the
 * degenerate cases (shared points, a point on an edge, collinear edges,
 * identical polygons, one inside the other, contact without area).  Two
 * polygons whose intersection has no area give S = 0 and nv = 0.
 *
 * Contact (Feng and Owen's energy-based corner/corner model, Ch. 4.4).  P
 * moves (its reference point xp, e.g. its centroid, and its rotation theta
 * about xp), Q is held.  The contact energy is W(S) (Table 4.2) and
 *   force on P      F  = -dW/dxp     = -W'(S) grad S      (Eqs. 4.10-4.13)
 *   moment about xp M  = -dW/dtheta  = -W'(S) dS/dtheta    (Eq. 4.14)
 * Moving P by u changes S by the flux of u through the part of P's boundary
 * inside Q; for the usual contact that part is one chain of P's edges,
 * entering Q at h and leaving it at g (anticlockwise along P), and then
 *   grad S = (dy, -dx) with (dx, dy) = g - h          (Eqs. 4.18-4.22)
 *   dS/dtheta = -(g - h) . (c - xp),  c = (g + h)/2   (Eqs. 4.24-4.26)
 * whatever P's edges between h and g: the contact line h-g, its width
 * b_w = |g - h|, the normal n = -grad S / b_w (moving P along n reduces
 * the overlap fastest), |F| = W'(S) b_w (Eq. 4.28) acting at the reference
 * contact point c, the middle of the contact line (Eq. 4.27).  Where P's
 * boundary enters Q more than once (one polygon through the other, Figs.
 * 4.7(c)-(d); two convex polygons can cross at up to 2 min(n, m) points),
 * each chain k adds its own term (Eq. 4.31): grad S = sum (dy_k, -dx_k),
 * b_w = |grad S|, and c is the point of the line of action of the total
 * force nearest the overlap's centroid.  The force on Q is -F along the
 * same line (no moment at c).
 */
#ifndef DEM_CONTACT_POLYGON_H
#define DEM_CONTACT_POLYGON_H

/* Mass properties of a region: area, centroid, and the polar moment of
 * area about the centroid, J = integral of |x - centroid|^2 dA (the moment
 * of inertia is density times J). */
typedef struct dem_area_props {
	double A;
	double c[2];
	double J;
} dem_area_props_t;

/* The inscribed polygon of the superquadric |x/a|^m + |y/b|^m = 1 centred
 * at the origin (Box 4.1, above), tolerance tau > 0 (relative flatness,
 * e.g. 1e-3).  Writes at most cap points into v and returns the number of
 * points the polygon has (call with cap = 0 to size the buffer; call again
 * if the return exceeds cap), or -1 for bad parameters (a, b <= 0, m < 1,
 * tau <= 0 or not finite).  The refinement stops at depth 24 (2^24
 * points a quarter) whatever tau. */
int dem_superquadric_polygon(double a, double b, double m, double tau, int cap,
                             double (*v)[2]);

/* Exact area and polar moment of the superquadric (centroid 0):
 *   A = 4 a b G(1 + 1/m)^2 / G(1 + 2/m),
 *   J = 4 a b (a^2 + b^2) G(3/m) G(1/m) / (m^2 G(1 + 4/m))
 * (G the gamma function; the Dirichlet integrals of the quarter). */
void dem_superquadric_props(double a, double b, double m, dem_area_props_t *p);

/* Area, centroid and polar moment of the polygon v[n] (any simple
 * polygon; anticlockwise gives A > 0).  n < 3 or zero area: all zero,
 * the centroid the mean of the points. */
void dem_polygon_props(int n, const double (*v)[2], dem_area_props_t *p);

/* The body stream's polygon (shape 1, dem-streams(5)): the m points
 * (a cos p, b sin p), p = -pi/2 + pi/m + 2 pi k/m, k = 0 .. m-1, so
 * anticlockwise with a side flat at the bottom: the regular m-gon of
 * circumradius 1 stretched by a along x and b along y (m >= 3). */
void dem_polygon_regular(int m, double a, double b, double (*v)[2]);

/* w[i] = x + R(theta) v[i]: the polygon v[n] turned by theta about the
 * origin and moved to x (a body's pose).  w may be v. */
void dem_polygon_place(int n, const double (*v)[2], const double x[2], double theta,
                       double (*w)[2]);

/* The intersection of two convex polygons. */
typedef struct dem_overlap {
	double S;      /* area */
	double c[2];   /* centroid (0, 0 when S = 0) */
	int nv;        /* points written to the caller's v (0 when S = 0) */
	int steps;     /* the method's work count (below) */
} dem_overlap_t;

/* Overlap of P (n points) and Q (m points), both convex and anticlockwise,
 * by the chase (above); clip: 1 for the bounding-box clip of Ch. 4.3.2, 0
 * for the plain linear algorithm.  v: room for 2 (n + m) points (the
 * result has at most n + m; the room spares a check per point); side:
 * room for as many labels, or NULL: side[i] is 0 when the edge
 * v[i] -> v[(i+1) % nv] lies on P's boundary, 1 on Q's (either for an edge
 * on both).  work: room for 2 (n + m) points (the clipped copies; unused
 * and may be NULL when clip = 0).  o->steps: the pairs of edges examined
 * (at most 2 (n + m) until the first crossing, as many again to close).
 * Returns 1 when S > 0, else 0. */
int dem_polygon_chase(int n, const double (*P)[2], int m, const double (*Q)[2], int clip,
                      double (*v)[2], unsigned char *side, double (*work)[2],
                      dem_overlap_t *o);

/* The same by full Sutherland-Hodgman clipping of P by Q's edges (the
 * reference).  v and side: room for n + m points and labels, required;
 * work: room for 2 (n + m) points (the other buffer of points and
 * labels).  o->steps: the points tested against a line.  Returns 1 when
 * S > 0, else 0. */
int dem_polygon_clip(int n, const double (*P)[2], int m, const double (*Q)[2],
                     double (*v)[2], unsigned char *side, double (*work)[2],
                     dem_overlap_t *o);

/* Energy functions of Table 4.2: W(S) = kn S (linear), 2/3 kn S^(3/2)
 * (Hertz-type), kn S^p / p (power, exponent p >= 1). */
typedef enum dem_wlaw {
	DEM_W_LINEAR,
	DEM_W_HERTZ,
	DEM_W_POWER
} dem_wlaw_t;

/* W(S) and W'(S) for law (p: the power law's exponent, otherwise unused). */
double dem_wlaw_energy(dem_wlaw_t law, double kn, double p, double S);
double dem_wlaw_slope(dem_wlaw_t law, double kn, double p, double S);

/* The contact of P (moving) against Q (held), from their overlap. */
typedef struct dem_poly_contact {
	double S;         /* overlap area */
	double cs[2];     /* its centroid */
	int chains;       /* pieces of P's boundary inside Q (1: corner contact) */
	double g[2], h[2];/* ends of the contact line (chains = 1: P enters Q at h, leaves at g) */
	double gradS[2];  /* dS/dxp */
	double dSdth;     /* dS/dtheta, P turning about xp */
	double bw;        /* contact width |grad S| */
	double n[2];      /* unit normal on P, -grad S / bw */
	double c[2];      /* reference contact point */
	double W;         /* energy W(S) */
	double Fn;        /* |F| = W'(S) bw */
	double F[2];      /* force on P, Fn n, at c (-F on Q) */
	double M;         /* moment of F about xp, -W'(S) dS/dtheta = (c - xp) x F */
} dem_poly_contact_t;

/* From an overlap o with its points v[o->nv] and edge labels side (either
 * method's), P's reference point xp and the law: fills k.  Returns 1 in
 * contact (S > 0 and bw > 0), 0 otherwise (k zeroed), which includes one
 * polygon wholly inside the other: S is then the smaller one's area
 * whatever a small move, and the model has no force to give. */
int dem_polygon_contact(const dem_overlap_t *o, const double (*v)[2],
                        const unsigned char *side, const double xp[2], dem_wlaw_t law,
                        double kn, double p, dem_poly_contact_t *k);

#endif
