/* test_fe_ranks.c - lib/fe/explicit on several ranks (issue 22; explicit.h,
 * "Ranks"; lib/par): a shot of Ch. 7.5 hitting a small block, run by this
 * process alone (opts.par NULL) and by the whole group of ranks, compared
 * at the end on every rank.
 *
 * References: the serial run.  One rank gives it to the bit (the
 * partitioned code with one rank is the serial code); more ranks add the
 * internal forces of the shared node planes in another order, so they give
 * it to round-off: every node displacement, element stress and plastic
 * strain, the shot's position and velocity and the energies within 1e-9
 * of the field's largest magnitude (issue 22, acceptance 1).  Every rank
 * holds the same bits after dem_fe_sync (what rank 0 writes is what all
 * ranks integrated).  A run the test cannot tell apart from a broken one
 * would be one with no contact or no plastic flow: both are asserted.
 *
 * The plain build runs it as one rank; `make MPI=1` builds it on MPI and
 * make check runs it under mpirun -np 1, 2 and 4 (tests/mpi/run.sh).
 *
 * Data of Ch. 7.5 (thesis-data.yaml, shot_peening_3d): shot radius 0.5 mm
 * at 19 m/s, aluminium E = 68 GPa, yield 157 MPa, hardening 120 MPa;
 * steel shot 7800 kg/m^3, aluminium 2700 kg/m^3 and nu = 0.33 are textbook
 * values; the global damping ratio 0.05 of Ch. 7.5 (explicit.h).
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

#include "contact/model.h"
#include "fe/explicit.h"
#include "fe/material.h"
#include "mesh/mesh.h"
#include "par/par.h"
#include "shot/shotset.h"

typedef struct result {
	double *u, *sig, *ep;   /* displacements, stresses, plastic strains */
	double shot[6];         /* shot centre and velocity */
	double en[4];           /* kinetic, internal, plastic, external */
	size_t nn, ne;
	double contact_steps;
} result_t;

/* What the group shares for the tests (cmocka's state). */
typedef struct group {
	dem_par_t *par;
} group_t;

static void result_free(result_t *r)
{
	free(r->u), free(r->sig), free(r->ep);
}

/* The Ch. 7.5 block (half width 1 mm, 1 mm thick, fine 0.1 mm elements in
 * 0.4 mm around the impact and 0.3 mm deep, growing by 1.3 outside), one
 * shot, nsteps steps, by the ranks of par (NULL: this process). */
