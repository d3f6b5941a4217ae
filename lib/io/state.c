/* state.c - the state stream: a mesh and its fields frame by frame (see
 * state.h and dem-streams(5)). */
#include "io/state.h"

#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NSLOT 13
#define NCOL (2 + NSLOT)
#define PER DEM_STATE_PER_ROW

/* The slots of each record, as the header declares them ("# record"). */
static const char *const records[] = {
	"node 1 per=4 x:m y:m z:m",
	"hex 2 per=1 n0:- n1:- n2:- n3:- n4:- n5:- n6:- n7:-",
	"frame 3 per=1 time:s nodes:- elements:-",
	"disp 4 per=4 ux:m uy:m uz:m",
	"elem 5 per=1 sxx:Pa syy:Pa szz:Pa sxy:Pa syz:Pa szx:Pa "
	"exx:- eyy:- ezz:- exy:- eyz:- ezx:- ep:-",
	NULL
};

/* Header keys the stream itself owns: not copied from the caller's lines. */
static const char *const own_keys[] = {"record", "nodes", "elements", "grid", "block", NULL};

static int is_own_key(const char *k)
{
	for (int i = 0; own_keys[i]; i++)
		if (strcmp(k, own_keys[i]) == 0)
			return 1;
	return 0;
}

static void state_header(dem_header_t *h)
{
	char name[16];
	dem_header_init(h, "state", 1, 3);
	dem_header_add_col(h, "rec", DEM_U32, "-");
	dem_header_add_col(h, "id", DEM_U32, "-");
	for (int i = 0; i < NSLOT; i++) {
		snprintf(name, sizeof name, "v%d", i);
		dem_header_add_col(h, name, DEM_F64, "-");
	}
}

/* ---- writer ------------------------------------------------------------ */

struct dem_state_writer {
	dem_writer_t *w;
	size_t nn, ne;
};

void dem_state_writer_abort(dem_state_writer_t *s)
{
	if (!s)
		return;
	dem_writer_abort(s->w);
	free(s);
}

/* Rows of up to PER nodes' 3-vectors x, starting at first node n. */
static int write_node_rows(dem_state_writer_t *s, int rec, const double *x,
			   dem_error_t *e)
{
	double v[NCOL];
	for (size_t n = 0; n < s->nn; n += PER) {
		memset(v, 0, sizeof v);
		v[0] = rec;
		v[1] = (double)n;
		size_t m = s->nn - n < PER ? s->nn - n : PER;
		memcpy(v + 2, x + 3 * n, 3 * m * sizeof *x);
		if (dem_writer_row(s->w, v, e))
			return e->code;
	}
	return DEM_OK;
}

static int finite_all(const double *x, size_t n, size_t *bad)
{
	for (size_t i = 0; i < n; i++)
		if (!isfinite(x[i])) {
			*bad = i;
			return 0;
		}
	return 1;
}

