/* test_compress.c - sphere packing by compression (Ch. 6): after every
 * stage no two spheres overlap and none crosses a wall (checked by brute
 * force over all pairs and all walls, to 1e-9 of the smaller radius); the
 * fill fraction never falls from stage to stage; the potential energy
 * (Eq. 6.7) never rises within a compression (global, shake, relax); the
 * same seed gives the same packing; the relaxation under gravity lifts the
 * density above what the thesis's stages alone reach, its core above
 * random loose packing; the sampled density agrees with the exact one. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/rng.h"
#include "pack/compress.h"

/* What the stage callback saw. */
struct watch {
	const dem_domain_t *dom;
	double worst_overlap, worst_wall;   /* relative to the smaller radius */
	double last_density, last_pe;
	int stages, density_fell, pe_rose;
	double sum;                         /* a fingerprint of the packing */
	size_t n;
};

/* Brute force: every pair and every wall (box, cylinder). */
static void invariant(struct watch *w, const dem_compress_stage_t *s)
{
	const dem_domain_t *d = w->dom;
	for (size_t i = 0; i < s->n; i++) {
		double ri = s->r[i];
		for (size_t j = i + 1; j < s->n; j++) {
			double dx = s->x[0][i] - s->x[0][j], dy = s->x[1][i] - s->x[1][j];
			double dz = s->x[2][i] - s->x[2][j];
			double o = (ri + s->r[j] - sqrt(dx * dx + dy * dy + dz * dz))
				   / fmin(ri, s->r[j]);
			w->worst_overlap = fmax(w->worst_overlap, o);
		}
		for (int k = 0; k < 3; k++) {
			w->worst_wall = fmax(w->worst_wall, (d->lo[k] + ri - s->x[k][i]) / ri);
			w->worst_wall = fmax(w->worst_wall, (s->x[k][i] + ri - d->hi[k]) / ri);
		}
		for (size_t k = 0; k < d->nplane; k++) {
			const dem_plane_t *pl = &d->plane[k];
			double g = pl->n[0] * s->x[0][i] + pl->n[1] * s->x[1][i]
				   + pl->n[2] * s->x[2][i] - pl->d;
			w->worst_wall = fmax(w->worst_wall, (ri - g) / ri);
		}
		if (d->cylinder) {
			double qx = s->x[0][i] - d->axis[0], qy = s->x[1][i] - d->axis[1];
			w->worst_wall = fmax(w->worst_wall,
					     (sqrt(qx * qx + qy * qy) + ri - d->radius) / ri);
		}
	}
}

static int on_stage(void *ctx, const dem_compress_stage_t *s)
{
	struct watch *w = ctx;
	double before = w->worst_overlap + w->worst_wall;
	invariant(w, s);
	if (getenv("DBG") && w->worst_overlap + w->worst_wall > before)
		fprintf(stderr, "  broke at %s batch %d n %zu: %g %g\n", dem_compress_phase_names[s->phase], s->batch, s->n, w->worst_overlap, w->worst_wall);
	if (w->stages && s->density < w->last_density)
		w->density_fell = 1;
	/* within a compression (global, shake) the energy may only fall:
	 * every move has a component along -z that is >= 0 */
	if (w->stages && s->phase != DEM_COMPRESS_REFILL && s->pe > w->last_pe * (1 + 1e-12))
		w->pe_rose = 1;
	w->last_density = s->density;
	w->last_pe = s->pe;
	w->stages++;
	return 0;
}

static int on_emit(void *ctx, const double *x, double r)
{
	struct watch *w = ctx;
	w->sum += x[0] + 2 * x[1] + 3 * x[2] + 4 * r;
	w->n++;
	return 0;
}

static dem_compress_stats_t run(dem_compress_spec_t *s, unsigned long seed,
				struct watch *w)
{
	memset(w, 0, sizeof *w);
	w->dom = &s->dom;
	s->stage = on_stage;
	s->stage_ctx = w;
	gsl_rng *g = dem_rng_derive(seed, 0);
	dem_compress_stats_t st;
	dem_error_t e = {0};
	assert_int_equal(dem_pack_compress(s, g, on_emit, w, &st, &e), DEM_OK);
	gsl_rng_free(g);
	assert_int_equal(w->n, st.n);
	return st;
}

static void box(dem_compress_spec_t *s, double side, dem_radius_law_t law)
{
	dem_compress_spec_init(s);
	double lo[3] = {0, 0, 0}, hi[3] = {side, side, side};
	dem_domain_box(&s->dom, lo, hi);
	s->law = law;
	s->max_iter = 100;
	s->max_loops = 5;
	s->relax = 0;           /* the thesis's stages alone unless a test asks */
	s->tol = 1e-4;
}

static void expect_clean(const struct watch *w)
{
	if (getenv("DBG"))
		fprintf(stderr, "worst overlap %g wall %g\n", w->worst_overlap, w->worst_wall);
	assert_true(w->worst_overlap <= 1e-9);
	assert_true(w->worst_wall <= 1e-9);
	assert_false(w->density_fell);
	assert_false(w->pe_rose);
}

/* Mono spheres in a cube of 20 radii: invariant, monotone density and
 * energy, at least a random loose packing's density (0.45 with the walls
 * of so small a box). */
