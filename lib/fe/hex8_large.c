/* hex8_large.c - total Lagrangian hexahedron with incompatible modes (see
 * hex8_large.h).
 *
 * Each pseudo-node n (8 nodes, then 3 incompatible modes, 3 dofs each) has
 * a reference gradient g_n at every Gauss point; the deformation gradient is
 * F = I + sum_n q_n (x) g_n.  The variation of the Green-Lagrange strain is
 * dE_ab = (g_a F_ib + F_ia g_b)/2 dq_i (B_NL below), so that
 *   f_n = sum_p w_p B_NL^T S,
 *   K_nm = sum_p w_p (B_NL,n^T D B_NL,m + (g_n . S g_m) I),
 * the second term the geometric (initial stress) stiffness.
 */
#include "fe/hex8_large.h"

#include <math.h>
#include <string.h>

#include "fe/dense.h"

#define NPN 11                          /* pseudo-nodes */

/* Inverse of the 3x3 matrix with columns u, v, w: rows (v x w, w x u,
 * u x v) / det, so Ji[3 m + j] = d xi_m / d x_j.  Returns det. */
static double invert(const double u[3], const double v[3], const double w[3],
		     double Ji[9])
{
	const double *c[3] = { v, w, u }, *d[3] = { w, u, v };
	for (int r = 0; r < 3; r++) {
		Ji[3 * r] = c[r][1] * d[r][2] - c[r][2] * d[r][1];
		Ji[3 * r + 1] = c[r][2] * d[r][0] - c[r][0] * d[r][2];
		Ji[3 * r + 2] = c[r][0] * d[r][1] - c[r][1] * d[r][0];
	}
	double det = u[0] * Ji[0] + u[1] * Ji[1] + u[2] * Ji[2];
	for (int i = 0; i < 9; i++)
		Ji[i] /= det;
	return det;
}

/* The displacement gradient H = sum_n q_n (x) g_n (row-major H[3 i + j]);
 * F = I + H. */
static void dispgrad(int nb, const double (*g)[3], const double *q, double H[9])
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			double s = 0;
			for (int n = 0; n < nb; n++)
				s += q[3 * n + i] * g[n][j];
			H[3 * i + j] = s;
		}
}

/* Green-Lagrange strain, Voigt with engineering shears, from H as
 * (H + H^T + H^T H)/2: no cancellation against the identity, so that small
 * strains keep their relative precision. */
static void green(const double H[9], double E[6])
{
	double C[9];
	for (int a = 0; a < 3; a++)
		for (int b = 0; b < 3; b++)
			C[3 * a + b] = H[a] * H[b] + H[3 + a] * H[3 + b] + H[6 + a] * H[6 + b];
	E[0] = H[0] + 0.5 * C[0];
	E[1] = H[4] + 0.5 * C[4];
	E[2] = H[8] + 0.5 * C[8];
	E[3] = H[1] + H[3] + C[1];
	E[4] = H[5] + H[7] + C[5];
	E[5] = H[2] + H[6] + C[2];
}

/* The incompatible modes' strain, linear in their amplitudes q[24..32]
 * (enhanced Green-Lagrange strain): E += sym(sum_a q_a (x) g_a). */
static void add_modes(int nb, const double (*g)[3], const double *q, double E[6])
{
	for (int n = 8; n < nb; n++) {
		const double *a = q + 3 * n, *b = g[n];
		E[0] += a[0] * b[0];
		E[1] += a[1] * b[1];
		E[2] += a[2] * b[2];
		E[3] += a[0] * b[1] + a[1] * b[0];
		E[4] += a[1] * b[2] + a[2] * b[1];
		E[5] += a[2] * b[0] + a[0] * b[2];
	}
}

static const double I3[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };

static double det3(const double F[9])
{
	return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
	       F[2] * (F[3] * F[7] - F[4] * F[6]);
}

/* B_NL block of a pseudo-node with gradient g under F. */
static void bnl(const double g[3], const double F[9], double B[6][3])
{
	for (int i = 0; i < 3; i++) {
		const double *f = F + 3 * i;
		B[0][i] = f[0] * g[0];
		B[1][i] = f[1] * g[1];
		B[2][i] = f[2] * g[2];
		B[3][i] = f[0] * g[1] + f[1] * g[0];
		B[4][i] = f[1] * g[2] + f[2] * g[1];
		B[5][i] = f[2] * g[0] + f[0] * g[2];
	}
}

/* K += w (sum B_m^T D B_n + (g_m . S g_n) I) over pseudo-nodes, the
 * geometric term only among the first ngeo (the nodes: the modes enter the
 * strain linearly). */
static void add_k(int nb, double B[][6][3], const double (*g)[3], const double D[36],
		  const double s[6], double w, double *K, int nd, int off, int ngeo)
{
	for (int n = 0; n < nb; n++) {
		double DB[6][3], Sg[3];
		for (int r = 0; r < 6; r++)
			for (int j = 0; j < 3; j++) {
				double t = 0;
				for (int k = 0; k < 6; k++)
					t += D[6 * r + k] * B[n][k][j];
				DB[r][j] = w * t;
			}
		Sg[0] = w * (s[0] * g[n][0] + s[3] * g[n][1] + s[5] * g[n][2]);
		Sg[1] = w * (s[3] * g[n][0] + s[1] * g[n][1] + s[4] * g[n][2]);
		Sg[2] = w * (s[5] * g[n][0] + s[4] * g[n][1] + s[2] * g[n][2]);
		for (int mm = 0; mm < nb; mm++) {
			double geo = mm < ngeo && n < ngeo
				? g[mm][0] * Sg[0] + g[mm][1] * Sg[1] + g[mm][2] * Sg[2] : 0;
			for (int i = 0; i < 3; i++)
				for (int j = 0; j < 3; j++) {
					double t = i == j ? geo : 0;
					for (int r = 0; r < 6; r++)
						t += B[mm][r][i] * DB[r][j];
					K[(3 * (mm + off) + i) * nd + 3 * (n + off) + j] += t;
				}
		}
	}
}

