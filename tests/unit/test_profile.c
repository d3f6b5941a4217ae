/* test_profile.c - the profile stream (lib/io/profile) and the profiles and
 * surface metrics demprofile takes from a state frame.
 *
 * References: known layer values must come back exactly (the averaging is
 * exact for equal samples); unequal samples against a brute-force
 * volume-weighted mean and spread; coverage of spherical dimples of known
 * size against the analytic area (pi rho^2 each) and against a brute-force
 * count of the mesh nodes inside the dimples; Ra of a sine surface against
 * 2A/pi.  Axisymmetric frames (x the radius): the ring-weighted mean of
 * f(r) = a + b r^2 over the disk r < R0, a + b R0^2 / 2, and the surface of
 * a conical dimple (area pi R0^2, Ra, plastic share (r_p / R0)^2) in
 * closed form. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/consts.h"
#include "io/profile.h"

#define assert_close(a, b, tol) do { \
		double a_ = (a), b_ = (b); \
		if (!(fabs(a_ - b_) <= (tol))) \
			fail_msg("%s = %.17g, expected %.17g (tolerance %g)", #a, a_, b_, (double)(tol)); \
	} while (0)

#define TMPDIR_PREFIX "/tmp/dem-profile-"
#include "tmpdir.h"
#include "gridmesh.h"

/* Grid lines: uniform h over [a, b] (n elements), then graded outside. */
static double *uniform(double a, double b, int n)
{
	double *g = malloc((n + 1) * sizeof *g);
	for (int i = 0; i <= n; i++)
		g[i] = a + (b - a) * i / n;
	return g;
}

/* ---- the stream ---------------------------------------------------------- */

static void fill_profile(dem_profile_t *p, int pass, size_t n, double scale)
{
	assert_int_equal(dem_profile_alloc(p, n, NULL), 0);
	p->pass = pass;
	for (size_t i = 0; i < n; i++) {
		p->depth[i] = 1e-4 * (double)i + (i ? 0 : 0.5e-5);
		for (int c = 0; c < 6; c++) {
			p->sig[6 * i + c] = scale * (-3e8 + 1e7 * (double)(i * 6 + c)) / 3.0;
			p->eps[6 * i + c] = scale * 1e-3 * (double)c / 7.0;
		}
		p->ep[i] = scale * 0.01 / (1.0 + (double)i);
		for (int f = 0; f < 13; f++)
			p->sd[13 * i + f] = (double)f * 0.1 / 3;
		p->count[i] = 100 + (unsigned)i;
	}
}

static void profiles_equal(const dem_profile_t *a, const dem_profile_t *b)
{
	assert_int_equal(a->pass, b->pass);
	assert_int_equal(a->n, b->n);
	assert_memory_equal(a->depth, b->depth, a->n * sizeof(double));
	assert_memory_equal(a->sig, b->sig, 6 * a->n * sizeof(double));
	assert_memory_equal(a->eps, b->eps, 6 * a->n * sizeof(double));
	assert_memory_equal(a->ep, b->ep, a->n * sizeof(double));
	assert_memory_equal(a->sd, b->sd, 13 * a->n * sizeof(double));
	assert_memory_equal(a->count, b->count, a->n * sizeof(unsigned));
}

static void write_profiles(const char *p, dem_profile_t *ps, int n, int flags)
{
	dem_header_t h;
	dem_writer_t *w;
	dem_error_t e = {0};
	dem_profile_header(&h);
	assert_int_equal(dem_writer_open(&w, p, &h, flags, &e), 0);
	dem_header_free(&h);
	for (int i = 0; i < n; i++)
		assert_int_equal(dem_profile_write(w, &ps[i], &e), 0);
	assert_int_equal(dem_writer_close(w, &e), 0);
}

static void test_stream_round_trip(void **state)
{
	dem_profile_t ps[3], got, *all;
	dem_error_t e = {0};
	int n, flags[3] = {0, DEM_STREAM_BINARY, DEM_STREAM_GZIP};
	(void)state;
	fill_profile(&ps[0], 1, 5, 1);
	fill_profile(&ps[1], 2, 7, 1.5);
	fill_profile(&ps[2], 16, 3, 2);
	for (int q = 0; q < 3; q++) {
		const char *p = path("p.profile");
		write_profiles(p, ps, 3, flags[q]);
		assert_int_equal(dem_profile_read(p, 2, &got, &e), 0);
		profiles_equal(&got, &ps[1]);
		dem_profile_free(&got);
		assert_int_equal(dem_profile_read(p, -1, &got, &e), 0);
		profiles_equal(&got, &ps[2]);
		dem_profile_free(&got);
		assert_int_equal(dem_profile_read_all(p, &all, &n, &e), 0);
		assert_int_equal(n, 3);
		for (int i = 0; i < 3; i++) {
			profiles_equal(&all[i], &ps[i]);
			dem_profile_free(&all[i]);
		}
		free(all);
		/* a pass that is not there */
		assert_int_equal(dem_profile_read(p, 3, &got, &e), DEM_EINPUT);
		assert_non_null(strstr(e.msg, "no pass 3 in the profile stream (3 passes, 1 to 16)"));
		dem_error_clear(&e);
	}
	for (int i = 0; i < 3; i++)
		dem_profile_free(&ps[i]);
}