static void run(dem_par_t *par, dem_fe_rule_t rule, int large, long nsteps, result_t *r)
{
	dem_mesh_t mesh;
	dem_mat_t mat;
	dem_error_t e = { 0 };
	dem_fe_t *fe;
	dem_shotset_t *S;
	dem_contact_model_t cm;
	dem_axis_t ax[3] = {
		{ -1e-3, 1e-3, -0.4e-3, 0.4e-3, 0.1e-3, 1.3, 0 },
		{ -1e-3, 1e-3, -0.4e-3, 0.4e-3, 0.1e-3, 1.3, 0 },
		{ -1e-3, 0, -0.3e-3, 0, 0.1e-3, 1.3, 0 },
	};
	memset(r, 0, sizeof *r);
	assert_int_equal(dem_mesh_box(&mesh, ax, &e), DEM_OK);
	dem_bc_t bc[6] = { DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL, DEM_BC_NORMAL,
			   DEM_BC_FIXED, DEM_BC_FREE };
	dem_mesh_set_bc(&mesh, bc);
	dem_mat_param_t mp = { .E = 68e9, .nu = 0.33, .rho = 2700, .sy0 = 157e6, .H = 120e6 };
	assert_int_equal(dem_mat_init(&mat, &mp, &e), DEM_OK);
	dem_fe_opts_t fo;
	dem_fe_opts_default(&fo);
	fo.rule = rule;
	fo.large = large;
	fo.threads = 1;
	fo.damping = dem_fe_damping_alpha(&mat, 0.05, 1e-3);
	fo.par = par;
	int rc = dem_fe_create(&fe, &mesh, &mat, &fo, &e);
	if (rc)
		fprintf(stderr, "%s\n", e.msg);
	assert_int_equal(rc, DEM_OK);
	dem_contact_param_t cp = { 0 };
	assert_int_equal(dem_law_init(&cp.law, 2, 68e9, 1.5, &e), DEM_OK);
	assert_int_equal(dem_contact_model_init(&cm, &cp, &e), DEM_OK);
	dem_shotset_opts_t so = { .rho = 7800, .lambda = 0.2, .buffer = 0.1e-3, .gap = 1e-6, .threads = 1 };
	assert_int_equal(dem_shotset_create(&S, &mesh, dem_fe_mass(fe), &cm, &so, &e), DEM_OK);
	/* off the node lines, so no symmetry hides a misplaced force */
	dem_shot_t shot = { .x = { 0.03e-3, -0.02e-3 }, .r = 0.5e-3, .v = { 1, 0.5, -19 } };
	assert_int_equal(dem_shotset_begin(S, 1, &shot, dem_fe_coords(fe), &e), DEM_OK);
	dem_fe_set_load(fe, dem_shotset_hook, S);
	for (long n = 0; n < nsteps; n++) {
		double dt;
		assert_int_equal(dem_shotset_prepare(S, dem_fe_coords(fe), dem_fe_velocity(fe), dem_fe_dt(fe),
						     &dt, &e), DEM_OK);
		rc = dem_fe_step(fe, dt, &e);
		if (rc)
			fprintf(stderr, "step %ld: %s\n", n, e.msg);
		assert_int_equal(rc, DEM_OK);
		r->contact_steps += dem_shotset_body(S, 0)->contacts > 0;
		if (n == nsteps / 2)
			dem_fe_sync(fe);   /* an output half way must not change the run */
	}
	dem_fe_sync(fe);
	r->nn = mesh.nn, r->ne = mesh.ne;
	r->u = malloc(3 * mesh.nn * sizeof *r->u);
	r->sig = malloc(6 * mesh.ne * sizeof *r->sig);
	r->ep = malloc(mesh.ne * sizeof *r->ep);
	assert_true(r->u && r->sig && r->ep);
	dem_fe_displacements(fe, r->u);
	dem_fe_fields(fe, r->sig, NULL, r->ep);
	const dem_shot_body_t *b = dem_shotset_body(S, 0);
	memcpy(r->shot, b->x, 3 * sizeof *r->shot);
	memcpy(r->shot + 3, b->v, 3 * sizeof *r->shot);
	dem_fe_energy_t en;
	dem_fe_energy(fe, &en);
	r->en[0] = en.kinetic, r->en[1] = en.internal, r->en[2] = en.plastic, r->en[3] = en.external;
	dem_shotset_free(S);
	dem_fe_free(fe);
	dem_mat_free(&mat);
	dem_mesh_free(&mesh);
}

/* largest |a - b| over the largest |a| */
static double rel(const double *a, const double *b, size_t n)
{
	double d = 0, m = 0;
	for (size_t i = 0; i < n; i++) {
		d = fmax(d, fabs(a[i] - b[i]));
		m = fmax(m, fabs(a[i]));
	}
	return m > 0 ? d / m : d;
}

/* every rank's copy the same bits as rank 0's */
static int same_as_root(dem_par_t *par, const double *a, size_t n)
{
	double *c = malloc(n * sizeof *c);
	assert_non_null(c);
	memcpy(c, a, n * sizeof *c);
	dem_par_bcast(par, c, n * sizeof *c, 0);
	int bad = memcmp(c, a, n * sizeof *c) != 0;
	free(c);
	return dem_par_max_int(par, bad) == 0;
}