static void test_mono_box(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 20, (dem_radius_law_t){DEM_RADIUS_MONO, 1, 1});
	struct watch w;
	dem_compress_stats_t st = run(&s, 7, &w);
	expect_clean(&w);
	assert_true(w.stages >= 4);
	assert_true(st.n > 700);
	assert_true(st.density > 0.45);
}

/* URD with lambda 2 (a few thousand spheres): the same checks. */
static void test_urd_box(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 20, (dem_radius_law_t){DEM_RADIUS_URD, 0.5, 1});
	struct watch w;
	dem_compress_stats_t st = run(&s, 11, &w);
	expect_clean(&w);
	assert_true(st.n > 1500);
	assert_true(st.density > 0.45);
}

/* The exact curved wall: URD spheres in a cylinder. */
static void test_urd_cylinder(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 20, (dem_radius_law_t){DEM_RADIUS_URD, 0.5, 1});
	dem_domain_cylinder(&s.dom, 0, 0, 8, 0, 16);
	struct watch w;
	dem_compress_stats_t st = run(&s, 3, &w);
	expect_clean(&w);
	assert_true(st.n > 600);
	assert_true(st.density > 0.4);
}

/* A plane cutting the box (a wedge, x + z >= 8): no sphere crosses it
 * (the brute-force check includes the plane). */
static void test_plane(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 16, (dem_radius_law_t){DEM_RADIUS_MONO, 1, 1});
	const double c = sqrt(0.5);
	dem_plane_t pl = {{c, 0, c}, 16 * c * 0.5};     /* x + z >= 8 */
	s.dom.plane = &pl;
	s.dom.nplane = 1;
	struct watch w;
	dem_compress_stats_t st = run(&s, 5, &w);
	expect_clean(&w);
	assert_true(st.n > 100);
}

/* Same seed, same packing (the relaxation included); another seed,
 * another packing. */
static void test_seed(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 14, (dem_radius_law_t){DEM_RADIUS_URD, 0.5, 1});
	s.relax = 1;
	struct watch a, b, c;
	run(&s, 21, &a);
	run(&s, 21, &b);
	run(&s, 22, &c);
	assert_int_equal(a.n, b.n);
	assert_true(a.sum == b.sum);
	assert_true(a.sum != c.sum);
}

/* Relaxation: mono spheres in a cube of 16 radii, with and without it.
 * The packing stays valid, the density rises well above the thesis
 * stages' (by 0.05), and the core (a diameter from every wall) is denser
 * than random loose packing, 0.555 (Onoda and Liniger 1990): frictionless
 * spheres settled under gravity pack near random close packing, 0.64
 * (Silbert et al. 2002).  The whole-domain density of a packing filled to
 * the lid agrees with the sampled one below its top to 0.02. */
static void test_relax_mono(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 16, (dem_radius_law_t){DEM_RADIUS_MONO, 1, 1});
	struct watch w;
	dem_compress_stats_t thesis = run(&s, 5, &w);
	expect_clean(&w);
	s.relax = 1;
	dem_compress_stats_t st = run(&s, 5, &w);
	expect_clean(&w);
	assert_int_equal(st.removed, 0);
	assert_true(st.steps > 0);
	if (getenv("DBG")) fprintf(stderr, "thesis %g relax %g top %g core %g n %zu\n", thesis.density, st.density, st.density_top, st.density_core, st.n);
	assert_true(st.density > thesis.density + 0.05);
	assert_true(st.density_core > 0.555);
	assert_true(fabs(st.density_top - st.density) < 0.02);
	assert_true(st.density_core > st.density);     /* walls loosen */
}

/* Relaxation with URD spheres in a cylinder and in a box cut by a plane:
 * valid after every stage (brute force, the curved wall and the plane
 * included). */
static void test_relax_walls(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 20, (dem_radius_law_t){DEM_RADIUS_URD, 0.5, 1});
	dem_domain_cylinder(&s.dom, 0, 0, 6, 0, 12);
	s.relax = 1;
	struct watch w;
	dem_compress_stats_t st = run(&s, 9, &w);
	expect_clean(&w);
	assert_int_equal(st.removed, 0);
	assert_true(st.density > 0.5);

	box(&s, 12, (dem_radius_law_t){DEM_RADIUS_URD, 0.5, 1});
	const double c = sqrt(0.5);
	dem_plane_t pl = {{c, 0, c}, 12 * c * 0.5};     /* x + z >= 6 */
	s.dom.plane = &pl;
	s.dom.nplane = 1;
	s.relax = 1;
	st = run(&s, 4, &w);
	expect_clean(&w);
	assert_int_equal(st.removed, 0);
	assert_true(st.n > 200);
}

/* A bad spec is refused with DEM_EINPUT. */
static void test_bad_spec(void **state)
{
	(void)state;
	dem_compress_spec_t s;
	box(&s, 1.5, (dem_radius_law_t){DEM_RADIUS_MONO, 1, 1});
	gsl_rng *g = dem_rng_derive(1, 0);
	dem_error_t e = {0};
	assert_int_equal(dem_pack_compress(&s, g, NULL, NULL, NULL, &e), DEM_EINPUT);
	gsl_rng_free(g);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_mono_box),
		cmocka_unit_test(test_urd_box),
		cmocka_unit_test(test_urd_cylinder),
		cmocka_unit_test(test_plane),
		cmocka_unit_test(test_seed),
		cmocka_unit_test(test_relax_mono),
		cmocka_unit_test(test_relax_walls),
		cmocka_unit_test(test_bad_spec),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
