/* test_body.c - unit tests of lib/body: rigid 2D bodies with the
 * Feng-Owen contact (Han 2004, Ch. 4).
 *
 * References: closed forms for the mass properties (square: A = L^2,
 * J = L^4/6; disk: pi a^2, pi a^4/2), for the contact of a square lying
 * flat on a wall (F = kn L along the wall's normal, through the centroid,
 * linear law) and for the secant stiffness of Box 3.1 (flat side:
 * K = 2 kn^2 L^2 / (M v0^2); right-angled corner: K = 2 kn; Hertz-type on a
 * flat side: K = kn sqrt(L u) L / u, u = (3 E0 / (2 kn))^(2/3) / L);
 * conservation laws (the energy of a frictionless, undamped superquadric
 * bouncing on a wall under gravity, 100 impacts, Hertz-type law; linear and angular
 * momentum of two bodies in contact, with friction and damping, to
 * round-off); the degenerate contacts (touching without area, one body
 * inside the other, corner on corner) give no force and no NaN; absent
 * effects and the same effects at zero give the same motion bit for bit;
 * the body stream read back gives the bodies' values exactly (text,
 * binary, gzip); a scene with a bad or missing key is refused naming
 * file:line:col.
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

#include "body/body.h"
#include "body/frames.h"
#include "body/setup.h"
#include "core/cli.h"
#include "core/consts.h"
#include "core/rng.h"
#include "io/scene.h"

#define TMPDIR_PREFIX "/tmp/dem-body-"
#include "slow.h"
#include "tmpdir.h"

static dem_de_param_t param(dem_wlaw_t law, double kn)
{
	dem_de_param_t p;
	memset(&p, 0, sizeof p);
	p.law = law;
	p.kn = kn;
	p.p = 2;
	p.density = 2500;
	p.lambda = 0.2;
	p.v0 = 1;
	p.algo = DEM_DETECT_DCELL;
	return p;
}

static void test_shapes(void **state)
{
	(void)state;
	dem_shape_t s;
	dem_error_t e = {0};
	double L = 2e-3 * sqrt(2) / 2 * 2;   /* side of the square of circumradius 2 mm */
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_POLYGON, 2e-3, 0, 4, 0, &e), 0);
	assert_int_equal(s.nv, 4);
	assert_true(fabs(s.A - L * L) < 1e-15 * L * L);
	assert_true(fabs(s.J - L * L * L * L / 6) < 1e-12 * L * L * L * L);
	assert_true(fabs(s.r - 2e-3) < 1e-15);
	/* flat at the bottom: the two lowest points at the same height */
	assert_true(fabs(s.v[0][1] - s.v[3][1]) < 1e-15 * L && s.v[0][1] < 0);
	dem_shape_free(&s);
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_DISK, 1e-3, 0, 0, 0, &e), 0);
	assert_true(fabs(s.A - DEM_PI * 1e-6) < 1e-20 && fabs(s.J - DEM_PI * 1e-12 / 2) < 1e-26);
	dem_shape_free(&s);
	/* the superquadric's polygon: centroid 0, area within the sampling's reach of the curve's */
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_SUPERQUADRIC, 4.5e-3, 3.5e-3, 5, 1e-3, &e), 0);
	dem_area_props_t pr;
	dem_superquadric_props(4.5e-3, 3.5e-3, 5, &pr);
	assert_true(s.A < pr.A && s.A > 0.99 * pr.A);
	dem_shape_free(&s);
	/* refusals */
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_POLYGON, 1e-3, 0, 2, 0, &e), DEM_EINPUT);
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_POLYGON, 1e-3, 0, 4.5, 0, &e), DEM_EINPUT);
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_SUPERQUADRIC, 1e-3, 1e-3, 0.5, 1e-3, &e),
	                 DEM_EINPUT);
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_DISK, -1, 0, 0, 0, &e), DEM_EINPUT);
	dem_shape_free(&s);
}

/* A square lying flat on a floor, overlap depth d: F = kn L up, through
 * the centroid (linear law: W' = kn, bw = L). */
