/* demdetect - find the contact pairs of a particle or box stream.
 *
 *   demdetect [OPTION]... [FILE]
 *
 * Reads disks/spheres (each object's box is its bounding box, enlarged by
 * the buffer zone) or boxes, finds every pair of overlapping boxes with the
 * chosen algorithm of Ch. 2, and writes the pair stream (i < j, sorted) or,
 * with -c, only the number of pairs.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli.h"
#include "core/cost.h"
#include "detect/detect.h"
#include "io/scene.h"
#include "io/stream.h"

#define PROG "demdetect"

enum { OPT_SHAPE = DEM_OPT_PROGRAM, OPT_CELL, OPT_CELL_SIZE, OPT_BUFFER,
       OPT_PERIODIC, OPT_REPEAT };

static const dem_opt_t options[] = {
	{"algorithm", 'a', "ALGO", "dcell (default), nbs (2D), scell, adt, asdt or brute"},
	{"count", 'c', NULL, "print only the number of pairs"},
	{"shape", OPT_SHAPE, "[=TOL]", "keep pairs whose disks/spheres overlap by more than TOL x the smaller radius (default 0)"},
	{"cell", OPT_CELL, "FACTOR", "cell size as a multiple of the mean object size (default 3 in 2D, 2 in 3D)"},
	{"cell-size", OPT_CELL_SIZE, "L", "cell size as a length (overrides --cell)"},
	{"buffer", OPT_BUFFER, "B", "enlarge every particle's box by B on each side (default 0)"},
	{"periodic", OPT_PERIODIC, "AXES", "periodic along AXES (e.g. x, xy, xyz), period from the stream's domain"},
	{"repeat", OPT_REPEAT, "N", "detect N times with warm buffers, as a time loop does; report the median repeat as detect_warm_s"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] = "Usage: demdetect [OPTION]... [FILE]\n";
static const char purpose[] =
	"Find the contact pairs of a particle or box stream (FILE or standard input)\n"
	"and write them as a pair stream, or with -c print their number.\n";
static const char epilogue[] =
	"Examples:\n"
	"  dempack random -n 1000000 --seed 1 -b | demdetect -c\n"
	"  demdetect --shape 1e-9 -c packing.txt     # count overlapping disks\n"
	"\nSee demdetect(1), dem-scene(5) and dem-streams(5).\n";

struct cmdline {
	dem_common_t com;
	const char *input;
	int count;
	unsigned long repeat;   /* detections to time (1: just the one) */
};

static int looks_numeric(const char *s)
{
	char *end;
	strtod(s, &end);
	return end != s && *end == '\0';
}

static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *m = &cl->com;
	int k;

	memset(cl, 0, sizeof *cl);
	cl->repeat = 1;
	if (dem_common_init(m, argc) || dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	/* (of the common options, --seed and --accuracy have no use in detection) */
	while ((k = dem_cli_option(&c, m, argc, argv)) != -1) {
		switch (k) {
		case 'c': cl->count = 1; break;
		case OPT_REPEAT:
			dem_cli_ulong(&c, "--repeat", optarg, 1, 1000000, &cl->repeat);
			break;
		case 'a': dem_common_override(m, "detect.algorithm", optarg, "--algorithm"); break;
		case OPT_SHAPE:
			dem_common_override(m, "detect.shape", "true", "--shape");
			/* "--shape 1e-9" as well as "--shape=1e-9" */
			if (!optarg && optind < argc && looks_numeric(argv[optind]))
				optarg = argv[optind++];
			if (optarg)
				dem_common_override(m, "detect.shape_tol", optarg, "--shape");
			break;
		case OPT_CELL: dem_common_override(m, "detect.cell_factor", optarg, "--cell"); break;
		case OPT_CELL_SIZE: dem_common_override(m, "detect.cell", optarg, "--cell-size"); break;
		case OPT_BUFFER: dem_common_override(m, "detect.buffer", optarg, "--buffer"); break;
		case OPT_PERIODIC: dem_common_override(m, "detect.periodic", optarg, "--periodic"); break;
		default: break;
		}
	}
	if (c.done < 0) {
		cl->input = dem_cli_operand(&c, argc, argv, "input");
		if (cl->count && (m->output || m->binary || m->gzip))
			dem_cli_error(&c, "-c prints a number: -o, -b and -z do not apply");
	}
	return dem_cli_done(&c);
}

