/* test_contact_friction.c - unit tests of the friction model of
 * lib/contact/model.c (Han 2004, Eqs. 3.54-3.62).
 *
 * References: the Coulomb cone |F_t| <= mu F_n (Eq. 3.61) under random
 * sliding, rotating normals and falling normal force; the elasto-perfectly
 * plastic loop of Fig. 3.10 under an oscillating tangential displacement
 * u = A sin(w t) at constant F_n: force -k_t u while sticking, +-mu F_n
 * while slipping, reversal along k_t, loop area 4 mu F_n (A - mu F_n/k_t),
 * and no loss at all when A < mu F_n / k_t; the co-rotation: under a rigid
 * rotation of the contact (no relative sliding) the stored force keeps its
 * length, stays in the contact plane and turns with the body.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/model.h"
#include "core/consts.h"

static double urand(unsigned long *s)  /* [-1, 1) */
{
	*s = *s * 6364136223846793005ul + 1442695040888963407ul;
	return ((*s >> 11) * (1.0 / 9007199254740992.0)) * 2 - 1;
}

static double dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize(double a[3])
{
	double l = sqrt(dot(a, a));
	for (int i = 0; i < 3; i++)
		a[i] /= l;
}

/* Rodrigues: rotate v about the unit axis k by angle t */
static void rotate(const double k[3], double t, const double v[3], double out[3])
{
	double c = cos(t), s = sin(t), kv = dot(k, v), kx[3];
	kx[0] = k[1] * v[2] - k[2] * v[1];
	kx[1] = k[2] * v[0] - k[0] * v[2];
	kx[2] = k[0] * v[1] - k[1] * v[0];
	for (int i = 0; i < 3; i++)
		out[i] = v[i] * c + kx[i] * s + k[i] * kv * (1 - c);
}

static void test_cone(void **state)
{
	(void)state;
	unsigned long s = 7;
	dem_contact_state_t st;
	dem_contact_state_reset(&st);
	double n[3] = { 0, 0, 1 }, mu = 0.3, Fn = 1, worst = 0;
	for (int k = 0; k < 100000; k++) {
		/* the normal wanders, sometimes jumps; F_n rises and falls */
		double dn[3] = { urand(&s), urand(&s), urand(&s) };
		double step = (k % 1000 == 0) ? 0.5 : 0.02;
		for (int i = 0; i < 3; i++)
			n[i] += step * dn[i];
		normalize(n);
		Fn = fabs(Fn * (1 + 0.2 * urand(&s))) + ((k % 5000 == 0) ? 0 : 1e-3);
		if (k % 777 == 0)
			Fn *= 1e-3;  /* sudden unloading */
		double v[3] = { urand(&s), urand(&s), urand(&s) }, Ft[3];
		dem_friction_step(&st, n, v, urand(&s) * 10, 0.01, 50 * (1 + urand(&s)), mu, Fn, Ft);
		double f = sqrt(dot(Ft, Ft));
		worst = fmax(worst, f / (mu * Fn));
		assert_true(f <= mu * Fn * (1 + 1e-12));
		assert_true(fabs(dot(Ft, n)) <= 1e-12 * fmax(f, 1e-300) + 1e-300);
	}
	print_message("friction cone: max |F_t| / (mu F_n) = %.15f over 1e5 random steps\n", worst);
	/* mu = 0: no tangential force at all */
	double v[3] = { 1, 2, 0 }, Ft[3];
	dem_contact_state_reset(&st);
	dem_friction_step(&st, (double[3]){ 0, 0, 1 }, v, 0, 0.1, 10, 0, 5, Ft);
	assert_true(Ft[0] == 0 && Ft[1] == 0 && Ft[2] == 0);
}

/* one oscillation test: returns the dissipated work of the last cycle */
static double oscillate(double A, double kt, double mu, double Fn, const double n[3], const double t1[3],
                        double *max_err)
{
	dem_contact_state_t st;
	dem_contact_state_reset(&st);
	const int N = 4000;  /* steps per cycle */
	const double w = 2 * DEM_PI, dt = 1.0 / N;
	double W = 0, Fp = 0, u_rev = 0, F_rev = 0, up = 0, vprev = 1;
	*max_err = 0;
	for (int k = 0; k < 3 * N; k++) {
		/* velocity over this step, so that u follows A sin(w t) exactly */
		double t0 = k * dt, u1 = A * sin(w * (t0 + dt)), vel = (u1 - up) / dt;
		if (vel * vprev < 0)
			u_rev = up, F_rev = Fp;  /* reversal: the branch starts here */
		vprev = vel;
		double vr[3], Ft[3];
		for (int i = 0; i < 3; i++)
			vr[i] = vel * t1[i] + 0.3 * n[i];  /* a normal component must not matter */
		dem_friction_step(&st, n, vr, 0, dt, kt, mu, Fn, Ft);
		double F = dot(Ft, t1);
		/* Fig. 3.10: from the last reversal, slope -k_t, capped at mu F_n */
		double ref = fmax(-mu * Fn, fmin(mu * Fn, F_rev - kt * (u1 - u_rev)));
		*max_err = fmax(*max_err, fabs(F - ref) / (mu * Fn));
		if (k >= 2 * N)
			W += -0.5 * (F + Fp) * (u1 - up);  /* work done against friction */
		Fp = F, up = u1;
	}
	return W;
}

