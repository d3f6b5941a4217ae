/* test_front.c - the advancing front packing of disks (Han 2004, Ch. 5.2).
 *
 * References:
 *   - no overlap: every pair of boxes that brute force (dem_detect_brute,
 *     itself checked in test_detect.c) reports is checked with the exact
 *     centre distance; allowed overlap 1e-9 of the smaller radius (issue 3,
 *     acceptance 1);
 *   - inside: every disk within the rectangle, to 1e-9 of its radius;
 *   - the hexagonal lattice for equal disks, closed form (Ch. 5.2.4,
 *     Fig. 5.10(a)): away from the boundary every disk touches exactly six
 *     others and the covered fraction of a window, sampled on a fine
 *     raster, is at least 0.90 (the lattice's pi / (2 sqrt 3) = 0.9069);
 *   - gravity (Ch. 5.2.3, Fig. 5.9): every disk off the floor touches two
 *     supports (disks or side walls) such that the vertical through its
 *     centre meets the segment between them below the centre;
 *   - reproducibility from the seed;
 *   - polygons (Ch. 5.2.4, Figs. 5.12-5.13): convex (hexagon, trapezoid)
 *     and concave (L, hopper), lambda 1, 10, 100, with and without
 *     gravity: no overlap as above; every centre inside (crossing number)
 *     and every edge, as a segment, at least r(1 - 1e-9) away; under
 *     gravity every disk is held up by Fig. 5.9 with edges as supports at
 *     their contact points; the density against the polygon's area
 *     (shoelace) is reported; bad polygons are refused;
 *   - translation: a rectangle moved by 2^20 (1, -1) gives the disks at the
 *     origin moved, within 1e-6 of the radius (the tolerance adds the
 *     rounding of the coordinates);
 *   - scale: radii or coordinates whose squares overflow or underflow, or
 *     coordinates rounded to more than 1e-3 of the radii, are refused; a
 *     scene scaled by 2^300 or 2^-300 gives the disks scaled, bit for bit.
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

#include "core/consts.h"
#include "core/rng.h"
#include "detect/detect.h"
#include "pack/front.h"

#define TOL 1e-9

struct set {
	size_t n, cap;
	double *x, *y, *r;
	int stop_after, stop_code;      /* emit returns stop_code after that many */
};

static int collect(void *ctx, const double *x, double r)
{
	struct set *s = ctx;
	if (s->stop_after && s->n == (size_t)s->stop_after)
		return s->stop_code;
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 1024;
		s->x = realloc(s->x, s->cap * sizeof *s->x);
		s->y = realloc(s->y, s->cap * sizeof *s->y);
		s->r = realloc(s->r, s->cap * sizeof *s->r);
		assert_non_null(s->x);
		assert_non_null(s->y);
		assert_non_null(s->r);
	}
	s->x[s->n] = x[0];
	s->y[s->n] = x[1];
	s->r[s->n] = r;
	s->n++;
	return 0;
}

static void set_free(struct set *s)
{
	free(s->x);
	free(s->y);
	free(s->r);
	memset(s, 0, sizeof *s);
}

static dem_front_spec_t spec(dem_front_form_t form, double w, double h,
			     dem_radius_kind_t kind, double rmin, double lambda)
{
	dem_front_spec_t s;
	memset(&s, 0, sizeof s);
	s.form = form;
	s.lo[0] = 0;
	s.lo[1] = 0;
	s.hi[0] = w;
	s.hi[1] = h;
	s.law = (dem_radius_law_t){kind, rmin, rmin * lambda};
	return s;
}

static void run(const dem_front_spec_t *s, unsigned long seed, struct set *out,
		dem_front_stats_t *st)
{
	gsl_rng *g = dem_rng_derive(seed, 0);
	dem_error_t e;
	assert_non_null(g);
	dem_error_clear(&e);
	memset(out, 0, sizeof *out);
	int rc = dem_pack_front(s, g, collect, out, st, &e);
	if (rc)
		fail_msg("dem_pack_front: %d: %s", rc, e.msg);
	gsl_rng_free(g);
}

/* The pairs of boxes that overlap, by brute force. */
static void pairs_of(const struct set *s, dem_pairs_t *p)
{
	dem_boxes_t b;
	dem_detect_opts_t o;
	dem_error_t e;

	assert_int_equal(dem_boxes_alloc(&b, 2, s->n), DEM_OK);
	for (size_t i = 0; i < s->n; i++) {
		/* boxes a little larger, so disks touching in a vertical or
		 * horizontal stack (boxes meeting edge to edge) pair up too */
		double h = s->r[i] * (1 + TOL);
		b.lo[0][i] = s->x[i] - h;
		b.hi[0][i] = s->x[i] + h;
		b.lo[1][i] = s->y[i] - h;
		b.hi[1][i] = s->y[i] + h;
	}
	dem_detect_opts_init(&o);
	o.algo = DEM_DETECT_BRUTE;
	dem_error_clear(&e);
	dem_pairs_init(p);
	assert_int_equal(dem_detect(&b, &o, p, NULL, &e), DEM_OK);
	dem_boxes_free(&b);
}

static double gap(const struct set *s, size_t i, size_t j)
{
	return hypot(s->x[i] - s->x[j], s->y[i] - s->y[j]) - s->r[i] - s->r[j];
}

