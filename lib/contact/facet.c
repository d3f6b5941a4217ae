/* facet.c - sphere/facet contact geometry with partial contact (Han 2004,
 * Eqs. 3.13-3.22).  See facet.h. */
#include "contact/facet.h"

#include <math.h>
#include <string.h>

#include "contact/gauss.h"
#include "contact/vec3.h"
#include "core/consts.h"

/* The sums over one circle/triangle overlap: area S, first moments (Mx,
 * My), polar moment J, the moments (Kx, Ky) of r^2 x, r^2 y; and over the
 * arc of the circle inside the triangle (theta the direction on the
 * circle): its angle th, the sums of sin and cos differences sx = int cos,
 * sy = int sin, and s2, c2 the differences of sin 2 theta and cos 2 theta
 * (the integrals of nu nu^T d theta, nu the circle's unit normal). */
typedef struct overlap {
	double S, Mx, My, J, Kx, Ky;
	double th, sx, sy, s2, c2;
} overlap_t;

/* The stretches of the edge A + t (dx, dy), t in [0, 1], against the circle
 * (centre 0, radius r): [t0, t1] outside, [t1, t2] inside, [t2, t3]
 * outside, with t1 <= t2 the crossings clamped to [0, 1]; no crossing (or
 * a tangent): all outside. */
static void edge_cuts(double ax, double ay, double dx, double dy, double r, double t[4])
{
	double qa = dx * dx + dy * dy, qb = ax * dx + ay * dy, qc = ax * ax + ay * ay - r * r;
	t[0] = t[1] = t[2] = 0, t[3] = 1;
	double disc = qb * qb - qa * qc;
	if (qa > 0 && disc > 0) {
		double sq = sqrt(disc);
		/* roots of qa t^2 + 2 qb t + qc, without cancellation */
		double q = qb > 0 ? -(qb + sq) : -(qb - sq);
		double t1 = q / qa, t2 = q != 0 ? qc / q : t1;
		if (t1 > t2) {
			double h = t1;
			t1 = t2, t2 = h;
		}
		t[1] = fmin(fmax(t1, 0), 1);
		t[2] = fmin(fmax(t2, 0), 1);
	}
}

/* The circle's arc between the directions of P and Q (relative to its
 * centre), signed anticlockwise: its angle th, the differences of sin and
 * cos (sx = int cos, sy = int sin) and of sin 2 theta and cos 2 theta. */
typedef struct arc {
	double th, sx, sy, s2, c2;
} arc_t;

static arc_t sector_arc(double px, double py, double qx, double qy)
{
	double lp = sqrt(px * px + py * py), lq = sqrt(qx * qx + qy * qy);
	double cp = px / lp, sp = py / lp, cq = qx / lq, sq = qy / lq;
	return (arc_t){
		.th = atan2(px * qy - py * qx, px * qx + py * qy),
		.sx = sq - sp,
		.sy = cp - cq,
		.s2 = 2 * (sq * cq - sp * cp),
		.c2 = (cq * cq - sq * sq) - (cp * cp - sp * sp),
	};
}

/* The signed piece of one edge, A -> B (relative to the circle's centre):
 * the circle's part inside the triangle (0, A, B), signed by its
 * orientation.  The edge is cut where it crosses the circle; a stretch
 * inside the circle gives the triangle (0, P, Q), a stretch outside the
 * circular sector between the directions of P and Q, whose arc is the
 * arc's share of this piece. */
static void edge_piece(double ax, double ay, double bx, double by, double r, overlap_t *o)
{
	double dx = bx - ax, dy = by - ay, t[4];
	edge_cuts(ax, ay, dx, dy, r, t);
	double r2 = r * r;
	for (int i = 0; i < 3; i++) {
		if (!(t[i + 1] > t[i]))
			continue;
		double px = ax + t[i] * dx, py = ay + t[i] * dy;
		double qx = ax + t[i + 1] * dx, qy = ay + t[i + 1] * dy;
		double cr = px * qy - py * qx;
		if (i == 1) {
			/* triangle (0, P, Q); cubic moments by int s^a t^b = a! b!/(a+b+2)! */
			double s = 0.5 * cr, pp = px * px + py * py, qq = qx * qx + qy * qy, pq = px * qx + py * qy;
			o->S += s;
			o->Mx += s * (px + qx) / 3;
			o->My += s * (py + qy) / 3;
			o->J += s * (pp + qq + pq) / 6;
			o->Kx += cr * ((px * pp + qx * qq) / 20 + (2 * px * pq + qx * pp + px * qq + 2 * qx * pq) / 60);
			o->Ky += cr * ((py * pp + qy * qq) / 20 + (2 * py * pq + qy * pp + py * qq + 2 * qy * pq) / 60);
		} else {
			/* sector between the directions of P and Q */
			arc_t a = sector_arc(px, py, qx, qy);
			double s = 0.5 * r2 * a.th, c = r2 * r / 3;
			o->S += s;
			o->Mx += c * a.sx;
			o->My += c * a.sy;
			o->J += 0.5 * s * r2;
			o->Kx += 0.6 * c * r2 * a.sx;  /* r^5/5 */
			o->Ky += 0.6 * c * r2 * a.sy;
			o->th += a.th;
			o->sx += a.sx;
			o->sy += a.sy;
			o->s2 += a.s2;
			o->c2 += a.c2;
		}
	}
}

