/* tmpdir.h - a folder of temporary files for a test program: cmocka's
 * group setup and teardown make and remove it, path() names a file in it,
 * write_text() writes one.  Include after cmocka.h, with TMPDIR_PREFIX
 * defined ("/tmp/dem-NAME-"). */
#ifndef DEM_TEST_TMPDIR_H
#define DEM_TEST_TMPDIR_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char dir[64];

static int setup(void **state)
{
	(void)state;
	strcpy(dir, TMPDIR_PREFIX "XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
	char cmd[128];
	(void)state;
	snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
	return system(cmd);
}

/* dir/name, in one of four buffers used in turn */
static const char *path(const char *name)
{
	static char buf[4][128];
	static int k;
	k = (k + 1) % 4;
	snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
	return buf[k];
}

static void write_text(const char *p, const char *text)
{
	FILE *f = fopen(p, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

#endif
