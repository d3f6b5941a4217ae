/* stream.c - reading and writing the toolkit's record streams. */
#include "io/stream.h"

#include "core/afile.h"
#include "core/fmt.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "binary streams assume a little-endian host; add byte swapping"
#endif

static const char *const known_kinds[] = {
	"particles", "boxes", "pairs", "shots", "state", "history",
	"profile", "form", "bodies", NULL
};

int dem_stream_kind_known(const char *kind)
{
	for (const char *const *k = known_kinds; *k; k++)
		if (strcmp(*k, kind) == 0)
			return 1;
	return 0;
}

static const char *const type_names[] = {
	[DEM_F64] = "f64", [DEM_U32] = "u32", [DEM_I64] = "i64"
};
static const size_t type_size[] = {[DEM_F64] = 8, [DEM_U32] = 4, [DEM_I64] = 8};

/* ---- header ---------------------------------------------------------- */

void dem_header_init(dem_header_t *h, const char *kind, int version, int dim)
{
	memset(h, 0, sizeof *h);
	snprintf(h->kind, sizeof h->kind, "%s", kind);
	h->version = version;
	h->dim = dim;
}

void dem_header_free(dem_header_t *h)
{
	for (size_t i = 0; i < h->nline; i++) {
		free(h->line[i].key);
		free(h->line[i].val);
	}
	free(h->line);
	h->line = NULL;
	h->nline = 0;
}

int dem_header_add_col(dem_header_t *h, const char *name, dem_coltype_t type,
		       const char *unit)
{
	if (h->ncol >= DEM_STREAM_MAXCOL || strlen(name) >= sizeof h->col[0].name ||
	    strlen(unit) >= sizeof h->col[0].unit)
		return DEM_EINPUT;
	dem_col_t *c = &h->col[h->ncol++];
	strcpy(c->name, name);
	strcpy(c->unit, unit);
	c->type = type;
	return DEM_OK;
}

int dem_header_col(const dem_header_t *h, const char *name)
{
	for (int i = 0; i < h->ncol; i++)
		if (strcmp(h->col[i].name, name) == 0)
			return i;
	return -1;
}

int dem_header_col_factor(const dem_header_t *h, int col, dem_dim_t want,
			  const char *name, double *factor, dem_error_t *e)
{
	const char *u = h->col[col].unit;
	char text[40], why[160];

	if (strcmp(u, "-") == 0) {
		if (dem_dim_equal(want, DEM_DIM_NONE)) {
			*factor = 1;
			return DEM_OK;
		}
		return dem_error_set(e, DEM_EINPUT, "%s: column %s has no unit, expected %s",
				     name, h->col[col].name, dem_dim_si_name(want));
	}
	snprintf(text, sizeof text, "1 %s", u);
	if (dem_units_parse(text, want, factor, why, sizeof why) != 0)
		return dem_error_set(e, DEM_EINPUT, "%s: column %s: %s", name,
				     h->col[col].name, why);
	return DEM_OK;
}

static int header_vput(dem_header_t *h, int replace, const char *key,
		       const char *fmt, va_list ap)
{
	char *val;
	va_list aq;
	va_copy(aq, ap);
	int len = vsnprintf(NULL, 0, fmt, aq);
	va_end(aq);
	if (len < 0 || !(val = malloc((size_t)len + 1)))
		return DEM_EIO;
	vsnprintf(val, (size_t)len + 1, fmt, ap);
	if (replace)
		for (size_t i = 0; i < h->nline; i++)
			if (strcmp(h->line[i].key, key) == 0) {
				free(h->line[i].val);
				h->line[i].val = val;
				return DEM_OK;
			}
	dem_hline_t *l = realloc(h->line, (h->nline + 1) * sizeof *l);
	char *k = strdup(key);
	if (!l || !k) {
		free(val);
		free(k);
		if (l)
			h->line = l;
		return DEM_EIO;
	}
	h->line = l;
	h->line[h->nline++] = (dem_hline_t){k, val};
	return DEM_OK;
}

int dem_header_add(dem_header_t *h, const char *key, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int rc = header_vput(h, 0, key, fmt, ap);
	va_end(ap);
	return rc;
}

