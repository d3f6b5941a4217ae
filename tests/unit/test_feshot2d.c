/* test_feshot2d.c - unit tests of the FE shot of Ch. 7.4 (issue 18): the
 * disk's O-grid (mesh/mesh2.c dem_mesh2_disk), the node-to-segment
 * geometry (contact/node2d.c) and the FE shot (shot/feshot2d.c through
 * shot/shotset2d.c).
 *
 * References, per test:
 *  - disk mesh: the elements tile the inscribed polygon of the rim, so
 *    their areas sum to its area (N/2) R^2 sin(2 pi / N) to 1e-12, which is
 *    pi R^2 (1 - (2 pi / N)^2 / 6 + ...) (within (2 pi/N)^2 / 6 of pi R^2);
 *    every corner of every element has a positive Jacobian; the rim nodes
 *    lie on the circle to 1e-12 R and no rim segment is longer than h;
 *    the element and node counts are 4 n m + n^2 and 4 n (m + 1) + (n-1)^2
 *    (mesh2.h) and every inner edge is shared by exactly two elements, the
 *    4 n rim segments by one (a conforming mesh);
 *  - node/segment: penetration, foot and normal of hand-made cases;
 *  - drop, energy: an FE shot (E_s = 100 E) dropped on an elastic block
 *    without damping: the total energy (both bodies' kinetic and internal
 *    energy and the penalty's) within 1e-3 of the impact energy at every
 *    step and after the contact (the bound test_shotset2d.c puts on the
 *    block's balance under a rigid disk);
 *  - drop: the same shot against the rigid DE disk of shotset2d.c on the
 *    same block with the same law (the penalty is that law's Winkler
 *    form, feshot2d.h): peak force and contact time within 5 %, the
 *    tolerance of test_shotset2d.c's rigid drop against the closed form of
 *    the law, and the DE disk within 5 % of that closed form, as there,
 *    d = (5 M v^2 / (4 k))^(2/5), F = k d^(3/2), t_c = 2.94327 d / v (the
 *    block's own compliance is a few % of the approach, so the closed
 *    form is not the FE shot's reference: its difference is printed);
 *  - refusals: a law not of m = 1.5, friction, an axisymmetric block, two
 *    shots in a pass.
 * Material: steel (E 210 GPa, nu 0.3, 7800 kg/m^3), elastic.
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

#include "contact/law.h"
#include "contact/model.h"
#include "contact/node2d.h"
#include "fe/explicit2d.h"
#include "fe/material.h"
#include "mesh/mesh2.h"
#include "shot/feshot2d.h"
#include "shot/shotset2d.h"
#include "slow.h"

#define PI 3.14159265358979323846

static void steel(dem_mat_t *m)
{
	dem_mat_param_t p = { .E = 210e9, .nu = 0.3, .rho = 7800 };
	dem_error_t e = { 0 };
	assert_int_equal(dem_mat_init(m, &p, &e), DEM_OK);
}

static int edge_cmp(const void *a, const void *b)
{
	const uint64_t *x = a, *y = b;
	return *x < *y ? -1 : *x > *y;
}

static void disk_case(double R, double h)
{
	dem_mesh2_t m;
	dem_error_t e = { 0 };
	const double c[2] = { 0.3 * R, -1.7 * R };
	size_t nrim;
	assert_int_equal(dem_mesh2_disk(&m, R, h, c, &nrim, &e), DEM_OK);
	int n = (int)ceil(PI * R / (2 * h)), mm = (int)fmax(1, round(0.5 * R / h));
	assert_int_equal(nrim, 4 * (size_t)n);
	assert_int_equal(m.ne, 4 * (size_t)n * (size_t)mm + (size_t)n * (size_t)n);
	assert_int_equal(m.nn, 4 * (size_t)n * ((size_t)mm + 1) + (size_t)(n - 1) * (size_t)(n - 1));
	assert_int_equal(m.nx, 0);
	/* areas and Jacobians */
	double A = 0, jmin = HUGE_VAL;
	for (size_t el = 0; el < m.ne; el++) {
		double x[8];
		dem_mesh2_gather(&m, el, NULL, x);
		for (int I = 0; I < 4; I++) {
			int J = (I + 1) % 4, K = (I + 3) % 4;
			double j = (x[J] - x[I]) * (x[4 + K] - x[4 + I]) - (x[4 + J] - x[4 + I]) * (x[K] - x[I]);
			jmin = fmin(jmin, j);
			A += 0.5 * (x[I] * x[4 + J] - x[J] * x[4 + I]);
		}
	}
	double N = (double)nrim, Apoly = 0.5 * N * R * R * sin(2 * PI / N);
	double rmax = 0, lmax = 0;
	for (size_t k = 0; k < nrim; k++) {
		const double *p = m.X + 2 * k, *q = m.X + 2 * ((k + 1) % nrim);
		rmax = fmax(rmax, fabs(hypot(p[0] - c[0], p[1] - c[1]) - R));
		lmax = fmax(lmax, hypot(q[0] - p[0], q[1] - p[1]));
	}
	/* conformity: each edge, sorted, twice inside, once on the rim */
	uint64_t *ed = malloc(4 * m.ne * sizeof *ed);
	for (size_t el = 0; el < m.ne; el++)
		for (int I = 0; I < 4; I++) {
			uint64_t a = m.quad[4 * el + I], b = m.quad[4 * el + (I + 1) % 4];
			ed[4 * el + (size_t)I] = a < b ? a << 32 | b : b << 32 | a;
		}
	qsort(ed, 4 * m.ne, sizeof *ed, edge_cmp);
	size_t once = 0, bad = 0;
	for (size_t i = 0; i < 4 * m.ne;) {
		size_t j = i;
		while (j < 4 * m.ne && ed[j] == ed[i])
			j++;
		if (j - i == 1) {
			once++;
			uint64_t a = ed[i] >> 32, b = ed[i] & 0xffffffffu;
			bad += !(a < nrim && b < nrim);
		} else if (j - i != 2) {
			bad++;
		}
		i = j;
	}
	free(ed);
	printf("# disk R %g mm, h %g mm: %zu elements, %zu nodes, %zu rim segments (longest %.4g mm); "
	       "area / pi R^2 - 1 = %.3g (polygon %.3g), least corner Jacobian / h^2 %.3g\n", R * 1e3,
	       h * 1e3, m.ne, m.nn, nrim, lmax * 1e3, A / (PI * R * R) - 1, Apoly / (PI * R * R) - 1,
	       jmin / (h * h));
	assert_true(fabs(A / Apoly - 1) < 1e-12);
	assert_true(fabs(A / (PI * R * R) - 1) <= (2 * PI / N) * (2 * PI / N) / 6);
	assert_true(jmin > 0);
	assert_true(rmax < 1e-12 * R);
	assert_true(lmax <= h * (1 + 1e-12));
	assert_int_equal(once, nrim);
	assert_int_equal(bad, 0);
	/* the engine takes it: masses sum to rho A t */
	dem_mat_t mat;
	steel(&mat);
	dem_fe2_opts_t o;
	dem_fe2_opts_default(&o);
	dem_fe2_t *fe;
	assert_int_equal(dem_fe2_create(&fe, &m, &mat, &o, &e), DEM_OK);
	double M = 0;
	for (size_t i = 0; i < m.nn; i++)
		M += dem_fe2_mass(fe)[i];
	assert_true(fabs(M / (mat.rho * A * o.thick) - 1) < 1e-12);
	dem_fe2_free(fe);
	dem_mat_free(&mat);
	dem_mesh2_free(&m);
}