static void test_flat_on_wall(void **state)
{
	(void)state;
	dem_shape_t s;
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(DEM_W_LINEAR, 1e7);
	double L = 4e-3, a = L / sqrt(2), d = 1e-5;
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_POLYGON, a, 0, 4, 0, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 1, &s, &e), 0);
	double A[2] = {-1, 0}, B[2] = {1, 0};
	assert_true(dem_de_add_wall(&de, A, B, 0.01, &e) == 0);
	assert_true(dem_de_add_body(&de, 0, 0.3e-3, L / 2 - d, 0, 0, 0, 0, &e) == 0);
	assert_int_equal(dem_de_start(&de, &e), 0);
	assert_int_equal((int)de.ncontact, 1);
	assert_true(fabs(de.fx[0]) < 1e-9 * p.kn * L);
	assert_true(fabs(de.fy[0] - p.kn * L) < 1e-9 * p.kn * L);
	assert_true(fabs(de.mz[0]) < 1e-9 * p.kn * L * L);
	assert_true(fabs(de.W - p.kn * L * d) < 1e-6 * p.kn * L * d);
	dem_de_free(&de);
	dem_shape_free(&s);
}

/* No area, no force, no NaN: a square just touching the floor, one square
 * on another's corner point, two identical squares at the same pose (one
 * inside the other: S does not change with a small move), a disk wholly
 * inside another. */
static void test_degenerate(void **state)
{
	(void)state;
	dem_shape_t s[2];
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(DEM_W_HERTZ, 1e7);
	double L = 4e-3, a = L / sqrt(2);
	assert_int_equal(dem_shape_init(&s[0], DEM_SHAPE_POLYGON, a, 0, 4, 0, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 1, s, &e), 0);
	double A[2] = {-1, 0}, B[2] = {1, 0};
	assert_true(dem_de_add_wall(&de, A, B, 0.01, &e) == 0);
	dem_de_add_body(&de, 0, 0, L / 2, 0, 0, 0, 0, &e);              /* touching the floor */
	dem_de_add_body(&de, 0, 0.1, 0.1, 0, 0, 0, 0, &e);              /* two at one pose */
	dem_de_add_body(&de, 0, 0.1, 0.1, 0, 0, 0, 0, &e);
	dem_de_add_body(&de, 0, 0.2, 0.1, 0, 0, 0, 0, &e);              /* corner on corner */
	dem_de_add_body(&de, 0, 0.2 + L, 0.1 + L, 0, 0, 0, 0, &e);
	assert_int_equal(dem_de_start(&de, &e), 0);
	assert_int_equal((int)de.ncontact, 0);
	for (size_t i = 0; i < de.n; i++)
		assert_true(de.fx[i] == 0 && de.fy[i] == 0 && de.mz[i] == 0);
	assert_int_equal(dem_de_step(&de, &e), 0);
	dem_de_free(&de);
	dem_shape_free(&s[0]);
	assert_int_equal(dem_shape_init(&s[0], DEM_SHAPE_DISK, 2e-3, 0, 0, 0, &e), 0);
	assert_int_equal(dem_shape_init(&s[1], DEM_SHAPE_DISK, 1e-3, 0, 0, 0, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 2, s, &e), 0);
	dem_de_add_body(&de, 0, 0, 0, 0, 0, 0, 0, &e);
	dem_de_add_body(&de, 1, 0.5e-3, 0, 0, 0, 0, 0, &e);             /* inside */
	dem_de_add_body(&de, 1, 0.1, 0, 0, 0, 0, 0, &e);
	dem_de_add_body(&de, 1, 0.1 + 2e-3, 0, 0, 0, 0, 0, &e);         /* touching */
	assert_int_equal(dem_de_start(&de, &e), 0);
	assert_int_equal((int)de.ncontact, 0);
	dem_de_free(&de);
	dem_shape_free(&s[0]);
	dem_shape_free(&s[1]);
	/* disks and polygons in one run are refused */
	assert_int_equal(dem_shape_init(&s[0], DEM_SHAPE_DISK, 2e-3, 0, 0, 0, &e), 0);
	assert_int_equal(dem_shape_init(&s[1], DEM_SHAPE_POLYGON, 2e-3, 0, 3, 0, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 2, s, &e), DEM_EINPUT);
	dem_de_free(&de);
	dem_shape_free(&s[0]);
	dem_shape_free(&s[1]);
}

