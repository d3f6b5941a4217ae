/* test_contact_impact.c - a rigid sphere hitting rigid facets, integrated
 * with the central differences of Box 3.1 and the contact time step of
 * lib/contact (Han 2004, Ch. 3): the whole chain geometry -> kernel ->
 * time step, as the explicit driver will use it.
 *
 * References: the Hertz solution of a rigid sphere on an elastic
 * half-space (DESIGN.md, "Verification references"): indentation
 * d = (15 M v^2 / (16 E* sqrt(R)))^(2/5), force (4/3) E* sqrt(R) d^(3/2),
 * contact time c d / v with c = 2 integral_0^1 dx / sqrt(1 - x^(5/2)) =
 * (4/5) B(2/5, 1/2) = (4/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10) = 2.94327
 * (from M delta'^2 / 2 + (8/15) E* sqrt(R) delta^(5/2) = M v^2 / 2; DESIGN.md
 * rounds it to 2.94, 0.11 % low); the restitution of the hysteretic model,
 * (k_n/k'_n)^(1/(2m)) (Eq. 3.67); the restitution of the linear law with a
 * dash-pot that may not pull (closed form of the damped oscillator, ended
 * when k u + c u' = 0); Coulomb's law for an impact that slides
 * throughout: tangential impulse = mu x normal impulse; the bound on the
 * exit speed of the Box 3.1 step, v0 / sqrt(1 - lambda^2) (derived in
 * test_contact_law.c); friction absent and friction with mu = 0 give the
 * same numbers (DESIGN.md, "Effects"); with the separation correction
 * (model.h), the energy of a rigid pair before and after contact, to
 * rounding, and its momentum.
 *
 * Data: shot radius 0.5 mm, 19 m/s, target E = 68 GPa (thesis-data.yaml,
 * shot_peening_3d); alpha in {0.5, 1, 2, 5, 10}, impact angles 60 and 75
 * degrees, mu in {0, 0.05, 0.1, 0.2, 0.5} (ibid.).  Steel shot density
 * 7800 kg/m^3 and the aluminium Poisson ratio 0.33 are textbook values.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact/facet.h"
#include "contact/sphere.h"
#include "core/consts.h"

#define R_SHOT 0.5e-3
#define RHO 7800.0
#define E_AL 68e9
#define NU_AL 0.33
#define V_SHOT 19.0

/* Hertz contact time factor: (4/5) Gamma(2/5) Gamma(1/2) / Gamma(9/10) */
static double hertz_tc_factor(void)
{
	return 0.8 * tgamma(0.4) * sqrt(DEM_PI) / tgamma(0.9);
}

static const double M_SHOT = RHO * 4.0 / 3.0 * DEM_PI * R_SHOT * R_SHOT * R_SHOT;

/* ---- surfaces: one large facet, or a tiled square z = 0 ----------------- */

#define NQ 12
typedef struct surface {
	int nf;
	double X[2 * NQ * NQ][3][3];
} surface_t;

static surface_t surf;

static void one_facet(surface_t *s)
{
	double X[3][3] = { { -1, -1, 0 }, { 1, -1, 0 }, { 0, 1, 0 } };
	s->nf = 1;
	memcpy(s->X[0], X, sizeof X);
}

