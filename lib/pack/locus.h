/* locus.h - the geometry of the advancing front for polygons and ellipses
 * (Han 2004, Ch. 5.3-5.4): Minkowski sums of convex polygons, ellipses by
 * their support points, and the loci of a body sliding round another.
 *
 * A body W placed with its centre at x touches a convex body P (centre
 * c) without overlapping it exactly when x lies on the boundary of the
 * locus P + (-W) (the Minkowski sum of P and W turned through 180
 * degrees, Fig. 5.14(a)); x inside the locus means overlap.  The packer
 * places W where its loci round the two bodies of the active segment
 * cross (Fig. 5.14(b), Fig. 5.16(b)).
 *
 * Polygons: P + (-W) is the convex polygon whose edges are those of P and
 * -W merged by direction (na + nb vertices), built in linear time.
 *
 * Ellipses: an ellipse about 0 is its shape matrix M = R diag(a^2, b^2)
 * R^T, stored {mxx, mxy, myy} (x inside when x^T M^-1 x <= 1).  Its
 * support point in the unit direction n is M n / sqrt(n^T M n), so the
 * locus of W round P, with n = (cos u, sin u), is the curve
 *     L(u) = c + M_P n / sqrt(n^T M_P n) + M_W n / sqrt(n^T M_W n),
 * smooth and convex, whose outward normal at L(u) is n.  (The thesis
 * parametrises the same curve by the contact point's angle on P; the
 * normal angle gives both terms at once.)  The tangent lines at K evenly
 * spaced normals bound it from outside (a circumscribed polygon), and the
 * points L(u_k) from inside: the hierarchical bounds of Ch. 5.4.
 *
 * Overlap of two ellipses (the packer's test): the Perram-Wertheim
 * contact function F = max over l in [0, 1] of
 *     l (1 - l) d^T [(1 - l) M_A + l M_B]^-1 d      (d = c_B - c_A),
 * with one maximum in l, equal to s^2 for the factor s by which both
 * ellipses scaled about their centres would just touch: F < 1 overlap,
 * F = 1 touching, F > 1 apart.
 */
#ifndef DEM_PACK_LOCUS_H
#define DEM_PACK_LOCUS_H

/* The Minkowski sum S = A + B of the convex anticlockwise polygons A (na
 * points) and B (nb points); na or nb may be 1 (a point) or 2 (a
 * segment).  S has room for na + nb points; sa (may be NULL) receives,
 * for each point of S, its part from A (the point of A that touches
 * there).  Returns the number of points of S. */
int dem_minkowski(int na, const double (*A)[2], int nb, const double (*B)[2],
		  double (*S)[2], double (*sa)[2]);

/* How deep x lies inside the convex anticlockwise polygon S (n >= 2
 * points; collinear points allowed): the least signed distance from x to
 * the lines of its edges, positive inside. */
double dem_convex_depth(int n, const double (*S)[2], const double x[2]);

/* The shape matrix of the ellipse of semi-axes a, b turned by the angle
 * whose cosine and sine are c, s. */
void dem_ellipse_matrix(double a, double b, double c, double s, double m[3]);

/* The support function h(n) = sqrt(n^T M n) of the ellipse about 0 in
 * the direction n, and (sp, may be NULL) its support point M n / h. */
double dem_ellipse_support(const double m[3], const double n[2], double sp[2]);

/* The Perram-Wertheim function F of ellipses A and B whose centres are d
 * apart (above).  The search stops as soon as F >= stop is known (then
 * some value >= stop is returned): pass stop = HUGE_VAL for F itself.
 * *evals (may be NULL) is increased by the evaluations made. */
double dem_ellipse_pw(const double ma[3], const double mb[3], const double d[2], double stop,
		      long *evals);

/* A locus for the Newton solve: the line c + u t (line = 1, t a unit
 * vector), or the curve L(u) above with centre c, M_P = m1 (zero = a
 * point: the locus of W round a point is -W about it) and M_W = m2. */
typedef struct dem_locus {
	int line;
	double c[2], t[2];
	double m1[3], m2[3];
} dem_locus_t;

/* The locus's point at u and its derivative (dx may be NULL). */
void dem_locus_eval(const dem_locus_t *L, double u, double x[2], double dx[2]);

/* The curve's circumscribed polygon of K >= 3 points: v[k] where the
 * tangent lines at the normals u_k = 2 pi k / K and u_{k+1} meet, so the
 * edge v[k-1] -> v[k] lies on the tangent at u_k. */
void dem_locus_outer(const dem_locus_t *L, int K, double (*v)[2]);

/* Newton's method on A(u) = B(v) from (u, v): at most maxit steps, until
 * |A(u) - B(v)| <= tol.  Returns the steps taken, or -1 when it does not
 * converge (the Jacobian singular, a step not finite or of more than a
 * radian on a curve, maxit reached).  *steps (may be NULL): the steps
 * taken either way, for an honest count of the work. */
int dem_locus_meet(const dem_locus_t *A, const dem_locus_t *B, double *u, double *v,
		   double tol, int maxit, int *steps);

#endif
