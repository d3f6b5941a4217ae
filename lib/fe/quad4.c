/* quad4.c - 4-node quadrilateral kernels (see quad4.h).
 *
 * Uniform gradient.  With the diagonals d13 = x2 - x0 and d24 = x3 - x1
 * the area of the bilinear quadrilateral is A = (d13 x d24)/2 (2D cross
 * product), whatever its shape, and its derivative b_I = dA/dx_I is the
 * mean shape function gradient int grad N_I dA of Flanagan & Belytschko:
 *     b_xI = (y_{I+1} - y_{I-1}) / 2,   b_yI = (x_{I-1} - x_{I+1}) / 2
 * (indices mod 4).  As in hex8.c, sum_I x_I (x) b_I = A 1 for any shape,
 * so the mean velocity gradient is exact for linear fields and a constant
 * stress gives forces that cancel at interior nodes (plane strain).
 *
 * Hourglass vector.  The one bilinear mode not seen by the uniform gradient
 * is h = (1, -1, 1, -1) (h_I = xi_I eta_I); Flanagan & Belytschko's
 * gamma_I = h_I - (h . x_j) b_jI / A is h made orthogonal to every linear
 * field, here divided by |h| = 2 (the normalised basis, as hex8's 1/sqrt 8).
 *
 * Axisymmetric one-point element.  The hoop rate is taken at the centre,
 * where N_I = 1/4: v_r(0) / r0 with r0 the mean nodal radius; a uniform
 * expansion v_r = c r gives exactly c.  Its virtual work w A sig_zz
 * v_r(0) / r0 = 2 pi A sig_zz sum_I v_rI / 4 gives each node the radial
 * force pi A sig_zz / 2, with no radius in it.
 */
#include "fe/quad4.h"

#include <math.h>
#include <string.h>

#define TWO_PI 6.28318530717958647693
#define GAUSS 0.57735026918962576451 /* 1/sqrt(3) */

const double dem_quad4_node_xi[4] = { -1, 1, 1, -1 };
const double dem_quad4_node_eta[4] = { -1, -1, 1, 1 };

static const double HG[4] = { 1, -1, 1, -1 };

void dem_quad4_strain_rate(const double L[4], double zz, double d[6], double w[3])
{
	d[0] = L[0];
	d[1] = L[3];
	d[2] = zz;
	d[3] = L[1] + L[2];
	d[4] = 0;
	d[5] = 0;
	w[0] = 0.5 * (L[1] - L[2]);
	w[1] = 0;
	w[2] = 0;
}

/* A node at r < 0 (or NaN) in axisymmetry. */
static int off_axis(const double x[8], dem_quad4_mode_t mode)
{
	if (mode != DEM_QUAD4_AXISYM)
		return 0;
	for (int I = 0; I < 4; I++)
		if (!(x[I] >= 0))
			return 1;
	return 0;
}

/* ---- One-point integration ----------------------------------------------- */

int dem_quad4_1pt_geom(const double x[8], dem_quad4_mode_t mode, double t,
		       dem_quad4_1pt_t *g)
{
	const double *y = x + 4;
	g->mode = mode;
	for (int I = 0; I < 4; I++) {
		int n = (I + 1) & 3, p = (I + 3) & 3;
		g->b[I] = 0.5 * (y[n] - y[p]);
		g->b[4 + I] = 0.5 * (x[p] - x[n]);
	}
	g->area = 0.5 * ((x[2] - x[0]) * (y[3] - y[1]) - (x[3] - x[1]) * (y[2] - y[0]));
	g->r0 = 0.25 * (x[0] + x[1] + x[2] + x[3]);
	g->w = mode == DEM_QUAD4_AXISYM ? TWO_PI * g->r0 : t;
	g->vol = g->w * g->area;
	double bb = 0, hx = 0, hy = 0;
	for (int I = 0; I < 8; I++)
		bb += g->b[I] * g->b[I];
	for (int I = 0; I < 4; I++) {
		hx += HG[I] * x[I];
		hy += HG[I] * y[I];
	}
	g->bb = bb;
	if (!(g->area > 0) || !(g->w > 0) || off_axis(x, mode))
		return DEM_QUAD4_INVERTED;
	double r = 1 / g->area;
	for (int I = 0; I < 4; I++)
		g->gam[I] = 0.5 * (HG[I] - r * (hx * g->b[I] + hy * g->b[4 + I]));
	return DEM_QUAD4_OK;
}