/* A disk against a wall's rectangle, across its face and round its end:
 * the overlap area (the contact energy kn S of the linear law) against the
 * circle's inscribed polygon clipped by the rectangle (an independent
 * method, the polygon within 1e-9 of the circle's area), and the force
 * against the finite differences of kn S (it is the energy's gradient). */
static void test_disk_wall(void **state)
{
	(void)state;
	dem_shape_t s;
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(DEM_W_LINEAR, 1e7);
	double r = 2e-3, A[2] = {0, 0}, B[2] = {0.05, 0};
	static double v[1 << 17][2], o[1 << 18][2], w[1 << 18][2];
	static unsigned char side[1 << 18];
	int nv = dem_superquadric_polygon(r, r, 2, 1e-5, 1 << 17, v);
	assert_true(nv > 0 && nv <= 1 << 17);
	dem_area_props_t pr;
	dem_polygon_props(nv, (const double (*)[2])v, &pr);
	assert_true(fabs(pr.A - DEM_PI * r * r) < 1e-9 * DEM_PI * r * r);
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_DISK, r, 0, 0, 0, &e), 0);
	/* centres: across the face, over the end A, past it, half in, beyond the centre */
	static const double at[][2] = {{0.02, 1.5e-3}, {0.5e-3, 1e-3}, {-1e-3, 1e-3},
	                               {-1.2e-3, -0.5e-3}, {0.01, -0.7e-3}};
	for (size_t k = 0; k < sizeof at / sizeof *at; k++) {
		double x[3] = {at[k][0] - 1e-9, at[k][0], at[k][0] + 1e-9}, Wx[3], Wy[3];
		double Fx = 0, Fy = 0, W = 0;
		for (int d = 0; d < 2; d++)
			for (int q = 0; q < 3; q++) {
				assert_int_equal(dem_de_init(&de, &p, 1, &s, &e), 0);
				assert_true(dem_de_add_wall(&de, A, B, 0.01, &e) == 0);
				double xc = d == 0 ? x[q] : at[k][0], yc = at[k][1] + (d == 1 ? x[q] - at[k][0] : 0);
				dem_de_add_body(&de, 0, xc, yc, 0, 0, 0, 0, &e);
				assert_int_equal(dem_de_start(&de, &e), 0);
				(d == 0 ? Wx : Wy)[q] = de.W;
				if (q == 1 && d == 0)
					Fx = de.fx[0], Fy = de.fy[0], W = de.W;
				dem_de_free(&de);
			}
		/* the reference area: the fine polygon clipped by the rectangle */
		double Q[4][2] = {{B[0], B[1]}, {A[0], A[1]}, {A[0], A[1] - 0.01}, {B[0], B[1] - 0.01}};
		static double pv[1 << 17][2];
		double c[2] = {at[k][0], at[k][1]};
		dem_polygon_place(nv, (const double (*)[2])v, c, 0, pv);
		dem_overlap_t ov;
		dem_polygon_clip(nv, (const double (*)[2])pv, 4, (const double (*)[2])Q, o, side, w, &ov);
		if (getenv("TEST_VERBOSE"))
			fprintf(stderr, "# disk/wall %zu: S %.9g ref %.9g, F (%.6g, %.6g) fd (%.6g, %.6g)\n", k,
			        W / p.kn, ov.S, Fx, Fy, -(Wx[2] - Wx[0]) / 2e-9, -(Wy[2] - Wy[0]) / 2e-9);
		assert_true(W > 0);
		assert_true(fabs(W / p.kn - ov.S) < 1e-8 * DEM_PI * r * r);
		double F = hypot(Fx, Fy);
		assert_true(fabs(Fx + (Wx[2] - Wx[0]) / 2e-9) < 1e-5 * F);
		assert_true(fabs(Fy + (Wy[2] - Wy[0]) / 2e-9) < 1e-5 * F);
	}
	dem_shape_free(&s);
}

