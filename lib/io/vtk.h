/* vtk.h - packings as legacy VTK PolyData for ParaView.
 *
 * The file holds the centres as POINTS, one VERTICES cell per point (so
 * the points show without a filter) and a point-data scalar "radius";
 * ParaView's Glyph filter, scaled by "radius" with a scale factor of 2
 * (the glyphs are of unit diameter), draws the disks or spheres.  ASCII,
 * every value to 17 significant digits, so a reader gets the doubles back.
 *
 * The number of points is given at open (the legacy format states it
 * before the data); the points are written as they come, the radii are
 * held (8 bytes a point) until close.  The file is written under a
 * temporary name and renamed at close, so a failed run leaves no partial
 * file (as the stream writer does).
 */
#ifndef DEM_IO_VTK_H
#define DEM_IO_VTK_H

#include <stddef.h>

#include "core/error.h"

typedef struct dem_vtk dem_vtk_t;

/* Open path for n points of dimension dim (2: z written as 0, or 3);
 * title is the file's one-line title (newlines are replaced). */
int dem_vtk_open(dem_vtk_t **w, const char *path, int dim, size_t n,
		 const char *title, dem_error_t *e);
/* Write one point: centre x[dim], radius r. */
int dem_vtk_point(dem_vtk_t *w, const double *x, double r, dem_error_t *e);
/* Write the cells and radii, check that n points came, rename into place
 * and free w (also on failure). */
int dem_vtk_close(dem_vtk_t *w, dem_error_t *e);
/* Remove the temporary file and free w; NULL is fine. */
void dem_vtk_abort(dem_vtk_t *w);

#endif
