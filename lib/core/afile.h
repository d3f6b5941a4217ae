/* afile.h - a file written atomically: created beside its final path and
 * renamed into place only when complete, so a reader never sees a
 * half-written file and a failure leaves no file behind (DESIGN.md,
 * "Errors").  Where the system offers it (Linux's O_TMPFILE, with /proc),
 * the file has no name at all until the commit links it as
 * path.tmp.XXXXXX and renames that over path: a process killed by any
 * signal, SIGKILL too, leaves nothing behind.  Elsewhere it is created as
 * path.tmp.XXXXXX (mode 0644) from the start, removed on failure and on
 * the signals dem_tmp_guard catches.  A path that exists and is not a
 * regular file (/dev/null, a terminal, a FIFO) is written in place:
 * renaming over it would replace the device with a file. */
#ifndef DEM_CORE_AFILE_H
#define DEM_CORE_AFILE_H

#include <stdio.h>

#include "core/error.h"

typedef struct dem_afile {
	FILE *f;                /* write here (NULL when opened without a mode) */
	int fd;                 /* the temporary file's descriptor */
	char *path, *tmp;       /* tmp NULL: path itself is written (not a
				 * regular file), nothing to rename */
	int anon, keep;         /* anon: the file is unnamed (O_TMPFILE) and
				 * keep its own descriptor, open until the
				 * commit names it tmp */
} dem_afile_t;

/* Create the temporary file; mode as for fdopen ("w" or "wb").  DEM_EIO
 * naming path when it cannot be created.  With mode NULL no FILE is made:
 * the caller writes through fd by other means (zlib's gzdopen, say) and
 * closes it itself, a write error being its own to report, before
 * dem_afile_commit, which then only renames. */
int dem_afile_open(dem_afile_t *a, const char *path, const char *mode,
		   dem_error_t *e);
/* Close and rename into place (sync: fsync first, for checkpoints; only
 * with a FILE); on any failure the temporary file is removed and DEM_EIO
 * names path. */
int dem_afile_commit(dem_afile_t *a, int sync, dem_error_t *e);
/* Give up: close (the FILE, if any) and remove the temporary file.  A
 * zeroed or already finished a is fine. */
void dem_afile_abort(dem_afile_t *a);

/* Temporary files in progress, removed if a signal (SIGINT, SIGTERM,
 * SIGHUP, SIGPIPE) ends the process before they are renamed or removed:
 * the handler unlinks them and dies of the signal as before.  Every
 * writer of the library that makes a temporary file registers it (the
 * string must live until dem_tmp_forget) and forgets it before freeing
 * it.  At most 32 at once; beyond, a file is not guarded (no error). */
void dem_tmp_guard(const char *tmp);
void dem_tmp_forget(const char *tmp);

#endif
