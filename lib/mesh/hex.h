/* hex.h - the geometry of an 8-node hexahedron in modal form, shared by
 * the element (fe/hex8.c) and the streams of the mesh (io/profile.c: the
 * volumes of the elements of an unstructured mesh).  Private to libdem:
 * static inline, so each user compiles the same arithmetic.  The modal form and the volume formula are derived in
 * fe/hex8.c's header comment.  Nodal arrays are component-major (x[0..7],
 * y[8..15], z[16..23]) in the node order of fe/hex8.h.
 */
#ifndef DEM_MESH_HEX_H
#define DEM_MESH_HEX_H

#include <string.h>

/* a[k] = sum_I Lambda_k(I) u[I] (no 1/8): butterflies along xi, eta, zeta. */
static inline void dem_hex_walsh(const double *u, double *a)
{
	double sa = u[1] + u[0], da = u[1] - u[0]; /* eta -, zeta - */
	double sb = u[2] + u[3], db = u[2] - u[3]; /* eta +, zeta - */
	double sc = u[5] + u[4], dc = u[5] - u[4]; /* eta -, zeta + */
	double sd = u[6] + u[7], dd = u[6] - u[7]; /* eta +, zeta + */
	double ssm = sb + sa, sdm = sb - sa, dsm = db + da, ddm = db - da;
	double ssp = sd + sc, sdp = sd - sc, dsp = dd + dc, ddp = dd - dc;
	a[0] = ssp + ssm;
	a[3] = ssp - ssm;
	a[2] = sdp + sdm;
	a[4] = sdp - sdm;
	a[1] = dsp + dsm;
	a[5] = dsp - dsm;
	a[6] = ddp + ddm;
	a[7] = ddp - ddm;
}

/* u[I] = sum_k Lambda_k(I) F[k]: the butterflies backwards. */
static inline void dem_hex_walsh_inv(const double *F, double *u)
{
	double ssp = F[0] + F[3], ssm = F[0] - F[3];
	double sdp = F[2] + F[4], sdm = F[2] - F[4];
	double dsp = F[1] + F[5], dsm = F[1] - F[5];
	double ddp = F[6] + F[7], ddm = F[6] - F[7];
	double sd = ssp + sdp, sc = ssp - sdp, dd = dsp + ddp, dc = dsp - ddp;
	double sb = ssm + sdm, sa = ssm - sdm, db = dsm + ddm, da = dsm - ddm;
	u[6] = sd + dd;
	u[7] = sd - dd;
	u[5] = sc + dc;
	u[4] = sc - dc;
	u[2] = sb + db;
	u[3] = sb - db;
	u[1] = sa + da;
	u[0] = sa - da;
}

/* Modal coefficients a[k][i] of a component-major nodal field. */
static inline void dem_hex_modes(const double *x, double a[8][3])
{
	double t[8];
	for (int i = 0; i < 3; i++) {
		dem_hex_walsh(x + 8 * i, t);
		for (int k = 0; k < 8; k++)
			a[k][i] = 0.125 * t[k];
	}
}

static inline void dem_hex_cross_add(const double *p, const double *q, double s, double *r)
{
	r[0] += s * (p[1] * q[2] - p[2] * q[1]);
	r[1] += s * (p[2] * q[0] - p[0] * q[2]);
	r[2] += s * (p[0] * q[1] - p[1] * q[0]);
}

static inline double dem_hex_triple(const double *p, const double *q, const double *r)
{
	return p[0] * (q[1] * r[2] - q[2] * r[1]) + p[1] * (q[2] * r[0] - q[0] * r[2]) +
	       p[2] * (q[0] * r[1] - q[1] * r[0]);
}

/* Volume gradient modes c_k = dV/da_k and the volume (header comment). */
/* (a is not written; no const: C11 cannot pass double[8][3] as const) */
static inline void dem_hex_volume_modes(double a[8][3], double c[8][3],
					double *vol)
{
	const double e = 8.0, t = 8.0 / 3;
	memset(c, 0, 8 * sizeof c[0]);
	dem_hex_cross_add(a[2], a[3], e, c[1]);
	dem_hex_cross_add(a[6], a[5], t, c[1]);
	dem_hex_cross_add(a[3], a[1], e, c[2]);
	dem_hex_cross_add(a[4], a[6], t, c[2]);
	dem_hex_cross_add(a[1], a[2], e, c[3]);
	dem_hex_cross_add(a[5], a[4], t, c[3]);
	dem_hex_cross_add(a[6], a[2], t, c[4]);
	dem_hex_cross_add(a[3], a[5], t, c[4]);
	dem_hex_cross_add(a[1], a[6], t, c[5]);
	dem_hex_cross_add(a[4], a[3], t, c[5]);
	dem_hex_cross_add(a[5], a[1], t, c[6]);
	dem_hex_cross_add(a[2], a[4], t, c[6]);
	/* V is homogeneous of degree 3 in the a_k (k >= 1): V = 1/3 sum a_k . c_k */
	double v = 0;
	for (int k = 1; k <= 6; k++)
		v += a[k][0] * c[k][0] + a[k][1] * c[k][1] + a[k][2] * c[k][2];
	*vol = v / 3;
}

/* The volume of the hexahedron x, or 0 when it is inverted (its volume or
 * the Jacobian at its centre not positive), as dem_hex8_1pt_geom() judges
 * it. */
static inline double dem_hex_volume(const double x[24])
{
	double a[8][3], c[8][3], vol;
	dem_hex_modes(x, a);
	dem_hex_volume_modes(a, c, &vol);
	double j0 = dem_hex_triple(a[1], a[2], a[3]);
	return vol > 0 && j0 > 0 ? vol : 0;
}

#endif
