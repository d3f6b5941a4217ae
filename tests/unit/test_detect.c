/* test_detect.c - contact detection (lib/detect): every algorithm returns
 * exactly the pair set of brute force.
 *
 * The reference is dem_detect_brute, itself checked on hand-made sets whose
 * pairs are known; for periodic domains the reference is a minimum-image
 * brute force written here.  Every other algorithm runs through the public
 * dem_detect() and its sorted pairs must equal the reference's exactly: no
 * pair missing, none extra, none twice.  Random sets follow the Ch. 2.5
 * tests (disks and spheres, mono, URD, NRD and LNRD radii, size ratio
 * lambda = Rmax/Rmin); the hard sets are those of DESIGN.md: identical,
 * touching, zero-size, very unequal, collinear, tiny, far from the origin,
 * periodic.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "detect/detect.h"

/* The algorithms checked against brute force. */
static const dem_detect_algo_t algos[] = {
	DEM_DETECT_DCELL, DEM_DETECT_NBS, DEM_DETECT_SCELL,
	DEM_DETECT_ADT, DEM_DETECT_ASDT,
};
#define NALGO (sizeof algos / sizeof *algos)

#define PI 3.14159265358979323846

enum law { LAW_MONO, LAW_URD, LAW_NRD, LAW_LNRD };
static const char *const law_name[] = {"mono", "URD", "NRD", "LNRD"};

/* ------------------------------------------------------------------ */
/* Helpers */

static void boxes_new(dem_boxes_t *b, int dim, size_t n)
{
	assert_int_equal(dem_boxes_alloc(b, dim, n), DEM_OK);
}

static void set_box(dem_boxes_t *b, size_t i, const double *lo,
		    const double *hi)
{
	for (int d = 0; d < b->dim; d++) {
		b->lo[d][i] = lo[d];
		b->hi[d][i] = hi[d];
	}
}

/* Sort, then check the canonical form: i < j and no pair twice. */
static void sort_checked(dem_pairs_t *p, const char *what)
{
	assert_int_equal(dem_pairs_sort(p), DEM_OK);
	for (size_t k = 0; k < p->n; k++) {
		if (p->p[k].i >= p->p[k].j)
			fail_msg("%s: pair %zu is (%u, %u), not i < j", what, k,
				 p->p[k].i, p->p[k].j);
		if (k && p->p[k].i == p->p[k - 1].i && p->p[k].j == p->p[k - 1].j)
			fail_msg("%s: pair (%u, %u) reported twice", what,
				 p->p[k].i, p->p[k].j);
	}
}

/* Exact comparison of two sorted pair lists; names the first difference. */
static void expect_same(const dem_pairs_t *ref, const dem_pairs_t *got,
			const char *what)
{
	size_t k = 0;

	while (k < ref->n && k < got->n && ref->p[k].i == got->p[k].i &&
	       ref->p[k].j == got->p[k].j)
		k++;
	if (k == ref->n && k == got->n)
		return;
	char r[64] = "(end)", g[64] = "(end)";
	if (k < ref->n)
		snprintf(r, sizeof r, "(%u, %u)", ref->p[k].i, ref->p[k].j);
	if (k < got->n)
		snprintf(g, sizeof g, "(%u, %u)", got->p[k].i, got->p[k].j);
	fail_msg("%s: %zu pairs, brute force %zu; first difference at %zu: %s, brute force %s",
		 what, got->n, ref->n, k, g, r);
}

/* The brute-force reference, sorted; it must test every pair once. */
static void reference(const dem_boxes_t *b, dem_pairs_t *ref)
{
	dem_detect_stats_t st = {0};

	dem_pairs_init(ref);
	assert_int_equal(dem_detect_brute(b, ref, &st), DEM_OK);
	assert_int_equal(st.checks, b->n > 1 ? b->n * (b->n - 1) / 2 : 0);
	sort_checked(ref, "brute");
}

/* Run one algorithm through dem_detect with the options o (algo set
 * here); pairs sorted into got. */