/* A hand-written profile in other units, without spreads or counts. */
static void test_stream_hand_written(void **state)
{
	dem_profile_t p;
	dem_error_t e = {0};
	(void)state;
	write_text(path("h.profile"),
		   "# dem profile 1\n# columns pass:u32:- depth:f64:mm sxx:f64:MPa syy:f64:MPa "
		   "szz:f64:Pa sxy:f64:Pa syz:f64:Pa szx:f64:Pa exx:f64:- eyy:f64:- ezz:f64:- "
		   "exy:f64:- eyz:f64:- ezx:f64:- ep:f64:-\n# format text\n# data\n"
		   "0 0 -300 -300 0 0 0 0 0 0 0 0 0 0 0.02\n"
		   "0 0.5 100 100 0 0 0 0 0 0 0 0 0 0 0\n# end 2\n");
	assert_int_equal(dem_profile_read(path("h.profile"), -1, &p, &e), 0);
	assert_int_equal(p.n, 2);
	assert_true(p.depth[1] == 0.5e-3);
	assert_true(p.sig[0] == -300e6);
	assert_true(p.sig[6 + 1] == 100e6);
	assert_true(p.ep[0] == 0.02);
	assert_true(p.sd[0] == 0 && p.count[1] == 0);

	/* interpolation (linear) and clamping (constant) */
	double s[6], x[6], ep;
	dem_profile_eval(&p, 0.125e-3, s, x, &ep);
	assert_close(s[0], -200e6, 1e-6);
	assert_close(ep, 0.015, 1e-15);
	dem_profile_eval(&p, -1, s, NULL, &ep);
	assert_true(s[0] == -300e6 && ep == 0.02);
	dem_profile_eval(&p, 7e-3, s, NULL, NULL);
	assert_true(s[1] == 100e6);
	dem_profile_eval(&p, 0.5e-3, s, NULL, NULL);
	assert_true(s[1] == 100e6);
	dem_profile_free(&p);
}

static int expect_fail(const char *text, const char *what)
{
	dem_profile_t p;
	dem_error_t e = {0};
	write_text(path("bad.profile"), text);
	int rc = dem_profile_read(path("bad.profile"), -1, &p, &e);
	if (!strstr(e.msg, what))
		fail_msg("expected '%s' in '%s'", what, e.msg);
	return rc;
}

#define PHEAD "# dem profile 1\n# columns pass:u32:- depth:f64:m sxx:f64:Pa syy:f64:Pa " \
	"szz:f64:Pa sxy:f64:Pa syz:f64:Pa szx:f64:Pa exx:f64:- eyy:f64:- ezz:f64:- " \
	"exy:f64:- eyz:f64:- ezx:f64:- ep:f64:-\n# format text\n# data\n"

static void test_stream_refusals(void **state)
{
	(void)state;
	assert_int_equal(expect_fail(PHEAD "0 1e-4 0 0 0 0 0 0 0 0 0 0 0 0 0\n"
				     "0 1e-4 0 0 0 0 0 0 0 0 0 0 0 0 0\n# end 2\n",
				     "bad.profile:6: depth 0.0001 m: depths must be >= 0 and increase"),
			 DEM_EINPUT);
	assert_int_equal(expect_fail(PHEAD "0 -1e-4 0 0 0 0 0 0 0 0 0 0 0 0 0\n# end 1\n",
				     "bad.profile:5: depth -0.0001"), DEM_EINPUT);
	assert_int_equal(expect_fail(PHEAD "2 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n"
				     "1 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n# end 2\n",
				     "pass 1 after pass 2"), DEM_EINPUT);
	assert_int_equal(expect_fail(PHEAD "# end 0\n", "no profile: the stream has no rows"),
			 DEM_EINPUT);
	assert_int_equal(expect_fail(PHEAD "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n",
				     "truncated stream"), DEM_EINPUT);
	assert_int_equal(expect_fail("# dem profile 1\n# columns pass:u32:- depth:f64:m "
				     "sxx:f64:Pa\n# format text\n# data\n# end 0\n",
				     "no column 'syy'"), DEM_EINPUT);
	assert_int_equal(expect_fail("# dem profile 1\n# columns pass:u32:- depth:f64:s "
				     "sxx:f64:Pa\n# format text\n# data\n# end 0\n",
				     "column depth"), DEM_EINPUT);
	assert_int_equal(expect_fail("# dem shots 1\n# columns pass:u32:-\n# format text\n"
				     "# data\n# end 0\n", "a shots stream; expected a profile"),
			 DEM_EINPUT);
}

