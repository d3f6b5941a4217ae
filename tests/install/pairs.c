/* pairs.c - a program of its own built against an installed libdem, as a
 * user builds one (the tests of tests/install):
 *
 *     cc pairs.c $(pkg-config --cflags --libs dem) -o pairs
 *
 * It reads a particle stream (FILE or standard input; text, binary or
 * gzip-compressed) with the toolkit's stream reader, finds the contact
 * pairs of the particles' boxes with the D-cell detector and prints their
 * number, which demdetect -c prints for the same stream. */
#include <stdio.h>
#include <stdlib.h>

#include <detect/detect.h>
#include <io/stream.h>

/* Read the centres and radii of r, dim + 1 values a particle, into *rows
 * (malloc'd) and their number into *n. */
static int read_rows(dem_reader_t *r, double **rows, size_t *n, dem_error_t *e)
{
	static const char *const name[] = { "x", "y", "z" };
	const dem_header_t *h = dem_reader_header(r);
	double v[DEM_STREAM_MAXCOL];
	size_t cap = 0, w = (size_t)h->dim + 1;
	int c[DEM_MAXDIM + 1], got;

	*rows = NULL;
	*n = 0;
	if (h->dim < 1 || h->dim > DEM_MAXDIM)
		return dem_error_set(e, DEM_EINPUT, "%s: expected a particle stream of 1 to 3 dimensions",
				     dem_reader_name(r));
	for (int d = 0; d <= h->dim; d++) {
		c[d] = dem_header_col(h, d < h->dim ? name[d] : "r");
		if (c[d] < 0)
			return dem_error_set(e, DEM_EINPUT, "%s: no column %s", dem_reader_name(r),
					     d < h->dim ? name[d] : "r");
	}
	while ((got = dem_reader_next(r, v, e)) == 1) {
		if (*n == cap) {
			double *p = realloc(*rows, (cap ? 2 * cap : 1024) * w * sizeof *p);
			if (!p)
				return dem_error_nomem(e, "rows");
			*rows = p;
			cap = cap ? 2 * cap : 1024;
		}
		for (int d = 0; d <= h->dim; d++)
			(*rows)[*n * w + (size_t)d] = v[c[d]];
		(*n)++;
	}
	return got < 0 ? e->code : DEM_OK;
}

int main(int argc, char **argv)
{
	dem_error_t e = { DEM_OK, "" };
	dem_reader_t *r = NULL;
	dem_boxes_t b = { 0 };
	dem_detect_opts_t o;
	dem_pairs_t pairs;
	double *rows = NULL;
	size_t n = 0;
	int rc, dim;

	dem_pairs_init(&pairs);
	rc = dem_reader_open(&r, argc > 1 ? argv[1] : NULL, &e);
	if (!rc)
		rc = read_rows(r, &rows, &n, &e);
	if (!rc) {
		dim = dem_reader_header(r)->dim;
		if (dem_boxes_alloc(&b, dim, n))
			rc = dem_error_nomem(&e, "boxes");
		for (size_t i = 0; !rc && i < n; i++) {
			const double *p = &rows[i * (size_t)(dim + 1)];
			for (int d = 0; d < dim; d++) {
				b.lo[d][i] = p[d] - p[dim];
				b.hi[d][i] = p[d] + p[dim];
			}
		}
	}
	if (!rc) {
		dem_detect_opts_init(&o);
		o.algo = DEM_DETECT_DCELL;
		rc = dem_detect(&b, &o, &pairs, NULL, &e);
	}
	if (!rc)
		printf("%zu\n", pairs.n);
	else
		fprintf(stderr, "pairs: %s\n", e.msg);
	dem_pairs_free(&pairs);
	dem_boxes_free(&b);
	free(rows);
	if (r)
		dem_reader_close(r);
	return rc;
}
