/* error.h - error reports and the toolkit's exit codes.
 *
 * Library functions never print and never exit: they fill a dem_error_t and
 * return its code.  A program prints "prog: message" once and exits with the
 * code (DESIGN.md, "Errors").
 */
#ifndef DEM_CORE_ERROR_H
#define DEM_CORE_ERROR_H

#include <stdarg.h>

enum {
	DEM_OK = 0,
	DEM_EINPUT = 1,   /* bad input: scene or stream */
	DEM_EUSAGE = 2,   /* bad command line */
	DEM_ENUMERIC = 3, /* numerical failure: divergence, inverted element */
	DEM_EIO = 4       /* I/O or resource failure (including out of memory) */
};

typedef struct dem_error {
	int code;       /* one of the DEM_E* codes, DEM_OK when clear */
	char msg[768];  /* "where: what", without the program name */
} dem_error_t;

/* Record an error; returns code so callers can write `return dem_error_set(...)`.
 * A second error does not overwrite the first: the first cause is the one
 * worth reporting. */
int dem_error_set(dem_error_t *e, int code, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
int dem_error_vset(dem_error_t *e, int code, const char *fmt, va_list ap);

/* Record an out-of-memory error (DEM_EIO) naming what was being allocated. */
int dem_error_nomem(dem_error_t *e, const char *what);

void dem_error_clear(dem_error_t *e);

#endif