static int detect(const dem_boxes_t *b, const dem_detect_opts_t *o,
		  dem_detect_algo_t a, dem_pairs_t *got, dem_detect_stats_t *st)
{
	dem_detect_opts_t oo = *o;
	dem_error_t e;

	oo.algo = a;
	dem_error_clear(&e);
	dem_pairs_init(got);
	int rc = dem_detect(b, &oo, got, st, &e);
	if (rc == DEM_OK) {
		assert_int_equal(e.code, DEM_OK);
		assert_false(got->nomem);
	} else {
		assert_int_equal(e.code, rc);
		assert_true(e.msg[0] != '\0');
	}
	return rc;
}

/* Every algorithm with options o against the sorted reference ref.  NBS
 * is 2D only: elsewhere it must be refused with DEM_EINPUT and no pairs. */
static void check_algos(const dem_boxes_t *b, const dem_detect_opts_t *o,
			const dem_pairs_t *ref, const char *label)
{
	for (size_t a = 0; a < NALGO; a++) {
		dem_pairs_t got;
		dem_detect_stats_t st = {0};
		char what[160];

		snprintf(what, sizeof what, "%s: %s", label,
			 dem_detect_algo_name(algos[a]));
		int rc = detect(b, o, algos[a], &got, &st);
		if (algos[a] == DEM_DETECT_NBS && b->dim != 2) {
			if (rc != DEM_EINPUT)
				fail_msg("%s: %dD accepted (rc %d), expected DEM_EINPUT",
					 what, b->dim, rc);
			assert_int_equal(got.n, 0);
			dem_pairs_free(&got);
			continue;
		}
		if (rc != DEM_OK)
			fail_msg("%s: rc %d", what, rc);
		sort_checked(&got, what);
		expect_same(ref, &got, what);
		dem_pairs_free(&got);
	}
}

/* Brute force, then every algorithm with default options. */
static size_t check_all(const dem_boxes_t *b, const char *label)
{
	dem_detect_opts_t o;
	dem_pairs_t ref;

	dem_detect_opts_init(&o);
	reference(b, &ref);
	check_algos(b, &o, &ref, label);
	size_t n = ref.n;
	dem_pairs_free(&ref);
	return n;
}

static double draw_radius(gsl_rng *r, enum law law, double rmin, double rmax)
{
	if (law == LAW_MONO || !(rmax > rmin))
		return rmax;
	if (law == LAW_URD)
		return rmin + (rmax - rmin) * gsl_rng_uniform(r);
	if (law == LAW_NRD) {
		/* Ch. 2.5: mean (Rmin + Rmax) / 2, sd (Rmax - Rmin) / 6,
		 * truncated to [Rmin, Rmax] by rejection */
		double mu = 0.5 * (rmin + rmax), sd = (rmax - rmin) / 6;
		for (;;) {
			double x = mu + gsl_ran_gaussian(r, sd);
			if (x >= rmin && x <= rmax)
				return x;
		}
	}
	/* LNRD: ln R normal about the middle of [ln Rmin, ln Rmax] with a
	 * sixth of that range as sd, truncated the same way */
	double a = log(rmin), c = log(rmax), mu = 0.5 * (a + c), sd = (c - a) / 6;
	for (;;) {
		double x = exp(mu + gsl_ran_gaussian(r, sd));
		if (x >= rmin && x <= rmax)
			return x;
	}
}

/* n disks (2D) or spheres (3D, or segments in 1D) with radii in
 * [rmax / lambda, rmax] by the given law, centres uniform in a square or
 * cube placed at origin and sized for the packing density rho (overlaps
 * allowed, as in the random fills of Ch. 2.5); their bounding boxes.
 * Returns the side of the square or cube. */
