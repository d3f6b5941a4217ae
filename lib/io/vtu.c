/* vtu.c - VTK XML UnstructuredGrid writer for hexahedral meshes (vtu.h). */
#include "io/vtu.h"

#include "core/afile.h"

#include "core/fmt.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the VTU writer assumes a little-endian host"
#endif

/* An output file and, for binary arrays, the base64 encoder's state. */
struct out {
	FILE *f;
	int binary;
	unsigned char b[3];     /* bytes waiting for a group of 3 */
	int nb;
	int col;                /* characters on the line (ASCII values) */
};

static const char b64[] =
	"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

static void b64_group(struct out *o, int n)
{
	unsigned v = (unsigned)o->b[0] << 16 | (unsigned)o->b[1] << 8 | o->b[2];
	char c[4] = {b64[v >> 18 & 63], b64[v >> 12 & 63],
		     n > 1 ? b64[v >> 6 & 63] : '=', n > 2 ? b64[v & 63] : '='};
	fwrite(c, 1, 4, o->f);
}

static void b64_put(struct out *o, const void *p, size_t n)
{
	const unsigned char *s = p;
	for (size_t i = 0; i < n; i++) {
		o->b[o->nb++] = s[i];
		if (o->nb == 3) {
			b64_group(o, 3);
			o->nb = 0;
		}
	}
}

static void b64_end(struct out *o)
{
	if (o->nb) {
		for (int i = o->nb; i < 3; i++)
			o->b[i] = 0;
		b64_group(o, o->nb);
		o->nb = 0;
	}
}

/* Start a DataArray of count values of type ("Float64", "Int64",
 * "UInt8") with ncomp components; bytes is the size of its data. */
static void array_begin(struct out *o, const char *type, const char *name,
			int ncomp, const char *extra, uint64_t bytes)
{
	fprintf(o->f, "        <DataArray type=\"%s\"", type);
	if (name)
		fprintf(o->f, " Name=\"%s\"", name);
	if (ncomp > 1)
		fprintf(o->f, " NumberOfComponents=\"%d\"", ncomp);
	fprintf(o->f, "%s format=\"%s\">\n          ", extra ? extra : "",
		o->binary ? "binary" : "ascii");
	o->col = 0;
	if (o->binary)
		b64_put(o, &bytes, 8);
}

static void array_end(struct out *o)
{
	if (o->binary)
		b64_end(o);
	fputs("\n        </DataArray>\n", o->f);
}

static void put_f64(struct out *o, double v)
{
	if (o->binary) {
		b64_put(o, &v, 8);
		return;
	}
	char buf[32];
	int n = dem_fmt_double(buf, v == 0 ? 0 : v);
	if (o->col + n > 100) {
		fputs("\n          ", o->f);
		o->col = 0;
	} else if (o->col) {
		fputc(' ', o->f);
		o->col++;
	}
	fputs(buf, o->f);
	o->col += n;
}

static void put_i64(struct out *o, int64_t v)
{
	if (o->binary) {
		b64_put(o, &v, 8);
		return;
	}
	if (o->col > 100) {
		fputs("\n          ", o->f);
		o->col = 0;
	} else if (o->col) {
		fputc(' ', o->f);
		o->col++;
	}
	o->col += fprintf(o->f, "%lld", (long long)v);
}

static void put_u8(struct out *o, unsigned char v)
{
	if (o->binary) {
		b64_put(o, &v, 1);
		return;
	}
	put_i64(o, v);
}

