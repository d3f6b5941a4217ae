/* polygon.c - convex polygons and 2D superquadrics (Han 2004, Ch. 4.2-4.4).
 * See polygon.h. */
#include "contact/polygon.h"

#include <math.h>
#include <string.h>

#include "core/consts.h"

/* twice the signed area of (a, b, c): > 0 when c lies left of a -> b */
static inline double orient(const double a[2], const double b[2], const double c[2])
{
	return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* ---- superquadric ---------------------------------------------------- */

#define SQ_MAXDEPTH 24

typedef struct sq {
	double a, b, e, tau;  /* e = 2/m, the exponent of Eq. 4.3 */
	int cap, k;           /* room, points of the quarter so far */
	double (*v)[2];
} sq_t;

/* P(t) of Eq. 4.3 with exponent 2/m; cos(t) near pi/2 taken as
 * sin(pi/2 - t), so that a small power of it stays accurate */
static void sq_point(const sq_t *q, double t, double P[2])
{
	double c = t <= 0.25 * DEM_PI ? cos(t) : sin(0.5 * DEM_PI - t);
	double s = t >= 0.25 * DEM_PI ? sin(t) : cos(0.5 * DEM_PI - t);
	P[0] = q->a * pow(fmax(c, 0), q->e);
	P[1] = q->b * pow(fmax(s, 0), q->e);
}

static void sq_emit(sq_t *q, const double P[2])
{
	if (q->k < q->cap)
		q->v[q->k][0] = P[0], q->v[q->k][1] = P[1];
	q->k++;
}

/* Eq. 4.5: the distance of P2 from the segment P0 P1 below tau |P0 P1| */
static int sq_flat(const double P0[2], const double P1[2], const double P2[2], double tau)
{
	double dx = P1[0] - P0[0], dy = P1[1] - P0[1], l2 = dx * dx + dy * dy;
	double rx = P2[0] - P0[0], ry = P2[1] - P0[1];
	double u = l2 > 0 ? (rx * dx + ry * dy) / l2 : 0;
	u = fmin(fmax(u, 0), 1);
	double ex = rx - u * dx, ey = ry - u * dy;
	return ex * ex + ey * ey < tau * tau * l2;
}

/* Box 4.1, the points strictly between t0 and t1 in order (the text's
 * reading: a flat piece ends the refinement, otherwise its middle point is
 * a vertex between the two halves' points) */
static void sq_refine(sq_t *q, double t0, double t1, const double P0[2], const double P1[2],
                      int depth)
{
	double t2 = 0.5 * (t0 + t1), P2[2];
	sq_point(q, t2, P2);
	if (depth >= SQ_MAXDEPTH || sq_flat(P0, P1, P2, q->tau))
		return;
	sq_refine(q, t0, t2, P0, P2, depth + 1);
	sq_emit(q, P2);
	sq_refine(q, t2, t1, P2, P1, depth + 1);
}

int dem_superquadric_polygon(double a, double b, double m, double tau, int cap,
                             double (*v)[2])
{
	if (!(a > 0) || !(b > 0) || !(m >= 1) || !(tau > 0) || !isfinite(a) || !isfinite(b) ||
	    !isfinite(m) || !isfinite(tau))
		return -1;
	sq_t q = { a, b, 2 / m, tau, cap, 0, v };
	double P0[2] = { a, 0 }, P1[2] = { 0, b };
	sq_emit(&q, P0);
	sq_refine(&q, 0, 0.5 * DEM_PI, P0, P1, 0);
	int k = q.k, n = 4 * k;
	if (n > cap)
		return n;
	/* the other quarters: (0, b) and the mirrored points, and so on */
	for (int i = 0; i < k; i++) {
		int j = i == 0 ? 0 : k - i;  /* the quarter's points in reverse after its start */
		double x = v[j][0], y = v[j][1];
		if (i == 0)
			x = 0, y = b;
		v[k + i][0] = -x, v[k + i][1] = y;
	}
	for (int i = 0; i < k; i++) {
		v[2 * k + i][0] = -v[i][0], v[2 * k + i][1] = -v[i][1];
		v[3 * k + i][0] = -v[k + i][0], v[3 * k + i][1] = -v[k + i][1];
	}
	v[k][0] = 0;  /* not -0 */
	v[3 * k][0] = 0;
	v[2 * k][1] = 0;
	return n;
}

void dem_superquadric_props(double a, double b, double m, dem_area_props_t *p)
{
	double g1 = tgamma(1 + 1 / m);
	p->A = 4 * a * b * g1 * g1 / tgamma(1 + 2 / m);
	p->J = 4 * a * b * (a * a + b * b) * tgamma(3 / m) * tgamma(1 / m) / (m * m * tgamma(1 + 4 / m));
	p->c[0] = p->c[1] = 0;
}

/* ---- polygon properties --------------------------------------------- */

void dem_polygon_props(int n, const double (*v)[2], dem_area_props_t *p)
{
	memset(p, 0, sizeof *p);
	if (n <= 0)
		return;
	/* about v[0], against cancellation far from the origin */
	double ox = v[0][0], oy = v[0][1];
	double A2 = 0, mx = 0, my = 0, j = 0;
	for (int i = 0; i < n; i++) {
		int k = i + 1 == n ? 0 : i + 1;
		double x0 = v[i][0] - ox, y0 = v[i][1] - oy, x1 = v[k][0] - ox, y1 = v[k][1] - oy;
		double cr = x0 * y1 - x1 * y0;
		A2 += cr;
		mx += (x0 + x1) * cr;
		my += (y0 + y1) * cr;
		j += (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1) * cr;
	}
	if (A2 == 0) {
		double sx = 0, sy = 0;
		for (int i = 0; i < n; i++)
			sx += v[i][0], sy += v[i][1];
		p->c[0] = sx / n, p->c[1] = sy / n;
		return;
	}
	double cx = mx / (3 * A2), cy = my / (3 * A2);
	p->A = 0.5 * A2;
	p->c[0] = ox + cx, p->c[1] = oy + cy;
	p->J = j / 12 - p->A * (cx * cx + cy * cy);
}

void dem_polygon_regular(int m, double a, double b, double (*v)[2])
{
	for (int k = 0; k < m; k++) {
		double phi = -0.5 * DEM_PI + DEM_PI / m + 2 * DEM_PI * k / m;
		v[k][0] = a * cos(phi);
		v[k][1] = b * sin(phi);
	}
}

void dem_polygon_place(int n, const double (*v)[2], const double x[2], double theta,
                       double (*w)[2])
{
	double c = cos(theta), s = sin(theta);
	for (int i = 0; i < n; i++) {
		double px = v[i][0], py = v[i][1];
		w[i][0] = x[0] + c * px - s * py;
		w[i][1] = x[1] + s * px + c * py;
	}
}

/* ---- overlap: common --------------------------------------------------- */

/* The result list of an overlap method: points, the side each following
 * edge lies on, and the room. */
typedef struct olist {
	double (*v)[2];
	unsigned char *side;
	int n, cap;
} olist_t;

/* append X (side of the edge after it), skipping an exact repeat of the
 * last point (its side is updated instead) */
static void ol_emit(olist_t *l, const double X[2], int side)
{
	if (l->n > 0 && l->v[l->n - 1][0] == X[0] && l->v[l->n - 1][1] == X[1]) {
		if (l->side)
			l->side[l->n - 1] = (unsigned char)side;
		return;
	}
	if (l->n < l->cap) {
		l->v[l->n][0] = X[0], l->v[l->n][1] = X[1];
		if (l->side)
			l->side[l->n] = (unsigned char)side;
	}
	l->n++;
}

/* area and centroid of the list; S <= 0 (contact without area) gives an
 * empty result */
static int ol_finish(olist_t *l, dem_overlap_t *o)
{
	if (l->n > l->cap)
		l->n = l->cap;  /* cannot happen for convex input: see the tests */
	/* the closing point may repeat the first */
	while (l->n > 1 && l->v[l->n - 1][0] == l->v[0][0] && l->v[l->n - 1][1] == l->v[0][1])
		l->n--;
	dem_area_props_t p;
	dem_polygon_props(l->n, (const double (*)[2])l->v, &p);
	if (l->n < 3 || !(p.A > 0)) {
		o->S = 0, o->c[0] = o->c[1] = 0, o->nv = 0;
		return 0;
	}
	o->S = p.A, o->c[0] = p.c[0], o->c[1] = p.c[1], o->nv = l->n;
	return 1;
}

/* the point where edge ps -> pe crosses the line of an edge, from the
 * orientations d0, d1 of its ends against that line (opposite signs) */
static inline void cross_point(const double ps[2], const double pe[2], double d0, double d1,
                               double X[2])
{
	double s = d0 / (d0 - d1);
	X[0] = ps[0] + s * (pe[0] - ps[0]);
	X[1] = ps[1] + s * (pe[1] - ps[1]);
}

/* ---- overlap: the reference, full Sutherland-Hodgman ------------------ */

/* append X with the label of the edge after it, skipping an exact repeat
 * of the last point (whose label is updated instead) */
static void sh_emit(double (*v)[2], int *lab, int *cnt, int cap, const double X[2], int label)
{
	int k = *cnt;
	if (k > 0 && v[k - 1][0] == X[0] && v[k - 1][1] == X[1]) {
		lab[k - 1] = label;
		return;
	}
	if (k < cap)
		v[k][0] = X[0], v[k][1] = X[1], lab[k] = label;
	*cnt = k + 1;
}

/* Each point of the clipped polygon carries the label of the edge after it:
 * i < n when that edge lies on P's edge i, n + j on Q's edge j.  A crossing
 * is then computed as the chase computes it, from P's whole edge (not from
 * the piece an earlier line left), and where a piece of Q's edge j - 1
 * (or j + 1) meets the line of edge j the crossing is Q's point between
 * them, exactly: so both methods give the same points to the last bit
 * where they can, and Q's points are not recomputed from two nearly
 * parallel lines. */
int dem_polygon_clip(int n, const double (*P)[2], int m, const double (*Q)[2],
                     double (*v)[2], unsigned char *side, double (*work)[2],
                     dem_overlap_t *o)
{
	int cap = n + m;
	double (*cur)[2] = v, (*nxt)[2] = work;
	int *cl = (int *)(work + cap), *nl = cl + cap;
	int cn = n;
	for (int i = 0; i < n; i++)
		cur[i][0] = P[i][0], cur[i][1] = P[i][1], cl[i] = i;
	o->steps = 0;
	for (int j = 0; j < m && cn > 0; j++) {
		int jn = j + 1 == m ? 0 : j + 1, jp = j == 0 ? m - 1 : j - 1;
		const double *qs = Q[j], *qe = Q[jn];
		int nn = 0;
		double dprev = orient(qs, qe, cur[cn - 1]);
		for (int i = 0; i < cn; i++) {
			/* the edge k -> i of the current polygon, then point i */
			int k = i == 0 ? cn - 1 : i - 1;
			double d = orient(qs, qe, cur[i]);
			o->steps++;
			if ((dprev < 0 && d > 0) || (dprev > 0 && d < 0)) {
				double X[2];
				int lk = cl[k];
				const double *ps = P[lk < n ? lk : 0], *pe = P[lk + 1 < n ? lk + 1 : 0];
				double d0 = lk < n ? orient(qs, qe, ps) : 0, d1 = lk < n ? orient(qs, qe, pe) : 0;
				if (lk < n && d0 != d1) {
					cross_point(ps, pe, d0, d1, X);
				} else if (lk - n == jp) {
					X[0] = qs[0], X[1] = qs[1];
				} else if (lk - n == jn) {
					X[0] = qe[0], X[1] = qe[1];
				} else {
					cross_point(cur[k], cur[i], dprev, d, X);
				}
				/* entering: the subject's edge follows; leaving: the clip line */
				sh_emit(nxt, nl, &nn, cap, X, d > 0 ? lk : n + j);
			}
			if (d >= 0) {
				int inext = i + 1 == cn ? 0 : i + 1;
				double dn = orient(qs, qe, cur[inext]);
				/* on the line with the next point outside: the clip line follows */
				sh_emit(nxt, nl, &nn, cap, cur[i], d == 0 && dn < 0 ? n + j : cl[i]);
			}
			dprev = d;
		}
		/* the list's last point may repeat its first */
		if (nn > 1 && nxt[nn - 1][0] == nxt[0][0] && nxt[nn - 1][1] == nxt[0][1])
			nn--;
		cn = nn < 3 ? 0 : nn;
		double (*t)[2] = cur;
		cur = nxt, nxt = t;
		int *tl = cl;
		cl = nl, nl = tl;
	}
	if (cur != v)
		memcpy(v, cur, (size_t)cn * sizeof *v);
	for (int i = 0; i < cn; i++)
		side[i] = cl[i] >= n;
	olist_t l = { v, side, cn, cap };
	return ol_finish(&l, o);
}

/* ---- overlap: the linear algorithm (Box 4.2, Table 4.1) ---------------- */

enum { ADV_P = 1, ADV_Q = 2 };
enum { IN_NONE, IN_P, IN_Q };

/* The advancing rule.  Edges p (P's) and q (Q's) whose lines cross at
 * p(s) = q(t) (Eqs. 4.7-4.8); the classes of s and t are < 0, = 0,
 * (0, 1), = 1, > 1 (0 to 4).  O'Rourke et al.'s rule: when q turns left
 * from p (p x q > 0), advance p while the crossing lies before q's end
 * (t < 1, q_e inside p's half-plane), else q; when q turns right, advance
 * q while the crossing lies before p's end (s < 1), else p.  It is the
 * 'c' entry of Table 4.1 (advance q when q_e lies right of p, else p) for
 * p x q > 0, and the same with the roles of p and q swapped for p x q < 0.
 * It agrees with the table's fixed entries except in three cells for each
 * turning direction (six in all, each right for one direction only) and
 * in the cell s = t = 1, where the table advances both edges (we advance
 * one; the next pair finds the same point again).  Taken as printed, the
 * table loses crossings: 7 % of random pairs of triangles and 2 % of
 * squares came out wrong. */
static inline int advance(double cr, int sc, int tc)
{
	if (cr > 0)
		return tc <= 2 ? ADV_P : ADV_Q;
	return sc <= 2 ? ADV_Q : ADV_P;
}

/* the class of the parameter u = d0 / (d0 - d1) at which an edge whose
 * ends lie at orientations d0, d1 from a line crosses it (d0 != d1) */
static inline int uclass(double d0, double d1)
{
	if (d0 == 0)
		return 1;
	if (d1 == 0)
		return 3;
	if ((d0 > 0) != (d1 > 0))
		return 2;
	return fabs(d0) > fabs(d1) ? 4 : 0;
}

/* true when X is inside or on the convex polygon V[k] */
static int inside_convex(int k, const double (*V)[2], const double X[2])
{
	for (int i = 0; i < k; i++)
		if (orient(V[i], V[i + 1 == k ? 0 : i + 1], X) < 0)
			return 0;
	return 1;
}

/* ol_emit, but the first point reached again (once there are three)
 * closes the polygon: returns 1 then.  It closes in degenerate cases
 * where the first pair of edges is not met again (a point of both
 * boundaries found by other pairs, a collinear stretch passed by
 * advancing the other edge). */
static int chase_emit(olist_t *l, const double X[2], int side)
{
	if (l->n >= 3 && X[0] == l->v[0][0] && X[1] == l->v[0][1])
		return 1;
	ol_emit(l, X, side);
	return 0;
}

static int chase(int n, const double (*P)[2], int m, const double (*Q)[2], olist_t *l,
                 int *steps)
{
	int ia = 0, ib = 0, inflag = IN_NONE, found = 0, fa = -1, fb = -1;
	int maxit = 2 * (n + m), k;
	for (k = 0; k < maxit; k++) {
		int ja = ia + 1 == n ? 0 : ia + 1, jb = ib + 1 == m ? 0 : ib + 1;
		const double *ps = P[ia], *pe = P[ja], *qs = Q[ib], *qe = Q[jb];
		double ax = pe[0] - ps[0], ay = pe[1] - ps[1];
		double bx = qe[0] - qs[0], by = qe[1] - qs[1];
		double cr = ax * by - ay * bx;
		double oqs = orient(ps, pe, qs), oqe = orient(ps, pe, qe);  /* q against p's line */
		double ops = orient(qs, qe, ps), ope = orient(qs, qe, pe);  /* p against q's line */
		int adv;
		if (cr == 0 || oqs == oqe || ops == ope) {
			/* parallel edges: no cell of Table 4.1 */
			if (ax * bx + ay * by < 0) {
				/* opposite: Q on the far side of p's line, or touching along it:
				 * no area in common */
				if (oqs <= 0 && oqe <= 0)
					return 0;
				adv = ADV_P;
			} else if (oqs == 0 && oqe == 0) {
				adv = inflag == IN_P ? ADV_Q : ADV_P;
			} else {
				adv = oqe < 0 ? ADV_Q : ADV_P;
			}
		} else {
			int sc = uclass(ops, ope), tc = uclass(oqs, oqe);
			if (sc >= 1 && sc <= 3 && tc >= 1 && tc <= 3) {
				/* Box 4.2: the edges meet at X; the first point found again
				 * closes the polygon */
				double X[2];
				if (sc == 1)
					X[0] = ps[0], X[1] = ps[1];
				else if (sc == 3)
					X[0] = pe[0], X[1] = pe[1];
				else if (tc == 1)
					X[0] = qs[0], X[1] = qs[1];
				else if (tc == 3)
					X[0] = qe[0], X[1] = qe[1];
				else
					cross_point(ps, pe, ops, ope, X);
				/* the first crossing found again by the same pair closes the
				 * polygon (and so does its point reached again: chase_emit) */
				if (found && ia == fa && ib == fb)
					break;
				if (!found)  /* then at most one more round of each */
					found = 1, fa = ia, fb = ib, maxit = k + 1 + 2 * (n + m);
				/* which boundary runs inside the other from X on */
				if (ope > 0)
					inflag = IN_P;
				else if (oqe > 0)
					inflag = IN_Q;
				if (chase_emit(l, X, inflag == IN_Q))
					break;
			}
			adv = advance(cr, sc, tc);
		}
		if (adv & ADV_P) {
			if (inflag == IN_P && chase_emit(l, pe, 0))
				break;
			ia = ja;
		}
		if (adv & ADV_Q) {
			if (inflag == IN_Q && chase_emit(l, qe, 1))
				break;
			ib = jb;
		}
	}
	*steps = k;
	if (found)
		return 1;
	/* no crossing: one inside the other, or apart */
	l->n = 0;
	if (inside_convex(m, Q, P[0])) {
		for (int i = 0; i < n; i++)
			ol_emit(l, P[i], 0);
		return 1;
	}
	if (inside_convex(n, P, Q[0])) {
		for (int i = 0; i < m; i++)
			ol_emit(l, Q[i], 1);
		return 1;
	}
	return 0;
}

/* Ch. 4.3.2: V[k] against the window w (xmin, ymin, xmax, ymax), one side
 * at a time; a point is dropped when it and both its neighbours (in the
 * polygon left by the sides before) lie strictly outside the side.  The
 * sides' outcodes of every point first, then the passes on a list of
 * indices, and the points left gathered at the end.  buf: room for 2 k
 * points (the result, then the indices and codes).  Returns the points
 * left (in buf, *out), 0 when the polygon has no point inside a side. */
static int clip_window(int k, const double (*V)[2], const double w[4], double (*buf)[2],
                       const double (**out)[2])
{
	int k0 = k, *src = (int *)(buf + k), *dst = src + k;
	unsigned char *code = (unsigned char *)(dst + k);
	unsigned in = 0, outside = 0;
	const double x0 = w[0], y0 = w[1], x1 = w[2], y1 = w[3];  /* not reloaded past the stores */
	for (int i = 0; i < k; i++) {
		double x = V[i][0], y = V[i][1];
		unsigned c = (unsigned)(x < x0) | (unsigned)(y < y0) << 1 |
		             (unsigned)(x > x1) << 2 | (unsigned)(y > y1) << 3;
		code[i] = (unsigned char)c;
		in |= ~c, outside |= c;
		src[i] = i;
	}
	if ((in & 15) != 15)
		return 0;  /* every point beyond one side */
	for (int sd = 0; sd < 4; sd++) {
		unsigned bit = 1u << sd;
		if (!(outside & bit))
			continue;  /* no point beyond this side: nothing to drop */
		int cnt = 0;
		unsigned op = code[src[k - 1]] & bit, oc = code[src[0]] & bit;
		for (int i = 0; i < k; i++) {
			unsigned on = code[src[i + 1 == k ? 0 : i + 1]] & bit;
			if (!(op & oc & on))
				dst[cnt++] = src[i];
			op = oc, oc = on;
		}
		if (cnt == 0)
			return 0;  /* the polygon left lies beyond this side */
		k = cnt;
		int *t = src;
		src = dst, dst = t;
	}
	if (k == k0) {
		*out = V;  /* nothing dropped */
		return k;
	}
	for (int i = 0; i < k; i++)
		buf[i][0] = V[src[i]][0], buf[i][1] = V[src[i]][1];
	*out = (const double (*)[2])buf;
	return k;
}

static void bbox(int k, const double (*V)[2], double b[4])
{
	b[0] = b[2] = V[0][0], b[1] = b[3] = V[0][1];
	for (int i = 1; i < k; i++) {
		double x = V[i][0], y = V[i][1];
		b[0] = x < b[0] ? x : b[0], b[2] = x > b[2] ? x : b[2];
		b[1] = y < b[1] ? y : b[1], b[3] = y > b[3] ? y : b[3];
	}
}

int dem_polygon_chase(int n, const double (*P)[2], int m, const double (*Q)[2], int clip,
                      double (*v)[2], unsigned char *side, double (*work)[2],
                      dem_overlap_t *o)
{
	olist_t l = { v, side, 0, 2 * (n + m) };
	int steps = 0;
	o->steps = 0;
	if (clip) {
		double bp[4], bq[4], w[4];
		bbox(n, P, bp);
		bbox(m, Q, bq);
		w[0] = fmax(bp[0], bq[0]), w[1] = fmax(bp[1], bq[1]);
		w[2] = fmin(bp[2], bq[2]), w[3] = fmin(bp[3], bq[3]);
		/* boxes apart or touching: no area in common */
		if (!(w[0] < w[2] && w[1] < w[3]))
			return ol_finish(&l, o);
		const double (*Pc)[2], (*Qc)[2];
		int nc = clip_window(n, P, w, work, &Pc);
		int mc = nc ? clip_window(m, Q, w, work + 2 * n, &Qc) : 0;
		if (!nc || !mc)
			return ol_finish(&l, o);
		if (!chase(nc, Pc, mc, Qc, &l, &steps))
			l.n = 0;
	} else if (!chase(n, P, m, Q, &l, &steps)) {
		l.n = 0;
	}
	int r = ol_finish(&l, o);
	o->steps = steps;
	return r;
}

/* ---- contact (Ch. 4.4) --------------------------------------------------- */

double dem_wlaw_energy(dem_wlaw_t law, double kn, double p, double S)
{
	if (!(S > 0))
		return 0;
	switch (law) {
	case DEM_W_LINEAR:
		return kn * S;
	case DEM_W_HERTZ:
		return 2.0 / 3.0 * kn * S * sqrt(S);
	case DEM_W_POWER:
		return kn * pow(S, p) / p;
	}
	return 0;
}

double dem_wlaw_slope(dem_wlaw_t law, double kn, double p, double S)
{
	if (!(S > 0))
		return 0;
	switch (law) {
	case DEM_W_LINEAR:
		return kn;
	case DEM_W_HERTZ:
		return kn * sqrt(S);
	case DEM_W_POWER:
		return kn * pow(S, p - 1);
	}
	return 0;
}

int dem_polygon_contact(const dem_overlap_t *o, const double (*v)[2],
                        const unsigned char *side, const double xp[2], dem_wlaw_t law,
                        double kn, double p, dem_poly_contact_t *k)
{
	memset(k, 0, sizeof *k);
	int nv = o->nv;
	if (!(o->S > 0) || nv < 3)
		return 0;
	/* the edges on P's boundary (Eqs. 4.19-4.24, summed over the chains of
	 * Eq. 4.31; each edge's terms telescope along a chain) */
	double gx = 0, gy = 0, dth = 0;
	int chains = 0, first = -1, last = -1;
	for (int i = 0; i < nv; i++) {
		int j = i + 1 == nv ? 0 : i + 1;
		double dx = v[j][0] - v[i][0], dy = v[j][1] - v[i][1];
		if (dx == 0 && dy == 0)
			continue;
		if (side[i] == 0) {
			gx += dy, gy -= dx;
			dth -= dx * (0.5 * (v[i][0] + v[j][0]) - xp[0]) +
			       dy * (0.5 * (v[i][1] + v[j][1]) - xp[1]);
		}
		/* a chain starts where a P edge follows a Q edge */
		if (last >= 0 && side[i] == 0 && side[last] != 0)
			chains++;
		if (first < 0)
			first = i;
		last = i;
	}
	if (first < 0)
		return 0;
	if (side[first] == 0 && side[last] != 0)
		chains++;
	/* one polygon inside the other: S does not change as P moves a little
	 * (grad S would be round-off) */
	if (chains == 0)
		return 0;
	k->S = o->S;
	k->cs[0] = o->c[0], k->cs[1] = o->c[1];
	k->chains = chains;
	k->gradS[0] = gx, k->gradS[1] = gy;
	k->dSdth = dth;
	k->bw = hypot(gx, gy);
	if (!(k->bw > 0))
		return 0;
	k->n[0] = -gx / k->bw, k->n[1] = -gy / k->bw;
	if (chains == 1) {
		/* the chain's ends: h where it starts, g where it ends */
		for (int i = 0; i < nv; i++) {
			int prev = i == 0 ? nv - 1 : i - 1;
			/* skip zero-length edges backwards to the real previous side */
			while (prev != i && v[prev][0] == v[prev + 1 == nv ? 0 : prev + 1][0] &&
			       v[prev][1] == v[prev + 1 == nv ? 0 : prev + 1][1])
				prev = prev == 0 ? nv - 1 : prev - 1;
			int j = i + 1 == nv ? 0 : i + 1;
			if (v[j][0] == v[i][0] && v[j][1] == v[i][1])
				continue;
			if (side[i] == 0 && side[prev] != 0)
				k->h[0] = v[i][0], k->h[1] = v[i][1];
			if (side[i] != 0 && side[prev] == 0)
				k->g[0] = v[i][0], k->g[1] = v[i][1];
		}
		k->c[0] = 0.5 * (k->g[0] + k->h[0]), k->c[1] = 0.5 * (k->g[1] + k->h[1]);
	} else {
		/* the line of action's point nearest the centroid: (c - xp) x n =
		 * M / |F| = -dS/dtheta / bw */
		double tx = -k->n[1], ty = k->n[0];
		double rx = k->cs[0] - xp[0], ry = k->cs[1] - xp[1];
		double beta = rx * k->n[1] - ry * k->n[0] + dth / k->bw;
		k->c[0] = k->cs[0] + beta * tx, k->c[1] = k->cs[1] + beta * ty;
		/* g - h = (-grad_y S, grad_x S) = -bw t */
		k->g[0] = k->c[0] - 0.5 * k->bw * tx, k->g[1] = k->c[1] - 0.5 * k->bw * ty;
		k->h[0] = k->c[0] + 0.5 * k->bw * tx, k->h[1] = k->c[1] + 0.5 * k->bw * ty;
	}
	k->W = dem_wlaw_energy(law, kn, p, k->S);
	k->Fn = dem_wlaw_slope(law, kn, p, k->S) * k->bw;
	k->F[0] = k->Fn * k->n[0], k->F[1] = k->Fn * k->n[1];
	k->M = -dem_wlaw_slope(law, kn, p, k->S) * dth;
	return 1;
}
