/* test_contact_disk.c - unit tests of the 2D contact layer: the laws of
 * law.h at dim = 2, disk/segment contact with partial contact (disk.c) and
 * disk/disk contact through sphere.c in the plane (Han 2004, Ch. 3.2.1,
 * 3.3, 3.7).
 *
 * References.  The closed forms of the 2D laws: Poritsky's generalised
 * Hertz force beta E b^2 / R (Eqs. 3.30-3.31, b exact by Eq. 3.4), of
 * which the law is the small-overlap limit 2 beta E delta (Eq. 3.32): the
 * relative difference is exactly delta / (2R - delta); the Winkler force
 * k_w S with S the circle's segment (Eq. 3.5), of which the law
 * 4/3 sqrt(2R) k_w delta^(3/2) (Eq. 3.39) is the limit: S expanded in
 * e = delta/R is (4 sqrt(2)/3) R^2 e^(3/2) (1 - 3e/20 + O(e^2)), so the law
 * is above k_w S by 3e/20 to second order; S_p and its centroid by brute
 * force (a midpoint rule of 2e5 points over g(x), Eq. 3.2).  The 2D Hertz
 * line contact of a rigid cylinder on an elastic half-plane (Johnson,
 * Contact Mechanics, 1985, Ch. 4-5): P = pi E* a^2 / (4R); the approach
 * of the half-plane is logarithmic and defined only against a datum depth,
 * so only the load and the half width are compared here.  Poritsky's
 * coefficient from its k1..k4 (the text of Ch. 3.3.2) computed apart from
 * the library's beta(nu).  Box 3.1 and its exit velocity (Fig. 3.15,
 * dem_dt_wall_test), the bound v0 / sqrt(1 - lambda^2) of the linear law
 * (test_contact_law.c), the separation correction (model.h): exit speed =
 * impact speed to rounding.  Coulomb's law for an impact sliding
 * throughout (a solid disk: 3 mu (1 + e) v_n < v_t): J_t = mu J_n.  Statics
 * of a pair: force and moment of the disk's force at P and of the node
 * forces cancel about any point.  The potential scheme: its forces against
 * central differences of its energy, and its energy over a straight row
 * of segments against the law's, U(delta) = k_n delta^(m+1) / (m+1).
 *
 * Data: the Ch. 7.4 case (thesis-data.yaml, shot_peening_2d): disk R 20
 * mm at 12.2 m/s, E 210 GPa, nu 0.3; alpha in {0.5, 1, 2.5, 5, 10}; the
 * 3D friction study's angles 60, 75 deg and mu in {0, 0.05, 0.1, 0.2, 0.5}
 * (shot_peening_3d).  Steel density 7800 kg/m^3 (textbook); segments of
 * 1 mm (about the element size of the 2692-quad mesh of Ch. 7.4).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/disk.h"
#include "contact/sphere.h"
#include "core/consts.h"

#define R_DISK 20e-3
#define E_ST 210e9
#define NU_ST 0.3
#define RHO 7800.0
#define V_DISK 12.2
#define H_SEG 1e-3

static const double M_DISK = RHO * DEM_PI * R_DISK * R_DISK;  /* kg per m of thickness */

static void model(dem_contact_model_t *cm, dem_contact_param_t *p)
{
	dem_error_t e = { 0 };
	if (dem_contact_model_init(cm, p, &e))
		fail_msg("%s", e.msg);
}

static void law2(dem_law_t *l, double alpha, double m)
{
	dem_error_t e = { 0 };
	if (dem_law_init_dim(l, alpha, E_ST, m, 2, &e))
		fail_msg("%s", e.msg);
}

/* brute force: int g, int x g, int g^2/2 over [x0, x1] (midpoint rule) */
static void brute_overlap(double R, double d, double x0, double x1, double *S, double *Mx, double *My)
{
	const int n = 200000;
	double h = (x1 - x0) / n, s = 0, mx = 0, my = 0;
	for (int i = 0; i < n; i++) {
		double x = x0 + (i + 0.5) * h, g = sqrt(R * R - x * x) - d;
		if (g > 0)
			s += g * h, mx += x * g * h, my += 0.5 * g * g * h;
	}
	*S = s, *Mx = mx, *My = my;
}

/* ---- the laws ----------------------------------------------------------- */

static void test_laws_2d(void **state)
{
	(void)state;
	dem_law_t l;
	dem_error_t e = { 0 };
	/* R^(1-m): a force per unit thickness for every m */
	for (double m = 1; m <= 2.5; m += 0.5) {
		dem_law_t si, mm;
		assert_int_equal(dem_law_init_dim(&si, 2.5, 210e9, m, 2, &e), DEM_OK);
		assert_int_equal(dem_law_init_dim(&mm, 2.5, 210e3, m, 2, &e), DEM_OK);
		assert_true(fabs(dem_law_kn(&si, 3) - 2.5 * 210e9 * pow(3, 1 - m)) < 1e-12 * 2.5 * 210e9);
		/* N/m in SI, N/mm in mm: the same force, 1000 times the number */
		double fsi = dem_law_force(&si, dem_law_kn(&si, 20e-3), 1e-4);
		double fmm = dem_law_force(&mm, dem_law_kn(&mm, 20), 0.1);
		assert_true(fabs(fsi - 1000 * fmm) < 1e-12 * fsi);
		/* the 3D law of the same alpha is R times the 2D one: N against N/m */
		dem_law_t l3;
		assert_int_equal(dem_law_init(&l3, 2.5, 210e9, m, &e), DEM_OK);
		assert_true(l3.dim == 3);
		assert_true(fabs(dem_law_kn(&l3, 0.02) / dem_law_kn(&si, 0.02) - 0.02) < 1e-15);
	}
	/* Eq. 3.45 as printed for m = 1: F = alpha E delta */
	law2(&l, 2.5, 1);
	assert_true(fabs(dem_law_force(&l, dem_law_kn(&l, R_DISK), 1e-5) - 2.5 * E_ST * 1e-5) < 1e-6);
	/* the thesis's 2D law in mm, alpha_t E R^(m-1) delta^m (N per mm), is
	 * ours with alpha = alpha_t (R / 1 mm)^(2m-2) */
	for (double m = 1; m <= 1.5; m += 0.5) {
		double at = 2.5, Rmm = 20, dmm = 0.05, Emm = 210e3;
		double Ft = at * Emm * pow(Rmm, m - 1) * pow(dmm, m);  /* N/mm */
		law2(&l, dem_law_alpha_thesis2d(at, m, R_DISK), m);
		double F = dem_law_force(&l, dem_law_kn(&l, R_DISK), dmm * 1e-3);  /* N/m */
		assert_true(fabs(F / (1000 * Ft) - 1) < 1e-12);
	}
	/* a zero-initialised law is a 3D one (the literals of model.h users) */
	dem_law_t z = { .m = 1, .coef = 1 };
	assert_true(dem_law_kn(&z, 3) == 3);
	/* refused */
	assert_int_equal(dem_law_init_dim(&l, 1, 1, 1, 4, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "dimension"));
	dem_error_clear(&e);
	assert_int_equal(dem_law_ghertz2d(&l, E_ST, 0.6, &e), DEM_EINPUT);
	dem_error_clear(&e);
	/* the effects line names the dimension */
	dem_contact_param_t p = { 0 };
	law2(&p.law, 1, 1.5);
	p.partial = DEM_PARTIAL_WIDTH;
	dem_contact_model_t cm;
	model(&cm, &p);
	assert_non_null(strstr(cm.effects, "m=1.5 (2D)"));
	assert_non_null(strstr(cm.effects, "partial width"));
}