struct settings {
	dem_detect_opts_t opts;
	double buffer;
	int shape;
	double shape_tol;
	unsigned periodic;
};

static int read_scene(dem_scene_t *s, struct settings *st, dem_error_t *e)
{
	static const char *const algos[] = {"dcell", "nbs", "scell", "adt", "asdt", "brute", NULL};
	static const char *const sections[] = {"detect", NULL};
	const char *per;
	int algo;
	double cell;

	dem_detect_opts_init(&st->opts);
	if (dem_scene_choice(s, "detect.algorithm", algos, 0, &algo, e) ||
	    dem_scene_quantity(s, "detect.cell_factor", DEM_DIM_NONE, 0, 0, 1e6, &st->opts.cell_factor, e) ||
	    dem_scene_quantity(s, "detect.cell", DEM_DIM_LENGTH, 0, 0, HUGE_VAL, &cell, e) ||
	    dem_scene_quantity(s, "detect.buffer", DEM_DIM_LENGTH, 0, 0, HUGE_VAL, &st->buffer, e) ||
	    dem_scene_string(s, "detect.periodic", "", &per, e) ||
	    dem_scene_bool(s, "detect.shape", 0, &st->shape, e) ||
	    dem_scene_quantity(s, "detect.shape_tol", DEM_DIM_NONE, 0, -1, 1, &st->shape_tol, e))
		return e->code;
	st->opts.algo = (dem_detect_algo_t)algo;
	for (int d = 0; d < DEM_MAXDIM; d++)
		st->opts.cell[d] = cell;
	st->periodic = 0;
	for (const char *p = per; *p; p++) {
		const char *a = strchr("xyz", *p);
		if (!a)
			return dem_scene_error(s, "detect.periodic", e,
					       "'%s': expected axes among x, y, z (e.g. xy)", per);
		st->periodic |= 1u << (a - "xyz");
	}
	return dem_scene_check(s, sections, e);
}

/* The objects as read: boxes for detection, and centres and radii of
 * particles for --shape. */
struct objects {
	int particles;          /* 1: disks/spheres, 0: boxes */
	int centres;            /* centres and radii kept, for --shape */
	int dim;
	size_t n, cap;
	double *x[DEM_MAXDIM], *r;
	dem_boxes_t b;
};

static void objects_free(struct objects *o)
{
	for (int d = 0; d < DEM_MAXDIM; d++) {
		free(o->x[d]);
		free(o->b.lo[d]);
		free(o->b.hi[d]);
	}
	free(o->r);
}

static int objects_grow(struct objects *o)
{
	size_t cap = o->cap ? 2 * o->cap : 4096;
	for (int d = 0; d < o->dim; d++) {
		double **arr[3] = {&o->b.lo[d], &o->b.hi[d], &o->x[d]};
		for (int k = 0; k < (o->centres ? 3 : 2); k++) {
			double *p = realloc(*arr[k], cap * sizeof *p);
			if (!p)
				return DEM_EIO;
			*arr[k] = p;
		}
	}
	if (o->centres) {
		double *p = realloc(o->r, cap * sizeof *p);
		if (!p)
			return DEM_EIO;
		o->r = p;
	}
	o->cap = cap;
	return DEM_OK;
}

static int read_objects(dem_reader_t *rd, double buffer, int shape,
			struct objects *o, dem_error_t *e)
{
	const dem_header_t *h = dem_reader_header(rd);
	static const char *const pcol[] = {"x", "y", "z"};
	static const char *const lcol[] = {"xlo", "ylo", "zlo"};
	static const char *const hcol[] = {"xhi", "yhi", "zhi"};
	int ci[2 * DEM_MAXDIM + 1];
	double v[DEM_STREAM_MAXCOL];