void dem_quad4_1pt_rate(dem_quad4_1pt_t *g, const double v[8])
{
	double r = 1 / g->area;
	for (int i = 0; i < 2; i++) {
		const double *vi = v + 4 * i;
		for (int j = 0; j < 2; j++) {
			const double *bj = g->b + 4 * j;
			g->L[2 * i + j] = r * (vi[0] * bj[0] + vi[1] * bj[1] + vi[2] * bj[2] + vi[3] * bj[3]);
		}
		g->q[i] = vi[0] * g->gam[0] + vi[1] * g->gam[1] + vi[2] * g->gam[2] + vi[3] * g->gam[3];
	}
	g->zz = g->mode == DEM_QUAD4_AXISYM ?
		0.25 * (v[0] + v[1] + v[2] + v[3]) / g->r0 : 0;
}

void dem_quad4_1pt_force(const dem_quad4_1pt_t *g, const double sig[6],
			 const double Q[2], double f[8])
{
	double w = g->w;
	double hoop = g->mode == DEM_QUAD4_AXISYM ? 0.25 * TWO_PI * g->area * sig[2] : 0;
	for (int I = 0; I < 4; I++) {
		double bx = g->b[I], by = g->b[4 + I];
		f[I] = w * (sig[0] * bx + sig[3] * by) + hoop;
		f[4 + I] = w * (sig[3] * bx + sig[1] * by);
		if (Q) {
			f[I] += Q[0] * g->gam[I];
			f[4 + I] += Q[1] * g->gam[I];
		}
	}
}

void dem_quad4_hg_coef(const dem_quad4_1pt_t *g, const dem_mat_t *m,
		       double kappa_s, double kappa_v, double *ks, double *cv)
{
	double M = m->lam + 2 * m->G;  /* P-wave modulus K + 4G/3 */
	/* hex8's forms with the volume w A and volume gradient w b: the
	 * stiffness keeps hex8's (b . b)/(n V) with n = 2 dimensions; the
	 * damping's sqrt(b . b / 3) becomes sqrt(b . b): with 4 nodes and the
	 * basis h / 2 instead of 8 and h / sqrt 8, these give a square slab
	 * the forces of hex8's cube (quad4.h) */
	*ks = kappa_s * M * g->w * g->bb / (2 * g->area);
	*cv = kappa_v * m->rho * m->wave * g->w * sqrt(g->bb);
}

double dem_quad4_hg_resist(const dem_quad4_1pt_t *g, double ks, double cv,
			   double dt, double Qs[2], double Q[2])
{
	double p = 0, kdt = ks * dt;
	for (int i = 0; i < 2; i++) {
		Qs[i] += kdt * g->q[i];
		Q[i] = Qs[i] + cv * g->q[i];
		p += Q[i] * g->q[i];
	}
	return p;
}

/* Strain-displacement matrix (6 Voigt rows, 8 dofs 4 i + I) of a point
 * with shape function gradients dN[4 j + I] and hoop factors h[I] = N_I / r
 * (NULL in plane strain). */
static void bmatrix(const double dN[8], const double *h, double B[6][8])
{
	memset(B, 0, 6 * sizeof B[0]);
	for (int I = 0; I < 4; I++) {
		B[0][I] = dN[I];
		B[1][4 + I] = dN[4 + I];
		B[2][I] = h ? h[I] : 0;
		B[3][I] = dN[4 + I];
		B[3][4 + I] = dN[I];
	}
}