int dem_state_writer_open(dem_state_writer_t **sp, const char *path,
			  const dem_mesh_t *m, const dem_header_t *lines,
			  int flags, dem_error_t *e)
{
	dem_state_writer_t *s;
	dem_header_t h;
	size_t bad;
	int rc = DEM_OK;

	*sp = NULL;
	if (m->nn == 0 || m->ne == 0 || m->nn > UINT32_MAX || m->ne > UINT32_MAX)
		return dem_error_set(e, DEM_EINPUT, "state: a mesh of %zu nodes and %zu elements "
				     "(1 to 2^32 - 1 of each)", m->nn, m->ne);
	if (!finite_all(m->X, 3 * m->nn, &bad))
		return dem_error_set(e, DEM_EINPUT, "state: node %zu: a coordinate is not finite",
				     bad / 3);
	for (size_t i = 0; i < 8 * m->ne; i++)
		if (m->hex[i] >= m->nn)
			return dem_error_set(e, DEM_EINPUT, "state: element %zu: node %" PRIu32
					     " of %zu", i / 8, m->hex[i], m->nn);
	if (!(s = calloc(1, sizeof *s)))
		return dem_error_nomem(e, "state writer");
	s->nn = m->nn;
	s->ne = m->ne;

	double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
	for (size_t n = 0; n < m->nn; n++)
		for (int d = 0; d < 3; d++) {
			lo[d] = fmin(lo[d], m->X[3 * n + d]);
			hi[d] = fmax(hi[d], m->X[3 * n + d]);
		}
	state_header(&h);
	for (int i = 0; records[i] && !rc; i++)
		rc = dem_header_add(&h, "record", "%s", records[i]);
	rc = rc ? rc : dem_header_add(&h, "nodes", "%zu", m->nn);
	rc = rc ? rc : dem_header_add(&h, "elements", "%zu", m->ne);
	if (m->nx > 0 && (size_t)m->nx * (size_t)m->ny * (size_t)m->nz == m->ne)
		rc = rc ? rc : dem_header_add(&h, "grid", "%d %d %d", m->nx, m->ny, m->nz);
	rc = rc ? rc : dem_header_add(&h, "block", "%.17g %.17g %.17g %.17g %.17g %.17g",
				      lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
	for (size_t i = 0; lines && i < lines->nline && !rc; i++)
		if (!is_own_key(lines->line[i].key))
			rc = dem_header_add(&h, lines->line[i].key, "%s", lines->line[i].val);
	if (rc) {
		dem_header_free(&h);
		free(s);
		return dem_error_nomem(e, "state header");
	}
	rc = dem_writer_open(&s->w, path, &h, flags, e);
	dem_header_free(&h);
	if (rc) {
		free(s);
		return rc;
	}
	if (write_node_rows(s, DEM_STATE_NODE, m->X, e)) {
		dem_state_writer_abort(s);
		return e->code;
	}
	for (size_t el = 0; el < m->ne; el++) {
		double v[NCOL] = {DEM_STATE_HEX, (double)el};
		for (int k = 0; k < 8; k++)
			v[2 + k] = m->hex[8 * el + k];
		if (dem_writer_row(s->w, v, e)) {
			dem_state_writer_abort(s);
			return e->code;
		}
	}
	*sp = s;
	return DEM_OK;
}

int dem_state_write_frame(dem_state_writer_t *s, unsigned pass, double time,
			  const double *u, const double *sig,
			  const double *eps, const double *ep, dem_error_t *e)
{
	size_t bad;
	double v[NCOL];

	/* check everything first, so a refused frame leaves nothing behind */
	if (!isfinite(time))
		return dem_error_set(e, DEM_ENUMERIC, "state: pass %u: the time is not finite", pass);
	if (!finite_all(u, 3 * s->nn, &bad))
		return dem_error_set(e, DEM_ENUMERIC, "state: pass %u, time %g: node %zu: "
				     "a displacement is not finite", pass, time, bad / 3);
	const double *f[3] = {sig, eps, ep};
	static const char *const fname[3] = {"stress", "strain", "plastic strain"};
	for (int k = 0; k < 3; k++)
		if (!finite_all(f[k], (k < 2 ? 6 : 1) * s->ne, &bad))
			return dem_error_set(e, DEM_ENUMERIC, "state: pass %u, time %g: element %zu: "
					     "the %s is not finite", pass, time,
					     k < 2 ? bad / 6 : bad, fname[k]);

	memset(v, 0, sizeof v);
	v[0] = DEM_STATE_FRAME;
	v[1] = pass;
	v[2] = time;
	v[3] = (double)s->nn;
	v[4] = (double)s->ne;
	if (dem_writer_row(s->w, v, e) || write_node_rows(s, DEM_STATE_DISP, u, e))
		return e->code;
	for (size_t el = 0; el < s->ne; el++) {
		v[0] = DEM_STATE_ELEM;
		v[1] = (double)el;
		memcpy(v + 2, sig + 6 * el, 6 * sizeof *v);
		memcpy(v + 8, eps + 6 * el, 6 * sizeof *v);
		v[14] = ep[el];
		if (dem_writer_row(s->w, v, e))
			return e->code;
	}
	return DEM_OK;
}

int dem_state_writer_close(dem_state_writer_t *s, dem_error_t *e)
{
	int rc = dem_writer_close(s->w, e);
	free(s);
	return rc;
}

/* ---- reader ------------------------------------------------------------ */

struct dem_state_reader {
	dem_reader_t *rd;
	dem_mesh_t m;
	double *u, *sig, *eps, *ep;
	double row[NCOL];
};

void dem_state_reader_close(dem_state_reader_t *r)
{
	if (!r)
		return;
	dem_reader_close(r->rd);
	dem_mesh_free(&r->m);
	free(r->u);
	free(r->sig);
	free(r->eps);
	free(r->ep);
	free(r);
}

const dem_mesh_t *dem_state_mesh(const dem_state_reader_t *r)
{
	return &r->m;
}

const dem_header_t *dem_state_header(const dem_state_reader_t *r)
{
	return dem_reader_header(r->rd);
}

const char *dem_state_name(const dem_state_reader_t *r)
{
	return dem_reader_name(r->rd);
}

static const char *const rec_names[] = {"?", "node", "hex", "frame", "disp", "elem"};

static const char *rec_name(double rec)
{
	return rec >= 1 && rec <= 5 ? rec_names[(int)rec] : "unknown";
}

/* The next row, which must be a rec row for item id; what names it in the
 * messages. */
static int expect_row(dem_state_reader_t *r, int rec, size_t id,
		      const char *what, dem_error_t *e)
{
	int got = dem_reader_next(r->rd, r->row, e);
	if (got < 0)
		return e->code;
	if (got == 0)
		return dem_error_set(e, DEM_EINPUT, "%s: truncated state: the stream ends "
				     "before the %s row of %s %zu", dem_reader_where(r->rd),
				     rec_names[rec], what, id);
	if (r->row[0] != rec || r->row[1] != (double)id)
		return dem_error_set(e, DEM_EINPUT, "%s: expected the %s row of %s %zu, "
				     "got rec %.0f (%s) for %.0f", dem_reader_where(r->rd),
				     rec_names[rec], what, id, r->row[0], rec_name(r->row[0]),
				     r->row[1]);
	return DEM_OK;
}

/* Read "# nodes"-like header counts. */
static int header_count(dem_state_reader_t *r, const char *key, size_t *n,
			dem_error_t *e)
{
	const char *v = dem_header_get(dem_reader_header(r->rd), key);
	char *end;
	unsigned long long x;
	if (!v)
		return dem_error_set(e, DEM_EINPUT, "%s: the state header has no '# %s' line",
				     dem_reader_name(r->rd), key);
	x = strtoull(v, &end, 10);
	if (end == v || *end || x == 0 || x > UINT32_MAX || *v == '-')
		return dem_error_set(e, DEM_EINPUT, "%s: '# %s %s': expected a count from 1 to 2^32 - 1",
				     dem_reader_name(r->rd), key, v);
	*n = (size_t)x;
	return DEM_OK;
}

static int check_header(dem_state_reader_t *r, dem_error_t *e)
{
	const dem_header_t *h = dem_reader_header(r->rd);
	const char *name = dem_reader_name(r->rd);
	dem_header_t want;

	if (strcmp(h->kind, "state") != 0)
		return dem_error_set(e, DEM_EINPUT, "%s: a %s stream; expected a state stream",
				     name, h->kind);
	state_header(&want);
	int ok = h->ncol == want.ncol;
	for (int i = 0; ok && i < want.ncol; i++)
		ok = strcmp(h->col[i].name, want.col[i].name) == 0 && h->col[i].type == want.col[i].type;
	if (!ok)
		return dem_error_set(e, DEM_EINPUT, "%s: the state columns should be "
				     "rec:u32 id:u32 v0:f64 ... v12:f64", name);
	/* the record layouts are this version's, in order */
	int k = 0;
	for (size_t i = 0; i < h->nline; i++) {
		if (strcmp(h->line[i].key, "record") != 0)
			continue;
		if (!records[k] || strcmp(h->line[i].val, records[k]) != 0)
			return dem_error_set(e, DEM_EINPUT, "%s: '# record %s': this reader "
					     "knows the layout '%s'", name, h->line[i].val,
					     records[k] ? records[k] : "(no more records)");
		k++;
	}
	if (records[k])
		return dem_error_set(e, DEM_EINPUT, "%s: the header has no '# record %s' line",
				     name, records[k]);
	return DEM_OK;
}

/* The grid lines of a structured mesh ("# grid NX NY NZ") from its nodes,
 * checking that the nodes and hexes are those of mesh.h's numbering. */
static int read_grid(dem_state_reader_t *r, const char *g, dem_error_t *e)
{
	dem_mesh_t *m = &r->m;
	const char *name = dem_reader_name(r->rd);
	int nx, ny, nz;
	char extra;

	if (sscanf(g, "%d %d %d %c", &nx, &ny, &nz, &extra) != 3 || nx < 1 || ny < 1 || nz < 1 ||
	    (size_t)nx * ny * nz != m->ne || (size_t)(nx + 1) * (ny + 1) * (nz + 1) != m->nn)
		return dem_error_set(e, DEM_EINPUT, "%s: '# grid %s': expected NX NY NZ with "
				     "NX NY NZ elements and (NX+1)(NY+1)(NZ+1) nodes", name, g);
	m->nx = nx;
	m->ny = ny;
	m->nz = nz;
	m->gx = malloc((size_t)(nx + 1) * sizeof *m->gx);
	m->gy = malloc((size_t)(ny + 1) * sizeof *m->gy);
	m->gz = malloc((size_t)(nz + 1) * sizeof *m->gz);
	if (!m->gx || !m->gy || !m->gz)
		return dem_error_nomem(e, "state grid");
	for (int i = 0; i <= nx; i++)
		m->gx[i] = m->X[3 * dem_mesh_node(m, i, 0, 0)];
	for (int j = 0; j <= ny; j++)
		m->gy[j] = m->X[3 * dem_mesh_node(m, 0, j, 0) + 1];
	for (int k = 0; k <= nz; k++)
		m->gz[k] = m->X[3 * dem_mesh_node(m, 0, 0, k) + 2];
	const double *gl[3] = {m->gx, m->gy, m->gz};
	int n[3] = {nx, ny, nz};
	for (int d = 0; d < 3; d++)
		for (int i = 0; i < n[d]; i++)
			if (!(gl[d][i] < gl[d][i + 1]))
				return dem_error_set(e, DEM_EINPUT, "%s: '# grid': the %c grid lines "
						     "do not increase at line %d", name, "xyz"[d], i);
	for (int k = 0; k <= nz; k++)
		for (int j = 0; j <= ny; j++)
			for (int i = 0; i <= nx; i++) {
				size_t q = dem_mesh_node(m, i, j, k);
				if (m->X[3 * q] != m->gx[i] || m->X[3 * q + 1] != m->gy[j] ||
				    m->X[3 * q + 2] != m->gz[k])
					return dem_error_set(e, DEM_EINPUT, "%s: node %zu is not on "
							     "the grid lines of '# grid %s'", name, q, g);
			}
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++) {
				size_t el = dem_mesh_elem(m, i, j, k);
				if (m->hex[8 * el] != dem_mesh_node(m, i, j, k) ||
				    m->hex[8 * el + 6] != dem_mesh_node(m, i + 1, j + 1, k + 1))
					return dem_error_set(e, DEM_EINPUT, "%s: element %zu is not "
							     "element (%d, %d, %d) of '# grid %s'",
							     name, el, i, j, k, g);
			}
	return DEM_OK;
}

