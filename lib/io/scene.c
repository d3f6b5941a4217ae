/* scene.c - the scene: a YAML file read into a small tree of mappings,
 * sequences and scalars, read back through typed getters.
 *
 * libyaml's event parser builds the tree (not yaml_parser_load) so that
 * aliases can be refused and duplicate keys caught with their position, and
 * so that nesting is handled with an explicit stack.  Every node keeps its
 * 1-based line and column, or the command-line option that set it.
 *
 * The getters record each key they were asked for, in order, with the value
 * they resolved; that list drives both --dump-scene and dem_scene_check().
 *
 * A section may pull in a library file of the data directory ("material:
 * {use: al7075}"): its tree is merged into the section's when the scene is
 * loaded, the scene's own keys winning, so the getters never know.  Nodes
 * that came from a library keep its name for messages; the scene owns the
 * names (files), the nodes only point at them.
 */
#include "io/scene.h"

#include "core/cli.h"

#include "core/fmt.h"
#include "core/share.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <yaml.h>

/* Deeper nesting than this is not a scene; the limit keeps the recursive
 * walks (free, check) far from the end of the stack. */
#define MAX_DEPTH 256

/* The toolkit's top-level sections.  A program reading a new section adds
 * it here. */
static const char *const known_sections[] = {
	"pack", "detect", "shot", "block", "material", "contact", "run",
	"load", "profile", "form", "plate", "output", "meta", "bodies", "walls", "dim", NULL
};

static int in_list(const char *const *list, const char *name)
{
	for (; list && *list; list++)
		if (strcmp(*list, name) == 0)
			return 1;
	return 0;
}

/* Keys of a section that two programs of one pipeline read, each its own
 * part: the shot section gives dempack the stream (radius ... azimuth) and
 * demshot the bodies (density, gap, buffer; model, modulus_ratio and
 * element, the FE shot of a 2D block).  The check of one program
 * lets the other's keys pass; that program checks their values. */
static const char *const shared_keys[] = {
	"shot.radius", "shot.law", "shot.lambda", "shot.speed", "shot.speed_scatter",
	"shot.angle", "shot.azimuth",              /* dempack shots */
	"shot.density", "shot.gap", "shot.buffer",  /* demshot */
	"shot.model", "shot.modulus_ratio", "shot.element",  /* demshot, 2D */
	NULL
};

/* The sections that may pull in a library file with "use: NAME", and the
 * folder of the data directory that holds their files. */
static const struct {
	const char *section;
	const char *folder;
} library_folders[] = {
	{ "material", "materials" },
	{ "shot", "shots" },
};

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

enum node_kind { NODE_SCALAR, NODE_SEQ, NODE_MAP };

struct node;

/* A mapping entry (key set) or a sequence item (key NULL). */
struct entry {
	char *key;
	long line, col;         /* of the key */
	struct node *val;       /* NULL while a mapping waits for the value */
};

struct node {
	enum node_kind kind;
	char *text;             /* scalar */
	int plain;              /* a plain scalar, which may be null */
	long line, col;         /* 1-based; 0 when set on the command line */
	char *origin;           /* the option that set it, or NULL */
	const char *file;       /* the library file it came from (owned by the
				 * scene), or NULL for the scene's own */
	struct entry *ent;
	size_t n, cap;
};

/* A key a getter asked for and the value it resolved ("0.0007 m"); val
 * NULL when there is nothing to print (no default). */
struct rec {
	char *key;
	char *val;
};

/* A section's "use:" as --dump-scene writes it: "al7075  # /x/al7075.yaml". */
struct use {
	char *section;
	char *text;
};

struct dem_scene {
	char *name;             /* the file, for messages; NULL if none */
	struct node *root;      /* always a mapping */
	struct rec *rec;
	size_t nrec, caprec;
	char **keep;            /* strings handed out by dem_scene_string */
	size_t nkeep, capkeep;
	char **files;           /* library files read, named by their nodes */
	size_t nfiles, capfiles;
	struct use *use;
	size_t nuse, capuse;
};

/* ---- small helpers ------------------------------------------------------- */

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
	size_t c = *cap ? *cap : 8;
	void *q;

	if (need <= *cap)
		return 0;
	while (c < need)
		c *= 2;
	q = realloc(*p, c * size);
	if (!q)
		return -1;
	*p = q;
	*cap = c;
	return 0;
}

static char *xstrndup(const char *s, size_t n)
{
	char *d = malloc(n + 1);

	if (d) {
		memcpy(d, s, n);
		d[n] = '\0';
	}
	return d;
}

static char *xasprintf(const char *fmt, ...)
	__attribute__((format(printf, 1, 2)));

static char *xasprintf(const char *fmt, ...)
{
	va_list ap;
	char *buf;
	int n;

	va_start(ap, fmt);
	n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	if (n < 0)
		return NULL;
	buf = malloc((size_t)n + 1);
	if (!buf)
		return NULL;
	va_start(ap, fmt);
	vsnprintf(buf, (size_t)n + 1, fmt, ap);
	va_end(ap);
	return buf;
}

/* ---- the tree ------------------------------------------------------------ */

static struct node *node_new(enum node_kind kind, long line, long col)
{
	struct node *n = calloc(1, sizeof *n);

	if (n) {
		n->kind = kind;
		n->line = line;
		n->col = col;
	}
	return n;
}

static void node_free(struct node *n)
{
	size_t i;

	if (!n)
		return;
	for (i = 0; i < n->n; i++) {
		free(n->ent[i].key);
		node_free(n->ent[i].val);
	}
	free(n->ent);
	free(n->text);
	free(n->origin);
	free(n);
}

static struct entry *node_push(struct node *n)
{
	struct entry *en;

	if (grow((void **)&n->ent, &n->cap, n->n + 1, sizeof *n->ent) < 0)
		return NULL;
	en = &n->ent[n->n++];
	memset(en, 0, sizeof *en);
	return en;
}

/* YAML's null: an empty plain scalar, ~ or null. */
static int node_is_null(const struct node *n)
{
	return n->kind == NODE_SCALAR && n->plain &&
	       (n->text[0] == '\0' || strcmp(n->text, "~") == 0 ||
		strcmp(n->text, "null") == 0 || strcmp(n->text, "Null") == 0 ||
		strcmp(n->text, "NULL") == 0);
}

static struct entry *map_find(const struct node *map, const char *key,
			      size_t len)
{
	size_t i;

	for (i = 0; i < map->n; i++) {
		const char *k = map->ent[i].key;

		if (k && strlen(k) == len && memcmp(k, key, len) == 0)
			return &map->ent[i];
	}
	return NULL;
}

/* ---- messages ------------------------------------------------------------ */

/* file NULL is the scene's own file. */
static void where(const dem_scene_t *s, const char *file, const char *origin,
		  long line, long col, char *buf, size_t len)
{
	if (origin)
		snprintf(buf, len, "command line: %s", origin);
	else if (file)
		snprintf(buf, len, "%s:%ld:%ld", file, line, col);
	else
		snprintf(buf, len, "%s:%ld:%ld", s->name ? s->name : "scene",
			 line, col);
}

static int vfail_at(const dem_scene_t *s, const char *file,
		    const char *origin, long line, long col, dem_error_t *e,
		    int code, const char *fmt, va_list ap)
{
	char w[512], msg[768];

	where(s, file, origin, line, col, w, sizeof w);
	vsnprintf(msg, sizeof msg, fmt, ap);
	/* a bad value typed on the command line is a usage error (exit 2) */
	if (origin && code == DEM_EINPUT)
		code = DEM_EUSAGE;
	return dem_error_set(e, code, "%s: %s", w, msg);
}

static int fail_at(const dem_scene_t *s, const char *file, const char *origin,
		   long line, long col, dem_error_t *e, const char *fmt, ...)
	__attribute__((format(printf, 7, 8)));