static double von_mises(const double *s)
{
	double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
	return sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

static int check_finite(const double *x, size_t n, int per, const char *what,
			const char *item, dem_error_t *e)
{
	for (size_t i = 0; x && i < n * (size_t)per; i++)
		if (!isfinite(x[i]))
			return dem_error_set(e, DEM_ENUMERIC, "vtu: %s %zu: the %s is not finite",
					     item, i / (size_t)per, what);
	return DEM_OK;
}

int dem_vtu_write(const char *path, const dem_mesh_t *m,
		  const dem_vtu_fields_t *f, int binary, dem_error_t *e)
{
	static const dem_vtu_fields_t none = {0};
	struct out o = {0};
	size_t nn = m->nn, ne = m->ne;

	if (!f)
		f = &none;
	if (check_finite(m->X, nn, 3, "position", "node", e) ||
	    check_finite(f->u, nn, 3, "displacement", "node", e) ||
	    check_finite(f->sig, ne, 6, "stress", "element", e) ||
	    check_finite(f->eps, ne, 6, "strain", "element", e) ||
	    check_finite(f->ep, ne, 1, "plastic strain", "element", e))
		return e->code;
	for (size_t i = 0; i < 8 * ne; i++)
		if (m->hex[i] >= nn)
			return dem_error_set(e, DEM_EINPUT, "vtu: element %zu: node %lu of %zu",
					     i / 8, (unsigned long)m->hex[i], nn);

	dem_afile_t af;
	if (dem_afile_open(&af, path, "w", e))
		return e->code;
	o.f = af.f;
	o.binary = binary;

	fputs("<?xml version=\"1.0\"?>\n"
	      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
	      "header_type=\"UInt64\">\n  <UnstructuredGrid>\n", o.f);
	fprintf(o.f, "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", nn, ne);

	if (f->u) {
		fputs("      <PointData Vectors=\"displacement\">\n", o.f);
		array_begin(&o, "Float64", "displacement", 3, NULL, 24 * (uint64_t)nn);
		for (size_t i = 0; i < 3 * nn; i++)
			put_f64(&o, f->u[i]);
		array_end(&o);
		fputs("      </PointData>\n", o.f);
	}
	if (f->sig || f->eps || f->ep) {
		fputs("      <CellData", o.f);
		if (f->sig)
			fputs(" Tensors=\"stress\" Scalars=\"von_mises\"", o.f);
		fputs(">\n", o.f);
		static const char names[] =
			" ComponentName0=\"XX\" ComponentName1=\"YY\" ComponentName2=\"ZZ\""
			" ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\"";
		if (f->sig) {
			array_begin(&o, "Float64", "stress", 6, names, 48 * (uint64_t)ne);
			for (size_t i = 0; i < 6 * ne; i++)
				put_f64(&o, f->sig[i]);
			array_end(&o);
			array_begin(&o, "Float64", "von_mises", 1, NULL, 8 * (uint64_t)ne);
			for (size_t i = 0; i < ne; i++)
				put_f64(&o, von_mises(f->sig + 6 * i));
			array_end(&o);
		}
		if (f->eps) {
			array_begin(&o, "Float64", "strain", 6, names, 48 * (uint64_t)ne);
			for (size_t i = 0; i < 6 * ne; i++)
				put_f64(&o, i % 6 < 3 ? f->eps[i] : 0.5 * f->eps[i]);
			array_end(&o);
		}
		if (f->ep) {
			array_begin(&o, "Float64", "plastic_strain", 1, NULL, 8 * (uint64_t)ne);
			for (size_t i = 0; i < ne; i++)
				put_f64(&o, f->ep[i]);
			array_end(&o);
		}
		fputs("      </CellData>\n", o.f);
	}

	fputs("      <Points>\n", o.f);
	array_begin(&o, "Float64", "Points", 3, NULL, 24 * (uint64_t)nn);
	for (size_t i = 0; i < 3 * nn; i++)
		put_f64(&o, m->X[i]);
	array_end(&o);
	fputs("      </Points>\n      <Cells>\n", o.f);
	array_begin(&o, "Int64", "connectivity", 1, NULL, 64 * (uint64_t)ne);
	for (size_t i = 0; i < 8 * ne; i++)
		put_i64(&o, m->hex[i]);     /* hex8.h's node order is VTK's */
	array_end(&o);
	array_begin(&o, "Int64", "offsets", 1, NULL, 8 * (uint64_t)ne);
	for (size_t i = 0; i < ne; i++)
		put_i64(&o, 8 * (int64_t)(i + 1));
	array_end(&o);
	array_begin(&o, "UInt8", "types", 1, NULL, ne);
	for (size_t i = 0; i < ne; i++)
		put_u8(&o, 12);             /* VTK_HEXAHEDRON */
	array_end(&o);
	fputs("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n", o.f);

	return dem_afile_commit(&af, 0, e);
}