/* No pair overlaps by more than TOL of the smaller radius; every disk is
 * inside [lo, hi] to TOL of its radius (sp NULL: the overlaps only). */
static void check_packing(const struct set *s, const dem_front_spec_t *sp,
			  const char *label)
{
	dem_pairs_t p;
	pairs_of(s, &p);
	for (size_t k = 0; k < p.n; k++) {
		size_t i = p.p[k].i, j = p.p[k].j;
		double rm = fmin(s->r[i], s->r[j]);
		if (gap(s, i, j) < -TOL * rm)
			fail_msg("%s: disks %zu and %zu overlap by %g of the smaller radius",
				 label, i, j, -gap(s, i, j) / rm);
	}
	dem_pairs_free(&p);
	for (size_t i = 0; sp && i < s->n; i++) {
		double t = TOL * s->r[i];
		if (s->x[i] - s->r[i] < sp->lo[0] - t || s->x[i] + s->r[i] > sp->hi[0] + t ||
		    s->y[i] - s->r[i] < sp->lo[1] - t || s->y[i] + s->r[i] > sp->hi[1] + t)
			fail_msg("%s: disk %zu (%g, %g; %g) is not inside", label, i,
				 s->x[i], s->y[i], s->r[i]);
	}
}

/* The emitted set matches the statistics: count, area, density. */
static void check_stats(const struct set *s, const dem_front_spec_t *sp,
			const dem_front_stats_t *st)
{
	double a = 0;
	for (size_t i = 0; i < s->n; i++)
		a += DEM_PI * s->r[i] * s->r[i];
	assert_int_equal(st->kept, s->n);
	assert_true(st->placed >= st->kept);
	assert_true(fabs(st->area - a) <= 1e-12 * a);
	double area = (sp->hi[0] - sp->lo[0]) * (sp->hi[1] - sp->lo[1]);
	assert_true(fabs(st->density - a / area) <= 1e-12 * st->density + 1e-300);
}

struct law {
	dem_radius_kind_t kind;
	double rmin, lambda;
	const char *name;
};

static const struct law laws[] = {
	{DEM_RADIUS_MONO, 0.5, 1, "mono"},
	{DEM_RADIUS_URD, 0.5, 2, "urd lambda 2"},
	{DEM_RADIUS_URD, 0.1, 10, "urd lambda 10"},
	{DEM_RADIUS_URD, 0.01, 100, "urd lambda 100"},
	{DEM_RADIUS_NRD, 0.1, 10, "nrd lambda 10"},
	{DEM_RADIUS_LNRD, 0.02, 100, "lnrd lambda 100"},
};

/* Both forms, every law, with and without check limits (Ch. 5.2.4): no
 * overlap, all inside, statistics consistent, and a dense packing. */
static void check_form(dem_front_form_t form)
{
	static const int limits[] = {0, 5, 1};
	for (size_t l = 0; l < sizeof laws / sizeof laws[0]; l++)
		for (size_t k = 0; k < 3; k++) {
			dem_front_spec_t s = spec(form, 70, 50, laws[l].kind,
						  laws[l].rmin, laws[l].lambda);
			struct set out;
			dem_front_stats_t st;
			char label[96];
			s.check_limit = limits[k];
			snprintf(label, sizeof label, "%s, %s, check limit %d",
				 dem_front_form_names[form], laws[l].name, limits[k]);
			run(&s, 10 + l, &out, &st);
			print_message("# %s: %zu disks, density %.4f, cases %zu/%zu/%zu, failed %zu\n",
				      label, out.n, st.density, st.cases[0], st.cases[1],
				      st.cases[2], st.failed);
			assert_true(out.n > 1000);
			check_packing(&out, &s, label);
			check_stats(&out, &s, &st);
			/* culling leaves gaps along the sides of the closed form
			 * (Fig. 5.6(b)); the open form fills up to the lid */
			if (st.density < (form == DEM_FRONT_OPEN ? 0.75 : 0.68))
				fail_msg("%s: density %g", label, st.density);
			set_free(&out);
		}
}

static void test_closed(void **state)
{
	(void)state;
	check_form(DEM_FRONT_CLOSED);
}

static void test_open(void **state)
{
	(void)state;
	check_form(DEM_FRONT_OPEN);
}

/* About 20k disks, every pair by brute force, one run per form. */
static void test_large(void **state)
{
	(void)state;
	for (int f = 0; f < 2; f++) {
		dem_front_spec_t s = spec((dem_front_form_t)f, 200, 200, DEM_RADIUS_URD, 0.5, 2);
		struct set out;
		dem_front_stats_t st;
		run(&s, 3, &out, &st);
		assert_true(out.n > 15000 && out.n < 30000);
		check_packing(&out, &s, dem_front_form_names[f]);
		check_stats(&out, &s, &st);
		set_free(&out);
	}
}

/* Far from the origin and in an odd shape: the same guarantees (tangency
 * computed on large coordinates; a strip barely wider than a disk). */
