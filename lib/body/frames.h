/* frames.h - the body stream and the bodies as VTK polygons.
 *
 * The body stream (kind "bodies", dem-streams(5)): one row per body per
 * frame, the shape's parameters with the pose and velocities, so that a
 * reader can redraw every body without the scene:
 *
 *     # dem bodies 1
 *     # dim 2
 *     # columns frame:u32:- t:f64:s id:u32:- shape:u32:- a:f64:m b:f64:m m:f64:-
 *               x:f64:m y:f64:m theta:f64:rad vx:f64:m/s vy:f64:m/s w:f64:rad/s
 *     # shapes superquadric polygon disk        the names of the shape codes 0, 1, 2
 *     # wall AX AY BX BY THICKNESS              one line per wall (m)
 *     # data
 *     ...
 *     # end ROWS
 *
 * shape 0: superquadric |x/a|^m + |y/b|^m = 1; 1: the regular polygon of
 * m sides with circumradius a, a side flat at the bottom at theta = 0,
 * stretched along y to b (its points (a cos p, b sin p); b = a: regular); 2: the disk of radius a (b = a, m = 0).  (x, y) is the
 * centroid, theta the rotation about it (anticlockwise).  Frames are
 * numbered from 0 (the start); rows of a frame are in body order.
 */
#ifndef DEM_BODY_FRAMES_H
#define DEM_BODY_FRAMES_H

#include "body/body.h"
#include "io/stream.h"

/* One row of a body stream, in SI units. */
typedef struct dem_body_row {
	unsigned frame, id;
	int shape;
	double t, a, b, m, x, y, th, vx, vy, w;
} dem_body_row_t;

/* Open the stream at path (NULL or "-": standard output) for the bodies
 * and walls of de, with this program's provenance; flags as
 * dem_writer_open. */
int dem_bodies_writer_open(dem_writer_t **w, const char *path, const dem_de_t *de,
                           const char *prog, int argc, char **argv, int has_seed,
                           unsigned long seed, int flags, dem_error_t *e);
/* The header of a body stream with nw walls, each A x, A y, B x, B y,
 * thickness (m): kind, columns, shape names, walls; the caller adds its
 * provenance and lines.  Nonzero without memory. */
int dem_bodies_header(dem_header_t *h, size_t nw, const double (*wall)[5]);

/* Write one row (all its fields). */
int dem_bodies_write_row(dem_writer_t *w, const dem_body_row_t *row, dem_error_t *e);

/* Write the bodies' rows of frame number frame at de->t. */
int dem_bodies_write_frame(dem_writer_t *w, const dem_de_t *de, unsigned frame,
                           dem_error_t *e);


/* Open a body stream (NULL or "-": standard input): DEM_EINPUT for
 * another kind or missing columns. */
int dem_bodies_reader_open(dem_reader_t **r, const char *path, dem_error_t *e);
/* The next row: 1, 0 at the end of the stream, -1 on error. */
int dem_bodies_reader_next(dem_reader_t *r, dem_body_row_t *row, dem_error_t *e);

/* The bodies now and the walls as a VTK XML UnstructuredGrid of polygons
 * (VTK_POLYGON; a disk drawn with 64 points), cell data "id" and "speed";
 * ASCII, written under a temporary name and renamed. */
int dem_bodies_vtu(const char *path, const dem_de_t *de, dem_error_t *e);

#endif