/* ---- profiles of a frame ------------------------------------------------- */

/* A graded block: x, y from -2 to 2 mm in 0.25 mm elements inside
 * [-1, 1] mm and 0.5 mm ones outside; z from -2 mm to 0 in layers growing
 * with depth (0.05 mm at the top). */
static const double GXY[] = {-2e-3, -1.5e-3, -1e-3, -0.75e-3, -0.5e-3, -0.25e-3, 0,
			     0.25e-3, 0.5e-3, 0.75e-3, 1e-3, 1.5e-3, 2e-3};
static const double GZ[] = {-2e-3, -1.2e-3, -0.6e-3, -0.3e-3, -0.15e-3, -0.1e-3, -0.05e-3, 0};
enum { NXY = 12, NZ = 7 };

struct fields {
	double *sig, *eps, *ep;
};

static void alloc_fields(struct fields *f, size_t ne)
{
	f->sig = calloc(6 * ne, sizeof(double));
	f->eps = calloc(6 * ne, sizeof(double));
	f->ep = calloc(ne, sizeof(double));
}

static void free_fields(struct fields *f)
{
	free(f->sig);
	free(f->eps);
	free(f->ep);
}

/* The layer value of field c in layer k (from the bottom): awkward numbers. */
static double layer_value(int k, int c)
{
	return (c < 6 ? -1e8 : 1e-3) * (1.0 + k / 3.0) * (c + 1) / 7.0 + (c == 12 ? 0.1 / 3 : 0);
}

static double region_lo[2] = {-1e-3, -1e-3}, region_hi[2] = {1e-3, 1e-3};

/* Inside the region every element of layer k holds layer_value(k, .);
 * outside, a value far off, so any element wrongly taken shows. */
static void layered_fields(const dem_mesh_t *m, struct fields *f)
{
	for (int k = 0; k < m->nz; k++)
		for (int j = 0; j < m->ny; j++)
			for (int i = 0; i < m->nx; i++) {
				size_t el = dem_mesh_elem(m, i, j, k);
				double xc = 0.5 * (m->gx[i] + m->gx[i + 1]), yc = 0.5 * (m->gy[j] + m->gy[j + 1]);
				int in = xc >= region_lo[0] && xc <= region_hi[0] &&
					 yc >= region_lo[1] && yc <= region_hi[1];
				for (int c = 0; c < 13; c++) {
					double v = in ? layer_value(k, c) : 1e12;
					if (c < 6)
						f->sig[6 * el + c] = v;
					else if (c < 12)
						f->eps[6 * el + c - 6] = v;
					else
						f->ep[el] = v;
				}
			}
}

static void test_layers_exact(void **state)
{
	dem_mesh_t m;
	struct fields f;
	dem_profile_t p;
	dem_error_t e = {0};
	(void)state;
	make_mesh(&m, NXY, NXY, NZ, GXY, GXY, GZ);
	alloc_fields(&f, m.ne);
	layered_fields(&m, &f);
	dem_profile_opts_t o = {{-1e-3, -1e-3}, {1e-3, 1e-3}, 0, 1e-6, 0.002, 0};
	assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o, &p, &e), 0);
	assert_int_equal(p.n, NZ);
	for (size_t i = 0; i < p.n; i++) {
		int k = NZ - 1 - (int)i;
		/* layer centroid depth from the top face z = 0 */
		assert_true(p.depth[i] == 0 - 0.5 * (GZ[k] + GZ[k + 1]));
		assert_int_equal(p.count[i], 8 * 8);      /* 8 x 8 elements of 0.25 mm */
		for (int c = 0; c < 6; c++) {
			assert_true(p.sig[6 * i + c] == layer_value(k, c));
			assert_true(p.eps[6 * i + c] == layer_value(k, 6 + c));
		}
		assert_true(p.ep[i] == layer_value(k, 12));
		for (int c = 0; c < 13; c++)
			assert_true(p.sd[13 * i + c] == 0);
	}
	dem_profile_free(&p);

	/* a margin of one element each side: 6 x 6 elements, same values */
	dem_profile_opts_t o2 = {{-0.75e-3, -0.75e-3}, {0.75e-3, 0.75e-3}, 0, 1e-6, 0.002, 0};
	assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o2, &p, &e), 0);
	assert_int_equal(p.count[0], 6 * 6);
	assert_true(p.sig[0] == layer_value(NZ - 1, 0));
	dem_profile_free(&p);

	/* a region reaching one column of the coarse elements takes their
	 * 1e12 values in: the mean moves (so the test above could fail) */
	dem_profile_opts_t o3 = {{-1.25e-3, -1e-3}, {1e-3, 1e-3}, 0, 1e-6, 0.002, 0};
	assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o3, &p, &e), 0);
	assert_int_equal(p.count[0], 8 * 8 + 8);
	assert_true(p.sig[0] > 1e10);
	dem_profile_free(&p);

	/* an empty region */
	dem_profile_opts_t o4 = {{0.01, 0.01}, {0.02, 0.02}, 0, 1e-6, 0.002, 0};
	assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o4, &p, &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "no element centroid in the region"));
	free_fields(&f);
	dem_mesh_free(&m);
}