/* Box 3.1's secant stiffness against its closed forms. */
static void test_secant(void **state)
{
	(void)state;
	dem_shape_t s;
	dem_error_t e = {0};
	double L = 4e-3, a = L / sqrt(2), M = 0.01, v0 = 0.5, E0 = 0.5 * M * v0 * v0, K, u;
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_POLYGON, a, 0, 4, 0, &e), 0);
	dem_de_param_t p = param(DEM_W_LINEAR, 1e7);
	/* flat side: S = L u, F = kn L */
	assert_int_equal(dem_shape_secant(&s, 0, &p, M, v0, &K, &u, &e), 0);
	double Kc = 2 * p.kn * p.kn * L * L / (M * v0 * v0);
	assert_true(fabs(K - Kc) < 1e-9 * Kc);
	assert_true(fabs(u - E0 / (p.kn * L)) < 1e-9 * u);
	/* corner: S = u^2, bw = 2 u */
	assert_int_equal(dem_shape_secant(&s, DEM_PI / 4, &p, M, v0, &K, &u, &e), 0);
	assert_true(fabs(K - 2 * p.kn) < 1e-9 * p.kn);
	/* Hertz-type on the flat side */
	p = param(DEM_W_HERTZ, 1e9);
	assert_int_equal(dem_shape_secant(&s, 0, &p, M, v0, &K, &u, &e), 0);
	double uc = pow(1.5 * E0 / p.kn, 2.0 / 3) / L;
	Kc = p.kn * sqrt(L * uc) * L / uc;
	assert_true(fabs(u - uc) < 1e-9 * uc);
	assert_true(fabs(K - Kc) < 1e-8 * Kc);
	/* too soft: the body would sink through the wall */
	p = param(DEM_W_LINEAR, 1);
	assert_int_equal(dem_shape_secant(&s, 0, &p, M, v0, &K, &u, &e), DEM_ENUMERIC);
	dem_shape_free(&s);
	/* the run's step: no larger than the closed forms' (K is the largest over the orientations) */
	dem_de_t de;
	p = param(DEM_W_LINEAR, 1e7);
	p.v0 = v0;
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_POLYGON, a, 0, 4, 0, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 1, &s, &e), 0);
	dem_de_add_body(&de, 0, 0, 0, 0, 0, 0, 0, &e);
	assert_int_equal(dem_de_timestep(&de, &e), 0);
	double m = de.mass[0], I = de.inertia[0], Me = 0.5 / (1 / m + a * a / I);
	double Kf = 2 * p.kn * p.kn * L * L / (Me * v0 * v0);
	assert_true(de.K >= fmax(Kf, 2 * p.kn) * (1 - 1e-9));
	assert_true(fabs(de.dt - p.lambda * 2 * sqrt(Me / de.K)) < 1e-12 * de.dt);
	dem_de_free(&de);
	dem_shape_free(&s);
}

/* The hopper's superquadric (a 4.5, b 3.5 mm, exponent m), frictionless and
 * undamped, dropped tilted and spinning on a floor under gravity: its
 * energy (kinetic + potential + W(S)) between impacts stays within 1e-3
 * of the start's over 100 impacts. */
static void run_bounce(dem_wlaw_t law, double kn, double m, double lambda, double *drift,
                       long *steps)
{
	dem_shape_t s;
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(law, kn);
	p.gravity = 1;
	p.g[1] = -9.81;
	p.lambda = lambda;
	double h = 2e-3;
	p.v0 = 2 * sqrt(2 * 9.81 * 2 * h);
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_SUPERQUADRIC, 4.5e-3, 3.5e-3, m, 1e-3, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 1, &s, &e), 0);
	double A[2] = {-1, 0}, B[2] = {1, 0};
	dem_de_add_wall(&de, A, B, 0.01, &e);
	dem_de_add_body(&de, 0, 0, 4.5e-3 + h, 0.3, 0.05, 0, 2.0, &e);
	assert_int_equal(dem_de_start(&de, &e), 0);
	double E0 = dem_de_energy(&de), dmax = 0;
	int impacts = 0, was = 0;
	while (impacts < 100) {
		assert_int_equal(dem_de_step(&de, &e), 0);
		int in = de.ncontact > 0;
		if (in && !was)
			impacts++;
		if (!in)
			dmax = fmax(dmax, fabs(dem_de_energy(&de) - E0) / E0);
		was = in;
		assert_true(de.steps < 20000000);
	}
	*drift = dmax;
	*steps = de.steps;
	dem_de_free(&de);
	dem_shape_free(&s);
}