int dem_header_set(dem_header_t *h, const char *key, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int rc = header_vput(h, 1, key, fmt, ap);
	va_end(ap);
	return rc;
}

const char *dem_header_get(const dem_header_t *h, const char *key)
{
	for (size_t i = 0; i < h->nline; i++)
		if (strcmp(h->line[i].key, key) == 0)
			return h->line[i].val;
	return NULL;
}

int dem_header_has_word(const dem_header_t *h, const char *key, const char *word)
{
	const char *v = dem_header_get(h, key);
	size_t n = strlen(word);

	for (const char *p = v; p && *p; p++)
		if ((p == v || p[-1] == ' ') && strncmp(p, word, n) == 0 && (p[n] == '\0' || p[n] == ' '))
			return 1;
	return 0;
}

int dem_header_copy_lines(dem_header_t *dst, const dem_header_t *src)
{
	for (size_t i = 0; i < src->nline; i++)
		if (dem_header_add(dst, src->line[i].key, "%s", src->line[i].val))
			return DEM_EIO;
	return DEM_OK;
}

int dem_header_add_provenance(dem_header_t *h, const char *prog, int argc,
			      char **argv, int has_seed, unsigned long seed)
{
	size_t len = 64 + strlen(prog);
	for (int i = 1; i < argc; i++)
		len += 4 * strlen(argv[i]) + 3;
	char *s = malloc(len), *p = s;
	if (!s)
		return DEM_EIO;
	p += sprintf(p, "%s %s", prog, DEM_VERSION);
	if (has_seed)
		p += sprintf(p, " seed=%lu", seed);
	p += sprintf(p, " args:");
	for (int i = 1; i < argc; i++) {
		/* quoted for the shell where needed, so the line can be rerun;
		 * and kept on one line */
		const char *a = argv[i];
		int quote = !*a || a[strspn(a, "abcdefghijklmnopqrstuvwxyz"
					    "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.,:/=+@%^")];
		*p++ = ' ';
		if (quote)
			*p++ = '\'';
		for (; *a; a++) {
			if (*a == '\'') {
				memcpy(p, "'\\''", 4);
				p += 4;
			} else {
				*p++ = (*a == '\n' || *a == '\r') ? ' ' : *a;
			}
		}
		if (quote)
			*p++ = '\'';
	}
	*p = '\0';
	int rc = dem_header_add(h, "prog", "%s", s);
	free(s);
	return rc;
}

/* ---- writer ---------------------------------------------------------- */

enum { BLOCK = 4096 };          /* binary records per block */

struct dem_writer {
	gzFile gz;
	dem_header_t h;         /* columns only; lines are written at open */
	dem_afile_t af;         /* the file, written atomically; zeroed for stdout */
	char name[256];         /* for messages */
	size_t recsize;
	unsigned char *blk;     /* binary: the block being filled */
	size_t nblk;
	char *line;             /* text: the row being formatted */
	size_t linecap;
	uint64_t rows;
};

/* zlib prefixes its messages with the file name it was given, "<fd:3>: " */
static const char *zmsg(const char *msg)
{
	const char *p = msg && msg[0] == '<' ? strstr(msg, ">: ") : NULL;
	return p ? p + 3 : msg;
}

static int werr(dem_writer_t *w, dem_error_t *e)
{
	int zerr = 0;
	const char *msg = gzerror(w->gz, &zerr);
	if (zerr == Z_ERRNO || !msg || !*msg)
		return dem_error_set(e, DEM_EIO, "%s: %s", w->name, strerror(errno ? errno : EIO));
	return dem_error_set(e, DEM_EIO, "%s: %s", w->name, zmsg(msg));
}

static int wputs(dem_writer_t *w, const char *s, size_t n, dem_error_t *e)
{
	if (n && gzwrite(w->gz, s, (unsigned)n) != (int)n)
		return werr(w, e);
	return DEM_OK;
}