static int fail_at(const dem_scene_t *s, const char *file, const char *origin,
		   long line, long col, dem_error_t *e, const char *fmt, ...)
{
	va_list ap;
	int code;

	va_start(ap, fmt);
	code = vfail_at(s, file, origin, line, col, e, DEM_EINPUT, fmt, ap);
	va_end(ap);
	return code;
}

/* An input error at node n. */
static int fail(const dem_scene_t *s, const struct node *n, dem_error_t *e,
		const char *fmt, ...) __attribute__((format(printf, 4, 5)));

static int fail(const dem_scene_t *s, const struct node *n, dem_error_t *e,
		const char *fmt, ...)
{
	va_list ap;
	int code;

	va_start(ap, fmt);
	code = vfail_at(s, n->file, n->origin, n->line, n->col, e, DEM_EINPUT,
			fmt, ap);
	va_end(ap);
	return code;
}

/* What a node is, for "got ...": a mapping, a sequence, an empty value, or
 * the scalar quoted, shortened and kept on one line. */
static const char *describe(const struct node *n, char *buf, size_t len)
{
	const size_t max = 60;
	size_t i, k = 0;

	if (n->kind == NODE_MAP)
		return "a mapping";
	if (n->kind == NODE_SEQ)
		return "a sequence";
	if (node_is_null(n))
		return "an empty value";
	if (len < max + 8)
		return "a value";
	buf[k++] = '\'';
	for (i = 0; n->text[i] && i < max; i++) {
		unsigned char c = (unsigned char)n->text[i];

		buf[k++] = c < 0x20 || c == 0x7f ? ' ' : (char)c;
	}
	if (n->text[i]) {
		memcpy(buf + k, "...", 3);
		k += 3;
	}
	buf[k++] = '\'';
	buf[k] = '\0';
	return buf;
}

/* ---- loading ------------------------------------------------------------- */

static int read_all(const char *path, char **buf, size_t *len,
		    dem_error_t *e)
{
	FILE *f = fopen(path, "rb");
	size_t cap = 0, n = 0, got;
	char *p = NULL;

	if (!f)
		return dem_error_set(e, DEM_EIO, "%s: %s", path,
				     strerror(errno));
	do {
		if (grow((void **)&p, &cap, n + 4096, 1) < 0) {
			free(p);
			fclose(f);
			return dem_error_nomem(e, "scene file");
		}
		got = fread(p + n, 1, cap - n, f);
		n += got;
	} while (got > 0);
	if (ferror(f)) {
		int err = errno;

		free(p);
		fclose(f);
		return dem_error_set(e, DEM_EIO, "%s: %s", path,
				     strerror(err ? err : EIO));
	}
	fclose(f);
	*buf = p;
	*len = n;
	return DEM_OK;
}

/* The state of building the tree from libyaml's events. */
struct builder {
	dem_scene_t *s;
	const char *file;       /* a library file, or NULL for the scene */
	struct node **stack;    /* open mappings and sequences */
	size_t depth, cap;
	struct node *root;
	int docs;
};

/* The dotted path of the innermost open container, for messages: each
 * open container hangs from the last entry of the one below it. */
static void builder_path(const struct builder *b, char *buf, size_t len)
{
	size_t i, k = 0;

	buf[0] = '\0';
	for (i = 1; i < b->depth && k < len; i++) {
		const struct node *up = b->stack[i - 1];
		const struct entry *en = &up->ent[up->n - 1];
		int w;

		if (en->key)
			w = snprintf(buf + k, len - k, "%s%s", k ? "." : "",
				     en->key);
		else
			w = snprintf(buf + k, len - k, "[%zu]", up->n - 1);
		if (w > 0)
			k += (size_t)w;
	}
}

/* Hang node n (just read) where it belongs: the root, a sequence item, a
 * mapping key or a mapping value.  Takes ownership of n. */
static int builder_attach(struct builder *b, struct node *n, dem_error_t *e)
{
	const struct entry *first;
	struct node *top;
	struct entry *en;
	char path[512], got[80];

	if (b->depth == 0) {
		b->root = n;
		return DEM_OK;
	}
	top = b->stack[b->depth - 1];
	if (top->kind == NODE_MAP && top->n > 0 && !top->ent[top->n - 1].val) {
		top->ent[top->n - 1].val = n;
		return DEM_OK;
	}
	if (top->kind == NODE_MAP && n->kind != NODE_SCALAR) {
		fail(b->s, n, e, "a key must be a name, got %s",
		     describe(n, got, sizeof got));
		node_free(n);
		return e->code;
	}
	first = top->kind == NODE_MAP ?
		map_find(top, n->text, strlen(n->text)) : NULL;
	if (first) {
		builder_path(b, path, sizeof path);
		fail(b->s, n, e, "duplicate key '%s%s%s' (first at line %ld)",
		     path, path[0] ? "." : "", n->text, first->line);
		node_free(n);
		return e->code;
	}
	en = node_push(top);
	if (!en) {
		node_free(n);
		return dem_error_nomem(e, "scene");
	}
	if (top->kind == NODE_SEQ) {
		en->val = n;
		return DEM_OK;
	}
	en->key = n->text;
	en->line = n->line;
	en->col = n->col;
	n->text = NULL;
	node_free(n);
	return DEM_OK;
}

static int builder_open(struct builder *b, enum node_kind kind,
			const yaml_mark_t *m, dem_error_t *e)
{
	struct node *n = node_new(kind, (long)m->line + 1, (long)m->column + 1);
	int code;

	if (!n)
		return dem_error_nomem(e, "scene");
	n->file = b->file;
	if (b->depth >= MAX_DEPTH) {
		fail(b->s, n, e, "nested deeper than %d levels", MAX_DEPTH);
		node_free(n);
		return e->code;
	}
	code = builder_attach(b, n, e);
	if (code != DEM_OK)
		return code;
	if (grow((void **)&b->stack, &b->cap, b->depth + 1,
		 sizeof *b->stack) < 0)
		return dem_error_nomem(e, "scene");
	b->stack[b->depth++] = n;
	return DEM_OK;
}

static int builder_scalar(struct builder *b, const yaml_event_t *ev,
			  dem_error_t *e)
{
	const yaml_mark_t *m = &ev->start_mark;
	struct node *n = node_new(NODE_SCALAR, (long)m->line + 1,
				  (long)m->column + 1);

	if (!n)
		return dem_error_nomem(e, "scene");
	n->file = b->file;
	n->text = xstrndup((const char *)ev->data.scalar.value,
			   ev->data.scalar.length);
	if (!n->text) {
		node_free(n);
		return dem_error_nomem(e, "scene");
	}
	n->plain = ev->data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
	return builder_attach(b, n, e);
}

static int builder_event(struct builder *b, const yaml_event_t *ev,
			 dem_error_t *e)
{
	const yaml_mark_t *m = &ev->start_mark;

	switch (ev->type) {
	case YAML_DOCUMENT_START_EVENT:
		if (++b->docs > 1)
			return fail_at(b->s, b->file, NULL, (long)m->line + 1,
				       (long)m->column + 1, e,
				       "a second document; %s is one YAML "
				       "document", b->file ? "a library file" :
				       "a scene");
		return DEM_OK;
	case YAML_ALIAS_EVENT:
		/* aliases would make one value appear under several keys,
		 * which the unknown-key check and the dump cannot follow */
		return fail_at(b->s, b->file, NULL, (long)m->line + 1,
			       (long)m->column + 1, e,
			       "aliases (*%s) are not supported",
			       (const char *)ev->data.alias.anchor);
	case YAML_SCALAR_EVENT:
		return builder_scalar(b, ev, e);
	case YAML_SEQUENCE_START_EVENT:
		return builder_open(b, NODE_SEQ, m, e);
	case YAML_MAPPING_START_EVENT:
		return builder_open(b, NODE_MAP, m, e);
	case YAML_SEQUENCE_END_EVENT:
	case YAML_MAPPING_END_EVENT:
		b->depth--;
		return DEM_OK;
	default:
		return DEM_OK;
	}
}