static int read_mesh(dem_state_reader_t *r, dem_error_t *e)
{
	dem_mesh_t *m = &r->m;
	size_t nn, ne;

	if (header_count(r, "nodes", &nn, e) || header_count(r, "elements", &ne, e))
		return e->code;
	m->nn = nn;
	m->ne = ne;
	m->X = malloc(3 * nn * sizeof *m->X);
	m->hex = malloc(8 * ne * sizeof *m->hex);
	m->fix = calloc(nn, 1);
	r->u = malloc(3 * nn * sizeof *r->u);
	r->sig = malloc(6 * ne * sizeof *r->sig);
	r->eps = malloc(6 * ne * sizeof *r->eps);
	r->ep = malloc(ne * sizeof *r->ep);
	if (!m->X || !m->hex || !m->fix || !r->u || !r->sig || !r->eps || !r->ep)
		return dem_error_nomem(e, "state mesh and frame");
	for (size_t n = 0; n < nn; n += PER) {
		if (expect_row(r, DEM_STATE_NODE, n, "node", e))
			return e->code;
		size_t k = nn - n < PER ? nn - n : PER;
		memcpy(m->X + 3 * n, r->row + 2, 3 * k * sizeof *m->X);
	}
	for (size_t el = 0; el < ne; el++) {
		if (expect_row(r, DEM_STATE_HEX, el, "element", e))
			return e->code;
		for (int k = 0; k < 8; k++) {
			double v = r->row[2 + k];
			if (!(v >= 0 && v < (double)nn && v == floor(v)))
				return dem_error_set(e, DEM_EINPUT, "%s: element %zu: node '%g' "
						     "(expected 0 to %zu)", dem_reader_where(r->rd),
						     el, v, nn - 1);
			m->hex[8 * el + k] = (uint32_t)v;
		}
	}
	const char *g = dem_header_get(dem_reader_header(r->rd), "grid");
	return g ? read_grid(r, g, e) : DEM_OK;
}