static void test_hard_domains(void **state)
{
	(void)state;
	const double box[][4] = {
		{1e4, -2e4, 1e4 + 40, -2e4 + 30},       /* far away */
		{0, 0, 200, 3},                         /* flat strip */
		{0, 0, 2.2, 100},                       /* tall chimney */
		{0, 0, 1.5, 1.5},                       /* about one disk */
		{0, 0, 0.5, 0.5},                       /* smaller than any disk */
	};
	for (int f = 0; f < 2; f++)
		for (size_t b = 0; b < sizeof box / sizeof box[0]; b++)
			for (int g = 0; g <= f; g++) {
				dem_front_spec_t s = spec((dem_front_form_t)f, 1, 1, DEM_RADIUS_URD, 0.5, 2);
				struct set out;
				dem_front_stats_t st;
				char label[64];
				s.lo[0] = box[b][0];
				s.lo[1] = box[b][1];
				s.hi[0] = box[b][2];
				s.hi[1] = box[b][3];
				s.gravity = g;
				snprintf(label, sizeof label, "%s box %zu%s",
					 dem_front_form_names[f], b, g ? " gravity" : "");
				run(&s, 5, &out, &st);
				check_packing(&out, &s, label);
				check_stats(&out, &s, &st);
				if (b == 4)
					assert_int_equal(out.n, 0);
				set_free(&out);
			}
}

/* Translation (issue: the overlap tolerance was 1e-10 of the radius in
 * absolute terms, below the rounding of coordinates some 10^6 radii from
 * the origin): the packing of the rectangle moved by (X, Y) = 2^20 (1, -1)
 * (exactly representable, so the domain moves exactly) is the packing at
 * the origin moved by (X, Y): the same disks in the same order, each
 * centre within 1e-6 of its radius of the moved one, and as many segments
 * given up.  Equal disks in the closed form (the hexagonal lattice, all
 * contacts) are the sharpest case.  (Not the same disks placed: there the
 * lattice puts centres exactly on the rectangle's sides, and whether such
 * a disk counts as outside, to stop the front, depends on rounding; it is
 * culled either way.) */
static void test_far_from_origin(void **state)
{
	(void)state;
	const double X = 1048576, Y = -1048576;
	for (int c = 0; c < 4; c++) {
		dem_front_spec_t s = spec(c < 2 ? DEM_FRONT_CLOSED : DEM_FRONT_OPEN, 30, 20,
					  c == 0 ? DEM_RADIUS_MONO : DEM_RADIUS_URD, 0.5, c == 0 ? 1 : 2);
		s.gravity = c == 3;
		struct set a, b;
		dem_front_stats_t sa, sb;
		char label[64];
		snprintf(label, sizeof label, "%s%s%s, moved by 2^20", dem_front_form_names[s.form],
			 c == 0 ? " equal disks" : "", s.gravity ? " gravity" : "");
		run(&s, 8, &a, &sa);
		s.lo[0] += X, s.hi[0] += X, s.lo[1] += Y, s.hi[1] += Y;
		run(&s, 8, &b, &sb);
		if (b.n != a.n || sb.failed != sa.failed)
			fail_msg("%s: %zu disks (%zu placed, %zu failed), at the origin %zu (%zu, %zu)",
				 label, b.n, sb.placed, sb.failed, a.n, sa.placed, sa.failed);
		for (size_t i = 0; i < a.n; i++) {
			assert_true(b.r[i] == a.r[i]);
			if (fabs(b.x[i] - X - a.x[i]) > 1e-6 * a.r[i] ||
			    fabs(b.y[i] - Y - a.y[i]) > 1e-6 * a.r[i])
				fail_msg("%s: disk %zu at (%.17g, %.17g), at the origin (%.17g, %.17g)",
					 label, i, b.x[i] - X, b.y[i] - Y, a.x[i], a.y[i]);
		}
		check_packing(&b, &s, label);
		print_message("# %s: %zu disks (%zu placed, at the origin %zu), the same as at the "
			      "origin\n", label, b.n, sb.placed, sa.placed);
		set_free(&a);
		set_free(&b);
	}
	/* polygons of whole vertices (they move exactly too): the L and the
	 * hopper of test_polygons, with and without gravity */
	static const double L[12] = {0, 0, 0, 20, 10, 20, 10, 10, 20, 10, 20, 0};
	static const double H[12] = {0, 20, 8, 4, 8, 0, 12, 0, 12, 4, 20, 20};
	for (int c = 0; c < 4; c++) {
		const double *v0 = c < 2 ? L : H;
		double v[12];
		dem_front_spec_t s = spec(DEM_FRONT_OPEN, 1, 1, DEM_RADIUS_URD, 0.3, 2);
		s.polygon = v;
		s.npolygon = 6;
		s.gravity = c % 2;
		struct set a, b;
		dem_front_stats_t sa, sb;
		memcpy(v, v0, sizeof v);
		run(&s, 9, &a, &sa);
		for (int k = 0; k < 6; k++)
			v[2 * k] += X, v[2 * k + 1] += Y;
		run(&s, 9, &b, &sb);
		if (b.n != a.n || sb.failed != sa.failed)
			fail_msg("%s%s: %zu disks (%zu failed), at the origin %zu (%zu)", c < 2 ? "L" : "hopper",
				 s.gravity ? " gravity" : "", b.n, sb.failed, a.n, sa.failed);
		for (size_t i = 0; i < a.n; i++)
			if (!(b.r[i] == a.r[i] && fabs(b.x[i] - X - a.x[i]) <= 1e-6 * a.r[i] &&
			      fabs(b.y[i] - Y - a.y[i]) <= 1e-6 * a.r[i]))
				fail_msg("%s: disk %zu differs", c < 2 ? "L" : "hopper", i);
		check_packing(&b, NULL, "polygon moved");
		print_message("# %s%s, moved by 2^20: %zu disks, the same as at the origin\n",
			      c < 2 ? "L" : "hopper", s.gravity ? " gravity" : "", b.n);
		set_free(&a);
		set_free(&b);
	}
}