/* libyaml's reader reports a byte offset, not a mark: count lines. */
static void offset_to_mark(const char *buf, size_t len, size_t off,
			   long *line, long *col)
{
	size_t i, start = 0;

	*line = 1;
	for (i = 0; i < off && i < len; i++)
		if (buf[i] == '\n') {
			(*line)++;
			start = i + 1;
		}
	*col = (long)(off - start) + 1;
}

static int syntax_error(const dem_scene_t *s, const char *file,
			const yaml_parser_t *p, const char *buf, size_t len,
			dem_error_t *e)
{
	long line, col;

	switch (p->error) {
	case YAML_MEMORY_ERROR:
		return dem_error_nomem(e, "scene parser");
	case YAML_READER_ERROR:
		offset_to_mark(buf, len, p->problem_offset, &line, &col);
		return fail_at(s, file, NULL, line, col, e, "%s", p->problem);
	default:
		if (p->context)
			return fail_at(s, file, NULL,
				       (long)p->problem_mark.line + 1,
				       (long)p->problem_mark.column + 1, e,
				       "%s (%s at line %ld, column %ld)",
				       p->problem, p->context,
				       (long)p->context_mark.line + 1,
				       (long)p->context_mark.column + 1);
		return fail_at(s, file, NULL, (long)p->problem_mark.line + 1,
			       (long)p->problem_mark.column + 1, e, "%s",
			       p->problem ? p->problem : "syntax error");
	}
}

/* The top level must be a mapping (of sections, or of a library's
 * settings); an empty file, or a document holding only null, is an empty
 * mapping.  Hands the mapping to *out (NULL when empty). */
static int builder_root(struct builder *b, struct node **out, dem_error_t *e)
{
	struct node *r = b->root;
	char got[80];

	if (!r || node_is_null(r)) {
		node_free(r);
		b->root = NULL;
		return DEM_OK;
	}
	if (r->kind != NODE_MAP && b->file)
		return fail(b->s, r, e, "a library file is a mapping of a "
			    "section's settings (E:, nu:, ...), got %s",
			    describe(r, got, sizeof got));
	if (r->kind != NODE_MAP)
		return fail(b->s, r, e, "a scene is a mapping of sections "
			    "(pack:, detect:, ...), got %s",
			    describe(r, got, sizeof got));
	*out = r;
	b->root = NULL;
	return DEM_OK;
}

/* Parse the YAML text of file (NULL: the scene's own) into *out, a mapping
 * or NULL when empty. */
static int parse_text(dem_scene_t *s, const char *file, const char *buf,
		      size_t len, struct node **out, dem_error_t *e)
{
	struct builder b = { s, file, NULL, 0, 0, NULL, 0 };
	yaml_parser_t p;
	yaml_event_t ev;
	int code = DEM_OK, done = 0;

	if (!yaml_parser_initialize(&p))
		return dem_error_nomem(e, "scene parser");
	yaml_parser_set_input_string(&p, (const unsigned char *)buf, len);
	while (!done && code == DEM_OK) {
		if (!yaml_parser_parse(&p, &ev)) {
			code = syntax_error(s, file, &p, buf, len, e);
			break;
		}
		done = ev.type == YAML_STREAM_END_EVENT;
		code = builder_event(&b, &ev, e);
		yaml_event_delete(&ev);
	}
	yaml_parser_delete(&p);
	*out = NULL;
	if (code == DEM_OK)
		code = builder_root(&b, out, e);
	node_free(b.root);
	free(b.stack);
	return code;
}

/* ---- library files (use:) ----------------------------------------------- */

static char *yaml_text(const char *s);

static const char *library_folder(const char *section)
{
	size_t i;

	for (i = 0; i < COUNT(library_folders); i++)
		if (strcmp(library_folders[i].section, section) == 0)
			return library_folders[i].folder;
	return NULL;
}

static const struct use *use_find(const dem_scene_t *s, const char *section,
				  size_t len)
{
	size_t i;

	for (i = 0; i < s->nuse; i++)
		if (strlen(s->use[i].section) == len &&
		    memcmp(s->use[i].section, section, len) == 0)
			return &s->use[i];
	return NULL;
}

/* Keep the name of a library file for the life of the scene: its nodes
 * point at it. */
static const char *keep_file(dem_scene_t *s, const char *path)
{
	char *c;

	if (grow((void **)&s->files, &s->capfiles, s->nfiles + 1,
		 sizeof *s->files) < 0 || !(c = strdup(path)))
		return NULL;
	s->files[s->nfiles++] = c;
	return c;
}

/* Note the section's "use:" for --dump-scene: the name as written, and
 * where it was found as a comment when the path can be one. */
static int add_use(dem_scene_t *s, const char *section, const char *name,
		   const char *path, dem_error_t *e)
{
	char *text = yaml_text(name), *sec = strdup(section), *t;
	size_t i;

	for (i = 0; text && path[i]; i++)
		if ((unsigned char)path[i] < 0x20 || path[i] == 0x7f)
			break;
	if (text && !path[i]) {
		t = xasprintf("%s  # %s", text, path);
		free(text);
		text = t;
	}
	if (!text || !sec || grow((void **)&s->use, &s->capuse, s->nuse + 1,
				   sizeof *s->use) < 0) {
		free(text);
		free(sec);
		return dem_error_nomem(e, "scene library");
	}
	s->use[s->nuse].section = sec;
	s->use[s->nuse++].text = text;
	return DEM_OK;
}

/* A name with a '/' or ending in .yaml is a path; any other is looked up in
 * the data directory, and must be a plain file name there. */
static int use_is_path(const char *name)
{
	size_t n = strlen(name);

	return strchr(name, '/') || (n >= 5 && !strcmp(name + n - 5, ".yaml"));
}

static int use_name_ok(const char *name)
{
	return name[0] && name[0] != '.' && name[0] != '-' &&
	       strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
		      "0123456789._-") == strlen(name);
}

#define USE_WANT "a library name (e.g. 'al7075') or a path to a .yaml file"

/* The file that "use: NAME" (node n, in section) names: a path, relative
 * to the scene's folder unless absolute, or NAME.yaml in the section's
 * folder of the data directory.  *path is malloc'd. */
static int use_path(const dem_scene_t *s, const char *section,
		    const char *folder, const struct node *n, char **path,
		    dem_error_t *e)
{
	const char *name = n->text, *slash = s->name ? strrchr(s->name, '/') :
					     NULL;
	char tried[8192 + 256], *file;
	const char *why;
	struct stat st;
	int rc;

	*path = NULL;
	if (use_is_path(name)) {
		if (name[0] == '/' || !slash)
			*path = strdup(name);
		else
			*path = xasprintf("%.*s/%s", (int)(slash - s->name),
					  s->name, name);
		if (!*path)
			return dem_error_nomem(e, "scene library");
		if (stat(*path, &st) != 0)
			why = strerror(errno);
		else if (!S_ISREG(st.st_mode))
			why = "not a regular file";
		else
			return DEM_OK;
		rc = fail(s, n, e, "%s.use: cannot read '%s': %s", section,
			  *path, why);
		free(*path);
		*path = NULL;
		return rc;
	}
	if (!use_name_ok(name))
		return fail(s, n, e, "%s.use: expected " USE_WANT ", got "
			    "'%.60s'", section, name);
	file = xasprintf("%s.yaml", name);
	if (!file)
		return dem_error_nomem(e, "scene library");
	rc = dem_share_find(folder, file, path, tried, sizeof tried);
	free(file);
	if (rc < 0)
		return dem_error_nomem(e, "scene library");
	if (rc > 0)
		return fail(s, n, e, "%s.use: unknown library '%s': no "
			    "%s.yaml in %s", section, name, name, tried);
	return DEM_OK;
}