	memset(o, 0, sizeof *o);
	o->particles = strcmp(h->kind, "particles") == 0;
	o->centres = o->particles && shape;
	if (!o->particles && strcmp(h->kind, "boxes") != 0)
		return dem_error_set(e, DEM_EINPUT, "%s: a %s stream; expected particles or boxes",
				     dem_reader_name(rd), h->kind);
	o->dim = o->b.dim = h->dim;
	if (h->dim < 1)
		return dem_error_set(e, DEM_EINPUT, "%s: the header has no '# dim' line",
				     dem_reader_name(rd));
	for (int d = 0; d < h->dim; d++) {
		ci[d] = dem_header_col(h, o->particles ? pcol[d] : lcol[d]);
		ci[DEM_MAXDIM + d] = o->particles ? 0 : dem_header_col(h, hcol[d]);
		if (ci[d] < 0 || ci[DEM_MAXDIM + d] < 0)
			return dem_error_set(e, DEM_EINPUT, "%s: no column '%s'", dem_reader_name(rd),
					     ci[d] < 0 ? (o->particles ? pcol[d] : lcol[d]) : hcol[d]);
	}
	int cr = o->particles ? dem_header_col(h, "r") : 0;
	if (cr < 0)
		return dem_error_set(e, DEM_EINPUT, "%s: no column 'r'", dem_reader_name(rd));
	/* every column read is a length: convert to metres */
	double f[2 * DEM_MAXDIM + 1];
	for (int d = 0; d < h->dim; d++) {
		if (dem_header_col_factor(h, ci[d], DEM_DIM_LENGTH, dem_reader_name(rd), &f[d], e) ||
		    dem_header_col_factor(h, o->particles ? cr : ci[DEM_MAXDIM + d], DEM_DIM_LENGTH,
					  dem_reader_name(rd), &f[DEM_MAXDIM + d], e))
			return e->code;
	}
	double fr = f[DEM_MAXDIM];
	int got;
	while ((got = dem_reader_next(rd, v, e)) == 1) {
		if (o->n == o->cap && objects_grow(o))
			return dem_error_nomem(e, "objects");
		size_t i = o->n++;
		if (o->particles) {
			double r = v[cr] * fr;
			if (r < 0)
				return dem_error_set(e, DEM_EINPUT, "%s: negative radius %g",
						     dem_reader_where(rd), r);
			if (o->centres)
				o->r[i] = r;
			for (int d = 0; d < o->dim; d++) {
				double x = v[ci[d]] * f[d];
				if (o->centres)
					o->x[d][i] = x;
				o->b.lo[d][i] = x - r - buffer;
				o->b.hi[d][i] = x + r + buffer;
			}
		} else {
			for (int d = 0; d < o->dim; d++) {
				o->b.lo[d][i] = v[ci[d]] * f[d];
				o->b.hi[d][i] = v[ci[DEM_MAXDIM + d]] * f[DEM_MAXDIM + d];
				if (!(o->b.lo[d][i] <= o->b.hi[d][i]))
					return dem_error_set(e, DEM_EINPUT, "%s: %s > %s",
							     dem_reader_where(rd), lcol[d], hcol[d]);
			}
		}
	}
	o->b.n = o->n;
	return got < 0 ? e->code : DEM_OK;
}

/* The period of each periodic axis, from the stream's "# domain LO.. HI.." */
static int read_period(dem_reader_t *rd, unsigned periodic, int dim,
		       dem_detect_opts_t *o, dem_error_t *e)
{
	const char *dom = dem_header_get(dem_reader_header(rd), "domain");
	double v[2 * DEM_MAXDIM];
	int n = 0, used;

	if (periodic >> dim)
		return dem_error_set(e, DEM_EINPUT, "periodic axis %c in a %dD stream",
				     "xyz"[dim], dim);
	if (!dom)
		return dem_error_set(e, DEM_EINPUT,
				     "%s: no '# domain' line in the header: periodic detection needs the period",
				     dem_reader_name(rd));
	while (n < 2 * dim && sscanf(dom, "%lf%n", &v[n], &used) == 1) {
		dom += used;
		n++;
	}
	if (n != 2 * dim)
		return dem_error_set(e, DEM_EINPUT, "%s: '# domain' needs %d numbers (lower and upper corners)",
				     dem_reader_name(rd), 2 * dim);
	o->periodic = periodic;
	for (int d = 0; d < dim; d++) {
		o->period_lo[d] = v[d];
		o->period_hi[d] = v[dim + d];
	}
	return DEM_OK;
}

/* --shape: keep the pairs whose disks or spheres overlap by more than tol
 * times the smaller radius (minimum image along periodic axes). */
