/* stream.h - the toolkit's record streams (DESIGN.md, "Streams").
 *
 * A stream is a text header, rows, and a trailer:
 *
 *     # dem particles 1              kind and format version
 *     # dim 2
 *     # columns x:f64:m y:f64:m r:f64:m
 *     # format text                  or binary
 *     # prog dempack 0.1.0 seed=1 args: random -n 3     provenance, one per program
 *     # domain 0 0 1 1               any other "# key value" metadata
 *     # data
 *     0.1 0.2 0.01                   rows (text), or blocks of binary records
 *     # end 3                        trailer: the row count
 *
 * Binary rows come in blocks: a little-endian uint32 record count, then that
 * many fixed-size little-endian records (columns in order: f64 8 bytes, u32 4
 * bytes, i64 8 bytes); a block of count 0 ends the rows, then the text
 * trailer follows.  Every reader goes through zlib, so gzip-compressed input
 * is read transparently.  A stream that ends without its trailer is
 * truncated and an error.
 */
#ifndef DEM_IO_STREAM_H
#define DEM_IO_STREAM_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "core/units.h"

#define DEM_STREAM_MAXCOL 64

typedef enum dem_coltype { DEM_F64, DEM_U32, DEM_I64 } dem_coltype_t;

typedef struct dem_col {
	char name[24];
	char unit[16];          /* "-" when dimensionless */
	dem_coltype_t type;
} dem_col_t;

/* One "# key value" header line. */
typedef struct dem_hline {
	char *key, *val;
} dem_hline_t;

typedef struct dem_header {
	char kind[32];
	int version;
	int dim;                /* 0 when the stream has no dimension */
	int binary;
	int ncol;
	dem_col_t col[DEM_STREAM_MAXCOL];
	size_t nline;           /* other header lines, in order (prog, seed, ...) */
	dem_hline_t *line;
} dem_header_t;

/* Stream kinds the toolkit knows; a reader refuses any other. */
int dem_stream_kind_known(const char *kind);

void dem_header_init(dem_header_t *h, const char *kind, int version, int dim);
void dem_header_free(dem_header_t *h);
int dem_header_add_col(dem_header_t *h, const char *name, dem_coltype_t type,
		       const char *unit);
/* Index of the column named name, or -1. */
int dem_header_col(const dem_header_t *h, const char *name);
/* The factor converting column col to SI, after checking that its unit is
 * one of dimension want (a column in "mm" read as a length gives 0.001;
 * "-" is dimensionless).  name is the stream's name for the message. */
int dem_header_col_factor(const dem_header_t *h, int col, dem_dim_t want,
			  const char *name, double *factor, dem_error_t *e);
/* Append a "# key value" line (keys may repeat, e.g. prog). */
int dem_header_add(dem_header_t *h, const char *key, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* Replace the first line with key, or append one. */
int dem_header_set(dem_header_t *h, const char *key, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* Value of the first line with key, or NULL. */
const char *dem_header_get(const dem_header_t *h, const char *key);
/* Whether the first line with key holds word as one of its blank-separated
 * words (e.g. key "twod", word "mode=axisym"); 0 when there is no such line. */
int dem_header_has_word(const dem_header_t *h, const char *key, const char *word);
/* Copy every metadata line of src (provenance and the rest) into dst. */
int dem_header_copy_lines(dem_header_t *dst, const dem_header_t *src);
/* Append this program's provenance line: name, version, seed (if has_seed)
 * and its arguments. */
int dem_header_add_provenance(dem_header_t *h, const char *prog, int argc,
			      char **argv, int has_seed, unsigned long seed);

enum { DEM_STREAM_BINARY = 1, DEM_STREAM_GZIP = 2 };

typedef struct dem_writer dem_writer_t;

/* Open a stream for writing to path (NULL or "-": standard output).  A file
 * is written under a temporary name in the same folder and renamed on
 * dem_writer_close, so no half-written file is ever left at path. */
int dem_writer_open(dem_writer_t **w, const char *path, const dem_header_t *h,
		    int flags, dem_error_t *e);
/* Write one row of h->ncol values (integer columns are converted). */
int dem_writer_row(dem_writer_t *w, const double *v, dem_error_t *e);
/* Write the trailer, flush, close, rename into place. */
int dem_writer_close(dem_writer_t *w, dem_error_t *e);
/* Give up: no trailer; a temporary file is removed.  NULL is allowed. */
void dem_writer_abort(dem_writer_t *w);
uint64_t dem_writer_rows(const dem_writer_t *w);

typedef struct dem_reader dem_reader_t;

/* Open path (NULL or "-": standard input), read and check the header. */
int dem_reader_open(dem_reader_t **r, const char *path, dem_error_t *e);
const dem_header_t *dem_reader_header(const dem_reader_t *r);
/* Read the next row into v (ncol values).  Returns 1 for a row, 0 at the
 * end of the rows (the trailer was read and its count checked), -1 on error
 * (e says where: "name:LINE: ..." for text, "name: row N: ..." for binary). */
int dem_reader_next(dem_reader_t *r, double *v, dem_error_t *e);
/* Where the last row came from, for the caller's own checks:
 * "name:LINE" (text) or "name: row N" (binary). */
const char *dem_reader_where(dem_reader_t *r);
/* The stream's name as given in messages ("stdin" or the path). */
const char *dem_reader_name(const dem_reader_t *r);
void dem_reader_close(dem_reader_t *r);

#endif