/* Merge the library mapping lib into the section's mapping sec, taking
 * lib: a key the scene gives wins; where both give a mapping, the two
 * merge key by key; sequences and scalars are never mixed.  Returns -1
 * when out of memory. */
static int merge(struct node *sec, struct node *lib)
{
	size_t i;
	int rc = 0;

	for (i = 0; i < lib->n && rc == 0; i++) {
		struct entry *src = &lib->ent[i], *dst;

		dst = map_find(sec, src->key, strlen(src->key));
		if (!dst) {
			dst = node_push(sec);
			if (!dst) {
				rc = -1;
				break;
			}
			*dst = *src;
			src->key = NULL;
			src->val = NULL;
		} else if (dst->val->kind == NODE_MAP &&
			   src->val->kind == NODE_MAP) {
			rc = merge(dst->val, src->val);
			src->val = NULL;
		}
	}
	node_free(lib);
	return rc;
}

/* Read the library file named by section sec's "use:" (node u) and merge
 * it into the section. */
static int load_use(dem_scene_t *s, struct entry *sec, const struct node *u,
		    const char *folder, dem_error_t *e)
{
	char got[80], *path, *buf = NULL;
	const struct entry *inner;
	struct node *lib = NULL;
	const char *file;
	size_t len = 0;
	int code;

	if (u->kind != NODE_SCALAR || node_is_null(u))
		return fail(s, u, e, "%s.use: expected " USE_WANT ", got %s",
			    sec->key, describe(u, got, sizeof got));
	code = use_path(s, sec->key, folder, u, &path, e);
	if (code != DEM_OK)
		return code;
	file = keep_file(s, path);
	free(path);
	if (!file)
		return dem_error_nomem(e, "scene library");
	code = read_all(file, &buf, &len, e);
	if (code == DEM_OK)
		code = parse_text(s, file, buf, len, &lib, e);
	free(buf);
	if (code != DEM_OK)
		return code;
	/* one level only: a chain of files would hide where a value is */
	inner = lib ? map_find(lib, "use", 3) : NULL;
	if (inner)
		code = fail_at(s, file, NULL, inner->line, inner->col, e,
			       "%s.use: a library file cannot use another "
			       "(use: is for scenes)", sec->key);
	if (code == DEM_OK)
		code = add_use(s, sec->key, u->text, file, e);
	if (code != DEM_OK) {
		node_free(lib);
		return code;
	}
	if (lib && merge(sec->val, lib) < 0)
		return dem_error_nomem(e, "scene library");
	return DEM_OK;
}

/* Pull in the library files that sections name with "use:". */
static int load_uses(dem_scene_t *s, dem_error_t *e)
{
	char list[128];
	size_t i, j, k;
	int code = DEM_OK;

	for (i = 0; i < s->root->n && code == DEM_OK; i++) {
		struct entry *sec = &s->root->ent[i];
		const struct entry *u;
		const char *folder;

		if (sec->val->kind != NODE_MAP ||
		    !(u = map_find(sec->val, "use", 3)))
			continue;
		folder = library_folder(sec->key);
		if (folder) {
			code = load_use(s, sec, u->val, folder, e);
			continue;
		}
		for (j = k = 0; j < COUNT(library_folders) && k < sizeof list;
		     j++)
			k += (size_t)snprintf(list + k, sizeof list - k, "%s%s",
					      j == 0 ? "" :
					      j + 1 < COUNT(library_folders) ?
					      ", " : " and ",
					      library_folders[j].section);
		code = fail_at(s, NULL, NULL, u->line, u->col, e,
			       "%s.use: only the sections %s take a library "
			       "file (use:)", sec->key, list);
	}
	return code;
}

static int check_sections(const dem_scene_t *s, dem_error_t *e);

int dem_scene_load(dem_scene_t **sp, const char *path, dem_error_t *e)
{
	dem_scene_t *s = calloc(1, sizeof *s);
	struct node *root = NULL;
	char *buf = NULL;
	size_t len = 0;
	int code;

	*sp = NULL;
	if (!s || !(s->root = node_new(NODE_MAP, 0, 0))) {
		free(s);
		return dem_error_nomem(e, "scene");
	}
	if (path) {
		s->name = strdup(path);
		if (!s->name)
			code = dem_error_nomem(e, "scene");
		else
			code = read_all(path, &buf, &len, e);
		if (code == DEM_OK)
			code = parse_text(s, NULL, buf, len, &root, e);
		free(buf);
		if (root) {
			node_free(s->root);
			s->root = root;
		}
		/* a misspelt section first: its own keys would otherwise be
		 * reported missing from the section meant */
		if (code == DEM_OK)
			code = check_sections(s, e);
		if (code == DEM_OK)
			code = load_uses(s, e);
		if (code != DEM_OK) {
			dem_scene_free(s);
			return code;
		}
	}
	*sp = s;
	return DEM_OK;
}

void dem_scene_free(dem_scene_t *s)
{
	size_t i;

	if (!s)
		return;
	node_free(s->root);
	for (i = 0; i < s->nrec; i++) {
		free(s->rec[i].key);
		free(s->rec[i].val);
	}
	for (i = 0; i < s->nkeep; i++)
		free(s->keep[i]);
	for (i = 0; i < s->nfiles; i++)
		free(s->files[i]);
	for (i = 0; i < s->nuse; i++) {
		free(s->use[i].section);
		free(s->use[i].text);
	}
	free(s->rec);
	free(s->keep);
	free(s->files);
	free(s->use);
	free(s->name);
	free(s);
}

/* ---- looking up dotted keys ---------------------------------------------- */

/* Find key.  Returns 1 and the node, 0 if absent, or -1 (with e, if given)
 * when a part of the path is there but is not a mapping. */
static int lookup(const dem_scene_t *s, const char *key, struct node **out,
		  dem_error_t *e)
{
	struct node *cur = s->root;
	const char *p = key;
	char got[80];

	for (;;) {
		size_t len = strcspn(p, ".");
		const struct entry *en;

		if (node_is_null(cur))
			return 0;
		if (cur->kind != NODE_MAP) {
			if (e)
				fail(s, cur, e, "%.*s: expected a mapping, got %s",
				     (int)(p - key - 1), key,
				     describe(cur, got, sizeof got));
			return -1;
		}
		en = map_find(cur, p, len);
		if (!en)
			return 0;
		cur = en->val;
		if (p[len] == '\0')
			break;
		p += len + 1;
	}
	*out = cur;
	return 1;
}

int dem_scene_has(const dem_scene_t *s, const char *key)
{
	struct node *n;

	return lookup(s, key, &n, NULL) == 1;
}

int dem_scene_length(const dem_scene_t *s, const char *key)
{
	struct node *n;
	const char *c;
	int k = 1;

	if (lookup(s, key, &n, NULL) != 1 || node_is_null(n))
		return -1;
	if (n->kind == NODE_SEQ)
		return (int)n->n;
	if (n->kind != NODE_SCALAR)
		return 0;
	for (c = n->text; *c; c++)
		k += *c == ',';
	return k;
}

int dem_scene_error(const dem_scene_t *s, const char *key, dem_error_t *e,
		    const char *fmt, ...)
{
	struct node *n;
	char msg[768];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (lookup(s, key, &n, NULL) == 1)
		return fail(s, n, e, "%s: %s", key, msg);
	return dem_error_set(e, DEM_EINPUT, "%s: %s", key, msg);
}

/* ---- overrides ----------------------------------------------------------- */

