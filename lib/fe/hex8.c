/* hex8.c - 8-node hexahedron kernels (see hex8.h).
 *
 * Modal form.  With N_I = (1 + xi xi_I)(1 + eta eta_I)(1 + zeta zeta_I)/8,
 * a nodal field u_I has the modal coefficients a_k = 1/8 sum_I Lambda_k(I) u_I
 * where Lambda_k(I) is the k-th of 1, xi_I, eta_I, zeta_I, eta_I zeta_I,
 * zeta_I xi_I, xi_I eta_I, xi_I eta_I zeta_I, and u(xi) = sum_k a_k
 * Lambda_k(xi).  The rows Lambda_k are orthogonal (sum_I Lambda_k Lambda_l
 * = 8 delta_kl), so the transform and its inverse are the same 24-addition
 * butterfly.  Lambda_4..7 are the hourglass base vectors h of Flanagan &
 * Belytschko (1981).  (Equation numbers of that paper are not cited here:
 * the formulas below are derived in this comment and checked by the tests.)
 *
 * Volume.  det J = x_xi . (x_eta x x_zeta) with x_xi = a1 + a6 eta + a5 zeta
 * + a7 eta zeta and so on; integrating over the cube keeps the terms even in
 * every coordinate:
 *     V = 8 [a1,a2,a3] + 8/3 ([a1,a6,a5] + [a6,a2,a4] + [a5,a4,a3])
 * ([p,q,r] = p . (q x r); a7 drops out).  Its gradient c_k = dV/da_k gives
 * the uniform gradient of Flanagan & Belytschko, b_I = dV/dx_I = int grad N_I
 * dV (the mean of the shape function gradients; they give it as explicit
 * polynomials in the coordinates), as b_I = 1/8 sum_k Lambda_k(I) c_k.  Being the exact derivative of the exact volume, it gives
 * sum_I x_I (x) b_I = V 1 for any shape: the mean strain rate is exact for
 * linear velocity fields, and the forces of a constant stress cancel at
 * interior nodes, so distorted meshes pass the patch test.
 */
#include "fe/hex8.h"

#include <math.h>
#include <string.h>

#include "fe/dense.h"
#include "fe/simd.h"
#include "mesh/hex.h"

const double dem_hex8_node_xi[8] = { -1, 1, 1, -1, -1, 1, 1, -1 };
const double dem_hex8_node_eta[8] = { -1, -1, 1, 1, -1, -1, 1, 1 };
const double dem_hex8_node_zeta[8] = { -1, -1, -1, -1, 1, 1, 1, 1 };

#define SQRT8 2.8284271247461900976
#define GAUSS 0.57735026918962576451 /* 1/sqrt(3) */

int dem_hex8_1pt_geom(const double x[24], dem_hex8_1pt_t *g)
{
	dem_hex_modes(x, g->a);
	dem_hex_volume_modes(g->a, g->c, &g->vol);
	/* det J at the centre is [a1, a2, a3] */
	double j0 = dem_hex_triple(g->a[1], g->a[2], g->a[3]);
	if (!(g->vol > 0) || !(j0 > 0))
		return DEM_HEX8_INVERTED;
	return DEM_HEX8_OK;
}

void dem_hex8_1pt_rate(dem_hex8_1pt_t *g, const double v[24])
{
	double av[8][3];
	dem_hex_modes(v, av);
	/* L = 1/V sum_I v_I (x) b_I = 1/V sum_k av_k (x) c_k */
	double r = 1 / g->vol;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			double s = 0;
			for (int k = 1; k <= 6; k++)
				s += av[k][i] * g->c[k][j];
			g->L[3 * i + j] = s * r;
		}
	/* Flanagan & Belytschko's hourglass velocities with their gamma
	 * vectors, gamma_alpha,I = h_alpha,I - (h_alpha . x_j) B_jI (h taken
	 * orthogonal to the linear field), so
	 * q_alpha = sum_I v_I gamma_alpha,I = 8 (av_k - L a_k), k = alpha + 4,
	 * here in the normalised basis (h / sqrt 8). */
	for (int al = 0; al < 4; al++) {
		const double *ak = g->a[al + 4];
		for (int i = 0; i < 3; i++) {
			const double *Li = g->L + 3 * i;
			g->q[3 * al + i] = SQRT8 * (av[al + 4][i] -
				(Li[0] * ak[0] + Li[1] * ak[1] + Li[2] * ak[2]));
		}
	}
}

void dem_hex8_strain_rate(const double L[9], double d[6], double w[3])
{
	d[0] = L[0];
	d[1] = L[4];
	d[2] = L[8];
	d[3] = L[1] + L[3];
	d[4] = L[5] + L[7];
	d[5] = L[6] + L[2];
	w[0] = 0.5 * (L[1] - L[3]);
	w[1] = 0.5 * (L[5] - L[7]);
	w[2] = 0.5 * (L[6] - L[2]);
}