static int count_body(void *ctx, const dem_front_body_t *b)
{
	(void)b;
	++*(size_t *)ctx;
	return 0;
}

/* Extreme scales.  The packer squares lengths (distances, radii), so
 * radii and coordinates whose squares overflow (or underflow) give
 * infinities and NaNs, and a NaN passes every "overlap > tol" test: such
 * scenes are refused as bad input, with nothing emitted.  Within range
 * the method has no scale: the same scene scaled by 2^300 or 2^-300
 * (exact in binary) gives the same disks scaled, bit for bit. */
static void test_extreme_scales(void **state)
{
	(void)state;
	const double huge[][3] = {      /* rmin, the domain's side, its lower corner */
		{1e200, 4e201, 0},      /* radii whose squares overflow */
		{1e154, 4e155, 0},      /* squared sums and distances do */
		{1e-3, 0.4, 1e12},      /* coordinates rounded to more than 1e-3 r */
		{1e-170, 4e-169, 0},    /* squares underflow to zero */
	};
	gsl_rng *g = dem_rng_derive(1, 0);
	for (int f = 0; f < 2; f++)
		for (size_t k = 0; k < sizeof huge / sizeof huge[0]; k++) {
			dem_front_spec_t s = spec((dem_front_form_t)f, huge[k][1], huge[k][1],
						  DEM_RADIUS_URD, huge[k][0], 2);
			s.lo[0] += huge[k][2], s.hi[0] += huge[k][2];
			struct set out = {0};
			dem_error_t e;
			dem_error_clear(&e);
			int rc = dem_pack_front(&s, g, collect, &out, NULL, &e);
			for (size_t i = 0; i < out.n; i++)
				if (!(isfinite(out.x[i]) && isfinite(out.y[i])))
					fail_msg("case %zu: disk %zu at (%g, %g)", k, i, out.x[i], out.y[i]);
			if (rc != DEM_EINPUT)
				fail_msg("case %zu (%s, radii %g): %d, %zu disks", k,
					 dem_front_form_names[f], huge[k][0], rc, out.n);
			assert_int_equal(out.n, 0);
			if (!strstr(e.msg, "range"))
				fail_msg("case %zu: %s", k, e.msg);
			set_free(&out);
			/* the same through dem_pack_front_bodies, as ellipses */
			size_t nb = 0;
			s.shape = DEM_FRONT_ELLIPSE;
			dem_error_clear(&e);
			assert_int_equal(dem_pack_front_bodies(&s, g, count_body, &nb, NULL, &e), DEM_EINPUT);
			assert_int_equal(nb, 0);
		}
	for (int f = 0; f < 3; f++)
		for (int sg = -1; sg <= 1; sg += 2) {
			const double k = ldexp(1, 300 * sg);
			dem_front_spec_t s = spec(f ? DEM_FRONT_OPEN : DEM_FRONT_CLOSED, 30, 20,
						  DEM_RADIUS_URD, 0.5, 2);
			s.gravity = f == 2;
			struct set a, b;
			dem_front_stats_t st;
			run(&s, 6, &a, &st);
			s.hi[0] *= k, s.hi[1] *= k, s.law.rmin *= k, s.law.rmax *= k;
			run(&s, 6, &b, &st);
			assert_int_equal(b.n, a.n);
			assert_true(a.n > 100);
			for (size_t i = 0; i < a.n; i++)
				if (b.x[i] != a.x[i] * k || b.y[i] != a.y[i] * k || b.r[i] != a.r[i] * k)
					fail_msg("form %d, scale 2^%d: disk %zu differs", f, 300 * sg, i);
			set_free(&a);
			set_free(&b);
		}
	gsl_rng_free(g);
}