static void circle_triangle(const double x[3], const double y[3], double r, overlap_t *o)
{
	*o = (overlap_t){ 0 };
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3;
		edge_piece(x[i], y[i], x[j], y[j], r, o);
	}
}

void dem_circle_triangle(const double x[3], const double y[3], double r,
                         double *S, double *Mx, double *My, double *J)
{
	overlap_t o;
	circle_triangle(x, y, r, &o);
	*S = o.S, *Mx = o.Mx, *My = o.My, *J = o.J;
}

/* The point of the segment A B nearest to O into q; its squared distance. */
static double segment_closest(const double O[3], const double A[3], const double B[3], double q[3])
{
	double d[3], w[3];
	v3_sub(B, A, d);
	v3_sub(O, A, w);
	double dd = v3_dot(d, d), t = dd > 0 ? v3_dot(w, d) / dd : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	for (int i = 0; i < 3; i++)
		q[i] = A[i] + t * d[i];
	v3_sub(O, q, w);
	return v3_dot(w, w);
}

double dem_triangle_closest(const double O[3], const double X[3][3], double q[3])
{
	double e1[3], e2[3], n[3], w[3], c[3];
	v3_sub(X[1], X[0], e1);
	v3_sub(X[2], X[0], e2);
	v3_sub(O, X[0], w);
	v3_cross(e1, e2, n);
	double nn = v3_dot(n, n);
	if (nn > 0) {
		/* O's projection on the plane, X0 + s e1 + t e2 */
		v3_cross(w, e2, c);
		double s = v3_dot(c, n) / nn;
		v3_cross(e1, w, c);
		double t = v3_dot(c, n) / nn;
		if (s >= 0 && t >= 0 && s + t <= 1) {
			double h = v3_dot(w, n) / nn;
			for (int i = 0; i < 3; i++)
				q[i] = O[i] - h * n[i];
			return h * h * nn;
		}
	}
	/* outside (or degenerate): the nearest of the three edges */
	double best = HUGE_VAL, p[3];
	for (int a = 0; a < 3; a++) {
		double d2 = segment_closest(O, X[a], X[(a + 1) % 3], p);
		if (d2 < best) {
			best = d2;
			memcpy(q, p, sizeof p);
		}
	}
	return best;
}