/* Unequal samples: the mean and spread are the volume-weighted ones of a
 * brute-force sum; bins hold the layers whose centroids fall in them. */
static void test_layers_and_bins_brute_force(void **state)
{
	dem_mesh_t m;
	struct fields f;
	dem_profile_t p;
	dem_error_t e = {0};
	(void)state;
	make_mesh(&m, NXY, NXY, NZ, GXY, GXY, GZ);
	alloc_fields(&f, m.ne);
	for (size_t el = 0; el < m.ne; el++) {
		for (int c = 0; c < 6; c++) {
			f.sig[6 * el + c] = -1e8 + 1e6 * sin(0.37 * (double)el + c);
			f.eps[6 * el + c] = 1e-3 * cos(0.11 * (double)el * (c + 1));
		}
		f.ep[el] = 0.01 * (1 + sin(0.05 * (double)el));
	}
	/* a region that cuts through the graded elements: [-1.6, 0.6] x [-0.4, 1.9] mm */
	double bins[3] = {0, 0.12e-3, 0.5e-3};
	for (int b = 0; b < 3; b++) {
		dem_profile_opts_t o = {{-1.6e-3, -0.4e-3}, {0.6e-3, 1.9e-3}, bins[b], 1e-6, 0.002, 0};
		assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o, &p, &e), 0);
		/* brute force, group by group */
		int ng = b == 0 ? NZ : (int)(2e-3 / bins[b]) + 1;
		size_t np = 0;
		for (int g = 0; g < ng; g++) {
			double W = 0, D = 0, S[13] = {0}, S2[13] = {0};
			unsigned n = 0;
			for (int pass = 0; pass < 2; pass++) {
				for (int k = 0; k < NZ; k++)
					for (int j = 0; j < NXY; j++)
						for (int i = 0; i < NXY; i++) {
							double xc = 0.5 * (GXY[i] + GXY[i + 1]), yc = 0.5 * (GXY[j] + GXY[j + 1]);
							double depth = -0.5 * (GZ[k] + GZ[k + 1]);
							int gg = b == 0 ? NZ - 1 - k : (int)(depth / bins[b]);
							if (gg != g || xc < o.lo[0] || xc > o.hi[0] || yc < o.lo[1] || yc > o.hi[1])
								continue;
							size_t el = dem_mesh_elem(&m, i, j, k);
							double vol = (GXY[i + 1] - GXY[i]) * (GXY[j + 1] - GXY[j]) * (GZ[k + 1] - GZ[k]);
							for (int c = 0; c < 13; c++) {
								double v = c < 6 ? f.sig[6 * el + c] : c < 12 ? f.eps[6 * el + c - 6] : f.ep[el];
								if (pass == 0)
									S[c] += vol * v;
								else
									S2[c] += vol * (v - S[c]) * (v - S[c]);
							}
							if (pass == 0) {
								W += vol;
								D += vol * depth;
								n++;
							}
						}
				if (pass == 0 && n)
					for (int c = 0; c < 13; c++)
						S[c] /= W;
			}
			if (!n)
				continue;
			assert_true(np < p.n);
			assert_int_equal(p.count[np], n);
			assert_close(p.depth[np], D / W, 1e-15);
			for (int c = 0; c < 13; c++) {
				double got = c < 6 ? p.sig[6 * np + c] : c < 12 ? p.eps[6 * np + c - 6] : p.ep[np];
				double tol = 1e-12 * (c < 6 ? 1e8 : 1e-2);
				assert_close(got, S[c], tol);
				assert_close(p.sd[13 * np + c], sqrt(S2[c] / W), tol);
			}
			np++;
		}
		assert_int_equal(np, p.n);
		if (b == 2) /* 0.5 mm bins: the top five layers (centroids 0.025 to
			     * 0.45 mm deep) share the first */
			assert_int_equal(p.count[0], 5 * (size_t)p.count[p.n - 1]);
		dem_profile_free(&p);
	}
	free_fields(&f);
	dem_mesh_free(&m);
}

/* ---- surface metrics ----------------------------------------------------- */

/* The indentation of a spherical dimple of shot radius R, depth d0 at its
 * centre, at distance r from it (0 outside the cap). */
static double cap(double R, double d0, double r)
{
	if (r >= R)
		return 0;
	double d = d0 - (R - sqrt(R * R - r * r));
	return d > 0 ? d : 0;
}

