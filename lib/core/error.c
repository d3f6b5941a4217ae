#include "core/error.h"

#include <stdio.h>
#include <string.h>

int dem_error_vset(dem_error_t *e, int code, const char *fmt, va_list ap)
{
	if (!e)
		return code;
	if (e->code != DEM_OK)
		return e->code;
	e->code = code;
	vsnprintf(e->msg, sizeof e->msg, fmt, ap);
	return code;
}

int dem_error_set(dem_error_t *e, int code, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	code = dem_error_vset(e, code, fmt, ap);
	va_end(ap);
	return code;
}

int dem_error_nomem(dem_error_t *e, const char *what)
{
	return dem_error_set(e, DEM_EIO, "out of memory (%s)", what);
}

void dem_error_clear(dem_error_t *e)
{
	e->code = DEM_OK;
	e->msg[0] = '\0';
}