static int key_valid(const char *key)
{
	const char *p = key;

	if (!key || !*key)
		return 0;
	for (;;) {
		size_t len = strcspn(p, ".");

		if (len == 0)
			return 0;
		if (p[len] == '\0')
			return 1;
		p += len + 1;
	}
}

static struct node *override_node(enum node_kind kind, const char *text,
				  const char *origin)
{
	struct node *n = node_new(kind, 0, 0);

	if (!n)
		return NULL;
	n->origin = strdup(origin);
	n->text = text ? strdup(text) : NULL;
	if (!n->origin || (text && !n->text)) {
		node_free(n);
		return NULL;
	}
	return n;
}

/* Set the value under key part p[0..len) of map to n (taking it). */
static int map_set(struct node *map, const char *p, size_t len,
		   struct node *n)
{
	struct entry *en = map_find(map, p, len);

	if (!en) {
		en = node_push(map);
		if (!en || !(en->key = xstrndup(p, len))) {
			if (en)
				map->n--;
			node_free(n);
			return -1;
		}
	}
	node_free(en->val);
	en->val = n;
	return 0;
}

int dem_scene_override_all(dem_scene_t *s, const struct dem_override *ov,
			   int n, dem_error_t *e)
{
	for (int i = 0; i < n; i++) {
		int rc = dem_scene_override(s, ov[i].key, ov[i].text, ov[i].origin, e);
		if (rc)
			return rc;
	}
	return DEM_OK;
}

int dem_scene_open(dem_scene_t **s, const dem_common_t *m, dem_error_t *e)
{
	int rc = dem_scene_load(s, m->scene, e);
	return rc ? rc : dem_scene_override_all(*s, m->ov, m->nov, e);
}

int dem_scene_override(dem_scene_t *s, const char *key, const char *text,
		       const char *origin, dem_error_t *e)
{
	struct node *cur = s->root, *n;
	const char *p = key;
	char got[80], w[256];

	if (!origin)
		origin = key ? key : "?";
	if (!key_valid(key))
		return dem_error_set(e, DEM_EUSAGE, "command line: %s: bad "
				     "scene key '%s'", origin, key ? key : "");
	/* a library file is merged as the scene loads, before any option */
	if (!strcmp(key + strcspn(key, "."), ".use"))
		return dem_error_set(e, DEM_EUSAGE, "command line: %s: %s "
				     "cannot be set on the command line; write "
				     "it in the scene", origin, key);
	for (;;) {
		size_t len = strcspn(p, ".");
		struct entry *en;

		if (p[len] == '\0') {
			n = override_node(NODE_SCALAR, text ? text : "", origin);
			if (!n || map_set(cur, p, len, n) < 0)
				return dem_error_nomem(e, "scene override");
			return DEM_OK;
		}
		en = map_find(cur, p, len);
		if (en && en->val->kind != NODE_MAP && !node_is_null(en->val)) {
			where(s, en->val->file, en->val->origin, en->val->line,
			      en->val->col, w, sizeof w);
			return dem_error_set(e, DEM_EUSAGE, "command line: %s: "
					     "cannot set %s: %.*s is %s (%s)",
					     origin, key, (int)(p - key + len),
					     key, describe(en->val, got,
							   sizeof got), w);
		}
		if (!en || en->val->kind != NODE_MAP) {
			n = override_node(NODE_MAP, NULL, origin);
			if (!n || map_set(cur, p, len, n) < 0)
				return dem_error_nomem(e, "scene override");
			en = map_find(cur, p, len);
		}
		cur = en->val;
		p += len + 1;
	}
}

/* ---- records: what the getters asked for and resolved -------------------- */

static struct rec *rec_find(const dem_scene_t *s, const char *key)
{
	size_t i;

	for (i = 0; i < s->nrec; i++)
		if (strcmp(s->rec[i].key, key) == 0)
			return &s->rec[i];
	return NULL;
}

/* Before the first key asked in a section that uses a library file, record
 * its "use:", so that --dump-scene shows first where the section's values
 * came from.  Returns -1 when out of memory. */
static int rec_use(dem_scene_t *s, const char *key)
{
	size_t len = strcspn(key, ".");
	const struct use *u = use_find(s, key, len);
	char *k;

	if (!u || key[len] == '\0')
		return 0;
	k = xasprintf("%s.use", u->section);
	if (!k)
		return -1;
	if (!strcmp(k, key) || rec_find(s, k)) {
		free(k);
		return 0;
	}
	if (grow((void **)&s->rec, &s->caprec, s->nrec + 1,
		 sizeof *s->rec) < 0 || !(s->rec[s->nrec].val = strdup(u->text))) {
		free(k);
		return -1;
	}
	s->rec[s->nrec++].key = k;
	return 0;
}

/* Note that key was asked for; returns its index or -1 (out of memory). */
static long rec_ask(dem_scene_t *s, const char *key, dem_error_t *e)
{
	struct rec *r = rec_find(s, key);

	if (r)
		return (long)(r - s->rec);
	if (rec_use(s, key) < 0) {
		dem_error_nomem(e, "scene record");
		return -1;
	}
	if (grow((void **)&s->rec, &s->caprec, s->nrec + 1,
		 sizeof *s->rec) < 0 || !(s->rec[s->nrec].key = strdup(key))) {
		dem_error_nomem(e, "scene record");
		return -1;
	}
	s->rec[s->nrec].val = NULL;
	return (long)s->nrec++;
}

/* Store the resolved value (taking val; NULL means out of memory). */
static int rec_value(dem_scene_t *s, long i, char *val, dem_error_t *e)
{
	if (!val)
		return dem_error_nomem(e, "scene record");
	free(s->rec[i].val);
	s->rec[i].val = val;
	return DEM_OK;
}

static char *quantity_text(double v, dem_dim_t dim)
{
	char num[32], unit[64];

	dem_fmt_double(num, v);
	dem_dim_format(dim, unit, sizeof unit);
	return xasprintf("%s%s%s", num, unit[0] ? " " : "", unit);
}

/* Can s be written as a plain YAML scalar that reads back as the same
 * string (and not as null)?  Conservative: a few safe characters only. */
static int plain_ok(const char *s)
{
	if (!*s || *s == '-' || strcasecmp(s, "null") == 0)
		return 0;
	return strspn(s, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
		      "0123456789_./+-") == strlen(s);
}

/* s as a YAML scalar: plain when safe, else double-quoted. */
static char *yaml_text(const char *s)
{
	char *buf, *q;
	size_t i;

	if (plain_ok(s))
		return strdup(s);
	buf = malloc(4 * strlen(s) + 3);
	if (!buf)
		return NULL;
	q = buf;
	*q++ = '"';
	for (i = 0; s[i]; i++) {
		unsigned char c = (unsigned char)s[i];

		if (c == '"' || c == '\\') {
			*q++ = '\\';
			*q++ = (char)c;
		} else if (c < 0x20 || c == 0x7f) {
			q += sprintf(q, "\\x%02x", c);
		} else {
			*q++ = (char)c;
		}
	}
	*q++ = '"';
	*q = '\0';
	return buf;
}

/* ---- getters ------------------------------------------------------------- */

/* Find key as a non-null scalar.  Returns 1 (found), 0 (absent) or -1 with
 * "KEY: expected WANT, got ..." for anything else. */
static int get_scalar(const dem_scene_t *s, const char *key, const char *want,
		      struct node **out, dem_error_t *e)
{
	char got[80];
	int rc = lookup(s, key, out, e);

	if (rc != 1)
		return rc;
	if ((*out)->kind != NODE_SCALAR || node_is_null(*out)) {
		fail(s, *out, e, "%s: expected %s, got %s", key, want,
		     describe(*out, got, sizeof got));
		return -1;
	}
	return 1;
}