static void shape_filter(const struct objects *ob, const dem_detect_opts_t *o,
			 double tol, dem_pairs_t *p)
{
	size_t k = 0;
	for (size_t q = 0; q < p->n; q++) {
		uint32_t i = p->p[q].i, j = p->p[q].j;
		double dd = 0;
		for (int d = 0; d < ob->dim; d++) {
			double dx = ob->x[d][j] - ob->x[d][i];
			if (o->periodic >> d & 1) {
				double L = o->period_hi[d] - o->period_lo[d];
				dx -= L * nearbyint(dx / L);
			}
			dd += dx * dx;
		}
		double ri = ob->r[i], rj = ob->r[j];
		double overlap = ri + rj - sqrt(dd);
		if (overlap > tol * (ri < rj ? ri : rj))
			p->p[k++] = p->p[q];
	}
	p->n = k;
}

static int write_pairs(const struct cmdline *cl, dem_reader_t *rd, int argc,
		       char **args, size_t nobj, const dem_pairs_t *p,
		       dem_error_t *e)
{
	dem_header_t h;
	dem_writer_t *w = NULL;
	int rc;

	dem_header_init(&h, "pairs", 1, 0);
	dem_header_add_col(&h, "i", DEM_U32, "-");
	dem_header_add_col(&h, "j", DEM_U32, "-");
	if ((rc = dem_header_copy_lines(&h, dem_reader_header(rd))) ||
	    (rc = dem_header_add_provenance(&h, PROG, argc, args, 0, 0)) ||
	    (rc = dem_header_set(&h, "objects", "%zu", nobj))) {
		dem_header_free(&h);
		return dem_error_nomem(e, "header");
	}
	int flags = (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0);
	rc = dem_writer_open(&w, cl->com.output, &h, flags, e);
	dem_header_free(&h);
	if (rc)
		return rc;
	for (size_t q = 0; q < p->n; q++) {
		double v[2] = {p->p[q].i, p->p[q].j};
		if ((rc = dem_writer_row(w, v, e))) {
			dem_writer_abort(w);
			return rc;
		}
	}
	return dem_writer_close(w, e);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* --repeat: the steady cost of detection in a time loop, where buffers are
 * warm from the step before: the median of n more runs.  Detection is
 * deterministic, so the runs refill the same pair list with the same pairs
 * and no second list is needed. */
static int time_repeats(const dem_boxes_t *b, const dem_detect_opts_t *o,
			unsigned long n, dem_pairs_t *p, dem_cost_t *cost,
			dem_error_t *e)
{
	double *t = malloc(n * sizeof *t);
	size_t first = p->n;
	int rc = DEM_OK;

	if (!t)
		return dem_error_nomem(e, "timings");
	for (unsigned long k = 0; k < n && rc == DEM_OK; k++) {
		p->n = 0;
		double t0 = dem_wall();
		rc = dem_detect(b, o, p, NULL, e);
		t[k] = dem_wall() - t0;
		if (rc == DEM_OK && p->n != first)
			rc = dem_error_set(e, DEM_ENUMERIC, "repeated detection found %zu pairs, not %zu",
					   p->n, first);
	}
	if (rc == DEM_OK) {
		qsort(t, n, sizeof *t, cmp_double);
		dem_cost_time(cost, "detect_warm", n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]));
	}
	free(t);
	return rc;
}

/* A run: the settings, the objects read and the pairs found. */
struct job {
	struct settings set;
	struct objects ob;
	dem_reader_t *rd;
	dem_pairs_t pairs;
	dem_detect_stats_t stats;
	size_t box_pairs;       /* before --shape */
};

/* The scene's settings with the options' overrides; --dump-scene prints
 * them. */
static int get_settings(const struct cmdline *cl, struct settings *set, dem_error_t *e)
{
	dem_scene_t *scene = NULL;
	int rc = dem_scene_open(&scene, &cl->com, e);

	if (!rc)
		rc = read_scene(scene, set, e);
	if (!rc && cl->com.dump)
		dem_scene_dump(scene, stdout);
	dem_scene_free(scene);
	return rc;
}