static void compare(dem_par_t *par, dem_fe_rule_t rule, int large, const char *name)
{
	result_t s, p;
	const long nsteps = 400;
	run(NULL, rule, large, nsteps, &s);
	run(par, rule, large, nsteps, &p);
	int np = dem_par_size(par);
	double du = rel(s.u, p.u, 3 * s.nn), ds = rel(s.sig, p.sig, 6 * s.ne), de = rel(s.ep, p.ep, s.ne);
	double dx = rel(s.shot, p.shot, 3), dv = rel(s.shot + 3, p.shot + 3, 3), dE = rel(s.en, p.en, 4);
	double epmax = 0;
	for (size_t i = 0; i < s.ne; i++)
		epmax = fmax(epmax, s.ep[i]);
	printf("# %s, %d ranks: relative differences from the serial run: u %.3g, stress %.3g, "
	       "plastic strain %.3g, shot x %.3g v %.3g, energies %.3g (contact %g steps, ep max %.4f)\n",
	       name, np, du, ds, de, dx, dv, dE, s.contact_steps, epmax);
	/* a run that shows something: the shot touched, the block flowed */
	assert_true(s.contact_steps > 50);
	assert_true(epmax > 1e-3);
	if (np == 1) {
		assert_memory_equal(s.u, p.u, 3 * s.nn * sizeof *s.u);
		assert_memory_equal(s.sig, p.sig, 6 * s.ne * sizeof *s.sig);
		assert_memory_equal(s.ep, p.ep, s.ne * sizeof *s.ep);
		assert_memory_equal(s.shot, p.shot, sizeof s.shot);
		assert_memory_equal(s.en, p.en, sizeof s.en);
	} else {
		assert_true(du <= 1e-9 && ds <= 1e-9 && de <= 1e-9);
		assert_true(dx <= 1e-9 && dv <= 1e-9 && dE <= 1e-9);
	}
	assert_true(same_as_root(par, p.u, 3 * p.nn));
	assert_true(same_as_root(par, p.sig, 6 * p.ne));
	assert_true(same_as_root(par, p.shot, 6));
	assert_true(same_as_root(par, p.en, 4));
	result_free(&s);
	result_free(&p);
}

/* Ch. 7.5's run: one-point elements, large strain */
static void test_large(void **state)
{
	compare(((group_t *)*state)->par, DEM_FE_1PT, 1, "one-point, large strain");
}

static void test_small(void **state)
{
	compare(((group_t *)*state)->par, DEM_FE_1PT, 0, "one-point, small strain");
}

static void test_full(void **state)
{
	compare(((group_t *)*state)->par, DEM_FE_FULL, 1, "2x2x2 B-bar, large strain");
}

/* More ranks than slabs of element layers: a clear refusal (and one rank
 * is never refused: there is a layer). */
static void test_too_many(void **state)
{
	dem_par_t *par = ((group_t *)*state)->par;
	int np = dem_par_size(par);
	dem_mesh_t mesh;
	dem_mat_t mat;
	dem_error_t e = { 0 };
	int nz = np > 1 ? np - 1 : 1;
	dem_axis_t ax[3] = {
		{ 0, 2e-3, 0, 2e-3, 1e-3, 1, 0 },
		{ 0, 2e-3, 0, 2e-3, 1e-3, 1, 0 },
		{ 0, nz * 1e-3, 0, nz * 1e-3, 1e-3, 1, 0 },
	};
	assert_int_equal(dem_mesh_box(&mesh, ax, &e), DEM_OK);
	assert_int_equal(mesh.nz, nz);
	dem_mat_param_t mp = { .E = 68e9, .nu = 0.33, .rho = 2700 };
	assert_int_equal(dem_mat_init(&mat, &mp, &e), DEM_OK);
	dem_fe_opts_t fo;
	dem_fe_opts_default(&fo);
	fo.par = par;
	dem_fe_t *fe = NULL;
	int rc = dem_fe_create(&fe, &mesh, &mat, &fo, &e);
	if (np > 1) {
		assert_int_equal(rc, DEM_EINPUT);
		assert_non_null(strstr(e.msg, "ranks for"));
		assert_null(fe);
	} else {
		assert_int_equal(rc, DEM_OK);
	}
	dem_fe_free(fe);
	dem_mat_free(&mat);
	dem_mesh_free(&mesh);
}