void dem_hex8_1pt_force(const dem_hex8_1pt_t *g, const double sig[6],
			const double Q[12], double f[24])
{
	/* f_I = sig b_I + sum_alpha Q_alpha gamma_alpha,I / sqrt 8.  In modes:
	 * with gamma_alpha,I = Lambda_k(I) - (1/V) sum_l Lambda_l(I) (a_k . c_l),
	 * f_I = sum_l Lambda_l(I) F_l where F_l = T c_l / 8 for l = 1..6,
	 * T = sig - (sqrt 8 / V) sum_alpha Q_alpha (x) a_k, and F_k += Q_alpha
	 * / sqrt 8 for the hourglass modes k = alpha + 4. */
	double T[9] = { sig[0], sig[3], sig[5], sig[3], sig[1], sig[4], sig[5], sig[4], sig[2] };
	double F[3][8];
	memset(F, 0, sizeof F);
	if (Q) {
		double s = SQRT8 / g->vol;
		for (int al = 0; al < 4; al++) {
			const double *ak = g->a[al + 4];
			for (int i = 0; i < 3; i++) {
				double Qi = Q[3 * al + i];
				T[3 * i + 0] -= s * Qi * ak[0];
				T[3 * i + 1] -= s * Qi * ak[1];
				T[3 * i + 2] -= s * Qi * ak[2];
				F[i][al + 4] = Qi * (1 / SQRT8);
			}
		}
	}
	for (int l = 1; l <= 6; l++) {
		const double *cl = g->c[l];
		for (int i = 0; i < 3; i++)
			F[i][l] += 0.125 * (T[3 * i] * cl[0] + T[3 * i + 1] * cl[1] + T[3 * i + 2] * cl[2]);
	}
	for (int i = 0; i < 3; i++)
		dem_hex_walsh_inv(F[i], f + 8 * i);
}

/* b . b = sum_I |b_I|^2 = 1/8 sum_k |c_k|^2 (orthogonality of the modes). */
static double grad_norm2(const double c[8][3])
{
	double s = 0;
	for (int k = 1; k <= 6; k++)
		s += c[k][0] * c[k][0] + c[k][1] * c[k][1] + c[k][2] * c[k][2];
	return s / 8;
}

void dem_hex8_hg_coef(const dem_hex8_1pt_t *g, const dem_mat_t *m,
		      double kappa_s, double kappa_v, double *ks, double *cv)
{
	double bb = grad_norm2(g->c);
	double M = m->lam + 2 * m->G;  /* P-wave modulus K + 4G/3 */
	/* the two forms of hourglass resistance of Flanagan & Belytschko
	 * (1981), scaled by the element's stiffness and acoustic impedance
	 * (normalised basis, see hex8.h) */
	*ks = kappa_s * M * bb / (3 * g->vol);
	*cv = kappa_v * m->rho * m->wave * sqrt(bb / 3);
}

double dem_hex8_hg_resist(const dem_hex8_1pt_t *g, double ks, double cv,
			  double dt, double Qs[12], double Q[12])
{
	double p = 0, kdt = ks * dt;
	for (int i = 0; i < 12; i++) {
		Qs[i] += kdt * g->q[i];
		Q[i] = Qs[i] + cv * g->q[i];
		p += Q[i] * g->q[i];
	}
	return p;
}

void dem_hex8_1pt_grad(const dem_hex8_1pt_t *g, double B[24])
{
	double F[8];
	double s = 0.125 / g->vol;
	for (int i = 0; i < 3; i++) {
		for (int k = 0; k < 8; k++)
			F[k] = s * g->c[k][i];
		dem_hex_walsh_inv(F, B + 8 * i);
	}
}

void dem_hex8_1pt_gamma(const dem_hex8_1pt_t *g, double gam[32])
{
	double B[24];
	dem_hex8_1pt_grad(g, B);
	const double *Lam[4] = { NULL, NULL, NULL, NULL };
	static const double h4[8] = { 1, 1, -1, -1, -1, -1, 1, 1 };   /* eta zeta */
	static const double h5[8] = { 1, -1, -1, 1, -1, 1, 1, -1 };   /* zeta xi */
	static const double h6[8] = { 1, -1, 1, -1, 1, -1, 1, -1 };   /* xi eta */
	static const double h7[8] = { -1, 1, -1, 1, 1, -1, 1, -1 };   /* xi eta zeta */
	Lam[0] = h4;
	Lam[1] = h5;
	Lam[2] = h6;
	Lam[3] = h7;
	for (int al = 0; al < 4; al++) {
		const double *ak = g->a[al + 4];
		for (int I = 0; I < 8; I++) {
			double hx = 8 * (ak[0] * B[I] + ak[1] * B[8 + I] + ak[2] * B[16 + I]);
			gam[8 * al + I] = (Lam[al][I] - hx) / SQRT8;
		}
	}
}

/* Strain-displacement block of a node (or pseudo-node) with gradient
 * (bx, by, bz): engineering strains xx yy zz xy yz zx from its 3 dofs. */
static void bblock(double bx, double by, double bz, double B[6][3])
{
	memset(B, 0, 6 * sizeof B[0]);
	B[0][0] = bx;
	B[1][1] = by;
	B[2][2] = bz;
	B[3][0] = by;
	B[3][1] = bx;
	B[4][1] = bz;
	B[4][2] = by;
	B[5][0] = bz;
	B[5][2] = bx;
}