/* "a velocity (e.g. '46.5 m/s')" */
static void want_quantity(dem_dim_t dim, char *buf, size_t len)
{
	char d[96], ex[96];

	dem_dim_describe(dim, 0, d, sizeof d);
	dem_dim_example(dim, ex, sizeof ex);
	snprintf(buf, len, "%s (e.g. '%s')", d, ex);
}

/* The range part of "expected a length of at least 0 m": bounds are text,
 * NULL when infinite; open_lo for the (0, ...) of DEM_SCENE_GT0. */
static void range_text(const char *lo, const char *hi, int open_lo,
		       const char *unit, char *buf, size_t len)
{
	const char *sp = unit[0] ? " " : "";

	if (lo && hi)
		snprintf(buf, len, " in %s%s, %s]%s%s", open_lo ? "(" : "[",
			 open_lo ? "0" : lo, hi, sp, unit);
	else if (lo && open_lo)
		snprintf(buf, len, " greater than 0%s%s", sp, unit);
	else if (lo)
		snprintf(buf, len, " of at least %s%s%s", lo, sp, unit);
	else if (hi)
		snprintf(buf, len, " of at most %s%s%s", hi, sp, unit);
	else
		buf[0] = '\0';
}

static int is_bare_number(const char *text)
{
	char *end;

	strtod(text, &end);
	while (isspace((unsigned char)*end))
		end++;
	return *end == '\0';
}

/* Parse text (from node n, named label) as a quantity in [min, max]. */
static int parse_quantity(const dem_scene_t *s, const struct node *n,
			  const char *label, const char *text, dem_dim_t dim,
			  double min, double max, double *out, dem_error_t *e)
{
	char why[256], want[256], d[96], lo[32], hi[32], unit[64], range[200];
	char si[160], shown[32];
	double v;

	want_quantity(dim, want, sizeof want);
	if (dem_units_parse(text, dim, &v, why, sizeof why) < 0) {
		/* a wrong dimension already says what was expected */
		if (strstr(why, ", expected "))
			return fail(s, n, e, "%s: %s (e.g. '%s')", label, why,
				    dem_dim_example(dim, d, sizeof d));
		return fail(s, n, e, "%s: expected %s, got '%.60s' (%s)",
			    label, want, text, why);
	}
	if (v >= min && v <= max) {
		*out = v;
		return DEM_OK;
	}
	dem_fmt_double(lo, min);
	dem_fmt_double(hi, max);
	dem_dim_format(dim, unit, sizeof unit);
	range_text(isinf(min) ? NULL : lo, isinf(max) ? NULL : hi,
		   min == DBL_TRUE_MIN, unit, range, sizeof range);
	si[0] = '\0';
	if (!is_bare_number(text)) {
		dem_fmt_double(shown, v);
		snprintf(si, sizeof si, " (= %s%s%s)", shown,
			 unit[0] ? " " : "", unit);
	}
	return fail(s, n, e, "%s: %.60s%s is out of range, expected %s%s",
		    label, text, si, dem_dim_describe(dim, 0, d, sizeof d),
		    range);
}

int dem_scene_quantity(dem_scene_t *s, const char *key, dem_dim_t dim,
		       double def, double min, double max, double *out,
		       dem_error_t *e)
{
	char want[256];
	struct node *n;
	double v = def;
	long r = rec_ask(s, key, e);
	int rc;

	if (r < 0)
		return e->code;
	want_quantity(dim, want, sizeof want);
	rc = get_scalar(s, key, want, &n, e);
	if (rc < 0)
		return e->code;
	if (rc == 1 && parse_quantity(s, n, key, n->text, dim, min, max, &v,
				      e) != DEM_OK)
		return e->code;
	*out = v;
	/* a non-finite default means "not set": nothing to write back */
	return isfinite(v) ? rec_value(s, r, quantity_text(v, dim), e) : DEM_OK;
}

/* An integer as written ("12"), or a number that is one ("1e6").
 * Returns 0, or -1 if not an integer, or 1 if beyond the range of long. */
static int parse_long(const char *text, long *out)
{
	char *end, why[64];
	double d;
	long v;

	errno = 0;
	v = strtol(text, &end, 10);
	while (isspace((unsigned char)*end))
		end++;
	if (end != text && *end == '\0') {
		*out = v;
		return errno == ERANGE ? 1 : 0;
	}
	if (dem_units_parse(text, DEM_DIM_NONE, &d, why, sizeof why) < 0 ||
	    d != floor(d))
		return -1;
	if (d < -0x1p63 || d >= 0x1p63)
		return 1;
	*out = (long)d;
	return 0;
}

int dem_scene_int(dem_scene_t *s, const char *key, long def, long min,
		  long max, long *out, dem_error_t *e)
{
	char lo[32], hi[32], range[128];
	struct node *n;
	long v = def, r = rec_ask(s, key, e);
	int rc;

	if (r < 0)
		return e->code;
	rc = get_scalar(s, key, "an integer", &n, e);
	if (rc < 0)
		return e->code;
	if (rc == 1) {
		rc = parse_long(n->text, &v);
		if (rc < 0)
			return fail(s, n, e, "%s: expected an integer, got '%.60s'",
				    key, n->text);
		if (rc > 0 || v < min || v > max) {
			snprintf(lo, sizeof lo, "%ld", min);
			snprintf(hi, sizeof hi, "%ld", max);
			range_text(min == LONG_MIN ? NULL : lo,
				   max == LONG_MAX ? NULL : hi, 0, "", range,
				   sizeof range);
			return fail(s, n, e, "%s: %.60s is out of range, "
				    "expected an integer%s", key, n->text, range);
		}
	}
	*out = v;
	return rec_value(s, r, xasprintf("%ld", v), e);
}

int dem_scene_bool(dem_scene_t *s, const char *key, int def, int *out,
		   dem_error_t *e)
{
	const char *want = "true or false (or yes, no)";
	struct node *n;
	long r = rec_ask(s, key, e);
	int v = def != 0, rc;

	if (r < 0)
		return e->code;
	rc = get_scalar(s, key, want, &n, e);
	if (rc < 0)
		return e->code;
	if (rc == 1) {
		if (!strcasecmp(n->text, "true") || !strcasecmp(n->text, "yes"))
			v = 1;
		else if (!strcasecmp(n->text, "false") ||
			 !strcasecmp(n->text, "no"))
			v = 0;
		else
			return fail(s, n, e, "%s: expected %s, got '%.60s'",
				    key, want, n->text);
	}
	*out = v;
	return rec_value(s, r, strdup(v ? "true" : "false"), e);
}

int dem_scene_choice(dem_scene_t *s, const char *key,
		     const char *const *choices, int def, int *out,
		     dem_error_t *e)
{
	char want[512];
	struct node *n;
	size_t k = 0;
	long r = rec_ask(s, key, e);
	int i, count, rc, v = def;

	if (r < 0)
		return e->code;
	k = (size_t)snprintf(want, sizeof want, "one of");
	for (count = 0; choices[count]; count++)
		if (k < sizeof want)
			k += (size_t)snprintf(want + k, sizeof want - k, "%s %s",
					      count ? "," : "", choices[count]);
	rc = get_scalar(s, key, want, &n, e);
	if (rc < 0)
		return e->code;
	if (rc == 1) {
		for (i = 0; i < count && strcmp(choices[i], n->text); i++)
			;
		if (i == count)
			return fail(s, n, e, "%s: expected %s, got '%.60s'",
				    key, want, n->text);
		v = i;
	}
	*out = v;
	if (v < 0 || v >= count)
		return DEM_OK;      /* no default: nothing to write back */
	return rec_value(s, r, yaml_text(choices[v]), e);
}

/* The items of a vector written as one scalar, "[1, 2] mm" or "1, 2": each
 * item with the trailing unit appended.  For the command line, where a
 * YAML sequence cannot be written. */
