/* test_fe_hex8.c - unit tests of lib/fe/hex8.c: the 8-node hexahedron.
 *
 * References: the patch test (Irons; a linear displacement field on a
 * distorted mesh must give the constant strain and the exact stress, with
 * the forces of interior nodes cancelling); the properties of the uniform
 * gradient and hourglass vectors of Flanagan & Belytschko (1981): b_I =
 * int grad N_I dV (checked against 2x2x2 Gauss quadrature, exact for it),
 * gamma orthogonal to the linear field; the rank of element stiffness
 * matrices (6 rigid modes; 12 more hourglass modes under one-point
 * integration); Euler-Bernoulli beam theory for pure bending, kappa =
 * M / (E I); and the wave speed of the critical time step.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_linalg.h>

#include "fe/hex8.h"
#include "fe/material.h"
#include "zeromodes.h"

#define GPA 1e9

static const dem_hex8_hist_t HZERO;  /* a virgin, stress-free history */

/* deterministic pseudo-random numbers in [-1, 1] */
static double urand(unsigned long *s)
{
	*s = *s * 6364136223846793005ul + 1442695040888963407ul;
	return ((*s >> 11) * (1.0 / 9007199254740992.0)) * 2 - 1;
}

static double rel(double a, double b)
{
	return fabs(a - b) / fmax(fabs(b), 1e-300);
}