/* Fig. 5.10(a): equal disks, closed form, give the hexagonal lattice. */
static void test_hexagonal(void **state)
{
	(void)state;
	const double L = 100, r = 1, w0 = 20, w1 = 80;
	dem_front_spec_t s = spec(DEM_FRONT_CLOSED, L, L, DEM_RADIUS_MONO, r, 1);
	struct set out;
	dem_front_stats_t st;
	run(&s, 1, &out, &st);

	/* a bucket grid of cell 2r for the neighbour counts and the raster */
	int nc = (int)(L / (2 * r)) + 1;
	int *head = malloc((size_t)nc * nc * sizeof *head), *nxt = malloc(out.n * sizeof *nxt);
	assert_non_null(head);
	assert_non_null(nxt);
	for (int i = 0; i < nc * nc; i++)
		head[i] = -1;
	for (size_t i = 0; i < out.n; i++) {
		int cx = (int)(out.x[i] / (2 * r)), cy = (int)(out.y[i] / (2 * r));
		nxt[i] = head[cy * nc + cx];
		head[cy * nc + cx] = (int)i;
	}
	size_t inner = 0;
	for (size_t i = 0; i < out.n; i++) {
		if (out.x[i] < w0 || out.x[i] > w1 || out.y[i] < w0 || out.y[i] > w1)
			continue;
		int cx = (int)(out.x[i] / (2 * r)), cy = (int)(out.y[i] / (2 * r)), touch = 0;
		for (int y = cy - 1; y <= cy + 1; y++)
			for (int x = cx - 1; x <= cx + 1; x++)
				for (int j = head[y * nc + x]; j >= 0; j = nxt[j]) {
					if ((size_t)j == i)
						continue;
					double g = gap(&out, i, (size_t)j);
					if (fabs(g) <= TOL * r)
						touch++;
					else
						assert_true(g > 0.1 * r);
				}
		if (touch != 6)
			fail_msg("disk %zu at (%g, %g) touches %d disks, not 6", i, out.x[i], out.y[i], touch);
		inner++;
	}
	assert_true(inner > 800);

	/* covered fraction of the window [w0, w1]^2 on a raster of step r/25 */
	long hit = 0, all = 0;
	const double h = r / 25;
	for (double py = w0 + h / 2; py < w1; py += h)
		for (double px = w0 + h / 2; px < w1; px += h) {
			int cx = (int)(px / (2 * r)), cy = (int)(py / (2 * r)), in = 0;
			for (int y = cy - 1; y <= cy + 1 && !in; y++)
				for (int x = cx - 1; x <= cx + 1 && !in; x++)
					for (int j = head[y * nc + x]; j >= 0 && !in; j = nxt[j])
						in = hypot(px - out.x[j], py - out.y[j]) <= r;
			hit += in;
			all++;
		}
	double rho = (double)hit / (double)all;
	print_message("# hexagonal: %zu disks, %zu inner with 6 contacts, window density %.4f "
		      "(lattice %.4f), whole domain %.4f\n",
		      out.n, inner, rho, DEM_PI / (2 * sqrt(3.0)), st.density);
	assert_true(rho >= 0.90);
	assert_true(fabs(rho - DEM_PI / (2 * sqrt(3.0))) < 0.005);
	free(head);
	free(nxt);
	set_free(&out);
}

/* Fig. 5.9: is disk i held up?  Its supports: the disks it touches and
 * the side walls it touches, each at its contact point's abscissa; some
 * two of them must lie one on each side of (or under) the centre, with
 * the segment between them below the centre.  A disk on the floor rests
 * on it. */
static int supported(const struct set *s, const dem_front_spec_t *sp,
		     const dem_pair_t *p, const size_t *first, size_t i)
{
	double x = s->x[i], y = s->y[i], r = s->r[i];
	double sx[64], sy[64];
	int ns = 0;

	if (fabs(y - r - sp->lo[1]) <= TOL * r)
		return 1;
	if (fabs(x - r - sp->lo[0]) <= TOL * r) {
		sx[ns] = sp->lo[0];
		sy[ns++] = y;
	}
	if (fabs(x + r - sp->hi[0]) <= TOL * r) {
		sx[ns] = sp->hi[0];
		sy[ns++] = y;
	}
	for (size_t k = first[i]; k < first[i + 1] && ns < 64; k++) {
		size_t j = p[k].j;
		if (fabs(gap(s, i, j)) <= TOL * fmin(r, s->r[j])) {
			sx[ns] = s->x[j];
			sy[ns++] = s->y[j];
		}
	}
	for (int a = 0; a < ns; a++)
		for (int b = 0; b < ns; b++) {
			if (!(sx[a] <= x + TOL * r && x <= sx[b] + TOL * r && sx[a] < sx[b]))
				continue;
			double t = (x - sx[a]) / (sx[b] - sx[a]);
			if (y > sy[a] + t * (sy[b] - sy[a]))
				return 1;
		}
	return 0;
}

static int by_i(const void *a, const void *b)
{
	const dem_pair_t *p = a, *q = b;
	return p->i < q->i ? -1 : p->i > q->i;
}

/* Gravity (Ch. 5.2.3): open form, every kept disk is stable by Fig. 5.9. */
static void test_gravity(void **state)
{
	(void)state;
	for (size_t l = 0; l < 4; l++) {
		dem_front_spec_t s = spec(DEM_FRONT_OPEN, 60, 45, laws[l].kind, laws[l].rmin,
					  laws[l].lambda);
		struct set out;
		dem_front_stats_t st;
		dem_pairs_t p;
		struct {
			dem_pair_t *p;
			size_t n;
		} q;
		s.gravity = 1;
		run(&s, 20 + l, &out, &st);
		print_message("# gravity, %s: %zu disks, density %.4f, unstable %zu, dropped %zu\n",
			      laws[l].name, out.n, st.density, st.unstable, st.dropped);
		check_packing(&out, &s, "gravity");
		check_stats(&out, &s, &st);
		assert_true(st.density > 0.74);
		if (laws[l].kind != DEM_RADIUS_MONO)    /* the rule did act */
			assert_true(st.unstable > 0);

		/* both orientations of every pair, grouped by first index */
		pairs_of(&out, &p);
		q.n = 2 * p.n;
		q.p = malloc((q.n + 1) * sizeof *q.p);
		assert_non_null(q.p);
		for (size_t k = 0; k < p.n; k++) {
			q.p[2 * k] = p.p[k];
			q.p[2 * k + 1] = (dem_pair_t){p.p[k].j, p.p[k].i};
		}
		qsort(q.p, q.n, sizeof *q.p, by_i);
		size_t *first = calloc(out.n + 1, sizeof *first);
		assert_non_null(first);
		for (size_t k = 0; k < q.n; k++)
			first[q.p[k].i + 1]++;
		for (size_t i = 0; i < out.n; i++)
			first[i + 1] += first[i];
		for (size_t i = 0; i < out.n; i++)
			if (!supported(&out, &s, q.p, first, i))
				fail_msg("gravity, %s: disk %zu at (%g, %g; %g) is not supported",
					 laws[l].name, i, out.x[i], out.y[i], out.r[i]);
		free(first);
		dem_pairs_free(&p);
		free(q.p);
		set_free(&out);
	}
}