/* K += w sum B_m^T D B_n over pseudo-nodes (dofs 3 n + j, size 3 nb). */
static void add_btdb(int nb, double Bp[][6][3], const double D[36], double w,
		     double *K)
{
	int nd = 3 * nb;
	for (int n = 0; n < nb; n++) {
		double DB[6][3];
		for (int r = 0; r < 6; r++)
			for (int j = 0; j < 3; j++) {
				double s = 0;
				for (int t = 0; t < 6; t++)
					s += D[6 * r + t] * Bp[n][t][j];
				DB[r][j] = w * s;
			}
		for (int mm = 0; mm < nb; mm++)
			for (int i = 0; i < 3; i++)
				for (int j = 0; j < 3; j++) {
					double s = 0;
					for (int r = 0; r < 6; r++)
						s += Bp[mm][r][i] * DB[r][j];
					K[(3 * mm + i) * nd + 3 * n + j] += s;
				}
	}
}

int dem_hex8_1pt_stiffness(const double x[24], const double D[36], double ks,
			   double K[576])
{
	dem_hex8_1pt_t g;
	int rc = dem_hex8_1pt_geom(x, &g);
	if (rc)
		return rc;
	double B[24], gam[32], Kn[576];
	double Bp[8][6][3];
	dem_hex8_1pt_grad(&g, B);
	dem_hex8_1pt_gamma(&g, gam);
	for (int I = 0; I < 8; I++)
		bblock(B[I], B[8 + I], B[16 + I], Bp[I]);
	memset(Kn, 0, sizeof Kn);
	add_btdb(8, Bp, D, g.vol, Kn);
	/* to component-major, with the hourglass stiffness */
	for (int i = 0; i < 3; i++)
		for (int I = 0; I < 8; I++)
			for (int j = 0; j < 3; j++)
				for (int J = 0; J < 8; J++) {
					double k = Kn[(3 * I + i) * 24 + 3 * J + j];
					if (i == j)
						for (int al = 0; al < 4; al++)
							k += ks * gam[8 * al + I] * gam[8 * al + J];
					K[(8 * i + I) * 24 + 8 * j + J] = k;
				}
	return DEM_HEX8_OK;
}

/* The batched kernels are the hot loop of the explicit stage: compiled
 * at -O3 with fused multiply-adds (results differ from the scalar kernels
 * by round-off only). */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("O3", "fp-contract=fast")
#endif

/* ---- One-point integration, batched ------------------------------------- */

/* The batch kernels are the scalar ones written over a vector of NB doubles
 * (simd.h): one lane per element. */

static inline void walsh_v(const vec *u, vec *a)
{
	vec sa = u[1] + u[0], da = u[1] - u[0];
	vec sb = u[2] + u[3], db = u[2] - u[3];
	vec sc = u[5] + u[4], dc = u[5] - u[4];
	vec sd = u[6] + u[7], dd = u[6] - u[7];
	vec ssm = sb + sa, sdm = sb - sa, dsm = db + da, ddm = db - da;
	vec ssp = sd + sc, sdp = sd - sc, dsp = dd + dc, ddp = dd - dc;
	a[3] = ssp - ssm;
	a[2] = sdp + sdm;
	a[4] = sdp - sdm;
	a[1] = dsp + dsm;
	a[5] = dsp - dsm;
	a[6] = ddp + ddm;
	a[7] = ddp - ddm;
}

static inline void walsh_inv_v(const vec *F, vec *u)
{
	/* F[0] = 0: forces have no constant mode */
	vec ssp = F[3], ssm = -F[3];
	vec sdp = F[2] + F[4], sdm = F[2] - F[4];
	vec dsp = F[1] + F[5], dsm = F[1] - F[5];
	vec ddp = F[6] + F[7], ddm = F[6] - F[7];
	vec sd = ssp + sdp, sc = ssp - sdp, dd = dsp + ddp, dc = dsp - ddp;
	vec sb = ssm + sdm, sa = ssm - sdm, db = dsm + ddm, da = dsm - ddm;
	u[6] = sd + dd;
	u[7] = sd - dd;
	u[5] = sc + dc;
	u[4] = sc - dc;
	u[2] = sb + db;
	u[3] = sb - db;
	u[1] = sa + da;
	u[0] = sa - da;
}

static inline void vcross_add(const vec *p, const vec *q, double s, vec *r)
{
	r[0] += s * (p[1] * q[2] - p[2] * q[1]);
	r[1] += s * (p[2] * q[0] - p[0] * q[2]);
	r[2] += s * (p[0] * q[1] - p[1] * q[0]);
}