/* 4 x 4 dimples as Ch. 8.6 places its shots: shots of radius R = 0.7 mm
 * centred at (i + 0.5, j + 0.5) pitch over the area, each d0 deep.  Returns u
 * (z only) on the mesh of n x n elements over the area.  With a threshold
 * t, the dimpled disk of each has radius rho, d0 - t = R - sqrt(R^2 - rho^2). */
static double *dimple_field(const dem_mesh_t *m, double R, double d0, int grid,
			    double pitch)
{
	double *u = calloc(3 * m->nn, sizeof *u);
	for (size_t n = 0; n < m->nn; n++) {
		double x = m->X[3 * n], y = m->X[3 * n + 1], d = 0;
		for (int a = 0; a < grid; a++)
			for (int b = 0; b < grid; b++) {
				double r = hypot(x - (a + 0.5) * pitch, y - (b + 0.5) * pitch);
				d = fmax(d, cap(R, d0, r));
			}
		/* only the top face matters; deeper nodes get the same, harmlessly */
		u[3 * n + 2] = -d;
	}
	return u;
}

static void test_coverage_dimples(void **state)
{
	const double R = 0.7e-3, d0 = 80e-6, t = 5e-6, pitch = 1e-3;
	const double rho = sqrt(R * R - (R - (d0 - t)) * (R - (d0 - t)));
	double err[2];
	(void)state;
	for (int q = 0; q < 2; q++) {
		int n = q ? 320 : 160;          /* 25 and 12.5 um elements */
		double *g = uniform(0, 4e-3, n), gz[2] = {-0.1e-3, 0};
		dem_mesh_t m;
		dem_surface_t s;
		dem_error_t e = {0};
		make_mesh(&m, n, n, 1, g, g, gz);
		double *u = dimple_field(&m, R, d0, 4, pitch);
		dem_profile_opts_t o = {{0, 0}, {4e-3, 4e-3}, 0, t, 0.002, 0};
		assert_int_equal(dem_surface_compute(&m, u, NULL, &o, &s, &e), 0);
		double exact = 16 * DEM_PI * rho * rho / (4e-3 * 4e-3);
		/* brute force: the trapezoid weights of the nodes strictly
		 * inside a dimpled disk, from geometry alone */
		double h = 4e-3 / n, cov = 0;
		for (int j = 0; j <= n; j++)
			for (int i = 0; i <= n; i++) {
				double x = g[i], y = g[j], w = h * h;
				if (i == 0 || i == n)
					w /= 2;
				if (j == 0 || j == n)
					w /= 2;
				double rmin = 1;
				for (int a = 0; a < 4; a++)
					for (int b = 0; b < 4; b++)
						rmin = fmin(rmin, hypot(x - (a + 0.5) * pitch, y - (b + 0.5) * pitch));
				if (d0 - (R - sqrt(R * R - rmin * rmin)) > t)
					cov += w;
			}
		cov /= 4e-3 * 4e-3;
		assert_close(s.indented, cov, 1e-12);
		err[q] = fabs(s.indented - exact);
		/* a disk of radius rho = 0.315 mm holds about pi (rho/h)^2 nodes,
		 * rho/h = 12.6 and 25; the nodes' cells cover its area within
		 * 1 % (measured 0.5 % and 0.15 %; the bound from the cells cut
		 * by the circle, 2 sqrt(2) h / rho, is 22 % and 11 %) */
		if (err[q] > 0.01 * exact)
			fail_msg("n %d: coverage %.6f, exact %.6f", n, s.indented, exact);
		assert_int_equal(s.dimples, 16);
		assert_int_equal(s.patches, 16);
		assert_close(s.depth_mean, d0, 1e-15);   /* centres on nodes */
		assert_close(s.depth_max, d0, 1e-15);
		assert_close(s.radius, rho, 0.02 * rho);
		assert_close(s.area, 16e-6, 1e-10 * 16e-6);
		free(u);
		free(g);
		dem_mesh_free(&m);
	}
	fprintf(stderr, "# coverage error: %.2e (25 um), %.2e (12.5 um)\n", err[0], err[1]);

	/* overlapping dimples at a 0.3 mm pitch: one patch; the coverage
	 * against a brute-force raster of the union of the disks */
	int n = 160;
	double *g = uniform(0, 2e-3, n), gz[2] = {-0.1e-3, 0};
	dem_mesh_t m;
	dem_surface_t s;
	dem_error_t e = {0};
	make_mesh(&m, n, n, 1, g, g, gz);
	double *u = dimple_field(&m, R, d0, 4, 0.3e-3);
	dem_profile_opts_t o = {{0, 0}, {2e-3, 2e-3}, 0, t, 0.002, 0};
	assert_int_equal(dem_surface_compute(&m, u, NULL, &o, &s, &e), 0);
	long in = 0, N = 2000;
	for (long j = 0; j < N; j++)
		for (long i = 0; i < N; i++) {
			double x = (i + 0.5) * 2e-3 / N, y = (j + 0.5) * 2e-3 / N;
			for (int a = 0, hit = 0; a < 4 && !hit; a++)
				for (int b = 0; b < 4 && !hit; b++)
					if (hypot(x - (a + 0.5) * 0.3e-3, y - (b + 0.5) * 0.3e-3) < rho) {
						in++;
						hit = 1;
					}
		}
	double exact = (double)in / (double)(N * N);
	assert_close(s.indented, exact, 0.01 * exact);
	assert_int_equal(s.patches, 1);
	assert_int_equal(s.dimples, 0);         /* it reaches the edge: cut */
	assert_true(s.radius == 0 && s.depth_mean == 0);
	free(u);
	free(g);
	dem_mesh_free(&m);
}