static char **split_vector(const char *text, int *count)
{
	const char *p = text, *end, *unit = "", *q;
	char **items = NULL;
	size_t cap = 0;
	int n = 0;

	while (isspace((unsigned char)*p))
		p++;
	end = p + strlen(p);
	if (*p == '[') {
		q = strrchr(p, ']');
		if (!q)
			return NULL;
		unit = q + 1;
		while (isspace((unsigned char)*unit))
			unit++;
		end = q;
		p++;
	}
	for (;;) {
		size_t len = strcspn(p, ",");
		const char *stop = p + len < end ? p + len : end;

		if (grow((void **)&items, &cap, (size_t)n + 2, sizeof *items) < 0)
			goto nomem;
		items[n] = xasprintf("%.*s%s%s", (int)(stop - p), p,
				     unit[0] ? " " : "", unit);
		if (!items[n])
			goto nomem;
		items[++n] = NULL;
		if (stop >= end)
			break;
		p = stop + 1;
	}
	*count = n;
	return items;
nomem:
	while (n > 0)
		free(items[--n]);
	free(items);
	*count = -1;
	return NULL;
}

static void free_items(char **items)
{
	size_t i;

	for (i = 0; items && items[i]; i++)
		free(items[i]);
	free(items);
}

/* "2 lengths (e.g. '[0.7 mm, 0.7 mm]')" */
static void want_vector(dem_dim_t dim, int n, char *buf, size_t len)
{
	char d[96], ex[96];
	size_t k;
	int i;

	dem_dim_describe(dim, n != 1, d, sizeof d);
	dem_dim_example(dim, ex, sizeof ex);
	k = (size_t)snprintf(buf, len, "%d %s", n, d);
	if (n < 1 || n > 4 || k >= len)
		return;
	for (i = 0; i < n && k < len; i++)
		k += (size_t)snprintf(buf + k, len - k, "%s%s",
				      i ? ", " : " (e.g. '[", ex);
	if (k < len)
		snprintf(buf + k, len - k, "]')");
}

/* Read a vector written as a scalar (see split_vector). */
static int vector_scalar(const dem_scene_t *s, const struct node *n,
			 const char *key, dem_dim_t dim, int want, double min,
			 double max, double *v, dem_error_t *e)
{
	char wantbuf[256], label[512];
	int count = 0, i, code = DEM_OK;
	char **items = split_vector(n->text, &count);

	if (!items && count < 0)
		return dem_error_nomem(e, "scene vector");
	want_vector(dim, want, wantbuf, sizeof wantbuf);
	if (!items || count != want) {
		free_items(items);
		return fail(s, n, e, "%s: expected %s, got '%.60s'", key,
			    wantbuf, n->text);
	}
	for (i = 0; i < want && code == DEM_OK; i++) {
		snprintf(label, sizeof label, "%s[%d]", key, i);
		code = parse_quantity(s, n, label, items[i], dim, min, max,
				      &v[i], e);
	}
	free_items(items);
	return code;
}

static int vector_seq(const dem_scene_t *s, const struct node *n,
		      const char *key, dem_dim_t dim, int want, double min,
		      double max, double *v, dem_error_t *e)
{
	char wantbuf[256], label[512], got[80], d[96];
	size_t i;

	want_vector(dim, want, wantbuf, sizeof wantbuf);
	if (n->n != (size_t)want)
		return fail(s, n, e, "%s: expected %s, got a sequence of %zu",
			    key, wantbuf, n->n);
	for (i = 0; i < n->n; i++) {
		const struct node *it = n->ent[i].val;

		snprintf(label, sizeof label, "%s[%zu]", key, i);
		if (it->kind != NODE_SCALAR || node_is_null(it))
			return fail(s, it, e, "%s: expected %s, got %s", label,
				    dem_dim_describe(dim, 0, d, sizeof d),
				    describe(it, got, sizeof got));
		if (parse_quantity(s, it, label, it->text, dim, min, max,
				   &v[i], e) != DEM_OK)
			return e->code;
	}
	return DEM_OK;
}

static char *vector_text(const double *v, int n, dem_dim_t dim)
{
	char *buf = NULL, *q;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	int i;

	if (!f)
		return NULL;
	fputc('[', f);
	for (i = 0; i < n; i++) {
		q = quantity_text(v[i], dim);
		fprintf(f, "%s%s", i ? ", " : "", q ? q : "?");
		free(q);
	}
	fputc(']', f);
	if (fclose(f) != 0) {
		free(buf);
		return NULL;
	}
	return buf;
}

int dem_scene_vector(dem_scene_t *s, const char *key, dem_dim_t dim, int n,
		     const double *def, double min, double max, double *out,
		     dem_error_t *e)
{
	char wantbuf[256], got[80];
	struct node *node;
	double *v;
	long r = rec_ask(s, key, e);
	int rc, code = DEM_OK, i;

	if (r < 0)
		return e->code;
	rc = lookup(s, key, &node, e);
	if (rc < 0)
		return e->code;
	if (rc == 0) {
		if (!def)
			return DEM_OK;  /* no default: out stays as it is */
		for (i = 0; i < n; i++)
			out[i] = def[i];
		return rec_value(s, r, vector_text(out, n, dim), e);
	}
	/* fill out only once every item is good */
	v = calloc(n > 0 ? (size_t)n : 1, sizeof *v);
	if (!v)
		return dem_error_nomem(e, "scene vector");
	if (node->kind == NODE_SEQ)
		code = vector_seq(s, node, key, dim, n, min, max, v, e);
	else if (node->kind == NODE_SCALAR && !node_is_null(node))
		code = vector_scalar(s, node, key, dim, n, min, max, v, e);
	else {
		want_vector(dim, n, wantbuf, sizeof wantbuf);
		code = fail(s, node, e, "%s: expected %s, got %s", key,
			    wantbuf, describe(node, got, sizeof got));
	}
	if (code == DEM_OK) {
		for (i = 0; i < n; i++)
			out[i] = v[i];
		code = rec_value(s, r, vector_text(v, n, dim), e);
	}
	free(v);
	return code;
}

/* Keep a copy of str for the life of the scene. */
static const char *keep(dem_scene_t *s, const char *str)
{
	char *c;

	if (grow((void **)&s->keep, &s->capkeep, s->nkeep + 1,
		 sizeof *s->keep) < 0 || !(c = strdup(str)))
		return NULL;
	s->keep[s->nkeep++] = c;
	return c;
}

int dem_scene_string(dem_scene_t *s, const char *key, const char *def,
		     const char **out, dem_error_t *e)
{
	const char *v = def;
	struct node *n;
	long r = rec_ask(s, key, e);
	int rc;

	if (r < 0)
		return e->code;
	rc = get_scalar(s, key, "a string", &n, e);
	if (rc < 0)
		return e->code;
	if (rc == 1)
		v = n->text;
	if (v && !(v = keep(s, v)))
		return dem_error_nomem(e, "scene string");
	*out = v;
	return v ? rec_value(s, r, yaml_text(v), e) : DEM_OK;
}

/* ---- dem_scene_check ----------------------------------------------------- */

static int asked(const dem_scene_t *s, const char *key)
{
	return rec_find(s, key) != NULL;
}

static int asked_below(const dem_scene_t *s, const char *prefix)
{
	size_t i, n = strlen(prefix);

	for (i = 0; i < s->nrec; i++)
		if (!strncmp(s->rec[i].key, prefix, n) &&
		    s->rec[i].key[n] == '.')
			return 1;
	return 0;
}