SIMD_CLONES
unsigned dem_hex8_batch_kin(dem_hex8_batch_t *restrict b,
			    const double *restrict x, const double *restrict v)
{
	vec a[8][3], av[8][3], c[8][3];
	for (int i = 0; i < 3; i++) {
		vec u[8], t[8];
		for (int I = 0; I < 8; I++)
			VLOAD(u[I], x + (8 * i + I) * NB);
		walsh_v(u, t);
		for (int k = 1; k < 8; k++) {
			a[k][i] = 0.125 * t[k];
			VSTORE(b->a[k][i], a[k][i]);
		}
		for (int I = 0; I < 8; I++)
			VLOAD(u[I], v + (8 * i + I) * NB);
		walsh_v(u, t);
		for (int k = 1; k < 8; k++)
			av[k][i] = 0.125 * t[k];
	}
	const vec zero = { 0 };
	for (int k = 1; k < 7; k++)
		c[k][0] = c[k][1] = c[k][2] = zero;
	const double E8 = 8.0, T8 = 8.0 / 3;
	vcross_add(a[2], a[3], E8, c[1]);
	vcross_add(a[6], a[5], T8, c[1]);
	vcross_add(a[3], a[1], E8, c[2]);
	vcross_add(a[4], a[6], T8, c[2]);
	vcross_add(a[1], a[2], E8, c[3]);
	vcross_add(a[5], a[4], T8, c[3]);
	vcross_add(a[6], a[2], T8, c[4]);
	vcross_add(a[3], a[5], T8, c[4]);
	vcross_add(a[1], a[6], T8, c[5]);
	vcross_add(a[4], a[3], T8, c[5]);
	vcross_add(a[5], a[1], T8, c[6]);
	vcross_add(a[2], a[4], T8, c[6]);
	vec vol = zero, bb = zero;
	for (int k = 1; k < 7; k++)
		for (int i = 0; i < 3; i++) {
			VSTORE(b->c[k][i], c[k][i]);
			vol += a[k][i] * c[k][i];
			bb += c[k][i] * c[k][i];
		}
	vol *= 1.0 / 3;
	vec j0 = a[1][0] * (a[2][1] * a[3][2] - a[2][2] * a[3][1]) +
		 a[1][1] * (a[2][2] * a[3][0] - a[2][0] * a[3][2]) +
		 a[1][2] * (a[2][0] * a[3][1] - a[2][1] * a[3][0]);
	bb *= 0.125;
	VSTORE(b->vol, vol);
	VSTORE(b->bb, bb);
	/* a bad element's lanes get a unit volume so that they stay finite;
	 * (NaN > 0) is false, so NaN coordinates count as bad */
	lvec ok = (vol > zero) & (j0 > zero);
	vec one = zero + 1;
	vec r = one / (vec)((ok & (lvec)vol) | (~ok & (lvec)one));
	vec L[9];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			vec s = av[1][i] * c[1][j];
			for (int k = 2; k < 7; k++)
				s += av[k][i] * c[k][j];
			L[3 * i + j] = s * r;
			VSTORE(b->L[3 * i + j], L[3 * i + j]);
		}
	/* as dem_hex8_strain_rate */
	vec dw[9] = { L[0], L[4], L[8], L[1] + L[3], L[5] + L[7], L[6] + L[2],
		      0.5 * (L[1] - L[3]), 0.5 * (L[5] - L[7]), 0.5 * (L[6] - L[2]) };
	for (int k = 0; k < 6; k++)
		VSTORE(b->d[k], dw[k]);
	for (int k = 0; k < 3; k++)
		VSTORE(b->w[k], dw[6 + k]);
	for (int al = 0; al < 4; al++)
		for (int i = 0; i < 3; i++) {
			const vec *ak = a[al + 4];
			vec q = SQRT8 * (av[al + 4][i] - (L[3 * i] * ak[0] + L[3 * i + 1] * ak[1] +
							   L[3 * i + 2] * ak[2]));
			VSTORE(b->q[3 * al + i], q);
		}
	unsigned bad = 0;
	for (int e = 0; e < NB; e++)
		if (!ok[e])
			bad |= 1u << e;
	return bad;
}


SIMD_CLONES
void dem_hex8_batch_hg(const dem_hex8_batch_t *restrict b, const dem_mat_t *m,
		       double kappa_s, double kappa_v, double dt, const double *kscale,
		       double *restrict Qs, double *restrict Q, double *restrict P)
{
	/* as dem_hex8_hg_coef and dem_hex8_hg_resist */
	double ksc = kappa_s * (m->lam + 2 * m->G) / 3 * dt;
	double cvc = kappa_v * m->rho * m->wave / sqrt(3);
	double cvs[NB];
	for (int e = 0; e < NB; e++)
		cvs[e] = cvc * sqrt(b->bb[e]);
	vec bb, vol, cv, p = { 0 };
	VLOAD(bb, b->bb);
	VLOAD(vol, b->vol);
	VLOAD(cv, cvs);
	vec kdt = ksc * bb / vol;
	if (kscale) {
		/* an increment that loads the stiffness form (raises |Qs|)
		 * grows on the element's factor, one that unloads it on the
		 * full stiffness: like plastic loading and elastic unloading,
		 * so a cycle can only take energy, never give it.  Lane by
		 * lane by a mask, not a branch: which lanes load changes from
		 * mode to mode and step to step, a branch per lane mispredicts */
		vec ks;
		const vec zero = { 0 };
		VLOAD(ks, kscale);
		for (int i = 0; i < 12; i++) {
			vec qi, qs;
			VLOAD(qi, b->q[i]);
			VLOAD(qs, Qs + i * NB);
			vec inc = kdt * qi, incs = inc * ks;
			lvec load = qs * inc > zero;
			qs += (vec)((load & (lvec)incs) | (~load & (lvec)inc));
			vec qq = qs + cv * qi;
			VSTORE(Qs + i * NB, qs);
			VSTORE(Q + i * NB, qq);
			p += qq * qi;
		}
		VSTORE(P, p);
		return;
	}
	for (int i = 0; i < 12; i++) {
		vec qi, qs;
		VLOAD(qi, b->q[i]);
		VLOAD(qs, Qs + i * NB);
		qs += kdt * qi;
		vec qq = qs + cv * qi;
		VSTORE(Qs + i * NB, qs);
		VSTORE(Q + i * NB, qq);
		p += qq * qi;
	}
	VSTORE(P, p);
}

