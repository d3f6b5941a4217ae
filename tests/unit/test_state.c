/* test_state.c - the state stream (lib/io/state): the mesh and every frame
 * read back bit for bit (binary gzip, plain binary and text), the grid of a
 * structured mesh recovered, and the refusals: truncation anywhere, a
 * missing or misplaced row, a wrong kind, values that are not finite.
 * Also the other output of a state, the VTU file (lib/io/vtu): its arrays
 * decoded back bit for bit, ASCII and base64. */
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

#include "io/state.h"
#include "io/vtu.h"

#define TMPDIR_PREFIX "/tmp/dem-state-"
#include "tmpdir.h"
#include "gridmesh.h"

/* Awkward doubles: subnormals, -0, extremes, values with 17 digits. */
static uint64_t rng = 88172645463325252ull;
static double awkward(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	switch (rng % 8) {
	case 0: return -0.0;
	case 1: return 4.9e-324 * (double)(rng % 1000);
	case 2: return 1.7976931348623157e308 / (double)(1 + rng % 7);
	case 3: return -2.2250738585072014e-308;
	default: {
		uint64_t bits = rng & 0x7fefffffffffffffull;   /* finite, random */
		double d;
		memcpy(&d, &bits, 8);
		return rng & 1ull << 63 ? -d : d;
	}
	}
}

struct frame {
	unsigned pass;
	double time;
	double *u, *sig, *eps, *ep;
};

static void make_frame(struct frame *f, const dem_mesh_t *m, unsigned pass, double t)
{
	f->pass = pass;
	f->time = t;
	f->u = malloc(3 * m->nn * sizeof(double));
	f->sig = malloc(6 * m->ne * sizeof(double));
	f->eps = malloc(6 * m->ne * sizeof(double));
	f->ep = malloc(m->ne * sizeof(double));
	for (size_t i = 0; i < 3 * m->nn; i++)
		f->u[i] = awkward();
	for (size_t i = 0; i < 6 * m->ne; i++) {
		f->sig[i] = awkward();
		f->eps[i] = awkward();
	}
	for (size_t i = 0; i < m->ne; i++)
		f->ep[i] = awkward();
}

static void free_frame(struct frame *f)
{
	free(f->u);
	free(f->sig);
	free(f->eps);
	free(f->ep);
}

/* 3 x 2 x 5 elements: 72 nodes, not a multiple of 4 per row... (72 is; the
 * second mesh below has 3 x 3 x 2 = 18 elements, 48 nodes; the odd one
 * 1 x 1 x 2 has 12 nodes): the last node row is checked full and partial. */
static const double GX[] = {-1.5e-3, -0.25e-3, 0.1e-3, 2e-3};
static const double GY[] = {-1e-3, 0.3e-3, 1e-3};
static const double GZ[] = {-4e-3, -1e-3, -0.3e-3, -0.1e-3, -0.05e-3, 0};

static void write_stream(const char *p, const dem_mesh_t *m, struct frame *f,
			 int nf, int flags)
{
	dem_state_writer_t *w;
	dem_error_t e = {0};
	dem_header_t lines;

	dem_header_init(&lines, "x", 1, 0);
	dem_header_add(&lines, "prog", "test_state 0 args: none");
	dem_header_add(&lines, "area", "-0.0028 -0.0028 0.0028 0.0028");
	dem_header_add(&lines, "nodes", "999");   /* the writer's own: dropped */
	assert_int_equal(dem_state_writer_open(&w, p, m, &lines, flags, &e), 0);
	dem_header_free(&lines);
	for (int i = 0; i < nf; i++)
		assert_int_equal(dem_state_write_frame(w, f[i].pass, f[i].time, f[i].u, f[i].sig,
						       f[i].eps, f[i].ep, &e), 0);
	assert_int_equal(dem_state_writer_close(w, &e), 0);
}

static void bits_equal(const double *a, const double *b, size_t n)
{
	assert_memory_equal(a, b, n * sizeof(double));
}

