/* test_shot_impact.c - lib/shot: rigid shots hitting the finite element
 * block through the load hook of lib/fe/explicit (issue 5, acceptance
 * items 1, 3 and 5, fast versions on coarse meshes).
 *
 * References, per test:
 *  - Hertz impact of a rigid sphere on an elastic half-space (DESIGN.md,
 *    "Verification references"): indentation d = (15 M v^2 / (16 E*
 *    sqrt(R)))^(2/5), largest force (4/3) E* sqrt(R) d^(3/2), contact time
 *    2.94327 d / v.  The block stands for the half-space: 20 contact radii
 *    thick, 20 wide, v / c = 1/700 (quasi-static).  What the finite block
 *    changes: its rigid base stiffens it by about Boussinesq's displacement
 *    at depth H under the load, 0.73 a / H of the indentation for nu = 0.3,
 *    3.6 % here, worth about 1.5 % on the force and contact time.  The
 *    coarse mesh here puts 4 elements on the contact radius a; the bound is
 *    the 5 % of the full case (10 elements on a, examples/hertz).
 *  - energy: the shots' kinetic energy plus the block's kinetic, internal,
 *    hourglass and damping energies never exceed the shots' initial
 *    kinetic energy by more than 1 % (no blow-up), for the linear law with
 *    alpha = 0.5 to 10 (Ch. 7.5.2, Fig. 7.16), oblique impacts at 60 and 75
 *    degrees with mu = 0 to 0.5 (Ch. 7.5.3), two shots at one point at
 *    once, and a shot at 150 m/s;
 *  - Coulomb: the tangential force of every shot never exceeds mu times
 *    its normal force (Eq. 3.48, summed over its contacts);
 *  - effects: friction absent and friction with mu = 0 give bitwise the
 *    same block and shots (DESIGN.md, "Effects"); the number of threads
 *    does not change a bit.
 * Data of Ch. 7.5 (thesis-data.yaml, shot_peening_3d): shot radius 0.5 mm
 * at 19 m/s, aluminium E = 68 GPa, yield 157 MPa, hardening 120 MPa; the
 * density of steel shot 7800 kg/m^3, aluminium's 2700 kg/m^3 and nu =
 * 0.33 are textbook values.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/facet.h"
#include "contact/model.h"
#include "core/consts.h"
#include "fe/explicit.h"
#include "fe/material.h"
#include "mesh/mesh.h"
#include "shot/shotset.h"

/* Under the sanitizers (minutes a run) the slow sweeps run their first
 * case only (slow.h); the plain build runs them all. */
#include "slow.h"

/* ---- the set-up ---------------------------------------------------------- */

typedef struct setup {
	/* block: half width L, thickness H, fine region half width Lf and
	 * depth Hf with element h, growth ratio outside */
	double L, H, Lf, Hf, h, ratio;
	dem_mat_param_t mat;
	double damping_xi;
	int large;
	/* contact */
	dem_contact_param_t cp;
	double rho_shot, lambda, gap;
	/* shots */
	size_t ns;
	dem_shot_t shot[4];
	double t_end;       /* 0: until the shots have left */
	int threads;
	int check_step;     /* count the steps held below the block's (free_steps) */
} setup_t;

typedef struct result {
	double Fmax;          /* largest z force on shot 0 */
	double t_first, t_last;
	double ftmax;         /* largest Ft / (mu Fn) over shots and steps */
	double E0, Emax, Eend;   /* total energy: start, largest, end */
	double v[4][3], w[4][3], x[4][3];
	double *u;            /* node displacements at the end (caller frees) */
	long steps;
	double sphere_contacts, contacts;
	double sepfix_J;      /* energy the separation correction took */
	/* check_step: steps at which shot 0 is out of reach of the surface by
	 * brute force (free), and those of them whose step was below the
	 * block's (held); the first such step held */
	long free_steps, held_steps;
	double held_t, held_dt, held_gap;
	int rc;
} result_t;