/* K += w B^T D B (8x8). */
static void add_btdb(const double B[6][8], const double D[36], double w, double K[64])
{
	double DB[6][8];
	for (int r = 0; r < 6; r++)
		for (int j = 0; j < 8; j++) {
			double s = 0;
			for (int k = 0; k < 6; k++)
				s += D[6 * r + k] * B[k][j];
			DB[r][j] = w * s;
		}
	for (int i = 0; i < 8; i++)
		for (int j = 0; j < 8; j++) {
			double s = 0;
			for (int r = 0; r < 6; r++)
				s += B[r][i] * DB[r][j];
			K[8 * i + j] += s;
		}
}

int dem_quad4_1pt_stiffness(const double x[8], dem_quad4_mode_t mode, double t,
			    const double D[36], double ks, double K[64])
{
	dem_quad4_1pt_t g;
	int rc = dem_quad4_1pt_geom(x, mode, t, &g);
	if (rc)
		return rc;
	double dN[8], h[4], B[6][8];
	for (int I = 0; I < 8; I++)
		dN[I] = g.b[I] / g.area;
	for (int I = 0; I < 4; I++)
		h[I] = 0.25 / g.r0;
	bmatrix(dN, mode == DEM_QUAD4_AXISYM ? h : NULL, B);
	memset(K, 0, 64 * sizeof *K);
	add_btdb(B, D, g.vol, K);
	for (int i = 0; i < 2; i++)
		for (int I = 0; I < 4; I++)
			for (int J = 0; J < 4; J++)
				K[(4 * i + I) * 8 + 4 * i + J] += ks * g.gam[I] * g.gam[J];
	return DEM_QUAD4_OK;
}

/* ---- Full integration ---------------------------------------------------- */

/* Shape functions at Gauss point p: N_I(p) = (1 + xi_p xi_I)(1 + eta_p
 * eta_I) / 4 with xi_p = xi_P / sqrt 3, so (1 + s/3 + ...) / 4. */
static inline double shape_gp(int p, int I)
{
	return 0.25 * (1 + GAUSS * dem_quad4_node_xi[p] * dem_quad4_node_xi[I]) *
	       (1 + GAUSS * dem_quad4_node_eta[p] * dem_quad4_node_eta[I]);
}

int dem_quad4_full_geom(const double x[8], dem_quad4_mode_t mode, double t,
			dem_quad4_full_t *g)
{
	const double *y = x + 4;
	g->mode = mode;
	double area = 0.5 * ((x[2] - x[0]) * (y[3] - y[1]) - (x[3] - x[1]) * (y[2] - y[0]));
	int bad = !(area > 0) || off_axis(x, mode);
	g->vol = 0;
	memset(g->bv, 0, sizeof g->bv);
	for (int p = 0; p < 4; p++) {
		double xi = GAUSS * dem_quad4_node_xi[p], eta = GAUSS * dem_quad4_node_eta[p];
		double nxi[4], neta[4];
		double J[4] = { 0, 0, 0, 0 }, r = 0;
		for (int I = 0; I < 4; I++) {
			nxi[I] = 0.25 * dem_quad4_node_xi[I] * (1 + eta * dem_quad4_node_eta[I]);
			neta[I] = 0.25 * dem_quad4_node_eta[I] * (1 + xi * dem_quad4_node_xi[I]);
			J[0] += nxi[I] * x[I];   /* dx/dxi */
			J[1] += neta[I] * x[I];  /* dx/deta */
			J[2] += nxi[I] * y[I];   /* dy/dxi */
			J[3] += neta[I] * y[I];  /* dy/deta */
			r += shape_gp(p, I) * x[I];
		}
		double det = J[0] * J[3] - J[1] * J[2];
		bad |= !(det > 0);
		double rd = 1 / det;
		/* grad_x N = J^-T grad_xi N */
		for (int I = 0; I < 4; I++) {
			g->dN[p][I] = rd * (J[3] * nxi[I] - J[2] * neta[I]);
			g->dN[p][4 + I] = rd * (J[0] * neta[I] - J[1] * nxi[I]);
		}
		g->r[p] = r;
		double w = mode == DEM_QUAD4_AXISYM ? TWO_PI * r : t;
		bad |= !(w > 0);
		g->wdet[p] = w * det;
		g->vol += g->wdet[p];
		for (int I = 0; I < 4; I++) {
			g->bv[I] += g->wdet[p] * g->dN[p][I];
			g->bv[4 + I] += g->wdet[p] * g->dN[p][4 + I];
			if (mode == DEM_QUAD4_AXISYM)
				g->bv[I] += TWO_PI * det * shape_gp(p, I);  /* wdet N_I / r */
		}
	}
	if (bad)
		return DEM_QUAD4_INVERTED;
	for (int I = 0; I < 8; I++)
		g->bv[I] /= g->vol;
	return DEM_QUAD4_OK;
}