static void round_trip(int flags, int nx, int ny, int nz)
{
	dem_mesh_t m;
	struct frame f[3];
	const char *p = path("rt.state");
	dem_state_reader_t *r;
	dem_state_frame_t got;
	dem_error_t e = {0};

	make_mesh(&m, nx, ny, nz, GX, GY, GZ + 5 - nz);
	make_frame(&f[0], &m, 0, 0.0);
	make_frame(&f[1], &m, 1, 2.5e-5);
	make_frame(&f[2], &m, 1, 3.0000000000000004e-5);
	write_stream(p, &m, f, 3, flags);

	assert_int_equal(dem_state_reader_open(&r, p, &e), 0);
	const dem_mesh_t *rm = dem_state_mesh(r);
	assert_int_equal(rm->nn, m.nn);
	assert_int_equal(rm->ne, m.ne);
	assert_int_equal(rm->nx, nx);
	assert_int_equal(rm->ny, ny);
	assert_int_equal(rm->nz, nz);
	bits_equal(rm->X, m.X, 3 * m.nn);
	assert_memory_equal(rm->hex, m.hex, 8 * m.ne * sizeof(uint32_t));
	bits_equal(rm->gx, m.gx, nx + 1);
	bits_equal(rm->gy, m.gy, ny + 1);
	bits_equal(rm->gz, m.gz, nz + 1);
	const dem_header_t *h = dem_state_header(r);
	assert_string_equal(dem_header_get(h, "area"), "-0.0028 -0.0028 0.0028 0.0028");
	assert_string_equal(dem_header_get(h, "prog"), "test_state 0 args: none");
	char nodes[32];
	snprintf(nodes, sizeof nodes, "%zu", m.nn);
	assert_string_equal(dem_header_get(h, "nodes"), nodes);
	for (int i = 0; i < 3; i++) {
		assert_int_equal(dem_state_next(r, &got, &e), 1);
		assert_int_equal(got.pass, f[i].pass);
		bits_equal(&got.time, &f[i].time, 1);
		bits_equal(got.u, f[i].u, 3 * m.nn);
		bits_equal(got.sig, f[i].sig, 6 * m.ne);
		bits_equal(got.eps, f[i].eps, 6 * m.ne);
		bits_equal(got.ep, f[i].ep, m.ne);
	}
	assert_int_equal(dem_state_next(r, &got, &e), 0);
	assert_int_equal(e.code, 0);
	dem_state_reader_close(r);
	for (int i = 0; i < 3; i++)
		free_frame(&f[i]);
	dem_mesh_free(&m);
}

static void test_round_trip_gzip_binary(void **state)
{
	(void)state;
	round_trip(DEM_STATE_FLAGS, 3, 2, 5);   /* 72 nodes: full node rows */
	round_trip(DEM_STATE_FLAGS, 1, 1, 2);   /* 12 nodes */
	round_trip(DEM_STATE_FLAGS, 2, 2, 1);   /* 18 nodes: a partial last row */
}

static void test_round_trip_binary(void **state)
{
	(void)state;
	round_trip(DEM_STREAM_BINARY, 3, 2, 5);
	round_trip(DEM_STREAM_BINARY, 2, 2, 1);
}

static void test_round_trip_text(void **state)
{
	(void)state;
	round_trip(0, 3, 2, 5);
	round_trip(DEM_STREAM_GZIP, 2, 2, 1);
}

/* The default output is gzip: the file starts with the gzip magic. */
static void test_default_is_gzip(void **state)
{
	dem_mesh_t m;
	struct frame f;
	unsigned char magic[2] = {0};
	(void)state;
	make_mesh(&m, 1, 1, 2, GX, GY, GZ);
	make_frame(&f, &m, 0, 0);
	write_stream(path("gz.state"), &m, &f, 1, DEM_STATE_FLAGS);
	FILE *fp = fopen(path("gz.state"), "rb");
	assert_non_null(fp);
	assert_int_equal(fread(magic, 1, 2, fp), 2);
	fclose(fp);
	assert_int_equal(magic[0], 0x1f);
	assert_int_equal(magic[1], 0x8b);
	free_frame(&f);
	dem_mesh_free(&m);
}

static long file_size(const char *p)
{
	FILE *f = fopen(p, "rb");
	assert_non_null(f);
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fclose(f);
	return n;
}

/* Read the whole stream; return the error code (0 if it read cleanly). */
static int read_all(const char *p, dem_error_t *e, int *frames)
{
	dem_state_reader_t *r;
	dem_state_frame_t f;
	int got;
	*frames = 0;
	if (dem_state_reader_open(&r, p, e))
		return e->code;
	while ((got = dem_state_next(r, &f, e)) == 1)
		++*frames;
	dem_state_reader_close(r);
	return got < 0 ? e->code : 0;
}