static void make_elastic(dem_mat_t *m)
{
	dem_mat_param_t p = { .E = 72 * GPA, .nu = 0.33, .rho = 2800 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

/* A structured box mesh of nx x ny x nz hexahedra on [x0, x0 + lx] x ... */
typedef struct mesh {
	int nx, ny, nz, nn, ne;
	double *X;      /* node coordinates, 3 per node */
	int (*conn)[8];
} mesh_t;

static int node_id(const mesh_t *m, int i, int j, int k)
{
	return i + (m->nx + 1) * (j + (m->ny + 1) * k);
}

static void mesh_box(mesh_t *m, int nx, int ny, int nz, const double lo[3], const double len[3])
{
	m->nx = nx;
	m->ny = ny;
	m->nz = nz;
	m->nn = (nx + 1) * (ny + 1) * (nz + 1);
	m->ne = nx * ny * nz;
	m->X = malloc(3 * sizeof(double) * (size_t)m->nn);
	m->conn = malloc(sizeof *m->conn * (size_t)m->ne);
	assert_non_null(m->X);
	assert_non_null(m->conn);
	for (int k = 0; k <= nz; k++)
		for (int j = 0; j <= ny; j++)
			for (int i = 0; i <= nx; i++) {
				double *x = m->X + 3 * node_id(m, i, j, k);
				x[0] = lo[0] + len[0] * i / nx;
				x[1] = lo[1] + len[1] * j / ny;
				x[2] = lo[2] + len[2] * k / nz;
			}
	int e = 0;
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++, e++) {
				int *c = m->conn[e];
				c[0] = node_id(m, i, j, k);
				c[1] = node_id(m, i + 1, j, k);
				c[2] = node_id(m, i + 1, j + 1, k);
				c[3] = node_id(m, i, j + 1, k);
				c[4] = node_id(m, i, j, k + 1);
				c[5] = node_id(m, i + 1, j, k + 1);
				c[6] = node_id(m, i + 1, j + 1, k + 1);
				c[7] = node_id(m, i, j + 1, k + 1);
			}
}

static void mesh_free(mesh_t *m)
{
	free(m->X);
	free(m->conn);
}

/* Gather a nodal field (3 per node) of element e, component-major. */
static void gather(const mesh_t *m, int e, const double *u, double ue[24])
{
	for (int I = 0; I < 8; I++)
		for (int i = 0; i < 3; i++)
			ue[8 * i + I] = u[3 * m->conn[e][I] + i];
}

/* The distorted 2x2x2 patch on [0,1]^3: every node moved at random by up
 * to 0.1 (so faces are warped); node 13 is the interior node. */
static void patch_mesh(mesh_t *m)
{
	static const double lo[3] = { 0, 0, 0 }, len[3] = { 1, 1, 1 };
	mesh_box(m, 2, 2, 2, lo, len);
	unsigned long s = 12345;
	for (int n = 0; n < m->nn; n++)
		for (int i = 0; i < 3; i++)
			m->X[3 * n + i] += 0.1 * urand(&s);
}

/* A general linear field u = A x + c. */
static const double LA[9] = { 1.0e-3, 2.0e-4, -3.0e-4, -1.0e-4, -5.0e-4, 4.0e-4, 6.0e-4, 1.5e-4, 2.5e-4 };
static const double LC[3] = { 1e-4, -2e-4, 3e-4 };

static void linear_field(const mesh_t *m, double *u)
{
	for (int n = 0; n < m->nn; n++)
		for (int i = 0; i < 3; i++) {
			const double *x = m->X + 3 * n;
			u[3 * n + i] = LA[3 * i] * x[0] + LA[3 * i + 1] * x[1] + LA[3 * i + 2] * x[2] + LC[i];
		}
}

/* The exact strain of the linear field (engineering shears) and stress. */
static void exact_state(const dem_mat_t *mat, double eps[6], double sig[6])
{
	eps[0] = LA[0];
	eps[1] = LA[4];
	eps[2] = LA[8];
	eps[3] = LA[1] + LA[3];
	eps[4] = LA[5] + LA[7];
	eps[5] = LA[6] + LA[2];
	double D[36];
	dem_mat_elastic_stiffness(mat, D);
	for (int i = 0; i < 6; i++) {
		sig[i] = 0;
		for (int j = 0; j < 6; j++)
			sig[i] += D[6 * i + j] * eps[j];
	}
}

static double vmax(const double *v, int n)
{
	double s = 0;
	for (int i = 0; i < n; i++)
		s = fmax(s, fabs(v[i]));
	return s;
}

/* The uniform gradient b_I = dV/dx_I of the modal closed form equals
 * int grad N_I dV by 2x2x2 Gauss quadrature (exact for it: the integrand
 * is at most quadratic in each natural coordinate), and the volume equals
 * sum det J.  Linear consistency: sum_I x_I (x) b_I = V 1. */
static void test_uniform_gradient(void **state)
{
	(void)state;
	unsigned long s = 99;
	for (int trial = 0; trial < 20; trial++) {
		double x[24];
		for (int I = 0; I < 8; I++) {
			x[I] = 0.5 * (1 + dem_hex8_node_xi[I]) * 2.0 + 0.25 * urand(&s);
			x[8 + I] = 0.5 * (1 + dem_hex8_node_eta[I]) * 1.0 + 0.2 * urand(&s);
			x[16 + I] = 0.5 * (1 + dem_hex8_node_zeta[I]) * 0.5 + 0.1 * urand(&s);
		}
		dem_hex8_1pt_t g;
		dem_hex8_full_t f;
		assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
		assert_int_equal(dem_hex8_full_geom(x, &f), DEM_HEX8_OK);
		double B[24], bq[24] = { 0 }, vq = 0;
		dem_hex8_1pt_grad(&g, B);
		for (int p = 0; p < 8; p++) {
			double xi = dem_hex8_node_xi[p] / sqrt(3), eta = dem_hex8_node_eta[p] / sqrt(3),
			       zeta = dem_hex8_node_zeta[p] / sqrt(3);
			vq += f.wdet[p];
			for (int I = 0; I < 8; I++) {
				double xI = dem_hex8_node_xi[I], eI = dem_hex8_node_eta[I], zI = dem_hex8_node_zeta[I];
				double n[3] = { xI * (1 + eta * eI) * (1 + zeta * zI) / 8,
						eI * (1 + xi * xI) * (1 + zeta * zI) / 8,
						zI * (1 + xi * xI) * (1 + eta * eI) / 8 };
				for (int j = 0; j < 3; j++)
					bq[8 * j + I] += f.wdet[p] * (f.Jinv[p][j] * n[0] + f.Jinv[p][3 + j] * n[1] +
								      f.Jinv[p][6 + j] * n[2]);
			}
		}
		assert_true(rel(g.vol, vq) < 1e-14);
		assert_true(rel(f.vol, vq) < 1e-14);
		for (int i = 0; i < 24; i++)
			assert_true(fabs(B[i] * g.vol - bq[i]) < 1e-14 * vmax(bq, 24));
		for (int i = 0; i < 3; i++)
			for (int j = 0; j < 3; j++) {
				double sxb = 0;
				for (int I = 0; I < 8; I++)
					sxb += x[8 * i + I] * B[8 * j + I];
				assert_true(fabs(sxb - (i == j)) < 1e-13);
			}
	}
}

/* Flanagan & Belytschko's gamma vectors are orthogonal to the linear field
 * (gamma_alpha . x_i = 0, gamma_alpha . 1 = 0, by construction) and reduce to the
 * base vectors h_alpha / sqrt 8 for a parallelepiped. */
static void test_hourglass_vectors(void **state)
{
	(void)state;
	mesh_t m;
	patch_mesh(&m);
	for (int e = 0; e < m.ne; e++) {
		double x[24], gam[32];
		dem_hex8_1pt_t g;
		gather(&m, e, m.X, x);
		assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
		dem_hex8_1pt_gamma(&g, gam);
		for (int al = 0; al < 4; al++) {
			double s1 = 0;
			for (int I = 0; I < 8; I++)
				s1 += gam[8 * al + I];
			assert_true(fabs(s1) < 1e-13);
			for (int i = 0; i < 3; i++) {
				double sx = 0;
				for (int I = 0; I < 8; I++)
					sx += gam[8 * al + I] * x[8 * i + I];
				assert_true(fabs(sx) < 1e-13);
			}
		}
	}
	mesh_free(&m);
	/* a box: gamma = h / sqrt 8 */
	double x[24], gam[32];
	for (int I = 0; I < 8; I++) {
		x[I] = 3 * dem_hex8_node_xi[I];
		x[8 + I] = 2 * dem_hex8_node_eta[I];
		x[16 + I] = dem_hex8_node_zeta[I];
	}
	dem_hex8_1pt_t g;
	assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
	assert_true(rel(g.vol, 48) < 1e-15);
	dem_hex8_1pt_gamma(&g, gam);
	for (int I = 0; I < 8; I++) {
		double xi = dem_hex8_node_xi[I], eta = dem_hex8_node_eta[I], zeta = dem_hex8_node_zeta[I];
		double h[4] = { eta * zeta, zeta * xi, xi * eta, xi * eta * zeta };
		for (int al = 0; al < 4; al++)
			assert_true(fabs(gam[8 * al + I] - h[al] / sqrt(8)) < 1e-15);
	}
}

/* Power balance of the one-point kernel: for any velocity field the
 * internal power f . v equals V sig : d plus the hourglass power Q . q
 * that dem_hex8_hg_resist reports (so the hourglass energy a driver sums is
 * the work its forces do); the hourglass forces alone do work Q . q. */
static void test_hourglass_power(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	unsigned long s = 21;
	for (int trial = 0; trial < 10; trial++) {
		double x[24], v[24];
		for (int I = 0; I < 8; I++) {
			x[I] = dem_hex8_node_xi[I] + 0.25 * urand(&s);
			x[8 + I] = dem_hex8_node_eta[I] + 0.25 * urand(&s);
			x[16 + I] = 0.3 * dem_hex8_node_zeta[I] + 0.05 * urand(&s);
		}
		for (int i = 0; i < 24; i++)
			v[i] = urand(&s);
		dem_hex8_1pt_t g;
		assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
		dem_hex8_1pt_rate(&g, v);
		assert_true(vmax(g.q, 12) > 0.1);
		double ks, cv, Qs[12], Q[12];
		for (int i = 0; i < 12; i++)
			Qs[i] = 1e3 * urand(&s);   /* some stored hourglass force */
		dem_hex8_hg_coef(&g, &mat, 0.05, 0.1, &ks, &cv);
		double P = dem_hex8_hg_resist(&g, ks, cv, 1e-8, Qs, Q);
		double sig[6] = { 1e8, -2e7, 3e7, 4e7, -1e7, 2e7 }, zero[6] = { 0 }, d[6], w[3], f[24], fh[24];
		dem_hex8_strain_rate(g.L, d, w);
		dem_hex8_1pt_force(&g, sig, Q, f);
		dem_hex8_1pt_force(&g, zero, Q, fh);
		double pf = 0, ph = 0, ps = 0;
		for (int i = 0; i < 24; i++) {
			pf += f[i] * v[i];
			ph += fh[i] * v[i];
		}
		for (int i = 0; i < 6; i++)
			ps += sig[i] * d[i] * g.vol;
		assert_true(fabs(ph - P) < 1e-12 * (fabs(P) + fabs(ps)));
		assert_true(fabs(pf - ps - P) < 1e-12 * (fabs(P) + fabs(ps)));
	}
	dem_mat_free(&mat);
}

/* The batched one-point kernels give the scalar kernels' results lane by
 * lane (velocity gradient, rates, hourglass velocities and forces, forces
 * to round-off); an inverted element in one lane is flagged in the mask
 * while the other lanes are unaffected and every lane stays finite. */
static void test_batch_kernels(void **state)
{
	(void)state;
	enum { NB = DEM_HEX8_NB };
	dem_mat_t mat;
	make_elastic(&mat);
	unsigned long s = 77;
	for (int trial = 0; trial < 20; trial++) {
		double x[24][NB], v[24][NB], sig[6][NB], Qs[12][NB], Q[12][NB], P[NB], f[24][NB];
		double xs[NB][24], vs[NB][24];
		int badlane = trial % 5 == 4 ? trial % NB : -1;
		for (int l = 0; l < NB; l++) {
			for (int I = 0; I < 8; I++) {
				xs[l][I] = dem_hex8_node_xi[I] + 0.25 * urand(&s);
				xs[l][8 + I] = dem_hex8_node_eta[I] + 0.25 * urand(&s);
				xs[l][16 + I] = 0.3 * dem_hex8_node_zeta[I] + 0.05 * urand(&s);
				if (l == badlane)
					xs[l][16 + I] = -xs[l][16 + I];   /* turned inside out */
			}
			for (int i = 0; i < 24; i++) {
				vs[l][i] = urand(&s);
				x[i][l] = xs[l][i];
				v[i][l] = vs[l][i];
			}
			for (int k = 0; k < 6; k++)
				sig[k][l] = 1e8 * urand(&s);
			for (int k = 0; k < 12; k++)
				Qs[k][l] = 1e3 * urand(&s);
		}
		dem_hex8_batch_t b;
		unsigned bad = dem_hex8_batch_kin(&b, x[0], v[0]);
		assert_int_equal(bad, badlane >= 0 ? 1u << badlane : 0u);
		double Qs0[12][NB];
		memcpy(Qs0, Qs, sizeof Qs0);
		dem_hex8_batch_hg(&b, &mat, 0.05, 0.1, 1e-8, NULL, Qs[0], Q[0], P);
		dem_hex8_batch_force(&b, sig[0], Q[0], f[0]);
		for (int l = 0; l < NB; l++) {
			for (int i = 0; i < 24; i++)
				assert_true(isfinite(f[i][l]));
			if (l == badlane)
				continue;
			dem_hex8_1pt_t g;
			assert_int_equal(dem_hex8_1pt_geom(xs[l], &g), DEM_HEX8_OK);
			dem_hex8_1pt_rate(&g, vs[l]);
			assert_true(rel(b.vol[l], g.vol) < 1e-15);
			double d[6], w[3];
			dem_hex8_strain_rate(g.L, d, w);
			for (int k = 0; k < 9; k++)
				assert_true(fabs(b.L[k][l] - g.L[k]) <= 1e-14 * vmax(g.L, 9));
			for (int k = 0; k < 6; k++)
				assert_true(fabs(b.d[k][l] - d[k]) <= 1e-14 * vmax(g.L, 9));
			for (int k = 0; k < 3; k++)
				assert_true(fabs(b.w[k][l] - w[k]) <= 1e-14 * vmax(g.L, 9));
			for (int k = 0; k < 12; k++)
				assert_true(fabs(b.q[k][l] - g.q[k]) <= 1e-14 * vmax(g.q, 12));
			double ks, cv, Qsl[12], Ql[12], sl[6], fl[24];
			for (int k = 0; k < 12; k++)
				Qsl[k] = Qs0[k][l];
			for (int k = 0; k < 6; k++)
				sl[k] = sig[k][l];
			dem_hex8_hg_coef(&g, &mat, 0.05, 0.1, &ks, &cv);
			double Pl = dem_hex8_hg_resist(&g, ks, cv, 1e-8, Qsl, Ql);
			assert_true(fabs(P[l] - Pl) <= 1e-12 * fabs(Pl));
			for (int k = 0; k < 12; k++)
				assert_true(fabs(Q[k][l] - Ql[k]) <= 1e-13 * vmax(Ql, 12));
			dem_hex8_1pt_force(&g, sl, Ql, fl);
			for (int i = 0; i < 24; i++)
				assert_true(fabs(f[i][l] - fl[i]) <= 1e-13 * vmax(fl, 24));
		}
		/* with a tangent factor per lane: an increment that raises
		 * |Qs| is scaled by the lane's factor, one that lowers it is
		 * not; half the modes of each lane start with Qs against the
		 * increment, so both branches run in every lane */
		double ksl[NB], Qk[12][NB], Pk[NB], Qsk[12][NB];
		for (int l = 0; l < NB; l++)
			ksl[l] = l == 0 ? 0 : l == 1 ? 1 : 0.1 + 0.8 * fabs(urand(&s));
		for (int k = 0; k < 12; k++)
			for (int l = 0; l < NB; l++)
				Qsk[k][l] = (k % 2 ? -1 : 1) * fabs(Qs0[k][l]) * (b.q[k][l] < 0 ? -1 : 1);
		double Qsk0[12][NB];
		memcpy(Qsk0, Qsk, sizeof Qsk0);
		dem_hex8_batch_hg(&b, &mat, 0.05, 0.1, 1e-8, ksl, Qsk[0], Qk[0], Pk);
		int up = 0, down = 0;
		for (int l = 0; l < NB; l++) {
			if (l == badlane)
				continue;
			dem_hex8_1pt_t g;
			assert_int_equal(dem_hex8_1pt_geom(xs[l], &g), DEM_HEX8_OK);
			dem_hex8_1pt_rate(&g, vs[l]);
			double ks, cv, pl = 0;
			dem_hex8_hg_coef(&g, &mat, 0.05, 0.1, &ks, &cv);
			for (int k = 0; k < 12; k++) {
				double inc = ks * 1e-8 * g.q[k], qs = Qsk0[k][l];
				if (qs * inc > 0)
					inc *= ksl[l], up++;
				else
					down++;
				qs += inc;
				double qq = qs + cv * g.q[k];
				pl += qq * g.q[k];
				assert_true(fabs(Qsk[k][l] - qs) <= 1e-13 * fabs(qs) + 1e-300);
				assert_true(fabs(Qk[k][l] - qq) <= 1e-13 * vmax(Qk[0], 12 * NB));
			}
			assert_true(fabs(Pk[l] - pl) <= 1e-12 * fabs(pl));
		}
		assert_true(up > 0 && down > 0);
	}
	dem_mat_free(&mat);
}

/* Patch test, one-point integration: on the distorted 2x2x2 mesh a linear
 * velocity field gives in every element the exact constant strain rate and
 * (through the elastic update) the exact stress to 1e-10; the hourglass
 * velocities vanish, so the hourglass forces do (viscous and stiffness form
 * alike); the assembled forces cancel at the interior node. */
static void test_patch_1pt(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	mesh_t m;
	patch_mesh(&m);
	double *u = malloc(3 * sizeof(double) * (size_t)m.nn);
	double *F = calloc(3 * (size_t)m.nn, sizeof(double));
	assert_non_null(u);
	assert_non_null(F);
	linear_field(&m, u);
	double eps_x[6], sig_x[6];
	exact_state(&mat, eps_x, sig_x);
	double fscale = 0;
	for (int e = 0; e < m.ne; e++) {
		double x[24], v[24], f[24], d[6], w[3];
		dem_hex8_1pt_t g;
		gather(&m, e, m.X, x);
		gather(&m, e, u, v);
		assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
		dem_hex8_1pt_rate(&g, v);
		dem_hex8_strain_rate(g.L, d, w);
		for (int i = 0; i < 6; i++)
			assert_true(fabs(d[i] - eps_x[i]) < 1e-10 * vmax(eps_x, 6));
		/* small strain: the rate over dt = 1 is the strain */
		double sig[6] = { 0 }, ep = 0, wp;
		dem_mat_update(&mat, d, 1, sig, &ep, NULL, &wp);
		for (int i = 0; i < 6; i++)
			assert_true(fabs(sig[i] - sig_x[i]) < 1e-10 * vmax(sig_x, 6));
		assert_true(vmax(g.q, 12) < 1e-14);
		double ks, cv, Qs[12] = { 0 }, Q[12];
		dem_hex8_hg_coef(&g, &mat, 0.1, 0.1, &ks, &cv);
		assert_true(ks > 0 && cv > 0);
		double power = dem_hex8_hg_resist(&g, ks, cv, 1, Qs, Q);
		assert_true(fabs(power) < 1e-20 * ks);
		dem_hex8_1pt_force(&g, sig, Q, f);
		/* hourglass forces alone vanish */
		double fh[24], zero[6] = { 0 };
		dem_hex8_1pt_force(&g, zero, Q, fh);
		assert_true(vmax(fh, 24) < 1e-12 * vmax(f, 24));
		for (int I = 0; I < 8; I++)
			for (int i = 0; i < 3; i++)
				F[3 * m.conn[e][I] + i] += f[8 * i + I];
		fscale = fmax(fscale, vmax(f, 24));
	}
	int c = node_id(&m, 1, 1, 1);
	for (int i = 0; i < 3; i++)
		assert_true(fabs(F[3 * c + i]) < 1e-12 * fscale);
	free(u);
	free(F);
	mesh_free(&m);
	dem_mat_free(&mat);
}

/* Patch test, full 2x2x2 integration (plain and mean-dilatation): the
 * velocity gradient at every Gauss point is the imposed one, the stress is
 * exact, the interior node's forces cancel. */
static void test_patch_full(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	mesh_t m;
	patch_mesh(&m);
	double *u = malloc(3 * sizeof(double) * (size_t)m.nn);
	double *F = malloc(3 * sizeof(double) * (size_t)m.nn);
	assert_non_null(u);
	assert_non_null(F);
	linear_field(&m, u);
	double eps_x[6], sig_x[6];
	exact_state(&mat, eps_x, sig_x);
	for (int bbar = 0; bbar <= 1; bbar++) {
		memset(F, 0, 3 * sizeof(double) * (size_t)m.nn);
		double fscale = 0;
		for (int e = 0; e < m.ne; e++) {
			double x[24], v[24], f[24], sig[48] = { 0 };
			dem_hex8_full_t g;
			gather(&m, e, m.X, x);
			gather(&m, e, u, v);
			assert_int_equal(dem_hex8_full_geom(x, &g), DEM_HEX8_OK);
			dem_hex8_full_rate(&g, v, bbar);
			for (int p = 0; p < 8; p++) {
				for (int k = 0; k < 9; k++)
					assert_true(fabs(g.L[p][k] - LA[k]) < 1e-10 * vmax(LA, 9));
				double d[6], w[3], ep = 0, wp;
				dem_hex8_strain_rate(g.L[p], d, w);
				dem_mat_update(&mat, d, 1, sig + 6 * p, &ep, NULL, &wp);
				for (int i = 0; i < 6; i++)
					assert_true(fabs(sig[6 * p + i] - sig_x[i]) < 1e-10 * vmax(sig_x, 6));
			}
			dem_hex8_full_force(&g, sig, bbar, f);
			for (int I = 0; I < 8; I++)
				for (int i = 0; i < 3; i++)
					F[3 * m.conn[e][I] + i] += f[8 * i + I];
			fscale = fmax(fscale, vmax(f, 24));
		}
		int c = node_id(&m, 1, 1, 1);
		for (int i = 0; i < 3; i++)
			assert_true(fabs(F[3 * c + i]) < 1e-12 * fscale);
	}
	free(u);
	free(F);
	mesh_free(&m);
	dem_mat_free(&mat);
}

/* Patch test of the implicit element, each rule: with the boundary nodes
 * of the distorted patch displaced by the linear field and the interior
 * node solved for, the interior node takes the linear field's value and
 * every Gauss point the exact stress (to 1e-10); the incompatible modes
 * stay at zero. */
static void test_patch_static(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	mesh_t m;
	patch_mesh(&m);
	double *u = malloc(3 * sizeof(double) * (size_t)m.nn);
	assert_non_null(u);
	double eps_x[6], sig_x[6];
	exact_state(&mat, eps_x, sig_x);
	int c = node_id(&m, 1, 1, 1);
	for (int rule = DEM_HEX8_FULL; rule <= DEM_HEX8_EAS; rule++) {
		linear_field(&m, u);
		double uc[3] = { u[3 * c], u[3 * c + 1], u[3 * c + 2] };
		u[3 * c] = u[3 * c + 1] = u[3 * c + 2] = 0;
		/* residual at the interior node and its 3x3 stiffness block */
		double r[3] = { 0 }, Kc[9] = { 0 };
		for (int e = 0; e < m.ne; e++) {
			double x[24], du[24], f[24], K[576];
			dem_hex8_hist_t hn = HZERO, h = HZERO;
			gather(&m, e, m.X, x);
			gather(&m, e, u, du);
			assert_int_equal(dem_hex8_static(&mat, rule, x, du, &hn, &h, f, K, NULL), DEM_HEX8_OK);
			for (int I = 0; I < 8; I++) {
				if (m.conn[e][I] != c)
					continue;
				for (int i = 0; i < 3; i++) {
					r[i] += f[8 * i + I];
					for (int j = 0; j < 3; j++)
						Kc[3 * i + j] += K[(8 * i + I) * 24 + 8 * j + I];
				}
			}
		}
		gsl_matrix_view A = gsl_matrix_view_array(Kc, 3, 3);
		gsl_vector_view b = gsl_vector_view_array(r, 3);
		double xs[3];
		gsl_vector_view xv = gsl_vector_view_array(xs, 3);
		gsl_permutation *perm = gsl_permutation_alloc(3);
		int sgn;
		gsl_linalg_LU_decomp(&A.matrix, perm, &sgn);
		gsl_linalg_LU_solve(&A.matrix, perm, &b.vector, &xv.vector);
		gsl_permutation_free(perm);
		for (int i = 0; i < 3; i++)
			assert_true(fabs(-xs[i] - uc[i]) < 1e-10 * vmax(uc, 3));
		/* the full linear field: exact stresses, no modes */
		linear_field(&m, u);
		for (int e = 0; e < m.ne; e++) {
			double x[24], du[24], f[24];
			dem_hex8_hist_t hn = HZERO, h = HZERO;
			gather(&m, e, m.X, x);
			gather(&m, e, u, du);
			assert_int_equal(dem_hex8_static(&mat, rule, x, du, &hn, &h, f, NULL, NULL), DEM_HEX8_OK);
			for (int p = 0; p < 8; p++)
				for (int i = 0; i < 6; i++)
					assert_true(fabs(h.sig[6 * p + i] - sig_x[i]) < 1e-10 * vmax(sig_x, 6));
			assert_true(vmax(h.alpha, 9) < 1e-12 * vmax(LA, 9));
		}
	}
	free(u);
	mesh_free(&m);
	dem_mat_free(&mat);
}

/* Rigid-body motion: a translation plus a rotation rate (v = v0 + w x x)
 * gives zero strain rate, zero hourglass velocities and zero forces, one
 * point and full; an infinitesimal rotation gives zero static forces. */
static void test_rigid_body(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	mesh_t m;
	patch_mesh(&m);
	static const double v0[3] = { 3, -1, 2 }, om[3] = { 0.7, -1.3, 0.4 };
	for (int e = 0; e < m.ne; e++) {
		double x[24], v[24];
		gather(&m, e, m.X, x);
		for (int I = 0; I < 8; I++) {
			double p[3] = { x[I], x[8 + I], x[16 + I] };
			v[I] = v0[0] + om[1] * p[2] - om[2] * p[1];
			v[8 + I] = v0[1] + om[2] * p[0] - om[0] * p[2];
			v[16 + I] = v0[2] + om[0] * p[1] - om[1] * p[0];
		}
		dem_hex8_1pt_t g;
		assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
		dem_hex8_1pt_rate(&g, v);
		double d[6], w[3];
		dem_hex8_strain_rate(g.L, d, w);
		assert_true(vmax(d, 6) < 1e-13);
		assert_true(fabs(w[0] + om[2]) < 1e-13 && fabs(w[1] + om[0]) < 1e-13 &&
			    fabs(w[2] + om[1]) < 1e-13);
		assert_true(vmax(g.q, 12) < 1e-13);
		double sig[6] = { 0 }, ep = 0, wp, f[24];
		dem_mat_update(&mat, d, 1e-3, sig, &ep, NULL, &wp);
		double ks, cv, Qs[12] = { 0 }, Q[12];
		dem_hex8_hg_coef(&g, &mat, 0.1, 0.1, &ks, &cv);
		dem_hex8_hg_resist(&g, ks, cv, 1e-3, Qs, Q);
		dem_hex8_1pt_force(&g, sig, Q, f);
		assert_true(vmax(f, 24) < 1e-13 * mat.E * g.vol);

		dem_hex8_full_t gf;
		assert_int_equal(dem_hex8_full_geom(x, &gf), DEM_HEX8_OK);
		dem_hex8_full_rate(&gf, v, 0);
		for (int p = 0; p < 8; p++) {
			dem_hex8_strain_rate(gf.L[p], d, w);
			assert_true(vmax(d, 6) < 1e-13);
		}
		for (int rule = DEM_HEX8_FULL; rule <= DEM_HEX8_EAS; rule++) {
			double du[24];
			for (int i = 0; i < 24; i++)
				du[i] = 1e-4 * v[i];
			dem_hex8_hist_t hn = HZERO, h = HZERO;
			assert_int_equal(dem_hex8_static(&mat, rule, x, du, &hn, &h, f, NULL, NULL), DEM_HEX8_OK);
			assert_true(vmax(f, 24) < 1e-13 * mat.E * g.vol * 1e-4);
		}
	}
	mesh_free(&m);
	dem_mat_free(&mat);
}

/* Rank of the element stiffness matrices of a distorted element (its
 * eigenvalues): one-point integration alone leaves 18 zero-energy modes,
 * the 6 rigid modes and the 12 hourglass modes (4 gamma vectors x 3
 * directions); the hourglass stiffness of Flanagan & Belytschko takes away
 * exactly the 12; full integration, B-bar and the incompatible-mode element
 * have the 6 rigid modes only.  Also: the one-point stiffness is the
 * derivative of the explicit kernel's forces (f = K u for a small-strain
 * step), and the element stiffness of dem_hex8_static is symmetric. */
static void test_stiffness_rank(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	double x[24];
	unsigned long s = 7;
	for (int I = 0; I < 8; I++) {
		x[I] = dem_hex8_node_xi[I] + 0.2 * urand(&s);
		x[8 + I] = 0.8 * dem_hex8_node_eta[I] + 0.2 * urand(&s);
		x[16 + I] = 0.6 * dem_hex8_node_zeta[I] + 0.1 * urand(&s);
	}
	double D[36], K[576];
	dem_mat_elastic_stiffness(&mat, D);
	dem_hex8_1pt_t g;
	assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
	assert_int_equal(dem_hex8_1pt_stiffness(x, D, 0, K), DEM_HEX8_OK);
	assert_int_equal(zero_modes(K, 24, 1e-10), 18);
	/* its zero-energy hourglass modes: n_alpha = h_alpha - (B_j . h_alpha)
	 * x_j in each direction (the h vectors with their linear part taken
	 * out, so that B n = 0; the dual of FB's gamma vectors) */
	double B[24], nmode[4][8];
	dem_hex8_1pt_grad(&g, B);
	for (int al = 0; al < 4; al++) {
		double h[8], c[3] = { 0, 0, 0 };
		for (int I = 0; I < 8; I++) {
			double xi = dem_hex8_node_xi[I], eta = dem_hex8_node_eta[I], zeta = dem_hex8_node_zeta[I];
			double hv[4] = { eta * zeta, zeta * xi, xi * eta, xi * eta * zeta };
			h[I] = hv[al];
			for (int j = 0; j < 3; j++)
				c[j] += B[8 * j + I] * h[I];
		}
		for (int I = 0; I < 8; I++)
			nmode[al][I] = h[I] - c[0] * x[I] - c[1] * x[8 + I] - c[2] * x[16 + I];
		for (int i = 0; i < 3; i++)
			for (int r = 0; r < 24; r++) {
				double t = 0;
				for (int I = 0; I < 8; I++)
					t += K[r * 24 + 8 * i + I] * nmode[al][I];
				assert_true(fabs(t) < 1e-12 * mat.E);
			}
	}
	double ks, cv;
	dem_hex8_hg_coef(&g, &mat, 0.1, 0, &ks, &cv);
	assert_int_equal(dem_hex8_1pt_stiffness(x, D, ks, K), DEM_HEX8_OK);
	assert_int_equal(zero_modes(K, 24, 1e-10), 6);
	/* which the hourglass stiffness now resists */
	for (int al = 0; al < 4; al++) {
		double e = 0;
		for (int I = 0; I < 8; I++)
			for (int J = 0; J < 8; J++)
				e += nmode[al][I] * K[I * 24 + J] * nmode[al][J];
		assert_true(e > 1e-3 * ks);
	}

	/* f = K u: one explicit small-strain step (dt = 1, v = u) */
	double u[24], f[24], Ku[24];
	for (int i = 0; i < 24; i++)
		u[i] = 1e-4 * urand(&s);
	dem_hex8_1pt_rate(&g, u);
	double d[6], w[3], sig[6] = { 0 }, ep = 0, wp, Qs[12] = { 0 }, Q[12];
	dem_hex8_strain_rate(g.L, d, w);
	dem_mat_update(&mat, d, 1, sig, &ep, NULL, &wp);
	dem_hex8_hg_resist(&g, ks, 0, 1, Qs, Q);
	dem_hex8_1pt_force(&g, sig, Q, f);
	for (int r = 0; r < 24; r++) {
		Ku[r] = 0;
		for (int c = 0; c < 24; c++)
			Ku[r] += K[24 * r + c] * u[c];
	}
	for (int r = 0; r < 24; r++)
		assert_true(fabs(f[r] - Ku[r]) < 1e-12 * vmax(Ku, 24));

	for (int rule = DEM_HEX8_FULL; rule <= DEM_HEX8_EAS; rule++) {
		double du[24] = { 0 }, fi[24];
		dem_hex8_hist_t hn = HZERO, h = HZERO;
		assert_int_equal(dem_hex8_static(&mat, rule, x, du, &hn, &h, fi, K, NULL), DEM_HEX8_OK);
		for (int r = 0; r < 24; r++)
			for (int c = 0; c < r; c++)
				assert_true(fabs(K[24 * r + c] - K[24 * c + r]) < 1e-12 * mat.E);
		assert_int_equal(zero_modes(K, 24, 1e-10), 6);
	}
	dem_mat_free(&mat);
}

/* The explicit full-integration kernel (modal form) and the implicit
 * element (explicit B matrices) give the same nodal forces for the same
 * small-strain state, plain and B-bar: two independent codings of the
 * same integral. */
static void test_full_vs_static(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	double x[24], u[24];
	unsigned long s = 3;
	for (int I = 0; I < 8; I++) {
		x[I] = dem_hex8_node_xi[I] + 0.25 * urand(&s);
		x[8 + I] = dem_hex8_node_eta[I] + 0.25 * urand(&s);
		x[16 + I] = 0.5 * dem_hex8_node_zeta[I] + 0.1 * urand(&s);
	}
	for (int i = 0; i < 24; i++)
		u[i] = 1e-4 * urand(&s);
	for (int bbar = 0; bbar <= 1; bbar++) {
		dem_hex8_full_t g;
		assert_int_equal(dem_hex8_full_geom(x, &g), DEM_HEX8_OK);
		dem_hex8_full_rate(&g, u, bbar);
		double sig[48] = { 0 }, f[24], fs[24];
		for (int p = 0; p < 8; p++) {
			double d[6], w[3], ep = 0, wp;
			dem_hex8_strain_rate(g.L[p], d, w);
			dem_mat_update(&mat, d, 1, sig + 6 * p, &ep, NULL, &wp);
		}
		dem_hex8_full_force(&g, sig, bbar, f);
		dem_hex8_hist_t hn = HZERO, h = HZERO;
		assert_int_equal(dem_hex8_static(&mat, bbar ? DEM_HEX8_BBAR : DEM_HEX8_FULL, x, u, &hn, &h,
						 fs, NULL, NULL), DEM_HEX8_OK);
		for (int i = 0; i < 24; i++)
			assert_true(fabs(f[i] - fs[i]) < 1e-12 * vmax(fs, 24));
		for (int i = 0; i < 48; i++)
			assert_true(fabs(sig[i] - h.sig[i]) < 1e-12 * vmax(h.sig, 48));
	}
	dem_mat_free(&mat);
}

/* The implicit element's tangent is the derivative of its internal force:
 * a central finite difference of fint agrees to 1e-6 for every rule, in an
 * elastic state and in a plastic one (J2 with the Table 7.1-like linear
 * hardening, prestressed), with the incompatible modes condensed. */
static void test_static_tangent_fd(void **state)
{
	(void)state;
	dem_mat_t mat;
	dem_mat_param_t p = { .E = 72 * GPA, .nu = 0.33, .rho = 2800, .sy0 = 450e6, .H = 2 * GPA };
	dem_error_t err = { 0 };
	assert_int_equal(dem_mat_init(&mat, &p, &err), DEM_OK);
	double x[24];
	unsigned long s = 11;
	for (int I = 0; I < 8; I++) {
		x[I] = 2.5e-3 * dem_hex8_node_xi[I] + 2e-4 * urand(&s);
		x[8 + I] = 2.5e-3 * dem_hex8_node_eta[I] + 2e-4 * urand(&s);
		x[16 + I] = 2.5e-4 * dem_hex8_node_zeta[I] + 2e-5 * urand(&s);
	}
	for (int plastic = 0; plastic <= 1; plastic++) {
		double du[24];
		for (int i = 0; i < 24; i++)
			du[i] = (plastic ? 2e-5 : 1e-7) * urand(&s);
		/* bending-like part so the modes are active */
		for (int I = 0; I < 8; I++)
			du[I] += (plastic ? 3e-5 : 1e-7) * dem_hex8_node_zeta[I] * dem_hex8_node_xi[I];
		for (int rule = DEM_HEX8_FULL; rule <= DEM_HEX8_EAS; rule++) {
			dem_hex8_hist_t hn = HZERO, h;
			for (int q = 0; q < 8; q++) {
				hn.sig[6 * q] = 200e6;   /* an initial (residual) stress */
				hn.sig[6 * q + 1] = 200e6;
			}
			memcpy(&h, &hn, sizeof h);
			double f[24], K[576], wp;
			assert_int_equal(dem_hex8_static(&mat, rule, x, du, &hn, &h, f, K, &wp), DEM_HEX8_OK);
			double epmax = vmax(h.ep, 8);
			assert_true(plastic ? epmax > 0 : epmax == 0);
			double err2 = 0, big = vmax(K, 576);
			for (int j = 0; j < 24; j++) {
				double dp[24], dm[24], fp[24], fm[24];
				double hstep = 1e-6 * vmax(du, 24);
				memcpy(dp, du, sizeof dp);
				memcpy(dm, du, sizeof dm);
				dp[j] += hstep;
				dm[j] -= hstep;
				dem_hex8_hist_t h1, h2;
				memcpy(&h1, &h, sizeof h1);
				memcpy(&h2, &h, sizeof h2);
				assert_int_equal(dem_hex8_static(&mat, rule, x, dp, &hn, &h1, fp, NULL, NULL), 0);
				assert_int_equal(dem_hex8_static(&mat, rule, x, dm, &hn, &h2, fm, NULL, NULL), 0);
				for (int i = 0; i < 24; i++)
					err2 = fmax(err2, fabs((fp[i] - fm[i]) / (2 * hstep) - K[24 * i + j]));
			}
			printf("# element rule %d, %s: tangent vs finite difference %.1e\n", rule,
			       plastic ? "plastic" : "elastic", err2 / big);
			assert_true(err2 < 1e-6 * big);
		}
	}
	dem_mat_free(&mat);
}

/* Pure bending of a thin beam (x along the length L, y the width w, z the
 * thickness t), clamped in x at x = 0 with the section free to distort,
 * loaded at x = L by the linear traction sigma_xx = M z / I: beam theory
 * gives the uniform curvature kappa = M / (E I), I = w t^3 / 12, and a
 * deflection kappa L^2 / 2 of the mid-surface edge.  The mesh is that of
 * Ch. 8.6: 5 x 5 mm in plane, thin layers (0.5 mm and 0.05 mm: aspect
 * ratios 10 and 100).  The incompatible-mode element must be within 3 %
 * (it is exact for rectangles); the plain full-integration hexahedron
 * locks in shear and gives a fraction of the deflection. */
static double bend_ratio(int rule, double t, int nz)
{
	dem_mat_t mat;
	make_elastic(&mat);
	const double L = 50e-3, w = 5e-3, M = 1e-2 * t * t / 1e-6;  /* N m */
	int nx = 10, ny = 1;
	const double lo[3] = { 0, -w / 2, -t / 2 }, len[3] = { L, w, t };
	mesh_t m;
	mesh_box(&m, nx, ny, nz, lo, len);
	int nd = 3 * m.nn;
	double *K = calloc((size_t)nd * (size_t)nd, sizeof(double));
	double *r = calloc((size_t)nd, sizeof(double));
	assert_non_null(K);
	assert_non_null(r);
	for (int e = 0; e < m.ne; e++) {
		double x[24], du[24] = { 0 }, f[24], Ke[576];
		dem_hex8_hist_t hn = HZERO, h = HZERO;
		gather(&m, e, m.X, x);
		assert_int_equal(dem_hex8_static(&mat, (dem_hex8_rule_t)rule, x, du, &hn, &h, f, Ke, NULL),
				 DEM_HEX8_OK);
		for (int i = 0; i < 3; i++)
			for (int I = 0; I < 8; I++)
				for (int j = 0; j < 3; j++)
					for (int J = 0; J < 8; J++)
						K[(size_t)(3 * m.conn[e][I] + i) * (size_t)nd + 3 * m.conn[e][J] + j] +=
							Ke[(8 * i + I) * 24 + 8 * j + J];
	}
	/* end traction sigma_xx = M z / I: consistent nodal forces of a
	 * linear traction on each layer, half the width to each y node */
	double Iz = w * t * t * t / 12;
	for (int k = 0; k < nz; k++) {
		double z0 = -t / 2 + t * k / nz, z1 = -t / 2 + t * (k + 1) / nz, hz = z1 - z0;
		double t0 = M * z0 / Iz, t1 = M * z1 / Iz;
		for (int j = 0; j <= ny; j++) {
			r[3 * node_id(&m, nx, j, k)] += w / 2 * hz * (2 * t0 + t1) / 6;
			r[3 * node_id(&m, nx, j, k + 1)] += w / 2 * hz * (t0 + 2 * t1) / 6;
		}
	}
	/* constraints: u_x = 0 on x = 0; u_y = u_z = 0 on x = 0, z = 0 */
	for (int k = 0; k <= nz; k++)
		for (int j = 0; j <= ny; j++) {
			int n = node_id(&m, 0, j, k);
			int fix[3] = { 1, 2 * k == nz, 2 * k == nz };
			for (int i = 0; i < 3; i++) {
				if (!fix[i])
					continue;
				int d = 3 * n + i;
				for (int c = 0; c < nd; c++)
					K[(size_t)d * (size_t)nd + c] = K[(size_t)c * (size_t)nd + d] = 0;
				K[(size_t)d * (size_t)nd + d] = mat.E * t;
				r[d] = 0;
			}
		}
	gsl_matrix_view A = gsl_matrix_view_array(K, (size_t)nd, (size_t)nd);
	gsl_vector_view b = gsl_vector_view_array(r, (size_t)nd);
	assert_int_equal(gsl_linalg_cholesky_decomp1(&A.matrix), 0);
	assert_int_equal(gsl_linalg_cholesky_svx(&A.matrix, &b.vector), 0);
	double kappa = M / (mat.E * Iz);
	double defl = -0.5 * (r[3 * node_id(&m, nx, 0, nz / 2) + 2] + r[3 * node_id(&m, nx, ny, nz / 2) + 2]);
	free(K);
	free(r);
	mesh_free(&m);
	dem_mat_free(&mat);
	return defl / (kappa * L * L / 2);
}

static void test_bending(void **state)
{
	(void)state;
	static const struct { double t; int nz; } cases[] = {
		{ 1e-3, 2 },    /* layers 0.5 mm: aspect 10 */
		{ 0.2e-3, 4 },  /* layers 0.05 mm: aspect 100 */
		{ 4e-3, 8 },    /* the Ch. 8.6 strip thickness, 0.5 mm layers */
	};
	for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
		double eas = bend_ratio(DEM_HEX8_EAS, cases[c].t, cases[c].nz);
		double full = bend_ratio(DEM_HEX8_FULL, cases[c].t, cases[c].nz);
		double bbar = bend_ratio(DEM_HEX8_BBAR, cases[c].t, cases[c].nz);
		printf("# bending t=%g mm nz=%d: deflection / beam theory: EAS %.6f, full %.4f, B-bar %.4f\n",
		       cases[c].t * 1e3, cases[c].nz, eas, full, bbar);
		assert_true(fabs(eas - 1) < 0.03);
		assert_true(fabs(eas - 1) < 1e-5);   /* in fact exact for rectangles, to round-off */
		/* the plain element locks (shear locking: worse the thinner the
		 * layer against the 5 mm in-plane size), and B-bar, a cure for
		 * volumetric locking only, does no better */
		double lock = cases[c].t < 2e-3 ? 0.2 : 0.8;
		assert_true(full < lock);
		assert_true(bbar < lock);
	}
}

