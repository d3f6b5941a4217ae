/* afile.c - files written atomically (see afile.h). */
#define _GNU_SOURCE     /* O_TMPFILE (Linux); without it, named temporaries */
#include "core/afile.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ---- temporary files removed on a fatal signal -------------------------- */

#define GUARD_MAX 32
static const char *volatile guarded[GUARD_MAX];
static volatile sig_atomic_t handlers_set;
static const int guard_sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGPIPE };

static void on_fatal_signal(int sig)
{
	for (int i = 0; i < GUARD_MAX; i++)
		if (guarded[i])
			unlink(guarded[i]);   /* async-signal-safe */
	signal(sig, SIG_DFL);
	raise(sig);
}

static void set_handlers(void)
{
	for (size_t k = 0; k < sizeof guard_sigs / sizeof *guard_sigs; k++) {
		struct sigaction old, sa;
		/* leave alone a signal the caller ignores or handles */
		if (sigaction(guard_sigs[k], NULL, &old) != 0 || old.sa_handler != SIG_DFL)
			continue;
		memset(&sa, 0, sizeof sa);
		sa.sa_handler = on_fatal_signal;
		sigemptyset(&sa.sa_mask);
		sigaction(guard_sigs[k], &sa, NULL);
	}
	handlers_set = 1;
}

void dem_tmp_guard(const char *tmp)
{
	if (!tmp)
		return;
	if (!handlers_set)
		set_handlers();
	for (int i = 0; i < GUARD_MAX; i++)
		if (!guarded[i]) {
			guarded[i] = tmp;
			return;
		}
}

void dem_tmp_forget(const char *tmp)
{
	for (int i = 0; tmp && i < GUARD_MAX; i++)
		if (guarded[i] == tmp)
			guarded[i] = NULL;
}

/* ---- atomic files ----------------------------------------------------- */

/* An unnamed file in the folder of path (O_TMPFILE), or -1 where the
 * system or the file system has none, or where /proc (through which the
 * commit names it) is missing. */
static int open_unnamed(const char *path)
{
#ifdef O_TMPFILE
	const char *slash = strrchr(path, '/');
	char *dir;
	int fd;

	if (access("/proc/self/fd", X_OK) != 0)
		return -1;
	if (!slash)
		dir = strdup(".");
	else if (slash == path)
		dir = strdup("/");
	else
		dir = strndup(path, (size_t)(slash - path));
	if (!dir)
		return -1;
	fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
	free(dir);
	return fd;
#else
	(void)path;
	return -1;
#endif
}

/* Give the unnamed file a->keep the name a->tmp (path.tmp. and six
 * letters not in use), 0 or -1 with errno. */
static int name_unnamed(dem_afile_t *a)
{
	static const char abc[] =
		"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
	static unsigned long calls;
	char proc[64];
	size_t n = strlen(a->tmp);
	struct timespec ts;

	snprintf(proc, sizeof proc, "/proc/self/fd/%d", a->keep);
	clock_gettime(CLOCK_REALTIME, &ts);
	unsigned long long x = (unsigned long long)ts.tv_nsec ^
		((unsigned long long)getpid() << 32) ^ (++calls * 0x9e3779b97f4a7c15ULL);
	for (int attempt = 0; attempt < 100; attempt++) {
		for (size_t i = n - 6; i < n; i++) {
			x = x * 6364136223846793005ULL + 1442695040888963407ULL;
			a->tmp[i] = abc[(x >> 33) % (sizeof abc - 1)];
		}
		if (linkat(AT_FDCWD, proc, AT_FDCWD, a->tmp, AT_SYMLINK_FOLLOW) == 0)
			return 0;
		if (errno != EEXIST)
			return -1;
	}
	return -1;
}

int dem_afile_open(dem_afile_t *a, const char *path, const char *mode,
		   dem_error_t *e)
{
	size_t n = strlen(path) + sizeof ".tmp.XXXXXX";
	struct stat st;
	int fd;

	memset(a, 0, sizeof *a);
	if (!(a->path = strdup(path))) {
		dem_afile_abort(a);
		return dem_error_nomem(e, path);
	}
	if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
		/* a device, a FIFO, a directory: written in place or refused
		 * by open (EISDIR), never renamed over */
		fd = open(path, O_WRONLY | O_CLOEXEC);
		if (fd < 0 || (mode && !(a->f = fdopen(fd, mode)))) {
			int err = errno;

			if (fd >= 0)
				close(fd);
			dem_afile_abort(a);
			return dem_error_set(e, DEM_EIO, "%s: %s", path,
					     strerror(err));
		}
		a->fd = fd;
		return DEM_OK;
	}
	if (!(a->tmp = malloc(n))) {
		dem_afile_abort(a);
		return dem_error_nomem(e, path);
	}
	snprintf(a->tmp, n, "%s.tmp.XXXXXX", path);
	if ((a->keep = open_unnamed(path)) >= 0) {
		/* the caller's descriptor (or FILE) is a second one, so that
		 * closing it leaves the file to name */
		a->anon = 1;
		fd = fcntl(a->keep, F_DUPFD_CLOEXEC, 0);
	} else
		fd = mkstemp(a->tmp);
	if (fd < 0 || (mode && !(a->f = fdopen(fd, mode)))) {
		int err = errno;

		if (fd >= 0) {
			close(fd);
			if (!a->anon)
				unlink(a->tmp);
		}
		free(a->tmp);
		a->tmp = NULL;
		dem_afile_abort(a);
		return dem_error_set(e, DEM_EIO, "%s: %s", path, strerror(err));
	}
	fchmod(fd, 0644);       /* whatever the umask, as mkstemp's 0600 is not */
	a->fd = fd;
	if (!a->anon)
		dem_tmp_guard(a->tmp);
	return DEM_OK;
}

int dem_afile_commit(dem_afile_t *a, int sync, dem_error_t *e)
{
	int bad = 0;

	errno = 0;
	if (a->f) {     /* else the caller has closed its descriptor */
		bad = ferror(a->f) || fflush(a->f) != 0 ||
		      (sync && a->tmp && fsync(fileno(a->f)) != 0);
		bad |= fclose(a->f) != 0;
		a->f = NULL;
	}
	if (!bad && a->anon) {
		/* name it, guarded from the link to the rename */
		dem_tmp_guard(a->tmp);
		bad = name_unnamed(a) != 0;
		if (bad)
			dem_tmp_forget(a->tmp);
		else {
			close(a->keep);
			a->anon = 0;    /* a named temporary from here on */
		}
	}
	if (!bad && (!a->tmp || rename(a->tmp, a->path) == 0))
		dem_tmp_forget(a->tmp);
	else {
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
	if (a->anon)
		close(a->keep);         /* unnamed: gone with its last descriptor */
	else if (a->tmp) {
		unlink(a->tmp);
		dem_tmp_forget(a->tmp);
	}
	free(a->path);
	free(a->tmp);
	memset(a, 0, sizeof *a);
}