static void test_energy(void **state)
{
	(void)state;
	/* the drift falls with the step (m = 2: 3.5e-3 at lambda = 0.2,
	 * 7.6e-4 at 0.1, 1.1e-4 at 0.05): the m = 2 ellipse at 0.1, the
	 * blockier m = 5 at the default 0.2 */
	static const struct { double m, lambda; } run[] = {{2, 0.1}, {5, 0.2}};
	/* under the sanitizers the first case only (slow.h) */
	for (int k = 0; k < SLOW_CASES(2, 1); k++) {
		double d;
		long n;
		run_bounce(DEM_W_HERTZ, 1e10, run[k].m, run[k].lambda, &d, &n);
		if (getenv("TEST_VERBOSE"))
			fprintf(stderr, "# energy: Hertz-type law, m = %g, lambda = %g: drift %.3g "
			        "over 100 impacts (%ld steps)\n", run[k].m, run[k].lambda, d, n);
		assert_true(d < 1e-3);
	}
}

/* Two bodies in contact, with friction and damping: the total momentum
 * and angular momentum about the origin are kept to round-off. */
static void run_momentum(int kind1, double a1, double b1, double m1, int kind2, double a2,
                         double b2, double m2)
{
	dem_shape_t s[2];
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(DEM_W_LINEAR, 1e7);
	p.friction = 1, p.mu = 0.5;
	p.damping = 1, p.xi = 0.3;
	p.v0 = 2;
	assert_int_equal(dem_shape_init(&s[0], kind1, a1, b1, m1, 1e-3, &e), 0);
	assert_int_equal(dem_shape_init(&s[1], kind2, a2, b2, m2, 1e-3, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 2, s, &e), 0);
	dem_de_add_body(&de, 0, 0.01, 0.02, 0.4, 0.5, 0.1, 30, &e);
	dem_de_add_body(&de, 1, 0.01 + 0.85 * (a1 + a2), 0.0215, -0.2, -0.5, 0.05, -20, &e);
	assert_int_equal(dem_de_start(&de, &e), 0);
	/* the scales: the sums of the terms' sizes */
	double P0[3] = {0, 0, 0}, scale = 0, scaleL = 0;
	for (size_t i = 0; i < 2; i++) {
		double m = de.mass[i];
		P0[0] += m * de.vx[i], P0[1] += m * de.vy[i];
		P0[2] += m * (de.x[i] * de.vy[i] - de.y[i] * de.vx[i]) + de.inertia[i] * de.w[i];
		scale += m * hypot(de.vx[i], de.vy[i]);
		scaleL += m * hypot(de.x[i], de.y[i]) * hypot(de.vx[i], de.vy[i]) +
		          de.inertia[i] * fabs(de.w[i]);
	}
	long contact = 0;
	double err = 0, errL = 0;
	for (int k = 0; k < 4000; k++) {
		assert_int_equal(dem_de_step(&de, &e), 0);
		contact += de.ncontact > 0;
		double P[3] = {0, 0, 0};
		for (size_t i = 0; i < 2; i++) {
			double m = de.mass[i];
			P[0] += m * de.vx[i], P[1] += m * de.vy[i];
			P[2] += m * (de.x[i] * de.vy[i] - de.y[i] * de.vx[i]) + de.inertia[i] * de.w[i];
		}
		err = fmax(err, hypot(P[0] - P0[0], P[1] - P0[1]) / scale);
		errL = fmax(errL, fabs(P[2] - P0[2]) / scaleL);
	}
	if (getenv("TEST_VERBOSE"))
		fprintf(stderr, "# momentum: %s/%s: %ld steps in contact, linear %.2g, angular %.2g\n",
	        dem_shape_kind_name(kind1), dem_shape_kind_name(kind2), contact, err, errL);
	assert_true(contact > 10);
	assert_true(err < 1e-12);
	assert_true(errL < 1e-12);
	dem_de_free(&de);
	dem_shape_free(&s[0]);
	dem_shape_free(&s[1]);
}