SIMD_CLONES
void dem_hex8_batch_force(const dem_hex8_batch_t *restrict b,
			  const double *restrict sig, const double *restrict Q,
			  double *restrict f)
{
	vec S[6];
	for (int k = 0; k < 6; k++)
		VLOAD(S[k], sig + k * NB);
	vec T[9] = { S[0], S[3], S[5], S[3], S[1], S[4], S[5], S[4], S[2] };
	vec F[3][8];
	if (Q) {
		vec vol;
		VLOAD(vol, b->vol);
		vec s = SQRT8 / vol;
		for (int al = 0; al < 4; al++) {
			vec a0, a1, a2;
			VLOAD(a0, b->a[al + 4][0]);
			VLOAD(a1, b->a[al + 4][1]);
			VLOAD(a2, b->a[al + 4][2]);
			for (int i = 0; i < 3; i++) {
				vec Qi;
				VLOAD(Qi, Q + (3 * al + i) * NB);
				vec sq = s * Qi;
				T[3 * i + 0] -= sq * a0;
				T[3 * i + 1] -= sq * a1;
				T[3 * i + 2] -= sq * a2;
				F[i][al + 4] = Qi * (1 / SQRT8);
			}
		}
	} else {
		const vec zero = { 0 };
		for (int i = 0; i < 3; i++)
			F[i][4] = F[i][5] = F[i][6] = F[i][7] = zero;
	}
	for (int l = 1; l <= 6; l++) {
		vec c0, c1, c2;
		VLOAD(c0, b->c[l][0]);
		VLOAD(c1, b->c[l][1]);
		VLOAD(c2, b->c[l][2]);
		c0 *= 0.125;
		c1 *= 0.125;
		c2 *= 0.125;
		for (int i = 0; i < 3; i++) {
			vec t = T[3 * i] * c0 + T[3 * i + 1] * c1 + T[3 * i + 2] * c2;
			F[i][l] = l >= 4 ? F[i][l] + t : t;
		}
	}
	for (int i = 0; i < 3; i++) {
		vec u[8];
		walsh_inv_v(F[i], u);
		for (int I = 0; I < 8; I++)
			VSTORE(f + (8 * i + I) * NB, u[I]);
	}
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
#endif

/* ---- Full integration ---------------------------------------------------- */

/* Natural coordinates of Gauss point p (numbered like the nodes). */
static inline void gauss_xi(int p, double *xi, double *eta, double *zeta)
{
	*xi = GAUSS * dem_hex8_node_xi[p];
	*eta = GAUSS * dem_hex8_node_eta[p];
	*zeta = GAUSS * dem_hex8_node_zeta[p];
}

/* Columns of the Jacobian at (xi, eta, zeta) from the modes a. */
static inline void jacobian(double a[8][3], double xi, double eta, double zeta,
			    double u[3], double v[3], double w[3])
{
	for (int i = 0; i < 3; i++) {
		u[i] = a[1][i] + a[6][i] * eta + a[5][i] * zeta + a[7][i] * eta * zeta;
		v[i] = a[2][i] + a[6][i] * xi + a[4][i] * zeta + a[7][i] * xi * zeta;
		w[i] = a[3][i] + a[5][i] * xi + a[4][i] * eta + a[7][i] * xi * eta;
	}
}

/* Inverse of J = [u v w] (columns): rows (v x w, w x u, u x v) / det. */
static inline double invert(const double u[3], const double v[3], const double w[3],
			    double Ji[9])
{
	memset(Ji, 0, 9 * sizeof *Ji);
	dem_hex_cross_add(v, w, 1, Ji);
	dem_hex_cross_add(w, u, 1, Ji + 3);
	dem_hex_cross_add(u, v, 1, Ji + 6);
	double det = u[0] * Ji[0] + u[1] * Ji[1] + u[2] * Ji[2];
	double r = 1 / det;
	for (int i = 0; i < 9; i++)
		Ji[i] *= r;
	return det;
}

int dem_hex8_full_geom(const double x[24], dem_hex8_full_t *g)
{
	dem_hex_modes(x, g->a);
	dem_hex_volume_modes(g->a, g->c, &g->vol);
	int bad = !(g->vol > 0) || !(dem_hex_triple(g->a[1], g->a[2], g->a[3]) > 0);
	for (int p = 0; p < 8; p++) {
		double xi, eta, zeta, u[3], v[3], w[3];
		gauss_xi(p, &xi, &eta, &zeta);
		jacobian(g->a, xi, eta, zeta, u, v, w);
		double det = invert(u, v, w, g->Jinv[p]);
		g->wdet[p] = det;  /* Gauss weights are 1 */
		bad |= !(det > 0);
	}
	return bad ? DEM_HEX8_INVERTED : DEM_HEX8_OK;
}

void dem_hex8_full_rate(dem_hex8_full_t *g, const double v[24], int bbar)
{
	double av[8][3];
	dem_hex_modes(v, av);
	double trm = 0;
	if (bbar) {
		for (int k = 1; k <= 6; k++)
			trm += av[k][0] * g->c[k][0] + av[k][1] * g->c[k][1] + av[k][2] * g->c[k][2];
		trm /= g->vol;
	}
	for (int p = 0; p < 8; p++) {
		double xi, eta, zeta, vx[3], ve[3], vz[3];
		gauss_xi(p, &xi, &eta, &zeta);
		jacobian(av, xi, eta, zeta, vx, ve, vz);
		/* L = [v_xi v_eta v_zeta] J^-1 */
		const double *Ji = g->Jinv[p];
		double *L = g->L[p];
		for (int i = 0; i < 3; i++)
			for (int j = 0; j < 3; j++)
				L[3 * i + j] = vx[i] * Ji[j] + ve[i] * Ji[3 + j] + vz[i] * Ji[6 + j];
		if (bbar) {
			double dv = (trm - (L[0] + L[4] + L[8])) / 3;
			L[0] += dv;
			L[4] += dv;
			L[8] += dv;
		}
	}
}

void dem_hex8_full_force(const dem_hex8_full_t *g, const double sig[48],
			 int bbar, double f[24])
{
	double F[3][8];
	memset(F, 0, sizeof F);
	double psum = 0;
	for (int p = 0; p < 8; p++) {
		double xi, eta, zeta;
		gauss_xi(p, &xi, &eta, &zeta);
		const double *s = sig + 6 * p;
		double S[9] = { s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2] };
		if (bbar) {
			double pr = (s[0] + s[1] + s[2]) / 3;
			S[0] -= pr;
			S[4] -= pr;
			S[8] -= pr;
			psum += g->wdet[p] * pr;
		}
		/* P = wdet S J^-T: f_I = sum_p P grad_xi N_I(p) */
		const double *Ji = g->Jinv[p];
		double P[3][3];
		for (int i = 0; i < 3; i++)
			for (int j = 0; j < 3; j++)
				P[i][j] = g->wdet[p] * (S[3 * i] * Ji[3 * j] + S[3 * i + 1] * Ji[3 * j + 1] +
							S[3 * i + 2] * Ji[3 * j + 2]);
		/* grad_xi N_I = 1/8 (Lambda_1 + eta L6 + zeta L5 + eta zeta L7,
		 * Lambda_2 + xi L6 + zeta L4 + xi zeta L7,
		 * Lambda_3 + xi L5 + eta L4 + xi eta L7)(I) */
		for (int i = 0; i < 3; i++) {
			double p0 = P[i][0], p1 = P[i][1], p2 = P[i][2];
			F[i][1] += p0;
			F[i][2] += p1;
			F[i][3] += p2;
			F[i][4] += zeta * p1 + eta * p2;
			F[i][5] += zeta * p0 + xi * p2;
			F[i][6] += eta * p0 + xi * p1;
			F[i][7] += eta * zeta * p0 + xi * zeta * p1 + xi * eta * p2;
		}
	}
	double pm = bbar ? psum / g->vol : 0;
	for (int i = 0; i < 3; i++) {
		for (int k = 1; k <= 7; k++)
			F[i][k] = 0.125 * (F[i][k] + (k <= 6 ? pm * g->c[k][i] : 0));
		dem_hex_walsh_inv(F[i], f + 8 * i);
	}
}