int dem_facet_geom(const double O[3], double R, const double X[3][3], int scheme,
                   dem_facet_geom_t *g)
{
	double e1[3], e2[3], nf[3];
	v3_sub(X[1], X[0], e1);
	v3_sub(X[2], X[0], e2);
	v3_cross(e1, e2, nf);
	double A2 = v3_norm(nf);  /* twice the facet's area */
	if (!(A2 > 0))
		return 0;
	for (int i = 0; i < 3; i++)
		nf[i] /= A2;
	double rel[3];
	v3_sub(O, X[0], rel);
	double d = v3_dot(rel, nf);
	if (!(d > 0) || d >= R)
		return 0;
	double delta = R - d;
	double b2 = delta * (2 * R - delta), b = sqrt(b2);

	/* facet frame: u along edge 1, w = nf x u; coordinates relative to C */
	double l1 = v3_norm(e1), u[3], w[3];
	for (int i = 0; i < 3; i++)
		u[i] = e1[i] / l1;
	v3_cross(nf, u, w);
	double cx = v3_dot(rel, u), cy = v3_dot(rel, w);  /* C relative to X1 */
	double x[3] = { -cx, l1 - cx, v3_dot(e2, u) - cx };
	double y[3] = { -cy, -cy, v3_dot(e2, w) - cy };

	/* signed distances of C from the edges (positive inside) */
	int full = 1;
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3;
		double ex = x[j] - x[i], ey = y[j] - y[i];
		double len = sqrt(ex * ex + ey * ey);
		double dist = (ex * (-y[i]) - ey * (-x[i])) / len;  /* C left of the edge: > 0 */
		if (dist <= -b)
			return 0;  /* the circle lies wholly outside this edge */
		if (dist < b)
			full = 0;
	}
	double S, gx = 0, gy = 0;
	g->gamma = 1;
	g->pot = 0;
	if (full) {
		S = DEM_PI * b2;
	} else {
		overlap_t o;
		circle_triangle(x, y, b, &o);
		S = o.S;
		/* grazing: nothing left but round-off */
		if (!(S > 1e-13 * DEM_PI * b2))
			return 0;
		if (scheme == DEM_PARTIAL_VOLUME) {
			/* V_p / V_f over the cap delta (1 - r^2/b^2), and G its
			 * centroid projected on the plane */
			double wv = S - o.J / b2;
			if (!(wv > 0))
				return 0;
			g->gamma = 2 * wv / (DEM_PI * b2);
			gx = (o.Mx - o.Kx / b2) / wv, gy = (o.My - o.Ky / b2) / wv;
		} else {
			g->gamma = S / (DEM_PI * b2);  /* Eq. 3.15 */
			gx = o.Mx / S, gy = o.My / S;  /* Eq. 3.21, G relative to C */
		}
		if (g->gamma > 1)
			g->gamma = 1;
		if (scheme == DEM_PARTIAL_POTENTIAL) {
			g->pot = 1;
			g->R = R;
			g->d = d;
			g->A2 = A2;
			for (int i = 0; i < 3; i++) {
				g->nf[i] = nf[i], g->u[i] = u[i], g->w[i] = w[i];
				g->x[i] = x[i], g->y[i] = y[i];
			}
		}
	}
	g->delta = delta;
	g->b = b;
	g->Sp = S;
	g->full = full;
	double on[3];
	for (int i = 0; i < 3; i++) {
		g->G[i] = O[i] - d * nf[i] + gx * u[i] + gy * w[i];
		on[i] = O[i] - g->G[i];
	}
	double lo = v3_norm(on);
	for (int i = 0; i < 3; i++)
		g->n[i] = on[i] / lo;
	/* area coordinates of G: sub-triangle areas over the whole */
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3, k = (i + 2) % 3;
		g->N[i] = ((x[j] - gx) * (y[k] - gy) - (x[k] - gx) * (y[j] - gy)) / A2;
	}
	return 1;
}

/* ---- The potential scheme (facet.h) ------------------------------------- */

/* The branch of the law, F(g) = c g^m for g > 0, g = R' - q the overlap of
 * a point at distance q from O with the branch's sphere of radius R'. */
typedef struct branch {
	double c, m, R, d, delta;  /* c, m, R', the plane's distance d, R' - d */
	double w0;                 /* w at C: F(delta) / (2 pi d) */
	double W0;                 /* W(delta) = c delta^(m+1) / (m+1) */
} branch_t;

/* g^m, without pow() for the named laws */
static inline double br_pow(double m, double g)
{
	return m == 1.0 ? g : m == 1.5 ? g * sqrt(g) : m == 2.0 ? g * g : pow(g, m);
}

/* At distance q from O: w(q^2) = F(R' - q) / (2 pi q), the energy per unit
 * area of a surface point there (see facet.h), and W(R' - q) */
static inline void br_wW(const branch_t *B, double q, double *w, double *W)
{
	double g = B->R - q;
	if (!(g > 0)) {
		*w = *W = 0;
		return;
	}
	double F = B->c * br_pow(B->m, g);
	*w = F / (2 * DEM_PI * q);
	*W = F * g / (B->m + 1);
}

/* The integrals over the part of the circle (centre C = 0, radius b) inside
 * the convex polygon (x, y) of nv vertices, anticlockwise (a facet's
 * triangle; disk.c's strip): A0 = int w dA, B0 = int 2 w' dA, B1 = int 2 w' y dA,
 * B2 = int 2 w' y y^T dA (w' = dw/d(q^2), y in-plane relative to C).  The
 * region is summed from the signed edge pieces as S_p is (sectors in
 * closed form, the triangles (0, P, Q) along their chords, the radial
 * integrals being closed); B1 is int grad w dA, the flux of w through the
 * region's boundary, where w = 0 on the arc: only the chords inside the
 * circle count.  Along a chord: two 8-point Gauss-Legendre panels in tau,
 * t = tau^2 (3 - 2 tau), which smooths the ends where the chord meets the
 * circle (w ~ g^m there): the forces then match central differences of the
 * potential to 1e-6 of the force (tests/unit/test_contact_facet.c), against
 * 3e-4 with 8 plain points. */