static void mesh_build(const setup_t *s, dem_mesh_t *m)
{
	dem_axis_t ax[3] = {
		{ -s->L, s->L, -s->Lf, s->Lf, s->h, s->ratio, 0 },
		{ -s->L, s->L, -s->Lf, s->Lf, s->h, s->ratio, 0 },
		{ -s->H, 0, -s->Hf, 0, s->h, s->ratio, 0 },
	};
	dem_error_t e = { 0 };
	int rc = dem_mesh_box(m, ax, &e);
	if (rc)
		fprintf(stderr, "%s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL,
			   DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh_set_bc(m, bc);
}

/* A lower bound of the distance from O to the block's top surface at x:
 * the nearest of the four triangles of each top quad (both diagonals, a
 * superset of the shot set's facets, shotset.c), and the largest speed of a
 * top node into *vmax. */
static double surface_distance(const dem_mesh_t *m, const double *x, const double *v,
			       const double O[3], double *vmax)
{
	double best = HUGE_VAL, w = 0;
	for (int j = 0; j <= m->ny; j++)
		for (int i = 0; i <= m->nx; i++) {
			const double *vn = v + 3 * dem_mesh_node(m, i, j, m->nz);
			w = fmax(w, sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2]));
		}
	for (int j = 0; j < m->ny; j++)
		for (int i = 0; i < m->nx; i++) {
			size_t q[4] = { dem_mesh_node(m, i, j, m->nz), dem_mesh_node(m, i + 1, j, m->nz),
					dem_mesh_node(m, i + 1, j + 1, m->nz), dem_mesh_node(m, i, j + 1, m->nz) };
			static const int t[4][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 1, 3 }, { 1, 2, 3 } };
			for (int k = 0; k < 4; k++) {
				double X[3][3], p[3];
				for (int a = 0; a < 3; a++)
					memcpy(X[a], x + 3 * q[t[k][a]], sizeof X[a]);
				best = fmin(best, dem_triangle_closest(O, (const double (*)[3])X, p));
			}
		}
	*vmax = w;
	return sqrt(best);
}

