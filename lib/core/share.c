/* share.c - the toolkit's data directory: which one, and files in it. */
#include "core/share.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef DEM_DATADIR
#define DEM_DATADIR "/usr/local/share/dem"
#endif

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

static int is_dir(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static int is_file(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* The running program's directory, or "" where /proc/self/exe is not
 * there to say (the search then goes on to the compiled-in directory). */
static void exe_dir(char *buf, size_t len)
{
	ssize_t n = readlink("/proc/self/exe", buf, len - 1);
	char *slash;

	if (n <= 0 || (size_t)n >= len - 1) {
		buf[0] = '\0';
		return;
	}
	buf[n] = '\0';
	slash = strrchr(buf, '/');
	if (!slash)
		buf[0] = '\0';
	else
		*(slash == buf ? slash + 1 : slash) = '\0';
}

/* Walk up from dir to the first ancestor that is the toolkit's source
 * tree (share/folder beside lib/core/share.h: an installed program's
 * ancestors, e.g. /usr for /usr/bin, are not taken for one because some
 * other package has a share/materials); write its share/ into out.
 * Returns 1 if found. */
static int share_above(const char *dir, const char *folder, char *out,
		       size_t len)
{
	char d[PATH_MAX], probe[PATH_MAX + 64], mark[PATH_MAX + 32];
	char *slash;

	if (!dir[0] || strlen(dir) >= sizeof d)
		return 0;
	strcpy(d, dir);
	for (;;) {
		const char *top = strcmp(d, "/") ? d : "";
		int n = snprintf(probe, sizeof probe, "%s/share/%s", top,
				 folder);
		int m = snprintf(mark, sizeof mark, "%s/lib/core/share.h",
				 top);

		if (n > 0 && (size_t)n < sizeof probe && m > 0 &&
		    (size_t)m < sizeof mark && is_dir(probe) &&
		    is_file(mark)) {
			size_t dl = strcmp(d, "/") ? strlen(d) : 0;

			if (dl + sizeof "/share" > len)
				return 0;
			memcpy(out, d, dl);
			memcpy(out + dl, "/share", sizeof "/share");
			return 1;
		}
		if (strcmp(d, "/") == 0)
			return 0;
		slash = strrchr(d, '/');
		if (!slash)
			return 0;
		*(slash == d ? slash + 1 : slash) = '\0';
	}
}

int dem_share_find(const char *folder, const char *file, char **path,
		   char *tried, size_t triedlen)
{
	char dir[PATH_MAX], exe[PATH_MAX], how[PATH_MAX + 128];
	const char *env = getenv("DEM_DATA");
	size_t n;
	char *p;

	*path = NULL;
	if (env && *env) {
		snprintf(dir, sizeof dir, "%s", env);
		snprintf(how, sizeof how, "from DEM_DATA");
	} else {
		exe_dir(exe, sizeof exe);
		if (share_above(exe, folder, dir, sizeof dir)) {
			snprintf(how, sizeof how, "the source tree's share/ "
				 "above the program, %s", exe);
		} else {
			snprintf(dir, sizeof dir, "%s", DEM_DATADIR);
			snprintf(how, sizeof how, "the compiled-in data "
				 "directory; DEM_DATA is not set and %s is not "
				 "in a source tree", exe[0] ? exe : "the program");
		}
	}
	/* "dir/" and "dir" name the same folder: write one slash */
	n = strlen(dir);
	while (n > 0 && dir[n - 1] == '/')
		dir[--n] = '\0';
	p = malloc(n + strlen(folder) + strlen(file) + 3);
	if (!p)
		return -1;
	sprintf(p, "%s/%s/%s", dir, folder, file);
	if (is_file(p)) {
		*path = p;
		return 0;
	}
	free(p);
	if (triedlen > 0)
		snprintf(tried, triedlen, "%s/%s (%s)", dir, folder, how);
	return 1;
}