/* A stream cut anywhere is refused: in the header, the mesh, a frame, just
 * before the trailer; compressed or not. */
static void test_truncated(void **state)
{
	dem_mesh_t m;
	struct frame f[2];
	(void)state;
	make_mesh(&m, 2, 2, 1, GX, GY, GZ + 4);
	make_frame(&f[0], &m, 0, 0);
	make_frame(&f[1], &m, 1, 1e-5);
	int flags[3] = {DEM_STATE_FLAGS, DEM_STREAM_BINARY, 0};
	for (int q = 0; q < 3; q++) {
		const char *p = path("full.state");
		write_stream(p, &m, f, 2, flags[q]);
		long n = file_size(p);
		char *buf = malloc(n);
		FILE *fp = fopen(p, "rb");
		assert_int_equal(fread(buf, 1, n, fp), (size_t)n);
		fclose(fp);
		int frames;
		dem_error_t e = {0};
		assert_int_equal(read_all(p, &e, &frames), 0);
		assert_int_equal(frames, 2);
		for (long cut = 1; cut < n; cut += 1 + n / 97) {
			const char *c = path("cut.state");
			fp = fopen(c, "wb");
			fwrite(buf, 1, cut, fp);
			fclose(fp);
			dem_error_clear(&e);
			int rc = read_all(c, &e, &frames);
			if (rc != DEM_EINPUT)
				fail_msg("flags %d, cut at %ld of %ld: code %d, %d frames: %s",
					 flags[q], cut, n, rc, frames, e.msg);
			assert_non_null(strstr(e.msg, "cut.state"));
		}
		/* the very last byte (the newline of the trailer) too */
		if (!(flags[q] & DEM_STREAM_GZIP)) {
			const char *c = path("cut.state");
			fp = fopen(c, "wb");
			fwrite(buf, 1, n - 1, fp);
			fclose(fp);
			dem_error_t e2 = {0};
			assert_int_equal(read_all(c, &e2, &frames), DEM_EINPUT);
			assert_non_null(strstr(e2.msg, "truncated"));
		}
		free(buf);
	}
	for (int i = 0; i < 2; i++)
		free_frame(&f[i]);
	dem_mesh_free(&m);
}

#define HEAD \
	"# dem state 1\n# dim 3\n# columns rec:u32:- id:u32:- v0:f64:- v1:f64:- v2:f64:- " \
	"v3:f64:- v4:f64:- v5:f64:- v6:f64:- v7:f64:- v8:f64:- v9:f64:- v10:f64:- " \
	"v11:f64:- v12:f64:-\n# format text\n" \
	"# record node 1 per=4 x:m y:m z:m\n" \
	"# record hex 2 per=1 n0:- n1:- n2:- n3:- n4:- n5:- n6:- n7:-\n" \
	"# record frame 3 per=1 time:s nodes:- elements:-\n" \
	"# record disp 4 per=4 ux:m uy:m uz:m\n" \
	"# record elem 5 per=1 sxx:Pa syy:Pa szz:Pa sxy:Pa syz:Pa szx:Pa " \
	"exx:- eyy:- ezz:- exy:- eyz:- ezx:- ep:-\n"
/* one element, the unit cube: 8 nodes in two rows */
#define MESH1 \
	"# nodes 8\n# elements 1\n# grid 1 1 1\n# data\n" \
	"1 0 0 0 0 1 0 0 0 1 0 1 1 0 0\n" \
	"1 4 0 0 1 1 0 1 0 1 1 1 1 1 0\n" \
	"2 0 0 1 3 2 4 5 7 6 0 0 0 0 0\n"
#define FRAME1(pass) \
	"3 " #pass " 0 8 1 0 0 0 0 0 0 0 0 0 0\n" \
	"4 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n" \
	"4 4 0 0 0 0 0 0 0 0 0 0 0 0 0\n" \
	"5 0 -1e8 -1e8 0 0 0 0 -1e-3 -1e-3 0 0 0 0 0.01\n"