static double random_set(dem_boxes_t *b, int dim, size_t n, enum law law,
			 double lambda, double rho, double rmax, double origin,
			 unsigned long seed)
{
	gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
	double *rad = malloc((n ? n : 1) * sizeof *rad), vol = 0;

	assert_non_null(r);
	assert_non_null(rad);
	gsl_rng_set(r, seed);
	for (size_t i = 0; i < n; i++) {
		rad[i] = draw_radius(r, law, rmax / lambda, rmax);
		vol += dim == 1 ? 2 * rad[i] : dim == 2 ? PI * rad[i] * rad[i] :
			4.0 / 3 * PI * rad[i] * rad[i] * rad[i];
	}
	double side = pow(vol / rho, 1.0 / dim);
	boxes_new(b, dim, n);
	for (size_t i = 0; i < n; i++)
		for (int d = 0; d < dim; d++) {
			double c = origin + side * gsl_rng_uniform(r);
			b->lo[d][i] = c - rad[i];
			b->hi[d][i] = c + rad[i];
		}
	free(rad);
	gsl_rng_free(r);
	return side;
}

static double mean_extent(const dem_boxes_t *b, int d)
{
	double s = 0;
	for (size_t i = 0; i < b->n; i++)
		s += b->hi[d][i] - b->lo[d][i];
	return s / (double)b->n;
}

/* ------------------------------------------------------------------ */
/* Brute force itself, against hand-counted pairs. */

/* Four 2D boxes: A and B share an edge, B and C share only a corner, D is
 * one ulp away from A; pairs A-B and B-C, six tests. */
static void test_brute_hand(void **state)
{
	(void)state;
	dem_boxes_t b;
	dem_pairs_t p;
	dem_detect_stats_t st = {0};

	boxes_new(&b, 2, 4);
	set_box(&b, 0, (double[]){0, 0}, (double[]){1, 1});
	set_box(&b, 1, (double[]){1, 0}, (double[]){2, 1});
	set_box(&b, 2, (double[]){2, 1}, (double[]){3, 2});
	set_box(&b, 3, (double[]){-1, nextafter(1, 2)}, (double[]){0, 2});
	dem_pairs_init(&p);
	assert_int_equal(dem_detect_brute(&b, &p, &st), DEM_OK);
	assert_int_equal(st.checks, 6);
	sort_checked(&p, "brute");
	assert_int_equal(p.n, 2);
	assert_int_equal(p.p[0].i, 0);
	assert_int_equal(p.p[0].j, 1);
	assert_int_equal(p.p[1].i, 1);
	assert_int_equal(p.p[1].j, 2);
	/* the same set, through every algorithm */
	assert_int_equal(check_all(&b, "hand"), 2);
	dem_pairs_free(&p);
	dem_boxes_free(&b);
}

/* ------------------------------------------------------------------ */
/* Random sets: every radius law, lambda in {1, 10, 100, 1000}, against
 * brute force. */

typedef struct rcase {
	int dim;
	enum law law;
} rcase_t;

static void test_random(void **state)
{
	const rcase_t *c = *state;
	static const double lambdas[] = {1, 10, 100, 1000};
	size_t n = c->dim == 2 ? 3000 : 2000;
	double rho = c->dim == 2 ? 0.6 : 0.3;

	for (size_t l = 0; l < 4; l++) {
		if (c->law == LAW_MONO && l > 0)
			break;          /* lambda does not apply */
		dem_boxes_t b;
		char label[96];
		snprintf(label, sizeof label, "%dD %s lambda=%g", c->dim,
			 law_name[c->law], lambdas[l]);
		random_set(&b, c->dim, n, c->law, lambdas[l], rho, 1, 0,
			   1000u * c->dim + 10u * c->law + l);
		size_t np = check_all(&b, label);
		assert_true(np > 0);
		dem_boxes_free(&b);
	}
}

/* The same random set at a lower density (0.3 in 2D) and 1D segments. */
static void test_random_sparse_1d(void **state)
{
	(void)state;
	dem_boxes_t b;

	random_set(&b, 2, 3000, LAW_URD, 10, 0.3, 1, 0, 77);
	check_all(&b, "2D URD rho=0.3");
	dem_boxes_free(&b);
	random_set(&b, 1, 3000, LAW_URD, 10, 0.5, 1, 0, 78);
	check_all(&b, "1D URD");
	dem_boxes_free(&b);
}

/* ------------------------------------------------------------------ */
/* The cell knob: D-cell, S-cell and NBS give the brute-force set whatever
 * the cell size (0.1, 1 and 10 times the mean size) or cell factor. */
