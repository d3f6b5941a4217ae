/* state.h - the state stream: a hexahedral mesh and its fields, frame by
 * frame (demshot writes it, demprofile reads it; dem-streams(5)).
 *
 * It is a stream of the toolkit's family (stream.h): kind "state",
 * version 1, one set of columns shared by every row,
 *
 *   rec:u32 id:u32 v0 ... v12:f64
 *
 * where rec says what the row holds and id which item (the slots v0..v12
 * are used as the record needs, the rest are 0):
 *
 *   rec 1 node   id = first node n;  v0..v11 = x y z of nodes n..n+3  (m)
 *   rec 2 hex    id = element;       v0..v7  = its 8 node numbers (hex8.h order)
 *   rec 3 frame  id = pass;          v0 = time (s), v1 = nodes, v2 = elements
 *   rec 4 disp   id = first node n;  v0..v11 = ux uy uz of nodes n..n+3  (m)
 *   rec 5 elem   id = element;       v0..v5 stress sxx syy szz sxy syz szx (Pa),
 *                                    v6..v11 total strain exx .. ezx
 *                                    (engineering shears), v12 effective
 *                                    plastic strain
 *
 * The header declares these layouts in "# record" lines (names and units of
 * the slots), the mesh size in "# nodes", "# elements" and, for a
 * structured box mesh (mesh.h), "# grid NX NY NZ".  The rows are the mesh
 * (every node row, then every hex row, in order), then the frames, each a
 * frame row followed by all its disp rows and all its elem rows, in order.
 * Four nodes share a row so a frame costs about 104 bytes an element plus
 * 28 a node in binary.  Binary rows copy the doubles, so a stream reads
 * back bit for bit (text rows too: 17 significant digits where needed).
 *
 * Writer and reader hold one frame at most: memory is bounded by the mesh
 * and one frame, whatever the number of frames.
 */
#ifndef DEM_IO_STATE_H
#define DEM_IO_STATE_H

#include <stddef.h>

#include "core/error.h"
#include "io/stream.h"
#include "mesh/mesh.h"

/* Record codes (column rec). */
enum { DEM_STATE_NODE = 1, DEM_STATE_HEX, DEM_STATE_FRAME, DEM_STATE_DISP,
       DEM_STATE_ELEM };

/* Nodes per node or disp row. */
#define DEM_STATE_PER_ROW 4

/* The writer's default: binary records, gzip-compressed. */
#define DEM_STATE_FLAGS (DEM_STREAM_BINARY | DEM_STREAM_GZIP)

typedef struct dem_state_writer dem_state_writer_t;

/* Open a state stream on path (NULL or "-": standard output; a file is
 * written atomically, as dem_writer_open) and write the header and the mesh
 * m.  lines (may be NULL) are metadata lines copied into the header in order
 * (provenance, "# area XLO YLO XHI YHI" of the impact area in metres, which
 * demprofile reads, ...).  flags: DEM_STREAM_BINARY, DEM_STREAM_GZIP
 * (DEM_STATE_FLAGS is the usual choice). */
int dem_state_writer_open(dem_state_writer_t **w, const char *path,
			  const dem_mesh_t *m, const dem_header_t *lines,
			  int flags, dem_error_t *e);
/* Write one frame: pass number, time (s), node displacements u (3 per
 * node), and per element the stress sig (6, Pa), the total strain eps (6,
 * engineering shears) and the effective plastic strain ep (1).  A value
 * that is not finite is refused (DEM_ENUMERIC naming the element or node)
 * and nothing of the frame is written after it. */
int dem_state_write_frame(dem_state_writer_t *w, unsigned pass, double time,
			  const double *u, const double *sig,
			  const double *eps, const double *ep, dem_error_t *e);
/* Write the trailer and close (rename into place). */
int dem_state_writer_close(dem_state_writer_t *w, dem_error_t *e);
/* Give up: no trailer, a temporary file removed.  NULL is allowed. */
void dem_state_writer_abort(dem_state_writer_t *w);

/* One frame as read; the arrays belong to the reader and hold until the
 * next call of dem_state_next. */
typedef struct dem_state_frame {
	unsigned pass;
	double time;
	double *u;      /* 3 per node */
	double *sig;    /* 6 per element */
	double *eps;    /* 6 per element */
	double *ep;     /* 1 per element */
} dem_state_frame_t;

typedef struct dem_state_reader dem_state_reader_t;

/* Open path (NULL or "-": standard input; gzip read transparently), check
 * the header and read the mesh.  Errors name the stream and row: DEM_EINPUT
 * for a bad or truncated stream, DEM_EIO for an unreadable file. */
int dem_state_reader_open(dem_state_reader_t **r, const char *path,
			  dem_error_t *e);
/* The mesh: reference coordinates and hexes; for a stream with a "# grid"
 * line also nx, ny, nz and the grid lines gx, gy, gz (otherwise nx = ny =
 * nz = 0 and the grid lines NULL).  fix is all zero (free). */
const dem_mesh_t *dem_state_mesh(const dem_state_reader_t *r);
const dem_header_t *dem_state_header(const dem_state_reader_t *r);
/* The stream's name in messages ("stdin" or the path). */
const char *dem_state_name(const dem_state_reader_t *r);
/* Read the next frame: 1 for a frame, 0 at the end of the stream (trailer
 * checked), -1 on error (e names the stream and row). */
int dem_state_next(dem_state_reader_t *r, dem_state_frame_t *f,
		   dem_error_t *e);
void dem_state_reader_close(dem_state_reader_t *r);

#endif