static int expect_fail(const char *text, const char *what)
{
	const char *p = path("bad.state");
	dem_error_t e = {0};
	int frames;
	write_text(p, text);
	int rc = read_all(p, &e, &frames);
	if (!strstr(e.msg, what))
		fail_msg("expected '%s' in '%s'", what, e.msg);
	return rc;
}

static void test_hand_written(void **state)
{
	const char *p = path("ok.state");
	dem_error_t e = {0};
	int frames;
	(void)state;
	write_text(p, HEAD MESH1 FRAME1(1) FRAME1(2) "# end 11\n");
	assert_int_equal(read_all(p, &e, &frames), 0);
	assert_int_equal(frames, 2);

	/* a mesh alone is a valid stream of no frames */
	write_text(p, HEAD MESH1 "# end 3\n");
	assert_int_equal(read_all(p, &e, &frames), 0);
	assert_int_equal(frames, 0);
}

static void test_refusals(void **state)
{
	(void)state;
	/* truncated inside a frame: the trailer's count cannot save it */
	assert_int_equal(expect_fail(HEAD MESH1 "3 1 0 8 1 0 0 0 0 0 0 0 0 0 0\n"
				     "4 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n# end 5\n",
				     "bad.state:19: truncated state: the stream ends before "
				     "the disp row of pass 1: node 4"), DEM_EINPUT);
	/* no trailer */
	assert_int_equal(expect_fail(HEAD MESH1 FRAME1(1), "truncated stream"), DEM_EINPUT);
	/* a row out of place */
	assert_int_equal(expect_fail(HEAD MESH1 "3 1 0 8 1 0 0 0 0 0 0 0 0 0 0\n"
				     "4 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n"
				     "5 0 -1e8 -1e8 0 0 0 0 -1e-3 -1e-3 0 0 0 0 0.01\n# end 6\n",
				     "bad.state:19: expected the disp row of pass 1: node 4, "
				     "got rec 5 (elem) for 0"), DEM_EINPUT);
	/* a frame for another mesh */
	assert_int_equal(expect_fail(HEAD MESH1 "3 1 0 9 1 0 0 0 0 0 0 0 0 0 0\n# end 4\n",
				     "a frame of 9 nodes"), DEM_EINPUT);
	/* an element's node out of range, and not an integer */
	assert_int_equal(expect_fail(HEAD "# nodes 8\n# elements 1\n# data\n"
				     "1 0 0 0 0 1 0 0 0 1 0 1 1 0 0\n"
				     "1 4 0 0 1 1 0 1 0 1 1 1 1 1 0\n"
				     "2 0 0 1 3 2 4 5 7 8 0 0 0 0 0\n# end 3\n",
				     "element 0: node '8'"), DEM_EINPUT);
	assert_int_equal(expect_fail(HEAD "# nodes 8\n# elements 1\n# data\n"
				     "1 0 0 0 0 1 0 0 0 1 0 1 1 0 0\n"
				     "1 4 0 0 1 1 0 1 0 1 1 1 1 1 0\n"
				     "2 0 0 1 3 2 4 5 7 6.5 0 0 0 0 0\n# end 3\n",
				     "element 0: node '6.5'"), DEM_EINPUT);
	/* a grid the nodes do not follow */
	assert_int_equal(expect_fail(HEAD "# nodes 8\n# elements 1\n# grid 1 1 1\n# data\n"
				     "1 0 0 0 0 1 0 0 0 1 0 1 1 0 0\n"
				     "1 4 0 0 1 1 0 1 0 1 1 1 0.5 1 0\n"
				     "2 0 0 1 3 2 4 5 7 6 0 0 0 0 0\n# end 3\n",
				     "node 7 is not on the grid lines"), DEM_EINPUT);
	/* a wrong kind, columns, record layout, missing counts */
	assert_int_equal(expect_fail("# dem profile 1\n# columns a:f64:-\n# format text\n# data\n# end 0\n",
				     "a profile stream; expected a state stream"), DEM_EINPUT);
	assert_int_equal(expect_fail("# dem state 1\n# columns rec:u32:- id:u32:-\n# format text\n"
				     "# data\n# end 0\n", "the state columns should be"), DEM_EINPUT);
	assert_int_equal(expect_fail(HEAD "# record extra 6 per=1 a:-\n" MESH1 "# end 3\n",
				     "'# record extra 6 per=1 a:-'"), DEM_EINPUT);
	assert_int_equal(expect_fail(HEAD "# elements 1\n# data\n# end 0\n",
				     "no '# nodes' line"), DEM_EINPUT);
	/* an unreadable path is an input error naming it */
	dem_error_t e = {0};
	int frames;
	assert_int_equal(read_all(path("none.state"), &e, &frames), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "none.state"));
}