/* A free plate with an equi-biaxial initial stress s(z) (z from the
 * mid-plane), the implicit stage's problem of Ch. 8.5 (Eqs. 8.1-8.5) in its
 * linear elastic form: one Newton step from the initial stress.  Closed
 * form (DESIGN.md, verification references): the plate takes the uniform
 * curvature kappa = -12 (1 - nu) int s z dz / (E h^3) in both directions,
 * the membrane strain eps_m = -(1 - nu) int s dz / (E h), and the stress
 * s(z) + E / (1 - nu) (eps_m + kappa z).  With s(z) = a + b z + c z^2,
 * int s z dz = b h^3 / 12 and int s dz = a h + c h^3 / 12.  Mesh: 5 x 5 mm
 * in plane as Ch. 8.6, 4 layers through 1 mm; minimal constraints.  The
 * curvature is fitted to the mid-plane deflection along the centre lines;
 * the incompatible-mode element must give it within 1 % (it is within
 * 0.1 %); the equilibrium after the step is checked too. */
static double plate_s(double z, double h)
{
	double t = 2 * z / h;
	return (-50 - 150 * t + 100 * t * t) * 1e6;
}

static void test_plate_initial_stress(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	const double lx = 40e-3, ly = 20e-3, h = 1e-3;
	const int nx = 8, ny = 4, nz = 4;
	const double lo[3] = { -lx / 2, -ly / 2, -h / 2 }, len[3] = { lx, ly, h };
	mesh_t m;
	mesh_box(&m, nx, ny, nz, lo, len);
	int nd = 3 * m.nn;
	double *K = calloc((size_t)nd * (size_t)nd, sizeof(double));
	double *r = calloc((size_t)nd, sizeof(double));
	double *u = calloc((size_t)nd, sizeof(double));
	dem_hex8_hist_t *hn = malloc(sizeof *hn * (size_t)m.ne), *hh = malloc(sizeof *hh * (size_t)m.ne);
	assert_true(K && r && u && hn && hh);
	for (int e = 0; e < m.ne; e++) {
		double x[24], xg[24], du[24] = { 0 }, f[24], Ke[576];
		gather(&m, e, m.X, x);
		dem_hex8_gauss_points(x, xg);
		hn[e] = HZERO;
		for (int p = 0; p < 8; p++)
			hn[e].sig[6 * p] = hn[e].sig[6 * p + 1] = plate_s(xg[16 + p], h);
		hh[e] = hn[e];
		assert_int_equal(dem_hex8_static(&mat, DEM_HEX8_EAS, x, du, &hn[e], &hh[e], f, Ke, NULL),
				 DEM_HEX8_OK);
		for (int i = 0; i < 3; i++)
			for (int I = 0; I < 8; I++) {
				int a = 3 * m.conn[e][I] + i;
				r[a] -= f[8 * i + I];
				for (int j = 0; j < 3; j++)
					for (int J = 0; J < 8; J++)
						K[(size_t)a * (size_t)nd + 3 * m.conn[e][J] + j] +=
							Ke[(8 * i + I) * 24 + 8 * j + J];
			}
	}
	double rload = vmax(r, nd);
	/* minimal constraints on the mid-plane: the centre node fixed, the
	 * next node along x held in y and z, the next along y held in z */
	int A = node_id(&m, nx / 2, ny / 2, nz / 2), B = node_id(&m, nx / 2 + 1, ny / 2, nz / 2),
	    C = node_id(&m, nx / 2, ny / 2 + 1, nz / 2);
	int fixed[6] = { 3 * A, 3 * A + 1, 3 * A + 2, 3 * B + 1, 3 * B + 2, 3 * C + 2 };
	for (int k = 0; k < 6; k++) {
		int d = fixed[k];
		for (int c = 0; c < nd; c++)
			K[(size_t)d * (size_t)nd + c] = K[(size_t)c * (size_t)nd + d] = 0;
		K[(size_t)d * (size_t)nd + d] = mat.E * h;
		r[d] = 0;
	}
	gsl_matrix_view Am = gsl_matrix_view_array(K, (size_t)nd, (size_t)nd);
	gsl_vector_view b = gsl_vector_view_array(r, (size_t)nd);
	assert_int_equal(gsl_linalg_cholesky_decomp1(&Am.matrix), 0);
	assert_int_equal(gsl_linalg_cholesky_svx(&Am.matrix, &b.vector), 0);
	memcpy(u, r, sizeof(double) * (size_t)nd);

	/* least-squares quadratic w = c0 + c1 s + c2 s^2 along each centre line */
	double kap[2];
	for (int dir = 0; dir < 2; dir++) {
		int n = dir ? ny + 1 : nx + 1;
		gsl_matrix *V = gsl_matrix_alloc((size_t)n, 3);
		gsl_vector *wv = gsl_vector_alloc((size_t)n), *cf = gsl_vector_alloc(3), *res = gsl_vector_alloc((size_t)n);
		gsl_vector *tau = gsl_vector_alloc(3);
		for (int k = 0; k < n; k++) {
			int id = dir ? node_id(&m, nx / 2, k, nz / 2) : node_id(&m, k, ny / 2, nz / 2);
			double sc = m.X[3 * id + dir];
			gsl_matrix_set(V, (size_t)k, 0, 1);
			gsl_matrix_set(V, (size_t)k, 1, sc);
			gsl_matrix_set(V, (size_t)k, 2, sc * sc);
			gsl_vector_set(wv, (size_t)k, u[3 * id + 2]);
		}
		gsl_linalg_QR_decomp(V, tau);
		gsl_linalg_QR_lssolve(V, tau, wv, cf, res);
		kap[dir] = -2 * gsl_vector_get(cf, 2);
		gsl_matrix_free(V);
		gsl_vector_free(wv);
		gsl_vector_free(cf);
		gsl_vector_free(res);
		gsl_vector_free(tau);
	}
	double sa = -50e6, sb = -150e6 * 2 / h, sq = 100e6 * 4 / (h * h);
	double kappa = -12 * (1 - mat.nu) * (sb * h * h * h / 12) / (mat.E * h * h * h);
	double epsm = -(1 - mat.nu) * (sa * h + sq * h * h * h / 12) / (mat.E * h);
	printf("# plate: kappa_x / closed form %.6f, kappa_y / closed form %.6f\n", kap[0] / kappa,
	       kap[1] / kappa);
	assert_true(rel(kap[0], kappa) < 0.01);
	assert_true(rel(kap[1], kappa) < 0.01);

	/* equilibrium after the step, and the redistributed stress at the
	 * plate centre against the closed form */
	double *rr = calloc((size_t)nd, sizeof(double));
	assert_non_null(rr);
	double smax = 0;
	for (int e = 0; e < m.ne; e++) {
		double x[24], du[24], f[24], xg[24];
		gather(&m, e, m.X, x);
		gather(&m, e, u, du);
		assert_int_equal(dem_hex8_static(&mat, DEM_HEX8_EAS, x, du, &hn[e], &hh[e], f, NULL, NULL),
				 DEM_HEX8_OK);
		for (int i = 0; i < 3; i++)
			for (int I = 0; I < 8; I++)
				rr[3 * m.conn[e][I] + i] += f[8 * i + I];
		dem_hex8_gauss_points(x, xg);
		int centre = fabs(xg[0] + xg[1]) < 6e-3 && fabs(xg[8] + xg[10]) < 6e-3;  /* near x = y = 0 */
		for (int p = 0; p < 8 && centre; p++) {
			double z = xg[16 + p];
			double want = plate_s(z, h) + mat.E / (1 - mat.nu) * (epsm + kappa * z);
			smax = fmax(smax, fabs(hh[e].sig[6 * p] - want) / 300e6);
		}
	}
	for (int k = 0; k < 6; k++)
		rr[fixed[k]] = 0;
	assert_true(vmax(rr, nd) < 1e-9 * rload);
	printf("# plate: redistributed stress near the centre within %.2e of the peak initial stress\n", smax);
	assert_true(smax > 0 && smax < 0.01);
	free(rr);
	free(K);
	free(r);
	free(u);
	free(hn);
	free(hh);
	mesh_free(&m);
	dem_mat_free(&mat);
}