/* Generalised Hertz 2D (Poritsky) against its closed form and against the
 * Hertz line contact with the overlap's chord as the contact width. */
static void test_ghertz2d(void **state)
{
	(void)state;
	for (double nu = 0.0; nu <= 0.5; nu += 0.1) {
		/* Poritsky's k_n from k1..k4 with a nearly rigid disk: beta E */
		double E1 = E_ST, G1 = E1 / (2 * (1 + nu)), G2 = 1e9 * G1, nu2 = 0.3;
		double k1 = (1 - nu) / G1, k2 = (1 - nu2) / G2, k3 = 2 / DEM_PI * (k1 + k2);
		double k4 = (1 - 2 * nu) / G1 - (1 - 2 * nu2) / G2;
		double kn = DEM_PI / 4 * (1 + (k4 / k3) * (k4 / k3)) / (k1 + k2);
		double beta = dem_law_ghertz2d_beta(nu);
		assert_true(fabs(kn / (beta * E1) - 1) < 1e-8);
		dem_law_t l;
		dem_error_t e = { 0 };
		assert_int_equal(dem_law_ghertz2d(&l, E1, nu, &e), DEM_OK);
		assert_true(l.m == 1 && l.dim == 2);
		double knl = dem_law_kn(&l, R_DISK);
		for (double ed = 1e-4; ed <= 0.05; ed *= 2) {
			double delta = ed * R_DISK, b2 = delta * (2 * R_DISK - delta);
			double exact = beta * E1 * b2 / R_DISK;  /* Eq. 3.30 */
			double F = dem_law_force(&l, knl, delta);
			assert_true(fabs(F / exact - 1 - delta / (2 * R_DISK - delta)) < 1e-12);
		}
		/* Johnson's line contact P = pi E* a^2 / (4R) with a^2 = 2 R delta:
		 * the same linear law, (pi/2) E* delta; Poritsky's is (1 + (k4/k3)^2)/2
		 * of it */
		double Es = E1 / (1 - nu * nu), delta = 1e-5;
		double PJ = DEM_PI * Es * 2 * R_DISK * delta / (4 * R_DISK);
		double ratio = dem_law_force(&l, knl, delta) / PJ, r43 = DEM_PI * (1 - 2 * nu) / (2 * (1 - nu));
		assert_true(fabs(ratio - (1 + r43 * r43) / 2) < 1e-12);
		if (fabs(nu - 0.3) < 1e-9)
			print_message("generalised Hertz 2D, nu 0.3: beta %.4f, alpha = 2 beta = %.4f; force %.4f of the "
			              "Hertz line contact's (Johnson) at a = b\n", beta, 2 * beta, ratio);
	}
}

/* 2D Winkler: the law against k_w S, S by Eq. 3.5 and by brute force. */
static void test_winkler2d(void **state)
{
	(void)state;
	const double kw = E_ST / R_DISK;  /* a foundation as deep as the disk is wide */
	dem_law_t l;
	law2(&l, dem_law_winkler2d_alpha(kw, E_ST, R_DISK), 1.5);
	double kn = dem_law_kn(&l, R_DISK), worst = 0;
	for (double ed = 1e-4; ed <= 0.1; ed *= 1.5) {
		double delta = ed * R_DISK, d = R_DISK - delta, b = sqrt(delta * (2 * R_DISK - delta));
		double S = dem_disk_segment_area(R_DISK, delta), Sb, mx, my;
		brute_overlap(R_DISK, d, -b, b, &Sb, &mx, &my);
		assert_true(fabs(S / Sb - 1) < 1e-6);
		/* the geometry's own S_f (quadrature, cancellation-free) */
		dem_seg_geom_t g;
		double O[2] = { 0.3 * b, d }, A[2] = { 0, 0 }, B[2] = { 1, 0 };
		assert_int_equal(dem_segment_geom(O, R_DISK, A, B, DEM_PARTIAL_AREA, &g), 1);
		assert_true(!g.full && fabs(g.Sf / S - 1) < 1e-9);
		/* Eq. 3.7 and the law */
		double F = dem_law_force(&l, kn, delta), ex = kw * S;
		double err = F / ex - 1 - 0.15 * ed;
		worst = fmax(worst, fabs(F / ex - 1));
		assert_true(fabs(err) < ed * ed);
		assert_true(fabs(4.0 / 3.0 * sqrt(2 * R_DISK * delta) * delta / S - 1) < ed);
	}
	print_message("Winkler 2D: law / (k_w S) - 1 = 3/20 delta/R to second order; up to %.4f for delta/R <= 0.1\n",
	              worst);
}

/* ---- geometry ----------------------------------------------------------- */

/* Partial contact factors and centroids against brute force; collinear
 * pieces add up to the full contact. */