/* The writer refuses a frame with a NaN or an infinity and writes nothing
 * of it: the stream stays valid with the frames before. */
static void test_writer_refuses_nonfinite(void **state)
{
	dem_mesh_t m;
	struct frame f;
	dem_state_writer_t *w;
	dem_error_t e = {0};
	const char *p = path("nan.state");
	int frames;
	(void)state;
	make_mesh(&m, 2, 1, 1, GX, GY, GZ + 4);
	make_frame(&f, &m, 0, 0);
	assert_int_equal(dem_state_writer_open(&w, p, &m, NULL, DEM_STATE_FLAGS, &e), 0);
	assert_int_equal(dem_state_write_frame(w, 0, 0, f.u, f.sig, f.eps, f.ep, &e), 0);
	f.sig[6 * 1 + 3] = NAN;
	assert_int_equal(dem_state_write_frame(w, 1, 1, f.u, f.sig, f.eps, f.ep, &e), DEM_ENUMERIC);
	assert_non_null(strstr(e.msg, "element 1: the stress is not finite"));
	f.sig[6 * 1 + 3] = 0;
	f.u[3 * 5 + 2] = INFINITY;
	dem_error_clear(&e);
	assert_int_equal(dem_state_write_frame(w, 1, 1, f.u, f.sig, f.eps, f.ep, &e), DEM_ENUMERIC);
	assert_non_null(strstr(e.msg, "node 5"));
	dem_error_clear(&e);
	assert_int_equal(dem_state_writer_close(w, &e), 0);
	assert_int_equal(read_all(p, &e, &frames), 0);
	assert_int_equal(frames, 1);
	/* an aborted writer leaves no file */
	assert_int_equal(dem_state_writer_open(&w, path("gone.state"), &m, NULL, 0, &e), 0);
	dem_state_writer_abort(w);
	assert_int_equal(access(path("gone.state"), F_OK), -1);
	free_frame(&f);
	dem_mesh_free(&m);
}

/* A mesh without a grid (nx = 0) goes through without "# grid". */
static void test_unstructured(void **state)
{
	dem_mesh_t m;
	struct frame f;
	dem_state_reader_t *r;
	dem_error_t e = {0};
	(void)state;
	make_mesh(&m, 2, 1, 1, GX, GY, GZ + 4);
	m.nx = m.ny = m.nz = 0;
	make_frame(&f, &m, 3, 1);
	write_stream(path("u.state"), &m, &f, 1, 0);
	assert_int_equal(dem_state_reader_open(&r, path("u.state"), &e), 0);
	assert_null(dem_header_get(dem_state_header(r), "grid"));
	assert_int_equal(dem_state_mesh(r)->nx, 0);
	assert_null(dem_state_mesh(r)->gx);
	bits_equal(dem_state_mesh(r)->X, m.X, 3 * m.nn);
	dem_state_reader_close(r);
	m.nx = 2;
	m.ny = m.nz = 1;
	free_frame(&f);
	dem_mesh_free(&m);
}

/* The mesher's graded box (lib/fe/mesh) goes through: its nodes lie on its
 * grid lines and its hexes are numbered as the reader checks. */
static void test_mesher_mesh(void **state)
{
	dem_mesh_t m;
	dem_axis_t ax[3] = {
		{-4e-3, 4e-3, -1e-3, 1e-3, 0.25e-3, 1.5, 1e-3},
		{-4e-3, 4e-3, -1e-3, 1e-3, 0.25e-3, 1.5, 1e-3},
		{-4e-3, 0, -0.5e-3, 0, 0.1e-3, 1.4, 1e-3},
	};
	dem_state_reader_t *r;
	dem_error_t e = {0};
	struct frame f;
	(void)state;
	assert_int_equal(dem_mesh_box(&m, ax, &e), 0);
	make_frame(&f, &m, 7, 1e-4);
	write_stream(path("box.state"), &m, &f, 1, DEM_STATE_FLAGS);
	assert_int_equal(dem_state_reader_open(&r, path("box.state"), &e), 0);
	const dem_mesh_t *rm = dem_state_mesh(r);
	assert_int_equal(rm->nx, m.nx);
	assert_int_equal(rm->nz, m.nz);
	bits_equal(rm->gz, m.gz, m.nz + 1);
	assert_memory_equal(rm->hex, m.hex, 8 * m.ne * sizeof(uint32_t));
	dem_state_reader_close(r);
	free_frame(&f);
	dem_mesh_free(&m);
}

