/* disk.c - disk/segment contact with partial contact (Han 2004, Ch. 3.2.1,
 * Eqs. 3.2-3.11).  See disk.h. */
#include "contact/disk.h"

#include <math.h>

#include "contact/gauss.h"
#include "core/consts.h"

double dem_disk_segment_area(double R, double delta)
{
	if (!(delta > 0))
		return 0;
	if (delta >= 2 * R)
		return DEM_PI * R * R;
	double d = R - delta, b = sqrt(delta * (2 * R - delta));
	return 2 * R * R * atan(delta / b) - d * b;  /* Eq. 3.5 (atan: no acos near 1) */
}

/* The overlap g(x) = sqrt(R^2 - x^2) - d (Eq. 3.2) over [x0, x1]: its area
 * S, and the first moments Mx = int x g dx, My = int g^2/2 dx (depth below
 * the line), with g = (b - x)(b + x) / (sqrt(R^2 - x^2) + d), free of the
 * cancellation of Eq. 3.5 at small delta.  Two 8-point Gauss-Legendre
 * panels: g is smooth on [-b, b] (its nearest singularity at x = +-R), to
 * 1e-15 of S for delta < R/10. */
static void overlap(double R, double d, double b, double x0, double x1, double *S, double *Mx,
                    double *My)
{
	double h = 0.5 * (x1 - x0), s = 0, mx = 0, my = 0;
	for (int kk = 0; kk < 16; kk++) {
		int k = kk % 8;
		double x = x0 + h * ((kk / 8) + gl_t[k]), w = h * gl_w[k];
		double g = (b - x) * (b + x) / (sqrt((R - x) * (R + x)) + d);
		s += w * g;
		mx += w * x * g;
		my += w * 0.5 * g * g;
	}
	*S = s, *Mx = mx, *My = my;
}

int dem_segment_geom(const double O[2], double R, const double A[2], const double B[2], int scheme,
                     dem_seg_geom_t *g)
{
	double tx = B[0] - A[0], ty = B[1] - A[1], L = hypot(tx, ty);
	if (!(L > 0))
		return 0;
	tx /= L, ty /= L;
	double nx = -ty, ny = tx;  /* out of the solid, to the disk */
	double rx = O[0] - A[0], ry = O[1] - A[1];
	double d = rx * nx + ry * ny;
	if (!(d > 0) || !(d < R))
		return 0;
	double delta = R - d, b = sqrt(delta * (2 * R - delta));  /* Eqs. 3.3-3.4 */
	double sc = rx * tx + ry * ty;                              /* C along t from A */
	double x0 = fmax(-b, -sc), x1 = fmin(b, L - sc);
	if (!(x1 > x0))
		return 0;
	g->full = -sc <= -b && L - sc >= b;
	g->gamma = 1;
	g->Sp = g->Sf = 0;
	double gx = 0, gy = 0, px = 0;  /* G: gx along t, gy below the line; P: px along t */
	if (!g->full) {
		if (scheme == DEM_PARTIAL_WIDTH) {
			g->gamma = (x1 - x0) / (2 * b);  /* Eq. 3.11 */
			gx = px = 0.5 * (x0 + x1);
		} else {
			double Mx, My, mx, my;
			overlap(R, d, b, -b, b, &g->Sf, &mx, &my);
			overlap(R, d, b, x0, x1, &g->Sp, &Mx, &My);
			if (!(g->Sp > 0) || !(g->Sf > 0))
				return 0;
			g->gamma = fmin(g->Sp / g->Sf, 1);  /* Eq. 3.10 */
			gx = Mx / g->Sp, gy = My / g->Sp;
			px = gx * d / (d + gy);  /* where G O meets the line */
		}
	}
	double ox = -gx, oy = d + gy, lo = hypot(ox, oy);  /* O - G in (t, nf) */
	for (int i = 0; i < 2; i++) {
		double t = i ? ty : tx, n = i ? ny : nx, c = O[i] - d * n;
		g->G[i] = c + gx * t - gy * n;
		g->P[i] = c + px * t;
		g->n[i] = (ox * t + oy * n) / lo;
	}
	g->delta = delta;
	g->d = d;
	g->b = b;
	g->x0 = x0, g->x1 = x1;
	g->xi = (sc + px) / L;
	g->pot = scheme == DEM_PARTIAL_POTENTIAL && !g->full;
	g->R = R, g->L = L, g->sc = sc;
	g->t[0] = tx, g->t[1] = ty, g->nf[0] = nx, g->nf[1] = ny;
	return 1;
}