static void test_segment_geom(void **state)
{
	(void)state;
	const double R = R_DISK, delta = 0.01 * R, d = R - delta, b = sqrt(delta * (2 * R - delta));
	const double A[2] = { 0, 0 }, B[2] = { 1.3 * b, 0 };
	dem_seg_geom_t g, g1, g2;
	/* full contact: gamma 1, along the normal, through the foot */
	double Oc[2] = { 0.65 * b, d };
	for (int sch = 0; sch < 2; sch++) {
		int scheme = sch ? DEM_PARTIAL_WIDTH : DEM_PARTIAL_AREA;
		dem_seg_geom_t gl;
		const double LA[2] = { -5 * b, 0 }, LB[2] = { 5 * b, 0 };
		assert_int_equal(dem_segment_geom(Oc, R, LA, LB, scheme, &gl), 1);
		assert_true(gl.full && gl.gamma == 1 && fabs(gl.n[0]) < 1e-15 && fabs(gl.n[1] - 1) < 1e-15);
		assert_true(fabs(gl.P[0] - 0.65 * b) < 1e-15 && fabs(gl.delta - delta) < 1e-15);
	}
	/* the disk over the end B, at several offsets */
	for (double off = -0.9; off <= 0.9; off += 0.15) {
		double O[2] = { B[0] + off * b, d };
		assert_int_equal(dem_segment_geom(O, R, A, B, DEM_PARTIAL_AREA, &g), 1);
		double x0 = fmax(-b, -O[0]), x1 = fmin(b, B[0] - O[0]), S, Mx, My, Sf, mx, my;
		brute_overlap(R, d, x0, x1, &S, &Mx, &My);
		brute_overlap(R, d, -b, b, &Sf, &mx, &my);
		assert_false(g.full);
		assert_true(fabs(g.gamma - S / Sf) < 1e-6);
		assert_true(fabs(g.G[0] - (O[0] + Mx / S)) < 1e-6 * b);
		assert_true(fabs(g.G[1] - (-My / S)) < 1e-6 * delta);
		/* P on the segment's line and on the line G O */
		assert_true(fabs(g.P[1]) < 1e-15);
		double cr = (g.P[0] - g.G[0]) * (O[1] - g.G[1]) - (g.P[1] - g.G[1]) * (O[0] - g.G[0]);
		assert_true(fabs(cr) < 1e-12 * b * R);
		/* the width factor */
		assert_int_equal(dem_segment_geom(O, R, A, B, DEM_PARTIAL_WIDTH, &g), 1);
		assert_true(fabs(g.gamma - (x1 - x0) / (2 * b)) < 1e-14);
		assert_true(fabs(g.P[0] - (O[0] + 0.5 * (x0 + x1))) < 1e-14 * b);  /* rounding of O - d nf + px t */
		assert_true(g.xi >= 0 && g.xi <= 1);
		/* the other side of the joint: a collinear segment B -> C; the
		 * factors add up to one, the first moments to the full contact's */
		const double A1[2] = { B[0] - 3 * b, 0 }, C2[2] = { B[0] + 3 * b, 0 };
		for (int sch = 0; sch < 2; sch++) {
			int scheme = sch ? DEM_PARTIAL_WIDTH : DEM_PARTIAL_AREA;
			int c1 = dem_segment_geom(O, R, A1, B, scheme, &g1), c2 = dem_segment_geom(O, R, B, C2, scheme, &g2);
			assert_true(c1 && c2);
			assert_true(fabs(g1.gamma + g2.gamma - 1) < 1e-12);
			if (!sch)
				assert_true(fabs(g1.Sp * (g1.G[0] - O[0]) + g2.Sp * (g2.G[0] - O[0])) < 1e-12 * g1.Sf * b);
		}
	}
	/* no contact: apart, behind the line, beyond an end */
	double Ofar[2] = { 0.5 * b, R * 1.01 }, Obehind[2] = { 0.5 * b, -0.1 * R }, Opast[2] = { B[0] + 1.01 * b, d };
	assert_int_equal(dem_segment_geom(Ofar, R, A, B, DEM_PARTIAL_AREA, &g), 0);
	assert_int_equal(dem_segment_geom(Obehind, R, A, B, DEM_PARTIAL_AREA, &g), 0);
	assert_int_equal(dem_segment_geom(Opast, R, A, B, DEM_PARTIAL_AREA, &g), 0);
	assert_int_equal(dem_segment_geom(Opast, R, A, A, DEM_PARTIAL_AREA, &g), 0);
	/* the area factor stays accurate at a grazing overlap (no cancellation) */
	double dl = 1e-9 * R, bl = sqrt(dl * (2 * R - dl));
	double Og[2] = { B[0] + 0.5 * bl, R - dl };
	assert_int_equal(dem_segment_geom(Og, R, A, B, DEM_PARTIAL_AREA, &g), 1);
	/* S_p / S_f for the parabola b^2 - x^2 over [-b, -b/2]: 5/32 */
	assert_true(fabs(g.gamma - 5.0 / 32.0) < 1e-6);
}

/* ---- pairs -------------------------------------------------------------- */

/* A tiny LCG: reproducible scatter without the library's rng. */
/* The three 2D partial schemes by number: 0 area, 1 width, 2 potential. */
#define SCHEME(i) ((i) == 0 ? DEM_PARTIAL_AREA : (i) == 1 ? DEM_PARTIAL_WIDTH : DEM_PARTIAL_POTENTIAL)
#define SCHEME_NAME(i) ((i) == 0 ? "area" : (i) == 1 ? "width" : "potential")

static double lcg(unsigned long *s)
{
	*s = *s * 6364136223846793005UL + 1442695040888963407UL;
	return (double)(*s >> 11) / 9007199254740992.0;
}

/* Force and moment equilibrium of a pair: the disk's force with its torque,
 * the nodes' forces, about the origin.  Moving nodes, spin, friction and
 * damping; both schemes; full and partial contacts. */
static void test_equilibrium(void **state)
{
	(void)state;
	unsigned long seed = 12345;
	int partial = 0, full = 0;
	for (int sch = 0; sch < 3; sch++) {
		dem_contact_param_t p = { .damping = DEM_DAMP_VISCOUS, .xi = 0.3, .friction = 1, .mu = 0.3,
		                          .partial = SCHEME(sch) };
		law2(&p.law, 2.5, 1.5);
		dem_contact_model_t cm;
		model(&cm, &p);
		double worstF = 0, worstM = 0;
		for (int it = 0; it < 2000; it++) {
			/* a segment of length 0.3-3 mm, any direction; the disk near it */
			double th = 2 * DEM_PI * lcg(&seed), L = (0.3 + 2.7 * lcg(&seed)) * 1e-3;
			double X[2][2] = { { 0.01 * lcg(&seed), 0.01 * lcg(&seed) }, { 0, 0 } };
			X[1][0] = X[0][0] + L * cos(th), X[1][1] = X[0][1] + L * sin(th);
			/* b up to 1.3 mm: full and partial contacts */
			double delta = R_DISK * 0.002 * lcg(&seed), s = (-0.5 + 2 * lcg(&seed)) * L;
			dem_sphere_t sp = { .R = R_DISK, .kn = dem_law_kn(&p.law, R_DISK) };
			sp.x[0] = X[0][0] + s * cos(th) - (R_DISK - delta) * sin(th);
			sp.x[1] = X[0][1] + s * sin(th) + (R_DISK - delta) * cos(th);
			sp.v[0] = 5 * (lcg(&seed) - 0.5), sp.v[1] = -5 * lcg(&seed), sp.w[2] = 300 * (lcg(&seed) - 0.5);
			double V[2][2] = { { lcg(&seed) - 0.5, lcg(&seed) - 0.5 }, { lcg(&seed) - 0.5, lcg(&seed) - 0.5 } };
			dem_contact_state_t st;
			dem_contact_state_reset(&st);
			dem_seg_out_t o;
			/* two steps, so that friction has a history */
			int in = 0;
			for (int k = 0; k < 2; k++)
				in = dem_contact_disk_segment(&cm, &sp, (const double (*)[2])X, (const double (*)[2])V, M_DISK,
				                              1e-7, &st, &o);
			if (!in)
				continue;
			if (o.g.full)
				full++;
			else
				partial++;
			const double *F = o.c.F;
			assert_true(F[2] == 0 && o.c.T[0] == 0 && o.c.T[1] == 0);
			double sF[2], Fs = hypot(F[0], F[1]);
			for (int i = 0; i < 2; i++)
				sF[i] = F[i] + o.Fnode[0][i] + o.Fnode[1][i];
			double M = sp.x[0] * F[1] - sp.x[1] * F[0] + o.c.T[2];
			for (int a = 0; a < 2; a++)
				M += X[a][0] * o.Fnode[a][1] - X[a][1] * o.Fnode[a][0];
			Fs = fmax(Fs, fabs(o.c.Fe));
			worstF = fmax(worstF, hypot(sF[0], sF[1]) / Fs);
			worstM = fmax(worstM, fabs(M) / (Fs * R_DISK));
			/* rounding, of the elastic force too: the potential
			 * scheme's node forces are sums of elastic terms, which
			 * damping may nearly cancel in F */
			assert_true(hypot(sF[0], sF[1]) <= 1e-14 * Fs);
			assert_true(fabs(M) <= 1e-12 * Fs * R_DISK);
			/* Coulomb */
			assert_true(o.c.Ft <= cm.p.mu * o.c.Fn * (1 + 1e-12));
			/* the point of action on the segment */
			assert_true(o.g.xi >= -1e-9 && o.g.xi <= 1 + 1e-9);
		}
		print_message("equilibrium, %s scheme: |sum F| / max(|F|, F_e) up to %.1e, |sum M| / (.. R) up to %.1e "
		              "(%d full, %d partial contacts so far)\n", SCHEME_NAME(sch), worstF, worstM, full, partial);
	}
	assert_true(partial > 200 && full > 200);
}

