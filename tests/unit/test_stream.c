/* test_stream.c - the record streams of lib/io/stream: round trips in text,
 * binary and gzip, and every refusal the DESIGN requires (truncation,
 * NaN/Inf, malformed rows, unknown kinds), each naming stream and row. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "io/stream.h"

#define TMPDIR_PREFIX "/tmp/dem-stream-"
#include "tmpdir.h"

static void make_header(dem_header_t *h)
{
	dem_header_init(h, "particles", 1, 2);
	assert_int_equal(dem_header_add_col(h, "x", DEM_F64, "m"), 0);
	assert_int_equal(dem_header_add_col(h, "y", DEM_F64, "m"), 0);
	assert_int_equal(dem_header_add_col(h, "id", DEM_U32, "-"), 0);
	assert_int_equal(dem_header_add_col(h, "k", DEM_I64, "-"), 0);
	assert_int_equal(dem_header_add(h, "seed", "%d", 42), 0);
	assert_int_equal(dem_header_add(h, "prog", "%s", "a"), 0);
	assert_int_equal(dem_header_add(h, "prog", "%s", "b"), 0);
}

/* Values that stress the text form: shortest round trip, tiny, huge,
 * negative zero, integers at their limits. */
static const double rows[][4] = {
	{0.1, -2.5e-300, 0, -3},
	{1.0 / 3.0, 1e300, 4294967295.0, 9007199254740992.0},
	{-0.0, 6.02214076e23, 17, -9007199254740992.0},
};

static void write_rows(const char *p, int flags)
{
	dem_header_t h;
	dem_writer_t *w;
	dem_error_t e = {0};
	make_header(&h);
	assert_int_equal(dem_writer_open(&w, p, &h, flags, &e), 0);
	dem_header_free(&h);
	for (int n = 0; n < 3000; n++)          /* spans binary blocks */
		assert_int_equal(dem_writer_row(w, rows[n % 3], &e), 0);
	assert_int_equal(dem_writer_close(w, &e), 0);
}

static void read_rows(const char *p)
{
	dem_reader_t *r;
	dem_error_t e = {0};
	double v[4];
	int got, n = 0;
	assert_int_equal(dem_reader_open(&r, p, &e), 0);
	const dem_header_t *h = dem_reader_header(r);
	assert_string_equal(h->kind, "particles");
	assert_int_equal(h->dim, 2);
	assert_int_equal(h->ncol, 4);
	assert_int_equal(h->col[2].type, DEM_U32);
	assert_string_equal(dem_header_get(h, "seed"), "42");
	assert_string_equal(dem_header_get(h, "prog"), "a");
	while ((got = dem_reader_next(r, v, &e)) == 1) {
		for (int c = 0; c < 4; c++)     /* bit-exact */
			assert_memory_equal(&v[c], &rows[n % 3][c], sizeof v[c]);
		n++;
	}
	assert_int_equal(got, 0);
	assert_int_equal(n, 3000);
	dem_reader_close(r);
}

/* Text, binary, gzip text and gzip binary all give back the same values. */
static void test_round_trip(void **state)
{
	(void)state;
	const int flags[] = {0, DEM_STREAM_BINARY, DEM_STREAM_GZIP,
			     DEM_STREAM_BINARY | DEM_STREAM_GZIP};
	for (int k = 0; k < 4; k++) {
		write_rows(path("rt"), flags[k]);
		read_rows(path("rt"));
	}
}

/* The gzip flag really compresses (gzip magic 1f 8b). */
static void test_gzip_magic(void **state)
{
	(void)state;
	write_rows(path("gz"), DEM_STREAM_GZIP);
	FILE *f = fopen(path("gz"), "rb");
	unsigned char m[2] = {0};
	assert_int_equal(fread(m, 1, 2, f), 2);
	fclose(f);
	assert_int_equal(m[0], 0x1f);
	assert_int_equal(m[1], 0x8b);
}

/* Reads text from a file and expects failure with code and message part. */
static void expect_bad(const char *text, int code, const char *part)
{
	dem_reader_t *r;
	dem_error_t e = {0};
	double v[8];
	int got = 0;
	write_text(path("bad"), text);
	int rc = dem_reader_open(&r, path("bad"), &e);
	if (rc == 0) {
		while ((got = dem_reader_next(r, v, &e)) == 1)
			;
		dem_reader_close(r);
		assert_int_equal(got, -1);
	}
	assert_int_equal(e.code, code);
	if (!strstr(e.msg, part))
		fail_msg("message '%s' lacks '%s'", e.msg, part);
}

#define HDR "# dem particles 1\n# dim 2\n# columns x:f64:m r:f64:m\n# format text\n# data\n"