/* Ra of uz = A sin(2 pi x / L) over whole periods is 2A/pi; a threshold
 * above every indentation covers nothing. */
static void test_roughness(void **state)
{
	const double A = 4e-6, L = 0.5e-3;
	int n = 400;
	double *g = uniform(0, 2e-3, n), gz[3] = {-0.2e-3, -0.1e-3, 0};
	dem_mesh_t m;
	dem_surface_t s;
	dem_error_t e = {0};
	(void)state;
	make_mesh(&m, n, 4, 2, g, g, gz);
	double *u = calloc(3 * m.nn, sizeof *u);
	for (size_t q = 0; q < m.nn; q++)
		u[3 * q + 2] = A * sin(2 * DEM_PI * m.X[3 * q] / L) - 1e-6;  /* plus a sink */
	dem_profile_opts_t o = {{0, 0}, {2e-3, 1e-3}, 0, 10e-6, 0.002, 0};
	assert_int_equal(dem_surface_compute(&m, u, NULL, &o, &s, &e), 0);
	assert_close(s.ra, 2 * A / DEM_PI, 5e-4 * 2 * A / DEM_PI);
	assert_true(s.indented == 0);
	assert_int_equal(s.patches, 0);
	assert_close(s.depth_max, A + 1e-6, 1e-12);
	free(u);
	free(g);
	dem_mesh_free(&m);
}

/* The plastic share: the top faces of the region's top-layer elements whose
 * ep exceeds the threshold, by area, against a count by hand: a disk of
 * plastic top elements, a plastic layer beneath that must not count, one
 * element at the threshold exactly (not above it), a region that holds
 * part of the disk; no ep, no share. */
static void test_plastic_share(void **state)
{
	(void)state;
	const int n = 40;
	double *g = uniform(0, 4e-3, n), gz[4] = {-0.3e-3, -0.2e-3, -0.1e-3, 0};
	dem_mesh_t m;
	dem_surface_t s;
	dem_error_t e = {0};
	make_mesh(&m, n, n, 3, g, g, gz);
	double *u = calloc(3 * m.nn, sizeof *u), *ep = calloc(m.ne, sizeof *ep);
	assert_non_null(u);
	assert_non_null(ep);
	for (int j = 0; j < n; j++)
		for (int i = 0; i < n; i++) {
			double xc = 0.5 * (g[i] + g[i + 1]), yc = 0.5 * (g[j] + g[j + 1]);
			if (hypot(xc - 2e-3, yc - 2e-3) < 1e-3)
				ep[dem_mesh_elem(&m, i, j, 2)] = 0.01;
			ep[dem_mesh_elem(&m, i, j, 1)] = 0.05;
		}
	ep[dem_mesh_elem(&m, 0, 0, 2)] = 0.002;
	for (int q = 0; q < 2; q++) {
		/* q = 1: the region x <= 2 mm, half the disk */
		dem_profile_opts_t o = {{0, 0}, {q ? 2e-3 : 4e-3, 4e-3}, 0, 1e-6, 0.002, 0};
		assert_int_equal(dem_surface_compute(&m, u, ep, &o, &s, &e), 0);
		int cnt = 0, all = 0;
		for (int j = 0; j < n; j++)
			for (int i = 0; i < n; i++) {
				double xc = 0.5 * (g[i] + g[i + 1]), yc = 0.5 * (g[j] + g[j + 1]);
				if (xc > o.hi[0])
					continue;
				all++;
				cnt += hypot(xc - 2e-3, yc - 2e-3) < 1e-3;
			}
		assert_true(cnt > 100);
		assert_close(s.plastic, (double)cnt / all, 1e-12);
		assert_close(s.indented, 0, 0);
	}
	dem_profile_opts_t o = {{0, 0}, {4e-3, 4e-3}, 0, 1e-6, 0.002, 0};
	assert_int_equal(dem_surface_compute(&m, u, NULL, &o, &s, &e), 0);
	assert_close(s.plastic, 0, 0);
	free(u);
	free(ep);
	free(g);
	dem_mesh_free(&m);
}

/* ---- axisymmetric frames ------------------------------------------------ */

/* A 2D axisymmetric block as demshot writes it: x the radius from the axis,
 * graded (0.1 to 0.4 mm elements), one element thick in y; 4 layers. */