/* ---- the potential scheme ------------------------------------------------ */

#define NROW 64  /* segments in a row (test_potential_flat, row_force) */

/* The potential scheme's forces against the central differences of its
 * energy, relative to the branch's full contact force: its integrals are
 * quadratures along the chords (facet.c, which meets 1e-6 in 3D), the
 * forces' and the energy's two different ones, so they agree to the
 * quadrature's error, not to rounding. */
#define POT_TOL 1e-5

/* The energy of the pair (O, R; A -> B) on the branch F = bc (g - g0)^m,
 * with the forces when F, Fnode are not NULL; 0 and no forces out of
 * contact.  Returns the contact's state: 0 none, 1 partial, 2 full. */
static int pot_pair(const double O[2], double R, const double A[2], const double B[2], double m,
                    double bc, double bg0, double *Phi, double F[2], double Fnode[2][2])
{
	dem_seg_geom_t g;
	double Fd[2], Fn[2][2];
	*Phi = 0;
	if (!dem_segment_geom(O, R, A, B, DEM_PARTIAL_POTENTIAL, &g))
		return 0;
	double x = g.delta - bg0, f = x > 0 ? g.gamma * bc * pow(x, m) : 0;
	dem_contact_out_t o = { .F = { f * g.n[0], f * g.n[1], 0 }, .Fe = f, .bc = bc, .bg0 = bg0 };
	dem_segment_forces(&g, &o, m, F ? F : Fd, Fnode ? Fnode : Fn, Phi);
	return g.full ? 2 : 1;
}

/* Forces = minus the gradient of the energy, by central differences in
 * the disk's position and both nodes', over random pairs (segments of any
 * direction and length 0.3-3 mm, partial and full contacts), the laws
 * m = 1, 1.5, 2 on loading and on an unloading branch (g0 = 0.4 delta). */
static void test_potential_gradient(void **state)
{
	(void)state;
	unsigned long seed = 777;
	const double ms[3] = { 1, 1.5, 2 };
	int partial = 0, full = 0;
	double worst = 0, worst_sum = 0, worst_mom = 0;
	for (int it = 0; it < 3000; it++) {
		double m = ms[it % 3], kn = 1e11;
		double th = 2 * DEM_PI * lcg(&seed), L = (0.3 + 2.7 * lcg(&seed)) * 1e-3;
		double X[2][2] = { { 0.01 * lcg(&seed), 0.01 * lcg(&seed) }, { 0, 0 } };
		X[1][0] = X[0][0] + L * cos(th), X[1][1] = X[0][1] + L * sin(th);
		double delta = R_DISK * 0.002 * lcg(&seed), sc = (-0.5 + 2 * lcg(&seed)) * L;
		double O[2] = { X[0][0] + sc * cos(th) - (R_DISK - delta) * sin(th),
		                X[0][1] + sc * sin(th) + (R_DISK - delta) * cos(th) };
		int unload = (it / 3) % 2;
		double bg0 = unload ? 0.4 * delta : 0, bc = unload ? kn / pow(0.6, m) : kn;
		double Phi, F[2], Fnode[2][2];
		int c = pot_pair(O, R_DISK, X[0], X[1], m, bc, bg0, &Phi, F, Fnode);
		if (!c)
			continue;
		c == 1 ? partial++ : full++;
		double Ffull = bc * pow(delta - bg0, m), h = 1e-4 * delta;
		/* unknowns: O, A, B; forces F, Fnode[0], Fnode[1] */
		double *pos[3] = { O, X[0], X[1] }, *frc[3] = { F, Fnode[0], Fnode[1] };
		for (int a = 0; a < 3; a++)
			for (int i = 0; i < 2; i++) {
				double keep = pos[a][i], Pp, Pm;
				pos[a][i] = keep + h;
				pot_pair(O, R_DISK, X[0], X[1], m, bc, bg0, &Pp, NULL, NULL);
				pos[a][i] = keep - h;
				pot_pair(O, R_DISK, X[0], X[1], m, bc, bg0, &Pm, NULL, NULL);
				pos[a][i] = keep;
				double err = fabs(frc[a][i] + (Pp - Pm) / (2 * h)) / Ffull;
				worst = fmax(worst, err);
				assert_true(err < POT_TOL);
			}
		/* the three forces sum to zero, with zero moment */
		double sx = F[0] + Fnode[0][0] + Fnode[1][0], sy = F[1] + Fnode[0][1] + Fnode[1][1];
		double M = O[0] * F[1] - O[1] * F[0];
		for (int a = 0; a < 2; a++)
			M += X[a][0] * Fnode[a][1] - X[a][1] * Fnode[a][0];
		worst_sum = fmax(worst_sum, hypot(sx, sy) / Ffull);
		worst_mom = fmax(worst_mom, fabs(M) / (Ffull * R_DISK));
		assert_true(hypot(sx, sy) <= 1e-12 * Ffull);
		assert_true(fabs(M) <= 1e-10 * Ffull * R_DISK);
	}
	print_message("potential: %d partial, %d full contacts; force + FD gradient <= %.2g F_full, "
	              "sum <= %.2g F_full, moment <= %.2g F_full R\n", partial, full, worst, worst_sum, worst_mom);
	assert_true(partial > 300 && full > 200);
}

/* A long flat of many segments (lengths b/2 and 10 b) under the disk at
 * rest, its centre anywhere along it: the segments' energies add up to the
 * law's, U(delta) = k_n delta^(m+1) / (m+1) (their sum is int w2 dx over
 * the line, whatever the joints), and the force is the law's (the gradient
 * of that sum: see test_joint_crossing). */
