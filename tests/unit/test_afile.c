/* test_afile.c - lib/core/afile: the file appears only on commit, whole;
 * abort and failures leave nothing; a path that is not a regular file is
 * written in place, never renamed over. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
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

/* The entries in dir, . and .. aside. */
static int entries(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *de;
	int n = 0;

	assert_non_null(d);
	while ((de = readdir(d)))
		n += strcmp(de->d_name, ".") != 0 && strcmp(de->d_name, "..") != 0;
	closedir(d);
	return n;
}

/* Where the file is unnamed until the commit (O_TMPFILE), a process
 * killed by SIGKILL while writing, which no handler can catch, leaves
 * nothing in the folder: neither the file nor a temporary. */
static void test_afile_killed(void **state)
{
	char dir[] = "/tmp/dem-test-afile-XXXXXX", path[64];
	dem_afile_t a;
	dem_error_t e = {0};
	int anon, st;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof path, "%s/out", dir);
	assert_int_equal(dem_afile_open(&a, path, "w", &e), DEM_OK);
	anon = a.anon;
	fputs("hello", a.f);
	fflush(a.f);
	assert_int_equal(entries(dir), anon ? 0 : 1);   /* unnamed, or path.tmp.XXXXXX */
	assert_int_equal(dem_afile_commit(&a, 0, &e), DEM_OK);
	assert_int_equal(entries(dir), 1);              /* path alone */
	assert_holds(path, "hello");
	unlink(path);
	if (!anon) {
		assert_int_equal(rmdir(dir), 0);
		skip();                 /* no O_TMPFILE here: named temporaries */
	}
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		if (dem_afile_open(&a, path, "w", &e) != DEM_OK)
			_exit(1);
		fputs("half", a.f);
		fflush(a.f);
		raise(SIGKILL);
		_exit(2);
	}
	assert_int_equal(waitpid(pid, &st, 0), pid);
	assert_true(WIFSIGNALED(st) && WTERMSIG(st) == SIGKILL);
	assert_int_equal(entries(dir), 0);
	assert_int_equal(rmdir(dir), 0);
}

/* A FIFO (as a device such as /dev/null) is written in place: the reader
 * gets the bytes and the FIFO is still a FIFO, with no temporary beside
 * it.  Renaming a temporary over it (as for a regular file) would leave a
 * regular file in its place: as root, `-o /dev/null` replaced the device.
 * A directory is refused, naming it. */
static void test_afile_not_regular(void **state)
{
	char dir[] = "/tmp/dem-test-afile-XXXXXX", path[64], buf[16] = {0};
	dem_afile_t a;
	dem_error_t e = {0};
	struct stat st;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof path, "%s/fifo", dir);
	assert_int_equal(mkfifo(path, 0600), 0);
	int rd = open(path, O_RDONLY | O_NONBLOCK);     /* a reader, so the writer does not block */
	assert_true(rd >= 0);
	assert_int_equal(dem_afile_open(&a, path, "w", &e), DEM_OK);
	fputs("hello", a.f);
	assert_int_equal(dem_afile_commit(&a, 1, &e), DEM_OK);  /* sync: no fsync on a FIFO */
	assert_int_equal(read(rd, buf, sizeof buf - 1), 5);
	assert_string_equal(buf, "hello");
	close(rd);
	assert_int_equal(lstat(path, &st), 0);
	assert_true(S_ISFIFO(st.st_mode));
	/* abort of a FIFO write removes nothing */
	rd = open(path, O_RDONLY | O_NONBLOCK);
	assert_int_equal(dem_afile_open(&a, path, NULL, &e), DEM_OK);
	assert_int_equal(close(a.fd), 0);
	dem_afile_abort(&a);
	close(rd);
	assert_int_equal(lstat(path, &st), 0);
	assert_true(S_ISFIFO(st.st_mode));
	unlink(path);
	/* a directory: refused */
	assert_int_equal(dem_afile_open(&a, dir, "w", &e), DEM_EIO);
	assert_non_null(strstr(e.msg, dir));
	dem_afile_abort(&a);
	assert_int_equal(rmdir(dir), 0);                /* empty: no temporary left */
	/* /dev/null itself, where it is a character device */
	if (stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode)) {
		assert_int_equal(dem_afile_open(&a, "/dev/null", "w", &e), DEM_OK);
		fputs("hello", a.f);
		assert_int_equal(dem_afile_commit(&a, 1, &e), DEM_OK);
		assert_int_equal(stat("/dev/null", &st), 0);
		assert_true(S_ISCHR(st.st_mode));
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_afile),
		cmocka_unit_test(test_afile_fd),
		cmocka_unit_test(test_afile_not_regular),
		cmocka_unit_test(test_afile_killed),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