int dem_hex8_large(const dem_mat_t *m, int eas, const double X[24],
		   const double un[24], const double du[24],
		   const dem_hex8_hist_t *hn, dem_hex8_hist_t *h,
		   double fint[24], double K[576], double *wp)
{
	dem_hex8_full_t geo;
	if (dem_hex8_full_geom(X, &geo))
		return DEM_HEX8_INVERTED;
	int nb = eas ? NPN : 8, nd = 3 * nb;
	double J0i[9] = { 0 }, j0 = 0;
	if (eas)
		j0 = invert(geo.a[1], geo.a[2], geo.a[3], J0i);

	/* reference gradients of the pseudo-nodes at the Gauss points, the
	 * modes as DEM_HEX8_EAS's */
	double g[8][NPN][3];
	for (int p = 0; p < 8; p++)
		dem_hex8_grads(&geo, p, eas, j0, J0i, g[p]);

	/* generalised displacements: nodal (pseudo-node-major) then modes */
	double qn[3 * NPN], q[3 * NPN];
	for (int I = 0; I < 8; I++)
		for (int i = 0; i < 3; i++) {
			qn[3 * I + i] = un[8 * i + I];
			q[3 * I + i] = un[8 * i + I] + du[8 * i + I];
		}
	double En[8][6];
	for (int p = 0; p < 8; p++) {
		double H[9];
		if (eas)
			memcpy(qn + 24, hn->alpha, 9 * sizeof *qn);
		dispgrad(8, (const double (*)[3])g[p], qn, H);
		green(H, En[p]);
		add_modes(nb, (const double (*)[3])g[p], qn, En[p]);
	}
	if (!eas)
		memset(h->alpha, 0, sizeof h->alpha);

	/* local Newton iteration on the modes with backtracking, as in
	 * dem_hex8_static() */
	double Dg[8][36], Fg[8][9], B[8][NPN][6][3], r[3 * NPN];
	double wpl = 0;
	dem_hex8_modes_t mi = { .step = 1 };
	int it, maxit = eas ? DEM_HEX8_MODES_MAXIT : 1;
	for (it = 0; it < maxit; it++) {
		if (eas)
			memcpy(q + 24, h->alpha, 9 * sizeof *q);
		memset(r, 0, sizeof r);
		double ref = 0;
		wpl = 0;
		for (int p = 0; p < 8; p++) {
			double E[6], de[6], w, H[9];
			dispgrad(8, (const double (*)[3])g[p], q, H);
			green(H, E);
			add_modes(nb, (const double (*)[3])g[p], q, E);
			memcpy(Fg[p], H, sizeof H);
			Fg[p][0] += 1;
			Fg[p][4] += 1;
			Fg[p][8] += 1;
			if (!(det3(Fg[p]) > 0))
				return DEM_HEX8_INVERTED;
			for (int t = 0; t < 6; t++)
				de[t] = E[t] - En[p][t];
			double *s = h->sig + 6 * p;
			memcpy(s, hn->sig + 6 * p, 6 * sizeof *s);
			h->ep[p] = hn->ep[p];
			dem_mat_update_tangent(m, de, 0, s, &h->ep[p], NULL, &w, Dg[p]);
			wpl += w * geo.wdet[p];
			for (int n = 0; n < nb; n++) {
				bnl(g[p][n], n < 8 ? Fg[p] : I3, B[p][n]);
				for (int i = 0; i < 3; i++) {
					double t = 0;
					for (int k = 0; k < 6; k++)
						t += B[p][n][k][i] * s[k];
					r[3 * n + i] += geo.wdet[p] * t;
				}
			}
			for (int k = 0; k < 6; k++)
				ref += geo.wdet[p] * fabs(s[k]);
		}
		if (!eas)
			break;
		int next = dem_hex8_modes_check(&mi, it, r + 24, ref, geo.vol, m->E, h->alpha);
		if (next == DEM_HEX8_MODES_DONE)
			break;
		if (next == DEM_HEX8_MODES_HALVED)
			continue;
		double Kaa[81] = { 0 };
		for (int p = 0; p < 8; p++)
			add_k(3, &B[p][8], (const double (*)[3])&g[p][8], Dg[p], h->sig + 6 * p,
			      geo.wdet[p], Kaa, 9, 0, 0);
		if (dem_hex8_modes_newton(&mi, Kaa, r + 24, h->alpha))
			return DEM_HEX8_NOCONV;
	}
	if (eas && it == maxit)
		return DEM_HEX8_NOCONV;
	if (wp)
		*wp = wpl;
	double Kf[3 * NPN * 3 * NPN];
	if (K) {
		memset(Kf, 0, sizeof Kf);
		for (int p = 0; p < 8; p++)
			add_k(nb, B[p], (const double (*)[3])g[p], Dg[p], h->sig + 6 * p,
			      geo.wdet[p], Kf, nd, 0, 8);
	}
	return dem_hex8_condense(eas, Kf, nd, r, fint, K);
}