static void test_potential_flat(void **state)
{
	(void)state;
	const double ms[3] = { 1, 1.5, 2 }, eds[2] = { 1e-3, 1e-2 }, kn = 1e11;
	double worst = 0;
	for (int j = 0; j < 3; j++)
		for (int q = 0; q < 2; q++)
			for (int mesh = 0; mesh < 2; mesh++) {
				double delta = eds[q] * R_DISK, b = sqrt(delta * (2 * R_DISK - delta));
				double h = mesh ? 0.5 * b : 10 * b, U = kn * pow(delta, ms[j] + 1) / (ms[j] + 1);
				for (int i = 0; i <= 200; i++) {
					double O[2] = { -2 * b + 4 * b * i / 200.0, R_DISK - delta }, sum = 0;
					for (int s = 0; s < NROW; s++) {
						double A[2] = { (s - NROW / 2) * h, 0 }, B[2] = { A[0] + h, 0 }, Phi;
						pot_pair(O, R_DISK, A, B, ms[j], kn, 0, &Phi, NULL, NULL);
						sum += Phi;
					}
					worst = fmax(worst, fabs(sum / U - 1));
				}
			}
	print_message("potential on a flat of segments: sum of the energies / U(delta) - 1 up to %.2e\n", worst);
	/* the quadrature's error, as in the forces */
	assert_true(worst < POT_TOL);
}

/* The force on a disk of the Ch. 7.4 size held at overlap delta over a row
 * of collinear segments of length h, its centre at x: the sum over the
 * segments it meets.  scheme < 0: the naive scheme, each segment's nearest
 * point with the full law (delta_i = R - |O - q_i|, no factor). */
static void row_force(const dem_contact_model_t *cm, double x, double delta, double h, int scheme,
                      double F[2])
{
	double kn = dem_law_kn(&cm->p.law, R_DISK), O[2] = { x, R_DISK - delta };
	F[0] = F[1] = 0;
	for (int s = 0; s < NROW; s++) {
		double A[2] = { (s - NROW / 2) * h, 0 }, B[2] = { A[0] + h, 0 };
		if (scheme < 0) {
			double q = fmin(fmax(x, A[0]), B[0]), dx = x - q, dy = O[1], dist = hypot(dx, dy);
			double f = dem_law_force(&cm->p.law, kn, R_DISK - dist);
			F[0] += f * dx / dist, F[1] += f * dy / dist;
			continue;
		}
		dem_seg_geom_t g;
		if (!dem_segment_geom(O, R_DISK, A, B, scheme, &g))
			continue;
		double f = g.gamma * dem_law_force(&cm->p.law, kn, g.delta);
		/* the kernel's elastic output on loading (model.h: bc = k_n, bg0 = 0) */
		dem_contact_out_t o = { .F = { f * g.n[0], f * g.n[1], 0 }, .Fe = f, .bc = kn };
		double Fd[2], Fnode[2][2];
		dem_segment_forces(&g, &o, cm->m, Fd, Fnode, NULL);
		F[0] += Fd[0], F[1] += Fd[1];
	}
}

/* A disk sliding across the joints of collinear segments at a fixed
 * overlap: the force stays the full contact's within 5 % (both schemes),
 * while the naive scheme jumps.  Two meshes: segments 10 b long (one joint
 * at a time, as the issue words it) and b/2 long (four or five segments in
 * the contact). */
static void test_joint_crossing(void **state)
{
	(void)state;
	const double ms[2] = { 1, 1.5 }, eds[2] = { 1e-3, 1e-2 };
	for (int j = 0; j < 2; j++)
		for (int q = 0; q < 2; q++) {
			dem_contact_param_t p = { 0 };
			law2(&p.law, 2.5, ms[j]);
			dem_contact_model_t cm;
			model(&cm, &p);
			double delta = eds[q] * R_DISK, b = sqrt(delta * (2 * R_DISK - delta));
			double Ffull = dem_law_force(&p.law, dem_law_kn(&p.law, R_DISK), delta);
			for (int mesh = 0; mesh < 2; mesh++) {
				double h = mesh ? 0.5 * b : 10 * b, dev[4] = { 0 }, jump[4] = { 0 }, side[4] = { 0 };
				for (int sc = 0; sc < 4; sc++) {
					int scheme = sc == 0 ? DEM_PARTIAL_AREA : sc == 1 ? DEM_PARTIAL_WIDTH :
					             sc == 3 ? DEM_PARTIAL_POTENTIAL : -1;
					double prev = -1;
					/* across the joint at x = 0 (and those within 2b of it) */
					for (int i = 0; i <= 4000; i++) {
						double x = -2 * b + 4 * b * i / 4000.0, F[2];
						row_force(&cm, x, delta, h, scheme, F);
						double f = hypot(F[0], F[1]);
						dev[sc] = fmax(dev[sc], fabs(f / Ffull - 1));
						side[sc] = fmax(side[sc], fabs(F[0]) / Ffull);
						if (prev >= 0)
							jump[sc] = fmax(jump[sc], fabs(f - prev) / Ffull);
						prev = f;
					}
				}
				print_message("crossing, m = %.1f, delta/R %.0e, segments %s: |F|/F_full - 1 up to %.2e area, "
				              "%.2e width, %.2f naive; side force %.1e, %.1e, %.2f; largest step-to-step change "
				              "%.1e, %.1e, %.2f\n", ms[j], eds[q], mesh ? "b/2" : "10b", dev[0], dev[1], dev[2],
				              side[0], side[1], side[2], jump[0], jump[1], jump[2]);
				print_message("  potential scheme: |F|/F_full - 1 up to %.2e, side force %.1e\n", dev[3], side[3]);
				assert_true(dev[0] < 0.05 && dev[1] < 0.05);
				assert_true(side[0] < 0.05 && side[1] < 0.05);
				/* the potential scheme: the law itself, to its quadrature
				 * (test_potential_gradient's tolerance) */
				assert_true(dev[3] < POT_TOL && side[3] < POT_TOL);
				/* the naive scheme does see the joint */
				assert_true(dev[2] > 0.2);
			}
		}
}

/* ---- the rigid disk on a row of segments: Box 3.1 in 2D ------------------ */

typedef struct run2 {
	double v[2], w;      /* exit velocity and spin */
	double Fmax, dmax;   /* largest normal force and overlap */
	double ftmax;        /* largest |F_t| / (mu F_n) over pairs and steps */
	double Jn, Jt;       /* impulses on the disk */
	double jump;         /* largest change of |F| between steps, over the largest |F| */
	double dE;           /* energy the separation correction took */
	long steps;
	int finite;
} run2_t;

static dem_contact_state_t states[NROW];

/* The disk from (x0, R) with velocity v0 onto the row of NROW segments of
 * length h along y = 0, Box 3.1 with the step of dem_contact_dt (from the
 * state) or, impact = 1, that of Box 3.1 (u_max of the impact, Eq. 3.81),
 * until it has left; fix: the separation correction as a driver applies it
 * (model.h). */