static void test_disk_mesh(void **state)
{
	(void)state;
	disk_case(20e-3, 0.5e-3);   /* Ch. 7.4's shot at the block's element */
	disk_case(20e-3, 3e-3);
	disk_case(1e-3, 1e-3);      /* the coarsest: n = 2, m = 1 */
	disk_case(0.25e-3, 7e-6);
	dem_mesh2_t m;
	dem_error_t e = { 0 };
	assert_int_equal(dem_mesh2_disk(&m, 1, 0, (double[2]){ 0, 0 }, NULL, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	dem_error_clear(&e);
	assert_int_equal(dem_mesh2_disk(&m, 1, 1e-5, (double[2]){ 0, 0 }, NULL, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
}

static void test_node_segment(void **state)
{
	(void)state;
	const double A[2] = { 0, 0 }, B[2] = { 2, 0 };  /* outside: +y */
	dem_node_seg_t g;
	assert_int_equal(dem_node_segment((double[2]){ 0.5, -0.1 }, A, B, 1, 0, &g), 1);
	assert_true(fabs(g.g - 0.1) < 1e-15 && fabs(g.xi - 0.25) < 1e-15);
	assert_true(g.n[0] == 0 && g.n[1] == 1 && g.L == 2);
	assert_int_equal(dem_node_segment((double[2]){ 0.5, 0.1 }, A, B, 1, 0, &g), 0);   /* outside */
	assert_int_equal(dem_node_segment((double[2]){ 0.5, -1.5 }, A, B, 1, 0, &g), 0);  /* too deep */
	assert_int_equal(dem_node_segment((double[2]){ 2.01, -0.1 }, A, B, 1, 0, &g), 0); /* off the end */
	assert_int_equal(dem_node_segment((double[2]){ 2.01, -0.1 }, A, B, 1, 0.01, &g), 1);
	assert_true(g.xi == 1);
	/* the reversed segment has its outside below */
	assert_int_equal(dem_node_segment((double[2]){ 0.5, 0.1 }, B, A, 1, 0, &g), 1);
	assert_true(fabs(g.xi - 0.75) < 1e-15 && g.n[1] == -1);
}

/* The drop of test_shotset2d.c (a disk of radius R at v0 on a plane
 * strain block, the thesis's 2D Hertz law of Eq. 3.45 m = 3/2), with a
 * larger contact (b/R about 0.2) so that the FE disk's rim resolves it. */
typedef struct drop {
	double R, v0, k, M, d, Fc, tc, b;
	dem_mesh2_t m;
	dem_mat_t mat;
	dem_law_t law;
} drop_t;

typedef struct res {
	double Fmax, t_on, t_off, v_end, emax, eend, ke0, dt;
	long steps;
	size_t ne;
} res_t;

static void drop_init(drop_t *d, int nb)
{
	dem_error_t e = { 0 };
	memset(d, 0, sizeof *d);
	steel(&d->mat);
	d->R = 1e-3, d->v0 = 10;
	d->M = 7800 * PI * d->R * d->R;
	/* the overlap d = 0.02 R at the peak, so b = sqrt(2 R d) = 0.2 R */
	double dd = 0.02 * d->R;
	d->k = 5 * d->M * d->v0 * d->v0 / (4 * pow(dd, 2.5));
	double alpha = d->k * sqrt(d->R) / d->mat.E;
	assert_int_equal(dem_law_init_dim(&d->law, alpha, d->mat.E, 1.5, 2, &e), DEM_OK);
	d->d = dd;
	d->Fc = d->k * pow(dd, 1.5);
	d->tc = 2.94327 * dd / d->v0;
	d->b = sqrt(2 * d->R * dd);
	double h = d->b / nb, W = 20 * d->b, H = 10 * d->b;
	dem_axis_t ax[2] = { { -W / 2, W / 2, -2 * d->b, 2 * d->b, h, 1.25, 0 },
			     { -H, 0, -2 * d->b, 0, h, 1.25, 0 } };
	assert_int_equal(dem_mesh2_rect(&d->m, ax, &e), DEM_OK);
	dem_bc_t bc[4] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh2_set_bc(&d->m, bc);
}

static void drop_free(drop_t *d)
{
	dem_mesh2_free(&d->m);
	dem_mat_free(&d->mat);
}

/* fe: NULL for the rigid DE disk, else the FE shot's options */
static void drop_run(drop_t *d, const dem_feshot2d_opts_t *fe, res_t *r)
{
	dem_error_t e = { 0 };
	dem_fe2_opts_t fo;
	dem_fe2_opts_default(&fo);
	dem_fe2_t *blk;
	assert_int_equal(dem_fe2_create(&blk, &d->m, &d->mat, &fo, &e), DEM_OK);
	dem_contact_model_t cm;
	dem_contact_param_t cp = { .law = d->law, .partial = DEM_PARTIAL_AREA };
	assert_int_equal(dem_contact_model_init(&cm, &cp, &e), DEM_OK);
	dem_shotset2d_opts_t so = { .mode = DEM_QUAD4_PLANE, .thick = 1, .rho = 7800, .lambda = 0.2,
				    .gap = 0, .fe = fe };
	dem_shotset2d_t *S;
	assert_int_equal(dem_shotset2d_create(&S, &d->m, dem_fe2_mass(blk), &cm, &so, &e), DEM_OK);
	dem_shot_t sh = { .pass = 0, .r = d->R, .v = { 0, 0, -d->v0 } };
	assert_int_equal(dem_shotset2d_begin(S, 1, &sh, dem_fe2_coords(blk), &e), DEM_OK);
	dem_fe2_set_load(blk, dem_shotset2d_hook, S);
	const dem_feshot2d_t *F = dem_shotset2d_feshot(S);
	memset(r, 0, sizeof *r);
	r->t_on = -1;
	r->ke0 = dem_shotset2d_kinetic(S);
	r->dt = HUGE_VAL;
	const dem_shot_body_t *b = dem_shotset2d_body(S, 0);
	while (dem_fe2_time(blk) < 4 * d->tc) {
		double dt, t = dem_fe2_time(blk);
		assert_int_equal(dem_shotset2d_prepare(S, dem_fe2_coords(blk), dem_fe2_velocity(blk),
						       dem_fe2_dt(blk), &dt, &e), DEM_OK);
		r->dt = fmin(r->dt, dt);
		int rc = dem_fe2_step(blk, dt, &e);
		if (rc)
			printf("# %s\n", e.msg);
		assert_int_equal(rc, DEM_OK);
		if (b->contacts > 0) {
			if (r->t_on < 0)
				r->t_on = t;
			r->t_off = t + dt;
			r->Fmax = fmax(r->Fmax, b->F[1]);
		}
		if (F) {
			/* the energy of both bodies and of the penalty, at t_n:
			 * each body's balance counts the contact's work on it as
			 * external; their sum is minus the penalty's energy */
			dem_fe_energy_t eb, es;
			dem_fe2_energy(blk, &eb);
			dem_fe2_energy(dem_feshot2d_model(F), &es);
			double err = fabs(eb.balance + es.balance + eb.external + es.external +
					  dem_feshot2d_penalty_energy(F)) / r->ke0;
			r->emax = fmax(r->emax, err);
			r->eend = err;
		}
		if (dem_shotset2d_done(S))
			break;
	}
	assert_true(dem_shotset2d_done(S));
	r->v_end = b->v[1];
	r->steps = dem_fe2_steps(blk);
	r->ne = d->m.ne + (F ? dem_feshot2d_mesh(F)->ne : 0);
	dem_shotset2d_free(S);
	dem_fe2_free(blk);
}

static void fe_opts(const drop_t *d, double ratio, double h, dem_feshot2d_opts_t *o)
{
	memset(o, 0, sizeof *o);
	o->element = h;
	o->E = ratio * d->mat.E, o->nu = d->mat.nu, o->rho = 7800;
	dem_fe2_opts_default(&o->fe);
}

static void test_drop(void **state)
{
	(void)state;
	drop_t d;
	int nb = SLOW_CASES(8, 4);
	drop_init(&d, nb);
	dem_feshot2d_opts_t o;
	fe_opts(&d, 100, d.b / 4, &o);  /* 4 rim segments on the half width */
	res_t rf, rd;
	drop_run(&d, &o, &rf);
	drop_run(&d, NULL, &rd);
	double tf = rf.t_off - rf.t_on, td = rd.t_off - rd.t_on;
	printf("# energy: FE shot E_s = 100 E, %zu elements in all, %ld steps of %.3g s: total energy "
	       "error at most %.3g of the impact energy, %.3g after the contact; rebound %.4f v0\n",
	       rf.ne, rf.steps, rf.dt, rf.emax, rf.eend, rf.v_end / d.v0);
	assert_true(rf.emax < 1e-3);
	assert_true(rf.eend < 1e-3);
	printf("# drop b/h %d: closed form F %.5g N/m, t_c %.4g us; DE disk F %.5g (%+.2f %%), t_c %.4g "
	       "us (%+.2f %%); FE shot F %.5g (%+.2f %% of DE, %+.2f %% of closed), t_c %.4g us (%+.2f %% "
	       "of DE, %+.2f %% of closed); cost %ld x %zu against %ld x %zu element steps\n", nb, d.Fc,
	       d.tc * 1e6, rd.Fmax, 100 * (rd.Fmax / d.Fc - 1), td * 1e6, 100 * (td / d.tc - 1), rf.Fmax,
	       100 * (rf.Fmax / rd.Fmax - 1), 100 * (rf.Fmax / d.Fc - 1), tf * 1e6, 100 * (tf / td - 1),
	       100 * (tf / d.tc - 1), rf.steps, rf.ne, rd.steps, rd.ne);
	assert_true(fabs(rf.Fmax / rd.Fmax - 1) <= 0.05);
	assert_true(fabs(tf / td - 1) <= 0.05);
	assert_true(fabs(rd.Fmax / d.Fc - 1) <= 0.05);
	assert_true(fabs(td / d.tc - 1) <= 0.05);
	drop_free(&d);
}

static void test_refused(void **state)
{
	(void)state;
	drop_t d;
	drop_init(&d, 2);
	dem_error_t e = { 0 };
	double *mass = calloc(d.m.nn, sizeof *mass);
	for (size_t i = 0; i < d.m.nn; i++)
		mass[i] = 1e-6;
	dem_feshot2d_opts_t o;
	fe_opts(&d, 100, d.b, &o);
	dem_law_t lin;
	assert_int_equal(dem_law_init_dim(&lin, 1, d.mat.E, 1, 2, &e), DEM_OK);
	dem_contact_model_t c1, cf, ch;
	assert_int_equal(dem_contact_model_init(&c1, &(dem_contact_param_t){ .law = lin }, &e), DEM_OK);
	assert_int_equal(dem_contact_model_init(&cf, &(dem_contact_param_t){ .law = d.law, .friction = 1,
									      .mu = 0.1 }, &e), DEM_OK);
	assert_int_equal(dem_contact_model_init(&ch, &(dem_contact_param_t){ .law = d.law }, &e), DEM_OK);
	dem_shotset2d_opts_t so = { .mode = DEM_QUAD4_PLANE, .thick = 1, .rho = 7800, .lambda = 0.2, .fe = &o };
	dem_shotset2d_t *S;
	assert_int_equal(dem_shotset2d_create(&S, &d.m, mass, &c1, &so, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	dem_error_clear(&e);
	assert_int_equal(dem_shotset2d_create(&S, &d.m, mass, &cf, &so, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	dem_error_clear(&e);
	o.fe.mode = DEM_QUAD4_AXISYM;
	assert_int_equal(dem_shotset2d_create(&S, &d.m, mass, &ch, &so, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	dem_error_clear(&e);
	o.fe.mode = DEM_QUAD4_PLANE;
	assert_int_equal(dem_shotset2d_create(&S, &d.m, mass, &ch, &so, &e), DEM_OK);
	dem_shot_t sh[2] = { { .r = d.R, .x = { -2 * d.R, 0 }, .v = { 0, 0, -1 } },
			     { .r = d.R, .x = { 2 * d.R, 0 }, .v = { 0, 0, -1 } } };
	assert_int_equal(dem_shotset2d_begin(S, 2, sh, d.m.X, &e), DEM_EINPUT);
	printf("# %s\n", e.msg);
	dem_error_clear(&e);
	assert_int_equal(dem_shotset2d_begin(S, 1, sh, d.m.X, &e), DEM_OK);
	dem_shotset2d_free(S);
	free(mass);
	drop_free(&d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_disk_mesh),
		cmocka_unit_test(test_node_segment),
		cmocka_unit_test(test_drop),
		cmocka_unit_test(test_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