/* Inverted and degenerate elements are reported by a return code, never
 * by NaN: an element turned inside out, one collapsed flat, one with a NaN
 * coordinate, and one whose corner is pushed past the centre (positive at
 * the centre, negative at a Gauss point: only the full rule sees it). */
static void test_inverted(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	double cube[24];
	for (int I = 0; I < 8; I++) {
		cube[I] = 0.5 * (1 + dem_hex8_node_xi[I]);
		cube[8 + I] = 0.5 * (1 + dem_hex8_node_eta[I]);
		cube[16 + I] = 0.5 * (1 + dem_hex8_node_zeta[I]);
	}
	double bad[4][24];
	for (int c = 0; c < 4; c++)
		memcpy(bad[c], cube, sizeof cube);
	for (int I = 0; I < 8; I++) {
		bad[0][16 + I] = 1 - cube[16 + I];  /* top and bottom swapped */
		bad[1][16 + I] = 0;                 /* flat */
	}
	bad[2][8 + 3] = NAN;
	bad[3][6] = bad[3][8 + 6] = bad[3][16 + 6] = 0.2;   /* corner 6 pushed through */
	for (int c = 0; c < 4; c++) {
		dem_hex8_1pt_t g;
		dem_hex8_full_t gf;
		double dt = 1, ms[8], f[24], K[576], du[24] = { 0 };
		dem_hex8_hist_t hn = HZERO, h = HZERO;
		int r1 = dem_hex8_1pt_geom(bad[c], &g);
		if (c < 3) {
			assert_int_equal(r1, DEM_HEX8_INVERTED);
			assert_int_equal(dem_hex8_dt_crit(bad[c], mat.wave, &dt), DEM_HEX8_INVERTED);
			assert_true(dt == 0);
		}
		assert_int_equal(dem_hex8_full_geom(bad[c], &gf), DEM_HEX8_INVERTED);
		assert_int_equal(dem_hex8_lumped_mass(bad[c], mat.rho, ms), DEM_HEX8_INVERTED);
		for (int I = 0; I < 8; I++)
			assert_true(ms[I] == 0);
		for (int rule = DEM_HEX8_FULL; rule <= DEM_HEX8_EAS; rule++)
			assert_int_equal(dem_hex8_static(&mat, rule, bad[c], du, &hn, &h, f, K, NULL),
					 DEM_HEX8_INVERTED);
	}
	/* the good cube passes everything */
	dem_hex8_full_t gf;
	assert_int_equal(dem_hex8_full_geom(cube, &gf), DEM_HEX8_OK);
	dem_mat_free(&mat);
}