static void impact2d(const dem_contact_model_t *cm, double h, const double x0[2], const double v0[2],
                     double lambda, int impact, int fix, run2_t *r)
{
	const double I = 0.5 * M_DISK * R_DISK * R_DISK;
	dem_sphere_t sp = { .R = R_DISK, .kn = dem_law_kn(&cm->p.law, R_DISK) };
	sp.x[0] = x0[0], sp.x[1] = x0[1], sp.v[0] = v0[0], sp.v[1] = v0[1];
	for (int s = 0; s < NROW; s++)
		dem_contact_state_reset(&states[s]);
	memset(r, 0, sizeof *r);
	r->finite = 1;
	const double umax0 = dem_dt_umax(cm->m, sp.kn, M_DISK, fabs(v0[1]));  /* Eq. 3.81 */
	const double nf[3] = { 0, 1, 0 };
	double dtp = 0, Fprev = 0;
	int touched = 0;
	for (long n = 0; n < 10000000L; n++) {
		double u = R_DISK - sp.x[1];
		double dt = impact ? lambda * 2 * sqrt(M_DISK / dem_dt_secant(cm->m, sp.kn, umax0, u))
		                   : dem_contact_dt(cm, sp.kn, M_DISK, u, sp.v[1], lambda);
		double hh = 0.5 * (dtp + dt), F[2] = { 0, 0 }, T = 0;
		int any = 0;
		for (int s = 0; s < NROW; s++) {
			double X[2][2] = { { (s - NROW / 2) * h, 0 }, { (s - NROW / 2 + 1) * h, 0 } };
			dem_seg_out_t o;
			dem_contact_state_t keep = states[s];
			if (!dem_contact_disk_segment(cm, &sp, (const double (*)[2])X, NULL, M_DISK, dt, &states[s], &o)) {
				if (fix) {
					double J[3];
					r->dE += dem_sepfix_release(cm, &keep, sp.kn, M_DISK, nf, sp.v, J);
					F[0] += J[0] / hh, F[1] += J[1] / hh;
				}
				continue;
			}
			if (fix) {
				double n3[3] = { o.g.n[0], o.g.n[1], 0 };
				dem_sepfix_record(&states[s], n3, sp.v, o.c.Fe, hh);
			}
			any = 1;
			F[0] += o.c.F[0], F[1] += o.c.F[1], T += o.c.T[2];
			if (cm->p.friction && o.c.Fn > 0)
				r->ftmax = fmax(r->ftmax, o.c.Ft / (cm->p.mu * o.c.Fn));
			else if (cm->p.friction && o.c.Ft > 0)
				r->ftmax = HUGE_VAL;
		}
		double Fm = hypot(F[0], F[1]);
		if (any) {
			r->Fmax = fmax(r->Fmax, F[1]);
			if (touched)
				r->jump = fmax(r->jump, fabs(Fm - Fprev));
			Fprev = Fm;
		}
		r->dmax = fmax(r->dmax, u);
		for (int i = 0; i < 2; i++)
			sp.v[i] += F[i] / M_DISK * hh;
		sp.w[2] += T / I * hh;
		r->Jn += F[1] * hh, r->Jt += F[0] * hh;
		for (int i = 0; i < 2; i++)
			sp.x[i] += sp.v[i] * dt;
		dtp = dt;
		touched |= any;
		if (!isfinite(sp.x[1]) || !isfinite(sp.v[1])) {
			r->finite = 0;
			break;
		}
		if (touched && !any && sp.v[1] > 0 && sp.x[1] > R_DISK) {
			r->steps = n + 1;
			break;
		}
	}
	r->v[0] = sp.v[0], r->v[1] = sp.v[1], r->w = sp.w[2];
	if (r->Fmax > 0)
		r->jump /= r->Fmax;
}

/* Box 3.1 for the 2D laws through the disk/segment pair: a rigid disk on a
 * long segment with the step of Eq. 3.81 is the rigid sphere/wall test,
 * whose exit velocity depends on m and lambda only; with the separation
 * correction it leaves at its impact speed. */
static void test_box31_2d(void **state)
{
	(void)state;
	dem_contact_param_t ps[3];
	memset(ps, 0, sizeof ps);
	dem_error_t e = { 0 };
	law2(&ps[0].law, 1, 1);                                    /* linear */
	assert_int_equal(dem_law_ghertz2d(&ps[1].law, E_ST, NU_ST, &e), DEM_OK);
	law2(&ps[2].law, dem_law_winkler2d_alpha(E_ST / R_DISK, E_ST, R_DISK), 1.5);  /* Winkler */
	const char *names[3] = { "linear", "generalised Hertz", "Winkler" };
	const double h = 1.0;  /* segments 1 m long: full contact throughout */
	const double x0[2] = { 0.5 * h, R_DISK }, v0[2] = { 0, -V_DISK };
	for (int j = 0; j < 3; j++) {
		dem_contact_model_t cm, off;
		model(&cm, &ps[j]);
		ps[j].sepfix = DEM_SEPFIX_OFF;
		model(&off, &ps[j]);
		double m = cm.m, hi = 0, lo = 2, dev = 0;
		for (int i = 1; i <= 60; i++) {
			double lambda = 0.3 * i / 60;
			run2_t r, rc;
			impact2d(&off, h, x0, v0, lambda, 1, 0, &r);
			impact2d(&cm, h, x0, v0, lambda, 1, 1, &rc);
			double ratio = hypot(r.v[0], r.v[1]) / V_DISK, rcor = hypot(rc.v[0], rc.v[1]) / V_DISK;
			double box = dem_dt_wall_test(m, 1, 1, 1, lambda, NULL, NULL);
			assert_true(r.finite && rc.finite);
			assert_true(fabs(ratio - box) < 1e-9);  /* Ch. 3.7.2: only m and lambda matter */
			assert_true(ratio <= 1 / sqrt(1 - lambda * lambda) * (1 + 1e-12));
			assert_true(fabs(rcor - 1) < 1e-9);
			assert_true(r.dmax <= dem_dt_umax(m, dem_law_kn(&cm.p.law, R_DISK), M_DISK, V_DISK) * (1 + lambda * lambda));
			hi = fmax(hi, ratio), lo = fmin(lo, ratio), dev = fmax(dev, fabs(rcor - 1));
		}
		print_message("Box 3.1, 2D %s (m = %.1f), lambda in (0, 0.3]: v_exit/v0 %.5f to %.5f (thesis scheme), "
		              "corrected within 1 +- %.1e\n", names[j], m, lo, hi, dev);
	}
}

/* The Ch. 7.4 disk on 1 mm segments: alpha 0.5-10, linear and Winkler
 * (m = 1.5) laws, both partial schemes, the default lambda, the step from
 * the state (as a driver): bounded exit speed, the rigid wall's for
 * m = 1.5, straight back, and no force jump at the joints the contact
 * crosses as it spreads. */