static void test_cell_size(void **state)
{
	(void)state;
	static const double scale[] = {0.1, 1, 10};
	static const double factor[] = {0.5, 1, 3, 5, 20};
	static const dem_detect_algo_t cellalgos[] = {
		DEM_DETECT_DCELL, DEM_DETECT_SCELL, DEM_DETECT_NBS,
	};

	for (int dim = 2; dim <= 3; dim++) {
		dem_boxes_t b;
		dem_pairs_t ref;
		random_set(&b, dim, 2000, LAW_URD, 10, 0.5, 1, 0, 300u + dim);
		reference(&b, &ref);
		for (int k = 0; k < 3 + 5; k++) {
			dem_detect_opts_t o;
			dem_detect_opts_init(&o);
			if (k < 3)
				for (int d = 0; d < dim; d++)
					o.cell[d] = scale[k] * mean_extent(&b, d);
			else
				o.cell_factor = factor[k - 3];
			for (size_t a = 0; a < 3; a++) {
				if (cellalgos[a] == DEM_DETECT_NBS && dim != 2)
					continue;
				dem_pairs_t got;
				dem_detect_stats_t st = {0};
				char what[128];
				snprintf(what, sizeof what, "%dD %s cell=%g factor=%g",
					 dim, dem_detect_algo_name(cellalgos[a]),
					 o.cell[0], o.cell_factor);
				assert_int_equal(detect(&b, &o, cellalgos[a], &got, &st),
						 DEM_OK);
				sort_checked(&got, what);
				expect_same(&ref, &got, what);
				/* the grid used is reported */
				for (int d = 0; d < dim; d++) {
					assert_true(st.cells[d] >= 1);
					assert_true(st.cell[d] > 0);
				}
				dem_pairs_free(&got);
			}
		}
		dem_pairs_free(&ref);
		dem_boxes_free(&b);
	}
}

/* ------------------------------------------------------------------ */
/* Hard sets. */

/* All boxes identical (unit boxes, then points): every pair overlaps,
 * n(n-1)/2 of them; the tree methods build a chain n deep. */
static void test_identical(void **state)
{
	(void)state;
	const size_t n = 400;

	for (int dim = 1; dim <= 3; dim++)
		for (int zero = 0; zero <= 1; zero++) {
			dem_boxes_t b;
			char label[64];
			boxes_new(&b, dim, n);
			for (size_t i = 0; i < n; i++)
				for (int d = 0; d < dim; d++) {
					b.lo[d][i] = 3.25;
					b.hi[d][i] = zero ? 3.25 : 4.5;
				}
			snprintf(label, sizeof label, "%dD identical%s", dim,
				 zero ? " points" : "");
			assert_int_equal(check_all(&b, label), n * (n - 1) / 2);
			dem_boxes_free(&b);
		}
}

/* A k x k (x k) grid of unit boxes with integer corners, offset by org and
 * scaled by h (both exact in binary): every box touches its neighbours on
 * faces, edges and corners.  Per axis, (3k - 2) ordered pairs of indices
 * differ by at most 1, so the pair count is ((3k-2)^dim - k^dim) / 2: in 2D
 * 2k(k-1) face pairs plus 2(k-1)^2 corner pairs. */
static void touching_grid(dem_boxes_t *b, int dim, size_t k, double org,
			  double h)
{
	size_t n = 1;
	for (int d = 0; d < dim; d++)
		n *= k;
	boxes_new(b, dim, n);
	for (size_t i = 0; i < n; i++) {
		size_t r = i;
		for (int d = 0; d < dim; d++) {
			b->lo[d][i] = org + h * (double)(r % k);
			b->hi[d][i] = org + h * (double)(r % k + 1);
			r /= k;
		}
	}
}

static void test_touching(void **state)
{
	(void)state;
	static const double org[] = {0, -7, 1e6};
	static const double h[] = {1, 0.5, 1};

	for (int dim = 1; dim <= 3; dim++) {
		size_t k = dim == 1 ? 500 : dim == 2 ? 30 : 9;
		size_t all = 1, self = 1;
		for (int d = 0; d < dim; d++) {
			all *= 3 * k - 2;
			self *= k;
		}
		for (int v = 0; v < 3; v++) {
			dem_boxes_t b;
			char label[96];
			touching_grid(&b, dim, k, org[v], h[v]);
			snprintf(label, sizeof label, "%dD touching grid k=%zu org=%g h=%g",
				 dim, k, org[v], h[v]);
			assert_int_equal(check_all(&b, label), (all - self) / 2);
			dem_boxes_free(&b);
		}
	}
}