/* Each malformed input is refused, naming the line. */
static void test_refusals(void **state)
{
	(void)state;
	expect_bad(HDR "1 2\n3 4\n", DEM_EINPUT, "bad:7: truncated stream");
	expect_bad(HDR "1 2\n# end 2\n", DEM_EINPUT, "bad:7: the trailer counts 2 rows but 1");
	expect_bad(HDR "1 nan\n# end 1\n", DEM_EINPUT, "bad:6: column r: nan is not finite");
	expect_bad(HDR "1 2\ninf 2\n# end 2\n", DEM_EINPUT, "bad:7: column x: inf is not finite");
	expect_bad(HDR "1 abc\n# end 1\n", DEM_EINPUT, "bad:6: column r: 'abc' is not a number");
	expect_bad(HDR "1 2x\n# end 1\n", DEM_EINPUT, "bad:6: column r: '2x' is not a number");
	expect_bad(HDR "1\n# end 1\n", DEM_EINPUT, "bad:6: 1 values, expected 2");
	expect_bad(HDR "1 2 3\n# end 1\n", DEM_EINPUT, "bad:6: more than 2 values");
	expect_bad(HDR "1 2\n# end 1\n5 6\n", DEM_EINPUT, "bad:8: data after the trailer");
	expect_bad("# dem widgets 1\n", DEM_EINPUT, "bad:1: unknown stream kind 'widgets'");
	expect_bad("x y r\n1 2 3\n", DEM_EINPUT, "bad:1: not a dem stream");
	expect_bad("", DEM_EINPUT, "empty input");
	expect_bad("# dem pairs 1\n# columns i:u32:-\n# format text\n", DEM_EINPUT,
		   "the header ends without '# data'");
	expect_bad("# dem pairs 1\n# columns i:u16:-\n# format text\n# data\n", DEM_EINPUT,
		   "unknown type 'u16'");
	expect_bad("# dem pairs 1\n# columns i:u32:-\n# format text\n# data\n-1\n# end 1\n",
		   DEM_EINPUT, "bad:5: column i: '-1' is out of range");
	expect_bad("# dem pairs 1\n# format text\n# data\n", DEM_EINPUT, "no '# columns' line");
}

/* Blank lines and CRLF line ends are tolerated. */
static void test_lenient(void **state)
{
	(void)state;
	dem_reader_t *r;
	dem_error_t e = {0};
	double v[2];
	write_text(path("ok"), HDR "1 2\r\n\n  3   4  \n# end 2\n");
	assert_int_equal(dem_reader_open(&r, path("ok"), &e), 0);
	assert_int_equal(dem_reader_next(r, v, &e), 1);
	assert_true(v[0] == 1 && v[1] == 2);
	assert_int_equal(dem_reader_next(r, v, &e), 1);
	assert_true(v[0] == 3 && v[1] == 4);
	assert_int_equal(dem_reader_next(r, v, &e), 0);
	dem_reader_close(r);
}

/* A binary stream cut anywhere is a truncated stream, never a short valid
 * one; the error names the row. */
static void test_binary_truncated(void **state)
{
	(void)state;
	write_rows(path("bin"), DEM_STREAM_BINARY);
	FILE *f = fopen(path("bin"), "rb");
	fseek(f, 0, SEEK_END);
	long size = ftell(f);
	fseek(f, 0, SEEK_SET);
	char *buf = malloc((size_t)size);
	assert_int_equal(fread(buf, 1, (size_t)size, f), (size_t)size);
	fclose(f);
	const long cuts[] = {size - 1, size - 9, size - 200, size / 2, 300};
	for (size_t k = 0; k < sizeof cuts / sizeof *cuts; k++) {
		FILE *g = fopen(path("cut"), "wb");
		fwrite(buf, 1, (size_t)cuts[k], g);
		fclose(g);
		dem_reader_t *r;
		dem_error_t e = {0};
		double v[4];
		int got;
		assert_int_equal(dem_reader_open(&r, path("cut"), &e), 0);
		while ((got = dem_reader_next(r, v, &e)) == 1)
			;
		assert_int_equal(got, -1);
		assert_int_equal(e.code, DEM_EINPUT);
		if (!strstr(e.msg, "truncated"))
			fail_msg("cut at %ld: %s", cuts[k], e.msg);
		dem_reader_close(r);
	}
	free(buf);
}