int dem_writer_open(dem_writer_t **wp, const char *path, const dem_header_t *h,
		    int flags, dem_error_t *e)
{
	dem_writer_t *w = calloc(1, sizeof *w);
	int fd = -1;

	*wp = NULL;
	if (!w)
		return dem_error_nomem(e, "stream writer");
	if (path && strcmp(path, "-") != 0) {
		snprintf(w->name, sizeof w->name, "%s", path);
		int rc = dem_afile_open(&w->af, path, NULL, e);
		if (rc) {
			dem_writer_abort(w);
			return rc;
		}
		fd = w->af.fd;  /* zlib's from gzdopen on */
	} else {
		snprintf(w->name, sizeof w->name, "stdout");
		fd = dup(STDOUT_FILENO);
		if (fd < 0) {
			dem_writer_abort(w);
			return dem_error_set(e, DEM_EIO, "stdout: %s", strerror(errno));
		}
	}
	w->gz = gzdopen(fd, (flags & DEM_STREAM_GZIP) ? "wb6" : "wbT");
	if (!w->gz) {
		close(fd);
		dem_writer_abort(w);
		return dem_error_nomem(e, "stream writer");
	}
	gzbuffer(w->gz, 1 << 17);

	dem_header_init(&w->h, h->kind, h->version, h->dim);
	w->h.binary = !!(flags & DEM_STREAM_BINARY);
	w->h.ncol = h->ncol;
	memcpy(w->h.col, h->col, sizeof h->col);
	for (int i = 0; i < h->ncol; i++)
		w->recsize += type_size[h->col[i].type];
	if (w->h.binary && !(w->blk = malloc(4 + BLOCK * w->recsize))) {
		dem_writer_abort(w);
		return dem_error_nomem(e, "stream writer");
	}

	/* the header, as text whatever the row format */
	int rc = DEM_OK;
	char buf[512];
	int n = snprintf(buf, sizeof buf, "# dem %s %d\n", h->kind, h->version);
	rc = rc ? rc : wputs(w, buf, (size_t)n, e);
	if (h->dim) {
		n = snprintf(buf, sizeof buf, "# dim %d\n", h->dim);
		rc = rc ? rc : wputs(w, buf, (size_t)n, e);
	}
	rc = rc ? rc : wputs(w, "# columns", 9, e);
	for (int i = 0; i < h->ncol && !rc; i++) {
		n = snprintf(buf, sizeof buf, " %s:%s:%s", h->col[i].name,
			     type_names[h->col[i].type], h->col[i].unit);
		rc = wputs(w, buf, (size_t)n, e);
	}
	rc = rc ? rc : wputs(w, "\n", 1, e);
	n = snprintf(buf, sizeof buf, "# format %s\n", w->h.binary ? "binary" : "text");
	rc = rc ? rc : wputs(w, buf, (size_t)n, e);
	for (size_t i = 0; i < h->nline && !rc; i++) {
		rc = wputs(w, "# ", 2, e);
		rc = rc ? rc : wputs(w, h->line[i].key, strlen(h->line[i].key), e);
		rc = rc ? rc : wputs(w, " ", 1, e);
		rc = rc ? rc : wputs(w, h->line[i].val, strlen(h->line[i].val), e);
		rc = rc ? rc : wputs(w, "\n", 1, e);
	}
	rc = rc ? rc : wputs(w, "# data\n", 7, e);
	if (rc) {
		dem_writer_abort(w);
		return rc;
	}
	*wp = w;
	return DEM_OK;
}

static int flush_block(dem_writer_t *w, dem_error_t *e)
{
	uint32_t cnt = (uint32_t)w->nblk;
	memcpy(w->blk, &cnt, 4);
	w->nblk = 0;
	return wputs(w, (const char *)w->blk, 4 + cnt * w->recsize, e);
}