/* ---- Implicit element ------------------------------------------------------ */

#define NPN 11  /* pseudo-nodes: 8 nodes and 3 incompatible modes */

int dem_hex8_static(const dem_mat_t *m, dem_hex8_rule_t rule, const double X[24],
		    const double du[24], const dem_hex8_hist_t *hn,
		    dem_hex8_hist_t *h, double fint[24], double K[576], double *wp)
{
	dem_hex8_full_t g;
	if (dem_hex8_full_geom(X, &g))
		return DEM_HEX8_INVERTED;
	int eas = rule == DEM_HEX8_EAS;
	int nb = eas ? NPN : 8, nd = 3 * nb;

	/* mean gradient for B-bar; centre Jacobian for the incompatible modes */
	double bm[24], J0i[9] = { 0 }, j0 = 0;
	if (rule == DEM_HEX8_BBAR) {
		dem_hex8_1pt_t g1;
		memcpy(g1.a, g.a, sizeof g1.a);
		memcpy(g1.c, g.c, sizeof g1.c);
		g1.vol = g.vol;
		dem_hex8_1pt_grad(&g1, bm);
	}
	if (eas)
		j0 = invert(g.a[1], g.a[2], g.a[3], J0i);

	/* strain-displacement blocks at each Gauss point */
	double Bp[8][NPN][6][3];
	for (int p = 0; p < 8; p++) {
		double b[NPN][3];
		dem_hex8_grads(&g, p, eas, j0, J0i, b);
		for (int I = 0; I < nb; I++)
			bblock(b[I][0], b[I][1], b[I][2], Bp[p][I]);
		if (rule == DEM_HEX8_BBAR)
			for (int I = 0; I < 8; I++)
				/* volumetric strain from the mean gradient (Hughes 1980) */
				for (int j = 0; j < 3; j++) {
					double dv = (bm[8 * j + I] - b[I][j]) / 3;
					Bp[p][I][0][j] += dv;
					Bp[p][I][1][j] += dv;
					Bp[p][I][2][j] += dv;
				}
	}

	/* local dofs: pseudo-node-major 3 n + i; the nodal ones from du */
	double dq[3 * NPN];
	for (int I = 0; I < 8; I++)
		for (int i = 0; i < 3; i++)
			dq[3 * I + i] = du[8 * i + I];
	if (!eas)
		memset(h->alpha, 0, sizeof h->alpha);

	/* Local Newton iteration on the modes (none without them): the modes
	 * must make their own residual r_a = int G^T sig dV vanish.  A plastic
	 * Gauss point switching between loading and unloading can make the
	 * plain iteration cycle, so steps that do not reduce |r_a| are
	 * halved (backtracking on the residual norm). */
	double Dg[8][36], r[3 * NPN];
	double wpl = 0;
	dem_hex8_modes_t mi = { .step = 1 };
	int it, maxit = eas ? DEM_HEX8_MODES_MAXIT : 1;
	for (it = 0; it < maxit; it++) {
		if (eas)
			for (int a = 0; a < 9; a++)
				dq[24 + a] = h->alpha[a] - hn->alpha[a];
		/* stresses and tangents at the Gauss points */
		memset(r, 0, sizeof r);
		double ref = 0;
		wpl = 0;
		for (int p = 0; p < 8; p++) {
			double de[6] = { 0 };
			for (int n = 0; n < nb; n++)
				for (int t = 0; t < 6; t++)
					de[t] += Bp[p][n][t][0] * dq[3 * n] + Bp[p][n][t][1] * dq[3 * n + 1] +
						 Bp[p][n][t][2] * dq[3 * n + 2];
			double *s = h->sig + 6 * p, w;
			memcpy(s, hn->sig + 6 * p, 6 * sizeof *s);
			h->ep[p] = hn->ep[p];
			dem_mat_update_tangent(m, de, 0, s, &h->ep[p], NULL, &w, Dg[p]);
			wpl += w * g.wdet[p];
			for (int n = 0; n < nb; n++)
				for (int i = 0; i < 3; i++) {
					double t = 0;
					for (int k = 0; k < 6; k++)
						t += Bp[p][n][k][i] * s[k];
					r[3 * n + i] += g.wdet[p] * t;
				}
			for (int k = 0; k < 6; k++)
				ref += g.wdet[p] * fabs(s[k]);
		}
		if (!eas)
			break;
		int next = dem_hex8_modes_check(&mi, it, r + 24, ref, g.vol, m->E, h->alpha);
		if (next == DEM_HEX8_MODES_DONE)
			break;
		if (next == DEM_HEX8_MODES_HALVED)
			continue;
		/* Newton step on the modes: K_aa dalpha = -r_a */
		double Kaa[81] = { 0 };
		for (int p = 0; p < 8; p++)
			add_btdb(3, &Bp[p][8], Dg[p], g.wdet[p], Kaa);
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
			add_btdb(nb, Bp[p], Dg[p], g.wdet[p], Kf);
	}
	return dem_hex8_condense(eas, Kf, nd, r, fint, K);
}