static void tiled(surface_t *s, double h)
{
	s->nf = 0;
	for (int i = 0; i < NQ; i++)
		for (int j = 0; j < NQ; j++) {
			double x0 = (i - NQ / 2) * h, y0 = (j - NQ / 2) * h;
			double P[4][3] = { { x0, y0, 0 }, { x0 + h, y0, 0 }, { x0 + h, y0 + h, 0 }, { x0, y0 + h, 0 } };
			int t[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
			if ((i + j) % 2)
				t[0][2] = 3, t[1][0] = 1;  /* (0 1 3), (1 2 3): the other diagonal */
			for (int f = 0; f < 2; f++, s->nf++)
				for (int k = 0; k < 3; k++)
					memcpy(s->X[s->nf][k], P[t[f][k]], sizeof P[0]);
		}
}

/* ---- the integrator ----------------------------------------------------- */

static double speed(const double v[3])
{
	return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

typedef struct run {
	double v[3], w[3];    /* exit velocity and spin */
	double Fmax;          /* largest normal (z) force */
	double t_in, t_out;   /* crossings of z = R */
	double dmax;          /* largest overlap */
	double ftmax;         /* largest |F_t| / (mu F_n) over pairs */
	double Jn, Jt[2];     /* impulses on the sphere: normal, tangential */
	double dpeak;         /* peak of the parabola through the largest overlap and its neighbours */
	double dE;            /* energy taken by the separation correction */
	long steps;
	int finite;
} run_t;

static dem_contact_state_t states[2 * NQ * NQ];
#define NSTEP 200000
static double ts[NSTEP], dz[NSTEP];  /* time and overlap at each step */

/* The peak of the parabola through (t, f) at k - 1, k, k + 1. */
static double parabola_peak(const double *t, const double *f, long k)
{
	double a = t[k - 1] - t[k], b = t[k + 1] - t[k];
	double p = (f[k - 1] - f[k]) / a, q = (f[k + 1] - f[k]) / b;
	double c2 = (p - q) / (a - b), c1 = p - c2 * a;  /* f = f_k + c1 s + c2 s^2 */
	return c2 < 0 ? f[k] - c1 * c1 / (4 * c2) : f[k];
}

/* fix: apply the separation correction (model.h) when a pair leaves; the
 * facets' own normal is the pair's (a sphere leaving a facet's plane). */
static void impact(const dem_contact_model_t *cm, const surface_t *s, const double x0[3],
                   const double v0[3], double lambda, int fix, run_t *r)
{
	const double I = 0.4 * M_SHOT * R_SHOT * R_SHOT;
	dem_sphere_t sp = { .R = R_SHOT, .kn = dem_law_kn(&cm->p.law, R_SHOT) };
	memcpy(sp.x, x0, sizeof sp.x);
	memcpy(sp.v, v0, sizeof sp.v);  /* v_{-1/2} */
	for (int f = 0; f < s->nf; f++)
		dem_contact_state_reset(&states[f]);
	memset(r, 0, sizeof *r);
	r->finite = 1;
	r->t_in = -1;
	double t = 0, dtp = 0;
	int touched = 0;
	long kmax = 0;
	double dbig = 0;
	for (long n = 0; n < NSTEP; n++) {
		double z = sp.x[2];
		double dt = dem_contact_dt(cm, sp.kn, M_SHOT, R_SHOT - z, sp.v[2], lambda);
		double h = 0.5 * (dtp + dt);
		double F[3] = { 0, 0, 0 }, T[3] = { 0, 0, 0 };
		int any = 0;
		for (int f = 0; f < s->nf; f++) {
			dem_facet_out_t o;
			dem_contact_state_t keep = states[f];  /* the pair function resets it on leaving */
			if (!dem_contact_sphere_facet(cm, &sp, (const double (*)[3])s->X[f], NULL, M_SHOT, dt, &states[f], &o)) {
				if (fix) {  /* nothing to do (J = 0) unless the pair was in contact */
					const double (*X)[3] = s->X[f];
					double a[3], b[3], nf[3], J[3];
					for (int i = 0; i < 3; i++)
						a[i] = X[1][i] - X[0][i], b[i] = X[2][i] - X[0][i];
					nf[0] = a[1] * b[2] - a[2] * b[1];
					nf[1] = a[2] * b[0] - a[0] * b[2];
					nf[2] = a[0] * b[1] - a[1] * b[0];
					double l = speed(nf);
					for (int i = 0; i < 3; i++)
						nf[i] /= l;
					r->dE += dem_sepfix_release(cm, &keep, sp.kn, M_SHOT, nf, sp.v, J);
					for (int i = 0; i < 3; i++)
						F[i] += J[i] / h;  /* the impulse J in this step's velocity update */
				}
				continue;
			}
			if (fix)
				dem_sepfix_record(&states[f], o.g.n, sp.v, o.c.Fe, h);
			any = 1;
			for (int i = 0; i < 3; i++)
				F[i] += o.c.F[i], T[i] += o.c.T[i];
			if (cm->p.friction && o.c.Fn > 0)
				r->ftmax = fmax(r->ftmax, o.c.Ft / (cm->p.mu * o.c.Fn));
			else if (cm->p.friction && o.c.Ft > 0)
				r->ftmax = HUGE_VAL;
		}
		if (any)
			r->Fmax = fmax(r->Fmax, F[2]);
		ts[n] = t, dz[n] = R_SHOT - z;
		if (dz[n] > dbig)
			dbig = dz[n], kmax = n;
		r->dmax = fmax(r->dmax, R_SHOT - z);
		/* Box 3.1 */
		for (int i = 0; i < 3; i++) {
			sp.v[i] += F[i] / M_SHOT * h;
			sp.w[i] += T[i] / I * h;
		}
		r->Jn += F[2] * h, r->Jt[0] += F[0] * h, r->Jt[1] += F[1] * h;
		for (int i = 0; i < 3; i++)
			sp.x[i] += sp.v[i] * dt;
		double zn = sp.x[2];
		if (z > R_SHOT && zn <= R_SHOT && r->t_in < 0)
			r->t_in = t + dt * (z - R_SHOT) / (z - zn);
		if (z == R_SHOT && r->t_in < 0)
			r->t_in = t;
		if (z < R_SHOT && zn >= R_SHOT)
			r->t_out = t + dt * (R_SHOT - z) / (zn - z);
		t += dt;
		dtp = dt;
		touched |= any;
		if (!isfinite(sp.x[2]) || !isfinite(sp.v[2])) {
			r->finite = 0;
			break;
		}
		if (touched && !any && sp.v[2] > 0 && zn > R_SHOT) {
			r->steps = n + 1;
			break;
		}
	}
	memcpy(r->v, sp.v, sizeof r->v);
	memcpy(r->w, sp.w, sizeof r->w);
	r->dpeak = kmax > 0 && kmax + 1 < NSTEP ? parabola_peak(ts, dz, kmax) : r->dmax;
}

static void model(dem_contact_model_t *cm, dem_contact_param_t *p)
{
	dem_error_t e = { 0 };
	if (dem_contact_model_init(cm, p, &e))
		fail_msg("%s", e.msg);
}

/* ---- tests -------------------------------------------------------------- */

/* The DE Hertz law alone on a rigid facet against the Hertz solution. */
static void test_hertz(void **state)
{
	(void)state;
	dem_contact_param_t p = { 0 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_hertz(&p.law, E_AL, NU_AL, &e), DEM_OK);
	dem_contact_model_t cm;
	model(&cm, &p);
	one_facet(&surf);
	double x0[3] = { 0.05, 0.1, R_SHOT }, v0[3] = { 0, 0, -V_SHOT };
	run_t r;
	impact(&cm, &surf, x0, v0, 0.002, 0, &r);
	double Es = E_AL / (1 - NU_AL * NU_AL);
	double d = pow(15 * M_SHOT * V_SHOT * V_SHOT / (16 * Es * sqrt(R_SHOT)), 0.4);
	double F = 4.0 / 3.0 * Es * sqrt(R_SHOT) * pow(d, 1.5), tc = hertz_tc_factor() * d / V_SHOT;
	double eF = r.Fmax / F - 1, et = (r.t_out - r.t_in) / tc - 1, ed = r.dmax / d - 1;
	print_message("Hertz, R 0.5 mm, 19 m/s, E* %.1f GPa: F_max %.2f N (%+.4f%%), contact %.4f us (%+.4f%%), "
	              "indentation %.3f um (%+.4f%%), %ld steps\n", Es / 1e9, r.Fmax, 100 * eF,
	              1e6 * (r.t_out - r.t_in), 100 * et, 1e6 * r.dmax, 100 * ed, r.steps);
	assert_true(fabs(eF) < 5e-3);
	assert_true(fabs(et) < 5e-3);
	assert_true(fabs(ed) < 5e-3);
	assert_true(fabs(speed(r.v) / V_SHOT - 1) < 1e-3);
}

/* Issue 5, item 1, the DE part: the law of Eq. 3.45 with m = 3/2 and
 * alpha = 4 / (3 (1 - nu^2)), which is the Hertz law of a rigid sphere on
 * a half-space (Eq. 3.29), integrated as the library does (Box 3.1, the
 * secant step from the state, dem_contact_dt) at the default lambda = 0.2,
 * with and without the separation correction, against the closed form:
 * largest force and contact time within 0.5 %.  The force is looked at
 * at the steps only (about ten in the contact): the largest sampled force
 * depends on where the steps fall near the peak (-0.49 % at lambda = 0.2,
 * up to -0.86 % at 0.17), so the force at the top of the parabola through
 * the three largest overlaps is reported too (+0.6 % at 0.2, growing as
 * lambda^2: the discrete motion overshoots slightly).  The contact
 * time of central differences is short (the discrete frequency is higher,
 * sin(Omega dt / 2) = omega dt / 2 for a linear spring), by about
 * 17 lambda^2 %: 0.69 % at lambda = 0.2, so it meets 0.5 % only below; the
 * test finds that lambda. */
static void test_hertz_default_lambda(void **state)
{
	(void)state;
	const double alpha = 4 / (3 * (1 - NU_AL * NU_AL)), Es = E_AL / (1 - NU_AL * NU_AL);
	const double d = pow(15 * M_SHOT * V_SHOT * V_SHOT / (16 * Es * sqrt(R_SHOT)), 0.4);
	const double F = 4.0 / 3.0 * Es * sqrt(R_SHOT) * pow(d, 1.5), tc = hertz_tc_factor() * d / V_SHOT;
	one_facet(&surf);
	double x0[3] = { 0.05, 0.1, R_SHOT }, v0[3] = { 0, 0, -V_SHOT };
	assert_true(fabs(hertz_tc_factor() - 2.94327) < 1e-5);
	dem_contact_param_t p = { 0 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_init(&p.law, alpha, E_AL, 1.5, &e), DEM_OK);
	dem_contact_model_t cm;
	model(&cm, &p);
	run_t r[2];
	for (int fix = 0; fix < 2; fix++) {
		impact(&cm, &surf, x0, v0, DEM_DT_LAMBDA_DEFAULT, fix, &r[fix]);
		double eF = r[fix].Fmax / F - 1, et = (r[fix].t_out - r[fix].t_in) / tc - 1;
		double eP = pow(r[fix].dpeak / d, 1.5) - 1;
		print_message("Hertz (alpha = 4/(3(1-nu^2)), m = 1.5) on a rigid facet, lambda 0.2, %s: largest force "
		              "%+.3f%% (at the parabola's top overlap %+.3f%%), contact time %+.3f%%, exit/impact "
		              "speed %.6f, %ld steps\n",
		              fix ? "corrected" : "thesis scheme", 100 * eF, 100 * eP, 100 * et,
		              speed(r[fix].v) / V_SHOT, r[fix].steps);
		assert_true(fabs(eF) < 5e-3);
		(void)eP;
		assert_true(fabs(et) < 1e-2);  /* 0.69 %: see above */
	}
	/* the correction acts when the pair has left: the same contact */
	assert_true(r[0].Fmax == r[1].Fmax && r[0].t_out == r[1].t_out);
	assert_true(speed(r[0].v) / V_SHOT > 1 + 1e-3);                  /* the scheme's gain ... */
	assert_true(fabs(speed(r[1].v) / V_SHOT - 1) < 1e-9);            /* ... taken back */
	assert_true(fabs(r[1].dE - 0.5 * M_SHOT * (r[0].v[2] * r[0].v[2] - V_SHOT * V_SHOT))
	            < 1e-9 * 0.5 * M_SHOT * V_SHOT * V_SHOT);
	/* the lambda below which the contact time is within 0.5 %: the error
	 * grows with lambda (about 17 lambda^2 %) */
	double lok = 0, worstF = 0;
	for (double l = 0.2; l > 0.005; l -= 0.005) {
		run_t q;
		impact(&cm, &surf, x0, v0, l, 0, &q);
		double et = (q.t_out - q.t_in) / tc - 1;
		worstF = fmax(worstF, fabs(q.Fmax / F - 1));
		if (lok == 0 && fabs(et) < 5e-3)
			lok = l;
		if (lok > 0)
			assert_true(fabs(et) < 5e-3);
	}
	print_message("Hertz, contact time within 0.5 %% for lambda <= %.3f; largest sampled force off by up to "
	              "%.3f%% for lambda in (0, 0.2]\n", lok, 100 * worstF);
	assert_true(lok >= 0.15 && lok < 0.2);
}

/* Two rigid spheres, oblique, through dem_contact_sphere_sphere with the
 * separation correction wired as a driver would (model.h): after the
 * contact the kinetic energy is what it was, to rounding (the normal turns
 * during the contact; the work is taken along each step's normal), and the
 * momentum is kept.  Unequal spheres; the linear and Hertz laws at
 * lambda = 0.2 and 0.3; the impact parameter half the sum of the radii. */
static void test_sphere_pair(void **state)
{
	(void)state;
	const double R1 = 0.5e-3, R2 = 0.3e-3, v = V_SHOT, ms[2] = { 1, 1.5 }, lambdas[2] = { 0.2, 0.3 };
	const double M1 = RHO * 4.0 / 3.0 * DEM_PI * R1 * R1 * R1, M2 = RHO * 4.0 / 3.0 * DEM_PI * R2 * R2 * R2;
	const double meff = dem_contact_meff(M1, M2), E0 = 0.5 * M2 * v * v;
	for (int j = 0; j < 2; j++)
		for (int l = 0; l < 2; l++)
			for (int fix = 0; fix < 2; fix++) {
				dem_contact_param_t p = { 0 };
				dem_error_t e = { 0 };
				assert_int_equal(dem_law_init(&p.law, 1, 210e9, ms[j], &e), DEM_OK);
				dem_contact_model_t cm;
				model(&cm, &p);
				double kn = dem_law_kn(&p.law, dem_law_reff(R1, R2));
				dem_sphere_t s1 = { .R = R1 }, s2 = { .R = R2, .x = { 0.5 * (R1 + R2), 0.1e-3, 1.2e-3 },
				                                            .v = { 0, 0, -v } };
				dem_contact_state_t st;
				dem_contact_state_reset(&st);
				double dtp = 0, th0 = 0, th1 = 0, dE = 0;
				int touched = 0, apart = 0;
				for (long n = 0; n < NSTEP && apart < 3; n++) {
					double d[3], w[3];
					for (int i = 0; i < 3; i++)
						d[i] = s2.x[i] - s1.x[i], w[i] = s2.v[i] - s1.v[i];
					double dist = speed(d), delta = R1 + R2 - dist, vn = -(d[0] * w[0] + d[1] * w[1] + d[2] * w[2]) / dist;
					double dt = dem_contact_dt(&cm, kn, meff, delta, delta > 0 ? vn : speed(w), lambdas[l]);
					double h = 0.5 * (dtp + dt), F[3] = { 0, 0, 0 };
					dem_contact_state_t keep = st;
					dem_pair_out_t o;
					if (dem_contact_sphere_sphere(&cm, &s1, &s2, kn, meff, dt, &st, &o)) {
						memcpy(F, o.c.F, sizeof F);
						if (fix)
							dem_sepfix_record(&st, o.n, w, o.c.Fe, h);
						if (!touched)
							th0 = atan2(o.n[0], o.n[2]);
						th1 = atan2(o.n[0], o.n[2]);
						touched = 1;
					} else if (touched) {
						if (fix && !apart) {
							double n[3] = { d[0] / dist, d[1] / dist, d[2] / dist }, J[3];
							dE = dem_sepfix_release(&cm, &keep, kn, meff, n, w, J);
							for (int i = 0; i < 3; i++)
								F[i] = J[i] / h;
						}
						apart++;
					}
					for (int i = 0; i < 3; i++) {
						s2.v[i] += F[i] / M2 * h, s1.v[i] -= F[i] / M1 * h;
						s2.x[i] += s2.v[i] * dt, s1.x[i] += s1.v[i] * dt;
					}
					dtp = dt;
				}
				assert_true(touched && apart == 3);
				double E1 = 0.5 * M1 * (s1.v[0] * s1.v[0] + s1.v[1] * s1.v[1] + s1.v[2] * s1.v[2])
				            + 0.5 * M2 * (s2.v[0] * s2.v[0] + s2.v[1] * s2.v[1] + s2.v[2] * s2.v[2]);
				for (int i = 0; i < 3; i++)  /* momentum */
					assert_true(fabs(M1 * s1.v[i] + M2 * s2.v[i] - (i == 2 ? -M2 * v : 0)) < 1e-12 * M2 * v);
				print_message("spheres 0.5/0.3 mm, m = %.1f, lambda %.1f, %s: energy out/in - 1 = %+.2e "
				              "(normal turned %.1f deg)\n", ms[j], lambdas[l], fix ? "corrected" : "thesis scheme",
				              E1 / E0 - 1, fabs(th1 - th0) * 180 / DEM_PI);
				if (fix) {
					assert_true(fabs(E1 / E0 - 1) < 1e-12);
					assert_true(dE != 0);
				}
			}
}

/* Eq. 3.45 with alpha from 0.5 to 10 on a tiled surface (partial contacts
 * across edges and vertices) with the default lambda, for the two laws the
 * thesis retains (Ch. 3.3.5).  (The Winkler law m = 2 is far softer at
 * these overlaps: with alpha = 0.5 the 19 m/s shot would sink by more than
 * its radius, outside the small-overlap assumption of Eq. 3.1.) */
static void test_alpha_range(void **state)
{
	(void)state;
	const double alphas[5] = { 0.5, 1, 2, 5, 10 }, ms[2] = { 1, 1.5 }, lambda = DEM_DT_LAMBDA_DEFAULT;
	tiled(&surf, 0.05e-3);  /* 50 um facets (Ch. 7.5): the contact circle spans 0.3-4.5 */
	double x0[3] = { 0.3 * 0.05e-3, 0.7 * 0.05e-3, R_SHOT }, v0[3] = { 0, 0, -V_SHOT };
	for (int j = 0; j < 2; j++) {
		double worst = 0;
		for (int a = 0; a < 5; a++) {
			dem_contact_param_t p = { 0 };
			dem_error_t e = { 0 };
			assert_int_equal(dem_law_init(&p.law, alphas[a], E_AL, ms[j], &e), DEM_OK);
			dem_contact_model_t cm;
			model(&cm, &p);
			run_t r;
			impact(&cm, &surf, x0, v0, lambda, 0, &r);
			double ratio = speed(r.v) / V_SHOT;
			double umax = dem_dt_umax(ms[j], dem_law_kn(&p.law, R_SHOT), M_SHOT, V_SHOT);
			assert_true(r.finite);
			assert_true(r.steps > 0);
			assert_true(ratio <= 1 / sqrt(1 - lambda * lambda));
			/* the same as the rigid wall of Box 3.1: partial contacts add no error */
			/* the same as the rigid wall of Box 3.1: partial contacts add
			 * no error.  For the Hertz law the exit ratio is a smooth
			 * function of lambda; for the linear law it depends on the
			 * phase of the step at first contact (Fig. 3.15b: exact points
			 * between overshoots), which the wall test fixes at u(0) = 0 and
			 * a free flight does not, so there only the bound above holds */
			if (ms[j] != 1)
				assert_true(fabs(ratio - dem_dt_wall_test(ms[j], 1, 1, 1, lambda, NULL, NULL)) < 1e-3);
			assert_true(r.dmax <= umax * (1 + lambda * lambda));
			assert_true(r.dmax < 0.05 * R_SHOT);
			/* a flat surface pushes straight back */
			assert_true(hypot(r.v[0], r.v[1]) < 1e-3 * V_SHOT);
			worst = fmax(worst, ratio);
		}
		print_message("alpha 0.5-10, m = %.1f, lambda %.1f: largest exit/impact speed %.5f\n", ms[j], lambda, worst);
	}
}

/* 150 m/s on one facet with lambda = 0.2, linear and Hertz laws with the
 * thesis' recommended penalties alpha = 1 and 5 (thesis-data.yaml).  The
 * exit speed must be that of the speed-independent rigid wall test of
 * Box 3.1 at the same lambda: nothing extra goes wrong at high speed. */
static void test_high_speed(void **state)
{
	(void)state;
	one_facet(&surf);
	const double ms[2] = { 1, 1.5 }, alphas[2] = { 1, 5 }, lambda = 0.2, v = 150;
	for (int j = 0; j < 2; j++)
		for (int a = 0; a < 2; a++) {
			dem_contact_param_t p = { 0 };
			dem_error_t e = { 0 };
			assert_int_equal(dem_law_init(&p.law, alphas[a], E_AL, ms[j], &e), DEM_OK);
			dem_contact_model_t cm;
			model(&cm, &p);
			double x0[3] = { 0, 0, R_SHOT }, v0[3] = { 0, 0, -v };
			run_t r;
			impact(&cm, &surf, x0, v0, lambda, 0, &r);
			double ratio = speed(r.v) / v;
			double umax = dem_dt_umax(ms[j], dem_law_kn(&p.law, R_SHOT), M_SHOT, v);
			double box = dem_dt_wall_test(ms[j], 1, 1, 1, lambda, NULL, NULL);
			print_message("150 m/s, m = %.1f, alpha %g, lambda 0.2: exit/impact speed %.6f (Box 3.1: %.6f), "
			              "overlap %.2f%% of R\n", ms[j], alphas[a], ratio, box, 100 * r.dmax / R_SHOT);
			assert_true(r.finite && r.steps > 0);
			assert_true(r.dmax <= umax * (1 + lambda * lambda));
			assert_true(ratio <= 1 / sqrt(1 - lambda * lambda));
			assert_true(fabs(ratio - box) < 1e-3);
		}
}

/* Hysteresis: restitution (k_n/k'_n)^(1/(2m)), independent of the speed. */
static void test_hysteresis(void **state)
{
	(void)state;
	one_facet(&surf);
	const double ms[3] = { 1, 1.5, 2 }, rho = 0.6;
	for (int j = 0; j < 3; j++)
		for (double v = 0.5; v <= 5; v *= 10) {  /* m = 2 at 5 m/s: overlap 0.26 R */
			dem_contact_param_t p = { .damping = DEM_DAMP_HYSTERESIS };
			dem_error_t e = { 0 };
			assert_int_equal(dem_law_init(&p.law, 2, E_AL, ms[j], &e), DEM_OK);
			p.unload = dem_hyst_unload_ratio(rho, ms[j]);
			dem_contact_model_t cm;
			model(&cm, &p);
			double x0[3] = { 0, 0, R_SHOT }, v0[3] = { 0, 0, -v };
			run_t r;
			impact(&cm, &surf, x0, v0, 0.01, 0, &r);
			assert_true(fabs(speed(r.v) / v - rho) < 2e-3 * rho);
			/* and with the default lambda the stiffer unloading is covered */
			impact(&cm, &surf, x0, v0, DEM_DT_LAMBDA_DEFAULT, 0, &r);
			assert_true(r.finite && speed(r.v) / v <= rho / sqrt(1 - 0.04));
		}
}

/* Viscous damping of the linear law: the exact restitution of a dash-pot
 * that may not pull. */
static void test_viscous(void **state)
{
	(void)state;
	one_facet(&surf);
	for (double xi = 0.05; xi < 0.7; xi += 0.2) {
		dem_contact_param_t p = { .damping = DEM_DAMP_VISCOUS, .xi = xi };
		dem_error_t e = { 0 };
		assert_int_equal(dem_law_init(&p.law, 1, E_AL, 1, &e), DEM_OK);
		dem_contact_model_t cm;
		model(&cm, &p);
		double x0[3] = { 0, 0, R_SHOT }, v0[3] = { 0, 0, -V_SHOT };
		run_t r;
		impact(&cm, &surf, x0, v0, 0.002, 0, &r);
		/* u = v0/wd e^(-xi w t) sin(wd t); the force k u + c u' vanishes at
		 * wd t* = pi - atan2(2 xi sqrt(1-xi^2), 1 - 2 xi^2); the exit speed
		 * is u'(t*) */
		double s = sqrt(1 - xi * xi), wdt = DEM_PI - atan2(2 * xi * s, 1 - 2 * xi * xi);
		double rho = exp(-xi / s * wdt) * (-cos(wdt) + xi / s * sin(wdt));
		double got = speed(r.v) / V_SHOT;
		print_message("viscous xi = %.2f: restitution %.5f, exact %.5f (Eq. 3.71, dash-pot pulling: %.5f)\n",
		              xi, got, rho, dem_visc_restitution_linear(xi));
		assert_true(fabs(got - rho) < 2e-3);
	}
}

/* Oblique impacts with friction on a tiled surface. */
static void test_oblique_friction(void **state)
{
	(void)state;
	const double angles[2] = { 60, 75 }, mus[5] = { 0, 0.05, 0.1, 0.2, 0.5 }, lambda = DEM_DT_LAMBDA_DEFAULT;
	tiled(&surf, 0.05e-3);
	const double I = 0.4 * M_SHOT * R_SHOT * R_SHOT;
	for (int a = 0; a < 2; a++) {
		double th = angles[a] * DEM_PI / 180;
		double x0[3] = { -0.01e-3, 0.013e-3, R_SHOT }, v0[3] = { V_SHOT * cos(th), 0, -V_SHOT * sin(th) };
		double E0 = 0.5 * M_SHOT * V_SHOT * V_SHOT;
		run_t r0;
		{
			dem_contact_param_t p = { 0 };
			dem_error_t e = { 0 };
			assert_int_equal(dem_law_init(&p.law, 1, E_AL, 1.5, &e), DEM_OK);
			dem_contact_model_t cm;
			model(&cm, &p);
			impact(&cm, &surf, x0, v0, lambda, 0, &r0);  /* no friction at all */
		}
		for (int k = 0; k < 5; k++) {
			dem_contact_param_t p = { .friction = 1, .mu = mus[k] };
			dem_error_t e = { 0 };
			assert_int_equal(dem_law_init(&p.law, 1, E_AL, 1.5, &e), DEM_OK);
			dem_contact_model_t cm;
			model(&cm, &p);
			run_t r;
			impact(&cm, &surf, x0, v0, lambda, 0, &r);
			assert_true(r.finite);
			assert_true(r.ftmax <= 1 + 1e-12);  /* per pair, every step */
			double E1 = 0.5 * M_SHOT * (r.v[0] * r.v[0] + r.v[1] * r.v[1] + r.v[2] * r.v[2])
			            + 0.5 * I * (r.w[0] * r.w[0] + r.w[1] * r.w[1] + r.w[2] * r.w[2]);
			assert_true(E1 <= E0 / (1 - lambda * lambda));
			if (mus[k] == 0) {
				/* an absent effect and the same effect at zero */
				assert_memory_equal(r.v, r0.v, sizeof r.v);
				assert_true(r.w[0] == 0 && r.w[1] == 0 && r.w[2] == 0);
				continue;
			}
			/* sliding throughout when mu (1 + e) v_n < v_t / 3.5 (solid sphere):
			 * then J_t = mu J_n (Coulomb) */
			double vt = V_SHOT * cos(th), vn = V_SHOT * sin(th);
			double ratio = hypot(r.Jt[0], r.Jt[1]) / r.Jn;
			print_message("oblique %2.0f deg, mu %.2f: J_t/J_n %.4f, spin %.0f rad/s, energy out/in %.4f\n",
			              angles[a], mus[k], ratio, r.w[1], E1 / E0);
			if (mus[k] * 2 * vn < vt / 3.5)
				assert_true(fabs(ratio / mus[k] - 1) < 0.02);
			else
				assert_true(ratio <= mus[k] * (1 + 1e-9));
			/* friction opposes the sliding: the sphere slows along x, spins about +y */
			assert_true(r.v[0] < vt && r.w[1] > 0);
		}
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_hertz),
		cmocka_unit_test(test_hertz_default_lambda),
		cmocka_unit_test(test_sphere_pair),
		cmocka_unit_test(test_alpha_range),
		cmocka_unit_test(test_high_speed),
		cmocka_unit_test(test_hysteresis),
		cmocka_unit_test(test_viscous),
		cmocka_unit_test(test_oblique_friction),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