void dem_segment_forces(const dem_seg_geom_t *g, const dem_contact_out_t *o, double m, double F[2],
                        double Fnode[2][2], double *Phi)
{
	double xi = g->xi;
	if (!g->pot) {
		for (int i = 0; i < 2; i++) {
			F[i] = o->F[i];
			Fnode[0][i] = -(1 - xi) * o->F[i];
			Fnode[1][i] = -xi * o->F[i];
		}
		if (Phi) {
			double x = g->delta - o->bg0;
			*Phi = x > 0 ? g->gamma * o->bc * pow(x, m + 1) / (m + 1) : 0;
		}
		return;
	}
	/* the strip swept by the segment, x along t from C, y across (the
	 * extrusion), cut to a rectangle that holds the circle's part in it */
	double h = 2 * g->b, xl = fmax(-g->sc, -h), xr = fmin(g->L - g->sc, h);
	double x[4] = { xl, xr, xr, xl }, y[4] = { -h, -h, h, h };
	double A0, B0, B1[2], B2[3];
	dem_potential_polygon(o->bc, m, g->R - o->bg0, g->d, x, y, 4, &A0, &B0, B1, B2);
	/* F_O = int 2 w' (y - O) dA, y - O = x t - d nf; the nodes (N_A = 1 -
	 * tau, N_B = tau, tau = (sc + x) / L, grad N = -+ t / L):
	 * dPhi/dX_a = A0 g_a t + N_a(C) (B1x t - d B0 nf) + g_a (B2xx t - d B1x nf) */
	double ga[2] = { -1 / g->L, 1 / g->L }, Nc[2] = { 1 - g->sc / g->L, g->sc / g->L };
	for (int i = 0; i < 2; i++) {
		double rest = o->F[i] - o->Fe * g->n[i];  /* damping and friction, at P */
		double fo = B1[0] * g->t[i] - g->d * B0 * g->nf[i];
		F[i] = rest + fo;
		for (int a = 0; a < 2; a++) {
			double dp = A0 * ga[a] * g->t[i] + Nc[a] * fo +
				    ga[a] * (B2[0] * g->t[i] - g->d * B1[0] * g->nf[i]);
			Fnode[a][i] = -(a ? xi : 1 - xi) * rest - dp;
		}
	}
	if (Phi)
		*Phi = A0;
}

int dem_contact_disk_segment(const dem_contact_model_t *cm, const dem_sphere_t *s,
                             const double X[2][2], const double (*V)[2], double meff, double dt,
                             dem_contact_state_t *st, dem_seg_out_t *out)
{
	dem_seg_geom_t *g = &out->g;
	if (!dem_segment_geom(s->x, s->R, X[0], X[1], cm->p.partial, g)) {
		dem_contact_state_reset(st);
		return 0;
	}
	double xi = g->xi;
	dem_contact_kin_t k;
	k.r[0] = g->P[0] - s->x[0], k.r[1] = g->P[1] - s->x[1], k.r[2] = 0;
	/* Eqs. 3.54-3.56 at P: w x r for a spin about z; the segment's
	 * velocity there, interpolated */
	double wr[2] = { -s->w[2] * k.r[1], s->w[2] * k.r[0] };
	for (int i = 0; i < 2; i++) {
		double vt = V ? (1 - xi) * V[0][i] + xi * V[1][i] : 0;
		k.vrel[i] = s->v[i] + wr[i] - vt;
		k.n[i] = g->n[i];
	}
	k.vrel[2] = k.n[2] = 0;
	k.delta = g->delta;
	k.gamma = g->gamma;
	k.wn = 0;  /* in the plane, no spin about the normal */
	k.kn = s->kn;
	k.meff = meff;
	k.dt = dt;
	cm->kernel(cm, &k, st, &out->c);
	double F[2];
	dem_segment_forces(g, &out->c, cm->m, F, out->Fnode, NULL);
	out->c.F[0] = F[0], out->c.F[1] = F[1];
	return 1;
}