/* ---- polygons --------------------------------------------------------- */

struct poly {
	const char *name;
	int n;
	double v[16];
	double rmax;            /* largest radius, so the counts stay moderate */
};

static const struct poly polys[] = {
	{"hexagon", 6, {10, 0, 20, 0, 25, 8.66, 20, 17.32, 10, 17.32, 5, 8.66}, 0.6},
	{"trapezoid", 4, {0, 0, 24, 0, 18, 14, 6, 14}, 0.6},
	/* clockwise on purpose: either orientation is accepted */
	{"L", 6, {0, 0, 0, 20, 10, 20, 10, 10, 20, 10, 20, 0}, 0.6},
	{"hopper", 6, {0, 20, 8, 4, 8, 0, 12, 0, 12, 4, 20, 20}, 0.6},
};

static double seg_dist(double px, double py, double ax, double ay, double bx, double by,
		       double *cx, double *cy)
{
	double dx = bx - ax, dy = by - ay;
	double t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	*cx = ax + t * dx;
	*cy = ay + t * dy;
	return hypot(px - *cx, py - *cy);
}

static int in_poly(const struct poly *P, double x, double y)
{
	int in = 0;
	for (int i = 0, j = P->n - 1; i < P->n; j = i++) {
		double xi = P->v[2 * i], yi = P->v[2 * i + 1];
		double xj = P->v[2 * j], yj = P->v[2 * j + 1];
		if ((yi > y) != (yj > y) && x < xj + (y - yj) * (xi - xj) / (yi - yj))
			in = !in;
	}
	return in;
}

static double poly_area(const struct poly *P)
{
	double a = 0;
	for (int i = 0; i < P->n; i++) {
		int j = (i + 1) % P->n;
		a += P->v[2 * i] * P->v[2 * j + 1] - P->v[2 * i + 1] * P->v[2 * j];
	}
	return fabs(a) / 2;
}

/* Fig. 5.9 in a polygon: the supports of disk i are the disks it touches
 * (at their centres) and the edges it touches (at the contact point); it
 * rests when one support is right under its centre, or two lie one each
 * side with the segment between them below the centre. */
static int supported_poly(const struct set *s, const struct poly *P,
			  const dem_pair_t *p, const size_t *first, size_t i)
{
	double x = s->x[i], y = s->y[i], r = s->r[i];
	double sx[64], sy[64];
	int ns = 0;

	for (int k = 0; k < P->n && ns < 64; k++) {
		int k1 = (k + 1) % P->n;
		double cx, cy;
		double d = seg_dist(x, y, P->v[2 * k], P->v[2 * k + 1], P->v[2 * k1],
				    P->v[2 * k1 + 1], &cx, &cy);
		if (fabs(d - r) <= TOL * r) {
			if (fabs(cx - x) <= TOL * r && cy < y)
				return 1;       /* on a floor */
			sx[ns] = cx;
			sy[ns++] = cy;
		}
	}
	for (size_t k = first[i]; k < first[i + 1] && ns < 64; k++) {
		size_t j = p[k].j;
		if (fabs(gap(s, i, j)) <= TOL * fmin(r, s->r[j])) {
			sx[ns] = s->x[j];
			sy[ns++] = s->y[j];
		}
	}
	for (int a = 0; a < ns; a++)
		for (int b = 0; b < ns; b++) {
			if (!(sx[a] <= x + TOL * r && x <= sx[b] + TOL * r && sx[a] < sx[b]))
				continue;
			double t = (x - sx[a]) / (sx[b] - sx[a]);
			if (y > sy[a] + t * (sy[b] - sy[a]))
				return 1;
		}
	return 0;
}

static void check_gravity_poly(const struct set *out, const struct poly *P,
			       const char *label)
{
	dem_pairs_t p;
	pairs_of(out, &p);
	dem_pair_t *q = malloc((2 * p.n + 1) * sizeof *q);
	size_t *first = calloc(out->n + 1, sizeof *first);
	assert_non_null(q);
	assert_non_null(first);
	for (size_t k = 0; k < p.n; k++) {
		q[2 * k] = p.p[k];
		q[2 * k + 1] = (dem_pair_t){p.p[k].j, p.p[k].i};
	}
	qsort(q, 2 * p.n, sizeof *q, by_i);
	for (size_t k = 0; k < 2 * p.n; k++)
		first[q[k].i + 1]++;
	for (size_t i = 0; i < out->n; i++)
		first[i + 1] += first[i];
	for (size_t i = 0; i < out->n; i++)
		if (!supported_poly(out, P, q, first, i))
			fail_msg("%s: disk %zu at (%g, %g; %g) is not supported",
				 label, i, out->x[i], out->y[i], out->r[i]);
	free(first);
	free(q);
	dem_pairs_free(&p);
}

