/* frames.c - the body stream and VTK polygons of the bodies (frames.h). */
#include "body/frames.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/afile.h"
#include "core/consts.h"
#include "core/fmt.h"

#define NCOL 13

static const struct {
	const char *name;
	dem_coltype_t type;
	const char *unit;
	dem_dim_t dim;
} cols[NCOL] = {
	{"frame", DEM_U32, "-", DEM_DIM_NONE},
	{"t", DEM_F64, "s", DEM_DIM_TIME},
	{"id", DEM_U32, "-", DEM_DIM_NONE},
	{"shape", DEM_U32, "-", DEM_DIM_NONE},
	{"a", DEM_F64, "m", DEM_DIM_LENGTH},
	{"b", DEM_F64, "m", DEM_DIM_LENGTH},
	{"m", DEM_F64, "-", DEM_DIM_NONE},
	{"x", DEM_F64, "m", DEM_DIM_LENGTH},
	{"y", DEM_F64, "m", DEM_DIM_LENGTH},
	{"theta", DEM_F64, "rad", DEM_DIM_ANGLE},
	{"vx", DEM_F64, "m/s", DEM_DIM_VELOCITY},
	{"vy", DEM_F64, "m/s", DEM_DIM_VELOCITY},
	{"w", DEM_F64, "rad/s", {0, 0, -1, 1, 0}},   /* angular velocity */
};

int dem_bodies_header(dem_header_t *h, size_t nw, const double (*wall)[5])
{
	int rc = DEM_OK;
	dem_header_init(h, "bodies", 1, 2);
	for (int k = 0; k < NCOL && !rc; k++)
		rc = dem_header_add_col(h, cols[k].name, cols[k].type, cols[k].unit);
	if (!rc)
		rc = dem_header_add(h, "shapes", "superquadric polygon disk");
	for (size_t k = 0; k < nw && !rc; k++) {
		char b[5][32];
		for (int i = 0; i < 5; i++)
			dem_fmt_double(b[i], wall[k][i]);
		rc = dem_header_add(h, "wall", "%s %s %s %s %s", b[0], b[1], b[2], b[3], b[4]);
	}
	return rc;
}

int dem_bodies_write_row(dem_writer_t *w, const dem_body_row_t *r, dem_error_t *e)
{
	double v[NCOL] = {r->frame, r->t, r->id, r->shape, r->a, r->b, r->m,
	                  r->x, r->y, r->th, r->vx, r->vy, r->w};
	return dem_writer_row(w, v, e);
}

int dem_bodies_writer_open(dem_writer_t **w, const char *path, const dem_de_t *de,
                           const char *prog, int argc, char **argv, int has_seed,
                           unsigned long seed, int flags, dem_error_t *e)
{
	dem_header_t h;
	double (*wall)[5] = malloc((de->nw ? de->nw : 1) * sizeof *wall);
	int rc = DEM_OK;
	if (!wall)
		return dem_error_nomem(e, "body stream header");
	for (size_t k = 0; k < de->nw; k++) {
		const double (*q)[2] = (const double (*)[2])de->wall[k];
		wall[k][0] = q[1][0], wall[k][1] = q[1][1];
		wall[k][2] = q[0][0], wall[k][3] = q[0][1];
		wall[k][4] = hypot(q[2][0] - q[1][0], q[2][1] - q[1][1]);
	}
	rc = dem_bodies_header(&h, de->nw, (const double (*)[5])wall);
	free(wall);
	if (!rc)
		rc = dem_header_add_provenance(&h, prog, argc, argv, has_seed, seed);
	if (rc)
		rc = dem_error_nomem(e, "body stream header");
	else
		rc = dem_writer_open(w, path, &h, flags, e);
	dem_header_free(&h);
	return rc;
}

int dem_bodies_write_frame(dem_writer_t *w, const dem_de_t *de, unsigned frame,
                           dem_error_t *e)
{
	for (size_t i = 0; i < de->n; i++) {
		const dem_shape_t *s = &de->shape[de->sh[i]];
		double v[NCOL] = {frame, de->t, (double)i, s->kind, s->a, s->b, s->m,
		                  de->x[i], de->y[i], de->th[i], de->vx[i], de->vy[i], de->w[i]};
		if (dem_writer_row(w, v, e))
			return e->code;
	}
	return DEM_OK;
}

int dem_bodies_reader_open(dem_reader_t **r, const char *path, dem_error_t *e)
{
	int rc = dem_reader_open(r, path, e);
	if (rc)
		return rc;
	const dem_header_t *h = dem_reader_header(*r);
	const char *name = dem_reader_name(*r);
	double f;
	if (strcmp(h->kind, "bodies") != 0)
		rc = dem_error_set(e, DEM_EINPUT, "%s: a %s stream: expected a body stream", name,
		                   h->kind);
	else if (h->ncol != NCOL)
		rc = dem_error_set(e, DEM_EINPUT, "%s: %d columns: a body stream has %d", name,
		                   h->ncol, NCOL);
	for (int k = 0; k < NCOL && !rc; k++) {
		if (strcmp(h->col[k].name, cols[k].name) != 0)
			rc = dem_error_set(e, DEM_EINPUT, "%s: column %d is '%s': expected '%s'",
			                   name, k + 1, h->col[k].name, cols[k].name);
		else if (!(rc = dem_header_col_factor(h, k, cols[k].dim, name, &f, e)) && f != 1)
			rc = dem_error_set(e, DEM_EINPUT, "%s: column %s in %s: expected %s", name,
			                   cols[k].name, h->col[k].unit, cols[k].unit);
	}
	if (rc) {
		dem_reader_close(*r);
		*r = NULL;
	}
	return rc;
}