/* Corners only: the black squares of a k x k checkerboard touch only at
 * corners, (k-1)^2 pairs; and the same boxes shrunk by one ulp on the
 * upper side touch nothing. */
static void test_corners(void **state)
{
	(void)state;
	const size_t k = 41;
	dem_boxes_t b;

	for (int gap = 0; gap <= 1; gap++) {
		boxes_new(&b, 2, (k * k + 1) / 2);
		size_t m = 0;
		for (size_t y = 0; y < k; y++)
			for (size_t x = 0; x < k; x++) {
				if ((x + y) % 2)
					continue;
				double lo[2] = {(double)x + 1e6, (double)y};
				double hi[2] = {(double)x + 1 + 1e6, (double)y + 1};
				if (gap) {
					hi[0] = nextafter(hi[0], 0);
					hi[1] = nextafter(hi[1], 0);
				}
				set_box(&b, m++, lo, hi);
			}
		assert_int_equal(m, b.n);
		assert_int_equal(check_all(&b, gap ? "checkerboard, ulp gap" :
					  "checkerboard"), gap ? 0 : (k - 1) * (k - 1));
		dem_boxes_free(&b);
	}
}

/* Zero-size boxes: a k x k lattice of points, each point twice (k^2 pairs),
 * and, against brute force, points on the faces and corners of unit boxes
 * mixed with zero-width segments. */
static void test_zero_size(void **state)
{
	(void)state;
	const size_t k = 40;
	dem_boxes_t b;

	boxes_new(&b, 2, 2 * k * k);
	for (size_t i = 0; i < 2 * k * k; i++) {
		double p[2] = {(double)(i % (k * k) % k), (double)(i % (k * k) / k)};
		set_box(&b, i, p, p);
	}
	assert_int_equal(check_all(&b, "point lattice twice"), k * k);
	dem_boxes_free(&b);

	for (int dim = 2; dim <= 3; dim++) {
		gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
		const size_t n = 3000;
		gsl_rng_set(r, 500u + dim);
		boxes_new(&b, dim, n);
		for (size_t i = 0; i < n; i++) {
			int kind = (int)(i % 3);
			for (int d = 0; d < dim; d++) {
				/* corners on a 0.5 lattice so contacts are exact */
				double x = 0.5 * (double)gsl_rng_uniform_int(r, 40);
				b.lo[d][i] = x;
				/* unit box, point, or zero width along axis 0 */
				b.hi[d][i] = kind == 0 ? x + 1 : kind == 1 ? x :
					     d == 0 ? x : x + 0.5;
			}
		}
		char label[64];
		snprintf(label, sizeof label, "%dD points and segments", dim);
		check_all(&b, label);
		dem_boxes_free(&b);
		gsl_rng_free(r);
	}
}

/* One huge box among small ones: covering all of them (n - 1 pairs with
 * it, at the start, middle and end of the input), and covering half. */
static void test_huge(void **state)
{
	(void)state;
	for (int dim = 2; dim <= 3; dim++)
		for (int where = 0; where < 4; where++) {
			dem_boxes_t b;
			char label[64];
			size_t n = 2000, at = where == 0 ? 0 : where == 1 ? n / 2 : n - 1;
			random_set(&b, dim, n, LAW_URD, 2, 0.4, 1, 0, 600u + dim);
			double side = 0;
			for (size_t i = 0; i < n; i++)
				side = fmax(side, b.hi[0][i]);
			for (int d = 0; d < dim; d++) {
				b.lo[d][at] = -1e3;
				b.hi[d][at] = where == 3 ? 0.5 * side : 1e3;
			}
			snprintf(label, sizeof label, "%dD huge box at %zu%s", dim, at,
				 where == 3 ? " (half)" : "");
			size_t np = check_all(&b, label);
			assert_true(np >= (where == 3 ? n / 8 : n - 1));
			dem_boxes_free(&b);
		}
}

