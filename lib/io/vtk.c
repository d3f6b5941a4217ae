/* vtk.c - legacy VTK PolyData writer for packings (see vtk.h). */
#include "io/vtk.h"

#include "core/afile.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct dem_vtk {
	dem_afile_t af;         /* written to af.f, renamed into place at close */
	int dim;
	size_t n, got;
	double *r;
};

void dem_vtk_abort(dem_vtk_t *w)
{
	if (!w)
		return;
	dem_afile_abort(&w->af);
	free(w->r);
	free(w);
}

static int fail_io(dem_vtk_t *w, dem_error_t *e)
{
	int err = errno ? errno : EIO;
	dem_error_set(e, DEM_EIO, "%s: %s", w->af.path, strerror(err));
	dem_vtk_abort(w);
	return DEM_EIO;
}

int dem_vtk_open(dem_vtk_t **wp, const char *path, int dim, size_t n,
		 const char *title, dem_error_t *e)
{
	dem_vtk_t *w = calloc(1, sizeof *w);
	char line[256];

	*wp = NULL;
	if (!w)
		return dem_error_nomem(e, "vtk writer");
	if (dim != 2 && dim != 3) {
		free(w);
		return dem_error_set(e, DEM_EINPUT, "vtk: dimension %d (2 or 3)", dim);
	}
	w->dim = dim;
	w->n = n;
	if (!(w->r = malloc((n ? n : 1) * sizeof *w->r))) {
		dem_vtk_abort(w);
		return dem_error_nomem(e, "vtk writer");
	}
	int rc = dem_afile_open(&w->af, path, "w", e);
	if (rc) {
		dem_vtk_abort(w);
		return rc;
	}
	/* the title is one line of at most 255 characters */
	snprintf(line, sizeof line, "%s", title ? title : "dem packing");
	for (char *p = line; *p; p++)
		if (*p == '\n' || *p == '\r')
			*p = ' ';
	errno = 0;
	if (fprintf(w->af.f, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET POLYDATA\n"
		    "POINTS %zu double\n", line, n) < 0)
		return fail_io(w, e);
	*wp = w;
	return DEM_OK;
}

int dem_vtk_point(dem_vtk_t *w, const double *x, double r, dem_error_t *e)
{
	if (w->got == w->n) {
		dem_error_set(e, DEM_EIO, "%s: more than the %zu points announced", w->af.path, w->n);
		dem_vtk_abort(w);
		return DEM_EIO;
	}
	errno = 0;
	if (fprintf(w->af.f, "%.17g %.17g %.17g\n", x[0], x[1], w->dim == 3 ? x[2] : 0.0) < 0)
		return fail_io(w, e);
	w->r[w->got++] = r;
	return DEM_OK;
}

int dem_vtk_close(dem_vtk_t *w, dem_error_t *e)
{
	if (w->got != w->n) {
		dem_error_set(e, DEM_EIO, "%s: %zu points written, %zu announced", w->af.path, w->got, w->n);
		dem_vtk_abort(w);
		return DEM_EIO;
	}
	errno = 0;
	if (fprintf(w->af.f, "VERTICES %zu %zu\n", w->n, 2 * w->n) < 0)
		return fail_io(w, e);
	for (size_t i = 0; i < w->n; i++)
		if (fprintf(w->af.f, "1 %zu\n", i) < 0)
			return fail_io(w, e);
	if (fprintf(w->af.f, "POINT_DATA %zu\nSCALARS radius double 1\nLOOKUP_TABLE default\n", w->n) < 0)
		return fail_io(w, e);
	for (size_t i = 0; i < w->n; i++)
		if (fprintf(w->af.f, "%.17g\n", w->r[i]) < 0)
			return fail_io(w, e);
	int rc = dem_afile_commit(&w->af, 0, e);
	dem_vtk_abort(w);       /* frees; nothing left to remove */
	return rc;
}
