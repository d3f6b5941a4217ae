/* afile.c - files written atomically (see afile.h). */
#include "core/afile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int dem_afile_open(dem_afile_t *a, const char *path, const char *mode,
		   dem_error_t *e)
{
	size_t n = strlen(path) + sizeof ".tmp.XXXXXX";
	int fd;

	memset(a, 0, sizeof *a);
	if (!(a->path = strdup(path)) || !(a->tmp = malloc(n))) {
		dem_afile_abort(a);
		return dem_error_nomem(e, path);
	}
	snprintf(a->tmp, n, "%s.tmp.XXXXXX", path);
	fd = mkstemp(a->tmp);
	if (fd < 0 || !(a->f = fdopen(fd, mode))) {
		int err = errno;

		if (fd >= 0) {
			close(fd);
			unlink(a->tmp);
		}
		free(a->tmp);
		a->tmp = NULL;
		dem_afile_abort(a);
		return dem_error_set(e, DEM_EIO, "%s: %s", path, strerror(err));
	}
	fchmod(fd, 0644);
	return DEM_OK;
}

int dem_afile_commit(dem_afile_t *a, int sync, dem_error_t *e)
{
	int bad;

	errno = 0;
	bad = ferror(a->f) || fflush(a->f) != 0 ||
	      (sync && fsync(fileno(a->f)) != 0);
	bad |= fclose(a->f) != 0;
	a->f = NULL;
	if (bad || rename(a->tmp, a->path) != 0) {
		dem_error_set(e, DEM_EIO, "%s: %s", a->path,
			      strerror(errno ? errno : EIO));
		dem_afile_abort(a);
		return DEM_EIO;
	}
	free(a->path);
	free(a->tmp);
	memset(a, 0, sizeof *a);
	return DEM_OK;
}

void dem_afile_abort(dem_afile_t *a)
{
	if (a->f)
		fclose(a->f);
	if (a->tmp)
		unlink(a->tmp);
	free(a->path);
	free(a->tmp);
	memset(a, 0, sizeof *a);
}