static void local_integrals(const branch_t *B, const double *x, const double *y, int nv, double b,
                            double *A0, double *B0, double B1[2], double B2[3])
{
	*A0 = *B0 = 0;
	B1[0] = B1[1] = B2[0] = B2[1] = B2[2] = 0;
	double d2 = B->d * B->d;
	for (int e = 0; e < nv; e++) {
		int f = (e + 1) % nv;
		double ax = x[e], ay = y[e], dx = x[f] - ax, dy = y[f] - ay, t[4];
		edge_cuts(ax, ay, dx, dy, b, t);
		for (int i = 0; i < 3; i++) {
			if (!(t[i + 1] > t[i]))
				continue;
			double px = ax + t[i] * dx, py = ay + t[i] * dy;
			double qx = ax + t[i + 1] * dx, qy = ay + t[i + 1] * dy;
			double cr = px * qy - py * qx;
			if (i != 1) {
				/* sector: int_0^b w r dr = W0 / (2 pi), int_0^b 2 w' r dr =
				 * -w0, int_0^b 2 w' r^3 dr = -2 int_0^b w r dr */
				arc_t a = sector_arc(px, py, qx, qy);
				double rb2 = -B->W0 / DEM_PI;
				*A0 += a.th * B->W0 / (2 * DEM_PI);
				*B0 -= a.th * B->w0;
				B2[0] += rb2 * (0.5 * a.th + 0.25 * a.s2);
				B2[1] += rb2 * (-0.25 * a.c2);
				B2[2] += rb2 * (0.5 * a.th - 0.25 * a.s2);
				continue;
			}
			/* triangle (0, P, Q): points s y_t, y_t = P + t (Q - P), dA =
			 * cr s ds dt; for f(r) phi(y), phi of degree k, int_0^1 f(s rho)
			 * s^(k+1) ds = R_k(rho) / rho^(k+2), with R_0 = int_0^rho w r dr
			 * = (W0 - W(g)) / (2 pi), int_0^rho 2 w' r dr = w(rho) - w0 and
			 * int_0^rho 2 w' r^3 dr = rho^2 w(rho) - 2 R_0 (rho = |y_t|,
			 * g = R' - sqrt(rho^2 + d^2)); fw: int_0^1 w dt on the chord */
			double ex = qx - px, ey = qy - py, fw = 0;
			for (int kk = 0; kk < 16; kk++) {
				int k = kk % 8;
				double tau = ((kk / 8) + gl_t[k]) / 2;
				double tt = tau * tau * (3 - 2 * tau), jac = 6 * tau * (1 - tau);
				double yx = px + tt * ex, yy = py + tt * ey;
				double r2 = yx * yx + yy * yy, q = sqrt(r2 + d2);
				double wq, Wq;
				br_wW(B, q, &wq, &Wq);
				double R0 = (B->W0 - Wq) / (2 * DEM_PI);
				double cw = cr * gl_w[k] * jac / 2 / r2;
				*A0 += cw * R0;
				*B0 += cw * (wq - B->w0);
				double r4 = (r2 * wq - 2 * R0) / r2;
				B2[0] += cw * r4 * yx * yx;
				B2[1] += cw * r4 * yx * yy;
				B2[2] += cw * r4 * yy * yy;
				fw += gl_w[k] * jac / 2 * wq;
			}
			/* outward normal of an anticlockwise edge: (ey, -ex) / |e| */
			B1[0] += ey * fw;
			B1[1] -= ex * fw;
		}
	}
}