/* All boxes on one line: unit boxes every 0.75 along x, along the
 * diagonal, and along the last axis; each overlaps only its successor,
 * n - 1 pairs. */
static void test_line(void **state)
{
	(void)state;
	const size_t n = 4000;

	for (int dim = 1; dim <= 3; dim++)
		for (int dir = 0; dir < 3; dir++) {
			dem_boxes_t b;
			char label[64];
			boxes_new(&b, dim, n);
			for (size_t i = 0; i < n; i++)
				for (int d = 0; d < dim; d++) {
					int moves = dir == 0 ? d == 0 : dir == 1 ? 1 :
						    d == dim - 1;
					double x = moves ? 0.75 * (double)i : 5;
					b.lo[d][i] = x;
					b.hi[d][i] = x + 1;
				}
			snprintf(label, sizeof label, "%dD line %s", dim,
				 dir == 0 ? "x" : dir == 1 ? "diagonal" : "last axis");
			assert_int_equal(check_all(&b, label), n - 1);
			dem_boxes_free(&b);
		}
}

/* N = 0, 1 and 2 in 1, 2 and 3 dimensions: no pairs, then one. */
static void test_tiny(void **state)
{
	(void)state;
	for (int dim = 1; dim <= 3; dim++)
		for (size_t n = 0; n <= 2; n++) {
			dem_boxes_t b;
			char label[64];
			boxes_new(&b, dim, n);
			for (size_t i = 0; i < n; i++)
				for (int d = 0; d < dim; d++) {
					b.lo[d][i] = (double)i;
					b.hi[d][i] = (double)i + 1;
				}
			snprintf(label, sizeof label, "%dD n=%zu", dim, n);
			assert_int_equal(check_all(&b, label), n == 2);
			dem_boxes_free(&b);
		}
}

/* Far from the origin: small boxes (radii 1e-3 .. 1e-2) about 1e6, where
 * the spacing of doubles is 1e-10. */
static void test_far(void **state)
{
	(void)state;
	for (int dim = 2; dim <= 3; dim++) {
		dem_boxes_t b;
		char label[64];
		random_set(&b, dim, 3000, LAW_URD, 10, 0.5, 1e-2, 1e6, 700u + dim);
		snprintf(label, sizeof label, "%dD at 1e6", dim);
		assert_true(check_all(&b, label) > 0);
		dem_boxes_free(&b);
		random_set(&b, dim, 3000, LAW_MONO, 1, 0.5, 1e-3, -1e6, 710u + dim);
		snprintf(label, sizeof label, "%dD at -1e6", dim);
		assert_true(check_all(&b, label) > 0);
		dem_boxes_free(&b);
	}
}

/* Determinism and the append contract: two runs give the same pairs in
 * the same order, after whatever out already held; counters are filled,
 * and a NULL stats pointer is fine. */
static void test_repeat(void **state)
{
	(void)state;
	dem_boxes_t b;
	dem_detect_opts_t o;

	random_set(&b, 2, 2000, LAW_URD, 10, 0.5, 1, 0, 800);
	dem_detect_opts_init(&o);
	for (size_t a = 0; a < NALGO; a++) {
		dem_pairs_t p1, p2;
		dem_detect_stats_t st = {0};
		dem_error_t e;
		dem_error_clear(&e);
		o.algo = algos[a];
		dem_pairs_init(&p1);
		dem_pairs_init(&p2);
		dem_pairs_push(&p1, 7, 3);              /* stored as (3, 7) */
		assert_int_equal(dem_detect(&b, &o, &p1, &st, &e), DEM_OK);
		assert_int_equal(dem_detect(&b, &o, &p2, NULL, &e), DEM_OK);
		assert_int_equal(p1.n, p2.n + 1);
		assert_int_equal(p1.p[0].i, 3);
		assert_int_equal(p1.p[0].j, 7);
		assert_memory_equal(p1.p + 1, p2.p, p2.n * sizeof *p2.p);
		assert_true(st.checks >= p2.n);
		dem_pairs_free(&p1);
		dem_pairs_free(&p2);
	}
	dem_boxes_free(&b);
}