static void test_stick_slip_reversal(void **state)
{
	(void)state;
	double n[3] = { 0.3, -0.2, 0.9 }, t1[3] = { 1, 0, 0 };
	normalize(n);
	double p = dot(t1, n);
	for (int i = 0; i < 3; i++)
		t1[i] -= p * n[i];
	normalize(t1);
	const double kt = 1000, mu = 0.4, Fn = 10;  /* mu F_n / k_t = 0.004 */
	double err;
	/* slipping cycles: loop area of Fig. 3.10 */
	for (double A = 0.01; A <= 0.05; A += 0.02) {
		double W = oscillate(A, kt, mu, Fn, n, t1, &err);
		double ref = 4 * mu * Fn * (A - mu * Fn / kt);
		assert_true(err < 1e-9);
		assert_true(fabs(W - ref) < 2e-3 * ref);
		print_message("stick/slip A = %.2f: loop area %.6f, Fig. 3.10 gives %.6f\n", A, W, ref);
	}
	/* sticking only: elastic, nothing lost */
	double W = oscillate(0.003, kt, mu, Fn, n, t1, &err);
	assert_true(err < 1e-9);
	assert_true(fabs(W) < 1e-9 * mu * Fn * 0.003);
}

/* Rigid rotation of the contact: the body turns about a fixed axis at a
 * constant rate, the contact turns with it, nothing slides. */
static void test_corotation(void **state)
{
	(void)state;
	double axes[3][3] = { { 1, 0, 0 }, { 0, 0, 1 }, { 0.6, 0.3, 0.74 } };
	for (int a = 0; a < 3; a++) {
		double k[3] = { axes[a][0], axes[a][1], axes[a][2] };
		normalize(k);
		double n0[3] = { 0, 0, 1 }, F0[3] = { 0.3, -0.1, 0 };
		dem_contact_state_t st;
		dem_contact_state_reset(&st);
		memcpy(st.Ft, F0, sizeof F0);
		memcpy(st.n, n0, sizeof n0);
		const double Om = 2.0, dt = 1e-3;  /* rad/s, s: 2 rad in 1000 steps */
		double L0 = sqrt(dot(F0, F0)), maxdev = 0, Ft[3];
		for (int s = 1; s <= 1000; s++) {
			double n[3], ref[3], v0[3] = { 0, 0, 0 };
			rotate(k, Om * s * dt, n0, n);
			rotate(k, Om * s * dt, F0, ref);
			/* mu F_n large: the cone never bites */
			dem_friction_step(&st, n, v0, Om * dot(k, n), dt, 100, 1, 1e3, Ft);
			double L = sqrt(dot(Ft, Ft));
			assert_true(fabs(L - L0) < 1e-12 * L0);
			assert_true(fabs(dot(Ft, n)) < 1e-12 * L0);
			double d[3] = { Ft[0] - ref[0], Ft[1] - ref[1], Ft[2] - ref[2] };
			maxdev = fmax(maxdev, sqrt(dot(d, d)) / L0);
		}
		/* the split tilt + spin follows the rotation to first order in dt */
		assert_true(maxdev < 5e-3);
		print_message("co-rotation about axis %d: |F_t| kept, largest deviation from the rigid rotation %.1e\n",
		              a, maxdev);
	}
	/* a 37-degree tilt of the normal in one step: the stored force turns
	 * with it, length kept (a bare projection would shorten it to 0.8) */
	dem_contact_state_t st;
	dem_contact_state_reset(&st);
	st.Ft[0] = 1, st.n[2] = 1;
	double Ft[3], v0[3] = { 0, 0, 0 };
	dem_friction_step(&st, (double[3]){ 0.6, 0, 0.8 }, v0, 0, 1e-3, 0, 10, 10, Ft);
	assert_true(fabs(sqrt(dot(Ft, Ft)) - 1) < 1e-12);
	assert_true(fabs(Ft[0] - 0.8) < 1e-12 && fabs(Ft[2] + 0.6) < 1e-12);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cone),
		cmocka_unit_test(test_stick_slip_reversal),
		cmocka_unit_test(test_corotation),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