static void test_polygons(void **state)
{
	static const double lambdas[] = {1, 10, 100};
	(void)state;
	for (size_t k = 0; k < sizeof polys / sizeof polys[0]; k++)
		for (int l = 0; l < 3; l++)
			for (int g = 0; g < 2; g++) {
				const struct poly *P = &polys[k];
				dem_front_spec_t s = spec(DEM_FRONT_OPEN, 1, 1, DEM_RADIUS_URD,
							  P->rmax / lambdas[l], lambdas[l]);
				struct set out;
				dem_front_stats_t st;
				char label[96];
				s.polygon = P->v;
				s.npolygon = P->n;
				s.gravity = g;
				snprintf(label, sizeof label, "%s, lambda %g%s", P->name,
					 lambdas[l], g ? ", gravity" : "");
				run(&s, 30 + k, &out, &st);
				print_message("# %s: %zu disks, density %.4f, failed %zu, unstable %zu\n",
					      label, out.n, st.density, st.failed, st.unstable);
				assert_true(out.n > 100);
				check_packing(&out, NULL, label);
				double a = 0;
				for (size_t i = 0; i < out.n; i++) {
					double r = out.r[i], cx, cy;
					a += DEM_PI * r * r;
					if (!in_poly(P, out.x[i], out.y[i]))
						fail_msg("%s: disk %zu centre outside", label, i);
					for (int e = 0; e < P->n; e++) {
						int e1 = (e + 1) % P->n;
						if (seg_dist(out.x[i], out.y[i], P->v[2 * e], P->v[2 * e + 1],
							     P->v[2 * e1], P->v[2 * e1 + 1], &cx, &cy) < r * (1 - TOL))
							fail_msg("%s: disk %zu crosses edge %d", label, i, e);
					}
				}
				assert_int_equal(st.kept, out.n);
				assert_true(fabs(st.density - a / poly_area(P)) <= 1e-12 * st.density);
				/* well packed, though the lid stays untouched and
				 * lambda 1 cannot pack against slanted walls */
				if (st.density < 0.6)
					fail_msg("%s: density %g", label, st.density);
				if (g)
					check_gravity_poly(&out, P, label);
				set_free(&out);
			}
}

/* A polygon of more vertices than the first reservation of disks holds
 * (that reservation comes from the area over the mean disk area: here a
 * disk's worth of a few, so 64 to 128 objects) packs like any other: the
 * walls, one object per edge, were once written past the end of the
 * arrays (a heap overflow that ASan reports and glibc's malloc aborts on).
 * 300 and the scene's largest, 4096, edges round a circle of radius 1,
 * disks of radius 0.3: every disk inside, none overlapping. */
static void test_polygon_many_vertices(void **state)
{
	(void)state;
	static const int counts[] = {300, 4096};
	for (int c = 0; c < 2; c++) {
		int n = counts[c];
		double *v = malloc(2 * (size_t)n * sizeof *v);
		assert_non_null(v);
		for (int k = 0; k < n; k++) {
			v[2 * k] = cos(2 * DEM_PI * k / n);
			v[2 * k + 1] = sin(2 * DEM_PI * k / n);
		}
		dem_front_spec_t s = spec(DEM_FRONT_OPEN, 1, 1, DEM_RADIUS_MONO, 0.3, 1);
		s.polygon = v;
		s.npolygon = n;
		struct set out;
		dem_front_stats_t st;
		run(&s, 3, &out, &st);
		assert_true(out.n >= 3);
		check_packing(&out, NULL, "many vertices");
		for (size_t i = 0; i < out.n; i++)
			assert_true(hypot(out.x[i], out.y[i]) <= 1 - out.r[i] * (1 - TOL));
		set_free(&out);
		free(v);
	}
}