void dem_facet_forces(const dem_facet_geom_t *g, const dem_contact_out_t *o, double m,
                      double F[3], double Fnode[3][3], double *Phi)
{
	if (!g->pot) {
		for (int a = 0; a < 3; a++)
			for (int i = 0; i < 3; i++)
				Fnode[a][i] = -g->N[a] * o->F[i];
		for (int i = 0; i < 3; i++)
			F[i] = o->F[i];
		if (Phi) {
			double x = g->delta - o->bg0;
			*Phi = x > 0 ? g->gamma * o->bc * pow(x, m + 1) / (m + 1) : 0;
		}
		return;
	}
	/* the branch's sphere, R' = R - g0 */
	branch_t B = { .c = o->bc, .m = m, .R = g->R - o->bg0, .d = g->d };
	B.delta = B.R - B.d;
	double rest[3];
	for (int i = 0; i < 3; i++)
		rest[i] = o->F[i] - o->Fe * g->n[i];  /* damping and friction, at G */
	double A0 = 0, B0 = 0, B1[2] = { 0, 0 }, B2[3] = { 0, 0, 0 };
	if (B.delta > 0 && B.c > 0) {
		double F0 = B.c * br_pow(m, B.delta);
		B.w0 = F0 / (2 * DEM_PI * B.d);
		B.W0 = F0 * B.delta / (m + 1);
		local_integrals(&B, g->x, g->y, 3, sqrt(B.delta * (B.R + B.d)), &A0, &B0, B1, B2);
	}
	/* dPhi/dO = -int 2 w' (y - O) dA with y - O = (y - C) - d nf */
	double b1[3];
	for (int i = 0; i < 3; i++) {
		b1[i] = B1[0] * g->u[i] + B1[1] * g->w[i];
		F[i] = rest[i] + b1[i] - g->d * B0 * g->nf[i];
	}
	/* dPhi/dX_a = A0 g_a + N_a(C) (B1 - d B0 nf) + B2 g_a - d (B1 . g_a) nf */
	const double *x = g->x, *y = g->y;
	for (int a = 0; a < 3; a++) {
		int j = (a + 1) % 3, k = (a + 2) % 3;
		double gx = (y[j] - y[k]) / g->A2, gy = (x[k] - x[j]) / g->A2;
		double Nc = (x[j] * y[k] - x[k] * y[j]) / g->A2;
		double px = A0 * gx + Nc * B1[0] + B2[0] * gx + B2[1] * gy;
		double py = A0 * gy + Nc * B1[1] + B2[1] * gx + B2[2] * gy;
		double pn = -g->d * (Nc * B0 + B1[0] * gx + B1[1] * gy);
		for (int i = 0; i < 3; i++)
			Fnode[a][i] = -g->N[a] * rest[i] - (px * g->u[i] + py * g->w[i] + pn * g->nf[i]);
	}
	if (Phi)
		*Phi = A0;
}

void dem_potential_polygon(double c, double m, double R, double d, const double *x,
                           const double *y, int nv, double *A0, double *B0, double B1[2],
                           double B2[3])
{
	branch_t B = { .c = c, .m = m, .R = R, .d = d };
	B.delta = R - d;
	*A0 = *B0 = B1[0] = B1[1] = B2[0] = B2[1] = B2[2] = 0;
	if (!(B.delta > 0) || !(c > 0) || !(d > 0))
		return;
	double F0 = c * br_pow(m, B.delta);
	B.w0 = F0 / (2 * DEM_PI * d);
	B.W0 = F0 * B.delta / (m + 1);
	local_integrals(&B, x, y, nv, sqrt(B.delta * (R + d)), A0, B0, B1, B2);
}

int dem_contact_sphere_facet(const dem_contact_model_t *cm, const dem_sphere_t *s,
                             const double X[3][3], const double (*V)[3], double meff,
                             double dt, dem_contact_state_t *st, dem_facet_out_t *out)
{
	dem_facet_geom_t *g = &out->g;
	if (!dem_facet_geom(s->x, s->R, X, cm->p.partial, g)) {
		dem_contact_state_reset(st);
		return 0;
	}
	dem_contact_kin_t k;
	double wr[3];
	for (int i = 0; i < 3; i++)
		k.r[i] = g->G[i] - s->x[i];
	v3_cross(s->w, k.r, wr);
	for (int i = 0; i < 3; i++) {
		double vt = V ? g->N[0] * V[0][i] + g->N[1] * V[1][i] + g->N[2] * V[2][i] : 0;
		k.vrel[i] = s->v[i] + wr[i] - vt;  /* Eqs. 3.54-3.56; a facet does not spin */
		k.n[i] = g->n[i];
	}
	k.delta = g->delta;
	k.gamma = g->gamma;
	k.wn = v3_dot(s->w, g->n);
	k.kn = s->kn;
	k.meff = meff;
	k.dt = dt;
	cm->kernel(cm, &k, st, &out->c);
	double F[3];
	dem_facet_forces(g, &out->c, cm->m, F, out->Fnode, NULL);
	for (int i = 0; i < 3; i++)
		out->c.F[i] = F[i];
	return 1;
}