int dem_writer_row(dem_writer_t *w, const double *v, dem_error_t *e)
{
	if (w->h.binary) {
		unsigned char *p = w->blk + 4 + w->nblk * w->recsize;
		for (int i = 0; i < w->h.ncol; i++) {
			switch (w->h.col[i].type) {
			case DEM_F64: memcpy(p, &v[i], 8); p += 8; break;
			case DEM_U32: { uint32_t u = (uint32_t)v[i]; memcpy(p, &u, 4); p += 4; break; }
			case DEM_I64: { int64_t u = (int64_t)v[i]; memcpy(p, &u, 8); p += 8; break; }
			}
		}
		w->rows++;
		if (++w->nblk == BLOCK)
			return flush_block(w, e);
		return DEM_OK;
	}
	size_t need = 32 * (size_t)w->h.ncol + 2;
	if (w->linecap < need) {
		char *l = realloc(w->line, need);
		if (!l)
			return dem_error_nomem(e, "stream row");
		w->line = l;
		w->linecap = need;
	}
	char *p = w->line;
	for (int i = 0; i < w->h.ncol; i++) {
		if (i)
			*p++ = ' ';
		if (w->h.col[i].type == DEM_F64)
			p += dem_fmt_double(p, v[i]);
		else if (w->h.col[i].type == DEM_U32)
			p += sprintf(p, "%" PRIu32, (uint32_t)v[i]);
		else
			p += sprintf(p, "%" PRId64, (int64_t)v[i]);
	}
	*p++ = '\n';
	w->rows++;
	return wputs(w, w->line, (size_t)(p - w->line), e);
}

uint64_t dem_writer_rows(const dem_writer_t *w)
{
	return w->rows;
}

static void writer_free(dem_writer_t *w)
{
	dem_header_free(&w->h);
	dem_afile_abort(&w->af);        /* removes the file unless committed */
	free(w->blk);
	free(w->line);
	free(w);
}

int dem_writer_close(dem_writer_t *w, dem_error_t *e)
{
	int rc = DEM_OK;
	char buf[64];

	if (w->h.binary) {
		if (w->nblk)
			rc = flush_block(w, e);
		if (!rc)
			rc = flush_block(w, e);     /* the empty block ends the rows */
	}
	int n = snprintf(buf, sizeof buf, "# end %" PRIu64 "\n", w->rows);
	if (!rc)
		rc = wputs(w, buf, (size_t)n, e);
	if (!rc && gzflush(w->gz, Z_FINISH) != Z_OK)
		rc = werr(w, e);
	int zrc = gzclose(w->gz);
	w->gz = NULL;
	if (!rc && zrc != Z_OK)
		rc = dem_error_set(e, DEM_EIO, "%s: %s", w->name,
				   zrc == Z_ERRNO ? strerror(errno) : "write failed");
	if (!rc && w->af.tmp)
		rc = dem_afile_commit(&w->af, 0, e);
	if (rc) {
		dem_writer_abort(w);
		return rc;
	}
	writer_free(w);
	return DEM_OK;
}

void dem_writer_abort(dem_writer_t *w)
{
	if (!w)
		return;
	if (w->gz)
		gzclose(w->gz);
	writer_free(w);
}

/* ---- reader ---------------------------------------------------------- */

struct dem_reader {
	gzFile gz;
	dem_header_t h;
	char name[256];
	char where[300];
	char *line;
	size_t linecap;
	uint64_t lineno;        /* text: line number of the last line read */
	uint64_t rows;          /* rows read so far */
	size_t recsize;
	unsigned char *blk;     /* binary: current block */
	size_t nblk, iblk;
	int ended;
	int in_binary;          /* reading binary records: errors name the row */
	int nl;                 /* the last line read ended with a newline */
};

/* Read one line of any length; returns its length, 0 at end of file, -1 on
 * error.  The newline is removed. */
static long read_line(dem_reader_t *r, dem_error_t *e)
{
	size_t len = 0;
	for (;;) {
		if (r->linecap - len < 2) {
			size_t cap = r->linecap ? r->linecap * 2 : 4096;
			char *l = realloc(r->line, cap);
			if (!l)
				return dem_error_nomem(e, "stream line"), -1;
			r->line = l;
			r->linecap = cap;
		}
		if (!gzgets(r->gz, r->line + len, (int)(r->linecap - len))) {
			int zerr;
			const char *msg = gzerror(r->gz, &zerr);
			if (zerr != Z_OK && zerr != Z_BUF_ERROR) {
				dem_error_set(e, zerr == Z_ERRNO ? DEM_EIO : DEM_EINPUT,
					      "%s: %s", r->name,
					      zerr == Z_ERRNO ? strerror(errno) : zmsg(msg));
				return -1;
			}
			break;
		}
		len += strlen(r->line + len);
		if (len && r->line[len - 1] == '\n')
			break;
	}
	if (len == 0)
		return 0;
	r->lineno++;
	r->nl = r->line[len - 1] == '\n';
	while (len && (r->line[len - 1] == '\n' || r->line[len - 1] == '\r'))
		r->line[--len] = '\0';
	return (long)len + 1;   /* +1 so an empty line is not end of file */
}