void dem_quad4_full_rate(dem_quad4_full_t *g, const double v[8], int bbar)
{
	const double *vy = v + 4;
	int axi = g->mode == DEM_QUAD4_AXISYM;
	double tm = 0;
	if (bbar)
		for (int I = 0; I < 8; I++)
			tm += v[I] * g->bv[I];
	for (int p = 0; p < 4; p++) {
		const double *dx = g->dN[p], *dy = g->dN[p] + 4;
		double *L = g->L[p], zz = 0;
		L[0] = L[1] = L[2] = L[3] = 0;
		for (int I = 0; I < 4; I++) {
			L[0] += v[I] * dx[I];
			L[1] += v[I] * dy[I];
			L[2] += vy[I] * dx[I];
			L[3] += vy[I] * dy[I];
			if (axi)
				zz += shape_gp(p, I) * v[I];
		}
		if (axi)
			zz /= g->r[p];
		if (bbar) {
			double dv = (tm - (L[0] + L[3] + zz)) / 3;
			L[0] += dv;
			L[3] += dv;
			zz += dv;
		}
		g->zz[p] = zz;
	}
}

void dem_quad4_full_force(const dem_quad4_full_t *g, const double sig[24],
			  int bbar, double f[8])
{
	int axi = g->mode == DEM_QUAD4_AXISYM;
	double psum = 0;
	memset(f, 0, 8 * sizeof *f);
	for (int p = 0; p < 4; p++) {
		const double *s = sig + 6 * p, *dx = g->dN[p], *dy = g->dN[p] + 4;
		double sxx = s[0], syy = s[1], szz = s[2], sxy = s[3], wd = g->wdet[p];
		if (bbar) {
			/* the pressure acts through the mean gradient (below) */
			double pr = (sxx + syy + szz) / 3;
			sxx -= pr;
			syy -= pr;
			szz -= pr;
			psum += wd * pr;
		}
		double hz = axi ? szz / g->r[p] : 0;
		for (int I = 0; I < 4; I++) {
			f[I] += wd * (sxx * dx[I] + sxy * dy[I] + (axi ? hz * shape_gp(p, I) : 0));
			f[4 + I] += wd * (sxy * dx[I] + syy * dy[I]);
		}
	}
	if (bbar)
		for (int I = 0; I < 8; I++)
			f[I] += psum * g->bv[I];
}

/* ---- Implicit element ------------------------------------------------------ */