/* The gradients of the pseudo-nodes at Gauss point p (hex8.h). */
void dem_hex8_grads(const dem_hex8_full_t *g, int p, int eas, double j0,
		    const double J0i[9], double b[][3])
{
	double gx[3];
	gauss_xi(p, &gx[0], &gx[1], &gx[2]);
	const double *Ji = g->Jinv[p];
	for (int I = 0; I < 8; I++) {
		/* grad_xi N_I, then grad_x N_I = J^-T grad_xi N_I */
		double xI = dem_hex8_node_xi[I], eI = dem_hex8_node_eta[I], zI = dem_hex8_node_zeta[I];
		double n0 = 0.125 * xI * (1 + gx[1] * eI) * (1 + gx[2] * zI);
		double n1 = 0.125 * eI * (1 + gx[0] * xI) * (1 + gx[2] * zI);
		double n2 = 0.125 * zI * (1 + gx[0] * xI) * (1 + gx[1] * eI);
		for (int j = 0; j < 3; j++)
			b[I][j] = Ji[j] * n0 + Ji[3 + j] * n1 + Ji[6 + j] * n2;
	}
	if (!eas)
		return;
	/* mode 1 - xi_m^2: d/dxi_m = -2 xi_m, mapped with J0 and scaled by
	 * j0 / j so that its integral over the element vanishes (the patch
	 * test condition) */
	double s = j0 / g->wdet[p];
	for (int mm = 0; mm < 3; mm++) {
		double d = -2 * gx[mm] * s;
		for (int j = 0; j < 3; j++)
			b[8 + mm][j] = d * J0i[3 * mm + j];
	}
}

/* The local iteration on the modes (hex8.h): converged when the mode
 * residual is negligible against the element's stress resultant (N);
 * steps that do not reduce |r_a| are halved (backtracking). */
int dem_hex8_modes_check(dem_hex8_modes_t *mi, int it, const double ra[9],
			 double ref, double vol, double E, double alpha[9])
{
	double h3 = cbrt(vol);
	double tol = 1e-11 * ref / h3 + 1e-15 * E * h3 * h3;
	double rmax = 0, rn = 0;
	for (int a = 0; a < 9; a++) {
		rmax = fmax(rmax, fabs(ra[a]));
		rn += ra[a] * ra[a];
	}
	mi->rn = sqrt(rn);
	if (rmax <= tol)
		return DEM_HEX8_MODES_DONE;
	if (it > 0 && mi->rn > (1 - 1e-4 * mi->step) * mi->rprev && mi->step > 1.0 / 64) {
		mi->step *= 0.5;
		for (int a = 0; a < 9; a++)
			alpha[a] = mi->a0[a] - mi->step * mi->da[a];
		return DEM_HEX8_MODES_HALVED;
	}
	return DEM_HEX8_MODES_NEWTON;
}