/* An input error at the current text line, or (binary data) at the row
 * being read. */
static int bad(dem_reader_t *r, dem_error_t *e, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
static int bad(dem_reader_t *r, dem_error_t *e, const char *fmt, ...)
{
	char msg[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (r->in_binary)
		return dem_error_set(e, DEM_EINPUT, "%s: row %" PRIu64 ": %s",
				     r->name, r->rows + 1, msg);
	return dem_error_set(e, DEM_EINPUT, "%s:%" PRIu64 ": %s", r->name,
			     r->lineno, msg);
}

static int parse_columns(dem_reader_t *r, char *val, dem_error_t *e)
{
	char *save = NULL;
	for (char *tok = strtok_r(val, " \t", &save); tok;
	     tok = strtok_r(NULL, " \t", &save)) {
		char *t1 = strchr(tok, ':'), *t2 = t1 ? strchr(t1 + 1, ':') : NULL;
		if (!t1 || !t2)
			return bad(r, e, "column '%s': expected name:type:unit", tok);
		*t1++ = '\0';
		*t2++ = '\0';
		int type = -1;
		for (int k = 0; k < 3; k++)
			if (strcmp(t1, type_names[k]) == 0)
				type = k;
		if (type < 0)
			return bad(r, e, "column '%s': unknown type '%s' (expected f64, u32 or i64)", tok, t1);
		if (dem_header_add_col(&r->h, tok, (dem_coltype_t)type, t2))
			return bad(r, e, "column '%s': too many columns or too long a name", tok);
	}
	if (r->h.ncol == 0)
		return bad(r, e, "no columns");
	return DEM_OK;
}

/* The header: "# dem KIND VERSION" first, then "# key value" lines up to
 * "# data". */
static int read_header(dem_reader_t *r, dem_error_t *e)
{
	long n = read_line(r, e);
	char kind[32];
	int version, got_cols = 0, got_fmt = 0;

	if (n < 0)
		return e->code;
	if (n == 0)
		return dem_error_set(e, DEM_EINPUT, "%s: empty input, expected a dem stream", r->name);
	if (sscanf(r->line, "# dem %31s %d", kind, &version) != 2)
		return bad(r, e, "not a dem stream: the first line should be '# dem KIND VERSION'");
	if (!dem_stream_kind_known(kind))
		return bad(r, e, "unknown stream kind '%s'", kind);
	if (version != 1)
		return bad(r, e, "%s stream version %d: this reader knows version 1",
			   kind, version);
	dem_header_init(&r->h, kind, version, 0);
	for (;;) {
		n = read_line(r, e);
		if (n < 0)
			return e->code;
		if (n == 0)
			return bad(r, e, "truncated stream: the header ends without '# data'");
		if (r->line[0] != '#')
			return bad(r, e, "expected a '# key value' header line or '# data'");
		char *key = r->line + 1;
		while (*key == ' ')
			key++;
		char *val = key + strcspn(key, " \t");
		if (*val)
			*val++ = '\0';
		while (*val == ' ' || *val == '\t')
			val++;
		if (strcmp(key, "data") == 0)
			break;
		if (strcmp(key, "dim") == 0) {
			if (sscanf(val, "%d", &r->h.dim) != 1 || r->h.dim < 1 || r->h.dim > 3)
				return bad(r, e, "dim '%s': expected 1, 2 or 3", val);
		} else if (strcmp(key, "columns") == 0) {
			int rc = parse_columns(r, val, e);
			if (rc)
				return rc;
			got_cols = 1;
		} else if (strcmp(key, "format") == 0) {
			if (strcmp(val, "text") != 0 && strcmp(val, "binary") != 0)
				return bad(r, e, "format '%s': expected text or binary", val);
			r->h.binary = strcmp(val, "binary") == 0;
			got_fmt = 1;
		} else if (*key && dem_header_add(&r->h, key, "%s", val)) {
			return dem_error_nomem(e, "stream header");
		}
	}
	if (!got_cols)
		return bad(r, e, "the header has no '# columns' line");
	if (!got_fmt)
		return bad(r, e, "the header has no '# format' line");
	for (int i = 0; i < r->h.ncol; i++)
		r->recsize += type_size[r->h.col[i].type];
	return DEM_OK;
}

int dem_reader_open(dem_reader_t **rp, const char *path, dem_error_t *e)
{
	dem_reader_t *r = calloc(1, sizeof *r);
	int fd;

	*rp = NULL;
	if (!r)
		return dem_error_nomem(e, "stream reader");
	if (path && strcmp(path, "-") != 0) {
		snprintf(r->name, sizeof r->name, "%s", path);
		fd = open(path, O_RDONLY);
		struct stat sb;
		if (fd >= 0 && fstat(fd, &sb) == 0 && S_ISDIR(sb.st_mode)) {
			close(fd);
			fd = -1;
			errno = EISDIR;
		}
		if (fd < 0) {
			int err = errno;
			free(r);
			return dem_error_set(e, err == ENOENT || err == EISDIR ? DEM_EINPUT : DEM_EIO,
					     "%s: %s", path, strerror(err));
		}
	} else {
		snprintf(r->name, sizeof r->name, "stdin");
		fd = dup(STDIN_FILENO);
		if (fd < 0) {
			free(r);
			return dem_error_set(e, DEM_EIO, "stdin: %s", strerror(errno));
		}
	}
	r->gz = gzdopen(fd, "rb");
	if (!r->gz) {
		close(fd);
		free(r);
		return dem_error_nomem(e, "stream reader");
	}
	gzbuffer(r->gz, 1 << 17);
	int rc = read_header(r, e);
	if (rc) {
		dem_reader_close(r);
		return rc;
	}
	*rp = r;
	return DEM_OK;
}

const dem_header_t *dem_reader_header(const dem_reader_t *r)
{
	return &r->h;
}

const char *dem_reader_name(const dem_reader_t *r)
{
	return r->name;
}

const char *dem_reader_where(dem_reader_t *r)
{
	if (r->h.binary)
		snprintf(r->where, sizeof r->where, "%s: row %" PRIu64, r->name, r->rows);
	else
		snprintf(r->where, sizeof r->where, "%s:%" PRIu64, r->name, r->lineno);
	return r->where;
}

/* The trailer "# end N" must match the rows read and be the last line. */
static int read_trailer(dem_reader_t *r, const char *line, dem_error_t *e)
{
	uint64_t n;
	char extra;
	if (!r->nl)     /* a cut "# end 3000" could read as "# end 30" */
		return bad(r, e, "truncated stream: the last line is incomplete");
	if (sscanf(line, "# end %" SCNu64 " %c", &n, &extra) != 1)
		return bad(r, e, "expected a row or the trailer '# end N'");
	if (n != r->rows)
		return bad(r, e, "the trailer counts %" PRIu64 " rows but %" PRIu64 " were read", n, r->rows);
	long m;
	while ((m = read_line(r, e)) > 0)
		if (r->line[strspn(r->line, " \t")] != '\0')
			return bad(r, e, "data after the trailer");
	if (m < 0)
		return -1;
	r->ended = 1;
	return 0;
}

static int next_text(dem_reader_t *r, double *v, dem_error_t *e)
{
	for (;;) {
		long n = read_line(r, e);
		if (n < 0)
			return -1;
		if (n == 0) {
			bad(r, e, "truncated stream: it ends after %" PRIu64 " rows without the trailer '# end N'", r->rows);
			return -1;
		}
		char *p = r->line + strspn(r->line, " \t");
		if (*p == '\0')
			continue;
		if (!r->nl) {
			bad(r, e, "truncated stream: the last line is incomplete");
			return -1;
		}
		if (*p == '#')
			return read_trailer(r, p, e) ? -1 : 0;
		for (int i = 0; i < r->h.ncol; i++) {
			char *end;
			while (*p == ' ' || *p == '\t')
				p++;
			if (*p == '\0') {
				bad(r, e, "%d values, expected %d", i, r->h.ncol);
				return -1;
			}
			errno = 0;
			if (r->h.col[i].type == DEM_F64) {
				v[i] = strtod(p, &end);
			} else {
				long long x = strtoll(p, &end, 10);
				v[i] = (double)x;
				if (end != p && (errno == ERANGE ||
				    (r->h.col[i].type == DEM_U32 && (x < 0 || x > UINT32_MAX)))) {
					bad(r, e, "column %s: '%.*s' is out of range", r->h.col[i].name,
					    (int)strcspn(p, " \t"), p);
					return -1;
				}
			}
			if (end == p || (*end && *end != ' ' && *end != '\t')) {
				bad(r, e, "column %s: '%.*s' is not a number", r->h.col[i].name,
				    (int)strcspn(p, " \t"), p);
				return -1;
			}
			if (!isfinite(v[i])) {
				bad(r, e, "column %s: %.*s is not finite", r->h.col[i].name,
				    (int)strcspn(p, " \t"), p);
				return -1;
			}
			p = end;
		}
		p += strspn(p, " \t");
		if (*p) {
			bad(r, e, "more than %d values", r->h.ncol);
			return -1;
		}
		r->rows++;
		return 1;
	}
}

/* Read exactly n bytes; a short read is a truncated stream, reported at the
 * first record it cut. */
static int gzread_all(dem_reader_t *r, void *buf, size_t n, dem_error_t *e)
{
	int got = n ? gzread(r->gz, buf, (unsigned)n) : 0;
	if (got < 0) {
		int zerr;
		const char *msg = gzerror(r->gz, &zerr);
		dem_error_set(e, zerr == Z_ERRNO ? DEM_EIO : DEM_EINPUT, "%s: %s", r->name,
			      zerr == Z_ERRNO ? strerror(errno) : zmsg(msg));
		return -1;
	}
	if ((size_t)got != n) {
		if (buf == r->blk)
			r->rows += (size_t)got / r->recsize;
		bad(r, e, "truncated stream: it ends inside the binary rows");
		return -1;
	}
	return 0;
}

static int next_binary(dem_reader_t *r, double *v, dem_error_t *e)
{
	r->in_binary = 1;
	if (r->iblk == r->nblk) {
		uint32_t cnt;
		if (gzread_all(r, &cnt, 4, e))
			return -1;
		if (cnt == 0) {
			r->in_binary = 0;
			long n = read_line(r, e);
			if (n < 0)
				return -1;
			if (n == 0) {
				bad(r, e, "truncated stream: no trailer '# end N' after the binary rows");
				return -1;
			}
			return read_trailer(r, r->line, e) ? -1 : 0;
		}
		if (cnt > (1u << 24)) {
			bad(r, e, "corrupt binary block (%" PRIu32 " records)", cnt);
			return -1;
		}
		unsigned char *b = realloc(r->blk, (size_t)cnt * r->recsize);
		if (!b) {
			dem_error_nomem(e, "stream block");
			return -1;
		}
		r->blk = b;
		if (gzread_all(r, r->blk, (size_t)cnt * r->recsize, e))
			return -1;
		r->nblk = cnt;
		r->iblk = 0;
	}
	const unsigned char *p = r->blk + r->iblk * r->recsize;
	for (int i = 0; i < r->h.ncol; i++) {
		switch (r->h.col[i].type) {
		case DEM_F64: memcpy(&v[i], p, 8); p += 8; break;
		case DEM_U32: { uint32_t u; memcpy(&u, p, 4); v[i] = u; p += 4; break; }
		case DEM_I64: { int64_t u; memcpy(&u, p, 8); v[i] = (double)u; p += 8; break; }
		}
		if (!isfinite(v[i])) {
			bad(r, e, "column %s: %g is not finite", r->h.col[i].name, v[i]);
			return -1;
		}
	}
	r->iblk++;
	r->rows++;
	return 1;
}

int dem_reader_next(dem_reader_t *r, double *v, dem_error_t *e)
{
	if (r->ended)
		return 0;
	return r->h.binary ? next_binary(r, v, e) : next_text(r, v, e);
}

void dem_reader_close(dem_reader_t *r)
{
	if (!r)
		return;
	if (r->gz)
		gzclose(r->gz);
	dem_header_free(&r->h);
	free(r->line);
	free(r->blk);
	free(r);
}