static void test_alpha_range(void **state)
{
	(void)state;
	const double alphas[5] = { 0.5, 1, 2.5, 5, 10 }, ms[2] = { 1, 1.5 }, lambda = DEM_DT_LAMBDA_DEFAULT;
	const double x0[2] = { 0.37 * H_SEG, R_DISK }, v0[2] = { 0, -V_DISK };
	for (int sch = 0; sch < 2; sch++)
		for (int j = 0; j < 2; j++) {
			double worst = 0, wj = 0;
			for (int a = 0; a < 5; a++) {
				dem_contact_param_t p = { .partial = sch ? DEM_PARTIAL_WIDTH : DEM_PARTIAL_AREA };
				law2(&p.law, alphas[a], ms[j]);
				dem_contact_model_t cm;
				model(&cm, &p);
				run2_t r;
				impact2d(&cm, H_SEG, x0, v0, lambda, 0, 0, &r);
				double ratio = hypot(r.v[0], r.v[1]) / V_DISK;
				double umax = dem_dt_umax(ms[j], dem_law_kn(&p.law, R_DISK), M_DISK, V_DISK);
				assert_true(r.finite && r.steps > 0);
				assert_true(ratio <= 1 / sqrt(1 - lambda * lambda));
				if (ms[j] != 1)
					assert_true(fabs(ratio - dem_dt_wall_test(ms[j], 1, 1, 1, lambda, NULL, NULL)) < 1e-3);
				assert_true(r.dmax <= umax * (1 + lambda * lambda));
				assert_true(r.dmax < 0.05 * R_DISK);
				assert_true(fabs(r.v[0]) < 1e-3 * V_DISK);
				worst = fmax(worst, ratio), wj = fmax(wj, r.jump);
			}
			print_message("alpha 0.5-10, %s scheme, m = %.1f, lambda 0.2: largest exit/impact speed %.5f, largest "
			              "step-to-step force change %.2f of the peak\n", sch ? "width" : "area", ms[j], worst, wj);
		}
}

/* Oblique impacts at 60 and 75 deg with friction on the 1 mm segments:
 * |F_t| <= mu F_n at every pair and step; mu = 0 as no friction; Coulomb
 * impulse ratio when sliding throughout. */
static void test_oblique_friction(void **state)
{
	(void)state;
	const double angles[2] = { 60, 75 }, mus[5] = { 0, 0.05, 0.1, 0.2, 0.5 }, lambda = DEM_DT_LAMBDA_DEFAULT;
	const double I = 0.5 * M_DISK * R_DISK * R_DISK;
	for (int sch = 0; sch < 2; sch++)
		for (int a = 0; a < 2; a++) {
			double th = angles[a] * DEM_PI / 180;
			double x0[2] = { -0.013 * H_SEG, R_DISK }, v0[2] = { V_DISK * cos(th), -V_DISK * sin(th) };
			double E0 = 0.5 * M_DISK * V_DISK * V_DISK;
			int scheme = sch ? DEM_PARTIAL_WIDTH : DEM_PARTIAL_AREA;
			run2_t r0;
			{
				dem_contact_param_t p = { .partial = scheme };
				law2(&p.law, 2.5, 1.5);
				dem_contact_model_t cm;
				model(&cm, &p);
				impact2d(&cm, H_SEG, x0, v0, lambda, 0, 0, &r0);
			}
			for (int k = 0; k < 5; k++) {
				dem_contact_param_t p = { .friction = 1, .mu = mus[k], .partial = scheme };
				law2(&p.law, 2.5, 1.5);
				dem_contact_model_t cm;
				model(&cm, &p);
				run2_t r;
				impact2d(&cm, H_SEG, x0, v0, lambda, 0, 0, &r);
				assert_true(r.finite);
				assert_true(r.ftmax <= 1 + 1e-12);
				double E1 = 0.5 * M_DISK * (r.v[0] * r.v[0] + r.v[1] * r.v[1]) + 0.5 * I * r.w * r.w;
				assert_true(E1 <= E0 / (1 - lambda * lambda));
				if (mus[k] == 0) {
					assert_memory_equal(r.v, r0.v, sizeof r.v);
					assert_true(r.w == 0);
					continue;
				}
				double vt = V_DISK * cos(th), vn = V_DISK * sin(th), ratio = fabs(r.Jt) / r.Jn;
				if (sch == 0)
					print_message("oblique %2.0f deg, mu %.2f: J_t/J_n %.4f, spin %.1f rad/s, energy out/in %.4f, "
					              "largest |F_t|/(mu F_n) %.4f\n", angles[a], mus[k], ratio, r.w, E1 / E0, r.ftmax);
				if (3 * mus[k] * 2 * vn < vt)
					assert_true(fabs(ratio / mus[k] - 1) < 0.02);
				else
					assert_true(ratio <= mus[k] * (1 + 1e-9));
				/* friction slows the sliding and spins the disk clockwise (about -z) */
				assert_true(r.v[0] < vt && r.w < 0);
			}
		}
}

/* A disk rolling, then sliding with friction, across a joint of two
 * collinear segments, driven at a fixed overlap: the normal and the
 * tangential force change by less than 5 % of the normal force across the
 * joint with both schemes; the naive scheme doubles the normal force. */
static void test_rolling_joint(void **state)
{
	(void)state;
	const double delta = 1e-3 * R_DISK, b = sqrt(delta * (2 * R_DISK - delta)), vx = 1.0, mu = 0.3;
	const double X1[2][2] = { { -20 * b, 0 }, { 0, 0 } }, X2[2][2] = { { 0, 0 }, { 20 * b, 0 } };
	for (int roll = 0; roll < 2; roll++)
		for (int sch = 0; sch < 3; sch++) {
			dem_contact_param_t p = { .friction = 1, .mu = mu, .partial = SCHEME(sch) };
			law2(&p.law, 2.5, 1.5);
			dem_contact_model_t cm;
			model(&cm, &p);
			dem_sphere_t sp = { .R = R_DISK, .kn = dem_law_kn(&p.law, R_DISK) };
			double Fn0 = dem_law_force(&p.law, sp.kn, delta);
			sp.x[0] = -3 * b, sp.x[1] = R_DISK - delta, sp.v[0] = vx;
			sp.w[2] = roll ? -vx / (R_DISK - delta) : 0;  /* rolling: no slip at C, at depth R - delta */
			dem_contact_state_t s1, s2;
			dem_contact_state_reset(&s1);
			dem_contact_state_reset(&s2);
			const double dt = 0.002 * b / vx;
			double devn = 0, devt = 0, jumpn = 0, jumpt = 0, pn = -1, pt = 0, ftmax = 0;
			for (int n = 0; sp.x[0] < 3 * b; n++) {
				dem_seg_out_t o1, o2;
				double F[2] = { 0, 0 };
				if (dem_contact_disk_segment(&cm, &sp, X1, NULL, M_DISK, dt, &s1, &o1))
					F[0] += o1.c.F[0], F[1] += o1.c.F[1], ftmax = fmax(ftmax, o1.c.Ft / (mu * o1.c.Fn));
				if (dem_contact_disk_segment(&cm, &sp, X2, NULL, M_DISK, dt, &s2, &o2))
					F[0] += o2.c.F[0], F[1] += o2.c.F[1], ftmax = fmax(ftmax, o2.c.Ft / (mu * o2.c.Fn));
				sp.x[0] += vx * dt;
				if (n < 1000)
					continue;  /* the friction force built up */
				double fn = F[1], ft = F[0];
				devn = fmax(devn, fabs(fn / Fn0 - 1));
				/* sliding: -mu Fn; rolling: none */
				devt = fmax(devt, fabs(ft - (roll ? 0 : -mu * Fn0)) / Fn0);
				if (pn >= 0)
					jumpn = fmax(jumpn, fabs(fn - pn) / Fn0), jumpt = fmax(jumpt, fabs(ft - pt) / Fn0);
				pn = fn, pt = ft;
			}
			print_message("%s across a joint, %s scheme, mu %.1f: F_n off by up to %.2e, F_t by %.2e of F_n; "
			              "step-to-step %.1e, %.1e; |F_t|/(mu F_n) up to %.4f\n", roll ? "rolling" : "sliding",
			              SCHEME_NAME(sch), mu, devn, devt, jumpn, jumpt, ftmax);
			assert_true(devn < 0.05 && devt < 0.05);
			assert_true(ftmax <= 1 + 1e-12);
		}
	/* the naive scheme at the joint: both segments' nearest point is the
	 * joint itself, at distance d: twice the force */
	dem_contact_param_t p = { 0 };
	law2(&p.law, 2.5, 1.5);
	dem_contact_model_t cm;
	model(&cm, &p);
	double F[2], Fs[2];
	row_force(&cm, 0, delta, 20 * b, -1, F);
	row_force(&cm, 0, delta, 20 * b, DEM_PARTIAL_AREA, Fs);
	print_message("naive scheme at the joint: %.3f of the full contact force (area scheme %.6f)\n",
	              F[1] / dem_law_force(&p.law, dem_law_kn(&p.law, R_DISK), delta),
	              Fs[1] / dem_law_force(&p.law, dem_law_kn(&p.law, R_DISK), delta));
	assert_true(F[1] > 1.9 * dem_law_force(&p.law, dem_law_kn(&p.law, R_DISK), delta));
}