static void test_momentum(void **state)
{
	(void)state;
	run_momentum(DEM_SHAPE_SUPERQUADRIC, 4.5e-3, 3.5e-3, 5, DEM_SHAPE_SUPERQUADRIC, 4.5e-3,
	             3.5e-3, 15);
	run_momentum(DEM_SHAPE_POLYGON, 4e-3, 0, 3, DEM_SHAPE_POLYGON, 4e-3, 0, 4);
	run_momentum(DEM_SHAPE_DISK, 4e-3, 0, 0, DEM_SHAPE_DISK, 3e-3, 0, 0);
}

/* Absent effects and the same effects at zero: the same motion, bit for bit. */
static void run_pile(int friction, int damping, double *out)
{
	dem_shape_t s;
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(DEM_W_LINEAR, 1e7);
	p.friction = friction, p.mu = 0;
	p.damping = damping, p.xi = 0;
	p.gravity = 1, p.g[1] = -9.81;
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_SUPERQUADRIC, 4.5e-3, 3.5e-3, 2, 1e-2, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 1, &s, &e), 0);
	double A[2] = {-1, 0}, B[2] = {1, 0};
	dem_de_add_wall(&de, A, B, 0.01, &e);
	for (int k = 0; k < 6; k++)
		dem_de_add_body(&de, 0, 0.0085 * (k % 3) + 0.001 * k, 0.004 + 0.008 * (k / 3), 0.3 * k,
		                0, 0, 0, &e);
	assert_int_equal(dem_de_start(&de, &e), 0);
	for (int k = 0; k < 3000; k++)
		assert_int_equal(dem_de_step(&de, &e), 0);
	for (size_t i = 0; i < de.n; i++)
		out[3 * i] = de.x[i], out[3 * i + 1] = de.y[i], out[3 * i + 2] = de.th[i];
	dem_de_free(&de);
	dem_shape_free(&s);
}

static void test_effects_at_zero(void **state)
{
	(void)state;
	double a[18], b[18], c[18];
	run_pile(0, 0, a);
	run_pile(1, 0, b);
	run_pile(0, 1, c);
	assert_memory_equal(a, b, sizeof a);
	assert_memory_equal(a, c, sizeof a);
}