int dem_bodies_reader_next(dem_reader_t *r, dem_body_row_t *row, dem_error_t *e)
{
	double v[NCOL];
	int k = dem_reader_next(r, v, e);
	if (k != 1)
		return k;
	/* the shape code is checked as read, before it becomes an int: a u32
	 * column holds up to 2^32 - 1, which no int does */
	if (!(v[3] <= DEM_SHAPE_DISK)) {
		dem_error_set(e, DEM_EINPUT, "%s: shape %.0f: expected 0, 1 or 2", dem_reader_where(r),
		              v[3]);
		return -1;
	}
	row->frame = (unsigned)v[0], row->t = v[1], row->id = (unsigned)v[2];
	row->shape = (int)v[3];
	row->a = v[4], row->b = v[5], row->m = v[6];
	row->x = v[7], row->y = v[8], row->th = v[9];
	row->vx = v[10], row->vy = v[11], row->w = v[12];
	return 1;
}

/* ---- VTK polygons -------------------------------------------------------- */

#define DISK_POINTS 64

static int npoints(const dem_de_t *de, size_t i)
{
	int nv = de->shape[de->sh[i]].nv;
	return nv ? nv : DISK_POINTS;
}

static void put(FILE *f, double v)
{
	char b[32];
	dem_fmt_double(b, v);
	fputs(b, f);
}

int dem_bodies_vtu(const char *path, const dem_de_t *de, dem_error_t *e)
{
	dem_afile_t af;
	size_t np = 4 * de->nw, nc = de->n + de->nw;
	int maxnv = DISK_POINTS;
	for (size_t i = 0; i < de->n; i++) {
		np += (size_t)npoints(de, i);
		if (npoints(de, i) > maxnv)
			maxnv = npoints(de, i);
	}
	double (*v)[2] = malloc((size_t)maxnv * sizeof *v);
	if (!v)
		return dem_error_nomem(e, "vtu");
	int rc = dem_afile_open(&af, path, "w", e);
	if (rc) {
		free(v);
		return rc;
	}
	FILE *f = af.f;
	fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
	        "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n"
	        "<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n<Points>\n"
	        "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", np, nc);
	for (size_t i = 0; i < de->n; i++) {
		int n = dem_de_outline(de, i, maxnv, v);
		if (n == 0) {
			double r = de->shape[de->sh[i]].a;
			n = DISK_POINTS;
			for (int k = 0; k < n; k++) {
				double phi = de->th[i] + 2 * DEM_PI * k / n;
				v[k][0] = de->x[i] + r * cos(phi), v[k][1] = de->y[i] + r * sin(phi);
			}
		}
		for (int k = 0; k < n; k++) {
			put(f, v[k][0]), fputc(' ', f), put(f, v[k][1]), fputs(" 0\n", f);
		}
	}
	for (size_t k = 0; k < de->nw; k++)
		for (int q = 0; q < 4; q++)
			put(f, de->wall[k][q][0]), fputc(' ', f), put(f, de->wall[k][q][1]),
				fputs(" 0\n", f);
	fprintf(f, "</DataArray>\n</Points>\n<Cells>\n"
	        "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
	size_t p = 0;
	for (size_t c = 0; c < nc; c++) {
		int n = c < de->n ? npoints(de, c) : 4;
		for (int k = 0; k < n; k++)
			fprintf(f, "%zu%c", p++, k + 1 == n ? '\n' : ' ');
	}
	fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
	p = 0;
	for (size_t c = 0; c < nc; c++) {
		p += (size_t)(c < de->n ? npoints(de, c) : 4);
		fprintf(f, "%zu\n", p);
	}
	fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
	for (size_t c = 0; c < nc; c++)
		fputs("7\n", f);        /* VTK_POLYGON */
	fprintf(f, "</DataArray>\n</Cells>\n<CellData Scalars=\"id\">\n"
	        "<DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">\n");
	for (size_t c = 0; c < nc; c++)
		fprintf(f, "%lld\n", c < de->n ? (long long)c : -1 - (long long)(c - de->n));
	fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"speed\" format=\"ascii\">\n");
	for (size_t c = 0; c < nc; c++)
		put(f, c < de->n ? hypot(de->vx[c], de->vy[c]) : 0), fputc('\n', f);
	fprintf(f, "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
	free(v);
	return dem_afile_commit(&af, 0, e);
}