static void run(const setup_t *s, result_t *r)
{
	dem_mesh_t mesh;
	dem_mat_t mat;
	dem_error_t e = { 0 };
	dem_fe_t *fe;
	dem_shotset_t *S;
	dem_contact_model_t cm;

	memset(r, 0, sizeof *r);
	mesh_build(s, &mesh);
	assert_int_equal(dem_mat_init(&mat, &s->mat, &e), DEM_OK);
	dem_fe_opts_t fo;
	dem_fe_opts_default(&fo);
	fo.large = s->large;
	fo.threads = s->threads;
	if (s->damping_xi > 0)
		fo.damping = dem_fe_damping_alpha(&mat, s->damping_xi, s->H);
	assert_int_equal(dem_fe_create(&fe, &mesh, &mat, &fo, &e), DEM_OK);
	assert_int_equal(dem_contact_model_init(&cm, &s->cp, &e), DEM_OK);
	dem_shotset_opts_t so = { .rho = s->rho_shot, .lambda = s->lambda,
				  .buffer = s->h, .gap = s->gap, .threads = s->threads };
	int rc = dem_shotset_create(&S, &mesh, dem_fe_mass(fe), &cm, &so, &e);
	if (rc)
		fprintf(stderr, "%s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
	assert_int_equal(dem_shotset_begin(S, s->ns, s->shot, dem_fe_coords(fe), &e), DEM_OK);
	dem_fe_set_load(fe, dem_shotset_hook, S);

	r->E0 = dem_shotset_kinetic(S);
	r->Emax = r->E0;
	r->t_first = -1;
	int left = 0;
	for (long n = 0; n < 400000; n++) {
		double t = dem_fe_time(fe);
		double dt, gap = 0, reach = 0;
		if (s->check_step) {
			const dem_shot_body_t *b = dem_shotset_body(S, 0);
			double vmax, vs = sqrt(b->v[0] * b->v[0] + b->v[1] * b->v[1] + b->v[2] * b->v[2]);
			gap = surface_distance(&mesh, dem_fe_coords(fe), dem_fe_velocity(fe), b->x, &vmax) - b->R;
			reach = 2 * (vs + vmax) * dem_fe_dt(fe);
		}
		assert_int_equal(dem_shotset_prepare(S, dem_fe_coords(fe), dem_fe_velocity(fe), dem_fe_dt(fe), &dt, &e), DEM_OK);
		if (s->check_step && gap > reach) {
			r->free_steps++;
			if (dt < dem_fe_dt(fe) && r->held_steps++ == 0)
				r->held_t = t, r->held_dt = dt, r->held_gap = gap;
		}
		if ((rc = dem_fe_step(fe, dt, &e))) {
			fprintf(stderr, "step %ld: %s\n", n, e.msg);
			r->rc = rc;
			break;
		}
		r->steps++;

		for (size_t i = 0; i < s->ns; i++) {
			const dem_shot_body_t *b = dem_shotset_body(S, i);
			if (s->cp.friction && b->Fn > 0)
				r->ftmax = fmax(r->ftmax, s->cp.mu > 0 ? b->Ft / (s->cp.mu * b->Fn) : b->Ft);
		}
		const dem_shot_body_t *b0 = dem_shotset_body(S, 0);
		if (b0->contacts > 0) {
			if (r->t_first < 0)
				r->t_first = t;
			r->t_last = t;
			r->Fmax = fmax(r->Fmax, b0->F[2]);
		}
		dem_fe_energy_t en;
		dem_fe_energy(fe, &en);
		double E = dem_shotset_kinetic(S) + en.kinetic + en.internal + en.hourglass + en.damping;
		assert_true(isfinite(E));
		r->Emax = fmax(r->Emax, E);
		r->Eend = E;
		if (s->t_end > 0 ? dem_fe_time(fe) >= s->t_end : dem_shotset_done(S) && ++left > 20)
			break;
	}
	for (size_t i = 0; i < s->ns; i++) {
		const dem_shot_body_t *b = dem_shotset_body(S, i);
		memcpy(r->v[i], b->v, sizeof r->v[i]);
		memcpy(r->w[i], b->w, sizeof r->w[i]);
		memcpy(r->x[i], b->x, sizeof r->x[i]);
	}
	dem_shotset_stats_t st;
	dem_shotset_stats(S, &st);
	r->sphere_contacts = st.sphere_contacts;
	r->sepfix_J = st.sepfix_J;
	r->contacts = st.contacts;
	r->u = malloc(3 * mesh.nn * sizeof *r->u);
	assert_non_null(r->u);
	dem_fe_displacements(fe, r->u);
	for (size_t k = 0; k < 3 * mesh.nn; k++)
		assert_true(isfinite(r->u[k]));
	dem_shotset_free(S);
	dem_fe_free(fe);
	dem_mat_free(&mat);
	dem_mesh_free(&mesh);
}

/* ---- Hertz ---------------------------------------------------------------- */

/* The soft block of test_hertz: a = 4 h, R = 20 a, d = a^2 / R; block
 * 20 a wide (half 10 a) and 20 a thick, its fine region 2 a around the
 * impact and 2 a deep.  Fills F and tc with Hertz's force and contact
 * time. */
static void hertz_run(double alpha, int scheme, result_t *r, double *F, double *tc)
{
	const double h = getenv("HH") ? atof(getenv("HH")) : 1e-3, a = 4e-3, R = 20 * a, d = a * a / R;
	const double v = 0.5, E = 100e6, nu = 0.3, rho = 1000;
	const double Es = E / (1 - nu * nu);
	/* the shot's mass for that indentation: M = 16 E* sqrt(R) d^(5/2) / (15 v^2) */
	const double M = 16 * Es * sqrt(R) * pow(d, 2.5) / (15 * v * v);
	setup_t s = { .L = 10 * a, .H = 20 * a, .Lf = 2 * a, .Hf = 2 * a, .h = h, .ratio = 1.3,
		      .mat = { .E = E, .nu = nu, .rho = rho },
		      .rho_shot = M / (4.0 / 3.0 * DEM_PI * R * R * R), .lambda = 0.2, .gap = 0.01 * h,
		      .ns = 1, .shot = { { .r = R, .v = { 0, 0, -v } } }, .threads = 1 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_init(&s.cp.law, alpha, E, 1.5, &e), DEM_OK);
	s.cp.partial = scheme;
	run(&s, r);
	/* contact time 2 d / v int_0^1 dx / sqrt(1 - x^(5/2)) = 2.94327 d / v */
	*F = 4.0 / 3.0 * Es * sqrt(R) * pow(d, 1.5), *tc = 2.94327 * d / v;
}

static void test_hertz(void **state)
{
	(void)state;
	/* a stiff penalty, F = alpha E sqrt(R) delta^1.5 with alpha = 30.  In
	 * this conforming contact (the surface takes the sphere's shape) each
	 * of the ~100 facets under the sphere carries the law on its own small
	 * overlap, so the penalty is far stiffer than one Hertz law in series
	 * with the block: its compliance is small (alpha 20 gives -1 % on the
	 * force against alpha 30), and the reference is Hertz's.  Bound 5 %
	 * (issue 5, item 1, there with 10 elements on a: examples/hertz, which
	 * measured +0.4 % on the force and +0.8 % on the contact time).  The
	 * area scheme (the default), and the potential scheme. */
	const double alpha = getenv("HALPHA") ? atof(getenv("HALPHA")) : 30;
	static const int scheme[] = { DEM_PARTIAL_AREA, DEM_PARTIAL_POTENTIAL };
	for (int k = 0; k < SLOW_CASES(2, 1); k++) {
		result_t r;
		double F, tc;
		hertz_run(alpha, getenv("HVOL") ? DEM_PARTIAL_VOLUME : scheme[k], &r, &F, &tc);
		double T = r.t_last - r.t_first;
		printf("# hertz, %s: Fmax %.6g N (Hertz %.6g: %+.2f %%), contact %.6g s (Hertz %.6g: %+.2f %%), "
		       "%ld steps, E end/start %.5f\n", k ? "potential" : "area", r.Fmax, F,
		       100 * (r.Fmax / F - 1), T, tc, 100 * (T / tc - 1), r.steps, r.Eend / r.E0);
		assert_int_equal(r.rc, DEM_OK);
		assert_true(fabs(r.Fmax / F - 1) < 0.05);
		assert_true(fabs(T / tc - 1) < 0.05);
		assert_true(r.Emax <= 1.01 * r.E0);
		free(r.u);
	}
}

/* The soft block with a softer penalty, alpha 2 to 10: the area scheme's
 * forces, which do not derive from a potential, gain energy without bound
 * there (measured: at alpha 5 the shot left at 25 times its speed, E end /
 * start 3e4); the potential scheme's (facet.h) conserve it: the total stays
 * within 1 % of the input and the shot bounces back slower than it came
 * (the block keeps its waves). */
static void test_soft_block(void **state)
{
	(void)state;
	static const double alpha[] = { 5, 2, 10 };
	for (int k = 0; k < SLOW_CASES(3, 1); k++) {
		result_t r;
		double F, tc;
		hertz_run(alpha[k], DEM_PARTIAL_POTENTIAL, &r, &F, &tc);
		printf("# soft block, potential, alpha %g: Fmax %+.2f %% of Hertz, contact %+.2f %%, "
		       "E max/start %.5f, end/start %.5f, exit vz %.4g m/s\n", alpha[k],
		       100 * (r.Fmax / F - 1), 100 * ((r.t_last - r.t_first) / tc - 1), r.Emax / r.E0,
		       r.Eend / r.E0, r.v[0][2]);
		assert_int_equal(r.rc, DEM_OK);
		assert_true(r.Emax <= 1.01 * r.E0);
		assert_true(r.v[0][2] > 0 && r.v[0][2] < 0.5);
		free(r.u);
	}
}

/* ---- the Ch. 7.5 shot on a coarse aluminium block ------------------------- */

static void alu_setup(setup_t *s, double alpha, double m)
{
	memset(s, 0, sizeof *s);
	s->L = 1e-3, s->H = 1e-3, s->Lf = 0.4e-3, s->Hf = 0.3e-3, s->h = 0.1e-3, s->ratio = 1.3;
	s->mat = (dem_mat_param_t){ .E = 68e9, .nu = 0.33, .rho = 2700, .sy0 = 157e6, .H = 120e6 };
	s->large = 1;
	s->rho_shot = 7800, s->lambda = 0.2, s->gap = 1e-6;
	s->ns = 1;
	s->shot[0] = (dem_shot_t){ .r = 0.5e-3, .v = { 0, 0, -19 } };
	s->threads = 1;
	dem_error_t e = { 0 };
	assert_int_equal(dem_law_init(&s->cp.law, alpha, 68e9, m, &e), DEM_OK);
}

/* Ch. 7.5.2 (Fig. 7.16): alpha = 0.5 to 10 with the default partial
 * contact (the potential scheme, contact/facet.h), for the Hertz-type law
 * (demshot's default) and the thesis's linear law: the total energy stays
 * within 1 % of the input (measured: at most 1.0004 with m = 1.5, 1.0010
 * with the linear law at alpha 10).  The thesis's schemes are not
 * conservative on a dimpled surface (each facet's force gamma_i f(delta_i)
 * along G_i -> O is not the gradient of one potential): measured here with
 * the linear law, the area factor gains 2.6 % at alpha 5, the volume
 * factor up to 3 % at alpha 0.5 (m = 1.5). */
static void alpha_sweep(double law_m)
{
	static const double alpha[] = { 0.5, 1, 2, 5, 10 };
	for (int i = 0; i < 5; i++) {
		setup_t s;
		result_t r;
		alu_setup(&s, alpha[i], law_m);
		run(&s, &r);
		printf("# alpha %g, m = %g: Fmax %.4g N, E max/start %.5f, end/start %.4f, "
		       "exit vz %.3g m/s, %ld steps\n", alpha[i], law_m, r.Fmax,
		       r.Emax / r.E0, r.Eend / r.E0, r.v[0][2], r.steps);
		assert_int_equal(r.rc, DEM_OK);
		assert_true(r.Emax <= 1.01 * r.E0);
		assert_true(r.Fmax > 0);
		assert_true(r.v[0][2] > 0);   /* it bounced */
		free(r.u);
	}
}

static void test_alpha(void **state)
{
	(void)state;
	alpha_sweep(1.5);
}

/* The linear law, whose facet forces start hard at first touch (the
 * pressure of a linear law does not vanish at the contact circle's rim).
 * It was a known failure, E max/start 1.066 at alpha 1 with the area
 * factor, from two causes: the step of a shot landing on a node whose 4-8
 * facets all press on it was up to twice too long (each pair's limit took
 * the facet's mass over its share gamma, as if spread over three nodes;
 * the nodes' own limit, shotset.c, fixed it), and the area factor's forces
 * do not derive from a potential. */
static void test_alpha_linear(void **state)
{
	(void)state;
	alpha_sweep(1);
}

static void test_oblique(void **state)
{
	(void)state;
	static const double angle[] = { 60, 75 }, mu[] = { 0, 0.1, 0.5 };
	for (int a = 0; a < 2; a++) {
		double vt_prev = HUGE_VAL;
		for (int k = 0; k < 3; k++) {
			setup_t s;
			result_t r;
			alu_setup(&s, 2, 1.5);
			s.cp.friction = 1;
			s.cp.mu = mu[k];
			double th = angle[a] * DEM_PI / 180;
			s.shot[0].v[0] = 19 * cos(th);
			s.shot[0].v[2] = -19 * sin(th);
			run(&s, &r);
			printf("# angle %g mu %g: exit v (%.4g, %.4g, %.4g) m/s, spin %.4g rad/s, "
			       "max Ft/(mu Fn) %.6f, E max/start %.5f\n", angle[a], mu[k], r.v[0][0],
			       r.v[0][1], r.v[0][2], r.w[0][1], r.ftmax, r.Emax / r.E0);
			assert_int_equal(r.rc, DEM_OK);
			assert_true(r.Emax <= 1.01 * r.E0);
			if (mu[k] > 0)
				assert_true(r.ftmax <= 1 + 1e-12);
			else
				assert_true(r.ftmax == 0);
			/* friction slows the tangential motion and spins the shot
			 * forward (about +y for motion along +x); a high mu makes
			 * it stick and roll, so the slowing is not monotonic */
			if (mu[k] > 0) {
				assert_true(r.v[0][0] < vt_prev);
				assert_true(r.w[0][1] > 0);
			} else {
				vt_prev = r.v[0][0];
			}
			free(r.u);
		}
	}
}

/* Two shots at one point at once; the pair of rigid shots gets the
 * separation correction (contact/model.h) by default: it acts (the energy
 * it moves is not zero, and small against the input); switched off, the
 * pair keeps the thesis scheme's error and nothing is moved. */
static void test_two_shots(void **state)
{
	(void)state;
	for (int fix = 0; fix < 2; fix++) {
		setup_t s;
		result_t r;
		alu_setup(&s, 2, 1.5);
		s.ns = 2;
		s.shot[1] = s.shot[0];
		s.cp.sepfix = fix ? DEM_SEPFIX_OFF : DEM_SEPFIX_ON;
		run(&s, &r);
		printf("# two shots%s: exit vz %.4g, %.4g m/s, sphere contacts %g, E max/start %.5f, "
		       "separation correction %.3g J (of %.3g J)\n", fix ? " (no correction)" : "",
		       r.v[0][2], r.v[1][2], r.sphere_contacts, r.Emax / r.E0, r.sepfix_J, r.E0);
		assert_int_equal(r.rc, DEM_OK);
		assert_true(r.sphere_contacts > 0);
		assert_true(r.Emax <= 1.01 * r.E0);
		/* the second shot started touching the first, above it */
		assert_true(r.x[1][2] > r.x[0][2]);
		if (fix)
			assert_true(r.sepfix_J == 0);
		else
			assert_true(r.sepfix_J != 0 && fabs(r.sepfix_J) < 0.01 * r.E0);
		free(r.u);
	}
}

static void test_fast_shot(void **state)
{
	(void)state;
	setup_t s;
	result_t r;
	alu_setup(&s, 2, 1.5);
	s.shot[0].v[2] = -150;
	run(&s, &r);
	printf("# 150 m/s: Fmax %.4g N, exit vz %.4g m/s, E max/start %.5f, end/start %.4f\n",
	       r.Fmax, r.v[0][2], r.Emax / r.E0, r.Eend / r.E0);
	assert_int_equal(r.rc, DEM_OK);
	assert_true(r.Emax <= 1.01 * r.E0);
	free(r.u);
}

/* friction absent and friction with mu = 0; 1 and 2 threads */
static void test_effects(void **state)
{
	(void)state;
	setup_t s;
	result_t r0, r1, r2;
	alu_setup(&s, 2, 1.5);
	s.shot[0].v[0] = 19 * cos(DEM_PI / 3);
	s.shot[0].v[2] = -19 * sin(DEM_PI / 3);
	s.ns = 2;
	s.shot[1] = s.shot[0];
	s.shot[1].x[0] = 0.3e-3;
	run(&s, &r0);
	s.cp.friction = 1;
	s.cp.mu = 0;
	run(&s, &r1);
	s.threads = 2;
	run(&s, &r2);
	dem_mesh_t mesh;
	mesh_build(&s, &mesh);
	assert_memory_equal(r0.u, r1.u, 3 * mesh.nn * sizeof *r0.u);
	assert_memory_equal(r0.v, r1.v, sizeof r0.v);
	assert_memory_equal(r0.x, r1.x, sizeof r0.x);
	assert_memory_equal(r1.u, r2.u, 3 * mesh.nn * sizeof *r0.u);
	assert_memory_equal(r1.x, r2.x, sizeof r0.x);
	assert_int_equal(r0.steps, r1.steps);
	dem_mesh_free(&mesh);
	free(r0.u), free(r1.u), free(r2.u);
}

/* The step after the shot has left: whenever the shot is out of reach of
 * the surface within the block's step (a lower bound of its distance to
 * the facets by brute force, above twice the closing speed bound |v_shot|
 * + the fastest top node's speed times the block's step), the step is the
 * block's.  The Ch. 7.5 shot leaves a dimple on the plastic block and
 * rises out of it; the run goes on for three contact times.  The planes
 * of the dimple's tilted facets cut the rising shot: counting them as in
 * reach held the contact step (2.4e-9 s against the block's 1.3e-8 s at
 * lambda 0.05 on examples/ch75's mesh) to the end of the pass. */
static void test_step_after_rebound(void **state)
{
	(void)state;
	setup_t s;
	result_t r;
	alu_setup(&s, 2, 1.5);
	s.lambda = 0.05;
	s.check_step = 1;
	s.t_end = 12e-6;
	run(&s, &r);
	printf("# rebound: contact %.3g to %.3g s, then to %.3g s: %ld steps out of reach, "
	       "%ld held below the block's step, %ld steps in all\n",
	       r.t_first, r.t_last, s.t_end, r.free_steps, r.held_steps, r.steps);
	if (r.held_steps)
		printf("# first held: t %.4g s, dt %.3g s, gap %.3g m\n", r.held_t, r.held_dt, r.held_gap);
	assert_int_equal(r.rc, DEM_OK);
	assert_true(r.t_first >= 0 && r.t_last < 0.5 * s.t_end);   /* it touched, and left */
	assert_true(r.v[0][2] > 0);
	assert_true(r.free_steps > 100);
	assert_int_equal(r.held_steps, 0);
	free(r.u);
}

/* A shot whose path misses the block (aimed beside it, flying outward and
 * down) has left as soon as it starts: the pass ends when the shot that
 * hits has left, at the same step and with the same block, bit for bit,
 * as without the other shot.  Before, "left" meant moving up, and such a
 * shot held its pass to the pass's time limit (examples/verification, at
 * 60 degrees).  A shot beside the block flying toward it has not left. */
static void test_shot_misses(void **state)
{
	(void)state;
	setup_t s;
	result_t r1, r2;
	alu_setup(&s, 2, 1.5);
	s.gap = 1e-6;
	run(&s, &r1);
	s.ns = 2;
	s.shot[1] = (dem_shot_t){ .r = 0.5e-3, .x = { s.L + 2 * 0.5e-3, 0 }, .v = { 10, 0, -19 } };
	run(&s, &r2);
	printf("# a shot beside the block: %ld steps with it, %ld without; its exit v (%.3g, %.3g, %.3g) m/s\n",
	       r2.steps, r1.steps, r2.v[1][0], r2.v[1][1], r2.v[1][2]);
	assert_int_equal(r1.rc, DEM_OK);
	assert_int_equal(r2.rc, DEM_OK);
	assert_int_equal(r1.steps, r2.steps);
	dem_mesh_t mesh;
	mesh_build(&s, &mesh);
	assert_memory_equal(r1.u, r2.u, 3 * mesh.nn * sizeof *r1.u);
	assert_memory_equal(r1.v[0], r2.v[0], sizeof r1.v[0]);
	assert_true(r2.v[1][2] == -19 && r2.v[1][0] == 10);   /* it never touched */
	free(r1.u), free(r2.u);

	/* beside the block and above it, flying toward it: not left */
	dem_contact_model_t cm;
	dem_mat_t mat;
	dem_fe_t *fe;
	dem_shotset_t *S;
	dem_error_t e = { 0 };
	dem_fe_opts_t fo;
	dem_fe_opts_default(&fo);
	assert_int_equal(dem_mat_init(&mat, &s.mat, &e), DEM_OK);
	assert_int_equal(dem_fe_create(&fe, &mesh, &mat, &fo, &e), DEM_OK);
	assert_int_equal(dem_contact_model_init(&cm, &s.cp, &e), DEM_OK);
	dem_shotset_opts_t so = { .rho = s.rho_shot, .lambda = s.lambda, .buffer = s.h, .gap = s.gap, .threads = 1 };
	assert_int_equal(dem_shotset_create(&S, &mesh, dem_fe_mass(fe), &cm, &so, &e), DEM_OK);
	dem_shot_t in = { .r = 0.5e-3, .x = { s.L + 2 * 0.5e-3, 0 }, .v = { -10, 0, -19 } };
	assert_int_equal(dem_shotset_begin(S, 1, &in, dem_fe_coords(fe), &e), DEM_OK);
	assert_false(dem_shotset_done(S));
	dem_shot_t out = { .r = 0.5e-3, .x = { s.L + 2 * 0.5e-3, 0 }, .v = { 10, 0, -19 } };
	assert_int_equal(dem_shotset_begin(S, 1, &out, dem_fe_coords(fe), &e), DEM_OK);
	assert_true(dem_shotset_done(S));
	dem_shotset_free(S);
	dem_fe_free(fe);
	dem_mat_free(&mat);
	dem_mesh_free(&mesh);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_hertz),
		cmocka_unit_test(test_soft_block),
		cmocka_unit_test(test_alpha),
		cmocka_unit_test(test_alpha_linear),
		cmocka_unit_test(test_oblique),
		cmocka_unit_test(test_two_shots),
		cmocka_unit_test(test_fast_shot),
		cmocka_unit_test(test_effects),
		cmocka_unit_test(test_step_after_rebound),
		cmocka_unit_test(test_shot_misses),
	};
	if (getenv("ONLY"))
		cmocka_set_test_filter(getenv("ONLY"));
	return cmocka_run_group_tests(tests, NULL, NULL);
}