int dem_quad4_static(const dem_mat_t *m, dem_quad4_mode_t mode, double t,
		     dem_quad4_rule_t rule, const double X[8], const double du[8],
		     const dem_quad4_hist_t *hn, dem_quad4_hist_t *h,
		     double fint[8], double K[64], double *wp)
{
	dem_quad4_full_t g;
	if (dem_quad4_full_geom(X, mode, t, &g))
		return DEM_QUAD4_INVERTED;
	int axi = mode == DEM_QUAD4_AXISYM;
	double wpl = 0;
	memset(fint, 0, 8 * sizeof *fint);
	if (K)
		memset(K, 0, 64 * sizeof *K);
	for (int p = 0; p < 4; p++) {
		double hp[4], B[6][8];
		for (int I = 0; I < 4; I++)
			hp[I] = axi ? shape_gp(p, I) / g.r[p] : 0;
		bmatrix(g.dN[p], axi ? hp : NULL, B);
		if (rule == DEM_QUAD4_BBAR)
			/* volumetric strain from the mean gradient (Hughes 1980) */
			for (int I = 0; I < 8; I++) {
				double bvol = I < 4 ? B[0][I] + B[2][I] : B[1][I];
				double dv = (g.bv[I] - bvol) / 3;
				B[0][I] += dv;
				B[1][I] += dv;
				B[2][I] += dv;
			}
		double de[6] = { 0 };
		for (int k = 0; k < 6; k++)
			for (int j = 0; j < 8; j++)
				de[k] += B[k][j] * du[j];
		double *s = h->sig + 6 * p, D[36], w;
		memcpy(s, hn->sig + 6 * p, 6 * sizeof *s);
		h->ep[p] = hn->ep[p];
		dem_mat_update_tangent(m, de, 0, s, &h->ep[p], NULL, &w, D);
		wpl += w * g.wdet[p];
		for (int j = 0; j < 8; j++) {
			double sum = 0;
			for (int k = 0; k < 6; k++)
				sum += B[k][j] * s[k];
			fint[j] += g.wdet[p] * sum;
		}
		if (K)
			add_btdb(B, D, g.wdet[p], K);
	}
	if (wp)
		*wp = wpl;
	return DEM_QUAD4_OK;
}

/* ---- Helpers ----------------------------------------------------------------- */

void dem_quad4_gauss_points(const double x[8], double xg[8])
{
	for (int p = 0; p < 4; p++) {
		xg[p] = xg[4 + p] = 0;
		for (int I = 0; I < 4; I++) {
			double N = shape_gp(p, I);
			xg[p] += N * x[I];
			xg[4 + p] += N * x[4 + I];
		}
	}
}

int dem_quad4_lumped_mass(const double x[8], dem_quad4_mode_t mode, double t,
			  double rho, double mass[4])
{
	dem_quad4_full_t g;
	int rc = dem_quad4_full_geom(x, mode, t, &g);
	for (int I = 0; I < 4; I++) {
		double s = 0;
		for (int p = 0; p < 4; p++)
			s += shape_gp(p, I) * g.wdet[p];
		mass[I] = rc ? 0 : rho * s;
	}
	return rc;
}

int dem_quad4_dt_crit(const double x[8], dem_quad4_mode_t mode, double c, double *dt)
{
	const double *y = x + 4;
	*dt = 0;
	double d13x = x[2] - x[0], d13y = y[2] - y[0], d24x = x[3] - x[1], d24y = y[3] - y[1];
	double area = 0.5 * (d13x * d24y - d24x * d13y);
	double emax = 0;
	for (int I = 0; I < 4; I++) {
		int n = (I + 1) & 3;
		emax = fmax(emax, hypot(x[n] - x[I], y[n] - y[I]));
	}
	if (!(area > 0) || !(emax > 0) || !(c > 0) || off_axis(x, mode))
		return DEM_QUAD4_INVERTED;
	double l = area / emax;
	if (mode == DEM_QUAD4_AXISYM) {
		/* the hoop strain stiffens an element whose radial extent is
		 * not small against its distance from the axis (quad4.h) */
		double rmin = fmin(fmin(x[0], x[1]), fmin(x[2], x[3]));
		double rmax = fmax(fmax(x[0], x[1]), fmax(x[2], x[3]));
		double r0 = 0.25 * (x[0] + x[1] + x[2] + x[3]), s = 0.2 * (rmax - rmin) / r0;
		l /= sqrt(1 + s * s);
	}
	*dt = l / c;
	return DEM_QUAD4_OK;
}