static int read_input(const struct cmdline *cl, struct job *j, dem_cost_t *cost, dem_error_t *e)
{
	double t = dem_wall();
	int rc;

	if ((rc = dem_reader_open(&j->rd, cl->input, e)) ||
	    (rc = read_objects(j->rd, j->set.buffer, j->set.shape, &j->ob, e)))
		return rc;
	if (j->set.shape && !j->ob.particles)
		return dem_error_set(e, DEM_EINPUT, "%s: --shape needs disks or spheres, not boxes",
				     dem_reader_name(j->rd));
	if (j->set.periodic &&
	    (rc = read_period(j->rd, j->set.periodic, j->ob.dim, &j->set.opts, e)))
		return rc;
	dem_cost_time(cost, "read", dem_wall() - t);
	return DEM_OK;
}

/* Detection (timed again with --repeat), then --shape's filter. */
static int find_pairs(const struct cmdline *cl, struct job *j, dem_cost_t *cost, dem_error_t *e)
{
	int rc;

	if (cl->repeat > 1 && !(j->set.opts.ws = dem_detect_ws_new()))
		return dem_error_nomem(e, "detection workspace");
	double t = dem_wall();
	if ((rc = dem_detect(&j->ob.b, &j->set.opts, &j->pairs, &j->stats, e)))
		return rc;
	dem_cost_time(cost, "detect", dem_wall() - t);
	if (cl->repeat > 1 &&
	    (rc = time_repeats(&j->ob.b, &j->set.opts, cl->repeat - 1, &j->pairs, cost, e)))
		return rc;
	j->box_pairs = j->pairs.n;
	if (j->set.shape) {
		t = dem_wall();
		shape_filter(&j->ob, &j->set.opts, j->set.shape_tol, &j->pairs);
		dem_cost_time(cost, "shape", dem_wall() - t);
	}
	return DEM_OK;
}

/* The count (-c), or the pair stream in (i, j) order. */
static int put_pairs(const struct cmdline *cl, struct job *j, dem_main_t *r)
{
	int rc;

	if (cl->count) {
		printf("%zu\n", j->pairs.n);
		return DEM_OK;
	}
	double t = dem_wall();
	if (dem_pairs_sort(&j->pairs))
		return dem_error_nomem(&r->e, "sorting pairs");
	dem_cost_time(&r->cost, "sort", dem_wall() - t);
	t = dem_wall();
	if ((rc = write_pairs(cl, j->rd, r->argc, r->args, j->ob.n, &j->pairs, &r->e)))
		return rc;
	dem_cost_time(&r->cost, "write", dem_wall() - t);
	return DEM_OK;
}

static void report(const struct cmdline *cl, const struct job *j, dem_cost_t *cost)
{
	dem_cost_count(cost, "objects", (double)j->ob.n);
	dem_cost_count(cost, "pairs", (double)j->pairs.n);
	if (j->set.shape)
		dem_cost_count(cost, "box_pairs", (double)j->box_pairs);
	dem_cost_count(cost, "checks", (double)j->stats.checks);
	if (j->stats.ghosts)
		dem_cost_count(cost, "images", (double)j->stats.ghosts);
	if (cl->com.verbose)
		fprintf(stderr, "%s: %s, %zu objects, cell %g x %g x %g\n", PROG,
			dem_detect_algo_name(j->set.opts.algo), j->ob.n, j->stats.cell[0],
			j->stats.cell[1], j->stats.cell[2]);
}

int main(int argc, char **argv)
{
	struct cmdline cl;
	struct job j = {0};
	dem_main_t r;
	int rc;

	if ((rc = dem_main_start(&r, PROG, argc, argv)))
		return rc;
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0)
		return dem_main_quit(&r, &cl.com, rc);
	dem_pairs_init(&j.pairs);
	if (!(rc = get_settings(&cl, &j.set, &r.e)) && !cl.com.dump &&
	    !(rc = read_input(&cl, &j, &r.cost, &r.e)) &&
	    !(rc = find_pairs(&cl, &j, &r.cost, &r.e)) &&
	    !(rc = put_pairs(&cl, &j, &r)))
		report(&cl, &j, &r.cost);
	dem_detect_ws_free(j.set.opts.ws);
	dem_pairs_free(&j.pairs);
	objects_free(&j.ob);
	dem_reader_close(j.rd);
	return dem_main_end(&r, &cl.com, rc);
}