/* lib/par's operations against what they must give, computed here by
 * brute force from the values every rank is known to hold (exact: sums of
 * small integers, and the ordered sum redone in the same order). */
static void test_par(void **state)
{
	dem_par_t *par = ((group_t *)*state)->par;
	int np = dem_par_size(par), r = dem_par_rank(par);
	enum { N = 5 };
	double lo[N], hi[N], buf[2 * N];
	for (int i = 0; i < N; i++)
		lo[i] = 10 * r + i, hi[i] = 100 * r + i;
	dem_par_halo_sum(par, lo, hi, N, buf);
	for (int i = 0; i < N; i++) {
		/* the plane below: rank r - 1's hi + my lo; above: my hi + rank r + 1's lo */
		assert_true(r == 0 ? lo[i] == i : lo[i] == 100.0 * (r - 1) + i + (10.0 * r + i));
		assert_true(r == np - 1 ? hi[i] == 100.0 * r + i : hi[i] == 100.0 * r + i + (10.0 * (r + 1) + i));
	}
	double v[N], *sb = malloc((size_t)np * N * sizeof *sb);
	assert_non_null(sb);
	for (int i = 0; i < N; i++)
		v[i] = 0.1 * (r + 1) + 1e-17 * i;
	dem_par_sum_ordered(par, v, N, sb);
	for (int i = 0; i < N; i++) {
		double want = 0.1 * 1 + 1e-17 * i;
		for (int q = 1; q < np; q++)
			want += 0.1 * (q + 1) + 1e-17 * i;
		assert_true(v[i] == want);
	}
	free(sb);
	assert_true(dem_par_min(par, 0.5 * (r + 1)) == 0.5);
	assert_int_equal(dem_par_max_int(par, r), np - 1);
	/* rank q fills items [q (q + 1) / 2, (q + 1) (q + 2) / 2): q + 1 items */
	size_t *off = malloc((size_t)(np + 1) * sizeof *off);
	assert_non_null(off);
	for (int q = 0; q <= np; q++)
		off[q] = (size_t)q * (size_t)(q + 1) / 2;
	double (*it)[2] = calloc(off[np], sizeof *it);
	assert_non_null(it);
	for (size_t k = off[r]; k < off[r + 1]; k++)
		it[k][0] = r, it[k][1] = (double)k;
	dem_par_gather(par, it, sizeof *it, off);
	for (int q = 0; q < np; q++)
		for (size_t k = off[q]; k < off[q + 1]; k++)
			assert_true(it[k][0] == q && it[k][1] == (double)k);
	free(it), free(off);
	char msg[8] = "";
	if (r == 0)
		memcpy(msg, "rank 0", 7);
	dem_par_bcast(par, msg, sizeof msg, 0);
	assert_string_equal(msg, "rank 0");
	dem_par_barrier(par);
}

int main(int argc, char **argv)
{
	group_t g;
	dem_error_t e = { 0 };
	if (dem_par_init(&g.par, &argc, &argv, &e)) {
		fprintf(stderr, "%s\n", e.msg);
		return 1;
	}
	/* rank 0 reports; the others' failures show in their exit codes */
	if (dem_par_rank(g.par) != 0 && !freopen("/dev/null", "w", stdout))
		return 1;
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_prestate(test_par, &g),
		cmocka_unit_test_prestate(test_large, &g),
		cmocka_unit_test_prestate(test_small, &g),
		cmocka_unit_test_prestate(test_full, &g),
		cmocka_unit_test_prestate(test_too_many, &g),
	};
	int rc = cmocka_run_group_tests(tests, NULL, NULL);
	/* a failure on any rank fails every rank */
	rc = dem_par_max_int(g.par, rc);
	dem_par_finalize(g.par);
	return rc ? 1 : 0;
}