/* Frames written and read back: every value exact, in each format. */
static void test_stream_round_trip(void **state)
{
	(void)state;
	dem_shape_t s;
	dem_de_t de;
	dem_error_t e = {0};
	dem_de_param_t p = param(DEM_W_LINEAR, 1e7);
	p.gravity = 1, p.g[1] = -9.81;
	assert_int_equal(dem_shape_init(&s, DEM_SHAPE_SUPERQUADRIC, 4.5e-3, 3.5e-3, 15, 1e-2, &e), 0);
	assert_int_equal(dem_de_init(&de, &p, 1, &s, &e), 0);
	double A[2] = {-0.1, 0}, B[2] = {0.1, 0};
	dem_de_add_wall(&de, A, B, 0.01, &e);
	for (int k = 0; k < 5; k++)
		dem_de_add_body(&de, 0, 0.01 * k, 0.005 + 0.001 * k, 0.7 * k, 0.1 * k, -0.2, 3.0 / 7 * k, &e);
	assert_int_equal(dem_de_start(&de, &e), 0);
	const int flags[3] = {0, DEM_STREAM_BINARY, DEM_STREAM_GZIP};
	for (int f = 0; f < 3; f++) {
		dem_writer_t *w;
		const char *file = path("bodies.txt");
		char *argv[] = {"test", NULL};
		assert_int_equal(dem_bodies_writer_open(&w, file, &de, "test", 1, argv, 1, 7, flags[f], &e), 0);
		assert_int_equal(dem_bodies_write_frame(w, &de, 0, &e), 0);
		assert_int_equal(dem_de_step(&de, &e), 0);
		assert_int_equal(dem_bodies_write_frame(w, &de, 1, &e), 0);
		assert_int_equal(dem_writer_close(w, &e), 0);
		dem_reader_t *r;
		dem_body_row_t row;
		if (dem_bodies_reader_open(&r, file, &e))
			fprintf(stderr, "# %s\n", e.msg);
		assert_int_equal(e.code, 0);
		const char *wl = dem_header_get(dem_reader_header(r), "wall");
		assert_non_null(wl);
		assert_string_equal(wl, "-0.1 0 0.1 0 0.01");
		int rows = 0;
		while (dem_bodies_reader_next(r, &row, &e) == 1) {
			size_t i = row.id;
			assert_true(i < de.n);
			if (row.frame == 1) {
				assert_true(row.t == de.t);
				assert_true(row.x == de.x[i] && row.y == de.y[i] && row.th == de.th[i]);
				assert_true(row.vx == de.vx[i] && row.vy == de.vy[i] && row.w == de.w[i]);
			}
			assert_true(row.shape == 0 && row.a == 4.5e-3 && row.b == 3.5e-3 && row.m == 15);
			rows++;
		}
		if (e.code)
			fprintf(stderr, "# %s\n", e.msg);
		assert_int_equal(e.code, 0);
		assert_int_equal(rows, 10);
		dem_reader_close(r);
	}
	/* another kind of stream is refused */
	write_text(path("p.txt"), "# dem particles 1\n# dim 2\n# columns x:f64:m y:f64:m r:f64:m\n"
	           "# format text\n# data\n0 0 1\n# end 1\n");
	dem_reader_t *r;
	assert_int_equal(dem_bodies_reader_open(&r, path("p.txt"), &e), DEM_EINPUT);
	if (!strstr(e.msg, "expected a body stream"))
		fprintf(stderr, "# %s\n", e.msg);
	assert_non_null(strstr(e.msg, "expected a body stream"));
	/* a shape code beyond the three, up to the largest a u32 column holds
	 * (found by fuzzing: it was converted to int before it was checked),
	 * is refused by the row's reader */
	static const char *const codes[] = {"3", "2147483648", "4294967295"};
	for (int k = 0; k < 3; k++) {
		char text[512];
		snprintf(text, sizeof text, "# dem bodies 1\n# dim 2\n# columns frame:u32:- t:f64:s id:u32:- "
			 "shape:u32:- a:f64:m b:f64:m m:f64:- x:f64:m y:f64:m theta:f64:rad vx:f64:m/s "
			 "vy:f64:m/s w:f64:rad/s\n# format text\n# data\n0 0 0 %s 1 1 2 0 0 0 0 0 0\n"
			 "# end 1\n", codes[k]);
		write_text(path("s.txt"), text);
		dem_body_row_t row;
		memset(&e, 0, sizeof e);
		assert_int_equal(dem_bodies_reader_open(&r, path("s.txt"), &e), 0);
		assert_int_equal(dem_bodies_reader_next(r, &row, &e), -1);
		char want[48];
		snprintf(want, sizeof want, "shape %s: expected 0, 1 or 2", codes[k]);
		if (!strstr(e.msg, want))
			fprintf(stderr, "# %s\n", e.msg);
		assert_non_null(strstr(e.msg, want));
		dem_reader_close(r);
	}
	/* the VTK polygons: one cell a body and a wall */
	assert_int_equal(dem_bodies_vtu(path("b.vtu"), &de, &e), 0);
	FILE *fp = fopen(path("b.vtu"), "r");
	assert_non_null(fp);
	char line[256];
	int cells = -1;
	while (fgets(line, sizeof line, fp))
		if (sscanf(line, "<Piece NumberOfPoints=\"%*d\" NumberOfCells=\"%d\"", &cells) == 1)
			break;
	fclose(fp);
	assert_int_equal(cells, 6);
	dem_de_free(&de);
	dem_shape_free(&s);
}

/* Load text as a scene and read it as a DE-only run (setup and the
 * unknown-key check): the code, e filled; the run's bodies and the shape's
 * points through n and nv. */
static int from_scene(const char *text, dem_error_t *e, size_t *n, int *nv)
{
	dem_scene_t *sc;
	dem_de_setup_t su;
	dem_de_t de;
	int have = 1;
	unsigned long seed = 1;
	gsl_rng *rng = dem_rng_new(&have, &seed);
	write_text(path("s.yaml"), text);
	assert_int_equal(dem_scene_load(&sc, path("s.yaml"), e), 0);
	int rc = dem_de_setup_read(sc, DEM_ACCURACY_NORMAL, rng, &su, &de, e);
	if (!rc) {
		rc = dem_scene_check(sc, dem_de_sections, e);
		*n = de.n, *nv = su.shape.nv;
		dem_de_setup_free(&su, &de);
	}
	dem_scene_free(sc);
	gsl_rng_free(rng);
	return rc;
}