int dem_state_reader_open(dem_state_reader_t **rp, const char *path,
			  dem_error_t *e)
{
	dem_state_reader_t *r = calloc(1, sizeof *r);

	*rp = NULL;
	if (!r)
		return dem_error_nomem(e, "state reader");
	if (dem_reader_open(&r->rd, path, e) || check_header(r, e) || read_mesh(r, e)) {
		dem_state_reader_close(r);
		return e->code;
	}
	*rp = r;
	return DEM_OK;
}

int dem_state_next(dem_state_reader_t *r, dem_state_frame_t *f, dem_error_t *e)
{
	const dem_mesh_t *m = &r->m;
	int got = dem_reader_next(r->rd, r->row, e);

	if (got <= 0)
		return got;
	if (r->row[0] != DEM_STATE_FRAME) {
		dem_error_set(e, DEM_EINPUT, "%s: expected a frame row (rec %d) or the end, "
			      "got rec %.0f (%s)", dem_reader_where(r->rd),
			      DEM_STATE_FRAME, r->row[0], rec_name(r->row[0]));
		return -1;
	}
	if (r->row[3] != (double)m->nn || r->row[4] != (double)m->ne) {
		dem_error_set(e, DEM_EINPUT, "%s: a frame of %g nodes and %g elements "
			      "for a mesh of %zu and %zu", dem_reader_where(r->rd),
			      r->row[3], r->row[4], m->nn, m->ne);
		return -1;
	}
	f->pass = (unsigned)r->row[1];
	f->time = r->row[2];
	char what[64];
	snprintf(what, sizeof what, "pass %u: node", f->pass);
	for (size_t n = 0; n < m->nn; n += PER) {
		if (expect_row(r, DEM_STATE_DISP, n, what, e))
			return -1;
		size_t k = m->nn - n < PER ? m->nn - n : PER;
		memcpy(r->u + 3 * n, r->row + 2, 3 * k * sizeof *r->u);
	}
	snprintf(what, sizeof what, "pass %u: element", f->pass);
	for (size_t el = 0; el < m->ne; el++) {
		if (expect_row(r, DEM_STATE_ELEM, el, what, e))
			return -1;
		memcpy(r->sig + 6 * el, r->row + 2, 6 * sizeof *r->sig);
		memcpy(r->eps + 6 * el, r->row + 8, 6 * sizeof *r->eps);
		r->ep[el] = r->row[14];
	}
	f->u = r->u;
	f->sig = r->sig;
	f->eps = r->eps;
	f->ep = r->ep;
	return 1;
}