/* NBS is 2D only: 3D (and 1D) is refused with DEM_EINPUT, nothing
 * appended. */
static void test_nbs_3d(void **state)
{
	(void)state;
	for (int dim = 1; dim <= 3; dim += 2) {
		dem_boxes_t b;
		dem_pairs_t p;
		dem_detect_opts_t o;
		random_set(&b, dim, 100, LAW_MONO, 1, 0.5, 1, 0, 900);
		dem_detect_opts_init(&o);
		assert_int_equal(detect(&b, &o, DEM_DETECT_NBS, &p, NULL), DEM_EINPUT);
		assert_int_equal(p.n, 0);
		dem_pairs_free(&p);
		dem_boxes_free(&b);
	}
}

/* ------------------------------------------------------------------ */
/* Periodic domains. */

/* Minimum-image brute force: i and j overlap when, on every axis, some
 * shift of j by k periods (k in {-1, 0, 1}; 0 only on open axes) makes the
 * closed intervals meet. */
static void periodic_reference(const dem_boxes_t *b, const dem_detect_opts_t *o,
			       dem_pairs_t *ref)
{
	dem_pairs_init(ref);
	for (size_t i = 0; i < b->n; i++)
		for (size_t j = i + 1; j < b->n; j++) {
			int all = 1;
			for (int d = 0; d < b->dim && all; d++) {
				int per = o->periodic >> d & 1, any = 0;
				double L = o->period_hi[d] - o->period_lo[d];
				for (int k = per ? -1 : 0; k <= (per ? 1 : 0); k++)
					any |= b->lo[d][i] <= b->hi[d][j] + k * L &&
					       b->lo[d][j] + k * L <= b->hi[d][i];
				all = any;
			}
			if (all)
				dem_pairs_push(ref, (uint32_t)i, (uint32_t)j);
		}
	assert_false(ref->nomem);
	sort_checked(ref, "periodic brute");
}

static void check_periodic(const dem_boxes_t *b, const dem_detect_opts_t *o,
			   const char *label, size_t expect)
{
	dem_pairs_t ref;
	char what[128];

	periodic_reference(b, o, &ref);
	if (expect != (size_t)-1)
		assert_int_equal(ref.n, expect);
	check_algos(b, o, &ref, label);
	/* the dispatcher's images with brute force, too */
	dem_pairs_t got;
	snprintf(what, sizeof what, "%s: brute", label);
	assert_int_equal(detect(b, o, DEM_DETECT_BRUTE, &got, NULL), DEM_OK);
	sort_checked(&got, what);
	expect_same(&ref, &got, what);
	dem_pairs_free(&got);
	dem_pairs_free(&ref);
}

/* Random disks and spheres in a period [-3.5, -3.5 + L) on all axes and on
 * some, boxes straddling the faces; against the minimum-image reference. */
static void test_periodic_random(void **state)
{
	(void)state;
	for (int dim = 2; dim <= 3; dim++) {
		dem_boxes_t b;
		/* the period is the square or cube the centres fill */
		double side = random_set(&b, dim, 2000, LAW_URD, 10, 0.5, 1,
					 -3.5, 1000u + dim);
		unsigned masks[] = {(1u << dim) - 1, 1, 2, 5};
		for (int m = 0; m < 4; m++) {
			if (masks[m] >= (1u << dim))
				continue;
			dem_detect_opts_t o;
			char label[64];
			dem_detect_opts_init(&o);
			o.periodic = masks[m];
			for (int d = 0; d < dim; d++) {
				o.period_lo[d] = -3.5;
				o.period_hi[d] = -3.5 + side;
			}
			snprintf(label, sizeof label, "%dD periodic mask %u", dim,
				 masks[m]);
			check_periodic(&b, &o, label, (size_t)-1);
		}
		dem_boxes_free(&b);
	}
}

/* A k x k (x k) grid of unit boxes filling the period exactly: with
 * wrap-around every box touches its 3^dim - 1 neighbours, (3^dim - 1) k^dim
 * / 2 pairs, the ones across the faces found only through images. */