static const double GR[] = {0, 0.1e-3, 0.2e-3, 0.3e-3, 0.45e-3, 0.6e-3, 0.75e-3, 0.9e-3,
			    1.2e-3, 1.6e-3, 2e-3};
static const double GY1[] = {-0.05e-3, 0.05e-3};
static const double GZ4[] = {-0.5e-3, -0.3e-3, -0.15e-3, -0.05e-3, 0};
enum { NR = 10, NZ4 = 4 };

/* f(r) = a + b r^2 with a per layer and field: each element holds its mean
 * over its ring, a + b (r0^2 + r1^2) / 2 (the integral of f 2 pi r dr over
 * [r0, r1] by the ring's area), so the ring-weighted mean over the disk
 * r < R0 is exactly that of f, a + b R0^2 / 2, for R0 on a grid line. */
static double ring_a(int k, int c)
{
	return (c < 6 ? -1.5e8 : c < 12 ? -2e-3 : 0.05) * (1 + 0.3 * k) * (c % 6 + 1) / 6.0;
}

static double ring_b(int c)
{
	return (c < 6 ? 2e14 : c < 12 ? 3e3 : -4e4) * (c % 5 + 1) / 5.0;   /* per m^2 */
}

static void test_axisym_ring_mean(void **state)
{
	dem_mesh_t m;
	struct fields f;
	dem_profile_t p;
	dem_error_t e = {0};
	(void)state;
	make_mesh(&m, NR, 1, NZ4, GR, GY1, GZ4);
	alloc_fields(&f, m.ne);
	for (int k = 0; k < NZ4; k++)
		for (int i = 0; i < NR; i++) {
			size_t el = dem_mesh_elem(&m, i, 0, k);
			double q = 0.5 * (GR[i] * GR[i] + GR[i + 1] * GR[i + 1]);
			for (int c = 0; c < 13; c++) {
				double v = ring_a(k, c) + ring_b(c) * q;
				if (c < 6)
					f.sig[6 * el + c] = v;
				else if (c < 12)
					f.eps[6 * el + c - 6] = v;
				else
					f.ep[el] = v;
			}
		}
	const double R0[3] = {0.3e-3, 0.9e-3, 2e-3};
	const int inside[3] = {3, 7, 10};
	for (int t = 0; t < 3; t++) {
		for (int bins = 0; bins < 2; bins++) {
			/* the disk r < R0: the x range [-R0, R0] (centroids), all of y;
			 * bins of 0.07 mm hold one layer each (centroids 0.025,
			 * 0.1, 0.225, 0.4 mm deep) */
			dem_profile_opts_t o = {{-R0[t], -1}, {R0[t], 1}, bins ? 0.07e-3 : 0, 1e-6, 0.002, 1};
			assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o, &p, &e), 0);
			assert_int_equal(p.n, NZ4);
			for (size_t i = 0; i < p.n; i++) {
				int k = NZ4 - 1 - (int)i;
				assert_int_equal(p.count[i], inside[t]);
				assert_close(p.depth[i], -0.5 * (GZ4[k] + GZ4[k + 1]), 1e-18);
				for (int c = 0; c < 13; c++) {
					double want = ring_a(k, c) + ring_b(c) * R0[t] * R0[t] / 2;
					double got = c < 6 ? p.sig[6 * i + c] : c < 12 ? p.eps[6 * i + c - 6] : p.ep[i];
					double scale = fabs(ring_a(k, c)) + fabs(ring_b(c)) * R0[t] * R0[t];
					assert_close(got, want, 1e-13 * scale);
					/* the spread: ring-weighted, by brute force */
					double W = 0, S2 = 0;
					for (int j = 0; j < inside[t]; j++) {
						double w = (GR[j + 1] * GR[j + 1] - GR[j] * GR[j]);
						double d = ring_a(k, c) + ring_b(c) * 0.5 *
							   (GR[j] * GR[j] + GR[j + 1] * GR[j + 1]) - want;
						W += w;
						S2 += w * d * d;
					}
					assert_close(p.sd[13 * i + c], sqrt(S2 / W), 1e-9 * scale);
				}
			}
			dem_profile_free(&p);
		}
		/* the same disk averaged as a plane strip (every element alike)
		 * misses the closed form by far: b R0^2 / 2 against the mean of
		 * (r0^2 + r1^2) / 2 over the elements, 0.3 of the ring term and
		 * more (so the test above can fail) */
		dem_profile_opts_t o = {{-R0[t], -1}, {R0[t], 1}, 0, 1e-6, 0.002, 0};
		assert_int_equal(dem_profile_compute(&m, f.sig, f.eps, f.ep, &o, &p, &e), 0);
		double want = ring_a(NZ4 - 1, 0) + ring_b(0) * R0[t] * R0[t] / 2;
		assert_true(fabs(p.sig[0] - want) > 0.1 * ring_b(0) * R0[t] * R0[t] / 2);
		dem_profile_free(&p);
	}
	free_fields(&f);
	dem_mesh_free(&m);
}