/* A scene's mistake: refused with its place in the file. */
static void refuse(const char *text, const char *want)
{
	dem_error_t e = {0};
	size_t n;
	int nv;
	int rc = from_scene(text, &e, &n, &nv);
	if (rc != DEM_EINPUT || !strstr(e.msg, want))
		fprintf(stderr, "# got %d '%s', want '%s'\n", rc, e.msg, want);
	assert_int_equal(rc, DEM_EINPUT);
	assert_non_null(strstr(e.msg, want));
}

static void test_scene_refusals(void **state)
{
	(void)state;
	const char *ok = "bodies:\n  shape: polygon\n  sides: 3\n  a: 4 mm\n"
	                 "  at: [0 mm, 10 mm, 20 mm, 10 mm]\n"
	                 "contact:\n  kn: 1e6 Pa\nrun:\n  end: 1 ms\n  gravity: [0, -9.81 m/s^2]\n";
	char buf[1024];
	/* the good one passes */
	dem_error_t e = {0};
	size_t n = 0;
	int nv = 0;
	assert_int_equal(from_scene(ok, &e, &n, &nv), 0);
	assert_int_equal((int)n, 2);
	assert_int_equal(nv, 3);
	snprintf(buf, sizeof buf, "%s  colour: red\n", ok);
	refuse(buf, "s.yaml:11:3: unknown key 'run.colour'");
	refuse("bodies:\n  shape: star\n  a: 1 mm\n", "s.yaml:2:10: bodies.shape");
	refuse("bodies:\n  a: 1 mm\n  at: [0 mm, 0 mm]\nrun:\n  end: 1 s\n", "contact.kn: missing");
	refuse("bodies:\n  a: 1 mm\n  at: [0 mm, 0 mm, 1 mm]\ncontact:\n  kn: 1 Pa\nrun:\n  end: 1 s\n",
	       "s.yaml:3:7: bodies.at: expected x, y pairs");
	refuse("bodies:\n  a: 1 mm\n  count: 50\n  region: [0 mm, 0 mm, 10 mm, 10 mm]\n"
	       "contact:\n  kn: 1 Pa\nrun:\n  end: 1 s\n", "s.yaml:4:11: bodies.region: room for 16 bodies");
	refuse("bodies:\n  shape: polygon\n  sides: 2\n  a: 1 mm\n", "s.yaml:3:10: bodies.sides");
	refuse("bodies:\n  a: 1 mm\n  at: [0 mm, 0 mm]\ncontact:\n  kn: 1 Pa\nrun:\n  end: 1 s\n",
	       "run.speed: missing");
	refuse("bodies:\n  a: 1 mm\n  at: [0 mm, 0 mm]\nwalls:\n  segments: [0 mm, 0 mm, 1 mm]\n"
	       "contact:\n  kn: 1 Pa\nrun:\n  end: 1 s\n  speed: 1 m/s\n", "s.yaml:5:13: walls.segments");
	refuse("bodies:\n  a: 1 mm\n  at: [0 mm, 0 mm]\nwalls:\n  segments: [0 mm, 0 mm, 0 mm, 0 mm]\n"
	       "contact:\n  kn: 1 Pa\nrun:\n  end: 1 s\n  speed: 1 m/s\n", "wall 1: wall");
	refuse("bodies:\n  a: 1 mm\n  at: [0 mm, 0 mm]\ncontact:\n  kn: 1 mm\nrun:\n  end: 1 s\n",
	       "s.yaml:5:7: contact.kn");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_shapes),
		cmocka_unit_test(test_flat_on_wall),
		cmocka_unit_test(test_degenerate),
		cmocka_unit_test(test_disk_wall),
		cmocka_unit_test(test_secant),
		cmocka_unit_test(test_momentum),
		cmocka_unit_test(test_effects_at_zero),
		cmocka_unit_test(test_stream_round_trip),
		cmocka_unit_test(test_scene_refusals),
		cmocka_unit_test(test_energy),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