/* Polygons that are not simple, or have no area, are refused. */
static void test_polygon_errors(void **state)
{
	(void)state;
	static const struct {
		int n;
		double v[10];
	} bad[] = {
		{2, {0, 0, 1, 0}},                              /* too few */
		{4, {0, 0, 1, 1, 1, 0, 0, 1}},                  /* a bow tie */
		{3, {0, 0, 1, 1, 2, 2}},                        /* no area */
		{4, {0, 0, 1, 0, 1, 0, 0, 1}},                  /* repeated vertex */
		{5, {0, 0, 4, 0, 4, 4, 2, 0, 0, 4}},            /* a vertex on an edge */
		{4, {0, 0, 2, 0, 1, 0, 1, 1}},                  /* folds back */
	};
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		dem_error_t e;
		dem_error_clear(&e);
		if (dem_front_polygon_check(bad[k].v, bad[k].n, &e) != DEM_EINPUT)
			fail_msg("bad polygon %zu accepted", k);
		assert_true(e.msg[0] != '\0');
	}
	dem_error_t e;
	dem_error_clear(&e);
	assert_int_equal(dem_front_polygon_check(polys[2].v, polys[2].n, &e), DEM_OK);
	/* where a polygon lies does not decide whether it has an area: a
	 * square of side 0.5 far from the origin has one (its area was once
	 * held against 1e-12 of the coordinates squared, 1, not of its
	 * size squared), and a line there has none */
	static const double far[8] = {1e6, 1e6, 1e6 + 0.5, 1e6, 1e6 + 0.5, 1e6 + 0.5, 1e6, 1e6 + 0.5};
	static const double farline[6] = {1e6, 1e6, 1e6 + 1, 1e6 + 1, 1e6 + 2, 1e6 + 2};
	dem_error_clear(&e);
	if (dem_front_polygon_check(far, 4, &e) != DEM_OK)
		fail_msg("a square of side 0.5 at (1e6, 1e6) refused: %s", e.msg);
	dem_error_clear(&e);
	assert_int_equal(dem_front_polygon_check(farline, 3, &e), DEM_EINPUT);
	dem_error_clear(&e);
	/* the packer names itself before the polygon's fault */
	{
		dem_front_spec_t bt = spec(DEM_FRONT_OPEN, 1, 1, DEM_RADIUS_URD, 0.1, 2);
		gsl_rng *g = dem_rng_derive(1, 0);
		struct set out = {0};
		bt.polygon = bad[1].v;
		bt.npolygon = bad[1].n;
		assert_int_equal(dem_pack_front(&bt, g, collect, &out, NULL, &e), DEM_EINPUT);
		if (!strstr(e.msg, "advancing front: polygon edges"))
			fail_msg("bow tie: '%s'", e.msg);
		assert_int_equal(out.n, 0);
		gsl_rng_free(g);
	}
	dem_error_clear(&e);
	/* a polygon with the closed form */
	dem_front_spec_t s = spec(DEM_FRONT_CLOSED, 1, 1, DEM_RADIUS_URD, 0.5, 2);
	s.polygon = polys[0].v;
	s.npolygon = polys[0].n;
	gsl_rng *g = dem_rng_derive(1, 0);
	struct set out = {0};
	assert_int_equal(dem_pack_front(&s, g, collect, &out, NULL, &e), DEM_EINPUT);
	assert_int_equal(out.n, 0);
	gsl_rng_free(g);
}

/* The same seed gives the same packing, another seed another. */
static void test_seed(void **state)
{
	(void)state;
	for (int f = 0; f < 2; f++) {
		dem_front_spec_t s = spec((dem_front_form_t)f, 40, 30, DEM_RADIUS_URD, 0.2, 5);
		struct set a, b, c;
		dem_front_stats_t st;
		s.gravity = f;
		run(&s, 99, &a, &st);
		run(&s, 99, &b, &st);
		run(&s, 100, &c, &st);
		assert_int_equal(a.n, b.n);
		assert_memory_equal(a.x, b.x, a.n * sizeof *a.x);
		assert_memory_equal(a.y, b.y, a.n * sizeof *a.y);
		assert_memory_equal(a.r, b.r, a.n * sizeof *a.r);
		assert_true(a.n != c.n || memcmp(a.x, c.x, a.n * sizeof *a.x) != 0);
		set_free(&a);
		set_free(&b);
		set_free(&c);
	}
}

/* Bad specs are DEM_EINPUT with a message; emit's nonzero value stops the
 * output and is returned. */
static void test_errors(void **state)
{
	(void)state;
	dem_front_spec_t good = spec(DEM_FRONT_OPEN, 20, 20, DEM_RADIUS_URD, 0.5, 2);
	dem_front_spec_t bad[6];
	for (int k = 0; k < 6; k++)
		bad[k] = good;
	bad[0].hi[0] = 0;                       /* empty */
	bad[1].lo[1] = NAN;                     /* not finite */
	bad[2].law.rmin = 0;                    /* radii */
	bad[3].law.rmax = 0.25;                 /* rmax < rmin */
	bad[4].form = DEM_FRONT_CLOSED;         /* gravity needs the open form */
	bad[4].gravity = 1;
	bad[5].check_limit = -1;
	gsl_rng *g = dem_rng_derive(1, 0);
	for (int k = 0; k < 6; k++) {
		struct set out = {0};
		dem_front_stats_t st;
		dem_error_t e;
		dem_error_clear(&e);
		assert_int_equal(dem_pack_front(&bad[k], g, collect, &out, &st, &e), DEM_EINPUT);
		assert_int_equal(e.code, DEM_EINPUT);
		assert_true(e.msg[0] != '\0');
		assert_int_equal(out.n, 0);
	}
	struct set out = {0};
	dem_error_t e;
	dem_error_clear(&e);
	out.stop_after = 10;
	out.stop_code = 42;
	assert_int_equal(dem_pack_front(&good, g, collect, &out, NULL, &e), 42);
	assert_int_equal(out.n, 10);
	set_free(&out);
	gsl_rng_free(g);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_closed),
		cmocka_unit_test(test_open),
		cmocka_unit_test(test_large),
		cmocka_unit_test(test_hard_domains),
		cmocka_unit_test(test_far_from_origin),
		cmocka_unit_test(test_extreme_scales),
		cmocka_unit_test(test_hexagonal),
		cmocka_unit_test(test_gravity),
		cmocka_unit_test(test_seed),
		cmocka_unit_test(test_errors),
		cmocka_unit_test(test_polygons),
		cmocka_unit_test(test_polygon_errors),
		cmocka_unit_test(test_polygon_many_vertices),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