static void test_periodic_touching(void **state)
{
	(void)state;
	for (int dim = 2; dim <= 3; dim++) {
		size_t k = dim == 2 ? 12 : 5, n = 1, nb = 1;
		dem_boxes_t b;
		dem_detect_opts_t o;
		char label[64];
		touching_grid(&b, dim, k, 0, 1);
		dem_detect_opts_init(&o);
		o.periodic = (1u << dim) - 1;
		for (int d = 0; d < dim; d++) {
			o.period_lo[d] = 0;
			o.period_hi[d] = (double)k;
			n *= k;
			nb *= 3;
		}
		snprintf(label, sizeof label, "%dD periodic touching grid", dim);
		check_periodic(&b, &o, label, (nb - 1) * n / 2);
		dem_boxes_free(&b);
	}
}

/* A box longer than half the period along a periodic axis is refused
 * with DEM_EINPUT by every algorithm; along an open axis it is fine. */
static void test_periodic_refused(void **state)
{
	(void)state;
	dem_boxes_t b;
	dem_detect_opts_t o;

	boxes_new(&b, 2, 3);
	set_box(&b, 0, (double[]){0, 0}, (double[]){1, 1});
	set_box(&b, 1, (double[]){1, 0}, (double[]){7.1, 1});   /* 6.1 > 10/2 */
	set_box(&b, 2, (double[]){5, 5}, (double[]){6, 6});
	dem_detect_opts_init(&o);
	o.period_lo[0] = o.period_lo[1] = 0;
	o.period_hi[0] = o.period_hi[1] = 10;
	for (int mask = 1; mask <= 2; mask++) {
		o.periodic = (unsigned)mask;
		for (size_t a = 0; a <= NALGO; a++) {
			dem_detect_algo_t al = a < NALGO ? algos[a] : DEM_DETECT_BRUTE;
			dem_pairs_t p;
			int rc = detect(&b, &o, al, &p, NULL);
			if (mask == 1 && rc != DEM_EINPUT)
				fail_msg("%s: long box on periodic x accepted (rc %d)",
					 dem_detect_algo_name(al), rc);
			if (mask == 2) {
				assert_int_equal(rc, DEM_OK);
				assert_int_equal(p.n, 1);       /* 0-1 touch */
			}
			dem_pairs_free(&p);
		}
	}
	dem_boxes_free(&b);
}

int main(void)
{
	static const rcase_t rc[] = {
		{2, LAW_MONO}, {2, LAW_URD}, {2, LAW_NRD}, {2, LAW_LNRD},
		{3, LAW_MONO}, {3, LAW_URD}, {3, LAW_NRD}, {3, LAW_LNRD},
	};
	/* one test per dimension and law, named for the report */
#define RANDOM(k, name) { "test_random_" name, test_random, NULL, NULL, \
			  (void *)&rc[k] }
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_brute_hand),
		RANDOM(0, "2d_mono"),
		RANDOM(1, "2d_urd"),
		RANDOM(2, "2d_nrd"),
		RANDOM(3, "2d_lnrd"),
		RANDOM(4, "3d_mono"),
		RANDOM(5, "3d_urd"),
		RANDOM(6, "3d_nrd"),
		RANDOM(7, "3d_lnrd"),
		cmocka_unit_test(test_random_sparse_1d),
		cmocka_unit_test(test_cell_size),
		cmocka_unit_test(test_identical),
		cmocka_unit_test(test_touching),
		cmocka_unit_test(test_corners),
		cmocka_unit_test(test_zero_size),
		cmocka_unit_test(test_huge),
		cmocka_unit_test(test_line),
		cmocka_unit_test(test_tiny),
		cmocka_unit_test(test_far),
		cmocka_unit_test(test_repeat),
		cmocka_unit_test(test_nbs_3d),
		cmocka_unit_test(test_periodic_random),
		cmocka_unit_test(test_periodic_touching),
		cmocka_unit_test(test_periodic_refused),
	};

	gsl_set_error_handler_off();
	return cmocka_run_group_tests(tests, NULL, NULL);
}