/* Critical time step: a cube of side h has the characteristic length
 * V / A_max = h, so dt = h sqrt(rho / (K + 4G/3)); a 1 x 2 x 3 box has
 * V / A_max = 6 / 6 = 1, its shortest side.  Lumped masses: rho V / 8 each
 * for a box, and rho V in total for a distorted element. */
static void test_dt_and_mass(void **state)
{
	(void)state;
	dem_mat_t mat;
	make_elastic(&mat);
	double h = 0.05e-3, x[24];
	for (int I = 0; I < 8; I++) {
		x[I] = h * 0.5 * (1 + dem_hex8_node_xi[I]);
		x[8 + I] = h * 0.5 * (1 + dem_hex8_node_eta[I]);
		x[16 + I] = h * 0.5 * (1 + dem_hex8_node_zeta[I]);
	}
	double dt;
	assert_int_equal(dem_hex8_dt_crit(x, mat.wave, &dt), DEM_HEX8_OK);
	assert_true(rel(dt, h * sqrt(mat.rho / (mat.K + 4 * mat.G / 3))) < 1e-14);
	double ms[8];
	assert_int_equal(dem_hex8_lumped_mass(x, mat.rho, ms), DEM_HEX8_OK);
	for (int I = 0; I < 8; I++)
		assert_true(rel(ms[I], mat.rho * h * h * h / 8) < 1e-14);
	for (int I = 0; I < 8; I++) {
		x[I] = 0.5 * (1 + dem_hex8_node_xi[I]);
		x[8 + I] = 1 + dem_hex8_node_eta[I];
		x[16 + I] = 1.5 * (1 + dem_hex8_node_zeta[I]);
	}
	assert_int_equal(dem_hex8_dt_crit(x, 1, &dt), DEM_HEX8_OK);
	assert_true(rel(dt, 1) < 1e-14);
	unsigned long s = 5;
	for (int i = 0; i < 24; i++)
		x[i] += 0.1 * urand(&s);
	dem_hex8_1pt_t g;
	assert_int_equal(dem_hex8_1pt_geom(x, &g), DEM_HEX8_OK);
	assert_int_equal(dem_hex8_lumped_mass(x, 2, ms), DEM_HEX8_OK);
	double tot = 0;
	for (int I = 0; I < 8; I++)
		tot += ms[I];
	assert_true(rel(tot, 2 * g.vol) < 1e-14);
	/* Gauss points of the box lie at the centre -+ half side / sqrt 3 */
	double xg[24];
	for (int I = 0; I < 8; I++) {
		x[I] = 0.5 * (1 + dem_hex8_node_xi[I]);
		x[8 + I] = 1 + dem_hex8_node_eta[I];
		x[16 + I] = 1.5 * (1 + dem_hex8_node_zeta[I]);
	}
	dem_hex8_gauss_points(x, xg);
	for (int p = 0; p < 8; p++)
		assert_true(fabs(xg[16 + p] - (1.5 + 1.5 * dem_hex8_node_zeta[p] / sqrt(3))) < 1e-15);
	dem_mat_free(&mat);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_uniform_gradient),
		cmocka_unit_test(test_hourglass_vectors),
		cmocka_unit_test(test_hourglass_power),
		cmocka_unit_test(test_batch_kernels),
		cmocka_unit_test(test_patch_1pt),
		cmocka_unit_test(test_patch_full),
		cmocka_unit_test(test_patch_static),
		cmocka_unit_test(test_rigid_body),
		cmocka_unit_test(test_stiffness_rank),
		cmocka_unit_test(test_full_vs_static),
		cmocka_unit_test(test_static_tangent_fd),
		cmocka_unit_test(test_bending),
		cmocka_unit_test(test_plate_initial_stress),
		cmocka_unit_test(test_inverted),
		cmocka_unit_test(test_dt_and_mass),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