/* ---- VTU ------------------------------------------------------------------ */

static char *slurp(const char *p)
{
	FILE *f = fopen(p, "rb");
	assert_non_null(f);
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fseek(f, 0, SEEK_SET);
	char *s = malloc(n + 1);
	assert_int_equal(fread(s, 1, n, f), (size_t)n);
	s[n] = '\0';
	fclose(f);
	return s;
}

/* The text between '>' and '<' of the DataArray named name. */
static char *array_text(const char *doc, const char *name)
{
	char key[64];
	snprintf(key, sizeof key, "Name=\"%s\"", name);
	const char *a = strstr(doc, key);
	if (!a)
		fail_msg("no array %s", name);
	a = strchr(a, '>') + 1;
	const char *b = strchr(a, '<');
	char *t = malloc(b - a + 1);
	memcpy(t, a, b - a);
	t[b - a] = '\0';
	return t;
}

/* Decode base64 (one run, whitespace skipped); returns the bytes. */
static unsigned char *unbase64(const char *t, size_t *n)
{
	static const char al[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	unsigned char *out = malloc(strlen(t));
	unsigned v = 0;
	int k = 0;
	*n = 0;
	for (; *t; t++) {
		const char *c = strchr(al, *t);
		if (*t == '=' || !c || !*t)
			continue;
		v = v << 6 | (unsigned)(c - al);
		if (++k == 4) {
			out[(*n)++] = v >> 16;
			out[(*n)++] = v >> 8 & 255;
			out[(*n)++] = v & 255;
			k = 0;
			v = 0;
		}
	}
	if (k == 2)
		out[(*n)++] = v >> 4;
	else if (k == 3) {
		out[(*n)++] = v >> 10;
		out[(*n)++] = v >> 2 & 255;
	}
	return out;
}

/* Array name of the file as doubles (ASCII or binary with its count). */
static double *vtu_doubles(const char *doc, const char *name, int binary, size_t *n)
{
	char *t = array_text(doc, name);
	double *x;
	if (binary) {
		size_t nb;
		unsigned char *b = unbase64(t, &nb);
		uint64_t count;
		memcpy(&count, b, 8);
		assert_int_equal(count, nb - 8);
		*n = (nb - 8) / 8;
		x = malloc(nb);
		memcpy(x, b + 8, nb - 8);
		free(b);
	} else {
		x = malloc(strlen(t) * sizeof *x);
		char *p = t, *end;
		*n = 0;
		for (;;) {
			double v = strtod(p, &end);
			if (end == p)
				break;
			x[(*n)++] = v;
			p = end;
		}
	}
	free(t);
	return x;
}

static void test_vtu(void **state)
{
	dem_mesh_t m;
	struct frame f;
	dem_error_t e = {0};
	size_t n;
	(void)state;
	make_mesh(&m, 3, 2, 2, GX, GY, GZ + 3);
	make_frame(&f, &m, 0, 0);
	for (size_t i = 0; i < 6 * m.ne; i++) {      /* finite, moderate values */
		f.sig[i] = 1e8 * sin((double)i);
		f.eps[i] = 1e-3 * cos((double)i);
	}
	/* element 0 uniaxial, element 1 pure shear: von Mises 100 and 10 sqrt 3 */
	memset(f.sig, 0, 12 * sizeof(double));
	f.sig[0] = 100;
	f.sig[6 + 3] = 10;
	for (int binary = 0; binary < 2; binary++) {
		const char *p = path(binary ? "b.vtu" : "a.vtu");
		dem_vtu_fields_t fl = {f.u, f.sig, f.eps, f.ep};
		assert_int_equal(dem_vtu_write(p, &m, &fl, binary, &e), 0);
		char *doc = slurp(p);
		assert_non_null(strstr(doc, "<VTKFile type=\"UnstructuredGrid\""));
		char piece[96];
		snprintf(piece, sizeof piece, "<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">", m.nn, m.ne);
		assert_non_null(strstr(doc, piece));
		double *x = vtu_doubles(doc, "Points", binary, &n);
		assert_int_equal(n, 3 * m.nn);
		bits_equal(x, m.X, n);
		free(x);
		x = vtu_doubles(doc, "displacement", binary, &n);
		assert_int_equal(n, 3 * m.nn);
		for (size_t i = 0; i < n; i++)  /* -0 is written as 0 in ASCII */
			assert_true(x[i] == f.u[i]);
		free(x);
		x = vtu_doubles(doc, "stress", binary, &n);
		assert_int_equal(n, 6 * m.ne);
		bits_equal(x, f.sig, n);
		free(x);
		x = vtu_doubles(doc, "strain", binary, &n);
		for (size_t i = 0; i < n; i++)
			assert_true(x[i] == (i % 6 < 3 ? 1 : 0.5) * f.eps[i]);
		free(x);
		x = vtu_doubles(doc, "von_mises", binary, &n);
		assert_int_equal(n, m.ne);
		assert_true(fabs(x[0] - 100) < 1e-12);
		assert_true(fabs(x[1] - 10 * sqrt(3)) < 1e-12);
		free(x);
		x = vtu_doubles(doc, "plastic_strain", binary, &n);
		for (size_t i = 0; i < n; i++)
			assert_true(x[i] == f.ep[i]);
		free(x);
		/* connectivity, offsets and types */
		char *t = array_text(doc, "connectivity");
		if (binary) {
			size_t nb;
			unsigned char *b = unbase64(t, &nb);
			assert_int_equal(nb, 8 + 64 * m.ne);
			for (size_t i = 0; i < 8 * m.ne; i++) {
				int64_t v;
				memcpy(&v, b + 8 + 8 * i, 8);
				assert_int_equal(v, m.hex[i]);
			}
			free(b);
			free(t);
			t = array_text(doc, "types");
			b = unbase64(t, &nb);
			assert_int_equal(nb, 8 + m.ne);
			for (size_t i = 0; i < m.ne; i++)
				assert_int_equal(b[8 + i], 12);
			free(b);
		} else {
			char *p2 = t;
			for (size_t i = 0; i < 8 * m.ne; i++)
				assert_int_equal(strtol(p2, &p2, 10), m.hex[i]);
			free(t);
			t = array_text(doc, "offsets");
			p2 = t;
			for (size_t i = 0; i < m.ne; i++)
				assert_int_equal(strtol(p2, &p2, 10), 8 * (i + 1));
			free(t);
			t = array_text(doc, "types");
			p2 = t;
			for (size_t i = 0; i < m.ne; i++)
				assert_int_equal(strtol(p2, &p2, 10), 12);
		}
		free(t);
		free(doc);
	}
	/* a NaN: refused, no file */
	f.ep[3] = NAN;
	dem_vtu_fields_t fl = {f.u, f.sig, f.eps, f.ep};
	assert_int_equal(dem_vtu_write(path("nan.vtu"), &m, &fl, 1, &e), DEM_ENUMERIC);
	assert_non_null(strstr(e.msg, "element 3: the plastic strain is not finite"));
	assert_int_equal(access(path("nan.vtu"), F_OK), -1);
	/* the mesh alone; an unwritable path */
	dem_error_clear(&e);
	assert_int_equal(dem_vtu_write(path("mesh.vtu"), &m, NULL, 0, &e), 0);
	assert_int_equal(dem_vtu_write("/nonexistent/dir/x.vtu", &m, NULL, 0, &e), DEM_EIO);
	assert_non_null(strstr(e.msg, "/nonexistent/dir/x.vtu"));
	free_frame(&f);
	dem_mesh_free(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_round_trip_gzip_binary),
		cmocka_unit_test(test_round_trip_binary),
		cmocka_unit_test(test_round_trip_text),
		cmocka_unit_test(test_default_is_gzip),
		cmocka_unit_test(test_truncated),
		cmocka_unit_test(test_hand_written),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_writer_refuses_nonfinite),
		cmocka_unit_test(test_unstructured),
		cmocka_unit_test(test_mesher_mesh),
		cmocka_unit_test(test_vtu),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