/* Two disks, oblique, with friction, through dem_contact_sphere_sphere in
 * the plane: the force stays in the plane, momentum and angular momentum
 * are kept, and with the separation correction the energy too. */
static void test_disk_pair(void **state)
{
	(void)state;
	const double R1 = R_DISK, R2 = 0.6 * R_DISK, M1 = RHO * DEM_PI * R1 * R1, M2 = RHO * DEM_PI * R2 * R2;
	const double I1 = 0.5 * M1 * R1 * R1, I2 = 0.5 * M2 * R2 * R2, meff = dem_contact_meff(M1, M2);
	for (int fric = 0; fric < 2; fric++) {
		dem_contact_param_t p = { .friction = fric, .mu = 0.3 };
		law2(&p.law, 2.5, 1.5);
		dem_contact_model_t cm;
		model(&cm, &p);
		double kn = dem_law_kn(&p.law, dem_law_reff(R1, R2));
		dem_sphere_t s1 = { .R = R1 }, s2 = { .R = R2, .x = { 0.5 * (R1 + R2), R1 + R2 + 1e-4 }, .v = { 0, -V_DISK } };
		dem_contact_state_t st;
		dem_contact_state_reset(&st);
		double dtp = 0, L0 = M2 * (s2.x[0] * s2.v[1] - s2.x[1] * s2.v[0]), E0 = 0.5 * M2 * V_DISK * V_DISK;
		int touched = 0, apart = 0;
		for (long n = 0; n < 1000000 && apart < 3; n++) {
			double d[3], w[3];
			for (int i = 0; i < 3; i++)
				d[i] = s2.x[i] - s1.x[i], w[i] = s2.v[i] - s1.v[i];
			double dist = hypot(d[0], d[1]), delta = R1 + R2 - dist, vn = -(d[0] * w[0] + d[1] * w[1]) / dist;
			double dt = dem_contact_dt(&cm, kn, meff, delta, delta > 0 ? vn : hypot(w[0], w[1]), 0.2);
			double h = 0.5 * (dtp + dt), F[3] = { 0, 0, 0 }, T1 = 0, T2 = 0;
			dem_contact_state_t keep = st;
			dem_pair_out_t o;
			if (dem_contact_sphere_sphere(&cm, &s1, &s2, kn, meff, dt, &st, &o)) {
				assert_true(o.c.F[2] == 0 && o.c.T[0] == 0 && o.c.T[1] == 0 && o.T1[0] == 0 && o.T1[1] == 0);
				memcpy(F, o.c.F, sizeof F);
				T2 = o.c.T[2], T1 = o.T1[2];
				dem_sepfix_record(&st, o.n, w, o.c.Fe, h);
				touched = 1;
			} else if (touched) {
				if (!apart) {
					double nn[3] = { d[0] / dist, d[1] / dist, 0 }, J[3];
					dem_sepfix_release(&cm, &keep, kn, meff, nn, w, J);
					for (int i = 0; i < 3; i++)
						F[i] = J[i] / h;
				}
				apart++;
			}
			for (int i = 0; i < 2; i++) {
				s2.v[i] += F[i] / M2 * h, s1.v[i] -= F[i] / M1 * h;
				s2.x[i] += s2.v[i] * dt, s1.x[i] += s1.v[i] * dt;
			}
			s2.w[2] += T2 / I2 * h, s1.w[2] += T1 / I1 * h;
			dtp = dt;
		}
		assert_true(touched && apart == 3);
		double P[2] = { M1 * s1.v[0] + M2 * s2.v[0], M1 * s1.v[1] + M2 * s2.v[1] };
		double L = M1 * (s1.x[0] * s1.v[1] - s1.x[1] * s1.v[0]) + M2 * (s2.x[0] * s2.v[1] - s2.x[1] * s2.v[0])
		           + I1 * s1.w[2] + I2 * s2.w[2];
		double E = 0.5 * M1 * (s1.v[0] * s1.v[0] + s1.v[1] * s1.v[1]) + 0.5 * M2 * (s2.v[0] * s2.v[0] + s2.v[1] * s2.v[1])
		           + 0.5 * I1 * s1.w[2] * s1.w[2] + 0.5 * I2 * s2.w[2] * s2.w[2];
		print_message("disk pair, %s: momentum %.1e, %.1e of M2 v; angular momentum off by %.1e; energy out/in %.6f; "
		              "spins %.2f, %.2f rad/s\n", fric ? "friction 0.3" : "frictionless", P[0] / (M2 * V_DISK),
		              P[1] / (M2 * V_DISK) + 1, fabs(L - L0) / fabs(L0), E / E0, s1.w[2], s2.w[2]);
		assert_true(fabs(P[0]) < 1e-12 * M2 * V_DISK && fabs(P[1] + M2 * V_DISK) < 1e-12 * M2 * V_DISK);
		assert_true(fabs(L - L0) < 1e-9 * fabs(L0));
		if (!fric)
			assert_true(fabs(E / E0 - 1) < 1e-12);
		else  /* the bound of the step on the elastic parts (test_contact_impact.c) */
			assert_true(E <= E0 / (1 - 0.2 * 0.2) && s1.w[2] != 0);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_laws_2d),
		cmocka_unit_test(test_ghertz2d),
		cmocka_unit_test(test_winkler2d),
		cmocka_unit_test(test_segment_geom),
		cmocka_unit_test(test_equilibrium),
		cmocka_unit_test(test_potential_gradient),
		cmocka_unit_test(test_potential_flat),
		cmocka_unit_test(test_joint_crossing),
		cmocka_unit_test(test_box31_2d),
		cmocka_unit_test(test_alpha_range),
		cmocka_unit_test(test_oblique_friction),
		cmocka_unit_test(test_rolling_joint),
		cmocka_unit_test(test_disk_pair),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