int dem_hex8_modes_newton(dem_hex8_modes_t *mi, double Kaa[81], const double ra[9],
			  double alpha[9])
{
	memcpy(mi->da, ra, sizeof mi->da);
	if (dem_dense_solve(9, Kaa, 1, mi->da))
		return DEM_HEX8_NOCONV;
	memcpy(mi->a0, alpha, sizeof mi->a0);
	mi->rprev = mi->rn;
	mi->step = 1;
	for (int a = 0; a < 9; a++)
		alpha[a] = mi->a0[a] - mi->da[a];
	return DEM_HEX8_OK;
}

/* Static condensation of the incompatible modes (hex8.h). */
int dem_hex8_condense(int eas, double *Kf, int nd, double *r, double fint[24],
		      double K[576])
{
	if (!K) {       /* the modes' residual is converged: r_u is fint */
		for (int I = 0; I < 8; I++)
			for (int i = 0; i < 3; i++)
				fint[8 * i + I] = r[3 * I + i];
		return DEM_HEX8_OK;
	}
	if (eas) {
		/* static condensation: K = Kuu - Kua Kaa^-1 Kau,
		 * f = r_u - Kua Kaa^-1 r_a */
		double Kaa[81], Z[9 * 25];
		for (int a = 0; a < 9; a++) {
			for (int b = 0; b < 9; b++)
				Kaa[9 * a + b] = Kf[(24 + a) * nd + 24 + b];
			for (int j = 0; j < 24; j++)
				Z[25 * a + j] = Kf[(24 + a) * nd + j];
			Z[25 * a + 24] = r[24 + a];
		}
		if (dem_dense_solve(9, Kaa, 25, Z))
			return DEM_HEX8_NOCONV;
		for (int i = 0; i < 24; i++) {
			for (int j = 0; j < 24; j++) {
				double s = 0;
				for (int a = 0; a < 9; a++)
					s += Kf[i * nd + 24 + a] * Z[25 * a + j];
				Kf[i * nd + j] -= s;
			}
			double s = 0;
			for (int a = 0; a < 9; a++)
				s += Kf[i * nd + 24 + a] * Z[25 * a + 24];
			r[i] -= s;
		}
	}
	for (int I = 0; I < 8; I++)
		for (int i = 0; i < 3; i++) {
			fint[8 * i + I] = r[3 * I + i];
			for (int J = 0; J < 8; J++)
				for (int j = 0; j < 3; j++)
					K[(8 * i + I) * 24 + 8 * j + J] = Kf[(3 * I + i) * nd + 3 * J + j];
		}
	return DEM_HEX8_OK;
}

/* ---- Helpers ----------------------------------------------------------------- */

void dem_hex8_gauss_points(const double x[24], double xg[24])
{
	double a[8][3];
	dem_hex_modes(x, a);
	for (int p = 0; p < 8; p++) {
		double xi, eta, zeta;
		gauss_xi(p, &xi, &eta, &zeta);
		for (int i = 0; i < 3; i++)
			xg[8 * i + p] = a[0][i] + a[1][i] * xi + a[2][i] * eta + a[3][i] * zeta +
					a[4][i] * eta * zeta + a[5][i] * zeta * xi + a[6][i] * xi * eta +
					a[7][i] * xi * eta * zeta;
	}
}

int dem_hex8_lumped_mass(const double x[24], double rho, double mass[8])
{
	dem_hex8_full_t g;
	int rc = dem_hex8_full_geom(x, &g);
	for (int I = 0; I < 8; I++) {
		double s = 0;
		for (int p = 0; p < 8; p++) {
			double xi, eta, zeta;
			gauss_xi(p, &xi, &eta, &zeta);
			double N = 0.125 * (1 + xi * dem_hex8_node_xi[I]) * (1 + eta * dem_hex8_node_eta[I]) *
				   (1 + zeta * dem_hex8_node_zeta[I]);
			s += N * g.wdet[p];
		}
		mass[I] = rc ? 0 : rho * s;
	}
	return rc;
}

int dem_hex8_dt_crit(const double x[24], double c, double *dt)
{
	static const int face[6][4] = {
		{ 0, 1, 2, 3 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
		{ 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 }
	};
	dem_hex8_1pt_t g;
	*dt = 0;
	if (dem_hex8_1pt_geom(x, &g))
		return DEM_HEX8_INVERTED;
	double amax = 0;
	for (int f = 0; f < 6; f++) {
		/* area of a (possibly warped) quadrilateral: half the cross
		 * product of its diagonals */
		const int *n = face[f];
		double d1[3], d2[3], A[3] = { 0, 0, 0 };
		for (int i = 0; i < 3; i++) {
			d1[i] = x[8 * i + n[2]] - x[8 * i + n[0]];
			d2[i] = x[8 * i + n[3]] - x[8 * i + n[1]];
		}
		dem_hex_cross_add(d1, d2, 0.5, A);
		amax = fmax(amax, sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]));
	}
	if (!(amax > 0) || !(c > 0))
		return DEM_HEX8_INVERTED;
	*dt = g.vol / amax / c;
	return DEM_HEX8_OK;
}