/* NaN in a binary record is refused with the row number. */
static void test_binary_nan(void **state)
{
	(void)state;
	dem_header_t h;
	dem_writer_t *w;
	dem_error_t e = {0};
	dem_header_init(&h, "particles", 1, 1);
	dem_header_add_col(&h, "x", DEM_F64, "m");
	dem_header_add_col(&h, "r", DEM_F64, "m");
	assert_int_equal(dem_writer_open(&w, path("nan"), &h, DEM_STREAM_BINARY, &e), 0);
	dem_header_free(&h);
	double ok[2] = {1, 2}, nan[2] = {3, NAN};
	dem_writer_row(w, ok, &e);
	dem_writer_row(w, ok, &e);
	dem_writer_row(w, nan, &e);
	assert_int_equal(dem_writer_close(w, &e), 0);
	dem_reader_t *r;
	double v[2];
	assert_int_equal(dem_reader_open(&r, path("nan"), &e), 0);
	assert_int_equal(dem_reader_next(r, v, &e), 1);
	assert_int_equal(dem_reader_next(r, v, &e), 1);
	assert_int_equal(dem_reader_next(r, v, &e), -1);
	assert_non_null(strstr(e.msg, "nan: row 3: column r"));
	dem_reader_close(r);
}

static int count_files(void)
{
	DIR *d = opendir(dir);
	struct dirent *de;
	int n = 0;
	while ((de = readdir(d)))
		n += de->d_name[0] != '.';
	closedir(d);
	return n;
}

/* Output to a file is atomic: nothing at the path until close; abort
 * leaves nothing, not even the temporary file. */
static void test_atomic(void **state)
{
	(void)state;
	dem_header_t h;
	dem_writer_t *w;
	dem_error_t e = {0};
	double row[4] = {1, 2, 3, 4};
	int before = count_files();
	make_header(&h);
	assert_int_equal(dem_writer_open(&w, path("atomic"), &h, 0, &e), 0);
	dem_writer_row(w, row, &e);
	assert_int_equal(access(path("atomic"), F_OK), -1);
	dem_writer_abort(w);
	assert_int_equal(access(path("atomic"), F_OK), -1);
	assert_int_equal(count_files(), before);
	assert_int_equal(dem_writer_open(&w, path("atomic"), &h, 0, &e), 0);
	dem_writer_row(w, row, &e);
	assert_int_equal(dem_writer_close(w, &e), 0);
	assert_int_equal(access(path("atomic"), F_OK), 0);
	assert_int_equal(count_files(), before + 1);
	dem_header_free(&h);
	/* an unwritable folder is an I/O error naming the path */
	assert_int_not_equal(dem_writer_open(&w, "/nonexistent-dir/x", &h, 0, &e), 0);
	assert_int_equal(e.code, DEM_EIO);
	assert_non_null(strstr(e.msg, "/nonexistent-dir/x"));
}

/* A missing input file is bad input naming the path. */
static void test_missing_file(void **state)
{
	(void)state;
	dem_reader_t *r;
	dem_error_t e = {0};
	assert_int_equal(dem_reader_open(&r, path("none"), &e), DEM_EINPUT);
	assert_non_null(strstr(e.msg, "No such file"));
}

/* A header line of any length, and provenance args that contain newlines,
 * stay one line each. */
static void test_long_lines(void **state)
{
	(void)state;
	dem_header_t h;
	dem_writer_t *w;
	dem_error_t e = {0};
	char *big = malloc(20000);
	memset(big, 'a', 19999);
	big[19999] = '\0';
	char *argv[] = {"prog", "one\ntwo", big, NULL};
	make_header(&h);
	assert_int_equal(dem_header_add_provenance(&h, "prog", 3, argv, 1, 7), 0);
	assert_int_equal(dem_writer_open(&w, path("long"), &h, 0, &e), 0);
	dem_header_free(&h);
	assert_int_equal(dem_writer_close(w, &e), 0);
	dem_reader_t *r;
	assert_int_equal(dem_reader_open(&r, path("long"), &e), 0);
	const dem_header_t *g = dem_reader_header(r);
	const char *prov = NULL;
	for (size_t i = 0; i < g->nline; i++)
		if (strcmp(g->line[i].key, "prog") == 0)
			prov = g->line[i].val;  /* the last prog line */
	assert_non_null(prov);
	/* quoted for the shell, newline folded */
	assert_non_null(strstr(prov, "seed=7 args: 'one two' aaaa"));
	assert_int_equal(strlen(prov), strlen("prog " DEM_VERSION " seed=7 args: 'one two' ") + 19999);
	dem_reader_close(r);
	free(big);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_round_trip),
		cmocka_unit_test(test_gzip_magic),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_lenient),
		cmocka_unit_test(test_binary_truncated),
		cmocka_unit_test(test_binary_nan),
		cmocka_unit_test(test_atomic),
		cmocka_unit_test(test_missing_file),
		cmocka_unit_test(test_long_lines),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
