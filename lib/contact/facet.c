/* facet.c - sphere/facet contact geometry with partial contact (Han 2004,
 * Eqs. 3.13-3.22).  See facet.h. */
#include "contact/facet.h"

#include <math.h>

#include "contact/vec3.h"
#include "core/consts.h"

/* The signed piece of one edge, A -> B (relative to the circle's centre):
 * the circle's part inside the triangle (0, A, B), signed by its
 * orientation.  The edge is cut where it crosses the circle; a stretch
 * inside the circle gives the triangle (0, P, Q), a stretch outside the
 * circular sector between the directions of P and Q. */
static void edge_piece(double ax, double ay, double bx, double by, double r,
                       double *S, double *Mx, double *My, double *J, double *Kx, double *Ky)
{
	double dx = bx - ax, dy = by - ay;
	double qa = dx * dx + dy * dy, qb = ax * dx + ay * dy, qc = ax * ax + ay * ay - r * r;
	/* the edge's stretches: [0, t1] outside, [t1, t2] inside, [t2, 1]
	 * outside, with t1 < t2 the crossings of the circle clamped to [0, 1];
	 * no crossing (or a tangent): all outside */
	double t[4] = { 0, 0, 0, 1 };
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
			*S += s;
			*Mx += s * (px + qx) / 3;
			*My += s * (py + qy) / 3;
			*J += s * (pp + qq + pq) / 6;
			*Kx += cr * ((px * pp + qx * qq) / 20 + (2 * px * pq + qx * pp + px * qq + 2 * qx * pq) / 60);
			*Ky += cr * ((py * pp + qy * qq) / 20 + (2 * py * pq + qy * pp + py * qq + 2 * qy * pq) / 60);
		} else {
			/* sector between the directions of P and Q */
			double th = atan2(cr, px * qx + py * qy);
			double s = 0.5 * r2 * th;
			double lp = sqrt(px * px + py * py), lq = sqrt(qx * qx + qy * qy);
			double sx = qy / lq - py / lp, sy = px / lp - qx / lq;
			double c = r2 * r / 3;
			*S += s;
			*Mx += c * sx;
			*My += c * sy;
			*J += 0.5 * s * r2;
			*Kx += 0.6 * c * r2 * sx;  /* r^5/5 */
			*Ky += 0.6 * c * r2 * sy;
		}
	}
}

static void circle_triangle(const double x[3], const double y[3], double r, double *S, double *Mx,
                            double *My, double *J, double *Kx, double *Ky)
{
	*S = *Mx = *My = *J = *Kx = *Ky = 0;
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3;
		edge_piece(x[i], y[i], x[j], y[j], r, S, Mx, My, J, Kx, Ky);
	}
}

void dem_circle_triangle(const double x[3], const double y[3], double r,
                         double *S, double *Mx, double *My, double *J)
{
	double Kx, Ky;
	circle_triangle(x, y, r, S, Mx, My, J, &Kx, &Ky);
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
	double S, Mx, My, J, Kx, Ky, gx = 0, gy = 0;
	g->gamma = 1;
	if (full) {
		S = DEM_PI * b2;
	} else {
		circle_triangle(x, y, b, &S, &Mx, &My, &J, &Kx, &Ky);
		/* grazing: nothing left but round-off */
		if (!(S > 1e-13 * DEM_PI * b2))
			return 0;
		if (scheme == DEM_PARTIAL_VOLUME) {
			/* V_p / V_f over the cap delta (1 - r^2/b^2), and G its
			 * centroid projected on the plane */
			double w = S - J / b2;
			if (!(w > 0))
				return 0;
			g->gamma = 2 * w / (DEM_PI * b2);
			gx = (Mx - Kx / b2) / w, gy = (My - Ky / b2) / w;
		} else {
			g->gamma = S / (DEM_PI * b2);  /* Eq. 3.15 */
			gx = Mx / S, gy = My / S;      /* Eq. 3.21, G relative to C */
		}
		if (g->gamma > 1)
			g->gamma = 1;
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
	for (int a = 0; a < 3; a++)
		for (int i = 0; i < 3; i++)
			out->Fnode[a][i] = -g->N[a] * out->c.F[i];
	return 1;
}