static int cmp_str(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The keys asked for directly under prefix, sorted, comma-separated:
 * "density, dim, n".  NULL when out of memory. */
static char *known_below(const dem_scene_t *s, const char *prefix)
{
	size_t i, j, n = 0, plen = strlen(prefix), len = 0;
	char **names = malloc((s->nrec + 1) * sizeof *names), *buf = NULL;
	FILE *f;

	if (!names)
		return NULL;
	for (i = 0; i < s->nrec; i++) {
		const char *k = s->rec[i].key;

		if (strncmp(k, prefix, plen) || k[plen] != '.')
			continue;
		names[n] = xstrndup(k + plen + 1, strcspn(k + plen + 1, "."));
		if (!names[n])
			goto out;
		for (j = 0; j < n && strcmp(names[j], names[n]); j++)
			;
		if (j < n)
			free(names[n]);
		else
			n++;
	}
	qsort(names, n, sizeof *names, cmp_str);
	f = open_memstream(&buf, &len);
	if (f) {
		for (i = 0; i < n; i++)
			fprintf(f, "%s%s", i ? ", " : "", names[i]);
		if (fclose(f) != 0) {
			free(buf);
			buf = NULL;
		}
	}
out:
	for (i = 0; i < n; i++)
		free(names[i]);
	free(names);
	return buf;
}

static int unknown_key(const dem_scene_t *s, const struct entry *en,
		       const char *prefix, const char *full, dem_error_t *e)
{
	char *known = known_below(s, prefix);
	int code;

	if (!known)
		return dem_error_nomem(e, "scene check");
	code = fail_at(s, en->val->file, en->val->origin, en->line, en->col, e,
		       "unknown key '%s'; %s%s", full,
		       known[0] ? "known keys here: " : "no keys are read here",
		       known);
	free(known);
	return code;
}

/* Every key under map (at prefix) must have been asked for, or lead to
 * keys that were. */
static int check_map(const dem_scene_t *s, const struct node *map,
		     const char *prefix, dem_error_t *e)
{
	char got[80], *full;
	size_t i;
	int code = DEM_OK;

	if (node_is_null(map))
		return DEM_OK;
	if (map->kind != NODE_MAP)
		return fail(s, map, e, "%s: expected a mapping, got %s", prefix,
			    describe(map, got, sizeof got));
	for (i = 0; i < map->n && code == DEM_OK; i++) {
		const struct entry *en = &map->ent[i];

		full = xasprintf("%s.%s", prefix, en->key);
		if (!full)
			return dem_error_nomem(e, "scene check");
		if (asked(s, full) || (in_list(shared_keys, full) && en->val->kind == NODE_SCALAR))
			code = DEM_OK;
		else if (!strcmp(en->key, "use") &&
			 use_find(s, prefix, strlen(prefix)))
			code = DEM_OK;  /* the section's library file */
		else if ((en->val->kind == NODE_MAP || node_is_null(en->val)) &&
			 asked_below(s, full))
			code = check_map(s, en->val, full, e);
		else if (en->val->file)
			/* a library may hold what other laws need (a hardening
			 * table beside Johnson-Cook): what the program does not
			 * read of it is not the scene's typo */
			code = DEM_OK;
		else
			code = unknown_key(s, en, prefix, full, e);
		free(full);
	}
	return code;
}

/* The edit distance of a and b (insertions, deletions, substitutions
 * and swaps of two neighbours), or 3 when it is more than 2: enough to
 * tell a typo from another word. */
static int typo_distance(const char *a, const char *b)
{
	enum { MAXLEN = 32 };
	size_t m = strlen(a), n = strlen(b);
	int d[MAXLEN + 1][MAXLEN + 1];

	if (m > MAXLEN || n > MAXLEN || (m > n ? m - n : n - m) > 2)
		return 3;
	for (size_t i = 0; i <= m; i++)
		for (size_t j = 0; j <= n; j++) {
			if (!i || !j) {
				d[i][j] = (int)(i + j);
				continue;
			}
			int c = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
			if (d[i - 1][j] + 1 < c)
				c = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < c)
				c = d[i][j - 1] + 1;
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
			    d[i - 2][j - 2] + 1 < c)
				c = d[i - 2][j - 2] + 1;
			d[i][j] = c;
		}
	return d[m][n] < 3 ? d[m][n] : 3;
}

static int unknown_section(const dem_scene_t *s, const struct entry *en,
			   dem_error_t *e)
{
	char known[512], hint[64] = "";
	size_t i, k = 0;
	/* a typo: one slip in a short word, two in a longer one */
	int best = strlen(en->key) <= 4 ? 2 : 3;

	known[0] = '\0';
	for (i = 0; known_sections[i] && k < sizeof known; i++) {
		int dist = typo_distance(en->key, known_sections[i]);
		if (dist < best) {
			best = dist;
			snprintf(hint, sizeof hint, " (did you mean '%s'?)", known_sections[i]);
		}
		k += (size_t)snprintf(known + k, sizeof known - k, "%s%s",
				      i ? ", " : "", known_sections[i]);
	}
	return fail_at(s, en->val->file, en->val->origin, en->line, en->col, e,
		       "unknown section '%s'%s; known sections: %s", en->key,
		       hint, known);
}

/* Every top-level key is a known section. */
static int check_sections(const dem_scene_t *s, dem_error_t *e)
{
	for (size_t i = 0; i < s->root->n; i++)
		if (!in_list(known_sections, s->root->ent[i].key))
			return unknown_section(s, &s->root->ent[i], e);
	return DEM_OK;
}

int dem_scene_check(const dem_scene_t *s, const char *const *sections,
		    dem_error_t *e)
{
	size_t i;
	int code = DEM_OK;

	for (i = 0; i < s->root->n && code == DEM_OK; i++) {
		const struct entry *en = &s->root->ent[i];

		if (!in_list(known_sections, en->key))
			code = unknown_section(s, en, e);
		else if (in_list(sections, en->key))
			code = check_map(s, en->val, en->key, e);
	}
	return code;
}

/* ---- dem_scene_dump ------------------------------------------------------ */

/* Is the first dotted part of key (after plen bytes of prefix) the same as
 * that of an earlier record under the same prefix?  Then it was printed. */
static int seen_before(const dem_scene_t *s, size_t i, const char *prefix,
		       size_t plen, const char *part, size_t len)
{
	size_t j;

	for (j = 0; j < i; j++) {
		const char *k = s->rec[j].key;

		if (s->rec[j].val && !strncmp(k, prefix, plen) &&
		    !strncmp(k + plen, part, len) &&
		    (k[plen + len] == '.' || k[plen + len] == '\0'))
			return 1;
	}
	return 0;
}

/* Print the records whose keys start with prefix ("" or "pack.radius."),
 * grouped by their next dotted part, in the order first asked. */
static void dump_group(const dem_scene_t *s, FILE *f, const char *prefix,
		       int depth)
{
	size_t i, plen = strlen(prefix);

	for (i = 0; i < s->nrec; i++) {
		const char *k = s->rec[i].key, *part;
		char *sub, *name;
		size_t len;

		if (!s->rec[i].val || strncmp(k, prefix, plen))
			continue;
		part = k + plen;
		len = strcspn(part, ".");
		if (seen_before(s, i, prefix, plen, part, len))
			continue;
		sub = xstrndup(k, plen + len);
		name = sub ? yaml_text(sub + plen) : NULL;
		if (name && part[len] == '\0') {
			fprintf(f, "%*s%s: %s\n", 2 * depth, "", name,
				s->rec[i].val);
		} else if (name) {
			char *deeper = xasprintf("%s.", sub);

			fprintf(f, "%*s%s:\n", 2 * depth, "", name);
			if (deeper)
				dump_group(s, f, deeper, depth + 1);
			free(deeper);
		}
		free(name);
		free(sub);
	}
}

void dem_scene_dump(const dem_scene_t *s, FILE *f)
{
	dump_group(s, f, "", 0);
}
