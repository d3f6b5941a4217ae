/* test_afile.c - lib/core/afile: the file appears only on commit, whole;
 * abort and failures leave nothing. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/afile.h"

/* The file at path holds text. */
static void assert_holds(const char *path, const char *text)
{
	char buf[16] = {0};
	FILE *f = fopen(path, "r");

	assert_non_null(f);
	assert_non_null(fgets(buf, sizeof buf, f));
	fclose(f);
	assert_string_equal(buf, text);
}

static void test_afile(void **state)
{
	char dir[] = "/tmp/dem-test-afile-XXXXXX", path[64];
	dem_afile_t a;
	dem_error_t e = {0};

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof path, "%s/out", dir);
	assert_int_equal(dem_afile_open(&a, path, "w", &e), DEM_OK);
	fputs("hello", a.f);
	assert_int_equal(access(path, F_OK), -1);       /* not there yet */
	assert_int_equal(dem_afile_commit(&a, 1, &e), DEM_OK);
	assert_holds(path, "hello");
	/* abort leaves the old file and no temporary */
	assert_int_equal(dem_afile_open(&a, path, "w", &e), DEM_OK);
	fputs("other", a.f);
	dem_afile_abort(&a);
	assert_holds(path, "hello");
	unlink(path);
	assert_int_equal(rmdir(dir), 0);                /* empty: no temporary left */
	/* a missing folder is an I/O error naming the path */
	assert_int_equal(dem_afile_open(&a, "/nonexistent-dir/x", "w", &e), DEM_EIO);
	assert_non_null(strstr(e.msg, "/nonexistent-dir/x"));
	dem_afile_abort(&a);
}

/* Without a mode the caller writes through the descriptor and closes it
 * (as the stream writer does through zlib); commit only renames. */
static void test_afile_fd(void **state)
{
	char dir[] = "/tmp/dem-test-afile-XXXXXX", path[64];
	dem_afile_t a;
	dem_error_t e = {0};

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof path, "%s/out", dir);
	assert_int_equal(dem_afile_open(&a, path, NULL, &e), DEM_OK);
	assert_null(a.f);
	assert_int_equal(write(a.fd, "hello", 5), 5);
	assert_int_equal(close(a.fd), 0);
	assert_int_equal(access(path, F_OK), -1);       /* not there yet */
	assert_int_equal(dem_afile_commit(&a, 0, &e), DEM_OK);
	assert_holds(path, "hello");
	/* abort removes the temporary, the descriptor stays the caller's */
	assert_int_equal(dem_afile_open(&a, path, NULL, &e), DEM_OK);
	int fd = a.fd;
	assert_int_equal(write(fd, "other", 5), 5);
	dem_afile_abort(&a);
	assert_int_equal(close(fd), 0);
	assert_holds(path, "hello");
	unlink(path);
	assert_int_equal(rmdir(dir), 0);                /* empty: no temporary left */
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_afile),
		cmocka_unit_test(test_afile_fd),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