/* The top of an axisymmetric block indented as a cone, uz = -(d0 - k r):
 * linear in r, so the interpolant the node weights integrate is exact.
 * Over the disk r < R0: area pi R0^2; with the cone's mean level at
 * r* = 2 R0 / 3, a grid line, Ra = 2 k (r*^3/6 + (R0^3 - r*^3)/3 -
 * r* (R0^2 - r*^2)/2) / R0^2; the deepest point d0 on the axis; a plastic
 * disk of top faces r < r_p covers (r_p / R0)^2 of it (a strip would say
 * r_p / R0).  The indented nodes i <= n (r_n < r_t < r_n+1) weigh the
 * integral of their shape functions, r_n^2 / 2 + h (2 r_n + r_n+1) / 6 of
 * r dr (h = r_n+1 - r_n); a whole dimple, on the axis. */
static void test_axisym_surface(void **state)
{
	const double R0 = 0.9e-3, rs = 0.6e-3, d0 = 30e-6, kc = 20e-3;   /* k: 20 um per mm */
	dem_mesh_t m;
	dem_surface_t s;
	dem_error_t e = {0};
	(void)state;
	make_mesh(&m, NR, 1, NZ4, GR, GY1, GZ4);
	double *u = calloc(3 * m.nn, sizeof *u), *ep = calloc(m.ne, sizeof *ep);
	assert_non_null(u);
	assert_non_null(ep);
	for (size_t n = 0; n < m.nn; n++)
		u[3 * n + 2] = -(d0 - kc * m.X[3 * n]);
	for (int i = 0; i < 4; i++)             /* plastic top faces r < 0.45 mm */
		ep[dem_mesh_elem(&m, i, 0, NZ4 - 1)] = 0.01;
	ep[dem_mesh_elem(&m, 2, 0, NZ4 - 2)] = 0.01;    /* beneath: not counted */
	/* threshold: r_t = 0.5 mm, between the nodes at 0.45 and 0.6 mm */
	const double thr = d0 - kc * 0.5e-3;
	dem_profile_opts_t o = {{-R0, -1}, {R0, 1}, 0, thr, 0.002, 1};
	assert_int_equal(dem_surface_compute(&m, u, ep, &o, &s, &e), 0);
	assert_close(s.area, DEM_PI * R0 * R0, 1e-12 * DEM_PI * R0 * R0);
	double ra = 2 * kc * (rs * rs * rs / 6 + (R0 * R0 * R0 - rs * rs * rs) / 3 -
			      rs * (R0 * R0 - rs * rs) / 2) / (R0 * R0);
	assert_close(s.ra, ra, 1e-12 * ra);
	assert_close(s.depth_max, d0, 1e-18);
	assert_close(s.plastic, 0.45e-3 * 0.45e-3 / (R0 * R0), 1e-12);
	double rn = 0.45e-3, h = 0.15e-3;
	double ind = 2 * DEM_PI * (rn * rn / 2 + h * (2 * rn + rn + h) / 6);
	assert_close(s.indented, ind / (DEM_PI * R0 * R0), 1e-12);
	assert_int_equal(s.patches, 1);
	assert_int_equal(s.dimples, 1);
	assert_close(s.radius, sqrt(ind / DEM_PI), 1e-12 * R0);
	assert_close(s.depth_mean, d0, 1e-18);
	/* plane weighting of the same surface: the plastic share is the strip's */
	o.axisym = 0;
	assert_int_equal(dem_surface_compute(&m, u, ep, &o, &s, &e), 0);
	assert_close(s.plastic, 0.45e-3 / R0, 1e-12);
	assert_int_equal(s.dimples, 0);         /* every node on the layer's y sides */
	/* a region ending inside the dimple (r < 0.3 mm) cuts it */
	dem_profile_opts_t o2 = {{-0.3e-3, -1}, {0.3e-3, 1}, 0, thr, 0.002, 1};
	assert_int_equal(dem_surface_compute(&m, u, ep, &o2, &s, &e), 0);
	assert_int_equal(s.patches, 1);
	assert_int_equal(s.dimples, 0);
	assert_close(s.indented, 1, 1e-15);
	free(u);
	free(ep);
	dem_mesh_free(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_stream_round_trip),
		cmocka_unit_test(test_stream_hand_written),
		cmocka_unit_test(test_stream_refusals),
		cmocka_unit_test(test_layers_exact),
		cmocka_unit_test(test_layers_and_bins_brute_force),
		cmocka_unit_test(test_coverage_dimples),
		cmocka_unit_test(test_roughness),
		cmocka_unit_test(test_plastic_share),
		cmocka_unit_test(test_axisym_ring_mean),
		cmocka_unit_test(test_axisym_surface),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
